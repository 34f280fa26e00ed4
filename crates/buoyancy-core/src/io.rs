//! Reading triangle meshes: Wavefront OBJ, STL (ASCII and binary) and PLY (ASCII and binary,
//! little and big endian).
//!
//! [`parse_obj`] and [`parse_stl`] work on in-memory text or bytes (no_std); [`parse_ply`] and
//! [`load`], which reads a file and chooses the format by its extension, need the `std`
//! feature. They return `(vertices, triangles)` for [`Mesh::new`](crate::Mesh::new), which
//! does the validation. Vertices are in the file's units (taken as metres) and frame; indices
//! are 0-based, whatever the file's convention (OBJ counts from 1).

use alloc::string::String;

use crate::Error;

mod obj;
#[cfg(feature = "std")]
mod ply;
mod stl;

pub use obj::parse_obj;
#[cfg(feature = "std")]
pub use ply::parse_ply;
pub use stl::parse_stl;

#[cfg(feature = "std")]
use crate::{Real, shape::Shape};

/// An [`Error::Parse`] at one-based `line` (0: not tied to a line).
fn parse_error(line: usize, message: String) -> Error {
    Error::Parse { line, message }
}

/// Reads a mesh file, its format chosen by its extension (case-insensitive): `.obj`
/// ([`parse_obj`]), `.stl` ([`parse_stl`]) or `.ply` ([`parse_ply`]).
///
/// # Errors
/// [`Error::UnknownFormat`] for any other extension; [`Error::Io`] if the file cannot be read
/// (its [`kind`](std::io::ErrorKind) says why, e.g. `NotFound`); [`Error::Parse`] if its
/// content is not a mesh of that format.
#[cfg(feature = "std")]
pub fn load<T: Real>(path: impl AsRef<std::path::Path>) -> Result<Shape<T>, Error> {
    use alloc::string::ToString;
    let path = path.as_ref();
    let io_error = |e: std::io::Error| Error::Io {
        path: path.display().to_string(),
        kind: e.kind(),
        message: e.to_string(),
    };
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .map(|e| e.to_ascii_lowercase());
    match extension.as_deref() {
        Some("obj") => {
            let text = std::fs::read_to_string(path).map_err(io_error)?;
            parse_obj(&text)
        }
        Some("stl") => parse_stl(&std::fs::read(path).map_err(io_error)?),
        Some("ply") => parse_ply(&std::fs::read(path).map_err(io_error)?),
        _ => Err(Error::UnknownFormat {
            path: path.display().to_string(),
        }),
    }
}
