//! Bodies of several parts (colliders, compound shapes): each collider floats once, and the
//! angular damping is the whole body's.

mod common;

use buoyancy_core::DampingCoefficients;
use buoyancy_rapier::FloatOptions;
use common::{DT, Pool};
use rapier3d::prelude::*;

/// A collider listed twice in `FloatOptions::colliders` floats once.
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

/// The angular damping is the whole body's (total volume and wetted fraction): a cube split
/// into 8 parts is damped like the cube.
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

/// A body registered with parts of its own (not its colliders) floats with them: a 1 m cube of
/// 500 kg given as one part floats half submerged, as its cuboid collider would; no part, or a
/// body the set does not hold, is an error.
#[test]
fn explicit_parts_float_instead_of_the_colliders() {
    use buoyancy_core::controller::Part;
    use buoyancy_core::{Mesh, Pose, mesh::primitives};
    use std::sync::Arc;

    let mut pool = Pool::new();
    // A ball collider of the cube's mass: only the given cube floats.
    let (h, _) = pool.world.insert(
        RigidBodyBuilder::dynamic().can_sleep(false),
        ColliderBuilder::ball(0.5).mass(500.0),
    );
    let (v, t) = primitives::cube::<f64>(1).unwrap();
    let part = Part {
        mesh: Arc::new(Mesh::new(v, t).unwrap()),
        shape_to_body: Pose::identity(),
    };
    pool.water
        .register_parts(h, &pool.world.bodies, vec![part], FloatOptions::default())
        .unwrap();
    pool.run(20.0);
    pool.assert_equilibrium(h, 1.0, "cube given as a part");
    let report = pool.water.report(h).unwrap();
    assert!(
        (report.submerged_volume - 0.5).abs() < 2e-3,
        "{}",
        report.submerged_volume
    );
    assert_eq!(
        pool.water
            .register_parts(h, &pool.world.bodies, vec![], FloatOptions::default())
            .unwrap_err(),
        buoyancy_rapier::Error::NothingToFloat(h)
    );
    let gone = RigidBodyHandle::from_raw_parts(99, 0);
    assert_eq!(
        pool.water
            .register_parts(gone, &pool.world.bodies, vec![], FloatOptions::default())
            .unwrap_err(),
        buoyancy_rapier::Error::UnknownBody(gone)
    );
}
