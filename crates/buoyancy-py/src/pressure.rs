//! The pressure model of `Waves` (`pressure="hydrostatic" | "froude_krylov"`): which of the
//! core's integrations `Mesh.buoyancy` runs under them.

use pyo3::prelude::*;
use pyo3::types::PyString;

use crate::errors::{arg_error, type_error};

/// The pressure of Airy and spectral waves on a body.
#[derive(Clone, Copy, PartialEq, Eq, Default, Debug)]
pub enum Pressure {
    /// `p = ρ g (η − h)`, `h` the height above the still plane: the core's
    /// `Mesh::buoyancy_in_waves`.
    #[default]
    Hydrostatic,
    /// The linear Froude–Krylov pressure, whose wave part decays with depth as
    /// `cosh k(h + d) / cosh k d` (`e^{k h}` in deep water): the core's
    /// `Mesh::buoyancy_froude_krylov`.
    FroudeKrylov,
}

impl Pressure {
    /// The `pressure` argument: `"hydrostatic"` (also when absent or `None`) or
    /// `"froude_krylov"`; any other string is a `ValueError`, any other type a `TypeError`, each
    /// naming `pressure`.
    pub fn parse(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let Some(obj) = obj.filter(|o| !o.is_none()) else {
            return Ok(Pressure::Hydrostatic);
        };
        let expected = "'hydrostatic' or 'froude_krylov'";
        let text = obj
            .cast::<PyString>()
            .map_err(|_| type_error("pressure", expected, obj))?;
        match text.to_str()? {
            "hydrostatic" => Ok(Pressure::Hydrostatic),
            "froude_krylov" => Ok(Pressure::FroudeKrylov),
            other => Err(arg_error(
                "pressure",
                format!("unknown pressure model '{other}': pass {expected}"),
            )),
        }
    }

    /// The name Python passes: `"hydrostatic"` or `"froude_krylov"`.
    pub fn name(self) -> &'static str {
        match self {
            Pressure::Hydrostatic => "hydrostatic",
            Pressure::FroudeKrylov => "froude_krylov",
        }
    }

    /// What a repr adds inside its parentheses: nothing for the default, else
    /// `", pressure='froude_krylov'"`.
    pub fn repr_argument(self) -> String {
        match self {
            Pressure::Hydrostatic => String::new(),
            other => format!(", pressure='{}'", other.name()),
        }
    }
}
