//! A Python callable as a water surface: `f(points, t)` called once per evaluation with the
//! still-plane points of every vertex, holding the interpreter lock only around the call.

use std::sync::Mutex;

use buoyancy_core::nalgebra::Point3;
use buoyancy_core::water::WaterSurface;
use buoyancy_core::{Error, Water};
use pyo3::prelude::*;

use crate::arrays;
use crate::convert::{floats, shape_str};
use crate::errors::type_name;

/// Why a call of the surface function gave no elevations.
pub enum FunctionFailure {
    /// The function raised this exception.
    Raised(PyErr),
    /// It returned something that is not one finite elevation per point: what is wrong.
    Invalid(String),
}

/// The Python callable `function` as a [`WaterSurface`], for one evaluation: a failure of the
/// call is kept (the core's error type carries no Python exception) for [`SurfaceFunction::failure`].
pub struct SurfaceFunction<'a> {
    function: &'a Py<PyAny>,
    failure: Mutex<Option<FunctionFailure>>,
}

impl<'a> SurfaceFunction<'a> {
    pub fn new(function: &'a Py<PyAny>) -> Self {
        SurfaceFunction {
            function,
            failure: Mutex::new(None),
        }
    }

    /// The failure of the last call, if it failed.
    pub fn failure(self) -> Option<FunctionFailure> {
        self.failure.into_inner().unwrap_or_else(|p| p.into_inner())
    }

    /// Calls `function(points (N, 3), time)` and checks that it returned N finite numbers.
    fn call(
        &self,
        py: Python<'_>,
        points: &[Point3<f64>],
        time: f64,
        elevations: &mut [f64],
    ) -> Result<(), FunctionFailure> {
        let n = points.len();
        let array = arrays::rows3(py, points.iter().map(|p| [p.x, p.y, p.z]));
        let returned = self
            .function
            .bind(py)
            .call1((array, time))
            .map_err(FunctionFailure::Raised)?;
        let values = floats(&returned, "waves").map_err(|_| {
            FunctionFailure::Invalid(format!(
                "the surface function must return {n} numbers (one elevation per point, m), got {}",
                type_name(&returned)
            ))
        })?;
        if values.shape != [n] {
            return Err(FunctionFailure::Invalid(format!(
                "the surface function returned shape {}; expected ({n},): one elevation per point, m",
                shape_str(&values.shape)
            )));
        }
        if let Some(i) = values.values.iter().position(|v| !v.is_finite()) {
            let p = points[i];
            return Err(FunctionFailure::Invalid(format!(
                "the surface function returned {} at point {i} ({}, {}, {}) of {n}; elevations must be finite (m)",
                values.values[i], p.x, p.y, p.z
            )));
        }
        elevations.copy_from_slice(&values.values);
        Ok(())
    }
}

impl WaterSurface<f64> for SurfaceFunction<'_> {
    fn elevations(
        &self,
        _: &Water<f64>,
        points: &[Point3<f64>],
        time: f64,
        elevations: &mut [f64],
    ) -> Result<(), Error> {
        Python::attach(|py| self.call(py, points, time, elevations)).map_err(|failure| {
            *self.failure.lock().unwrap_or_else(|p| p.into_inner()) = Some(failure);
            Error::InvalidSurface {
                parameter: "surface",
                reason: "the Python surface function failed",
            }
        })
    }
}
