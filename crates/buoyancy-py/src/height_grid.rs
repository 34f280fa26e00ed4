//! `HeightGrid`: elevations on a regular grid (an ocean computed elsewhere), the core's
//! `HeightGrid`, its axes chosen from the normal of the water it is given to, its heights
//! replaceable in place.

use std::sync::{RwLock, RwLockReadGuard};

use buoyancy_core::nalgebra::{Point3, Vector3};
use buoyancy_core::water::{HeightGrid, WaterSurface};
use buoyancy_core::{Error, Water};
use numpy::IntoPyArray;
use numpy::PyArray2;
use numpy::ndarray::Array2;
use pyo3::prelude::*;
use pyo3::types::PyType;

use crate::arrays;
use crate::convert::{self, floats, shape_str};
use crate::errors::{arg_error, to_py};
use crate::format::g;

/// `HeightGrid(heights, spacing, origin, periodic)`'s arguments.
type HeightGridArgs<'py> = (Bound<'py, PyArray2<f64>>, (f64, f64), (f64, f64), bool);

/// The two world axes (0 = x, 1 = y, 2 = z) along which a grid's columns and rows run in water
/// of up normal `normal`: those other than the axis most aligned with the normal (ties go to y,
/// then z), in the order (x, z) for y, (x, y) for z, (y, z) for x.
pub fn grid_axes(normal: &Vector3<f64>) -> [usize; 2] {
    let a = normal.abs();
    if a.y >= a.z && a.y >= a.x {
        [0, 2]
    } else if a.z >= a.x {
        [0, 1]
    } else {
        [1, 2]
    }
}

/// Heights on a regular grid, interpolated bilinearly: the elevation ``η`` of the water surface
/// above its still plane (m, along the up normal), for an ocean computed elsewhere (an FFT
/// ocean, a game engine's water). The heights do not depend on time: replace them each step
/// with :meth:`set_heights`.
///
/// Parameters
/// ----------
/// heights : array_like, shape (rows, columns)
///     Elevations at the nodes, m, finite; at least 2 rows and 2 columns.
///     ``heights[j, i]`` is the node of column ``i`` and row ``j``.
/// spacing : float or array_like, shape (2,)
///     Distance between neighbouring columns and between neighbouring rows, m, finite and
///     positive; one number for both.
/// origin : array_like, shape (2,)
///     Where node ``[0, 0]`` is, along the column and the row axis, m (default ``(0, 0)``).
/// periodic : bool
///     Whether the grid repeats (default ``True``), with periods ``columns * spacing[0]`` and
///     ``rows * spacing[1]`` (one tile, as an FFT ocean's: the last column is not a copy of the
///     first). Otherwise the edge values hold beyond the edges.
///
/// The axes come from the up normal of the :class:`Water` the grid is given to: a point of the
/// still plane is found on the grid by its two world coordinates other than the one most
/// aligned with the normal. For y up, columns run along x and rows along z; for z up, along x
/// and y; for x up, along y and z. So with y up, ``heights[j, i]`` is the elevation at
/// ``x = origin[0] + i * spacing[0]``, ``z = origin[1] + j * spacing[1]``. For a tilted normal
/// the grid is the one seen along that axis (the axis most aligned with the normal; ties go to
/// y, then z), projected along it onto the still plane.
///
/// Raises ``ValueError`` naming the parameter that is out of range or of the wrong shape.
///
/// Examples
/// --------
/// >>> x = np.arange(64) * 0.5                           # 64 columns, 0.5 m apart
/// >>> heights = np.tile(0.3 * np.cos(2 * np.pi * x / 32.0), (8, 1))  # (8, 64): crests along z
/// >>> grid = buoyancy.HeightGrid(heights, spacing=0.5)
/// >>> grid
/// HeightGrid(shape=(8, 64), spacing=(0.5, 0.5), origin=(0, 0), periodic=True)
/// >>> sea = buoyancy.Water(waves=grid)                 # y up: columns along x, rows along z
/// >>> sea.elevation([(0, 0, 0), (8, 0, 1.2), (48, 0, 0)]).round(12).tolist()  # 48 m: wrapped
/// [0.3, 0.0, -0.3]
/// >>> grid.set_heights(np.zeros((8, 64)))               # in place: the water follows
/// >>> sea.elevation((0, 0, 0))
/// 0.0
///
/// A ``HeightGrid`` is the one object of this package that changes (:meth:`set_heights`);
/// every :class:`Water` holding it sees the new heights. It compares by value (so it is not
/// hashable) and pickles with the heights it has.
#[pyclass(frozen, eq, module = "buoyancy", name = "HeightGrid")]
pub struct PyHeightGrid {
    /// The core's grid in grid coordinates: node `(i, j)` at `origin + (i·spacing[0], j·spacing[1], 0)`.
    grid: RwLock<HeightGrid<f64>>,
    rows: usize,
    columns: usize,
    spacing: [f64; 2],
    origin: [f64; 2],
    periodic: bool,
}

