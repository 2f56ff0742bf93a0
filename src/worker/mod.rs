//! A layout on a thread of its own: [`LayoutWorker`] owns a [`RapierLayout`] on a
//! worker thread, takes the host's edits, pins, drags and forces as messages, and
//! publishes the newest positions after every step. The host's thread never waits for
//! a step, except when it drops the worker.

mod thread;

use std::hash::Hash;
use std::sync::mpsc::{channel, Sender};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::Duration;

use euclid::default::{Box2D, Point2D};

use self::thread::{Command, Slot, Worker};
use crate::config::RapierLayoutConfig;
use crate::input::clusters::Cluster;
use crate::input::constraints::Constraint;
use crate::input::layout::{LayoutExtras, NodeMap, NodeSet};
use crate::input::node_forces::NodeForces;
use crate::input::scene::{CanvasEdge, CanvasNode, CanvasSceneInput};
use crate::input::shape::NodeShape;
#[cfg(doc)]
use crate::RapierLayout;

/// The positions of one step of a [`LayoutWorker`], as the host reads them.
#[derive(Clone, Debug)]
pub struct LayoutFrame<N> {
    /// The node ids, in the worker's scene order (the host's order, nodes added since
    /// at the end). Shared between frames until the node set changes.
    pub ids: Arc<Vec<N>>,
    /// Each id's index in [`ids`](Self::ids) and [`positions`](Self::positions).
    pub index: Arc<NodeMap<N, usize>>,
    /// Each node's position after the step, in the order of [`ids`](Self::ids).
    pub positions: Vec<Point2D<f32>>,
    /// Whether the layout rested after this step ([`crate::Layout::is_converged`]).
    pub converged: bool,
    /// Each cluster's box after the step ([`RapierLayout::cluster_bounds`]), in the
    /// order of the cluster list the step held: the last one sent among the
    /// [`applied`](Self::applied) messages (a list sent since reaches a later frame);
    /// empty without clusters.
    pub cluster_bounds: Arc<Vec<Box2D<f32>>>,
    /// The constraints the step left more than a unit from holding
    /// ([`RapierLayout::violated_constraints`]), as indices into the last constraint
    /// list sent.
    pub violated_constraints: Arc<Vec<usize>>,
    /// The clusters the step left more than a unit from holding
    /// ([`RapierLayout::violated_clusters`]), as indices into the last cluster list sent.
    pub violated_clusters: Arc<Vec<usize>>,
    /// How many of the host's messages the worker had applied before this step.
    pub applied: u64,
    /// Steps the worker has taken in all.
    pub steps: u64,
    /// The wall time of each step since the host's previous
    /// [`frame`](LayoutWorker::frame) call (the worker may step more often than the host
    /// reads; empty when it has not stepped since).
    pub step_times: Vec<Duration>,
}

impl<N> Default for LayoutFrame<N> {
    fn default() -> Self {
        Self {
            ids: Arc::default(),
            index: Arc::default(),
            positions: Vec::new(),
            converged: false,
            cluster_bounds: Arc::default(),
            violated_constraints: Arc::default(),
            violated_clusters: Arc::default(),
            applied: 0,
            steps: 0,
            step_times: Vec::new(),
        }
    }
}

