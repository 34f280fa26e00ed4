//! Fuzzing of the constructor and the evaluation with arbitrary input: whatever comes in,
//! `Mesh::new` returns a mesh or a typed error, and a query returns finite numbers or a typed
//! error; nothing panics and nothing non-finite is handed back. The same for every shape
//! generator (whose shapes `Mesh::new` must accept), the parsers on arbitrary bytes, Airy waves
//! of arbitrary components under both pressures, and the solvers at arbitrary loading: each
//! `Err` is checked to be one of the typed errors of its input.

use buoyancy_core::nalgebra::{Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::query::{Pressure, Sea};
use std::sync::atomic::{AtomicUsize, Ordering};

use buoyancy_core::{Buoyancy, Error, Mesh, Method, Pose, Water, mesh::primitives};
use proptest::prelude::*;
use proptest::test_runner::TestRunner;

fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => -2.0..2.0f64,
        1 => prop::num::f64::ANY,
        1 => prop_oneof![Just(0.0), Just(1e300), Just(-1e-300), Just(f64::MAX)],
    ]
}

/// Every method returns finite numbers, or the errors a valid mesh may give for this pose and
/// water: a pose that is not finite, or a result that overflows. Anything else fails.
fn check_query(mesh: &Mesh<f64>, pose: &Pose<f64>, water: &Water<f64>) {
    for method in Method::ALL {
        match mesh.buoyancy(pose, water, method) {
            Ok(b) => assert!(all_finite(&b), "{method}: {b:?}"),
            Err(Error::InvalidPose { .. } | Error::NonFiniteResult) => {}
            Err(e) => panic!("{method} on a valid mesh: {e}"),
        }
    }
}

/// Whether every number of `b` is finite.
fn all_finite(b: &Buoyancy<f64>) -> bool {
    [b.submerged_volume, b.wetted_area]
        .into_iter()
        .chain(b.center_of_buoyancy.iter().copied())
        .chain(b.force.iter().copied())
        .chain(b.torque.iter().copied())
        .all(f64::is_finite)
}

fn pose_from((tx, ty, tz, qx, qy, qz, qw): (f64, f64, f64, f64, f64, f64, f64)) -> Pose<f64> {
    let q = UnitQuaternion::new_unchecked(Quaternion::new(qw, qx, qy, qz));
    Pose::from_parts(Translation3::new(tx, ty, tz), q)
}

/// Index soups: half of them a closed cube with up to three of its indices overwritten (so that
/// valid meshes are reached, and near misses of every kind), half entirely random.
fn soup() -> impl Strategy<Value = Vec<[u32; 3]>> {
    let (_, cube) = primitives::cube::<f64>(1).unwrap();
    let edited =
        prop::collection::vec((0..12usize, 0..3usize, 0..10u32), 0..4).prop_map(move |edits| {
            let mut t = cube.clone();
            for (triangle, corner, index) in edits {
                t[triangle][corner] = index;
            }
            t
        });
    let random = prop::collection::vec((0..10u32, 0..10u32, 0..10u32), 0..20)
        .prop_map(|t| t.into_iter().map(|(a, b, c)| [a, b, c]).collect());
    prop_oneof![edited, random]
}

