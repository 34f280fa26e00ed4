//! The adapter's share of a body's force and torque stays exactly one buoyancy + damping
//! through body type changes, `unregister` and rapier's NaN quarantine.

mod common;

use common::{DT, Pool};
use rapier3d::prelude::*;

/// dynamic → kinematic (or fixed) → dynamic does not double the buoyancy: rapier ignores
/// `add_force` on bodies that are not dynamic but keeps their stored force, and the adapter
/// leaves its share as it is meanwhile.
#[test]
fn body_type_round_trip_keeps_one_buoyancy() {
    for other in [
        RigidBodyType::KinematicPositionBased,
        RigidBodyType::KinematicVelocityBased,
        RigidBodyType::Fixed,
    ] {
        let mut pool = Pool::new();
        let h = pool.half_density_cube(0.0);
        pool.run(3.0);
        pool.world.bodies[h].set_body_type(other, true);
        pool.run(0.5);
        pool.world.bodies[h].set_body_type(RigidBodyType::Dynamic, true);
        pool.water.apply(&mut pool.world.bodies, DT);
        let (own_force, own_torque) = pool.own_wrench(h);
        assert!(
            own_force.length() < 1.0 && own_torque.length() < 1.0,
            "{other:?}: phantom force {own_force:?}, torque {own_torque:?}"
        );
        let stored = pool.body(h).user_force().y;
        assert!(
            (stored - 4905.0).abs() < 50.0,
            "{other:?}: stored force {stored} N, expected ≈ 4905 N"
        );
        pool.run(3.0);
        let y = pool.body(h).translation().y;
        assert!(
            y.abs() < 0.05,
            "{other:?}: at y = {y} m after 3 s, expected ≈ 0"
        );
    }
}

/// `unregister` takes the share off a body that is not dynamic too (rapier would ignore the
/// `add_force` that takes it back), and leaves the body's type as it was.
#[test]
fn unregister_while_kinematic_takes_the_share_off() {
    let mut pool = Pool::new();
    let h = pool.half_density_cube(0.0);
    pool.run(1.0);
    pool.world.bodies[h].set_body_type(RigidBodyType::KinematicPositionBased, true);
    pool.step();
    assert!(pool.water.unregister(h, &mut pool.world.bodies));
    assert_eq!(
        pool.body(h).body_type(),
        RigidBodyType::KinematicPositionBased
    );
    pool.world.bodies[h].set_body_type(RigidBodyType::Dynamic, true);
    assert!(
        pool.body(h).user_force().length() < 1e-2,
        "left behind: {:?}",
        pool.body(h).user_force()
    );
    assert!(pool.body(h).user_torque().length() < 1e-2);
}

/// rapier's NaN quarantine zeroes the body's forces: the adapter notices and does not take
/// back a share that is no longer there, and the re-enabled body floats with one buoyancy.
#[test]
fn quarantined_body_gets_no_phantom_force() {
    let mut pool = Pool::new();
    let h = pool.half_density_cube(0.0);
    pool.run(3.0);
    // A NaN force goes non-finite inside the step, after the adapter has added its share.
    pool.world.bodies[h].add_force(Vector::NAN, true);
    pool.step();
    assert_eq!(pool.world.quarantine().bodies(), &[h]);
    pool.step();
    assert!(!pool.body(h).is_enabled());
    assert!(
        pool.body(h).user_force().length() < 1e-3,
        "phantom force {:?}",
        pool.body(h).user_force()
    );
    pool.world.bodies[h].set_enabled(true);
    pool.run(3.0);
    let (own_force, _) = pool.own_wrench(h);
    assert!(own_force.length() < 1.0, "phantom force {own_force:?}");
    assert!(
        pool.body(h).translation().y.abs() < 0.02,
        "at {}",
        pool.body(h).translation().y
    );
}