/// Two grids are equal when they have the same shape, spacing, origin, periodicity and heights.
impl PartialEq for PyHeightGrid {
    fn eq(&self, other: &Self) -> bool {
        if std::ptr::eq(self, other) {
            return true;
        }
        self.rows == other.rows
            && self.columns == other.columns
            && self.spacing == other.spacing
            && self.origin == other.origin
            && self.periodic == other.periodic
            && self.read().heights() == other.read().heights()
    }
}

/// Two numbers: one for both (when `one_for_both`) or an array-like of shape (2,).
fn pair(obj: &Bound<'_, PyAny>, name: &str, one_for_both: bool) -> PyResult<[f64; 2]> {
    if one_for_both && let Ok(x) = obj.extract::<f64>() {
        return Ok([x, x]);
    }
    let a = floats(obj, name)?;
    if a.shape != [2] {
        let expected = if one_for_both {
            "one number or 2 numbers (shape (2,))"
        } else {
            "2 numbers (shape (2,))"
        };
        return Err(arg_error(
            name,
            format!("expected {expected}, got shape {}", shape_str(&a.shape)),
        ));
    }
    Ok([a.values[0], a.values[1]])
}

/// Heights of shape (rows, columns), as (rows, columns, values row after row).
fn height_array(obj: &Bound<'_, PyAny>) -> PyResult<(usize, usize, Vec<f64>)> {
    let a = floats(obj, "heights")?;
    match a.shape.as_slice() {
        &[rows, columns] if rows >= 2 && columns >= 2 => Ok((rows, columns, a.values)),
        _ => Err(arg_error(
            "heights",
            format!(
                "expected shape (rows, columns) with at least 2 rows and 2 columns, got shape {}",
                shape_str(&a.shape)
            ),
        )),
    }
}

impl PyHeightGrid {
    /// The core's grid, for reading (a poisoned lock is taken over: the grid is never left
    /// half-written, `set_heights` checks before it copies).
    fn read(&self) -> RwLockReadGuard<'_, HeightGrid<f64>> {
        self.grid.read().unwrap_or_else(|p| p.into_inner())
    }

    /// Runs `work` with this grid as a surface of `water`: the still-plane points it is given are
    /// read at their two world coordinates along the grid's axes (see [`grid_axes`]).
    pub fn with_surface<R>(
        &self,
        water: &Water<f64>,
        work: impl FnOnce(&dyn WaterSurface<f64>) -> R,
    ) -> R {
        let grid = self.read();
        let on_water = GridOnWater {
            grid: &grid,
            axes: grid_axes(water.normal()),
        };
        work(&on_water)
    }
}

/// A grid read at the world coordinates `axes` of each still-plane point.
struct GridOnWater<'a> {
    grid: &'a HeightGrid<f64>,
    axes: [usize; 2],
}

impl WaterSurface<f64> for GridOnWater<'_> {
    fn elevations(
        &self,
        water: &Water<f64>,
        points: &[Point3<f64>],
        time: f64,
        elevations: &mut [f64],
    ) -> Result<(), Error> {
        let [u, v] = self.axes;
        let on_grid: Vec<Point3<f64>> = points
            .iter()
            .map(|p| Point3::new(p[u], p[v], 0.0))
            .collect();
        self.grid.elevations(water, &on_grid, time, elevations)
    }

    fn elevation_bound(&self) -> Option<f64> {
        self.grid.elevation_bound()
    }

    /// The grid's range over the disc about the center's still-plane point read at the grid's
    /// axes: dropping a coordinate brings no two points further apart, so the points of the
    /// disc are read within the same radius.
    fn elevation_range(
        &self,
        water: &Water<f64>,
        center: &Point3<f64>,
        radius: f64,
        time: f64,
    ) -> Option<(f64, f64)> {
        let [u, v] = self.axes;
        let q = water.project(center);
        // The grid's own plane is z = 0: a water of up normal z reads its points as they are.
        let flat = Water::new(water.density(), water.gravity(), Vector3::z(), 0.0).ok()?;
        self.grid
            .elevation_range(&flat, &Point3::new(q[u], q[v], 0.0), radius, time)
    }
}

