//! The host's input: the `Layout` trait and its maps (`layout.rs`), the scene it hands over every frame, per-node forces, the scene file format, what
//! counts as bad input (in a scene, and in a snapshot handed back), and the topology
//! (node set, edge set, pins) with the order-free hash that says whether it changed.
//!
//! Nothing here touches rapier; the adapter reads these types and decides what the world
//! models.

pub(crate) mod clusters;
pub(crate) mod constraints;
pub(crate) mod layout;
pub(crate) mod node_forces;
#[cfg(feature = "petgraph")]
pub(crate) mod petgraph;
pub(crate) mod scene;
pub(crate) mod scene_file;
pub(crate) mod shape;
pub(crate) mod snapshot_error;
pub(crate) mod topology;
pub(crate) mod validation;
