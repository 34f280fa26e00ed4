//! The adapter's share of a body's force and torque: what it added and has not taken back (see
//! [Forces the application adds itself](crate#forces-the-application-adds-itself)).

use rapier3d::math::Vector;
use rapier3d::prelude::{RigidBody, RigidBodyType};

/// The force (N) and torque (N·m, about the world center of mass) the adapter has added to a
/// body and not taken back, in rapier's `f32`, world frame, and what it held the last time the
/// body was awake.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct AppliedShare {
    pub force: Vector,
    pub torque: Vector,
    /// The share held when the body was last awake: a sleeping body is woken when the share
    /// has changed enough since, so that slow changes (a rising tide) add up.
    awake_force: Vector,
    awake_torque: Vector,
}

impl AppliedShare {
    /// The share is zero from now on (the body's forces were reset).
    pub fn forget(&mut self) {
        (self.force, self.torque) = (Vector::ZERO, Vector::ZERO);
    }

    /// Forgets the share if rapier wiped it: a dynamic body whose force and torque are both
    /// exactly zero while the share is not (rapier's NaN quarantine, or `reset_forces` +
    /// `reset_torques`).
    pub fn forget_if_wiped(&mut self, rb: &RigidBody) {
        let ours = self.force != Vector::ZERO || self.torque != Vector::ZERO;
        if ours
            && rb.is_dynamic()
            && rb.user_force() == Vector::ZERO
            && rb.user_torque() == Vector::ZERO
        {
            self.forget();
        }
    }

    /// Makes the share `force` and `torque`: adds the difference to the body.
    ///
    /// A sleeping body is woken when the share differs from the one it had when last awake by
    /// more than 0.1 % of that force plus the body's weight (`gravity`, m/s², times its mass),
    /// or the torque by more than 0.1 % of that torque plus the same force scale times `size`
    /// (m, the body's length scale).
    pub fn hold(
        &mut self,
        rb: &mut RigidBody,
        force: Vector,
        torque: Vector,
        gravity: f32,
        size: f32,
    ) {
        let sleeping = rb.is_sleeping();
        let weight = rb.mass() * gravity;
        let (changed_force, changed_torque) =
            (force - self.awake_force, torque - self.awake_torque);
        let force_scale = self.awake_force.length() + weight + f32::MIN_POSITIVE;
        let wake = changed_force.length() > 1e-3 * force_scale
            || changed_torque.length() > 1e-3 * (self.awake_torque.length() + force_scale * size);
        let (delta_force, delta_torque) = (force - self.force, torque - self.torque);
        if delta_force != Vector::ZERO || delta_torque != Vector::ZERO {
            rb.add_force(delta_force, wake);
            rb.add_torque(delta_torque, wake);
            (self.force, self.torque) = (force, torque);
        }
        if !sleeping || wake {
            (self.awake_force, self.awake_torque) = (force, torque);
        }
    }

    /// Takes the share back off the body. rapier ignores `add_force` on bodies that are not
    /// dynamic, so those are made dynamic for the time of the subtraction.
    pub fn take_back(&self, rb: &mut RigidBody) {
        if self.force == Vector::ZERO && self.torque == Vector::ZERO {
            return;
        }
        let body_type = rb.body_type();
        if !body_type.is_dynamic() {
            rb.set_body_type(RigidBodyType::Dynamic, false);
        }
        rb.add_force(-self.force, false);
        rb.add_torque(-self.torque, false);
        if !body_type.is_dynamic() {
            rb.set_body_type(body_type, false);
        }
    }
}
