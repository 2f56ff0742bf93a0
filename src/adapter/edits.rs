//! Topology edits: when the scene's nodes, edges or pins differ from the world's, the
//! world is patched in place (untouched bodies keep their motion) or, by configuration
//! or on the first call, built from scratch. Nodes are inserted in scene order and
//! joints in edge order, so the same session builds the same world.

use std::collections::{HashMap, HashSet};
use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};

use super::seating::Seating;
use super::RapierLayout;
use crate::clusters::Clusters;
use crate::config::{BodyKindPolicy, EdgeJoint, RapierLayoutConfig, SpringModel, TopologyUpdate};
use crate::constraints::Compiled;
use crate::input::layout::{IdHasher, LayoutExtras};
use crate::input::scene::{CanvasNode, CanvasSceneInput};
use crate::input::topology::Topology;
use crate::input::validation::node_is_valid;
use crate::stress::{start_world, StartConstraints, WorldOrigin};
use crate::world::bindings::{ColliderSpec, NodeAvatarBinding, SceneBodyKind};
use crate::world::nodes::body_mass;
use crate::world::rapier_joint::scaled_spring;
use crate::world::RapierSceneWorld;

/// Partings of the clusters' levels after each descent pass of a start layout, at most.
const START_ROUNDS: usize = 8;

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// Brings the world's topology to the scene's. Returns whether the world's structure
    /// changed (a disturbance).
    pub(super) fn sync_topology(
        &mut self,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
    ) -> bool {
        let Some(topology) = self.candidate_topology(scene, extras) else {
            return false;
        };
        // Counted here, with the edges the next call compares against (not by
        // `topology_changed`, which may look at another scene).
        self.matching.topology_problems = topology.problems;
        self.matching.remember_edges(scene);
        let same_edges = topology.hash == self.built.topology_hash;
        if self.world.is_some() && same_edges && topology.weight_hash == self.built.weight_hash {
            return false;
        }
        let rebuild = self.config.topology_update == TopologyUpdate::Rebuild && !same_edges;
        if self.world.is_none() || rebuild || self.built.start_again {
            self.build_world(scene, extras, &topology);
        } else {
            // Also a weight edit alone: its joints are re-tuned in place.
            self.patch_world(scene, extras, &topology);
        }
        self.built.topology_hash = topology.hash;
        self.built.weight_hash = topology.weight_hash;
        if let Some(world) = self.world.as_mut() {
            world.set_topology_hash(topology.hash);
        }
        // The slots moved: match again.
        self.match_nodes(scene, extras);
        true
    }

    /// A new world for `topology`. Nodes whose values are unusable this call keep their
    /// old body's position, and drags in progress survive, so a release still throws.
    fn build_world(
        &mut self,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
        topology: &Topology,
    ) {
        // The first world, or one that starts anew as the first did.
        let again = std::mem::take(&mut self.built.start_again);
        let first = self.built.rebuilds == 0 || again;
        let mut world = RapierSceneWorld::with_options(self.world_options());
        world.set_timestep(self.built.joint_dt);
        world.set_springs_as_forces(self.config.springs.model == SpringModel::Forces);
        // A new world counts its versions from 0 again.
        self.forces.reset();
        // Contacts stay out of the first unfolding until the heat lets them in.
        world.set_contacts_enabled(!(self.heat.state.unfolding || first));
        insert_missing_nodes(
            &mut world,
            scene,
            topology,
            &self.config,
            Placement::Build(self.world.as_ref()),
            &mut Vec::new(),
        );
        // NOTE: before the joints, which rest at the hop length it chooses.
        let origin = WorldOrigin {
            previous_hop: self.world.as_ref().and_then(RapierSceneWorld::hop_length),
            first,
            cold_start: self.built.cold_start && !again,
        };
        // The start holds the constraints as it descends.
        let mut held = Compiled::default();
        held.sync(self.config.flow, scene, extras, &world, (u64::MAX, 0));
        let mut boxed = Clusters::for_start(&extras.clusters, &world);
        let any = !held.is_empty() || !boxed.is_empty();
        let passes = self.config.solver.constraint_passes();
        let mut hold = |xy: &mut [[f32; 2]], unit: f32| {
            boxed.project_points(xy, unit, START_ROUNDS);
            held.project_points(xy, unit, passes);
        };
        let model = self.config.stress.map(|stress| {
            let constraints = StartConstraints {
                hold: &mut hold,
                any,
            };
            start_world(
                stress,
                origin,
                &mut world,
                (scene, topology, extras),
                constraints,
            )
        });
        let degrees = topology.degrees(scene.nodes.len());
        insert_joints(
            &mut world,
            scene,
            topology,
            &degrees,
            &self.config,
            |_, _| {},
        );
        if let (Some(model), Some(stress)) = (model, self.config.stress) {
            let pivots = stress.pivot_count(world.slot_count());
            self.forces
                .stress_mut()
                .adopt(&world, model, pivots, stress.exact_hops.max(1));
        }
        // A new world starts again: every body at rest where the host has it.
        self.heat.spread.reset();
        self.heat.spread.touch_everything();
        self.world = Some(world);
        self.built.applied = Some(self.config.clone());
        if first {
            // Later builds are disturbances: they reheat.
            self.heat.state.alpha = 1.0;
            self.heat.state.unfolding = true;
        }
        self.built.rebuilds += 1;
    }

    /// Inserts and removes only what changed; untouched bodies keep their motion.
    fn patch_world(
        &mut self,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
        topology: &Topology,
    ) {
        let config = &self.config;
        let Some(world) = self.world.as_mut() else {
            return;
        };
        // Removals, in the world's own (deterministic) slot order.
        let mut keep: HashSet<&N, IdHasher> =
            HashSet::with_capacity_and_hasher(topology.nodes.len(), IdHasher::default());
        keep.extend(topology.nodes.iter().map(|&i| &scene.nodes[i].id));
        let gone: Vec<N> = world
            .node_ids()
            .filter(|id| !keep.contains(id))
            .cloned()
            .collect();
        // What the edit touches: the neighbours of removed nodes, new nodes, and the
        // ends of edges that came or went.
        let mut touched: Vec<N> = Vec::new();
        if !gone.is_empty() {
            let leaving: HashSet<&N, IdHasher> = gone.iter().collect();
            for (a, b) in world.joint_ends() {
                let (ia, ib) = (world.id_at(a), world.id_at(b));
                match (leaving.contains(ia), leaving.contains(ib)) {
                    (true, false) => touched.push(ib.clone()),
                    (false, true) => touched.push(ia.clone()),
                    _ => {}
                }
            }
        }
        for id in &gone {
            world.remove_node(id);
        }
        world.set_timestep(self.built.joint_dt);
        // Pinned and dragged nodes go where the host puts them.
        let held = |id: &N| {
            config.body_kind_policy == BodyKindPolicy::AllKinematic
                || extras.pinned.contains(id)
                || extras.dragging.contains(id)
        };
        let mut inserted = Vec::new();
        insert_missing_nodes(
            world,
            scene,
            topology,
            config,
            Placement::Patch(None, &held),
            &mut inserted,
        );
        touched.extend(
            inserted
                .iter()
                .filter(|(_, seated)| !seated)
                .map(|(id, _)| id.clone()),
        );
        // Joints: drop those whose edge went away, add the new ones.
        let index_of: HashMap<&N, usize, IdHasher> = topology
            .nodes
            .iter()
            .map(|&i| (&scene.nodes[i].id, i))
            .collect();
        let weight_of: HashMap<(usize, usize), f32, IdHasher> = topology
            .edges
            .iter()
            .zip(&topology.weights)
            .map(|(&(a, b), &w)| ((a.min(b), a.max(b)), w))
            .collect();
        world.retain_edge_joints(|a, b| {
            let kept = match (index_of.get(a), index_of.get(b)) {
                (Some(&x), Some(&y)) => weight_of.contains_key(&(x.min(y), x.max(y))),
                _ => false,
            };
            if !kept {
                touched.extend([a.clone(), b.clone()]);
            }
            kept
        });
        let degrees = topology.degrees(scene.nodes.len());
        // A node seated beside its neighbours (its host position overlapped a disk) is
        // where it belongs already: it settles there as a coasting node does, and its
        // neighbours stay asleep where they rest. Every other edit heats its ends.
        let seated: HashSet<&N, IdHasher> = inserted
            .iter()
            .filter_map(|(id, seated)| seated.then_some(id))
            .collect();
        insert_joints(world, scene, topology, &degrees, config, |a, b| {
            for (end, other) in [(a, b), (b, a)] {
                if !seated.contains(end) && !seated.contains(other) {
                    touched.push(end.clone());
                }
            }
        });
        let weight = |a: &N, b: &N| match (index_of.get(a), index_of.get(b)) {
            (Some(&x), Some(&y)) => weight_of.get(&(x.min(y), x.max(y))).copied(),
            _ => None,
        };
        // A weight edit touches the edge's ends.
        world.update_joint_weights(
            |a, b| weight(a, b).unwrap_or(1.0),
            |a, b| touched.extend([a.clone(), b.clone()]),
        );
        // Springs whose ends changed degree take their new share, and edges whose weight
        // changed their new strength or length.
        let hop = world.hop_length();
        world.retune_edge_joints(|a, b| match (index_of.get(a), index_of.get(b)) {
            (Some(&x), Some(&y)) => edge_joint_for(
                config,
                hop,
                degrees[x],
                degrees[y],
                weight(a, b).unwrap_or(1.0),
            ),
            _ => config.edge_joint,
        });
        // In scene order (never the set's): wakes reach rapier in this order.
        for (id, _) in inserted.iter().filter(|(_, seated)| *seated) {
            if let Some(s) = world.slot_of(id) {
                self.heat.spread.touch_settling(s);
            }
        }
        for id in &touched {
            if let Some(s) = world.slot_of(id) {
                self.heat.spread.touch(s, true);
                // Springs applied as forces link no rapier island that would wake them.
                let body = world.body_at_mut(s);
                if body.is_dynamic() && body.is_sleeping() {
                    body.wake_up(true);
                }
            }
        }
        self.built.patches += 1;
    }
}

