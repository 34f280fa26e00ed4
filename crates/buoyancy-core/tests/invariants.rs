//! Invariants of the exact methods, property-tested over every test mesh (procedural, the
//! shared meshes when present, and random non-convex closed meshes), random poses and random
//! water planes of any orientation.
//!
//! Tolerances are relative to the mesh: volumes to its volume V, lengths to its bounding radius
//! R, forces to ρgV, torques to ρgVR.

mod common;

use buoyancy_core::nalgebra::{Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::query::Query;
use buoyancy_core::{Buoyancy, Mesh, Method, Pose, Traversal, Water, mesh::primitives};
use common::{all_meshes, assert_close, assert_close_v, pose, pose_at_height, reference};
use proptest::prelude::*;
use proptest::sample::Index;

/// Scales of a mesh in a given water: volume, length, force, torque, area.
struct Scales {
    volume: f64,
    length: f64,
    force: f64,
    torque: f64,
    area: f64,
}

fn scales(mesh: &Mesh<f64>, water: &Water<f64>) -> Scales {
    let weight = water.density() * water.gravity();
    Scales {
        area: mesh.surface_area(),
        volume: mesh.volume(),
        length: mesh.bounding_radius(),
        force: weight * mesh.volume(),
        torque: weight * mesh.volume() * mesh.bounding_radius(),
    }
}

#[track_caller]
fn assert_same(what: &str, a: &Buoyancy<f64>, b: &Buoyancy<f64>, s: &Scales, tol: f64) {
    assert_close(
        &format!("{what}: volume"),
        a.submerged_volume,
        b.submerged_volume,
        tol,
        s.volume,
    );
    assert_close_v(&format!("{what}: force"), &a.force, &b.force, tol, s.force);
    assert_close_v(
        &format!("{what}: torque"),
        &a.torque,
        &b.torque,
        tol,
        s.torque,
    );
    assert_close(
        &format!("{what}: wetted area"),
        a.wetted_area,
        b.wetted_area,
        tol,
        s.area,
    );
    if a.submerged_volume.abs() > 1e-9 * s.volume {
        // The center of a sliver is defined only up to round-off over its volume.
        let tol = tol * s.volume / a.submerged_volume.abs();
        assert_close_v(
            &format!("{what}: center"),
            &a.center_of_buoyancy.coords,
            &b.center_of_buoyancy.coords,
            tol,
            s.length,
        );
    }
}

/// The water upside down: what was above the surface is now below it.
fn flipped(water: &Water<f64>) -> Water<f64> {
    water
        .with_surface(-water.normal().into_inner(), -water.level())
        .unwrap()
}

/// The height of every vertex of triangle `t` above the surface, world frame, and its
/// corners there.
fn world_triangle(
    mesh: &Mesh<f64>,
    pose: &Pose<f64>,
    water: &Water<f64>,
    t: &[u32; 3],
) -> ([Point3<f64>; 3], [f64; 3]) {
    let p = t.map(|i| pose * mesh.vertex(i as usize));
    let n = water.normal().into_inner();
    (p, p.map(|p| n.dot(&p.coords) - water.level()))
}

/// The wetted area computed independently of the library: every triangle moved to the world
/// frame, clipped against the half-space under the surface by Sutherland–Hodgman (a vertex in
/// the surface is under water) and its polygon's area summed from its fan by square roots.
fn reference_wetted_area(mesh: &Mesh<f64>, pose: &Pose<f64>, water: &Water<f64>) -> f64 {
    let mut area = 0.0;
    let mut polygon = Vec::with_capacity(4);
    for t in mesh.triangles() {
        let (p, h) = world_triangle(mesh, pose, water, t);
        polygon.clear();
        for k in 0..3 {
            let j = (k + 1) % 3;
            if h[k] <= 0.0 {
                polygon.push(p[k]);
            }
            if (h[k] < 0.0 && h[j] > 0.0) || (h[k] > 0.0 && h[j] < 0.0) {
                polygon.push(p[k] + (p[j] - p[k]) * (h[k] / (h[k] - h[j])));
            }
        }
        for k in 1..polygon.len().saturating_sub(1) {
            let (a, b, c) = (polygon[0], polygon[k], polygon[k + 1]);
            area += (b - a).cross(&(c - a)).norm() / 2.0;
        }
    }
    area
}

/// The area of the triangles with no vertex above the surface (world frame): what `Fast` and
/// `FastSurface` count as wetted.
fn fully_submerged_area(mesh: &Mesh<f64>, pose: &Pose<f64>, water: &Water<f64>) -> f64 {
    mesh.triangles()
        .iter()
        .map(|t| world_triangle(mesh, pose, water, t))
        .filter(|(_, h)| h.iter().all(|h| *h <= 0.0))
        .map(|(p, _)| (p[1] - p[0]).cross(&(p[2] - p[0])).norm() / 2.0)
        .sum()
}

/// The wetted area of every method by every traversal lies between zero and the mesh's surface
/// area: the exact methods' (`Improved` included) is the clipped area, `Fast`'s and
/// `FastSurface`'s the area of the triangles entirely under water, never more.
fn check_wetted_area(name: &str, mesh: &Mesh<f64>, pose: &Pose<f64>, water: &Water<f64>) {
    let total = mesh.surface_area();
    let clipped = reference_wetted_area(mesh, pose, water);
    let full = fully_submerged_area(mesh, pose, water);
    assert!(
        full <= clipped + 1e-12 * total,
        "{name}: {full} > {clipped}"
    );
    for method in Method::ALL {
        for traversal in Traversal::ALL {
            let b = mesh
                .buoyancy(pose, water, Query::new(method).with_traversal(traversal))
                .unwrap();
            let what = format!("{name}, {method}, {traversal:?}: wetted area");
            assert!(
                b.wetted_area >= 0.0 && b.wetted_area <= total * (1.0 + 1e-12),
                "{what} {} of {total}",
                b.wetted_area
            );
            let expected = match method {
                Method::Fast | Method::FastSurface => full,
                Method::Improved | Method::Exact | Method::ExactSurface => clipped,
            };
            assert_close(&what, b.wetted_area, expected, 1e-12, total);
        }
    }
}

fn check_exact_invariants(name: &str, mesh: &Mesh<f64>, pose: &Pose<f64>, water: &Water<f64>) {
    let s = scales(mesh, water);
    let exact = mesh.buoyancy(pose, water, Method::Exact).unwrap();
    let surface = mesh.buoyancy(pose, water, Method::ExactSurface).unwrap();

    // Exact = Exact Surface for a flat plane.
    assert_same(
        &format!("{name}: exact vs exact surface"),
        &exact,
        &surface,
        &s,
        1e-12,
    );
    assert_eq!(exact.fully_submerged, surface.fully_submerged);
    assert_eq!(exact.partially_submerged, surface.partially_submerged);

    // Against the independent clip.
    let area = reference_wetted_area(mesh, pose, water);
    for b in [&exact, &surface] {
        assert_close(
            &format!("{name}: wetted area vs reference"),
            b.wetted_area,
            area,
            1e-12,
            s.area,
        );
    }
    let r = reference(mesh, pose, water);
    assert_close(
        &format!("{name}: volume vs reference"),
        exact.submerged_volume,
        r.volume,
        1e-12,
        s.volume,
    );
    assert_close_v(
        &format!("{name}: force vs reference"),
        &surface.force,
        &r.force,
        1e-12,
        s.force,
    );
    assert_close_v(
        &format!("{name}: torque vs reference"),
        &surface.torque,
        &r.torque,
        1e-12,
        s.torque,
    );
    assert_close_v(
        &format!("{name}: torque vs reference"),
        &exact.torque,
        &r.torque,
        1e-12,
        s.torque,
    );
    if r.volume > 1e-9 * s.volume {
        let tol = 1e-12 * s.volume / r.volume;
        assert_close_v(
            &format!("{name}: center vs reference"),
            &exact.center_of_buoyancy.coords,
            &r.center.coords,
            tol,
            s.length,
        );
    }

    // Below + above = whole, for volume and first moment.
    let above = mesh.buoyancy(pose, &flipped(water), Method::Exact).unwrap();
    assert_close(
        &format!("{name}: V below + V above"),
        exact.submerged_volume + above.submerged_volume,
        mesh.volume(),
        1e-12,
        s.volume,
    );
    // Every triangle is wetted below or above but for the pieces cut off, and no triangle lies
    // in a random plane.
    assert_close(
        &format!("{name}: wetted area below + above"),
        exact.wetted_area + above.wetted_area,
        mesh.surface_area(),
        1e-12,
        s.area,
    );
    let com = pose * mesh.centroid();
    let moments = (exact.center_of_buoyancy - com) * exact.submerged_volume
        + (above.center_of_buoyancy - com) * above.submerged_volume;
    assert_close_v(
        &format!("{name}: V_b·C_b + V_a·C_a"),
        &moments,
        &Vector3::zeros(),
        1e-12,
        s.volume * s.length,
    );
}

/// A star-shaped, non-convex closed mesh: a UV sphere whose vertices are moved to the given radii.
fn star_mesh(radii: &[f64]) -> Mesh<f64> {
    let (v, t) = primitives::uv_sphere::<f64>(1.0, 12, 8).unwrap();
    assert_eq!(v.len(), radii.len());
    let v = v.iter().zip(radii).map(|(p, r)| p * *r).collect();
    Mesh::new(v, t).unwrap()
}

fn uniform3(lo: f64, hi: f64) -> impl Strategy<Value = [f64; 3]> {
    (lo..hi, lo..hi, lo..hi).prop_map(|(a, b, c)| [a, b, c])
}

/// Three numbers in [0, 1), for [`pose`]'s uniform rotations.
fn unit3() -> impl Strategy<Value = [f64; 3]> {
    uniform3(0.0, 1.0)
}

fn water_strategy() -> impl Strategy<Value = Water<f64>> {
    (500.0..1500.0f64, 1.0..20.0f64, unit3(), -3.0..3.0f64).prop_map(
        |(density, gravity, u, level)| {
            let normal = pose(Vector3::zeros(), u).rotation * Vector3::y();
            Water::new(density, gravity, normal, level).unwrap()
        },
    )
}

/// Heights of the centroid (in bounding radii) from fully under to fully above the surface.
fn height_strategy() -> impl Strategy<Value = f64> {
    prop_oneof![-1.3..1.3f64, Just(-1.5), Just(1.5)]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn exact_invariants_on_test_meshes(
        which in any::<Index>(),
        water in water_strategy(),
        height in height_strategy(),
        offset in uniform3(-2.0, 2.0),
        u in unit3(),
    ) {
        let meshes = all_meshes();
        let (name, mesh) = which.get(&meshes);
        let pose = pose_at_height(mesh, &water, height, Vector3::from(offset), u);
        check_exact_invariants(name, mesh, &pose, &water);
    }

    #[test]
    fn exact_invariants_on_random_star_meshes(
        radii in prop::collection::vec(0.3..1.7f64, 86),
        water in water_strategy(),
        height in height_strategy(),
        u in unit3(),
    ) {
        let mesh = star_mesh(&radii);
        let pose = pose_at_height(&mesh, &water, height, Vector3::zeros(), u);
        check_exact_invariants("star", &mesh, &pose, &water);
    }

    #[test]
    fn wetted_area_never_exceeds_the_surface_area(
        which in any::<Index>(),
        water in water_strategy(),
        height in height_strategy(),
        offset in uniform3(-2.0, 2.0),
        u in unit3(),
    ) {
        let meshes = all_meshes();
        let (name, mesh) = which.get(&meshes);
        let pose = pose_at_height(mesh, &water, height, Vector3::from(offset), u);
        check_wetted_area(name, mesh, &pose, &water);
    }

    #[test]
    fn wetted_area_never_exceeds_the_surface_area_of_star_meshes(
        radii in prop::collection::vec(0.3..1.7f64, 86),
        water in water_strategy(),
        height in height_strategy(),
        u in unit3(),
    ) {
        let mesh = star_mesh(&radii);
        let pose = pose_at_height(&mesh, &water, height, Vector3::zeros(), u);
        check_wetted_area("star", &mesh, &pose, &water);
    }

    #[test]
    fn all_methods_agree_when_fully_submerged(
        which in any::<Index>(),
        water in water_strategy(),
        depth in 1.01..5.0f64,
        u in unit3(),
    ) {
        let meshes = all_meshes();
        let (name, mesh) = which.get(&meshes);
        let s = scales(mesh, &water);
        let pose = pose_at_height(mesh, &water, -depth, Vector3::zeros(), u);
        let exact = mesh.buoyancy(&pose, &water, Method::Exact).unwrap();
        assert_close(name, exact.submerged_volume, mesh.volume(), 1e-12, s.volume);
        assert_close_v(name, &exact.center_of_buoyancy.coords, &(pose * mesh.centroid()).coords, 1e-12, s.length);
        for method in Method::ALL {
            let b = mesh.buoyancy(&pose, &water, method).unwrap();
            assert_same(&format!("{name}, {method}"), &b, &exact, &s, 1e-12);
            assert_eq!((b.fully_submerged, b.partially_submerged), (mesh.triangle_count(), 0));
            assert_close(&format!("{name}, {method}: wetted area"), b.wetted_area, mesh.surface_area(), 1e-12, s.area);
        }
    }

    /// Starting each triangle at another vertex changes nothing but round-off.
    #[test]
    fn cyclic_reordering_of_triangles_changes_nothing(
        which in any::<Index>(),
        shifts in prop::collection::vec(0..3usize, 64),
        water in water_strategy(),
        height in -1.0..1.0f64,
        u in unit3(),
    ) {
        let meshes = all_meshes();
        let (name, mesh) = which.get(&meshes);
        let vertices = (0..mesh.vertex_count()).map(|i| mesh.vertex(i)).collect();
        let triangles = mesh.triangles().iter().enumerate().map(|(i, t)| {
            let k = shifts[i % shifts.len()];
            [t[k], t[(k + 1) % 3], t[(k + 2) % 3]]
        }).collect();
        let reordered = Mesh::new(vertices, triangles).unwrap();
        let s = scales(mesh, &water);
        let pose = pose_at_height(mesh, &water, height, Vector3::zeros(), u);
        for method in Method::ALL {
            let a = mesh.buoyancy(&pose, &water, method).unwrap();
            let b = reordered.buoyancy(&pose, &water, method).unwrap();
            assert_same(&format!("{name}, {method}"), &a, &b, &s, 1e-12);
        }
    }

    /// A cube turned only about the vertical, or standing on a corner and turned about the
    /// vertical through it, is symmetric about that vertical: no torque at any depth.
    #[test]
    fn no_torque_on_a_symmetric_body_at_a_symmetric_pose(
        yaw in 0.0..std::f64::consts::TAU,
        height in -0.9..0.9f64,
        on_corner in any::<bool>(),
    ) {
        let (v, t) = primitives::cube::<f64>(5).unwrap();
        let mesh = Mesh::new(v, t).unwrap();
        let water = Water::default();
        let corner_up = if on_corner {
            UnitQuaternion::rotation_between(&Vector3::new(1.0, 1.0, 1.0), &Vector3::y()).unwrap()
        } else {
            UnitQuaternion::identity()
        };
        let rotation = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), yaw) * corner_up;
        let pose = Pose::from_parts(Translation3::new(0.3, height, -0.7), rotation);
        let s = scales(&mesh, &water);
        for method in Method::ALL {
            let b = mesh.buoyancy(&pose, &water, method).unwrap();
            assert_close_v(&format!("{method} torque"), &b.torque, &Vector3::zeros(), 1e-12, s.torque);
            assert_close(&format!("{method} center x"), b.center_of_buoyancy.x, 0.3, 1e-12, 1.0);
            assert_close(&format!("{method} center z"), b.center_of_buoyancy.z, -0.7, 1e-12, 1.0);
        }
    }

    /// Moving body and water 10⁶ m away together changes the answer by at most 1e-9 relative.
    #[test]
    fn far_from_the_origin(
        which in any::<Index>(),
        water in water_strategy(),
        height in -1.2..1.2f64,
        u in unit3(),
        far in uniform3(-1.0, 1.0),
    ) {
        let meshes = all_meshes();
        let (name, mesh) = which.get(&meshes);
        let near = pose_at_height(mesh, &water, height, Vector3::zeros(), u);
        let shift = Vector3::from(far).normalize() * 1e6;
        let far_pose = Pose::from_parts(Translation3::from(near.translation.vector + shift), near.rotation);
        let far_water = water.with_surface(water.normal().into_inner(), water.level() + water.normal().dot(&shift)).unwrap();
        let s = scales(mesh, &water);
        for method in [Method::Exact, Method::ExactSurface] {
            let a = mesh.buoyancy(&near, &water, method).unwrap();
            let mut b = mesh.buoyancy(&far_pose, &far_water, method).unwrap();
            b.center_of_buoyancy -= shift;
            b.torque_point -= shift;
            assert_same(&format!("{name}, {method}, 1e6 m away"), &a, &b, &s, 1e-9);
        }
    }

    /// The same body at 10⁻⁶ and 10⁶ times the size: volume scales by s³, lengths by s,
    /// forces by s³, torques by s⁴, to round-off.
    #[test]
    fn tiny_and_huge_bodies(
        which in any::<Index>(),
        height in -1.2..1.2f64,
        u in unit3(),
        exponent in prop_oneof![Just(-6i32), Just(6i32), -3..3i32],
    ) {
        let meshes = all_meshes();
        let (name, mesh) = which.get(&meshes);
        let scale = 10f64.powi(exponent);
        let scaled = Mesh::new((0..mesh.vertex_count()).map(|i| mesh.vertex(i) * scale).collect(), mesh.triangles().to_vec()).unwrap();
        let water = Water::default();
        let pose_unit = pose_at_height(mesh, &water, height, Vector3::zeros(), u);
        let pose_scaled = pose_at_height(&scaled, &water, height, Vector3::zeros(), u);
        let s = scales(mesh, &water);
        for method in Method::ALL {
            let a = mesh.buoyancy(&pose_unit, &water, method).unwrap();
            let b = scaled.buoyancy(&pose_scaled, &water, method).unwrap();
            let back = Buoyancy {
                submerged_volume: b.submerged_volume / scale.powi(3),
                center_of_buoyancy: b.center_of_buoyancy / scale,
                force: b.force / scale.powi(3),
                torque: b.torque / scale.powi(4),
                torque_point: b.torque_point / scale,
                wetted_area: b.wetted_area / scale.powi(2),
                ..b
            };
            assert_same(&format!("{name}, {method}, ×{scale:e}"), &a, &back, &s, 1e-11);
            assert_eq!((a.fully_submerged, a.partially_submerged), (b.fully_submerged, b.partially_submerged));
        }
    }
}

