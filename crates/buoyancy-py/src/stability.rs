//! `Mesh.equilibrium`, `Mesh.gz_curve` and `Mesh.hydrostatic_table`: the core's equilibrium
//! solver, righting-arm curves and hydrostatic tables, with angles in degrees, and their result
//! classes.

use buoyancy_core::hydrostatics::{
    Equilibrium, EquilibriumOptions, GzCurve, HydrostaticRow, LoadingCondition, TableOptions, Trim,
    UnitsWarning, units_warnings,
};
use buoyancy_core::nalgebra::{Point3, UnitQuaternion};
use buoyancy_core::{Error, Water};
use numpy::{PyArray1, PyArray2};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arrays;
use crate::convert::{self, given};
use crate::errors::{arg_error, to_py, warn_user};
use crate::format::g;
use crate::hydrostatics::{self, PyHydrostatics};
use crate::mesh::PyMesh;
use crate::pickling;

/// The Python exception for a core error of the solvers: a solver option or table option names
/// the Python argument (`python_names` maps the core's parameter names to the Python ones), a
/// loading condition's error as [`hydrostatics::loading_error`]; no convergence is a
/// `RuntimeError` (nothing is wrong with the arguments); the rest as [`to_py`].
fn solver_error(e: Error, python_names: &[(&str, &str)]) -> PyErr {
    let rename = |parameter: &'static str| {
        python_names
            .iter()
            .find(|(core, _)| *core == parameter)
            .map_or(parameter, |(_, python)| python)
            .to_owned()
    };
    match e {
        Error::InvalidSolverOption { parameter, reason }
        | Error::InvalidTableOption { parameter, reason } => {
            let name = rename(parameter);
            // The core takes radians; an argument named `…_deg` is in degrees.
            if name.ends_with("_deg") {
                arg_error(&name, reason.replace("(rad)", "(degrees)"))
            } else {
                arg_error(&name, reason)
            }
        }
        Error::InvalidLoading { .. } => hydrostatics::loading_error(e),
        Error::InvalidMass { reason } => arg_error("mass", reason),
        Error::InvalidDraft { index, .. } => arg_error(&format!("drafts[{index}]"), e),
        Error::OutOfMemory { parameter, .. } => to_py(e, Some(&rename(parameter))),
        Error::NoConvergence { .. } => PyRuntimeError::new_err(e.to_string()),
        e => to_py(e, None),
    }
}

