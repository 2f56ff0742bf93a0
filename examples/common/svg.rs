//! SVG pictures of a scene for the examples: edges, disks and label boxes coloured by
//! the caller, an
//! optional trail (a thrown node's path, dotted every 10 frames) and guides (the rings
//! and lines the per-node forces aim at).

use std::fmt::Write as _;

use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasSceneInput, NodeShape};

/// A shape drawn under the graph, in world units.
#[derive(Clone, Copy, Debug)]
pub enum Guide {
    Circle(Point2D<f32>, f32),
    VerticalLine(f32),
    HorizontalLine(f32),
    /// A box (a cluster's), from its min to its max corner.
    Box(Point2D<f32>, Point2D<f32>),
}

/// The default disk colour.
pub const BLUE: &str = "#1f77b4";

/// Colours for groups, by `key % PALETTE.len()`.
pub const PALETTE: [&str; 6] = [
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b",
];

/// The scene as an SVG document titled `title`; `colour` picks each node's fill.
pub fn svg(
    scene: &CanvasSceneInput<u32>,
    title: &str,
    trail: &[Point2D<f32>],
    guides: &[Guide],
    colour: impl Fn(u32) -> &'static str,
) -> String {
    let frame = 1.0 / 60.0;
    let mut pts: Vec<Point2D<f32>> = scene.nodes.iter().map(|n| n.position).collect();
    pts.extend(trail.iter().copied());
    for guide in guides {
        match *guide {
            Guide::Circle(c, r) => {
                pts.push(Point2D::new(c.x - r, c.y - r));
                pts.push(Point2D::new(c.x + r, c.y + r));
            }
            Guide::Box(lo, hi) => pts.extend([lo, hi]),
            _ => {}
        }
    }
    let (mut lo, mut hi) = (
        Point2D::new(f32::MAX, f32::MAX),
        Point2D::new(f32::MIN, f32::MIN),
    );
    for p in pts {
        lo = lo.min(p);
        hi = hi.max(p);
    }
    let pad = 40.0;
    // Lines and text keep their size on the page however large the layout is.
    let unit = ((hi.x - lo.x).max(hi.y - lo.y) / 1_000.0).max(1.0);
    // A band above the drawing holds the title.
    let top = pad + 32.0 * unit;
    let (w, h) = (hi.x - lo.x + 2.0 * pad, hi.y - lo.y + pad + top);
    let at = |p: Point2D<f32>| (p.x - lo.x + pad, p.y - lo.y + top);
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.0} {h:.0}" font-family="sans-serif">"#
    );
    let _ = writeln!(
        out,
        r#"<rect width="100%" height="100%" fill="white"/><text x="{:.0}" y="{:.0}" font-size="{:.0}">{title}</text>"#,
        12.0 * unit,
        24.0 * unit,
        16.0 * unit
    );
    for guide in guides {
        let style = r##"fill="none" stroke="#bbb" stroke-width="1.5" stroke-dasharray="6 4""##;
        let _ = match *guide {
            Guide::Circle(c, r) => {
                let (x, y) = at(c);
                writeln!(
                    out,
                    r#"<circle cx="{x:.1}" cy="{y:.1}" r="{r:.1}" {style}/>"#
                )
            }
            Guide::VerticalLine(gx) => {
                let (x, _) = at(Point2D::new(gx, 0.0));
                writeln!(
                    out,
                    r#"<line x1="{x:.1}" y1="0" x2="{x:.1}" y2="{h:.0}" {style}/>"#
                )
            }
            Guide::Box(a, b) => {
                let ((x1, y1), (x2, y2)) = (at(a), at(b));
                let (w, h) = (x2 - x1, y2 - y1);
                writeln!(
                    out,
                    r#"<rect x="{x1:.1}" y="{y1:.1}" width="{w:.1}" height="{h:.1}" {style}/>"#
                )
            }
            Guide::HorizontalLine(gy) => {
                let (_, y) = at(Point2D::new(0.0, gy));
                writeln!(
                    out,
                    r#"<line x1="0" y1="{y:.1}" x2="{w:.0}" y2="{y:.1}" {style}/>"#
                )
            }
        };
    }
    let position: std::collections::HashMap<u32, Point2D<f32>> =
        scene.nodes.iter().map(|n| (n.id, n.position)).collect();
    for e in &scene.edges {
        let ((x1, y1), (x2, y2)) = (at(position[&e.source]), at(position[&e.target]));
        let _ = writeln!(
            out,
            r##"<line x1="{x1:.1}" y1="{y1:.1}" x2="{x2:.1}" y2="{y2:.1}" stroke="#999" stroke-width="{unit:.1}"/>"##
        );
    }
    if trail.len() > 1 {
        let path: Vec<String> = trail
            .iter()
            .map(|p| {
                let (x, y) = at(*p);
                format!("{x:.1},{y:.1}")
            })
            .collect();
        let _ = writeln!(
            out,
            r##"<polyline points="{}" fill="none" stroke="#d62728" stroke-width="{:.1}"/>"##,
            path.join(" "),
            2.0 * unit
        );
        // A marker every 10 frames where the trail has moved on from the last one (a
        // node resting or turning back does not pile labels on one spot).
        let mut last: Option<(f32, f32)> = None;
        for (i, p) in trail.iter().enumerate().step_by(10) {
            let (x, y) = at(*p);
            if last.is_some_and(|(lx, ly)| (x - lx).hypot(y - ly) < 40.0 * unit) {
                continue;
            }
            last = Some((x, y));
            let _ = writeln!(
                out,
                r##"<circle cx="{x:.1}" cy="{y:.1}" r="{:.1}" fill="#d62728"/><text x="{:.1}" y="{:.1}" font-size="{:.0}" fill="#d62728">{:.2}s</text>"##,
                3.0 * unit,
                x + 4.0 * unit,
                y - 4.0 * unit,
                10.0 * unit,
                i as f32 * frame
            );
        }
    }
    for n in &scene.nodes {
        let (x, y) = at(n.position);
        let fill = colour(n.id);
        let _ = match n.shape {
            NodeShape::Rect {
                width,
                height,
                corner_radius,
            } => {
                // A label box, its label inside.
                let (left, top) = (x - 0.5 * width, y - 0.5 * height);
                let label = n.label.as_deref().unwrap_or("");
                writeln!(
                    out,
                    r##"<rect x="{left:.1}" y="{top:.1}" width="{width:.1}" height="{height:.1}" rx="{corner_radius:.1}" fill="{fill}" fill-opacity="0.85" stroke="white"/><text x="{x:.1}" y="{:.1}" font-size="{:.1}" text-anchor="middle" fill="white">{label}</text>"##,
                    y + 0.3 * height,
                    0.6 * height
                )
            }
            NodeShape::Disk => {
                let r = if n.radius > 0.0 { n.radius } else { 16.0 };
                writeln!(
                    out,
                    r##"<circle cx="{x:.1}" cy="{y:.1}" r="{r}" fill="{fill}" fill-opacity="0.8" stroke="white"/>"##
                )
            }
        };
    }
    out.push_str("</svg>\n");
    out
}
