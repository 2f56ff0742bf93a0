//! Interactive demo: a real graph on a live `RapierLayout`.
//!
//! - drag a node with the left button and let go to throw it;
//! - right-click a node to pin or unpin it;
//! - click a node to select it, then shift-click another to add or remove the edge;
//! - ctrl-click nodes to pick them and group them into a cluster (its box drawn);
//! - the side panel adds and removes nodes, switches presets, joints and the
//!   force-directed configuration, draws the nodes as label boxes ("node <id>") or
//!   disks, and shows frame time, step time and convergence.
//!
//! `cargo run --release -p graph-canvas-layout-demo [scene.json] [--boxes] [--worker]
//! [--frames N]` (`--boxes` starts with labels as boxes; `--worker` steps the layout on
//! a thread of its own, as graphs of 5,000 nodes or more always are; `--frames N` quits
//! after N frames, for unattended checks).

mod engine;
mod groups;

use std::time::Instant;

use engine::{Engine, WORKER_FROM};

use eframe::egui;
use graph_canvas_layout::config::{Accuracy, Flow};
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::scene::SceneFile;
use graph_canvas_layout::{
    CanvasEdge, CanvasNode, CanvasSceneInput, EdgeJoint, LayoutExtras, NodeShape,
    RapierLayoutConfig,
};

/// A label box's width per character and height, in world units.
const CHAR_WIDTH: f32 = 7.0;
const BOX_HEIGHT: f32 = 20.0;
/// The least drop from an edge's source to its target under the flow toggle.
const FLOW_GAP: f32 = 60.0;

struct Demo {
    scene: CanvasSceneInput<u32>,
    engine: Engine,
    extras: LayoutExtras<u32>,
    selected: Option<u32>,
    picked: groups::Picked,
    grabbed: Option<u32>,
    next_id: u32,
    last_frame: Instant,
    frame_ms: f32,
    step_us: f32,
    zoom: f32,
    pan: egui::Vec2,
    preset: Preset,
    /// Whether nodes are label boxes ("node <id>") rather than disks.
    boxes: bool,
    /// Frames drawn.
    frames: u64,
    frames_left: Option<u64>,
}

impl Demo {
    fn new(scene: CanvasSceneInput<u32>, frames_left: Option<u64>, worker: bool) -> Self {
        let next_id = scene.nodes.iter().map(|n| n.id).max().map_or(0, |m| m + 1);
        let worker = worker || scene.nodes.len() >= WORKER_FROM;
        Self {
            engine: Engine::new(&scene, RapierLayoutConfig::stress(), worker),
            scene,
            extras: LayoutExtras::default(),
            selected: None,
            picked: groups::Picked::default(),
            grabbed: None,
            next_id,
            last_frame: Instant::now(),
            frame_ms: 0.0,
            step_us: 0.0,
            zoom: 0.45,
            pan: egui::Vec2::ZERO,
            preset: Preset::Stress,
            boxes: false,
            frames: 0,
            frames_left,
        }
    }

    fn to_screen(&self, rect: egui::Rect, p: Point2D<f32>) -> egui::Pos2 {
        rect.center() + self.pan + egui::vec2(p.x, p.y) * self.zoom
    }

    fn to_world(&self, rect: egui::Rect, p: egui::Pos2) -> Point2D<f32> {
        let v = (p - rect.center() - self.pan) / self.zoom;
        Point2D::new(v.x, v.y)
    }

    fn node_at(&self, rect: egui::Rect, p: egui::Pos2) -> Option<u32> {
        self.scene
            .nodes
            .iter()
            .rev()
            .find(|n| {
                let d = p - self.to_screen(rect, n.position);
                match n.shape {
                    NodeShape::Rect { width, height, .. } => {
                        d.x.abs() <= 0.5 * width * self.zoom + 2.0
                            && d.y.abs() <= 0.5 * height * self.zoom + 2.0
                    }
                    NodeShape::Disk => d.length() <= n.radius.max(16.0) * self.zoom + 2.0,
                }
            })
            .map(|n| n.id)
    }

