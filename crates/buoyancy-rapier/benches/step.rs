//! One adapter step (buoyancy + damping for every body, forces applied) for 100 bunnies
//! (the procedural torus knot when the shared meshes are absent), in still water and on an
//! 8-component Airy sea (amplitudes 5 cm, wavelengths 3 to 14.9 m, eight directions), and
//! asleep in still water (each step the inputs of the last), serially and, with the `rayon`
//! feature, across threads:
//!
//! ```sh
//! cargo bench -p buoyancy-rapier --bench step
//! cargo bench -p buoyancy-rapier --bench step --features rayon
//! ```

use std::sync::Arc;

use buoyancy_core::nalgebra::{Point3, Vector3 as NVector3};
use buoyancy_core::water::{AiryComponent, AiryWaves};
use buoyancy_core::{Mesh, mesh::primitives};
use buoyancy_rapier::{FloatOptions, FloatingBodies};
use criterion::{Criterion, criterion_group, criterion_main};
use rapier3d::prelude::*;

/// The bunny (the procedural torus knot when the sample meshes are absent, saying so; under
/// `CI=true` their absence fails), scaled to a bounding radius of 0.3 m about its centroid.
fn bunny() -> (String, Mesh<f64>) {
    // A file that exists but does not load fails the benchmark.
    let loaded = buoyancy_samples::mesh_or_fallback(Some("bunny.obj"), "the procedural torus knot")
        .map(|p| {
            buoyancy_core::io::load::<f64>(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
        });
    let (name, (v, t)) = match loaded {
        Some(shape) => ("bunny".to_string(), shape),
        None => (
            "torus knot".to_string(),
            primitives::torus_knot::<f64>(2, 3, 1.0, 0.3, 256, 16).unwrap(),
        ),
    };
    let mesh = Mesh::new(v, t).unwrap();
    let (c, k) = (mesh.centroid(), 0.3 / mesh.bounding_radius());
    let v = (0..mesh.vertex_count())
        .map(|i| Point3::from((mesh.vertex(i) - c) * k))
        .collect();
    (name, Mesh::new(v, mesh.triangles().to_vec()).unwrap())
}

fn step(c: &mut Criterion) {
    let (name, mesh) = bunny();
    let mut world = PhysicsWorld::default();
    let mut water = FloatingBodies::new(world.gravity).unwrap();
    let vertices: Vec<Vector> = (0..mesh.vertex_count())
        .map(|i| {
            let p = mesh.vertex(i);
            Vector::new(p.x as f32, p.y as f32, p.z as f32)
        })
        .collect();
    let shape = SharedShape::trimesh(vertices, mesh.triangles().to_vec()).unwrap();
    for i in 0..100 {
        // Half-submerged, tilted and moving: every body has waterline triangles to clip and drag.
        let pose = Pose::from_parts(
            Vector::new(
                (i % 10) as f32,
                -0.05 + 0.01 * (i % 7) as f32,
                (i / 10) as f32,
            ),
            Rotation::from_scaled_axis(Vector::new(0.1 * (i % 5) as f32, 0.3, 0.0)),
        );
        let body = RigidBodyBuilder::dynamic()
            .pose(pose)
            .linvel(Vector::new(0.2, -0.5, 0.1))
            .angvel(Vector::new(0.3, 0.0, -0.2));
        // One shape for every body, as a scene of many copies has: one mesh for all.
        let collider = ColliderBuilder::new(shape.clone()).density(500.0);
        let (h, _) = world.insert(body, collider);
        water
            .register(h, &world.bodies, &world.colliders, FloatOptions::default())
            .unwrap();
    }
    let mode = if cfg!(feature = "rayon") {
        "rayon"
    } else {
        "serial"
    };
    let id = format!(
        "adapter step, 100 × {name} ({} triangles), {mode}",
        mesh.triangle_count()
    );
    let dt = world.integration_parameters.dt;
    // Moving bodies: each step sees a velocity other than the last step's (a nudge of
    // 10⁻⁶ m/s, back and forth), as in a simulation, so that no evaluation is taken again.
    let mut parity = 0.0;
    let mut moving_step = |world: &mut PhysicsWorld, water: &mut FloatingBodies| {
        parity = 1.0 - parity;
        for (_, body) in world.bodies.iter_mut() {
            body.set_linvel(Vector::new(0.2 + 1e-6 * parity, -0.5, 0.1), false);
        }
        water.apply(&mut world.bodies, dt);
    };
    c.bench_function(&id, |b| b.iter(|| moving_step(&mut world, &mut water)));
    // The same bodies on a sea of 8 components, its time advancing with every step.
    let sea = AiryWaves::new(
        (0..8)
            .map(|i| AiryComponent {
                amplitude: 0.05,
                wavelength: 3.0 + 1.7 * i as f64,
                direction: NVector3::new((i as f64).cos(), 0.0, (i as f64).sin()),
                phase: 0.7 * i as f64,
            })
            .collect(),
        None,
    )
    .unwrap();
    water.set_surface(Some(Arc::new(sea)));
    let id = format!(
        "adapter step on 8 Airy components, 100 × {name} ({} triangles), {mode}",
        mesh.triangle_count()
    );
    c.bench_function(&id, |b| b.iter(|| moving_step(&mut world, &mut water)));
    // The same bodies asleep in still water: the engine holds their poses, and each step finds
    // the inputs of the last one.
    water.set_surface(None);
    for (_, body) in world.bodies.iter_mut() {
        body.sleep();
    }
    let id = format!(
        "adapter step asleep in still water, 100 × {name} ({} triangles), {mode}",
        mesh.triangle_count()
    );
    c.bench_function(&id, |b| b.iter(|| water.apply(&mut world.bodies, dt)));
}

criterion_group!(benches, step);
criterion_main!(benches);
