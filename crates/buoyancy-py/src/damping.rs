//! The hydrodynamic damping model of `buoyancy_core::damping`: `DampingCoefficients` (the
//! model's parameters) and `Damping` (one evaluation). `Mesh.damping` itself is in `mesh.rs`.

use buoyancy_core::DampingCoefficients;
use buoyancy_core::nalgebra::Vector3;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyType;

use crate::arrays;
use crate::convert;
use crate::errors::to_py;
use crate::format::{g, g3};

type V3 = (f64, f64, f64);

fn tuple(v: &[f64; 3]) -> V3 {
    (v[0], v[1], v[2])
}

/// `DampingCoefficients(linear_drag, drag_coefficient, angular_drag_linear,
/// angular_drag_quadratic, current)`'s arguments.
type CoefficientArgs = (f64, f64, f64, f64, V3);
/// `Damping(force, torque, about, wetted_area, wetted_fraction)`'s arguments.
type DampingArgs = (V3, V3, V3, f64, f64);

/// The coefficients of the hydrodynamic damping model, SI units.
///
/// The model (``buoyancy-core``'s ``damping`` module) damps a body moving through the water so
/// that it settles instead of bobbing forever. With ``u`` the velocity of a surface point
/// relative to the water (``current``), each wetted triangle of area ``A`` and outward normal
/// ``n`` moving into the water (``u_n = n·u > 0``) feels the pressure
/// ``linear_drag * u_n + 0.5 * density * drag_coefficient * u_n**2`` against its normal; the
/// body also feels the angular damping torque
/// ``-f * density * V**(5/3) * (angular_drag_linear + angular_drag_quadratic * |ω|) * ω``, with
/// ``f`` the wetted fraction of its surface and ``V`` its volume. Nothing acts on what is above
/// water.
///
/// Parameters
/// ----------
/// linear_drag : float
///     Linear pressure-drag coefficient ``c₁``, Pa per m/s (default 1000).
/// drag_coefficient : float
///     Dimensionless quadratic drag coefficient ``C_D`` (default 1; a flat plate face-on is about
///     1.2, a sphere about 0.5).
/// angular_drag_linear : float
///     Linear angular damping rate ``a₁``, 1/s (default 0.1).
/// angular_drag_quadratic : float
///     Dimensionless quadratic angular damping coefficient ``a₂`` (default 0.1).
/// current : array_like, shape (3,)
///     Velocity of the water, world frame, m/s (default zero).
///
/// Every coefficient must be finite and non-negative, and the current finite; anything else
/// raises ``ValueError`` naming the parameter (``TypeError`` for a value that is not a number).
///
/// Examples
/// --------
/// >>> buoyancy.DampingCoefficients()
/// DampingCoefficients(linear_drag=1000, drag_coefficient=1, angular_drag_linear=0.1, angular_drag_quadratic=0.1, current=(0, 0, 0))
/// >>> buoyancy.DampingCoefficients.off().is_off
/// True
/// >>> buoyancy.DampingCoefficients(linear_drag=-1.0)
/// Traceback (most recent call last):
/// ...
/// ValueError: linear_drag: must be finite and non-negative
///
/// ``DampingCoefficients`` is immutable, compares by value and pickles.
#[pyclass(frozen, eq, module = "buoyancy", name = "DampingCoefficients")]
#[derive(Clone, Copy, PartialEq)]
pub struct PyDampingCoefficients {
    pub inner: DampingCoefficients<f64>,
}

