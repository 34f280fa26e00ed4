//! `Water`: a body of water, its still plane and, optionally, the waves on it.

use buoyancy_core::nalgebra::Point3;
use numpy::PyArray1;
use pyo3::IntoPyObjectExt;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyType;

use crate::arrays;
use crate::convert::{self, floats, shape_str};
use crate::errors::{arg_error, to_py, type_name};
use crate::format::g;
use crate::water_waves::WaterWaves;

/// `Water(density, gravity, level, normal, waves)`'s arguments.
type WaterArgs<'py> = (f64, f64, f64, (f64, f64, f64), Option<Bound<'py, PyAny>>);

/// A body of water, world frame, SI units: its still plane, and optionally the waves on it.
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
/// waves : optional
///     The free surface, as its elevation ``η`` (m, along ``normal``) above the still plane at
///     horizontal positions (world points projected onto the still plane) and time ``t`` (s):
///     an :class:`AiryWave`, :class:`Waves`, a :class:`HeightGrid`, or a vectorised callable
///     ``f(points, t)`` taking the positions as an (N, 3) array and returning N elevations,
///     called once per evaluation (with the interpreter lock held around the call only).
///     ``None`` (default): still water, ``η = 0``.
///
/// On waves, :meth:`Mesh.buoyancy` integrates the hydrostatic pressure ``ρ g (η − h)`` (``h``
/// the height above the still plane) over the wetted surface, which is cut exactly where the
/// depth, interpolated linearly between the vertices, is zero: the methods ``"exact"`` (the
/// default) and ``"exact_surface"`` alike (the other methods assume a flat surface). Under :class:`Waves` of
/// ``pressure="froude_krylov"`` it integrates the linear Froude–Krylov pressure instead, whose
/// wave part decays with depth (see :class:`Waves`).
///
/// Raises ``ValueError`` naming the parameter that is out of range, ``TypeError`` naming the
/// parameter that is not a number (or not 3 numbers, for ``normal``; or not a surface, for
/// ``waves``).
///
/// >>> buoyancy.Water(density=1025.0, normal=(0, 0, 1))
/// Water(density=1025, gravity=9.81, level=0, normal=(0, 0, 1))
/// >>> buoyancy.Water(gravity=(0, 0, -9.81))
/// Traceback (most recent call last):
/// ...
/// TypeError: gravity: expected a number, the magnitude of gravity in m/s², got tuple; its direction is -normal: for the vector (0, 0, -9.81) write Water(gravity=9.81, normal=(0, 0, 1))
///
/// A swell along x, and the elevation it gives:
///
/// >>> swell = buoyancy.Water(waves=buoyancy.AiryWave(amplitude=0.5, wavelength=20.0))
/// >>> swell
/// Water(density=1000, gravity=9.81, level=0, normal=(0, 1, 0), waves=AiryWave(amplitude=0.5, wavelength=20, direction=(1, 0, 0), phase=0))
/// >>> round(swell.elevation((0, -3, 0)), 12), round(swell.elevation((10, 2, 0)), 12)
/// (0.5, -0.5)
///
/// ``Water`` is immutable, safe to share between threads, compares by value (the same callable,
/// for waves given as one) and pickles (with waves given as a callable: only if the callable
/// pickles). Its waves can be a :class:`HeightGrid`, whose heights change in place.
#[pyclass(frozen, eq, module = "buoyancy", name = "Water")]
pub struct PyWater {
    pub inner: buoyancy_core::Water<f64>,
    /// The normal as given, for pickling bit for bit.
    given_normal: [f64; 3],
    /// The waves; `None` for still water.
    pub waves: Option<WaterWaves>,
}

/// Two waters are equal when they are the same physical water (normals compared after
/// normalisation) with the same waves.
impl PartialEq for PyWater {
    fn eq(&self, other: &Self) -> bool {
        self.inner == other.inner && self.waves == other.waves
    }
}

