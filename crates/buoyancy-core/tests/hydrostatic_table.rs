//! The hydrostatic table (`Mesh::hydrostatic_table`) against analytic values: a box, whose
//! figures are exact, and the Wigley hull, whose figures at the design draft converge as the
//! square of the mesh spacing; the displacement column against `ρ·A_wp`; bad drafts and options.

use std::f64::consts::FRAC_PI_2;

use buoyancy_core::hydrostatics::{HydrostaticRow, TableOptions};
use buoyancy_core::nalgebra::{Point3, UnitQuaternion, Vector3};
use buoyancy_core::{Error, Mesh, Water, mesh::primitives};

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// A box `length` (x) × `depth` (y, up) × `beam` (z), each face split in `n × n` squares, its
/// center at `center` (mesh frame).
fn block(length: f64, depth: f64, beam: f64, n: usize, center: Vector3<f64>) -> Mesh<f64> {
    let (v, t) = primitives::cube(n).unwrap();
    Mesh::new(v, t)
        .unwrap()
        .scaled(&Vector3::new(length, depth, beam))
        .unwrap()
        .translated(&center)
        .unwrap()
}

fn table(mesh: &Mesh<f64>, drafts: &[f64]) -> Vec<HydrostaticRow<f64>> {
    mesh.hydrostatic_table(&Water::default(), drafts, &TableOptions::new())
        .unwrap()
}

#[test]
fn box_rows_match_the_formulas() {
    let (length, beam, depth) = (6.0, 2.0, 1.5);
    // Off the mesh origin: LCB and LCF are measured from it.
    let center = Vector3::new(1.3, -0.4, 0.7);
    let hull = block(length, depth, beam, 3, center);
    let water = Water::<f64>::default();
    let rho = water.density();
    // Drafts between the vertex rows and on one (0.5 = depth/3).
    let drafts = [0.1, 0.3, 0.5, 0.8, 1.2];
    let rows = table(&hull, &drafts);
    let mut worst: f64 = 0.0;
    for (row, &t) in rows.iter().zip(&drafts) {
        let bm_t = beam * beam / (12.0 * t);
        let bm_l = length * length / (12.0 * t);
        let v = length * beam * t;
        let errors = [
            relative(row.displaced_volume, v),
            relative(row.displacement, rho * v),
            relative(row.kb, t / 2.0),
            relative(row.bm_transverse, bm_t),
            relative(row.bm_longitudinal, bm_l),
            relative(row.km_transverse, t / 2.0 + bm_t),
            relative(row.km_longitudinal, t / 2.0 + bm_l),
            relative(row.waterplane_area, length * beam),
            relative(row.tpc, rho * length * beam / 1e5),
            relative(row.waterline_length, length),
            relative(row.lcb, center.x),
            relative(row.lcf, center.x),
            // MCT with GM_L ≈ BM_L and L the waterline length: ρ·V·BM_L/(100·L) = ρBL²/1200.
            relative(row.mct, rho * beam * length * length / 1200.0),
        ];
        let row_worst = errors.iter().cloned().fold(0.0, f64::max);
        assert!(row_worst < 1e-13, "draft {t}: {errors:?}");
        worst = worst.max(row_worst);
        assert_eq!(row.draft, t);
        // The keel is at the draft: the bottom y = center.y − depth/2 at −t.
        assert!((row.hydrostatics.keel.y + t).abs() < 1e-14);
        assert!((row.pose.translation.vector.y - (-t - (center.y - depth / 2.0))).abs() < 1e-14);
    }
    eprintln!("box table: worst relative error {worst:.2e}");
}

#[test]
fn box_with_a_center_of_gravity_and_a_length() {
    let (length, beam, depth) = (6.0, 2.0, 1.5);
    let hull = block(length, depth, beam, 2, Vector3::zeros());
    let water = Water::default();
    // G 1 m above the keel (y = −0.75 + 1), MCT over L = 5 m.
    let options = TableOptions::new()
        .with_center_of_gravity(Point3::new(0.0, 0.25, 0.0))
        .unwrap()
        .with_length(5.0)
        .unwrap();
    let t = 0.6;
    let row = hull.hydrostatic_table(&water, &[t], &options).unwrap()[0];
    let gm_l = t / 2.0 + length * length / (12.0 * t) - 1.0;
    assert!(relative(row.gm_longitudinal, gm_l) < 1e-13);
    assert_eq!(row.trim_length, 5.0);
    let mct = water.density() * length * beam * t * gm_l / (100.0 * 5.0);
    assert!(relative(row.mct, mct) < 1e-13, "{} {mct}", row.mct);
    assert!(relative(row.hydrostatics.kg, 1.0) < 1e-14);
}

