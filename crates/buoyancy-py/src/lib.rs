//! `buoyancy._core`: the Python bindings of `buoyancy-core`.
//!
//! Thin: every computation is the core's; this crate converts arguments (naming the argument
//! in each error), releases the interpreter lock around the work, and runs batches of poses on
//! rayon. The Python package `buoyancy` (python/buoyancy) re-exports it.
//!
//! The doc comments of the Python-facing items are their Python docstrings (numpydoc, with
//! `>>>` examples), not rustdoc: brackets in them are slices, not links.
#![allow(rustdoc::broken_intra_doc_links)]

mod convert;
mod damping;
mod result;

use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use buoyancy_core::nalgebra::{Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::{Error, Method, Pose, Traversal};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::create_exception;
use pyo3::exceptions::{PyFileNotFoundError, PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyTuple, PyType};
use rayon::prelude::*;

use convert::{arg_error, floats, shape_str};
use damping::{PyDamping, PyDampingCoefficients};
use result::{PyBuoyancy, PyBuoyancyBatch, Row, g, g3};

create_exception!(
    buoyancy,
    MeshError,
    PyValueError,
    "A mesh that cannot be used: not a closed, consistently oriented 2-manifold, bad vertex or face\narrays, or a mesh file that cannot be parsed. The message names the vertex, triangle or edge."
);

/// Meshes this large are evaluated with the interpreter lock released.
const DETACH_TRIANGLES: usize = 4096;

/// The Python exception for a core error: mesh problems are `MeshError`, file problems
/// `OSError`, everything else `ValueError`, prefixed with the argument's name when known.
pub(crate) fn to_py(e: Error, argument: Option<&str>) -> PyErr {
    if let Error::InvalidShape { parameter, reason } = e {
        return arg_error(parameter, reason);
    }
    let message = match argument {
        Some(name) => format!("{name}: {e}"),
        None => e.to_string(),
    };
    match e {
        Error::EmptyMesh
        | Error::TooManyVertices { .. }
        | Error::NonFiniteVertex { .. }
        | Error::IndexOutOfRange { .. }
        | Error::RepeatedIndex { .. }
        | Error::OpenEdge { .. }
        | Error::NonManifoldEdge { .. }
        | Error::InconsistentOrientation { .. }
        | Error::ZeroVolume { .. }
        | Error::Parse { .. } => MeshError::new_err(message),
        Error::Io { .. } | Error::UnknownFormat { .. } => PyOSError::new_err(message),
        _ => PyValueError::new_err(message),
    }
}

fn parse_method(method: &str) -> PyResult<Method> {
    method.parse().map_err(|e| to_py(e, Some("method")))
}

fn parse_traversal(traversal: &str) -> PyResult<Traversal> {
    traversal.parse().map_err(|e| to_py(e, Some("traversal")))
}

/// Vertices and triangles, as `buoyancy_core::Mesh::new` takes them.
type Shape = (Vec<Point3<f64>>, Vec<[u32; 3]>);

/// What `__reduce__` returns: the class and the arguments that rebuild the object.
type Reduced<'py, A> = (Bound<'py, PyType>, A);
/// `Mesh(vertices, faces)`'s arguments.
type MeshArgs<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<i64>>);
/// `Water(density, gravity, level, normal)`'s arguments.
type WaterArgs = (f64, f64, f64, (f64, f64, f64));

/// Shape (n, 3), or an empty array (left to the core to report as an empty mesh).
fn rows_of_three(shape: &[usize], len: usize) -> bool {
    (shape.len() == 2 && shape[1] == 3) || (len == 0 && shape.len() <= 2)
}

