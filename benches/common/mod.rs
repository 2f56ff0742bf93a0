//! Scene factories and host loops shared by the benchmarks.
#![allow(dead_code)]

use graph_canvas_layout::rapier2d::prelude::{
    ActiveEvents, ChannelEventCollector, ColliderBuilder, IntegrationParameters, MotorModel,
    PhysicsWorld, RigidBodyBuilder, RigidBodyHandle, SpringJointBuilder, Vector,
};
use graph_canvas_layout::scene::SceneFile;
use graph_canvas_layout::{
    CanvasSceneInput, CanvasViewport, DeltaMap, Layout, LayoutExtras, RapierLayout,
    RapierLayoutConfig, RapierLayoutState,
};

pub mod generate;

pub const FRAME: f32 = 1.0 / 60.0;

/// Loads `scenes/<name>.json`, or generates the scene a generator's name stands for
/// (`ba_n10000_m2`, `random_n100000_e250000`: [`generate::by_name`]).
pub fn scene(name: &str) -> CanvasSceneInput<u32> {
    if let Some(scene) = generate::by_name(name) {
        return scene;
    }
    let path = format!("{}/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str::<SceneFile>(&text)
        .unwrap_or_else(|e| panic!("{path}: {e}"))
        .into_scene()
}

/// A host canvas: owns the positions and adds the deltas, as a real one would.
pub struct Host {
    pub scene: CanvasSceneInput<u32>,
    pub layout: RapierLayout<u32>,
    pub state: RapierLayoutState,
    pub extras: LayoutExtras<u32>,
}

impl Host {
    pub fn new(scene: CanvasSceneInput<u32>, config: RapierLayoutConfig) -> Self {
        Self {
            scene,
            layout: RapierLayout::new(config),
            state: RapierLayoutState::default(),
            extras: LayoutExtras::default(),
        }
    }

    pub fn frame(&mut self) -> DeltaMap<u32> {
        let deltas = self.layout.step(
            &self.scene,
            &mut self.state,
            FRAME,
            &CanvasViewport::default(),
            &self.extras,
        );
        self.scene.apply_deltas(&deltas);
        deltas
    }
}

/// Which bare rapier model to build.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BareModel {
    /// The same bodies, colliders and joints as the layout's default world: rotations
    /// locked, no events, length unit 100, the layout's solver settings.
    Layout,
    /// `Layout` with disks free to rotate: what locking rotations saves.
    LayoutRotating,
    /// A plain rapier world: disks free to rotate, colliders with collision events into
    /// channels, spring joints, default integration parameters.
    RotatingEvents,
}

/// A bare rapier world for a scene, with nothing of the adapter around it.
pub struct Bare {
    pub world: PhysicsWorld,
    pub handles: Vec<RigidBodyHandle>,
    pub model: BareModel,
    collector: ChannelEventCollector,
    _receivers: (
        std::sync::mpsc::Receiver<graph_canvas_layout::rapier2d::prelude::CollisionEvent>,
        std::sync::mpsc::Receiver<graph_canvas_layout::rapier2d::prelude::ContactForceEvent>,
        std::sync::mpsc::Receiver<graph_canvas_layout::rapier2d::prelude::SoftBodyTearEvent>,
    ),
}

impl Bare {
    pub fn new(scene: &CanvasSceneInput<u32>, model: BareModel) -> Self {
        let config = RapierLayoutConfig::default();
        let mut world = PhysicsWorld::new();
        world.gravity = Vector::ZERO;
        if model != BareModel::RotatingEvents {
            world.integration_parameters = IntegrationParameters {
                length_unit: config.solver.length_unit,
                num_solver_iterations: config.solver.accuracy.settings().0,
                normalized_max_linear_velocity: config.solver.max_speed / config.solver.length_unit,
                ..IntegrationParameters::default()
            };
        }
        let mut index = std::collections::HashMap::new();
        let mut handles = Vec::new();
        let m = config.material;
        for n in &scene.nodes {
            let r = if n.radius > 0.0 {
                n.radius
            } else {
                config.default_radius
            };
            let mass = m.density * std::f32::consts::PI * r * r;
            let mut body = RigidBodyBuilder::dynamic()
                .translation(Vector::new(n.position.x, n.position.y))
                .linear_damping(m.linear_damping);
            let mut collider = ColliderBuilder::ball(r).friction(m.friction);
            match model {
                BareModel::Layout => {
                    body = body.lock_rotations().additional_mass(mass);
                    collider = collider.density(0.0);
                }
                BareModel::LayoutRotating => {
                    collider = collider.density(m.density);
                }
                BareModel::RotatingEvents => {
                    collider = collider
                        .density(m.density)
                        .active_events(ActiveEvents::COLLISION_EVENTS);
                }
            }
            let (h, _) = world.insert(body, collider);
            index.insert(n.id, h);
            handles.push(h);
        }
        let mut seen = std::collections::HashSet::new();
        for e in &scene.edges {
            let key = (e.source.min(e.target), e.source.max(e.target));
            if e.source == e.target || !seen.insert(key) {
                continue;
            }
            let joint =
                SpringJointBuilder::new(100.0, 50.0, 1.0).spring_model(MotorModel::ForceBased);
            world.insert_impulse_joint(index[&e.source], index[&e.target], joint);
        }
        let (cs, cr) = std::sync::mpsc::channel();
        let (fs, fr) = std::sync::mpsc::channel();
        let (ts, tr) = std::sync::mpsc::channel();
        Self {
            world,
            handles,
            model,
            collector: ChannelEventCollector::new(cs, fs, ts),
            _receivers: (cr, fr, tr),
        }
    }

    pub fn step(&mut self) {
        match self.model {
            BareModel::Layout | BareModel::LayoutRotating => self.world.step(),
            BareModel::RotatingEvents => {
                self.world.step_with_events(&(), &self.collector);
                while self._receivers.0.try_recv().is_ok() {}
            }
        }
    }
}
