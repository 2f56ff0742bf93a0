//! The worker's side of [`LayoutWorker`](super::LayoutWorker): the host's messages
//! applied to the worker's own scene in the order they were sent, one step per frame
//! (one frame of simulated time, no faster than real time), the newest positions
//! published after each step, and a blocking wait while the layout rests. A step is
//! told which nodes the messages changed (`adapter/known.rs`), so a drag on a settled
//! graph does not match and sync every node; a message that changes more than nodes
//! makes the next step a full [`Layout::step`].

use std::hash::Hash;
use std::sync::mpsc::{Receiver, RecvTimeoutError, TryRecvError};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use euclid::default::{Box2D, Point2D};

use super::LayoutFrame;
use crate::adapter::{RapierLayout, RapierLayoutState};
use crate::config::RapierLayoutConfig;
use crate::input::clusters::Cluster;
use crate::input::constraints::Constraint;
use crate::input::layout::{Layout, LayoutExtras, NodeMap};
use crate::input::node_forces::NodeForces;
use crate::input::scene::{CanvasEdge, CanvasNode, CanvasSceneInput, CanvasViewport};
use crate::input::shape::NodeShape;

/// One host message. The worker applies them in the order they were sent.
pub(super) enum Command<N> {
    AddNode(CanvasNode<N>),
    RemoveNode(N),
    AddEdge(CanvasEdge<N>),
    RemoveEdge(N, N),
    Move(N, Point2D<f32>),
    Drag(N, Point2D<f32>),
    Release(N),
    Pin(N, bool),
    Forces(N, Option<NodeForces>),
    Configure(Box<RapierLayoutConfig>),
    Reshape(N, f32, NodeShape),
    PoolAwake(bool),
    Constraints(Vec<Constraint<N>>),
    Clusters(Vec<Cluster<N>>),
}

/// The newest frame, waiting for the host to take it.
pub(super) type Slot<N> = Arc<Mutex<Option<LayoutFrame<N>>>>;

/// Everything the worker thread owns.
pub(super) struct Worker<N> {
    scene: CanvasSceneInput<N>,
    extras: LayoutExtras<N>,
    layout: RapierLayout<N>,
    state: RapierLayoutState,
    frame_time: Duration,
    commands: Receiver<(u64, Command<N>)>,
    slot: Slot<N>,
    /// Node id to its index in `scene.nodes`, rebuilt when the node set changes.
    index: Arc<NodeMap<N, usize>>,
    ids: Arc<Vec<N>>,
    nodes_changed: bool,
    /// The scene indices of the nodes the host's messages changed since the last step
    /// (`adapter/known.rs`).
    changed: Vec<usize>,
    /// Whether a message changed more than nodes since the last step (the node set, the
    /// edges, pins, forces or the configuration): the step is then a full one.
    restructured: bool,
    /// The sequence number of the last message applied.
    applied: u64,
    steps: u64,
    step_times: Vec<Duration>,
    /// The cluster boxes last published, shared with the frames until they change.
    bounds: Arc<Vec<Box2D<f32>>>,
    /// The violated constraints and clusters last published, shared likewise.
    violated_constraints: Arc<Vec<usize>>,
    violated_clusters: Arc<Vec<usize>>,
}

