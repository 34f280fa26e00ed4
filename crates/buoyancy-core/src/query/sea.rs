//! The water of one query: [`Sea`] (the still water, its free surface at a time, the pressure)
//! and [`Pressure`].

use core::fmt;
use core::str::FromStr;

use crate::water::{AiryWaves, WaterSurface};
use crate::{Error, Real, Water};

/// The pressure of a moving sea on a body (see the [guide](crate::query)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Pressure {
    /// `p = ρ·g·(η − h)` below the free surface, `h` the height above the still plane and `η`
    /// the surface's elevation above the point: the hydrostatic pressure of the local water
    /// column, for any surface. Its wave part does not decay with depth.
    #[default]
    Hydrostatic,
    /// The linear Froude–Krylov pressure of the undisturbed wave, `p = ρ·g·(−h + Σ aᵢ·Kᵢ(h)·cos θᵢ)`,
    /// whose wave part decays as `Kᵢ = cosh kᵢ(h + d)/cosh kᵢd` (`e^{kᵢh}` in deep water): for
    /// [`AiryWaves`] (and spectral seas, which are Airy waves) only.
    FroudeKrylov,
}

impl Pressure {
    /// Both pressures.
    pub const ALL: [Pressure; 2] = [Pressure::Hydrostatic, Pressure::FroudeKrylov];

    /// The pressure's name: `hydrostatic` or `froude_krylov`.
    pub const fn name(self) -> &'static str {
        match self {
            Pressure::Hydrostatic => "hydrostatic",
            Pressure::FroudeKrylov => "froude_krylov",
        }
    }
}

impl fmt::Display for Pressure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Pressure {
    type Err = Error;

    /// Parses a name of [`Pressure::name`] (case-insensitive, `_` and `-` optional).
    fn from_str(s: &str) -> Result<Self, Error> {
        Pressure::ALL
            .into_iter()
            .find(|p| crate::query::method::names_match(p.name(), s))
            .ok_or(Error::Unsupported {
                parameter: "pressure",
                reason: "is not a pressure: give 'hydrostatic' or 'froude_krylov'",
            })
    }
}

/// The water a body is in at one instant: the still water (density, gravity, still plane), its
/// free surface at a time (calm by default) and the pressure that acts. What
/// [`Mesh::buoyancy`](crate::Mesh::buoyancy) takes.
///
/// A [`Water`] is a calm sea (`From<&Water>`), so still water needs no `Sea` at all:
///
/// ```
/// use buoyancy_core::query::{Pressure, Sea};
/// use buoyancy_core::water::{AiryComponent, AiryWaves};
/// use buoyancy_core::{mesh::primitives, Mesh, Method, Pose, Water};
/// use nalgebra::{Translation3, UnitQuaternion, Vector3};
///
/// let (v, t) = primitives::cube::<f64>(4)?;
/// let cube = Mesh::new(v, t)?;
/// let pose = Pose::from_parts(Translation3::new(0.0, -0.2, 0.0), UnitQuaternion::identity());
/// let water = Water::default();
/// let swell = AiryWaves::new(
///     vec![AiryComponent { amplitude: 0.1, wavelength: 50.0, direction: Vector3::x(), phase: 0.0 }],
///     None,
/// )?;
///
/// let still = cube.buoyancy(&pose, &water, Method::Exact)?;
/// let crest = cube.buoyancy(&pose, Sea::new(&water, &swell, 0.0), Method::Exact)?;
/// let decayed = Sea::new(&water, &swell, 0.0).with_pressure(Pressure::FroudeKrylov);
/// let froude_krylov = cube.buoyancy(&pose, decayed, Method::Exact)?;
/// assert!(crest.force.y > still.force.y && froude_krylov.force.y > still.force.y);
/// # Ok::<(), buoyancy_core::Error>(())
/// ```
#[derive(Clone, Copy)]
pub struct Sea<'a, T: Real> {
    water: Water<T>,
    surface: Option<&'a dyn WaterSurface<T>>,
    time: T,
    pressure: Pressure,
}

impl<T: Real> fmt::Debug for Sea<'_, T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Sea")
            .field("water", &self.water)
            .field("waves", &self.surface.is_some())
            .field("time", &self.time)
            .field("pressure", &self.pressure)
            .finish()
    }
}

impl<'a, T: Real> Sea<'a, T> {
    /// Still water: no waves, the hydrostatic pressure below the still plane of `water`.
    pub fn calm(water: &Water<T>) -> Self {
        Sea {
            water: *water,
            surface: None,
            time: T::zero(),
            pressure: Pressure::Hydrostatic,
        }
    }

    /// `water` under the free surface `surface` at `time` (s), with the
    /// [hydrostatic](Pressure::Hydrostatic) pressure of the waves.
    pub fn new(water: &Water<T>, surface: &'a dyn WaterSurface<T>, time: T) -> Self {
        Sea {
            water: *water,
            surface: Some(surface),
            time,
            pressure: Pressure::Hydrostatic,
        }
    }

    /// This sea with `pressure` (checked by the query: the Froude–Krylov pressure needs
    /// [`AiryWaves`]).
    pub fn with_pressure(mut self, pressure: Pressure) -> Self {
        self.pressure = pressure;
        self
    }

    /// The still water: density, gravity and the still plane.
    pub fn water(&self) -> &Water<T> {
        &self.water
    }

    /// The free surface; `None` for still water.
    pub fn surface(&self) -> Option<&'a dyn WaterSurface<T>> {
        self.surface
    }

    /// The time the surface is taken at (s).
    pub fn time(&self) -> T {
        self.time
    }

    /// The pressure that acts.
    pub fn pressure(&self) -> Pressure {
        self.pressure
    }

    /// Whether the free surface is the still plane: no surface, or one whose
    /// [`elevation_bound`](WaterSurface::elevation_bound) is zero. The Froude–Krylov pressure of
    /// a calm sea is the hydrostatic one.
    pub fn is_calm(&self) -> bool {
        self.surface
            .is_none_or(|s| s.elevation_bound() == Some(T::zero()))
    }

    /// The Airy waves the Froude–Krylov pressure takes its components from.
    ///
    /// # Errors
    /// [`Error::Unsupported`] (`pressure`) for a surface that is not [`AiryWaves`].
    pub(crate) fn airy_waves(&self) -> Result<&'a AiryWaves<T>, Error> {
        self.surface
            .and_then(|s| s.as_airy_waves())
            .ok_or(Error::Unsupported {
                parameter: "pressure",
                reason: "froude_krylov decays the wave part of each Airy component with depth, \
                         and this surface is not AiryWaves: give AiryWaves (or a sea state's) or \
                         the hydrostatic pressure",
            })
    }
}

impl<T: Real> From<&Water<T>> for Sea<'_, T> {
    /// Still water.
    fn from(water: &Water<T>) -> Self {
        Sea::calm(water)
    }
}
