//! Bad input gives a typed error naming the culprit, never a panic or a NaN; the quirks of the
//! shared meshes (inward winding, zero-area triangles) are handled.

mod common;

use buoyancy::nalgebra::{Translation3, UnitQuaternion, Vector3};
use buoyancy::{Error, Mesh, Method, Pose, Traversal, Water, shape};
use common::{meshes_dir, shared_meshes};

fn load(name: &str) -> Option<shape::Shape<f64>> {
    let path = meshes_dir()?.join(name);
    Some(buoyancy::io::load(path).unwrap())
}

#[test]
fn armadillo_is_stored_inward_and_is_flipped() {
    let Some((v, t)) = load("armadillo.obj") else {
        return;
    };
    let mesh = Mesh::new(v, t).unwrap();
    assert!(mesh.was_reoriented());
    // The README's signed volume is -1.902: flipped, it is positive.
    assert!((mesh.volume() - 1.902).abs() < 1e-3, "{}", mesh.volume());
    for (name, mesh) in shared_meshes() {
        assert_eq!(mesh.was_reoriented(), name == "armadillo.obj", "{name}");
    }
}

#[test]
fn zero_area_triangles_are_accepted() {
    let Some((v, t)) = load("2-tori.obj") else {
        return;
    };
    let degenerate = t
        .iter()
        .filter(|t| {
            let [a, b, c] = t.map(|i| v[i as usize]);
            (b - a).cross(&(c - a)).norm() == 0.0
        })
        .count();
    assert_eq!(degenerate, 12);
    let mesh = Mesh::new(v, t).unwrap();
    let b = mesh
        .buoyancy(&Pose::identity(), &Water::default(), Method::Exact)
        .unwrap();
    assert!(b.submerged_volume.is_finite() && b.submerged_volume > 0.0);
}

#[test]
fn broken_shared_meshes_are_rejected_with_the_culprit() {
    let Some((v, t)) = load("bunny.obj") else {
        return;
    };
    // A hole: drop triangle 100.
    let mut holed = t.clone();
    let removed = holed.remove(100);
    match Mesh::new(v.clone(), holed).unwrap_err() {
        Error::OpenEdge { edge, .. } => {
            assert!(
                edge.iter().all(|i| removed.contains(i)),
                "{edge:?} not in {removed:?}"
            )
        }
        e => panic!("{e}"),
    }
    // One triangle flipped.
    let mut flipped = t.clone();
    flipped[42].swap(0, 1);
    match Mesh::new(v.clone(), flipped).unwrap_err() {
        Error::InconsistentOrientation { triangles, .. } => assert!(triangles.contains(&42)),
        e => panic!("{e}"),
    }
    // A triangle listed twice.
    let mut doubled = t.clone();
    doubled.push(t[7]);
    match Mesh::new(v.clone(), doubled).unwrap_err() {
        Error::NonManifoldEdge {
            triangle_count,
            triangles,
            ..
        } => {
            assert_eq!(triangle_count, 3);
            assert!(triangles.contains(&7) || triangles.contains(&t.len()));
        }
        e => panic!("{e}"),
    }
    // A NaN coordinate.
    let mut nan = v.clone();
    nan[10].z = f64::NAN;
    assert_eq!(
        Mesh::new(nan, t.clone()).unwrap_err(),
        Error::NonFiniteVertex { vertex: 10 }
    );
    let mut inf = v;
    inf[3].x = f64::NEG_INFINITY;
    assert_eq!(
        Mesh::new(inf, t).unwrap_err(),
        Error::NonFiniteVertex { vertex: 3 }
    );
}

