//! Cooling and the force-directed preset: every shipped graph comes to rest in bounded
//! time without overlaps, stays exactly still once at rest, and wakes again (and
//! settles again) when the user drags a node or the graph is edited.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{quality, CanvasSceneInput, Layout, RapierLayoutConfig};

/// d3-force stops after 300 ticks; the target is at most twice that.
const SETTLE_BUDGET: usize = 600;

#[test]
fn every_shipped_graph_settles_within_twice_d3s_ticks_without_overlaps() {
    for name in [
        "karate",
        "les_miserables",
        "florentine",
        "n200_e500",
        "tree_1023",
        "grid_30x30",
        "n1000_e2500",
    ] {
        let mut host = Host::new(load_scene(name), RapierLayoutConfig::force_directed());
        let frames = host.settle(SETTLE_BUDGET);
        let overlaps = quality::overlapping_pairs(&host.scene, 16.0, 0.5);
        assert_eq!(
            overlaps, 0,
            "{name}: {overlaps} overlapping pairs after {frames} frames"
        );
        // At rest means still: nothing is reported for a further two seconds.
        let before = positions(&host.scene);
        for frame in 0..120 {
            let deltas = host.frame(FRAME);
            assert!(
                deltas.is_empty(),
                "{name}: {} nodes moved {frame} frames after rest",
                deltas.len()
            );
        }
        assert_eq!(before, positions(&host.scene), "{name}");
        // Rest is a spread layout, not a frozen explosion or a collapse: mean edge length
        // within [0.9, 3.5] × rest length (d3-force: 104 to 261 on these graphs; springs
        // that outlast repulsion draw edges to their rest length, and a dense core, its
        // nodes held apart by contacts, keeps some shorter).
        let mean = quality::mean_edge_length(&host.scene).unwrap();
        assert!(
            (90.0..350.0).contains(&mean),
            "{name}: mean edge length {mean} at rest"
        );
    }
}

#[test]
fn heat_falls_over_the_schedule_and_stops_at_its_floor() {
    let config = RapierLayoutConfig::force_directed();
    let cooling = config.cooling.unwrap();
    let mut host = Host::new(load_scene("florentine"), config);
    host.frame(FRAME);
    let first = host.layout.heat().unwrap();
    host.frames(59);
    let after_one_second = host.layout.heat().unwrap();
    // Geometric decay: after t seconds, min_alpha^(t / duration).
    let expected = cooling.min_alpha.powf(1.0 / cooling.duration);
    assert!(
        (after_one_second - expected).abs() < 1e-3,
        "heat after 1 s: {after_one_second}, expected {expected}"
    );
    assert!(first > after_one_second, "{first} then {after_one_second}");
    host.frames((cooling.duration * 60.0) as usize);
    assert_eq!(host.layout.heat(), Some(cooling.min_alpha));
    assert_eq!(
        RapierLayoutConfig::default().cooling,
        None,
        "the physical default does not cool"
    );
}

#[test]
fn a_drag_reheats_the_whole_layout_without_a_reach() {
    // `reheat_hops: None` is d3-force's whole-graph reheat.
    let mut config = RapierLayoutConfig::force_directed();
    if let Some(cooling) = config.cooling.as_mut() {
        cooling.reheat_hops = None;
    }
    let cooling = config.cooling.unwrap();
    let mut host = Host::new(load_scene("les_miserables"), config);
    host.settle(SETTLE_BUDGET);
    let grabbed = 11; // Valjean, the hub
    let neighbour = 48;
    let neighbour_before = host.pos(&neighbour);
    host.extras.dragging.insert(grabbed);
    let start = host.pos(&grabbed);
    for k in 1..=20 {
        host.set_pos(
            &grabbed,
            start + Point2D::new(15.0 * k as f32, 0.0).to_vector(),
        );
        host.frame(FRAME);
        // Reheated to 1 before the call, then cooled over its frame.
        let hot = cooling.cooled(1.0, FRAME);
        assert_eq!(host.layout.heat(), Some(hot), "frame {k} of the drag");
        assert!(!host.layout.is_converged(&host.state));
    }
    host.extras.dragging.clear();
    // Asleep, the neighbour would not move at all; woken, its spring drags it along
    // (a soft one: its share is 1 / its own degree).
    let moved = dist(host.pos(&neighbour), neighbour_before);
    assert!(
        moved > 20.0,
        "dragging the hub 300 units moved its neighbour only {moved}"
    );
    let frames = host.settle(SETTLE_BUDGET);
    assert!(
        host.pos(&grabbed).x > start.x + 100.0,
        "the hub went back to {:?} from {start:?}",
        host.pos(&grabbed)
    );
    assert!(
        frames > 60,
        "settled after only {frames} frames: the drag did not reheat"
    );
}

