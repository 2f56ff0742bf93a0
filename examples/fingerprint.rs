//! Replays fixed host sessions and prints one hash of every output bit per session: the
//! deltas (`to_bits()`), the bodies' positions and velocities, the heat, convergence,
//! contact events and recovered nodes. Two builds that print the same lines behave the
//! same bit for bit on these sessions; a refactor that must not change behaviour is
//! checked by running this before and after it.
//!
//! Run with `cargo run --release --example fingerprint`.

use std::hash::Hasher;

use graph_canvas_layout::config::TopologyUpdate;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::{
    BodyKindPolicy, CanvasEdge, CanvasNode, CanvasSceneInput, CanvasViewport, EdgeJoint, Layout,
    LayoutExtras, RapierLayout, RapierLayoutConfig, RapierLayoutState,
};

mod common;

use common::{load, Fnv};
use graph_canvas_layout::config::Contacts;

const FRAME: f32 = 1.0 / 60.0;

/// A small deterministic generator (xorshift64*).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * (self.next() >> 40) as f32 / (1u64 << 24) as f32
    }
}

struct Session {
    scene: CanvasSceneInput<u32>,
    layout: RapierLayout<u32>,
    state: RapierLayoutState,
    extras: LayoutExtras<u32>,
    hash: Fnv,
    frames: u64,
}

impl Session {
    fn new(scene: CanvasSceneInput<u32>, config: RapierLayoutConfig) -> Self {
        Self {
            scene,
            layout: RapierLayout::new(config),
            state: RapierLayoutState::default(),
            extras: LayoutExtras::default(),
            hash: Fnv::new(),
            frames: 0,
        }
    }

    fn frame(&mut self, dt: f32) {
        let deltas = self.layout.step(
            &self.scene,
            &mut self.state,
            dt,
            &CanvasViewport::default(),
            &self.extras,
        );
        self.frames += 1;
        let h = &mut self.hash;
        for node in &self.scene.nodes {
            if let Some(d) = deltas.get(&node.id) {
                h.write_u32(node.id);
                h.f32(d.x);
                h.f32(d.y);
            }
        }
        h.write_usize(deltas.len());
        self.scene.apply_deltas(&deltas);
        h.write_u8(u8::from(self.layout.is_converged(&self.state)));
        if let Some(heat) = self.layout.heat() {
            h.f32(heat);
        }
        h.write_u64(self.layout.current_topology_hash());
        h.write_u64(self.layout.rebuild_count());
        h.write_u64(self.layout.patch_count());
        for id in self.layout.recovered_nodes() {
            h.write_u32(*id);
        }
        for event in self.layout.drain_events() {
            h.write(format!("{event:?}").as_bytes());
        }
        if let Some(world) = self.layout.world() {
            h.write_usize(world.body_count());
            h.write_usize(world.joint_count());
            for id in world.node_ids() {
                let p = world.get_position(id).expect("body");
                let v = world.linear_velocity(id).expect("body");
                h.write_u32(*id);
                h.f32(p.x);
                h.f32(p.y);
                h.f32(v.x);
                h.f32(v.y);
                h.write(format!("{:?}", world.body_type(id)).as_bytes());
            }
        }
    }

    fn pos(&self, id: u32) -> Option<Point2D<f32>> {
        self.scene
            .nodes
            .iter()
            .find(|n| n.id == id)
            .map(|n| n.position)
    }

    fn set_pos(&mut self, id: u32, p: Point2D<f32>) {
        if let Some(n) = self.scene.nodes.iter_mut().find(|n| n.id == id) {
            n.position = p;
        }
    }
}

/// The determinism test's session: a drag, a throw, a pin and an added node.
fn scripted(config: RapierLayoutConfig, frames: usize) -> Session {
    let mut s = Session::new(load("les_miserables"), config);
    for frame in 0..frames {
        match frame {
            10 => {
                s.extras.dragging.insert(11);
            }
            11..=20 => {
                let p = s.pos(11).expect("node 11");
                s.set_pos(11, p + Vector2D::new(8.0, -3.0));
            }
            21 => s.extras.dragging.clear(),
            30 => {
                s.extras.pinned.insert(0);
            }
            40 => s
                .scene
                .nodes
                .push(CanvasNode::new(1000, Point2D::new(5.0, 5.0))),
            _ => {}
        }
        s.frame(FRAME);
    }
    s
}

