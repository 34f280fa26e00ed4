//! The controller's share of a body's force and torque: what it added to the engine and has
//! not taken back (see [the controller](super#forces-the-application-adds-itself)).

use nalgebra::Vector3;

use super::state::{BodyState, Command, Motion};

/// The force (N) and torque (N·m, about the center of mass) the controller has added to a body
/// and not taken back, in the engine's `f32`, world frame, and what it held the last time the
/// body was awake.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct AppliedShare {
    pub force: Vector3<f32>,
    pub torque: Vector3<f32>,
    /// The share held when the body was last awake: a sleeping body is woken when the share
    /// has changed enough since, so that slow changes (a rising tide) add up.
    awake_force: Vector3<f32>,
    awake_torque: Vector3<f32>,
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
    /// A sleeping body is woken when the share differs from the one it had when last awake by
    /// more than 0.1 % of that force plus the body's weight (`gravity`, m/s², times its mass),
    /// or the torque by more than 0.1 % of that torque plus the same force scale times `size`
    /// (m, the body's length scale).
    pub fn hold(
        &mut self,
        state: &BodyState,
        force: Vector3<f32>,
        torque: Vector3<f32>,
        gravity: f32,
        size: f32,
    ) -> Command {
        let weight = state.mass as f32 * gravity;
        let (changed_force, changed_torque) =
            (force - self.awake_force, torque - self.awake_torque);
        let force_scale = self.awake_force.norm() + weight + f32::MIN_POSITIVE;
        let wake = changed_force.norm() > 1e-3 * force_scale
            || changed_torque.norm() > 1e-3 * (self.awake_torque.norm() + force_scale * size);
        let mut command = Command {
            add_force: force - self.force,
            add_torque: torque - self.torque,
            wake,
        };
        // Nothing added, nothing to wake the body for.
        command.wake &= command.adds_anything();
        if command.adds_anything() {
            (self.force, self.torque) = (force, torque);
        }
        if !state.sleeping || wake {
            (self.awake_force, self.awake_torque) = (force, torque);
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
