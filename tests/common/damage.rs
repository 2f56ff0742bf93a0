//! Damaged snapshots, shared by `tests/snapshot_damage.rs` and the `restore` fuzz target:
//! a real snapshot taken mid-drag, every way of damaging one of its values or arrays,
//! and what a host meets when it restores one and carries on.
#![allow(dead_code)]

use std::panic::{catch_unwind, AssertUnwindSafe};

use graph_canvas_layout::euclid::default::Vector2D;
use graph_canvas_layout::{LayoutSnapshot, RapierLayout, RapierLayoutConfig};
use serde_json::Value;

use super::{edge, node, Host, FRAME};

/// A host mid-session on a 30-node graph under `config`: laid out for 40 frames, node 3
/// dragged for the last 8 of them (still held), node 17 thrown and in flight, node 0
/// pinned. The session a damaged snapshot continues is [`carry_on`].
pub fn host_mid_drag(config: RapierLayoutConfig) -> Host<u32> {
    let nodes = (0..30)
        .map(|i| node(i, (i % 6) as f32 * 40.0, (i / 6) as f32 * 40.0))
        .collect();
    // A ring with chords: cycles and a few hubs, one component.
    let mut edges: Vec<_> = (0..30).map(|i| edge(i, (i + 1) % 30)).collect();
    edges.extend((0..30).step_by(5).map(|i| edge(i, (i + 12) % 30)));
    edges.push(edge(4, 22));
    let mut host = Host::new(
        graph_canvas_layout::CanvasSceneInput::new(nodes, edges),
        config,
    );
    host.extras.pinned.insert(0);
    for frame in 0..40 {
        match frame {
            20 => {
                host.extras.dragging.insert(17);
            }
            21..=23 => {
                let p = host.pos(&17);
                host.set_pos(&17, p + Vector2D::new(25.0, -10.0));
            }
            24 => {
                host.extras.dragging.remove(&17);
            }
            32 => {
                host.extras.dragging.insert(3);
            }
            33.. => {
                let p = host.pos(&3);
                host.set_pos(&3, p + Vector2D::new(-4.0, 3.0));
            }
            _ => {}
        }
        host.frame(FRAME);
    }
    host
}

/// What restoring a damaged snapshot came to.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// The damaged text did not read back as a snapshot.
    Unread,
    /// `restore` refused it.
    Refused,
    /// Restored, and the session carried on with finite positions.
    Ran,
    /// Restored, then a call panicked: the message.
    Panicked(String),
    /// Restored, then a position or delta went non-finite: which.
    NonFinite(String),
}

/// Restores `value` into a new layout and carries the host's session on from it
/// ([`carry_on`]); every call is caught, so a panic is an outcome, not a test failure.
pub fn restore_and_run(value: Value, host: &Host<u32>) -> Outcome {
    let Ok(snapshot) = serde_json::from_value::<LayoutSnapshot<u32>>(value) else {
        return Outcome::Unread;
    };
    let mut layout = RapierLayout::default();
    let restored = catch_unwind(AssertUnwindSafe(|| layout.restore(snapshot)));
    match restored {
        Err(panic) => return Outcome::Panicked(format!("in restore: {}", message(&panic))),
        Ok(Err(_)) => return Outcome::Refused,
        Ok(Ok(())) => {}
    }
    let mut host = Host {
        scene: host.scene.clone(),
        layout,
        state: host.state.clone(),
        extras: host.extras.clone(),
    };
    match catch_unwind(AssertUnwindSafe(|| carry_on(&mut host))) {
        Err(panic) => Outcome::Panicked(message(&panic)),
        Ok(Err(what)) => Outcome::NonFinite(what),
        Ok(Ok(())) => Outcome::Ran,
    }
}

