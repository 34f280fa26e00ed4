//! Fuzzing of the constructor and the evaluation with arbitrary input: whatever comes in,
//! `Mesh::new` returns a mesh or a typed error, and a query returns finite numbers or a typed
//! error; nothing panics and nothing non-finite is handed back.

mod common;

use buoyancy::nalgebra::{Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use buoyancy::{Mesh, Method, Pose, Water, shape};
use proptest::prelude::*;

fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => -2.0..2.0f64,
        1 => prop::num::f64::ANY,
        1 => prop_oneof![Just(0.0), Just(1e300), Just(-1e-300), Just(f64::MAX)],
    ]
}

fn check_query(mesh: &Mesh<f64>, pose: &Pose<f64>, water: &Water<f64>) {
    for method in Method::ALL {
        if let Ok(b) = mesh.buoyancy(pose, water, method) {
            let numbers = [b.submerged_volume]
                .into_iter()
                .chain(b.center_of_buoyancy.iter().copied())
                .chain(b.force.iter().copied())
                .chain(b.torque.iter().copied());
            for x in numbers {
                assert!(x.is_finite(), "{method}: {b:?}");
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Random soups of vertices and indices.
    #[test]
    fn arbitrary_soups(
        vertices in prop::collection::vec((coordinate(), coordinate(), coordinate()), 0..12),
        triangles in prop::collection::vec((0..14u32, 0..14u32, 0..14u32), 0..20),
        pose in (coordinate(), coordinate(), coordinate(), coordinate(), coordinate(), coordinate(), coordinate()),
    ) {
        let vertices: Vec<_> = vertices.into_iter().map(|(x, y, z)| Point3::new(x, y, z)).collect();
        let triangles: Vec<_> = triangles.into_iter().map(|(a, b, c)| [a, b, c]).collect();
        if let Ok(mesh) = Mesh::new(vertices, triangles) {
            assert!(mesh.volume().is_finite() && mesh.volume() > 0.0);
            let (tx, ty, tz, qx, qy, qz, qw) = pose;
            let q = UnitQuaternion::new_unchecked(Quaternion::new(qw, qx, qy, qz));
            let pose = Pose::from_parts(Translation3::new(tx, ty, tz), q);
            check_query(&mesh, &pose, &Water::default());
        }
    }

    /// Valid meshes with random vertex perturbations (possibly self-intersecting) at arbitrary
    /// poses in arbitrary water.
    #[test]
    fn perturbed_meshes_at_arbitrary_poses(
        noise in prop::collection::vec(-0.5..0.5f64, 3 * 26),
        pose in (coordinate(), coordinate(), coordinate(), coordinate(), coordinate(), coordinate(), coordinate()),
        normal in (coordinate(), coordinate(), coordinate()),
        level in coordinate(),
        density in prop_oneof![Just(1000.0), 1e-3..1e6f64],
    ) {
        let (v, t) = shape::cube::<f64>(2).unwrap();
        let v = v.iter().enumerate().map(|(i, p)| p + Vector3::new(noise[3 * i], noise[3 * i + 1], noise[3 * i + 2])).collect();
        let Ok(mesh) = Mesh::new(v, t) else { return Ok(()) };
        let Ok(water) = Water::new(density, 9.81, Vector3::new(normal.0, normal.1, normal.2), level) else { return Ok(()) };
        let (tx, ty, tz, qx, qy, qz, qw) = pose;
        let q = UnitQuaternion::new_unchecked(Quaternion::new(qw, qx, qy, qz));
        check_query(&mesh, &Pose::from_parts(Translation3::new(tx, ty, tz), q), &water);
    }
}
