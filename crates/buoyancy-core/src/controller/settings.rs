//! The water, method and damping of a controller, and one body's overrides of them.

use crate::{DampingCoefficients, Method, Water};

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