    /// Every node a label box of "node <id>" (with [`boxes`](Self::boxes)) or a disk;
    /// the nodes whose shape changed are sent to the worker.
    fn apply_shapes(&mut self) {
        for n in &mut self.scene.nodes {
            let before = n.shape;
            *n = if self.boxes {
                let label = format!("node {}", n.id);
                let width = CHAR_WIDTH * label.len() as f32 + 8.0;
                n.clone().with_rect(width, BOX_HEIGHT).with_label(label)
            } else {
                n.clone().with_disk()
            };
            if n.shape != before {
                self.engine.reshape(n);
            }
        }
    }

    fn toggle_edge(&mut self, a: u32, b: u32) {
        let before = self.scene.edges.len();
        self.scene
            .edges
            .retain(|e| !((e.source == a && e.target == b) || (e.source == b && e.target == a)));
        if self.scene.edges.len() == before {
            self.scene.edges.push(CanvasEdge::new(a, b));
            self.engine.add_edge(a, b);
        } else {
            self.engine.remove_edge(a, b);
        }
    }

    fn side_panel(&mut self, ui: &mut egui::Ui) {
        ui.heading("graph-canvas-layout");
        ui.label(format!(
            "frame {:.1} ms, step {:.0} µs",
            self.frame_ms, self.step_us
        ));
        ui.label(format!(
            "{} nodes, {} edges",
            self.scene.nodes.len(),
            self.scene.edges.len()
        ));
        let converged = self.engine.is_converged();
        ui.label(if converged {
            "converged: at rest"
        } else {
            "converged: moving"
        });
        ui.label(match self.engine.counts() {
            Some((rebuilds, patches)) => format!("rebuilds {rebuilds}, patches {patches}"),
            None => "on a thread of its own (LayoutWorker)".to_string(),
        });
        let mut config = self.engine.config().clone();
        ui.separator();
        ui.label("layout preset");
        let before = self.preset;
        for preset in Preset::ALL {
            ui.radio_value(&mut self.preset, preset, preset.name());
        }
        if self.preset != before {
            // The preset's accuracy comes with it; the chosen joint and flow stay.
            let keep = (config.edge_joint, config.flow);
            config = self.preset.config();
            (config.edge_joint, config.flow) = keep;
        }
        ui.label("accuracy");
        let preset_accuracy = self.preset.config().solver.accuracy;
        for (name, accuracy) in accuracy_choices(config.solver.accuracy, preset_accuracy) {
            ui.radio_value(&mut config.solver.accuracy, accuracy, name);
        }
        ui.label("edge joint");
        for (name, joint) in joint_choices(config.edge_joint) {
            ui.radio_value(&mut config.edge_joint, joint, name);
        }
        let mut flowing = config.flow.is_some();
        if ui
            .checkbox(&mut flowing, "flow: every edge points down")
            .changed()
        {
            config.flow = flowing.then(|| Flow::down(FLOW_GAP));
        }
        if let Some(flow) = config.flow {
            let mut layered = flow.layered();
            if ui.checkbox(&mut layered, "in layers").changed() {
                let free = Flow::down(FLOW_GAP);
                config.flow = Some(if layered { free.in_layers() } else { free });
            }
        }
        if config != *self.engine.config() {
            self.engine.set_config(config);
        }
        ui.separator();
        if ui.checkbox(&mut self.boxes, "labels as boxes").changed() {
            self.apply_shapes();
        }
        ui.separator();
        if ui.button("add node").clicked() {
            let id = self.next_id;
            self.next_id += 1;
            let anchor = self
                .selected
                .and_then(|s| self.scene.nodes.iter().find(|n| n.id == s))
                .map(|n| n.position);
            let at = anchor.unwrap_or_default()
                + graph_canvas_layout::euclid::default::Vector2D::new(40.0, 10.0);
            self.scene
                .nodes
                .push(CanvasNode::new(id, at).with_radius(16.0));
            self.apply_shapes();
            if let Some(node) = self.scene.nodes.last() {
                self.engine.add_node(node);
            }
            if let Some(s) = self.selected {
                self.scene.edges.push(CanvasEdge::new(s, id));
                self.engine.add_edge(s, id);
            }
            self.selected = Some(id);
        }
        if ui
            .add_enabled(
                self.selected.is_some(),
                egui::Button::new("remove selected"),
            )
            .clicked()
        {
            if let Some(s) = self.selected.take() {
                self.scene.nodes.retain(|n| n.id != s);
                self.scene.edges.retain(|e| e.source != s && e.target != s);
                self.extras.pinned.remove(&s);
                self.picked.forget(s, &mut self.extras);
                self.engine.remove_node(s);
            }
        }
        self.picked.panel(ui, &mut self.extras);
        ui.separator();
        ui.label("drag: move and throw\nright-click: pin / unpin\nclick, then shift-click: add or remove an edge\nscroll: zoom, middle-drag: pan");
    }