/// Vertices (N, 3) and faces (M, 3) from any array-likes.
fn mesh_arrays(vertices: &Bound<'_, PyAny>, faces: &Bound<'_, PyAny>) -> PyResult<Shape> {
    let mesh_err = |e: PyErr| MeshError::new_err(e.value(vertices.py()).to_string());
    let v = floats(vertices, "vertices").map_err(mesh_err)?;
    if !rows_of_three(&v.shape, v.values.len()) {
        return Err(MeshError::new_err(format!(
            "vertices: expected shape (N, 3), got shape {}",
            shape_str(&v.shape)
        )));
    }
    let f = floats(faces, "faces").map_err(mesh_err)?;
    if !rows_of_three(&f.shape, f.values.len()) {
        return Err(MeshError::new_err(format!(
            "faces: expected shape (M, 3) of vertex indices, got shape {}",
            shape_str(&f.shape)
        )));
    }
    let mut triangles = Vec::with_capacity(f.values.len() / 3);
    for (k, t) in f.values.chunks_exact(3).enumerate() {
        let mut tri = [0u32; 3];
        for (slot, &x) in tri.iter_mut().zip(t) {
            if !(x >= 0.0 && x <= u32::MAX as f64 && x.fract() == 0.0) {
                return Err(MeshError::new_err(format!(
                    "faces[{k}]: {x} is not a vertex index (a non-negative integer)"
                )));
            }
            *slot = x as u32;
        }
        triangles.push(tri);
    }
    let points = v.values.chunks_exact(3).map(Point3::from_slice).collect();
    Ok((points, triangles))
}

/// A closed triangle mesh, validated and prepared for buoyancy queries.
///
/// Parameters
/// ----------
/// vertices : array_like, shape (N, 3)
///     Vertex positions in the mesh frame, metres (any numeric dtype; converted to float64).
/// faces : array_like, shape (M, 3)
///     Triangles as zero-based vertex indices (any integer dtype, or integral floats), wound
///     counter-clockwise seen from outside. All-inward winding is detected and flipped.
///
/// Raises
/// ------
/// MeshError
///     (a ``ValueError``) if the arrays have the wrong shape, or the triangles are not a closed,
///     consistently oriented 2-manifold enclosing a volume; the message names the vertex,
///     triangle or edge at fault.
///
/// Examples
/// --------
/// >>> import buoyancy
/// >>> v = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
/// >>> f = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
/// >>> tet = buoyancy.Mesh(v, f)
/// >>> tet
/// Mesh(n_vertices=4, n_triangles=4, volume=0.166667, centroid=[0.25, 0.25, 0.25])
/// >>> buoyancy.Mesh(v, f[:3])
/// Traceback (most recent call last):
/// ...
/// buoyancy.MeshError: the mesh is not closed: edge (1, 2) of triangle 0 has no neighbour
///
/// ``Mesh`` is immutable, safe to share between threads, and pickles.
#[pyclass(frozen, module = "buoyancy", name = "Mesh")]
pub struct PyMesh {
    inner: buoyancy_core::Mesh<f64>,
    /// The vertices as given (for `vertices` and pickling, bit for bit).
    vertices: Vec<Point3<f64>>,
}

impl PyMesh {
    fn build(py: Python<'_>, (vertices, triangles): Shape) -> PyResult<Self> {
        let kept = vertices.clone();
        let inner = py
            .detach(move || buoyancy_core::Mesh::new(vertices, triangles))
            .map_err(|e| to_py(e, None))?;
        Ok(PyMesh {
            inner,
            vertices: kept,
        })
    }

