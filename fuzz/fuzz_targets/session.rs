//! A host session decoded from the fuzzer's bytes: a configuration (a flow or none),
//! then host actions (nodes and edges added and removed, pins, drags, throws, host
//! moves, hard constraints, bad values, any frame time, runs to rest), with the
//! invariants of `tests/sessions.rs` checked after every call and a second layout fed
//! the same session, saved and restored through JSON wherever the session says so,
//! compared bit for bit. Any broken invariant or panic is a finding.
#![no_main]

use arbitrary::{Result, Unstructured};
use graph_canvas_layout::config::{Contacts, TopologyUpdate};
use graph_canvas_layout::scene::AxisLock;
use graph_canvas_layout::{
    Axis, BodyKindPolicy, Constraint, EdgeJoint, Flow, NodeForces, RapierLayoutConfig,
};
use libfuzzer_sys::fuzz_target;

#[path = "../../tests/common/mod.rs"]
mod common;

use common::session::{run, run_resuming, Action};
use common::FRAME;

/// Ids the session draws from: few, so actions meet the same nodes again.
const IDS: u32 = 12;
/// The longest session one input decodes to.
const MAX_ACTIONS: usize = 400;

fn config(u: &mut Unstructured) -> Result<RapierLayoutConfig> {
    let base = match u.int_in_range(0..=2)? {
        0 => RapierLayoutConfig::default(),
        1 => RapierLayoutConfig::force_directed(),
        _ => RapierLayoutConfig::force_directed_fast(),
    };
    let edge_joint = match u.int_in_range(0..=4)? {
        0 => EdgeJoint::Rope {
            max_length: 120.0,
            stiffness: 1e4,
        },
        1 => EdgeJoint::Distance { length: 80.0 },
        2 => EdgeJoint::None,
        _ => base.edge_joint,
    };
    let body_kind_policy = match u.int_in_range(0..=5)? {
        0 => BodyKindPolicy::PinnedKinematic,
        1 => BodyKindPolicy::AllKinematic,
        _ => BodyKindPolicy::PinnedStatic,
    };
    Ok(RapierLayoutConfig {
        edge_joint,
        body_kind_policy,
        topology_update: if u.ratio(1, 4)? {
            TopologyUpdate::Rebuild
        } else {
            TopologyUpdate::Incremental
        },
        contacts: Contacts {
            enabled: if u.ratio(1, 4)? {
                !base.contacts.enabled
            } else {
                base.contacts.enabled
            },
            events: u.ratio(1, 4)?,
            ..base.contacts
        },
        flow: match u.int_in_range(0..=7)? {
            0 => Some(Flow::down(gap(u)?)),
            1 => Some(Flow::up(gap(u)?)),
            2 => Some(Flow::right(gap(u)?)),
            3 => Some(Flow::left(gap(u)?)),
            _ => None,
        },
        ..base
    })
}

/// A constraint's or a flow's gap: an ordinary one, 0, or any bits.
fn gap(u: &mut Unstructured) -> Result<f32> {
    Ok(match u.int_in_range(0..=3)? {
        0 => f32::from_bits(u.arbitrary()?),
        1 => 0.0,
        n => 40.0 * n as f32,
    })
}

/// A hard constraint between the session's ids: a separation or a row.
fn constraint(u: &mut Unstructured) -> Result<Constraint<u32>> {
    let axis = if u.arbitrary()? { Axis::X } else { Axis::Y };
    let id = |u: &mut Unstructured| u.int_in_range(0..=IDS - 1);
    Ok(if u.ratio(3, 4)? {
        Constraint::separation(axis, id(u)?, id(u)?, gap(u)?)
    } else {
        let count = u.int_in_range(0..=4)?;
        Constraint::align(axis, (0..count).map(|_| id(u)).collect::<Result<_>>()?)
    })
}

/// A coordinate: mostly on the canvas, sometimes anything an `f32` holds.
/// A box's side: a label's, 0, or any bits.
fn side(u: &mut Unstructured) -> Result<f32> {
    Ok(match u.int_in_range(0..=4)? {
        0 => f32::from_bits(u.arbitrary()?),
        1 => 0.0,
        n => 20.0 * n as f32,
    })
}

fn coordinate(u: &mut Unstructured) -> Result<f32> {
    Ok(match u.int_in_range(0..=9)? {
        0 => f32::from_bits(u.arbitrary()?),
        1 => 0.0,
        2 => u.int_in_range(-100_000..=100_000)? as f32,
        _ => u.int_in_range(-400..=400)? as f32,
    })
}

