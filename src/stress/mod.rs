//! The stress model, whole: its graph work apart from the physics (hop distances by the
//! crate's breadth-first search, `graph.rs`, the sparse model's terms and weights in `model.rs`, a global start
//! layout from them in `start.rs`: pivot MDS in `mds.rs`, stress SGD in `sgd.rs`,
//! components packed in `pack.rs`), the new world's hop length and start turned to the
//! host's held nodes (`placement.rs`), the force that keeps the terms in the physics
//! (`force/`), and the balance kept at rest (`rest_bias.rs`). The settings are
//! [`StressModel`](crate::config::StressModel); the preset is
//! [`RapierLayoutConfig::stress`](crate::RapierLayoutConfig::stress).

mod force;
mod mds;
pub(crate) mod model;
mod pack;
mod placement;
mod rest_bias;
pub(crate) mod sgd;
pub(crate) mod start;

pub(crate) use force::StressForce;
pub(crate) use placement::{start_world, StartConstraints, WorldOrigin};
pub(crate) use rest_bias::RestBias;
