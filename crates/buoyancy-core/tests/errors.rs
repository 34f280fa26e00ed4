//! Bad input gives a typed error naming the culprits, never a panic or a NaN; the quirks of
//! real meshes (inward winding, zero-area triangles) are handled. Every mesh is built here.

use buoyancy_core::query::Query;
use std::collections::BTreeMap;

use buoyancy_core::nalgebra::{Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::{
    Culprit, Defect, DefectKind, Error, Mesh, MeshDefects, Method, Pose, Traversal, Water,
    mesh::primitives,
};

/// A torus of 24 × 12 quads: 576 triangles, 288 vertices.
fn torus() -> primitives::Shape<f64> {
    primitives::torus::<f64>(1.0, 0.4, 24, 12).unwrap()
}

fn defects(vertices: Vec<Point3<f64>>, triangles: Vec<[u32; 3]>) -> MeshDefects {
    match Mesh::new(vertices, triangles) {
        Err(Error::InvalidMesh(defects)) => defects,
        other => panic!("expected Error::InvalidMesh, got {other:?}"),
    }
}

/// The mesh's only kind of defect, which must be `kind`.
fn only(defects: &MeshDefects, kind: DefectKind) -> &Defect {
    let kinds: Vec<_> = defects.defects.iter().map(|d| d.kind).collect();
    assert_eq!(kinds, [kind], "{defects}");
    &defects.defects[0]
}

fn edge_of(culprit: &Culprit) -> ([u32; 2], &[usize]) {
    match culprit {
        Culprit::Edge { edge, triangles } => (*edge, triangles),
        other => panic!("expected an edge, got {other:?}"),
    }
}

/// Per undirected edge, the triangles that traverse it smaller → larger and larger → smaller:
/// a count of the edges' uses independent of the validation's sort.
fn edge_uses(triangles: &[[u32; 3]]) -> BTreeMap<[u32; 2], [usize; 2]> {
    let mut uses = BTreeMap::new();
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let entry = uses.entry([a.min(b), a.max(b)]).or_insert([0, 0]);
            entry[usize::from(a > b)] += 1;
        }
    }
    uses
}

#[test]
fn an_inward_wound_mesh_is_flipped() {
    let (v, t) = torus();
    let outward = Mesh::new(v.clone(), t.clone()).unwrap();
    assert!(!outward.was_reoriented());
    let inward: Vec<[u32; 3]> = t.iter().map(|&[a, b, c]| [a, c, b]).collect();
    let flipped = Mesh::new(v, inward.clone()).unwrap();
    assert!(flipped.was_reoriented());
    assert!(flipped.volume() > 0.0);
    assert!((flipped.volume() - outward.volume()).abs() < 1e-14 * outward.volume());
    // Every triangle turned back outward, in the input order.
    for (given, kept) in inward.iter().zip(flipped.triangles()) {
        assert_eq!(*kept, [given[0], given[2], given[1]]);
    }
    let pose = Pose::from_parts(
        Translation3::new(0.0, 0.1, 0.0),
        UnitQuaternion::from_euler_angles(0.3, 0.2, 0.1),
    );
    for method in Method::ALL {
        let a = outward.buoyancy(&pose, &Water::default(), method).unwrap();
        let b = flipped.buoyancy(&pose, &Water::default(), method).unwrap();
        assert!(b.submerged_volume > 0.0, "{method}");
        assert!(
            (a.force - b.force).norm() < 1e-9 * a.force.norm(),
            "{method}: {} against {}",
            a.force,
            b.force
        );
    }
}

