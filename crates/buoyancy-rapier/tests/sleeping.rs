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

/// rapier puts a crate still heaving by millimetres to sleep (below 0.05 m/s for 0.5 s): asleep out
/// of balance, it is woken until it settles, and then sleeps at its draft.
#[test]
fn body_asleep_before_it_settles_is_woken_until_it_settles() {
    let mut pool = Pool::new();
    // 1.2 m × 0.5 m × 0.8 m, density 750: draft 0.375 m, its center 0.125 m below the surface.
    let (h, _) = pool.world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.175, 0.0)),
        ColliderBuilder::cuboid(0.6, 0.25, 0.4).density(750.0),
    );
    pool.water
        .register(
            h,
            &pool.world.bodies,
            &pool.world.colliders,
            FloatOptions::default(),
        )
        .unwrap();
    pool.run(40.0);
    assert!(pool.body(h).is_sleeping(), "the crate never fell asleep");
    let y = f64::from(pool.body(h).translation().y);
    assert!(
        (y + 0.125).abs() < 5e-4,
        "asleep with its center at {y} m, not −0.125 m"
    );
}

/// A box that the sea bed holds out of balance (its buoyancy short of its weight) is woken once
/// at most for each pose it falls asleep at: it still sleeps.
#[test]
fn body_held_out_of_balance_by_the_ground_still_sleeps() {
    let mut pool = Pool::new();
    // The sea bed 0.2 m down; a box 1 m × 0.5 m × 1 m of density 900 would draw 0.45 m.
    pool.world.insert(
        RigidBodyBuilder::fixed().translation(Vector::new(0.0, -0.7, 0.0)),
        ColliderBuilder::cuboid(5.0, 0.5, 5.0),
    );
    let (h, _) = pool.world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.1, 0.0)),
        ColliderBuilder::cuboid(0.5, 0.25, 0.5).density(900.0),
    );
    pool.water
        .register(
            h,
            &pool.world.bodies,
            &pool.world.colliders,
            FloatOptions::default(),
        )
        .unwrap();
    let mut wakes = 0;
    let mut was_sleeping = false;
    for _ in 0..(20.0 / common::DT) as usize {
        pool.step();
        let sleeping = pool.body(h).is_sleeping();
        if was_sleeping && !sleeping {
            wakes += 1;
        }
        was_sleeping = sleeping;
    }
    assert!(
        pool.body(h).is_sleeping(),
        "woken {wakes} times, awake at the end"
    );
    assert!(wakes <= 3, "woken {wakes} times on the sea bed");
    let bottom = f64::from(pool.body(h).translation().y) - 0.25;
    assert!((bottom + 0.2).abs() < 0.01, "its bottom at {bottom} m");
}
