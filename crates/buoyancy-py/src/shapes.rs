//! The procedural meshes of `buoyancy_core::shape`, as `buoyancy.shapes`: closed meshes built
//! without files.

use pyo3::prelude::*;

use crate::convert::{count_or, real, real_or, vector3};
use crate::errors::to_py;
use crate::mesh::PyMesh;

/// A non-negative integer argument (`n`, `slices`, `p`, …) that also fits in a `u32`.
fn small_count(obj: Option<&Bound<'_, PyAny>>, name: &str, default: u32) -> PyResult<u32> {
    let n = count_or(obj, name, default as usize)?;
    u32::try_from(n).map_err(|_| {
        crate::errors::arg_error(name, format!("must be at most {}, got {n}", u32::MAX))
    })
}

/// The unit cube [-1/2, 1/2]³, each face split in n × n squares (12·n² triangles).
///
/// >>> buoyancy.shapes.cube(10).n_triangles
/// 1200
#[pyfunction]
#[pyo3(signature = (n=None), text_signature = "(n=1)")]
pub fn cube(py: Python<'_>, n: Option<&Bound<'_, PyAny>>) -> PyResult<PyMesh> {
    let n = count_or(n, "n", 1)?;
    PyMesh::build(
        py,
        buoyancy_core::mesh::primitives::cube(n).map_err(|e| to_py(e, None))?,
    )
}

/// A UV sphere of the given radius (m) about the origin: `slices` segments around the y axis,
/// `stacks` from pole to pole (2·slices·(stacks − 1) triangles).
///
/// >>> buoyancy.shapes.uv_sphere(1.0, 50, 50).n_triangles
/// 4900
#[pyfunction]
#[pyo3(
    signature = (radius=None, slices=None, stacks=None),
    text_signature = "(radius=1.0, slices=32, stacks=16)"
)]
pub fn uv_sphere(
    py: Python<'_>,
    radius: Option<&Bound<'_, PyAny>>,
    slices: Option<&Bound<'_, PyAny>>,
    stacks: Option<&Bound<'_, PyAny>>,
) -> PyResult<PyMesh> {
    let radius = real_or(radius, "radius", 1.0)?;
    let slices = count_or(slices, "slices", 32)?;
    let stacks = count_or(stacks, "stacks", 16)?;
    PyMesh::build(
        py,
        buoyancy_core::mesh::primitives::uv_sphere(radius, slices, stacks)
            .map_err(|e| to_py(e, None))?,
    )
}

/// A torus about the y axis: the tube of radius `minor` (m) swept around the circle of radius
/// `major` (m), `segments` around the axis and `sides` around the tube (2·segments·sides
/// triangles).
///
/// >>> round(buoyancy.shapes.torus(1.0, 0.25, 96, 32).volume, 3)  # the true torus: 2π²·R·r² = 1.234
/// 1.225
#[pyfunction]
#[pyo3(
    signature = (major=None, minor=None, segments=None, sides=None),
    text_signature = "(major=1.0, minor=0.25, segments=48, sides=16)"
)]
pub fn torus(
    py: Python<'_>,
    major: Option<&Bound<'_, PyAny>>,
    minor: Option<&Bound<'_, PyAny>>,
    segments: Option<&Bound<'_, PyAny>>,
    sides: Option<&Bound<'_, PyAny>>,
) -> PyResult<PyMesh> {
    let major = real_or(major, "major", 1.0)?;
    let minor = real_or(minor, "minor", 0.25)?;
    let segments = count_or(segments, "segments", 48)?;
    let sides = count_or(sides, "sides", 16)?;
    PyMesh::build(
        py,
        buoyancy_core::mesh::primitives::torus(major, minor, segments, sides)
            .map_err(|e| to_py(e, None))?,
    )
}