#[test]
fn a_rotation_turns_the_body_upright() {
    // The same box modelled z up: turned by −90° about x (z → y), the table is the box's.
    let (length, beam, depth) = (6.0, 2.0, 1.5);
    let y_up = block(length, depth, beam, 2, Vector3::zeros());
    let z_up = block(length, beam, depth, 2, Vector3::zeros());
    let water = Water::default();
    let turn = UnitQuaternion::from_scaled_axis(Vector3::x() * -FRAC_PI_2);
    let options = TableOptions::new().with_rotation(turn).unwrap();
    let drafts = [0.2, 0.9];
    let a = table(&y_up, &drafts);
    let b = z_up.hydrostatic_table(&water, &drafts, &options).unwrap();
    for (a, b) in a.iter().zip(&b) {
        for (x, y) in [
            (a.displaced_volume, b.displaced_volume),
            (a.kb, b.kb),
            (a.bm_transverse, b.bm_transverse),
            (a.bm_longitudinal, b.bm_longitudinal),
            (a.waterplane_area, b.waterplane_area),
            (a.mct, b.mct),
        ] {
            assert!(relative(x, y) < 1e-13, "{x} {y}");
        }
    }
}

/// The Wigley benchmark's proportions, L/B = 10 and L/T = 16.
const LENGTH: f64 = 2.5;
const BEAM: f64 = 0.25;
const DRAFT: f64 = 0.15625;
const FREEBOARD: f64 = 0.1;

fn wigley(stations: usize, waterlines: usize) -> Mesh<f64> {
    let (v, t) =
        primitives::wigley_hull(LENGTH, BEAM, DRAFT, FREEBOARD, stations, waterlines).unwrap();
    Mesh::new(v, t).unwrap()
}

#[test]
fn wigley_hull_at_its_design_draft_converges_as_the_square_of_the_spacing() {
    let (l, b, t) = (LENGTH, BEAM, DRAFT);
    let exact = [
        ("V", 4.0 * l * b * t / 9.0),
        ("A_wp", 2.0 * l * b / 3.0),
        ("KB", 5.0 * t / 8.0),
        ("BM_T", 3.0 * b * b / (35.0 * t)),
        ("BM_L", 3.0 * l * l / (40.0 * t)),
    ];
    let mut errors = vec![Vec::new(); exact.len()];
    for (stations, waterlines) in [(21, 9), (41, 17), (81, 33)] {
        let row = table(&wigley(stations, waterlines), &[DRAFT])[0];
        let values = [
            row.displaced_volume,
            row.waterplane_area,
            row.kb,
            row.bm_transverse,
            row.bm_longitudinal,
        ];
        for (k, (value, (_, exact))) in values.iter().zip(&exact).enumerate() {
            errors[k].push(relative(*value, *exact));
        }
        // Symmetric fore and aft about the mesh origin, which is at midship.
        assert!(row.lcb.abs() < 1e-14 && row.lcf.abs() < 1e-14);
        assert!(relative(row.waterline_length, LENGTH) < 1e-14);
    }
    for ((name, _), errors) in exact.iter().zip(&errors) {
        for pair in errors.windows(2) {
            let ratio = pair[0] / pair[1];
            eprintln!(
                "Wigley {name}: relative error {:.3e} -> {:.3e}, ratio {ratio:.3}",
                pair[0], pair[1]
            );
            assert!((ratio - 4.0).abs() < 0.25, "{name}: {errors:?}");
        }
        assert!(errors[2] < 1e-3, "{name}: {errors:?}");
    }
}

#[test]
fn displacement_rises_with_draft_at_rho_times_the_waterplane_area() {
    let hull = wigley(41, 17);
    let water = Water::<f64>::default();
    let rho = water.density();
    // Drafts over the whole hull, keel to deck, between the vertex rows (spacing T/16).
    let drafts: Vec<f64> = (1..40).map(|k| k as f64 * 0.0061).collect();
    let rows = table(&hull, &drafts);
    for pair in rows.windows(2) {
        assert!(pair[1].displacement > pair[0].displacement);
    }
    // dΔ/dT = ρ·A_wp: central differences at draft T with steps ±δ (Δ is a cubic in T between
    // the rows, so the difference is off by δ²·Δ'''/6 only).
    let step = 1e-6;
    let mut worst: f64 = 0.0;
    for &t in &drafts {
        let r = table(&hull, &[t - step, t, t + step]);
        let derivative = (r[2].displacement - r[0].displacement) / (2.0 * step);
        let error = relative(derivative, rho * r[1].waterplane_area);
        worst = worst.max(error);
        assert!(
            error < 1e-6,
            "draft {t}: {derivative} vs {}",
            rho * r[1].waterplane_area
        );
        // TPC is the same derivative per centimetre, in tonnes.
        assert!(relative(r[1].tpc, derivative * 0.01 / 1000.0) < 1e-6);
    }
    eprintln!("dΔ/dT against ρ·A_wp: worst relative error {worst:.2e}");
}