#[test]
fn water_parameters_are_checked() {
    let bad = [
        Water::new(0.0, 9.81, Vector3::y(), 0.0),
        Water::new(f64::NAN, 9.81, Vector3::y(), 0.0),
        Water::new(1000.0, -1.0, Vector3::y(), 0.0),
        Water::new(1000.0, f64::INFINITY, Vector3::y(), 0.0),
        Water::new(1000.0, 9.81, Vector3::zeros(), 0.0),
        Water::new(1000.0, 9.81, Vector3::new(0.0, f64::NAN, 0.0), 0.0),
        Water::new(1000.0, 9.81, Vector3::y(), f64::INFINITY),
    ];
    let names = [
        "density", "density", "gravity", "gravity", "normal", "normal", "level",
    ];
    for (w, name) in bad.iter().zip(names) {
        match w {
            Err(Error::InvalidWater { parameter, .. }) => assert_eq!(*parameter, name),
            other => panic!("{name}: {other:?}"),
        }
    }
    // A non-unit normal is normalised; zero gravity is allowed (and gives no force).
    let w = Water::new(1000.0, 0.0, Vector3::new(0.0, 0.0, 3.0), 1.0).unwrap();
    assert_eq!(w.normal().into_inner(), Vector3::z());
    let (v, t) = shape::cube::<f64>(1).unwrap();
    let b = Mesh::new(v, t)
        .unwrap()
        .buoyancy(&Pose::identity(), &w, Method::Exact)
        .unwrap();
    assert_eq!(b.force, Vector3::zeros());
    assert_eq!(b.submerged_volume, 1.0);
}

#[test]
fn method_names_round_trip() {
    for m in Method::ALL {
        assert_eq!(m.name().parse::<Method>().unwrap(), m);
    }
    assert_eq!(
        "Exact-Surface".parse::<Method>().unwrap(),
        Method::ExactSurface
    );
    let e = "precise".parse::<Method>().unwrap_err();
    assert!(e.to_string().contains("fast_surface"), "{e}");
}

#[test]
fn missing_or_unknown_files_are_errors() {
    assert!(matches!(
        buoyancy::io::load::<f64>("/nonexistent/x.obj"),
        Err(Error::Io { .. })
    ));
    assert!(matches!(
        buoyancy::io::load::<f64>("mesh.xyz"),
        Err(Error::UnknownFormat { .. })
    ));
}

/// f32 follows f64 to single precision, including far from the origin of the mesh frame.
#[test]
fn f32_matches_f64() {
    let (v, t) = shape::uv_sphere::<f64>(1.0, 50, 50).unwrap();
    let offset = Vector3::new(100.0, -50.0, 20.0);
    let v64: Vec<_> = v.iter().map(|p| p + offset).collect();
    let v32: Vec<_> = v64.iter().map(|p| p.map(|c| c as f32)).collect();
    let (m64, m32) = (
        Mesh::new(v64, t.clone()).unwrap(),
        Mesh::<f32>::new(v32, t).unwrap(),
    );
    for h in [-1.2, -0.5, 0.0, 0.3, 0.99] {
        let rot = UnitQuaternion::from_euler_angles(0.4, 0.1, -0.3);
        let p64 = Pose::from_parts(
            Translation3::from(Vector3::new(0.0, h, 0.0) - rot * offset),
            rot,
        );
        let p32 = p64.cast::<f32>();
        for method in Method::ALL {
            let a = m64.buoyancy(&p64, &Water::default(), method).unwrap();
            let b = m32.buoyancy(&p32, &Water::default(), method).unwrap();
            let rel = (a.submerged_volume - b.submerged_volume as f64).abs() / m64.volume();
            assert!(rel < 1e-5, "{method}, h = {h}: {rel:e}");
            let dc = (a.center_of_buoyancy - b.center_of_buoyancy.cast::<f64>()).norm();
            assert!(dc < 1e-4, "{method}, h = {h}: center off by {dc:e}");
            // In f32 too, the hierarchy classifies every triangle as the scan does.
            let scan = m32
                .buoyancy_with(&p32, &Water::default(), method, Traversal::Scan)
                .unwrap();
            let walk = m32
                .buoyancy_with(&p32, &Water::default(), method, Traversal::Hierarchy)
                .unwrap();
            assert_eq!(
                (scan.fully_submerged, scan.partially_submerged),
                (walk.fully_submerged, walk.partially_submerged),
                "{method}, h = {h}"
            );
            assert!(
                (scan.submerged_volume - walk.submerged_volume).abs() < 1e-5 * m32.volume(),
                "{method}, h = {h}"
            );
        }
    }
}

#[test]
fn traversal_names_round_trip() {
    for t in Traversal::ALL {
        assert_eq!(t.name().parse::<Traversal>().unwrap(), t);
    }
    assert_eq!(
        "Hierarchy".parse::<Traversal>().unwrap(),
        Traversal::Hierarchy
    );
    let e = "bvh".parse::<Traversal>().unwrap_err();
    assert!(e.to_string().contains("auto, scan, hierarchy"), "{e}");
}
