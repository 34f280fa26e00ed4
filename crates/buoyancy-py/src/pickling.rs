//! Pickling of the results that have no public constructor (`Waterplane`, `Hydrostatics`,
//! `Equilibrium`, `GzCurve`, `HydrostaticTable`, `BuoyancyBatch`): each pickles as the JSON of
//! the core's result (its `serde` form) and is rebuilt by `buoyancy._core._unpickle(class,
//! state)`, so that a result crosses a process pool (`multiprocessing`, Dask) as it is. JSON
//! writes every `f64` so that it reads back bit for bit.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::hydrostatics::{PyHydrostatics, PyWaterplane};
use crate::result::PyBuoyancyBatch;
use crate::stability::{PyEquilibrium, PyGzCurve, PyHydrostaticTable};

/// What a result's `__reduce__` returns: `_unpickle` and its arguments `(class, state)`.
pub type Reduce<'py> = (Bound<'py, PyAny>, (&'static str, String));

/// `__reduce__`'s value for the object of class `class` whose core result is `value`.
pub fn reduce<'py, S: Serialize>(
    py: Python<'py>,
    class: &'static str,
    value: &S,
) -> PyResult<Reduce<'py>> {
    let state = serde_json::to_string(value)
        .map_err(|e| PyValueError::new_err(format!("cannot pickle this {class}: {e}")))?;
    let unpickle = py.import("buoyancy._core")?.getattr("_unpickle")?;
    Ok((unpickle, (class, state)))
}

/// The core result a pickled `class` holds.
pub fn state<D: DeserializeOwned>(class: &str, state: &str) -> PyResult<D> {
    serde_json::from_str(state).map_err(|e| {
        PyValueError::new_err(format!(
            "state: not the pickled state of a {class} of this version of buoyancy ({e})"
        ))
    })
}

/// Rebuilds a pickled result: `class_name` is its class's name, `state` what `__reduce__` wrote.
#[pyfunction]
pub fn _unpickle(py: Python<'_>, class_name: &str, state: &str) -> PyResult<Py<PyAny>> {
    Ok(match class_name {
        "Waterplane" => PyWaterplane::from_state(state)?
            .into_pyobject(py)?
            .into_any(),
        "Hydrostatics" => PyHydrostatics::from_state(state)?
            .into_pyobject(py)?
            .into_any(),
        "Equilibrium" => PyEquilibrium::from_state(state)?
            .into_pyobject(py)?
            .into_any(),
        "GzCurve" => PyGzCurve::from_state(state)?.into_pyobject(py)?.into_any(),
        "HydrostaticTable" => PyHydrostaticTable::from_state(state)?
            .into_pyobject(py)?
            .into_any(),
        "BuoyancyBatch" => PyBuoyancyBatch::from_state(py, state)?
            .into_pyobject(py)?
            .into_any(),
        _ => {
            return Err(PyValueError::new_err(format!(
                "class_name: no pickled buoyancy result is called {}",
                PyTuple::new(py, [class_name])?.get_item(0)?.repr()?
            )));
        }
    }
    .unbind())
}
