//! Open hulls (`Mesh::close_openings`): a hull without a deck, closed by a flat lid, has the
//! hydrostatics of the closed hull while the water stays below the rim, and a typed error the
//! moment it reaches it; a rim that is not planar is an error naming it; a closed mesh is
//! built as `Mesh::new` builds it.

use buoyancy_core::hydrostatics::{LoadingCondition, TableOptions};
use buoyancy_core::nalgebra::{Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::{DefectKind, Error, Mesh, Method, Pose, Water, mesh::primitives};

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

/// A box `length` (x) × `depth` (y, up) × `beam` (z) about the origin, each face split in
/// `n × n` squares: its vertices and triangles.
fn box_parts(length: f64, depth: f64, beam: f64, n: usize) -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
    let (v, t) = primitives::cube::<f64>(n).unwrap();
    let v = v
        .iter()
        .map(|p| Point3::new(p.x * length, p.y * depth, p.z * beam))
        .collect();
    (v, t)
}

/// The triangles whose three vertices satisfy `on`, left out.
fn without(v: &[Point3<f64>], t: &[[u32; 3]], on: impl Fn(&Point3<f64>) -> bool) -> Vec<[u32; 3]> {
    t.iter()
        .filter(|t| !t.iter().all(|&i| on(&v[i as usize])))
        .copied()
        .collect()
}

fn at_y(y: f64) -> Pose<f64> {
    Pose::from_parts(Translation3::new(0.0, y, 0.0), UnitQuaternion::identity())
}

/// Compares everything `Mesh::hydrostatics` gives; returns the worst relative difference.
fn compare(a: &Mesh<f64>, b: &Mesh<f64>, pose: &Pose<f64>, loading: &LoadingCondition<f64>) -> f64 {
    let water = Water::default();
    let (x, y) = (
        a.hydrostatics(pose, &water, loading).unwrap(),
        b.hydrostatics(pose, &water, loading).unwrap(),
    );
    let scale = x.stiffness.abs().max();
    [
        relative(x.displaced_volume, y.displaced_volume),
        relative(x.waterplane.area, y.waterplane.area),
        relative(x.kb, y.kb),
        relative(x.bm_transverse, y.bm_transverse),
        relative(x.bm_longitudinal, y.bm_longitudinal),
        relative(x.gm_transverse, y.gm_transverse),
        (x.center_of_buoyancy - y.center_of_buoyancy).norm(),
        (x.waterplane.center_of_flotation - y.waterplane.center_of_flotation).norm(),
        (x.stiffness - y.stiffness).abs().max() / scale,
    ]
    .into_iter()
    .fold(0.0, f64::max)
}

