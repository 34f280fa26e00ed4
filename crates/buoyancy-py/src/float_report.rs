//! `FloatReport`: what the controller computed and applied for one body at its last step.

use buoyancy_core::controller::{FloatReport, Outcome};
use buoyancy_core::nalgebra::{Point3, Vector3};
use numpy::PyArray1;
use pyo3::exceptions::PyDeprecationWarning;
use pyo3::prelude::*;
use pyo3::types::{PyString, PyType};

use crate::arrays;
use crate::convert;
use crate::errors::{arg_error, type_error};
use crate::format::{g, g3};

type V3 = (f64, f64, f64);

fn tuple(v: &[f64]) -> V3 {
    (v[0], v[1], v[2])
}

/// `FloatReport(...)`'s arguments, as `__reduce__` returns them.
type ReportArgs = (f64, V3, V3, V3, V3, V3, V3, f64, &'static str);

/// The name of an outcome, as Python sees it.
pub fn outcome_name(outcome: Outcome) -> &'static str {
    match outcome {
        Outcome::NotEvaluated => "not_evaluated",
        Outcome::Applied => "applied",
        Outcome::Inactive => "inactive",
        Outcome::NotFinite => "not_finite",
        Outcome::Unsupported => "unsupported",
        // `Outcome` is non-exhaustive: a newer core's outcome this binding does not know yet.
        _ => "unknown",
    }
}

/// The outcomes by name, in the order of the stub's `Literal`.
const OUTCOMES: [(&str, Outcome); 5] = [
    ("not_evaluated", Outcome::NotEvaluated),
    ("applied", Outcome::Applied),
    ("inactive", Outcome::Inactive),
    ("not_finite", Outcome::NotFinite),
    ("unsupported", Outcome::Unsupported),
];

fn parse_outcome(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Outcome> {
    let Some(obj) = convert::given(obj) else {
        return Ok(Outcome::NotEvaluated);
    };
    let name = obj
        .cast::<PyString>()
        .map_err(|_| type_error("outcome", "an outcome name such as 'applied'", obj))?
        .to_str()?
        .to_owned();
    OUTCOMES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|&(_, o)| o)
        .ok_or_else(|| {
            let names: Vec<_> = OUTCOMES.iter().map(|(n, _)| format!("'{n}'")).collect();
            arg_error(
                "outcome",
                format!(
                    "unknown outcome '{name}'; expected one of {}",
                    names.join(", ")
                ),
            )
        })
}

/// What :meth:`Controller.step` computed and applied for one body at its last step, world
/// frame, SI units, torques about the body's world center of mass.
///
/// Attributes
/// ----------
/// submerged_volume : float
///     Volume under water, m³ (all the body's parts).
/// center_of_buoyancy : ndarray, shape (3,)
///     Center of the submerged volume, m (the volume-weighted mean of the parts' centers; the
///     center of mass projected onto the surface when nothing is under water).
/// center_of_mass : ndarray, shape (3,)
///     The body's world center of mass, as the engine gave it, m.
/// buoyancy_force, buoyancy_torque : ndarray, shape (3,)
///     Buoyant force, N, and its torque about the center of mass, N·m.
/// damping_force, damping_torque : ndarray, shape (3,)
///     Hydrodynamic damping as applied, after the semi-implicit step, N and N·m.
/// wetted_area : float
///     Area of the surface under water, m².
/// outcome : str
///     What became of the body at the last step: ``"not_evaluated"`` (added, not stepped
///     since), ``"applied"`` (the forces above are the controller's share of the body's force),
///     ``"inactive"`` (not dynamic, or disabled: nothing computed, the share it had left as it
///     is), ``"not_finite"`` (a pose, velocity or result was not finite: no force, the share
///     taken back) or ``"unsupported"`` (the query was refused: a method that assumes a flat
///     surface under waves, or the Froude–Krylov pressure under waves that are not Airy waves).
///     Unless ``"applied"``, the forces are zero and the center of buoyancy is the
///     center of mass.
/// force, torque : ndarray, shape (3,)
///     ``buoyancy_force + damping_force`` and ``buoyancy_torque + damping_torque``: what the
///     controller holds on the body.
///
/// ``FloatReport(submerged_volume=0.0, ..., outcome="not_evaluated")`` builds one (for
/// unpickling and tests). It is immutable, compares by value and pickles; each array attribute
/// returns a new, read-only array.
///
/// Examples
/// --------
/// >>> controller = buoyancy.Controller()
/// >>> report = controller.report(controller.add(buoyancy.shapes.cube()))
/// >>> report.outcome, report.submerged_volume
/// ('not_evaluated', 0.0)
#[pyclass(frozen, eq, module = "buoyancy", name = "FloatReport")]
#[derive(Clone, Copy, PartialEq)]
pub struct PyFloatReport {
    pub inner: FloatReport,
}

