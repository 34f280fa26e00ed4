//! Sleeping bodies: woken when the adapter's force on them has changed enough since they were
//! last awake, so that slow changes add up.

mod common;

use buoyancy_core::nalgebra::Vector3;
use buoyancy_rapier::FloatOptions;
use common::Pool;
use rapier3d::prelude::*;

/// A sleeping cube wakes and follows water that rises by 0.5 mm per step, each step's change
/// far below the waking threshold.
#[test]
fn sleeping_body_wakes_for_a_slowly_rising_tide() {
    let mut pool = Pool::new();
    let (h, _) = pool.world.insert(
        RigidBodyBuilder::dynamic(),
        ColliderBuilder::cuboid(0.5, 0.5, 0.5).density(500.0),
    );
    pool.water
        .register(
            h,
            &pool.world.bodies,
            &pool.world.colliders,
            FloatOptions::default(),
        )
        .unwrap();
    pool.run(10.0);
    assert!(
        pool.body(h).is_sleeping(),
        "the cube should have fallen asleep"
    );
    let mut level = 0.0;
    for _ in 0..600 {
        level += 0.0005;
        let raised = pool
            .water
            .water()
            .with_surface(Vector3::y(), level)
            .unwrap();
        pool.water.set_water(raised);
        pool.step();
    }
    pool.run(5.0);
    let y = pool.body(h).translation().y as f64;
    assert!(
        (y - level).abs() < 0.02,
        "the cube is at {y} m, the water at {level} m"
    );
}
