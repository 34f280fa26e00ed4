//! `FloatingBodies::place_at_rest`: a body placed at its equilibrium stays there, and the
//! equilibrium is where the same body dropped into the water settles.

mod common;

use buoyancy_core::Error as CoreError;
use buoyancy_rapier::Error;
use common::Pool;
use rapier3d::prelude::*;

/// A box 2 × 0.5 × 1 m (x × y × z) of 400 kg/m³ with 30 kg more at (0.4, -0.1, 0.2) in its
/// frame: it floats heeled and trimmed.
fn loaded_box(pool: &mut Pool, start: Pose) -> RigidBodyHandle {
    let extra = MassProperties::new(Vector::new(0.4, -0.1, 0.2), 30.0, Vector::splat(0.5));
    pool.add(
        RigidBodyBuilder::dynamic()
            .pose(start)
            .additional_mass_properties(extra),
        ColliderBuilder::cuboid(1.0, 0.25, 0.5).density(400.0),
    )
}

fn start() -> Pose {
    Pose::from_parts(
        Vector::new(0.5, 1.5, -0.3),
        Rotation::from_rotation_x(0.3)
            * Rotation::from_rotation_z(-0.25)
            * Rotation::from_rotation_y(0.2),
    )
}

/// The world position of the body's center of mass and its up axis (the body's y), from its
/// pose (rapier updates its world center of mass at the next step).
fn attitude(rb: &RigidBody) -> (Vector, Vector) {
    let com = rb.position() * rb.mass_properties().local_mprops.local_com;
    (com, *rb.rotation() * Vector::Y)
}

#[test]
fn a_body_placed_at_rest_stays_there() {
    let mut pool = Pool::new();
    let h = loaded_box(&mut pool, start());
    let rest = pool
        .water
        .place_at_rest(h, &mut pool.world.bodies, &pool.world.colliders)
        .unwrap();
    let e = &rest.equilibrium;
    assert!(e.stable, "{e:?}");
    let (com, up) = attitude(pool.body(h));
    // The load off center tilts it at rest (its up axis about 3° from the vertical).
    let tilt = up.angle_between(Vector::Y).to_degrees();
    assert!(tilt > 1.0 && tilt < 10.0, "tilted {tilt}° at rest");
    pool.run(5.0);
    let (com_after, up_after) = attitude(pool.body(h));
    let moved = (com_after - com).length();
    let turned = up.angle_between(up_after).to_degrees();
    eprintln!("placed at rest: moved {moved:.2e} m and turned {turned:.2e}° in 5 s");
    assert!(moved < 2e-3, "the center of mass moved {moved} m in 5 s");
    assert!(turned < 0.2, "the body turned {turned}° in 5 s");
    let rb = pool.body(h);
    assert!(rb.linvel().length() < 1e-2 && rb.angvel().length() < 1e-2);
}

#[test]
fn the_rest_is_where_a_dropped_body_settles() {
    let mut dropped = Pool::new();
    let h = loaded_box(&mut dropped, start());
    dropped.run(40.0);
    dropped.assert_equilibrium(h, 2.0, "dropped box");
    let (com, up) = attitude(dropped.body(h));

    let mut placed = Pool::new();
    let p = loaded_box(&mut placed, start());
    placed
        .water
        .place_at_rest(p, &mut placed.world.bodies, &placed.world.colliders)
        .unwrap();
    let (com_rest, up_rest) = attitude(placed.body(p));
    let height = (com.y - com_rest.y).abs();
    let turned = up.angle_between(up_rest).to_degrees();
    eprintln!("dropped: settled {height:.2e} m and {turned:.2e}° from the rest");
    assert!(height < 1e-4, "settled {height} m from the rest height");
    assert!(turned < 0.3, "settled {turned}° from the rest attitude");
}

#[test]
fn unknown_and_sinking_bodies_are_errors() {
    let mut pool = Pool::new();
    let stone = pool.add(
        RigidBodyBuilder::dynamic(),
        ColliderBuilder::ball(0.5).density(2500.0),
    );
    let err = pool
        .water
        .place_at_rest(stone, &mut pool.world.bodies, &pool.world.colliders)
        .unwrap_err();
    assert!(
        matches!(err, Error::Core(CoreError::TooHeavyToFloat { .. })),
        "{err}"
    );
    let (loose, _) = pool.world.insert(
        RigidBodyBuilder::dynamic(),
        ColliderBuilder::ball(0.5).density(100.0),
    );
    assert!(matches!(
        pool.water
            .place_at_rest(loose, &mut pool.world.bodies, &pool.world.colliders),
        Err(Error::UnknownBody(h)) if h == loose
    ));
}
