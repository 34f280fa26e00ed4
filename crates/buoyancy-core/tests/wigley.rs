//! The Wigley hull (`primitives::wigley_hull`) against its analytic hydrostatics: below the design
//! waterline `y = 0` it displaces `V = 4LBT/9` with its center of buoyancy `KB = 5T/8` above the
//! keel, and its wall-sided topside of freeboard `D` holds `2LBD/3`. The mesh's vertices lie on
//! the hull, so the underwater figures converge as the square of the spacing; the topside is a
//! prism on the polygonal waterline, whose area the trapezoidal rule gives exactly.

use buoyancy_core::nalgebra::{Translation3, UnitQuaternion};
use buoyancy_core::{Buoyancy, Error, Mesh, Method, Pose, Water, mesh::primitives};

/// The Wigley benchmark's proportions, L/B = 10 and L/T = 16, with a freeboard of 0.64 T.
const LENGTH: f64 = 2.5;
const BEAM: f64 = 0.25;
const DRAFT: f64 = 0.15625;
const FREEBOARD: f64 = 0.1;

/// Resolutions of halving spacing: `(stations, waterlines)`, i.e. 20·2^k × 8·2^k cells a side.
const RESOLUTIONS: [(usize, usize); 3] = [(21, 9), (41, 17), (81, 33)];

fn hull(stations: usize, waterlines: usize) -> Mesh<f64> {
    let (v, t) = primitives::wigley_hull(LENGTH, BEAM, DRAFT, FREEBOARD, stations, waterlines)
        .unwrap_or_else(|e| panic!("{stations} × {waterlines}: {e}"));
    Mesh::new(v, t).unwrap_or_else(|e| panic!("{stations} × {waterlines}: {e}"))
}

/// The part below the design waterline: the hull at the identity pose in `Water::default()`.
fn underwater(mesh: &Mesh<f64>) -> Buoyancy<f64> {
    mesh.buoyancy(&Pose::identity(), &Water::default(), Method::Exact)
        .unwrap()
}

fn displacement() -> f64 {
    4.0 * LENGTH * BEAM * DRAFT / 9.0
}

/// The topside of the mesh: `D` times the area of the polygon through the waterline's
/// `stations` equally spaced points, `(2LB/3)·(1 − h²/L²)` with `h = L/(stations − 1)` (the
/// trapezoidal rule's error on a parabola, `(h²/12)·(f'(L/2) − f'(−L/2))`, is exact).
fn topside(length: f64, beam: f64, freeboard: f64, stations: usize) -> f64 {
    let intervals = (stations - 1) as f64;
    freeboard * 2.0 * length * beam / 3.0 * (1.0 - 1.0 / (intervals * intervals))
}

/// Errors at the resolutions of `RESOLUTIONS`, asserting that each halving of the spacing
/// divides the error by more than 3 (second order: 4).
fn assert_second_order(what: &str, errors: &[f64]) {
    for pair in errors.windows(2) {
        let ratio = pair[0] / pair[1];
        println!(
            "{what}: error {:.3e} -> {:.3e}, ratio {ratio:.3}",
            pair[0], pair[1]
        );
        assert!(
            ratio > 3.0 && ratio < 5.0,
            "{what}: errors {errors:?}, ratio {ratio}"
        );
    }
}

#[test]
fn displacement_converges_as_the_square_of_the_spacing() {
    let exact = displacement();
    let errors: Vec<f64> = RESOLUTIONS
        .iter()
        .map(|&(stations, waterlines)| {
            let b = underwater(&hull(stations, waterlines));
            let error = (b.submerged_volume - exact).abs();
            println!(
                "{stations} stations × {waterlines} waterlines: V = {:.10} (exact {exact:.10}), \
                 relative error {:.3e}",
                b.submerged_volume,
                error / exact
            );
            // ρ·g·V, straight up.
            let weight = 1000.0 * 9.81 * b.submerged_volume;
            assert!((b.force.y - weight).abs() < 1e-12 * weight);
            assert!(b.force.x.abs() + b.force.z.abs() < 1e-12 * weight);
            error
        })
        .collect();
    assert!(errors[2] < 1e-3 * exact, "{errors:?}");
    assert_second_order("V", &errors);
}