/// Random soups over the cube's 8 vertices (perturbed, sometimes to NaN or huge values) plus
/// two more: `Mesh::new` returns a mesh or a typed error, and a valid mesh answers every query.
/// At least one case in twenty must reach a valid mesh (about one in eleven does), or the test
/// checks little.
#[test]
fn arbitrary_soups() {
    let (cube, _) = primitives::cube::<f64>(1).unwrap();
    let valid = AtomicUsize::new(0);
    let cases = 2000;
    let strategy = (
        prop::collection::vec((coordinate(), coordinate(), coordinate()), 10),
        prop::collection::vec(prop_oneof![9 => Just(true), 1 => Just(false)], 10),
        soup(),
        (
            coordinate(),
            coordinate(),
            coordinate(),
            coordinate(),
            coordinate(),
            coordinate(),
            coordinate(),
        ),
    );
    let mut runner = TestRunner::new(ProptestConfig::with_cases(cases));
    runner
        .run(&strategy, |(random, keep, triangles, pose)| {
            let vertices: Vec<_> = (0..10)
                .map(|i| match (cube.get(i), keep[i]) {
                    (Some(p), true) => *p,
                    _ => Point3::new(random[i].0, random[i].1, random[i].2),
                })
                .collect();
            if let Ok(mesh) = Mesh::new(vertices, triangles) {
                valid.fetch_add(1, Ordering::Relaxed);
                assert!(mesh.volume().is_finite() && mesh.volume() > 0.0);
                check_query(&mesh, &pose_from(pose), &Water::default());
            }
            Ok(())
        })
        .unwrap();
    let valid = valid.into_inner();
    assert!(
        valid >= cases as usize / 20,
        "only {valid} of {cases} soups were valid meshes"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

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
        let (v, t) = primitives::cube::<f64>(2).unwrap();
        let v = v.iter().enumerate().map(|(i, p)| p + Vector3::new(noise[3 * i], noise[3 * i + 1], noise[3 * i + 2])).collect();
        let Ok(mesh) = Mesh::new(v, t) else { return Ok(()) };
        let Ok(water) = Water::new(density, 9.81, Vector3::new(normal.0, normal.1, normal.2), level) else { return Ok(()) };
        check_query(&mesh, &pose_from(pose), &water);
    }
}

/// A length parameter: usually plausible, sometimes zero, negative, huge or not a number.
fn length() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => 0.01..10.0f64,
        1 => prop::num::f64::ANY,
        1 => prop_oneof![Just(0.0), Just(-1.0), Just(1e300), Just(f64::MIN_POSITIVE)],
    ]
}

/// A count parameter: usually small, sometimes below the minimum or beyond what `u32` indices
/// or the memory can hold.
fn count() -> impl Strategy<Value = usize> {
    prop_oneof![
        8 => 0..24usize,
        2 => prop_oneof![Just(usize::MAX), Just(usize::MAX - 1), Just(1usize << 40)],
    ]
}