#[pymethods]
impl PyFloatReport {
    #[new]
    #[pyo3(
        signature = (submerged_volume=None, center_of_buoyancy=None, center_of_mass=None, buoyancy_force=None, buoyancy_torque=None, damping_force=None, damping_torque=None, wetted_area=None, outcome=None),
        text_signature = "(submerged_volume=0.0, center_of_buoyancy=(0, 0, 0), center_of_mass=(0, 0, 0), buoyancy_force=(0, 0, 0), buoyancy_torque=(0, 0, 0), damping_force=(0, 0, 0), damping_torque=(0, 0, 0), wetted_area=0.0, outcome='not_evaluated')"
    )]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        submerged_volume: Option<&Bound<'_, PyAny>>,
        center_of_buoyancy: Option<&Bound<'_, PyAny>>,
        center_of_mass: Option<&Bound<'_, PyAny>>,
        buoyancy_force: Option<&Bound<'_, PyAny>>,
        buoyancy_torque: Option<&Bound<'_, PyAny>>,
        damping_force: Option<&Bound<'_, PyAny>>,
        damping_torque: Option<&Bound<'_, PyAny>>,
        wetted_area: Option<&Bound<'_, PyAny>>,
        outcome: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let vector = |v: Option<&Bound<'_, PyAny>>, name: &str| match convert::given(v) {
            Some(v) => convert::vector3(v, name),
            None => Ok(Vector3::zeros()),
        };
        Ok(PyFloatReport {
            inner: FloatReport {
                submerged_volume: convert::real_or(submerged_volume, "submerged_volume", 0.0)?,
                center_of_buoyancy: Point3::from(vector(center_of_buoyancy, "center_of_buoyancy")?),
                center_of_mass: Point3::from(vector(center_of_mass, "center_of_mass")?),
                buoyancy_force: vector(buoyancy_force, "buoyancy_force")?,
                buoyancy_torque: vector(buoyancy_torque, "buoyancy_torque")?,
                damping_force: vector(damping_force, "damping_force")?,
                damping_torque: vector(damping_torque, "damping_torque")?,
                wetted_area: convert::real_or(wetted_area, "wetted_area", 0.0)?,
                outcome: parse_outcome(outcome)?,
            },
        })
    }

    /// Volume under water, m³.
    #[getter]
    fn submerged_volume(&self) -> f64 {
        self.inner.submerged_volume
    }
    /// Center of buoyancy, m, shape (3,).
    #[getter]
    fn center_of_buoyancy<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.center_of_buoyancy.coords.as_slice())
    }
    /// The body's world center of mass, m, shape (3,).
    #[getter]
    fn center_of_mass<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.center_of_mass.coords.as_slice())
    }
    /// Buoyant force, N, shape (3,).
    #[getter]
    fn buoyancy_force<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.buoyancy_force.as_slice())
    }
    /// Torque of the buoyancy about the center of mass, N·m, shape (3,).
    #[getter]
    fn buoyancy_torque<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.buoyancy_torque.as_slice())
    }
    /// Damping force as applied (after the semi-implicit step), N, shape (3,).
    #[getter]
    fn damping_force<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.damping_force.as_slice())
    }
    /// Damping torque as applied, about the center of mass, N·m, shape (3,).
    #[getter]
    fn damping_torque<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.damping_torque.as_slice())
    }
    /// Area of the surface under water, m².
    #[getter]
    fn wetted_area(&self) -> f64 {
        self.inner.wetted_area
    }
    /// ``"not_evaluated"``, ``"applied"``, ``"inactive"``, ``"not_finite"`` or ``"unsupported"``.
    #[getter]
    fn outcome(&self) -> &'static str {
        outcome_name(self.inner.outcome)
    }
    /// The total force held on the body, ``buoyancy_force + damping_force``, N, shape (3,).
    #[getter]
    fn force<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let f = self.inner.buoyancy_force + self.inner.damping_force;
        arrays::vector(py, f.as_slice())
    }
    /// The total torque held on the body about its center of mass, N·m, shape (3,).
    #[getter]
    fn torque<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let t = self.inner.buoyancy_torque + self.inner.damping_torque;
        arrays::vector(py, t.as_slice())
    }
    /// Deprecated: ``outcome == "not_finite"``.
    #[getter]
    fn skipped(&self, py: Python<'_>) -> PyResult<bool> {
        PyErr::warn(
            py,
            &py.get_type::<PyDeprecationWarning>(),
            c"FloatReport.skipped is deprecated: use FloatReport.outcome == 'not_finite' (or != 'applied')",
            1,
        )?;
        Ok(self.inner.outcome == Outcome::NotFinite)
    }

    fn __repr__(&self) -> String {
        let r = &self.inner;
        let v = |x: &Vector3<f64>| g3(&[x.x, x.y, x.z]);
        format!(
            "FloatReport(outcome='{}', submerged_volume={}, center_of_buoyancy={}, center_of_mass={}, buoyancy_force={}, buoyancy_torque={}, damping_force={}, damping_torque={}, wetted_area={})",
            outcome_name(r.outcome),
            g(r.submerged_volume),
            v(&r.center_of_buoyancy.coords),
            v(&r.center_of_mass.coords),
            v(&r.buoyancy_force),
            v(&r.buoyancy_torque),
            v(&r.damping_force),
            v(&r.damping_torque),
            g(r.wetted_area),
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> (Bound<'py, PyType>, ReportArgs) {
        let r = slf.get().inner;
        (
            slf.get_type(),
            (
                r.submerged_volume,
                tuple(r.center_of_buoyancy.coords.as_slice()),
                tuple(r.center_of_mass.coords.as_slice()),
                tuple(r.buoyancy_force.as_slice()),
                tuple(r.buoyancy_torque.as_slice()),
                tuple(r.damping_force.as_slice()),
                tuple(r.damping_torque.as_slice()),
                r.wetted_area,
                outcome_name(r.outcome),
            ),
        )
    }
}
