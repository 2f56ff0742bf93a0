//! A node's outline, read from how egui_graphs draws it: its display's boundary probed
//! along the axes gives the width and height, and along the diagonal tells a disk (the
//! diagonal as far as the sides) from a box (further). Sizes are rounded to a sixteenth
//! of a unit, so the coordinates' rounding as a node moves does not read as a resize.

use egui::Vec2;
use egui_graphs::DisplayNode;
use graph_canvas_layout::CanvasNode;
use petgraph::stable_graph::IndexType;
use petgraph::EdgeType;

/// Sizes are rounded to this many steps a unit: the probes are points on the canvas, so
/// a size is a difference of coordinates that carries their rounding, which changes as
/// the node moves, and the layout takes any change of size as an edit that wakes it.
const STEPS: f32 = 16.0;

/// How far apart two lengths may be, as a share of the larger, and still count as equal:
/// a circle's boundary point is worked out with a square root, a box's with divisions.
const SAME: f32 = 0.01;

/// `node` shaped as `display` draws it: a disk of its radius, a box of its width and
/// height, or, where the display gives no usable extent, the layout's default disk.
///
/// A disk is given as a box rounded into that disk (the same outline to the contacts):
/// the layout weighs a box as a node of its default radius, whatever its size, while a
/// disk's mass follows its area, and egui_graphs' default disks (radius 5) would weigh
/// a tenth of that, springing back from a throw three times as fast.
pub(crate) fn shaped<N, E, Ty, Ix, D>(node: CanvasNode<usize>, display: &D) -> CanvasNode<usize>
where
    N: Clone,
    E: Clone,
    Ty: EdgeType,
    Ix: IndexType,
    D: DisplayNode<N, E, Ty, Ix>,
{
    let probe = |x: f32, y: f32| display.closest_boundary_point(Vec2::new(x, y));
    let (right, left, down, up) = (
        probe(1.0, 0.0),
        probe(-1.0, 0.0),
        probe(0.0, 1.0),
        probe(0.0, -1.0),
    );
    let round = |v: f32| (v * STEPS).round() / STEPS;
    let (width, height) = (round(right.x - left.x), round(down.y - up.y));
    let centre = egui::pos2(0.5 * (right.x + left.x), 0.5 * (down.y + up.y));
    let diagonal = (probe(1.0, 1.0) - centre).length();
    if !(width.is_finite() && height.is_finite() && diagonal.is_finite())
        || width <= 0.0
        || height <= 0.0
    {
        return node;
    }
    let same = |a: f32, b: f32| (a - b).abs() <= SAME * a.max(b);
    if same(width, height) && same(diagonal, 0.5 * width) {
        let radius = 0.5 * width;
        node.with_rounded_rect(width, width, radius)
    } else {
        node.with_rect(width, height)
    }
}
