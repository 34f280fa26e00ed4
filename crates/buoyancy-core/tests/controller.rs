//! The controller's bodies are independent: a body's command and report do not depend on which
//! other bodies the controller holds, nor on their order. With the `rayon` feature the bodies
//! are stepped in parallel, without it one after another; this file runs in both builds
//! (`scripts/test.sh` runs it with and without the features), so both paths are held to it.

use std::sync::Arc;

use buoyancy_core::controller::{BodyOptions, BodyState, Command, Controller, Motion, Part};
use buoyancy_core::nalgebra::{Matrix3, Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::{Mesh, Pose, mesh::primitives};

fn cube() -> Arc<Mesh<f64>> {
    let (v, t) = primitives::cube::<f64>(2).unwrap();
    Arc::new(Mesh::new(v, t).unwrap())
}

fn sphere() -> Arc<Mesh<f64>> {
    let (v, t) = primitives::uv_sphere::<f64>(0.6, 24, 12).unwrap();
    Arc::new(Mesh::new(v, t).unwrap())
}

/// Body `i` of a small fleet: a different pose, velocity and mass for each.
fn state(i: usize) -> BodyState {
    let x = i as f64;
    let mass = 300.0 + 40.0 * x;
    let pose = Pose::from_parts(
        Translation3::new(3.0 * x, 0.1 - 0.07 * x, -x),
        UnitQuaternion::from_euler_angles(0.2 * x, -0.1 * x, 0.3),
    );
    BodyState {
        pose,
        center_of_mass: Point3::new(3.0 * x, 0.1 - 0.07 * x, -x),
        linear_velocity: Vector3::new(0.1 * x, -0.3, 0.05),
        angular_velocity: Vector3::new(0.0, 0.2 * x, -0.1),
        mass,
        inverse_mass: Vector3::repeat(1.0 / mass),
        inverse_inertia: Matrix3::identity() * (6.0 / mass),
        gravity_scale: 1.0,
        applied_force: Vector3::zeros(),
        applied_torque: Vector3::zeros(),
        motion: if i == 3 {
            Motion::Inactive
        } else {
            Motion::Dynamic
        },
        sleeping: false,
    }
}

fn parts(i: usize) -> Vec<Part> {
    let mesh = if i.is_multiple_of(2) {
        cube()
    } else {
        sphere()
    };
    vec![Part {
        mesh,
        shape_to_body: Pose::identity(),
    }]
}

const FLEET: usize = 6;
const DT: f64 = 1.0 / 60.0;

#[test]
fn a_body_steps_as_it_would_alone() {
    let mut fleet = Controller::default();
    for i in 0..FLEET {
        fleet.add(parts(i), BodyOptions::default()).unwrap();
    }
    let states: Vec<BodyState> = (0..FLEET).map(state).collect();
    let mut commands = vec![Command::default(); FLEET];
    // Two steps, so that the second one's commands go through the books of the first.
    fleet.step(&states, DT, &mut commands);
    fleet.step(&states, DT, &mut commands);

    let mut floating = 0;
    for (i, (state, in_fleet)) in states.iter().zip(&commands).enumerate() {
        let mut alone = Controller::default();
        alone.add(parts(i), BodyOptions::default()).unwrap();
        let mut command = [Command::default()];
        alone.step(&[*state], DT, &mut command);
        alone.step(&[*state], DT, &mut command);
        assert_eq!(*in_fleet, command[0], "body {i}");
        assert_eq!(fleet.report(i), alone.report(0), "body {i}");
        if in_fleet.adds_anything() {
            floating += 1;
        }
    }
    // The first step adds the buoyancy; the second adds the difference, which is not zero for a
    // body whose forces the engine did not take (the states are not updated): every dynamic
    // body in the water must have a command, or the comparison above proves nothing.
    assert!(floating >= 4, "{floating} bodies with a command");
}

#[test]
fn the_order_of_the_bodies_does_not_matter() {
    let order: Vec<usize> = (0..FLEET).rev().collect();
    let mut forward = Controller::default();
    let mut backward = Controller::default();
    for (i, &j) in order.iter().enumerate() {
        forward.add(parts(i), BodyOptions::default()).unwrap();
        backward.add(parts(j), BodyOptions::default()).unwrap();
    }
    let states: Vec<BodyState> = (0..FLEET).map(state).collect();
    let reversed: Vec<BodyState> = order.iter().map(|&i| states[i]).collect();
    let mut a = vec![Command::default(); FLEET];
    let mut b = vec![Command::default(); FLEET];
    forward.step(&states, DT, &mut a);
    backward.step(&reversed, DT, &mut b);
    for (k, &i) in order.iter().enumerate() {
        assert_eq!(a[i], b[k], "body {i}");
    }
}
