//! The waves of a `Water`: Airy or Gerstner waves, a height grid or a Python callable, as given,
//! and the evaluations on them (buoyancy, elevations), whose failures name what failed.

use buoyancy_core::nalgebra::Point3;
use buoyancy_core::query::{Pressure, Query, Sea};
use buoyancy_core::water::{AiryComponent, AiryWaves, BREAKING_STEEPNESS, WaterSurface};
use buoyancy_core::{Buoyancy, Error, Mesh, Pose, Water};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyType;

use crate::airy::{PyAiryWave, PyWaves};
use crate::errors::{to_py, type_error, warn_user};
use crate::gerstner::PyGerstnerWaves;
use crate::height_grid::PyHeightGrid;
use crate::surface_function::{FunctionFailure, SurfaceFunction};

/// What the `waves` argument of `Water` accepts, for error messages.
const EXPECTED: &str = "a buoyancy.AiryWave, buoyancy.Waves, buoyancy.GerstnerWaves, buoyancy.HeightGrid or a callable f(points, t)";

/// The surface the core integrates under.
enum Surface {
    Airy(PyWaves),
    Gerstner(PyGerstnerWaves),
    Grid(Py<PyHeightGrid>),
    Function(Py<PyAny>),
}

/// A `Water`'s waves: the object given, and the surface it stands for.
pub struct WaterWaves {
    given: Py<PyAny>,
    surface: Surface,
}

/// Why an evaluation on waves failed.
pub enum Failure {
    /// The core's error.
    Core(Error),
    /// The Python surface function's.
    Function(FunctionFailure),
    /// A warning turned into an error (`warnings.simplefilter("error")`).
    Raised(PyErr),
}

impl Failure {
    /// The Python exception, its message prefixed with `argument` when given (`"pose 3"`): the
    /// core's errors as [`to_py`] maps them, a surface function's exception as it raised it, its
    /// wrong result as a `ValueError` naming `waves`.
    pub fn into_py(self, argument: Option<&str>) -> PyErr {
        match self {
            Failure::Core(e) => to_py(e, argument),
            Failure::Raised(e) => e,
            Failure::Function(FunctionFailure::Raised(e)) => e,
            Failure::Function(FunctionFailure::Invalid(message)) => {
                PyValueError::new_err(match argument {
                    Some(a) => format!("{a}: waves: {message}"),
                    None => format!("waves: {message}"),
                })
            }
        }
    }
}

/// Two waves are equal when they are the same surface: equal Airy waves, equal grids, the same
/// callable.
impl PartialEq for WaterWaves {
    fn eq(&self, other: &Self) -> bool {
        match (&self.surface, &other.surface) {
            (Surface::Airy(a), Surface::Airy(b)) => a == b,
            (Surface::Gerstner(a), Surface::Gerstner(b)) => a == b,
            (Surface::Grid(a), Surface::Grid(b)) => a.get() == b.get(),
            (Surface::Function(a), Surface::Function(b)) => a.is(b),
            _ => false,
        }
    }
}