/// A random host session over `ids` node ids: nodes and edges coming and going, pins,
/// drags, throws, host moves, bad values, odd frame times.
fn random(config: RapierLayoutConfig, seed: u64, calls: usize, ids: u32) -> Session {
    let mut s = Session::new(CanvasSceneInput::default(), config);
    let mut rng = Rng(seed);
    let times = [
        FRAME,
        1.0 / 144.0,
        1.0 / 30.0,
        0.5,
        0.0,
        -1.0,
        f32::NAN,
        1e-7,
        0.1,
    ];
    let mut poisoned = 0;
    for _ in 0..calls {
        for _ in 0..rng.below(3) {
            let id = rng.below(u64::from(ids)) as u32;
            let has = s.pos(id).is_some();
            match rng.below(12) {
                0 | 1 if !has => {
                    let (x, y) = (rng.range(-400.0, 400.0), rng.range(-400.0, 400.0));
                    s.scene.nodes.push(CanvasNode::new(id, Point2D::new(x, y)));
                }
                2 => {
                    s.scene.nodes.retain(|n| n.id != id);
                    s.scene.edges.retain(|e| e.source != id && e.target != id);
                }
                3 | 4 => {
                    let other = rng.below(u64::from(ids)) as u32;
                    if has && s.pos(other).is_some() {
                        s.scene.edges.push(CanvasEdge::new(id, other));
                    }
                }
                5 if !s.scene.edges.is_empty() => {
                    let i = rng.below(s.scene.edges.len() as u64) as usize;
                    s.scene.edges.remove(i);
                }
                // Toggles: out if in, else in.
                6 => {
                    let _ = s.extras.pinned.remove(&id) || s.extras.pinned.insert(id);
                }
                7 => {
                    let _ = s.extras.dragging.remove(&id) || s.extras.dragging.insert(id);
                }
                8 => {
                    let (x, y) = (rng.range(-200.0, 200.0), rng.range(-200.0, 200.0));
                    if let Some(p) = s.pos(id).filter(|p| p.x.is_finite()) {
                        s.set_pos(id, p + Vector2D::new(x, y));
                    }
                }
                9 if has && poisoned == 0 => {
                    s.set_pos(id, Point2D::new(f32::NAN, 0.0));
                    poisoned = 6;
                }
                10 => {
                    if let Some(n) = s.scene.nodes.iter_mut().find(|n| n.id == id) {
                        n.radius = rng.range(0.0, 30.0);
                    }
                }
                _ => {}
            }
        }
        let dragged: Vec<u32> = s.extras.dragging.iter().copied().collect();
        let mut dragged = dragged;
        dragged.sort_unstable();
        for id in dragged {
            if let Some(p) = s.pos(id).filter(|p| p.x.is_finite()) {
                s.set_pos(id, p + Vector2D::new(3.0, -2.0));
            }
        }
        if poisoned > 0 {
            poisoned -= 1;
            if poisoned == 0 {
                for n in &mut s.scene.nodes {
                    if !n.position.x.is_finite() {
                        n.position = Point2D::new(n.id as f32 * 10.0, 0.0);
                    }
                }
            }
        }
        let dt = times[rng.below(times.len() as u64) as usize];
        s.frame(dt);
    }
    s
}

/// Lays `name` out with `config` until it rests (or `budget` frames), then drags the
/// node farthest from the centre and lets it go, and runs to rest again.
fn to_rest_and_throw(name: &str, config: RapierLayoutConfig, budget: usize) -> Session {
    let mut s = Session::new(load(name), config);
    let mut rest = 0;
    for frame in 0..budget {
        s.frame(FRAME);
        if s.layout.is_converged(&s.state) {
            rest = frame + 1;
            break;
        }
    }
    s.hash.write_usize(rest);
    let far = s
        .scene
        .nodes
        .iter()
        .max_by(|a, b| {
            let (da, db) = (
                a.position.to_vector().length(),
                b.position.to_vector().length(),
            );
            da.total_cmp(&db)
        })
        .map(|n| n.id)
        .expect("nodes");
    s.extras.dragging.insert(far);
    for _ in 0..10 {
        let p = s.pos(far).expect("dragged");
        let out = p.to_vector().normalize() * 30.0;
        s.set_pos(far, p + out);
        s.frame(FRAME);
    }
    s.extras.dragging.clear();
    for _ in 0..budget {
        s.frame(FRAME);
        if s.layout.is_converged(&s.state) {
            break;
        }
    }
    s
}

