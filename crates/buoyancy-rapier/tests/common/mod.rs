//! Shared helpers of the adapter's tests: a small world, settling, and the equilibrium checks.
#![allow(dead_code)]

use buoyancy_core::{Mesh, mesh::primitives};
use buoyancy_rapier::{FloatOptions, FloatingBodies};
use rapier3d::prelude::*;

/// The step of [`Pool`]'s world, s.
pub const DT: f32 = 1.0 / 60.0;

/// A rapier world (gravity −9.81 y, 60 Hz) with water at y = 0.
pub struct Pool {
    pub world: PhysicsWorld,
    pub water: FloatingBodies,
}

impl Pool {
    pub fn new() -> Self {
        let world = PhysicsWorld::default();
        let water = FloatingBodies::new(world.gravity).unwrap();
        Pool { world, water }
    }

    /// Adds a dynamic body that never sleeps, and makes it float.
    pub fn add(
        &mut self,
        body: RigidBodyBuilder,
        collider: impl Into<Collider>,
    ) -> RigidBodyHandle {
        self.add_with(body, collider, FloatOptions::default())
    }

    pub fn add_with(
        &mut self,
        body: RigidBodyBuilder,
        collider: impl Into<Collider>,
        options: FloatOptions,
    ) -> RigidBodyHandle {
        let (handle, _) = self.world.insert(body.can_sleep(false), collider);
        self.water
            .register(handle, &self.world.bodies, &self.world.colliders, options)
            .unwrap();
        handle
    }

    /// One step: buoyancy and damping, then rapier.
    pub fn step(&mut self) {
        self.water
            .apply(&mut self.world.bodies, self.world.integration_parameters.dt);
        self.world.step();
    }

    pub fn run(&mut self, seconds: f32) {
        let steps = (seconds / self.world.integration_parameters.dt).round() as usize;
        for _ in 0..steps {
            self.step();
        }
    }

    pub fn body(&self, h: RigidBodyHandle) -> &RigidBody {
        &self.world.bodies[h]
    }

    /// A 1 m cube of density 500 kg/m³ centered at height `y`: it floats half submerged, its
    /// center at the surface.
    pub fn half_density_cube(&mut self, y: f32) -> RigidBodyHandle {
        self.add(
            RigidBodyBuilder::dynamic().translation(Vector::new(0.0, y, 0.0)),
            ColliderBuilder::cuboid(0.5, 0.5, 0.5).density(500.0),
        )
    }

    /// The application's own force and torque on `h`: rapier's stored user force and torque
    /// minus what the adapter reports it applied.
    pub fn own_wrench(&self, h: RigidBodyHandle) -> (Vector, Vector) {
        let r = self.water.report(h).unwrap();
        let f = (r.buoyancy_force + r.damping_force).cast::<f32>();
        let t = (r.buoyancy_torque + r.damping_torque).cast::<f32>();
        let rb = self.body(h);
        (
            rb.user_force() - Vector::new(f.x, f.y, f.z),
            rb.user_torque() - Vector::new(t.x, t.y, t.z),
        )
    }

    /// Checks the equilibrium conditions: submerged volume = m/ρ within 0.5 %, the center of
    /// buoyancy on the vertical through the center of mass within 1 % of `size`, at rest.
    pub fn assert_equilibrium(&mut self, h: RigidBodyHandle, size: f64, what: &str) {
        self.water
            .apply(&mut self.world.bodies, self.world.integration_parameters.dt);
        let rb = &self.world.bodies[h];
        let report = *self.water.report(h).unwrap();
        let expected = rb.mass() as f64 / self.water.water().density();
        let volume_error = (report.submerged_volume - expected).abs() / expected;
        assert!(
            volume_error < 0.005,
            "{what}: submerged {} m³ vs m/ρ = {expected} m³ ({:.3} %)",
            report.submerged_volume,
            volume_error * 100.0
        );
        let up = self.water.water().normal().into_inner();
        let offset = report.center_of_buoyancy - report.center_of_mass;
        let horizontal = (offset - up * up.dot(&offset)).norm();
        assert!(
            horizontal <= 0.01 * size,
            "{what}: center of buoyancy {horizontal} m off the vertical through the center of mass (size {size} m)"
        );
        assert!(
            rb.linvel().length() < 0.02 && rb.angvel().length() < 0.02,
            "{what}: not at rest: v {:?} ω {:?}",
            rb.linvel(),
            rb.angvel()
        );
    }
}

/// The angle in degrees between the vertical and the body axis closest to it: 0 when some face
/// of a box is horizontal.
pub fn tilt_degrees(rb: &RigidBody) -> f32 {
    let r = rb.rotation();
    let cos = [Vector::X, Vector::Y, Vector::Z]
        .iter()
        .map(|a| (*r * *a).y.abs())
        .fold(0.0f32, f32::max);
    cos.min(1.0).acos().to_degrees()
}

/// A sample mesh scaled so that its bounding radius is `radius`, wound outward and centered on
/// its centroid, or the procedural torus knot (with a note) when the file is absent; under
/// `CI=true` a missing file fails the test.
#[track_caller]
pub fn model(file: &str, radius: f64) -> (String, Mesh<f64>) {
    // A file that exists but does not load fails the test.
    let loaded =
        buoyancy_samples::mesh_or_fallback(Some(file), "the procedural torus knot").map(|p| {
            buoyancy_core::io::load::<f64>(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
        });
    let (name, (v, t)) = match loaded {
        Some(shape) => (file.to_string(), shape),
        None => (
            "procedural torus knot".to_string(),
            primitives::torus_knot::<f64>(2, 3, 1.0, 0.3, 128, 12).unwrap(),
        ),
    };
    let mesh = Mesh::new(v, t).unwrap();
    let c = mesh.centroid();
    let k = radius / mesh.bounding_radius();
    let v = (0..mesh.vertex_count())
        .map(|i| buoyancy_core::nalgebra::Point3::from((mesh.vertex(i) - c) * k))
        .collect();
    (name, Mesh::new(v, mesh.triangles().to_vec()).unwrap())
}

/// A rapier trimesh collider of a mesh.
pub fn trimesh(mesh: &Mesh<f64>) -> ColliderBuilder {
    let v = (0..mesh.vertex_count())
        .map(|i| {
            let p = mesh.vertex(i);
            Vector::new(p.x as f32, p.y as f32, p.z as f32)
        })
        .collect();
    ColliderBuilder::trimesh(v, mesh.triangles().to_vec()).unwrap()
}
