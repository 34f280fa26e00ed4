//! Errors as Python sees them: `MeshError`, and the mapping of the core's [`Error`] to Python
//! exceptions, each message starting with the name of the argument at fault.

use std::fmt::Display;
use std::io::ErrorKind;

use buoyancy_core::Error;
use pyo3::create_exception;
use pyo3::exceptions::{
    PyFileNotFoundError, PyIsADirectoryError, PyMemoryError, PyOSError, PyPermissionError,
    PyTypeError, PyUserWarning, PyValueError,
};
use pyo3::prelude::*;

create_exception!(
    buoyancy,
    MeshError,
    PyValueError,
    "A mesh that cannot be used: not a closed, consistently oriented 2-manifold, bad vertex or face\narrays, or a mesh file that cannot be parsed. The message names the vertices, triangles or edges\nat fault and what usually fixes them.\n\nAttributes\n----------\ndefects : tuple of MeshDefect\n    Each kind of problem of the triangles, with its count and first culprits; empty when the\n    problem is not there (an empty or flat mesh, arrays of the wrong shape, a file that cannot\n    be parsed).\ntriangle_soup : bool\n    Whether no two triangles share a vertex, as STL files store a mesh: weld the vertices.\ncoincident_vertices : int\n    How many used vertices sit exactly where a vertex of lower index does (counted when the\n    mesh has open edges): welding them closes the edges they split.\none_based_indices : bool\n    Whether the indices look one-based (as in an OBJ file): subtract 1 from every index."
);

/// `ValueError("{name}: {message}")`: an argument of the right type with a wrong value.
pub fn arg_error(name: &str, message: impl Display) -> PyErr {
    PyValueError::new_err(format!("{name}: {message}"))
}

/// `TypeError("{name}: expected {expected}, got {type of obj}")`: an argument of the wrong type.
pub fn type_error(name: &str, expected: impl Display, obj: &Bound<'_, PyAny>) -> PyErr {
    PyTypeError::new_err(format!(
        "{name}: expected {expected}, got {}",
        type_name(obj)
    ))
}

/// A `UserWarning` with `message`, attributed to the caller's line (Python shows it once per
/// line; `warnings.simplefilter("error")` makes it the returned error).
pub fn warn_user(py: Python<'_>, message: &str) -> PyResult<()> {
    let message = std::ffi::CString::new(message).unwrap_or_default();
    PyErr::warn(py, &py.get_type::<PyUserWarning>(), &message, 1)
}

/// The name of `obj`'s type as Python prints it (`float`, `tuple`, `numpy.ndarray`).
pub fn type_name(obj: &Bound<'_, PyAny>) -> String {
    let ty = obj.get_type();
    let name = ty.name().map_or_else(|_| "?".into(), |n| n.to_string());
    match ty.module() {
        Ok(module) if module != "builtins" => format!("{module}.{name}"),
        _ => name,
    }
}

/// The Python exception for a core error:
///
/// * a parameter out of range (shape, water, damping) is a `ValueError` naming the parameter;
/// * a mesh that cannot be used, or a file that cannot be parsed, is a [`MeshError`], with the
///   core's report of a broken mesh as its attributes (`defects`, …);
/// * a request whose memory cannot be allocated is a `MemoryError` naming `argument` (else the
///   core's parameter);
/// * a file that cannot be read is the `OSError` subclass of its kind (`FileNotFoundError`,
///   `PermissionError`, `IsADirectoryError`, else `OSError`), and one of an unknown format a
///   `ValueError`;
/// * anything else is a `ValueError`.
///
/// The message is prefixed with `argument` when given (`"pose 3: …"`).
pub fn to_py(e: Error, argument: Option<&str>) -> PyErr {
    match e {
        Error::InvalidShape { parameter, reason }
        | Error::InvalidWater { parameter, reason }
        | Error::InvalidDamping { parameter, reason }
        | Error::InvalidLoading { parameter, reason } => return arg_error(parameter, reason),
        // The core names its parameter; the message names the argument it came from.
        Error::OutOfMemory { parameter, .. } => {
            let name = argument.unwrap_or(parameter);
            return PyMemoryError::new_err(e.to_string().replace(parameter, name));
        }
        _ => {}
    }
    let message = match argument {
        Some(name) => format!("{name}: {e}"),
        None => e.to_string(),
    };
    match e {
        Error::InvalidMesh(defects) => {
            let error = MeshError::new_err(message);
            Python::attach(|py| {
                crate::defects::describe(error.value(py), &defects).map_or_else(|e| e, |()| error)
            })
        }
        Error::EmptyMesh
        | Error::TooManyVertices { .. }
        | Error::ZeroVolume { .. }
        | Error::Parse { .. } => MeshError::new_err(message),
        Error::Io { kind, .. } => match kind {
            ErrorKind::NotFound => PyFileNotFoundError::new_err(message),
            ErrorKind::PermissionDenied => PyPermissionError::new_err(message),
            ErrorKind::IsADirectory => PyIsADirectoryError::new_err(message),
            _ => PyOSError::new_err(message),
        },
        _ => PyValueError::new_err(message),
    }
}
