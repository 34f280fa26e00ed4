//! Fuzzing of the constructor and the evaluation with arbitrary input: whatever comes in,
//! `Mesh::new` returns a mesh or a typed error, and a query returns finite numbers or a typed
//! error; nothing panics and nothing non-finite is handed back.

use buoyancy_core::nalgebra::{Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use std::sync::atomic::{AtomicUsize, Ordering};

use buoyancy_core::{Error, Mesh, Method, Pose, Water, shape};
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
            Ok(b) => {
                let numbers = [b.submerged_volume]
                    .into_iter()
                    .chain(b.center_of_buoyancy.iter().copied())
                    .chain(b.force.iter().copied())
                    .chain(b.torque.iter().copied());
                for x in numbers {
                    assert!(x.is_finite(), "{method}: {b:?}");
                }
            }
            Err(Error::InvalidPose { .. } | Error::NonFiniteResult) => {}
            Err(e) => panic!("{method} on a valid mesh: {e}"),
        }
    }
}

fn pose_from((tx, ty, tz, qx, qy, qz, qw): (f64, f64, f64, f64, f64, f64, f64)) -> Pose<f64> {
    let q = UnitQuaternion::new_unchecked(Quaternion::new(qw, qx, qy, qz));
    Pose::from_parts(Translation3::new(tx, ty, tz), q)
}

/// Index soups: half of them a closed cube with up to three of its indices overwritten (so that
/// valid meshes are reached, and near misses of every kind), half entirely random.
fn soup() -> impl Strategy<Value = Vec<[u32; 3]>> {
    let (_, cube) = shape::cube::<f64>(1).unwrap();
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
    let (cube, _) = shape::cube::<f64>(1).unwrap();
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
        let (v, t) = shape::cube::<f64>(2).unwrap();
        let v = v.iter().enumerate().map(|(i, p)| p + Vector3::new(noise[3 * i], noise[3 * i + 1], noise[3 * i + 2])).collect();
        let Ok(mesh) = Mesh::new(v, t) else { return Ok(()) };
        let Ok(water) = Water::new(density, 9.81, Vector3::new(normal.0, normal.1, normal.2), level) else { return Ok(()) };
        check_query(&mesh, &pose_from(pose), &water);
    }
}
