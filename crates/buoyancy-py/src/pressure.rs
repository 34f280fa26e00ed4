//! The `pressure` argument of `Waves` (`"hydrostatic" | "froude_krylov"`), as the core's
//! [`Pressure`].

use buoyancy_core::query::Pressure;
use pyo3::prelude::*;
use pyo3::types::PyString;

use crate::errors::{arg_error, type_error};

/// The `pressure` argument: `"hydrostatic"` (also when absent or `None`) or `"froude_krylov"`;
/// any other string is a `ValueError`, any other type a `TypeError`, each naming `pressure`.
pub fn parse(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Pressure> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(Pressure::Hydrostatic);
    };
    let expected = "'hydrostatic' or 'froude_krylov'";
    let text = obj
        .cast::<PyString>()
        .map_err(|_| type_error("pressure", expected, obj))?;
    let text = text.to_str()?;
    Pressure::ALL
        .into_iter()
        .find(|p| p.name() == text)
        .ok_or_else(|| {
            arg_error(
                "pressure",
                format!("unknown pressure model '{text}': pass {expected}"),
            )
        })
}

/// What a repr adds inside its parentheses: nothing for the default, else
/// `", pressure='froude_krylov'"`.
pub fn repr_argument(pressure: Pressure) -> String {
    match pressure {
        Pressure::Hydrostatic => String::new(),
        other => format!(", pressure='{}'", other.name()),
    }
}
