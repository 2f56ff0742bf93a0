//! Changes a caller vouches for. A host that hands [`Layout::step`](crate::Layout) its
//! scene is matched and synced node by node each call, since any node may have changed;
//! a caller that owns the scene and applies every change itself (the worker,
//! `worker/thread.rs`) knows which nodes it changed, and lists them. A large settled
//! graph under a drag then costs a call what the listed nodes cost, where matching and
//! syncing every node (O(n) a call) was a large share of it (`docs/performance.md`, A
//! layout on its own thread, gives it).
//!
//! The promise a list makes ([`RapierLayout::step_known`]): since the last call, the
//! scene kept its node ids, their order and its edges, `extras` kept its pins and
//! per-node forces, and no node changed but the listed ones, apart from the last call's
//! deltas added to the positions (with the same f32 addition). Every dragged and every
//! pinned node is listed. Debug builds (the tests) check the promise on every call
//! against what the full pass would do.

use std::hash::Hash;

use super::RapierLayout;
use crate::config::BodyKindPolicy;
use crate::input::layout::{DeltaMap, LayoutExtras};
use crate::input::scene::CanvasSceneInput;
use crate::input::validation::node_is_valid;
use crate::RapierLayoutState;

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// [`Layout::step`](crate::Layout::step) for a caller that owns `scene` and lists
    /// the nodes it changed since the last call (`changed`: scene indices, ascending and
    /// each once), under the promise of this module's docs. The call matches and syncs
    /// only the listed nodes when the last call's matches can stand for this call's;
    /// otherwise (the first call, a rebuild, a node left out, a listed node unusable or
    /// re-pinned) it does what `step` does.
    pub(crate) fn step_known(
        &mut self,
        scene: &CanvasSceneInput<N>,
        state: &mut RapierLayoutState,
        dt: f32,
        extras: &LayoutExtras<N>,
        changed: &[usize],
    ) -> DeltaMap<N> {
        self.advance(scene, state, dt, extras, Some(changed))
    }

    /// Whether the last call's matches stand for this call's, the listed nodes checked:
    /// every node matched and usable, the edges known, no node held by the policy, and
    /// every listed node still usable, with its pin and its body's id.
    pub(super) fn rematch_known(
        &self,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
        changed: &[usize],
    ) -> bool {
        let Some(world) = self.world.as_ref() else {
            return false;
        };
        let matches = self.matching.matches();
        let trusted = matches.len() == scene.nodes.len()
            && self.matching.bad_nodes == 0
            && self.built.topology_hash != 0
            && self.matching.knows_edges()
            && self.config.body_kind_policy != BodyKindPolicy::AllKinematic;
        trusted
            && changed.iter().all(|&i| {
                let (Some(node), Some(m)) = (scene.nodes.get(i), matches.get(i)) else {
                    return false;
                };
                let s = m.slot as usize;
                s < world.slot_count()
                    && *world.id_at(s) == node.id
                    && node_is_valid(node)
                    && m.valid
                    && m.pinned == extras.pinned.contains(&node.id)
            })
    }
}

/// Debug builds: every node the list left out is one the full pass would leave as it
/// is (matched as before, its shape unchanged, free, synced, and where it was told), so
/// skipping it changed nothing.
#[cfg(debug_assertions)]
pub(super) fn check_unlisted<N: Clone + Eq + Hash>(
    world: &crate::world::RapierSceneWorld<N>,
    config: &crate::RapierLayoutConfig,
    scene: &CanvasSceneInput<N>,
    extras: &LayoutExtras<N>,
    matches: &[super::matching::NodeMatch],
    listed: &[usize],
) {
    let mut next = listed.iter().copied().peekable();
    for (i, (node, m)) in scene.nodes.iter().zip(matches).enumerate() {
        if next.peek() == Some(&i) {
            next.next();
            continue;
        }
        let s = m.slot as usize;
        let sync = world.host_at(s);
        let shape = super::edits::shape_of(config, node);
        let free = super::sync_in::desired_type(
            config.body_kind_policy,
            m.valid,
            m.pinned,
            extras.dragging.contains(&node.id),
        ) == Some(rapier2d::prelude::RigidBodyType::Dynamic);
        let untouched = world.slot_of(&node.id) == Some(s)
            && m.valid == node_is_valid(node)
            && m.pinned == extras.pinned.contains(&node.id)
            && super::sync_in::same_spec(world.shape_at(s), shape)
            && free
            && sync.synced
            && sync.told == node.position
            && world.anchor_at(s) == node.position;
        assert!(
            untouched,
            "the caller's list of changed nodes left out scene node {i} (slot {s}), which \
             the full sync would change: valid {} pinned {} free {free} synced {} told \
             {:?} anchor {:?} at {:?}",
            m.valid,
            m.pinned,
            sync.synced,
            sync.told,
            world.anchor_at(s),
            node.position
        );
    }
}

