//! Random host sessions (nodes and edges coming and going, pins, drags, throws, host
//! moves, bad values, odd frame times) with an invariant checker after every call, and
//! two layouts fed the same session compared bit for bit. Short sessions over every
//! configuration; long ones (hundreds of calls, drags that outlive edits and pin
//! toggles, nodes dragged as they are added, grabs of flying nodes, frame times mixing
//! tiny and capped ones, runs to rest and the halted world after it) under the default
//! and the force-directed configuration.

mod common;

use std::collections::{HashMap, HashSet};

use common::*;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::{
    CanvasSceneInput, DeltaMap, EdgeJoint, Layout, RapierLayoutConfig, TopologyUpdate,
};
use proptest::prelude::*;

const IDS: u32 = 12;

/// One call's deltas as `(id, x bits, y bits)`, sorted by id.
type DeltaBits = Vec<(u32, u32, u32)>;

#[derive(Clone, Debug)]
enum Action {
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
    /// Calls at 1/60 s until the layout rests (at most 600).
    Settle,
    Step(f32),
}

fn coordinate() -> impl Strategy<Value = f32> {
    prop_oneof![4 => -400.0_f32..400.0, 1 => Just(0.0_f32), 1 => -1e5_f32..1e5]
}

fn frame_time() -> impl Strategy<Value = f32> {
    prop_oneof![
        6 => Just(FRAME),
        2 => Just(1.0_f32 / 144.0),
        1 => Just(1.0_f32 / 30.0),
        1 => Just(0.5_f32),
        2 => 0.0_f32..0.3,
        1 => Just(0.0_f32),
        1 => Just(-1.0_f32),
        1 => Just(f32::NAN),
        1 => Just(f32::INFINITY),
        1 => Just(1e-7_f32),
        1 => Just(5.0_f32),
    ]
}

fn action() -> impl Strategy<Value = Action> {
    let id = 0..IDS;
    prop_oneof![
        3 => (id.clone(), coordinate(), coordinate()).prop_map(|(i, x, y)| Action::AddNode(i, x, y)),
        1 => id.clone().prop_map(Action::RemoveNode),
        3 => (id.clone(), id.clone()).prop_map(|(a, b)| Action::AddEdge(a, b)),
        1 => (0usize..40).prop_map(Action::RemoveEdge),
        1 => id.clone().prop_map(Action::Pin),
        1 => id.clone().prop_map(Action::Unpin),
        1 => id.clone().prop_map(Action::DragStart),
        2 => (id.clone(), -60.0_f32..60.0, -60.0_f32..60.0).prop_map(|(i, x, y)| Action::DragTo(i, x, y)),
        1 => id.clone().prop_map(Action::DragEnd),
        1 => (id.clone(), coordinate(), coordinate()).prop_map(|(i, x, y)| Action::HostMove(i, x, y)),
        1 => id.clone().prop_map(Action::Poison),
        6 => frame_time().prop_map(Action::Step),
    ]
}

/// The actions of a long session: fewer bad values, more drags, throws and grabs.
fn long_action() -> impl Strategy<Value = Action> {
    let id = 0..IDS;
    prop_oneof![
        3 => (id.clone(), coordinate(), coordinate()).prop_map(|(i, x, y)| Action::AddNode(i, x, y)),
        2 => (id.clone(), coordinate(), coordinate()).prop_map(|(i, x, y)| Action::AddDragged(i, x, y)),
        2 => id.clone().prop_map(Action::RemoveNode),
        3 => (id.clone(), id.clone()).prop_map(|(a, b)| Action::AddEdge(a, b)),
        1 => (0usize..40).prop_map(Action::RemoveEdge),
        2 => id.clone().prop_map(Action::Pin),
        2 => id.clone().prop_map(Action::Unpin),
        2 => id.clone().prop_map(Action::DragStart),
        1 => id.clone().prop_map(Action::DragEnd),
        2 => (id.clone(), -80.0_f32..80.0, -80.0_f32..80.0).prop_map(|(i, x, y)| Action::Throw(i, x, y)),
        1 => (id.clone(), -200.0_f32..200.0, -200.0_f32..200.0).prop_map(|(i, x, y)| Action::HostMove(i, x, y)),
        1 => Just(Action::Settle),
        12 => frame_time().prop_map(Action::Step),
    ]
}

