//! What a body's report says became of it at the last `apply`: not evaluated yet, applied,
//! inactive (kinematic, fixed or disabled), or not finite.

mod common;

use buoyancy_rapier::Outcome;
use common::{DT, Pool};
use rapier3d::prelude::*;

/// Each outcome, with what it does to the adapter's share of the body's force.
#[test]
fn report_outcome_follows_the_body() {
    let mut pool = Pool::new();
    let h = pool.half_density_cube(0.0);
    let report = *pool.water.report(h).unwrap();
    assert_eq!(report.outcome, Outcome::NotEvaluated);

    pool.run(1.0);
    let report = *pool.water.report(h).unwrap();
    assert_eq!(report.outcome, Outcome::Applied);
    assert!(report.buoyancy_force.y > 4000.0, "{report:?}");
    let held = pool.body(h).user_force();

    // Kinematic: nothing computed, the share left as it is.
    pool.world.bodies[h].set_body_type(RigidBodyType::KinematicPositionBased, true);
    pool.water.apply(&mut pool.world.bodies, DT);
    let report = *pool.water.report(h).unwrap();
    assert_eq!(report.outcome, Outcome::Inactive);
    assert_eq!(report.buoyancy_force.y, 0.0);
    assert_eq!(report.center_of_buoyancy, report.center_of_mass);
    pool.world.bodies[h].set_body_type(RigidBodyType::Dynamic, true);
    assert_eq!(pool.body(h).user_force(), held);

    // A NaN velocity: no force, the share taken back.
    pool.world.bodies[h].set_linvel(Vector::new(f32::NAN, 0.0, 0.0), true);
    pool.water.apply(&mut pool.world.bodies, DT);
    let report = *pool.water.report(h).unwrap();
    assert_eq!(report.outcome, Outcome::NotFinite);
    assert_eq!(report.buoyancy_force.y, 0.0);
    assert!(
        pool.body(h).user_force().length() < 1e-3,
        "{:?}",
        pool.body(h).user_force()
    );

    // Finite again: the whole share comes back.
    pool.world.bodies[h].set_linvel(Vector::ZERO, true);
    pool.water.apply(&mut pool.world.bodies, DT);
    assert_eq!(pool.water.report(h).unwrap().outcome, Outcome::Applied);
    assert!((pool.body(h).user_force().y - held.y).abs() < 0.01 * held.y);
}
