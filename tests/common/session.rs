//! The host session grammar shared by the random-session tests and the fuzz target:
//! host actions, how a host applies them, and the invariants checked after every call.
//! Each check returns the first broken invariant as a message.
#![allow(dead_code)]

use std::collections::{HashMap, HashSet};

use graph_canvas_layout::config::EdgeWeight;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::scene::{AxisLock, Cluster};
use graph_canvas_layout::{
    CanvasNode, CanvasSceneInput, Constraint, DeltaMap, EdgeJoint, Layout, LayoutSnapshot,
    NodeForces, RapierLayout, RapierLayoutConfig, MAX_COORDINATE,
};

use super::{edge, node, Host, FRAME};

/// One call's deltas as `(id, x bits, y bits)`, sorted by id.
pub type DeltaBits = Vec<(u32, u32, u32)>;

/// `Err` with the message unless `cond` holds.
macro_rules! ensure {
    ($cond:expr, $($msg:tt)+) => {
        let holds: bool = $cond;
        if !holds {
            return Err(format!($($msg)+));
        }
    };
}

/// `Err` with both values and the message unless they are equal.
macro_rules! ensure_eq {
    ($a:expr, $b:expr) => {
        ensure_eq!($a, $b, "")
    };
    ($a:expr, $b:expr, $($msg:tt)+) => {
        let (a, b) = (&$a, &$b);
        if a != b {
            return Err(format!("{:?} != {:?}: {}", a, b, format!($($msg)+)));
        }
    };
}

#[derive(Clone, Debug)]
pub enum Action {
    AddNode(u32, f32, f32),
    /// A node added under the pointer: dragged from its first call.
    AddDragged(u32, f32, f32),
    RemoveNode(u32),
    AddEdge(u32, u32),
    RemoveEdge(usize),
    Pin(u32),
    Unpin(u32),
    DragStart(u32),
    DragTo(u32, f32, f32),
    DragEnd(u32),
    HostMove(u32, f32, f32),
    Poison(u32),
    /// A quick drag and release: three calls moving the node by the vector each.
    Throw(u32, f32, f32),
    /// Sets the weight of edge `i % edges` (if any): any value, bad ones too.
    Weigh(usize, f32),
    /// Sets a node's forces (targets, group, lock; bad values too), or clears them when
    /// they are the default.
    Force(u32, NodeForces),
    /// Makes a node a box of width × height with that corner radius (any values, bad
    /// ones too), or a disk again when width and height are both 0.
    Reshape(u32, f32, f32, f32),
    /// Adds a hard constraint (bad ones too: a node the scene lacks, a bad gap); past
    /// eight, the oldest goes.
    Constrain(Constraint<u32>),
    /// The host drops every constraint.
    Unconstrain,
    /// Adds a cluster (bad ones too: a node the scene lacks, a bad padding, a parent out
    /// of range or in a cycle); past four, the oldest goes.
    Group(Cluster<u32>),
    /// The host drops every cluster.
    Ungroup,
    /// Calls at 1/60 s until the layout rests (at most 600).
    Settle,
    /// The host saves the layout and carries on with it restored from the save (a
    /// snapshot through JSON) in a [`run_resuming`]; nothing in a [`run`].
    Resume,
    Step(f32),
}

