//! Edge joints: what each [`EdgeJoint`] kind becomes in rapier.

use rapier2d::prelude::{
    GenericJoint, GenericJointBuilder, JointAxesMask, JointAxis, MotorModel, RopeJointBuilder,
    SpringCoefficients, SpringJointBuilder,
};

use crate::world::EdgeJoint;

/// Stiffness, per unit of mass, of the constraint behind [`EdgeJoint::Distance`]:
/// a natural frequency of 1,000 rad/s, far above any frame rate, so the rod is rigid at
/// every timestep while staying an implicit (unconditionally stable) spring.
const DISTANCE_STIFFNESS: f32 = 1.0e6;
/// Critical damping for [`DISTANCE_STIFFNESS`]: `2 √k`.
const DISTANCE_DAMPING: f32 = 2.0e3;
/// Highest natural frequency given to a rope's limit; rapier's own rigid joints use 1e6.
const MAX_ROPE_FREQUENCY: f32 = 1.0e6;

/// A finite, non-negative copy of `x` (0 otherwise), so no host value can put a NaN
/// into the solver.
fn non_negative(x: f32) -> f32 {
    if x.is_finite() && x > 0.0 {
        x
    } else {
        0.0
    }
}

/// The stiffest spring a timestep `dt` resolves between bodies of reduced mass
/// `reduced_mass`: natural frequency `1 / dt`, i.e. `k = m / dt²`. Stiffer springs would
/// correct their whole stretch in less than one step; in a graph whose edges cannot all
/// have their rest length (most graphs), such springs fight each other every step and
/// the layout never settles. Above this stiffness a spring behaves as this one: as
/// stiff as the timestep can show.
pub fn max_resolved_stiffness(reduced_mass: f32, dt: f32) -> f32 {
    let limit = reduced_mass / (dt * dt);
    if limit.is_finite() && limit > 0.0 {
        limit
    } else {
        f32::MAX
    }
}

/// `kind` with `scale` applied to a spring's stiffness and damping; other kinds as they
/// are.
pub(crate) fn scaled_spring(kind: &EdgeJoint, scale: impl Fn(f32) -> f32) -> EdgeJoint {
    match *kind {
        EdgeJoint::Spring {
            rest_length,
            stiffness,
            damping,
        } => EdgeJoint::Spring {
            rest_length,
            stiffness: scale(stiffness),
            damping: scale(damping),
        },
        other => other,
    }
}

/// The rapier joint for one edge, or `None` for [`EdgeJoint::None`].
///
/// `reduced_mass` is `m1 m2 / (m1 + m2)` of the two bodies: the rope uses it to turn
/// its stiffness (force per unit of stretch) into the limit's natural frequency, and
/// the spring to cap its stiffness at what the timestep `dt` resolves.
pub(crate) fn rapier_joint(kind: &EdgeJoint, reduced_mass: f32, dt: f32) -> Option<GenericJoint> {
    match *kind {
        EdgeJoint::Spring {
            rest_length,
            stiffness,
            damping,
        } => Some(
            SpringJointBuilder::new(
                non_negative(rest_length),
                non_negative(stiffness).min(max_resolved_stiffness(reduced_mass, dt)),
                non_negative(damping),
            )
            .spring_model(MotorModel::ForceBased)
            .build()
            .into(),
        ),
        EdgeJoint::Rope {
            max_length,
            stiffness,
        } => {
            let omega = (non_negative(stiffness) / reduced_mass.max(f32::MIN_POSITIVE)).sqrt();
            let omega = if omega.is_finite() {
                omega.min(MAX_ROPE_FREQUENCY)
            } else {
                MAX_ROPE_FREQUENCY
            };
            let mut rope = RopeJointBuilder::new(non_negative(max_length)).build();
            let _ = rope.set_softness(SpringCoefficients::new(omega, 1.0));
            Some(rope.into())
        }
        EdgeJoint::Distance { length } => Some(
            GenericJointBuilder::new(JointAxesMask::empty())
                .coupled_axes(JointAxesMask::LIN_AXES)
                .motor_position(
                    JointAxis::LinX,
                    non_negative(length),
                    DISTANCE_STIFFNESS,
                    DISTANCE_DAMPING,
                )
                .motor_model(JointAxis::LinX, MotorModel::AccelerationBased)
                .build(),
        ),
        EdgeJoint::None => None,
    }
}
