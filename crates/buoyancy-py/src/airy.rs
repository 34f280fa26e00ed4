//! Linear (Airy) waves: `AiryWave` (one component) and `Waves` (a sum of them over water of a
//! finite or infinite depth), the core's `AiryComponent` and `AiryWaves`.

use buoyancy_core::Error;
use buoyancy_core::nalgebra::Vector3;
use buoyancy_core::water::{AiryComponent, AiryWaves};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyTuple, PyType};

use crate::arrays;
use crate::convert;
use crate::errors::{arg_error, to_py, type_error};
use crate::format::g;
use crate::pressure;
use crate::sea_state::{SeaArguments, SeaOrigin};
use buoyancy_core::query::Pressure;

type V3 = (f64, f64, f64);

/// `AiryWave(amplitude, wavelength, direction, phase)`'s arguments.
type AiryWaveArgs = (f64, f64, V3, f64);

/// What `Waves.__reduce__` returns: a callable and its arguments.
type WavesReduce<'py> = (Bound<'py, PyAny>, Bound<'py, PyTuple>);

/// More components than this are summarised in `Waves`' repr.
const REPR_COMPONENTS: usize = 4;

/// One linear (Airy) wave component, world frame, SI units:
/// ``η(q, t) = amplitude * cos(k·q − ω t + phase)``, with ``k`` of length
/// ``2π / wavelength`` along ``direction`` and ``ω`` from the dispersion relation
/// ``ω² = g k tanh(k h)`` (``g k`` in deep water) of the :class:`Waves` it belongs to.
///
/// Parameters
/// ----------
/// amplitude : float
///     ``a``, half the height from trough to crest, m; finite and non-negative.
/// wavelength : float
///     ``λ``, m; finite and positive.
/// direction : array_like, shape (3,)
///     The direction the wave travels in, world frame (default ``(1, 0, 0)``); finite and
///     non-zero. Its component along the water's up normal is dropped, so it must not be along
///     that normal (checked when the wave is given to a :class:`Water`).
/// phase : float
///     The phase at the world origin at ``t = 0``, rad (default 0: a crest there).
///
/// Raises ``ValueError`` naming the parameter that is out of range, ``TypeError`` naming the
/// one that is not a number.
///
/// Examples
/// --------
/// >>> swell = buoyancy.AiryWave(amplitude=0.5, wavelength=20.0)
/// >>> swell
/// AiryWave(amplitude=0.5, wavelength=20, direction=(1, 0, 0), phase=0)
/// >>> sea = buoyancy.Water(waves=swell)              # y up: the wave runs along x
/// >>> sea.elevation([(0, 0, 0), (5, 0, 0), (10, 0, 0)]).round(12).tolist()
/// [0.5, 0.0, -0.5]
/// >>> buoyancy.AiryWave(amplitude=-1.0, wavelength=20.0)
/// Traceback (most recent call last):
/// ...
/// ValueError: amplitude: invalid water surface: a wave amplitude must be finite and non-negative (m)
///
/// ``AiryWave`` is immutable, compares by value and pickles.
#[pyclass(frozen, eq, module = "buoyancy", name = "AiryWave")]
#[derive(Clone, Copy, PartialEq)]
pub struct PyAiryWave {
    pub inner: AiryComponent<f64>,
}

/// The core's components of an iterable of `AiryWave`, each error naming `components[i]`.
pub fn airy_components(components: &Bound<'_, PyAny>) -> PyResult<Vec<AiryComponent<f64>>> {
    let items = components
        .try_iter()
        .map_err(|_| type_error("components", "an iterable of buoyancy.AiryWave", components))?;
    let mut parsed = Vec::new();
    for (i, item) in items.enumerate() {
        let item = item?;
        let wave = item
            .cast::<PyAiryWave>()
            .map_err(|_| type_error(&format!("components[{i}]"), "a buoyancy.AiryWave", &item))?;
        parsed.push(wave.get().inner);
    }
    Ok(parsed)
}

