//! Random host sessions (nodes and edges coming and going, pins, drags, throws, host
//! moves, bad values, odd frame times) with an invariant checker after every call, and
//! two layouts fed the same session compared bit for bit. Short sessions over every
//! configuration; long ones (hundreds of calls, drags that outlive edits and pin
//! toggles, nodes dragged as they are added, grabs of flying nodes, frame times mixing
//! tiny and capped ones, runs to rest and the halted world after it) under the default
//! and the force-directed configuration. Any of them under a flow, with hard constraints
//! (bad ones too) coming and going.

mod common;

use common::session::{run, run_resuming, Action};
use common::FRAME;
use graph_canvas_layout::config::Contacts;
use graph_canvas_layout::config::TopologyUpdate;
use graph_canvas_layout::scene::AxisLock;
use graph_canvas_layout::scene::Cluster;
use graph_canvas_layout::{Axis, Constraint, EdgeJoint, Flow, NodeForces, RapierLayoutConfig};
use proptest::prelude::*;

const IDS: u32 = 12;

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

/// An edge weight: mostly ordinary ones, 0, and bad ones.
fn weight() -> impl Strategy<Value = f32> {
    prop_oneof![
        4 => prop_oneof![Just(0.5_f32), Just(1.0), Just(2.0), Just(3.0)],
        1 => Just(0.0_f32),
        1 => prop_oneof![Just(-1.0_f32), Just(f32::NAN), Just(f32::INFINITY)],
    ]
}

/// A box's side: a label's width or height, 0 (with the other 0: a disk again), or a
/// bad value.
fn side() -> impl Strategy<Value = f32> {
    prop_oneof![
        4 => prop_oneof![Just(20.0_f32), Just(63.0), Just(140.0)],
        1 => Just(0.0_f32),
        1 => prop_oneof![Just(-1.0_f32), Just(f32::NAN), Just(f32::INFINITY)],
    ]
}

/// A box's corner radius: square, rounded, more than the box holds, or bad.
fn corner() -> impl Strategy<Value = f32> {
    prop_oneof![
        3 => Just(0.0_f32),
        2 => prop_oneof![Just(4.0_f32), Just(1_000.0)],
        1 => prop_oneof![Just(-1.0_f32), Just(f32::NAN)],
    ]
}

/// A node's forces: targets, a ring, a group, a lock, bad values, or none.
fn node_forces() -> impl Strategy<Value = NodeForces> {
    let strength = prop_oneof![
        4 => prop_oneof![Just(0.1_f32), Just(1.0), Just(20.0)],
        1 => prop_oneof![Just(-1.0_f32), Just(f32::NAN), Just(0.0)],
    ];
    prop_oneof![
        2 => Just(NodeForces::default()),
        2 => (coordinate(), strength.clone()).prop_map(|(x, s)| NodeForces::default().toward_x(x, s)),
        1 => (coordinate(), strength.clone()).prop_map(|(y, s)| NodeForces::default().toward_y(y, s)),
        2 => (coordinate(), 0.0_f32..300.0, strength).prop_map(|(c, r, s)| NodeForces::default().on_ring(c, -c, r, s)),
        2 => (0_u32..3).prop_map(|g| NodeForces::default().in_group(g)),
        2 => prop_oneof![Just(AxisLock::X), Just(AxisLock::Y)].prop_map(|a| NodeForces::default().locked(a)),
    ]
}

/// A hard constraint between the session's ids: separations (bad gaps too) and rows.
fn constraint() -> impl Strategy<Value = Constraint<u32>> {
    let axis = prop_oneof![Just(Axis::X), Just(Axis::Y)];
    let gap = prop_oneof![
        4 => prop_oneof![Just(0.0_f32), Just(40.0), Just(90.0)],
        1 => prop_oneof![Just(-1.0_f32), Just(f32::NAN), Just(f32::INFINITY)],
    ];
    prop_oneof![
        3 => (axis.clone(), 0..IDS, 0..IDS, gap)
            .prop_map(|(a, l, r, g)| Constraint::separation(a, l, r, g)),
        1 => (axis, prop::collection::vec(0..IDS, 0..5)).prop_map(|(a, n)| Constraint::align(a, n)),
    ]
}