/// The rest of the session after a restore: the drag goes on and ends in a throw, a pin
/// is let go, a node and an edge are added and one removed, then frames of every kind of
/// frame time (none, long, tiny). `Err` names the first non-finite delta or position.
pub fn carry_on(host: &mut Host<u32>) -> Result<(), String> {
    let finite = |host: &Host<u32>, when: &str| -> Result<(), String> {
        for n in &host.scene.nodes {
            if !(n.position.x.is_finite() && n.position.y.is_finite()) {
                return Err(format!("node {} at {:?} {when}", n.id, n.position));
            }
        }
        Ok(())
    };
    for frame in 0..36 {
        match frame {
            0..=5 => {
                let p = host.pos(&3);
                host.set_pos(&3, p + Vector2D::new(-9.0, 6.0));
            }
            6 => {
                host.extras.dragging.remove(&3);
            }
            10 => {
                host.extras.pinned.remove(&0);
            }
            14 => {
                host.scene.nodes.push(node(30, 10.0, 10.0));
                host.scene.edges.push(edge(30, 5));
            }
            18 => {
                host.scene.nodes.retain(|n| n.id != 11);
                host.scene
                    .edges
                    .retain(|e| e.source != 11 && e.target != 11);
            }
            22 => {
                host.extras.dragging.insert(8);
            }
            23..=26 => {
                let p = host.pos(&8);
                host.set_pos(&8, p + Vector2D::new(30.0, 30.0));
            }
            27 => {
                host.extras.dragging.remove(&8);
            }
            _ => {}
        }
        let dt = match frame {
            28 => 0.0,
            29 => 5.0,
            30 => 1e-6,
            _ => FRAME,
        };
        let deltas = host.frame(dt);
        if let Some((id, d)) = deltas
            .iter()
            .find(|(_, d)| !(d.x.is_finite() && d.y.is_finite()))
        {
            return Err(format!("delta {d:?} of node {id} at call {frame}"));
        }
        finite(host, &format!("after call {frame}"))?;
    }
    Ok(())
}

fn message(panic: &Box<dyn std::any::Any + Send>) -> String {
    panic
        .downcast_ref::<String>()
        .cloned()
        .or_else(|| panic.downcast_ref::<&str>().map(|s| (*s).to_owned()))
        .unwrap_or_else(|| "a panic without a message".to_owned())
}

/// One damage: where in the snapshot's JSON, and what was done there.
#[derive(Clone, Debug)]
pub struct Damage {
    /// The value's path, `/`-separated (a JSON pointer).
    pub path: String,
    /// What was done to it.
    pub what: String,
    edit: Edit,
}

#[derive(Clone, Debug)]
enum Edit {
    Set(Value),
    Remove(usize),
    Repeat(usize),
    Empty,
    Reverse,
    SwapFirstTwo,
}

impl Damage {
    /// Sets the value at `path` to `value`.
    pub fn set(path: &str, value: Value) -> Self {
        Self {
            path: path.to_owned(),
            what: format!("set to {value}"),
            edit: Edit::Set(value),
        }
    }

    /// The `kind`-th array edit (mod 6) of the array at `path`, at item `at` (mod its
    /// length): removed, repeated, the array emptied, reversed, its first two swapped, or
    /// left as it is when it has no such item.
    pub fn array(path: &str, kind: u8, at: usize, len: usize) -> Self {
        let i = at % len.max(1);
        let (what, edit) = match (kind % 6, len) {
            (_, 0) => ("left empty".to_owned(), Edit::Empty),
            (0, _) => (format!("item {i} removed"), Edit::Remove(i)),
            (1, _) => (format!("item {i} repeated"), Edit::Repeat(i)),
            (2, _) => ("emptied".to_owned(), Edit::Empty),
            (3, _) => ("reversed".to_owned(), Edit::Reverse),
            (_, 1) => ("left as it is".to_owned(), Edit::Reverse),
            _ => ("first two swapped".to_owned(), Edit::SwapFirstTwo),
        };
        Self {
            path: path.to_owned(),
            what,
            edit,
        }
    }

    /// `root` with this damage done.
    pub fn apply(&self, root: &Value) -> Value {
        let mut copy = root.clone();
        self.apply_in(&mut copy);
        copy
    }

    /// Does this damage in `root` (nothing where `root` has no such path any more, or
    /// an array edit finds no array).
    pub fn apply_in(&self, root: &mut Value) {
        let Some(target) = root.pointer_mut(&self.path) else {
            return;
        };
        match (&self.edit, target) {
            (Edit::Set(v), target) => *target = v.clone(),
            (Edit::Remove(i), Value::Array(items)) if *i < items.len() => _ = items.remove(*i),
            (Edit::Repeat(i), Value::Array(items)) if *i < items.len() => {
                let item = items[*i].clone();
                items.insert(*i, item);
            }
            (Edit::Empty, Value::Array(items)) => items.clear(),
            (Edit::Reverse, Value::Array(items)) => items.reverse(),
            (Edit::SwapFirstTwo, Value::Array(items)) if items.len() > 1 => items.swap(0, 1),
            _ => {}
        }
    }
}

