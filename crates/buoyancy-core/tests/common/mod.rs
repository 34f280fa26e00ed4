//! Shared helpers of the integration tests: the test meshes, poses, and an independent
//! reference computation of buoyancy.
#![allow(dead_code)]

use std::sync::OnceLock;

use buoyancy_core::nalgebra::{Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::{Mesh, Pose, Water};

/// The sample meshes that exist, by file name, loaded once per test binary. Without their
/// folder, none (the tests run on the procedural meshes alone, saying so; under `CI=true` they
/// fail instead).
pub fn shared_meshes() -> &'static [(String, Mesh<f64>)] {
    static MESHES: OnceLock<Vec<(String, Mesh<f64>)>> = OnceLock::new();
    MESHES.get_or_init(|| {
        if buoyancy_samples::mesh_or_fallback(None, "the procedural meshes alone").is_none() {
            return Vec::new();
        }
        buoyancy_samples::obj_files()
            .into_iter()
            .map(|path| {
                let (v, t) = buoyancy_core::io::load::<f64>(&path).expect("parsable mesh");
                let name = path.file_name().unwrap().to_string_lossy().into_owned();
                let mesh = Mesh::new(v, t).unwrap_or_else(|e| panic!("{name}: {e}"));
                (name, mesh)
            })
            .collect()
    })
}

/// Procedural meshes, always available.
pub fn procedural_meshes() -> &'static [(String, Mesh<f64>)] {
    static MESHES: OnceLock<Vec<(String, Mesh<f64>)>> = OnceLock::new();
    MESHES.get_or_init(|| {
        use buoyancy_core::mesh::primitives;
        let build = |(v, t): primitives::Shape<f64>| Mesh::new(v, t).unwrap();
        vec![
            ("cube".into(), build(primitives::cube(3).unwrap())),
            (
                "sphere".into(),
                build(primitives::uv_sphere(1.0, 24, 16).unwrap()),
            ),
            (
                "torus".into(),
                build(primitives::torus(1.0, 0.4, 32, 16).unwrap()),
            ),
            (
                "torus knot".into(),
                build(primitives::torus_knot(2, 3, 1.0, 0.25, 80, 11).unwrap()),
            ),
        ]
    })
}

/// Every test mesh: the procedural ones and the shared ones that exist.
pub fn all_meshes() -> Vec<&'static (String, Mesh<f64>)> {
    procedural_meshes().iter().chain(shared_meshes()).collect()
}

/// A pose from a translation and three numbers in [0, 1) mapped uniformly onto rotations
/// (Shoemake's method).
pub fn pose(translation: Vector3<f64>, u: [f64; 3]) -> Pose<f64> {
    let tau = std::f64::consts::TAU;
    let (a, b) = ((1.0 - u[0]).sqrt(), u[0].sqrt());
    let q = Quaternion::new(
        b * (tau * u[2]).cos(),
        a * (tau * u[1]).sin(),
        a * (tau * u[1]).cos(),
        b * (tau * u[2]).sin(),
    );
    Pose::from_parts(
        Translation3::from(translation),
        UnitQuaternion::from_quaternion(q),
    )
}

/// A pose that puts the mesh centroid at signed height `height` (in units of the mesh's
/// bounding radius) above the water, at horizontal offset `offset`, rotated by `u`.
pub fn pose_at_height(
    mesh: &Mesh<f64>,
    water: &Water<f64>,
    height: f64,
    offset: Vector3<f64>,
    u: [f64; 3],
) -> Pose<f64> {
    let rotation = pose(Vector3::zeros(), u).rotation;
    let n = water.normal().into_inner();
    let horizontal = offset - n * n.dot(&offset);
    let target = n * (water.level() + height * mesh.bounding_radius()) + horizontal;
    let translation = target - rotation * mesh.centroid().coords;
    Pose::from_parts(Translation3::from(translation), rotation)
}

/// Buoyancy computed independently of the library: every triangle is moved to the world frame,
/// clipped against the half-space under the surface by Sutherland–Hodgman, fanned into
/// triangles, and summed as tetrahedra to a fixed point of the plane (the projection of the world
/// origin); force and torque are integrated with the edge-midpoint rule (exact for the quadratic
/// integrand of the moment).
pub struct Reference {
    pub volume: f64,
    pub center: Point3<f64>,
    pub force: Vector3<f64>,
    /// About the center of mass.
    pub torque: Vector3<f64>,
}

pub fn reference(mesh: &Mesh<f64>, pose: &Pose<f64>, water: &Water<f64>) -> Reference {
    let n = water.normal().into_inner();
    let weight = water.density() * water.gravity();
    let anchor = n * water.level();
    let com = pose * mesh.centroid();
    let (mut six_volume, mut moment24) = (0.0, Vector3::zeros());
    let (mut force, mut torque) = (Vector3::zeros(), Vector3::zeros());
    let height = |p: &Point3<f64>| n.dot(&p.coords) - water.level();
    let mut polygon = Vec::with_capacity(4);
    for t in mesh.triangles() {
        let p = t.map(|i| pose * mesh.vertex(i as usize));
        polygon.clear();
        for k in 0..3 {
            let (a, b) = (p[k], p[(k + 1) % 3]);
            let (ha, hb) = (height(&a), height(&b));
            if ha <= 0.0 {
                polygon.push(a);
            }
            if (ha < 0.0 && hb > 0.0) || (ha > 0.0 && hb < 0.0) {
                polygon.push(a + (b - a) * (ha / (ha - hb)));
            }
        }
        for k in 1..polygon.len().saturating_sub(1) {
            let q = [polygon[0], polygon[k], polygon[k + 1]];
            let r = q.map(|q| q.coords - anchor);
            let det = r[0].dot(&r[1].cross(&r[2]));
            six_volume += det;
            moment24 += (r[0] + r[1] + r[2]) * det;
            let area = (q[1] - q[0]).cross(&(q[2] - q[0])) / 2.0;
            for (a, b) in [(0, 1), (1, 2), (2, 0)] {
                let m = Point3::from((q[a].coords + q[b].coords) / 2.0);
                // dF = -p dA n̂ = ρ g h n̂ dA (h < 0 under water).
                let df = area * (weight * height(&m) / 3.0);
                force += df;
                torque += (m - com).cross(&df);
            }
        }
    }
    let volume = six_volume / 6.0;
    let center = if volume.abs() > 0.0 {
        Point3::from(anchor + moment24 / 24.0 / volume)
    } else {
        water.project(&com)
    };
    Reference {
        volume,
        center,
        force,
        torque,
    }
}

/// `|a − b| ≤ tol·scale`, with a message.
#[track_caller]
pub fn assert_close(what: &str, a: f64, b: f64, tol: f64, scale: f64) {
    assert!(
        (a - b).abs() <= tol * scale,
        "{what}: {a:e} vs {b:e}, difference {:e} > {tol:e} × {scale:e}",
        (a - b).abs()
    );
}

/// `|a − b| ≤ tol·scale` for vectors, with a message.
#[track_caller]
pub fn assert_close_v(what: &str, a: &Vector3<f64>, b: &Vector3<f64>, tol: f64, scale: f64) {
    assert!(
        (a - b).norm() <= tol * scale,
        "{what}: {a:?} vs {b:?}, difference {:e} > {tol:e} × {scale:e}",
        (a - b).norm()
    );
}
