//! Units a hull's input is unlikely to be in: what a mesh in millimetres, a density in t/m³ or a
//! mass in tonnes look like to the solvers, which take metres, kg/m³ and kg. Found before a
//! solve ([`units_warnings`]): a millimetre hull floats at a draft of nanometres, where the
//! solver's tolerance cannot be met, and its error alone would not say why.

use alloc::vec::Vec;
use core::fmt;

use crate::{Mesh, Real, Water};

/// A body larger than this, m (the size of the ball about its centroid that holds it), is a mesh
/// in millimetres or another small unit rather than metres: the largest ships are 460 m long.
pub const LARGEST_PLAUSIBLE_SIZE: f64 = 2000.0;

/// A water lighter than this, kg/m³, is a density in t/m³ or g/cm³ (water is 1000–1030 kg/m³).
pub const LIGHTEST_PLAUSIBLE_DENSITY: f64 = 100.0;

/// A body whose mass is less than this share of the mass of water its whole volume displaces
/// floats with almost nothing under water: a mass in tonnes (or a mesh in too small a unit).
pub const SMALLEST_PLAUSIBLE_LOAD: f64 = 1e-4;

/// One input in an unlikely unit: see [`units_warnings`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum UnitsWarning {
    /// The body spans `size` m (twice its [`bounding_radius`](Mesh::bounding_radius)), more
    /// than [`LARGEST_PLAUSIBLE_SIZE`]: millimetres read as metres?
    LargeBody {
        /// Twice the bounding radius, m.
        size: f64,
        /// The mesh's volume, m³.
        volume: f64,
    },
    /// The water's density is under [`LIGHTEST_PLAUSIBLE_DENSITY`] kg/m³: t/m³ or g/cm³?
    LightWater {
        /// The density given, kg/m³.
        density: f64,
    },
    /// The mass is less than [`SMALLEST_PLAUSIBLE_LOAD`] of the water the whole body
    /// displaces: tonnes read as kilograms, or a mesh in too small a unit?
    LightLoad {
        /// The mass given, kg.
        mass: f64,
        /// `ρ·V`, kg.
        capacity: f64,
    },
}

impl fmt::Display for UnitsWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            UnitsWarning::LargeBody { size, volume } => write!(
                f,
                "the mesh spans {size:.4e} m and holds {volume:.4e} m³: its coordinates are \
                 read as metres; if they are millimetres, scale the mesh by 0.001"
            ),
            UnitsWarning::LightWater { density } => write!(
                f,
                "the water's density is {density} kg/m³: if it is in t/m³ or g/cm³, multiply \
                 it by 1000 (sea water is 1025 kg/m³)"
            ),
            UnitsWarning::LightLoad { mass, capacity } => write!(
                f,
                "the mass, {mass:.4e} kg, is {:.2e} of the {capacity:.4e} kg of water the whole \
                 body displaces, so it floats with almost nothing under water: if the mass is \
                 in tonnes, multiply it by 1000; if the mesh is in millimetres, scale it by 0.001",
                mass / capacity
            ),
        }
    }
}

/// The inputs of a hydrostatic computation on `mesh` in `water` (with `mass`, kg, when there is
/// one) that are unlikely to be in SI units, with what they would be in the unit a person
/// probably meant. Empty when all is plausible. The solvers do not call it: a body can be a
/// kilometre long; the Python bindings and the stability command line warn with it.
pub fn units_warnings<T: Real>(
    mesh: &Mesh<T>,
    water: &Water<T>,
    mass: Option<T>,
) -> Vec<UnitsWarning> {
    let mut found = Vec::new();
    let size = 2.0 * mesh.bounding_radius().to_f64();
    let volume = mesh.volume().to_f64();
    if size > LARGEST_PLAUSIBLE_SIZE {
        found.push(UnitsWarning::LargeBody { size, volume });
    }
    let density = water.density().to_f64();
    if density < LIGHTEST_PLAUSIBLE_DENSITY {
        found.push(UnitsWarning::LightWater { density });
    }
    if let Some(mass) = mass.map(T::to_f64) {
        let capacity = density * volume;
        if mass > 0.0 && mass < SMALLEST_PLAUSIBLE_LOAD * capacity {
            found.push(UnitsWarning::LightLoad { mass, capacity });
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;
    use alloc::string::ToString;
    use nalgebra::Vector3;

    fn block(scale: f64) -> Mesh<f64> {
        let (v, t) = primitives::cube(1).unwrap();
        Mesh::new(v, t)
            .unwrap()
            .scaled(&Vector3::new(4.0, 2.0, 1.0).scale(scale))
            .unwrap()
    }

    #[test]
    fn a_hull_in_millimetres_a_density_in_tonnes_and_a_mass_in_tonnes() {
        let water = Water::default();
        assert_eq!(units_warnings(&block(1.0), &water, Some(3000.0)), []);
        // The same hull in millimetres, its mass in kg: too large, and too light for it.
        let found = units_warnings(&block(1000.0), &water, Some(3000.0));
        assert!(matches!(
            found[..],
            [
                UnitsWarning::LargeBody { .. },
                UnitsWarning::LightLoad { .. }
            ]
        ));
        assert!(found[0].to_string().contains("scale the mesh by 0.001"));
        // The mass in tonnes.
        let found = units_warnings(&block(1.0), &water, Some(0.1));
        assert!(matches!(found[..], [UnitsWarning::LightLoad { .. }]));
        assert!(found[0].to_string().contains("multiply it by 1000"));
        let light = Water::new(1.025, 9.81, Vector3::y(), 0.0).unwrap();
        let found = units_warnings(&block(1.0), &light, None);
        assert!(matches!(
            found[..],
            [UnitsWarning::LightWater { density: 1.025 }]
        ));
    }
}