#[test]
fn zero_area_triangles_are_accepted() {
    // At three edges of a cube, split one of the two triangles at the edge's midpoint and close
    // the slit with a triangle of zero area along the edge: [a, b, midpoint].
    let (mut v, mut t) = primitives::cube::<f64>(2).unwrap();
    let cube = Mesh::new(v.clone(), t.clone()).unwrap();
    for i in [0, 17, 40] {
        let [a, b, c] = t[i];
        let m = v.len() as u32;
        v.push(Point3::from(
            (v[a as usize].coords + v[b as usize].coords) / 2.0,
        ));
        t[i] = [a, m, c];
        t.extend([[m, b, c], [a, b, m]]);
    }
    let degenerate = t
        .iter()
        .filter(|t| {
            let [a, b, c] = t.map(|i| v[i as usize]);
            (b - a).cross(&(c - a)).norm() == 0.0
        })
        .count();
    assert_eq!(degenerate, 3);
    let mesh = Mesh::new(v, t).unwrap();
    assert!((mesh.volume() - 1.0).abs() < 1e-15);
    let pose = Pose::from_parts(
        Translation3::new(0.0, 0.1, 0.0),
        UnitQuaternion::from_euler_angles(0.5, 0.0, 0.4),
    );
    for method in Method::ALL {
        for traversal in Traversal::ALL {
            let b = mesh
                .buoyancy(
                    &pose,
                    &Water::default(),
                    Query::new(method).with_traversal(traversal),
                )
                .unwrap();
            let expected = cube
                .buoyancy(
                    &pose,
                    &Water::default(),
                    Query::new(method).with_traversal(traversal),
                )
                .unwrap();
            assert!(b.submerged_volume.is_finite() && b.submerged_volume > 0.0);
            assert!(
                (b.force - expected.force).norm() < 1e-9 * expected.force.norm(),
                "{method}, {traversal:?}"
            );
        }
    }
}

#[test]
fn a_hole_is_reported_with_its_open_edges() {
    let (v, t) = torus();
    let mut holed = t.clone();
    let removed = holed.remove(100);
    let d = defects(v.clone(), holed.clone());
    let open = only(&d, DefectKind::OpenEdge);
    assert_eq!(open.count, 3);
    assert_eq!(open.examples.len(), 3);
    for culprit in &open.examples {
        let (edge, triangles) = edge_of(culprit);
        assert!(edge.iter().all(|i| removed.contains(i)), "{edge:?}");
        // The one triangle left at the edge is the removed one's neighbour.
        let [neighbour] = triangles else {
            panic!("{triangles:?}")
        };
        assert!(edge.iter().all(|i| holed[*neighbour].contains(i)));
    }
    assert!(!d.triangle_soup);
    assert_eq!(d.coincident_vertices, 0);
    let message = d.to_string();
    assert!(message.contains("3 open edges"), "{message}");
    assert!(message.contains("fill the holes"), "{message}");

    // Every seventh triangle removed: holes that share edges, counted as an independent count
    // of the edges' uses does.
    let sparse: Vec<[u32; 3]> = t.iter().step_by(7).copied().collect();
    let kept: Vec<[u32; 3]> = t
        .iter()
        .enumerate()
        .filter(|(i, _)| i % 7 != 0)
        .map(|(_, t)| *t)
        .collect();
    let expected = edge_uses(&kept)
        .values()
        .filter(|[forward, backward]| forward + backward == 1)
        .count();
    assert!(expected > 3 * sparse.len() / 2, "{expected}");
    let d = defects(v, kept.clone());
    let open = only(&d, DefectKind::OpenEdge);
    assert_eq!(open.count, expected);
    assert_eq!(open.examples.len(), Defect::MAX_EXAMPLES);
    for culprit in &open.examples {
        let (edge, triangles) = edge_of(culprit);
        assert_eq!(edge_uses(&kept)[&edge].iter().sum::<usize>(), 1);
        assert!(edge.iter().all(|i| kept[triangles[0]].contains(i)));
    }
    let message = d.to_string();
    assert!(
        message.contains(&format!("{expected} open edges"))
            && message.contains(&format!("and {} more", expected - Defect::MAX_EXAMPLES)),
        "{message}"
    );
}

#[test]
fn a_triangle_soup_gets_the_weld_hint() {
    let (v, t) = torus();
    let soup_vertices: Vec<Point3<f64>> = t.iter().flat_map(|t| t.map(|i| v[i as usize])).collect();
    let soup_triangles: Vec<[u32; 3]> = (0..t.len() as u32)
        .map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
        .collect();
    let d = defects(soup_vertices, soup_triangles);
    assert_eq!(only(&d, DefectKind::OpenEdge).count, 3 * t.len());
    assert!(d.triangle_soup);
    // 3 · 576 corners at the torus's 288 positions.
    assert_eq!(d.coincident_vertices, 3 * t.len() - v.len());
    let message = d.to_string();
    assert!(
        message.contains("triangle soup")
            && message.contains("weld the vertices at the same position"),
        "{message}"
    );
}

