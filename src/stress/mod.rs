//! The stress model's graph work, apart from the physics: hop distances
//! (`graph.rs`), the sparse model's terms and weights (`model.rs`), and a global start
//! layout from them (`start.rs`: pivot MDS in `mds.rs`, stress SGD in `sgd.rs`,
//! components packed in `pack.rs`). The force that keeps the terms in the physics is
//! `forces/stress.rs`.

pub(crate) mod graph;
mod mds;
pub(crate) mod model;
mod pack;
pub(crate) mod sgd;
pub(crate) mod start;

#[cfg(test)]
mod experiment {
    use super::graph::Graph;
    use super::model::SparseStress;
    use super::start::{global_start, StartPlan};
    use euclid::default::Point2D;

    #[test]
    #[ignore]
    fn write_starts() {
        let pivots: usize = std::env::var("PIVOTS")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(200);
        let passes: usize = std::env::var("PASSES")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(30);
        let hops: u16 = std::env::var("HOPS")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(2);
        for name in std::env::var("SCENES").unwrap().split(',') {
            let path = if name.starts_with('/') {
                name.to_string()
            } else {
                format!("{}/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"))
            };
            let text = std::fs::read_to_string(&path).unwrap();
            let file: crate::SceneFile = serde_json::from_str(&text).unwrap();
            let scene = file.into_scene();
            let index: std::collections::HashMap<u32, usize> = scene
                .nodes
                .iter()
                .enumerate()
                .map(|(i, n)| (n.id, i))
                .collect();
            let edges: Vec<(usize, usize)> = scene
                .edges
                .iter()
                .map(|e| (index[&e.source], index[&e.target]))
                .collect();
            let t = std::time::Instant::now();
            let graph = Graph::new(scene.nodes.len(), edges.iter().copied());
            let model = SparseStress::new(&graph, pivots, hops);
            let t_model = t.elapsed().as_secs_f64();
            let radii = vec![16.0; scene.nodes.len()];
            let t2 = std::time::Instant::now();
            let start = global_start(
                &graph,
                &model,
                &radii,
                StartPlan {
                    min_length: 100.0,
                    fit: true,
                    gap: 2.0,
                    passes,
                    centre: Point2D::origin(),
                },
            );
            let t_all = t.elapsed().as_secs_f64();
            let pos: Vec<[f32; 2]> = start.positions.iter().map(|p| [p.x, p.y]).collect();
            let name = name.rsplit('/').next().unwrap();
            std::fs::write(
                format!("/tmp/start_{name}.json"),
                serde_json::json!({"positions": pos}).to_string(),
            )
            .unwrap();
            eprintln!(
                "{name}: model {t_model:.3}s start {:.3}s total {t_all:.3}s L {}",
                t2.elapsed().as_secs_f64(),
                start.hop_length
            );
        }
    }
}