#[cfg(test)]
mod tests {
    use euclid::default::{Point2D, Vector2D};

    use crate::{
        CanvasEdge, CanvasNode, CanvasSceneInput, CanvasViewport, DeltaMap, Layout, LayoutExtras,
        RapierLayout, RapierLayoutConfig, RapierLayoutState,
    };

    const FRAME: f32 = 1.0 / 60.0;

    /// A ring of 120 nodes with chords seven apart, on a spiral.
    fn scene() -> CanvasSceneInput<u32> {
        let n = 120_u32;
        let nodes = (0..n)
            .map(|i| {
                let (angle, r) = (i as f32 * 2.4, 12.0 * (i as f32).sqrt());
                CanvasNode::new(i, Point2D::new(r * angle.cos(), r * angle.sin()))
            })
            .collect();
        let edges = (0..n)
            .flat_map(|i| {
                [
                    CanvasEdge::new(i, (i + 1) % n),
                    CanvasEdge::new(i, (i + 7) % n),
                ]
            })
            .collect();
        CanvasSceneInput::new(nodes, edges)
    }

    /// What the host does at frame `k`: drags node 5 over frames 30–40 and lets go, moves
    /// node 9 at frame 60, makes node 11 a label box at frame 80, and drags node 5 again
    /// over frames 400–410, once the layout rests; node 20 is pinned throughout. Returns
    /// the scene indices it changed.
    fn host_frame(
        k: usize,
        scene: &mut CanvasSceneInput<u32>,
        extras: &mut LayoutExtras<u32>,
    ) -> Vec<usize> {
        match k {
            30..=40 | 400..=410 => {
                extras.dragging.insert(5);
                scene.nodes[5].position += Vector2D::new(12.0, -5.0);
                vec![5]
            }
            41 | 411 => {
                extras.dragging.remove(&5);
                vec![5]
            }
            60 => {
                scene.nodes[9].position += Vector2D::new(80.0, 0.0);
                vec![9]
            }
            80 => {
                scene.nodes[11] = scene.nodes[11].clone().with_rect(60.0, 20.0);
                vec![11]
            }
            _ => Vec::new(),
        }
    }

    fn bits(deltas: &DeltaMap<u32>) -> Vec<(u32, u32, u32)> {
        let mut out: Vec<_> = deltas
            .iter()
            .map(|(&id, d)| (id, d.x.to_bits(), d.y.to_bits()))
            .collect();
        out.sort_unstable();
        out
    }

    /// A caller that lists what it changed gets the same deltas, bit for bit, as a host
    /// whose whole scene is matched and synced every call, through drags, a throw, a host
    /// move, a reshape, a pin and a drag that wakes the layout at rest, under both
    /// layout presets.
    #[test]
    fn a_list_of_changes_steps_as_the_full_sync_does() {
        for (name, config) in [
            ("force_directed", RapierLayoutConfig::force_directed()),
            ("stress", RapierLayoutConfig::stress()),
        ] {
            let (mut full, mut listed) =
                (RapierLayout::new(config.clone()), RapierLayout::new(config));
            let (mut full_state, mut listed_state) =
                (RapierLayoutState::default(), RapierLayoutState::default());
            let (mut full_scene, mut listed_scene) = (scene(), scene());
            let mut extras = LayoutExtras::default();
            extras.pinned.insert(20);
            let mut moved = 0;
            for k in 0..520 {
                if k == 400 {
                    assert!(
                        full.is_converged(&full_state) && listed.is_converged(&listed_state),
                        "{name}: both layouts rest before the second drag"
                    );
                }
                host_frame(k, &mut full_scene, &mut extras.clone());
                let mut changed = host_frame(k, &mut listed_scene, &mut extras);
                changed.push(20);
                changed.extend(extras.dragging.iter().map(|&id| id as usize));
                changed.sort_unstable();
                changed.dedup();
                let viewport = CanvasViewport::default();
                let a = full.step(&full_scene, &mut full_state, FRAME, &viewport, &extras);
                let b =
                    listed.step_known(&listed_scene, &mut listed_state, FRAME, &extras, &changed);
                full_scene.apply_deltas(&a);
                listed_scene.apply_deltas(&b);
                let (a, b) = (bits(&a), bits(&b));
                assert!(
                    a == b,
                    "{name}, frame {k}: {} deltas in full, {} with the list; first differing: {:?}",
                    a.len(),
                    b.len(),
                    a.iter().zip(&b).find(|(x, y)| x != y)
                );
                moved += a.len();
            }
            assert!(
                moved > 1_000,
                "{name}: the session moved nodes ({moved} deltas)"
            );
        }
    }
}