#[test]
fn a_flipped_triangle_is_reported_with_its_three_edges() {
    let (v, mut t) = torus();
    t[42].swap(0, 1);
    let d = defects(v, t.clone());
    let flipped = only(&d, DefectKind::InconsistentOrientation);
    assert_eq!(flipped.count, 3);
    for culprit in &flipped.examples {
        let (edge, triangles) = edge_of(culprit);
        assert!(triangles.contains(&42), "{triangles:?}");
        assert_eq!(triangles.len(), 2);
        // Both triangles traverse the edge in the direction given.
        for &i in triangles {
            let corners = t[i];
            let k = corners.iter().position(|&c| c == edge[0]).unwrap();
            assert_eq!(corners[(k + 1) % 3], edge[1], "triangle {i}");
        }
    }
    let message = d.to_string();
    assert!(
        message.contains("flip the wrongly wound triangles"),
        "{message}"
    );
}

#[test]
fn a_doubled_triangle_makes_its_edges_non_manifold() {
    let (v, mut t) = torus();
    t.push(t[7]);
    let copy = t.len() - 1;
    let d = defects(v, t);
    let shared = only(&d, DefectKind::NonManifoldEdge);
    assert_eq!(shared.count, 3);
    for culprit in &shared.examples {
        let (_, triangles) = edge_of(culprit);
        assert_eq!(triangles.len(), 3, "{triangles:?}");
        assert!(
            triangles.contains(&7) && triangles.contains(&copy),
            "{triangles:?}"
        );
    }
    let message = d.to_string();
    assert!(
        message.contains("3 non-manifold edges") && message.contains("remove duplicate triangles"),
        "{message}"
    );
}

#[test]
fn non_finite_vertices_are_all_named() {
    let (mut v, t) = torus();
    v[200].x = f64::INFINITY;
    v[10].z = f64::NAN;
    v[3].x = f64::NEG_INFINITY;
    let d = defects(v, t);
    let bad = only(&d, DefectKind::NonFiniteVertex);
    assert_eq!(bad.count, 3);
    assert_eq!(
        bad.examples,
        [3, 10, 200].map(|vertex| Culprit::Vertex { vertex })
    );
    let message = d.to_string();
    assert!(
        message.contains(
            "3 vertices with a NaN or infinite coordinate: vertex 3, vertex 10, vertex 200."
        ),
        "{message}"
    );
}

#[test]
fn indices_out_of_range_are_named_and_one_based_indices_recognised() {
    let (v, t) = torus();
    let mut bad = t.clone();
    bad[30][1] = 10_000;
    let d = defects(v.clone(), bad);
    let out = &d.defects[0];
    assert_eq!(out.kind, DefectKind::IndexOutOfRange);
    assert_eq!(out.count, 1);
    assert_eq!(
        out.examples,
        [Culprit::Index {
            triangle: 30,
            index: 10_000
        }]
    );
    // Left out of the edge checks, the triangle leaves a hole.
    assert_eq!(d.count(DefectKind::OpenEdge), 3);
    assert!(!d.one_based_indices);

    let one_based: Vec<[u32; 3]> = t.iter().map(|t| t.map(|i| i + 1)).collect();
    let past_the_end = one_based
        .iter()
        .filter(|t| t.contains(&(v.len() as u32)))
        .count();
    let d = defects(v, one_based);
    assert!(d.one_based_indices);
    assert_eq!(d.count(DefectKind::IndexOutOfRange), past_the_end);
    let message = d.to_string();
    assert!(
        message.contains("the indices look 1-based")
            && message.contains("subtract 1 from every index"),
        "{message}"
    );
    assert!(message.contains("valid indices are 0 to 287"), "{message}");
    // The holes the left-out triangles open are reported, with their cause.
    assert!(d.count(DefectKind::OpenEdge) > 0);
    assert!(
        message.contains("fixing those may close edges reported here"),
        "{message}"
    );
}

