//! What is simulated: awake counts, waking bodies (all of them, or those in the path of
//! a host-moved kinematic or fixed body, which rapier does not wake), halting every
//! dynamic body at the end of a cooling schedule, and contacts on or off.

use std::hash::Hash;

use euclid::default::Point2D;
use rapier2d::prelude::Vector;

use super::RapierSceneWorld;

/// How far beyond touching a host-moved body wakes the sleeping bodies in its path, as
/// a factor on the sum of the two bounding radii: a tenth more, so a body that the move
/// only grazes is woken too.
const WAKE_MARGIN: f32 = 1.1;

impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    /// Number of bodies rapier is simulating (awake dynamic and kinematic ones). O(1).
    pub fn awake_body_count(&self) -> usize {
        self.islands.num_active_bodies()
    }

    /// Number of dynamic bodies that are awake.
    ///
    /// Test and debug introspection, not part of the API: it may change in any release.
    #[doc(hidden)]
    pub fn awake_dynamic_count(&self) -> usize {
        self.bodies
            .iter()
            .filter(|(_, b)| b.is_dynamic() && !b.is_sleeping())
            .count()
    }

    /// Stops every dynamic body where it is: velocity zeroed and added forces cleared,
    /// without waking anything. Returns how many dynamic bodies there are. A halted body
    /// moves again only if something pushes it in a later [`step`](Self::step) (a joint,
    /// a contact, gravity): [`RapierLayout`](crate::RapierLayout) halts a cooled layout
    /// and then stops stepping it until a disturbance.
    ///
    /// Rapier's own `RigidBody::sleep` is not used for this: it flags the body asleep
    /// without taking its island out of the simulation, so joints and gravity kept moving
    /// the flagged bodies while contacts between them were skipped.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, NodeAvatarBinding,
    ///     NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = NodeSnapshot { id: 0_u32, position: Point2D::origin(), radius: 16.0, pinned: false };
    /// world.build_bodies(&[NodeAvatarBinding::circle(0, 16.0)], &[snap]);
    /// world.apply_impulse(&0, Vector2D::new(100.0, 0.0));
    /// assert_eq!(world.halt_dynamic_bodies(), 1);
    /// world.step(Vector2D::zero());
    /// assert_eq!(world.get_position(&0), Some(Point2D::origin()), "halted, it did not fly");
    /// ```
    pub fn halt_dynamic_bodies(&mut self) -> usize {
        let mut halted = 0;
        for s in 0..self.slots.len() {
            let body = self.body_at_mut(s);
            if body.is_dynamic() {
                body.set_linvel(Vector::ZERO, false);
                body.reset_forces(false);
                halted += 1;
            }
        }
        halted
    }

    /// Puts every dynamic body to sleep (rapier's `RigidBody::sleep`: it stays asleep
    /// until something wakes it). O(n).
    pub(crate) fn sleep_dynamic_bodies_now(&mut self) {
        for s in 0..self.slots.len() {
            let body = self.body_at_mut(s);
            if body.is_dynamic() {
                body.sleep();
            }
        }
    }

    /// Wakes every sleeping dynamic body. Returns how many were woken. O(n).
    pub(crate) fn wake_dynamic_bodies(&mut self) -> usize {
        let mut woken = 0;
        for s in 0..self.slots.len() {
            let body = self.body_at_mut(s);
            if body.is_dynamic() && body.is_sleeping() {
                body.wake_up(true);
                woken += 1;
            }
        }
        woken
    }

    /// Wakes every sleeping dynamic body within reach of the node in `slot` as it moves
    /// from `from` to `to` (its bounding disk swept along the segment, plus a tenth of
    /// the two radii). A kinematic or fixed body that the host moves into a sleeping
    /// body does not wake it in rapier, so without this a dragged node passed through
    /// nodes at rest. Returns how many bodies were woken. O(n).
    ///
    /// `kept`: every body's position and whether it is a sleeping dynamic body, by slot,
    /// as the layout keeps them (exact for every body the world has not reported
    /// changed since), read instead of rapier's bodies: at 100,000 bodies, reading each
    /// from rapier is a cache miss a body, every dragged frame.
    pub(crate) fn wake_bodies_near_sweep(
        &mut self,
        slot: usize,
        from: Point2D<f32>,
        to: Point2D<f32>,
        kept: Option<(&[Point2D<f32>], &[bool])>,
    ) -> usize {
        let reach = self.slots[slot].shape.bounding_radius();
        let segment = to - from;
        let length_sq = segment.square_length();
        let n = self.slots.len();
        let kept = kept.filter(|(points, sleeping)| {
            points.len() == n && sleeping.len() == n && self.changed_slots().is_some()
        });
        let mut woken = 0;
        for s in 0..n {
            if s == slot {
                continue;
            }
            let handle = self.slots[s].body;
            let p = match kept {
                Some((points, sleeping)) if !self.is_changed(s) => {
                    #[cfg(debug_assertions)]
                    {
                        let body = &self.bodies[handle];
                        let asleep = body.is_dynamic() && body.is_sleeping();
                        let at = self.position_at(s);
                        assert!(
                            asleep == sleeping[s] && (!asleep || at == points[s]),
                            "slot {s}: kept {:?} asleep {}, rapier {at:?} asleep {asleep}",
                            points[s],
                            sleeping[s]
                        );
                    }
                    if !sleeping[s] {
                        continue;
                    }
                    points[s]
                }
                _ => {
                    let Some(body) = self.bodies.get(handle) else {
                        continue;
                    };
                    if !(body.is_dynamic() && body.is_sleeping()) {
                        continue;
                    }
                    self.position_at(s)
                }
            };
            let t = if length_sq > 0.0 {
                ((p - from).dot(segment) / length_sq).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let closest = from + segment * t;
            let within = WAKE_MARGIN * (reach + self.slots[s].shape.bounding_radius());
            if (p - closest).square_length() <= within * within {
                if let Some(body) = self.bodies.get_mut(handle) {
                    body.wake_up(true);
                    woken += 1;
                    self.touched = true;
                    self.mark_changed(s);
                }
            }
        }
        woken
    }

    /// Turns contacts between nodes off or on, keeping the colliders: off, the broad and
    /// narrow phases skip them (and report no contact events), so nodes pass through
    /// each other. Turning them on wakes every body, so overlaps made meanwhile are
    /// parted. Nodes inserted meanwhile follow the setting. O(n) when it changes, free
    /// otherwise.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, NodeAvatarBinding,
    ///     NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = |id, x| NodeSnapshot { id, position: Point2D::new(x, 0.0), radius: 16.0, pinned: false };
    /// world.build_bodies(
    ///     &[NodeAvatarBinding::circle(0_u32, 16.0), NodeAvatarBinding::circle(1, 16.0)],
    ///     &[snap(0, 0.0), snap(1, 10.0)],
    /// );
    /// world.set_contacts_enabled(false);
    /// world.step(Vector2D::zero());
    /// assert!(world.read_positions().is_empty(), "without contacts the overlap stays");
    /// world.set_contacts_enabled(true);
    /// world.step(Vector2D::zero());
    /// assert_eq!(world.read_positions().len(), 2, "contacts push the pair apart");
    /// ```
    pub fn set_contacts_enabled(&mut self, enabled: bool) {
        if enabled == self.contacts_enabled {
            return;
        }
        self.contacts_enabled = enabled;
        for slot in &self.slots {
            if let Some(collider) = slot.collider.and_then(|c| self.colliders.get_mut(c)) {
                collider.set_enabled(enabled);
            }
        }
        if enabled {
            // A body asleep in an overlap would not notice its new contacts.
            self.wake_dynamic_bodies();
        }
    }

    /// Whether contacts take part in the simulation; see
    /// [`set_contacts_enabled`](Self::set_contacts_enabled).
    ///
    /// Test and debug introspection, not part of the API: it may change in any release.
    #[doc(hidden)]
    pub fn contacts_enabled(&self) -> bool {
        self.contacts_enabled
    }
}
