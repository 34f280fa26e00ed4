//! What the controller reads from an engine per body per step, and what it asks back.

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