#[test]
fn a_triangle_with_a_repeated_vertex_is_left_out_of_the_edge_checks() {
    let (v, mut t) = torus();
    let [a, b, _] = t[5];
    t.push([a, b, b]);
    let d = defects(v, t.clone());
    let repeated = only(&d, DefectKind::RepeatedIndex);
    assert_eq!(
        repeated.examples,
        [Culprit::Triangle {
            triangle: t.len() - 1,
            indices: [a, b, b]
        }]
    );
    assert!(d.to_string().contains("remove these degenerate triangles"));
}

#[test]
fn every_kind_of_defect_is_reported_at_once() {
    let (mut v, mut t) = torus();
    v[0].y = f64::NAN;
    t[42].swap(0, 1);
    t.remove(300);
    let d = defects(v, t);
    let kinds: Vec<_> = d.defects.iter().map(|d| d.kind).collect();
    assert_eq!(
        kinds,
        [
            DefectKind::NonFiniteVertex,
            DefectKind::OpenEdge,
            DefectKind::InconsistentOrientation
        ]
    );
    assert_eq!((d.vertex_count, d.triangle_count), (288, 575));
    let message = d.to_string();
    assert_eq!(message.lines().count(), 4, "{message}");
    assert!(message.contains("indices are 0-based"), "{message}");
    assert!(
        message.contains("OBJ file is vertex n - 1 here"),
        "{message}"
    );
    assert_eq!(Error::InvalidMesh(d).to_string(), message);
}

#[test]
fn a_mesh_enclosing_no_volume_says_why() {
    // Two copies of one triangle, back to back: closed, but flat.
    let v = vec![
        Point3::new(0.0, 0.0, 0.0),
        Point3::new(1.0, 0.0, 0.0),
        Point3::new(0.0, 1.0, 0.0),
    ];
    let flat = Mesh::new(v, vec![[0, 1, 2], [0, 2, 1]]).unwrap_err();
    assert!(
        matches!(flat, Error::ZeroVolume { scale: 0.0, .. }),
        "{flat:?}"
    );
    let message = flat.to_string();
    assert!(message.contains("it is flat"), "{message}");
    assert!(!message.contains("0e0"), "{message}");

    // A torus and the same torus wound inward, as two shells: their volumes cancel.
    let (v, t) = torus();
    let n = v.len() as u32;
    let mut both_v = v.clone();
    both_v.extend(&v);
    let mut both_t = t.clone();
    both_t.extend(t.iter().map(|&[a, b, c]| [a + n, c + n, b + n]));
    let cancelling = Mesh::new(both_v, both_t).unwrap_err();
    let Error::ZeroVolume { volume, scale } = cancelling else {
        panic!("{cancelling:?}")
    };
    assert!(volume.abs() <= 1e-12 * scale && scale > 0.0);
    let message = cancelling.to_string();
    assert!(
        message.contains("parts of it wound inward cancel parts wound outward")
            && message.contains("m³"),
        "{message}"
    );

    // Coordinates so large that the volume overflows.
    let (v, t) = primitives::cube::<f64>(1).unwrap();
    let huge = v.iter().map(|p| p * 1e300).collect();
    let overflow = Mesh::new(huge, t).unwrap_err();
    assert!(matches!(overflow, Error::ZeroVolume { .. }), "{overflow:?}");
    assert!(overflow.to_string().contains("overflowed"), "{overflow}");
}

