//! What hosts need of the public types beyond the calls: a layout and its world move to
//! another thread and are shared by reference (Bevy keeps them in resources, egui apps
//! on worker threads), so they are `Send + Sync`.

mod common;

use common::*;
use graph_canvas_layout::{
    CanvasSceneInput, LayoutExtras, RapierLayout, RapierLayoutConfig, RapierLayoutState,
    RapierSceneWorld,
};

fn send_and_sync<T: Send + Sync>() {}

#[test]
fn layouts_and_worlds_are_send_and_sync() {
    send_and_sync::<RapierLayout<u32>>();
    send_and_sync::<RapierLayout<String>>();
    send_and_sync::<RapierSceneWorld<u64>>();
    send_and_sync::<CanvasSceneInput<u32>>();
    send_and_sync::<LayoutExtras<u32>>();
    send_and_sync::<RapierLayoutState>();
}

#[test]
fn a_layout_steps_on_another_thread() {
    let mut host = Host::new(load_scene("karate"), RapierLayoutConfig::force_directed());
    host.frames(5);
    let before = positions(&host.scene);
    let host = std::thread::spawn(move || {
        host.frames(30);
        host
    })
    .join()
    .expect("the worker thread");
    let moved = farthest_moved(&host.scene, &before);
    assert!(
        moved > 1.0,
        "the layout moved on the worker thread: {moved}"
    );
}
