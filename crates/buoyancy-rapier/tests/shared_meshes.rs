//! Bodies whose colliders share a rapier shape share one mesh.

use buoyancy_rapier::{FloatOptions, FloatingBodies};
use rapier3d::prelude::*;

#[test]
fn bodies_of_one_shape_share_its_mesh() {
    let mut world = PhysicsWorld::default();
    let mut water = FloatingBodies::new(world.gravity).unwrap();
    let shape = SharedShape::cuboid(0.5, 0.25, 0.5);
    let mut handles = Vec::new();
    for i in 0..3 {
        let (h, _) = world.insert(
            RigidBodyBuilder::dynamic().translation(Vector::new(2.0 * i as f32, 0.0, 0.0)),
            ColliderBuilder::new(shape.clone()).density(500.0),
        );
        water
            .register(h, &world.bodies, &world.colliders, FloatOptions::default())
            .unwrap();
        handles.push(h);
    }
    // A body of its own shape, the same size: a mesh of its own.
    let (other, _) = world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(-2.0, 0.0, 0.0)),
        ColliderBuilder::cuboid(0.5, 0.25, 0.5).density(500.0),
    );
    water
        .register(
            other,
            &world.bodies,
            &world.colliders,
            FloatOptions::default(),
        )
        .unwrap();
    fn mesh(water: &FloatingBodies, h: RigidBodyHandle) -> *const buoyancy_core::Mesh<f64> {
        water.meshes(h).next().unwrap().0
    }
    assert!(std::ptr::eq(
        mesh(&water, handles[0]),
        mesh(&water, handles[1])
    ));
    assert!(std::ptr::eq(
        mesh(&water, handles[0]),
        mesh(&water, handles[2])
    ));
    assert!(!std::ptr::eq(mesh(&water, handles[0]), mesh(&water, other)));
    // Other subdivisions make another mesh of the same shape.
    water
        .register(
            handles[2],
            &world.bodies,
            &world.colliders,
            FloatOptions::default().subdivisions(8),
        )
        .unwrap();
    assert!(std::ptr::eq(
        mesh(&water, handles[0]),
        mesh(&water, handles[1])
    ));
    assert!(!std::ptr::eq(
        mesh(&water, handles[0]),
        mesh(&water, handles[2])
    ));
    // They float alike: the same buoyancy at the same depth.
    water.apply(&mut world.bodies, world.integration_parameters.dt);
    let force = |h| water.report(h).unwrap().buoyancy_force;
    assert_eq!(force(handles[0]), force(handles[1]));
    assert!((force(handles[0]) - force(other)).norm() < 1e-9 * force(other).norm());
}