#[test]
fn center_of_buoyancy_converges_to_five_eighths_of_the_draft() {
    let kb = 5.0 * DRAFT / 8.0;
    let errors: Vec<f64> = RESOLUTIONS
        .iter()
        .map(|&(stations, waterlines)| {
            let b = underwater(&hull(stations, waterlines));
            let center = b.center_of_buoyancy;
            let error = (center.y + DRAFT - kb).abs();
            println!(
                "{stations} stations × {waterlines} waterlines: KB = {:.10} (exact {kb:.10}), \
                 relative error {:.3e}",
                center.y + DRAFT,
                error / kb
            );
            // Odd station counts: symmetric fore and aft as well as port and starboard.
            assert!(center.x.abs() < 1e-12 * LENGTH, "{center}");
            assert!(center.z.abs() < 1e-12 * LENGTH, "{center}");
            error
        })
        .collect();
    assert!(errors[2] < 1e-3 * kb, "{errors:?}");
    assert_second_order("KB", &errors);
}

#[test]
fn enclosed_volume_is_the_underwater_part_plus_the_topside() {
    for (length, beam, draft, freeboard) in [
        (LENGTH, BEAM, DRAFT, FREEBOARD),
        (1.0, 1.0, 1.0, 1.0),
        (100.0, 12.0, 4.0, 30.0),
        (0.3, 0.05, 0.2, 0.01),
    ] {
        for (stations, waterlines) in [(3, 2), (4, 3), (21, 9), (64, 5)] {
            let (v, t) =
                primitives::wigley_hull(length, beam, draft, freeboard, stations, waterlines)
                    .unwrap();
            let mesh = Mesh::new(v, t).unwrap();
            let below = underwater(&mesh).submerged_volume;
            let above = topside(length, beam, freeboard, stations);
            let what =
                format!("{length} × {beam} × {draft} + {freeboard}, {stations} × {waterlines}");
            assert!(
                (mesh.volume() - (below + above)).abs() < 1e-12 * mesh.volume(),
                "{what}: {} vs {below} + {above}",
                mesh.volume()
            );
            // Fully immersed, the whole of it is under water.
            let deep = Pose::from_parts(
                Translation3::new(0.0, -2.0 * freeboard, 0.0),
                UnitQuaternion::identity(),
            );
            let immersed = mesh
                .buoyancy(&deep, &Water::default(), Method::Exact)
                .unwrap()
                .submerged_volume;
            assert!(
                (immersed - mesh.volume()).abs() < 1e-12 * mesh.volume(),
                "{what}: {immersed} vs {}",
                mesh.volume()
            );
        }
    }
    // And the whole tends to the analytic hull, 4LBT/9 + 2LBD/3.
    let exact = displacement() + 2.0 * LENGTH * BEAM * FREEBOARD / 3.0;
    let errors: Vec<f64> = RESOLUTIONS
        .iter()
        .map(|&(stations, waterlines)| (hull(stations, waterlines).volume() - exact).abs())
        .collect();
    assert_second_order("total volume", &errors);
}

#[test]
fn the_topside_is_wall_sided() {
    // Sunk by s < D below the design draft, the hull displaces s times the (polygonal)
    // waterplane area more, exactly.
    for (stations, waterlines) in [(3, 2), (21, 9), (40, 5)] {
        let mesh = hull(stations, waterlines);
        let design = underwater(&mesh).submerged_volume;
        let waterplane = topside(LENGTH, BEAM, FREEBOARD, stations) / FREEBOARD;
        for s in [0.01, 0.05, 0.099] {
            let pose =
                Pose::from_parts(Translation3::new(0.0, -s, 0.0), UnitQuaternion::identity());
            let b = mesh
                .buoyancy(&pose, &Water::default(), Method::Exact)
                .unwrap();
            let expected = design + s * waterplane;
            assert!(
                (b.submerged_volume - expected).abs() < 1e-12 * expected,
                "{stations} × {waterlines}, s = {s}: {} vs {expected}",
                b.submerged_volume
            );
        }
    }
}

