//! Clusters: members in their box, other nodes and sibling boxes out of it, at rest and
//! while the user drags; nesting, flows, snapshots, and bad input named and left out.

mod common;

#[path = "../benches/common/generate.rs"]
#[allow(dead_code)]
mod generate;

use common::{Host, FRAME};
use graph_canvas_layout::euclid::default::{Box2D, Vector2D};
use graph_canvas_layout::quality::{self, ClusterViolations};
use graph_canvas_layout::scene::Cluster;
use graph_canvas_layout::{
    CanvasSceneInput, Flow, Layout, LayoutError, RapierLayout, RapierLayoutConfig,
};

/// A unit: how far from holding the tests allow (the "within 1 unit").
const WITHIN: f32 = 1.0;

/// Six communities of twenty, three edges inside each node, one in four joined outside.
fn communities() -> CanvasSceneInput<u32> {
    generate::communities(6, 20, 3, 4, 7)
}

/// One cluster per community of [`communities`].
fn by_community(scene: &CanvasSceneInput<u32>) -> Vec<Cluster<u32>> {
    let mut members = vec![Vec::new(); 6];
    for n in &scene.nodes {
        members[generate::community(n.id, 20)].push(n.id);
    }
    members.into_iter().map(Cluster::new).collect()
}

fn violations(host: &Host<u32>) -> ClusterViolations {
    let bounds = host.layout.cluster_bounds();
    quality::cluster_violations(&host.scene, &host.extras.clusters, bounds, 16.0, WITHIN)
}

/// A host with `clusters`, settled (at most 900 frames); returns it and the frames.
fn settled(
    scene: CanvasSceneInput<u32>,
    config: RapierLayoutConfig,
    clusters: Vec<Cluster<u32>>,
) -> (Host<u32>, usize) {
    let mut host = Host::new(scene, config);
    host.extras.clusters = clusters;
    let frames = host.settle(900);
    (host, frames)
}

#[test]
fn at_rest_every_box_holds_its_members_and_keeps_out_the_rest() {
    let scene = communities();
    let clusters = by_community(&scene);
    let (host, frames) = settled(scene.clone(), RapierLayoutConfig::stress(), clusters);
    assert!(
        host.layout.is_converged(&host.state),
        "not at rest after {frames} frames"
    );
    let v = violations(&host);
    assert!(v.is_empty(), "at rest after {frames} frames: {v:?}");
    let unheld = host.layout.violated_clusters();
    assert!(unheld.is_empty(), "held, yet {unheld:?} listed as not");
    let bounds = host.layout.cluster_bounds();
    assert_eq!(bounds.len(), 6, "one box per cluster");
    assert!(
        bounds.iter().all(|b| b.area() > 0.0),
        "every box holds its members: {bounds:?}"
    );
    // The picture keeps its quality: stress near the unclustered layout's.
    let (plain, _) = settled(scene, RapierLayoutConfig::stress(), Vec::new());
    let s = |h: &Host<u32>| quality::normalized_stress(&h.scene).expect("a connected graph");
    let (clustered, unclustered) = (s(&host), s(&plain));
    assert!(
        clustered <= 1.3 * unclustered,
        "stress {clustered:.4} with clusters against {unclustered:.4} without (more than 1.3 ×)"
    );
}

#[test]
fn nested_clusters_sit_inside_their_parent_apart_from_each_other() {
    let scene = communities();
    let mut clusters = by_community(&scene);
    // Communities 0 and 1 in one parent, whose members are theirs (none listed again).
    clusters.push(Cluster::new(Vec::new()).with_padding(20.0));
    clusters[0] = clusters[0].clone().inside(6);
    clusters[1] = clusters[1].clone().inside(6);
    let (host, frames) = settled(scene, RapierLayoutConfig::stress(), clusters);
    let v = violations(&host);
    assert!(v.is_empty(), "at rest after {frames} frames: {v:?}");
    let b = host.layout.cluster_bounds();
    for child in [0, 1] {
        assert!(
            b[6].contains_box(&b[child]),
            "child {child}'s box {:?} is not inside its parent's {:?}",
            b[child],
            b[6]
        );
    }
}

