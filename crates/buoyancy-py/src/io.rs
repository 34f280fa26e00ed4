//! `load`: a mesh read from a file by `buoyancy_core::io`.

use std::path::PathBuf;

use pyo3::prelude::*;

use crate::errors::{to_py, type_error};
use crate::mesh::PyMesh;

/// Reads a closed triangle mesh from a file, its format chosen by the extension
/// (case-insensitive): ``.obj`` (Wavefront), ``.stl`` (ASCII or binary) or ``.ply`` (ASCII or
/// binary, either byte order; polygons are split into triangles).
///
/// The vertices are taken as they are, in metres; no up axis is applied (files do not say
/// one). STL from CAD and hull files are usually z up, and :class:`Water`'s default is y up:
/// float such a mesh in ``Water(normal=(0, 0, 1))``.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file.
/// close_openings : bool
///     Close the mesh's planar openings with lids, as :meth:`Mesh.close_openings` does (a hull
///     without a deck); default ``False``, the mesh must be closed.
///
/// Memory: the file is read whole; preparing the mesh holds about 340 bytes per triangle at its
/// peak (a binary STL stores 50), so a 100 MB binary STL of 2 million triangles peaks at 680 MB,
/// 6.8 times its size (``python benches/mesh_memory.py``).
///
/// Raises
/// ------
/// FileNotFoundError, PermissionError, IsADirectoryError, OSError
///     If the file cannot be read (the ``OSError`` subclass of the operating system's reason);
///     a FIFO, device or socket is not read (an ``OSError``), it could wait or run forever.
/// MemoryError
///     If the memory to read or prepare it cannot be had.
/// ValueError
///     If the extension names no format that can be read.
/// MeshError
///     If the file cannot be parsed (bytes that are not a mesh, in any of the formats), or its
///     mesh is not closed and oriented.
///
/// Examples
/// --------
/// >>> import pathlib, tempfile
/// >>> path = pathlib.Path(tempfile.mkdtemp()) / "tetrahedron.obj"
/// >>> _ = path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
/// >>> buoyancy.load(path)
/// Mesh(n_vertices=4, n_triangles=4, volume=0.166667, centroid=[0.25, 0.25, 0.25])
#[pyfunction]
#[pyo3(signature = (path, close_openings=false), text_signature = "(path, close_openings=False)")]
pub fn load(py: Python<'_>, path: &Bound<'_, PyAny>, close_openings: bool) -> PyResult<PyMesh> {
    let path: PathBuf = path
        .extract()
        .map_err(|_| type_error("path", "a str or os.PathLike", path))?;
    let shape = py
        .detach(|| buoyancy_core::io::load::<f64>(&path))
        .map_err(|e| to_py(e, None))?;
    if close_openings {
        PyMesh::build_closing_openings(py, shape)
    } else {
        PyMesh::build(py, shape)
    }
}