/// The hierarchy walk gives the scan's result to round-off (1e-10 relative), for every mesh,
/// random poses and water, from fully under to fully above the surface.
fn check_strategies(name: &str, mesh: &Mesh<f64>, pose: &Pose<f64>, water: &Water<f64>) {
    let s = scales(mesh, water);
    for method in Method::ALL {
        let scan = mesh
            .buoyancy(
                pose,
                water,
                Query::new(method).with_traversal(Traversal::Scan),
            )
            .unwrap();
        let walk = mesh
            .buoyancy(
                pose,
                water,
                Query::new(method).with_traversal(Traversal::Hierarchy),
            )
            .unwrap();
        assert_same(
            &format!("{name}, {method}, hierarchy vs scan"),
            &walk,
            &scan,
            &s,
            1e-10,
        );
        assert_eq!(
            (walk.fully_submerged, walk.partially_submerged),
            (scan.fully_submerged, scan.partially_submerged),
            "{name}, {method}"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn hierarchy_equals_scan(
        which in any::<Index>(),
        water in water_strategy(),
        height in height_strategy(),
        offset in uniform3(-2.0, 2.0),
        u in unit3(),
    ) {
        let meshes = all_meshes();
        let (name, mesh) = which.get(&meshes);
        let pose = pose_at_height(mesh, &water, height, Vector3::from(offset), u);
        check_strategies(name, mesh, &pose, &water);
    }

    /// Axis-aligned bodies with whole rows of vertices in the surface.
    #[test]
    fn hierarchy_equals_scan_with_vertices_on_the_surface(row in 0..=8usize, yaw_quarter in 0..4u32) {
        let (v, t) = primitives::cube::<f64>(8).unwrap();
        let mesh = Mesh::new(v, t).unwrap();
        let h = 0.5 - row as f64 / 8.0;
        let rotation = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), std::f64::consts::FRAC_PI_2 * yaw_quarter as f64);
        let pose = Pose::from_parts(Translation3::new(0.0, h, 0.0), rotation);
        check_strategies("cube 8", &mesh, &pose, &Water::default());
    }
}