/// A (p, q) torus knot of the given radius (m) swept by a tube of radius `tube_radius` (m),
/// `segments` along the knot and `sides` around the tube (2·segments·sides triangles).
///
/// >>> buoyancy.shapes.torus_knot().n_triangles
/// 1760
#[pyfunction]
#[pyo3(
    signature = (p=None, q=None, radius=None, tube_radius=None, segments=None, sides=None),
    text_signature = "(p=2, q=3, radius=1.0, tube_radius=0.2, segments=80, sides=11)"
)]
pub fn torus_knot(
    py: Python<'_>,
    p: Option<&Bound<'_, PyAny>>,
    q: Option<&Bound<'_, PyAny>>,
    radius: Option<&Bound<'_, PyAny>>,
    tube_radius: Option<&Bound<'_, PyAny>>,
    segments: Option<&Bound<'_, PyAny>>,
    sides: Option<&Bound<'_, PyAny>>,
) -> PyResult<PyMesh> {
    let p = small_count(p, "p", 2)?;
    let q = small_count(q, "q", 3)?;
    let radius = real_or(radius, "radius", 1.0)?;
    let tube_radius = real_or(tube_radius, "tube_radius", 0.2)?;
    let segments = count_or(segments, "segments", 80)?;
    let sides = count_or(sides, "sides", 11)?;
    PyMesh::build(
        py,
        buoyancy_core::mesh::primitives::torus_knot(p, q, radius, tube_radius, segments, sides)
            .map_err(|e| to_py(e, None))?,
    )
}

/// A closed Wigley hull, the parabolic hull form of the seakeeping benchmarks, floating upright
/// at its design draft: ``length`` L, ``beam`` B and ``draft`` T (m), closed above the design
/// waterline by a wall-sided topside of ``freeboard`` D (m) and a flat deck; ``stations``
/// sections along the length and ``waterlines`` levels from the keel to the design waterline
/// (``4·(stations − 1)·waterlines + 2·(stations − 2)`` triangles: 2,798 for the defaults).
///
/// Frame (the frame of ``Water()``, y up): x along the length, ends at ``x = ±L/2``; keel at
/// ``y = −T``, design waterline at ``y = 0``, deck at ``y = D``; z across the beam. The
/// half-breadth underwater is ``(B/2)·(1 − (2x/L)²)·(1 − (y/T)²)``, and the topside carries the
/// waterline straight up. Below ``y = 0`` the hull displaces ``V = 4LBT/9`` (m³) with its center
/// of buoyancy at ``y = −3T/8``. With an odd number of stations, a body of mass ``ρ·V`` (the
/// mesh's volume below ``y = 0``) whose center of mass is on the mesh's vertical axis through its
/// centroid floats in equilibrium at the identity pose. ``ValueError`` naming the argument for a
/// length that is not finite and positive, ``stations < 3`` or ``waterlines < 2``.
///
/// >>> hull = buoyancy.shapes.wigley_hull(4.0, 0.6, 0.25, 0.15)
/// >>> hull.n_triangles
/// 2798
/// >>> below = hull.buoyancy().volume                   # m³ under water at the identity pose
/// >>> round(below / (4 * 4.0 * 0.6 * 0.25 / 9), 3)    # against 4LBT/9
/// 0.999
#[pyfunction]
#[pyo3(
    signature = (length=None, beam=None, draft=None, freeboard=None, stations=None, waterlines=None),
    text_signature = "(length=4.0, beam=0.6, draft=0.25, freeboard=0.15, stations=41, waterlines=17)"
)]
pub fn wigley_hull(
    py: Python<'_>,
    length: Option<&Bound<'_, PyAny>>,
    beam: Option<&Bound<'_, PyAny>>,
    draft: Option<&Bound<'_, PyAny>>,
    freeboard: Option<&Bound<'_, PyAny>>,
    stations: Option<&Bound<'_, PyAny>>,
    waterlines: Option<&Bound<'_, PyAny>>,
) -> PyResult<PyMesh> {
    let length = real_or(length, "length", 4.0)?;
    let beam = real_or(beam, "beam", 0.6)?;
    let draft = real_or(draft, "draft", 0.25)?;
    let freeboard = real_or(freeboard, "freeboard", 0.15)?;
    let stations = count_or(stations, "stations", 41)?;
    let waterlines = count_or(waterlines, "waterlines", 17)?;
    PyMesh::build(
        py,
        buoyancy_core::mesh::primitives::wigley_hull(
            length, beam, draft, freeboard, stations, waterlines,
        )
        .map_err(|e| to_py(e, None))?,
    )
}