/// A cluster of the session's ids (bad paddings and parents too).
fn cluster() -> impl Strategy<Value = Cluster<u32>> {
    let padding = prop_oneof![
        4 => prop_oneof![Just(0.0_f32), Just(10.0), Just(40.0)],
        1 => prop_oneof![Just(-1.0_f32), Just(f32::NAN)],
    ];
    let parent = prop_oneof![3 => Just(None), 1 => (0_usize..5).prop_map(Some)];
    (prop::collection::vec(0..IDS, 0..6), padding, parent).prop_map(|(members, p, parent)| {
        let c = Cluster::new(members).with_padding(p);
        match parent {
            Some(i) => c.inside(i),
            None => c,
        }
    })
}

/// No flow, or one along any direction, free or in layers.
fn flow() -> impl Strategy<Value = Option<Flow>> {
    prop_oneof![
        2 => Just(None),
        1 => prop_oneof![
            Just(Flow::down(60.0)),
            Just(Flow::up(0.0)),
            Just(Flow::right(40.0)),
            Just(Flow::left(f32::NAN)),
            Just(Flow::down(60.0).in_layers()),
            Just(Flow::right(40.0).in_layers()),
        ]
        .prop_map(Some),
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
        1 => (0usize..40, weight()).prop_map(|(i, w)| Action::Weigh(i, w)),
        1 => (id.clone(), node_forces()).prop_map(|(i, f)| Action::Force(i, f)),
        1 => (id.clone(), side(), side(), corner()).prop_map(|(i, w, h, c)| Action::Reshape(i, w, h, c)),
        1 => Just(Action::Resume),
        1 => constraint().prop_map(Action::Constrain),
        1 => cluster().prop_map(Action::Group),
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
        1 => (0usize..40, weight()).prop_map(|(i, w)| Action::Weigh(i, w)),
        1 => (id.clone(), node_forces()).prop_map(|(i, f)| Action::Force(i, f)),
        1 => (id.clone(), side(), side(), corner()).prop_map(|(i, w, h, c)| Action::Reshape(i, w, h, c)),
        1 => Just(Action::Resume),
        1 => constraint().prop_map(Action::Constrain),
        1 => Just(Action::Unconstrain),
        1 => cluster().prop_map(Action::Group),
        1 => Just(Action::Ungroup),
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
        0..3_u8,
        flow(),
    )
        .prop_map(|(edge_joint, topology_update, collisions, preset, flow)| {
            // The presets' extras: many-body repulsion, springs shared by degree, a
            // cooling schedule and firm contacts; or the stress model.
            let base = match preset {
                0 => RapierLayoutConfig::default(),
                1 => RapierLayoutConfig::force_directed(),
                _ => RapierLayoutConfig::stress(),
            };
            RapierLayoutConfig {
                edge_joint,
                topology_update,
                contacts: Contacts {
                    enabled: collisions,
                    ..base.contacts
                },
                flow,
                ..base
            }
        })
}

/// The configurations of the long sessions: each preset whole, under a flow or not.
fn long_config() -> impl Strategy<Value = RapierLayoutConfig> {
    (
        prop_oneof![
            Just(RapierLayoutConfig::default()),
            Just(RapierLayoutConfig::force_directed()),
            Just(RapierLayoutConfig::force_directed_fast()),
            Just(RapierLayoutConfig::stress()),
        ],
        flow(),
    )
        .prop_map(|(config, flow)| RapierLayoutConfig { flow, ..config })
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
        let first = run(&config, &actions).map_err(TestCaseError::fail)?;
        let second = run(&config, &actions).map_err(TestCaseError::fail)?;
        prop_assert_eq!(&first, &second, "two layouts fed the same session differ");
        let resumed = run_resuming(&config, &actions).map_err(TestCaseError::fail)?;
        prop_assert_eq!(first, resumed, "a layout saved and restored mid-session differs");
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
        let first = run(&config, &actions).map_err(TestCaseError::fail)?;
        let second = run(&config, &actions).map_err(TestCaseError::fail)?;
        prop_assert_eq!(&first, &second, "two layouts fed the same session differ");
        let resumed = run_resuming(&config, &actions).map_err(TestCaseError::fail)?;
        prop_assert_eq!(first, resumed, "a layout saved and restored mid-session differs");
    }
}