impl PyWater {
    /// Still water, `inner`.
    pub fn still(inner: buoyancy_core::Water<f64>) -> Self {
        PyWater {
            inner,
            given_normal: inner.normal().into_inner().into(),
            waves: None,
        }
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
        signature = (density=None, gravity=None, level=None, normal=None, waves=None),
        text_signature = "(density=1000.0, gravity=9.81, level=0.0, normal=(0.0, 1.0, 0.0), waves=None)"
    )]
    fn new(
        density: Option<&Bound<'_, PyAny>>,
        gravity: Option<&Bound<'_, PyAny>>,
        level: Option<&Bound<'_, PyAny>>,
        normal: Option<&Bound<'_, PyAny>>,
        waves: Option<&Bound<'_, PyAny>>,
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
        let waves = convert::given(waves)
            .map(|w| WaterWaves::parse(w, &inner))
            .transpose()?;
        Ok(PyWater {
            inner,
            given_normal: n.into(),
            waves,
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

    /// The waves as given (an :class:`AiryWave`, :class:`Waves`, :class:`HeightGrid` or
    /// callable), ``None`` for still water.
    #[getter]
    fn waves<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyAny>> {
        self.waves.as_ref().map(|w| w.given(py))
    }

    /// The elevation ``η`` of the free surface above the still plane, m (along ``normal``), at
    /// the given world points projected onto the still plane, at ``time``.
    ///
    /// Parameters
    /// ----------
    /// points : array_like, shape (N, 3) or (3,)
    ///     World points, m; only their projection onto the still plane matters.
    /// time : float
    ///     s, finite (default 0).
    ///
    /// Returns
    /// -------
    /// ndarray, shape (N,), or float for one point of shape (3,)
    ///     Zero everywhere on still water. The surface is at ``level + η`` along ``normal``.
    ///
    /// Examples
    /// --------
    /// >>> sea = buoyancy.Water(normal=(0, 0, 1), waves=lambda p, t: 0.1 * p[:, 0] + t)
    /// >>> sea.elevation([(1, 2, 3), (2, 0, -5)], time=0.5).tolist()  # z up: p[:, 2] is 0
    /// [0.6, 0.7]
    /// >>> buoyancy.Water().elevation((1, 2, 3))
    /// 0.0
    #[pyo3(signature = (points, time=None), text_signature = "(self, points, time=0.0)")]
    fn elevation<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
        time: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let time = convert::time(time, "time")?;
        let a = floats(points, "points")?;
        let single = match a.shape.as_slice() {
            [3] => true,
            [_, 3] => false,
            _ => {
                return Err(arg_error(
                    "points",
                    format!(
                        "expected shape (N, 3) or (3,), got shape {}",
                        shape_str(&a.shape)
                    ),
                ));
            }
        };
        if let Some(i) = a
            .values
            .chunks_exact(3)
            .position(|p| !p.iter().all(|x| x.is_finite()))
        {
            let name = if single {
                "points".into()
            } else {
                format!("points[{i}]")
            };
            return Err(arg_error(&name, "has a NaN or infinite component"));
        }
        let water = &self.inner;
        let projected: Vec<Point3<f64>> = a
            .values
            .chunks_exact(3)
            .map(|p| water.project(&Point3::from_slice(p)))
            .collect();
        let elevations = match &self.waves {
            None => vec![0.0; projected.len()],
            Some(waves) => waves
                .elevations(water, &projected, time)
                .map_err(|f| f.into_py(None))?,
        };
        if single {
            elevations[0].into_bound_py_any(py)
        } else {
            let array = PyArray1::from_vec(py, elevations);
            Ok(array.into_any())
        }
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let n = self.inner.normal();
        let waves = match &self.waves {
            Some(w) => format!(", waves={}", w.given(py).repr()?),
            None => String::new(),
        };
        Ok(format!(
            "Water(density={}, gravity={}, level={}, normal=({}, {}, {}){waves})",
            g(self.inner.density()),
            g(self.inner.gravity()),
            g(self.inner.level()),
            g(n.x),
            g(n.y),
            g(n.z)
        ))
    }

    /// Pickles as its arguments; the waves as given (a callable only if it pickles).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyType>, WaterArgs<'py>)> {
        let w = slf.get();
        let [x, y, z] = w.given_normal;
        let waves = w
            .waves
            .as_ref()
            .map(|waves| waves.to_pickle(slf.py()))
            .transpose()?;
        Ok((
            slf.get_type(),
            (
                w.inner.density(),
                w.inner.gravity(),
                w.inner.level(),
                (x, y, z),
                waves,
            ),
        ))
    }
}
