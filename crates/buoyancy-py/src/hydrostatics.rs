//! `Mesh.waterplane`, `Mesh.hydrostatics` and `Mesh.stiffness`: the core's
//! [`buoyancy_core::hydrostatics`] at a pose, and their result classes.

use buoyancy_core::hydrostatics::{Hydrostatics, LoadingCondition, Waterplane};
use buoyancy_core::nalgebra::{Point3, Unit, Vector3};
use buoyancy_core::{Error, Pose, Water};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::prelude::*;

use crate::arrays;
use crate::convert::{self, given};
use crate::errors::{arg_error, to_py};
use crate::format::{g, g3};
use crate::mesh::PyMesh;
use crate::pickling;
use crate::water_waves::WaterWaves;

/// A read-only (n, n) array of a matrix.
fn matrix<'py, const N: usize>(
    py: Python<'py>,
    m: &buoyancy_core::nalgebra::SMatrix<f64, N, N>,
) -> Bound<'py, PyArray2<f64>> {
    arrays::read_only(Array2::from_shape_fn((N, N), |(i, j)| m[(i, j)]).into_pyarray(py))
}

/// A read-only (2, 3) array of two unit vectors, one a row.
fn axes<'py>(py: Python<'py>, axes: &[Unit<Vector3<f64>>; 2]) -> Bound<'py, PyArray2<f64>> {
    arrays::rows3(py, axes.iter().map(|a| [a.x, a.y, a.z]))
}

/// Still water only: the hydrostatics are of the still plane.
pub fn still_water(waves: Option<&WaterWaves>) -> PyResult<()> {
    match waves {
        Some(_) => Err(arg_error(
            "water",
            "has waves; hydrostatics are of the still water plane: pass a Water without waves",
        )),
        None => Ok(()),
    }
}

/// The Python exception for a loading condition's error: a `ValueError` naming the Python
/// argument (`center_of_mass`, `axis`, `mass`, ...).
pub fn loading_error(e: Error) -> PyErr {
    match e {
        Error::InvalidLoading { parameter, reason } => arg_error(
            match parameter {
                "center_of_gravity" => "center_of_mass",
                "longitudinal_axis" => "axis",
                other => other,
            },
            reason,
        ),
        e => to_py(e, None),
    }
}

/// The loading condition of the keyword arguments (mesh frame).
pub fn loading(
    center_of_mass: &Bound<'_, PyAny>,
    mass: Option<&Bound<'_, PyAny>>,
    reference_point: Option<&Bound<'_, PyAny>>,
    axis: Option<&Bound<'_, PyAny>>,
    keel: Option<&Bound<'_, PyAny>>,
) -> PyResult<LoadingCondition<f64>> {
    let point = |obj: &Bound<'_, PyAny>, name: &str| -> PyResult<Point3<f64>> {
        Ok(Point3::from(convert::vector3(obj, name)?))
    };
    let core = loading_error;
    let mut loading =
        LoadingCondition::new(point(center_of_mass, "center_of_mass")?).map_err(core)?;
    if let Some(m) = given(mass) {
        loading = loading.with_mass(convert::real(m, "mass")?).map_err(core)?;
    }
    if let Some(p) = given(reference_point) {
        loading = loading
            .with_reference_point(point(p, "reference_point")?)
            .map_err(core)?;
    }
    if let Some(a) = given(axis) {
        loading = loading
            .with_longitudinal_axis(convert::vector3(a, "axis")?)
            .map_err(core)?;
    }
    if let Some(k) = given(keel) {
        loading = loading.with_keel(point(k, "keel")?).map_err(core)?;
    }
    Ok(loading)
}

/// The waterplane of `mesh` at `pose` in `water`, without the interpreter lock.
pub fn waterplane(
    py: Python<'_>,
    mesh: &PyMesh,
    pose: &Pose<f64>,
    water: &Water<f64>,
) -> PyResult<PyWaterplane> {
    let mesh = mesh.core();
    py.detach(|| mesh.waterplane(pose, water))
        .map(|inner| PyWaterplane { inner })
        .map_err(|e| to_py(e, None))
}

