//! The equilibrium solver and the righting-arm curve against analytic results: the draft of a
//! box for a mass, its heel from an off-center weight and its angle of loll, the wall-sided GZ
//! formula, a circular cylinder, the square log's attitudes, the energy of the GZ curve and its
//! slope at upright, a waterline through a vertex row, typed errors and `f32`.
//!
//! Boxes are `length` (x, the longitudinal axis) × `depth` (y, up) × `beam` (z) in the default
//! water (y up, level 0). Then `e₁ = x` and `e₂ = n × e₁ = −z`: a positive heel (right-handed
//! about x) puts the `+z` side down, and a center of gravity moved towards `+z` heels the box
//! positively.
//!
//! The wall-sided relations: in the body's transverse section (`y'` along `e₂`, `z'` up from
//! the keel), a box of beam `B` and draft `T` heeled by `φ` while its deck edge stays dry and
//! its bilge wet displaces the same volume about the same centerline draft `T`, and its center
//! of buoyancy moves to `y'_B = −BM·tan φ`, `z'_B = KB + ½·BM·tan²φ` (`KB = T/2`,
//! `BM = B²/(12T)`). A body point `(y', z')` lies at `y' cos φ − z' sin φ` along `e₂` in the
//! world. With `G = (a, KG)` (`a = G·e₂`), `GZ = −(B − G)·e₂ = sin φ·(GM + ½·BM·tan²φ) − a·cos φ`,
//! `GM = KB + BM − KG`. The equilibrium `GZ = 0` is
//! `tan φ·(GM + ½·BM·tan²φ) = a` (the heel from the offset `a` along `e₂`; here `a = −z_G`),
//! and with `a = 0`, `GM < 0`: `tan φ = √(−2·GM/BM)`, the angle of loll.

mod common;

use std::f64::consts::PI;

