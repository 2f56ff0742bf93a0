//! The presets for laying graphs out: [`RapierLayoutConfig::force_directed`] and
//! [`RapierLayoutConfig::force_directed_fast`], d3-force's default simulation in
//! physical units. The plain [`RapierLayoutConfig::default`] lives with the fields.

use crate::config::{
    Accuracy, ContactModel, ContactSoftness, Contacts, Cooling, EdgeJoint, RapierLayoutConfig,
    Repulsion, Solver, SpringModel, Springs, StressModel, Throw,
};
use crate::world::bindings::PhysicsMaterial;

impl RapierLayoutConfig {
    /// A configuration for laying graphs out: d3-force's default forces converted to
    /// physical units, on colliding disks, cooled to rest in bounded time, with a feel of
    /// its own: a throw flies on and is drawn back, and an edit or a drag heats only the
    /// nodes near it.
    ///
    /// d3-force moves nodes in units per tick; at 60 ticks per second and the default
    /// node mass (density 0.005 × π 16² ≈ 4.0) its forces become:
    /// - links of distance 100 with strength `1 / min(degree)`: springs of rest length
    ///   100, stiffness 7,200 divided by `min(degree)^0.6`
    ///   ([`Springs::degree_exponent`] 0.6), no spring
    ///   damping. 7,200 is what a 1/60 s step resolves between two default nodes
    ///   ([`max_resolved_stiffness`](crate::world::max_resolved_stiffness)), d3's link at full
    ///   heat. d3's full share (exponent 1) leaves hub edges too soft here, because
    ///   physical springs pass a subtree's whole pull on to its root edge. The springs
    ///   are forces of the layout's own ([`SpringModel::Forces`]): one loop over the
    ///   edges, where rapier solves spring joints one at a time;
    /// - d3's link bias, the end with fewer neighbours pulled harder
    ///   ([`Springs::link_bias`] 1);
    /// - many-body strength −30: [`Repulsion`] of strength 430,000 (`30 × m × 60²`),
    ///   theta 0.9, with a gentle centre pull;
    /// - velocity decay 0.4 per tick would be linear damping 40 per second; half of it,
    ///   20, lets tangles slip free before the layout freezes;
    /// - alpha decay: a [`Cooling`] schedule over 4.5 s (d3 takes 5 s) that scales
    ///   repulsion by the heat and springs by `heat^0.7` ([`Cooling::spring_exponent`]),
    ///   so edges draw toward their rest length as the layout cools, unless the springs'
    ///   median length is over twice their rest length ([`Cooling::stretch_limit`] 2;
    ///   fully like the heat from four times, blended in between): such a graph cannot
    ///   reach its rest lengths, and springs that outlast repulsion would only pack it
    ///   into overlaps (`docs/performance.md` counts them with and without the limit);
    /// - collide at the node radius: the layout's own disk separation
    ///   ([`ContactModel::Disks`]: soft contacts on a uniform grid, firm at 240 Hz, ζ = 1,
    ///   [`ContactSoftness`]) instead of rapier's pair bookkeeping, and the overlaps
    ///   left when the schedule ends projected apart before the world halts. On the
    ///   first unfolding only, contacts are left out until the heat falls to 0.3
    ///   ([`Cooling::first_contact_heat`]) and then firm up from soft
    ///   ([`Cooling::hot_contact_frequency`] 5 Hz), so a fresh scatter spreads instead
    ///   of jamming. Later reheats keep them firm, so a drag always pushes;
    /// - one solver iteration of three passes ([`Accuracy::Custom`] `1, 3, 1`): with
    ///   the disk separation, the passes over the pairs before and after each step.
    ///
    /// And beyond d3-force, for the feel:
    /// - a disturbance (drag, release, host move, pin, edit) heats only the touched
    ///   nodes and their neighbours ([`Cooling::reheat_hops`] 1), so the nodes three or
    ///   more hops away hardly move, where d3's whole-graph reheat (`reheat_hops: None`)
    ///   moves all of them (`docs/feel.md` measures both); a dragged or thrown node's
    ///   springs pull with 1 % of their strength after the release
    ///   ([`Cooling::coasting_spring_scale`]);
    /// - a thrown node is damped at 1/s until it turns back
    ///   ([`Throw::flight_damping`] 1): a throw flies on past where it was let go and
    ///   is drawn back (`docs/feel.md` gives the distances and speeds).
    ///
    /// Every shipped graph comes to rest (every body asleep, or halted at the end of the
    /// schedule) within 300 frames of the last disturbance, with no overlapping pair on
    /// the graphs of up to 1,000 nodes (`docs/quality.md`: edge-length spread, frames and step
    /// times beside d3-force's). On large graphs a step takes a fraction of d3-force's
    /// tick, and [`force_directed_fast`](Self::force_directed_fast) less again, without
    /// collisions (`docs/performance.md` gives the times).
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
            springs: Springs {
                model: SpringModel::Forces,
                degree_exponent: 0.6,
                link_bias: 1.0,
                ..defaults.springs
            },
            contacts: Contacts {
                model: ContactModel::Disks,
                softness: ContactSoftness {
                    natural_frequency: 240.0,
                    damping_ratio: 1.0,
                },
                ..defaults.contacts
            },
            repulsion: Some(Repulsion::default()),
            cooling: Some(Cooling {
                duration: 4.5,
                spring_exponent: 0.7,
                stretch_limit: Some(2.0),
                hot_contact_frequency: Some(5.0),
                first_contact_heat: Some(0.3),
                reheat_hops: Some(1),
                ..Cooling::default()
            }),
            throw: Throw {
                flight_damping: Some(1.0),
                ..defaults.throw
            },
            solver: Solver {
                accuracy: Accuracy::Custom {
                    solver_iterations: 1,
                    internal_pgs_iterations: 3,
                    substeps: 1,
                },
                ..defaults.solver
            },
            ..defaults
        }
    }

    /// [`force_directed`](Self::force_directed) without collisions, with d3's full
    /// degree share (spring exponent 1), springs that fade with the heat itself and no
    /// link bias: the fastest force-directed setting, for graphs of thousands of nodes.
    /// Repulsion alone keeps nodes apart, so some overlap where springs pull hard, as
    /// under d3-force; the stiffer hub springs and the bias of `force_directed()` would
    /// press more together without contacts. In exchange there is no pair search, and a
    /// step costs less than `force_directed()`'s, at the median and the 95th percentile
    /// (`docs/performance.md` counts the overlaps and gives the times). Its springs,
    /// fading with the heat, are weak once the layout rests, so a thrown node's springs
    /// pull with 5 % of their strength ([`Cooling::coasting_spring_scale`]) to bring it
    /// back.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::RapierLayoutConfig;
    /// use graph_canvas_layout::config::Accuracy;
    /// let config = RapierLayoutConfig::force_directed_fast();
    /// assert!(!config.contacts.enabled && config.solver.accuracy == Accuracy::Fast);
    /// assert_eq!(config.repulsion, RapierLayoutConfig::force_directed().repulsion);
    /// ```
    pub fn force_directed_fast() -> Self {
        let directed = Self::force_directed();
        Self {
            contacts: Contacts {
                enabled: false,
                ..directed.contacts
            },
            springs: Springs {
                degree_exponent: 1.0,
                link_bias: 0.0,
                ..directed.springs
            },
            cooling: directed.cooling.map(|cooling| Cooling {
                spring_exponent: 1.0,
                coasting_spring_scale: 0.05,
                ..cooling
            }),
            solver: Solver {
                accuracy: Accuracy::Fast,
                ..directed.solver
            },
            ..directed
        }
    }

    /// A configuration that draws the graph's structure: the stress model
    /// ([`StressModel`]) inside the physics, from a start that is already a layout. The
    /// recommended preset for laying a graph out.
    ///
    /// Every two nodes are kept near their graph distance, as stress majorization
    /// (Graphviz neato) and stress SGD (the lowest stress any published method reaches)
    /// keep them: meshes and grids come out flat, trees spread, power networks show their
    /// branches. The first world starts from a global layout (pivot MDS refined by stress
    /// SGD passes, components packed side by side), so the first frame shows the graph's
    /// shape and the physics refines it; drags, throws, pins, per-node forces, contacts
    /// and local heat work as under [`force_directed`](Self::force_directed):
    /// - edge springs of stiffness 7,200 resting at the hop length (at least 100 units,
    ///   longer where the nodes' disks need room: [`StressModel::fit_length`]), solved as
    ///   forces of the layout's own, and the stress terms beside them: the full stress
    ///   for graphs of up to 2,000 nodes, 100 pivots above, exact terms within two hops,
    ///   pivot terms worked out every fourth substep ([`StressModel`]);
    /// - no many-body repulsion: stress spreads the graph itself;
    /// - the layout's own disk separation at 240 Hz, ζ = 1, from the first 0.35 s on
    ///   ([`Cooling::first_contact_heat`] 0.3: the first frames of a large graph refine
    ///   the start faster than the contacts could follow);
    /// - a 2 s cooling schedule that scales every stress term with the heat (their
    ///   balance stays the same while the push toward it fades), so a graph rests within
    ///   150 frames; local reheat (one hop), and a thrown node coasting with 0.3 % of its
    ///   terms' strength ([`Cooling::coasting_spring_scale`]: the stress terms of a node
    ///   outnumber its edges) and damped at 1/s until it turns back;
    /// - linear damping 20 per second, one solver iteration of three passes.
    ///
    /// `docs/quality.md` gives its stress against neato, sfdp and stress SGD on the
    /// standard graphs, its frames and time to rest, and the trade of pivots, pivot
    /// period and start against them.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::RapierLayoutConfig;
    /// let config = RapierLayoutConfig::stress();
    /// assert!(config.stress.is_some() && config.repulsion.is_none());
    /// ```
    pub fn stress() -> Self {
        let directed = Self::force_directed();
        Self {
            repulsion: None,
            springs: Springs {
                degree_exponent: 0.0,
                link_bias: 0.0,
                ..directed.springs
            },
            cooling: directed.cooling.map(|cooling| Cooling {
                duration: 2.0,
                spring_exponent: 1.0,
                stretch_limit: None,
                hot_contact_frequency: None,
                coasting_spring_scale: 0.003,
                ..cooling
            }),
            stress: Some(StressModel::default()),
            ..directed
        }
    }
}