/// The hydrostatics of `mesh` at `pose` in `water`, without the interpreter lock.
pub fn hydrostatics(
    py: Python<'_>,
    mesh: &PyMesh,
    pose: &Pose<f64>,
    water: &Water<f64>,
    loading: &LoadingCondition<f64>,
) -> PyResult<PyHydrostatics> {
    let mesh = mesh.core();
    py.detach(|| mesh.hydrostatics(pose, water, loading))
        .map(|inner| PyHydrostatics { inner })
        .map_err(loading_error)
}

/// The waterplane of a body at a pose: the section of the still water plane through the body,
/// world frame, SI units (m², m, m⁴). From :meth:`Mesh.waterplane`.
///
/// Attributes
/// ----------
/// area : float
///     Waterplane area, m².
/// center_of_flotation : ndarray, shape (3,)
///     Its centroid, on the water plane, m.
/// axes : ndarray, shape (2, 3)
///     The in-plane unit vectors ``e1``, ``e2`` (``e1 x e2`` is the water's up normal) that
///     ``second_moments`` is written in: ``e1`` the body's longitudinal axis projected on the
///     plane.
/// second_moments : ndarray, shape (2, 2)
///     ``[[∫η² dA, −∫ξη dA], [−∫ξη dA, ∫ξ² dA]]`` about the center of flotation, m⁴, with
///     ``ξ, η`` the coordinates along ``e1``, ``e2``: the first diagonal entry is the
///     transverse moment (about ``e1``, what rolling feels), the second the longitudinal one.
/// principal_moments : ndarray, shape (2,)
///     Its eigenvalues, least first, m⁴.
/// principal_axes : ndarray, shape (2, 3)
///     The in-plane lines through the center of flotation about which the second moments are
///     ``principal_moments``, unit vectors.
///
/// Examples
/// --------
/// >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))   # 4 m long, 2 m wide, y up
/// >>> w = box.waterplane()
/// >>> round(w.area, 12), w.second_moments.diagonal().round(12).tolist()
/// (8.0, [2.666666666667, 10.666666666667])
#[pyclass(frozen, module = "buoyancy", name = "Waterplane")]
pub struct PyWaterplane {
    inner: Waterplane<f64>,
}

impl PyWaterplane {
    pub fn from_state(state: &str) -> PyResult<Self> {
        pickling::state("Waterplane", state).map(|inner| PyWaterplane { inner })
    }
}

#[pymethods]
impl PyWaterplane {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<pickling::Reduce<'py>> {
        pickling::reduce(py, "Waterplane", &self.inner)
    }
    #[getter]
    fn area(&self) -> f64 {
        self.inner.area
    }
    #[getter]
    fn center_of_flotation<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.center_of_flotation.coords.as_slice())
    }
    #[getter]
    fn axes<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        axes(py, &self.inner.axes)
    }
    #[getter]
    fn second_moments<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        matrix::<2>(py, &self.inner.second_moments)
    }
    #[getter]
    fn principal_moments<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, &self.inner.principal_moments)
    }
    #[getter]
    fn principal_axes<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        axes(py, &self.inner.principal_axes)
    }
    fn __repr__(&self) -> String {
        format!(
            "Waterplane(area={}, center_of_flotation={})",
            g(self.inner.area),
            g3(&self.inner.center_of_flotation.coords.into())
        )
    }
}

