use graph_canvas_layout::*;
fn main() {
    let text = std::fs::read_to_string("scenes/n200_e500.json").unwrap();
    let f: SceneFile = serde_json::from_str(&text).unwrap();
    let mut scene = f.into_scene();
    let mut layout = RapierLayout::default();
    let mut st = RapierLayoutState::default();
    let ex = LayoutExtras::default();
    let mode = std::env::args().nth(1).unwrap_or_default();
    if mode == "asleep" {
        while !layout.is_converged(&st) {
            let d = layout.step(&scene, &mut st, 1.0/60.0, &Default::default(), &ex);
            for n in &mut scene.nodes { if let Some(x) = d.get(&n.id) { n.position += *x; } }
        }
        eprintln!("converged after {}", st.step_count);
        for _ in 0..200000 {
            let d = layout.step(&scene, &mut st, 1.0/60.0, &Default::default(), &ex);
            for n in &mut scene.nodes { if let Some(x) = d.get(&n.id) { n.position += *x; } }
        }
    } else {
        for _ in 0..3000 {
            let d = layout.step(&scene, &mut st, 1.0/60.0, &Default::default(), &ex);
            for n in &mut scene.nodes { if let Some(x) = d.get(&n.id) { n.position += *x; } }
        }
    }
}
