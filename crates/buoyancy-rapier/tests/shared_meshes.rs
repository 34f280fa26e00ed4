//! Bodies whose colliders share a rapier shape share one mesh, and so do shapes of their own
//! that give the same triangles.

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
    // A body of its own shape, the same size: the same triangles, the same mesh; another size,
    // a mesh of its own.
    let mut own = |half_height: f32, x: f32| {
        let (h, _) = world.insert(
            RigidBodyBuilder::dynamic().translation(Vector::new(x, 0.0, 0.0)),
            ColliderBuilder::cuboid(0.5, half_height, 0.5).density(500.0),
        );
        water
            .register(h, &world.bodies, &world.colliders, FloatOptions::default())
            .unwrap();
        h
    };
    let (other, taller) = (own(0.25, -2.0), own(0.3, -4.0));
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
    assert!(std::ptr::eq(mesh(&water, handles[0]), mesh(&water, other)));
    assert!(!std::ptr::eq(
        mesh(&water, handles[0]),
        mesh(&water, taller)
    ));
    // A box has the same triangles at any subdivisions: the same mesh. A ball of the same
    // radius on each body: one mesh per number of subdivisions.
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
        mesh(&water, handles[2])
    ));
    let mut ball = |subdivisions: u32| {
        let (h, _) = world.insert(
            RigidBodyBuilder::dynamic(),
            ColliderBuilder::ball(0.4).density(500.0),
        );
        let options = FloatOptions::default().subdivisions(subdivisions);
        water
            .register(h, &world.bodies, &world.colliders, options)
            .unwrap();
        h
    };
    let balls = [ball(16), ball(16), ball(24)];
    assert!(std::ptr::eq(mesh(&water, balls[0]), mesh(&water, balls[1])));
    assert!(!std::ptr::eq(
        mesh(&water, balls[0]),
        mesh(&water, balls[2])
    ));
    // They float alike: the same buoyancy at the same depth.
    water.apply(&mut world.bodies, world.integration_parameters.dt);
    let force = |h| water.report(h).unwrap().buoyancy_force;
    assert_eq!(force(handles[0]), force(handles[1]));
    assert!((force(handles[0]) - force(other)).norm() < 1e-9 * force(other).norm());
}