    fn canvas(&mut self, ui: &mut egui::Ui) {
        let (response, painter) =
            ui.allocate_painter(ui.available_size(), egui::Sense::click_and_drag());
        let rect = response.rect;
        painter.rect_filled(rect, 0.0, egui::Color32::from_rgb(250, 250, 248));
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if response.hovered() && scroll != 0.0 {
            self.zoom = (self.zoom * (1.0 + scroll * 0.002)).clamp(0.05, 5.0);
        }
        if response.dragged_by(egui::PointerButton::Middle) {
            self.pan += response.drag_delta();
        }
        let pointer = response.interact_pointer_pos().or(response.hover_pos());
        if response.drag_started_by(egui::PointerButton::Primary) {
            // Hit-test where the button went down: by the time egui calls it a drag the
            // pointer has left a small node.
            let origin = ui.input(|i| i.pointer.press_origin()).or(pointer);
            self.grabbed = origin.and_then(|p| self.node_at(rect, p));
        }
        if let (Some(id), Some(p)) = (self.grabbed, pointer) {
            if response.dragged_by(egui::PointerButton::Primary) {
                let at = self.to_world(rect, p);
                if let Some(n) = self.scene.nodes.iter_mut().find(|n| n.id == id) {
                    n.position = at;
                }
                self.extras.dragging.insert(id);
            }
        }
        if response.drag_stopped() {
            self.grabbed = None;
            self.extras.dragging.clear();
        }
        if response.clicked() {
            let hit = pointer.and_then(|p| self.node_at(rect, p));
            let shift = ui.input(|i| i.modifiers.shift);
            let ctrl = ui.input(|i| i.modifiers.command);
            match (shift, self.selected, hit) {
                (_, _, Some(id)) if ctrl => self.picked.toggle(id),
                (true, Some(a), Some(b)) if a != b => self.toggle_edge(a, b),
                (_, _, hit) => self.selected = hit,
            }
        }
        if response.secondary_clicked() {
            if let Some(id) = pointer.and_then(|p| self.node_at(rect, p)) {
                if !self.extras.pinned.remove(&id) {
                    self.extras.pinned.insert(id);
                }
            }
        }
        let position: std::collections::HashMap<u32, Point2D<f32>> = self
            .scene
            .nodes
            .iter()
            .map(|n| (n.id, n.position))
            .collect();
        // Under a flow, edges are arrows from source to target, ending at the target's
        // outline.
        let arrows = self.engine.config().flow.is_some();
        let stroke = egui::Stroke::new(1.0, egui::Color32::from_gray(170));
        for e in &self.scene.edges {
            if let (Some(a), Some(b)) = (position.get(&e.source), position.get(&e.target)) {
                let (from, to) = (self.to_screen(rect, *a), self.to_screen(rect, *b));
                let (v, cut) = (to - from, 16.0 * self.zoom);
                if arrows && v.length() > 2.0 * cut {
                    painter.arrow(from, v * ((v.length() - cut) / v.length()), stroke);
                } else {
                    painter.line_segment([from, to], stroke);
                }
            }
        }
        let bounds = self.engine.cluster_bounds();
        groups::draw(&painter, bounds, |p| self.to_screen(rect, p));
        for n in &self.scene.nodes {
            let fill = if self.extras.pinned.contains(&n.id) {
                egui::Color32::from_rgb(214, 39, 40)
            } else if self.extras.dragging.contains(&n.id) {
                egui::Color32::from_rgb(255, 127, 14)
            } else {
                egui::Color32::from_rgb(31, 119, 180)
            };
            let c = self.to_screen(rect, n.position);
            let selected = Some(n.id) == self.selected || self.picked.0.contains(&n.id);
            let outline = egui::Stroke::new(
                if selected { 2.0 } else { 1.0 },
                if selected {
                    egui::Color32::BLACK
                } else {
                    egui::Color32::WHITE
                },
            );
            match n.shape {
                NodeShape::Rect { width, height, .. } => {
                    let size = egui::vec2(width, height) * self.zoom;
                    let r = egui::Rect::from_center_size(c, size);
                    painter.rect(r, 2.0, fill, outline, egui::StrokeKind::Inside);
                    painter.text(
                        c,
                        egui::Align2::CENTER_CENTER,
                        n.label.as_deref().unwrap_or(""),
                        egui::FontId::monospace(11.0 * self.zoom),
                        egui::Color32::WHITE,
                    );
                }
                NodeShape::Disk => {
                    painter.circle(c, n.radius.max(1.0) * self.zoom, fill, outline);
                }
            }
        }
    }
}

