//! Regression tests of the adapter review: body type changes, the damping's stability scheme,
//! sleeping, rapier's NaN quarantine, compounds.

mod common;

use buoyancy_core::DampingCoefficients;
use buoyancy_core::nalgebra::{Isometry3, Vector3};
use buoyancy_rapier::FloatOptions;
use common::Pool;
use rapier3d::prelude::*;

const DT: f32 = 1.0 / 60.0;

/// A 1 m cube of density 500 kg/m³ (floats half submerged, center at the surface).
fn half_cube(pool: &mut Pool, y: f32) -> RigidBodyHandle {
    pool.add(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, y, 0.0)),
        ColliderBuilder::cuboid(0.5, 0.5, 0.5).density(500.0),
    )
}

/// The application's own force and torque on `h`: rapier's stored user force minus what the
/// adapter reports it applied.
fn own_wrench(pool: &Pool, h: RigidBodyHandle) -> (Vector, Vector) {
    let r = pool.water.report(h).unwrap();
    let f = (r.buoyancy_force + r.damping_force).cast::<f32>();
    let t = (r.buoyancy_torque + r.damping_torque).cast::<f32>();
    let rb = pool.body(h);
    (
        rb.user_force() - Vector::new(f.x, f.y, f.z),
        rb.user_torque() - Vector::new(t.x, t.y, t.z),
    )
}