    fn pose(
        position: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Pose<f64>> {
        let t = match position {
            Some(p) => convert::vector3(p, "position")?,
            None => Vector3::zeros(),
        };
        let r = match rotation {
            Some(r) if !r.is_none() => convert::rotation(r, "rotation")?,
            _ => UnitQuaternion::identity(),
        };
        Ok(Pose::from_parts(Translation3::from(t), r))
    }
}

/// The point the batch's torques are taken about.
enum About {
    CenterOfMass,
    Point(Point3<f64>),
    PerPose(Vec<Point3<f64>>),
}

/// Thread pools by size, built on first use and kept (`buoyancy_batch(threads=n)`).
static POOLS: Mutex<Vec<(usize, Arc<rayon::ThreadPool>)>> = Mutex::new(Vec::new());

fn pool(threads: usize) -> PyResult<Arc<rayon::ThreadPool>> {
    let mut pools = POOLS.lock().unwrap_or_else(|p| p.into_inner());
    if let Some((_, p)) = pools.iter().find(|(n, _)| *n == threads) {
        return Ok(p.clone());
    }
    let p = Arc::new(
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| arg_error("threads", e))?,
    );
    pools.push((threads, p.clone()));
    Ok(p)
}

#[pymethods]
impl PyMesh {
    #[new]
    #[pyo3(text_signature = "(vertices, faces)")]
    fn new(
        py: Python<'_>,
        vertices: &Bound<'_, PyAny>,
        faces: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let shape = mesh_arrays(vertices, faces)?;
        PyMesh::build(py, shape)
    }