#[test]
fn an_edit_heats_its_neighbourhood_without_a_rebuild() {
    let mut host = Host::new(load_scene("karate"), RapierLayoutConfig::force_directed());
    host.settle(SETTLE_BUDGET);
    // A new leaf in free space, 150 units beyond the outermost node, joined to it.
    let centre = host
        .scene
        .nodes
        .iter()
        .fold(Point2D::origin(), |c, n| c + n.position.to_vector() / 34.0);
    let outer = host
        .scene
        .nodes
        .iter()
        .max_by(|a, b| dist(a.position, centre).total_cmp(&dist(b.position, centre)))
        .map(|n| n.id)
        .unwrap();
    let at = host.pos(&outer) + (host.pos(&outer) - centre).normalize() * 150.0;
    host.scene.nodes.push(node(100, at.x, at.y));
    host.scene.edges.push(edge(outer, 100));
    host.frame(FRAME);
    assert_eq!(host.layout.rebuild_count(), 1);
    assert_eq!(host.layout.patch_count(), 1);
    let cooling = host.layout.config.cooling.unwrap();
    // The layout stays cold; the new node and its neighbour are heated, as by a reheat
    // to 1 cooled over one frame.
    assert_eq!(host.layout.heat(), Some(cooling.min_alpha));
    let hot = cooling.cooled(1.0, FRAME);
    for id in [100, outer] {
        assert_eq!(host.layout.node_heat(&id), Some(hot), "node {id}");
    }
    host.settle(SETTLE_BUDGET);
    let gap = dist(host.pos(&100), host.pos(&outer));
    assert!(
        (32.0..300.0).contains(&gap),
        "the new leaf settled {gap} from its neighbour (rest length 100, radius 16 each)"
    );
    assert_eq!(quality::overlapping_pairs(&host.scene, 16.0, 0.5), 0);
}

#[test]
fn a_node_added_on_top_of_another_is_seated_and_heats_nothing() {
    let mut host = Host::new(load_scene("karate"), RapierLayoutConfig::force_directed());
    host.settle(SETTLE_BUDGET);
    let anchor = host.pos(&0);
    host.scene
        .nodes
        .push(node(100, anchor.x + 5.0, anchor.y + 5.0));
    host.scene.edges.push(edge(0, 100));
    let deltas = host.frame(FRAME);
    let cooling = host.layout.config.cooling.unwrap();
    // Seated an edge length from its hub (the first call reports the way there), it
    // settles as a thrown node coasts; the hub and the rest of the layout stay cold.
    let seated = dist(host.pos(&100), host.pos(&0));
    assert!(
        (90.0..200.0).contains(&seated) && deltas[&100].length() > 60.0,
        "seated {seated} from its hub, moved {:?} in the first call",
        deltas[&100]
    );
    assert_eq!(host.layout.heat(), Some(cooling.min_alpha));
    assert_eq!(
        host.layout.node_heat(&0),
        Some(cooling.min_alpha),
        "the hub"
    );
    let coasting = host.layout.node_heat(&100).unwrap();
    assert!(
        coasting < 0.01,
        "the seated node is heated to {coasting}, not a coasting heat"
    );
    host.settle(SETTLE_BUDGET);
    // Not heated, the hub rests where it was (a contact with the seated leaf could nudge
    // it, well under a unit).
    let moved = dist(host.pos(&0), anchor);
    assert!(moved < 1.0, "the hub moved {moved} units");
    assert_eq!(quality::overlapping_pairs(&host.scene, 16.0, 0.5), 0);
}