/// Finding 1: dynamic → kinematic (or fixed) → dynamic must not double the buoyancy: rapier
/// ignores `add_force` on non-dynamic bodies but keeps their stored force.
#[test]
fn body_type_round_trip_keeps_one_buoyancy() {
    for other in [
        RigidBodyType::KinematicPositionBased,
        RigidBodyType::KinematicVelocityBased,
        RigidBodyType::Fixed,
    ] {
        let mut pool = Pool::new();
        let h = half_cube(&mut pool, 0.0);
        pool.run(3.0);
        pool.world.bodies[h].set_body_type(other, true);
        pool.run(0.5);
        pool.world.bodies[h].set_body_type(RigidBodyType::Dynamic, true);
        pool.water.apply(&mut pool.world.bodies, DT);
        let (own_force, own_torque) = own_wrench(&pool, h);
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

/// Finding 1, `unregister` of a body that is not dynamic: rapier ignores the `add_force` that
/// takes the adapter's share back, so the share must come off another way.
#[test]
fn unregister_while_kinematic_takes_the_share_off() {
    let mut pool = Pool::new();
    let h = half_cube(&mut pool, 0.0);
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

/// Finding 2: the stability scaling keeps the moment of the pressure drag and its line of
/// action (one factor for the force and the torque).
#[test]
fn damping_keeps_the_drag_moment_and_its_line_of_action() {
    let mut pool = Pool::new();
    let h = half_cube(&mut pool, 0.0);
    pool.world.bodies[h].set_linvel(Vector::new(2.0, 0.0, 0.0), true);
    pool.water.apply(&mut pool.world.bodies, DT);
    let r = *pool.water.report(h).unwrap();
    let (mesh, shape_to_body) = pool.water.meshes(h).next().unwrap();
    let pose =
        Isometry3::translation(0.0, pool.body(h).translation().y as f64, 0.0) * shape_to_body;
    let core = mesh
        .damping(
            &pose,
            &Vector3::new(2.0, 0.0, 0.0),
            &Vector3::zeros(),
            pool.water.water(),
            pool.water.damping(),
        )
        .unwrap();
    // Sideways drag on the wetted lower half of the front face: −2000 N, moment −500 N·m.
    assert!(
        (core.force.x + 2000.0).abs() < 1.0 && (core.torque.z + 500.0).abs() < 1.0,
        "{core:?}"
    );
    assert!(
        r.damping_torque.z < -0.8 * 500.0,
        "applied drag moment {:?}",
        r.damping_torque
    );
    let s = r.damping_force.x / core.force.x;
    assert!(s > 0.8 && s <= 1.0 + 1e-9, "scale {s}");
    assert!(
        (r.damping_torque - core.torque * s).norm() < 1e-6 * 500.0,
        "line of action moved: {:?} vs {:?}",
        r.damping_torque,
        core.torque * s
    );

    // Spinning without moving (at the floating height, so that buoyancy and weight cancel):
    // the drag force of the paddling faces is kept too.
    let mut pool = Pool::new();
    let h = half_cube(&mut pool, 0.0);
    pool.world.bodies[h].set_angvel(Vector::new(0.0, 0.0, 3.0), true);
    pool.water.apply(&mut pool.world.bodies, DT);
    let r = *pool.water.report(h).unwrap();
    let (mesh, shape_to_body) = pool.water.meshes(h).next().unwrap();
    let pose = Isometry3::translation(0.0, 0.0, 0.0) * shape_to_body;
    let core = mesh
        .damping(
            &pose,
            &Vector3::zeros(),
            &Vector3::new(0.0, 0.0, 3.0),
            pool.water.water(),
            pool.water.damping(),
        )
        .unwrap();
    assert!(core.force.norm() > 100.0, "{core:?}");
    let s = r.damping_torque.z / core.torque.z;
    assert!(s > 0.3 && s <= 1.0 + 1e-9, "scale {s}");
    assert!(
        (r.damping_force - core.force * s).norm() < 1e-6 * core.force.norm(),
        "drag force {:?} vs core {:?} × {s}",
        r.damping_force,
        core.force
    );
}

/// Finding 3: a light ball rises at the terminal velocity of the damping model, where the
/// drag balances the net buoyancy (not at the speed the step's buoyancy adds each step).
#[test]
fn light_ball_rises_at_the_model_terminal_velocity() {
    let mut pool = Pool::new();
    let h = pool.add(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, -200.0, 0.0)),
        ColliderBuilder::ball(0.05).density(10.0),
    );
    pool.run(2.0);
    let y0 = pool.body(h).translation().y;
    pool.run(2.0);
    let speed = (pool.body(h).translation().y - y0) as f64 / 2.0;

    // The model's terminal velocity: drag(v) = ρ g V − m g, the drag of the very mesh the adapter
    // floats with, deep under water.
    let (mesh, shape_to_body) = pool.water.meshes(h).next().unwrap();
    let water = *pool.water.water();
    let pose = Isometry3::translation(0.0, -100.0, 0.0) * shape_to_body;
    let drag = |v: f64| {
        mesh.damping(
            &pose,
            &Vector3::new(0.0, v, 0.0),
            &Vector3::zeros(),
            &water,
            pool.water.damping(),
        )
        .unwrap()
        .force
        .y
    };
    let net =
        water.specific_weight() * mesh.volume() - pool.body(h).mass() as f64 * water.gravity();
    assert!(net > 0.0);
    let (mut lo, mut hi) = (0.0, 100.0);
    for _ in 0..100 {
        let v = 0.5 * (lo + hi);
        if -drag(v) < net { lo = v } else { hi = v }
    }
    let terminal = lo;
    assert!(
        (terminal - 0.76).abs() < 0.05,
        "model terminal velocity {terminal}"
    );
    assert!(
        (speed - terminal).abs() < 0.03 * terminal,
        "rises at {speed} m/s, the model's terminal velocity is {terminal} m/s"
    );
}

/// Finding 5: a sleeping body wakes when the water changes slowly, step after step.
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

/// Finding 6: rapier's NaN quarantine zeroes the body's forces; the adapter must not then take
/// back a share that is no longer there.
#[test]
fn quarantined_body_gets_no_phantom_force() {
    let mut pool = Pool::new();
    let h = half_cube(&mut pool, 0.0);
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
    let (own_force, _) = own_wrench(&pool, h);
    assert!(own_force.length() < 1.0, "phantom force {own_force:?}");
    assert!(
        pool.body(h).translation().y.abs() < 0.02,
        "at {}",
        pool.body(h).translation().y
    );
}

/// Finding 9: a collider listed twice floats once.
#[test]
fn repeated_collider_floats_once() {
    let mut pool = Pool::new();
    let (h, c) = pool.world.insert(
        RigidBodyBuilder::dynamic(),
        ColliderBuilder::cuboid(0.5, 0.5, 0.5).density(500.0),
    );
    pool.water
        .register(
            h,
            &pool.world.bodies,
            &pool.world.colliders,
            FloatOptions::default().colliders([c, c]),
        )
        .unwrap();
    pool.water.apply(&mut pool.world.bodies, DT);
    assert_eq!(pool.water.meshes(h).count(), 1);
    let v = pool.water.report(h).unwrap().submerged_volume;
    assert!((v - 0.5).abs() < 1e-9, "submerged {v} m³");
}

/// Finding 9: the angular damping is the whole body's: a cube split into 8 parts is damped like
/// the cube.
#[test]
fn angular_damping_of_a_body_split_into_parts() {
    let angular_only = DampingCoefficients::new(0.0, 0.0, 0.1, 0.1).unwrap();
    let mut pool = Pool::new();
    pool.water.set_damping(angular_only);
    let omega = Vector::new(0.3, 1.0, -0.5);
    let whole = pool.add(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, -5.0, 0.0))
            .angvel(omega),
        ColliderBuilder::cuboid(0.5, 0.5, 0.5).density(1000.0),
    );
    let mut eighths = Vec::new();
    for i in 0..8 {
        let corner = |bit: i32| if i & bit == 0 { -0.25 } else { 0.25 };
        eighths.push((
            Pose::translation(corner(1), corner(2), corner(4)),
            SharedShape::cuboid(0.25, 0.25, 0.25),
        ));
    }
    let split = pool.add(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(5.0, -5.0, 0.0))
            .angvel(omega),
        ColliderBuilder::compound(eighths).density(1000.0),
    );
    pool.water.apply(&mut pool.world.bodies, DT);
    let (a, b) = (
        pool.water.report(whole).unwrap().damping_torque,
        pool.water.report(split).unwrap().damping_torque,
    );
    assert!(a.norm() > 10.0, "{a:?}");
    assert!(
        (a - b).norm() < 1e-4 * a.norm(),
        "whole cube {a:?}, split {b:?}"
    );
}
