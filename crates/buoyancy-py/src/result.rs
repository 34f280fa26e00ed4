//! The result types: `Buoyancy` (one pose) and `BuoyancyBatch` (K poses).

use buoyancy_core::Method;
use numpy::{PyArray1, PyArray2};
use pyo3::exceptions::PyIndexError;
use pyo3::prelude::*;
use pyo3::types::PyType;

use crate::arrays;
use crate::convert;
use crate::format::{g, g3};
use crate::pickling;

/// One evaluation, world frame, SI units.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Row {
    pub volume: f64,
    pub center: [f64; 3],
    pub force: [f64; 3],
    pub torque: [f64; 3],
    pub about: [f64; 3],
    pub fully_submerged: usize,
    pub partially_submerged: usize,
    pub wetted_area: f64,
}

impl Row {
    pub fn new(b: &buoyancy_core::Buoyancy<f64>) -> Self {
        Row {
            volume: b.submerged_volume,
            center: b.center_of_buoyancy.coords.into(),
            force: b.force.into(),
            torque: b.torque.into(),
            about: b.torque_point.coords.into(),
            fully_submerged: b.fully_submerged,
            partially_submerged: b.partially_submerged,
            wetted_area: b.wetted_area,
        }
    }
}

type V3 = (f64, f64, f64);

fn tuple(v: &[f64; 3]) -> V3 {
    (v[0], v[1], v[2])
}

