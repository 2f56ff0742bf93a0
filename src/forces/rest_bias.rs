//! A stress layout's balance at rest. When the schedule ends, a layout rests where its
//! forces have nearly stopped moving it, not where they cancel: a random graph's stress
//! layout holds a pull on every node (normalised stress 0.18 to 0.19, where the sum of
//! the terms would only reach its minimum over far more time). A drag later wakes and
//! heats a neighbourhood, the woken nodes feel that held pull, move, wake the next by
//! contact, and the motion spreads over the whole graph.
//!
//! So at each cold stop the springs' pull on every dynamic body (edges and stress terms,
//! per unit of the world's spring scale) is kept, and taken off the pull from then on:
//! the rest becomes the springs' exact balance, and a disturbance moves what its change
//! of the forces reaches. Kept while the world's bodies and joints stay as they were
//! (the world's version); a reheat of the whole layout forgets it, so a relayout goes on
//! toward the stress minimum.

use std::hash::Hash;

use euclid::default::Vector2D;
use serde::{Deserialize, Serialize};

use crate::world::RapierSceneWorld;

/// The springs' pull on each body at the last cold stop, per unit of spring scale, by
/// world slot, and the world version it belongs to.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub(crate) struct RestBias {
    per_slot: Vec<Vector2D<f32>>,
    version: Option<u64>,
}

impl RestBias {
    /// The balance of `springs` (the springs' pull on every body, by slot) in `world`.
    pub(crate) fn capture<N: Clone + Eq + Hash>(
        world: &RapierSceneWorld<N>,
        springs: &[Vector2D<f32>],
    ) -> Self {
        let scale = world.applied_spring_scale();
        if !(scale > 0.0 && scale.is_finite()) {
            return Self::default();
        }
        Self {
            per_slot: springs
                .iter()
                .map(|&f| {
                    let f = f / scale;
                    if f.is_finite() {
                        f
                    } else {
                        Vector2D::zero()
                    }
                })
                .collect(),
            version: Some(world.version()),
        }
    }

    /// Whether the balance belongs to `world` as it is.
    pub(crate) fn holds<N: Clone + Eq + Hash>(
        &self,
        world: &RapierSceneWorld<N>,
        n: usize,
    ) -> bool {
        self.version == Some(world.version()) && self.per_slot.len() == n
    }

    /// Takes the balance off the springs' pull on each pushed body (a no-op once the
    /// world changed since the capture).
    pub(crate) fn take_from<N: Clone + Eq + Hash>(
        &self,
        world: &RapierSceneWorld<N>,
        pushed: &[bool],
        springs: &mut [Vector2D<f32>],
    ) {
        if self.version != Some(world.version()) || self.per_slot.len() != springs.len() {
            return;
        }
        let scale = world.applied_spring_scale();
        for ((f, &bias), &pushed) in springs.iter_mut().zip(&self.per_slot).zip(pushed) {
            if pushed {
                *f -= bias * scale;
            }
        }
    }
}