/// Where the bodies of new nodes start.
enum Placement<'a, N> {
    /// A new world: at the host's positions (coincident ones spread apart); a node whose
    /// values are unusable takes its position, and its drag, from the old world (and is
    /// left out without one).
    Build(Option<&'a RapierSceneWorld<N>>),
    /// Nodes added to a world in motion: seated beside their neighbours when the host's
    /// position overlaps another disk (`seating.rs`, the disks in place gathered at the
    /// first new node), unless held (pinned or dragged).
    Patch(Option<Seating>, &'a dyn Fn(&N) -> bool),
}

/// Inserts a body for every node of `topology` that `world` lacks, in scene order, where
/// `placement` says, anchored at the host's position; records each in `inserted` with
/// whether it was seated away from the host's position.
fn insert_missing_nodes<N: Clone + Eq + Hash>(
    world: &mut RapierSceneWorld<N>,
    scene: &CanvasSceneInput<N>,
    topology: &Topology,
    config: &RapierLayoutConfig,
    mut placement: Placement<'_, N>,
    inserted: &mut Vec<(N, bool)>,
) {
    let mut spread = CoincidenceSpreader::default();
    let neighbours = match placement {
        Placement::Patch(..) => new_node_neighbours(world, scene, topology),
        Placement::Build(_) => HashMap::default(),
    };
    let mut around = Vec::new();
    for &i in &topology.nodes {
        let node = &scene.nodes[i];
        if world.contains_node(&node.id) {
            continue;
        }
        let old = match placement {
            Placement::Build(old) => old,
            Placement::Patch(..) => None,
        };
        let position = if node_is_valid(node) {
            node.position
        } else {
            match old.and_then(|w| w.get_position(&node.id)) {
                Some(p) => p,
                None => continue,
            }
        };
        let (start, seated) = match &mut placement {
            Placement::Build(_) => (spread.place(position), false),
            Placement::Patch(seating, held) => {
                let seating = seating.get_or_insert_with(|| {
                    Seating::new(
                        world,
                        world
                            .hop_length()
                            .filter(|_| config.stress.is_some())
                            .unwrap_or_else(|| config.edge_length()),
                    )
                });
                if held(&node.id) {
                    seating.occupy(position, shape_of(config, node).bounding_radius());
                    (position, false)
                } else {
                    around.clear();
                    around.extend(
                        neighbours
                            .get(&i)
                            .into_iter()
                            .flatten()
                            .filter_map(|&j| world.get_position(&scene.nodes[j].id)),
                    );
                    match seating.seat(position, shape_of(config, node).bounding_radius(), &around)
                    {
                        Some(seat) => (seat, true),
                        None => (position, false),
                    }
                }
            }
        };
        let binding = binding_for(config, node);
        world.insert_node(&binding, start);
        if !matches!(binding.collider, ColliderSpec::Circle { .. }) {
            if let Some(s) = world.slot_of(&node.id) {
                world.set_mass_at(s, mass_of(config, binding.collider));
            }
        }
        world.rebase_initial_position(&node.id, position);
        inserted.push((node.id.clone(), seated));
        let before = old.and_then(|w| Some(*w.host_at(w.slot_of(&node.id)?)));
        if let (Some(before), Some(s)) = (before, world.slot_of(&node.id)) {
            // A drag in progress survives the rebuild, so its release still throws.
            let host = world.host_at_mut(s);
            host.dragging = before.dragging;
            host.drag_position = before.drag_position;
            host.drag_velocity = before.drag_velocity;
            host.drag_still = before.drag_still;
        }
    }
}

/// The neighbours (scene indices) of every node of `topology` that `world` lacks, in
/// edge order.
fn new_node_neighbours<N: Clone + Eq + Hash>(
    world: &RapierSceneWorld<N>,
    scene: &CanvasSceneInput<N>,
    topology: &Topology,
) -> HashMap<usize, Vec<usize>, IdHasher> {
    let mut neighbours: HashMap<usize, Vec<usize>, IdHasher> = HashMap::default();
    let is_new = |i: usize| !world.contains_node(&scene.nodes[i].id);
    for &(a, b) in &topology.edges {
        if is_new(a) {
            neighbours.entry(a).or_default().push(b);
        }
        if is_new(b) {
            neighbours.entry(b).or_default().push(a);
        }
    }
    neighbours
}

/// Inserts the joint of every edge of `topology` (pairs that have one are skipped) and
/// records the ends of the new ones in `ends`.
fn insert_joints<N: Clone + Eq + Hash>(
    world: &mut RapierSceneWorld<N>,
    scene: &CanvasSceneInput<N>,
    topology: &Topology,
    degrees: &[u32],
    config: &RapierLayoutConfig,
    mut joined: impl FnMut(&N, &N),
) {
    world.reserve_joints(topology.edges.len().saturating_sub(world.joint_count()));
    for (&(a, b), &weight) in topology.edges.iter().zip(&topology.weights) {
        let (ia, ib) = (&scene.nodes[a].id, &scene.nodes[b].id);
        let kind = edge_joint_for(config, world.hop_length(), degrees[a], degrees[b], weight);
        if world.insert_weighted_edge_joint(ia, ib, &kind, weight) {
            joined(ia, ib);
        }
    }
}

/// The node's radius, or the configured default for 0 (an unusable default counts
/// as 16), as the world stores it: finite and non-negative.
fn radius_of<N>(config: &RapierLayoutConfig, node: &CanvasNode<N>) -> f32 {
    if node.radius > 0.0 && node.radius.is_finite() {
        node.radius
    } else {
        default_radius(config)
    }
}

/// The configured default radius (an unusable one counts as 16).
fn default_radius(config: &RapierLayoutConfig) -> f32 {
    let default = config.default_radius;
    if default.is_finite() && default >= 0.0 {
        default
    } else {
        16.0
    }
}

/// The node's outline as the world stores it: the disk of [`radius_of`], or its box
/// (rounded where its corners are), with finite, non-negative extents.
pub(super) fn shape_of<N>(config: &RapierLayoutConfig, node: &CanvasNode<N>) -> ColliderSpec {
    node.shape.collider(radius_of(config, node))
}

/// A body's mass in the layout: a disk's `density × π r²`, a box's that of a disk of
/// the default radius, so a box throws and settles the same whatever its size.
pub(super) fn mass_of(config: &RapierLayoutConfig, shape: ColliderSpec) -> f32 {
    let density = config.material.density;
    match shape {
        ColliderSpec::Circle { .. } => body_mass(shape, density),
        _ => body_mass(
            ColliderSpec::Circle {
                radius: default_radius(config),
            },
            density,
        ),
    }
}

/// How the node's body is built: a dynamic body of the node's shape and the configured
/// material.
fn binding_for<N: Clone>(
    config: &RapierLayoutConfig,
    node: &CanvasNode<N>,
) -> NodeAvatarBinding<N> {
    NodeAvatarBinding {
        node_id: node.id.clone(),
        collider: shape_of(config, node),
        material: config.material,
        body_kind: SceneBodyKind::Dynamic,
    }
}

/// The joint `config` gives an edge of weight `weight` whose ends have `da` and `db`
/// distinct neighbours: [`RapierLayoutConfig::edge_joint`], with a spring's stiffness
/// and damping divided by `min(da, db)^exponent` and, in a stress layout, its rest
/// length the world's hop length `hop`
/// ([`Springs::degree_exponent`](crate::config::Springs::degree_exponent); unusable exponents count as 0), then
/// weighted as [`Springs::weight`](crate::config::Springs::weight) says.
fn edge_joint_for(
    config: &RapierLayoutConfig,
    hop: Option<f32>,
    da: u32,
    db: u32,
    weight: f32,
) -> EdgeJoint {
    let base = match (config.edge_joint, hop.filter(|_| config.stress.is_some())) {
        (
            EdgeJoint::Spring {
                stiffness, damping, ..
            },
            Some(rest_length),
        ) => EdgeJoint::Spring {
            rest_length,
            stiffness,
            damping,
        },
        (joint, _) => joint,
    };
    let shared = match degree_exponent(config) {
        Some(exponent) => {
            let share = (da.min(db).max(1) as f32).powf(exponent);
            scaled_spring(&base, |x| x / share)
        }
        None => base,
    };
    config.springs.weight.weigh(shared, weight)
}

/// [`Springs::degree_exponent`](crate::config::Springs::degree_exponent) when it scales anything: finite and
/// not zero.
fn degree_exponent(config: &RapierLayoutConfig) -> Option<f32> {
    let exponent = config.springs.degree_exponent;
    (exponent.is_finite() && exponent.abs() > 0.0).then_some(exponent)
}

/// Spreads nodes inserted at exactly the same position along a golden-angle spiral
/// (k-th repeat at `√k` units), so contacts get distinct normals and push the nodes
/// apart radially instead of along one arbitrary axis.
#[derive(Default)]
struct CoincidenceSpreader {
    seen: HashMap<(u32, u32), u32, IdHasher>,
}

impl CoincidenceSpreader {
    fn place(&mut self, p: Point2D<f32>) -> Point2D<f32> {
        let count = self.seen.entry((p.x.to_bits(), p.y.to_bits())).or_insert(0);
        let k = *count;
        *count += 1;
        if k == 0 {
            return p;
        }
        let angle = k as f32 * 2.399_963; // the golden angle, radians
        let r = (k as f32).sqrt();
        p + Vector2D::new(angle.cos(), angle.sin()) * r
    }
}
