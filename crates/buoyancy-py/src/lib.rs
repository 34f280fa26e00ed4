//! `buoyancy._core`: the Python bindings of `buoyancy-core`.
//!
//! Thin: every computation is the core's; this crate converts arguments (naming the argument
//! in each error), releases the interpreter lock around the work, and runs batches of poses on
//! rayon. The Python package `buoyancy` (python/buoyancy) re-exports it.
//!
//! The doc comments of the Python-facing items are their Python docstrings (numpydoc, with
//! `>>>` examples), not rustdoc: brackets in them are slices, not links.
#![allow(rustdoc::broken_intra_doc_links)]

mod airy;
mod arrays;
mod batch;
mod controller;
mod convert;
mod damping;
mod defects;
mod detach;
mod errors;
mod float_report;
mod format;
mod gerstner;
mod height_grid;
mod hydrostatics;
mod io;
mod mesh;
mod pickling;
mod pressure;
mod rapier_bodies;
mod result;
mod sea_state;
mod shapes;
mod stability;
mod step_inputs;
mod surface_function;
mod threads;
mod water;
mod water_waves;

use buoyancy_core::Method;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add_class::<mesh::PyMesh>()?;
    m.add_class::<water::PyWater>()?;
    m.add_class::<airy::PyAiryWave>()?;
    m.add_class::<airy::PyWaves>()?;
    m.add_class::<gerstner::PyGerstnerWaves>()?;
    m.add_class::<height_grid::PyHeightGrid>()?;
    m.add_class::<result::PyBuoyancy>()?;
    m.add_class::<result::PyBuoyancyBatch>()?;
    m.add_class::<damping::PyDamping>()?;
    m.add_class::<damping::PyDampingCoefficients>()?;
    m.add_class::<defects::PyMeshDefect>()?;
    m.add_class::<controller::PyController>()?;
    m.add_class::<float_report::PyFloatReport>()?;
    m.add_class::<hydrostatics::PyWaterplane>()?;
    m.add_class::<hydrostatics::PyHydrostatics>()?;
    m.add_class::<stability::PyEquilibrium>()?;
    m.add_class::<stability::PyGzCurve>()?;
    m.add_class::<stability::PyHydrostaticTable>()?;
    let mesh_error = py.get_type::<errors::MeshError>();
    defects::set_defaults(&mesh_error)?;
    m.add("MeshError", mesh_error)?;
    m.add_function(wrap_pyfunction!(io::load, m)?)?;
    m.add_function(wrap_pyfunction!(pickling::_unpickle, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::cube, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::uv_sphere, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::torus, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::torus_knot, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::wigley_hull, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::cuboid, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::ellipsoid, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::cylinder, m)?)?;
    m.add_function(wrap_pyfunction!(shapes::capsule, m)?)?;
    m.add_function(wrap_pyfunction!(rapier_bodies::rapier_bodies, m)?)?;
    m.add_function(wrap_pyfunction!(rapier_bodies::world_inverse_inertias, m)?)?;
    m.add("METHODS", PyTuple::new(py, Method::ALL.map(Method::name))?)?;
    m.add("QUATERNION_TOLERANCE", convert::QUATERNION_TOLERANCE)?;
    m.add("MATRIX_TOLERANCE", convert::MATRIX_TOLERANCE)?;
    Ok(())
}
