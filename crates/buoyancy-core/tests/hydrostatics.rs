//! Hydrostatics against analytic values: the waterplane of boxes, a torus at its equator and a
//! tilted cube, the metacentre of a sphere, and the stiffness against finite differences of
//! `Mesh::buoyancy`.

mod common;

use std::f64::consts::PI;

use buoyancy_core::hydrostatics::{Hydrostatics, LoadingCondition, Waterplane};
use buoyancy_core::nalgebra::{Isometry3, Matrix3, Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::{Error, Mesh, Method, Pose, Water, mesh::primitives};

fn at(x: f64, y: f64, z: f64) -> Pose<f64> {
    Pose::from_parts(Translation3::new(x, y, z), UnitQuaternion::identity())
}

/// A box `length` (x) × `depth` (y, up) × `beam` (z) about the origin, each face split in
/// `n × n` squares: vertex rows at `y = depth·(k/n − 1/2)`.
fn block(length: f64, depth: f64, beam: f64, n: usize) -> Mesh<f64> {
    let (v, t) = primitives::cube(n).unwrap();
    Mesh::new(v, t)
        .unwrap()
        .scaled(&Vector3::new(length, depth, beam))
        .unwrap()
}

/// The pose that puts the bottom of a box of `depth` at `y = −draft`.
fn at_draft(depth: f64, draft: f64) -> Pose<f64> {
    at(0.0, depth / 2.0 - draft, 0.0)
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn cube_waterplane_is_a_positive_unit_square() {
    // The orientation of the segments: counter-clockwise seen from above, area +1.
    let cube = block(1.0, 1.0, 1.0, 1);
    let water = Water::default();
    for y in [-0.3, 0.0, 0.2] {
        let wp = cube.waterplane(&at(0.5, y, -2.0), &water).unwrap();
        assert!((wp.area - 1.0).abs() < 1e-14, "{y}: {}", wp.area);
        assert!((wp.center_of_flotation - Point3::new(0.5, 0.0, -2.0)).norm() < 1e-14);
        for k in 0..2 {
            assert!((wp.principal_moments[k] - 1.0 / 12.0).abs() < 1e-15);
        }
        // The basis: e₁ the body's x axis, e₂ = n × e₁ = −z.
        assert!((wp.axes[0].into_inner() - Vector3::x()).norm() < 1e-15);
        assert!((wp.axes[1].into_inner() + Vector3::z()).norm() < 1e-15);
    }
    // Upside down and with z up, still +1.
    let flipped = Pose::from_parts(
        Translation3::identity(),
        UnitQuaternion::from_scaled_axis(Vector3::x() * PI),
    );
    let wp = cube.waterplane(&flipped, &water).unwrap();
    assert!((wp.area - 1.0).abs() < 1e-14);
    let z_up = Water::new(1025.0, 9.81, Vector3::z(), 0.1).unwrap();
    let wp = cube.waterplane(&Pose::identity(), &z_up).unwrap();
    assert!((wp.area - 1.0).abs() < 1e-14);
    assert!((wp.center_of_flotation - Point3::new(0.0, 0.0, 0.1)).norm() < 1e-14);
    assert!((wp.axes[1].into_inner() - Vector3::y()).norm() < 1e-15);
}

#[test]
fn box_at_draft_matches_the_formulas() {
    let (length, beam, depth, draft) = (4.0, 2.0, 1.5, 0.6);
    let hull = block(length, depth, beam, 3);
    let water = Water::default();
    // Center of gravity on the centerline, 0.2 m above the waterline.
    let g = Point3::new(0.0, draft + 0.2 - depth / 2.0, 0.0);
    let loading = LoadingCondition::new(g).unwrap();
    let h = hull
        .hydrostatics(&at_draft(depth, draft), &water, &loading)
        .unwrap();
    let wp = &h.waterplane;
    let (bm_t, bm_l) = (
        beam * beam / (12.0 * draft),
        length * length / (12.0 * draft),
    );
    let errors = [
        relative(wp.area, length * beam),
        relative(h.displaced_volume, length * beam * draft),
        relative(h.kb, draft / 2.0),
        relative(h.kg, draft + 0.2),
        relative(h.bm_transverse, bm_t),
        relative(h.bm_longitudinal, bm_l),
        relative(h.bm_principal[0], bm_t),
        relative(h.bm_principal[1], bm_l),
        relative(h.gm_transverse, draft / 2.0 + bm_t - draft - 0.2),
        relative(h.gm_longitudinal, draft / 2.0 + bm_l - draft - 0.2),
        relative(wp.second_moments[(0, 0)], length * beam.powi(3) / 12.0),
        relative(wp.second_moments[(1, 1)], beam * length.powi(3) / 12.0),
    ];
    let worst = errors.iter().cloned().fold(0.0, f64::max);
    eprintln!("box: worst relative error {worst:.2e}");
    assert!(worst < 1e-14, "{errors:?}");
    assert!(wp.second_moments[(0, 1)].abs() < 1e-14);
    assert!(wp.center_of_flotation.coords.norm() < 1e-14);
    assert!((h.keel.y + draft).abs() < 1e-15);
    // A keel given: heights from it (here 0.1 m above the bottom).
    let raised = loading
        .with_keel(Point3::new(1.0, 0.1 - depth / 2.0, 0.3))
        .unwrap();
    let from_keel = hull
        .hydrostatics(&at_draft(depth, draft), &water, &raised)
        .unwrap();
    assert!((from_keel.kb - (draft / 2.0 - 0.1)).abs() < 1e-14);
    assert!((from_keel.kg - (draft + 0.1)).abs() < 1e-14);
    assert!((from_keel.gm_transverse - h.gm_transverse).abs() < 1e-14);
    // The least principal axis is the longitudinal one.
    assert!((wp.principal_axes[0].into_inner() - Vector3::x()).norm() < 1e-14);
}

#[test]
fn waterline_through_a_vertex_row_equals_a_hair_above() {
    // Rows at y = −1.5, −1, −0.5, 0, 0.5: the waterline runs along the fourth.
    let (length, beam, depth, draft) = (3.0, 1.2, 2.0, 1.5);
    let hull = block(length, depth, beam, 4);
    let water = Water::default();
    let g = Point3::new(0.0, -0.6, 0.0);
    let loading = LoadingCondition::new(g).unwrap();
    for yaw in [0.0, 0.4] {
        let turn = UnitQuaternion::from_scaled_axis(Vector3::y() * yaw);
        let pose = |hair: f64| {
            Pose::from_parts(
                Translation3::new(0.0, depth / 2.0 - draft - hair, 0.0),
                turn,
            )
        };
        // No triangle is cut: the row lies exactly in the surface.
        let b = hull.buoyancy(&pose(0.0), &water, Method::Exact).unwrap();
        assert_eq!(b.partially_submerged, 0);
        let on = hull.hydrostatics(&pose(0.0), &water, &loading).unwrap();
        let above = hull.hydrostatics(&pose(1e-9), &water, &loading).unwrap();
        let bm_t = beam * beam / (12.0 * draft);
        eprintln!(
            "row, yaw {yaw}: area {:.3e}, BM_T {:.3e}, against 1e-9 above: area {:.1e}, BM_T {:.1e}",
            relative(on.waterplane.area, length * beam),
            relative(on.bm_transverse, bm_t),
            relative(on.waterplane.area, above.waterplane.area),
            relative(on.bm_transverse, above.bm_transverse),
        );
        assert!(relative(on.waterplane.area, length * beam) < 1e-14);
        assert!(relative(on.waterplane.area, above.waterplane.area) < 1e-14);
        assert!(relative(on.bm_transverse, bm_t) < 1e-14);
        assert!(relative(on.bm_longitudinal, length * length / (12.0 * draft)) < 1e-14);
        assert!(relative(on.bm_transverse, above.bm_transverse) < 1e-9);
        assert!(relative(on.gm_transverse, above.gm_transverse) < 1e-8);
        assert!(on.gm_transverse > 0.0);
        let c_on = on.waterplane.center_of_flotation;
        let c_above = above.waterplane.center_of_flotation;
        assert!((c_on - c_above).norm() < 1e-14);
        // The principal axes turn with the body.
        let along = turn * Vector3::x();
        assert!(on.waterplane.principal_axes[0].dot(&along).abs() > 1.0 - 1e-14);
    }
}

#[test]
fn faces_lying_in_the_surface_follow_the_raised_surface() {
    // A vertex at h = 0 counts as under water: as if the surface were a hair higher.
    let cube = block(1.0, 1.0, 1.0, 2);
    let water = Water::default();
    // The bottom face lying in the surface: the raised surface cuts the whole section.
    let touching = cube.waterplane(&at(0.0, 0.5, 0.0), &water).unwrap();
    assert!((touching.area - 1.0).abs() < 1e-15, "{}", touching.area);
    // The top face lying in the surface: the raised surface leaves nothing to cut.
    let awash = cube.waterplane(&at(0.0, -0.5, 0.0), &water).unwrap();
    assert_eq!(awash.area, 0.0);
    assert_eq!(awash.principal_moments, [0.0, 0.0]);
}

/// Area and second moment (about any in-plane line through the center) of the regular
/// `n`-gon of circumradius `rho`: `n` triangles from the center of angle `α = 2π/n`.
fn regular_polygon(n: usize, rho: f64) -> (f64, f64) {
    let alpha = 2.0 * PI / n as f64;
    let area = n as f64 * rho * rho * alpha.sin() / 2.0;
    let polar = n as f64 * rho.powi(4) * alpha.sin() * (2.0 + alpha.cos()) / 12.0;
    (area, polar / 2.0)
}

#[test]
fn torus_at_its_equator_is_an_annulus() {
    let (major, minor) = (1.0, 0.4);
    let water = Water::default();
    let mut previous = None;
    for segments in [16, 32, 64, 128, 256] {
        let (v, t) = primitives::torus::<f64>(major, minor, segments, 16).unwrap();
        let torus = Mesh::new(v, t).unwrap();
        let wp = torus.waterplane(&Pose::identity(), &water).unwrap();
        // The outer ring of vertices lies in the surface, the inner one within 1e-16 of it:
        // the annulus between two regular polygons.
        let (outer, outer_i) = regular_polygon(segments, major + minor);
        let (inner, inner_i) = regular_polygon(segments, major - minor);
        let polygon = relative(wp.area, outer - inner);
        let moments = (0..2)
            .map(|k| relative(wp.principal_moments[k], outer_i - inner_i))
            .fold(0.0, f64::max);
        let annulus = 4.0 * PI * major * minor;
        let error = relative(wp.area, annulus);
        let moment_error = relative(
            wp.principal_moments[0],
            PI / 4.0 * ((major + minor).powi(4) - (major - minor).powi(4)),
        );
        let ratio = previous.map_or(f64::NAN, |p: f64| p / error);
        eprintln!(
            "torus {segments}: against the polygons {polygon:.1e} (area), {moments:.1e} \
             (moments); against the annulus {error:.3e} (area, ratio {ratio:.3}), \
             {moment_error:.3e} (moment)"
        );
        assert!(polygon < 1e-14 && moments < 1e-13);
        assert!(wp.center_of_flotation.coords.norm() < 1e-14);
        if let Some(p) = previous {
            assert!((ratio - 4.0).abs() < 0.05, "{p} {error}");
        }
        previous = Some(error);
    }
}

#[test]
fn sphere_metacentre_is_its_center() {
    // KB + BM = R at any draft (every normal passes through the center), up to the mesh. The
    // waterline runs along rings of vertices common to every mesh (polar angles πi/16), each
    // ring a regular polygon inscribed in the circle of latitude: the error then falls
    // smoothly, as the square of the spacing.
    let radius = 1.5;
    let water = Water::default();
    let rings = [3, 6, 8, 10, 13];
    let mut previous: Option<f64> = None;
    for n in [16, 32, 64, 128, 256] {
        let (v, t) = primitives::uv_sphere::<f64>(radius, n, n).unwrap();
        let sphere = Mesh::new(v, t).unwrap();
        let loading = LoadingCondition::new(Point3::origin()).unwrap();
        let worst = rings
            .iter()
            .map(|&i| {
                // Vertex 1 + (k − 1)·n starts ring k; ring i of 16 is ring i·n/16.
                let ring = sphere.vertex(1 + (i * n / 16 - 1) * n).y;
                let h = sphere
                    .hydrostatics(&at(0.0, -ring, 0.0), &water, &loading)
                    .unwrap();
                let km = [h.kb + h.bm_transverse, h.kb + h.bm_longitudinal];
                km.iter()
                    .map(|km| relative(*km, radius))
                    .fold(0.0, f64::max)
            })
            .fold(0.0, f64::max);
        let ratio = previous.map_or(f64::NAN, |p| p / worst);
        eprintln!("sphere {n}×{n}: |KM − R|/R {worst:.3e} (ratio {ratio:.3})");
        if let Some(p) = previous {
            assert!((ratio - 4.0).abs() < 0.2, "{p} {worst}");
        }
        previous = Some(worst);
    }
    assert!(previous.unwrap() < 1e-4);
}

#[test]
fn tilted_large_cube_section_through_the_hierarchy() {
    // 120,000 triangles; tilted by θ about x, the plane through the center cuts a rectangle
    // 1 (along x) by 1/cos θ.
    let cube = block(1.0, 1.0, 1.0, 100);
    let water = Water::default();
    for theta in [0.1, 0.3, 0.7] {
        let pose = Pose::from_parts(
            Translation3::new(2.0, 0.0, -1.0),
            UnitQuaternion::from_scaled_axis(Vector3::x() * theta),
        );
        let wp = cube.waterplane(&pose, &water).unwrap();
        let width = 1.0 / f64::cos(theta);
        let errors = [
            relative(wp.area, width),
            relative(wp.second_moments[(0, 0)], width.powi(3) / 12.0),
            relative(wp.second_moments[(1, 1)], width / 12.0),
        ];
        eprintln!(
            "tilted cube θ = {theta}: {:.1e} {:.1e} {:.1e}",
            errors[0], errors[1], errors[2]
        );
        assert!(errors.iter().all(|e| *e < 1e-12), "{errors:?}");
        assert!(wp.second_moments[(0, 1)].abs() < 1e-13);
        assert!((wp.center_of_flotation - Point3::new(2.0, 0.0, -1.0)).norm() < 1e-13);
    }
}

#[test]
fn two_hulls_add_their_waterplanes_about_the_common_center() {
    // A catamaran: two boxes L × B, their centerlines ±s apart across; one mesh.
    let (length, beam, depth, s) = (5.0, 0.8, 1.0, 1.5);
    let (v, t) = primitives::cube::<f64>(2).unwrap();
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    for side in [-1.0, 1.0] {
        let offset = vertices.len() as u32;
        vertices.extend(
            v.iter()
                .map(|p| Point3::new(p.x * length, p.y * depth, p.z * beam + side * s)),
        );
        triangles.extend(t.iter().map(|t| t.map(|k| k + offset)));
    }
    let catamaran = Mesh::new(vertices, triangles).unwrap();
    let wp = catamaran
        .waterplane(&at(0.0, 0.1, 0.0), &Water::default())
        .unwrap();
    let area = 2.0 * length * beam;
    let transverse = 2.0 * (length * beam.powi(3) / 12.0 + length * beam * s * s);
    assert!(relative(wp.area, area) < 1e-14);
    assert!(relative(wp.second_moments[(0, 0)], transverse) < 1e-14);
    assert!(
        relative(
            wp.second_moments[(1, 1)],
            2.0 * beam * length.powi(3) / 12.0
        ) < 1e-14
    );
    assert!(wp.center_of_flotation.coords.norm() < 1e-14);
}

/// The vertical force and the moments about `p` along `e₁`, `e₂` of buoyancy and the weight of
/// `mass` at `g` (mesh frame).
fn load(
    mesh: &Mesh<f64>,
    pose: &Pose<f64>,
    water: &Water<f64>,
    mass: f64,
    g: &Point3<f64>,
    p: &Point3<f64>,
    axes: &[Vector3<f64>; 3],
) -> Vector3<f64> {
    let b = mesh.buoyancy(pose, water, Method::Exact).unwrap();
    let n = water.normal().into_inner();
    let weight = -n * (mass * water.gravity());
    let force = b.force + weight;
    let moment = b.torque_about(p) + (pose * g - p).cross(&weight);
    Vector3::new(
        force.dot(&axes[2]),
        moment.dot(&axes[0]),
        moment.dot(&axes[1]),
    )
}

/// The stiffness by central differences of `load`: heave along `n`, rotations about `e₁` and
/// `e₂` through `P`.
fn finite_difference_stiffness(
    mesh: &Mesh<f64>,
    pose: &Pose<f64>,
    water: &Water<f64>,
    loading: &LoadingCondition<f64>,
    h: &Hydrostatics<f64>,
    step: f64,
) -> Matrix3<f64> {
    let axes = [
        h.waterplane.axes[0].into_inner(),
        h.waterplane.axes[1].into_inner(),
        water.normal().into_inner(),
    ];
    let p = h.reference_point;
    let g = loading.center_of_gravity();
    let displaced = |j: usize, delta: f64| -> Pose<f64> {
        let motion = if j == 0 {
            Isometry3::from_parts(
                Translation3::from(axes[2] * delta),
                UnitQuaternion::identity(),
            )
        } else {
            Isometry3::rotation_wrt_point(UnitQuaternion::from_scaled_axis(axes[j - 1] * delta), p)
        };
        motion * pose
    };
    let mut c = Matrix3::zeros();
    for j in 0..3 {
        let plus = load(mesh, &displaced(j, step), water, h.mass, &g, &p, &axes);
        let minus = load(mesh, &displaced(j, -step), water, h.mass, &g, &p, &axes);
        c.set_column(j, &(-(plus - minus) / (2.0 * step)));
    }
    c
}

#[test]
fn stiffness_matches_finite_differences_of_the_load() {
    let water = Water::new(1025.0, 9.81, Vector3::y(), 0.3).unwrap();
    let mut worst: f64 = 0.0;
    let meshes = common::procedural_meshes();
    for (name, mesh) in meshes {
        let scale = mesh.bounding_radius();
        for k in 0..12 {
            let u = [
                (0.37 + 0.618 * k as f64) % 1.0,
                (0.11 + 0.414 * k as f64) % 1.0,
                (0.73 + 0.732 * k as f64) % 1.0,
            ];
            let depth = scale * (0.6 * ((k as f64 * 0.29) % 1.0) - 0.3);
            let pose = common::pose(Vector3::new(0.4, 0.3 + depth, -0.2), u);
            // A body lighter than its displacement, G and P off its center.
            let g = mesh.centroid() + Vector3::new(0.05, -0.1, 0.02) * scale;
            let volume = mesh
                .buoyancy(&pose, &water, Method::Exact)
                .unwrap()
                .submerged_volume;
            let loading = LoadingCondition::new(g)
                .unwrap()
                .with_mass(0.7 * water.density() * volume)
                .unwrap()
                .with_reference_point(mesh.centroid() + Vector3::new(-0.1, 0.2, 0.1) * scale)
                .unwrap()
                .with_longitudinal_axis(Vector3::new(1.0, 0.2, -0.3))
                .unwrap();
            let h = mesh.hydrostatics(&pose, &water, &loading).unwrap();
            let fd = finite_difference_stiffness(mesh, &pose, &water, &loading, &h, 1e-5);
            let size = h.stiffness.abs().max().max(1e-300);
            let error = (fd - h.stiffness).abs().max() / size;
            assert!(
                error < 1e-5,
                "{name}, pose {k}: {error:.2e}\n{}\n{fd}",
                h.stiffness
            );
            worst = worst.max(error);
            // C₃₃ = ρgA.
            let area = h.waterplane.area;
            assert!((h.stiffness[(0, 0)] - water.specific_weight() * area).abs() <= 1e-12 * size);
        }
    }
    eprintln!("stiffness against finite differences: worst {worst:.2e} of max |C|");
}

#[test]
fn stiffness_in_equilibrium_is_rho_g_v_gm() {
    let (length, beam, depth, draft) = (4.0, 2.0, 1.5, 0.6);
    let hull = block(length, depth, beam, 3);
    let water = Water::default();
    let g = Point3::new(0.0, draft + 0.2 - depth / 2.0, 0.0);
    let h = hull
        .hydrostatics(
            &at_draft(depth, draft),
            &water,
            &LoadingCondition::new(g).unwrap(),
        )
        .unwrap();
    let rho_g_v = water.specific_weight() * h.displaced_volume;
    let c = &h.stiffness;
    assert!(relative(c[(1, 1)], rho_g_v * h.gm_transverse) < 1e-13);
    assert!(relative(c[(2, 2)], rho_g_v * h.gm_longitudinal) < 1e-13);
    assert!(relative(c[(0, 0)], water.specific_weight() * length * beam) < 1e-14);
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        assert!(c[(i, j)].abs() < 1e-10 && c[(i, j)] == c[(j, i)]);
    }
    // The restoring moment of a small heel: −ρgV·GM_T·φ about e₁ (the x axis).
    let (force, moment) = h.restoring(0.0, 0.02, 0.0);
    assert!(force.norm() < 1e-9);
    assert!(relative(moment.x, -rho_g_v * h.gm_transverse * 0.02) < 1e-13);
    // A heave: −ρgA·δ along the normal.
    let (force, _) = h.restoring(0.01, 0.0, 0.0);
    assert!(relative(force.y, -water.specific_weight() * length * beam * 0.01) < 1e-14);
}

#[test]
fn dry_and_submerged_bodies_have_no_waterplane() {
    let cube = block(1.0, 1.0, 1.0, 2);
    let water = Water::default();
    let loading = LoadingCondition::new(Point3::origin()).unwrap();
    for y in [3.0, -3.0] {
        let wp: Waterplane<f64> = cube.waterplane(&at(1.0, y, 2.0), &water).unwrap();
        assert_eq!(wp.area, 0.0);
        assert_eq!(wp.center_of_flotation, Point3::new(1.0, 0.0, 2.0));
        let h = cube
            .hydrostatics(&at(1.0, y, 2.0), &water, &loading)
            .unwrap();
        assert_eq!((h.bm_transverse, h.bm_longitudinal), (0.0, 0.0));
        assert!(h.stiffness.iter().all(|c| c.is_finite()));
        assert_eq!(h.stiffness[(0, 0)], 0.0);
        assert!(
            (h.kb - if y > 0.0 { -2.5 } else { 0.5 }).abs() < 1e-14,
            "{}",
            h.kb
        );
    }
}

#[test]
fn f32_agrees_with_f64() {
    let (v, t) = primitives::torus::<f32>(1.0, 0.4, 48, 16).unwrap();
    let torus32 = Mesh::new(v, t).unwrap();
    let (v, t) = primitives::torus::<f64>(1.0, 0.4, 48, 16).unwrap();
    let torus64 = Mesh::new(v, t).unwrap();
    let rotation = UnitQuaternion::from_scaled_axis(Vector3::new(0.2, 0.5, -0.1));
    let wp32 = torus32
        .waterplane(
            &Pose::from_parts(Translation3::new(0.0, 0.1, 0.0), rotation.cast()),
            &Water::default(),
        )
        .unwrap();
    let wp64 = torus64
        .waterplane(
            &Pose::from_parts(Translation3::new(0.0, 0.1, 0.0), rotation),
            &Water::default(),
        )
        .unwrap();
    assert!(relative(wp32.area as f64, wp64.area) < 1e-5);
    for k in 0..2 {
        assert!(relative(wp32.principal_moments[k] as f64, wp64.principal_moments[k]) < 1e-5);
    }
}

#[test]
fn invalid_inputs_are_errors() {
    let cube = block(1.0, 1.0, 1.0, 1);
    let water = Water::default();
    let nan = Point3::new(f64::NAN, 0.0, 0.0);
    assert!(matches!(
        cube.waterplane(&at(f64::NAN, 0.0, 0.0), &water),
        Err(Error::InvalidPose { .. })
    ));
    let names = |e: Result<LoadingCondition<f64>, Error>| match e {
        Err(Error::InvalidLoading { parameter, .. }) => parameter,
        other => panic!("{other:?}"),
    };
    assert_eq!(names(LoadingCondition::new(nan)), "center_of_gravity");
    let loading = LoadingCondition::new(Point3::origin()).unwrap();
    for mass in [-1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(names(loading.with_mass(mass)), "mass");
    }
    assert_eq!(names(loading.with_reference_point(nan)), "reference_point");
    assert_eq!(names(loading.with_keel(nan)), "keel");
    assert_eq!(
        names(loading.with_longitudinal_axis(Vector3::zeros())),
        "longitudinal_axis"
    );
    // Along the vertical at this pose: no direction in the waterplane.
    let upright = loading.with_longitudinal_axis(Vector3::y()).unwrap();
    let e = cube
        .hydrostatics(&Pose::identity(), &water, &upright)
        .unwrap_err();
    assert!(
        matches!(
            e,
            Error::InvalidLoading {
                parameter: "longitudinal_axis",
                ..
            }
        ),
        "{e}"
    );
    assert!(e.to_string().contains("vertical"), "{e}");
}

/// Area and second moments (`I_T` about the centerline, `I_L` about midship) of the polygon
/// the Wigley hull's waterline makes: the half-breadth `w = (B/2)(1 − ξ²)` at `stations`
/// equally spaced stations, linear between them. Each piece exactly: `∫(2/3)w³ dx` of a linear
/// `w` by its closed form, `∫2x²w dx` (cubic) by Simpson's rule.
fn wigley_polygon(length: f64, beam: f64, stations: usize) -> (f64, f64, f64) {
    let x =
        |i: usize| length / 2.0 * (2.0 * i as f64 - (stations - 1) as f64) / (stations - 1) as f64;
    let w = |x: f64| beam / 2.0 * (1.0 - (2.0 * x / length).powi(2));
    let (mut area, mut transverse, mut longitudinal) = (0.0, 0.0, 0.0);
    for i in 0..stations - 1 {
        let (xa, xb) = (x(i), x(i + 1));
        let (wa, wb) = (w(xa), w(xb));
        let dx = xb - xa;
        let linear = |t: f64| wa + (wb - wa) * (t - xa) / dx;
        let xm = (xa + xb) / 2.0;
        area += dx * (wa + wb);
        transverse +=
            2.0 / 3.0 * dx * (wa.powi(3) + wa * wa * wb + wa * wb * wb + wb.powi(3)) / 4.0;
        longitudinal += 2.0 * dx / 6.0 * (xa * xa * wa + 4.0 * xm * xm * linear(xm) + xb * xb * wb);
    }
    (area, transverse, longitudinal)
}

#[test]
fn wigley_hull_matches_the_analytic_figures() {
    // The benchmark's proportions: L/B = 10, B/T = 1.6. V = 4LBT/9, A = 2LB/3,
    // I_T = ∫(2/3)w³ dx = 4LB³/105, I_L = ∫2x²w dx = BL³/30: KB = 5T/8, BM_T = 3B²/(35T),
    // BM_L = 3L²/(40T).
    let (length, beam, draft) = (2.5, 0.25, 0.15625);
    let water = Water::default();
    let analytic = [
        2.0 * length * beam / 3.0,
        5.0 * draft / 8.0,
        3.0 * beam * beam / (35.0 * draft),
        3.0 * length * length / (40.0 * draft),
    ];
    let mut previous: Option<[f64; 4]> = None;
    for k in 0..5 {
        let (stations, waterlines) = (10 * (1 << k) + 1, 4 * (1 << k) + 1);
        let (v, t) =
            primitives::wigley_hull::<f64>(length, beam, draft, 0.1, stations, waterlines).unwrap();
        let hull = Mesh::new(v, t).unwrap();
        // The mesh's centroid is the center of gravity: KG does not enter BM.
        let loading = LoadingCondition::new(hull.centroid()).unwrap();
        let h = hull
            .hydrostatics(&Pose::identity(), &water, &loading)
            .unwrap();
        // The waterline runs along a row of vertices: exactly the polygon.
        let (area, transverse, longitudinal) = wigley_polygon(length, beam, stations);
        let wp = &h.waterplane;
        let polygon = [
            relative(wp.area, area),
            relative(wp.second_moments[(0, 0)], transverse),
            relative(wp.second_moments[(1, 1)], longitudinal),
        ];
        assert!(polygon.iter().all(|e| *e < 1e-13), "{polygon:?}");
        assert!(
            relative(
                area,
                analytic[0] * (1.0 - 1.0 / ((stations - 1) * (stations - 1)) as f64)
            ) < 1e-14
        );
        let errors = [
            relative(wp.area, analytic[0]),
            relative(h.kb, analytic[1]),
            relative(h.bm_transverse, analytic[2]),
            relative(h.bm_longitudinal, analytic[3]),
        ];
        let ratios = previous.map(|p| [0, 1, 2, 3].map(|i| p[i] / errors[i]));
        eprintln!(
            "wigley {stations}×{waterlines}: polygon {:.1e}; A {:.3e}, KB {:.3e}, BM_T {:.3e}, \
             BM_L {:.3e}; ratios {ratios:.3?}",
            polygon.iter().cloned().fold(0.0, f64::max),
            errors[0],
            errors[1],
            errors[2],
            errors[3],
        );
        // Second order in the spacing once the mesh resolves the hull (BM_L's errors of
        // I_L and V partly cancel on the coarsest meshes).
        if let (Some(r), true) = (ratios, k >= 2) {
            assert!(r.iter().all(|r| (r - 4.0).abs() < 0.2), "{r:?}");
        }
        previous = Some(errors);
    }
    assert!(previous.unwrap().iter().all(|e| *e < 5e-5));
}
