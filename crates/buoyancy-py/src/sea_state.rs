//! Irregular seas from a spectrum (`Waves.jonswap`, `Waves.pierson_moskowitz`): the core's
//! `SeaState`, drawn into Airy components for the gravity and up normal of a water.

use buoyancy_core::nalgebra::Vector3;
use buoyancy_core::water::{AiryWaves, SeaState, Spectrum};
use buoyancy_core::{Error, Water};
use pyo3::prelude::*;
use pyo3::types::{PyTuple, PyType};

use crate::convert;
use crate::errors::{arg_error, to_py};
use crate::format::g;
use crate::water::PyWater;

/// The arguments of `Waves.jonswap` and `Waves.pierson_moskowitz`, as Python passes them.
pub struct SeaArguments<'a, 'py> {
    pub hs: &'a Bound<'py, PyAny>,
    pub tp: &'a Bound<'py, PyAny>,
    /// JONSWAP's `γ` (`None` when absent: 3.3), or `None` for Pierson–Moskowitz.
    pub gamma: Option<Option<&'a Bound<'py, PyAny>>>,
    pub direction: Option<&'a Bound<'py, PyAny>>,
    pub spreading: Option<&'a Bound<'py, PyAny>>,
    pub n: Option<&'a Bound<'py, PyAny>>,
    pub seed: Option<&'a Bound<'py, PyAny>>,
    pub depth: Option<&'a Bound<'py, PyAny>>,
    pub water: Option<&'a Bound<'py, PyAny>>,
}

/// Where a `Waves`' components were drawn from: the sea state, the depth, and the water whose
/// gravity (the wavelengths) and up normal (the spreading) they were drawn for.
#[derive(Clone, Copy)]
pub struct SeaOrigin {
    sea: SeaState<f64>,
    depth: Option<f64>,
    water: Water<f64>,
    /// Whether that water was given (`water=`); if not, the waves are drawn again for the
    /// water they are given to.
    water_given: bool,
}

/// JONSWAP's default peak enhancement, the North Sea mean.
const DEFAULT_GAMMA: f64 = 3.3;
/// The default number of components.
const DEFAULT_COMPONENTS: usize = 64;

impl SeaOrigin {
    /// The components of the sea state `args` describe, and where they come from. The core
    /// checks the arguments; its error names the one at fault.
    pub fn draw(py: Python<'_>, args: SeaArguments<'_, '_>) -> PyResult<(AiryWaves<f64>, Self)> {
        let spectrum = match args.gamma {
            None => Spectrum::PiersonMoskowitz,
            Some(gamma) => Spectrum::Jonswap {
                gamma: convert::real_or(gamma, "gamma", DEFAULT_GAMMA)?,
            },
        };
        let direction = match convert::given(args.direction) {
            Some(d) => convert::vector3(d, "direction")?,
            None => Vector3::x(),
        };
        let spreading = match convert::given(args.spreading) {
            Some(s) => Some(convert::real(s, "spreading")?),
            None => None,
        };
        let seed = match convert::given(args.seed) {
            Some(s) => convert::unsigned64(s, "seed")?,
            None => 0,
        };
        let depth = match convert::given(args.depth) {
            Some(d) => Some(convert::real(d, "depth")?),
            None => None,
        };
        let given_water = convert::instance::<PyWater>(args.water, "water")?;
        let water_given = given_water.is_some();
        let still = given_water.map_or_else(Water::default, |w| w.get().inner);
        let sea = SeaState {
            spectrum,
            significant_height: convert::real(args.hs, "hs")?,
            peak_period: convert::real(args.tp, "tp")?,
            direction,
            spreading,
            components: convert::count_or(args.n, "n", DEFAULT_COMPONENTS)?,
            seed,
        };
        let waves = py
            .detach(|| AiryWaves::from_sea_state(&sea, &still, depth))
            .map_err(|e| {
                // The core names its parameter; the error names the argument it came from.
                let argument = match e {
                    Error::InvalidSurface { parameter, .. }
                    | Error::OutOfMemory { parameter, .. } => Some(match parameter {
                        "significant_height" => "hs",
                        "peak_period" => "tp",
                        "components" => "n",
                        other => other,
                    }),
                    _ => None,
                };
                to_py(e, argument)
            })?;
        Ok((
            waves,
            SeaOrigin {
                sea,
                depth,
                water: still,
                water_given,
            },
        ))
    }