/// Applies a host action to the scene (not a step).
pub fn apply_action(host: &mut Host<u32>, action: &Action) {
    let has = |host: &Host<u32>, id: u32| host.scene.nodes.iter().any(|n| n.id == id);
    match *action {
        Action::AddNode(id, x, y) => {
            if !has(host, id) {
                host.scene.nodes.push(node(id, x, y));
            }
        }
        Action::AddDragged(id, x, y) => {
            if !has(host, id) {
                host.scene.nodes.push(node(id, x, y));
                host.extras.dragging.insert(id);
            }
        }
        Action::RemoveNode(id) => {
            host.scene.nodes.retain(|n| n.id != id);
            host.scene
                .edges
                .retain(|e| e.source != id && e.target != id);
        }
        Action::AddEdge(a, b) => {
            if has(host, a) && has(host, b) {
                host.scene.edges.push(edge(a, b));
            }
        }
        Action::RemoveEdge(i) => {
            if i < host.scene.edges.len() {
                host.scene.edges.remove(i);
            }
        }
        Action::Pin(id) => {
            host.extras.pinned.insert(id);
        }
        Action::Unpin(id) => {
            host.extras.pinned.remove(&id);
        }
        Action::DragStart(id) => {
            host.extras.dragging.insert(id);
        }
        Action::DragTo(id, dx, dy) => {
            if host.extras.dragging.contains(&id) && has(host, id) {
                let p = host.pos(&id);
                if p.x.is_finite() && p.y.is_finite() {
                    host.set_pos(&id, p + Vector2D::new(dx, dy));
                }
            }
        }
        Action::DragEnd(id) => {
            host.extras.dragging.remove(&id);
        }
        Action::HostMove(id, x, y) => {
            if has(host, id) {
                host.set_pos(&id, Point2D::new(x, y));
            }
        }
        Action::Poison(id) => {
            if has(host, id) {
                host.set_pos(&id, Point2D::new(f32::NAN, 0.0));
            }
        }
        Action::Weigh(i, weight) => {
            let count = host.scene.edges.len();
            if count > 0 {
                host.scene.edges[i % count].weight = weight;
            }
        }
        Action::Force(id, forces) => {
            if forces == NodeForces::default() {
                host.extras.forces.remove(&id);
            } else {
                host.extras.forces.insert(id, forces);
            }
        }
        Action::Reshape(id, width, height, corner) => {
            if let Some(n) = host.scene.nodes.iter_mut().find(|n| n.id == id) {
                *n = if width == 0.0 && height == 0.0 {
                    n.clone().with_disk()
                } else {
                    n.clone().with_rounded_rect(width, height, corner)
                };
            }
        }
        Action::Constrain(ref c) => {
            if host.extras.constraints.len() >= 8 {
                host.extras.constraints.remove(0);
            }
            host.extras.constraints.push(c.clone());
        }
        Action::Unconstrain => host.extras.constraints.clear(),
        Action::Group(ref c) => {
            if host.extras.clusters.len() >= 4 {
                host.extras.clusters.remove(0);
            }
            host.extras.clusters.push(c.clone());
        }
        Action::Ungroup => host.extras.clusters.clear(),
        Action::Throw(..) | Action::Settle | Action::Resume | Action::Step(_) => {}
    }
}

/// Every dragged node moves by (3, −2) per call, as a pointer held in motion would.
pub fn move_dragged(host: &mut Host<u32>) {
    for n in &mut host.scene.nodes {
        if host.extras.dragging.contains(&n.id) && n.position.x.is_finite() {
            n.position += Vector2D::new(3.0, -2.0);
        }
    }
}

/// Fixes any poisoned node some frames later, as a host would.
pub fn heal(scene: &mut CanvasSceneInput<u32>) {
    for n in &mut scene.nodes {
        if !(n.position.x.abs() <= MAX_COORDINATE && n.position.y.abs() <= MAX_COORDINATE) {
            n.position = Point2D::new(n.id as f32 * 10.0, 0.0);
        }
    }
}