#[test]
fn metacentre_converges_to_kb_plus_bm() {
    // Heeled by a small angle φ about the x axis (through the waterline), the center of
    // buoyancy moves across to z_B = KM·sin φ from the keel's vertical: the metacentre, at
    // KB + BM = 5T/8 + 3B²/(35T) above the keel (the wall sides add O(φ²)).
    let km = 5.0 * DRAFT / 8.0 + 3.0 * BEAM * BEAM / (35.0 * DRAFT);
    let heel = 1e-4_f64;
    let pose = Pose::from_parts(
        Translation3::identity(),
        UnitQuaternion::from_euler_angles(heel, 0.0, 0.0),
    );
    let errors: Vec<f64> = RESOLUTIONS
        .iter()
        .map(|&(stations, waterlines)| {
            let b = hull(stations, waterlines)
                .buoyancy(&pose, &Water::default(), Method::Exact)
                .unwrap();
            // The body's centre line meets the vertical through B at the height z_B / sin φ.
            let measured = b.center_of_buoyancy.z / heel.sin() + DRAFT;
            println!("{stations} × {waterlines}: KM = {measured:.10} (exact {km:.10})");
            (measured - km).abs()
        })
        .collect();
    assert!(errors[2] < 1e-3 * km, "{errors:?}");
    assert_second_order("KM", &errors);
}

#[test]
fn floats_upright_at_the_design_draft() {
    // A body of mass ρ·V (V: the mesh's volume below y = 0) at the identity pose is in
    // equilibrium: the buoyant force passes through its centroid.
    let mesh = hull(41, 17);
    let b = underwater(&mesh);
    let centroid = mesh.centroid();
    assert!(
        centroid.x.abs() < 1e-12 && centroid.z.abs() < 1e-12,
        "{centroid}"
    );
    // A uniform body's center of mass: (V·(−3T/8) + (2LBD/3)·(D/2)) / (V + 2LBD/3).
    let (t, d) = (DRAFT, FREEBOARD);
    let height = (6.0 * d * d - 3.0 * t * t) / (8.0 * t + 12.0 * d);
    assert!(
        (centroid.y - height).abs() < 1e-3 * t,
        "{centroid} vs {height}"
    );
    assert_eq!(b.torque_point, centroid);
    let scale = b.force.y * LENGTH;
    assert!(b.torque.norm() < 1e-12 * scale, "{}", b.torque);
}