#[test]
fn bad_drafts_are_errors_naming_the_entry() {
    let hull = block(4.0, 1.0, 2.0, 1, Vector3::zeros());
    let water = Water::default();
    let options = TableOptions::new();
    let draft_error = |drafts: &[f64]| match hull.hydrostatic_table(&water, drafts, &options) {
        Err(Error::InvalidDraft {
            index,
            height,
            reason,
            ..
        }) => {
            assert!((height - 1.0).abs() < 1e-15, "{height}");
            (index, reason)
        }
        other => panic!("{drafts:?}: {other:?}"),
    };
    assert_eq!(draft_error(&[0.2, -0.1]).0, 1);
    assert!(draft_error(&[-1e-300]).1.contains("negative"));
    assert_eq!(draft_error(&[0.2, 0.3, f64::NAN]).0, 2);
    assert_eq!(draft_error(&[f64::INFINITY]).0, 0);
    let (index, reason) = draft_error(&[0.5, 1.0 + 1e-12]);
    assert_eq!(index, 1);
    assert!(reason.contains("height"), "{reason}");
    let message = hull
        .hydrostatic_table(&water, &[0.5, 1.5], &options)
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("draft 1 (1.5 m)") && message.contains("1 m"),
        "{message}"
    );
    // The ends are accepted: the keel touching the surface, the body just under it.
    let rows = hull
        .hydrostatic_table(&water, &[0.0, 1.0], &options)
        .unwrap();
    assert_eq!(rows[0].displaced_volume, 0.0);
    assert_eq!((rows[0].bm_transverse, rows[0].mct), (0.0, 0.0));
    assert!((rows[1].displaced_volume - 8.0).abs() < 1e-14);
    assert_eq!(rows[1].waterplane_area, 0.0);
    for row in &rows {
        let h = &row.hydrostatics;
        assert!(
            [
                row.kb,
                row.km_transverse,
                row.lcb,
                row.lcf,
                row.tpc,
                row.mct
            ]
            .iter()
            .all(|x| x.is_finite())
                && h.stiffness.iter().all(|x| x.is_finite())
        );
    }
    assert!(
        hull.hydrostatic_table(&water, &[], &options)
            .unwrap()
            .is_empty()
    );
}

#[test]
fn bad_options_are_errors_naming_the_option() {
    let option = |e: Result<TableOptions<f64>, Error>| match e {
        Err(Error::InvalidTableOption { parameter, .. }) => parameter,
        other => panic!("{other:?}"),
    };
    let o = TableOptions::<f64>::new();
    assert_eq!(option(o.with_length(0.0)), "length");
    assert_eq!(option(o.with_length(f64::NAN)), "length");
    assert_eq!(option(o.with_length(-2.0)), "length");
    assert_eq!(
        option(o.with_longitudinal_axis(Vector3::zeros())),
        "longitudinal_axis"
    );
    assert_eq!(
        option(o.with_longitudinal_axis(Vector3::new(f64::NAN, 0.0, 0.0))),
        "longitudinal_axis"
    );
    assert_eq!(
        option(o.with_center_of_gravity(Point3::new(0.0, f64::INFINITY, 0.0))),
        "center_of_gravity"
    );
    let nan = UnitQuaternion::new_unchecked(buoyancy_core::nalgebra::Quaternion::new(
        f64::NAN,
        0.0,
        0.0,
        0.0,
    ));
    assert_eq!(option(o.with_rotation(nan)), "rotation");
    // The longitudinal axis along the vertical: no direction in the waterplane.
    let hull = block(4.0, 1.0, 2.0, 1, Vector3::zeros());
    let vertical = o.with_longitudinal_axis(Vector3::y()).unwrap();
    let e = hull
        .hydrostatic_table(&Water::default(), &[0.5], &vertical)
        .unwrap_err();
    assert!(
        matches!(
            e,
            Error::InvalidTableOption {
                parameter: "longitudinal_axis",
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn f32_agrees_with_f64() {
    let (v, t) = primitives::wigley_hull::<f32>(LENGTH, BEAM, DRAFT, FREEBOARD, 41, 17).unwrap();
    let hull32 = Mesh::new(v, t).unwrap();
    let hull64 = wigley(41, 17);
    let drafts = [0.05, DRAFT, 0.2];
    let drafts32 = drafts.map(|d| d as f32);
    let a = hull32
        .hydrostatic_table(&Water::default(), &drafts32, &TableOptions::new())
        .unwrap();
    let b = table(&hull64, &drafts);
    for (a, b) in a.iter().zip(&b) {
        for (x, y) in [
            (a.displaced_volume, b.displaced_volume),
            (a.kb, b.kb),
            (a.bm_transverse, b.bm_transverse),
            (a.bm_longitudinal, b.bm_longitudinal),
            (a.waterplane_area, b.waterplane_area),
            (a.mct, b.mct),
        ] {
            assert!(relative(x as f64, y) < 1e-4, "{x} {y}");
        }
    }
}