/// The invariants a host relies on, checked after every call.
pub fn check(
    host: &Host<u32>,
    before: &CanvasSceneInput<u32>,
    deltas: &DeltaMap<u32>,
) -> Result<(), String> {
    // What the layout takes as a usable position.
    let valid = |p: Point2D<f32>| p.x.abs() <= MAX_COORDINATE && p.y.abs() <= MAX_COORDINATE;
    // A node the layout models this call: a usable position and shape.
    let usable = |n: &CanvasNode<u32>| valid(n.position) && n.shape.is_valid();
    let ids: HashSet<u32> = before.nodes.iter().map(|n| n.id).collect();
    let bounds = host.layout.cluster_bounds();
    ensure_eq!(
        bounds.len(),
        host.extras.clusters.len(),
        "a box for every listed cluster"
    );
    for (c, b) in bounds.iter().enumerate() {
        let corners = [b.min.x, b.min.y, b.max.x, b.max.y];
        ensure!(
            corners.iter().all(|v| v.is_finite()) && b.min.x <= b.max.x && b.min.y <= b.max.y,
            "cluster {c}: box {b:?} is not a finite box"
        );
    }
    for (id, d) in deltas {
        ensure!(
            d.x.is_finite() && d.y.is_finite(),
            "node {id}: non-finite delta {d:?}"
        );
        ensure!(
            ids.contains(id),
            "delta for node {id}, which is not in the scene"
        );
        ensure!(
            !host.extras.pinned.contains(id),
            "delta for pinned node {id}: {d:?}"
        );
        ensure!(
            !host.extras.dragging.contains(id),
            "delta for dragged node {id}: {d:?}"
        );
        let n = before.nodes.iter().find(|n| n.id == *id).unwrap();
        ensure!(
            usable(n),
            "delta {d:?} for node {id} whose position {:?} or shape {:?} is unusable",
            n.position,
            n.shape
        );
    }
    let Some(world) = host.layout.world() else {
        ensure!(before.nodes.is_empty(), "no world for a non-empty scene");
        return Ok(());
    };
    // World and scene agree on the node set (nodes with usable values, plus bodies kept
    // for nodes whose values are unusable right now).
    for n in &before.nodes {
        if usable(n) {
            ensure!(
                world.contains_node(&n.id),
                "scene node {} has no body",
                n.id
            );
        }
    }
    for id in world.node_ids() {
        ensure!(ids.contains(id), "body for node {id}, which left the scene");
    }
    ensure_eq!(world.body_count(), world.node_ids().count());
    let (constraints, edges) = (host.extras.constraints.len(), host.scene.edges.len());
    for &c in host.layout.violated_constraints() {
        ensure!(c < constraints, "violated constraint {c} of {constraints}");
    }
    for &e in host
        .layout
        .flow_exempt_edges()
        .iter()
        .chain(host.layout.violated_flow_edges())
    {
        ensure!(e < edges, "flow edge {e} reported of {edges}");
    }
    check_joints(host, before)?;
    for n in &host.scene.nodes {
        if !usable(n) {
            continue;
        }
        let w = world.get_position(&n.id).unwrap();
        ensure!(valid(w), "node {}: body at {:?}", n.id, w);
        if host.extras.dragging.contains(&n.id) || host.extras.pinned.contains(&n.id) {
            ensure_eq!(
                w,
                n.position,
                "held node {} is not where the host put it",
                n.id
            );
        } else {
            // A locked axis does not move (beyond what the report threshold still owes).
            let lock = host.extras.forces.get(&n.id).and_then(|f| f.lock);
            if let (Some(axis), Some(d)) = (lock, deltas.get(&n.id)) {
                let along = match axis {
                    AxisLock::X => d.x,
                    AxisLock::Y => d.y,
                };
                ensure!(
                    along.abs() <= 1e-3,
                    "node {} locked on {axis:?} moved {along} along it",
                    n.id
                );
            }
            // Deltas sum to the world's positions: the host's position after applying
            // them is the body's, up to rounding and the 1e-4 report threshold. The
            // host's f32 addition `old + delta` rounds at the larger operand's scale: a
            // node the first call brings from 87,381 units out to 166 lands within
            // half an ulp of 87,381 (0.004), not of 166.
            let old = before
                .nodes
                .iter()
                .find(|b| b.id == n.id)
                .map_or(Point2D::origin(), |b| b.position);
            let largest = |p: Point2D<f32>| p.x.abs().max(p.y.abs());
            let scale = 1.0 + largest(n.position).max(largest(old));
            let gap = (w - n.position).length();
            ensure!(
                gap <= 1e-3 + scale * 4.0 * f32::EPSILON,
                "node {}: host {:?} vs body {:?} ({gap})",
                n.id,
                n.position,
                w
            );
        }
    }
    Ok(())
}

/// Every modelled edge has the joint the configuration gives it; with degree-scaled
/// springs, the share its ends' current degrees give it, however the topology got there.
pub fn check_joints(host: &Host<u32>, before: &CanvasSceneInput<u32>) -> Result<(), String> {
    let world = host.layout.world().expect("a world");
    let config = &host.layout.config;
    ensure_eq!(
        config.springs.weight,
        EdgeWeight::Strength,
        "the checker knows strengths"
    );
    // Each modelled pair with the weight of its first occurrence (bad weights count as 0).
    let mut weight_of: HashMap<(u32, u32), f32> = HashMap::new();
    for e in &before.edges {
        if e.source != e.target && world.contains_node(&e.source) && world.contains_node(&e.target)
        {
            let usable = if e.weight.is_finite() && e.weight >= 0.0 {
                e.weight
            } else {
                0.0
            };
            weight_of
                .entry((e.source.min(e.target), e.source.max(e.target)))
                .or_insert(usable);
        }
    }
    let mut pairs: Vec<(u32, u32)> = weight_of.keys().copied().collect();
    pairs.sort_unstable();
    let mut degree: HashMap<u32, u32> = HashMap::new();
    for &(a, b) in &pairs {
        *degree.entry(a).or_default() += 1;
        *degree.entry(b).or_default() += 1;
    }
    for &(a, b) in &pairs {
        let expected = match config.edge_joint {
            EdgeJoint::None => None,
            EdgeJoint::Spring {
                rest_length,
                stiffness,
                damping,
            } if config.springs.degree_exponent > 0.0 => {
                let share =
                    (degree[&a].min(degree[&b]) as f32).powf(config.springs.degree_exponent);
                Some(EdgeJoint::Spring {
                    rest_length,
                    stiffness: stiffness / share,
                    damping: damping / share,
                })
            }
            kind => Some(kind),
        };
        // Weighted: strength times the weight, no joint at weight 0.
        let weight = weight_of[&(a, b)];
        let expected = expected.filter(|_| weight > 0.0).map(|kind| match kind {
            EdgeJoint::Spring {
                rest_length,
                stiffness,
                damping,
            } => EdgeJoint::Spring {
                rest_length,
                stiffness: stiffness * weight,
                damping: damping * weight,
            },
            EdgeJoint::Rope {
                max_length,
                stiffness,
            } => EdgeJoint::Rope {
                max_length,
                stiffness: stiffness * weight,
            },
            kind => kind,
        });
        ensure_eq!(
            world.edge_joint(&a, &b),
            expected,
            "edge {}-{} (degrees {}, {})",
            a,
            b,
            degree[&a],
            degree[&b]
        );
    }
    let weighted = pairs.iter().filter(|p| weight_of[p] > 0.0).count();
    ensure_eq!(
        world.joint_count(),
        if config.edge_joint == EdgeJoint::None {
            0
        } else {
            weighted
        },
        "joints for {} modelled edges ({} of positive weight)",
        pairs.len(),
        weighted
    );
    Ok(())
}