impl<N: Clone + Eq + Hash + Send + Sync + 'static> Worker<N> {
    pub(super) fn new(
        scene: CanvasSceneInput<N>,
        config: RapierLayoutConfig,
        extras: LayoutExtras<N>,
        frame_time: Duration,
        commands: Receiver<(u64, Command<N>)>,
        slot: Slot<N>,
    ) -> Self {
        Self {
            scene,
            extras,
            layout: RapierLayout::new(config),
            state: RapierLayoutState::default(),
            frame_time,
            commands,
            slot,
            index: Arc::default(),
            ids: Arc::default(),
            nodes_changed: true,
            changed: Vec::new(),
            restructured: true,
            applied: 0,
            steps: 0,
            step_times: Vec::new(),
            bounds: Arc::default(),
            violated_constraints: Arc::default(),
            violated_clusters: Arc::default(),
        }
    }

    /// Whether the layout rests: converged, or nothing to lay out.
    fn at_rest(&self) -> bool {
        self.scene.nodes.is_empty() || self.layout.is_converged(&self.state)
    }

    /// Steps until the host drops its handle.
    pub(super) fn run(mut self) {
        let mut previous: Option<Instant> = None;
        loop {
            if self.at_rest() && self.steps > 0 {
                // At rest: sleep until the host sends something.
                match self.commands.recv() {
                    Ok((seq, command)) => self.apply(seq, command),
                    Err(_) => return,
                }
                previous = None;
            }
            // One frame of simulated time a step, no sooner than a frame after the last
            // (messages are applied as they arrive meanwhile): a step slower than the
            // frame runs the layout in slow motion rather than making the next step
            // simulate (and cost) more.
            let next = previous.and_then(|at| at.checked_add(self.frame_time));
            loop {
                let wait = next.map_or(Duration::ZERO, |next| {
                    next.saturating_duration_since(Instant::now())
                });
                let received = if wait.is_zero() {
                    self.commands.try_recv().map_err(|e| match e {
                        TryRecvError::Empty => RecvTimeoutError::Timeout,
                        TryRecvError::Disconnected => RecvTimeoutError::Disconnected,
                    })
                } else {
                    self.commands.recv_timeout(wait)
                };
                match received {
                    Ok((seq, command)) => self.apply(seq, command),
                    Err(RecvTimeoutError::Timeout) => break,
                    Err(RecvTimeoutError::Disconnected) => return,
                }
            }
            let started = Instant::now();
            previous = Some(started);
            if self.scene.nodes.is_empty() {
                // Nothing to lay out: publish the empty frame and rest.
                self.steps += 1;
                self.publish();
                continue;
            }
            let dt = self.frame_time.as_secs_f32();
            let deltas = if std::mem::take(&mut self.restructured) {
                self.changed.clear();
                self.layout.step(
                    &self.scene,
                    &mut self.state,
                    dt,
                    &CanvasViewport::default(),
                    &self.extras,
                )
            } else {
                // Every dragged and pinned node is listed with the changed ones.
                self.reindex();
                let index = &self.index;
                let held = self.extras.dragging.iter().chain(&self.extras.pinned);
                self.changed
                    .extend(held.filter_map(|id| index.get(id).copied()));
                self.changed.sort_unstable();
                self.changed.dedup();
                let deltas = self.layout.step_known(
                    &self.scene,
                    &mut self.state,
                    dt,
                    &self.extras,
                    &self.changed,
                );
                self.changed.clear();
                deltas
            };
            // Each delta to its node, found by id (the first node of an id, as
            // `apply_deltas` does) rather than by a pass over every node.
            self.reindex();
            for (id, delta) in &deltas {
                if let Some(&i) = self.index.get(id) {
                    self.scene.nodes[i].position += *delta;
                }
            }
            self.steps += 1;
            self.step_times.push(started.elapsed());
            self.publish();
        }
    }

    fn apply(&mut self, seq: u64, command: Command<N>) {
        self.applied = seq;
        match &command {
            Command::Move(id, _)
            | Command::Drag(id, _)
            | Command::Release(id)
            | Command::Reshape(id, _, _) => {
                self.reindex();
                if let Some(&i) = self.index.get(id) {
                    self.changed.push(i);
                }
            }
            Command::PoolAwake(_) => {}
            _ => self.restructured = true,
        }
        match command {
            Command::AddNode(node) => {
                self.scene.nodes.push(node);
                self.nodes_changed = true;
            }
            Command::RemoveNode(id) => {
                // The body goes now: an id added again in the same batch is a new node.
                self.layout.forget_node(&id);
                self.scene.nodes.retain(|n| n.id != id);
                self.scene
                    .edges
                    .retain(|e| e.source != id && e.target != id);
                self.extras.pinned.remove(&id);
                self.extras.dragging.remove(&id);
                self.extras.forces.remove(&id);
                self.nodes_changed = true;
            }
            Command::AddEdge(edge) => self.scene.edges.push(edge),
            Command::RemoveEdge(a, b) => self.scene.edges.retain(|e| {
                !((e.source == a && e.target == b) || (e.source == b && e.target == a))
            }),
            Command::Move(id, at) => self.put(&id, at),
            Command::Drag(id, at) => {
                self.put(&id, at);
                self.extras.dragging.insert(id);
            }
            Command::Release(id) => {
                self.extras.dragging.remove(&id);
            }
            Command::Pin(id, true) => {
                self.extras.pinned.insert(id);
            }
            Command::Pin(id, false) => {
                self.extras.pinned.remove(&id);
            }
            Command::Forces(id, Some(forces)) => {
                self.extras.forces.insert(id, forces);
            }
            Command::Forces(id, None) => {
                self.extras.forces.remove(&id);
            }
            Command::Configure(config) => self.layout.config = *config,
            Command::Constraints(list) => self.extras.constraints = list,
            Command::Clusters(list) => self.extras.clusters = list,
            Command::PoolAwake(on) => self.layout.set_pool_awake(on),
            Command::Reshape(id, radius, shape) => {
                self.reindex();
                if let Some(&i) = self.index.get(&id) {
                    let node = &mut self.scene.nodes[i];
                    node.radius = radius;
                    node.shape = shape;
                }
            }
        }
    }

    /// Puts node `id` at `at` in the worker's scene, as a host moves its own node.
    fn put(&mut self, id: &N, at: Point2D<f32>) {
        self.reindex();
        if let Some(&i) = self.index.get(id) {
            self.scene.nodes[i].position = at;
        }
    }

    /// The id index and id list again, if the node set changed.
    fn reindex(&mut self) {
        if !self.nodes_changed {
            return;
        }
        let mut index = NodeMap::default();
        for (i, n) in self.scene.nodes.iter().enumerate() {
            index.entry(n.id.clone()).or_insert(i);
        }
        self.index = Arc::new(index);
        self.ids = Arc::new(self.scene.nodes.iter().map(|n| n.id.clone()).collect());
        self.nodes_changed = false;
    }

    /// Hands the newest positions to the host; step times the host has not read yet
    /// carry over.
    fn publish(&mut self) {
        self.reindex();
        // With no node, the layout was not stepped: its reports are the last step's.
        let stepped = !self.scene.nodes.is_empty();
        let layout = &self.layout;
        let mut frame = LayoutFrame {
            ids: Arc::clone(&self.ids),
            index: Arc::clone(&self.index),
            positions: self.scene.nodes.iter().map(|n| n.position).collect(),
            converged: self.at_rest(),
            cluster_bounds: share(&mut self.bounds, layout.cluster_bounds(), stepped),
            violated_constraints: share(
                &mut self.violated_constraints,
                layout.violated_constraints(),
                stepped,
            ),
            violated_clusters: share(
                &mut self.violated_clusters,
                layout.violated_clusters(),
                stepped,
            ),
            applied: self.applied,
            steps: self.steps,
            step_times: std::mem::take(&mut self.step_times),
        };
        let unread = {
            let mut slot = self.slot.lock().unwrap_or_else(|e| e.into_inner());
            if let Some(old) = slot.as_mut() {
                let mut times = std::mem::take(&mut old.step_times);
                times.append(&mut frame.step_times);
                frame.step_times = times;
            }
            slot.replace(frame)
        };
        // The unread frame is freed outside the lock.
        drop(unread);
    }
}

/// `now` (none unless the layout `stepped`), shared through `kept`: a new list only
/// when it differs from the one kept.
fn share<T: Clone + PartialEq>(kept: &mut Arc<Vec<T>>, now: &[T], stepped: bool) -> Arc<Vec<T>> {
    let now = if stepped { now } else { &[] };
    if kept.as_slice() != now {
        *kept = Arc::new(now.to_vec());
    }
    Arc::clone(kept)
}
