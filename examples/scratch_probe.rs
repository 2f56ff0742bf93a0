use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::*;
fn main() {
    let mut scene =
        CanvasSceneInput::new(vec![CanvasNode::new(6u32, Point2D::new(0.0, 0.0))], vec![]);
    let mut layout = RapierLayout::default();
    let mut st = RapierLayoutState::default();
    let ex = LayoutExtras::default();
    let show = |l: &RapierLayout<u32>, tag: &str| {
        println!(
            "{tag}: bodies {:?} ids {:?}",
            l.world().map(|w| w.body_count()),
            l.world().map(|w| w.node_ids().cloned().collect::<Vec<_>>())
        )
    };
    layout.step(&scene, &mut st, 1.0 / 60.0, &Default::default(), &ex);
    show(&layout, "1");
    scene.nodes[0].position.x = f32::NAN;
    scene.nodes.push(CanvasNode::new(0, Point2D::new(0.0, 0.0)));
    layout.step(&scene, &mut st, 1.0 / 60.0, &Default::default(), &ex);
    show(&layout, "2");
    layout.step(&scene, &mut st, 1.0 / 60.0, &Default::default(), &ex);
    show(&layout, "3");
    scene.nodes[0].position = Point2D::new(60.0, 0.0);
    layout.step(&scene, &mut st, 1.0 / 60.0, &Default::default(), &ex);
    show(&layout, "4");
}