#[test]
fn open_top_box_floats_as_the_closed_box_until_the_water_reaches_the_rim() {
    let (length, depth, beam) = (4.0, 1.0, 2.0);
    let (v, t) = box_parts(length, depth, beam, 4);
    let closed = Mesh::new(v.clone(), t.clone()).unwrap();
    let hull = without(&v, &t, |p| p.y == depth / 2.0);
    assert_eq!(hull.len(), t.len() - 32);
    assert!(Mesh::new(v.clone(), hull.clone()).is_err());
    let open = Mesh::close_openings(v.clone(), hull.clone()).unwrap();
    assert_eq!(open.openings().len(), 1);
    let opening = &open.openings()[0];
    // The rim: the 16 vertices around the top, the lid a fan of 16 triangles about its center.
    assert_eq!(opening.rim().len(), 16);
    assert_eq!(opening.center() as usize, v.len());
    assert_eq!(opening.triangles(), hull.len()..hull.len() + 16);
    assert!(
        opening
            .rim()
            .iter()
            .all(|&i| v[i as usize].y == depth / 2.0)
    );
    assert!(open.vertex(v.len()).coords.norm() - depth / 2.0 < 1e-15);
    assert!(relative(open.volume(), closed.volume()) < 1e-14);
    assert!((open.centroid() - closed.centroid()).norm() < 1e-15);

    let water = Water::default();
    let loading = LoadingCondition::new(Point3::new(0.1, -0.2, 0.05)).unwrap();
    let mut worst: f64 = 0.0;
    for (k, draft) in [0.05, 0.3, 0.5, 0.75, 0.99].into_iter().enumerate() {
        let turn = UnitQuaternion::from_scaled_axis(Vector3::new(0.02 * k as f64, 0.3, -0.01));
        let upright = at_y(depth / 2.0 - draft);
        let turned = Pose::from_parts(upright.translation, turn);
        // Turned, the rim dips 0.02·k m or so: only with the freeboard for it.
        let poses = if draft < 0.9 {
            vec![upright, turned]
        } else {
            vec![upright]
        };
        for pose in poses {
            open.check_openings(&pose, &water).unwrap();
            worst = worst.max(compare(&open, &closed, &pose, &loading));
        }
    }
    eprintln!("open-top box against the closed box, rim dry: worst difference {worst:.2e}");
    assert!(worst < 1e-13);
    let drafts = [0.2, 0.6, 0.9];
    let a = open
        .hydrostatic_table(&water, &drafts, &TableOptions::new())
        .unwrap();
    let b = closed
        .hydrostatic_table(&water, &drafts, &TableOptions::new())
        .unwrap();
    for (a, b) in a.iter().zip(&b) {
        assert!(relative(a.displacement, b.displacement) < 1e-14);
        assert!(relative(a.km_transverse, b.km_transverse) < 1e-14);
        assert!(relative(a.mct, b.mct) < 1e-13);
    }

    // The rim reaches the surface (a vertex at h = 0 counts as under water) and goes under.
    for draft in [depth, depth + 0.1] {
        let e = open
            .check_openings(&at_y(depth / 2.0 - draft), &water)
            .unwrap_err();
        let Error::OpeningSubmerged {
            opening,
            vertex,
            height,
        } = e
        else {
            panic!("{e:?}");
        };
        assert_eq!(opening, 0);
        assert!(opening_rim_has(&open, vertex));
        assert!((height + (draft - depth)).abs() < 1e-15, "{height}");
        assert!(e.to_string().contains("opening 0"), "{e}");
    }
    // Heeled until one side of the rim dips: 0.1 m of freeboard, 1 m from the centerline.
    let heel = |angle: f64| {
        Pose::from_parts(
            Translation3::new(0.0, -0.4, 0.0),
            UnitQuaternion::from_scaled_axis(Vector3::x() * angle),
        )
    };
    open.check_openings(&heel(0.09), &water).unwrap();
    assert!(matches!(
        open.check_openings(&heel(0.11), &water),
        Err(Error::OpeningSubmerged { opening: 0, .. })
    ));
    // The waterplane too: the closed box's while the rim is dry, an error once it is wet.
    let (a, b) = (
        open.waterplane(&heel(0.09), &water).unwrap(),
        closed.waterplane(&heel(0.09), &water).unwrap(),
    );
    assert!(relative(a.area, b.area) < 1e-14, "{} {}", a.area, b.area);
    assert!((a.center_of_flotation - b.center_of_flotation).norm() < 1e-14);
    assert!(
        (a.principal_moments[0] - b.principal_moments[0]).abs() < 1e-13
            && (a.principal_moments[1] - b.principal_moments[1]).abs() < 1e-13
    );
    assert!(matches!(
        open.waterplane(&heel(0.11), &water),
        Err(Error::OpeningSubmerged { opening: 0, .. })
    ));
    // The table refuses the first draft that reaches the rim; the closed box takes it.
    let e = open
        .hydrostatic_table(&water, &[0.5, 1.0], &TableOptions::new())
        .unwrap_err();
    assert!(
        matches!(e, Error::OpeningSubmerged { opening: 0, .. }),
        "{e}"
    );
    closed
        .hydrostatic_table(&water, &[0.5, 1.0], &TableOptions::new())
        .unwrap();
    // A closed mesh has nothing to check.
    closed.check_openings(&at_y(-5.0), &water).unwrap();
}

fn opening_rim_has(mesh: &Mesh<f64>, vertex: u32) -> bool {
    mesh.openings().iter().any(|o| o.rim().contains(&vertex))
}

const LENGTH: f64 = 2.5;
const BEAM: f64 = 0.25;
const DRAFT: f64 = 0.15625;
const FREEBOARD: f64 = 0.1;