/// A 1-D array of numbers (a scalar is one).
fn numbers(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<f64>> {
    let floats = convert::floats(obj, name)?;
    if floats.shape.len() > 1 {
        return Err(arg_error(
            name,
            format!(
                "expected a 1-D array of numbers, got shape {}",
                convert::shape_str(&floats.shape)
            ),
        ));
    }
    Ok(floats.values)
}

/// The Python exception for an error of `Controller::rest`: a gravity scale out of range names
/// `gravity_scale`.
pub fn rest_error(e: Error) -> PyErr {
    match e {
        Error::InvalidMass { reason } if reason.contains("gravity scale") => {
            arg_error("gravity_scale", reason)
        }
        e => solver_error(e, &[]),
    }
}

/// Degrees to radians.
fn radians(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    Ok(convert::real(obj, name)?.to_radians())
}

/// The solver options of the keyword arguments: the start pose (upright orientation), the
/// tolerance and the iterations.
pub fn options(
    position: Option<&Bound<'_, PyAny>>,
    rotation: Option<&Bound<'_, PyAny>>,
    tolerance: Option<&Bound<'_, PyAny>>,
    max_iterations: Option<&Bound<'_, PyAny>>,
) -> PyResult<EquilibriumOptions<f64>> {
    let mut options = EquilibriumOptions::default();
    if given(position).is_some() || given(rotation).is_some() {
        options = options.with_start(PyMesh::pose(position, rotation)?);
    }
    if let Some(t) = given(tolerance) {
        options = options.with_tolerance(convert::real(t, "tolerance")?);
    }
    if let Some(n) = given(max_iterations) {
        options.max_iterations = convert::count(n, "max_iterations")?;
    }
    Ok(options)
}

/// The loading condition of a floating body: its mass, center of mass and axes (mesh frame),
/// the mass required.
pub fn loading(
    mass: &Bound<'_, PyAny>,
    center_of_mass: &Bound<'_, PyAny>,
    axis: Option<&Bound<'_, PyAny>>,
    keel: Option<&Bound<'_, PyAny>>,
) -> PyResult<LoadingCondition<f64>> {
    hydrostatics::loading(center_of_mass, Some(mass), None, axis, keel)
}

/// `(x, y, z, w)`, scipy's order, as the pose arguments take it.
fn quaternion(q: &UnitQuaternion<f64>) -> [f64; 4] {
    [q.i, q.j, q.k, q.w]
}

/// The equilibrium of `mesh`, without the interpreter lock.
pub fn equilibrium(
    py: Python<'_>,
    mesh: &PyMesh,
    water: &Water<f64>,
    loading: &LoadingCondition<f64>,
    options: &EquilibriumOptions<f64>,
) -> PyResult<PyEquilibrium> {
    let mesh = mesh.core();
    let units = warn_of_units(py, mesh, water, loading.mass())?;
    py.detach(|| mesh.equilibrium_with(water, loading, options))
        .map(|inner| PyEquilibrium { inner })
        .map_err(|e| with_units(solver_error(e, &[]), &units))
}

/// `error` with what the units warnings said appended, when it is the solver's failure to
/// converge (which a mesh in millimetres causes: its draft is nanometres).
fn with_units(error: PyErr, units: &[UnitsWarning]) -> PyErr {
    Python::attach(|py| {
        if units.is_empty() || !error.is_instance_of::<PyRuntimeError>(py) {
            return error;
        }
        let notes: Vec<String> = units.iter().map(|u| u.to_string()).collect();
        PyRuntimeError::new_err(format!(
            "{}; but first check the units: {}",
            error.value(py),
            notes.join("; ")
        ))
    })
}

/// Warns (a `UserWarning`) of each input unlikely to be in SI units (a mesh in millimetres, a
/// density in t/m³, a mass in tonnes: the core's `units_warnings`), before a solve whose
/// failure alone would not say why.
fn warn_of_units(
    py: Python<'_>,
    mesh: &buoyancy_core::Mesh<f64>,
    water: &Water<f64>,
    mass: Option<f64>,
) -> PyResult<Vec<UnitsWarning>> {
    let found = units_warnings(mesh, water, mass);
    for warning in &found {
        warn_user(py, &format!("units: {warning}"))?;
    }
    Ok(found)
}

/// The righting-arm curve of `mesh`, without the interpreter lock; `heels` in degrees.
#[allow(clippy::too_many_arguments)]
pub fn gz_curve(
    py: Python<'_>,
    mesh: &PyMesh,
    water: &Water<f64>,
    loading: &LoadingCondition<f64>,
    heel_deg: &Bound<'_, PyAny>,
    free_trim: bool,
    trim_deg: Option<&Bound<'_, PyAny>>,
    options: &EquilibriumOptions<f64>,
) -> PyResult<PyGzCurve> {
    let degrees = numbers(heel_deg, "heel_deg")?;
    let span = degrees.iter().fold(0.0f64, |m, h| m.max(h.abs()));
    if degrees.len() > 1 && span < 2.0 && span > 0.0 {
        warn_user(
            py,
            &format!(
                "heel_deg: the heels reach only {}°: they are read as degrees; if they are \
                 radians, convert them (numpy.degrees)",
                crate::format::g(span)
            ),
        )?;
    }
    let heels: Vec<f64> = degrees.iter().map(|h| h.to_radians()).collect();
    let trim = match (free_trim, given(trim_deg)) {
        (true, None) => Trim::Free,
        (true, Some(_)) => {
            return Err(arg_error(
                "trim_deg",
                "is the trim held with free_trim=False; with free trim it is solved",
            ));
        }
        (false, Some(t)) => Trim::Fixed(radians(t, "trim_deg")?),
        (false, None) => Trim::Fixed(0.0),
    };
    let mesh = mesh.core();
    let units = warn_of_units(py, mesh, water, loading.mass())?;
    py.detach(|| mesh.gz_curve(water, loading, &heels, trim, options))
        .map(|inner| PyGzCurve { inner })
        .map_err(|e| {
            let error = solver_error(e, &[("heels", "heel_deg"), ("trim", "trim_deg")]);
            with_units(error, &units)
        })
}

/// The table options of the keyword arguments.
pub fn table_options(
    rotation: Option<&Bound<'_, PyAny>>,
    axis: Option<&Bound<'_, PyAny>>,
    center_of_mass: Option<&Bound<'_, PyAny>>,
    length: Option<&Bound<'_, PyAny>>,
) -> PyResult<TableOptions<f64>> {
    let names = [
        ("longitudinal_axis", "axis"),
        ("center_of_gravity", "center_of_mass"),
    ];
    let err = |e| solver_error(e, &names);
    let mut options = TableOptions::new();
    if let Some(r) = given(rotation) {
        options = options
            .with_rotation(convert::rotation(r, "rotation")?)
            .map_err(err)?;
    }
    if let Some(a) = given(axis) {
        options = options
            .with_longitudinal_axis(convert::vector3(a, "axis")?)
            .map_err(err)?;
    }
    if let Some(p) = given(center_of_mass) {
        options = options
            .with_center_of_gravity(Point3::from(convert::vector3(p, "center_of_mass")?))
            .map_err(err)?;
    }
    if let Some(l) = given(length) {
        options = options
            .with_length(convert::real(l, "length")?)
            .map_err(err)?;
    }
    Ok(options)
}

/// The hydrostatic table of `mesh`, without the interpreter lock.
pub fn hydrostatic_table(
    py: Python<'_>,
    mesh: &PyMesh,
    water: &Water<f64>,
    drafts: &Bound<'_, PyAny>,
    options: &TableOptions<f64>,
) -> PyResult<PyHydrostaticTable> {
    let drafts = numbers(drafts, "drafts")?;
    let mesh = mesh.core();
    py.detach(|| mesh.hydrostatic_table(water, &drafts, options))
        .map(|rows| PyHydrostaticTable { rows })
        .map_err(|e| solver_error(e, &[]))
}

/// A floating body at rest: the pose where the displaced water's mass equals the body's and
/// the center of buoyancy lies on the vertical through the center of mass, the stable one.
/// World frame, SI units, angles in degrees. From :meth:`Mesh.equilibrium`.
///
/// Attributes
/// ----------
/// position : ndarray, shape (3,)
///     Translation of the mesh frame at rest, m.
/// rotation : ndarray, shape (4,)
///     Rotation of the mesh frame at rest, quaternion ``(x, y, z, w)``: pass both to
///     :meth:`Mesh.buoyancy` to find the body at rest.
/// draft : float
///     Depth of the keel (the lowest vertex) below the surface, m.
/// heel, trim : float
///     Degrees from the upright orientation (the ``rotation`` argument): heel about the body's
///     longitudinal axis ``e1``, right-handed, so that a positive heel puts the side towards
///     ``-e2`` down (``e2 = n x e1``, ``n`` the water's up normal: for a ship modelled x
///     forward and z up, ``e2`` is y, port, and a positive heel puts starboard down); trim about
///     ``e2``, right-handed (positive puts the head of the longitudinal axis down).
/// residual : ndarray, shape (3,)
///     Relative residuals: ``(rho V - m) / m`` and the moments about ``G`` over ``m g L``.
/// length : float
///     The body length ``L`` the moments are scaled by, m.
/// iterations, restarts : int
///     Newton iterations, and restarts from an unstable state.
/// stable : bool
///     Whether every eigenvalue of the heave-roll-pitch stiffness (scaled as
///     ``stiffness_eigenvalues``) exceeds the square root of the tolerance, 6.1e-6 by default:
///     ``False`` for a neutral state (a uniform cylinder rolling about its axis).
/// stiffness_eigenvalues : ndarray, shape (3,)
///     Those eigenvalues, scaled to be dimensionless (a tilt's is ``GM / L``), least first.
/// hydrostatics : Hydrostatics
///     The hydrostatics at rest (``gm_transverse``, ...).
///
/// Examples
/// --------
/// A box 4 m long, 1 m deep, 2 m wide, of 2 t, its center of mass 0.1 m below its center:
///
/// >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))
/// >>> rest = box.equilibrium(mass=2000.0, center_of_mass=(0, -0.1, 0))
/// >>> round(rest.draft, 9), round(rest.heel, 6), rest.stable   # 2 t / (1000 kg/m³ · 8 m²)
/// (0.25, 0.0, True)
#[pyclass(frozen, module = "buoyancy", name = "Equilibrium")]
pub struct PyEquilibrium {
    inner: Equilibrium<f64>,
}

impl From<Equilibrium<f64>> for PyEquilibrium {
    fn from(inner: Equilibrium<f64>) -> Self {
        PyEquilibrium { inner }
    }
}

impl PyEquilibrium {
    pub fn from_state(state: &str) -> PyResult<Self> {
        pickling::state("Equilibrium", state).map(|inner| PyEquilibrium { inner })
    }
}

#[pymethods]
impl PyEquilibrium {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<pickling::Reduce<'py>> {
        pickling::reduce(py, "Equilibrium", &self.inner)
    }
    #[getter]
    fn position<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.pose.translation.vector.as_slice())
    }
    #[getter]
    fn rotation<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, &quaternion(&self.inner.pose.rotation))
    }
    #[getter]
    fn draft(&self) -> f64 {
        self.inner.draft
    }
    #[getter]
    fn heel(&self) -> f64 {
        self.inner.heel.to_degrees()
    }
    #[getter]
    fn trim(&self) -> f64 {
        self.inner.trim.to_degrees()
    }
    #[getter]
    fn residual<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.residual.as_slice())
    }
    #[getter]
    fn length(&self) -> f64 {
        self.inner.length
    }
    #[getter]
    fn iterations(&self) -> usize {
        self.inner.iterations
    }
    #[getter]
    fn restarts(&self) -> usize {
        self.inner.restarts
    }
    #[getter]
    fn stable(&self) -> bool {
        self.inner.stable
    }
    #[getter]
    fn stiffness_eigenvalues<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, &self.inner.stiffness_eigenvalues)
    }
    #[getter]
    fn hydrostatics(&self) -> PyHydrostatics {
        PyHydrostatics::from(self.inner.hydrostatics)
    }
    fn __repr__(&self) -> String {
        let e = &self.inner;
        format!(
            "Equilibrium(draft={}, heel={}, trim={}, stable={}, iterations={})",
            g(e.draft),
            g(e.heel.to_degrees()),
            g(e.trim.to_degrees()),
            if e.stable { "True" } else { "False" },
            e.iterations
        )
    }
}

