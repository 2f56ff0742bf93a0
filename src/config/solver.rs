//! The solver group ([`Solver`]): the speed/accuracy trade ([`Accuracy`]), rapier's
//! length unit and the speed cap. The frame plan copies them into rapier's integration
//! parameters once per call (`adapter/substeps.rs`).

use serde::{Deserialize, Serialize};

/// How hard the solver works per step. Each level fixes rapier's solver iterations,
/// internal PGS iterations and substeps per timestep; cost grows about linearly with
/// `solver_iterations × substeps`. `docs/tradeoff.md` (`cargo run --release --example
/// tradeoff`) gives the measured cost and error of each.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Accuracy {
    /// 1 solver iteration, 1 substep per timestep: the cheapest step. Springs and
    /// contacts converge over several frames instead of one; fine for large graphs in
    /// motion, visibly softer contacts in dense clusters.
    Fast,
    /// 2 solver iterations, 1 substep per timestep: the knee of the cost/error curve
    /// on the shipped graphs.
    #[default]
    Balanced,
    /// 8 solver iterations, 2 internal PGS iterations and 2 substeps per timestep:
    /// 8× the solver work of `Balanced` (`docs/tradeoff.md` times it) for the stiffest
    /// constraints and the most faithful trajectories.
    Precise,
    /// Explicit settings.
    Custom {
        /// Rapier's `num_solver_iterations`, from 1 to 256 (a count beyond is
        /// taken as 256: a bound on a frame's cost whatever a configuration says).
        solver_iterations: usize,
        /// Rapier's `num_internal_pgs_iterations`, from 1 to 256.
        internal_pgs_iterations: usize,
        /// Substeps per fixed timestep, from 1 to 64: `k` shortens every
        /// substep `k`-fold.
        substeps: u32,
    },
}

/// The most solver or internal PGS iterations an [`Accuracy::Custom`] asks for: 32
/// times [`Accuracy::Precise`]'s, far past where more iterations change a layout, and a
/// bound on a frame's cost whatever a configuration (or a damaged snapshot) says.
pub(crate) const MAX_ITERATIONS: usize = 256;

/// The most substeps per fixed timestep an [`Accuracy::Custom`] asks for.
pub(crate) const MAX_SUBSTEPS: u32 = 64;

/// What an [`Accuracy`] setting asks of the solver, each at least 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SolverSettings {
    /// Rapier's `num_solver_iterations`.
    pub solver_iterations: usize,
    /// Rapier's `num_internal_pgs_iterations`.
    pub internal_pgs_iterations: usize,
    /// Substeps per fixed timestep.
    pub substeps: u32,
}

impl Accuracy {
    /// What this setting asks of the solver.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::config::{Accuracy, SolverSettings};
    /// let precise = Accuracy::Precise.solver_settings();
    /// assert_eq!(
    ///     precise,
    ///     SolverSettings { solver_iterations: 8, internal_pgs_iterations: 2, substeps: 2 }
    /// );
    /// ```
    pub fn solver_settings(self) -> SolverSettings {
        let (solver_iterations, internal_pgs_iterations, substeps) = self.settings();
        SolverSettings {
            solver_iterations,
            internal_pgs_iterations,
            substeps,
        }
    }

    /// `(solver_iterations, internal_pgs_iterations, substeps)` for this setting; see
    /// [`solver_settings`](Self::solver_settings) for the same with names.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::config::Accuracy;
    /// assert_eq!(Accuracy::Fast.settings(), (1, 1, 1));
    /// ```
    pub fn settings(self) -> (usize, usize, u32) {
        match self {
            Accuracy::Fast => (1, 1, 1),
            Accuracy::Balanced => (2, 1, 1),
            Accuracy::Precise => (8, 2, 2),
            Accuracy::Custom {
                solver_iterations,
                internal_pgs_iterations,
                substeps,
            } => (
                solver_iterations.clamp(1, MAX_ITERATIONS),
                internal_pgs_iterations.clamp(1, MAX_ITERATIONS),
                substeps.clamp(1, MAX_SUBSTEPS),
            ),
        }
    }
}

/// How hard rapier's solver works and the scale it works at. Every field takes effect
/// at the next call.
///
/// # Example
/// ```
/// use graph_canvas_layout::config::{Accuracy, Solver};
/// use graph_canvas_layout::RapierLayoutConfig;
/// let config = RapierLayoutConfig {
///     solver: Solver { accuracy: Accuracy::Fast, ..Solver::default() },
///     ..RapierLayoutConfig::default()
/// };
/// assert_eq!(config.solver.accuracy.solver_settings().solver_iterations, 1);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Solver {
    /// The speed/accuracy trade of the solver; see [`Accuracy`] for what each preset
    /// costs and buys. Default: [`Accuracy::Balanced`].
    pub accuracy: Accuracy,
    /// Rapier's `length_unit`: the size of a typical object in world units. Rapier
    /// scales its tolerances (contact slop, sleep threshold, speed cap) by it. Canvas
    /// nodes are about 30 pixels across and edges about 100, so the default suits pixel
    /// worlds. Default: `100.0`.
    pub length_unit: f32,
    /// Speed cap in world units per second; rapier clamps faster bodies each substep.
    /// A throw faster than this flies at the cap. Default: `40_000.0` (rapier's own
    /// 400 lengths/s at `length_unit` 100).
    pub max_speed: f32,
    /// Gauss–Seidel passes over the hard constraints (a [`Flow`](crate::config::Flow)'s
    /// edges, [`LayoutExtras::constraints`](crate::LayoutExtras::constraints)) after
    /// each substep. Each pass costs one visit to every constraint; fewer passes leave a
    /// long chain of constraints short for more frames while the layout moves (at rest
    /// every constraint holds within a unit whatever this is: the halt projects until it
    /// does). `docs/flow.md` measures the trade. Taken as 1 to 64. Costs nothing
    /// without constraints. Default: `8`.
    pub constraint_passes: u32,
}

impl Solver {
    /// [`constraint_passes`](Self::constraint_passes), from 1 to 64.
    pub(crate) fn constraint_passes(&self) -> usize {
        self.constraint_passes.clamp(1, 64) as usize
    }
}

impl Default for Solver {
    fn default() -> Self {
        Self {
            accuracy: Accuracy::Balanced,
            length_unit: 100.0,
            max_speed: 40_000.0,
            constraint_passes: 8,
        }
    }
}
