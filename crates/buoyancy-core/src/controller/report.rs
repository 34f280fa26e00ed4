//! What the controller computed and applied for a body at its last step.

use nalgebra::{Point3, Vector3};

/// What became of a body at the last [`Controller::step`](super::Controller::step).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Outcome {
    /// Registered, and no `apply` since: nothing computed or applied yet.
    #[default]
    NotEvaluated,
    /// Buoyancy and damping were computed, and the body holds them as the controller's share of
    /// its force and torque.
    Applied,
    /// The body is kinematic, fixed or disabled ([`Motion::Inactive`](super::Motion::Inactive)):
    /// nothing was computed, and the share it had is left as it is (engines ignore new forces
    /// on such bodies but keep the ones they hold).
    Inactive,
    /// A pose, velocity or result was not finite: no force was applied, and the share the body
    /// had was taken back.
    NotFinite,
    /// The buoyancy query was refused: a [`Method`](crate::Method) that assumes a flat surface
    /// (Fast, Improved, Fast Surface) under waves, or the
    /// [Froude–Krylov](crate::query::Pressure::FroudeKrylov) pressure on a surface that is not
    /// [`AiryWaves`](crate::water::AiryWaves). No force was applied, and the share the body had
    /// was taken back.
    Unsupported,
}

/// What the controller computed and applied for one body at the last
/// [`Controller::step`](super::Controller::step), world frame, SI units, torques about the
/// body's world center of mass.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FloatReport {
    /// Volume under water, m³ (all floating parts).
    pub submerged_volume: f64,
    /// Center of buoyancy, m: the volume-weighted mean of the parts' centers (the projection
    /// of the center of mass on the surface when nothing is under water).
    pub center_of_buoyancy: Point3<f64>,
    /// The body's world center of mass (the engine's), m.
    pub center_of_mass: Point3<f64>,
    /// Buoyant force, N.
    pub buoyancy_force: Vector3<f64>,
    /// Torque of the buoyancy about the center of mass, N·m.
    pub buoyancy_torque: Vector3<f64>,
    /// Damping force as applied, after the semi-implicit step (see [Stability](super#stability)),
    /// N.
    pub damping_force: Vector3<f64>,
    /// Damping torque as applied, after the semi-implicit step, N·m.
    pub damping_torque: Vector3<f64>,
    /// Wetted area, m².
    pub wetted_area: f64,
    /// Whether the forces above were applied; when not ([`Outcome::Inactive`],
    /// [`Outcome::NotFinite`]), they are zero and the center of buoyancy is the center of mass.
    pub outcome: Outcome,
}

impl FloatReport {
    /// The report of a body that got no force computed: zero volume, forces and area, the
    /// center of buoyancy at the center of mass.
    pub fn without_forces(center_of_mass: Point3<f64>, outcome: Outcome) -> Self {
        FloatReport {
            center_of_mass,
            center_of_buoyancy: center_of_mass,
            outcome,
            ..Default::default()
        }
    }
}