#[test]
fn wigley_hull_without_its_deck_equals_the_closed_hull() {
    let (v, t) = primitives::wigley_hull::<f64>(LENGTH, BEAM, DRAFT, FREEBOARD, 41, 17).unwrap();
    let closed = Mesh::new(v.clone(), t.clone()).unwrap();
    let hull = without(&v, &t, |p| p.y == FREEBOARD);
    assert_eq!(hull.len(), t.len() - 2 * (41 - 2));
    let open = Mesh::close_openings(v.clone(), hull).unwrap();
    assert_eq!(open.openings().len(), 1);
    // The deck's edge: both sides' 39 inner stations and the two stems.
    assert_eq!(open.openings()[0].rim().len(), 2 * 39 + 2);
    assert!(relative(open.volume(), closed.volume()) < 1e-14);
    let water = Water::default();
    let loading = LoadingCondition::new(Point3::new(0.0, -0.02, 0.0)).unwrap();
    let mut worst: f64 = 0.0;
    for (y, heel, trim) in [
        (0.0, 0.0, 0.0),
        (0.03, 0.0, 0.0),
        (-0.05, 0.1, 0.01),
        (0.01, -0.2, -0.02),
    ] {
        let pose = Pose::from_parts(
            Translation3::new(0.0, y, 0.0),
            UnitQuaternion::from_euler_angles(heel, 0.0, trim),
        );
        open.check_openings(&pose, &water).unwrap();
        worst = worst.max(compare(&open, &closed, &pose, &loading));
        let (a, b) = (
            open.buoyancy(&pose, &water, Method::Exact).unwrap(),
            closed.buoyancy(&pose, &water, Method::Exact).unwrap(),
        );
        worst = worst.max((a.force - b.force).norm() / b.force.norm());
        worst = worst.max((a.torque - b.torque).norm() / (b.force.norm() * LENGTH));
    }
    eprintln!("Wigley hull without a deck against the closed hull: worst {worst:.2e}");
    assert!(worst < 1e-12);
    // Sunk to the deck: the rim is in the surface.
    let e = open
        .check_openings(
            &Pose::from_parts(
                Translation3::new(0.0, -FREEBOARD, 0.0),
                UnitQuaternion::identity(),
            ),
            &water,
        )
        .unwrap_err();
    assert!(
        matches!(e, Error::OpeningSubmerged { opening: 0, .. }),
        "{e}"
    );
    // Transformed copies keep their lids (and their vertex numbers).
    let scaled = open.scaled(&Vector3::new(2.0, 2.0, 2.0)).unwrap();
    assert_eq!(scaled.openings(), open.openings());
    assert!(scaled.check_openings(&at_y(-0.19), &water).is_ok());
    assert!(scaled.check_openings(&at_y(-0.21), &water).is_err());
}

#[test]
fn a_rim_that_is_not_planar_is_an_error_naming_it() {
    // A tube: a box without its top and bottom, two openings; raise one vertex of the top rim.
    let (length, depth, beam) = (4.0, 1.0, 2.0);
    let (mut v, t) = box_parts(length, depth, beam, 2);
    let hull = without(&v, &t, |p| p.y.abs() == depth / 2.0);
    let tube = Mesh::close_openings(v.clone(), hull.clone()).unwrap();
    assert_eq!(tube.openings().len(), 2);
    assert!(relative(tube.volume(), length * depth * beam) < 1e-14);
    // Opening 0 holds the smallest rim vertex index.
    let smallest = |o: usize| *tube.openings()[o].rim().iter().min().unwrap();
    assert!(smallest(0) < smallest(1));
    assert_eq!(tube.openings()[0].rim()[0], smallest(0));
    let top = if v[smallest(0) as usize].y > 0.0 {
        0
    } else {
        1
    };
    // The middle vertex of the top rim's long edge at z = +beam/2.
    let raised = (0..v.len())
        .find(|&i| v[i] == Point3::new(0.0, depth / 2.0, beam / 2.0))
        .unwrap();
    v[raised].y += 1e-3;
    let e = Mesh::close_openings(v.clone(), hull.clone()).unwrap_err();
    let Error::NonPlanarOpening {
        opening,
        vertex,
        deviation,
        tolerance,
    } = e
    else {
        panic!("{e:?}");
    };
    assert_eq!(opening, top);
    assert_eq!(vertex as usize, raised);
    assert!(deviation > 5e-4 && deviation < 1e-3, "{deviation}");
    assert!(tolerance < 1e-5, "{tolerance}");
    assert!(e.to_string().contains(&format!("opening {top}")), "{e}");
    // Within the tolerance (10⁻⁶ of the rim's radius, 2.2 m), it is closed.
    v[raised].y = depth / 2.0 + 1e-7;
    let tube = Mesh::close_openings(v, hull).unwrap();
    assert!(relative(tube.volume(), length * depth * beam) < 1e-6);
}