#[pymethods]
impl PyDampingCoefficients {
    #[new]
    #[pyo3(
        signature = (linear_drag=None, drag_coefficient=None, angular_drag_linear=None, angular_drag_quadratic=None, current=None),
        text_signature = "(linear_drag=1000.0, drag_coefficient=1.0, angular_drag_linear=0.1, angular_drag_quadratic=0.1, current=(0.0, 0.0, 0.0))"
    )]
    fn new(
        linear_drag: Option<&Bound<'_, PyAny>>,
        drag_coefficient: Option<&Bound<'_, PyAny>>,
        angular_drag_linear: Option<&Bound<'_, PyAny>>,
        angular_drag_quadratic: Option<&Bound<'_, PyAny>>,
        current: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let default = DampingCoefficients::<f64>::default();
        let linear_drag = convert::real_or(linear_drag, "linear_drag", default.linear_drag())?;
        let drag_coefficient = convert::real_or(
            drag_coefficient,
            "drag_coefficient",
            default.drag_coefficient(),
        )?;
        let angular_drag_linear = convert::real_or(
            angular_drag_linear,
            "angular_drag_linear",
            default.angular_drag_linear(),
        )?;
        let angular_drag_quadratic = convert::real_or(
            angular_drag_quadratic,
            "angular_drag_quadratic",
            default.angular_drag_quadratic(),
        )?;
        let current = match convert::given(current) {
            Some(c) => convert::vector3(c, "current")?,
            None => Vector3::zeros(),
        };
        let inner = DampingCoefficients::new(
            linear_drag,
            drag_coefficient,
            angular_drag_linear,
            angular_drag_quadratic,
        )
        .and_then(|c| c.with_current(current))
        .map_err(|e| to_py(e, None))?;
        Ok(PyDampingCoefficients { inner })
    }

    /// No damping at all: ``Mesh.damping`` then returns zero force and torque.
    ///
    /// >>> buoyancy.DampingCoefficients.off()
    /// DampingCoefficients(linear_drag=0, drag_coefficient=0, angular_drag_linear=0, angular_drag_quadratic=0, current=(0, 0, 0))
    #[classmethod]
    fn off(_cls: &Bound<'_, PyType>) -> Self {
        PyDampingCoefficients {
            inner: DampingCoefficients::off(),
        }
    }

    /// Linear pressure-drag coefficient ``c₁``, Pa per m/s.
    #[getter]
    fn linear_drag(&self) -> f64 {
        self.inner.linear_drag()
    }
    /// Dimensionless quadratic pressure-drag coefficient ``C_D``.
    #[getter]
    fn drag_coefficient(&self) -> f64 {
        self.inner.drag_coefficient()
    }
    /// Linear angular damping rate ``a₁``, 1/s.
    #[getter]
    fn angular_drag_linear(&self) -> f64 {
        self.inner.angular_drag_linear()
    }
    /// Dimensionless quadratic angular damping coefficient ``a₂``.
    #[getter]
    fn angular_drag_quadratic(&self) -> f64 {
        self.inner.angular_drag_quadratic()
    }
    /// Velocity of the water, world frame, m/s, shape (3,) (a new, read-only array).
    #[getter]
    fn current<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.current().as_slice())
    }
    /// Whether every coefficient is zero (the current alone damps nothing).
    #[getter]
    fn is_off(&self) -> bool {
        self.inner.is_off()
    }

    fn __repr__(&self) -> String {
        let c = &self.inner;
        format!(
            "DampingCoefficients(linear_drag={}, drag_coefficient={}, angular_drag_linear={}, angular_drag_quadratic={}, current=({}, {}, {}))",
            g(c.linear_drag()),
            g(c.drag_coefficient()),
            g(c.angular_drag_linear()),
            g(c.angular_drag_quadratic()),
            g(c.current().x),
            g(c.current().y),
            g(c.current().z)
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> (Bound<'py, PyType>, CoefficientArgs) {
        let c = slf.get().inner;
        (
            slf.get_type(),
            (
                c.linear_drag(),
                c.drag_coefficient(),
                c.angular_drag_linear(),
                c.angular_drag_quadratic(),
                (c.current().x, c.current().y, c.current().z),
            ),
        )
    }
}

/// The hydrodynamic damping of a body at one instant, world frame, SI units.
///
/// Attributes
/// ----------
/// force : ndarray, shape (3,)
///     Damping force, N.
/// torque : ndarray, shape (3,)
///     Damping torque about ``about``, N·m (the moments of the pressure drag plus the angular
///     damping).
/// about : ndarray, shape (3,)
///     The point the torque is taken about: the ``about`` argument of ``Mesh.damping``, by
///     default the body's center of mass (the mesh centroid moved by the pose).
/// wetted_area : float
///     Area of the surface under water, m².
/// wetted_fraction : float
///     ``wetted_area`` over the whole surface area, in [0, 1].
///
/// ``Damping(force, torque, about, wetted_area=0.0, wetted_fraction=0.0)`` builds one (for
/// unpickling and tests). It is immutable, compares by value and pickles; each array attribute
/// returns a new, read-only array.
#[pyclass(frozen, eq, module = "buoyancy", name = "Damping")]
#[derive(Clone, Copy, PartialEq)]
pub struct PyDamping {
    pub force: [f64; 3],
    pub torque: [f64; 3],
    pub about: [f64; 3],
    pub wetted_area: f64,
    pub wetted_fraction: f64,
}

impl PyDamping {
    /// The result with the torque taken about `about` (default: the core's torque point).
    pub fn new(d: &buoyancy_core::Damping<f64>, about: Option<Vector3<f64>>) -> Self {
        let (torque, point) = match about {
            Some(q) => (d.torque_about(&q.into()), q),
            None => (d.torque, d.torque_point.coords),
        };
        PyDamping {
            force: d.force.into(),
            torque: torque.into(),
            about: point.into(),
            wetted_area: d.wetted_area,
            wetted_fraction: d.wetted_fraction,
        }
    }
}

#[pymethods]
impl PyDamping {
    #[new]
    #[pyo3(
        signature = (force, torque, about, wetted_area=None, wetted_fraction=None),
        text_signature = "(force, torque, about, wetted_area=0.0, wetted_fraction=0.0)"
    )]
    fn py_new(
        force: &Bound<'_, PyAny>,
        torque: &Bound<'_, PyAny>,
        about: &Bound<'_, PyAny>,
        wetted_area: Option<&Bound<'_, PyAny>>,
        wetted_fraction: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        Ok(PyDamping {
            force: convert::vector3(force, "force")?.into(),
            torque: convert::vector3(torque, "torque")?.into(),
            about: convert::vector3(about, "about")?.into(),
            wetted_area: convert::real_or(wetted_area, "wetted_area", 0.0)?,
            wetted_fraction: convert::real_or(wetted_fraction, "wetted_fraction", 0.0)?,
        })
    }

    #[getter]
    fn force<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, &self.force)
    }
    #[getter]
    fn torque<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, &self.torque)
    }
    #[getter]
    fn about<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, &self.about)
    }
    #[getter]
    fn wetted_area(&self) -> f64 {
        self.wetted_area
    }
    #[getter]
    fn wetted_fraction(&self) -> f64 {
        self.wetted_fraction
    }

    fn __repr__(&self) -> String {
        format!(
            "Damping(force={}, torque={}, about={}, wetted_area={}, wetted_fraction={})",
            g3(&self.force),
            g3(&self.torque),
            g3(&self.about),
            g(self.wetted_area),
            g(self.wetted_fraction)
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> (Bound<'py, PyType>, DampingArgs) {
        let d = slf.get();
        (
            slf.get_type(),
            (
                tuple(&d.force),
                tuple(&d.torque),
                tuple(&d.about),
                d.wetted_area,
                d.wetted_fraction,
            ),
        )
    }
}