impl PyAiryWave {
    /// A component whose every field has been checked, each error naming its parameter.
    fn checked(
        amplitude: f64,
        wavelength: f64,
        direction: Vector3<f64>,
        phase: f64,
    ) -> PyResult<Self> {
        // The core checks the amplitude, then the wavelength, and names the one at fault; the
        // direction and the phase are checked below, with messages of their own.
        let numbers = AiryComponent {
            amplitude,
            wavelength,
            direction: Vector3::x(),
            phase: 0.0,
        };
        AiryWaves::new(vec![numbers], None).map_err(|e| {
            let argument = match e {
                Error::InvalidSurface { parameter, .. } => Some(parameter),
                _ => None,
            };
            to_py(e, argument)
        })?;
        if direction == Vector3::zeros() {
            return Err(arg_error(
                "direction",
                "is the zero vector; give the direction the wave travels in, e.g. (1, 0, 0)",
            ));
        }
        if !phase.is_finite() {
            return Err(arg_error("phase", "must be finite (rad)"));
        }
        Ok(PyAiryWave {
            inner: AiryComponent {
                amplitude,
                wavelength,
                direction,
                phase,
            },
        })
    }
}

#[pymethods]
impl PyAiryWave {
    #[new]
    #[pyo3(
        signature = (amplitude, wavelength, direction=None, phase=None),
        text_signature = "(amplitude, wavelength, direction=(1.0, 0.0, 0.0), phase=0.0)"
    )]
    fn new(
        amplitude: &Bound<'_, PyAny>,
        wavelength: &Bound<'_, PyAny>,
        direction: Option<&Bound<'_, PyAny>>,
        phase: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let amplitude = convert::real(amplitude, "amplitude")?;
        let wavelength = convert::real(wavelength, "wavelength")?;
        let direction = match convert::given(direction) {
            Some(d) => convert::vector3(d, "direction")?,
            None => Vector3::x(),
        };
        let phase = convert::real_or(phase, "phase", 0.0)?;
        PyAiryWave::checked(amplitude, wavelength, direction, phase)
    }

    /// Amplitude ``a``, m.
    #[getter]
    fn amplitude(&self) -> f64 {
        self.inner.amplitude
    }
    /// Wavelength ``λ``, m.
    #[getter]
    fn wavelength(&self) -> f64 {
        self.inner.wavelength
    }
    /// The direction of travel as given, world frame, shape (3,) (a new, read-only array).
    #[getter]
    fn direction<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.direction.as_slice())
    }
    /// Phase at the world origin at ``t = 0``, rad.
    #[getter]
    fn phase(&self) -> f64 {
        self.inner.phase
    }
    /// Wave number ``k = 2π / wavelength``, rad/m.
    #[getter]
    fn wavenumber(&self) -> f64 {
        self.inner.wavenumber()
    }

    pub fn __repr__(&self) -> String {
        let c = &self.inner;
        format!(
            "AiryWave(amplitude={}, wavelength={}, direction=({}, {}, {}), phase={})",
            g(c.amplitude),
            g(c.wavelength),
            g(c.direction.x),
            g(c.direction.y),
            g(c.direction.z),
            g(c.phase)
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> (Bound<'py, PyType>, AiryWaveArgs) {
        let c = slf.get().inner;
        (
            slf.get_type(),
            (
                c.amplitude,
                c.wavelength,
                (c.direction.x, c.direction.y, c.direction.z),
                c.phase,
            ),
        )
    }
}

/// Linear (Airy) waves: the sum of :class:`AiryWave` components over water of a finite depth or
/// infinitely deep, ``η(q, t) = Σ aᵢ cos(kᵢ·q − ωᵢ t + φᵢ)``, each ``ωᵢ`` from the dispersion
/// relation ``ω² = g k tanh(k h)`` (``ω² = g k`` in deep water), ``g`` the gravity of the
/// :class:`Water` the waves are given to. Horizontal positions ``q`` are world points projected
/// onto the water's still plane; ``η`` is along its up normal; m, s.
///
/// Parameters
/// ----------
/// components : iterable of AiryWave
///     The components (none: calm water).
/// depth : float, optional
///     Depth of the water from the still level to the bottom, m, finite and positive; ``None``
///     (default) for deep water.
/// pressure : str
///     The pressure :meth:`Mesh.buoyancy` integrates over the wetted surface under these waves:
///     ``"hydrostatic"`` (default), ``p = ρ g (η − z)`` with ``z`` the height above the still
///     plane, what games use; or ``"froude_krylov"``, the linear Froude–Krylov pressure of the
///     undisturbed wave, ``p = ρ g (Σ aᵢ P(kᵢ, z) cos θᵢ − z)``, whose wave part decays with depth
///     as ``P = cosh k(z + h) / cosh k h`` (``e^{k z}`` in deep water) and is not stretched above
///     the still plane (``P = 1`` there); integrated by a degree-5 quadrature on each wetted
///     piece, its error falling as ``(k L)⁶`` for pieces of size ``L``. Either pressure is
///     clipped at zero, and the wetted surface is cut where ``η − z``, interpolated linearly
///     between the vertices, is zero.
///
/// Examples
/// --------
/// >>> sea = buoyancy.Waves(
/// ...     [buoyancy.AiryWave(0.5, 20.0), buoyancy.AiryWave(0.2, 7.0, direction=(0, 0, 1), phase=1.0)],
/// ...     depth=30.0,
/// ... )
/// >>> sea
/// Waves([AiryWave(amplitude=0.5, wavelength=20, direction=(1, 0, 0), phase=0), AiryWave(amplitude=0.2, wavelength=7, direction=(0, 0, 1), phase=1)], depth=30)
/// >>> (2 * np.pi / sea.angular_frequencies(gravity=9.81)).round(3).tolist()  # periods, s
/// [3.579, 2.117]
/// >>> hull = buoyancy.shapes.cube().scaled((4, 1, 1))
/// >>> b = hull.buoyancy(position=(0, -0.2, 0), water=buoyancy.Water(waves=sea), time=1.5)
/// >>> b.method
/// 'exact'
///
/// Under the Froude–Krylov pressure a ball of 0.5 m radius 3 m under a 10 m swell feels, besides
/// ``ρ g V`` up, ``ρ V`` times the water's acceleration at its center, whose component along x
/// is ``A ω² e^{k z} sin θ`` (a quarter period after a crest passed: ``θ = −π/2``):
///
/// >>> fk = buoyancy.Waves([buoyancy.AiryWave(0.5, 10.0)], pressure="froude_krylov")
/// >>> fk
/// Waves([AiryWave(amplitude=0.5, wavelength=10, direction=(1, 0, 0), phase=0)], depth=None, pressure='froude_krylov')
/// >>> ball = buoyancy.shapes.uv_sphere(0.5, 96, 48)
/// >>> k = 2 * np.pi / 10.0
/// >>> omega = np.sqrt(9.81 * k)
/// >>> quarter = np.pi / 2 / omega                      # s; θ = −π/2 at the center
/// >>> b = ball.buoyancy(position=(0, -3, 0), water=buoyancy.Water(waves=fk), time=quarter)
/// >>> a_x = 0.5 * omega**2 * np.exp(-3 * k) * np.sin(-np.pi / 2)   # m/s²
/// >>> round(float(b.force[0] / (1000 * ball.volume * a_x)), 3)
/// 1.0
/// >>> buoyancy.Waves([buoyancy.AiryWave(0.5, 20.0)], depth=0.0)
/// Traceback (most recent call last):
/// ...
/// ValueError: depth: invalid water surface: the depth must be finite and positive (m), or None for deep water
///
/// Irregular seas come from a spectrum: :meth:`jonswap` and :meth:`pierson_moskowitz`.
///
/// ``Waves`` is immutable, compares by value (its components, depth and pressure) and pickles;
/// its repr names the pressure when it is ``"froude_krylov"``.
#[pyclass(frozen, eq, module = "buoyancy", name = "Waves")]
#[derive(Clone)]
pub struct PyWaves {
    pub inner: AiryWaves<f64>,
    /// The sea state the components were drawn from, if they were.
    pub origin: Option<SeaOrigin>,
    /// The pressure `Mesh.buoyancy` integrates under these waves.
    pub pressure: Pressure,
}

/// Two waves are equal when their components, depth and pressure are.
impl PartialEq for PyWaves {
    fn eq(&self, other: &Self) -> bool {
        self.inner == other.inner && self.pressure == other.pressure
    }
}

impl PyWaves {
    /// Waves of one component over deep water.
    pub fn single(wave: &PyAiryWave) -> PyResult<Self> {
        AiryWaves::new(vec![wave.inner], None)
            .map(|inner| PyWaves {
                inner,
                origin: None,
                pressure: Pressure::Hydrostatic,
            })
            .map_err(|e| to_py(e, Some("waves")))
    }

    /// The waves of a sea state, under the `pressure` argument.
    fn drawn(
        py: Python<'_>,
        args: SeaArguments<'_, '_>,
        pressure: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let pressure = pressure::parse(pressure)?;
        let (inner, origin) = SeaOrigin::draw(py, args)?;
        Ok(PyWaves {
            inner,
            origin: Some(origin),
            pressure,
        })
    }
}

#[pymethods]
impl PyWaves {
    #[new]
    #[pyo3(
        signature = (components, depth=None, pressure=None),
        text_signature = "(components, depth=None, pressure='hydrostatic')"
    )]
    fn new(
        components: &Bound<'_, PyAny>,
        depth: Option<&Bound<'_, PyAny>>,
        pressure: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let parsed = airy_components(components)?;
        let depth = match convert::given(depth) {
            Some(d) => Some(convert::real(d, "depth")?),
            None => None,
        };
        let pressure = pressure::parse(pressure)?;
        AiryWaves::new(parsed, depth)
            .map(|inner| PyWaves {
                inner,
                origin: None,
                pressure,
            })
            .map_err(|e| to_py(e, Some("depth")))
    }

    /// Irregular waves from a JONSWAP spectrum (a fetch-limited wind sea): Pierson–Moskowitz
    /// times the peak enhancement ``gamma ** exp(−(ω − ω_p)² / (2 σ² ω_p²))``, ``σ = 0.07`` below
    /// the peak and 0.09 above, ``ω_p = 2π / tp``.
    ///
    /// The frequencies from ``ω_p / 2`` to ``4 ω_p`` are cut into ``n`` equal bins; each component
    /// takes a frequency drawn within its bin, the amplitude ``sqrt(2 S(ω) Δω)``, a random phase,
    /// the wavelength of its frequency by the dispersion relation, and, with ``spreading``, a
    /// direction drawn from ``cos^(2s)((θ − θ₀) / 2)`` about the water's up normal. The
    /// amplitudes are then scaled so that ``4 * sqrt(Σ aᵢ² / 2)`` is ``hs`` exactly. The same
    /// seed gives the same sea.
    ///
    /// Parameters
    /// ----------
    /// hs : float
    ///     Significant wave height, m (four standard deviations of ``η``); finite, non-negative.
    /// tp : float
    ///     Peak period, s; finite, positive.
    /// gamma : float
    ///     Peak enhancement factor, at least 1 (default 3.3, the North Sea mean; 1 is
    ///     Pierson–Moskowitz).
    /// direction : array_like, shape (3,)
    ///     Mean direction of travel, world frame (default ``(1, 0, 0)``); not along the normal.
    /// spreading : float, optional
    ///     The exponent ``s`` of the directional spreading, positive (larger is narrower: swell
    ///     about 25, wind sea 2 to 10); ``None`` (default) for long-crested waves.
    /// n : int
    ///     Number of components, at least 1 (default 64).
    /// seed : int
    ///     Seed of the random frequencies, phases and directions (default 0).
    /// depth : float, optional
    ///     Water depth, m; ``None`` (default) for deep water.
    /// water : Water, optional
    ///     The water the waves are for: the wavelengths follow from its gravity, the spreading
    ///     turns about its up normal. By default (``None``) the waves are drawn for the water
    ///     they are given to: ``Water(normal=(0, 0, 1), waves=Waves.jonswap(2.0, 8.0))`` is a
    ///     z-up sea, the same seed giving the same frequencies, amplitudes and phases (until
    ///     then, and for :attr:`components` read here, ``Water()``: 9.81 m/s², y up, so that a
    ///     ``direction`` along y needs ``water=``). With a water given, giving the waves to a
    ///     :class:`Water` of another gravity or normal is a ``ValueError``.
    /// pressure : str
    ///     ``"hydrostatic"`` (default) or ``"froude_krylov"``: the pressure
    ///     :meth:`Mesh.buoyancy` integrates under the waves (see :class:`Waves`).
    ///
    /// Examples
    /// --------
    /// >>> sea = buoyancy.Waves.jonswap(hs=2.0, tp=8.0, spreading=10.0, seed=7)
    /// >>> sea
    /// Waves.jonswap(hs=2, tp=8, gamma=3.3, direction=(1, 0, 0), spreading=10, n=64, seed=7, depth=None)
    /// >>> a = np.array([c.amplitude for c in sea.components])
    /// >>> round(float(4 * np.sqrt(np.sum(a**2) / 2)), 12)    # the significant height, m
    /// 2.0
    /// >>> ocean = buoyancy.Water(normal=(0, 0, 1), waves=buoyancy.Waves.jonswap(2.0, 8.0, spreading=10.0))
    /// >>> d = np.array([c.direction for c in ocean.waves.components])
    /// >>> bool(np.all(d[:, 2] == 0.0))    # drawn about the water's up normal, z
    /// True
    /// >>> buoyancy.Waves.jonswap(2.0, 8.0, n=16, pressure="froude_krylov").pressure
    /// 'froude_krylov'
    #[classmethod]
    #[pyo3(
        signature = (hs, tp, gamma=None, direction=None, spreading=None, n=None, seed=None, depth=None, water=None, pressure=None),
        text_signature = "(hs, tp, gamma=3.3, direction=(1.0, 0.0, 0.0), spreading=None, n=64, seed=0, depth=None, water=None, pressure='hydrostatic')"
    )]
    #[allow(clippy::too_many_arguments)]
    fn jonswap(
        cls: &Bound<'_, PyType>,
        hs: &Bound<'_, PyAny>,
        tp: &Bound<'_, PyAny>,
        gamma: Option<&Bound<'_, PyAny>>,
        direction: Option<&Bound<'_, PyAny>>,
        spreading: Option<&Bound<'_, PyAny>>,
        n: Option<&Bound<'_, PyAny>>,
        seed: Option<&Bound<'_, PyAny>>,
        depth: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyAny>>,
        pressure: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let args = SeaArguments {
            hs,
            tp,
            gamma: Some(gamma),
            direction,
            spreading,
            n,
            seed,
            depth,
            water,
        };
        PyWaves::drawn(cls.py(), args, pressure)
    }

    /// Irregular waves from a Pierson–Moskowitz spectrum (a fully developed sea),
    /// ``S(ω) = (5/16) hs² ω_p⁴ ω⁻⁵ exp(−(5/4) (ω_p / ω)⁴)``, ``ω_p = 2π / tp``, drawn into ``n``
    /// components as :meth:`jonswap` does (whose parameters these are, without ``gamma``).
    ///
    /// >>> sea = buoyancy.Waves.pierson_moskowitz(hs=1.0, tp=6.0, n=32)
    /// >>> len(sea), sea.depth
    /// (32, None)
    #[classmethod]
    #[pyo3(
        signature = (hs, tp, direction=None, spreading=None, n=None, seed=None, depth=None, water=None, pressure=None),
        text_signature = "(hs, tp, direction=(1.0, 0.0, 0.0), spreading=None, n=64, seed=0, depth=None, water=None, pressure='hydrostatic')"
    )]
    #[allow(clippy::too_many_arguments)]
    fn pierson_moskowitz(
        cls: &Bound<'_, PyType>,
        hs: &Bound<'_, PyAny>,
        tp: &Bound<'_, PyAny>,
        direction: Option<&Bound<'_, PyAny>>,
        spreading: Option<&Bound<'_, PyAny>>,
        n: Option<&Bound<'_, PyAny>>,
        seed: Option<&Bound<'_, PyAny>>,
        depth: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyAny>>,
        pressure: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let args = SeaArguments {
            hs,
            tp,
            gamma: None,
            direction,
            spreading,
            n,
            seed,
            depth,
            water,
        };
        PyWaves::drawn(cls.py(), args, pressure)
    }

    /// The components, a tuple of :class:`AiryWave`.
    #[getter]
    fn components<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(
            py,
            self.inner
                .components()
                .iter()
                .map(|&inner| PyAiryWave { inner }),
        )
    }

    /// Depth of the water, m; ``None`` for deep water.
    #[getter]
    fn depth(&self) -> Option<f64> {
        self.inner.depth()
    }

    /// The pressure :meth:`Mesh.buoyancy` integrates under these waves: ``"hydrostatic"`` or
    /// ``"froude_krylov"``.
    #[getter]
    fn pressure(&self) -> &'static str {
        self.pressure.name()
    }

    /// The angular frequency ``ω`` of each component under gravity ``gravity`` (m/s²), rad/s,
    /// shape (n,): ``ω² = g k tanh(k h)`` (``g k`` in deep water). ``2π / ω`` is the period, s.
    ///
    /// >>> buoyancy.Waves([buoyancy.AiryWave(1.0, 2 * np.pi)]).angular_frequencies(gravity=4.0).tolist()
    /// [2.0]
    #[pyo3(signature = (gravity=None), text_signature = "(self, gravity=9.81)")]
    fn angular_frequencies<'py>(
        &self,
        py: Python<'py>,
        gravity: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let gravity = convert::real_or(gravity, "gravity", 9.81)?;
        if !(gravity.is_finite() && gravity >= 0.0) {
            return Err(arg_error(
                "gravity",
                "must be finite and non-negative (m/s², a magnitude)",
            ));
        }
        let n = self.inner.components().len();
        Ok(PyArray1::from_iter(
            py,
            (0..n).map(|i| self.inner.angular_frequency(i, gravity)),
        ))
    }

    fn __len__(&self) -> usize {
        self.inner.components().len()
    }

    fn __repr__(&self) -> String {
        let pressure = pressure::repr_argument(self.pressure);
        if let Some(origin) = &self.origin {
            return origin.repr(&pressure);
        }
        let components = self.inner.components();
        let depth = self.inner.depth().map_or_else(|| "None".into(), g);
        if components.len() > REPR_COMPONENTS {
            return format!(
                "Waves({} components, depth={depth}{pressure})",
                components.len()
            );
        }
        let listed: Vec<String> = components
            .iter()
            .map(|&inner| PyAiryWave { inner }.__repr__())
            .collect();
        format!("Waves([{}], depth={depth}{pressure})", listed.join(", "))
    }

    /// Pickles as its components, depth and pressure, or as the sea state they were drawn from
    /// and the pressure.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<WavesReduce<'py>> {
        let this = slf.get();
        let cls = slf.get_type();
        let pressure = this.pressure.name();
        if let Some(origin) = &this.origin {
            return origin.reduce(&cls, pressure);
        }
        let args =
            (this.components(slf.py())?, this.inner.depth(), pressure).into_pyobject(slf.py())?;
        Ok((cls.into_any(), args))
    }
}
