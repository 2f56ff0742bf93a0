//! [`LabelBox`]: a node drawn as a box with its label inside, the shape label-heavy
//! canvases (knowledge maps, dependency graphs) draw. egui_graphs' default node is a
//! small disk with its label outside it, which a layout cannot keep clear.

use egui::epaint::{RectShape, TextShape};
use egui::{
    Color32, CornerRadius, FontFamily, FontId, Pos2, Rect, Shape, Stroke, StrokeKind, Vec2,
};
use egui_graphs::{DisplayNode, DrawContext, NodeProps};
use petgraph::stable_graph::IndexType;
use petgraph::EdgeType;

/// The box's width per character of its label, in canvas units.
pub const CHAR_WIDTH: f32 = 7.0;
/// The box's height, in canvas units.
pub const BOX_HEIGHT: f32 = 20.0;
/// Room beside the label, left and right together, in canvas units.
const PADDING: f32 = 8.0;
/// The label's monospace font size, in canvas units: its characters are about 0.6 of it
/// wide, so they fit [`CHAR_WIDTH`].
const FONT_SIZE: f32 = 11.0;

/// A node drawn as a level box of [`CHAR_WIDTH`] a character of its label (plus a
/// little room) by [`BOX_HEIGHT`], the label inside. With
/// [`RapierGraphLayout`](crate::RapierGraphLayout), the layout reads the box's size from
/// it and keeps the boxes from overlapping.
///
/// # Example
/// ```
/// use egui_graphs::Graph;
/// use graph_canvas_layout_egui_graphs::LabelBox;
/// use petgraph::stable_graph::StableGraph;
/// use petgraph::Undirected;
///
/// let mut g = StableGraph::<(), (), Undirected>::default();
/// let a = g.add_node(());
/// let b = g.add_node(());
/// g.add_edge(a, b, ());
/// let mut graph: Graph<(), (), Undirected, u32, LabelBox> = Graph::from(&g);
/// graph.g_mut().node_weight_mut(a).unwrap().set_label("Valjean".to_string());
/// ```
#[derive(Clone, Debug)]
pub struct LabelBox {
    /// The box's centre in canvas units.
    pub pos: Pos2,
    /// The text inside.
    pub label: String,
    /// The box's width and height in canvas units.
    pub size: Vec2,
    /// Whether the node is selected, dragged or hovered (drawn brighter).
    pub selected: bool,
    /// See [`selected`](Self::selected).
    pub dragged: bool,
    /// See [`selected`](Self::selected).
    pub hovered: bool,
    /// The node's own colour, if it has one.
    pub color: Option<Color32>,
}

/// The size of the box of `label`.
pub fn label_size(label: &str) -> Vec2 {
    Vec2::new(
        CHAR_WIDTH * label.chars().count() as f32 + PADDING,
        BOX_HEIGHT,
    )
}

impl<N: Clone> From<NodeProps<N>> for LabelBox {
    fn from(props: NodeProps<N>) -> Self {
        Self {
            pos: props.location(),
            size: label_size(&props.label),
            label: props.label.clone(),
            selected: props.selected,
            dragged: props.dragged,
            hovered: props.hovered,
            color: props.color(),
        }
    }
}

impl<N: Clone, E: Clone, Ty: EdgeType, Ix: IndexType> DisplayNode<N, E, Ty, Ix> for LabelBox {
    fn is_inside(&self, pos: Pos2) -> bool {
        Rect::from_center_size(self.pos, self.size).contains(pos)
    }

    fn closest_boundary_point(&self, dir: Vec2) -> Pos2 {
        boundary_point(self.pos, self.size * 0.5, dir)
    }

    fn shapes(&mut self, ctx: &DrawContext) -> Vec<Shape> {
        let interacted = self.selected || self.dragged || self.hovered;
        let visuals = &ctx.ctx.global_style().visuals;
        let fill = self.color.unwrap_or(if interacted {
            visuals.selection.bg_fill
        } else {
            visuals.widgets.inactive.bg_fill
        });
        let text = visuals.strong_text_color();
        let centre = ctx.meta.canvas_to_screen_pos(self.pos);
        let size = self.size * ctx.meta.zoom;
        let rect = Rect::from_center_size(centre, size);
        let stroke = Stroke::new(1.0, visuals.widgets.inactive.fg_stroke.color);
        let galley = ctx.ctx.fonts_mut(|f| {
            f.layout_no_wrap(
                self.label.clone(),
                FontId::new(
                    ctx.meta.canvas_to_screen_size(FONT_SIZE),
                    FontFamily::Monospace,
                ),
                text,
            )
        });
        let at = centre - galley.size() * 0.5;
        vec![
            RectShape::new(
                rect,
                CornerRadius::same(3),
                fill,
                stroke,
                StrokeKind::Inside,
            )
            .into(),
            TextShape::new(at, galley, text).into(),
        ]
    }

    fn update(&mut self, props: &NodeProps<N>) {
        self.pos = props.location();
        if props.label != self.label {
            self.label = props.label.clone();
            self.size = label_size(&self.label);
        }
        self.selected = props.selected;
        self.dragged = props.dragged;
        self.hovered = props.hovered;
        self.color = props.color();
    }
}

/// Where the ray from `centre` along `dir` leaves the box of `half` extents.
fn boundary_point(centre: Pos2, half: Vec2, dir: Vec2) -> Pos2 {
    let dir = dir.normalized();
    let t = |d: f32, h: f32| if d == 0.0 { f32::INFINITY } else { h / d.abs() };
    let reach = t(dir.x, half.x).min(t(dir.y, half.y));
    if reach.is_finite() {
        centre + dir * reach
    } else {
        centre
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A box of 60 × 20: along the axes, its sides; along the diagonal, its corner.
    #[test]
    fn the_boundary_is_the_boxs_outline() {
        let centre = Pos2::new(10.0, 10.0);
        let half = Vec2::new(30.0, 10.0);
        for (dir, expected) in [
            (Vec2::new(1.0, 0.0), Pos2::new(40.0, 10.0)),
            (Vec2::new(0.0, -2.0), Pos2::new(10.0, 0.0)),
            (Vec2::new(3.0, 1.0), Pos2::new(40.0, 20.0)),
        ] {
            let got = boundary_point(centre, half, dir);
            assert!(
                (got - expected).length() < 1e-4,
                "along {dir:?}: {got:?}, expected {expected:?}"
            );
        }
    }
}
