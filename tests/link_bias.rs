//! Link bias: a spring shares its pull between its ends like d3-force's link, the end
//! with fewer neighbours pulled harder, and no gain a host sets makes it blow up.

mod common;

use common::*;
use graph_canvas_layout::config::{Contacts, Springs};
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasSceneInput, EdgeJoint, RapierLayoutConfig};

/// A hub (node 0) with four leaves: leaf 1 stretched to 300 on the right, leaves 2–4 at
/// their rest length on the left, so only the stretched spring pulls at first.
fn hub_with_stretched_leaf() -> CanvasSceneInput<u32> {
    CanvasSceneInput {
        nodes: vec![
            node(0, 0.0, 0.0),
            node(1, 300.0, 0.0),
            node(2, -100.0, 0.0),
            node(3, -50.0, 86.6),
            node(4, -50.0, -86.6),
        ],
        edges: vec![edge(0, 1), edge(0, 2), edge(0, 3), edge(0, 4)],
    }
}

fn config(link_bias: f32) -> RapierLayoutConfig {
    RapierLayoutConfig {
        edge_joint: EdgeJoint::Spring {
            rest_length: 100.0,
            stiffness: 2_000.0,
            damping: 0.0,
        },
        contacts: Contacts {
            enabled: false,
            ..Default::default()
        },
        springs: Springs {
            link_bias,
            ..Default::default()
        },
        ..Default::default()
    }
}

/// How far the hub and the stretched leaf moved in their first three frames (a new
/// world's bodies join rapier's active set in its first step; forces start after it).
fn first_frames_moves(link_bias: f32) -> (f32, f32) {
    let mut host = Host::new(hub_with_stretched_leaf(), config(link_bias));
    host.frames(3);
    (
        dist(host.pos(&0), Point2D::new(0.0, 0.0)),
        dist(host.pos(&1), Point2D::new(300.0, 0.0)),
    )
}

#[test]
fn the_leaf_takes_more_of_the_pull_than_its_hub() {
    let (hub_even, leaf_even) = first_frames_moves(0.0);
    let (hub_biased, leaf_biased) = first_frames_moves(1.0);
    // d3's share for a degree-4 hub and a leaf: the hub 2/5, the leaf 8/5 of the even
    // pull. The first frame has no bias, the joint part is implicit and the other
    // springs answer, so over three frames expect about a quarter less and more.
    assert!(
        hub_biased < 0.85 * hub_even && leaf_biased > 1.15 * leaf_even,
        "hub moved {hub_biased} (even springs: {hub_even}), leaf {leaf_biased} (even: {leaf_even})"
    );
}

#[test]
fn gains_outside_zero_to_one_are_clamped_and_stay_finite() {
    let run = |gain: f32| {
        let mut host = Host::new(hub_with_stretched_leaf(), config(gain));
        host.frames(120);
        (0..5)
            .flat_map(|id| {
                let p = host.pos(&id);
                [p.x.to_bits(), p.y.to_bits()]
            })
            .collect::<Vec<u32>>()
    };
    assert_eq!(run(1e9), run(1.0), "a huge gain acts as 1");
    assert_eq!(run(f32::NAN), run(0.0), "NaN acts as 0");
    assert_eq!(run(-3.0), run(0.0), "a negative gain acts as 0");
    let settled = run(1.0);
    assert!(
        settled.iter().all(|&b| f32::from_bits(b).is_finite()),
        "positions after two seconds: {settled:?}"
    );
}