#[test]
fn switching_cooling_off_gives_the_springs_their_full_stiffness() {
    let mut host = Host::new(
        load_scene("florentine"),
        RapierLayoutConfig::force_directed(),
    );
    host.settle(SETTLE_BUDGET);
    // At rest the heat is at its floor, and the next call tunes the springs to it.
    host.frame(FRAME);
    let scale = host.layout.world().unwrap().spring_scale();
    let heat = host.layout.heat().unwrap();
    let exponent = host.layout.config.cooling.unwrap().spring_exponent;
    let expected = heat.powf(exponent);
    assert!(
        scale < 0.5 && (scale - expected).abs() <= 1e-6 * scale,
        "a cooled layout (heat {heat}, springs at heat^{exponent} = {expected}) has springs \
         at {scale} of their stiffness"
    );
    host.layout.config.cooling = None;
    host.frame(FRAME);
    assert_eq!(host.layout.heat(), None);
    // Exactly 1: the scale is set, not computed.
    let world = host.layout.world().unwrap();
    assert_eq!(world.spring_scale().to_bits(), 1.0_f32.to_bits());
    assert_eq!(world.applied_spring_scale().to_bits(), 1.0_f32.to_bits());
}

#[test]
fn a_graph_stopped_at_the_end_of_its_schedule_wakes_for_a_drag() {
    // A large connected graph is one rapier island that a few jostling contacts keep
    // awake; the end of the schedule stops it.
    let mut host = Host::new(
        load_scene("n1000_e2500"),
        RapierLayoutConfig::force_directed(),
    );
    host.settle(SETTLE_BUDGET);
    let fastest = (0..1000_u32)
        .filter_map(|id| host.layout.world().unwrap().linear_velocity(&id))
        .map(|v| v.length())
        .fold(0.0_f32, f32::max);
    let deltas = host.frame(FRAME);
    assert!(
        deltas.is_empty() && fastest <= 5.0,
        "converged, yet {} nodes moved the next frame (fastest body {fastest} units/s)",
        deltas.len()
    );
    let before = positions(&host.scene);
    host.extras.dragging.insert(0);
    let start = host.pos(&0);
    for k in 1..=10 {
        host.set_pos(&0, start + Point2D::new(20.0 * k as f32, 0.0).to_vector());
        host.frame(FRAME);
    }
    host.extras.dragging.clear();
    let followers = host
        .scene
        .nodes
        .iter()
        .filter(|n| n.id != 0 && dist(n.position, before[&n.id]) > 1.0)
        .count();
    assert!(
        followers > 0,
        "dragging node 0 by 200 units moved no other node by more than 1 unit"
    );
    let frames = host.settle(SETTLE_BUDGET);
    assert!(frames > 60, "back at rest after only {frames} frames");
}

#[test]
fn the_fast_variant_settles_a_thousand_nodes_with_few_overlaps() {
    let mut host = Host::new(
        load_scene("n1000_e2500"),
        RapierLayoutConfig::force_directed_fast(),
    );
    let frames = host.settle(SETTLE_BUDGET);
    let mean = quality::mean_edge_length(&host.scene).unwrap();
    assert!(
        (100.0..350.0).contains(&mean),
        "mean edge length {mean} at rest after {frames} frames"
    );
    // No colliders: repulsion alone keeps nodes apart. d3-force leaves 347 overlapping
    // pairs on this graph; fewer than one per node is the bound here.
    let overlaps = quality::overlapping_pairs(&host.scene, 16.0, 0.5);
    assert!(overlaps < 1000, "{overlaps} overlapping pairs");
}

