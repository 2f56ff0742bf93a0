//! Local disturbance ([`Cooling::reheat_hops`](crate::config::Cooling::reheat_hops)): what a
//! drag, a release, a host move, a pin or an edit touched this call, and the heat that
//! spreads from it along the edges, hop by hop, to the nodes near it. The heat itself,
//! and how it cools, is in `heat.rs`.

use std::hash::Hash;

use crate::world::RapierSceneWorld;

/// Each hop from what was touched is this much as hot as the one before.
const HOP_FALLOFF: f32 = 0.5;

/// The nodes touched this call and the buffers that spread their heat.
#[derive(Debug, Default)]
pub(super) struct Disturbances {
    /// `(slot, whether it heats itself, whether its heat spreads to its neighbours)`.
    touched: Vec<(u32, bool, bool)>,
    /// Something that reheats the whole layout happened (a configuration or gravity
    /// change, a new world).
    everything: bool,
    /// The world's joints as neighbour lists by slot, and the world version they are of.
    offsets: Vec<u32>,
    neighbours: Vec<u32>,
    version: Option<u64>,
    /// Hop distance reached by the spread, by slot (`u32::MAX`: not reached).
    reached: Vec<u32>,
    /// Whether the node in a slot heats itself, and whether its heat spreads.
    itself: Vec<bool>,
    spreads: Vec<bool>,
    queue: Vec<u32>,
}

impl Disturbances {
    /// Records that the node in `slot` was touched. A dragged or thrown node does not
    /// heat itself (`itself` false): it coasts, and its neighbours are heated.
    pub(super) fn touch(&mut self, slot: usize, itself: bool) {
        self.touched.push((slot as u32, itself, true));
    }

    /// Records a node that settles where it is without heating anything: a new node
    /// seated beside its neighbours (`seating.rs`) takes the heat of a coasting node and
    /// leaves its neighbourhood asleep.
    pub(super) fn touch_settling(&mut self, slot: usize) {
        self.touched.push((slot as u32, false, false));
    }

    /// Records a disturbance of the whole layout.
    pub(super) fn touch_everything(&mut self) {
        self.everything = true;
    }

    /// Whether the whole layout was disturbed this call.
    pub(super) fn everything(&self) -> bool {
        self.everything
    }

    /// Forgets this call's disturbances.
    pub(super) fn clear(&mut self) {
        self.touched.clear();
        self.everything = false;
    }

    /// Forgets the neighbour lists too (the world was dropped or built anew).
    pub(super) fn reset(&mut self) {
        self.clear();
        self.version = None;
    }

    /// Raises the heat of every node within `hops` of what was touched to at least
    /// `heat × 1/2^hop`, and wakes it.
    pub(super) fn spread<N: Clone + Eq + Hash>(
        &mut self,
        world: &mut RapierSceneWorld<N>,
        hops: u32,
        heat: f32,
        coasting: f32,
    ) {
        if self.touched.is_empty() {
            return;
        }
        self.index(world);
        let n = world.slot_count();
        self.reached.clear();
        self.reached.resize(n, u32::MAX);
        self.itself.clear();
        self.itself.resize(n, false);
        self.spreads.clear();
        self.spreads.resize(n, false);
        self.queue.clear();
        // A breadth-first search from every touched node at once.
        for &(slot, itself, spreads) in &self.touched {
            let s = slot as usize;
            if s >= n {
                continue;
            }
            self.itself[s] |= itself;
            self.spreads[s] |= spreads;
            if self.reached[s] != 0 {
                self.reached[s] = 0;
                self.queue.push(slot);
            }
        }
        let mut next = 0;
        while next < self.queue.len() {
            let s = self.queue[next] as usize;
            next += 1;
            let hop = self.reached[s];
            {
                let wanted = if hop > 0 || self.itself[s] {
                    heat * HOP_FALLOFF.powi(hop as i32)
                } else {
                    coasting
                };
                let host = world.host_at_mut(s);
                if wanted > host.heat {
                    host.heat = wanted;
                }
                let body = world.body_at_mut(s);
                if body.is_dynamic() && body.is_sleeping() {
                    body.wake_up(true);
                }
            }
            if hop >= hops || (hop == 0 && !self.spreads[s]) {
                continue;
            }
            for k in self.offsets[s]..self.offsets[s + 1] {
                let m = self.neighbours[k as usize] as usize;
                if self.reached[m] == u32::MAX {
                    self.reached[m] = hop + 1;
                    self.queue.push(m as u32);
                }
            }
        }
    }

    /// The world's joints as neighbour lists by slot, rebuilt when the world changed.
    fn index<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>) {
        if self.version == Some(world.version()) {
            return;
        }
        let n = world.slot_count();
        self.offsets.clear();
        self.offsets.resize(n + 1, 0);
        for (a, b) in world.joint_ends() {
            self.offsets[a + 1] += 1;
            self.offsets[b + 1] += 1;
        }
        for s in 0..n {
            self.offsets[s + 1] += self.offsets[s];
        }
        self.neighbours.clear();
        self.neighbours.resize(self.offsets[n] as usize, 0);
        let mut fill = self.offsets.clone();
        for (a, b) in world.joint_ends() {
            self.neighbours[fill[a] as usize] = b as u32;
            fill[a] += 1;
            self.neighbours[fill[b] as usize] = a as u32;
            fill[b] += 1;
        }
        self.version = Some(world.version());
    }
}