/// The errors a generator may give: a parameter out of range, or more than the memory holds.
fn shape_error(e: &Error) -> bool {
    matches!(e, Error::InvalidShape { .. } | Error::OutOfMemory { .. })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    /// Every generator, at arbitrary parameters: a shape that `Mesh::new` accepts (the
    /// generators make closed, consistently oriented meshes or say why not), whose volume is
    /// positive and whose queries answer, or a typed error naming the parameter.
    #[test]
    fn every_shape_generator_makes_a_valid_mesh_or_says_why_not(
        which in 0..9usize,
        (a, b, c, d) in (length(), length(), length(), length()),
        (m, n) in (count(), count()),
        (p, q) in (0..7u32, 0..7u32),
        pose in (coordinate(), coordinate(), coordinate(), coordinate(), coordinate(), coordinate(), coordinate()),
    ) {
        // The shape at counts of at most 48; the huge counts below, where they must be refused.
        let small = |k: usize| k.min(48);
        let made = match which {
            0 => primitives::cube::<f64>(small(m)),
            1 => primitives::uv_sphere(a, small(m), small(n)),
            2 => primitives::torus(a, b, small(m), small(n)),
            3 => primitives::torus_knot(p, q, a, b, small(m), small(n)),
            4 => primitives::wigley_hull(a, b, c, d, small(m), small(n)),
            5 => primitives::cuboid([a, b, c]),
            6 => primitives::ellipsoid([a, b, c], small(m), small(n)),
            7 => primitives::cylinder(a, b, small(m)),
            _ => primitives::capsule(a, b, small(m), small(n)),
        };
        // Huge counts too, where the product overflows the indices or the memory.
        if m > 48 || n > 48 {
            let huge = match which {
                0 => primitives::cube::<f64>(m),
                1 => primitives::uv_sphere(1.0, m, n.max(2)),
                2 => primitives::torus(1.0, 0.3, m, n.max(3)),
                6 => primitives::ellipsoid([1.0, 1.0, 1.0], m, n.max(2)),
                7 => primitives::cylinder(1.0, 1.0, m),
                _ => primitives::capsule(1.0, 1.0, m.max(3), 2 * (n / 2).max(1)),
            };
            if let Err(e) = &huge {
                prop_assert!(shape_error(e), "{which}: {e:?}");
            }
        }
        match made {
            Ok((v, t)) => {
                let mesh = Mesh::new(v, t);
                prop_assert!(mesh.is_ok(), "generator {which} made a mesh Mesh::new refuses: {:?}", mesh.err());
                let mesh = mesh.unwrap();
                prop_assert!(mesh.volume().is_finite() && mesh.volume() > 0.0);
                check_query(&mesh, &pose_from(pose), &Water::default());
            }
            Err(e) => prop_assert!(shape_error(&e), "generator {which}: {e:?}"),
        }
    }

    /// Arbitrary bytes as STL and as OBJ text: a shape or a parse error, never a panic; a shape
    /// that parses is a mesh or a typed mesh error.
    #[test]
    fn arbitrary_bytes_parse_or_say_where(
        bytes in prop_oneof![
            prop::collection::vec(any::<u8>(), 0..400),
            // A binary STL header that declares some triangles, then noise.
            (0..8u32, prop::collection::vec(any::<u8>(), 0..400)).prop_map(|(n, rest)| {
                let mut b = vec![0u8; 80];
                b.extend_from_slice(&n.to_le_bytes());
                b.extend(rest);
                b
            }),
            // OBJ-like lines.
            prop::collection::vec(
                prop_oneof![
                    (coordinate(), coordinate(), coordinate()).prop_map(|(x, y, z)| format!("v {x} {y} {z}\n")),
                    (1..9i64, 1..9i64, -2..9i64).prop_map(|(a, b, c)| format!("f {a} {b} {c}\n")),
                    Just("vn 0 0 1\n# comment\n".to_string()),
                    Just("f 1/1/1 2//2 3\n".to_string()),
                ],
                0..16,
            ).prop_map(|lines| lines.concat().into_bytes()),
        ],
    ) {
        let parsed = [
            buoyancy_core::io::parse_stl::<f64>(&bytes),
            buoyancy_core::io::parse_obj::<f64>(&String::from_utf8_lossy(&bytes)),
        ];
        for shape in parsed {
            match shape {
                Ok((v, t)) => match Mesh::new(v, t) {
                    Ok(mesh) => prop_assert!(mesh.volume().is_finite()),
                    Err(e) => prop_assert!(
                        matches!(
                            e,
                            Error::EmptyMesh
                                | Error::InvalidMesh(_)
                                | Error::ZeroVolume { .. }
                                | Error::TooManyVertices { .. }
                                | Error::OutOfMemory { .. }
                        ),
                        "{e:?}"
                    ),
                },
                Err(e) => prop_assert!(matches!(e, Error::Parse { .. }), "{e:?}"),
            }
        }
    }

    /// Arbitrary Airy waves: refused with a typed error naming the parameter, or evaluated on a
    /// valid mesh at an arbitrary pose and time by both pressures, giving finite numbers or the
    /// errors of the pose, the time or an overflow.
    #[test]
    fn arbitrary_waves_are_refused_or_give_finite_results(
        components in prop::collection::vec(
            (length(), length(), (coordinate(), coordinate(), coordinate()), coordinate()),
            0..4,
        ),
        depth in prop_oneof![Just(None), length().prop_map(Some)],
        time in coordinate(),
        pose in (coordinate(), coordinate(), coordinate(), coordinate(), coordinate(), coordinate(), coordinate()),
    ) {
        use buoyancy_core::water::{AiryComponent, AiryWaves};
        let components = components
            .into_iter()
            .map(|(amplitude, wavelength, (x, y, z), phase)| AiryComponent {
                amplitude: amplitude / 10.0,
                wavelength,
                direction: Vector3::new(x, y, z),
                phase,
            })
            .collect();
        let waves = match AiryWaves::new(components, depth) {
            Ok(waves) => waves,
            Err(e) => {
                prop_assert!(matches!(e, Error::InvalidSurface { .. }), "{e:?}");
                return Ok(());
            }
        };
        let (v, t) = primitives::cube::<f64>(2).unwrap();
        let mesh = Mesh::new(v, t).unwrap();
        let pose = pose_from(pose);
        let water = Water::default();
        let results = [
            mesh.buoyancy(&pose, Sea::new(&water, &waves, time), Method::ExactSurface),
            mesh.buoyancy(&pose, Sea::new(&water, &waves, time).with_pressure(Pressure::FroudeKrylov), Method::ExactSurface),
        ];
        for result in results {
            match result {
                Ok(b) => prop_assert!(all_finite(&b), "{b:?}"),
                Err(e) => prop_assert!(
                    matches!(
                        e,
                        Error::InvalidPose { .. } | Error::InvalidSurface { .. } | Error::NonFiniteResult
                    ),
                    "{e:?}"
                ),
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    /// The solvers at arbitrary loading: a finite equilibrium, curve and table, or the typed
    /// errors of their inputs (a mass out of range, a body too heavy, a solve that does not
    /// converge, an option, a draft or a heel out of range).
    #[test]
    fn the_solvers_answer_or_say_why_not(
        mass in prop_oneof![8 => 1.0..2000.0f64, 1 => prop::num::f64::ANY, 1 => Just(0.0)],
        center in (coordinate(), coordinate(), coordinate()),
        heels in prop::collection::vec(prop_oneof![4 => -3.2..3.2f64, 1 => coordinate()], 0..4),
        drafts in prop::collection::vec(coordinate(), 0..5),
    ) {
        use buoyancy_core::hydrostatics::{EquilibriumOptions, LoadingCondition, TableOptions, Trim};
        let (v, t) = primitives::cuboid::<f64>([1.0, 0.5, 0.25]).unwrap();
        let mesh = Mesh::new(v, t).unwrap();
        let water = Water::default();
        let typed = |e: &Error| {
            matches!(
                e,
                Error::InvalidMass { .. }
                    | Error::InvalidLoading { .. }
                    | Error::TooHeavyToFloat { .. }
                    | Error::NoConvergence { .. }
                    | Error::InvalidSolverOption { .. }
                    | Error::InvalidDraft { .. }
                    | Error::InvalidTableOption { .. }
                    | Error::NonFiniteResult
            )
        };
        let loading = LoadingCondition::new(Point3::new(center.0, center.1, center.2))
            .and_then(|l| l.with_mass(mass));
        match &loading {
            Ok(loading) => {
                match mesh.equilibrium(&water, loading) {
                    Ok(rest) => prop_assert!(
                        rest.draft.is_finite() && rest.heel.is_finite() && rest.trim.is_finite(),
                        "{rest:?}"
                    ),
                    Err(e) => prop_assert!(typed(&e), "{e:?}"),
                }
                let mut sorted = heels.clone();
                sorted.sort_by(f64::total_cmp);
                match mesh.gz_curve(&water, loading, &sorted, Trim::Free, &EquilibriumOptions::default()) {
                    Ok(curve) => prop_assert!(curve.points.iter().all(|p| p.gz.is_finite())),
                    Err(e) => prop_assert!(typed(&e), "{e:?}"),
                }
            }
            Err(e) => prop_assert!(typed(e), "{e:?}"),
        }
        match mesh.hydrostatic_table(&water, &drafts, &TableOptions::default()) {
            Ok(rows) => prop_assert!(rows.iter().all(|r| r.kb.is_finite() && r.displaced_volume.is_finite())),
            Err(e) => prop_assert!(typed(&e), "{e:?}"),
        }
    }
}
