//! The water, method and damping a body floats with: the world's, unless its
//! [`FloatOptions`] override them.

use buoyancy_core::{DampingCoefficients, Method, Water};

use crate::FloatOptions;

/// The water (level, normal, density, gravity), method and damping coefficients of a world or
/// of one body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Settings {
    pub water: Water<f64>,
    pub method: Method,
    pub damping: DampingCoefficients<f64>,
}

impl Settings {
    /// The settings of a body: these (the world's), each replaced by the body's override in
    /// `options` where it has one.
    pub fn resolve(&self, options: &FloatOptions) -> Settings {
        Settings {
            water: options.water.unwrap_or(self.water),
            method: options.method.unwrap_or(self.method),
            damping: options.damping.unwrap_or(self.damping),
        }
    }
}
