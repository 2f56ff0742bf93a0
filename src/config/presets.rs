//! The presets for laying graphs out: [`RapierLayoutConfig::force_directed`] and
//! [`RapierLayoutConfig::force_directed_fast`], d3-force's default simulation in
//! physical units. The plain [`RapierLayoutConfig::default`] lives with the fields.

use crate::config::cooling::Cooling;
use crate::config::edge_joint::EdgeJoint;
use crate::config::solver::{Accuracy, ContactSoftness};
use crate::config::RapierLayoutConfig;
use crate::forces::many_body::Repulsion;
use crate::world::bindings::PhysicsMaterial;

impl RapierLayoutConfig {
    /// A configuration for laying graphs out: d3-force's default forces converted to
    /// physical units, on colliding disks, cooled to rest in bounded time.
    ///
    /// d3-force moves nodes in units per tick; at 60 ticks per second and the default
    /// node mass (density 0.005 × π 16² ≈ 4.0) its forces become:
    /// - links of distance 100 with strength `1 / min(degree)`: springs of rest length
    ///   100, stiffness 7,200 divided by `min(degree)^0.6`
    ///   ([`spring_degree_exponent`](Self::spring_degree_exponent) 0.6), no spring
    ///   damping. 7,200 is what a 1/60 s step resolves between two default nodes
    ///   ([`max_resolved_stiffness`](crate::max_resolved_stiffness)), d3's link at full
    ///   heat. d3's full share (exponent 1) leaves hub edges too soft here, because
    ///   physical springs pass a subtree's whole pull on to its root edge;
    /// - d3's link bias, the end with fewer neighbours pulled harder
    ///   ([`link_bias`](Self::link_bias) 1);
    /// - many-body strength −30: [`Repulsion`] of strength 430,000 (`30 × m × 60²`),
    ///   theta 0.9, with a gentle centre pull;
    /// - velocity decay 0.4 per tick would be linear damping 40 per second; half of it,
    ///   20, lets tangles slip free before the layout freezes;
    /// - alpha decay: a [`Cooling`] schedule over 8 s (d3 takes 5 s; the longer schedule
    ///   untangles trees and grids further before they freeze) that scales repulsion by
    ///   the heat and springs by `heat^0.7` ([`Cooling::spring_exponent`]), so edges draw
    ///   toward their rest length as the layout cools, unless the springs' median length
    ///   is over twice their rest length ([`Cooling::stretch_limit`] 2; fully like the
    ///   heat from four times, blended in between): such a graph cannot reach its rest
    ///   lengths, and springs that outlast repulsion would only pack it into a creeping
    ///   jam of contacts;
    /// - collide at the node radius: firm contacts (240 Hz, ζ = 1, [`ContactSoftness`])
    ///   that no spring presses through. On the first unfolding only, they are left out
    ///   until the heat falls to 0.3 ([`Cooling::first_contact_heat`]) and then firm up
    ///   from soft ([`Cooling::hot_contact_frequency`] 5 Hz): a fresh scatter collapsing
    ///   into thousands of contact pairs would cost most of the step (d3's collide, too,
    ///   is weak next to its other forces early on). Later reheats keep them firm, so a
    ///   drag always pushes;
    /// - one solver iteration of three PGS passes ([`Accuracy::Custom`] `1, 3, 1`): at
    ///   the end of the schedule the springs press a large graph together into a jammed
    ///   packing, and a single pass ([`Accuracy::Fast`]) leaves up to a hundred slightly
    ///   overlapping pairs on `n1000_e2500` and is slower on `n10000_e25000` (68 ms per
    ///   step: under-resolved contacts make more pairs). Three PGS passes resolve them
    ///   as well as [`Accuracy::Balanced`]'s two solver iterations, without the second
    ///   constraint update and position integration: about 7 % less per step on
    ///   `n1000_e2500` (1.22 against 1.30 ms) and `n10000_e25000`, with no overlaps,
    ///   for a little more spread on karate and trees (README).
    ///
    /// Every shipped graph comes to rest (every body asleep, or halted at the end of the
    /// schedule) within 9 s of simulated time after the last disturbance. Contacts
    /// dominate the step of large random graphs (27.4 ms per step over frames 30–270
    /// at 10,000 nodes, 24 ms averaged until rest); for thousands of nodes
    /// [`force_directed_fast`](Self::force_directed_fast) takes 11 ms. The damping
    /// is d3's: a throw stops within a few frames. For a physical feel (coasting
    /// throws), start from [`RapierLayoutConfig::default`].
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::RapierLayoutConfig;
    /// let config = RapierLayoutConfig::force_directed();
    /// assert!(config.repulsion.is_some() && config.cooling.is_some());
    /// ```
    pub fn force_directed() -> Self {
        let defaults = Self::default();
        Self {
            edge_joint: EdgeJoint::Spring {
                rest_length: 100.0,
                stiffness: 7_200.0,
                damping: 0.0,
            },
            material: PhysicsMaterial {
                linear_damping: 20.0,
                ..defaults.material
            },
            repulsion: Some(Repulsion::default()),
            spring_degree_exponent: 0.6,
            cooling: Some(Cooling {
                duration: 8.0,
                spring_exponent: 0.7,
                stretch_limit: Some(2.0),
                hot_contact_frequency: Some(5.0),
                first_contact_heat: Some(0.3),
                ..Cooling::default()
            }),
            link_bias: 1.0,
            contact_softness: ContactSoftness {
                natural_frequency: 240.0,
                damping_ratio: 1.0,
            },
            accuracy: Accuracy::Custom {
                solver_iterations: 1,
                internal_pgs_iterations: 3,
                substeps: 1,
            },
            ..defaults
        }
    }

    /// [`force_directed`](Self::force_directed) without colliders, with d3's full
    /// degree share (spring exponent 1) and no link bias: the fastest force-directed
    /// setting, for graphs of thousands of nodes. Repulsion alone keeps nodes apart, so
    /// some overlap where springs pull hard (783 pairs on `n1000_e2500`; d3-force leaves
    /// 347); the stiffer hub springs and the bias of `force_directed()` would press
    /// twice as many together without contacts. In exchange the broad and narrow
    /// phases, which dominate the step of a large graph, are gone. Measured on
    /// `n10000_e25000` (README): 11.2 ms per step over frames 30–270, where
    /// `force_directed()` takes 27.4 ms.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{Accuracy, RapierLayoutConfig};
    /// let config = RapierLayoutConfig::force_directed_fast();
    /// assert!(!config.collisions && config.accuracy == Accuracy::Fast);
    /// assert_eq!(config.repulsion, RapierLayoutConfig::force_directed().repulsion);
    /// ```
    pub fn force_directed_fast() -> Self {
        let directed = Self::force_directed();
        Self {
            collisions: false,
            spring_degree_exponent: 1.0,
            link_bias: 0.0,
            cooling: directed.cooling.map(|cooling| Cooling {
                spring_exponent: 1.0,
                ..cooling
            }),
            accuracy: Accuracy::Fast,
            ..directed
        }
    }
}