/// A [`RapierLayout`] stepping on a thread of its own, for graphs whose step would cost
/// the host's UI thread its frame rate.
///
/// The host sends what changes (nodes and edges added or removed, pins, drags, host
/// moves, per-node forces, a new configuration): each message costs the host's thread
/// what it carries, never a copy of the scene, and the worker applies them in the order
/// they were sent. [`frame`](Self::frame) returns the newest positions without waiting
/// for a step; a dragged node reads where the host last put it, in the same frame. The
/// worker steps once per `frame_time` of real time with `dt = frame_time`; it sleeps
/// while the layout rests and wakes on the next message. Dropping the handle stops the
/// thread.
///
/// The trade: a step slower than `frame_time` (a graph of 100,000 nodes under
/// [`stress`](RapierLayoutConfig::stress), `docs/performance.md`) runs the layout in slow
/// motion instead of simulating the lost time in the next step, whose substeps would
/// make it slower still. The host keeps its frame rate and sees a new frame after
/// every step; a node let go in slow motion is thrown with the pointer's last move over
/// one simulated frame, faster than the hand moved.
///
/// Which step a message lands in depends on the machine's timing, so runs through a
/// worker are not bit-for-bit reproducible, as a [`RapierLayout`] stepped by the host
/// is.
///
/// # Example
/// ```
/// use graph_canvas_layout::worker::LayoutWorker;
/// use graph_canvas_layout::{euclid::default::Point2D, CanvasEdge, CanvasNode, CanvasSceneInput,
///     RapierLayoutConfig};
/// let scene = CanvasSceneInput::new(
///     (0..6).map(|i| CanvasNode::new(i, Point2D::origin())).collect(),
///     (0..6).map(|i| CanvasEdge::new(i, (i + 1) % 6)).collect(),
/// );
/// let mut worker = LayoutWorker::spawn(scene, RapierLayoutConfig::stress());
/// worker.pin(0);
/// // The UI loop: read the newest positions each frame, draw, send what the user did.
/// let started = std::time::Instant::now();
/// loop {
///     assert!(started.elapsed().as_secs() < 60, "at rest within a minute");
///     let frame = worker.frame();
///     assert!(frame.positions.len() == 6 || frame.steps == 0);
///     if worker.is_converged() {
///         break;
///     }
///     std::thread::sleep(std::time::Duration::from_millis(16));
/// }
/// let spread = worker.position(&3).unwrap() - worker.position(&0).unwrap();
/// assert!(spread.length() > 100.0, "laid out: 0 and 3 are {spread:?} apart");
/// ```
pub struct LayoutWorker<N: Clone + Eq + Hash + Send + Sync + 'static> {
    commands: Option<Sender<(u64, Command<N>)>>,
    slot: Slot<N>,
    thread: Option<JoinHandle<()>>,
    latest: LayoutFrame<N>,
    /// Where the host holds each dragged node.
    drags: NodeMap<N, Point2D<f32>>,
    /// The nodes the worker was told are pinned.
    pinned: NodeSet<N>,
    /// The last constraint list sent.
    constraints: Vec<Constraint<N>>,
    /// The last cluster list sent.
    clusters: Vec<Cluster<N>>,
    /// The sequence number of the last message sent.
    sent: u64,
}