/// A frame time: mostly ordinary ones, sometimes anything an `f32` holds.
fn frame_time(u: &mut Unstructured) -> Result<f32> {
    Ok(match u.int_in_range(0..=9)? {
        0 => f32::from_bits(u.arbitrary()?),
        1 => 1.0 / 144.0,
        2 => 1.0 / 30.0,
        3 => 0.5,
        4 => 0.0,
        _ => FRAME,
    })
}

fn action(u: &mut Unstructured) -> Result<Action> {
    let id = |u: &mut Unstructured| u.int_in_range(0..=IDS - 1);
    Ok(match u.int_in_range(0..=19)? {
        0 => Action::AddNode(id(u)?, coordinate(u)?, coordinate(u)?),
        1 => Action::AddDragged(id(u)?, coordinate(u)?, coordinate(u)?),
        2 => Action::RemoveNode(id(u)?),
        3 => Action::AddEdge(id(u)?, id(u)?),
        4 => Action::RemoveEdge(u.int_in_range(0..=40)?),
        5 => Action::Pin(id(u)?),
        6 => Action::Unpin(id(u)?),
        7 => Action::DragStart(id(u)?),
        8 => Action::DragTo(id(u)?, coordinate(u)?, coordinate(u)?),
        9 => Action::DragEnd(id(u)?),
        10 => Action::HostMove(id(u)?, coordinate(u)?, coordinate(u)?),
        11 => Action::Poison(id(u)?),
        12 => Action::Throw(id(u)?, coordinate(u)?, coordinate(u)?),
        13 if u.ratio(1, 8)? => Action::Settle,
        14 if u.ratio(1, 2)? => Action::Weigh(
            u.int_in_range(0..=40)?,
            match u.int_in_range(0..=5)? {
                0 => f32::from_bits(u.arbitrary()?),
                1 => 0.0,
                n => n as f32 / 2.0,
            },
        ),
        15 if u.ratio(1, 2)? => Action::Force(id(u)?, node_forces(u)?),
        16 if u.ratio(1, 4)? => Action::Resume,
        17 if u.ratio(1, 2)? => Action::Reshape(
            id(u)?,
            side(u)?,
            side(u)?,
            match u.int_in_range(0..=3)? {
                0 => f32::from_bits(u.arbitrary()?),
                n => (n - 1) as f32 * 8.0,
            },
        ),
        18 if u.ratio(1, 2)? => Action::Constrain(constraint(u)?),
        19 if u.ratio(1, 4)? => Action::Unconstrain,
        _ => Action::Step(frame_time(u)?),
    })
}

/// A node's forces: a target, a ring, a group or a lock (bad values too), or none.
fn node_forces(u: &mut Unstructured) -> Result<NodeForces> {
    let strength = |u: &mut Unstructured| -> Result<f32> {
        Ok(match u.int_in_range(0..=5)? {
            0 => f32::from_bits(u.arbitrary()?),
            1 => 0.1,
            2 => 20.0,
            _ => 1.0,
        })
    };
    let none = NodeForces::default();
    Ok(match u.int_in_range(0..=5)? {
        0 => none,
        1 => none.toward_x(coordinate(u)?, strength(u)?),
        2 => none.toward_y(coordinate(u)?, strength(u)?),
        3 => none.on_ring(
            coordinate(u)?,
            coordinate(u)?,
            coordinate(u)?.abs(),
            strength(u)?,
        ),
        4 => none.in_group(u.int_in_range(0..=2)?),
        _ => none.locked(if u.arbitrary()? {
            AxisLock::X
        } else {
            AxisLock::Y
        }),
    })
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Ok(config) = config(&mut u) else {
        return;
    };
    let mut actions = Vec::new();
    while !u.is_empty() && actions.len() < MAX_ACTIONS {
        match action(&mut u) {
            Ok(a) => actions.push(a),
            Err(_) => break,
        }
    }
    let first = run(&config, &actions);
    let second = run_resuming(&config, &actions);
    match (first, second) {
        (Ok(a), Ok(b)) => assert!(
            a == b,
            "a layout saved and restored mid-session differs from the one that never stopped"
        ),
        (Err(e), _) | (_, Err(e)) => panic!("{e}\nconfig: {config:?}\nactions: {actions:?}"),
    }
});
