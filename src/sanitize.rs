//! Host values made usable: every number the host or the configuration gives passes
//! through one of these before it reaches rapier, so no NaN or infinity gets in.

/// `x` when it is finite, else `fallback`.
pub(crate) fn finite_or(x: f32, fallback: f32) -> f32 {
    if x.is_finite() {
        x
    } else {
        fallback
    }
}

/// `x` when it is finite and positive, else `fallback`.
pub(crate) fn positive_or(x: f32, fallback: f32) -> f32 {
    if x.is_finite() && x > 0.0 {
        x
    } else {
        fallback
    }
}

/// Serde for an `f32` that may be infinite, in formats without infinities (JSON): a
/// finite value as itself, an infinite one as `null`, read back as `+∞`.
pub(crate) mod infinite_as_null {
    use serde::{Deserialize, Deserializer, Serializer};

    pub(crate) fn serialize<S: Serializer>(x: &f32, serializer: S) -> Result<S::Ok, S::Error> {
        if x.is_finite() {
            serializer.serialize_some(x)
        } else {
            serializer.serialize_none()
        }
    }

    pub(crate) fn deserialize<'de, D: Deserializer<'de>>(deserializer: D) -> Result<f32, D::Error> {
        Ok(Option::<f32>::deserialize(deserializer)?.unwrap_or(f32::INFINITY))
    }
}