/// A righting-arm (GZ) curve: at each heel imposed, the draft (and trim) solved so that the
/// body displaces its mass, and the lever ``GZ`` between the verticals through ``B`` and ``G``.
/// SI units, angles in degrees. From :meth:`Mesh.gz_curve`.
///
/// Attributes
/// ----------
/// heel, trim : ndarray, shape (K,)
///     Degrees (heel as given; trim solved, or held).
/// gz : ndarray, shape (K,)
///     The righting arm, m: positive turns the body back towards upright from a positive heel.
/// draft : ndarray, shape (K,)
///     Depth of the keel below the surface, m.
/// positions : ndarray, shape (K, 3)
/// rotations : ndarray, shape (K, 4)
///     The pose at each heel (quaternions ``(x, y, z, w)``).
/// residuals : ndarray, shape (K, 3)
///     Relative residuals ``(rho V - m) / m`` and the moments over ``m g L`` (the roll moment is
///     the heeling moment the curve measures, not a residual).
/// iterations : int
/// area : float
///     ``∫ GZ dφ`` over the curve, m·rad (trapezoidal rule).
/// max_gz, angle_of_max_gz : float
///     The greatest ``GZ`` (m) and its heel (degrees), refined by a parabola.
/// angle_of_vanishing_stability : float or None
///     The heel (degrees) past the upright where ``GZ`` falls back to zero, interpolated;
///     ``None`` if it does not within the curve (``positive_stability`` says why).
/// positive_stability : str
///     Where the range of positive stability ends: ``"vanishes"`` (at
///     ``angle_of_vanishing_stability``), ``"beyond"`` (``GZ`` is still positive at the last
///     heel) or ``"none"`` (``GZ`` is not positive at any heel above zero).
/// flooding_angle : float or None
///     For a hull whose openings were closed by lids: the first heel given (degrees) at which
///     the water reaches an opening; the curve stops before it. ``None`` otherwise.
///
/// Examples
/// --------
/// >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))
/// >>> curve = box.gz_curve(2000.0, (0, -0.1, 0), heel_deg=np.arange(0, 91, 5))
/// >>> bool((curve.gz[1:] > 0).all()), abs(round(float(curve.gz[0]), 12))
/// (True, 0.0)
/// >>> round(curve.angle_of_max_gz), round(curve.max_gz, 2), curve.angle_of_vanishing_stability
/// (40, 0.43, None)
/// >>> curve.positive_stability
/// 'beyond'
/// >>> box.gz_curve(2000.0, (0, 3.0, 0), heel_deg=np.arange(0, 91, 5)).positive_stability
/// 'none'
#[pyclass(frozen, module = "buoyancy", name = "GzCurve")]
pub struct PyGzCurve {
    inner: GzCurve<f64>,
}