/// Three lengths (m), each finite and positive, from a sequence of three numbers.
fn lengths3(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<[f64; 3]> {
    let v = vector3(obj, name)?;
    if v.iter().all(|x| x.is_finite() && *x > 0.0) {
        Ok([v.x, v.y, v.z])
    } else {
        Err(crate::errors::arg_error(
            name,
            format!(
                "must be three finite positive lengths, got {:?}",
                [v.x, v.y, v.z]
            ),
        ))
    }
}

/// A box of ``half_extents`` (a, b, c) (m) about the origin, edges along the axes: 12 triangles,
/// volume ``8·a·b·c`` exactly.
///
/// >>> buoyancy.shapes.cuboid((1.0, 0.5, 0.25)).volume
/// 1.0
#[pyfunction]
#[pyo3(text_signature = "(half_extents)")]
pub fn cuboid(py: Python<'_>, half_extents: &Bound<'_, PyAny>) -> PyResult<PyMesh> {
    let half_extents = lengths3(half_extents, "half_extents")?;
    PyMesh::build(
        py,
        buoyancy_core::mesh::primitives::cuboid(half_extents).map_err(|e| to_py(e, None))?,
    )
}

/// An ellipsoid of semi-axes ``radii`` (a, b, c) (m) along x, y, z about the origin: a UV
/// sphere (``slices`` around y, ``stacks`` from pole to pole) scaled by the radii and then
/// uniformly, just enough that it holds the ellipsoid's volume ``4π·a·b·c/3`` exactly.
///
/// >>> import math
/// >>> round(buoyancy.shapes.ellipsoid((1.0, 0.5, 0.5)).volume / (math.pi / 3), 12)
/// 1.0
#[pyfunction]
#[pyo3(
    signature = (radii, slices=None, stacks=None),
    text_signature = "(radii, slices=32, stacks=16)"
)]
pub fn ellipsoid(
    py: Python<'_>,
    radii: &Bound<'_, PyAny>,
    slices: Option<&Bound<'_, PyAny>>,
    stacks: Option<&Bound<'_, PyAny>>,
) -> PyResult<PyMesh> {
    let radii = lengths3(radii, "radii")?;
    let slices = count_or(slices, "slices", 32)?;
    let stacks = count_or(stacks, "stacks", 16)?;
    PyMesh::build(
        py,
        buoyancy_core::mesh::primitives::ellipsoid(radii, slices, stacks)
            .map_err(|e| to_py(e, None))?,
    )
}

/// A cylinder of ``radius`` (m) about the y axis from ``y = −half_height`` to ``half_height``:
/// a prism on a regular ``segments``-gon whose area is ``π·radius²``, so that it holds the
/// cylinder's volume ``2π·radius²·half_height`` exactly (4·segments triangles).
///
/// >>> import math
/// >>> round(buoyancy.shapes.cylinder(0.5, 1.0).volume / (math.pi / 2), 12)
/// 1.0
#[pyfunction]
#[pyo3(
    signature = (radius, half_height, segments=None),
    text_signature = "(radius, half_height, segments=32)"
)]
pub fn cylinder(
    py: Python<'_>,
    radius: &Bound<'_, PyAny>,
    half_height: &Bound<'_, PyAny>,
    segments: Option<&Bound<'_, PyAny>>,
) -> PyResult<PyMesh> {
    let radius = real(radius, "radius")?;
    let half_height = real(half_height, "half_height")?;
    let segments = count_or(segments, "segments", 32)?;
    PyMesh::build(
        py,
        buoyancy_core::mesh::primitives::cylinder(radius, half_height, segments)
            .map_err(|e| to_py(e, None))?,
    )
}

/// A capsule about the y axis: the cylinder of ``radius`` (m) from ``y = −half_height`` to
/// ``half_height`` capped by half spheres; ``segments`` around the axis, ``stacks`` (even)
/// latitude bands from pole to pole over both caps (2·segments·stacks triangles). Its rings are
/// scaled just enough that it holds the capsule's volume ``π·r²·(2·half_height + 4r/3)``
/// exactly.
///
/// >>> import math
/// >>> round(buoyancy.shapes.capsule(0.5, 1.0).volume / (math.pi * 0.25 * (2 + 2 / 3)), 12)
/// 1.0
#[pyfunction]
#[pyo3(
    signature = (radius, half_height, segments=None, stacks=None),
    text_signature = "(radius, half_height, segments=32, stacks=16)"
)]
pub fn capsule(
    py: Python<'_>,
    radius: &Bound<'_, PyAny>,
    half_height: &Bound<'_, PyAny>,
    segments: Option<&Bound<'_, PyAny>>,
    stacks: Option<&Bound<'_, PyAny>>,
) -> PyResult<PyMesh> {
    let radius = real(radius, "radius")?;
    let half_height = real(half_height, "half_height")?;
    let segments = count_or(segments, "segments", 32)?;
    let stacks = count_or(stacks, "stacks", 16)?;
    PyMesh::build(
        py,
        buoyancy_core::mesh::primitives::capsule(radius, half_height, segments, stacks)
            .map_err(|e| to_py(e, None))?,
    )
}