    /// Builds a mesh from a ``trimesh.Trimesh`` (or any object with ``vertices`` and ``faces``).
    ///
    /// >>> import trimesh  # doctest: +SKIP
    /// >>> buoyancy.Mesh.from_trimesh(trimesh.creation.box())  # doctest: +SKIP
    /// Mesh(n_vertices=8, n_triangles=12, volume=1, centroid=[0, 0, 0])
    #[classmethod]
    fn from_trimesh<'py>(
        cls: &Bound<'py, PyType>,
        obj: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let vertices = obj.getattr("vertices")?;
        let faces = obj.getattr("faces")?;
        cls.call1((vertices, faces))
    }

    /// Enclosed volume, m³ (positive).
    #[getter]
    fn volume(&self) -> f64 {
        self.inner.volume()
    }

    /// Centroid of the enclosed volume (center of mass of a uniform body), mesh frame, shape (3,).
    #[getter]
    fn centroid<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.inner.centroid().coords.as_slice())
    }

    /// Number of vertices.
    #[getter]
    fn n_vertices(&self) -> usize {
        self.inner.vertex_count()
    }

    /// Number of triangles.
    #[getter]
    fn n_triangles(&self) -> usize {
        self.inner.triangle_count()
    }

    /// Largest distance of a vertex from the centroid, m.
    #[getter]
    fn bounding_radius(&self) -> f64 {
        self.inner.bounding_radius()
    }

    /// Whether the faces were wound inward and have all been flipped.
    #[getter]
    fn was_reoriented(&self) -> bool {
        self.inner.was_reoriented()
    }

    /// The vertices as given, shape (N, 3), float64 (a copy).
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let flat: Vec<f64> = self.vertices.iter().flat_map(|p| [p.x, p.y, p.z]).collect();
        Array2::from_shape_vec((self.vertices.len(), 3), flat)
            .expect("N×3")
            .into_pyarray(py)
    }

    /// The triangles wound outward (flipped if ``was_reoriented``), shape (M, 3), int64 (a copy).
    #[getter]
    fn faces<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i64>> {
        self.faces_array(py, false)
    }

    /// The buoyancy of the mesh at one pose.
    ///
    /// Parameters
    /// ----------
    /// position : array_like, shape (3,)
    ///     Translation of the mesh frame in the world frame, m: ``x_world = R @ x_mesh + position``.
    /// rotation : array_like, shape (4,) or (3, 3), optional
    ///     Quaternion ``(x, y, z, w)`` (scipy's order) or rotation matrix; ``None`` for identity.
    ///     A quaternion must have norm 1 within 1e-5 (it is then normalised); a matrix must be
    ///     orthonormal within 1e-5 with determinant +1. Anything else raises ``ValueError``.
    /// water : Water, optional
    ///     Default ``Water()``: fresh water, y up, surface at y = 0.
    /// method : str
    ///     ``"fast"``, ``"improved"``, ``"exact"`` (default), ``"fast_surface"`` or ``"exact_surface"``.
    /// traversal : str
    ///     ``"auto"`` (default), ``"scan"`` or ``"hierarchy"``: visit every triangle, or only the
    ///     nodes of the mesh's bounding-volume hierarchy that the surface crosses.
    ///     ``"auto"`` takes the hierarchy from 128 triangles up.
    ///     All give the same result up to round-off.
    /// about : array_like, shape (3,), optional
    ///     World point the torque is taken about; default the body's center of mass (the mesh
    ///     centroid moved by the pose).
    ///
    /// Returns
    /// -------
    /// Buoyancy
    ///
    /// Examples
    /// --------
    /// >>> cube = buoyancy.shapes.cube()            # unit cube about the origin
    /// >>> b = cube.buoyancy(position=(0, -0.25, 0))
    /// >>> round(b.volume, 12), b.force.round(6).tolist()
    /// (0.75, [0.0, 7357.5, 0.0])
    #[pyo3(
        signature = (position=None, rotation=None, water=None, method="exact", about=None, traversal="auto"),
        text_signature = "(self, position=(0, 0, 0), rotation=None, water=None, method='exact', about=None, traversal='auto')"
    )]
    #[allow(clippy::too_many_arguments)]
    fn buoyancy(
        &self,
        py: Python<'_>,
        position: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyWater>>,
        method: &str,
        about: Option<&Bound<'_, PyAny>>,
        traversal: &str,
    ) -> PyResult<PyBuoyancy> {
        let method = parse_method(method)?;
        let traversal = parse_traversal(traversal)?;
        let pose = PyMesh::pose(position, rotation)?;
        let about = match about {
            Some(a) if !a.is_none() => Some(Point3::from(convert::vector3(a, "about")?)),
            _ => None,
        };
        let water = water.map_or_else(buoyancy_core::Water::default, |w| w.get().inner);
        let mesh = &self.inner;
        let evaluate = move || {
            let b = mesh.buoyancy_with(&pose, &water, method, traversal)?;
            Ok::<_, Error>(match about {
                Some(q) => b.about(&q),
                None => b,
            })
        };
        let b = if mesh.triangle_count() >= DETACH_TRIANGLES {
            py.detach(evaluate)
        } else {
            evaluate()
        }
        .map_err(|e| to_py(e, None))?;
        Ok(PyBuoyancy {
            row: Row::new(&b),
            method,
        })
    }

    /// The buoyancy of the mesh at K poses, computed in parallel without the interpreter lock.
    ///
    /// Parameters
    /// ----------
    /// positions : array_like, shape (K, 3)
    /// rotations : array_like, shape (K, 4) or (K, 3, 3), or None
    ///     Quaternions ``(x, y, z, w)`` or rotation matrices, checked as in :meth:`buoyancy`;
    ///     ``None`` for no rotation.
    /// water : Water, optional
    /// method : str
    /// about : array_like, shape (3,) or (K, 3), optional
    ///     One world point, or one per pose, for the torques; default each pose's center of mass.
    /// threads : int, optional
    ///     Run on a pool of this many threads (kept for later calls); default rayon's global
    ///     pool (``RAYON_NUM_THREADS``, else one thread per core).
    /// traversal : str
    ///     ``"auto"`` (default), ``"scan"`` or ``"hierarchy"``, as in :meth:`buoyancy`.
    ///
    /// Returns
    /// -------
    /// BuoyancyBatch
    ///     Arrays ``volume`` (K,), ``center``, ``force``, ``torque`` (K, 3); pose ``k`` gives
    ///     exactly what ``buoyancy(positions[k], rotations[k], ...)`` gives.
    ///
    /// Examples
    /// --------
    /// >>> cube = buoyancy.shapes.cube()
    /// >>> heights = np.linspace(-1, 1, 5)
    /// >>> batch = cube.buoyancy_batch(np.c_[0 * heights, heights, 0 * heights], None)
    /// >>> batch.volume.round(12).tolist()
    /// [1.0, 1.0, 0.5, 0.0, 0.0]
    #[pyo3(
        signature = (positions, rotations=None, water=None, method="exact", about=None, threads=None, traversal="auto"),
        text_signature = "(self, positions, rotations, water=None, method='exact', about=None, threads=None, traversal='auto')"
    )]
    #[allow(clippy::too_many_arguments)]
    fn buoyancy_batch(
        &self,
        py: Python<'_>,
        positions: &Bound<'_, PyAny>,
        rotations: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyWater>>,
        method: &str,
        about: Option<&Bound<'_, PyAny>>,
        threads: Option<usize>,
        traversal: &str,
    ) -> PyResult<PyBuoyancyBatch> {
        let method = parse_method(method)?;
        let traversal = parse_traversal(traversal)?;
        let translations = convert::rows3(positions, "positions")?;
        let k = translations.len();
        let rotations = match rotations {
            Some(r) if !r.is_none() => {
                let r = convert::rotations(r, "rotations")?;
                if r.len() != k {
                    return Err(arg_error(
                        "rotations",
                        format!("has {} rotations for {k} positions", r.len()),
                    ));
                }
                r
            }
            _ => vec![UnitQuaternion::identity(); k],
        };
        let about = match about {
            Some(a) if !a.is_none() => {
                let f = floats(a, "about")?;
                convert::finite(&f.values, "about")?;
                match f.shape.as_slice() {
                    [3] => About::Point(Point3::from_slice(&f.values)),
                    [n, 3] if *n == k => {
                        About::PerPose(f.values.chunks_exact(3).map(Point3::from_slice).collect())
                    }
                    _ => {
                        return Err(arg_error(
                            "about",
                            format!(
                                "expected one point (3,) or one per pose ({k}, 3), got shape {}",
                                shape_str(&f.shape)
                            ),
                        ));
                    }
                }
            }
            _ => About::CenterOfMass,
        };
        if threads == Some(0) {
            return Err(arg_error("threads", "must be at least 1"));
        }
        let pool = threads.map(pool).transpose()?;
        let water = water.map_or_else(buoyancy_core::Water::default, |w| w.get().inner);
        let mesh = &self.inner;
        let poses: Vec<Pose<f64>> = translations
            .into_iter()
            .zip(rotations)
            .map(|(t, r)| Pose::from_parts(Translation3::from(t), r))
            .collect();
        let rows = py
            .detach(move || {
                let run = || {
                    poses
                        .par_iter()
                        .enumerate()
                        .map(|(i, pose)| {
                            let b = mesh
                                .buoyancy_with(pose, &water, method, traversal)
                                .map_err(|e| (i, e))?;
                            let b = match &about {
                                About::CenterOfMass => b,
                                About::Point(q) => b.about(q),
                                About::PerPose(q) => b.about(&q[i]),
                            };
                            Ok(Row::new(&b))
                        })
                        .collect::<Result<Vec<Row>, (usize, Error)>>()
                };
                match pool {
                    Some(p) => p.install(run),
                    None => run(),
                }
            })
            .map_err(|(i, e)| to_py(e, Some(&format!("pose {i}"))))?;
        Ok(PyBuoyancyBatch::new(py, rows, method))
    }

    /// The hydrodynamic damping of the mesh at one pose and velocity: pressure drag on the wetted
    /// surface plus angular damping (see :class:`DampingCoefficients` for the model). Zero when
    /// dry or at rest relative to the water.
    ///
    /// Parameters
    /// ----------
    /// position, rotation : array_like, optional
    ///     The pose, as in :meth:`buoyancy`.
    /// linear_velocity : array_like, shape (3,)
    ///     Velocity of the body's center of mass (the mesh centroid moved by the pose), world
    ///     frame, m/s; default zero.
    /// angular_velocity : array_like, shape (3,)
    ///     Angular velocity, world frame, rad/s; default zero.
    /// water : Water, optional
    ///     Default ``Water()``.
    /// coefficients : DampingCoefficients, optional
    ///     Default ``DampingCoefficients()``.
    /// about : array_like, shape (3,), optional
    ///     World point the torque is taken about; default the body's center of mass.
    ///
    /// Returns
    /// -------
    /// Damping
    ///
    /// The model is explicit: a simulation applying it over a step ``dt`` should keep the impulse
    /// ``|force| * dt`` below the momentum it damps (``buoyancy.rapier`` clamps it so).
    ///
    /// Examples
    /// --------
    /// A unit cube under water sinking at 2 m/s: only its bottom face (1 m²) faces the flow,
    /// and feels ``1000 * 2 + 0.5 * 1000 * 1 * 2**2 = 4000`` Pa.
    ///
    /// >>> cube = buoyancy.shapes.cube()
    /// >>> d = cube.damping(position=(0, -3, 0), linear_velocity=(0, -2, 0))
    /// >>> d.force.round(9).tolist(), d.wetted_area
    /// ([0.0, 4000.0, 0.0], 6.0)
    /// >>> cube.damping(position=(0, 2, 0), linear_velocity=(0, -2, 0)).force.tolist()  # dry
    /// [0.0, 0.0, 0.0]
    #[pyo3(
        signature = (position=None, rotation=None, linear_velocity=None, angular_velocity=None, water=None, coefficients=None, about=None),
        text_signature = "(self, position=(0, 0, 0), rotation=None, linear_velocity=(0, 0, 0), angular_velocity=(0, 0, 0), water=None, coefficients=None, about=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn damping(
        &self,
        py: Python<'_>,
        position: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
        linear_velocity: Option<&Bound<'_, PyAny>>,
        angular_velocity: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyWater>>,
        coefficients: Option<&Bound<'_, PyDampingCoefficients>>,
        about: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyDamping> {
        let pose = PyMesh::pose(position, rotation)?;
        let velocity = |v: Option<&Bound<'_, PyAny>>, name: &str| match v {
            Some(v) if !v.is_none() => convert::vector3(v, name),
            _ => Ok(Vector3::zeros()),
        };
        let linear_velocity = velocity(linear_velocity, "linear_velocity")?;
        let angular_velocity = velocity(angular_velocity, "angular_velocity")?;
        let about = match about {
            Some(a) if !a.is_none() => Some(convert::vector3(a, "about")?),
            _ => None,
        };
        let water = water.map_or_else(buoyancy_core::Water::default, |w| w.get().inner);
        let coefficients = coefficients
            .map_or_else(buoyancy_core::DampingCoefficients::default, |c| {
                c.get().inner
            });
        let mesh = &self.inner;
        let evaluate = move || {
            mesh.damping(
                &pose,
                &linear_velocity,
                &angular_velocity,
                &water,
                &coefficients,
            )
        };
        let d = if mesh.triangle_count() >= DETACH_TRIANGLES {
            py.detach(evaluate)
        } else {
            evaluate()
        }
        .map_err(|e| to_py(e, None))?;
        Ok(PyDamping::new(&d, about))
    }

    fn __repr__(&self) -> String {
        let c = self.inner.centroid();
        format!(
            "Mesh(n_vertices={}, n_triangles={}, volume={}, centroid={})",
            self.inner.vertex_count(),
            self.inner.triangle_count(),
            g(self.inner.volume()),
            g3(&[c.x, c.y, c.z])
        )
    }

    /// Pickles as the vertices and faces as given: unpickling validates again and gives a
    /// mesh with bit-identical results.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Reduced<'py, MeshArgs<'py>>> {
        let py = slf.py();
        let this = slf.get();
        Ok((
            slf.get_type(),
            (this.vertices(py), this.faces_array(py, true)),
        ))
    }
}

