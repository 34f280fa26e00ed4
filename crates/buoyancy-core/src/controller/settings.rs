//! The water, method, damping and damping resolution of a controller, and one body's
//! overrides of them.

use crate::{DampingCoefficients, Method, Water};

/// How finely the pressure drag of a body's meshes is integrated (the
/// [damping](crate::damping) model; the buoyancy always takes the full mesh).
///
/// The default, [`DampingResolution::DEFAULT`], integrates it over a coarse copy of each mesh
/// of more than 384 triangles ([`ReducedMesh`](crate::mesh::ReducedMesh), built once per
/// mesh when a body is added, shared by the bodies with the same mesh), and exactly over the
/// smaller ones (a box, a cylinder or cone of up to 96 segments are unchanged). The bunny of
/// 5,002 triangles becomes 362: half under water and moving, its pressure drag costs about a
/// tenth, its force within 5 % and its torque within 2 % of `|F|` times its radius (at the
/// step benchmark's 100 poses).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DampingResolution {
    /// Over every triangle of every mesh ([`Mesh::damping`](crate::Mesh::damping)): the
    /// model exactly.
    Full,
    /// Over a copy of at most `max_triangles` triangles (at least
    /// [`MIN_REDUCED_TRIANGLES`](crate::mesh::MIN_REDUCED_TRIANGLES)) of each mesh of
    /// more ([`Mesh::reduced_damping`](crate::Mesh::reduced_damping)); a mesh that has no
    /// more, or that no reduction keeps within 10 % of its area and volume, is taken whole.
    Reduced {
        /// Most triangles of a reduced copy.
        max_triangles: usize,
    },
}

impl DampingResolution {
    /// `Reduced { max_triangles: 384 }`.
    pub const DEFAULT: DampingResolution = DampingResolution::Reduced { max_triangles: 384 };
}

impl Default for DampingResolution {
    /// [`DampingResolution::DEFAULT`].
    fn default() -> Self {
        DampingResolution::DEFAULT
    }
}

/// The water (level, normal, density, gravity), method and damping coefficients of a
/// controller, or of one body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// The water.
    pub water: Water<f64>,
    /// The method of the buoyancy under still water.
    pub method: Method,
    /// The damping coefficients ([`DampingCoefficients::off`] for none).
    pub damping: DampingCoefficients<f64>,
}

impl Default for Settings {
    /// Fresh water, y up, level 0, `g = 9.81`; [`Method::Exact`]; the default damping.
    fn default() -> Self {
        Settings {
            water: Water::default(),
            method: Method::Exact,
            damping: DampingCoefficients::default(),
        }
    }
}

/// One body's overrides of the controller's [`Settings`]: `None` takes the controller's.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BodyOptions {
    /// This body's method.
    pub method: Option<Method>,
    /// This body's water.
    pub water: Option<Water<f64>>,
    /// This body's damping.
    pub damping: Option<DampingCoefficients<f64>>,
    /// How finely this body's pressure drag is integrated.
    pub damping_resolution: Option<DampingResolution>,
}

impl Settings {
    /// The settings of a body: these, each replaced by the body's override where it has one.
    pub fn resolve(&self, options: &BodyOptions) -> Settings {
        Settings {
            water: options.water.unwrap_or(self.water),
            method: options.method.unwrap_or(self.method),
            damping: options.damping.unwrap_or(self.damping),
        }
    }
}
