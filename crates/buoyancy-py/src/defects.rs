//! What `MeshError` says of a broken mesh besides its message: `MeshDefect`, one kind of
//! problem with its count and first culprits (the core's [`Defect`]), and the attributes set on
//! the exception (`defects`, `triangle_soup`, `coincident_vertices`, `one_based_indices`).

use buoyancy_core::{Culprit, Defect, DefectKind, MeshDefects};

use crate::errors::arg_error;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple, PyType};

/// `MeshDefect(kind, count, examples)`'s arguments, as `__reduce__` returns them.
type DefectArgs = (&'static str, usize, Py<PyTuple>);

/// One kind of problem found in a mesh, an item of ``MeshError.defects``.
///
/// Attributes
/// ----------
/// kind : str
///     ``"non_finite_vertex"``, ``"index_out_of_range"``, ``"repeated_index"``,
///     ``"open_edge"``, ``"non_manifold_edge"`` or ``"inconsistent_orientation"``.
/// count : int
///     How many vertices (``non_finite_vertex``), triangles (``index_out_of_range``,
///     ``repeated_index``) or edges (the others) have the problem.
/// examples : tuple of dict
///     The first few of them (at most 5), zero-based: ``{"vertex": v}``,
///     ``{"triangle": t, "index": i}`` (its first index out of range),
///     ``{"triangle": t, "indices": (a, b, c)}``, or ``{"edge": (a, b), "triangles": (t, ...)}``
///     (every triangle that has the edge).
///
/// Examples
/// --------
/// >>> v = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
/// >>> try:
/// ...     buoyancy.Mesh(v, [(0, 2, 1), (0, 1, 3), (0, 3, 2)])  # the fourth face is missing
/// ... except buoyancy.MeshError as error:
/// ...     [(d.kind, d.count) for d in error.defects], error.defects[0].examples[0]
/// ([('open_edge', 3)], {'edge': (1, 2), 'triangles': (0,)})
#[pyclass(frozen, module = "buoyancy", name = "MeshDefect")]
pub struct PyMeshDefect {
    kind: &'static str,
    count: usize,
    examples: Py<PyTuple>,
}

#[pymethods]
impl PyMeshDefect {
    /// A defect of `kind` (one of the names above), as `MeshError` reports it; also how a
    /// pickled one is rebuilt.
    #[new]
    fn new(kind: &str, count: usize, examples: Bound<'_, PyTuple>) -> PyResult<Self> {
        let kind = DefectKind::ALL
            .iter()
            .map(|k| k.name())
            .find(|name| *name == kind)
            .ok_or_else(|| {
                let names: Vec<_> = DefectKind::ALL.iter().map(|k| k.name()).collect();
                arg_error(
                    "kind",
                    format!("must be one of {}, got '{kind}'", names.join(", ")),
                )
            })?;
        Ok(Self {
            kind,
            count,
            examples: examples.unbind(),
        })
    }

    /// Pickles as its three attributes.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyType>, DefectArgs)> {
        let this = slf.get();
        let py = slf.py();
        Ok((
            slf.get_type(),
            (this.kind, this.count, this.examples.clone_ref(py)),
        ))
    }

    #[getter]
    fn kind(&self) -> &'static str {
        self.kind
    }
    #[getter]
    fn count(&self) -> usize {
        self.count
    }
    #[getter]
    fn examples(&self, py: Python<'_>) -> Py<PyTuple> {
        self.examples.clone_ref(py)
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        Ok(format!(
            "MeshDefect(kind='{}', count={}, examples={})",
            self.kind,
            self.count,
            self.examples.bind(py).repr()?
        ))
    }
}

/// A culprit as a dict of its zero-based indices.
fn culprit<'py>(py: Python<'py>, c: &Culprit) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    match c {
        Culprit::Vertex { vertex } => d.set_item("vertex", vertex)?,
        Culprit::Index { triangle, index } => {
            d.set_item("triangle", triangle)?;
            d.set_item("index", index)?;
        }
        Culprit::Triangle { triangle, indices } => {
            d.set_item("triangle", triangle)?;
            d.set_item("indices", PyTuple::new(py, indices)?)?;
        }
        Culprit::Edge { edge, triangles } => {
            d.set_item("edge", PyTuple::new(py, edge)?)?;
            d.set_item("triangles", PyTuple::new(py, triangles)?)?;
        }
    }
    Ok(d)
}

fn defect(py: Python<'_>, d: &Defect) -> PyResult<PyMeshDefect> {
    let examples = d
        .examples
        .iter()
        .map(|c| culprit(py, c))
        .collect::<PyResult<Vec<_>>>()?;
    Ok(PyMeshDefect {
        kind: d.kind.name(),
        count: d.count,
        examples: PyTuple::new(py, examples)?.unbind(),
    })
}

/// Sets the attributes of a `MeshError` instance from the core's report.
pub fn describe(error: &Bound<'_, PyAny>, defects: &MeshDefects) -> PyResult<()> {
    let py = error.py();
    let items = defects
        .defects
        .iter()
        .map(|d| defect(py, d))
        .collect::<PyResult<Vec<_>>>()?;
    error.setattr("defects", PyTuple::new(py, items)?)?;
    error.setattr("triangle_soup", defects.triangle_soup)?;
    error.setattr("coincident_vertices", defects.coincident_vertices)?;
    error.setattr("one_based_indices", defects.one_based_indices)?;
    Ok(())
}

/// The attributes of a `MeshError` whose mesh has no defect of its triangles (an empty or flat
/// mesh, arrays of the wrong shape, a file that cannot be parsed), as class attributes.
pub fn set_defaults(mesh_error: &Bound<'_, PyType>) -> PyResult<()> {
    mesh_error.setattr("defects", PyTuple::empty(mesh_error.py()))?;
    mesh_error.setattr("triangle_soup", false)?;
    mesh_error.setattr("coincident_vertices", 0)?;
    mesh_error.setattr("one_based_indices", false)?;
    Ok(())
}
