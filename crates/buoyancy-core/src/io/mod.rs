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
use crate::Real;
#[cfg(feature = "std")]
use crate::mesh::primitives::Shape;

/// The memory [`load`] may hold while it reads and parses a file, per byte of the file: the
/// bytes, and the vertices and triangles parsed from them (a binary STL's 50 bytes a triangle
/// become 3 vertices of 24 bytes and 12 bytes of indices, 84; an ASCII format's are fewer).
#[cfg(feature = "std")]
pub const READ_BYTES_PER_FILE_BYTE: usize = 3;

/// An [`Error::Parse`] at one-based `line` (0: not tied to a line).
fn parse_error(line: usize, message: String) -> Error {
    Error::Parse { line, message }
}

/// Reads a mesh file, its format chosen by its extension (case-insensitive): `.obj`
/// ([`parse_obj`]), `.stl` ([`parse_stl`]) or `.ply` ([`parse_ply`]).
///
/// The file is read whole, then parsed: reading holds the file and the parsed vertices and
/// triangles at once, at most [`READ_BYTES_PER_FILE_BYTE`] times the file's size, which is
/// asked for before the read (building the [`Mesh`](crate::Mesh) then needs its own memory).
///
/// # Errors
/// [`Error::UnknownFormat`] for any other extension; [`Error::Io`] if the file cannot be read
/// (its [`kind`](std::io::ErrorKind) says why, e.g. `NotFound`, `IsADirectory`, or
/// `InvalidInput` for a FIFO, device or socket, which are not read); [`Error::OutOfMemory`]
/// (parameter `path`) if the memory to read it cannot be had; [`Error::Parse`] if its content
/// is not a mesh of that format.
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
    if !matches!(extension.as_deref(), Some("obj" | "stl" | "ply")) {
        return Err(Error::UnknownFormat {
            path: path.display().to_string(),
        });
    }
    // Only a regular file: opening a FIFO would wait for a writer, and a device such as
    // /dev/zero never ends.
    let metadata = std::fs::metadata(path).map_err(io_error)?;
    if metadata.is_dir() {
        return Err(io_error(std::io::ErrorKind::IsADirectory.into()));
    }
    if !metadata.is_file() {
        return Err(Error::Io {
            path: path.display().to_string(),
            kind: std::io::ErrorKind::InvalidInput,
            message: "not a regular file (a FIFO, device or socket): a mesh is read from a \
                      file of known size"
                .to_string(),
        });
    }
    let size = usize::try_from(metadata.len()).unwrap_or(usize::MAX);
    crate::error::check_memory(size, READ_BYTES_PER_FILE_BYTE, "path")?;
    let bytes = std::fs::read(path).map_err(io_error)?;
    match extension.as_deref() {
        // Text: bytes that are not UTF-8 (a comment in Latin-1) are replaced, so that what is
        // not a mesh is a parse error naming the line, as in the other formats.
        Some("obj") => parse_obj(&String::from_utf8_lossy(&bytes)),
        Some("stl") => parse_stl(&bytes),
        _ => parse_ply(&bytes),
    }
}