/// Every single-value damage of `root` (each number set to each of a list of values
/// that break assumptions: 0, ±1, off by one, negated, doubled, the largest integers,
/// huge and tiny floats; each bool flipped; each string emptied; each null given a
/// number) and every array damage (each of an array's first three and last elements
/// removed or repeated, the array emptied, reversed, its first two swapped).
pub fn damages(root: &Value) -> Vec<Damage> {
    let mut out = Vec::new();
    let mut paths = Vec::new();
    collect(root, String::new(), &mut paths);
    for path in paths {
        let target = root.pointer(&path).expect("a collected path");
        for (what, replacement) in replacements(target) {
            out.push(Damage {
                path: path.clone(),
                what,
                edit: Edit::Set(replacement),
            });
        }
        if let Value::Array(items) = target {
            for (what, edit) in array_edits(items.len()) {
                out.push(Damage {
                    path: path.clone(),
                    what,
                    edit,
                });
            }
        }
    }
    out
}

/// Every value's and every array's path in `root`, in document order.
pub fn paths(root: &Value) -> Vec<String> {
    let mut out = Vec::new();
    collect(root, String::new(), &mut out);
    out
}

fn collect(value: &Value, path: String, out: &mut Vec<String>) {
    match value {
        Value::Array(items) => {
            out.push(path.clone());
            for (i, item) in items.iter().enumerate() {
                collect(item, format!("{path}/{i}"), out);
            }
        }
        Value::Object(fields) => {
            for (key, item) in fields {
                let key = key.replace('~', "~0").replace('/', "~1");
                collect(item, format!("{path}/{key}"), out);
            }
        }
        _ => out.push(path),
    }
}

fn replacements(value: &Value) -> Vec<(String, Value)> {
    let num = |x: f64| serde_json::Number::from_f64(x).map(Value::Number);
    match value {
        Value::Bool(b) => vec![("flipped".into(), Value::Bool(!b))],
        Value::String(_) => vec![("emptied".into(), Value::String(String::new()))],
        Value::Null => vec![("given 1".into(), Value::from(1))],
        Value::Number(n) => {
            let mut out: Vec<(String, Value)> = vec![
                ("0".into(), Value::from(0)),
                ("1".into(), Value::from(1)),
                ("-1".into(), Value::from(-1)),
                ("u32::MAX".into(), Value::from(u32::MAX)),
                ("u64::MAX".into(), Value::from(u64::MAX)),
                ("1e30".into(), num(1e30).unwrap()),
                ("-1e30".into(), num(-1e30).unwrap()),
                ("1e-30".into(), num(1e-30).unwrap()),
            ];
            if let Some(u) = n.as_u64() {
                out.push(("+1".into(), Value::from(u.wrapping_add(1))));
                if u > 0 {
                    out.push(("-1 from it".into(), Value::from(u - 1)));
                }
                out.push(("doubled".into(), Value::from(u.wrapping_mul(2))));
            } else if let Some(x) = n.as_f64() {
                out.extend(num(-x).map(|v| ("negated".into(), v)));
                out.extend(num(x * 2.0 + 1.0).map(|v| ("doubled + 1".into(), v)));
            }
            out.retain(|(_, v)| v != value);
            out
        }
        Value::Array(_) | Value::Object(_) => Vec::new(),
    }
}

fn array_edits(len: usize) -> Vec<(String, Edit)> {
    let mut out = Vec::new();
    if len == 0 {
        return out;
    }
    let mut picks: Vec<usize> = (0..len.min(3)).collect();
    if len > 3 {
        picks.push(len - 1);
    }
    for i in picks {
        out.push((format!("item {i} removed"), Edit::Remove(i)));
        out.push((format!("item {i} repeated"), Edit::Repeat(i)));
    }
    out.push(("emptied".into(), Edit::Empty));
    if len > 1 {
        out.push(("reversed".into(), Edit::Reverse));
        out.push(("first two swapped".into(), Edit::SwapFirstTwo));
    }
    out
}
