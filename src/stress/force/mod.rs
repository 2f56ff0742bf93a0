//! The stress model's pull ([`StressModel`](crate::config::StressModel)): every node kept at its
//! graph distance from the nodes near it and from its component's pivots, by springs of
//! rest length `hops × hop length` and stiffness `edge stiffness × weight` (`1 / hops²`
//! for exact terms, `s / hops²` for a pivot standing for `s` nodes; `stress/model.rs`).
//! The edges themselves are the world's springs (`forces/springs.rs`). Each term pulls its own
//! node only, and reports its stiffness, so the step (`simulate/combine.rs`) takes an implicit step on it
//! as on the springs: stable at any stiffness. The terms scale with the world's spring
//! scale (the heat), so the balance they rest at is the same at every heat.
//!
//! The model is built from the world's joints (hop distances by breadth-first search
//! from every pivot) and built again when the graph's nodes or edges change.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};

use crate::forces::targets::NodeTargets;
use crate::forces::{BodyForce, ForceContext, ForceSums, Lane, SpareFrame};
use sums::{padded, pivot_pull};

mod sums;
use super::model::{Reach, SparseStress};
use crate::config::RapierLayoutConfig;
use crate::parallel;
use crate::world::RapierSceneWorld;

/// The stress terms of a world, and the pivot terms' last sums.
#[derive(Clone, Debug, Default, serde::Serialize, serde::Deserialize)]
pub(crate) struct StressForce {
    /// The world version the model was checked against (a restored force checks it
    /// again), and the shape it was built for (a hash of node serials in slot order and
    /// of the joints), with its settings.
    #[serde(skip)]
    version: Option<u64>,
    shape: Shape,
    model: SparseStress,
    /// Per slot, the pivot terms' force and stiffness as last worked out, and the
    /// substeps since.
    pivot_force: Vec<Vector2D<f32>>,
    pivot_stiffness: Vec<f32>,
    pivot_at: Vec<Point2D<f32>>,
    since: u32,
    /// The pivots' positions, by pivot, gathered once a substep.
    #[serde(skip)]
    xs: Vec<f32>,
    #[serde(skip)]
    ys: Vec<f32>,
    /// Where each component's pivots start in `xs` and `ys`.
    #[serde(skip)]
    pivot_start: Vec<usize>,
    /// Scratch: which nodes are heated, for a held layout.
    #[serde(skip)]
    heated: Vec<bool>,
    /// By run of [`NODES_A_RUN`] nodes, each pushed node's pull and stiffness of its
    /// terms on this substep `(node, pull, stiffness)` (a settled layout disturbed in
    /// one place keeps a few), between `work_out` and `add_to`.
    #[serde(skip)]
    pulls: Vec<Vec<(u32, Vector2D<f32>, f32)>>,
    /// Set for each substep by the forces: the layout rested and keeps its rest's
    /// balance (`stress/rest_bias.rs`), so the pivot terms are held for every node the
    /// disturbance did not heat (worked out afresh only for the heated ones), and a node
    /// that wakes finds the terms it rested with.
    #[serde(skip)]
    pub(crate) hold_cold: bool,
    /// What [`step_for`](Self::step_for) found of this substep, from `prepare` to
    /// `finish`.
    #[serde(skip)]
    step: Option<TermStep>,
}

impl StressForce {
    /// Gives the force a model already built for `world` (the start's), so the first
    /// substep does not build it again.
    pub(crate) fn adopt<N: Clone + Eq + Hash>(
        &mut self,
        world: &RapierSceneWorld<N>,
        model: SparseStress,
        pivots: usize,
        exact_hops: u16,
    ) {
        self.version = Some(world.version());
        self.shape = Shape::of(world, pivots, exact_hops);
        self.model = model;
        self.pivot_force.clear();
        self.since = 0;
    }

