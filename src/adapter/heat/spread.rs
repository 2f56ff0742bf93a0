//! Local disturbance ([`Cooling::reheat_hops`](crate::config::Cooling::reheat_hops)): what a
//! drag, a release, a host move, a pin or an edit touched this call, and the heat that
//! spreads from it along the edges (a breadth-first search over `graph.rs`), hop by
//! hop, to the nodes near it. The heat itself, and how it cools, is in `mod.rs`.

use std::hash::Hash;

use crate::graph::Graph;
use crate::world::RapierSceneWorld;

/// Each hop from what was touched is this much as hot as the one before.
const HOP_FALLOFF: f32 = 0.5;

/// The nodes touched this call and the buffers that spread their heat.
#[derive(Debug, Default)]
pub(in crate::adapter) struct Disturbances {
    /// `(slot, whether it heats itself, whether its heat spreads to its neighbours)`.
    touched: Vec<(u32, bool, bool)>,
    /// Something that reheats the whole layout happened (a configuration or gravity
    /// change, a new world).
    everything: bool,
    /// The world's joints as a graph of its slots, and the world version it is of.
    graph: Graph,
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
    pub(in crate::adapter) fn touch(&mut self, slot: usize, itself: bool) {
        self.touched.push((slot as u32, itself, true));
    }

    /// Records a node that settles where it is without heating anything: a new node
    /// seated beside its neighbours (`seating.rs`) takes the heat of a coasting node and
    /// leaves its neighbourhood asleep.
    pub(in crate::adapter) fn touch_settling(&mut self, slot: usize) {
        self.touched.push((slot as u32, false, false));
    }

    /// Records an edit of the hard constraints: the nodes in `slots` (those of the
    /// constraints added or removed) heat with their neighbourhoods. An edit that names
    /// half of the world's `slot_count` nodes or more (a flow turned on) heats it all.
    pub(in crate::adapter) fn touch_constraints(&mut self, slots: &[u32], slot_count: usize) {
        if 2 * slots.len() >= slot_count {
            self.touch_everything();
        } else {
            // A removed node's old slot may lie beyond the world now.
            let within = slots.iter().filter(|&&s| (s as usize) < slot_count);
            self.touched.extend(within.map(|&s| (s, true, true)));
        }
    }

    /// Records a disturbance of the whole layout.
    pub(in crate::adapter) fn touch_everything(&mut self) {
        self.everything = true;
    }

    /// Whether the whole layout was disturbed this call.
    pub(in crate::adapter) fn everything(&self) -> bool {
        self.everything
    }

    /// Forgets this call's disturbances.
    pub(in crate::adapter) fn clear(&mut self) {
        self.touched.clear();
        self.everything = false;
    }

    /// Forgets the neighbour lists too (the world was dropped or built anew).
    pub(in crate::adapter) fn reset(&mut self) {
        self.clear();
        self.version = None;
    }

    /// Raises the heat of every node within `hops` of what was touched to at least
    /// `heat × 1/2^hop`, and wakes it.
    pub(in crate::adapter) fn spread<N: Clone + Eq + Hash>(
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
        // A breadth-first search from every touched node at once.
        for &(slot, itself, spreads) in &self.touched {
            let s = slot as usize;
            if s < n {
                self.itself[s] |= itself;
                self.spreads[s] |= spreads;
            }
        }
        let sources = self.touched.iter().map(|t| t.0 as usize).filter(|&s| s < n);
        let spreads = &self.spreads;
        let reached = self
            .graph
            .search(sources, &mut self.reached, &mut self.queue, |s, hop| {
                hop < hops && (hop > 0 || spreads[s])
            });
        for &slot in reached {
            let s = slot as usize;
            let hop = self.reached[s];
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
    }

    /// The world's joints as a graph of its slots, built again when the world changed.
    fn index<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>) {
        if self.version != Some(world.version()) {
            self.graph = world.joint_graph();
            self.version = Some(world.version());
        }
    }
}
