//! A stress layout's new world ([`RapierLayoutConfig::stress`](crate::RapierLayoutConfig::stress)): the length of a hop its
//! edge springs rest at, and, for the first world with [`StressStart::Global`], a start
//! that is already a layout (`stress/start.rs`), turned to sit where the host's held
//! nodes (pinned or dragged) are.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::Vector;

use super::model::SparseStress;
use super::start::{global_start, StartPlan};
use crate::config::{StressModel, StressStart};
use crate::graph::{Graph, UNREACHED};
use crate::input::layout::LayoutExtras;
use crate::input::scene::CanvasSceneInput;
use crate::input::topology::Topology;
use crate::world::bindings::ColliderSpec;
use crate::world::RapierSceneWorld;

/// The gap, in world units, the hop length leaves between two seated disks.
const SEAT_GAP: f32 = 2.0;

/// Where a stress layout's new world comes from: what the layout knew before it.
pub(crate) struct WorldOrigin {
    /// The hop length of the world this one replaces, if any.
    pub(crate) previous_hop: Option<f32>,
    /// Whether this is the layout's first world.
    pub(crate) first: bool,
    /// Whether the first world starts cold on the host's picture
    /// ([`RapierLayout::at_rest`](crate::RapierLayout::at_rest)).
    pub(crate) cold_start: bool,
}

/// Hard constraints on the start: `hold(positions by slot, world units per unit)` after
/// each descent pass, and whether there are any (a start with them is shifted onto the
/// held nodes, not turned).
pub(crate) struct StartConstraints<'a> {
    pub(crate) hold: &'a mut dyn FnMut(&mut [[f32; 2]], f32),
    pub(crate) any: bool,
}

/// For a stress layout's new `world` (its bodies inserted, its joints not yet):
/// chooses the hop length and, on the first world with a global start, moves the
/// bodies to the start layout. Returns the model built on the way, for the force.
pub(crate) fn start_world<N: Clone + Eq + Hash>(
    stress: StressModel,
    origin: WorldOrigin,
    world: &mut RapierSceneWorld<N>,
    (scene, topology, extras): (&CanvasSceneInput<N>, &Topology, &LayoutExtras<N>),
    constraints: StartConstraints<'_>,
) -> SparseStress {
    let edges: Vec<(usize, usize)> = topology
        .edges
        .iter()
        .zip(&topology.weights)
        .filter(|(_, &w)| w > 0.0)
        .filter_map(|(&(a, b), _)| {
            Some((
                world.slot_of(&scene.nodes[a].id)?,
                world.slot_of(&scene.nodes[b].id)?,
            ))
        })
        .collect();
    let graph = Graph::new(world.slot_count(), edges.iter().copied());
    let model = SparseStress::new(
        &graph,
        stress.pivot_count(graph.len()),
        stress.exact_hops.max(1),
    );
    let global = origin.first && !origin.cold_start && stress.start == StressStart::Global;
    let hop = match origin.previous_hop {
        Some(hop) if !global => hop,
        _ if global || (stress.start == StressStart::HostPositions && stress.fit_length) => {
            let plan = plan_for(&stress, world, graph.len());
            let radii: Vec<f32> = (0..world.slot_count())
                .map(|s| seating_radius(world.shape_at(s)))
                .collect();
            let start = global_start(&graph, &model, &radii, plan, constraints.hold);
            if global {
                place(world, start.positions, (scene, extras), !constraints.any);
            }
            start.hop_length
        }
        // A saved picture: the scale it was drawn at.
        _ if origin.cold_start => picture_scale(world, &graph, &model).unwrap_or(stress.hop_length),
        _ => stress.hop_length,
    };
    world.set_hop_length(hop);
    model
}

/// The radius a node counts with when the hop length is fitted: a disk's own, and for a
/// box that of the disk of the same area. A box's bounding circle (66 units across for a
/// 63 × 20 label) would spread the picture for the corners' sake; the contacts part what
/// the area-equal disks leave touching.
fn seating_radius(shape: ColliderSpec) -> f32 {
    match shape {
        ColliderSpec::Circle { radius } => radius,
        _ => (shape.area() / std::f32::consts::PI).sqrt(),
    }
}

/// How the start is made for `nodes` nodes, centred where the world's bodies are.
fn plan_for<N: Clone + Eq + Hash>(
    stress: &StressModel,
    world: &RapierSceneWorld<N>,
    nodes: usize,
) -> StartPlan {
    let n = world.slot_count().max(1) as f32;
    let centre = (0..world.slot_count())
        .map(|s| world.position_at(s).to_vector() / n)
        .fold(Vector2D::zero(), |a, b| a + b)
        .to_point();
    StartPlan {
        min_length: if stress.hop_length.is_finite() && stress.hop_length > 0.0 {
            stress.hop_length
        } else {
            100.0
        },
        fit: stress.fit_length,
        gap: SEAT_GAP,
        passes: stress.passes_for(nodes),
        centre,
    }
}