impl PyGzCurve {
    pub fn from_state(state: &str) -> PyResult<Self> {
        pickling::state("GzCurve", state).map(|inner| PyGzCurve { inner })
    }

    fn column<'py>(
        &self,
        py: Python<'py>,
        f: impl Fn(&buoyancy_core::hydrostatics::GzPoint<f64>) -> f64,
    ) -> Bound<'py, PyArray1<f64>> {
        arrays::column(py, self.inner.points.iter().map(f))
    }
}

#[pymethods]
impl PyGzCurve {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<pickling::Reduce<'py>> {
        pickling::reduce(py, "GzCurve", &self.inner)
    }
    #[getter]
    fn heel<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(py, |p| p.heel.to_degrees())
    }
    #[getter]
    fn trim<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(py, |p| p.trim.to_degrees())
    }
    #[getter]
    fn gz<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(py, |p| p.gz)
    }
    #[getter]
    fn draft<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.column(py, |p| p.draft)
    }
    #[getter]
    fn positions<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        arrays::rows3(
            py,
            self.inner.points.iter().map(|p| {
                let t = p.pose.translation.vector;
                [t.x, t.y, t.z]
            }),
        )
    }
    #[getter]
    fn rotations<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let flat: Vec<f64> = self
            .inner
            .points
            .iter()
            .flat_map(|p| quaternion(&p.pose.rotation))
            .collect();
        let array = numpy::ndarray::Array2::from_shape_vec((flat.len() / 4, 4), flat)
            .unwrap_or_else(|_| unreachable!("rows of four values fill a (K, 4) array"));
        arrays::read_only(numpy::IntoPyArray::into_pyarray(array, py))
    }
    #[getter]
    fn residuals<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        arrays::rows3(
            py,
            self.inner
                .points
                .iter()
                .map(|p| [p.residual.x, p.residual.y, p.residual.z]),
        )
    }
    #[getter]
    fn iterations(&self) -> usize {
        self.inner.iterations
    }
    #[getter]
    fn area(&self) -> f64 {
        self.inner.area()
    }
    /// The area under the curve from its first heel to ``heel_deg`` (degrees, clamped to the
    /// curve), m·rad, trapezoidal with the last piece interpolated.
    #[pyo3(text_signature = "(self, heel_deg)")]
    fn area_up_to(&self, heel_deg: &Bound<'_, PyAny>) -> PyResult<f64> {
        Ok(self.inner.area_up_to(radians(heel_deg, "heel_deg")?))
    }
    #[getter]
    fn max_gz(&self) -> f64 {
        self.inner.max_gz().map_or(f64::NAN, |(_, gz)| gz)
    }
    #[getter]
    fn angle_of_max_gz(&self) -> f64 {
        self.inner
            .max_gz()
            .map_or(f64::NAN, |(heel, _)| heel.to_degrees())
    }
    #[getter]
    fn flooding_angle(&self) -> Option<f64> {
        self.inner.flooding.map(f64::to_degrees)
    }
    #[getter]
    fn angle_of_vanishing_stability(&self) -> Option<f64> {
        self.inner.vanishing_angle().map(f64::to_degrees)
    }
    #[getter]
    fn positive_stability(&self) -> &'static str {
        use buoyancy_core::hydrostatics::PositiveStability;
        match self.inner.positive_stability() {
            PositiveStability::VanishesAt(_) => "vanishes",
            PositiveStability::BeyondLastHeel => "beyond",
            PositiveStability::NotPositive => "none",
        }
    }
    fn __len__(&self) -> usize {
        self.inner.points.len()
    }
    fn __repr__(&self) -> String {
        format!(
            "GzCurve(points={}, max_gz={}, angle_of_max_gz={}, area={})",
            self.inner.points.len(),
            g(self.max_gz()),
            g(self.angle_of_max_gz()),
            g(self.inner.area())
        )
    }
}