fn config() -> impl Strategy<Value = RapierLayoutConfig> {
    (
        prop_oneof![
            Just(EdgeJoint::default()),
            Just(EdgeJoint::Rope {
                max_length: 120.0,
                stiffness: 1e4
            }),
            Just(EdgeJoint::Distance { length: 80.0 }),
            Just(EdgeJoint::None),
        ],
        prop_oneof![
            Just(TopologyUpdate::Incremental),
            Just(TopologyUpdate::Rebuild)
        ],
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(
            |(edge_joint, topology_update, collisions, force_directed)| {
                // The force-directed extras: many-body repulsion, springs shared by degree,
                // a cooling schedule and firm contacts.
                let base = if force_directed {
                    RapierLayoutConfig::force_directed()
                } else {
                    RapierLayoutConfig::default()
                };
                RapierLayoutConfig {
                    edge_joint,
                    topology_update,
                    collisions,
                    ..base
                }
            },
        )
}

/// Applies a host action to the scene (not a step).
fn apply_action(host: &mut Host<u32>, action: &Action) {
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
        Action::Throw(..) | Action::Settle | Action::Step(_) => {}
    }
}

/// Every dragged node moves by (3, −2) per call, as a pointer held in motion would.
fn move_dragged(host: &mut Host<u32>) {
    for n in &mut host.scene.nodes {
        if host.extras.dragging.contains(&n.id) && n.position.x.is_finite() {
            n.position += Vector2D::new(3.0, -2.0);
        }
    }
}

/// Fixes any poisoned node some frames later, as a host would.
fn heal(scene: &mut CanvasSceneInput<u32>) {
    for n in &mut scene.nodes {
        if !n.position.x.is_finite() {
            n.position = Point2D::new(n.id as f32 * 10.0, 0.0);
        }
    }
}

