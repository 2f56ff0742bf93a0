//! Les Misérables in egui_graphs' `GraphView`, laid out by graph-canvas-layout, each
//! character a box with its name inside ([`LabelBox`]) that the layout keeps clear of
//! the others: drag a node and let go to throw it; the layout settles and says so in
//! the top bar.
//!
//! `cargo run --release -p graph-canvas-layout-egui-graphs --example les_miserables
//! [-- --log]`: with `--log` every frame prints the frame number, whether the layout
//! rests, the dragged node, and the window position of the node farthest from the
//! centre, so a script can drive the window (`scripts/egui-graphs-xvfb.sh`).

use eframe::{run_native, App, CreationContext, NativeOptions};
use egui::{Panel, Pos2};
use egui_graphs::{
    Graph, GraphView, LayoutState, MetadataFrame, SettingsNavigation, SettingsStyle,
};
use graph_canvas_layout::scene::SceneFile;
use graph_canvas_layout_egui_graphs::{LabelBox, RapierGraphLayout, RapierGraphState};
use petgraph::stable_graph::{DefaultIx, NodeIndex, StableGraph};
use petgraph::Undirected;

type LesMis = Graph<(), (), Undirected, DefaultIx, LabelBox>;

/// The characters, by node id (networkx's order, which the scene file follows).
#[rustfmt::skip]
const NAMES: [&str; 77] = [
    "Napoleon", "Myriel", "MlleBaptistine", "MmeMagloire", "CountessDeLo", "Geborand",
    "Champtercier", "Cravatte", "Count", "OldMan", "Valjean", "Labarre", "Marguerite",
    "MmeDeR", "Isabeau", "Gervais", "Listolier", "Tholomyes", "Fameuil", "Blacheville",
    "Favourite", "Dahlia", "Zephine", "Fantine", "MmeThenardier", "Thenardier", "Cosette",
    "Javert", "Fauchelevent", "Bamatabois", "Perpetue", "Simplice", "Scaufflaire",
    "Woman1", "Judge", "Champmathieu", "Brevet", "Chenildieu", "Cochepaille", "Pontmercy",
    "Boulatruelle", "Eponine", "Anzelma", "Woman2", "MotherInnocent", "Gribier",
    "MmeBurgon", "Jondrette", "Gavroche", "Gillenormand", "Magnon", "MlleGillenormand",
    "MmePontmercy", "MlleVaubois", "LtGillenormand", "Marius", "BaronessT", "Mabeuf",
    "Enjolras", "Combeferre", "Prouvaire", "Feuilly", "Courfeyrac", "Bahorel", "Bossuet",
    "Joly", "Grantaire", "MotherPlutarch", "Gueulemer", "Babet", "Claquesous",
    "Montparnasse", "Toussaint", "Child1", "Child2", "Brujon", "MmeHucheloup",
];

struct LesMiserables {
    graph: LesMis,
    log: bool,
    frames: u64,
    /// Whether the layout has rested once: until then the view fits the graph.
    rested_once: bool,
    /// The node the log follows: the one farthest from the centre when the layout first
    /// rested.
    tracked: Option<NodeIndex>,
}

impl LesMiserables {
    fn new(_: &CreationContext<'_>, log: bool) -> Self {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../scenes/les_miserables.json"
        );
        let text = std::fs::read_to_string(path).expect("scenes/les_miserables.json");
        let file: SceneFile = serde_json::from_str(&text).expect("scene json");
        let mut g = StableGraph::<(), (), Undirected>::default();
        let mut index = std::collections::HashMap::new();
        for node in &file.nodes {
            index.insert(node.id, g.add_node(()));
        }
        for &(a, b) in &file.edges {
            g.add_edge(index[&a], index[&b], ());
        }
        let mut graph = LesMis::from(&g);
        for node in &file.nodes {
            if let Some(n) = graph.g_mut().node_weight_mut(index[&node.id]) {
                n.set_location(Pos2::new(node.x, node.y));
                let name = NAMES.get(node.id as usize).copied().unwrap_or("?");
                n.set_label(name.to_string());
            }
        }
        Self {
            graph,
            log,
            frames: 0,
            rested_once: false,
            tracked: None,
        }
    }

    /// The node farthest from the graph's centre.
    fn outermost(&self) -> Option<NodeIndex> {
        let nodes: Vec<(NodeIndex, Pos2)> = self
            .graph
            .nodes_iter()
            .map(|(i, n)| (i, n.location()))
            .collect();
        let centre = nodes
            .iter()
            .fold(egui::Vec2::ZERO, |s, (_, p)| s + p.to_vec2())
            / nodes.len().max(1) as f32;
        nodes
            .iter()
            .max_by(|a, b| {
                let (da, db) = (
                    (a.1.to_vec2() - centre).length(),
                    (b.1.to_vec2() - centre).length(),
                );
                da.total_cmp(&db)
            })
            .map(|(i, _)| *i)
    }
}

impl App for LesMiserables {
    fn ui(&mut self, ui: &mut egui::Ui, _: &mut eframe::Frame) {
        self.frames += 1;
        let state = RapierGraphState::load(ui, None);
        let converged = state.converged;
        self.rested_once |= converged && self.frames > 5;
        if !self.rested_once || self.tracked.is_none() {
            self.tracked = self.outermost();
        }
        Panel::top("status").show(ui, |ui| {
            ui.horizontal(|ui| {
                ui.label(format!(
                    "Les Misérables, {} nodes · frame {} · {}",
                    self.graph.node_count(),
                    self.frames,
                    if converged { "at rest" } else { "moving" }
                ));
                if let Some(heat) = state.with_layout(|l| l.heat()).flatten() {
                    ui.label(format!("heat {heat:.3}"));
                }
                ui.label("drag a node and let go to throw it");
            });
        });
        // Fit the graph to the window until it first rests, then hold the view still so
        // a drag stays under the pointer.
        let fit = !self.rested_once;
        let navigation = SettingsNavigation::new()
            .with_fit_to_screen_enabled(fit)
            .with_zoom_and_pan_enabled(!fit);
        egui::CentralPanel::default().show(ui, |ui| {
            let view = GraphView::<RapierGraphState, RapierGraphLayout>::new()
                .with_navigations(&navigation)
                .with_styles(&SettingsStyle::new().with_labels_always(false))
                .show(ui, &mut self.graph);
            if self.log {
                let meta = MetadataFrame::new(None).load(ui);
                let rect = view.response.rect;
                let tracked = self.tracked;
                let at = tracked
                    .and_then(|i| self.graph.g().node_weight(i))
                    .map(|n| n.location())
                    .unwrap_or_default();
                let screen = rect.min + meta.canvas_to_screen_pos(at).to_vec2();
                let ppp = ui.ctx().pixels_per_point();
                println!(
                    "frame {} converged {} dragged {:?} tracked {:?} at {:.1} {:.1} window {:.0} {:.0}",
                    self.frames,
                    converged,
                    self.graph.dragged_node().map(|i| i.index()),
                    tracked.map(|i| i.index()),
                    at.x,
                    at.y,
                    screen.x * ppp,
                    screen.y * ppp,
                );
            }
        });
    }
}

fn main() -> eframe::Result<()> {
    let log = std::env::args().any(|a| a == "--log");
    let options = NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1000.0, 760.0])
            .with_position([0.0, 0.0]),
        ..NativeOptions::default()
    };
    run_native(
        "graph-canvas-layout in egui_graphs",
        options,
        Box::new(move |cc| Ok(Box::new(LesMiserables::new(cc, log)))),
    )
}