/// The columns of a hydrostatic table: name, unit, value of a row.
type Column = (&'static str, &'static str, fn(&HydrostaticRow<f64>) -> f64);

const COLUMNS: [Column; 16] = [
    ("draft", "m", |r| r.draft),
    ("displaced_volume", "m3", |r| r.displaced_volume),
    ("displacement", "kg", |r| r.displacement),
    ("kb", "m", |r| r.kb),
    ("bm_transverse", "m", |r| r.bm_transverse),
    ("bm_longitudinal", "m", |r| r.bm_longitudinal),
    ("km_transverse", "m", |r| r.km_transverse),
    ("km_longitudinal", "m", |r| r.km_longitudinal),
    ("lcb", "m", |r| r.lcb),
    ("lcf", "m", |r| r.lcf),
    ("waterplane_area", "m2", |r| r.waterplane_area),
    ("waterline_length", "m", |r| r.waterline_length),
    ("tpc", "t/cm", |r| r.tpc),
    ("gm_longitudinal", "m", |r| r.gm_longitudinal),
    ("trim_length", "m", |r| r.trim_length),
    ("mct", "kg·m/cm", |r| r.mct),
];

/// A hydrostatic table: the body upright at each draft, one row a draft. From
/// :meth:`Mesh.hydrostatic_table`.
///
/// Each column is an attribute, a read-only array of shape (K,): ``draft`` (m),
/// ``displaced_volume`` (m³), ``displacement`` (kg), ``kb``, ``bm_transverse``,
/// ``bm_longitudinal``, ``km_transverse``, ``km_longitudinal`` (m), ``lcb``, ``lcf`` (m along
/// the longitudinal axis from the mesh origin), ``waterplane_area`` (m²), ``waterline_length``
/// (m), ``tpc`` (tonnes per centimetre immersion), ``gm_longitudinal`` and ``trim_length`` (m,
/// what the moment to change trim takes) and ``mct`` (moment to change trim one centimetre,
/// kg·m/cm). ``columns`` names them, ``units`` gives their units, ``as_dict()`` returns them
/// all.
///
/// Examples
/// --------
/// >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))
/// >>> table = box.hydrostatic_table([0.25, 0.5])
/// >>> table.displacement.round(6).tolist(), table.kb.round(12).tolist()
/// ([2000.0, 4000.0], [0.125, 0.25])
#[pyclass(frozen, module = "buoyancy", name = "HydrostaticTable")]
pub struct PyHydrostaticTable {
    rows: Vec<HydrostaticRow<f64>>,
}