fn report(name: &str, s: &Session) {
    println!(
        "{name:40} frames {:5} hash {:016x}",
        s.frames,
        s.hash.finish()
    );
}

fn main() {
    let default = RapierLayoutConfig::default;
    report("scripted/default", &scripted(default(), 120));
    report(
        "scripted/force_directed",
        &scripted(RapierLayoutConfig::force_directed(), 300),
    );
    report(
        "rest/les_miserables/force_directed",
        &to_rest_and_throw("les_miserables", RapierLayoutConfig::force_directed(), 1200),
    );
    report(
        "rest/karate/force_directed_fast",
        &to_rest_and_throw("karate", RapierLayoutConfig::force_directed_fast(), 1200),
    );
    report(
        "rest/n200_e500/force_directed",
        &to_rest_and_throw("n200_e500", RapierLayoutConfig::force_directed(), 1200),
    );
    report(
        "rest/karate/default",
        &to_rest_and_throw("karate", default(), 1200),
    );
    let configs: Vec<(&str, RapierLayoutConfig)> = vec![
        ("default", default()),
        ("force_directed", RapierLayoutConfig::force_directed()),
        (
            "force_directed_fast",
            RapierLayoutConfig::force_directed_fast(),
        ),
        (
            "rope/rebuild",
            RapierLayoutConfig {
                edge_joint: EdgeJoint::Rope {
                    max_length: 120.0,
                    stiffness: 1e4,
                },
                topology_update: TopologyUpdate::Rebuild,
                ..default()
            },
        ),
        (
            "distance/kinematic_pins/events",
            RapierLayoutConfig {
                edge_joint: EdgeJoint::Distance { length: 80.0 },
                body_kind_policy: BodyKindPolicy::PinnedKinematic,
                contacts: Contacts {
                    events: true,
                    ..Default::default()
                },
                ..default()
            },
        ),
        (
            "none/no_collisions",
            RapierLayoutConfig {
                edge_joint: EdgeJoint::None,
                contacts: Contacts {
                    enabled: false,
                    ..Default::default()
                },
                ..default()
            },
        ),
        (
            "all_kinematic",
            RapierLayoutConfig {
                body_kind_policy: BodyKindPolicy::AllKinematic,
                ..default()
            },
        ),
        (
            "force_directed/rebuild",
            RapierLayoutConfig {
                topology_update: TopologyUpdate::Rebuild,
                ..RapierLayoutConfig::force_directed()
            },
        ),
    ];
    for (label, config) in configs {
        for seed in [1_u64, 2, 3] {
            let s = random(config.clone(), seed * 0x9e37_79b9_7f4a_7c15, 1500, 24);
            report(&format!("random/{label}/seed{seed}"), &s);
        }
    }
    // A mid-session configuration change.
    let mut s = scripted(default(), 60);
    s.layout.config = RapierLayoutConfig::force_directed();
    for _ in 0..200 {
        s.frame(FRAME);
    }
    s.layout.config.edge_joint = EdgeJoint::Rope {
        max_length: 150.0,
        stiffness: 500.0,
    };
    for _ in 0..100 {
        s.frame(FRAME);
    }
    report("reconfigured", &s);
    // The stress model (after the sessions above, which keep their order).
    report(
        "rest/les_miserables/stress",
        &to_rest_and_throw("les_miserables", RapierLayoutConfig::stress(), 1200),
    );
    for seed in [1_u64, 2, 3] {
        let s = random(
            RapierLayoutConfig::stress(),
            seed * 0x9e37_79b9_7f4a_7c15,
            1500,
            24,
        );
        report(&format!("random/stress/seed{seed}"), &s);
    }
}