#[test]
fn meshes_are_valid_over_a_range_of_parameters() {
    for (length, beam, draft, freeboard) in [
        (LENGTH, BEAM, DRAFT, FREEBOARD),
        (1.0, 1.0, 1.0, 1.0),
        (1.0, 3.0, 0.01, 2.0),
        (1e3, 1e-2, 1e-1, 1e-3),
    ] {
        for stations in [3, 4, 5, 10, 33] {
            for waterlines in [2, 3, 7, 16] {
                let what =
                    format!("{length} × {beam} × {draft} + {freeboard}, {stations} × {waterlines}");
                let (v, t) = primitives::wigley_hull::<f64>(
                    length, beam, draft, freeboard, stations, waterlines,
                )
                .unwrap();
                assert_eq!(
                    v.len(),
                    2 * (stations - 1) * waterlines + stations,
                    "{what}"
                );
                assert_eq!(
                    t.len(),
                    4 * (stations - 1) * waterlines + 2 * (stations - 2),
                    "{what}"
                );
                // On the hull, the deck's vertices included (they are the sides' top edges).
                for p in &v {
                    assert!(p.x.abs() <= length / 2.0 && p.y >= -draft && p.y <= freeboard);
                    let waterline = beam / 2.0 * (1.0 - (2.0 * p.x / length).powi(2));
                    let w = if p.y > 0.0 {
                        waterline
                    } else {
                        waterline * (1.0 - (p.y / draft).powi(2))
                    };
                    assert!((p.z.abs() - w).abs() <= 1e-15 * beam, "{what}: {p}");
                }
                // No triangle of zero area.
                for tri in &t {
                    let [a, b, c] = tri.map(|i| v[i as usize]);
                    let area = (b - a).cross(&(c - a)).norm();
                    let longest = [(b - a).norm(), (c - b).norm(), (a - c).norm()]
                        .into_iter()
                        .fold(0.0, f64::max);
                    assert!(area > 1e-9 * longest * longest, "{what}: {tri:?}");
                }
                let mesh = Mesh::new(v, t).unwrap_or_else(|e| panic!("{what}: {e}"));
                assert!(!mesh.was_reoriented(), "{what}");
                assert!(mesh.volume() > 0.0, "{what}");
            }
        }
    }
    // Single precision too.
    let (v, t) = primitives::wigley_hull::<f32>(2.5, 0.25, 0.15625, 0.1, 41, 17).unwrap();
    let mesh = Mesh::new(v, t).unwrap();
    assert!(!mesh.was_reoriented());
    let b = mesh
        .buoyancy(&Pose::identity(), &Water::default(), Method::Exact)
        .unwrap();
    let v = underwater(&hull(41, 17)).submerged_volume as f32;
    assert!(
        (b.submerged_volume / v - 1.0).abs() < 1e-5,
        "{}",
        b.submerged_volume
    );
}

#[test]
fn bad_parameters_are_errors_naming_the_parameter() {
    let parameter = |r: Result<primitives::Shape<f64>, Error>| match r {
        Err(Error::InvalidShape { parameter, .. }) => parameter,
        other => panic!("{:?}", other.map(|(v, t)| (v.len(), t.len()))),
    };
    let hull = |l, b, t, d, s, w| parameter(primitives::wigley_hull(l, b, t, d, s, w));
    for bad in [0.0, -1.0, -0.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(hull(bad, 0.25, 0.15, 0.1, 21, 9), "length");
        assert_eq!(hull(2.5, bad, 0.15, 0.1, 21, 9), "beam");
        assert_eq!(hull(2.5, 0.25, bad, 0.1, 21, 9), "draft");
        assert_eq!(hull(2.5, 0.25, 0.15, bad, 21, 9), "freeboard");
    }
    for stations in [0, 1, 2] {
        assert_eq!(hull(2.5, 0.25, 0.15, 0.1, stations, 9), "stations");
    }
    for waterlines in [0, 1] {
        assert_eq!(hull(2.5, 0.25, 0.15, 0.1, 21, waterlines), "waterlines");
    }
    // Too many vertices for u32 indices, and counts that overflow.
    assert_eq!(hull(2.5, 0.25, 0.15, 0.1, 1 << 16, 1 << 16), "stations");
    assert_eq!(hull(2.5, 0.25, 0.15, 0.1, usize::MAX, 9), "stations");
    assert_eq!(hull(2.5, 0.25, 0.15, 0.1, 21, usize::MAX), "stations");
    // The first bad parameter is the one named.
    assert_eq!(hull(f64::NAN, 0.0, 0.15, 0.1, 1, 1), "length");
    let message = primitives::wigley_hull::<f64>(2.5, 0.25, 0.15, 0.1, 21, 1)
        .unwrap_err()
        .to_string();
    assert_eq!(
        message,
        "invalid shape parameter waterlines: must be at least 2"
    );
}