#[test]
fn a_dragged_member_pushes_the_neighbouring_boxes_away() {
    let scene = communities();
    let clusters = by_community(&scene);
    let (mut host, _) = settled(scene, RapierLayoutConfig::stress(), clusters);
    // Drag a member of cluster 0 towards the centre of cluster 1's box and beyond.
    let member = host.extras.clusters[0].members()[0];
    let target = host.layout.cluster_bounds()[1].center();
    let start = host.pos(&member);
    let step = (target - start) / 60.0;
    host.extras.dragging.insert(member);
    let mut worst_after = 0.0_f32;
    for frame in 1..=90 {
        let to = host.pos(&member) + if frame <= 60 { step } else { Vector2D::zero() };
        host.set_pos(&member, to);
        host.frame(FRAME);
        let v = violations(&host);
        if frame > 10 {
            worst_after = worst_after.max(v.worst);
        }
    }
    assert!(
        worst_after <= WITHIN,
        "dragging member {member} from {start:?} to {target:?}: boxes or outsiders {worst_after:.2} units in after the first 10 frames"
    );
    host.extras.dragging.clear();
    let frames = host.settle(900);
    let v = violations(&host);
    assert!(
        v.is_empty(),
        "at rest {frames} frames after the release: {v:?}"
    );
}

#[test]
fn a_clustered_dag_still_points_down() {
    // A binary tree of 63 nodes.
    let edges: Vec<(u32, u32)> = (1..63).map(|i| ((i - 1) / 2, i)).collect();
    let nodes = (0..63).map(|i| common::node(i, (i % 8) as f32 * 40.0, (i / 8) as f32 * 40.0));
    let scene = CanvasSceneInput::new(
        nodes.collect(),
        edges.iter().map(|&(a, b)| common::edge(a, b)).collect(),
    );
    let under = |top: u32| -> Vec<u32> {
        (0..63)
            .filter(|&i| {
                let mut k = i;
                while k > top {
                    k = (k - 1) / 2;
                }
                k == top
            })
            .collect()
    };
    // Cousins grouped across the halves, against the picture's own grouping.
    let across = |a: u32, b: u32| Cluster::new([under(a), under(b)].concat());
    let clusters = vec![across(3, 6), across(4, 5)];
    let config = RapierLayoutConfig::stress().with_flow(Flow::down(60.0));
    let (host, frames) = settled(scene, config, clusters);
    let v = violations(&host);
    assert!(v.is_empty(), "at rest after {frames} frames: {v:?}");
    let y = |i: u32| host.pos(&i).y;
    let short: Vec<(u32, u32, f32)> = edges
        .iter()
        .map(|&(a, b)| (a, b, y(b) - y(a)))
        .filter(|&(.., drop)| drop < 60.0 - WITHIN)
        .collect();
    assert!(
        short.is_empty(),
        "edges not pointing down by the gap: {short:?}"
    );
}

#[test]
fn a_restored_layout_goes_on_bit_for_bit() {
    let scene = communities();
    let clusters = by_community(&scene);
    let mut host = Host::new(scene, RapierLayoutConfig::stress());
    host.extras.clusters = clusters;
    host.frames(40);
    let text = serde_json::to_string(&host.layout.snapshot()).expect("saved");
    let mut twin = Host::new(host.scene.clone(), RapierLayoutConfig::stress());
    twin.state = host.state.clone();
    twin.extras = host.extras.clone();
    twin.layout = RapierLayout::new(RapierLayoutConfig::stress());
    twin.layout
        .restore(serde_json::from_str(&text).expect("read back"))
        .expect("restored");
    for frame in 1..=60 {
        let (a, b) = (host.frame(FRAME), twin.frame(FRAME));
        let bits = |d: &graph_canvas_layout::DeltaMap<u32>| {
            let mut v: Vec<(u32, u32, u32)> = d
                .iter()
                .map(|(k, p)| (*k, p.x.to_bits(), p.y.to_bits()))
                .collect();
            v.sort_unstable();
            v
        };
        assert_eq!(
            bits(&a),
            bits(&b),
            "the deltas part at frame {frame} after the restore"
        );
        let boxes = |h: &Host<u32>| -> Vec<[u32; 4]> {
            let b: &[Box2D<f32>] = h.layout.cluster_bounds();
            b.iter()
                .map(|b| [b.min.x, b.min.y, b.max.x, b.max.y].map(f32::to_bits))
                .collect()
        };
        assert_eq!(
            boxes(&host),
            boxes(&twin),
            "the boxes part at frame {frame}"
        );
    }
}

/// Whether an error names the bad cluster as it should.
type Named = fn(&LayoutError<u32>) -> bool;