    /// Whether a snapshot's force can be read as it is: its model the model of the
    /// shape it was built for ([`SparseStress::check`]), the shape's joints between its
    /// nodes, and the held pivot sums one a node and finite. A force whose shape is not
    /// the world's is built again on its first substep, whatever its model holds; a
    /// force with no shape holds no model. `Err` names the part.
    pub(crate) fn check(&self) -> Result<(), String> {
        if self.shape == Shape::default() {
            return Ok(());
        }
        let n = self.shape.serials.len();
        let within = |&(a, b): &(u32, u32)| (a as usize) < n && (b as usize) < n;
        if !self.shape.joints.iter().all(within) {
            return Err("forces.stress.shape.joints".into());
        }
        self.model
            .check(n)
            .map_err(|part| format!("forces.stress.model.{part}"))?;
        let held = self.pivot_force.len();
        if self.pivot_stiffness.len() != held || self.pivot_at.len() != held {
            return Err("forces.stress: pivot sums of different lengths".into());
        }
        let finite = self.pivot_force.iter().all(|f| f.is_finite())
            && self.pivot_stiffness.iter().all(|k| k.is_finite())
            && self.pivot_at.iter().all(|p| p.is_finite());
        if !finite {
            return Err("forces.stress: pivot sums not finite".into());
        }
        Ok(())
    }

    /// Works the pivot terms out afresh for every node on the next substep
    /// ([`step_for`](Self::step_for) and [`work_out`](Self::work_out)), instead of
    /// holding them: what a rest's balance is measured with, so that no node holds a pull worked out where the pivots were long
    /// ago.
    pub(crate) fn renew_pivot_terms(&mut self) {
        self.pivot_force.clear();
    }

    /// The model up to date with `world` for these settings: kept while the graph is
    /// the same, extended when leaves were added (a leaf changes no other pair's
    /// distance: its hops are its neighbour's plus one), built again otherwise.
    fn refresh<N: Clone + Eq + Hash>(
        &mut self,
        world: &RapierSceneWorld<N>,
        pivots: usize,
        exact_hops: u16,
    ) {
        let settings = (pivots, exact_hops);
        if self.version == Some(world.version()) && self.shape.settings == settings {
            return;
        }
        self.version = Some(world.version());
        let shape = Shape::of(world, pivots, exact_hops);
        if shape == self.shape {
            return;
        }
        let graph = world.joint_graph();
        match self.shape.added_leaves(&shape) {
            Some(leaves) => {
                let mut reach = Reach::new(graph.len());
                for (leaf, parent) in leaves {
                    self.model.add_leaf(&graph, leaf, parent, &mut reach);
                }
            }
            None => self.model = SparseStress::new(&graph, pivots, exact_hops),
        }
        self.shape = shape;
        self.pivot_force.clear();
        self.since = 0;
    }