/// `Buoyancy(volume, center, force, torque, about, fully_submerged, partially_submerged,
/// method, wetted_area)`'s arguments.
type BuoyancyArgs = (f64, V3, V3, V3, V3, usize, usize, &'static str, f64);

/// The `wetted_area` argument of `Buoyancy(...)`: a finite number, at least 0; 0 when absent.
fn wetted_area_argument(obj: Option<&Bound<'_, PyAny>>) -> PyResult<f64> {
    let area = convert::real_or(obj, "wetted_area", 0.0)?;
    if !(area.is_finite() && area >= 0.0) {
        return Err(crate::errors::arg_error(
            "wetted_area",
            format!("must be finite and at least 0 (m²), got {area}"),
        ));
    }
    Ok(area)
}

/// The buoyancy of a body at one pose, world frame, SI units (m, m³, N, N·m).
///
/// Attributes
/// ----------
/// volume : float
///     Submerged volume, m³ (for the surface methods: the volume implied by the force).
/// center : ndarray, shape (3,)
///     Center of buoyancy, the point of application of the force, m.
/// force : ndarray, shape (3,)
///     Buoyant force, N (``density * gravity * volume`` along the water's up normal).
/// torque : ndarray, shape (3,)
///     Torque of the buoyant force about ``about``, N·m.
/// about : ndarray, shape (3,)
///     The point the torque is taken about: the ``about`` argument, by default the body's center
///     of mass (the mesh centroid moved by the pose).
/// fully_submerged, partially_submerged : int
///     Number of triangles entirely under water, and cut by the surface.
/// wetted_area : float
///     Area of the mesh surface under water, m²: of the triangles entirely under water and of
///     the parts under water of those the surface cuts. Exact for ``"exact"``, ``"improved"``,
///     ``"exact_surface"`` and under waves (the wetted surface the pressure is integrated over);
///     ``"fast"`` and ``"fast_surface"`` count the triangles entirely under water only, what they
///     integrate over. A unit cube upright at draft ``d`` has ``1 + 4 d``.
/// method : str
///     The method that computed it.
///
/// ``Buoyancy(volume, center, force, torque, about, fully_submerged=0, partially_submerged=0,
/// method="exact", wetted_area=0.0)`` builds one (for unpickling and tests). It is immutable,
/// compares by value (every attribute) and pickles; each array attribute returns a new,
/// read-only array.
///
/// Examples
/// --------
/// >>> b = buoyancy.shapes.cube().buoyancy(position=(0, -0.25, 0))
/// >>> b.volume, b.center.tolist(), b.method
/// (0.75, [0.0, -0.375, 0.0], 'exact')
/// >>> import pickle
/// >>> pickle.loads(pickle.dumps(b)) == b
/// True
#[pyclass(frozen, eq, module = "buoyancy", name = "Buoyancy")]
#[derive(Clone, Copy, PartialEq)]
pub struct PyBuoyancy {
    pub row: Row,
    pub method: Method,
}

#[pymethods]
impl PyBuoyancy {
    #[new]
    #[pyo3(
        signature = (volume, center, force, torque, about, fully_submerged=None, partially_submerged=None, method=None, wetted_area=None),
        text_signature = "(volume, center, force, torque, about, fully_submerged=0, partially_submerged=0, method='exact', wetted_area=0.0)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        volume: &Bound<'_, PyAny>,
        center: &Bound<'_, PyAny>,
        force: &Bound<'_, PyAny>,
        torque: &Bound<'_, PyAny>,
        about: &Bound<'_, PyAny>,
        fully_submerged: Option<&Bound<'_, PyAny>>,
        partially_submerged: Option<&Bound<'_, PyAny>>,
        method: Option<&Bound<'_, PyAny>>,
        wetted_area: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        Ok(PyBuoyancy {
            row: Row {
                volume: convert::real(volume, "volume")?,
                center: convert::vector3(center, "center")?.into(),
                force: convert::vector3(force, "force")?.into(),
                torque: convert::vector3(torque, "torque")?.into(),
                about: convert::vector3(about, "about")?.into(),
                fully_submerged: convert::count_or(fully_submerged, "fully_submerged", 0)?,
                partially_submerged: convert::count_or(
                    partially_submerged,
                    "partially_submerged",
                    0,
                )?,
                wetted_area: wetted_area_argument(wetted_area)?,
            },
            method: convert::method(method)?,
        })
    }

    #[getter]
    fn volume(&self) -> f64 {
        self.row.volume
    }
    #[getter]
    fn center<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, &self.row.center)
    }
    #[getter]
    fn force<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, &self.row.force)
    }
    #[getter]
    fn torque<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, &self.row.torque)
    }
    #[getter]
    fn about<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, &self.row.about)
    }
    #[getter]
    fn fully_submerged(&self) -> usize {
        self.row.fully_submerged
    }
    #[getter]
    fn partially_submerged(&self) -> usize {
        self.row.partially_submerged
    }
    #[getter]
    fn wetted_area(&self) -> f64 {
        self.row.wetted_area
    }
    #[getter]
    fn method(&self) -> &'static str {
        self.method.name()
    }

    fn __repr__(&self) -> String {
        let r = &self.row;
        format!(
            "Buoyancy(volume={}, center={}, force={}, torque={}, method='{}')",
            g(r.volume),
            g3(&r.center),
            g3(&r.force),
            g3(&r.torque),
            self.method
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> (Bound<'py, PyType>, BuoyancyArgs) {
        let b = slf.get();
        let r = &b.row;
        (
            slf.get_type(),
            (
                r.volume,
                tuple(&r.center),
                tuple(&r.force),
                tuple(&r.torque),
                tuple(&r.about),
                r.fully_submerged,
                r.partially_submerged,
                b.method.name(),
                r.wetted_area,
            ),
        )
    }
}

/// The buoyancy of a body at K poses: arrays indexed by pose, world frame, SI units.
///
/// Attributes
/// ----------
/// volume : ndarray, shape (K,)
/// center : ndarray, shape (K, 3)
/// force : ndarray, shape (K, 3)
/// torque : ndarray, shape (K, 3)
/// about : ndarray, shape (K, 3)
///     The point each torque is taken about.
/// fully_submerged, partially_submerged : ndarray of int64, shape (K,)
/// wetted_area : ndarray, shape (K,)
///     Area under water, m², as :attr:`Buoyancy.wetted_area`.
/// method : str
///
/// ``len(batch)`` is K; ``batch[k]`` is the :class:`Buoyancy` of pose ``k``. The arrays are
/// created once and are read-only: attribute access returns the same array, and writing to it
/// raises ``ValueError`` (``np.array(batch.force)`` is a copy to change).
#[pyclass(frozen, module = "buoyancy", name = "BuoyancyBatch")]
pub struct PyBuoyancyBatch {
    rows: Vec<Row>,
    method: Method,
    volume: Py<PyArray1<f64>>,
    center: Py<PyArray2<f64>>,
    force: Py<PyArray2<f64>>,
    torque: Py<PyArray2<f64>>,
    about: Py<PyArray2<f64>>,
    fully_submerged: Py<PyArray1<i64>>,
    partially_submerged: Py<PyArray1<i64>>,
    wetted_area: Py<PyArray1<f64>>,
}

impl PyBuoyancyBatch {
    pub fn new(py: Python<'_>, rows: Vec<Row>, method: Method) -> Self {
        let rows3 = |f: fn(&Row) -> [f64; 3]| arrays::rows3(py, rows.iter().map(f)).unbind();
        let counts =
            |f: fn(&Row) -> usize| arrays::column(py, rows.iter().map(|r| f(r) as i64)).unbind();
        PyBuoyancyBatch {
            volume: arrays::column(py, rows.iter().map(|r| r.volume)).unbind(),
            center: rows3(|r| r.center),
            force: rows3(|r| r.force),
            torque: rows3(|r| r.torque),
            about: rows3(|r| r.about),
            fully_submerged: counts(|r| r.fully_submerged),
            partially_submerged: counts(|r| r.partially_submerged),
            wetted_area: arrays::column(py, rows.iter().map(|r| r.wetted_area)).unbind(),
            rows,
            method,
        }
    }

    /// The batch pickled as `state` (see [`pickling`]).
    pub fn from_state(py: Python<'_>, state: &str) -> PyResult<Self> {
        let (method, rows): (String, Vec<Row>) = pickling::state("BuoyancyBatch", state)?;
        let method = method
            .parse()
            .map_err(|e| crate::errors::to_py(e, Some("state")))?;
        Ok(Self::new(py, rows, method))
    }
}

#[pymethods]
impl PyBuoyancyBatch {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<pickling::Reduce<'py>> {
        pickling::reduce(py, "BuoyancyBatch", &(self.method.name(), &self.rows))
    }

    #[getter]
    fn volume(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.volume.clone_ref(py)
    }
    #[getter]
    fn center(&self, py: Python<'_>) -> Py<PyArray2<f64>> {
        self.center.clone_ref(py)
    }
    #[getter]
    fn force(&self, py: Python<'_>) -> Py<PyArray2<f64>> {
        self.force.clone_ref(py)
    }
    #[getter]
    fn torque(&self, py: Python<'_>) -> Py<PyArray2<f64>> {
        self.torque.clone_ref(py)
    }
    #[getter]
    fn about(&self, py: Python<'_>) -> Py<PyArray2<f64>> {
        self.about.clone_ref(py)
    }
    #[getter]
    fn fully_submerged(&self, py: Python<'_>) -> Py<PyArray1<i64>> {
        self.fully_submerged.clone_ref(py)
    }
    #[getter]
    fn partially_submerged(&self, py: Python<'_>) -> Py<PyArray1<i64>> {
        self.partially_submerged.clone_ref(py)
    }
    #[getter]
    fn wetted_area(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.wetted_area.clone_ref(py)
    }
    #[getter]
    fn method(&self) -> &'static str {
        self.method.name()
    }

    fn __len__(&self) -> usize {
        self.rows.len()
    }

    fn __getitem__(&self, index: &Bound<'_, PyAny>) -> PyResult<PyBuoyancy> {
        let k = self.rows.len();
        let i = crate::convert::index(index, "index")?;
        let row = i
            .and_then(|i| {
                if i < 0 {
                    k.checked_sub(usize::try_from(i.unsigned_abs()).ok()?)
                } else {
                    usize::try_from(i).ok().filter(|&i| i < k)
                }
            })
            .and_then(|i| self.rows.get(i));
        match row {
            Some(&row) => Ok(PyBuoyancy {
                row,
                method: self.method,
            }),
            None => Err(PyIndexError::new_err(format!(
                "pose index {} out of range for a batch of {k} poses",
                crate::convert::python_str(index)
            ))),
        }
    }

    fn __repr__(&self) -> String {
        let volumes = self.rows.iter().map(|r| r.volume);
        let (lo, hi) = volumes.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        });
        if self.rows.is_empty() {
            format!("BuoyancyBatch(0 poses, method='{}')", self.method)
        } else {
            format!(
                "BuoyancyBatch({} poses, volume from {} to {}, method='{}')",
                self.rows.len(),
                g(lo),
                g(hi),
                self.method
            )
        }
    }
}