impl PyMesh {
    /// Faces as int64, outward, or as given (`original`: flipped back if reoriented).
    fn faces_array<'py>(&self, py: Python<'py>, original: bool) -> Bound<'py, PyArray2<i64>> {
        let flip = original && self.inner.was_reoriented();
        let flat: Vec<i64> = self
            .inner
            .triangles()
            .iter()
            .flat_map(|t| {
                let t = if flip { [t[0], t[2], t[1]] } else { *t };
                t.map(i64::from)
            })
            .collect();
        Array2::from_shape_vec((self.inner.triangle_count(), 3), flat)
            .expect("M×3")
            .into_pyarray(py)
    }
}

/// A body of still water with a flat surface, world frame, SI units.
///
/// Parameters
/// ----------
/// density : float
///     kg/m³, finite and positive (default 1000, fresh water).
/// gravity : float
///     Magnitude of gravity, m/s², finite and non-negative (default 9.81).
/// level : float
///     The surface is the plane ``dot(normal, p) == level`` (default 0).
/// normal : array_like, shape (3,)
///     Up direction (out of the water, against gravity); normalised, must be non-zero.
///
/// Raises ``ValueError`` naming the parameter that is out of range.
///
/// >>> buoyancy.Water(density=1025.0, normal=(0, 0, 1))
/// Water(density=1025, gravity=9.81, level=0, normal=(0, 0, 1))
///
/// ``Water`` is immutable, safe to share between threads, and pickles.
#[pyclass(frozen, eq, module = "buoyancy", name = "Water")]
pub struct PyWater {
    inner: buoyancy_core::Water<f64>,
    /// The normal as given, for pickling bit for bit.
    given_normal: [f64; 3],
}