/// Moves every body to its start position, the start turned (when `turn`) and shifted
/// to put the host's held nodes (pinned or dragged, which stay where the host has them)
/// as near their own positions as a rigid motion can. A start under constraints is
/// only shifted: a turn would point a flow elsewhere.
fn place<N: Clone + Eq + Hash>(
    world: &mut RapierSceneWorld<N>,
    mut positions: Vec<Point2D<f32>>,
    (scene, extras): (&CanvasSceneInput<N>, &LayoutExtras<N>),
    turn: bool,
) {
    let held: Vec<(usize, Point2D<f32>)> = scene
        .nodes
        .iter()
        .filter(|n| extras.pinned.contains(&n.id) || extras.dragging.contains(&n.id))
        .filter_map(|n| Some((world.slot_of(&n.id)?, n.position)))
        .collect();
    align(&mut positions, &held, turn);
    for (s, p) in positions.into_iter().enumerate() {
        if p.is_finite() {
            world
                .body_at_mut(s)
                .set_translation(Vector::new(p.x, p.y), true);
        }
    }
}

/// The rigid motion (a turn, perhaps a mirror, and a shift; only the shift unless
/// `turns`) that puts `positions[s]` nearest `target` over the `held` pairs, applied to
/// every position.
fn align(positions: &mut [Point2D<f32>], held: &[(usize, Point2D<f32>)], turns: bool) {
    if held.is_empty() {
        return;
    }
    let count = held.len() as f32;
    let mean = |points: &mut dyn Iterator<Item = Point2D<f32>>| {
        points.fold(Vector2D::zero(), |a, p| a + p.to_vector() / count)
    };
    let from = mean(&mut held.iter().map(|&(s, _)| positions[s]));
    let to = mean(&mut held.iter().map(|&(_, p)| p));
    // The best turn (and mirror) from the covariance of the centred pairs.
    let (mut sxx, mut sxy, mut syx, mut syy) = (0.0_f32, 0.0, 0.0, 0.0);
    for &(s, p) in held {
        let (a, b) = (positions[s].to_vector() - from, p.to_vector() - to);
        sxx += a.x * b.x;
        sxy += a.x * b.y;
        syx += a.y * b.x;
        syy += a.y * b.y;
    }
    let turn = (sxy - syx).atan2(sxx + syy);
    let mirrored_turn = (sxy + syx).atan2(sxx - syy);
    let fit = |mirror: bool, angle: f32| {
        let (sin, cos) = angle.sin_cos();
        move |v: Vector2D<f32>| {
            let v = if mirror { Vector2D::new(v.x, -v.y) } else { v };
            Vector2D::new(cos * v.x - sin * v.y, sin * v.x + cos * v.y)
        }
    };
    let error = |f: &dyn Fn(Vector2D<f32>) -> Vector2D<f32>| -> f32 {
        held.iter()
            .map(|&(s, p)| {
                (f(positions[s].to_vector() - from) + to - p.to_vector()).square_length()
            })
            .sum()
    };
    let plain = fit(false, turn);
    let mirrored = fit(true, mirrored_turn);
    let best: &dyn Fn(Vector2D<f32>) -> Vector2D<f32> = if !turns {
        &|v| v
    } else if held.len() > 1 && error(&mirrored) < error(&plain) {
        &mirrored
    } else if held.len() > 1 {
        &plain
    } else {
        &|v| v
    };
    for p in positions.iter_mut() {
        *p = (best(p.to_vector() - from) + to).to_point();
    }
}

/// The hop length the world's bodies are drawn at: the scale that fits their distances
/// to the model's terms best (least squares over the edges and pivot terms).
fn picture_scale<N: Clone + Eq + Hash>(
    world: &RapierSceneWorld<N>,
    graph: &Graph,
    model: &SparseStress,
) -> Option<f32> {
    let (mut num, mut den) = (0.0_f64, 0.0_f64);
    let mut add = |i: usize, j: usize, d: f64, w: f64| {
        let e = f64::from((world.position_at(i) - world.position_at(j)).length());
        if e.is_finite() {
            num += w * e * d;
            den += w * d * d;
        }
    };
    for i in 0..graph.len() {
        for &j in graph.neighbours(i) {
            add(i, j as usize, 1.0, 1.0);
        }
        let (pivots, hops) = model.pivot_terms(i);
        for (&p, &h) in pivots.iter().zip(hops) {
            if h >= 2 && h != UNREACHED {
                let d = f64::from(h);
                add(i, p as usize, d, 1.0 / (d * d));
            }
        }
    }
    let scale = (num / den) as f32;
    (den > 0.0 && scale.is_finite() && scale > 0.0).then_some(scale)
}
