//! The centre pull: every pushed body is drawn toward [`Repulsion::center`] with
//! [`Repulsion::center_pull`] × heat per unit of distance, so parts of a graph that
//! repulsion pushes apart do not drift away for ever (d3-force's `forceCenter` moves the
//! whole graph instead; a pull per body is what a physics world can apply).

use std::hash::Hash;

use super::targets::NodeTargets;
use super::{BodyForce, ForceContext, ForceSums};
use crate::config::RapierLayoutConfig;
use crate::sanitize::finite_or;

#[cfg(doc)]
use crate::config::Repulsion;

/// Pulls every pushed body toward the repulsion's centre.
#[derive(Debug, Default)]
pub(crate) struct CenterPull;

impl<N: Clone + Eq + Hash> BodyForce<N> for CenterPull {
    fn is_active(&self, config: &RapierLayoutConfig, _: &NodeTargets) -> bool {
        config.repulsion.is_some()
    }

    fn apply(&mut self, frame: &ForceContext<'_, N>, out: &mut ForceSums) {
        let Some(repulsion) = &frame.config.repulsion else {
            return;
        };
        let pull = finite_or(repulsion.center_pull, 0.0) * frame.heat;
        let center = repulsion.center;
        if !(center.x.is_finite() && center.y.is_finite() && pull != 0.0) {
            return;
        }
        for (s, &point) in frame.points.iter().enumerate() {
            if frame.pushed[s] {
                out.forces[s] -= (point - center) * pull;
            }
        }
    }
}
