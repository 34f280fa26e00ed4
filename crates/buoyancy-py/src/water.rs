//! `Water`: a body of still water with a flat surface.

use numpy::PyArray1;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyType;

use crate::arrays;
use crate::convert;
use crate::errors::{to_py, type_name};
use crate::format::g;

/// `Water(density, gravity, level, normal)`'s arguments.
type WaterArgs = (f64, f64, f64, (f64, f64, f64));

/// A body of still water with a flat surface, world frame, SI units.
///
/// Parameters
/// ----------
/// density : float
///     kg/m³, finite and positive (default 1000, fresh water).
/// gravity : float
///     Magnitude of gravity, m/s², finite and non-negative (default 9.81). Its direction is
///     ``-normal``: a gravity vector such as ``(0, 0, -9.81)`` is ``gravity=9.81,
///     normal=(0, 0, 1)``.
/// level : float
///     The surface is the plane ``dot(normal, p) == level`` (default 0).
/// normal : array_like, shape (3,)
///     Up direction (out of the water, against gravity); normalised, must be non-zero.
///
/// Raises ``ValueError`` naming the parameter that is out of range, ``TypeError`` naming the
/// parameter that is not a number (or not 3 numbers, for ``normal``).
///
/// >>> buoyancy.Water(density=1025.0, normal=(0, 0, 1))
/// Water(density=1025, gravity=9.81, level=0, normal=(0, 0, 1))
/// >>> buoyancy.Water(gravity=(0, 0, -9.81))
/// Traceback (most recent call last):
/// ...
/// TypeError: gravity: expected a number, the magnitude of gravity in m/s², got tuple; its direction is -normal: for the vector (0, 0, -9.81) write Water(gravity=9.81, normal=(0, 0, 1))
///
/// ``Water`` is immutable, safe to share between threads, compares by value and pickles.
#[pyclass(frozen, eq, module = "buoyancy", name = "Water")]
pub struct PyWater {
    pub inner: buoyancy_core::Water<f64>,
    /// The normal as given, for pickling bit for bit.
    given_normal: [f64; 3],
}

/// Two waters are equal when they are the same physical water (normals compared after
/// normalisation).
impl PartialEq for PyWater {
    fn eq(&self, other: &Self) -> bool {
        self.inner == other.inner
    }
}

/// The magnitude of gravity, m/s²; a vector given instead is a `TypeError` that says how to
/// write it (`gravity=|g|, normal=-g/|g|`).
fn gravity_magnitude(gravity: Option<&Bound<'_, PyAny>>, default: f64) -> PyResult<f64> {
    let Some(obj) = convert::given(gravity) else {
        return Ok(default);
    };
    if let Ok(g) = obj.extract::<f64>() {
        return Ok(g);
    }
    let mut message = format!(
        "gravity: expected a number, the magnitude of gravity in m/s², got {}; its direction is -normal",
        type_name(obj)
    );
    if let Ok(v) = convert::vector3(obj, "gravity") {
        let magnitude = v.norm();
        if magnitude > 0.0 && magnitude.is_finite() {
            let up = -v / magnitude;
            message += &format!(
                ": for the vector ({}, {}, {}) write Water(gravity={}, normal=({}, {}, {}))",
                g(v.x),
                g(v.y),
                g(v.z),
                g(magnitude),
                g(up.x),
                g(up.y),
                g(up.z)
            );
        }
    }
    Err(PyTypeError::new_err(message))
}

#[pymethods]
impl PyWater {
    #[new]
    #[pyo3(
        signature = (density=None, gravity=None, level=None, normal=None),
        text_signature = "(density=1000.0, gravity=9.81, level=0.0, normal=(0.0, 1.0, 0.0))"
    )]
    fn new(
        density: Option<&Bound<'_, PyAny>>,
        gravity: Option<&Bound<'_, PyAny>>,
        level: Option<&Bound<'_, PyAny>>,
        normal: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        // Fresh water, y up, surface at y = 0.
        let default = buoyancy_core::Water::<f64>::default();
        let density = convert::real_or(density, "density", default.density())?;
        let gravity = gravity_magnitude(gravity, default.gravity())?;
        let level = convert::real_or(level, "level", default.level())?;
        let n = match convert::given(normal) {
            Some(n) => convert::vector3(n, "normal")?,
            None => default.normal().into_inner(),
        };
        let inner =
            buoyancy_core::Water::new(density, gravity, n, level).map_err(|e| to_py(e, None))?;
        Ok(PyWater {
            inner,
            given_normal: n.into(),
        })
    }

    /// Density, kg/m³.
    #[getter]
    fn density(&self) -> f64 {
        self.inner.density()
    }
    /// Magnitude of gravity, m/s².
    #[getter]
    fn gravity(&self) -> f64 {
        self.inner.gravity()
    }
    /// Signed distance of the surface from the origin along ``normal``, m.
    #[getter]
    fn level(&self) -> f64 {
        self.inner.level()
    }
    /// Unit up normal, shape (3,) (a new, read-only array).
    #[getter]
    fn normal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.normal().as_slice())
    }
    /// ``density * gravity``, N/m³.
    #[getter]
    fn specific_weight(&self) -> f64 {
        self.inner.specific_weight()
    }

    fn __repr__(&self) -> String {
        let n = self.inner.normal();
        format!(
            "Water(density={}, gravity={}, level={}, normal=({}, {}, {}))",
            g(self.inner.density()),
            g(self.inner.gravity()),
            g(self.inner.level()),
            g(n.x),
            g(n.y),
            g(n.z)
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> (Bound<'py, PyType>, WaterArgs) {
        let w = slf.get();
        let [x, y, z] = w.given_normal;
        (
            slf.get_type(),
            (
                w.inner.density(),
                w.inner.gravity(),
                w.inner.level(),
                (x, y, z),
            ),
        )
    }
}