    /// What a substep's terms need that reads the world (on the calling thread: a
    /// host's node type need not be shared between threads): the model brought up to
    /// date, the pivots' positions when their terms are due, and which nodes are heated.
    /// `None` when the terms pull nothing (no model settings, or no finite stiffness).
    pub(crate) fn step_for<N: Clone + Eq + Hash>(
        &mut self,
        frame: &ForceContext<'_, N>,
    ) -> Option<TermStep> {
        let stress = frame.config.stress?;
        let exact_hops = stress.exact_hops.max(1);
        self.refresh(
            frame.world,
            stress.pivot_count(frame.world.slot_count()),
            exact_hops,
        );
        let n = frame.points.len();
        let hop = frame.world.hop_length().unwrap_or(stress.hop_length);
        let k = frame.config.edge_stiffness() * frame.world.applied_spring_scale();
        if !(k > 0.0 && k.is_finite() && hop > 0.0 && hop.is_finite()) {
            return None;
        }
        let period = stress.pivot_period.max(1);
        let renew = self.pivot_force.len() != n;
        let fresh = renew || self.since % period == 0;
        let hold_cold = self.hold_cold && !renew;
        if fresh && !hold_cold {
            self.pivot_force.clear();
            self.pivot_force.resize(n, Vector2D::zero());
            self.pivot_stiffness.clear();
            self.pivot_stiffness.resize(n, 0.0);
            self.pivot_at.clear();
            self.pivot_at.resize(n, Point2D::origin());
        }
        self.since = self.since.wrapping_add(1);
        if fresh {
            // Each component's pivots' positions, padded to whole lanes.
            self.xs.clear();
            self.ys.clear();
            self.pivot_start.clear();
            for &(a, b) in &self.model.pivot_range {
                self.pivot_start.push(self.xs.len());
                for &q in &self.model.pivots[a as usize..b as usize] {
                    let point = frame.points[q as usize];
                    self.xs.push(point.x);
                    self.ys.push(point.y);
                }
                let width = self.pivot_start.last().map_or(0, |&s| s) + padded((b - a) as usize);
                self.xs.resize(width, 0.0);
                self.ys.resize(width, 0.0);
            }
        }
        let end = n.min(self.model.component.len());
        // Which nodes a held layout works out afresh.
        self.heated.clear();
        if fresh && hold_cold {
            self.heated
                .extend((0..end).map(|i| frame.world.host_at(i).heat > 0.0));
        }
        Some(TermStep {
            hop,
            k,
            dt2: frame.dt * frame.dt,
            fresh,
            hold_cold,
            end,
        })
    }

    /// Each pushed node's pull and stiffness of its terms for the substep `step`
    /// prepared, kept for [`add_to`](Self::add_to): in runs of nodes side by side
    /// under `parallel` (a node's sums are its own, so the bits do not depend on the
    /// thread count). Reads no world: it may run beside work that does.
    pub(crate) fn work_out(&mut self, step: TermStep, points: &[Point2D<f32>], pushed: &[bool]) {
        let terms = NodeTerms {
            model: &self.model,
            points,
            pushed,
            heated: &self.heated,
            xs: &self.xs,
            ys: &self.ys,
            pivot_start: &self.pivot_start,
            hop: step.hop,
            k: step.k,
            fresh: step.fresh,
            hold_cold: step.hold_cold,
        };
        let end = step.end;
        // The runs' lists keep their room from substep to substep.
        self.pulls.resize_with(end.div_ceil(NODES_A_RUN), Vec::new);
        let mut jobs: Vec<_> = self.pivot_force[..end]
            .chunks_mut(NODES_A_RUN)
            .zip(self.pivot_stiffness[..end].chunks_mut(NODES_A_RUN))
            .zip(self.pivot_at[..end].chunks_mut(NODES_A_RUN))
            .zip(self.pulls.iter_mut())
            .enumerate()
            .map(|(r, (((force, stiffness), at), pulls))| {
                let held = Held {
                    force,
                    stiffness,
                    at,
                };
                (r * NODES_A_RUN, held, pulls)
            })
            .collect();
        parallel::for_each(
            &mut jobs,
            <(Vec<f32>, Vec<f32>)>::default,
            |scratch, (first, held, pulls)| {
                pulls.clear();
                for o in 0..held.force.len() {
                    if let Some((f, stiffness)) = terms.pull_on(*first + o, held, o, scratch) {
                        pulls.push(((*first + o) as u32, f, stiffness));
                    }
                }
            },
        );
    }

    /// Adds the pulls [`work_out`](Self::work_out) found for `step` to the springs'
    /// sums (the stiffness, times `dt²`, to what the implicit step divides by).
    pub(crate) fn add_to(&self, step: TermStep, out: &mut ForceSums) {
        let (dt2, end) = (step.dt2, step.end);
        let resistance = &mut out.resistance[..end];
        let mut jobs: Vec<_> = out.springs[..end]
            .chunks_mut(NODES_A_RUN)
            .zip(resistance.chunks_mut(NODES_A_RUN))
            .zip(&self.pulls)
            .enumerate()
            .collect();
        parallel::for_each(
            &mut jobs,
            || (),
            |(), (r, ((springs, resistance), pulls))| {
                let first = *r * NODES_A_RUN;
                for &(i, f, stiffness) in pulls.iter() {
                    springs[i as usize - first] += f;
                    resistance[i as usize - first] += dt2 * stiffness;
                }
            },
        );
    }
}