/// The invariants a host relies on, checked after every call.
fn check(
    host: &Host<u32>,
    before: &CanvasSceneInput<u32>,
    deltas: &DeltaMap<u32>,
) -> Result<(), TestCaseError> {
    let valid = |p: Point2D<f32>| p.x.is_finite() && p.y.is_finite();
    let ids: HashSet<u32> = before.nodes.iter().map(|n| n.id).collect();
    for (id, d) in deltas {
        prop_assert!(
            d.x.is_finite() && d.y.is_finite(),
            "node {id}: non-finite delta {d:?}"
        );
        prop_assert!(
            ids.contains(id),
            "delta for node {id}, which is not in the scene"
        );
        prop_assert!(
            !host.extras.pinned.contains(id),
            "delta for pinned node {id}: {d:?}"
        );
        prop_assert!(
            !host.extras.dragging.contains(id),
            "delta for dragged node {id}: {d:?}"
        );
        let p = before.nodes.iter().find(|n| n.id == *id).unwrap().position;
        prop_assert!(
            valid(p),
            "delta {d:?} for node {id} whose position {p:?} is unusable"
        );
    }
    let Some(world) = host.layout.world() else {
        prop_assert!(before.nodes.is_empty(), "no world for a non-empty scene");
        return Ok(());
    };
    // World and scene agree on the node set (nodes with usable values, plus bodies kept
    // for nodes whose values are unusable right now).
    for n in &before.nodes {
        if valid(n.position) {
            prop_assert!(
                world.contains_node(&n.id),
                "scene node {} has no body",
                n.id
            );
        }
    }
    for id in world.node_ids() {
        prop_assert!(ids.contains(id), "body for node {id}, which left the scene");
    }
    prop_assert_eq!(world.body_count(), world.node_ids().count());
    check_joints(host, before)?;
    for n in &host.scene.nodes {
        if !valid(n.position) {
            continue;
        }
        let w = world.get_position(&n.id).unwrap();
        prop_assert!(valid(w), "node {}: body at {:?}", n.id, w);
        if host.extras.dragging.contains(&n.id) || host.extras.pinned.contains(&n.id) {
            prop_assert_eq!(
                w,
                n.position,
                "held node {} is not where the host put it",
                n.id
            );
        } else {
            // Deltas sum to the world's positions: the host's position after applying
            // them is the body's, up to rounding and the 1e-4 report threshold.
            let scale = 1.0 + n.position.x.abs().max(n.position.y.abs());
            let gap = (w - n.position).length();
            prop_assert!(
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
fn check_joints(host: &Host<u32>, before: &CanvasSceneInput<u32>) -> Result<(), TestCaseError> {
    let world = host.layout.world().expect("a world");
    let config = &host.layout.config;
    let mut pairs: Vec<(u32, u32)> = before
        .edges
        .iter()
        .filter(|e| e.source != e.target)
        .filter(|e| world.contains_node(&e.source) && world.contains_node(&e.target))
        .map(|e| (e.source.min(e.target), e.source.max(e.target)))
        .collect();
    pairs.sort_unstable();
    pairs.dedup();
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
            } if config.spring_degree_exponent > 0.0 => {
                let share = (degree[&a].min(degree[&b]) as f32).powf(config.spring_degree_exponent);
                Some(EdgeJoint::Spring {
                    rest_length,
                    stiffness: stiffness / share,
                    damping: damping / share,
                })
            }
            kind => Some(kind),
        };
        prop_assert_eq!(
            world.edge_joint(&a, &b),
            expected,
            "edge {}-{} (degrees {}, {})",
            a,
            b,
            degree[&a],
            degree[&b]
        );
    }
    prop_assert_eq!(
        world.joint_count(),
        if config.edge_joint == EdgeJoint::None {
            0
        } else {
            pairs.len()
        },
        "joints for {} modelled edges",
        pairs.len()
    );
    Ok(())
}

/// One call of `dt` seconds, checked, its deltas logged.
fn call(host: &mut Host<u32>, dt: f32, log: &mut Vec<DeltaBits>) -> Result<(), TestCaseError> {
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

fn run(config: &RapierLayoutConfig, actions: &[Action]) -> Result<Vec<DeltaBits>, TestCaseError> {
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

/// The configurations of the long sessions: the default and the force-directed one,
/// whole.
fn long_config() -> impl Strategy<Value = RapierLayoutConfig> {
    prop_oneof![
        Just(RapierLayoutConfig::default()),
        Just(RapierLayoutConfig::force_directed()),
        Just(RapierLayoutConfig::force_directed_fast()),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 256,
        failure_persistence: Some(Box::new(
            proptest::test_runner::FileFailurePersistence::Direct("proptest-regressions/sessions.txt"),
        )),
        ..ProptestConfig::default()
    })]

    #[test]
    fn random_sessions_keep_the_invariants_and_replay_bit_for_bit(
        config in config(),
        actions in prop::collection::vec(action(), 1..80),
    ) {
        let first = run(&config, &actions)?;
        let second = run(&config, &actions)?;
        prop_assert_eq!(first, second, "two layouts fed the same session differ");
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 96,
        failure_persistence: Some(Box::new(
            proptest::test_runner::FileFailurePersistence::Direct("proptest-regressions/long_sessions.txt"),
        )),
        ..ProptestConfig::default()
    })]

    #[test]
    fn long_sessions_keep_the_invariants_and_replay_bit_for_bit(
        config in long_config(),
        actions in prop::collection::vec(long_action(), 200..600),
    ) {
        let first = run(&config, &actions)?;
        let second = run(&config, &actions)?;
        prop_assert_eq!(first, second, "two layouts fed the same session differ");
    }
}