impl<N: Clone + Eq + Hash + Send + Sync + 'static> LayoutWorker<N> {
    /// Starts a worker laying `scene` out under `config`, one step per 1/60 s.
    ///
    /// # Panics
    /// If the operating system cannot start a thread.
    pub fn spawn(scene: CanvasSceneInput<N>, config: RapierLayoutConfig) -> Self {
        Self::spawn_with(
            scene,
            config,
            LayoutExtras::default(),
            Duration::from_secs_f64(1.0 / 60.0),
        )
    }

    /// [`spawn`](Self::spawn) with the host's pins, drags and forces from the first
    /// step on, and one step of `dt = frame_time` per `frame_time` of real time at most
    /// (a step that takes longer is followed by the next at once). `frame_time` is
    /// clamped to 1 ms ..= 1 s.
    ///
    /// # Panics
    /// If the operating system cannot start a thread.
    pub fn spawn_with(
        scene: CanvasSceneInput<N>,
        config: RapierLayoutConfig,
        extras: LayoutExtras<N>,
        frame_time: Duration,
    ) -> Self {
        #[cfg(feature = "parallel")]
        let threads = std::thread::available_parallelism().map_or(1, |n| n.get().max(2) - 1);
        #[cfg(not(feature = "parallel"))]
        let threads = 1;
        Self::start(scene, config, extras, frame_time, threads)
    }

    /// [`spawn_with`](Self::spawn_with) on a rayon pool of `threads` threads of the
    /// worker's own (at least 1), for the layout's parallel forces and rapier's solver.
    /// [`spawn`](Self::spawn) and `spawn_with` take one thread fewer than the machine
    /// has cores, so the host's UI thread keeps a core. The positions are the same bits
    /// on any thread count for layouts whose contacts are the layout's own
    /// ([`force_directed`](RapierLayoutConfig::force_directed),
    /// [`stress`](RapierLayoutConfig::stress)).
    ///
    /// # Panics
    /// If the operating system cannot start a thread (a pool that cannot be built falls
    /// back to rayon's global pool).
    #[cfg(feature = "parallel")]
    pub fn spawn_on_threads(
        scene: CanvasSceneInput<N>,
        config: RapierLayoutConfig,
        extras: LayoutExtras<N>,
        frame_time: Duration,
        threads: usize,
    ) -> Self {
        Self::start(scene, config, extras, frame_time, threads.max(1))
    }

    fn start(
        scene: CanvasSceneInput<N>,
        config: RapierLayoutConfig,
        extras: LayoutExtras<N>,
        frame_time: Duration,
        threads: usize,
    ) -> Self {
        let frame_time = frame_time.clamp(Duration::from_millis(1), Duration::from_secs(1));
        let (commands, receiver) = channel();
        let slot: Slot<N> = Arc::new(Mutex::new(None));
        let pinned = extras.pinned.clone();
        let (constraints, clusters) = (extras.constraints.clone(), extras.clusters.clone());
        let worker = Worker::new(
            scene,
            config,
            extras,
            frame_time,
            receiver,
            Arc::clone(&slot),
        );
        let thread = std::thread::Builder::new()
            .name("graph-canvas-layout".into())
            .spawn(move || run_on(worker, threads))
            .expect("a layout worker thread");
        Self {
            commands: Some(commands),
            slot,
            thread: Some(thread),
            latest: LayoutFrame::default(),
            drags: NodeMap::default(),
            pinned,
            constraints,
            clusters,
            sent: 0,
        }
    }

    /// The newest positions: the worker's last step, with every dragged node where the
    /// host last put it. Never waits for a step; the first frames before the worker's
    /// first step are empty.
    pub fn frame(&mut self) -> &LayoutFrame<N> {
        let newest = self.slot.lock().unwrap_or_else(|e| e.into_inner()).take();
        match newest {
            Some(frame) => self.latest = frame,
            // The step times went out with the frame that carried them.
            None => self.latest.step_times.clear(),
        }
        for (id, at) in &self.drags {
            if let Some(&i) = self.latest.index.get(id) {
                if let Some(p) = self.latest.positions.get_mut(i) {
                    *p = *at;
                }
            }
        }
        &self.latest
    }

    /// Node `id`'s position in the last [`frame`](Self::frame) read (a dragged node:
    /// where the host holds it).
    pub fn position(&self, id: &N) -> Option<Point2D<f32>> {
        let i = *self.latest.index.get(id)?;
        self.drags
            .get(id)
            .copied()
            .or_else(|| self.latest.positions.get(i).copied())
    }

    /// Whether the layout rests with every message sent so far applied, as of the last
    /// [`frame`](Self::frame) read (call that first, once a frame).
    pub fn is_converged(&self) -> bool {
        // A drag in progress is motion (a drag of an id the worker does not hold is not).
        self.latest.converged
            && self.latest.applied == self.sent
            && !self
                .drags
                .keys()
                .any(|id| self.latest.index.contains_key(id))
    }

    /// Whether the worker thread still runs (it stops only when the handle is dropped,
    /// or if a step panicked).
    pub fn is_running(&self) -> bool {
        self.thread.as_ref().is_some_and(|t| !t.is_finished())
    }

    /// Adds a node (an id already in the scene is left out of the layout, as
    /// [`Layout::step`](crate::Layout::step) leaves out repeats).
    pub fn add_node(&mut self, node: CanvasNode<N>) {
        self.send(Command::AddNode(node));
    }

    /// Removes node `id` and its edges, pin, drag and forces.
    pub fn remove_node(&mut self, id: N) {
        self.drags.remove(&id);
        self.pinned.remove(&id);
        self.send(Command::RemoveNode(id));
    }

    /// Adds an edge.
    pub fn add_edge(&mut self, edge: CanvasEdge<N>) {
        self.send(Command::AddEdge(edge));
    }

    /// Gives node `id` a new radius and shape ([`NodeShape`]): a label edited, a box
    /// toggled. The body is reshaped in place; the node keeps its motion.
    pub fn reshape(&mut self, id: N, radius: f32, shape: NodeShape) {
        self.send(Command::Reshape(id, radius, shape));
    }

    /// Removes every edge between `a` and `b`, either way round.
    pub fn remove_edge(&mut self, a: N, b: N) {
        self.send(Command::RemoveEdge(a, b));
    }

    /// Puts node `id` at `at`, as a host moves its own node (undo, snap).
    pub fn move_node(&mut self, id: N, at: Point2D<f32>) {
        self.send(Command::Move(id, at));
    }

    /// The user's pointer holds node `id` at `at` (call it every frame the pointer
    /// moves): the node reads there at once, and the release throws it with the
    /// pointer's last speed.
    pub fn drag(&mut self, id: N, at: Point2D<f32>) {
        self.drags.insert(id.clone(), at);
        self.send(Command::Drag(id, at));
    }

    /// The pointer lets node `id` go.
    pub fn release(&mut self, id: N) {
        self.drags.remove(&id);
        self.send(Command::Release(id));
    }

    /// Pins node `id` where it is.
    pub fn pin(&mut self, id: N) {
        self.pinned.insert(id.clone());
        self.send(Command::Pin(id, true));
    }

    /// Unpins node `id`.
    pub fn unpin(&mut self, id: N) {
        self.pinned.remove(&id);
        self.send(Command::Pin(id, false));
    }

    /// Sends what `extras` says of drags, pins, constraints and clusters where it
    /// changed: node by node in `scene`'s order, each dragged node where `scene` has
    /// it, a release for a node no longer dragged, a pin or an unpin; then the
    /// constraint and cluster lists, each when it differs from the one sent last. A
    /// host that keeps its own [`LayoutExtras`] calls this once a frame in place of
    /// [`drag`](Self::drag), [`release`](Self::release), [`pin`](Self::pin),
    /// [`unpin`](Self::unpin), [`set_constraints`](Self::set_constraints) and
    /// [`set_clusters`](Self::set_clusters). The lists are compared each call (a walk
    /// of their members; a NaN gap or padding equals itself, so an unchanged list is
    /// never sent again).
    pub fn hold(&mut self, scene: &CanvasSceneInput<N>, extras: &LayoutExtras<N>) {
        for node in &scene.nodes {
            let id = &node.id;
            if extras.dragging.contains(id) {
                self.drag(id.clone(), node.position);
            } else if self.drags.contains_key(id) {
                self.release(id.clone());
            }
            match (extras.pinned.contains(id), self.pinned.contains(id)) {
                (true, false) => self.pin(id.clone()),
                (false, true) => self.unpin(id.clone()),
                _ => {}
            }
        }
        if !same_list(&extras.constraints, &self.constraints, Constraint::same_as) {
            self.set_constraints(extras.constraints.clone());
        }
        if !same_list(&extras.clusters, &self.clusters, Cluster::same_as) {
            self.set_clusters(extras.clusters.clone());
        }
    }

    /// Replaces the hard constraints, as
    /// [`LayoutExtras::constraints`](crate::LayoutExtras::constraints) does for a
    /// [`RapierLayout`]: a constraint added, removed or changed reheats the nodes it
    /// names. [`LayoutFrame::violated_constraints`] indexes this list.
    pub fn set_constraints(&mut self, constraints: Vec<Constraint<N>>) {
        self.constraints.clone_from(&constraints);
        self.send(Command::Constraints(constraints));
    }

    /// Replaces the clusters, as [`LayoutExtras::clusters`](crate::LayoutExtras::clusters)
    /// does for a [`RapierLayout`]: a cluster added, removed or changed reheats its
    /// members. [`LayoutFrame::cluster_bounds`] gives the boxes in this list's order.
    pub fn set_clusters(&mut self, clusters: Vec<Cluster<N>>) {
        self.clusters.clone_from(&clusters);
        self.send(Command::Clusters(clusters));
    }

    /// Sets node `id`'s per-node forces ([`NodeForces`]), or clears them with `None`.
    pub fn set_forces(&mut self, id: N, forces: Option<NodeForces>) {
        self.send(Command::Forces(id, forces));
    }

    /// Replaces the layout's configuration, as assigning
    /// [`RapierLayout::config`] does.
    pub fn set_config(&mut self, config: RapierLayoutConfig) {
        self.send(Command::Configure(Box::new(config)));
    }

    /// Whether another thread of the worker's pool stays awake through a step's
    /// substeps, as [`RapierLayout::set_pool_awake`] says (default: on). A pool of one
    /// thread (the default where the machine has two cores) has no other thread to keep
    /// awake.
    pub fn set_pool_awake(&mut self, on: bool) {
        self.send(Command::PoolAwake(on));
    }

    fn send(&mut self, command: Command<N>) {
        self.sent += 1;
        if let Some(commands) = &self.commands {
            // A worker that stopped (a panicked step) has nothing to apply it to.
            let _ = commands.send((self.sent, command));
        }
    }
}