impl eframe::App for Demo {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        let now = Instant::now();
        let dt = (now - self.last_frame).as_secs_f32();
        self.last_frame = now;
        self.frame_ms = self.frame_ms * 0.9 + dt * 1e3 * 0.1;
        if let Some(step_us) = self.engine.frame(&mut self.scene, &self.extras, dt) {
            self.step_us = self.step_us * 0.9 + step_us * 0.1;
        }
        self.frames += 1;
        egui::Panel::left("controls").show(ui, |ui| self.side_panel(ui));
        egui::CentralPanel::default()
            .frame(egui::Frame::NONE)
            .show(ui, |ui| self.canvas(ui));
        if let Some(left) = self.frames_left.as_mut() {
            *left = left.saturating_sub(1);
            if *left == 0 {
                println!(
                    "frames done: {} frames, step {:.0} µs, converged {}, on the worker {}",
                    self.frames,
                    self.step_us,
                    self.engine.is_converged(),
                    self.engine.on_worker()
                );
                ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            }
        }
        ctx.request_repaint();
    }
}

/// The layout presets the demo offers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Preset {
    Stress,
    ForceDirected,
    Default,
}

impl Preset {
    const ALL: [Preset; 3] = [Preset::Stress, Preset::ForceDirected, Preset::Default];

    fn name(self) -> &'static str {
        match self {
            Preset::Stress => "stress (graph distances)",
            Preset::ForceDirected => "force-directed (repulsion)",
            Preset::Default => "physical canvas (default)",
        }
    }

    fn config(self) -> RapierLayoutConfig {
        match self {
            Preset::Stress => RapierLayoutConfig::stress(),
            Preset::ForceDirected => RapierLayoutConfig::force_directed(),
            Preset::Default => RapierLayoutConfig::default(),
        }
    }
}

/// The edge joint radio buttons: four joints, and the one in force when it is none of
/// them (`force_directed()`'s own spring), so one is always selected.
fn joint_choices(current: EdgeJoint) -> Vec<(String, EdgeJoint)> {
    let mut choices = vec![
        (
            "Spring".to_string(),
            EdgeJoint::Spring {
                rest_length: 100.0,
                stiffness: 50.0,
                damping: 2.0,
            },
        ),
        (
            "Rope".to_string(),
            EdgeJoint::Rope {
                max_length: 120.0,
                stiffness: 1e4,
            },
        ),
        (
            "Distance".to_string(),
            EdgeJoint::Distance { length: 100.0 },
        ),
        ("None".to_string(), EdgeJoint::None),
    ];
    if choices.iter().all(|(_, j)| *j != current) {
        let name = match current {
            EdgeJoint::Spring {
                rest_length,
                stiffness,
                ..
            } => format!("Spring (in force: rest {rest_length}, stiffness {stiffness})"),
            other => format!("{other:?}"),
        };
        choices.push((name, current));
    }
    choices
}

