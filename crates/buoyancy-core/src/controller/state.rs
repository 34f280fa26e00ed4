//! What the controller reads from an engine per body per step ([`BodyState`]), what it asks
//! back ([`Command`]), what it reports ([`FloatReport`], [`Outcome`]), and the force and torque
//! it sums them in (`Wrench`).

use nalgebra::{Matrix3, Point3, Vector3};

use crate::Pose;

/// Whether the engine moves a body by its forces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Motion {
    /// Moved by forces: it floats.
    #[default]
    Dynamic,
    /// Kinematic, fixed or disabled: the engine ignores new forces on it but keeps the ones it
    /// holds; the controller computes nothing for it and leaves its share as it is, so that a
    /// body made kinematic and dynamic again gets its buoyancy once, not twice.
    Inactive,
}

/// One body's state at the start of a step, as the engine has it, world frame, SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyState {
    /// The body frame → world (the frame its parts are placed in).
    pub pose: Pose<f64>,
    /// The center of mass, m.
    pub center_of_mass: Point3<f64>,
    /// Velocity of the center of mass, m/s.
    pub linear_velocity: Vector3<f64>,
    /// Angular velocity, rad/s.
    pub angular_velocity: Vector3<f64>,
    /// Mass, kg.
    pub mass: f64,
    /// Inverse mass per world axis, 1/kg (zero on a locked translation axis).
    pub inverse_mass: Vector3<f64>,
    /// Inverse inertia tensor about the center of mass, world frame, 1/(kg·m²) (zero rows and
    /// columns on locked rotation axes).
    pub inverse_inertia: Matrix3<f64>,
    /// The factor of gravity on this body.
    pub gravity_scale: f64,
    /// The force the engine holds for the body (its own forces and the controller's share), N,
    /// in the engine's `f32`.
    pub applied_force: Vector3<f32>,
    /// The torque the engine holds for the body, about its center of mass, N·m.
    pub applied_torque: Vector3<f32>,
    /// Whether the engine moves the body by forces.
    pub motion: Motion,
    /// Whether the body sleeps.
    pub sleeping: bool,
}

/// What to do to one body after a step of the controller: add this force and torque (about its
/// center of mass) to what the engine holds for it, waking it if `wake`. Zero means nothing to
/// add.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Command {
    /// Force to add, N, world frame.
    pub add_force: Vector3<f32>,
    /// Torque to add, N·m, world frame.
    pub add_torque: Vector3<f32>,
    /// Whether to wake the body (when it sleeps), also when there is nothing to add (a body
    /// asleep out of balance: see [the controller](super#sleeping-bodies)).
    pub wake: bool,
}

impl Command {
    /// Whether there is a force or torque to add.
    pub fn adds_anything(&self) -> bool {
        self.add_force != Vector3::zeros() || self.add_torque != Vector3::zeros()
    }
}

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

/// A force (N) and a torque (N·m, about a point the context names), world frame, `f64`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Wrench {
    pub force: Vector3<f64>,
    pub torque: Vector3<f64>,
}