#[test]
fn bad_clusters_are_named_by_try_step_and_left_out_by_step() {
    let scene = communities();
    let good = by_community(&scene);
    let cases: Vec<(Cluster<u32>, Named)> = vec![
        (Cluster::new(vec![999]), |e| {
            matches!(
                e,
                LayoutError::UnknownClusterMember {
                    cluster: 6,
                    node: 999
                }
            )
        }),
        (Cluster::new(Vec::new()).with_padding(f32::NAN), |e| {
            matches!(e, LayoutError::InvalidClusterPadding { cluster: 6, .. })
        }),
        (Cluster::new(Vec::new()).with_padding(-2.0), |e| {
            matches!(e, LayoutError::InvalidClusterPadding { cluster: 6, .. })
        }),
        (Cluster::new(Vec::new()).inside(17), |e| {
            matches!(
                e,
                LayoutError::InvalidClusterParent {
                    cluster: 6,
                    parent: 17
                }
            )
        }),
        (Cluster::new(Vec::new()).inside(6), |e| {
            matches!(
                e,
                LayoutError::InvalidClusterParent {
                    cluster: 6,
                    parent: 6
                }
            )
        }),
    ];
    for (bad, named) in cases {
        let mut host = Host::new(scene.clone(), RapierLayoutConfig::stress());
        host.extras.clusters = good.clone();
        host.extras.clusters.push(bad.clone());
        let before = host.scene.clone();
        let error = host
            .try_frame(FRAME)
            .expect_err("try_step refuses a bad cluster");
        assert!(named(&error), "{bad:?}: {error}");
        assert!(
            !host.layout.has_world(),
            "{bad:?}: the refused call built a world"
        );
        assert_eq!(
            host.scene.nodes, before.nodes,
            "{bad:?}: the refused call moved nodes"
        );
        host.settle(900);
        assert!(
            host.layout.skipped().iter().any(named),
            "{bad:?}: step does not list it: {:?}",
            host.layout.skipped()
        );
        // The rest is held: the good clusters as if the bad one were not there.
        host.extras.clusters.pop();
        let v = violations(&host);
        assert!(v.is_empty(), "{bad:?}: the good clusters at rest: {v:?}");
    }
    // A node in two clusters that do not nest: named, and the second listing left out.
    let mut host = Host::new(scene, RapierLayoutConfig::stress());
    host.extras.clusters = good.clone();
    let stray = good[0].members()[0];
    host.extras.clusters[1] = Cluster::new([good[1].members(), &[stray]].concat());
    let error = host
        .try_frame(FRAME)
        .expect_err("a node in two sibling clusters");
    assert!(
        matches!(error, LayoutError::NodeInTwoClusters { node, first: 0, second: 1 } if node == stray),
        "{error}"
    );
    host.settle(900);
    assert_eq!(
        host.layout.skipped().len(),
        1,
        "{:?}",
        host.layout.skipped()
    );
    host.extras.clusters[1] = good[1].clone();
    let v = violations(&host);
    assert!(
        v.is_empty(),
        "with node {stray} kept in cluster 0 alone: {v:?}"
    );
}

#[test]
fn collapsed_and_expanded_the_members_come_back_around_the_collapsed_node() {
    let scene = communities();
    let clusters = by_community(&scene);
    let (mut host, _) = settled(scene, RapierLayoutConfig::stress(), clusters);
    // Collapse cluster 2: its members out, one node in at the box's centre, joined to
    // whatever the members were joined to outside; the cluster goes from the list.
    let members: Vec<u32> = host.extras.clusters[2].members().to_vec();
    let inside = |id: u32| members.contains(&id);
    let centre = host.layout.cluster_bounds()[2].center();
    let saved: Vec<(u32, Vector2D<f32>)> = members
        .iter()
        .map(|&m| (m, host.pos(&m) - centre))
        .collect();
    let saved_edges: Vec<(u32, u32)> = host
        .scene
        .edges
        .iter()
        .filter(|e| inside(e.source) || inside(e.target))
        .map(|e| (e.source, e.target))
        .collect();
    const COLLAPSED: u32 = 1_000;
    host.scene.nodes.retain(|n| !inside(n.id));
    host.scene
        .edges
        .retain(|e| !inside(e.source) && !inside(e.target));
    host.scene
        .nodes
        .push(common::node(COLLAPSED, centre.x, centre.y));
    let mut outside: Vec<u32> = saved_edges
        .iter()
        .flat_map(|&(a, b)| [a, b])
        .filter(|&id| !inside(id))
        .collect();
    outside.sort_unstable();
    outside.dedup();
    host.scene
        .edges
        .extend(outside.iter().map(|&o| common::edge(COLLAPSED, o)));
    host.extras.clusters.remove(2);
    host.settle(900);
    // Expand: the members back where they sat around the centre, now around the node.
    let at = host.pos(&COLLAPSED);
    host.scene.nodes.retain(|n| n.id != COLLAPSED);
    host.scene
        .edges
        .retain(|e| e.source != COLLAPSED && e.target != COLLAPSED);
    for &(m, offset) in &saved {
        host.scene
            .nodes
            .push(common::node(m, at.x + offset.x, at.y + offset.y));
    }
    host.scene
        .edges
        .extend(saved_edges.iter().map(|&(a, b)| common::edge(a, b)));
    host.extras
        .clusters
        .insert(2, Cluster::new(members.clone()));
    let frames = host.settle(900);
    let v = violations(&host);
    assert!(
        v.is_empty(),
        "at rest {frames} frames after the expansion: {v:?}"
    );
    let sum = members
        .iter()
        .fold(Vector2D::zero(), |s, m| s + host.pos(m).to_vector());
    let centroid = (sum / members.len() as f32).to_point();
    let b = host.layout.cluster_bounds()[2];
    let half_diagonal = 0.5 * (b.max - b.min).length();
    assert!(
        (centroid - at).length() <= half_diagonal,
        "the expanded members rest around {centroid:?}, {:.0} units from the collapsed node's {at:?} (box half diagonal {half_diagonal:.0})",
        (centroid - at).length()
    );
}