#[test]
fn hot_contacts_let_nodes_through_early_and_part_them_at_rest() {
    // Two nodes of radius 16 with centres 12 apart: 20 units of overlap, nothing else.
    let overlapping = || CanvasSceneInput {
        nodes: vec![node(0, 0.0, 0.0), node(1, 12.0, 0.0)],
        ..Default::default()
    };
    let config = |hot: Option<f32>| {
        let mut config = RapierLayoutConfig::force_directed();
        config.repulsion = None;
        if let Some(cooling) = config.cooling.as_mut() {
            cooling.hot_contact_frequency = hot;
            cooling.first_contact_heat = None;
        }
        config
    };
    let mut soft = Host::new(overlapping(), config(Some(5.0)));
    let mut firm = Host::new(overlapping(), config(None));
    soft.frame(FRAME);
    firm.frame(FRAME);
    let (soft_gap, firm_gap) = (
        dist(soft.pos(&0), soft.pos(&1)),
        dist(firm.pos(&0), firm.pos(&1)),
    );
    assert!(
        soft_gap < 0.5 * (firm_gap - 12.0) + 12.0,
        "after one hot frame: 5 Hz contacts opened the gap to {soft_gap}, firm ones to {firm_gap}"
    );
    let frames = soft.settle(SETTLE_BUDGET);
    let gap = dist(soft.pos(&0), soft.pos(&1));
    assert!(
        gap >= 31.5,
        "at rest after {frames} frames the contacts are firm: centres {gap} apart (radii 16)"
    );
}

#[test]
fn the_first_unfolding_leaves_contacts_out_and_later_reheats_keep_them() {
    // Nodes 0 and 1 overlap by 20 units; node 2 is far away, to be dragged later.
    let scene = CanvasSceneInput {
        nodes: vec![node(0, 0.0, 0.0), node(1, 12.0, 0.0), node(2, 500.0, 0.0)],
        ..Default::default()
    };
    let mut config = RapierLayoutConfig::force_directed();
    config.repulsion = None;
    let gate = config.cooling.unwrap().first_contact_heat.unwrap();
    let mut host = Host::new(scene, config);
    host.frames(10);
    let heat = host.layout.heat().unwrap();
    let gap = dist(host.pos(&0), host.pos(&1));
    assert!(
        heat > gate && (gap - 12.0).abs() < 1e-3,
        "at heat {heat} (contacts from {gate}) the overlapping pair moved to {gap} apart"
    );
    let frames = host.settle(SETTLE_BUDGET);
    let gap = dist(host.pos(&0), host.pos(&1));
    assert!(
        gap >= 31.5,
        "at rest after {frames} frames contacts parted the pair: {gap} apart"
    );
    // A drag reheats to full heat; contacts stay on: dragged to 10 units from node 0,
    // node 2 pushes it.
    let before = host.pos(&0);
    let target = Point2D::new(before.x + 10.0, before.y);
    host.extras.dragging.insert(2);
    host.set_pos(&2, target);
    host.frames(3);
    assert!(
        host.layout.world().unwrap().contacts_enabled(),
        "contacts stay on after the first unfolding"
    );
    let pushed = dist(host.pos(&0), before);
    assert!(
        pushed > 5.0,
        "node 2 dragged next to node 0 pushed it only {pushed} (contacts off after a reheat?)"
    );
}

#[test]
fn a_drag_during_the_first_unfolding_lets_contacts_in() {
    let scene = CanvasSceneInput {
        nodes: vec![node(0, 0.0, 0.0), node(2, 500.0, 0.0)],
        ..Default::default()
    };
    let mut config = RapierLayoutConfig::force_directed();
    config.repulsion = None;
    let mut host = Host::new(scene, config);
    host.frames(5);
    assert!(
        !host.layout.world().unwrap().contacts_enabled(),
        "contacts are out of the first unfolding at heat {:?}",
        host.layout.heat()
    );
    let before = host.pos(&0);
    host.extras.dragging.insert(2);
    host.set_pos(&2, Point2D::new(before.x + 10.0, before.y));
    host.frames(10);
    let pushed = dist(host.pos(&0), before);
    assert!(
        pushed > 5.0,
        "node 2 dragged next to node 0 in the first second pushed it only {pushed}"
    );
}