/// Two waters are equal when they are the same physical water (normals compared after
/// normalisation).
impl PartialEq for PyWater {
    fn eq(&self, other: &Self) -> bool {
        self.inner == other.inner
    }
}

#[pymethods]
impl PyWater {
    #[new]
    #[pyo3(
        signature = (density=1000.0, gravity=9.81, level=0.0, normal=None),
        text_signature = "(density=1000.0, gravity=9.81, level=0.0, normal=(0.0, 1.0, 0.0))"
    )]
    fn new(
        density: f64,
        gravity: f64,
        level: f64,
        normal: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let n = match normal {
            Some(n) if !n.is_none() => convert::vector3(n, "normal")?,
            _ => Vector3::y(),
        };
        let inner =
            buoyancy_core::Water::new(density, gravity, n, level).map_err(|e| to_py(e, None))?;
        Ok(PyWater {
            inner,
            given_normal: n.into(),
        })
    }

    /// Density, kg/m³.
    #[getter]
    fn density(&self) -> f64 {
        self.inner.density()
    }
    /// Magnitude of gravity, m/s².
    #[getter]
    fn gravity(&self) -> f64 {
        self.inner.gravity()
    }
    /// Signed distance of the surface from the origin along ``normal``, m.
    #[getter]
    fn level(&self) -> f64 {
        self.inner.level()
    }
    /// Unit up normal, shape (3,).
    #[getter]
    fn normal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.inner.normal().as_slice())
    }
    /// ``density * gravity``, N/m³.
    #[getter]
    fn specific_weight(&self) -> f64 {
        self.inner.specific_weight()
    }

    fn __repr__(&self) -> String {
        let n = self.inner.normal();
        format!(
            "Water(density={}, gravity={}, level={}, normal=({}, {}, {}))",
            g(self.inner.density()),
            g(self.inner.gravity()),
            g(self.inner.level()),
            g(n.x),
            g(n.y),
            g(n.z)
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> Reduced<'py, WaterArgs> {
        let w = slf.get();
        let [x, y, z] = w.given_normal;
        (
            slf.get_type(),
            (
                w.inner.density(),
                w.inner.gravity(),
                w.inner.level(),
                (x, y, z),
            ),
        )
    }
}

