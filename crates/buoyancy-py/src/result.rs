//! The result types: `Buoyancy` (one pose) and `BuoyancyBatch` (K poses).

use buoyancy_core::Method;
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::PyIndexError;
use pyo3::prelude::*;

/// One evaluation, world frame, SI units.
#[derive(Clone, Copy, Debug)]
pub struct Row {
    pub volume: f64,
    pub center: [f64; 3],
    pub force: [f64; 3],
    pub torque: [f64; 3],
    pub about: [f64; 3],
    pub fully_submerged: usize,
    pub partially_submerged: usize,
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
        }
    }
}

/// A number the way Python's `%.6g` prints it.
pub fn g(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{}", if x == 0.0 { 0.0 } else { x });
    }
    let exponent = x.abs().log10().floor() as i32;
    let trim = |s: String| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    };
    if (-5..6).contains(&exponent) {
        trim(format!("{:.*}", (5 - exponent).max(0) as usize, x))
    } else {
        let s = format!("{x:.5e}");
        let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
        format!("{}e{exp}", trim(mantissa.to_string()))
    }
}

/// `[a, b, c]` with `%.6g` numbers.
pub fn g3(v: &[f64; 3]) -> String {
    format!("[{}, {}, {}]", g(v[0]), g(v[1]), g(v[2]))
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
/// method : str
///     The method that computed it.
///
/// Each array attribute returns a new array.
#[pyclass(frozen, module = "buoyancy", name = "Buoyancy")]
pub struct PyBuoyancy {
    pub row: Row,
    pub method: Method,
}

#[pymethods]
impl PyBuoyancy {
    #[getter]
    fn volume(&self) -> f64 {
        self.row.volume
    }
    #[getter]
    fn center<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.row.center)
    }
    #[getter]
    fn force<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.row.force)
    }
    #[getter]
    fn torque<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.row.torque)
    }
    #[getter]
    fn about<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.row.about)
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
/// method : str
///
/// ``len(batch)`` is K; ``batch[k]`` is the :class:`Buoyancy` of pose ``k``. The arrays are
/// created once: attribute access returns the same array.
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
}

impl PyBuoyancyBatch {
    pub fn new(py: Python<'_>, rows: Vec<Row>, method: Method) -> Self {
        let k = rows.len();
        let column3 = |f: fn(&Row) -> [f64; 3]| -> Py<PyArray2<f64>> {
            let flat: Vec<f64> = rows.iter().flat_map(f).collect();
            Array2::from_shape_vec((k, 3), flat)
                .expect("K×3 values")
                .into_pyarray(py)
                .unbind()
        };
        let counts = |f: fn(&Row) -> usize| -> Py<PyArray1<i64>> {
            Array1::from_iter(rows.iter().map(|r| f(r) as i64))
                .into_pyarray(py)
                .unbind()
        };
        PyBuoyancyBatch {
            volume: Array1::from_iter(rows.iter().map(|r| r.volume))
                .into_pyarray(py)
                .unbind(),
            center: column3(|r| r.center),
            force: column3(|r| r.force),
            torque: column3(|r| r.torque),
            about: column3(|r| r.about),
            fully_submerged: counts(|r| r.fully_submerged),
            partially_submerged: counts(|r| r.partially_submerged),
            rows,
            method,
        }
    }
}

#[pymethods]
impl PyBuoyancyBatch {
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
    fn method(&self) -> &'static str {
        self.method.name()
    }

    fn __len__(&self) -> usize {
        self.rows.len()
    }

    fn __getitem__(&self, index: isize) -> PyResult<PyBuoyancy> {
        let k = self.rows.len() as isize;
        let i = if index < 0 { index + k } else { index };
        if !(0..k).contains(&i) {
            return Err(PyIndexError::new_err(format!(
                "pose index {index} out of range for a batch of {k} poses"
            )));
        }
        Ok(PyBuoyancy {
            row: self.rows[i as usize],
            method: self.method,
        })
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        let volume = self.volume.bind(py).readonly();
        let v = volume.as_array();
        let (lo, hi) = v
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
                (lo.min(x), hi.max(x))
            });
        if v.is_empty() {
            format!("BuoyancyBatch(0 poses, method='{}')", self.method)
        } else {
            format!(
                "BuoyancyBatch({} poses, volume from {} to {}, method='{}')",
                v.len(),
                g(lo),
                g(hi),
                self.method
            )
        }
    }
}