#[test]
fn an_empty_mesh_is_an_error() {
    let (v, _) = torus();
    assert_eq!(Mesh::new(v, vec![]).unwrap_err(), Error::EmptyMesh);
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
    let (v, t) = primitives::cube::<f64>(1).unwrap();
    let b = Mesh::new(v, t)
        .unwrap()
        .buoyancy(&Pose::identity(), &w, Method::Exact)
        .unwrap();
    assert_eq!(b.force, Vector3::zeros());
    assert_eq!(b.submerged_volume, 1.0);
    // Normals whose squared norm overflows or underflows are normalised all the same (a normal
    // of 1e300 once became the zero vector, and the water then gave no force).
    let diagonal = Vector3::new(0.0, 1.0, 1.0).normalize();
    for scale in [1e300, f64::MAX, 1e-300, 5e-324] {
        let w = Water::new(1000.0, 9.81, Vector3::new(0.0, scale, scale), 0.0).unwrap();
        assert!(
            (w.normal().into_inner() - diagonal).norm() < 1e-15,
            "{scale}: {:?}",
            w.normal()
        );
    }
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

#[cfg(feature = "std")]
#[test]
fn missing_or_unknown_files_are_errors() {
    let missing =
        std::env::temp_dir().join(format!("buoyancy-core-missing-{}", std::process::id()));
    for name in ["x.obj", "x.stl", "x.ply"] {
        match buoyancy_core::io::load::<f64>(missing.join(name)) {
            Err(Error::Io { kind, path, .. }) => {
                assert_eq!(kind, std::io::ErrorKind::NotFound, "{name}");
                assert!(path.ends_with(name), "{path}");
            }
            other => panic!("{name}: {other:?}"),
        }
    }
    let unknown = buoyancy_core::io::load::<f64>("mesh.xyz").unwrap_err();
    assert!(
        matches!(unknown, Error::UnknownFormat { .. }),
        "{unknown:?}"
    );
    assert!(
        unknown
            .to_string()
            .contains("expected a .obj, .stl or .ply file"),
        "{unknown}"
    );
}

/// f32 follows f64 to single precision, including far from the origin of the mesh frame.
#[test]
fn f32_matches_f64() {
    let (v, t) = primitives::uv_sphere::<f64>(1.0, 50, 50).unwrap();
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
                .buoyancy(
                    &p32,
                    &Water::default(),
                    Query::new(method).with_traversal(Traversal::Scan),
                )
                .unwrap();
            let walk = m32
                .buoyancy(
                    &p32,
                    &Water::default(),
                    Query::new(method).with_traversal(Traversal::Hierarchy),
                )
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

/// Sizes whose bytes overflow `usize` are out of memory on every machine: an error naming the
/// parameter, not the allocator's abort.
#[test]
fn requests_beyond_the_address_space_are_out_of_memory() {
    let sea = buoyancy_core::water::SeaState {
        spectrum: buoyancy_core::water::Spectrum::PiersonMoskowitz,
        significant_height: 1.0,
        peak_period: 8.0,
        direction: Vector3::x(),
        spreading: None,
        components: usize::MAX / 4,
        seed: 0,
    };
    let error =
        buoyancy_core::water::AiryWaves::<f64>::from_sea_state(&sea, &Water::default(), None)
            .unwrap_err();
    assert!(
        matches!(
            error,
            Error::OutOfMemory {
                parameter: "components",
                bytes: usize::MAX
            }
        ),
        "{error:?}"
    );
    assert!(
        error
            .to_string()
            .starts_with("components asks for 18.447 EB of memory, more than can be allocated"),
        "{error}"
    );
}

#[cfg(unix)]
#[test]
fn a_fifo_or_a_device_is_not_read() {
    let folder = std::env::temp_dir().join(format!("buoyancy-fifo-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let fifo = folder.join("hull.stl");
    let _ = std::fs::remove_file(&fifo);
    // A FIFO nobody writes to: opening it would wait for ever.
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    if made.is_ok_and(|s| s.success()) {
        let error = buoyancy_core::io::load::<f64>(&fifo).unwrap_err();
        assert!(
            matches!(
                error,
                Error::Io {
                    kind: std::io::ErrorKind::InvalidInput,
                    ..
                }
            ),
            "{error:?}"
        );
        assert!(error.to_string().contains("not a regular file"), "{error}");
    }
    let zero = folder.join("zero.stl");
    let _ = std::fs::remove_file(&zero);
    std::os::unix::fs::symlink("/dev/zero", &zero).unwrap();
    let error = buoyancy_core::io::load::<f64>(&zero).unwrap_err();
    assert!(error.to_string().contains("not a regular file"), "{error}");
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn an_obj_that_is_not_text_is_a_parse_error() {
    let path = std::env::temp_dir().join(format!("buoyancy-garbage-{}.obj", std::process::id()));
    let bytes: Vec<u8> = (0..=255u8).cycle().take(2048).collect();
    std::fs::write(&path, bytes).unwrap();
    let error = buoyancy_core::io::load::<f64>(&path).unwrap_err();
    std::fs::remove_file(&path).unwrap();
    assert!(matches!(error, Error::Parse { .. }), "{error:?}");
}
