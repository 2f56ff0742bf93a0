//! Clusters held in the physics: each one's box is its members' outlines grown by its
//! padding (`boxes.rs`), so its members are inside by construction; what is held is
//! that no other node and no sibling's box enters it. After each substep the levels are
//! parted from the inside out (`part.rs`): within each cluster, its nested boxes and
//! its own members; then the top level, where the boxes meet the nodes in no cluster.
//! The host's list is compiled by world slot (`tree.rs`) when it or the world changes.
//!
//! A parting moves positions and stops the parted bodies' speed along its axis. At the
//! start and the cold stop the boxes move whole, so a cluster keeps its inside as it
//! is; while the layout moves, two sibling boxes meet at a wall that holds back the
//! members reaching past it (`walls.rs`).

mod boxes;
mod part;
mod tree;
mod walls;

use std::hash::Hash;

use euclid::default::{Box2D, Point2D};
use rapier2d::prelude::Vector;

use crate::input::clusters::Cluster;
use crate::input::node_forces::AxisLock;
use crate::world::RapierSceneWorld;
use boxes::{is_empty, Bodies, Boxes};
use part::{Ctx, Level, Moves};
use tree::Tree;

/// The host's clusters as held on the world, and their boxes as of the last call.
#[derive(Clone, Debug)]
pub(crate) struct Clusters<N> {
    /// The list the tree was compiled from, and the world it was compiled for.
    list: Vec<Cluster<N>>,
    generation: (u64, u64),
    tree: Tree,
    bodies: Bodies,
    boxes: Boxes,
    moves: Moves,
    level: Level,
    /// Each cluster's box after the last call, for the host.
    pub(crate) bounds: Vec<Box2D<f32>>,
    /// Whether a call compiled them since the layout was made or restored.
    primed: bool,
    /// Whether a parting moved a body since [`take_moved`](Self::take_moved): rapier
    /// counts a body woken that way as awake only from its next step.
    moved: bool,
    /// The clusters (indices into the host's list) the last check found more than a
    /// unit from holding, and the check's marks by cluster.
    pub(crate) violated: Vec<usize>,
    unheld: Vec<bool>,
    /// Whether the list was compiled since the last check.
    unchecked: bool,
}

impl<N> Default for Clusters<N> {
    fn default() -> Self {
        Self {
            list: Vec::new(),
            generation: (0, 0),
            tree: Tree::default(),
            bodies: Bodies::default(),
            boxes: Boxes::default(),
            moves: Moves::default(),
            level: Level::default(),
            bounds: Vec::new(),
            primed: false,
            moved: false,
            violated: Vec::new(),
            unheld: Vec::new(),
            unchecked: true,
        }
    }
}

impl<N: Clone + Eq + Hash> Clusters<N> {
    /// Compiles `clusters` for `world` (`generation`: its rebuild count and version)
    /// when either changed. When the list changed (a disturbance), returns the slots of
    /// the clusters that changed, which the heat stage reheats with their
    /// neighbourhoods; the first compile after the layout was made or restored is none.
    pub(crate) fn sync(
        &mut self,
        clusters: &[Cluster<N>],
        world: &RapierSceneWorld<N>,
        generation: (u64, u64),
    ) -> Option<Vec<u32>> {
        let primed = std::mem::replace(&mut self.primed, true);
        let same = |a: Option<&Cluster<N>>, b: Option<&Cluster<N>>| match (a, b) {
            (Some(a), Some(b)) => a.same_as(b),
            (a, b) => a.is_none() && b.is_none(),
        };
        let changed = |c: usize| !same(self.list.get(c), clusters.get(c));
        let same_list = self.list.len() == clusters.len() && !(0..clusters.len()).any(changed);
        if same_list && self.generation == generation {
            return None;
        }
        let tree = Tree::compile(clusters, world);
        let mut edit = Vec::new();
        if !same_list && primed {
            // Every member of a cluster added, removed or changed, before and after, by
            // the slots of this world (as a restored layout, which keeps no tree, finds
            // them too).
            let before = Tree::compile(&self.list, world);
            for c in (0..self.list.len().max(clusters.len())).filter(|&c| changed(c)) {
                for t in [&before, &tree] {
                    if t.held.get(c).copied().unwrap_or(false) {
                        t.for_each_slot(c, |s| edit.push(s as u32));
                    }
                }
            }
            edit.sort_unstable();
            edit.dedup();
        }
        self.tree = tree;
        self.list = clusters.to_vec();
        self.generation = generation;
        self.unchecked = true;
        (!same_list && primed).then_some(edit)
    }