/// What the model was built for: the nodes (by serial, in slot order), the joints (by
/// slot, in joint order) and the settings.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
struct Shape {
    serials: Vec<u64>,
    joints: Vec<(u32, u32)>,
    settings: (usize, u16),
}

impl Shape {
    fn of<N: Clone + Eq + Hash>(world: &RapierSceneWorld<N>, pivots: usize, hops: u16) -> Self {
        Self {
            serials: (0..world.slot_count())
                .map(|s| world.serial_at(s))
                .collect(),
            joints: world
                .joint_ends()
                .map(|(a, b)| (a as u32, b as u32))
                .collect(),
            settings: (pivots, hops),
        }
    }

    /// When `now` is this shape with leaves added (new nodes after the old ones, each
    /// joined by one new joint to a node before it, the old joints as they were), the
    /// leaves and their parents in slot order.
    fn added_leaves(&self, now: &Shape) -> Option<Vec<(usize, usize)>> {
        let old = self.serials.len();
        if self.settings != now.settings
            || self.serials.is_empty()
            || now.serials.len() <= old
            || now.serials[..old] != self.serials[..]
            || now.joints.len() != self.joints.len() + (now.serials.len() - old)
            || now.joints[..self.joints.len()] != self.joints[..]
        {
            return None;
        }
        let mut parent = vec![usize::MAX; now.serials.len() - old];
        for &(a, b) in &now.joints[self.joints.len()..] {
            let (leaf, other) = (a.max(b) as usize, a.min(b) as usize);
            if leaf < old || parent[leaf - old] != usize::MAX {
                return None;
            }
            parent[leaf - old] = other;
        }
        parent
            .into_iter()
            .enumerate()
            .map(|(k, p)| (p != usize::MAX).then_some((old + k, p)))
            .collect()
    }
}

impl<N: Clone + Eq + Hash> BodyForce<N> for StressForce {
    fn is_active(&self, config: &RapierLayoutConfig, _: &NodeTargets) -> bool {
        config.stress.is_some()
    }

    /// From positions alone once prepared, so beside the springs.
    fn lane(&self) -> Lane {
        Lane::Spare
    }

    fn prepare(&mut self, frame: &ForceContext<'_, N>) {
        self.step = self.step_for(frame);
    }

    fn apply_spare(&mut self, frame: &SpareFrame<'_>, _: &mut ForceSums) {
        if let Some(step) = self.step {
            self.work_out(step, frame.points, frame.pushed);
        }
    }

    /// Adds the terms worked out beside the springs: the last of the registry.
    fn finish(&mut self, out: &mut ForceSums) {
        if let Some(step) = self.step.take() {
            self.add_to(step, out);
        }
    }

    fn reset(&mut self) {
        // A new world counts its versions from 0 again.
        *self = Self::default();
    }
}

/// What [`StressForce::step_for`] found of a substep, for its terms.
#[derive(Clone, Copy, Debug)]
pub(crate) struct TermStep {
    hop: f32,
    k: f32,
    dt2: f32,
    fresh: bool,
    hold_cold: bool,
    end: usize,
}

/// Nodes whose stress terms are summed in one run (fixed, so the sums do not depend on
/// the thread count).
const NODES_A_RUN: usize = 512;

/// A run of nodes' held pivot terms (`StressForce::pivot_force` and the rest).
struct Held<'a> {
    force: &'a mut [Vector2D<f32>],
    stiffness: &'a mut [f32],
    at: &'a mut [Point2D<f32>],
}