impl<N: Clone + Eq + Hash + Send + Sync + 'static> Drop for LayoutWorker<N> {
    /// Stops the worker and joins its thread: it returns at once while it rests or waits
    /// for its next frame, and after the step in progress otherwise: the one call that
    /// waits for a step.
    fn drop(&mut self) {
        self.commands = None;
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

impl<N: Clone + Eq + Hash + Send + Sync + 'static + std::fmt::Debug> std::fmt::Debug
    for LayoutWorker<N>
{
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LayoutWorker")
            .field("sent", &self.sent)
            .field("steps", &self.latest.steps)
            .field("converged", &self.latest.converged)
            .finish_non_exhaustive()
    }
}

/// Whether lists `a` and `b` hold the same items by `same`.
fn same_list<T>(a: &[T], b: &[T], same: impl Fn(&T, &T) -> bool) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(a, b)| same(a, b))
}

/// Runs `worker` on a rayon pool of `threads` threads of its own under `parallel`.
#[cfg(feature = "parallel")]
fn run_on<N: Clone + Eq + Hash + Send + Sync + 'static>(worker: Worker<N>, threads: usize) {
    match rayon::ThreadPoolBuilder::new().num_threads(threads).build() {
        Ok(pool) => pool.install(|| worker.run()),
        Err(_) => worker.run(),
    }
}

/// Runs `worker` on its thread (no pool without `parallel`).
#[cfg(not(feature = "parallel"))]
fn run_on<N: Clone + Eq + Hash + Send + Sync + 'static>(worker: Worker<N>, _threads: usize) {
    worker.run()
}
