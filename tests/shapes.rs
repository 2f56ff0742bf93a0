//! Nodes as the canvas draws them: label boxes (`CanvasNode::with_rect`) that the layout
//! keeps apart by their outlines, under every model, through drags, with a mass that
//! does not depend on their size, and a layout of disks unchanged by any of it.

mod common;

#[path = "../benches/common/generate.rs"]
#[allow(dead_code)]
mod generate;

use common::*;
use generate::label_boxes;
use graph_canvas_layout::config::ContactModel;
use graph_canvas_layout::config::Contacts;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{
    quality, CanvasNode, CanvasSceneInput, EdgeJoint, LayoutError, RapierLayoutConfig,
};

/// A pair overlaps when each is more than this inside the other on both axes (world
/// units): the soft contacts hold a pressed pair a fraction of a unit inside.
const OVERLAP: f32 = 1.0;

fn presets() -> [(&'static str, RapierLayoutConfig); 2] {
    [
        ("force_directed", RapierLayoutConfig::force_directed()),
        ("stress", RapierLayoutConfig::stress()),
    ]
}

/// 1138_bus from its file to rest, each node a box of its label "node <id>" (7 units a
/// character by 20): no two boxes overlap, the layout rests within 300 frames, and its
/// edges are as even (centre to centre) as the same preset draws them with disks.
#[test]
fn label_boxes_on_1138_bus_rest_apart_under_each_preset() {
    for (preset, config) in presets() {
        let file = load_scene("1138_bus");
        let mut disks = Host::new(file.clone(), config.clone());
        disks.settle(300);
        let disk_cv = quality::edge_length_cv(&disks.scene).expect("edges");
        let mut boxes = Host::new(label_boxes(file, |_| false), config.clone());
        let frames = boxes.settle(300);
        let overlaps = quality::overlapping_pairs(&boxes.scene, 16.0, OVERLAP);
        let cv = quality::edge_length_cv(&boxes.scene).expect("edges");
        let line = format!(
            "{preset}: boxes at rest in {frames} frames, {overlaps} overlaps, edge CV {cv:.3} (disks {disk_cv:.3})"
        );
        assert_eq!(overlaps, 0, "{line}");
        // Within 10 % of the disks' spread of edge lengths, either way.
        assert!((cv / disk_cv - 1.0).abs() <= 0.10, "{line}");
    }
}

/// qh882 with every third node (id divisible by 3) a disk of radius 16 and the rest
/// label boxes: boxes part from disks as from boxes.
#[test]
fn a_mixed_scene_of_boxes_and_disks_rests_apart() {
    for (preset, config) in presets() {
        let scene = label_boxes(load_scene("qh882"), |id| id % 3 == 0);
        let mut host = Host::new(scene, config);
        let frames = host.settle(300);
        let overlaps = quality::overlapping_pairs(&host.scene, 16.0, OVERLAP);
        assert_eq!(
            overlaps, 0,
            "{preset}: {overlaps} overlapping pairs at rest after {frames} frames"
        );
    }
}

/// A box dragged into the middle of a settled crowd, held there and let go: when the
/// layout rests again nothing overlaps.
#[test]
fn a_box_dragged_into_a_settled_crowd_rests_apart_when_let_go() {
    for (preset, config) in presets() {
        let mut host = Host::new(label_boxes(load_scene("1138_bus"), |_| false), config);
        host.settle(300);
        // The node nearest the centroid is the crowd; the dragged one is the farthest.
        let (middle, dragged) = nearest_and_farthest_from_centroid(&host.scene);
        let (from, to) = (host.pos(&dragged), host.pos(&middle));
        host.extras.dragging.insert(dragged);
        for k in 1..=30 {
            host.set_pos(&dragged, from.lerp(to, k as f32 / 30.0));
            host.frame(FRAME);
        }
        host.frames(30);
        host.extras.dragging.clear();
        let frames = host.settle(600);
        let overlaps = quality::overlapping_pairs(&host.scene, 16.0, OVERLAP);
        assert_eq!(
            overlaps, 0,
            "{preset}: {overlaps} overlapping pairs at rest {frames} frames after the release"
        );
    }
}

/// Two boxes of 100 × 20 side by side, 10 units into each other across and 15 up and
/// down: parted across, the shallower way, until their sides touch (centres 100 apart),
/// not their bounding circles (101.8 with the 5 units up and down), by the layout's own
/// contacts and by rapier's (cuboids).
#[test]
fn boxes_part_until_their_sides_touch_under_either_contact_model() {
    for (model, config) in [
        (
            "Disks",
            RapierLayoutConfig {
                repulsion: None,
                ..RapierLayoutConfig::force_directed()
            },
        ),
        (
            "Rapier",
            RapierLayoutConfig {
                contacts: Contacts {
                    model: ContactModel::Rapier,
                    ..Default::default()
                },
                ..RapierLayoutConfig::default()
            },
        ),
    ] {
        let scene = CanvasSceneInput::new(
            vec![
                node(0, 0.0, 0.0).with_rect(100.0, 20.0),
                node(1, 90.0, 5.0).with_rect(100.0, 20.0),
            ],
            vec![],
        );
        let mut host = Host::new(scene, config);
        host.frames(240);
        let (a, b) = (host.pos(&0), host.pos(&1));
        let gap = (b.x - a.x).abs();
        // Within the overlap the tests allow (1 unit) of touching, and short of the
        // bounding circles by more than a unit.
        assert!(
            (99.0..=100.5).contains(&gap) && (b.y - a.y).abs() < 19.0,
            "{model}: centres {gap} apart along x and {} along y (touching sides: 100)",
            (b.y - a.y).abs()
        );
    }
}

/// A box weighs what a default disk weighs, whatever its size: a node thrown on an edge
/// long enough that nothing touches flies the same way as a short label, a long label
/// and a default disk.
#[test]
fn a_long_label_throws_like_a_short_one() {
    let thrown = |shape: fn(CanvasNode<u32>) -> CanvasNode<u32>| {
        let scene = CanvasSceneInput::new(
            vec![shape(node(0, 0.0, 0.0)), node(1, 400.0, 0.0)],
            vec![edge(0, 1)],
        );
        let config = RapierLayoutConfig {
            edge_joint: EdgeJoint::Spring {
                rest_length: 400.0,
                stiffness: 7_200.0,
                damping: 0.0,
            },
            ..RapierLayoutConfig::force_directed()
        };
        let mut host = Host::new(scene, config);
        host.frames(2);
        let start = host.pos(&0);
        host.extras.dragging.insert(0);
        for k in 1..=3 {
            host.set_pos(&0, Point2D::new(start.x, start.y - 10.0 * (k * k) as f32));
            host.frame(FRAME);
        }
        host.extras.dragging.clear();
        let released = host.pos(&0);
        host.frames(60);
        let gap = dist(host.pos(&0), host.pos(&1));
        (dist(host.pos(&0), released), gap)
    };
    let (disk, gap) = thrown(|n| n);
    let (short, _) = thrown(|n| n.with_rect(42.0, 20.0));
    let (long, _) = thrown(|n| n.with_rect(140.0, 20.0));
    // The same mass and forces, nothing touching: the same flight, bit for bit.
    for (what, flew) in [("short label", short), ("long label", long)] {
        assert!(
            flew.to_bits() == disk.to_bits() && disk > 20.0 && gap > 200.0,
            "{what} flew {flew} units, a default disk {disk} (the two ends {gap} apart)"
        );
    }
}

/// A box with a NaN or negative side is bad input: `try_step` names the node and the
/// side and changes nothing; `step` leaves the node out of the call.
#[test]
fn a_box_with_an_unusable_side_is_bad_input() {
    let scene = CanvasSceneInput::new(
        vec![
            node(0, 0.0, 0.0).with_rect(60.0, 20.0),
            node(1, 100.0, 0.0).with_rect(f32::NAN, 20.0),
            node(2, 200.0, 0.0).with_rounded_rect(60.0, 20.0, -1.0),
        ],
        vec![edge(0, 1), edge(1, 2)],
    );
    let mut host = Host::new(scene, RapierLayoutConfig::force_directed());
    let err = host
        .layout
        .try_step(
            &host.scene,
            &mut host.state,
            FRAME,
            &Default::default(),
            &host.extras,
        )
        .expect_err("a NaN width");
    assert!(
        matches!(
            err,
            LayoutError::InvalidShape {
                node: 1,
                part: "width",
                ..
            }
        ),
        "{err}"
    );
    assert!(err.to_string().contains("width"), "{err}");
    // Without node 1, node 2's negative corner radius is the first problem.
    let mut without = host.scene.clone();
    without.nodes.remove(1);
    without.edges.clear();
    let err = host
        .layout
        .try_step(
            &without,
            &mut host.state,
            FRAME,
            &Default::default(),
            &host.extras,
        )
        .expect_err("a negative corner radius");
    assert!(
        matches!(
            err,
            LayoutError::InvalidShape {
                node: 2,
                part: "corner radius",
                ..
            }
        ),
        "{err}"
    );
    assert!(!host.layout.has_world(), "a rejected call built a world");
    let deltas = host.frame(FRAME);
    assert!(
        !deltas.contains_key(&1) && !deltas.contains_key(&2),
        "bad boxes moved: {deltas:?}"
    );
    assert!(deltas.values().all(|d| d.x.is_finite() && d.y.is_finite()));
}

/// A node that becomes a box in a settled layout pushes its neighbours off its new
/// outline, without a rebuild.
#[test]
fn a_disk_edited_into_a_wide_box_pushes_its_neighbours_off() {
    let mut host = Host::new(load_scene("karate"), RapierLayoutConfig::force_directed());
    host.settle(300);
    let rebuilds = host.layout.rebuild_count();
    let hub = host.scene.nodes[0].id;
    for n in &mut host.scene.nodes {
        if n.id == hub {
            *n = n.clone().with_rect(240.0, 40.0);
        }
    }
    let covered = quality::overlapping_pairs(&host.scene, 16.0, OVERLAP);
    assert!(
        covered > 0,
        "the wide box covers none of its neighbours: no test"
    );
    let frames = host.settle(600);
    let overlaps = quality::overlapping_pairs(&host.scene, 16.0, OVERLAP);
    assert_eq!(
        overlaps, 0,
        "{overlaps} overlaps {frames} frames after the edit"
    );
    assert_eq!(
        host.layout.rebuild_count(),
        rebuilds,
        "the edit rebuilt the world"
    );
}
