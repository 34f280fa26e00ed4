//! The angular damping of the whole body: [`angular_damping`].

use nalgebra::Vector3;

use super::DampingCoefficients;
#[cfg(doc)]
use crate::Mesh;
use crate::Real;

/// The angular damping of the model, `τ_ω = −f·ρ·V^{5/3}·(a₁ + a₂·|ω|)·ω` (N·m, world frame),
/// for angular velocity `ω` (rad/s), wetted fraction `f`, volume `V` (m³; negative counts as
/// zero) and water density `ρ` (kg/m³): what [`Mesh::damping`] adds for one mesh, and what a
/// body of several meshes adds once for all of them (`f` their total wetted area over their
/// total area, `V` their total volume).
pub fn angular_damping<T: Real>(
    omega: &Vector3<T>,
    wetted_fraction: T,
    volume: T,
    density: T,
    coefficients: &DampingCoefficients<T>,
) -> Vector3<T> {
    -omega
        * (angular_size(wetted_fraction, volume, density)
            * (coefficients.angular_drag_linear()
                + coefficients.angular_drag_quadratic() * omega.norm()))
}

/// `s = f·ρ·V^{5/3}` (kg·m², a negative `V` counting as zero): the scale of the angular damping
/// for wetted fraction `f`, volume `V` and water density `ρ`.
pub(crate) fn angular_size<T: Real>(wetted_fraction: T, volume: T, density: T) -> T {
    wetted_fraction * density * volume.max(T::zero()).powf(T::from_f64_lossy(5.0 / 3.0))
}