#[test]
fn the_same_clusters_again_are_no_edit_and_a_changed_one_is() {
    let scene = communities();
    let mut clusters = by_community(&scene);
    // A bad padding too: a NaN equals itself here, so the same list is the same.
    clusters.push(Cluster::new(Vec::new()).with_padding(f32::NAN));
    let (mut host, frames) = settled(scene, RapierLayoutConfig::stress(), clusters);
    assert!(
        host.layout.is_converged(&host.state),
        "not at rest after {frames} frames"
    );
    // The host builds its list anew every frame, equal to the last.
    for frame in 1..=5 {
        host.extras.clusters = host.extras.clusters.to_vec();
        let moved = host.frame(FRAME);
        assert!(
            moved.is_empty(),
            "frame {frame} with the same clusters moved {} nodes",
            moved.len()
        );
    }
    // Cluster 0 takes a wider padding: its box grows into its neighbours'.
    host.extras.clusters[0] = host.extras.clusters[0].clone().with_padding(40.0);
    let members = host.extras.clusters[0].members().to_vec();
    let moved = host.frame(FRAME);
    assert!(
        members.iter().any(|m| moved.contains_key(m)),
        "the changed cluster's members did not move in the first frame after the edit"
    );
    let frames = host.settle(900);
    let v = violations(&host);
    assert!(
        v.is_empty(),
        "at rest {frames} frames after the edit: {v:?}"
    );
}

/// Label boxes (`with_rect`, 42 to 56 units wide and 20 high): a box is made from the
/// members' rectangles and parts the outsiders' rectangles, not their disks, so a wide
/// label stays inside its cluster and an outsider's label stays out (the check reads
/// the rectangles); every third node keeps a disk.
#[test]
fn label_boxes_stay_inside_their_cluster_and_outside_the_others() {
    let scene = generate::label_boxes(communities(), |id| id % 3 == 0);
    let clusters = by_community(&scene);
    let (host, frames) = settled(scene, RapierLayoutConfig::stress(), clusters);
    assert!(
        host.layout.is_converged(&host.state),
        "not at rest after {frames} frames"
    );
    let v = violations(&host);
    assert!(
        v.is_empty(),
        "label boxes at rest after {frames} frames: {v:?}"
    );
}

/// Clusters that cannot hold are listed: a member pinned inside another cluster's box,
/// where the pinned box cannot give way, leaves both boxes overlapping, and the layout
/// says which; unpinned, the boxes part and the list empties.
#[test]
fn clusters_that_cannot_hold_are_listed_and_the_list_empties_when_they_can() {
    let mut host = common::clusters_held_overlapping();
    let frames = host.settle(900);
    assert!(
        host.layout.is_converged(&host.state),
        "not at rest after {frames} frames"
    );
    let v = violations(&host);
    assert!(
        v.overlapping_siblings > 0,
        "the pins hold the boxes overlapping: {v:?}"
    );
    assert_eq!(
        host.layout.violated_clusters(),
        &[0, 1],
        "both overlapping boxes listed, at rest after {frames} frames"
    );
    host.frames(3);
    assert_eq!(
        host.layout.violated_clusters(),
        &[0, 1],
        "the list stands while the layout rests"
    );
    host.extras.pinned.remove(&2);
    let frames = host.settle(900);
    let v = violations(&host);
    assert!(v.is_empty(), "unpinned, held after {frames} frames: {v:?}");
    assert!(
        host.layout.violated_clusters().is_empty(),
        "held, listed none: {:?}",
        host.layout.violated_clusters()
    );
}
