//! Each pushed body's sums made one force: its springs at its own heat ([`HeatLaw`]),
//! the implicit step on its stiffness, and the force set on the body with the disk
//! separation's velocity change.

use std::hash::Hash;

use euclid::default::Vector2D;
use rapier2d::prelude::Vector;

use super::Forces;
use crate::config::cooling::HeatLaw;
use crate::forces::ForceSums;
use crate::world::RapierSceneWorld;

/// `m (M)⁻¹ f` with `M = (m + resistance) I + [[xx, xy], [xy, yy]]`: the implicit step
/// on a body's isotropic springs and its directed pulls at once.
fn implicit_with_pulls(
    f: Vector2D<f32>,
    m: f32,
    resistance: f32,
    [xx, xy, yy]: [f32; 3],
) -> Vector2D<f32> {
    let (a, c) = (m + resistance + xx, m + resistance + yy);
    let det = a * c - xy * xy;
    Vector2D::new(c * f.x - xy * f.y, a * f.y - xy * f.x) * (m / det)
}

/// Bodies a run of [`Forces::apply`]'s sums takes (fixed: each body's sum is its own).
const COMBINE_RUN: usize = 1_024;

impl<N: Clone + Eq + Hash> Forces<N> {
    /// Sums each pushed body's forces and springs at its own heat ([`HeatLaw`]) and
    /// takes the implicit step on its stiffness, in runs of [`COMBINE_RUN`] bodies side
    /// by side under `parallel` (each body's own arithmetic). A body whose sum is not
    /// finite is no longer pushed: it keeps the force it had, and what is kept of it no
    /// longer matches rapier, so it is read again at the next gather. With `velocity_dt`,
    /// also adds to each pushed body's velocity what its force gives it over that time
    /// (what the disk separation starts from).
    pub(super) fn combine(
        &mut self,
        world: &mut RapierSceneWorld<N>,
        law: HeatLaw,
        velocity_dt: Option<f32>,
    ) {
        let n = self.sums.forces.len();
        let view = world.slots_view();
        let ForceSums {
            forces,
            springs,
            resistance,
            pulls,
        } = &mut self.sums;
        let (springs, resistance, pulls) = (&springs[..], &resistance[..], &pulls[..]);
        let runs = || crate::parallel::runs(n, COMBINE_RUN);
        let mut jobs: Vec<_> = crate::parallel::split_ranges(forces, runs())
            .into_iter()
            .zip(crate::parallel::split_ranges(
                &mut self.bodies.pushed,
                runs(),
            ))
            .zip(crate::parallel::split_ranges(
                &mut self.bodies.velocities,
                runs(),
            ))
            .map(|((forces, (_, pushed)), (_, velocities))| {
                (forces, pushed, velocities, Vec::new())
            })
            .collect();
        crate::parallel::for_each(
            &mut jobs,
            || (),
            |(), ((range, forces), pushed, velocities, lost)| {
                let bodies = range.clone().zip(forces.iter_mut()).zip(pushed.iter_mut());
                for (((s, f), pushed), v) in bodies.zip(velocities.iter_mut()) {
                    if !*pushed {
                        continue;
                    }
                    let mut resistance = resistance[s];
                    let mut pulls = pulls[s];
                    match law.boosts(view.host_at(s).heat) {
                        None => *f += springs[s],
                        Some((springs_boost, others)) => {
                            // Heated by a local disturbance.
                            *f = *f * others + springs[s] * springs_boost;
                            resistance *= springs_boost;
                            pulls = pulls.map(|r| r * springs_boost);
                        }
                    }
                    let mass = view.mass_at(s);
                    if pulls.iter().any(|r| *r != 0.0) {
                        *f = implicit_with_pulls(*f, mass, resistance, pulls);
                    } else if resistance > 0.0 {
                        *f *= mass / (mass + resistance);
                    }
                    if !f.is_finite() {
                        *pushed = false;
                        lost.push(s);
                    } else if let Some(dt) = velocity_dt {
                        // The velocity this substep's force gives.
                        *v += *f * (dt / mass);
                    }
                }
            },
        );
        for s in jobs.into_iter().flat_map(|(.., lost)| lost) {
            world.mark_changed(s);
        }
    }

    /// Sets each pushed body's force to its sum and adds the disk separation's velocity
    /// change (when `separate`) to each dynamic body it changed.
    pub(super) fn put_on_bodies(&mut self, world: &mut RapierSceneWorld<N>, separate: bool) {
        let n = world.slot_count();
        let changes = if separate {
            self.collide.changes(n)
        } else {
            &[]
        };
        for s in 0..n {
            let change = changes.get(s).copied().unwrap_or_default();
            if !self.bodies.pushed[s] && change == Vector2D::zero() {
                continue;
            }
            let body = world.body_at_mut(s);
            if self.bodies.pushed[s] {
                let f = self.sums.forces[s];
                body.reset_forces(false);
                body.add_force(Vector::new(f.x, f.y), false);
            }
            if change != Vector2D::zero() && body.is_dynamic() {
                let v = body.linvel() + Vector::new(change.x, change.y);
                if v.is_finite() {
                    // Without waking: the bodies that gave way are awake already.
                    body.set_linvel(v, false);
                }
            }
        }
    }
}