/// Reads a closed triangle mesh from an OBJ or STL (ASCII or binary) file.
///
/// Raises ``FileNotFoundError``/``OSError`` if the file cannot be read, ``MeshError`` if it
/// cannot be parsed or is not a closed, oriented mesh.
#[pyfunction]
fn load(py: Python<'_>, path: PathBuf) -> PyResult<PyMesh> {
    if !path.exists() {
        return Err(PyFileNotFoundError::new_err(format!(
            "no such file: {}",
            path.display()
        )));
    }
    let shape = py
        .detach(|| buoyancy_core::io::load::<f64>(&path))
        .map_err(|e| to_py(e, None))?;
    PyMesh::build(py, shape)
}

/// The unit cube [-1/2, 1/2]³, each face split in n × n squares (12·n² triangles).
#[pyfunction]
#[pyo3(signature = (n=1))]
fn cube(py: Python<'_>, n: usize) -> PyResult<PyMesh> {
    PyMesh::build(
        py,
        buoyancy_core::shape::cube(n).map_err(|e| to_py(e, None))?,
    )
}

/// A UV sphere about the origin (2·slices·(stacks − 1) triangles).
#[pyfunction]
#[pyo3(signature = (radius=1.0, slices=32, stacks=16))]
fn uv_sphere(py: Python<'_>, radius: f64, slices: usize, stacks: usize) -> PyResult<PyMesh> {
    PyMesh::build(
        py,
        buoyancy_core::shape::uv_sphere(radius, slices, stacks).map_err(|e| to_py(e, None))?,
    )
}

