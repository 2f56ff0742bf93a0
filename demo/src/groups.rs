//! Clusters in the demo: ctrl-click nodes to pick them, group the picked nodes into a
//! cluster (a box no other node enters), and see every cluster's box drawn.

use std::collections::BTreeSet;

use eframe::egui;
use graph_canvas_layout::euclid::default::{Box2D, Point2D};
use graph_canvas_layout::scene::Cluster;
use graph_canvas_layout::LayoutExtras;

/// The nodes picked for the next cluster.
#[derive(Default)]
pub struct Picked(pub BTreeSet<u32>);

impl Picked {
    /// Picks node `id`, or unpicks it.
    pub fn toggle(&mut self, id: u32) {
        if !self.0.remove(&id) {
            self.0.insert(id);
        }
    }

    /// The side panel's part: group the picked nodes, or drop every cluster.
    pub fn panel(&mut self, ui: &mut egui::Ui, extras: &mut LayoutExtras<u32>) {
        ui.separator();
        ui.label(format!(
            "{} clusters; ctrl-click picks nodes ({} picked)",
            extras.clusters.len(),
            self.0.len()
        ));
        ui.horizontal(|ui| {
            let group = egui::Button::new("group picked");
            if ui.add_enabled(!self.0.is_empty(), group).clicked() {
                let members = std::mem::take(&mut self.0).into_iter().collect();
                extras.clusters.push(Cluster::new(members));
            }
            let ungroup = egui::Button::new("ungroup all");
            if ui
                .add_enabled(!extras.clusters.is_empty(), ungroup)
                .clicked()
            {
                extras.clusters.clear();
            }
        });
    }

    /// Drops node `id` (removed from the scene) from the picks and the clusters.
    pub fn forget(&mut self, id: u32, extras: &mut LayoutExtras<u32>) {
        self.0.remove(&id);
        for c in &mut extras.clusters {
            if c.members().contains(&id) {
                let rest = c.members().iter().copied().filter(|&m| m != id).collect();
                *c = Cluster::new(rest).with_padding(c.padding());
            }
        }
    }
}

/// Draws each cluster's box (`bounds`), `to_screen` placing world points.
pub fn draw(
    painter: &egui::Painter,
    bounds: &[Box2D<f32>],
    to_screen: impl Fn(Point2D<f32>) -> egui::Pos2,
) {
    let stroke = egui::Stroke::new(1.5, egui::Color32::from_rgb(148, 103, 189));
    for b in bounds.iter().filter(|b| b.area() > 0.0) {
        let r = egui::Rect::from_min_max(to_screen(b.min), to_screen(b.max));
        painter.rect_stroke(r, 4.0, stroke, egui::StrokeKind::Outside);
    }
}

#[cfg(test)]
mod tests {
    use super::Picked;
    use graph_canvas_layout::scene::Cluster;
    use graph_canvas_layout::LayoutExtras;

    #[test]
    fn a_removed_node_leaves_the_picks_and_its_cluster() {
        let mut picked = Picked::default();
        let mut extras = LayoutExtras::<u32>::default();
        extras
            .clusters
            .push(Cluster::new(vec![1, 2, 3]).with_padding(4.0));
        picked.toggle(2);
        picked.toggle(5);
        picked.forget(2, &mut extras);
        assert_eq!(picked.0.iter().copied().collect::<Vec<_>>(), [5]);
        assert_eq!(extras.clusters[0].members(), [1, 3]);
        assert_eq!(extras.clusters[0].padding(), 4.0, "the padding is kept");
    }
}