impl PyHydrostaticTable {
    pub fn from_state(state: &str) -> PyResult<Self> {
        pickling::state("HydrostaticTable", state).map(|rows| PyHydrostaticTable { rows })
    }

    fn get<'py>(&self, py: Python<'py>, name: &str) -> Bound<'py, PyArray1<f64>> {
        let (_, _, f) = COLUMNS
            .iter()
            .find(|(n, _, _)| *n == name)
            .unwrap_or_else(|| unreachable!("{name} is a column"));
        arrays::column(py, self.rows.iter().map(f))
    }
}

#[pymethods]
impl PyHydrostaticTable {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<pickling::Reduce<'py>> {
        pickling::reduce(py, "HydrostaticTable", &self.rows)
    }
    #[getter]
    fn columns(&self) -> Vec<&'static str> {
        COLUMNS.iter().map(|(n, _, _)| *n).collect()
    }
    #[getter]
    fn units(&self) -> Vec<&'static str> {
        COLUMNS.iter().map(|(_, u, _)| *u).collect()
    }
    /// Every column, by name.
    fn as_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for (name, _, _) in COLUMNS {
            dict.set_item(name, self.get(py, name))?;
        }
        Ok(dict)
    }
    #[getter]
    fn draft<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "draft")
    }
    #[getter]
    fn displaced_volume<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "displaced_volume")
    }
    #[getter]
    fn displacement<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "displacement")
    }
    #[getter]
    fn kb<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "kb")
    }
    #[getter]
    fn bm_transverse<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "bm_transverse")
    }
    #[getter]
    fn bm_longitudinal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "bm_longitudinal")
    }
    #[getter]
    fn km_transverse<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "km_transverse")
    }
    #[getter]
    fn km_longitudinal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "km_longitudinal")
    }
    #[getter]
    fn lcb<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "lcb")
    }
    #[getter]
    fn lcf<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "lcf")
    }
    #[getter]
    fn waterplane_area<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "waterplane_area")
    }
    #[getter]
    fn waterline_length<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "waterline_length")
    }
    #[getter]
    fn tpc<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "tpc")
    }
    #[getter]
    fn gm_longitudinal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "gm_longitudinal")
    }
    #[getter]
    fn trim_length<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "trim_length")
    }
    #[getter]
    fn mct<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.get(py, "mct")
    }
    fn __len__(&self) -> usize {
        self.rows.len()
    }
    fn __repr__(&self) -> String {
        format!("HydrostaticTable(rows={})", self.rows.len())
    }
}