/// A torus about the y axis (2·segments·sides triangles).
#[pyfunction]
#[pyo3(signature = (major=1.0, minor=0.25, segments=48, sides=16))]
fn torus(
    py: Python<'_>,
    major: f64,
    minor: f64,
    segments: usize,
    sides: usize,
) -> PyResult<PyMesh> {
    PyMesh::build(
        py,
        buoyancy_core::shape::torus(major, minor, segments, sides).map_err(|e| to_py(e, None))?,
    )
}

/// A (p, q) torus knot swept by a tube (2·segments·sides triangles).
#[pyfunction]
#[pyo3(signature = (p=2, q=3, radius=1.0, tube_radius=0.2, segments=80, sides=11))]
fn torus_knot(
    py: Python<'_>,
    p: u32,
    q: u32,
    radius: f64,
    tube_radius: f64,
    segments: usize,
    sides: usize,
) -> PyResult<PyMesh> {
    PyMesh::build(
        py,
        buoyancy_core::shape::torus_knot(p, q, radius, tube_radius, segments, sides)
            .map_err(|e| to_py(e, None))?,
    )
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add_class::<PyMesh>()?;
    m.add_class::<PyWater>()?;
    m.add_class::<PyBuoyancy>()?;
    m.add_class::<PyBuoyancyBatch>()?;
    m.add_class::<PyDamping>()?;
    m.add_class::<PyDampingCoefficients>()?;
    m.add("MeshError", py.get_type::<MeshError>())?;
    m.add_function(wrap_pyfunction!(load, m)?)?;
    m.add_function(wrap_pyfunction!(cube, m)?)?;
    m.add_function(wrap_pyfunction!(uv_sphere, m)?)?;
    m.add_function(wrap_pyfunction!(torus, m)?)?;
    m.add_function(wrap_pyfunction!(torus_knot, m)?)?;
    m.add("METHODS", PyTuple::new(py, Method::ALL.map(Method::name))?)?;
    m.add("QUATERNION_TOLERANCE", convert::QUATERNION_TOLERANCE)?;
    m.add("MATRIX_TOLERANCE", convert::MATRIX_TOLERANCE)?;
    Ok(())
}
