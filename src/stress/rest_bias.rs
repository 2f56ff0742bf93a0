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

/// The pull on each body at the last cold stop, by world slot: the springs' per unit of
/// spring scale, the other forces' as they were (the heat stays at its floor until a
/// reheat of the whole layout forgets the balance), and the world version they belong
/// to.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub(crate) struct RestBias {
    per_slot: Vec<Vector2D<f32>>,
    #[serde(default)]
    others: Vec<Vector2D<f32>>,
    version: Option<u64>,
}

impl RestBias {
    /// The balance of `springs` and `forces` (every body's pull, by slot) in `world`,
    /// kept for the dynamic bodies (`dynamic`); a body fixed or held then has none.
    pub(crate) fn capture<N: Clone + Eq + Hash>(
        world: &RapierSceneWorld<N>,
        dynamic: &[bool],
        springs: &[Vector2D<f32>],
        forces: &[Vector2D<f32>],
    ) -> Self {
        let scale = world.applied_spring_scale();
        if !(scale > 0.0 && scale.is_finite()) {
            return Self::default();
        }
        let kept = |f: Vector2D<f32>, dynamic: bool| {
            if dynamic && f.is_finite() {
                f
            } else {
                Vector2D::zero()
            }
        };
        Self {
            per_slot: springs
                .iter()
                .zip(dynamic)
                .map(|(&f, &d)| kept(f / scale, d))
                .collect(),
            others: forces
                .iter()
                .zip(dynamic)
                .map(|(&f, &d)| kept(f, d))
                .collect(),
            version: Some(world.version()),
        }
    }

    /// Whether a snapshot's balance can be read as it is: the springs' and the other
    /// forces' by the same slots (or none of the others), every pull finite.
    pub(crate) fn check(&self) -> Result<(), &'static str> {
        let same = self.others.is_empty() || self.others.len() == self.per_slot.len();
        let finite = self
            .per_slot
            .iter()
            .chain(&self.others)
            .all(|f| f.is_finite());
        if same && finite {
            Ok(())
        } else {
            Err("forces.rest_bias")
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

    /// Takes the balance off each pushed body's pull (a no-op once the world changed
    /// since the capture).
    pub(crate) fn take_from<N: Clone + Eq + Hash>(
        &self,
        world: &RapierSceneWorld<N>,
        pushed: &[bool],
        springs: &mut [Vector2D<f32>],
        forces: &mut [Vector2D<f32>],
    ) {
        if !self.holds(world, springs.len()) || self.others.len() != forces.len() {
            return;
        }
        let scale = world.applied_spring_scale();
        for (s, &pushed) in pushed.iter().enumerate() {
            if pushed {
                springs[s] -= self.per_slot[s] * scale;
                forces[s] -= self.others[s];
            }
        }
    }
}