/// The hydrostatics of a body at a pose: the waterplane, the centers, the metacentric radii and
/// heights, and the linear hydrostatic stiffness. World frame, SI units (m, m³, kg, N/m, N/rad,
/// N·m/rad). From :meth:`Mesh.hydrostatics`.
///
/// Heights are along the water's up normal ``n``; ``e1``, ``e2`` are ``waterplane.axes``
/// (``e1`` the body's longitudinal axis on the plane). *Transverse* quantities belong to
/// rolling (about ``e1``), *longitudinal* ones to pitching (about ``e2``).
///
/// Attributes
/// ----------
/// waterplane : Waterplane
/// displaced_volume : float
///     ``V``, m³.
/// center_of_buoyancy, center_of_gravity, keel, reference_point : ndarray, shape (3,)
///     ``B``, ``G``, the keel point ``K`` (the lowest vertex unless given) and the point ``P``
///     the stiffness is taken about (``G`` unless given), m.
/// mass : float
///     The mass of the weight's terms, kg: as given, else ``density * V``.
/// kb, kg : float
///     ``KB = n·(B − K)``, ``KG = n·(G − K)``, m.
/// bm_transverse, bm_longitudinal : float
///     ``I_T / V`` and ``I_L / V``, m.
/// gm_transverse, gm_longitudinal : float
///     ``KB + BM − KG``, m: positive is stable.
/// bm_principal, gm_principal : ndarray, shape (2,)
///     The same about the waterplane's principal axes, least first.
/// stiffness : ndarray, shape (3, 3)
///     The hydrostatic stiffness about ``P``, rows and columns heave (along ``n``), roll
///     (about ``e1``), pitch (about ``e2``): a small displacement ``x`` changes the vertical
///     force and the moments by ``−stiffness @ x``. In equilibrium about ``G``,
///     ``stiffness[1, 1] = density * gravity * V * gm_transverse``.
///
/// Examples
/// --------
/// >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))   # draft 0.5 m, beam 2 m
/// >>> h = box.hydrostatics(center_of_mass=(0, 0, 0))
/// >>> round(h.kb, 12), round(h.bm_transverse, 12), round(h.gm_transverse, 12)
/// (0.25, 0.666666666667, 0.416666666667)
#[pyclass(frozen, module = "buoyancy", name = "Hydrostatics")]
pub struct PyHydrostatics {
    inner: Hydrostatics<f64>,
}

impl PyHydrostatics {
    pub fn from_state(state: &str) -> PyResult<Self> {
        pickling::state("Hydrostatics", state).map(|inner| PyHydrostatics { inner })
    }
}

#[pymethods]
impl PyHydrostatics {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<pickling::Reduce<'py>> {
        pickling::reduce(py, "Hydrostatics", &self.inner)
    }
    #[getter]
    fn waterplane(&self) -> PyWaterplane {
        PyWaterplane {
            inner: self.inner.waterplane,
        }
    }
    #[getter]
    fn displaced_volume(&self) -> f64 {
        self.inner.displaced_volume
    }
    #[getter]
    fn center_of_buoyancy<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.center_of_buoyancy.coords.as_slice())
    }
    #[getter]
    fn center_of_gravity<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.center_of_gravity.coords.as_slice())
    }
    #[getter]
    fn keel<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.keel.coords.as_slice())
    }
    #[getter]
    fn reference_point<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.reference_point.coords.as_slice())
    }
    #[getter]
    fn mass(&self) -> f64 {
        self.inner.mass
    }
    #[getter]
    fn kb(&self) -> f64 {
        self.inner.kb
    }
    #[getter]
    fn kg(&self) -> f64 {
        self.inner.kg
    }
    #[getter]
    fn bm_transverse(&self) -> f64 {
        self.inner.bm_transverse
    }
    #[getter]
    fn bm_longitudinal(&self) -> f64 {
        self.inner.bm_longitudinal
    }
    #[getter]
    fn gm_transverse(&self) -> f64 {
        self.inner.gm_transverse
    }
    #[getter]
    fn gm_longitudinal(&self) -> f64 {
        self.inner.gm_longitudinal
    }
    #[getter]
    fn bm_principal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, &self.inner.bm_principal)
    }
    #[getter]
    fn gm_principal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, &self.inner.gm_principal)
    }
    #[getter]
    fn stiffness<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        matrix::<3>(py, &self.inner.stiffness)
    }
    fn __repr__(&self) -> String {
        let h = &self.inner;
        format!(
            "Hydrostatics(displaced_volume={}, kb={}, kg={}, gm_transverse={}, gm_longitudinal={})",
            g(h.displaced_volume),
            g(h.kb),
            g(h.kg),
            g(h.gm_transverse),
            g(h.gm_longitudinal)
        )
    }
}

impl From<Hydrostatics<f64>> for PyHydrostatics {
    fn from(inner: Hydrostatics<f64>) -> Self {
        PyHydrostatics { inner }
    }
}

impl PyHydrostatics {
    /// The stiffness matrix as an array.
    pub fn stiffness_array<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        matrix::<3>(py, &self.inner.stiffness)
    }
}
