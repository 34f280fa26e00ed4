//! The procedural meshes of `buoyancy_core::shape`, as `buoyancy.shapes`: closed meshes built
//! without files.

use pyo3::prelude::*;

use crate::convert::{count_or, real_or};
use crate::errors::to_py;
use crate::mesh::PyMesh;

/// A non-negative integer argument (`n`, `slices`, `p`, …) that also fits in a `u32`.
fn small_count(obj: Option<&Bound<'_, PyAny>>, name: &str, default: u32) -> PyResult<u32> {
    let n = count_or(obj, name, default as usize)?;
    u32::try_from(n).map_err(|_| crate::errors::arg_error(name, "is too large"))
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
        buoyancy_core::shape::cube(n).map_err(|e| to_py(e, None))?,
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
        buoyancy_core::shape::uv_sphere(radius, slices, stacks).map_err(|e| to_py(e, None))?,
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
        buoyancy_core::shape::torus(major, minor, segments, sides).map_err(|e| to_py(e, None))?,
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
        buoyancy_core::shape::torus_knot(p, q, radius, tube_radius, segments, sides)
            .map_err(|e| to_py(e, None))?,
    )
}
