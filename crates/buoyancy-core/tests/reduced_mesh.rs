//! The reduced meshes of the pressure drag: their shape against the full mesh's (area, volume,
//! the area-weighted normals of each octant), their damping against the full mesh's, the
//! controller's use of them, and the small meshes left as they are.

mod common;

use std::sync::Arc;

use buoyancy_core::controller::{
    BodyOptions, BodyState, Command, Controller, DampingResolution, Motion, Part,
};
use buoyancy_core::mesh::{MIN_REDUCED_TRIANGLES, ReducedMesh};
use buoyancy_core::nalgebra::{Matrix3, Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::{DampingCoefficients, Mesh, Pose, Water, mesh::primitives};

/// The meshes reduced here: a fine sphere, a fine torus, and the bunny when the samples exist.
fn meshes() -> Vec<(String, Mesh<f64>)> {
    let build = |(v, t): primitives::Shape<f64>| Mesh::new(v, t).unwrap();
    let mut meshes = vec![
        (
            "sphere".to_string(),
            build(primitives::uv_sphere(0.3, 64, 32).unwrap()),
        ),
        (
            "torus".to_string(),
            build(primitives::torus(1.0, 0.4, 128, 48).unwrap()),
        ),
    ];
    meshes.extend(
        common::shared_meshes()
            .iter()
            .filter(|(name, _)| name == "bunny.obj")
            .cloned(),
    );
    meshes
}

/// Area vectors `Σ A n̂` of the triangles in each octant about `center` (by triangle centroid).
fn octant_area_vectors(
    points: impl Fn(usize) -> Point3<f64>,
    triangles: &[[u32; 3]],
    center: &Point3<f64>,
) -> [Vector3<f64>; 8] {
    let mut sums = [Vector3::zeros(); 8];
    for t in triangles {
        let [a, b, c] = t.map(|k| points(k as usize));
        let centroid = (a.coords + b.coords + c.coords) / 3.0 - center.coords;
        let octant = (0..3).fold(0, |o, k| o | (usize::from(centroid[k] > 0.0) << k));
        sums[octant] += (b - a).cross(&(c - a)) * 0.5;
    }
    sums
}

/// Area, volume and the area-weighted normals of each octant within stated tolerances of the
/// full mesh's: the volume to 1e-9 (the copy is scaled to it), the area to 6 %, each octant's
/// area vector to 4 % of the mesh's area.
#[test]
fn the_reduced_mesh_keeps_the_shape() {
    for (name, mesh) in meshes() {
        for max_triangles in [384, 1024] {
            let reduced = ReducedMesh::new(&mesh, max_triangles)
                .unwrap_or_else(|| panic!("{name} at {max_triangles}: no reduction"));
            let (area, full_area) = (reduced.surface_area(), mesh.surface_area());
            assert!(
                reduced.triangle_count() <= max_triangles
                    && reduced.triangle_count() > max_triangles / 4,
                "{name}: {} triangles for {max_triangles}",
                reduced.triangle_count()
            );
            assert!(
                (area / full_area - 1.0).abs() < 0.06,
                "{name} at {max_triangles}: area {area} vs {full_area}"
            );
            assert!(
                (reduced.volume() / mesh.volume() - 1.0).abs() < 1e-9,
                "{name} at {max_triangles}: volume {} vs {}",
                reduced.volume(),
                mesh.volume()
            );
            assert!((reduced.area_scale() * area - full_area).abs() < 1e-12 * full_area);
            let center = mesh.centroid();
            let full = octant_area_vectors(|i| mesh.vertex(i), mesh.triangles(), &center);
            let coarse = octant_area_vectors(|i| reduced.vertex(i), reduced.triangles(), &center);
            for (octant, (f, c)) in full.iter().zip(&coarse).enumerate() {
                assert!(
                    (f - c).norm() < 0.04 * full_area,
                    "{name} at {max_triangles}, octant {octant}: {c:?} vs {f:?}"
                );
            }
            // The whole surface's area vectors cancel, as a closed mesh's do.
            let total: Vector3<f64> = coarse.iter().sum();
            assert!(total.norm() < 1e-12 * full_area, "{name}: {total:?}");
        }
    }
}

/// Poses half under water, tilted, and velocities of translation and rotation.
fn poses_and_motions() -> Vec<(Pose<f64>, Vector3<f64>, Vector3<f64>)> {
    let mut cases = Vec::new();
    for i in 0..24 {
        let f = i as f64;
        let pose = Pose::from_parts(
            Translation3::new(0.1 * f, -0.1 + 0.01 * (i % 7) as f64, -0.2 * f),
            UnitQuaternion::from_euler_angles(0.3 * (i % 5) as f64, 0.7 * f, -0.2 * (i % 3) as f64),
        );
        let v = Vector3::new(
            (0.9 * f).cos(),
            -0.8 + 0.1 * (i % 4) as f64,
            (1.3 * f).sin(),
        ) * 0.6;
        let w = Vector3::new(0.4 * (0.5 * f).sin(), 0.5 * (f * 1.1).cos(), -0.3);
        cases.push((pose, v, w));
    }
    cases
}

/// The damping over the reduced copy of at most 384 triangles: the force within 8 % of the full
/// mesh's, the torque within 5 % of `|F|·R` (`R` the bounding radius), the wetted area within
/// 6 %, at 24 poses half under water with translation and rotation, the meshes scaled to a
/// radius of 0.3 m.
#[test]
fn the_reduced_damping_is_close_to_the_full_damping() {
    let water = Water::default();
    let coefficients = DampingCoefficients::default();
    for (name, mesh) in meshes() {
        let k = 0.3 / mesh.bounding_radius();
        let c = mesh.centroid();
        let points = (0..mesh.vertex_count())
            .map(|i| Point3::from((mesh.vertex(i) - c) * k))
            .collect();
        let mesh = Mesh::new(points, mesh.triangles().to_vec()).unwrap();
        let reduced = ReducedMesh::new(&mesh, 384).unwrap();
        let radius = mesh.bounding_radius();
        let (mut worst_force, mut worst_torque) = (0.0f64, 0.0f64);
        for (pose, v, w) in poses_and_motions() {
            let full = mesh.damping(&pose, &v, &w, &water, &coefficients).unwrap();
            let coarse = mesh
                .reduced_damping(&reduced, &pose, &v, &w, &water, &coefficients)
                .unwrap();
            let scale = full.force.norm();
            assert!(scale > 0.0, "{name}: no drag at {pose:?}");
            worst_force = worst_force.max((coarse.force - full.force).norm() / scale);
            worst_torque =
                worst_torque.max((coarse.torque - full.torque).norm() / (scale * radius));
            assert_eq!(coarse.torque_point, full.torque_point);
            assert!(
                (coarse.wetted_area / full.wetted_area - 1.0).abs() < 0.06,
                "{name}: wetted area {} vs {}",
                coarse.wetted_area,
                full.wetted_area
            );
        }
        assert!(
            worst_force < 0.08 && worst_torque < 0.05,
            "{name}: force off by {worst_force}, torque by {worst_torque} of |F|·R"
        );
    }
}

/// A mesh of no more triangles than asked for is not reduced; nor is one asked for fewer than
/// the least, which counts as that; a thin tube that cells of the size asked for would
/// collapse keeps its full mesh.
#[test]
fn small_meshes_are_not_reduced() {
    let (v, t) = primitives::torus_knot::<f64>(2, 3, 1.0, 0.1, 256, 16).unwrap();
    let knot = Mesh::new(v, t).unwrap();
    assert!(ReducedMesh::new(&knot, 256).is_none());
    let (v, t) = primitives::cube::<f64>(1).unwrap();
    let cube = Mesh::new(v, t).unwrap();
    assert!(ReducedMesh::new(&cube, 0).is_none());
    assert!(ReducedMesh::new(&cube, 12).is_none());
    let (v, t) = primitives::uv_sphere::<f64>(1.0, 64, 32).unwrap();
    let sphere = Mesh::new(v, t).unwrap();
    assert!(ReducedMesh::new(&sphere, sphere.triangle_count()).is_none());
    let least = ReducedMesh::new(&sphere, 1).unwrap();
    assert!(least.triangle_count() <= MIN_REDUCED_TRIANGLES);
    // f32 meshes too, with finite damping.
    let (v, t) = primitives::uv_sphere::<f32>(1.0, 64, 32).unwrap();
    let sphere = Mesh::new(v, t).unwrap();
    let reduced = ReducedMesh::new(&sphere, 200).unwrap();
    let pose = Pose::from_parts(
        Translation3::new(0.0f32, -0.3, 0.0),
        UnitQuaternion::identity(),
    );
    let d = sphere
        .reduced_damping(
            &reduced,
            &pose,
            &Vector3::new(0.3, -1.0, 0.0),
            &Vector3::new(0.0, 0.5, 0.0),
            &Water::default(),
            &DampingCoefficients::default(),
        )
        .unwrap();
    assert!(d.force.y > 0.0 && d.force.iter().chain(d.torque.iter()).all(|x| x.is_finite()));
}

fn state(y: f64) -> BodyState {
    BodyState {
        pose: Pose::from_parts(
            Translation3::new(0.0, y, 0.0),
            UnitQuaternion::from_euler_angles(0.2, 0.1, 0.0),
        ),
        center_of_mass: Point3::new(0.0, y, 0.0),
        linear_velocity: Vector3::new(0.3, -0.5, 0.1),
        angular_velocity: Vector3::new(0.2, 0.0, -0.4),
        mass: 50.0,
        inverse_mass: Vector3::repeat(1.0 / 50.0),
        inverse_inertia: Matrix3::identity(),
        gravity_scale: 1.0,
        applied_force: Vector3::zeros(),
        applied_torque: Vector3::zeros(),
        motion: Motion::Dynamic,
        sleeping: false,
    }
}

/// One step's damping of a body in a controller at `resolution` (the controller's), with its
/// own `own` resolution if given.
fn step_damping(
    mesh: &Arc<Mesh<f64>>,
    resolution: DampingResolution,
    own: Option<DampingResolution>,
) -> (Vector3<f64>, Vector3<f64>) {
    let mut controller = Controller::default();
    controller.set_damping_resolution(resolution);
    let part = Part {
        mesh: mesh.clone(),
        shape_to_body: Pose::identity(),
    };
    let body = controller.add(vec![part], BodyOptions::default()).unwrap();
    controller.set_body_damping_resolution(body, own);
    let mut commands = [Command::default()];
    controller.step(&[state(-0.1)], 1.0 / 60.0, &mut commands);
    let report = controller.report(body).unwrap();
    (report.damping_force, report.damping_torque)
}

/// The controller integrates the drag of a small mesh over the mesh itself whatever the
/// resolution, and that of a large one over its reduced copy by default, exactly when asked.
#[test]
fn the_controller_reduces_large_meshes_only() {
    let (v, t) = primitives::cube::<f64>(2).unwrap();
    let cube = Arc::new(Mesh::new(v, t).unwrap());
    let full = step_damping(&cube, DampingResolution::Full, None);
    assert_eq!(full, step_damping(&cube, DampingResolution::DEFAULT, None));
    let (v, t) = primitives::uv_sphere::<f64>(0.5, 64, 32).unwrap();
    let sphere = Arc::new(Mesh::new(v, t).unwrap());
    let full = step_damping(&sphere, DampingResolution::Full, None);
    let reduced = step_damping(&sphere, DampingResolution::DEFAULT, None);
    assert_ne!(full, reduced);
    assert!(
        (full.0 - reduced.0).norm() < 0.05 * full.0.norm(),
        "{full:?} vs {reduced:?}"
    );
    // A body's own resolution wins over the controller's.
    assert_eq!(
        full,
        step_damping(
            &sphere,
            DampingResolution::DEFAULT,
            Some(DampingResolution::Full)
        )
    );
    assert_eq!(
        reduced,
        step_damping(
            &sphere,
            DampingResolution::Full,
            Some(DampingResolution::DEFAULT)
        )
    );
    let mut controller = Controller::default();
    assert_eq!(controller.damping_resolution(), DampingResolution::DEFAULT);
    assert_eq!(controller.body_damping_resolution(0), None);
    assert!(!controller.set_body_damping_resolution(0, None));
    let part = Part {
        mesh: sphere.clone(),
        shape_to_body: Pose::identity(),
    };
    controller.add(vec![part], BodyOptions::default()).unwrap();
    controller.set_damping_resolution(DampingResolution::Full);
    assert_eq!(
        controller.body_damping_resolution(0),
        Some(DampingResolution::Full)
    );
}
