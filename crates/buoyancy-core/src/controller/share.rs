//! The controller's share of a body's force and torque: what it added to the engine and has
//! not taken back (see [the controller](super#forces-the-application-adds-itself)).

use nalgebra::Vector3;

use super::state::{BodyState, Command, Motion};
use crate::Pose;

/// A sleeping body is out of balance when its net force (the controller's share, the
/// application's own forces and its weight) exceeds this fraction of its weight, or its net
/// torque this fraction of its weight times its size.
const BALANCE_TOLERANCE: f32 = 1e-3;

/// The force (N) and torque (N·m, about the center of mass) the controller has added to a body
/// and not taken back, in the engine's `f32`, world frame, and what it held the last time the
/// body was awake.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct AppliedShare {
    pub force: Vector3<f32>,
    pub torque: Vector3<f32>,
    /// The buoyancy (the share without damping) when the body was last awake: a sleeping body
    /// is woken when it has changed enough since, so that slow changes (a rising tide) add up.
    awake_force: Vector3<f32>,
    awake_torque: Vector3<f32>,
    /// The pose at which the body was last woken for being asleep out of balance.
    woken_out_of_balance_at: Option<Pose<f64>>,
}

impl AppliedShare {
    /// The share is zero from now on (the body's forces were reset).
    pub fn forget(&mut self) {
        (self.force, self.torque) = (Vector3::zeros(), Vector3::zeros());
    }

    /// Forgets the share if the engine wiped it: a dynamic body whose force and torque are both
    /// exactly zero while the share is not (rapier's NaN quarantine, or a reset of both).
    pub fn forget_if_wiped(&mut self, state: &BodyState) {
        let ours = self.force != Vector3::zeros() || self.torque != Vector3::zeros();
        if ours
            && state.motion == Motion::Dynamic
            && state.applied_force == Vector3::zeros()
            && state.applied_torque == Vector3::zeros()
        {
            self.forget();
        }
    }

    /// Makes the share `force` and `torque`: the command adds the difference.
    ///
    /// Whether a sleeping body is woken is decided on `buoyancy` (force and torque), the share
    /// without the damping: what the water does to a body at rest. It is woken when that
    /// differs from what it was when the body was last awake by more than 0.1 % of that force
    /// plus the body's weight (`gravity`, m/s², world frame, times its mass), or the torque by
    /// more than 0.1 % of that torque plus the same force scale times `size` (m, the body's
    /// length scale).
    ///
    /// It is woken too when the engine put it to sleep out of balance (see
    /// [the controller](super#sleeping-bodies)), unless it was woken for that at the same pose
    /// before: then something the controller does not see holds it (the ground, a joint).
    pub fn hold(
        &mut self,
        state: &BodyState,
        (force, torque): (Vector3<f32>, Vector3<f32>),
        buoyancy: (Vector3<f32>, Vector3<f32>),
        gravity: Vector3<f32>,
        size: f32,
    ) -> Command {
        let weight = state.mass as f32 * gravity.norm();
        let mut command = Command {
            add_force: force - self.force,
            add_torque: torque - self.torque,
            wake: false,
        };
        if state.sleeping && state.motion == Motion::Dynamic {
            let (changed_force, changed_torque) = (
                buoyancy.0 - self.awake_force,
                buoyancy.1 - self.awake_torque,
            );
            let force_scale = self.awake_force.norm() + weight + f32::MIN_POSITIVE;
            // Changed (and something to add: nothing to wake the body for otherwise).
            command.wake = command.adds_anything()
                && (changed_force.norm() > 1e-3 * force_scale
                    || changed_torque.norm()
                        > 1e-3 * (self.awake_torque.norm() + force_scale * size));
            if !command.wake {
                // Out of balance: the engine's forces besides the share are the application's.
                let net_force = buoyancy.0
                    + (state.applied_force - self.force)
                    + gravity * (state.mass * state.gravity_scale) as f32;
                let net_torque = buoyancy.1 + (state.applied_torque - self.torque);
                let scale = weight + f32::MIN_POSITIVE;
                let out_of_balance = net_force.norm() > BALANCE_TOLERANCE * scale
                    || net_torque.norm() > BALANCE_TOLERANCE * scale * size;
                let held_there = self
                    .woken_out_of_balance_at
                    .is_some_and(|pose| same_pose(&pose, &state.pose, f64::from(size)));
                if out_of_balance && !held_there {
                    command.wake = true;
                    self.woken_out_of_balance_at = Some(state.pose);
                }
            }
        }
        if command.adds_anything() {
            (self.force, self.torque) = (force, torque);
        }
        if !state.sleeping || command.wake {
            (self.awake_force, self.awake_torque) = buoyancy;
        }
        command
    }

    /// The command that takes the share back off the body (the engine must apply it even to a
    /// body that is not dynamic: rapier's adapter makes the body dynamic for that time).
    pub fn take_back(&self) -> Command {
        Command {
            add_force: -self.force,
            add_torque: -self.torque,
            wake: false,
        }
    }
}

/// Whether `a` and `b` are the same pose to 1e-4 of `size` (m) and 1e-4 rad.
fn same_pose(a: &Pose<f64>, b: &Pose<f64>, size: f64) -> bool {
    (a.translation.vector - b.translation.vector).norm() <= 1e-4 * size
        && a.rotation.angle_to(&b.rotation) <= 1e-4
}