    /// The components for `water`: `None` when they were drawn for its gravity and up normal,
    /// else, for waves drawn without `water=`, the same sea state drawn again for it (the draw
    /// is deterministic for a seed: the frequencies, amplitudes and phases are the same, the
    /// wavelengths follow `water`'s gravity, the spreading turns about its normal).
    ///
    /// # Errors
    /// A `ValueError` naming `waves` for waves drawn with `water=` another water, or a sea
    /// state that cannot be drawn for this one (its direction along the normal).
    pub fn for_water(
        &self,
        py: Python<'_>,
        water: &Water<f64>,
    ) -> PyResult<Option<(AiryWaves<f64>, Self)>> {
        if self.drawn_for(water) {
            return Ok(None);
        }
        if self.water_given {
            return Err(self.mismatch(water));
        }
        let (sea, depth) = (self.sea, self.depth);
        let waves = py
            .detach(|| AiryWaves::from_sea_state(&sea, water, depth))
            .map_err(|e| to_py(e, Some("waves")))?;
        Ok(Some((
            waves,
            // Drawn for `water` now, as if it had been given: they pickle with it.
            SeaOrigin {
                water: *water,
                water_given: true,
                ..*self
            },
        )))
    }

    /// Whether the components were drawn for `water`'s gravity and up normal.
    fn drawn_for(&self, water: &Water<f64>) -> bool {
        self.water.gravity() == water.gravity() && self.water.normal() == water.normal()
    }

    /// The error for `water`, whose gravity or up normal is not the one of the water the
    /// components were drawn for, given as `water=`.
    fn mismatch(&self, water: &Water<f64>) -> PyErr {
        let drawn_for = self.water;
        let (n, m) = (drawn_for.normal(), water.normal());
        arg_error(
            "waves",
            format!(
                "the sea state's components were drawn for the water given as water=, of gravity {} m/s² and up normal ({}, {}, {}), and this water has gravity {} and normal ({}, {}, {}): pass this water as water= to Waves.{}, or no water (the waves are then drawn for the water they are given to)",
                g(drawn_for.gravity()),
                g(n.x),
                g(n.y),
                g(n.z),
                g(water.gravity()),
                g(m.x),
                g(m.y),
                g(m.z),
                self.constructor()
            ),
        )
    }

    /// The name of the classmethod that draws this sea state.
    fn constructor(&self) -> &'static str {
        match self.sea.spectrum {
            Spectrum::PiersonMoskowitz => "pierson_moskowitz",
            Spectrum::Jonswap { .. } => "jonswap",
        }
    }

    /// `Waves.jonswap(…)` or `Waves.pierson_moskowitz(…)`, with every argument but the water,
    /// and `more` (the arguments that follow, each after `", "`) before the closing parenthesis.
    pub fn repr(&self, more: &str) -> String {
        let s = &self.sea;
        let gamma = match s.spectrum {
            Spectrum::Jonswap { gamma } => format!(", gamma={}", g(gamma)),
            Spectrum::PiersonMoskowitz => String::new(),
        };
        let optional = |x: Option<f64>| x.map_or_else(|| "None".into(), g);
        format!(
            "Waves.{}(hs={}, tp={}{gamma}, direction=({}, {}, {}), spreading={}, n={}, seed={}, depth={}{more})",
            self.constructor(),
            g(s.significant_height),
            g(s.peak_period),
            g(s.direction.x),
            g(s.direction.y),
            g(s.direction.z),
            optional(s.spreading),
            s.components,
            s.seed,
            optional(self.depth)
        )
    }

    /// What `__reduce__` returns: the classmethod and its arguments, the `pressure` last, which
    /// draw the same components again (the draw is deterministic for a seed).
    pub fn reduce<'py>(
        &self,
        cls: &Bound<'py, PyType>,
        pressure: &str,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = cls.py();
        let s = &self.sea;
        let direction = (s.direction.x, s.direction.y, s.direction.z);
        // Waves drawn without a water pickle without one, to be drawn again for the water they
        // are given to.
        let water = match self.water_given {
            true => Some(Py::new(py, PyWater::still(self.water))?),
            false => None,
        };
        let args = match s.spectrum {
            Spectrum::Jonswap { gamma } => (
                s.significant_height,
                s.peak_period,
                gamma,
                direction,
                s.spreading,
                s.components,
                s.seed,
                self.depth,
                water,
                pressure,
            )
                .into_pyobject(py)?,
            Spectrum::PiersonMoskowitz => (
                s.significant_height,
                s.peak_period,
                direction,
                s.spreading,
                s.components,
                s.seed,
                self.depth,
                water,
                pressure,
            )
                .into_pyobject(py)?,
        };
        Ok((cls.getattr(self.constructor())?, args))
    }
}
