//! Releasing the interpreter lock around work on a large mesh, so that other Python threads run
//! meanwhile; on a small mesh the release would cost more than the work.

use pyo3::marker::Ungil;
use pyo3::prelude::*;

/// Meshes of at least this many triangles are worked on with the interpreter lock released.
pub const LARGE_MESH_TRIANGLES: usize = 4096;

/// Runs `work`, with the interpreter lock released if the mesh has at least
/// [`LARGE_MESH_TRIANGLES`] triangles.
pub fn detach_if_large<T, F>(py: Python<'_>, triangles: usize, work: F) -> T
where
    F: Ungil + FnOnce() -> T,
    T: Ungil,
{
    if triangles >= LARGE_MESH_TRIANGLES {
        py.detach(work)
    } else {
        work()
    }
}
