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
