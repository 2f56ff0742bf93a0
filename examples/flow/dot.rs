//! Graphviz `dot` on the same graph: its layered layout, read back as scene positions
//! (`-Tplain`: inches, y up; turned into canvas units, y down), and its wall time.

use std::io::Write;
use std::process::{Command, Stdio};
use std::time::Instant;

use graph_canvas_layout::CanvasSceneInput;

/// The scene at `dot`'s positions and the seconds `dot` took, or why not.
pub fn layout(scene: &CanvasSceneInput<u32>) -> Result<(CanvasSceneInput<u32>, f64), String> {
    let mut text =
        String::from("digraph G {\nnode [shape=circle, width=0.44, fixedsize=true, label=\"\"];\n");
    for n in &scene.nodes {
        text.push_str(&format!("n{};\n", n.id));
    }
    for e in &scene.edges {
        text.push_str(&format!("n{} -> n{};\n", e.source, e.target));
    }
    text.push_str("}\n");
    let started = Instant::now();
    let mut child = Command::new("dot")
        .arg("-Tplain")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("dot: {e} (apt-get install graphviz)"))?;
    child
        .stdin
        .take()
        .expect("piped")
        .write_all(text.as_bytes())
        .map_err(|e| format!("dot: {e}"))?;
    let out = child.wait_with_output().map_err(|e| format!("dot: {e}"))?;
    let seconds = started.elapsed().as_secs_f64();
    if !out.status.success() {
        return Err(format!("dot: {}", String::from_utf8_lossy(&out.stderr)));
    }
    let mut laid = scene.clone();
    let mut placed = 0;
    for line in String::from_utf8_lossy(&out.stdout).lines() {
        let f: Vec<&str> = line.split_whitespace().collect();
        if f.first() != Some(&"node") || f.len() < 4 {
            continue;
        }
        let (Some(id), Ok(x), Ok(y)) = (
            f[1].strip_prefix('n').and_then(|s| s.parse::<usize>().ok()),
            f[2].parse::<f32>(),
            f[3].parse::<f32>(),
        ) else {
            continue;
        };
        if let Some(n) = laid.nodes.get_mut(id) {
            n.position.x = x * 72.0;
            n.position.y = -y * 72.0;
            placed += 1;
        }
    }
    if placed != scene.nodes.len() {
        return Err(format!(
            "dot placed {placed} of {} nodes",
            scene.nodes.len()
        ));
    }
    Ok((laid, seconds))
}