#[test]
fn a_mesh_without_opening_is_built_as_mesh_new_builds_it() {
    let water = Water::default();
    let pose = Pose::from_parts(
        Translation3::new(0.1, 0.2, -0.3),
        UnitQuaternion::from_scaled_axis(Vector3::new(0.3, -0.2, 0.5)),
    );
    for (v, t) in [
        primitives::torus::<f64>(1.0, 0.4, 32, 12).unwrap(),
        primitives::wigley_hull::<f64>(LENGTH, BEAM, DRAFT, FREEBOARD, 21, 9).unwrap(),
    ] {
        let a = Mesh::new(v.clone(), t.clone()).unwrap();
        let b = Mesh::close_openings(v, t).unwrap();
        assert!(b.openings().is_empty());
        assert_eq!(a.triangles(), b.triangles());
        assert_eq!(a.vertex_count(), b.vertex_count());
        assert_eq!((a.volume(), a.centroid()), (b.volume(), b.centroid()));
        for method in Method::ALL {
            assert_eq!(
                a.buoyancy(&pose, &water, method).unwrap(),
                b.buoyancy(&pose, &water, method).unwrap()
            );
        }
        b.check_openings(&pose, &water).unwrap();
    }
}

#[test]
fn other_defects_and_pinched_rims_are_refused() {
    // A triangle soup: every edge open, the weld hint, no lids.
    let (v, t) = primitives::cube::<f64>(1).unwrap();
    let soup_v: Vec<_> = t.iter().flat_map(|t| t.map(|i| v[i as usize])).collect();
    let soup_t: Vec<_> = (0..t.len() as u32)
        .map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
        .collect();
    let Err(Error::InvalidMesh(defects)) = Mesh::close_openings(soup_v, soup_t) else {
        panic!("a soup is not an open hull");
    };
    assert!(defects.triangle_soup);
    // An open box with a flipped triangle: the orientation is reported, not closed over.
    let (v, t) = box_parts(1.0, 1.0, 1.0, 2);
    let mut hull = without(&v, &t, |p| p.y == 0.5);
    hull[0].swap(1, 2);
    let Err(Error::InvalidMesh(defects)) = Mesh::close_openings(v.clone(), hull) else {
        panic!("inconsistent orientation");
    };
    assert!(defects.count(DefectKind::InconsistentOrientation) > 0);
    // Two boxes open at y = 0.5, the second the first mirrored upside down and moved so that
    // the rims share one corner and nothing else: two rims meet at a vertex.
    let hull = without(&v, &t, |p| p.y == 0.5);
    let corner = (0..v.len())
        .find(|&i| v[i] == Point3::new(0.5, 0.5, 0.5))
        .unwrap() as u32;
    let twin = (0..v.len())
        .find(|&i| v[i] == Point3::new(-0.5, 0.5, -0.5))
        .unwrap() as u32;
    let mut vertices = v.clone();
    let offset = vertices.len() as u32;
    vertices.extend(
        v.iter()
            .map(|p| Point3::new(p.x + 1.0, 1.0 - p.y, p.z + 1.0)),
    );
    let mut triangles = hull.clone();
    triangles.extend(hull.iter().map(|t| {
        let [a, b, c] = t.map(|i| if i == twin { corner } else { i + offset });
        [a, c, b]
    }));
    let e = Mesh::close_openings(vertices, triangles).unwrap_err();
    assert!(
        matches!(e, Error::InvalidOpening { vertex, .. } if vertex == corner),
        "{e:?}"
    );
}