#[test]
fn a_configuration_change_moves_a_stopped_layout() {
    let mut host = Host::new(
        load_scene("florentine"),
        RapierLayoutConfig::force_directed(),
    );
    host.settle(SETTLE_BUDGET);
    assert!(host.frame(FRAME).is_empty(), "at rest");
    let before = positions(&host.scene);
    if let Some(repulsion) = host.layout.config.repulsion.as_mut() {
        repulsion.strength *= 4.0;
    }
    host.frames(30);
    let moved = farthest_moved(&host.scene, &before);
    assert!(
        moved > 10.0,
        "four times the repulsion moved no node more than {moved} in half a second"
    );
}

#[test]
fn a_graph_too_dense_for_its_rest_lengths_is_not_packed_into_overlaps_as_it_cools() {
    // A random graph of 1,000 nodes and 2,500 edges, its median spring far over twice
    // its rest length. At rest: the overlapping pairs; at the start of the last tenth of
    // the schedule: the factor the springs have beside heat^0.7, the factor of springs
    // that outlast repulsion.
    let run = |stretch_limit: Option<f32>| {
        let mut config = RapierLayoutConfig::force_directed();
        config.cooling.as_mut().unwrap().stretch_limit = stretch_limit;
        let frames = (config.cooling.unwrap().duration * 60.0) as usize;
        let mut host = Host::new(load_scene("n1000_e2500"), config);
        host.frames(frames * 9 / 10);
        let world = host.layout.world().unwrap();
        let springs = (world.applied_spring_scale(), world.spring_scale());
        host.settle(SETTLE_BUDGET);
        let overlaps = quality::overlapping_pairs(&host.scene, 16.0, 0.5);
        (overlaps, springs)
    };
    let limit = RapierLayoutConfig::force_directed()
        .cooling
        .unwrap()
        .stretch_limit;
    let (limited, (springs, outlasting)) = run(limit);
    let (unlimited, (full, outlasting_too)) = run(None);
    // The springs' median length is beyond twice their rest length: they are blended
    // toward the heat (a tenth below heat^0.7 or more: the blend grows with the stretch
    // from 0 at twice the rest length to 1 at four times).
    assert!(
        springs < 0.9 * outlasting,
        "springs at {springs}, heat^0.7 at {outlasting}"
    );
    assert_eq!(
        full.to_bits(),
        outlasting_too.to_bits(),
        "without the limit springs follow heat^0.7"
    );
    // Without it the long springs pack the graph tighter than contacts can part.
    assert!(
        limited * 4 <= unlimited,
        "{limited} overlapping pairs at rest, {unlimited} without the limit"
    );
}

#[test]
fn graphs_near_their_rest_lengths_keep_springs_that_outlast_repulsion() {
    let mut host = Host::new(
        load_scene("les_miserables"),
        RapierLayoutConfig::force_directed(),
    );
    host.frames(300);
    let world = host.layout.world().unwrap();
    // Below the limit the springs have exactly the factor that outlasts repulsion,
    assert_eq!(
        world.applied_spring_scale().to_bits(),
        world.spring_scale().to_bits(),
        "springs at {}, heat^0.7 at {}",
        world.applied_spring_scale(),
        world.spring_scale()
    );
    // which follows heat^0.7 in 5 % steps, re-tuned at the start of a frame; the heat
    // is read at its end, 1 % cooler: within 7 %.
    let heat = host.layout.heat().unwrap();
    let expected = heat.powf(0.7);
    assert!(
        (world.spring_scale() / expected - 1.0).abs() <= 0.07,
        "springs {} at heat {heat}, expected about {expected}",
        world.spring_scale()
    );
}