/// Vertex rows lying exactly in the surface: the exact methods stay on the analytic curve.
#[test]
fn vertices_exactly_on_the_surface() {
    let (v, t) = primitives::cube::<f64>(4).unwrap();
    let mesh = Mesh::new(v, t).unwrap();
    let water = Water::new(1.0, 1.0, Vector3::y(), 0.0).unwrap();
    for k in 0..=4 {
        let h = 0.5 - k as f64 / 4.0;
        let pose = Pose::from_parts(Translation3::new(0.0, h, 0.0), UnitQuaternion::identity());
        for method in [Method::Exact, Method::ExactSurface] {
            let b = mesh.buoyancy(&pose, &water, method).unwrap();
            assert_close(
                &format!("{method}, h = {h}"),
                b.force.y,
                0.5 - h,
                1e-14,
                1.0,
            );
            let center = if h < 0.5 { (h - 0.5) / 2.0 } else { 0.0 };
            assert!(
                (b.center_of_buoyancy - Point3::new(0.0, center, 0.0)).norm() < 1e-14,
                "{method}, h = {h}: {b:?}"
            );
        }
    }
}

/// With rayon, the parallel result is bit-identical to the serial one, for every traversal.
#[cfg(feature = "rayon")]
#[test]
fn parallel_equals_serial() {
    // 105,340 triangles: the scan has 26 chunks, and the hierarchy's root is split in parallel
    // (from 100,000 triangles).
    let (v, t) = primitives::uv_sphere::<f64>(1.0, 230, 230).unwrap();
    let mesh = Mesh::new(v, t).unwrap();
    let water = Water::default();
    for (i, h) in [-1.2, -0.6, 0.0, 0.37, 0.9].into_iter().enumerate() {
        let p = pose(Vector3::new(0.1, h, 0.2), [0.1 * i as f64, 0.3, 0.7]);
        for method in Method::ALL {
            for traversal in [Traversal::Scan, Traversal::Hierarchy] {
                let serial = mesh
                    .buoyancy(&p, &water, Query::new(method).with_traversal(traversal))
                    .unwrap();
                for _ in 0..2 {
                    let parallel = mesh
                        .buoyancy(
                            &p,
                            &water,
                            Query::new(method).with_traversal(traversal).in_parallel(),
                        )
                        .unwrap();
                    assert_eq!(parallel, serial, "{method}, {traversal:?}, h = {h}");
                }
            }
            assert_eq!(
                mesh.buoyancy(&p, &water, Query::new(method).in_parallel())
                    .unwrap(),
                mesh.buoyancy(&p, &water, method).unwrap()
            );
        }
    }
}