    /// The list the last call held, for a snapshot (`None` before a first call).
    pub(crate) fn save(&self) -> Option<Vec<Cluster<N>>> {
        self.primed.then(|| self.list.clone())
    }

    /// The clusters as a snapshot saved them: the first call compares its list with the
    /// saved one, as the saved layout's next call would, and compiles for the world.
    pub(crate) fn restored(saved: Option<Vec<Cluster<N>>>) -> Self {
        let primed = saved.is_some();
        Self {
            list: saved.unwrap_or_default(),
            // No world has this generation: the first call compiles.
            generation: (u64::MAX, u64::MAX),
            primed,
            ..Self::default()
        }
    }

    /// Whether a parting moved a body since the last call of this (which forgets it).
    pub(crate) fn take_moved(&mut self) -> bool {
        std::mem::take(&mut self.moved)
    }

    /// Memberships and clusters the last compile left out (bad input).
    pub(crate) fn skipped(&self) -> usize {
        self.tree.skipped
    }

    /// Whether no held cluster has a body in it.
    pub(crate) fn is_empty(&self) -> bool {
        self.tree.is_empty()
    }

    /// Parts every level `rounds` times or until nothing moves (two free items that
    /// nothing drives at most `step` times the bodies' mean half size apart each time;
    /// `None`: by their whole overlap), and writes the moved bodies back, woken, their
    /// speed along the axis they were parted on stopped. A body whose axis one of
    /// `locks` holds does not give way along it. Returns how far the last round moved
    /// anything.
    pub(crate) fn project(
        &mut self,
        world: &mut RapierSceneWorld<N>,
        locks: &[(u32, AxisLock, f32)],
        (rounds, step): (usize, Option<f32>),
    ) -> f32 {
        if self.tree.is_empty() {
            return 0.0;
        }
        self.read(world, locks);
        let most = step.map_or(f32::INFINITY, |share| share * self.bodies.mean_half());
        let moved = self.part_rounds(rounds, most);
        self.write(world);
        moved
    }

    /// Parts every level of the bodies as read, `rounds` times or until a round moves
    /// nothing, free items that nothing drives at most `most` apart each time. Returns
    /// how far the last round moved anything.
    fn part_rounds(&mut self, rounds: usize, most: f32) -> f32 {
        self.moves
            .clear(self.bodies.points.len(), self.tree.held.len());
        let mut moved = 0.0;
        for _ in 0..rounds {
            self.boxes.make(&self.tree, &self.bodies);
            moved = self.visit_levels(most, false);
            if moved == 0.0 {
                break;
            }
        }
        moved
    }

    /// The clusters compiled for a new `world` whose start layout holds them
    /// ([`project_points`](Self::project_points)): the bodies' outlines read now.
    pub(crate) fn for_start(clusters: &[Cluster<N>], world: &RapierSceneWorld<N>) -> Self {
        let mut start = Self::default();
        start.sync(clusters, world, (u64::MAX, 0));
        if !start.tree.is_empty() {
            start.read(world, &[]);
        }
        start
    }

    /// Parts the clusters on `points` (by slot, `unit` world units each; a start
    /// layout's positions before there are bodies to move), at most `rounds` times,
    /// every body free to move.
    pub(crate) fn project_points(&mut self, points: &mut [[f32; 2]], unit: f32, rounds: usize) {
        let n = self.bodies.points.len();
        if self.tree.is_empty() || points.len() != n || !(unit.is_finite() && unit > 0.0) {
            return;
        }
        for (s, p) in points.iter().enumerate() {
            self.bodies.points[s] = [p[0] * unit, p[1] * unit];
        }
        self.bodies.free.iter_mut().for_each(|f| *f = [true; 2]);
        self.part_rounds(rounds, f32::INFINITY);
        for &s in &self.moves.list {
            let [x, y] = self.bodies.points[s as usize];
            points[s as usize] = [x / unit, y / unit];
        }
    }