impl WaterWaves {
    /// The `waves` argument of a `Water` whose still plane is `water`. Airy and Gerstner waves
    /// are evaluated once at the origin, so that a direction along the water's normal is
    /// reported here. A sea state drawn without `water=` for another gravity or normal is drawn
    /// again for this water's; one drawn with `water=` another water is an error.
    pub fn parse(obj: &Bound<'_, PyAny>, water: &Water<f64>) -> PyResult<Self> {
        let py = obj.py();
        let mut given = obj.clone();
        let surface = if let Ok(wave) = obj.cast::<PyAiryWave>() {
            Surface::Airy(PyWaves::single(wave.get())?)
        } else if let Ok(waves) = obj.cast::<PyWaves>() {
            let waves = waves.get();
            let redrawn = waves.origin.as_ref().map(|o| o.for_water(py, water));
            match redrawn.transpose()?.flatten() {
                Some((inner, origin)) => {
                    let drawn = PyWaves {
                        inner,
                        origin: Some(origin),
                        pressure: waves.pressure,
                    };
                    given = Bound::new(py, drawn.clone())?.into_any();
                    Surface::Airy(drawn)
                }
                None => Surface::Airy(waves.clone()),
            }
        } else if let Ok(waves) = obj.cast::<PyGerstnerWaves>() {
            Surface::Gerstner(waves.get().clone())
        } else if let Ok(grid) = obj.cast::<PyHeightGrid>() {
            Surface::Grid(grid.clone().unbind())
        } else if obj.is_callable() && !obj.is_instance_of::<PyType>() {
            Surface::Function(obj.clone().unbind())
        } else {
            return Err(type_error("waves", EXPECTED, obj));
        };
        let directions: Option<&dyn WaterSurface<f64>> = match &surface {
            Surface::Airy(waves) => Some(&waves.inner),
            Surface::Gerstner(waves) => Some(&waves.inner),
            _ => None,
        };
        if let Some(waves) = directions {
            waves
                .elevations(water, &[Point3::origin()], 0.0, &mut [0.0])
                .map_err(|e| to_py(e, Some("waves")))?;
        }
        let components = match &surface {
            Surface::Airy(waves) => Some(waves.inner.clone()),
            Surface::Gerstner(waves) => Some(
                AiryWaves::new(waves.inner.components().to_vec(), None)
                    .map_err(|e| to_py(e, Some("waves")))?,
            ),
            _ => None,
        };
        if let Some((k, steepness)) = components.and_then(|w| w.steepest())
            && steepness > BREAKING_STEEPNESS
        {
            let message = format!(
                "waves: component {k} is steeper than a wave can be (H/λ = {} > 1/7, where waves \
                 break): linear theory's surface and pressure are a look here, not the sea's",
                crate::format::g(steepness)
            );
            warn_user(py, &message)?;
        }
        Ok(WaterWaves {
            given: given.unbind(),
            surface,
        })
    }