#[test]
fn f32_hulls_close_too() {
    let (v, t) = primitives::wigley_hull::<f32>(LENGTH, BEAM, DRAFT, FREEBOARD, 41, 17).unwrap();
    let closed = Mesh::new(v.clone(), t.clone()).unwrap();
    let hull: Vec<[u32; 3]> = t
        .iter()
        .filter(|t| !t.iter().all(|&i| v[i as usize].y == FREEBOARD as f32))
        .copied()
        .collect();
    let open = Mesh::close_openings(v, hull).unwrap();
    assert!(((open.volume() - closed.volume()) / closed.volume()).abs() < 1e-6);
    let b = open
        .buoyancy(&Pose::identity(), &Water::default(), Method::Exact)
        .unwrap();
    let c = closed
        .buoyancy(&Pose::identity(), &Water::default(), Method::Exact)
        .unwrap();
    assert!(((b.submerged_volume - c.submerged_volume) / c.submerged_volume).abs() < 1e-6);
}

/// A unit cube with the upper half of its +x face open (a planar hole in its side, y from 0 to
/// 1/2), closed by a lid.
fn holed_box() -> Mesh<f64> {
    let (v, t) = primitives::cube::<f64>(2).unwrap();
    let hull: Vec<[u32; 3]> = t
        .into_iter()
        .filter(|t| {
            !t.iter()
                .all(|&i| v[i as usize].x == 0.5 && v[i as usize].y >= 0.0)
        })
        .collect();
    let mesh = Mesh::close_openings(v, hull).unwrap();
    assert_eq!(mesh.openings().len(), 1);
    mesh
}

#[test]
fn equilibrium_and_gz_stop_where_the_water_reaches_an_opening() {
    use buoyancy_core::hydrostatics::{EquilibriumOptions, LoadingCondition, Trim};
    let mesh = holed_box();
    let water = Water::default();
    // 300 kg: 0.3 m deep, the hole (from y = 0 in the box) 0.2 m above the water.
    let light = LoadingCondition::new(Point3::new(0.0, -0.2, 0.0))
        .unwrap()
        .with_mass(300.0)
        .unwrap()
        .with_longitudinal_axis(Vector3::z())
        .unwrap();
    let rest = mesh.equilibrium(&water, &light).unwrap();
    assert!((rest.draft - 0.3).abs() < 1e-9);
    // 700 kg would float 0.7 m deep, the water 0.2 m up the hole: the hull floods.
    let heavy = light.with_mass(700.0).unwrap();
    assert!(matches!(
        mesh.equilibrium(&water, &heavy),
        Err(Error::OpeningSubmerged { opening: 0, .. })
    ));
    // Heeled about z one way the holed side goes down, about −z the other: one curve stops at
    // the first heel whose waterline reaches y = 0 on the x = 1/2 face, the other runs to 90°.
    let heels: Vec<f64> = (0..=18).map(|k| f64::from(k) * 5f64.to_radians()).collect();
    let options = EquilibriumOptions::default();
    let up = mesh
        .gz_curve(&water, &light, &heels, Trim::Free, &options)
        .unwrap();
    // The other way: the same heels about the reversed axis.
    let reversed = light.with_longitudinal_axis(-Vector3::z()).unwrap();
    let down = mesh
        .gz_curve(&water, &reversed, &heels, Trim::Free, &options)
        .unwrap();
    let (flooded, dry) = match (up.flooding, down.flooding) {
        (Some(_), None) => (&up, &down),
        (None, Some(_)) => (&down, &up),
        other => panic!("one heel direction should flood, not {other:?}"),
    };
    assert_eq!(dry.points.len(), heels.len());
    let angle = flooded.flooding.unwrap().abs();
    // The hole's bottom edge (x = 1/2, y = 0) meets the water, wall-sided while the bottom is
    // wet: tan φ = (freeboard of y = 0) / (half breadth) = 0.2 / 0.5 → 21.8°.
    let wall_sided = (0.2f64 / 0.5).atan();
    assert!(angle >= wall_sided && angle < wall_sided + 5f64.to_radians() + 1e-12);
    assert!(flooded.points.iter().all(|p| p.heel.abs() < angle));
    assert!(!flooded.points.is_empty());
    // Upright with the hole under water: no curve at all.
    let sunk = [0.0, 0.1];
    assert!(matches!(
        mesh.gz_curve(&water, &heavy, &sunk, Trim::Free, &options),
        Err(Error::OpeningSubmerged { .. })
    ));
}