/// The accuracy radio buttons: the three named settings, the preset's own when it is
/// custom (`force_directed()`'s is), and whatever else is in force, so one is always
/// selected.
fn accuracy_choices(current: Accuracy, preset: Accuracy) -> Vec<(String, Accuracy)> {
    let mut choices = vec![
        ("Fast".to_string(), Accuracy::Fast),
        ("Balanced".to_string(), Accuracy::Balanced),
        ("Precise".to_string(), Accuracy::Precise),
    ];
    for (whose, accuracy) in [("preset", preset), ("custom", current)] {
        if let Accuracy::Custom {
            solver_iterations,
            substeps,
            ..
        } = accuracy
        {
            if choices.iter().all(|(_, a)| *a != accuracy) {
                let plural =
                    |n: usize, what: &str| format!("{n} {what}{}", if n == 1 { "" } else { "s" });
                let name = format!(
                    "{whose}: {} × {}",
                    plural(solver_iterations, "iteration"),
                    plural(substeps as usize, "substep")
                );
                choices.push((name, accuracy));
            }
        }
    }
    choices
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let frames_left = args
        .iter()
        .position(|a| a == "--frames")
        .and_then(|i| args.get(i + 1))
        .and_then(|n| n.parse().ok());
    let boxes = args.iter().any(|a| a == "--boxes");
    let worker = args.iter().any(|a| a == "--worker");
    let path = args
        .iter()
        .find(|a| a.ends_with(".json"))
        .cloned()
        .unwrap_or_else(|| {
            format!(
                "{}/../scenes/les_miserables.json",
                env!("CARGO_MANIFEST_DIR")
            )
        });
    let scene = serde_json::from_str::<SceneFile>(&std::fs::read_to_string(&path)?)?.into_scene();
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1100.0, 750.0])
            .with_title("graph-canvas-layout demo"),
        ..Default::default()
    };
    eframe::run_native(
        "graph-canvas-layout demo",
        options,
        Box::new(move |_cc| {
            let mut demo = Demo::new(scene, frames_left, worker);
            demo.boxes = boxes;
            demo.apply_shapes();
            Ok(Box::new(demo))
        }),
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_accuracy_in_force_is_always_a_choice() {
        for preset in Preset::ALL {
            let config = preset.config();
            let choices = accuracy_choices(config.solver.accuracy, config.solver.accuracy);
            assert!(
                choices.iter().any(|(_, a)| *a == config.solver.accuracy),
                "{:?} ({preset:?}) not among {choices:?}",
                config.solver.accuracy
            );
        }
        // A custom accuracy of the host's own shows too, beside the preset's.
        let own = Accuracy::Custom {
            solver_iterations: 3,
            internal_pgs_iterations: 1,
            substeps: 2,
        };
        let choices = accuracy_choices(own, Preset::ForceDirected.config().solver.accuracy);
        assert_eq!(choices.len(), 5, "{choices:?}");
        assert!(choices.iter().any(|(_, a)| *a == own));
    }

    #[test]
    fn labels_as_boxes_shape_every_node_and_back() {
        let scene = CanvasSceneInput::new(
            vec![
                CanvasNode::new(7, Point2D::new(0.0, 0.0)).with_radius(16.0),
                CanvasNode::new(1234, Point2D::new(50.0, 0.0)).with_radius(16.0),
            ],
            vec![CanvasEdge::new(7, 1234)],
        );
        let mut demo = Demo::new(scene, None, false);
        demo.boxes = true;
        demo.apply_shapes();
        let widths: Vec<_> = demo.scene.nodes.iter().map(|n| n.shape).collect();
        assert_eq!(
            widths,
            [
                NodeShape::Rect {
                    width: 50.0,
                    height: 20.0,
                    corner_radius: 0.0
                },
                NodeShape::Rect {
                    width: 71.0,
                    height: 20.0,
                    corner_radius: 0.0
                },
            ],
            "\"node 7\" and \"node 1234\" at 7 units a character, 8 of room"
        );
        demo.boxes = false;
        demo.apply_shapes();
        assert!(demo.scene.nodes.iter().all(|n| n.shape == NodeShape::Disk));
    }

    #[test]
    fn the_joint_in_force_is_always_a_choice() {
        for preset in Preset::ALL {
            let joint = preset.config().edge_joint;
            let choices = joint_choices(joint);
            assert!(
                choices.iter().any(|(_, j)| *j == joint),
                "{joint:?} ({preset:?}) not among {choices:?}"
            );
        }
    }
}