    /// The object given as `waves`.
    pub fn given<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        self.given.bind(py).clone()
    }

    /// The object to pickle in place of the waves: the one given, if it pickles (a Python
    /// callable pickles only by reference, as a module-level function).
    pub fn to_pickle<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let given = self.given(py);
        if let Surface::Function(_) = self.surface
            && let Err(cause) = py.import("pickle")?.call_method1("dumps", (&given,))
        {
            let error = PyTypeError::new_err(
                "waves: a Water whose waves are a Python callable pickles only if the callable does \
                 (a module-level function does, a lambda or a closure does not); rebuild the Water \
                 from the callable's parameters instead",
            );
            error.set_cause(py, Some(cause));
            return Err(error);
        }
        Ok(given)
    }

    /// Runs `work` on the surface at evaluation, and maps its error: the surface function's
    /// failure, if it failed, else the core's error.
    fn on_surface<R>(
        &self,
        water: &Water<f64>,
        work: impl FnOnce(&dyn WaterSurface<f64>) -> Result<R, Error>,
    ) -> Result<R, Failure> {
        match &self.surface {
            Surface::Airy(waves) => work(&waves.inner).map_err(Failure::Core),
            Surface::Gerstner(waves) => work(&waves.inner).map_err(Failure::Core),
            Surface::Grid(grid) => grid.get().with_surface(water, work).map_err(Failure::Core),
            Surface::Function(function) => {
                let surface = SurfaceFunction::new(function);
                let result = work(&surface);
                match (result, surface.failure()) {
                    (Err(_), Some(failure)) => Err(Failure::Function(failure)),
                    (result, _) => result.map_err(Failure::Core),
                }
            }
        }
    }

    /// The pressure of these waves: that of `Waves`, the hydrostatic one for other surfaces.
    fn pressure(&self) -> Pressure {
        match &self.surface {
            Surface::Airy(waves) => waves.pressure,
            _ => Pressure::Hydrostatic,
        }
    }

    /// The buoyancy of `mesh` at `pose` in `water` under these waves at `time` (s), computed as
    /// `query` says: the core's `Mesh::buoyancy` under a `Sea` of these waves and their
    /// pressure, after the warnings of the sampling and (for the hydrostatic pressure) the
    /// depth.
    pub fn buoyancy(
        &self,
        mesh: &Mesh<f64>,
        pose: &Pose<f64>,
        water: &Water<f64>,
        time: f64,
        query: Query,
    ) -> Result<Buoyancy<f64>, Failure> {
        self.check_sampling(mesh)?;
        let pressure = self.pressure();
        if pressure == Pressure::Hydrostatic {
            self.check_depth(mesh, pose, water)?;
        }
        self.on_surface(water, |surface| {
            mesh.buoyancy(
                pose,
                Sea::new(water, surface, time).with_pressure(pressure),
                query,
            )
        })
    }

    /// The components of Airy or Gerstner waves; `None` for a grid or a function.
    fn linear_components(&self) -> Option<&[AiryComponent<f64>]> {
        match &self.surface {
            Surface::Airy(waves) => Some(waves.inner.components()),
            Surface::Gerstner(waves) => Some(waves.inner.components()),
            _ => None,
        }
    }

    /// Warns (a `UserWarning`, once per place in the caller's code) when a body lies deeper
    /// under Airy or Gerstner waves than their longest wavelength over 2π, with the default
    /// hydrostatic pressure: that pressure carries the surface's `ρg(η − z)` to any depth, where
    /// the sea's decays as `e^{kz}` (already by 1/e there), so a submerged body would feel the
    /// wave force it feels at the surface. The Froude–Krylov pressure is the one for it.
    fn check_depth(
        &self,
        mesh: &Mesh<f64>,
        pose: &Pose<f64>,
        water: &Water<f64>,
    ) -> Result<(), Failure> {
        let Some(components) = self.linear_components() else {
            return Ok(());
        };
        let longest = components
            .iter()
            .filter(|c| c.amplitude > 0.0)
            .map(|c| c.wavelength)
            .reduce(f64::max);
        let Some(longest) = longest else {
            return Ok(());
        };
        let decay_depth = longest / std::f64::consts::TAU;
        let top = water.height(&(pose * mesh.centroid())) + mesh.bounding_radius();
        if top < -decay_depth && top.is_finite() {
            return Python::attach(|py| {
                warn_user(
                    py,
                    &format!(
                        "waves: the body lies deeper under the still level than its waves' \
                         longest wavelength over 2π ({} m): the default hydrostatic pressure \
                         carries the surface's ρg(η − z) to any depth, where the sea's decays as \
                         e^(kz); for a submerged body use Waves(..., pressure=\"froude_krylov\")",
                        crate::format::g(decay_depth)
                    ),
                )
            })
            .map_err(Failure::Raised);
        }
        Ok(())
    }

    /// Warns (a `UserWarning`, once per place in the caller's code) when the mesh's edges are
    /// longer than half the shortest wavelength: the surface is evaluated at the vertices, and a
    /// wave that short is not seen between them.
    fn check_sampling(&self, mesh: &Mesh<f64>) -> Result<(), Failure> {
        let shortest = self
            .linear_components()
            .and_then(|c| c.iter().map(|c| c.wavelength).reduce(f64::min));
        match shortest {
            Some(wavelength) if 2.0 * mesh.longest_edge() > wavelength => Python::attach(|py| {
                warn_user(
                    py,
                    &format!(
                        "waves: the mesh's longest edge, {} m, is more than half the shortest \
                         wavelength, {} m: the surface is sampled at the vertices, and a wave that \
                         short is not seen between them; use a finer mesh (or drop the short waves)",
                        crate::format::g(mesh.longest_edge()),
                        crate::format::g(wavelength)
                    ),
                )
            })
            .map_err(Failure::Raised),
            _ => Ok(()),
        }
    }

    /// The elevations at the still-plane `points` of `water` at `time` (s), m.
    pub fn elevations(
        &self,
        water: &Water<f64>,
        points: &[Point3<f64>],
        time: f64,
    ) -> Result<Vec<f64>, Failure> {
        let mut elevations = vec![0.0; points.len()];
        self.on_surface(water, |surface| {
            surface.elevations(water, points, time, &mut elevations)
        })?;
        Ok(elevations)
    }
}