#[pymethods]
impl PyHeightGrid {
    #[new]
    #[pyo3(
        signature = (heights, spacing, origin=None, periodic=None),
        text_signature = "(heights, spacing, origin=(0.0, 0.0), periodic=True)"
    )]
    fn new(
        py: Python<'_>,
        heights: &Bound<'_, PyAny>,
        spacing: &Bound<'_, PyAny>,
        origin: Option<&Bound<'_, PyAny>>,
        periodic: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let (rows, columns, values) = height_array(heights)?;
        let spacing = pair(spacing, "spacing", true)?;
        if !spacing.iter().all(|s| s.is_finite() && *s > 0.0) {
            return Err(arg_error("spacing", "must be finite and positive (m)"));
        }
        let origin = match convert::given(origin) {
            Some(o) => pair(o, "origin", false)?,
            None => [0.0, 0.0],
        };
        convert::finite(&origin, "origin")?;
        let periodic = match convert::given(periodic) {
            Some(p) => p
                .extract::<bool>()
                .map_err(|_| crate::errors::type_error("periodic", "True or False", p))?,
            None => true,
        };
        let grid = py
            .detach(move || {
                HeightGrid::new(
                    values,
                    columns,
                    rows,
                    Point3::new(origin[0], origin[1], 0.0),
                    Vector3::new(spacing[0], 0.0, 0.0),
                    Vector3::new(0.0, spacing[1], 0.0),
                    periodic,
                )
            })
            .map_err(|e| to_py(e, Some("heights")))?;
        Ok(PyHeightGrid {
            grid: RwLock::new(grid),
            rows,
            columns,
            spacing,
            origin,
            periodic,
        })
    }

    /// Replaces the heights in place (no new storage), shape ``(rows, columns)`` as the grid's,
    /// m, finite. Every :class:`Water` holding the grid sees them from then on; on an error the
    /// grid is unchanged.
    ///
    /// >>> grid = buoyancy.HeightGrid(np.zeros((4, 4)), spacing=1.0)
    /// >>> grid.set_heights(np.ones((4, 4)))
    /// >>> float(grid.heights.max())
    /// 1.0
    /// >>> grid.set_heights(np.ones((4, 5)))
    /// Traceback (most recent call last):
    /// ...
    /// ValueError: heights: expected shape (4, 4), the grid's (rows, columns), got shape (4, 5)
    #[pyo3(text_signature = "(self, heights)")]
    fn set_heights(&self, py: Python<'_>, heights: &Bound<'_, PyAny>) -> PyResult<()> {
        let a = floats(heights, "heights")?;
        if a.shape != [self.rows, self.columns] {
            return Err(arg_error(
                "heights",
                format!(
                    "expected shape ({}, {}), the grid's (rows, columns), got shape {}",
                    self.rows,
                    self.columns,
                    shape_str(&a.shape)
                ),
            ));
        }
        // Without the interpreter lock while waiting for evaluations that read the grid.
        py.detach(|| {
            self.grid
                .write()
                .unwrap_or_else(|p| p.into_inner())
                .set_heights(&a.values)
        })
        .map_err(|e| to_py(e, Some("heights")))
    }

    /// The heights, shape (rows, columns), m (a new, read-only array).
    #[getter]
    fn heights<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let values = self.read().heights().to_vec();
        let array = Array2::from_shape_vec((self.rows, self.columns), values)
            .unwrap_or_else(|_| unreachable!("the grid holds rows × columns heights"));
        arrays::read_only(array.into_pyarray(py))
    }
    /// ``(rows, columns)``.
    #[getter]
    fn shape(&self) -> (usize, usize) {
        (self.rows, self.columns)
    }
    /// Distance between neighbouring columns and between neighbouring rows, m.
    #[getter]
    fn spacing(&self) -> (f64, f64) {
        (self.spacing[0], self.spacing[1])
    }
    /// Where node ``[0, 0]`` is along the column and the row axis, m.
    #[getter]
    fn origin(&self) -> (f64, f64) {
        (self.origin[0], self.origin[1])
    }
    /// Whether the grid repeats beyond its edges.
    #[getter]
    fn periodic(&self) -> bool {
        self.periodic
    }

    fn __repr__(&self) -> String {
        format!(
            "HeightGrid(shape=({}, {}), spacing=({}, {}), origin=({}, {}), periodic={})",
            self.rows,
            self.columns,
            g(self.spacing[0]),
            g(self.spacing[1]),
            g(self.origin[0]),
            g(self.origin[1]),
            if self.periodic { "True" } else { "False" }
        )
    }

    /// Pickles as the heights it has now, the spacing, origin and periodicity.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> (Bound<'py, PyType>, HeightGridArgs<'py>) {
        let this = slf.get();
        (
            slf.get_type(),
            (
                this.heights(slf.py()),
                this.spacing(),
                this.origin(),
                this.periodic,
            ),
        )
    }
}