/// One call of `dt` seconds, checked, its deltas logged.
pub fn call(host: &mut Host<u32>, dt: f32, log: &mut Vec<DeltaBits>) -> Result<(), String> {
    move_dragged(host);
    let before = host.scene.clone();
    let deltas = host.frame(dt);
    check(host, &before, &deltas)?;
    let mut row: Vec<(u32, u32, u32)> = deltas
        .iter()
        .map(|(id, d)| (*id, d.x.to_bits(), d.y.to_bits()))
        .collect();
    row.sort_unstable();
    log.push(row);
    Ok(())
}

/// Runs `actions` on a new layout under `config`, checking every call; returns every
/// call's deltas. [`Action::Resume`] does nothing.
pub fn run(config: &RapierLayoutConfig, actions: &[Action]) -> Result<Vec<DeltaBits>, String> {
    run_with(config, actions, false)
}

/// [`run`], with the layout saved through JSON and restored into a new one at every
/// [`Action::Resume`]: the deltas must be the same bit for bit.
pub fn run_resuming(
    config: &RapierLayoutConfig,
    actions: &[Action],
) -> Result<Vec<DeltaBits>, String> {
    run_with(config, actions, true)
}

/// `layout` saved as a JSON snapshot and restored into a new layout.
pub fn resumed(layout: &RapierLayout<u32>) -> Result<RapierLayout<u32>, String> {
    let json = serde_json::to_string(&layout.snapshot()).map_err(|e| format!("save: {e}"))?;
    let snapshot: LayoutSnapshot<u32> =
        serde_json::from_str(&json).map_err(|e| format!("read back: {e}"))?;
    let mut restored = RapierLayout::default();
    restored
        .restore(snapshot)
        .map_err(|e| format!("restore: {e}"))?;
    Ok(restored)
}

fn run_with(
    config: &RapierLayoutConfig,
    actions: &[Action],
    resume: bool,
) -> Result<Vec<DeltaBits>, String> {
    let mut host = Host::new(CanvasSceneInput::default(), config.clone());
    let mut log = Vec::new();
    let mut since_poison = 0;
    for action in actions {
        apply_action(&mut host, action);
        since_poison += 1;
        if matches!(action, Action::Poison(_)) {
            since_poison = 0;
        }
        if since_poison == 6 {
            heal(&mut host.scene);
        }
        match *action {
            Action::Step(dt) => call(&mut host, dt, &mut log)?,
            Action::Throw(id, dx, dy) => {
                if !host
                    .scene
                    .nodes
                    .iter()
                    .any(|n| n.id == id && n.position.x.is_finite())
                {
                    continue;
                }
                host.extras.dragging.insert(id);
                for _ in 0..3 {
                    let p = host.pos(&id);
                    host.set_pos(&id, p + Vector2D::new(dx, dy));
                    call(&mut host, FRAME, &mut log)?;
                }
                host.extras.dragging.remove(&id);
                call(&mut host, FRAME, &mut log)?;
            }
            Action::Resume if resume => host.layout = resumed(&host.layout)?,
            Action::Settle => {
                for _ in 0..600 {
                    call(&mut host, FRAME, &mut log)?;
                    if host.layout.is_converged(&host.state) {
                        break;
                    }
                }
            }
            _ => {}
        }
    }
    Ok(log)
}