/// What a node's stress terms read on one substep.
struct NodeTerms<'a> {
    model: &'a SparseStress,
    points: &'a [Point2D<f32>],
    pushed: &'a [bool],
    /// With `hold_cold`, whether each node is heated.
    heated: &'a [bool],
    /// The pivots' positions and where each component's start.
    xs: &'a [f32],
    ys: &'a [f32],
    pivot_start: &'a [usize],
    hop: f32,
    k: f32,
    /// Whether the pivot terms are worked out this substep, and held for the nodes not
    /// heated.
    fresh: bool,
    hold_cold: bool,
}

impl NodeTerms<'_> {
    /// The pull of node `i`'s terms and their stiffness, or `None` for a node not
    /// pushed or a sum not finite. Works out its pivot terms again when they are due,
    /// into `held` at `o`; `scratch` holds the node's distances and weights.
    fn pull_on(
        &self,
        i: usize,
        held: &mut Held<'_>,
        o: usize,
        (hops_buffer, weights): &mut (Vec<f32>, Vec<f32>),
    ) -> Option<(Vector2D<f32>, f32)> {
        if !self.pushed[i] {
            return None;
        }
        let (model, hop, k) = (self.model, self.hop, self.k);
        let p = self.points[i];
        let (mut f, mut stiffness) = (Vector2D::zero(), 0.0_f32);
        let (near, near_hops) = model.near_terms_of(i);
        let scale = model.near_scale[i];
        for (&j, &d) in near.iter().zip(near_hops) {
            let d = f32::from(d);
            let w = scale / (d * d);
            f += pull(p, self.points[j as usize], hop * d, k * w);
            stiffness += k * w;
        }
        if self.fresh && (!self.hold_cold || self.heated[i]) {
            let c = model.component[i] as usize;
            let (a, b) = model.pivot_range[c];
            let width = padded((b - a) as usize);
            let start = self.pivot_start[c];
            let (xs, ys) = (
                &self.xs[start..start + width],
                &self.ys[start..start + width],
            );
            let (_, hops) = model.pivot_terms(i);
            // The node's distances and weights, padded to whole lanes.
            hops_buffer.clear();
            weights.clear();
            if model.full[c] {
                for &d in hops {
                    let d = f32::from(d);
                    hops_buffer.push(d);
                    weights.push(if d >= 2.0 { 1.0 / (d * d) } else { 0.0 });
                }
            } else {
                let stride = model.stride[c] as usize;
                let tables = model.component_weights(c);
                for (t, &d) in hops.iter().enumerate() {
                    hops_buffer.push(f32::from(d));
                    weights.push(tables[t * stride + (d as usize).min(stride - 1)]);
                }
            }
            hops_buffer.resize(width, 0.0);
            weights.resize(width, 0.0);
            let pull = pivot_pull((p.x, p.y), xs, ys, hops_buffer, weights, hop, k);
            held.force[o] = Vector2D::new(pull.x, pull.y);
            held.stiffness[o] = pull.stiffness;
            held.at[o] = p;
        }
        // Held between evaluations as its first-order model about where it was worked
        // out: the force less the stiffness times the way moved since (what the
        // implicit step assumes of it), so a held force does not push a node past
        // its balance.
        let moved = p - held.at[o];
        f += held.force[o] - moved * held.stiffness[o];
        stiffness += held.stiffness[o];
        (f.is_finite() && stiffness.is_finite()).then_some((f, stiffness))
    }
}

/// The pull on a node at `p` of a spring of stiffness `k` and rest length `rest` to `q`.
#[inline]
fn pull(p: Point2D<f32>, q: Point2D<f32>, rest: f32, k: f32) -> Vector2D<f32> {
    let d = q - p;
    let length = d.length();
    if length > 1e-3 {
        d * (k * (length - rest) / length)
    } else {
        Vector2D::zero()
    }
}
