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
