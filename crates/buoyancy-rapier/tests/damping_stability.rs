//! The semi-implicit damping (crate docs, "Stability"): one factor on the whole damping wrench
//! when the other forces balance, the damping model's terminal velocity for a light body, and
//! no overshoot however stiff the damping, in each direction at its own rate.

mod common;

use buoyancy_core::DampingCoefficients;
use buoyancy_core::nalgebra::{Isometry3, Vector3};
use common::{DT, Pool};
use rapier3d::prelude::*;

/// The stability scaling keeps the moment of the pressure drag and its line of action: the
/// force and the torque are scaled by one factor, for a body moving sideways and for a body
/// spinning in place.
#[test]
fn damping_keeps_the_drag_moment_and_its_line_of_action() {
    let mut pool = Pool::new();
    let h = pool.half_density_cube(0.0);
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
    let h = pool.half_density_cube(0.0);
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

/// A light ball rises at the terminal velocity of the damping model, where the drag balances
/// the net buoyancy (not at the speed the step's buoyancy adds each step).
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

/// A neutrally buoyant cube under water, moving down fast, spinning fast, or both, with a huge
/// linear drag, a huge angular damping, or both: explicit, one step of drag would throw it
/// back; semi-implicit, it can at most stop. With both, the spin is 10⁴ times stiffer than the
/// sinking for the one rate of the whole wrench: each direction must be damped at its own rate.
#[test]
fn stiff_damping_does_not_overshoot() {
    for (linear_drag, angular_drag, linvel, angvel) in [
        (1e7, 0.0, -5.0, 0.0),
        (0.0, 1e5, 0.0, 4.0),
        (1e7, 1e5, -5.0, 4.0),
    ] {
        let mut pool = Pool::new();
        pool.water.set_damping(
            DampingCoefficients::default()
                .with_linear_drag(linear_drag)
                .and_then(|d| d.with_angular_drag(angular_drag, 0.1))
                .unwrap(),
        );
        let h = pool.add(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, -3.0, 0.0))
                .linvel(Vector::new(0.0, linvel, 0.0))
                .angvel(Vector::new(0.0, angvel, 0.0)),
            ColliderBuilder::cuboid(0.5, 0.5, 0.5).density(1000.0),
        );
        for step in 0..3 {
            pool.step();
            let rb = pool.body(h);
            let (v, w) = (rb.linvel().y, rb.angvel().y);
            assert!(
                linvel <= v && v <= 1e-6 && -1e-6 <= w && w <= angvel * 1.001,
                "drag {linear_drag:e}, angular {angular_drag:e}, step {step}: v {v}, ω {w}"
            );
        }
        let report = pool.water.report(h).unwrap();
        assert!(report.damping_force.iter().all(|c| c.is_finite()));
    }
}