    /// Each level from the inside out: parted, or with `check`, checked (nothing moves;
    /// [`Clusters::unheld`] marks the boxes overlapping an item of their level).
    fn visit_levels(&mut self, most: f32, check: bool) -> f32 {
        let mut ctx = Ctx {
            tree: &self.tree,
            bodies: &mut self.bodies,
            boxes: &mut self.boxes,
            moves: &mut self.moves,
            most,
            unheld: check.then_some(&mut self.unheld[..]),
        };
        let mut moved = 0.0_f32;
        for &c in &self.tree.inside_out {
            let c = c as usize;
            let own = self.tree.own.of(c).iter().copied();
            moved = moved.max(self.level.part(self.tree.children.of(c), own, &mut ctx));
        }
        let clustered = &self.tree.clustered;
        let loose = (0..clustered.len() as u32).filter(|&s| !clustered[s as usize]);
        moved.max(self.level.part(&self.tree.top, loose, &mut ctx))
    }

    /// Notes in [`violated`](Self::violated) the clusters whose box overlaps a sibling
    /// box or a node not theirs by more than a unit, from the boxes as made.
    fn check(&mut self) {
        self.unheld.clear();
        self.unheld.resize(self.tree.held.len(), false);
        self.moves
            .clear(self.bodies.points.len(), self.tree.held.len());
        self.visit_levels(0.0, true);
        let unheld = self.unheld.iter().enumerate().filter(|&(_, &u)| u);
        self.violated.extend(unheld.map(|(c, _)| c));
    }

    /// Reads every body's centre, outline and whether it gives way.
    fn read(&mut self, world: &RapierSceneWorld<N>, locks: &[(u32, AxisLock, f32)]) {
        let b = &mut self.bodies;
        b.points.clear();
        b.half.clear();
        b.free.clear();
        for s in 0..world.slot_count() {
            let body = world.body_at(s);
            let t = body.translation();
            b.points.push([t.x, t.y]);
            let half = world.shape_at(s).half_extents();
            b.half.push([half.x, half.y]);
            b.free.push([body.is_dynamic(); 2]);
        }
        for &(slot, axis, _) in locks {
            if let Some(free) = b.free.get_mut(slot as usize) {
                free[usize::from(axis == AxisLock::Y)] = false;
            }
        }
    }

    /// Writes the moved bodies back, woken, their speed along the axes they were parted
    /// on stopped.
    fn write(&mut self, world: &mut RapierSceneWorld<N>) {
        self.moved |= !self.moves.list.is_empty();
        for &s in &self.moves.list {
            let s = s as usize;
            let (p, pushed) = (self.bodies.points[s], self.moves.pushed[s]);
            let body = world.body_at_mut(s);
            let mut v = body.linvel();
            for (axis, speed) in [&mut v.x, &mut v.y].into_iter().enumerate() {
                if pushed[axis] {
                    *speed = 0.0;
                }
            }
            body.set_translation(Vector::new(p[0], p[1]), true);
            body.set_linvel(v, true);
        }
    }

    /// Notes each listed cluster's box from `world` (an empty box for one left out or
    /// without members in the world), index-aligned with the host's list; and, when the
    /// call `stepped` the world or the list was compiled since, which clusters are more
    /// than a unit from holding. A call that did neither moved nothing: the last boxes
    /// and check stand.
    pub(crate) fn note_bounds(
        &mut self,
        world: Option<&RapierSceneWorld<N>>,
        listed: usize,
        stepped: bool,
    ) {
        let unchecked = std::mem::take(&mut self.unchecked);
        let check = stepped || unchecked;
        if !check && world.is_some() && self.bounds.len() == listed {
            // Nothing moved and the list is the one compiled: the boxes stand (a layout
            // at rest reads no body).
            return;
        }
        self.bounds.clear();
        if check {
            self.violated.clear();
        }
        if let Some(world) = world.filter(|_| !self.tree.is_empty()) {
            self.read(world, &[]);
            self.boxes.make(&self.tree, &self.bodies);
            if check {
                self.check();
            }
            self.bounds.extend(self.boxes.bounds.iter().map(|&b| {
                if is_empty(b) {
                    Box2D::zero()
                } else {
                    Box2D::new(
                        Point2D::new(b[0][0], b[0][1]),
                        Point2D::new(b[1][0], b[1][1]),
                    )
                }
            }));
        }
        self.bounds.resize(listed, Box2D::zero());
    }
}