use buoyancy_core::hydrostatics::{EquilibriumOptions, LoadingCondition, Trim};
use buoyancy_core::nalgebra::{Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::{Error, Mesh, Method, Pose, Water, mesh::primitives};

/// A box `length` (x) × `depth` (y, up) × `beam` (z) about the origin, each face split in
/// `n × n` squares.
fn block(length: f64, depth: f64, beam: f64, n: usize) -> Mesh<f64> {
    let (v, t) = primitives::cube(n).unwrap();
    Mesh::new(v, t)
        .unwrap()
        .scaled(&Vector3::new(length, depth, beam))
        .unwrap()
}

fn loading(g: Point3<f64>, mass: f64) -> LoadingCondition<f64> {
    LoadingCondition::new(g).unwrap().with_mass(mass).unwrap()
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// The root of `f` in `[a, b]` (a sign change) by bisection to round-off.
fn root(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let fa = f(a);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if (f(m) > 0.0) == (fa > 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// The box of the wall-sided tests: 4 × 1.5 × 2 m, vertex rows every 0.5 m in depth.
const BOX: (f64, f64, f64) = (4.0, 1.5, 2.0);

fn test_box() -> Mesh<f64> {
    block(BOX.0, BOX.1, BOX.2, 3)
}

/// The mass that floats the box at draft `t` in fresh water.
fn box_mass(t: f64) -> f64 {
    1000.0 * BOX.0 * BOX.2 * t
}

/// `G` at `kg` above the keel, `z` across.
fn box_g(kg: f64, z: f64) -> Point3<f64> {
    Point3::new(0.0, kg - BOX.1 / 2.0, z)
}

#[test]
fn box_draft_for_a_mass_is_m_over_rho_l_b() {
    let hull = test_box();
    let water = Water::default();
    let mut worst: f64 = 0.0;
    for t in [0.1, 0.37, 0.6, 0.75, 1.1] {
        let m = box_mass(t);
        // G low enough to be stable at every draft.
        let e = hull
            .equilibrium(&water, &loading(box_g(0.2, 0.0), m))
            .unwrap();
        let error = relative(e.draft, t);
        worst = worst.max(error);
        assert!(error < 1e-10, "T = {t}: draft {} ({error:.1e})", e.draft);
        assert!(e.heel.abs() < 1e-10 && e.trim.abs() < 1e-10, "{e:?}");
        assert!(e.stable, "{:?}", e.stiffness_eigenvalues);
        assert!(e.residual.amax() <= EquilibriumOptions::<f64>::default().tolerance);
        assert!(relative(e.hydrostatics.displaced_volume * 1000.0, m) < 1e-10);
        // Upright, the roll eigenvalue is GM_T/L (the smaller tilt one for this box).
        let gm = e.hydrostatics.gm_transverse;
        assert!(relative(e.stiffness_eigenvalues[0], gm / e.length) < 1e-8);
    }
    eprintln!("box draft for a mass: worst relative error {worst:.1e}");
}

#[test]
fn box_heel_from_a_transverse_offset_of_g() {
    let hull = test_box();
    let water = Water::default();
    let (t, kg) = (0.6, 0.7);
    let (b, d) = (BOX.2, BOX.1);
    let (kb, bm) = (t / 2.0, b * b / (12.0 * t));
    let gm = kb + bm - kg;
    let mut worst: f64 = 0.0;
    for offset in [0.01, 0.05, -0.08] {
        let e = hull
            .equilibrium(&water, &loading(box_g(kg, offset), box_mass(t)))
            .unwrap();
        // a = G·e₂ = −z_G: tan φ (GM + ½ BM tan²φ) = z_G.
        let tan = root(|x| x * (gm + 0.5 * bm * x * x) - offset, -1.0, 1.0);
        assert!(
            tan.abs() < (2.0 * t / b).min(2.0 * (d - t) / b),
            "not wall-sided"
        );
        let error = (e.heel - tan.atan()).abs() / tan.atan().abs();
        worst = worst.max(error);
        assert!(
            error < 1e-8,
            "offset {offset}: heel {} against {}",
            e.heel,
            tan.atan()
        );
        assert!(
            e.heel * offset > 0.0,
            "the +z side goes down for a positive heel"
        );
        assert!(e.trim.abs() < 1e-10);
        // The centerline draft is unchanged: the keel corner is at T + (B/2) tan φ.
        assert!((e.draft - (t + b / 2.0 * tan.abs()) * e.heel.cos()).abs() < 1e-9);
        // B on the vertical through G.
        let h = &e.hydrostatics;
        let lever = h.center_of_buoyancy - h.center_of_gravity;
        assert!((lever - water.normal().into_inner() * lever.y).norm() < 1e-9);
    }
    eprintln!("box heel from an offset G: worst relative error {worst:.1e}");
}

#[test]
fn box_trim_from_a_longitudinal_offset_of_g() {
    // The same wall-sided relation in pitch, about e₂ with the length for the beam:
    // tan θ·(GM_L + ½·BM_L·tan²θ) = x_G (positive trim puts the +x end down).
    let hull = test_box();
    let water = Water::default();
    let (t, kg) = (0.6, 0.7);
    let (length, d) = (BOX.0, BOX.1);
    let bm = length * length / (12.0 * t);
    let gm = t / 2.0 + bm - kg;
    let mut worst: f64 = 0.0;
    for offset in [0.05, -0.2] {
        let g = Point3::new(offset, kg - d / 2.0, 0.0);
        let e = hull.equilibrium(&water, &loading(g, box_mass(t))).unwrap();
        let tan = root(|x| x * (gm + 0.5 * bm * x * x) - offset, -1.0, 1.0);
        assert!(tan.abs() < (2.0 * t / length).min(2.0 * (d - t) / length));
        let error = (e.trim - tan.atan()).abs() / tan.atan().abs();
        worst = worst.max(error);
        assert!(
            error < 1e-8,
            "offset {offset}: trim {} against {}",
            e.trim,
            tan.atan()
        );
        assert!(e.trim * offset > 0.0 && e.heel.abs() < 1e-10 && e.stable);
    }
    eprintln!("box trim from an offset G: worst relative error {worst:.1e}");
}

#[test]
fn start_pose_keeps_yaw_and_the_vertical_through_g() {
    // z up, surface at z = 0.3, a box 4 (x) × 2 (y) × 1.5 (z, up); the start pose yawed by
    // 0.7 rad about z and far from the origin. The heel from a transverse offset is that of
    // the y-up box: in this frame e₂ = n × e₁ = y, so G towards −y heels positively.
    let (v, t) = primitives::cube::<f64>(3).unwrap();
    let hull = Mesh::new(v, t)
        .unwrap()
        .scaled(&Vector3::new(BOX.0, BOX.2, BOX.1))
        .unwrap();
    let water = Water::new(1000.0, 9.81, Vector3::z(), 0.3).unwrap();
    let g = Point3::new(0.0, -0.05, 0.7 - BOX.1 / 2.0);
    let start = Pose::from_parts(
        Translation3::new(120.0, -40.0, 7.0),
        UnitQuaternion::from_scaled_axis(Vector3::z() * 0.7),
    );
    let options = EquilibriumOptions::default().with_start(start);
    let e = hull
        .equilibrium_with(&water, &loading(g, box_mass(0.6)), &options)
        .unwrap();
    let reference = test_box()
        .equilibrium(&Water::default(), &loading(box_g(0.7, 0.05), box_mass(0.6)))
        .unwrap();
    let g_start = start * g;
    let g_rest = e.pose * g;
    let errors = [
        (e.heel - reference.heel).abs(),
        e.trim.abs(),
        (e.draft - reference.draft).abs(),
        (g_rest.x - g_start.x).abs() + (g_rest.y - g_start.y).abs(),
    ];
    // Yaw kept: the longitudinal axis still points along the start's, seen from above.
    let axis = e.pose.rotation * Vector3::x();
    let yaw = axis.y.atan2(axis.x);
    eprintln!("start pose: {errors:?}, yaw {yaw}");
    assert!(errors.iter().all(|x| *x < 1e-9), "{errors:?}");
    assert!((yaw - 0.7).abs() < 1e-12);
    assert!(e.heel > 0.0);
}

#[test]
fn angle_of_loll_when_gm_is_negative() {
    let hull = test_box();
    let water = Water::default();
    let (t, kg) = (0.6, 0.9);
    let (b, bm) = (BOX.2, BOX.2 * BOX.2 / (12.0 * 0.6));
    let g = box_g(kg, 0.0);
    let m = box_mass(t);
    // Upright is unstable.
    let upright = Pose::from_parts(
        Translation3::new(0.0, BOX.1 / 2.0 - t, 0.0),
        UnitQuaternion::identity(),
    );
    let gm = hull
        .hydrostatics(&upright, &water, &loading(g, m))
        .unwrap()
        .gm_transverse;
    assert!(gm < 0.0 && relative(gm, t / 2.0 + bm - kg) < 1e-13);
    let e = hull.equilibrium(&water, &loading(g, m)).unwrap();
    let tan = (-2.0 * gm / bm).sqrt();
    assert!(tan < 2.0 * t / b, "the bilge stays wet");
    let error = relative(e.heel.tan().abs(), tan);
    eprintln!(
        "angle of loll: tan φ = {:.6} against {tan:.6} (error {error:.1e}), {} restart(s), {} \
         iterations",
        e.heel.tan(),
        e.restarts,
        e.iterations
    );
    assert!(error < 1e-8);
    assert!(e.restarts >= 1);
    assert!(e.stable, "{:?}", e.stiffness_eigenvalues);
    // At the angle of loll the stiffness in roll is ρgV·BM·tan²φ/cos φ... positive.
    assert!(e.stiffness_eigenvalues[0] > 0.0);
}

#[test]
fn wall_sided_box_gz_is_sin_phi_gm_plus_half_bm_tan2() {
    let hull = test_box();
    let water = Water::default();
    let (t, kg) = (0.6, 0.7);
    let (b, d) = (BOX.2, BOX.1);
    let bm = b * b / (12.0 * t);
    let gm = t / 2.0 + bm - kg;
    // The deck edge stays dry and the bilge wet while tan φ < 2T/B = 0.6.
    let heels: Vec<f64> = (0..=20).map(|k| 0.5 * k as f64 / 20.0).collect();
    assert!(heels[20].tan() < (2.0 * t / b).min(2.0 * (d - t) / b));
    for trim in [Trim::Free, Trim::Fixed(0.0)] {
        let curve = hull
            .gz_curve(
                &water,
                &loading(box_g(kg, 0.0), box_mass(t)),
                &heels,
                trim,
                &EquilibriumOptions::default(),
            )
            .unwrap();
        let scale = curve.points.iter().map(|p| p.gz.abs()).fold(0.0, f64::max);
        let mut worst: f64 = 0.0;
        for p in &curve.points {
            let phi = p.heel;
            let analytic = phi.sin() * (gm + 0.5 * bm * phi.tan().powi(2));
            worst = worst.max((p.gz - analytic).abs() / scale);
            assert!(p.trim.abs() < 1e-10);
            assert!(relative(p.draft, (t + b / 2.0 * phi.tan()) * phi.cos()) < 1e-9);
        }
        eprintln!("wall-sided GZ ({trim:?}): worst error {worst:.1e} of max GZ");
        assert!(worst < 1e-10);
    }
}

/// A prism of `sides` sides inscribed in a circle of `radius` about the x axis, `length`
/// long, a vertex at the bottom.
fn cylinder(radius: f64, length: f64, sides: usize) -> Mesh<f64> {
    let mut v = Vec::new();
    for end in [-0.5, 0.5] {
        for k in 0..sides {
            let a = 2.0 * PI * k as f64 / sides as f64 - PI / 2.0;
            v.push(Point3::new(
                end * length,
                radius * a.cos(),
                radius * a.sin(),
            ));
        }
    }
    let n = sides as u32;
    v.push(Point3::new(-0.5 * length, 0.0, 0.0));
    v.push(Point3::new(0.5 * length, 0.0, 0.0));
    let mut t = Vec::new();
    for k in 0..n {
        let k1 = (k + 1) % n;
        t.push([k, k1, n + k1]);
        t.push([k, n + k1, n + k]);
        t.push([2 * n, k1, k]);
        t.push([2 * n + 1, n + k, n + k1]);
    }
    let mesh = Mesh::new(v, t).unwrap();
    assert!(!mesh.was_reoriented());
    mesh
}

#[test]
fn horizontal_circular_cylinder_gz_is_r_minus_kg_sin_phi() {
    let (radius, length, kg) = (0.5, 3.0, 0.25);
    let water = Water::default();
    let heels: Vec<f64> = (0..=33).map(|k| 0.1 * k as f64).collect();
    let mut previous: Option<f64> = None;
    for sides in [32, 64, 128] {
        let hull = cylinder(radius, length, sides);
        let m = 0.5 * 1000.0 * hull.volume();
        let g = Point3::new(0.0, kg - radius, 0.0);
        let curve = hull
            .gz_curve(
                &water,
                &loading(g, m),
                &heels,
                Trim::Free,
                &EquilibriumOptions::default(),
            )
            .unwrap();
        let worst = curve
            .points
            .iter()
            .map(|p| (p.gz - (radius - kg) * p.heel.sin()).abs() / (radius - kg))
            .fold(0.0, f64::max);
        let (phi_max, gz_max) = curve.max_gz().unwrap();
        let vanishing = curve.vanishing_angle().unwrap();
        let area = curve.area_up_to(PI);
        eprintln!(
            "cylinder, {sides} sides: worst GZ error {worst:.2e} of R − KG; max GZ {gz_max:.5} \
             at {phi_max:.4} rad; vanishing at {vanishing:.5}; area to π {area:.5} (2(R − KG) = \
             {:.5}); ratio {:.2}",
            2.0 * (radius - kg),
            previous.map_or(f64::NAN, |p| p / worst)
        );
        assert!(worst < 4.0 / (sides * sides) as f64, "{worst}");
        if let Some(p) = previous {
            assert!(p / worst > 3.0, "error does not shrink: {p} then {worst}");
        }
        previous = Some(worst);
        assert!((phi_max - PI / 2.0).abs() < 0.02);
        assert!(relative(gz_max, radius - kg) < 5.0 / (sides * sides) as f64 + 1e-3);
        assert!((vanishing - PI).abs() < 0.01);
        // Trapezoids of 0.1 rad: −h²/12·∫ GZ'' = h²/6·(R − KG) relative error of 8e-4.
        assert!(relative(area, 2.0 * (radius - kg)) < 2e-3);
        assert!(curve.points.iter().all(|p| p.trim.abs() < 1e-9));
    }
}

/// The square log of the tests: 1 × 1 in section, 3 long (x).
fn log() -> Mesh<f64> {
    block(3.0, 1.0, 1.0, 2)
}

#[test]
fn square_log_upright_is_stable_only_outside_the_middle_densities() {
    let hull = log();
    let water = Water::default();
    let low = (3.0 - 3f64.sqrt()) / 6.0;
    let high = (3.0 + 3f64.sqrt()) / 6.0;
    // GM at the upright draft changes sign at the thresholds.
    for (s, stable) in [
        (low - 0.005, true),
        (low + 0.005, false),
        (high - 0.005, false),
        (high + 0.005, true),
    ] {
        let upright = Pose::from_parts(
            Translation3::new(0.0, 0.5 - s, 0.0),
            UnitQuaternion::identity(),
        );
        let gm = hull
            .hydrostatics(&upright, &water, &loading(Point3::origin(), s * 3000.0))
            .unwrap()
            .gm_transverse;
        assert_eq!(gm > 0.0, stable, "s = {s}: GM {gm}");
    }
    // The solver lands on the stable attitude: upright, the wall-sided angle of loll, or a
    // corner down.
    for s in [0.1, 0.2, 0.23, 0.35, 0.5, 0.65, 0.77, 0.8, 0.9] {
        let e = hull
            .equilibrium(&water, &loading(Point3::origin(), s * 3000.0))
            .unwrap();
        let heel = e.heel.abs();
        let expected = if !(low..=high).contains(&s) {
            0.0
        } else if (0.29..=0.71).contains(&s) {
            PI / 4.0
        } else {
            // Wall-sided (tan φ = √(−2GM/BM) with T = s or 1 − s: GM = s/2 + 1/(12s) − 1/2).
            let t = s.min(1.0 - s);
            let gm = t / 2.0 + 1.0 / (12.0 * t) - 0.5;
            (-2.0 * gm * 12.0 * t).sqrt().atan()
        };
        eprintln!(
            "square log s = {s}: heel {:.6} (expected {expected:.6}), trim {:.1e}, {} \
             restart(s), eigenvalues {:?}",
            e.heel,
            e.trim,
            e.restarts,
            e.stiffness_eigenvalues.map(|x| format!("{x:.3e}"))
        );
        assert!((heel - expected).abs() < 1e-8, "s = {s}: {heel}");
        assert!(e.stable && e.trim.abs() < 1e-9);
        assert!(relative(e.hydrostatics.displaced_volume, 3.0 * s) < 1e-10);
    }
}

#[test]
fn integral_of_gz_is_the_change_of_potential() {
    let hull = test_box();
    let water = Water::default();
    let (t, kg) = (0.6, 0.7);
    let g = box_g(kg, 0.0);
    let heels: Vec<f64> = (0..=240).map(|k| 1.2 * k as f64 / 240.0).collect();
    let curve = hull
        .gz_curve(
            &water,
            &loading(g, box_mass(t)),
            &heels,
            Trim::Free,
            &EquilibriumOptions::default(),
        )
        .unwrap();
    // U/(mg) = z_G − z_B with ρV = m.
    let potential = |pose: &Pose<f64>| {
        let b = hull.buoyancy(pose, &water, Method::Exact).unwrap();
        water.height(&(pose * g)) - water.height(&b.center_of_buoyancy)
    };
    let first = &curve.points[0];
    let h = heels[1] - heels[0];
    let gz: Vec<f64> = curve.points.iter().map(|p| p.gz).collect();
    // GZ' by second-order differences (one-sided at the start).
    let slope = |k: usize| {
        if k == 0 {
            (-3.0 * gz[0] + 4.0 * gz[1] - gz[2]) / (2.0 * h)
        } else if k + 1 == gz.len() {
            (3.0 * gz[k] - 4.0 * gz[k - 1] + gz[k - 2]) / (2.0 * h)
        } else {
            (gz[k + 1] - gz[k - 1]) / (2.0 * h)
        }
    };
    let mut worst: f64 = 0.0;
    for k in [60, 120, 180, 240] {
        let p = &curve.points[k];
        let du = potential(&p.pose) - potential(&first.pose);
        let area = curve.area_up_to(p.heel);
        // The trapezoidal rule's leading error, +h²/12·(GZ'(φ) − GZ'(0)) (Euler–Maclaurin):
        // the raw difference must be of its size, and removing it must leave far less.
        let leading = h * h / 12.0 * (slope(k) - slope(0));
        let (raw, corrected) = (area - du, area - leading - du);
        eprintln!(
            "energy to {:.2} rad: ∫GZ = {area:.9}, ΔU/mg = {du:.9}: trapezoid {:.1e}, \
             Euler–Maclaurin estimate of it {:.1e}, corrected {:.1e} (relative)",
            p.heel,
            raw / du,
            leading / du,
            corrected / du
        );
        assert!(raw.abs() <= 1.5 * leading.abs() + 1e-12, "{raw} {leading}");
        worst = worst.max((corrected / du).abs());
    }
    assert!(worst < 1e-6, "{worst}");
    assert_eq!(curve.area(), curve.area_up_to(1.2));
}

#[test]
fn slope_of_gz_at_upright_is_gm() {
    let (length, beam, draft) = (2.5, 0.25, 0.15625);
    let (v, t) = primitives::wigley_hull::<f64>(length, beam, draft, 0.1, 81, 33).unwrap();
    let hull = Mesh::new(v, t).unwrap();
    let water = Water::default();
    let volume = hull
        .buoyancy(&Pose::identity(), &water, Method::Exact)
        .unwrap()
        .submerged_volume;
    let l = loading(Point3::new(0.0, -0.06, 0.0), 0.9 * 1000.0 * volume);
    let e = hull.equilibrium(&water, &l).unwrap();
    let gm = e.hydrostatics.gm_transverse;
    assert!(e.heel.abs() < 1e-10 && gm > 0.0);
    let h = 1e-3;
    let curve = hull
        .gz_curve(
            &water,
            &l,
            &[-h, 0.0, h],
            Trim::Free,
            &EquilibriumOptions::default(),
        )
        .unwrap();
    let slope = (curve.points[2].gz - curve.points[0].gz) / (2.0 * h);
    let error = relative(slope, gm);
    eprintln!("dGZ/dφ at upright {slope:.8} against GM {gm:.8}: {error:.1e}");
    // Central difference: GZ'''(0)·h²/6 ≈ (BM/2 + ...)·1e-6 of GM ≈ 0.035.
    assert!(error < 1e-4, "{error}");
    assert!(curve.points[1].gz.abs() < 1e-9 * length);
}

#[test]
fn waterline_through_a_vertex_row_equals_a_hair_above() {
    // Rows at y = −1, −0.5, 0, 0.5, 1 about the center: draft 1.5 puts the waterline on one.
    let (length, beam, depth, draft) = (3.0, 1.2, 2.0, 1.5);
    let hull = block(length, depth, beam, 4);
    let water = Water::default();
    let g = Point3::new(0.0, -0.6, 0.0);
    let m = 1000.0 * length * beam * draft;
    let hair = 1e-9;
    let on = hull.equilibrium(&water, &loading(g, m)).unwrap();
    let above = hull
        .equilibrium(&water, &loading(g, m * (1.0 + hair / draft)))
        .unwrap();
    // The box's figures at draft T with G on the centerline, KG = 0.4.
    let analytic = |t: f64| {
        let kg = g.y + depth / 2.0;
        [
            t,
            t / 2.0 + beam * beam / (12.0 * t) - kg,
            t / 2.0 + length * length / (12.0 * t) - kg,
        ]
    };
    let mut worst: f64 = 0.0;
    for (e, t) in [(&on, draft), (&above, draft + hair)] {
        let h = &e.hydrostatics;
        let a = analytic(t);
        let errors = [
            relative(e.draft, a[0]),
            relative(h.gm_transverse, a[1]),
            relative(h.gm_longitudinal, a[2]),
            relative(h.waterplane.area, length * beam),
            e.heel.abs(),
            e.trim.abs(),
        ];
        assert!(errors.iter().all(|x| *x < 1e-12), "{errors:?}");
        worst = errors.iter().cloned().fold(worst, f64::max);
    }
    eprintln!(
        "vertex row and 1e-9 above: worst error {worst:.1e}; drafts differ by {:.3e} m",
        above.draft - on.draft
    );
    assert!((above.draft - on.draft - hair).abs() < 1e-14);
    assert!(on.stable && above.stable);
}

#[test]
fn errors_are_typed() {
    let hull = test_box();
    let water = Water::default();
    let g = box_g(0.5, 0.0);
    let capacity = 1000.0 * hull.volume();
    match hull.equilibrium(&water, &loading(g, capacity * 1.001)) {
        Err(e @ Error::TooHeavyToFloat { .. }) => {
            assert!(e.to_string().contains("does not float"), "{e}")
        }
        other => panic!("{other:?}"),
    }
    // At neutral buoyancy, and within the tolerance of it, no draft (once: a draft above the
    // hull's height with a residual of 1e-15).
    for mass in [capacity, capacity * (1.0 - 1e-12), capacity * (1.0 - 1e-15)] {
        assert!(
            matches!(
                hull.equilibrium(&water, &loading(g, mass)),
                Err(Error::TooHeavyToFloat { .. })
            ),
            "mass {mass} of capacity {capacity}"
        );
    }
    // Just outside the tolerance it floats, within the hull.
    let nearly = hull
        .equilibrium(&water, &loading(g, capacity * (1.0 - 1e-8)))
        .unwrap();
    assert!(nearly.draft <= BOX.1, "{} > {}", nearly.draft, BOX.1);
    for l in [LoadingCondition::new(g).unwrap(), loading(g, 0.0)] {
        match hull.equilibrium(&water, &l) {
            Err(e @ Error::InvalidMass { .. }) => assert!(e.to_string().contains("mass"), "{e}"),
            other => panic!("{other:?}"),
        }
    }
    assert!(matches!(
        LoadingCondition::new(g).unwrap().with_mass(f64::NAN),
        Err(Error::InvalidLoading {
            parameter: "mass",
            ..
        })
    ));
    let l = loading(g, box_mass(0.6));
    let nan_pose = Pose::from_parts(
        Translation3::new(0.0, f64::NAN, 0.0),
        UnitQuaternion::identity(),
    );
    assert!(matches!(
        hull.equilibrium_with(
            &water,
            &l,
            &EquilibriumOptions::default().with_start(nan_pose)
        ),
        Err(Error::InvalidPose { .. })
    ));
    for tolerance in [f64::NAN, 0.0, -1.0, 0.5] {
        assert!(matches!(
            hull.equilibrium_with(
                &water,
                &l,
                &EquilibriumOptions::default().with_tolerance(tolerance)
            ),
            Err(Error::InvalidSolverOption {
                parameter: "tolerance",
                ..
            })
        ));
    }
    let no_gravity = Water::new(1000.0, 0.0, Vector3::y(), 0.0).unwrap();
    assert!(matches!(
        hull.equilibrium(&no_gravity, &l),
        Err(Error::InvalidWater {
            parameter: "gravity",
            ..
        })
    ));
    // Never a silent return: one iteration does not heel the box with G off center.
    let off = loading(box_g(0.7, 0.05), box_mass(0.6));
    let options = EquilibriumOptions {
        max_iterations: 1,
        ..EquilibriumOptions::default()
    };
    match hull.equilibrium_with(&water, &off, &options) {
        Err(
            e @ Error::NoConvergence {
                iterations: 1,
                residual,
                ..
            },
        ) => {
            assert!(residual > options.tolerance && residual.is_finite());
            assert!(e.to_string().contains("did not converge"), "{e}");
        }
        other => panic!("{other:?}"),
    }
    for heels in [
        &[][..],
        &[0.1, 0.1][..],
        &[0.0, f64::NAN][..],
        &[0.2, 0.1][..],
    ] {
        assert!(matches!(
            hull.gz_curve(
                &water,
                &l,
                heels,
                Trim::Free,
                &EquilibriumOptions::default()
            ),
            Err(Error::InvalidSolverOption {
                parameter: "heels",
                ..
            })
        ));
    }
    assert!(matches!(
        hull.gz_curve(
            &water,
            &l,
            &[0.0],
            Trim::Fixed(f64::INFINITY),
            &EquilibriumOptions::default()
        ),
        Err(Error::InvalidSolverOption {
            parameter: "trim",
            ..
        })
    ));
}

#[test]
fn f32_equilibrium_agrees_with_f64() {
    let (v, t) = primitives::cube::<f32>(3).unwrap();
    let hull = Mesh::new(v, t)
        .unwrap()
        .scaled(&Vector3::new(4.0, 1.5, 2.0))
        .unwrap();
    let water = Water::<f32>::default();
    let g = Point3::new(0.0f32, -0.05, 0.05);
    let l = LoadingCondition::new(g)
        .unwrap()
        .with_mass(4800.0f32)
        .unwrap();
    let e32 = hull.equilibrium(&water, &l).unwrap();
    let e64 = test_box()
        .equilibrium(&Water::default(), &loading(box_g(0.7, 0.05), box_mass(0.6)))
        .unwrap();
    let errors = [
        (e32.heel as f64 - e64.heel).abs() / e64.heel.abs(),
        (e32.draft as f64 - e64.draft).abs() / e64.draft,
    ];
    eprintln!(
        "f32: heel {} draft {} ({} iterations), against f64: {:?}",
        e32.heel,
        e32.draft,
        e32.iterations,
        errors.map(|x| format!("{x:.1e}"))
    );
    assert!(errors.iter().all(|e| *e < 1e-4), "{errors:?}");
    assert!(e32.stable);
    assert!(e32.residual.amax() <= EquilibriumOptions::<f32>::default().tolerance);
}

#[test]
fn every_test_mesh_comes_to_rest_with_b_under_g() {
    // Densities and centers of gravity across the meshes (the samples too when present): the
    // solver either converges to a stable state with B on the vertical through G and ρV = m,
    // or reports why; no mesh may fail.
    let water = Water::default();
    let mut worst: f64 = 0.0;
    let (mut count, mut most) = (0, 0);
    for (name, mesh) in common::all_meshes() {
        let r = mesh.bounding_radius();
        for (k, s) in [0.2, 0.45, 0.7].into_iter().enumerate() {
            let offset = Vector3::new(0.03, -0.15 + 0.05 * k as f64, -0.02 * k as f64) * r;
            let g = mesh.centroid() + offset;
            let m = s * 1000.0 * mesh.volume();
            let e = mesh
                .equilibrium(&water, &loading(g, m))
                .unwrap_or_else(|e| panic!("{name}, s = {s}: {e}"));
            let h = &e.hydrostatics;
            let lever = h.center_of_buoyancy - h.center_of_gravity;
            let n = water.normal().into_inner();
            let horizontal = (lever - n * n.dot(&lever)).norm() / e.length;
            worst = worst.max(horizontal).max(e.residual.amax());
            most = most.max(e.iterations);
            count += 1;
            assert!(horizontal < 1e-9, "{name}, s = {s}: {horizontal:.1e}");
            assert!(relative(h.displaced_volume * 1000.0, m) < 1e-9);
            assert!(e.stable, "{name}, s = {s}: {:?}", e.stiffness_eigenvalues);
        }
    }
    eprintln!(
        "{count} equilibria: worst relative residual or lever {worst:.1e}, at most {most} \
         iterations"
    );
}

/// `positive_stability` tells the two curves without an angle of vanishing stability apart: one
/// still positive at its last heel, one never positive (a center of gravity far above the
/// metacenter).
#[test]
fn positive_stability_tells_beyond_from_never() {
    use buoyancy_core::hydrostatics::PositiveStability;
    let hull = test_box();
    let water = Water::default();
    let mass = box_mass(0.75);
    let curve = |kg: f64, last_deg: f64| {
        let heels: Vec<f64> = (0..=10)
            .map(|i| (last_deg * i as f64 / 10.0).to_radians())
            .collect();
        hull.gz_curve(
            &water,
            &loading(Point3::new(0.0, kg - 0.5 * BOX.1, 0.0), mass),
            &heels,
            Trim::Free,
            &EquilibriumOptions::default(),
        )
        .unwrap()
    };
    // Low G, heels to 10°: GZ positive throughout.
    let low = curve(0.3, 10.0);
    assert!(low.points[1..].iter().all(|p| p.gz > 0.0));
    assert_eq!(low.vanishing_angle(), None);
    assert_eq!(low.positive_stability(), PositiveStability::BeyondLastHeel);
    // G just above the box's center (KG 0.78 m, KM 0.82 m upright and inverted), heels to
    // 180°: stable upright and inverted, so GZ vanishes between, at `vanishing_angle`.
    let full = curve(0.78, 180.0);
    let vanishing = full.vanishing_angle().unwrap();
    assert!(vanishing > 0.0 && vanishing < PI, "{vanishing}");
    assert_eq!(
        full.positive_stability(),
        PositiveStability::VanishesAt(vanishing)
    );
    // G 6 m above the keel: GZ negative at every heel to 90°.
    let high = curve(6.0, 90.0);
    assert!(high.points[1..].iter().all(|p| p.gz < 0.0));
    assert_eq!(high.vanishing_angle(), None);
    assert_eq!(high.positive_stability(), PositiveStability::NotPositive);
}

/// A round-off GZ at the upright (4e-18 m, as a capsizing box's curve has) is zero, not the
/// start of a range of stability that vanishes at 0° (once printed as such).
#[test]
fn round_off_at_the_upright_is_not_positive_stability() {
    use buoyancy_core::hydrostatics::{GzCurve, GzPoint, PositiveStability};
    let point = |heel_deg: f64, gz: f64| GzPoint {
        heel: heel_deg.to_radians(),
        trim: 0.0,
        draft: 0.5,
        gz,
        pose: Pose::identity(),
        residual: Vector3::zeros(),
    };
    let mut curve = GzCurve {
        points: vec![point(0.0, 4.3e-18), point(2.5, -0.09), point(5.0, -0.18)],
        flooding: None,
        iterations: 0,
    };
    assert_eq!(curve.vanishing_angle(), None);
    assert_eq!(curve.positive_stability(), PositiveStability::NotPositive);
    // A real positive GZ at the first heel does vanish, between the points.
    curve.points[0].gz = 0.09;
    let vanishing = curve.vanishing_angle().unwrap().to_degrees();
    assert!((vanishing - 1.25).abs() < 1e-12, "{vanishing}");
    assert_eq!(
        curve.positive_stability(),
        PositiveStability::VanishesAt(vanishing.to_radians())
    );
}
