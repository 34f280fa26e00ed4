//! `GerstnerWaves`: trochoidal waves in deep water, the core's `GerstnerWaves`.

use buoyancy_core::water::GerstnerWaves;
use pyo3::prelude::*;
use pyo3::types::{PyTuple, PyType};

use crate::airy::{PyAiryWave, airy_components};
use crate::errors::to_py;

/// `GerstnerWaves(components)`'s arguments.
type GerstnerArgs<'py> = (Bound<'py, PyTuple>,);

/// Trochoidal (Gerstner) waves in deep water, world frame, SI units: the water particle at rest
/// at horizontal position ``p`` moves to ``p − Σ dᵢ aᵢ sin θᵢ`` and rises by ``Σ aᵢ cos θᵢ``,
/// ``θᵢ = kᵢ·p − ωᵢ t + φᵢ``, ``ωᵢ² = g kᵢ``: crests sharper than troughs. The elevation at a
/// fixed point is that of the particle which is there, found by Newton's method to
/// ``1e-12 * Σ aᵢ`` (m).
///
/// Parameters
/// ----------
/// components : iterable of AiryWave
///     Amplitude, wavelength, direction and phase of each component (as for :class:`Waves`).
///     Their steepness ``Σ kᵢ aᵢ`` (``kᵢ = 2π / wavelengthᵢ``) must be below 1: at 1 the crests
///     become cusps, beyond they fold over (a ``ValueError``).
///
/// Examples
/// --------
/// >>> trochoid = buoyancy.GerstnerWaves([buoyancy.AiryWave(amplitude=1.0, wavelength=30.0)])
/// >>> sea = buoyancy.Water(waves=trochoid)
/// >>> sea.elevation([(0, 0, 0), (15, 0, 0)]).round(9).tolist()   # crest, trough
/// [1.0, -1.0]
/// >>> buoyancy.GerstnerWaves([buoyancy.AiryWave(amplitude=2.0, wavelength=12.0)])
/// Traceback (most recent call last):
/// ...
/// ValueError: components: invalid water surface: a Gerstner sea with steepness Σ k·a of 1 or more folds over: lower the amplitudes
///
/// ``GerstnerWaves`` is immutable, compares by value and pickles.
#[pyclass(frozen, eq, module = "buoyancy", name = "GerstnerWaves")]
#[derive(Clone, PartialEq)]
pub struct PyGerstnerWaves {
    pub inner: GerstnerWaves<f64>,
}

#[pymethods]
impl PyGerstnerWaves {
    #[new]
    #[pyo3(text_signature = "(components)")]
    fn new(components: &Bound<'_, PyAny>) -> PyResult<Self> {
        GerstnerWaves::new(airy_components(components)?)
            .map(|inner| PyGerstnerWaves { inner })
            .map_err(|e| to_py(e, Some("components")))
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

    /// The steepness ``Σ kᵢ aᵢ``, below 1.
    #[getter]
    fn steepness(&self) -> f64 {
        self.inner
            .components()
            .iter()
            .map(|c| c.wavenumber() * c.amplitude)
            .sum()
    }

    fn __len__(&self) -> usize {
        self.inner.components().len()
    }

    fn __repr__(&self) -> String {
        let listed: Vec<String> = self
            .inner
            .components()
            .iter()
            .map(|&inner| PyAiryWave { inner }.__repr__())
            .collect();
        format!("GerstnerWaves([{}])", listed.join(", "))
    }

    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyType>, GerstnerArgs<'py>)> {
        Ok((slf.get_type(), (slf.get().components(slf.py())?,)))
    }
}
