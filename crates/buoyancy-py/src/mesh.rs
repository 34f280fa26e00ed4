//! `Mesh`: a closed triangle mesh, and its queries (buoyancy at one pose or many, damping) and
//! transformed copies.

use std::sync::{Arc, OnceLock};

use buoyancy_core::nalgebra::{Matrix4, Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::{Error, Pose};
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;
use pyo3::types::{PySlice, PyType};

use crate::arrays;
use crate::batch::{About, Batch, batch_times};
use crate::convert::{self, floats, given, shape_str};
use crate::damping::{PyDamping, PyDampingCoefficients};
use crate::detach::detach_if_large;
use crate::errors::{MeshError, arg_error, to_py, type_error};
use crate::format::{g, g3};
use crate::hydrostatics::{self, PyHydrostatics, PyWaterplane};
use crate::result::{PyBuoyancy, PyBuoyancyBatch, Row};
use crate::stability::{self, PyEquilibrium, PyGzCurve, PyHydrostaticTable};
use crate::threads;
use crate::water::PyWater;
use crate::water_waves::{Failure, WaterWaves};

/// Vertices and triangles, as `buoyancy_core::Mesh::new` takes them.
pub type Shape = (Vec<Point3<f64>>, Vec<[u32; 3]>);

/// `Mesh(vertices, faces)`'s arguments, as `__reduce__` returns them.
type MeshArgs<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<i64>>);

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

/// The scale factors of `Mesh.scaled`: one number for all three axes, or three.
fn scale_factors(factor: &Bound<'_, PyAny>) -> PyResult<Vector3<f64>> {
    if let Ok(f) = factor.extract::<f64>() {
        return Ok(Vector3::repeat(f));
    }
    convert::vector3(factor, "factor")
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
/// buoyancy.MeshError: the mesh (4 vertices, 3 triangles) is not a closed, consistently oriented ...
/// - 3 open edges (of one triangle only: the mesh is not closed): edge (1, 2) of triangle 0, ...
///
/// The error's ``defects`` list the same problems as :class:`MeshDefect` items.
///
/// ``Mesh`` is immutable and safe to share between threads; it compares (and hashes) by value,
/// its vertices as given and its faces, and pickles. Its array attributes are read-only.
#[pyclass(frozen, eq, module = "buoyancy", name = "Mesh")]
pub struct PyMesh {
    /// Shared with the controllers' bodies it floats (a mesh is never changed).
    inner: Arc<buoyancy_core::Mesh<f64>>,
    /// The vertices as given (for `vertices`, equality and pickling, bit for bit), and after
    /// them the centers of the lids of a hull built by `close_openings`.
    vertices: Vec<Point3<f64>>,
    /// For a hull built by `close_openings`: how many of the vertices and triangles were
    /// given (the lids' follow), so that pickling rebuilds it from those.
    given: Option<(usize, usize)>,
    /// The hash of `vertices` and the faces, computed on first use.
    hash: OnceLock<u64>,
}

/// Two meshes are equal when their vertices (as given) and their faces (as given) are.
impl PartialEq for PyMesh {
    fn eq(&self, other: &Self) -> bool {
        self.vertices == other.vertices
            && self.given == other.given
            && self.inner.was_reoriented() == other.inner.was_reoriented()
            && self.inner.triangles() == other.inner.triangles()
    }
}

impl PyMesh {
    fn new(inner: buoyancy_core::Mesh<f64>, vertices: Vec<Point3<f64>>) -> Self {
        PyMesh {
            inner: Arc::new(inner),
            vertices,
            given: None,
            hash: OnceLock::new(),
        }
    }

    /// The core's mesh.
    pub fn core(&self) -> &buoyancy_core::Mesh<f64> {
        &self.inner
    }

    /// The hash of the vertices (as given) and the faces, consistent with `==`, computed once.
    ///
    /// The words (the coordinates' bits, `-0.0` as `0.0`, which it equals; the reorientation;
    /// three indices a triangle) are mixed one multiply each, as rustc's `FxHasher` does: a
    /// 2,352-triangle mesh hashes in a few µs, not the 60 µs of `DefaultHasher`. Equal meshes
    /// hash alike; telling unequal ones apart is `==`'s work.
    pub fn content_hash(&self) -> u64 {
        *self.hash.get_or_init(|| {
            let mix =
                |h: u64, word: u64| (h.rotate_left(5) ^ word).wrapping_mul(0x517c_c1b7_2722_0a95);
            let mut h = self.vertices.iter().fold(0, |h, p| {
                [p.x, p.y, p.z]
                    .iter()
                    .fold(h, |h, x| mix(h, (x + 0.0).to_bits()))
            });
            h = mix(h, u64::from(self.inner.was_reoriented()));
            for t in self.inner.triangles() {
                h = mix(h, u64::from(t[0]) | u64::from(t[1]) << 32);
                h = mix(h, u64::from(t[2]));
            }
            h
        })
    }

    /// The core's mesh, shared: the bodies of a controller made of the same `Mesh` share one
    /// core mesh (and its reduced copy for the damping), not a copy each.
    pub fn shared(&self) -> Arc<buoyancy_core::Mesh<f64>> {
        Arc::clone(&self.inner)
    }

    /// A mesh validated and prepared by the core from vertices and triangles, with the
    /// interpreter lock released.
    pub fn build(py: Python<'_>, (vertices, triangles): Shape) -> PyResult<Self> {
        let kept = vertices.clone();
        let inner = py
            .detach(move || buoyancy_core::Mesh::new(vertices, triangles))
            .map_err(|e| to_py(e, None))?;
        Ok(PyMesh::new(inner, kept))
    }

    /// A hull whose planar openings are closed by lids (the core's `Mesh::close_openings`),
    /// with the interpreter lock released.
    pub fn build_closing_openings(py: Python<'_>, (vertices, triangles): Shape) -> PyResult<Self> {
        let given = (vertices.len(), triangles.len());
        let mut kept = vertices.clone();
        let inner = py
            .detach(move || buoyancy_core::Mesh::close_openings(vertices, triangles))
            .map_err(|e| to_py(e, None))?;
        // The lids' centers, as the core placed them.
        kept.extend((given.0..inner.vertex_count()).map(|i| inner.vertex(i)));
        let opened = !inner.openings().is_empty();
        Ok(PyMesh {
            given: opened.then_some(given),
            ..PyMesh::new(inner, kept)
        })
    }

    /// This mesh mapped by `map`, the core's transform by the affine `matrix`, with the
    /// interpreter lock released; errors are prefixed with `argument`.
    fn mapped(
        &self,
        py: Python<'_>,
        matrix: &Matrix4<f64>,
        argument: &str,
        map: impl Send + FnOnce(&buoyancy_core::Mesh<f64>) -> Result<buoyancy_core::Mesh<f64>, Error>,
    ) -> PyResult<Self> {
        let mesh = &self.inner;
        let inner = py
            .detach(move || map(mesh))
            .map_err(|e| to_py(e, Some(argument)))?;
        // The vertices the core built the new mesh from, so that pickling the result rebuilds it
        // bit for bit.
        let vertices = (0..mesh.vertex_count())
            .map(|i| matrix.transform_point(&mesh.vertex(i)))
            .collect();
        // The core keeps the openings through the transform; pickling closes them again from
        // the moved rims (an affine map keeps a lid's center the mean of its rim).
        Ok(PyMesh {
            given: self.given,
            ..PyMesh::new(inner, vertices)
        })
    }

    pub(crate) fn pose(
        position: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Pose<f64>> {
        let t = match given(position) {
            Some(p) => convert::vector3(p, "position")?,
            None => Vector3::zeros(),
        };
        let r = match given(rotation) {
            Some(r) => convert::rotation(r, "rotation")?,
            None => UnitQuaternion::identity(),
        };
        Ok(Pose::from_parts(Translation3::from(t), r))
    }

    /// The `water` argument, default `Water()`: its still plane, and its waves.
    pub(crate) fn water<'a>(
        water: Option<&'a Bound<'_, PyAny>>,
    ) -> PyResult<(buoyancy_core::Water<f64>, Option<&'a WaterWaves>)> {
        Ok(match convert::instance::<PyWater>(water, "water")? {
            Some(w) => (w.get().inner, w.get().waves.as_ref()),
            None => (buoyancy_core::Water::default(), None),
        })
    }

    /// Faces as int64, outward, or as given (`original`: flipped back if reoriented).
    fn faces_array<'py>(&self, py: Python<'py>, original: bool) -> Bound<'py, PyArray2<i64>> {
        let flip = original && self.inner.was_reoriented();
        arrays::rows3(
            py,
            self.inner.triangles().iter().map(|t| {
                let t = if flip { [t[0], t[2], t[1]] } else { *t };
                t.map(i64::from)
            }),
        )
    }
}

/// The arguments of [`PyMesh::damping`] and [`PyMesh::damping_stiffness`], checked.
struct DampingArguments {
    pose: Pose<f64>,
    linear_velocity: Vector3<f64>,
    angular_velocity: Vector3<f64>,
    water: buoyancy_core::Water<f64>,
    coefficients: buoyancy_core::DampingCoefficients<f64>,
}

impl DampingArguments {
    /// The arguments, and the point `about` when given.
    fn parse(
        position: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
        linear_velocity: Option<&Bound<'_, PyAny>>,
        angular_velocity: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyAny>>,
        coefficients: Option<&Bound<'_, PyAny>>,
        about: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<(Self, Option<Vector3<f64>>)> {
        let pose = PyMesh::pose(position, rotation)?;
        let velocity = |v: Option<&Bound<'_, PyAny>>, name: &str| match given(v) {
            Some(v) => convert::vector3(v, name),
            None => Ok(Vector3::zeros()),
        };
        let linear_velocity = velocity(linear_velocity, "linear_velocity")?;
        let angular_velocity = velocity(angular_velocity, "angular_velocity")?;
        let about = match given(about) {
            Some(a) => Some(convert::vector3(a, "about")?),
            None => None,
        };
        let (water, waves) = PyMesh::water(water)?;
        if waves.is_some() {
            return Err(arg_error(
                "water",
                "the damping model assumes a flat water surface, and this water has waves: pass a Water without waves",
            ));
        }
        let coefficients =
            convert::instance::<PyDampingCoefficients>(coefficients, "coefficients")?
                .map_or_else(buoyancy_core::DampingCoefficients::default, |c| {
                    c.get().inner
                });
        let arguments = DampingArguments {
            pose,
            linear_velocity,
            angular_velocity,
            water,
            coefficients,
        };
        Ok((arguments, about))
    }
}

#[pymethods]
impl PyMesh {
    #[new]
    #[pyo3(text_signature = "(vertices, faces)")]
    fn py_new(
        py: Python<'_>,
        vertices: &Bound<'_, PyAny>,
        faces: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let shape = mesh_arrays(vertices, faces)?;
        PyMesh::build(py, shape)
    }

    /// A hull surface with planar openings (a hull without a deck, the usual input of naval
    /// architecture), each closed by a flat lid: a fan of triangles from a vertex added at the
    /// mean of the opening's rim. Everything computed counts the lids as hull, which holds while
    /// the water stays below every rim: :meth:`hydrostatics` and :meth:`equilibrium` raise
    /// ``ValueError`` when the water reaches one, :meth:`gz_curve` stops there
    /// (``GzCurve.flooding_angle``), :meth:`hydrostatic_table` refuses such a draft. A closed
    /// mesh is built as ``Mesh(vertices, faces)`` builds it.
    ///
    /// ``vertices`` then ``faces`` hold the lids' centers and triangles after the given ones;
    /// ``openings`` lists each rim's vertices. A rim that is not planar (within 1e-6 of its
    /// size) is a ``ValueError`` naming it.
    ///
    /// Examples
    /// --------
    /// >>> cube = buoyancy.shapes.cube(2)
    /// >>> top = np.all(cube.vertices[cube.faces][:, :, 1] == 0.5, axis=1)   # the y = 0.5 face
    /// >>> open_box = buoyancy.Mesh.close_openings(cube.vertices, cube.faces[~top])
    /// >>> len(open_box.openings), round(open_box.volume, 12)
    /// (1, 1.0)
    #[classmethod]
    #[pyo3(text_signature = "(vertices, faces)")]
    fn close_openings(
        _cls: &Bound<'_, PyType>,
        py: Python<'_>,
        vertices: &Bound<'_, PyAny>,
        faces: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let shape = mesh_arrays(vertices, faces)?;
        PyMesh::build_closing_openings(py, shape)
    }

    /// A closed mesh from a tessellation that repeats its vertices (the seams and poles of an
    /// engine's sphere, cylinder or capsule, such as ``rapier3d``'s ``to_trimesh``; an STL-like
    /// list of corners face by face): vertices within 1e-6 of the mesh's extent of an earlier one
    /// are merged and the triangles that collapse dropped (``buoyancy_core::mesh::primitives::weld``), then
    /// the mesh is built as ``Mesh(vertices, faces)`` builds it.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> corners = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    /// >>> faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    /// >>> soup = corners[faces].reshape(-1, 3)            # 12 vertices, one per corner of a face
    /// >>> round(buoyancy.Mesh.welded(soup, np.arange(12).reshape(4, 3)).volume, 15)
    /// 0.166666666666667
    #[classmethod]
    #[pyo3(text_signature = "(vertices, faces)")]
    fn welded(
        _cls: &Bound<'_, PyType>,
        py: Python<'_>,
        vertices: &Bound<'_, PyAny>,
        faces: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let (vertices, mut triangles) = mesh_arrays(vertices, faces)?;
        buoyancy_core::mesh::primitives::weld(&vertices, &mut triangles);
        PyMesh::build(py, (vertices, triangles))
    }

    /// The openings closed by lids (:meth:`close_openings`): a list of int64 arrays, each the
    /// indices of one rim's vertices in order; empty for a closed mesh.
    #[getter]
    fn openings<'py>(&self, py: Python<'py>) -> Vec<Bound<'py, PyArray1<i64>>> {
        self.inner
            .openings()
            .iter()
            .map(|o| arrays::column(py, o.rim().iter().map(|&i| i64::from(i))))
            .collect()
    }

    /// Builds a mesh from a ``trimesh.Trimesh`` (or any object with ``vertices`` and ``faces``),
    /// or from a ``trimesh.Scene``: its geometry concatenated, each part placed by the scene's
    /// transforms (``scene.to_geometry()``), which must together be closed.
    ///
    /// The vertices are taken as they are; no up axis is applied. trimesh, CAD files and naval
    /// tools are usually z up, and :class:`Water`'s default is y up: float such a mesh in
    /// ``Water(normal=(0, 0, 1))`` (see the README's conventions).
    ///
    /// >>> import trimesh  # doctest: +SKIP
    /// >>> buoyancy.Mesh.from_trimesh(trimesh.creation.box())  # doctest: +SKIP
    /// Mesh(n_vertices=8, n_triangles=12, volume=1, centroid=[0, 0, 0])
    /// >>> from types import SimpleNamespace
    /// >>> tet = SimpleNamespace(
    /// ...     vertices=[(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)],
    /// ...     faces=[(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)],
    /// ... )
    /// >>> buoyancy.Mesh.from_trimesh(tet)
    /// Mesh(n_vertices=4, n_triangles=4, volume=0.166667, centroid=[0.25, 0.25, 0.25])
    ///
    /// Raises ``TypeError`` naming ``obj`` for anything else.
    #[classmethod]
    fn from_trimesh<'py>(
        cls: &Bound<'py, PyType>,
        obj: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        const EXPECTED: &str =
            "a trimesh.Trimesh or trimesh.Scene (an object with vertices and faces arrays)";
        let geometry = if obj.hasattr("faces")? {
            obj.clone()
        } else if obj.hasattr("to_geometry")? {
            obj.call_method0("to_geometry")?
        } else {
            return Err(type_error("obj", EXPECTED, obj));
        };
        if !(geometry.hasattr("vertices")? && geometry.hasattr("faces")?) {
            return Err(type_error(
                "obj",
                format!("{EXPECTED}; the scene's geometry has no faces"),
                &geometry,
            ));
        }
        cls.call1((geometry.getattr("vertices")?, geometry.getattr("faces")?))
    }

    /// Enclosed volume, m³ (positive).
    #[getter]
    fn volume(&self) -> f64 {
        self.inner.volume()
    }

    /// Centroid of the enclosed volume (center of mass of a uniform body), mesh frame, shape (3,)
    /// (a new, read-only array).
    #[getter]
    fn centroid<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        arrays::vector(py, self.inner.centroid().coords.as_slice())
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

    /// The longest edge of the triangles, m: waves shorter than twice it are not seen between
    /// the vertices, where the surface is sampled (``buoyancy`` warns).
    #[getter]
    fn longest_edge(&self) -> f64 {
        self.inner.longest_edge()
    }

    /// Whether the faces were wound inward and have all been flipped.
    #[getter]
    fn was_reoriented(&self) -> bool {
        self.inner.was_reoriented()
    }

    /// The vertices as given, shape (N, 3), float64 (a new, read-only array).
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        arrays::rows3(py, self.vertices.iter().map(|p| [p.x, p.y, p.z]))
    }

    /// The triangles wound outward (flipped if ``was_reoriented``), shape (M, 3), int64 (a new,
    /// read-only array).
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
    ///     ``"fast"``, ``"improved"``, ``"exact"`` (default), ``"fast_surface"`` or
    ///     ``"exact_surface"``, in any case, with ``_``, ``-`` or nothing between the words
    ///     (``"ExactSurface"``, the Rust name, works too). On a water with waves ``"exact"`` and
    ///     ``"exact_surface"`` are the same exact integral of the pressure; the others assume a
    ///     flat surface (a ``ValueError``).
    /// traversal : str
    ///     ``"auto"`` (default), ``"scan"`` or ``"hierarchy"``: visit every triangle, or only the
    ///     nodes of the mesh's bounding-volume hierarchy that the surface crosses.
    ///     ``"auto"`` takes the hierarchy from 128 triangles up.
    ///     All give the same result up to round-off. On waves the hierarchy is walked against
    ///     the layer the surface lies in (``"scan"``: every vertex evaluated, every triangle on
    ///     its own); under the Froude–Krylov pressure every triangle is integrated.
    /// about : array_like, shape (3,), optional
    ///     World point the torque is taken about; default the body's center of mass (the mesh
    ///     centroid moved by the pose).
    /// time : float
    ///     The time of the water's waves, s, finite (default 0); still water does not depend on it.
    ///
    /// Returns
    /// -------
    /// Buoyancy
    ///     On waves: the hydrostatic pressure of the waves integrated exactly over the wetted
    ///     surface (sampled at the vertices, once per vertex), or, under :class:`Waves` of
    ///     ``pressure="froude_krylov"``, the linear Froude–Krylov pressure integrated over it by
    ///     a degree-5 quadrature; ``volume`` is the volume implied by
    ///     the force along the normal, ``force / (density * gravity)``, and ``center`` a point of
    ///     the force's line of action.
    ///
    /// Examples
    /// --------
    /// >>> cube = buoyancy.shapes.cube()            # unit cube about the origin
    /// >>> b = cube.buoyancy(position=(0, -0.25, 0))
    /// >>> round(b.volume, 12), b.force.round(6).tolist()
    /// (0.75, [0.0, 7357.5, 0.0])
    /// >>> cube.buoyancy(position=(0, -0.25, 0), method="ExactSurface").method
    /// 'exact_surface'
    ///
    /// On a surface tilted by the slope 0.1 along x the force leans against the slope:
    ///
    /// >>> ramp = buoyancy.Water(waves=lambda p, t: 0.1 * p[:, 0])
    /// >>> fx, fy, _ = cube.buoyancy(position=(0, -0.25, 0), water=ramp).force
    /// >>> round(float(fx / fy), 12)
    /// -0.1
    #[pyo3(
        signature = (position=None, rotation=None, water=None, method=None, about=None, traversal=None, time=None),
        text_signature = "(self, position=(0, 0, 0), rotation=None, water=None, method='exact', about=None, traversal='auto', time=0.0)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn buoyancy(
        &self,
        py: Python<'_>,
        position: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyAny>>,
        method: Option<&Bound<'_, PyAny>>,
        about: Option<&Bound<'_, PyAny>>,
        traversal: Option<&Bound<'_, PyAny>>,
        time: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyBuoyancy> {
        let (water, waves) = PyMesh::water(water)?;
        let query = convert::query(method, traversal)?;
        let pose = PyMesh::pose(position, rotation)?;
        let about = match given(about) {
            Some(a) => Some(Point3::from(convert::vector3(a, "about")?)),
            None => None,
        };
        let time = convert::time(time, "time")?;
        let mesh = &self.inner;
        // A Python surface function takes the interpreter lock back around its call.
        let b = detach_if_large(py, mesh.triangle_count(), move || {
            let b = match waves {
                None => mesh.buoyancy(&pose, &water, query).map_err(Failure::Core)?,
                Some(waves) => waves.buoyancy(mesh, &pose, &water, time, query)?,
            };
            Ok::<_, Failure>(match about {
                Some(q) => b.about(&q),
                None => b,
            })
        })
        .map_err(|f| f.into_py(None))?;
        Ok(PyBuoyancy {
            row: Row::new(&b),
            method: query.method(),
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
    ///     As in :meth:`buoyancy`.
    /// about : array_like, shape (3,) or (K, 3), optional
    ///     One world point, or one per pose, for the torques; default each pose's center of mass.
    /// threads : int, optional
    ///     Run on a pool of this many threads (kept for later calls); default rayon's global
    ///     pool (``RAYON_NUM_THREADS``, else one thread per core).
    /// traversal : str
    ///     ``"auto"`` (default), ``"scan"`` or ``"hierarchy"``, as in :meth:`buoyancy`.
    /// times : float or array_like, shape (K,), optional
    ///     The time of the water's waves at each pose, s, finite; one for every pose, or one per
    ///     pose; default 0. A callable surface is called once per pose, holding the interpreter
    ///     lock only around the call.
    ///
    /// Returns
    /// -------
    /// BuoyancyBatch
    ///     Read-only arrays ``volume`` (K,), ``center``, ``force``, ``torque`` (K, 3); pose ``k``
    ///     gives exactly what ``buoyancy(positions[k], rotations[k], ...)`` gives.
    ///
    /// Examples
    /// --------
    /// >>> cube = buoyancy.shapes.cube()
    /// >>> heights = np.linspace(-1, 1, 5)
    /// >>> batch = cube.buoyancy_batch(np.c_[0 * heights, heights, 0 * heights], None)
    /// >>> batch.volume.round(12).tolist()
    /// [1.0, 1.0, 0.5, 0.0, 0.0]
    ///
    /// A box riding a swell for one period, one time per pose:
    ///
    /// >>> swell = buoyancy.Waves([buoyancy.AiryWave(amplitude=0.1, wavelength=8.0)])
    /// >>> period = 2 * np.pi / swell.angular_frequencies()[0]
    /// >>> times = np.linspace(0, period, 5)
    /// >>> still = np.zeros((5, 3))
    /// >>> heave = cube.buoyancy_batch(still, None, water=buoyancy.Water(waves=swell), times=times)
    /// >>> heave.force[:, 1].round().tolist()     # N: crest, node, trough, node, crest
    /// [5811.0, 4905.0, 3999.0, 4905.0, 5811.0]
    #[pyo3(
        signature = (positions, rotations=None, water=None, method=None, about=None, threads=None, traversal=None, times=None),
        text_signature = "(self, positions, rotations, water=None, method='exact', about=None, threads=None, traversal='auto', times=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn buoyancy_batch(
        &self,
        py: Python<'_>,
        positions: &Bound<'_, PyAny>,
        rotations: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyAny>>,
        method: Option<&Bound<'_, PyAny>>,
        about: Option<&Bound<'_, PyAny>>,
        threads: Option<&Bound<'_, PyAny>>,
        traversal: Option<&Bound<'_, PyAny>>,
        times: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyBuoyancyBatch> {
        let (water, waves) = PyMesh::water(water)?;
        let query = convert::query(method, traversal)?;
        let translations = convert::rows3(positions, "positions")?;
        let k = translations.len();
        let rotations = match given(rotations) {
            Some(r) => {
                let r = convert::rotations(r, "rotations")?;
                if r.len() != k {
                    return Err(arg_error(
                        "rotations",
                        format!("has {} rotations for {k} positions", r.len()),
                    ));
                }
                r
            }
            None => vec![UnitQuaternion::identity(); k],
        };
        let about = About::parse(about, k)?;
        let times = batch_times(times, k)?;
        let pool = given(threads)
            .map(|t| threads::pool(convert::count(t, "threads")?))
            .transpose()?;
        let batch = Batch {
            mesh: &self.inner,
            poses: translations
                .into_iter()
                .zip(rotations)
                .map(|(t, r)| Pose::from_parts(Translation3::from(t), r))
                .collect(),
            water,
            waves,
            times,
            query,
            about,
        };
        let rows = py
            .detach(|| batch.run(pool.as_deref()))
            .map_err(|(i, f)| match f {
                // The query itself, refused for every pose alike: named by its argument alone.
                f @ Failure::Core(Error::Unsupported { .. }) => f.into_py(None),
                f => f.into_py(Some(&format!("pose {i}"))),
            })?;
        Ok(PyBuoyancyBatch::new(py, rows, query.method()))
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
    ///     Default ``Water()``; without waves (the model assumes a flat surface: a ``ValueError``).
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
    /// ``|force| * dt`` below the momentum it damps; :class:`Controller` (and so
    /// ``buoyancy.rapier``) applies it semi-implicitly, and :meth:`damping_stiffness` gives what
    /// an implicit integration needs.
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
        water: Option<&Bound<'_, PyAny>>,
        coefficients: Option<&Bound<'_, PyAny>>,
        about: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyDamping> {
        let (arguments, about) = DampingArguments::parse(
            position,
            rotation,
            linear_velocity,
            angular_velocity,
            water,
            coefficients,
            about,
        )?;
        let mesh = &self.inner;
        let d = detach_if_large(py, mesh.triangle_count(), move || {
            let a = &arguments;
            mesh.damping(
                &a.pose,
                &a.linear_velocity,
                &a.angular_velocity,
                &a.water,
                &a.coefficients,
            )
        })
        .map_err(|e| to_py(e, None))?;
        Ok(PyDamping::new(&d, about))
    }

    /// The stiffness of the damping, ``K = −∂W/∂q̇``: how the damping wrench ``W = (force,
    /// torque)`` of :meth:`damping` changes with the velocity ``q̇ = (linear_velocity,
    /// angular_velocity)``, what an implicit integration of the damping needs.
    ///
    /// Parameters are those of :meth:`damping`. The stiffness is taken about the point ``about``
    /// (default the center of mass): its rows are the force and the torque about that point, its
    /// columns the velocity of that point and the angular velocity.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray, shape (6, 6)
    ///     Symmetric and positive semi-definite, world frame, rows and columns in the order
    ///     ``(vx, vy, vz, ωx, ωy, ωz)``; N·s/m, N·s and N·m·s. The pressure drag's part is
    ///     ``∫ (c₁ + ρ·C_D·u) a aᵀ dA`` over the wetted surface facing the flow, with
    ///     ``a = (n, (p − about) × n)`` and ``u`` the normal velocity there, integrated exactly;
    ///     the angular damping adds ``s·((a₁ + a₂|ω|)·I + a₂·ω ωᵀ/|ω|)``, ``s = f·ρ·V^{5/3}``,
    ///     to the ``ω`` block.
    ///
    /// Examples
    /// --------
    /// The unit cube under water, sinking at 2 m/s: its bottom face (1 m²) feels ``1000·u +
    /// 500·u²`` Pa, so the heave stiffness is ``1000 + 1000·2 = 3000`` N·s/m.
    ///
    /// >>> cube = buoyancy.shapes.cube()
    /// >>> k = cube.damping_stiffness(position=(0, -3, 0), linear_velocity=(0, -2, 0))
    /// >>> k.shape, round(float(k[1, 1]), 9)
    /// ((6, 6), 3000.0)
    #[pyo3(
        signature = (position=None, rotation=None, linear_velocity=None, angular_velocity=None, water=None, coefficients=None, about=None),
        text_signature = "(self, position=(0, 0, 0), rotation=None, linear_velocity=(0, 0, 0), angular_velocity=(0, 0, 0), water=None, coefficients=None, about=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn damping_stiffness<'py>(
        &self,
        py: Python<'py>,
        position: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
        linear_velocity: Option<&Bound<'_, PyAny>>,
        angular_velocity: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyAny>>,
        coefficients: Option<&Bound<'_, PyAny>>,
        about: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let (arguments, about) = DampingArguments::parse(
            position,
            rotation,
            linear_velocity,
            angular_velocity,
            water,
            coefficients,
            about,
        )?;
        let mesh = &self.inner;
        let about = about.map_or_else(|| arguments.pose * mesh.centroid(), Point3::from);
        let k = detach_if_large(py, mesh.triangle_count(), move || {
            let a = &arguments;
            mesh.damping_with_stiffness(
                None,
                &a.pose,
                &a.linear_velocity,
                &a.angular_velocity,
                &a.water,
                &a.coefficients,
            )
            .map(|(_, k)| k.about(&about))
        })
        .map_err(|e| to_py(e, None))?;
        Ok(PyArray2::from_owned_array(
            py,
            numpy::ndarray::Array2::from_shape_fn((6, 6), |(i, j)| k[(i, j)]),
        ))
    }

    /// A copy of the mesh with every vertex mapped by an affine transform, mesh frame:
    /// ``x' = A @ x + b`` for ``matrix = [[A, b], [0, 0, 0, 1]]``.
    ///
    /// Parameters
    /// ----------
    /// matrix : array_like, shape (4, 4)
    ///     The homogeneous matrix, finite, its last row ``[0, 0, 0, 1]``. A mirroring map
    ///     (``det A < 0``) keeps the faces wound outward.
    ///
    /// Returns
    /// -------
    /// Mesh
    ///     Validated and prepared like any new mesh.
    ///
    /// Raises ``ValueError`` naming ``matrix`` if it is not such a matrix, ``MeshError`` if it is
    /// singular (it flattens the mesh).
    ///
    /// Examples
    /// --------
    /// >>> m = np.eye(4)
    /// >>> m[:3, :3] = np.diag([2.0, 0.5, 1.0])  # stretch along x, squash along y
    /// >>> m[:3, 3] = (0, 3, 0)                   # then move up 3 m
    /// >>> slab = buoyancy.shapes.cube().transformed(m)
    /// >>> round(slab.volume, 12), slab.centroid.round(12).tolist()
    /// (1.0, [0.0, 3.0, 0.0])
    #[pyo3(text_signature = "(self, matrix)")]
    fn transformed(&self, py: Python<'_>, matrix: &Bound<'_, PyAny>) -> PyResult<Self> {
        let m = convert::matrix4(matrix, "matrix")?;
        self.mapped(py, &m, "matrix", move |mesh| mesh.transformed(&m))
    }

    /// A copy of the mesh scaled about the origin of the mesh frame.
    ///
    /// Parameters
    /// ----------
    /// factor : float or array_like, shape (3,)
    ///     One factor for all three axes, or one per axis; finite and non-zero. A negative factor
    ///     mirrors the mesh (its faces stay wound outward).
    ///
    /// Returns
    /// -------
    /// Mesh
    ///
    /// Examples
    /// --------
    /// >>> cube = buoyancy.shapes.cube()
    /// >>> round(cube.scaled(2).volume, 12), round(cube.scaled((1, 2, 3)).volume, 12)
    /// (8.0, 6.0)
    #[pyo3(text_signature = "(self, factor)")]
    fn scaled(&self, py: Python<'_>, factor: &Bound<'_, PyAny>) -> PyResult<Self> {
        let factors = scale_factors(factor)?;
        let m = Matrix4::new_nonuniform_scaling(&factors);
        self.mapped(py, &m, "factor", move |mesh| mesh.scaled(&factors))
    }

    /// A copy of the mesh moved by ``offset``, mesh frame, m.
    ///
    /// Parameters
    /// ----------
    /// offset : array_like, shape (3,)
    ///     Finite.
    ///
    /// Returns
    /// -------
    /// Mesh
    ///
    /// Examples
    /// --------
    /// >>> buoyancy.shapes.cube().translated((0, 0.5, 0)).centroid.round(12).tolist()
    /// [0.0, 0.5, 0.0]
    #[pyo3(text_signature = "(self, offset)")]
    fn translated(&self, py: Python<'_>, offset: &Bound<'_, PyAny>) -> PyResult<Self> {
        let offset = convert::vector3(offset, "offset")?;
        let m = Matrix4::new_translation(&offset);
        self.mapped(py, &m, "offset", move |mesh| mesh.translated(&offset))
    }

    /// The waterplane at a pose: the section of the still water plane through the body, its
    /// area, center of flotation and second moments (exact for the mesh: the polygons where the
    /// plane cuts it, holes included).
    ///
    /// Parameters
    /// ----------
    /// position, rotation :
    ///     The pose, as in :meth:`buoyancy`.
    /// water : Water, optional
    ///     Still water (a ``Water`` with waves is a ``ValueError``); default ``Water()``.
    ///
    /// Returns
    /// -------
    /// Waterplane
    ///     World frame; its ``axes[0]`` is the mesh's x axis projected on the plane (its z axis
    ///     when x is within 30° of the vertical).
    ///
    /// Raises ``ValueError`` when the water reaches the rim of an opening closed by
    /// :meth:`close_openings` (its lid is no waterplane).
    ///
    /// Examples
    /// --------
    /// >>> ring = buoyancy.shapes.torus(1.0, 0.25, 64, 32)   # about y, the up axis
    /// >>> round(ring.waterplane().area / (np.pi * (1.25**2 - 0.75**2)), 3)   # an annulus
    /// 0.998
    #[pyo3(
        signature = (position=None, rotation=None, water=None),
        text_signature = "(self, position=(0, 0, 0), rotation=None, water=None)"
    )]
    fn waterplane(
        &self,
        py: Python<'_>,
        position: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyWaterplane> {
        let (water, waves) = PyMesh::water(water)?;
        hydrostatics::still_water(waves)?;
        let pose = PyMesh::pose(position, rotation)?;
        hydrostatics::waterplane(py, self, &pose, &water)
    }

    /// The hydrostatics at a pose: the waterplane, ``KB``, ``KG``, the metacentric radii and
    /// heights about both waterplane axes, and the hydrostatic stiffness in heave, roll and
    /// pitch.
    ///
    /// Parameters
    /// ----------
    /// center_of_mass : array_like, shape (3,)
    ///     ``G``, the center of mass (of gravity), mesh frame, m.
    /// position, rotation :
    ///     The pose, as in :meth:`buoyancy`.
    /// water : Water, optional
    ///     Still water (waves are a ``ValueError``); default ``Water()``.
    /// mass : float, optional
    ///     Kg, positive; default the mass of the water displaced at this pose (the body floats
    ///     freely there).
    /// reference_point : array_like, shape (3,), optional
    ///     The point the stiffness is taken about, mesh frame; default ``G``.
    /// axis : array_like, shape (3,), optional
    ///     The body's fore-and-aft axis, mesh frame, default ``(1, 0, 0)``: roll is about it.
    /// keel : array_like, shape (3,), optional
    ///     The point heights (``KB``, ``KG``) are measured from, mesh frame; default the lowest
    ///     vertex at this pose.
    ///
    /// Returns
    /// -------
    /// Hydrostatics
    ///
    /// Examples
    /// --------
    /// A box 4 m long (x), 1 m deep (y, up), 2 m wide, floating at half its depth:
    ///
    /// >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))
    /// >>> h = box.hydrostatics(center_of_mass=(0, 0, 0))
    /// >>> round(h.bm_transverse, 12) == round(2.0**2 / (12 * 0.5), 12)
    /// True
    #[pyo3(
        signature = (center_of_mass, position=None, rotation=None, water=None, mass=None, reference_point=None, axis=None, keel=None),
        text_signature = "(self, center_of_mass, position=(0, 0, 0), rotation=None, water=None, mass=None, reference_point=None, axis=(1, 0, 0), keel=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn hydrostatics(
        &self,
        py: Python<'_>,
        center_of_mass: &Bound<'_, PyAny>,
        position: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyAny>>,
        mass: Option<&Bound<'_, PyAny>>,
        reference_point: Option<&Bound<'_, PyAny>>,
        axis: Option<&Bound<'_, PyAny>>,
        keel: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyHydrostatics> {
        let (water, waves) = PyMesh::water(water)?;
        hydrostatics::still_water(waves)?;
        let pose = PyMesh::pose(position, rotation)?;
        let loading = hydrostatics::loading(center_of_mass, mass, reference_point, axis, keel)?;
        hydrostatics::hydrostatics(py, self, &pose, &water, &loading)
    }

    /// The hydrostatic stiffness at a pose, shape (3, 3): ``hydrostatics(...).stiffness``,
    /// rows and columns heave, roll, pitch (N/m, N/rad, N·m/m, N·m/rad), about
    /// ``reference_point`` (default ``G``). Arguments as in :meth:`hydrostatics`.
    ///
    /// Examples
    /// --------
    /// >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))
    /// >>> c = box.stiffness(center_of_mass=(0, 0, 0))
    /// >>> round(float(c[0, 0]) / (1000 * 9.81 * 8.0), 12)   # rho g A_wp
    /// 1.0
    #[pyo3(
        signature = (center_of_mass, position=None, rotation=None, water=None, mass=None, reference_point=None, axis=None, keel=None),
        text_signature = "(self, center_of_mass, position=(0, 0, 0), rotation=None, water=None, mass=None, reference_point=None, axis=(1, 0, 0), keel=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn stiffness<'py>(
        &self,
        py: Python<'py>,
        center_of_mass: &Bound<'_, PyAny>,
        position: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyAny>>,
        mass: Option<&Bound<'_, PyAny>>,
        reference_point: Option<&Bound<'_, PyAny>>,
        axis: Option<&Bound<'_, PyAny>>,
        keel: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let h = self.hydrostatics(
            py,
            center_of_mass,
            position,
            rotation,
            water,
            mass,
            reference_point,
            axis,
            keel,
        )?;
        Ok(h.stiffness_array(py))
    }

    /// The stable pose at rest for a mass and center of mass: the draft, heel and trim where
    /// the water displaced weighs what the body weighs and the center of buoyancy lies on the
    /// vertical through the center of mass (Newton on the potential energy, with restarts from
    /// unstable states: a box whose upright is unstable comes to rest heeled at its angle of
    /// loll, a square log of middling density corner-down).
    ///
    /// Parameters
    /// ----------
    /// mass : float
    ///     Kg, positive, less than the water the whole mesh displaces (else a ``ValueError``:
    ///     the body does not float).
    /// center_of_mass : array_like, shape (3,)
    ///     Mesh frame, m.
    /// water : Water, optional
    ///     Still water (waves are a ``ValueError``); default ``Water()``.
    /// rotation : array_like, optional
    ///     The upright orientation heel and trim are measured from (quaternion ``(x, y, z, w)``
    ///     or matrix); default the mesh frame's own. Its yaw is kept.
    /// position : array_like, shape (3,), optional
    ///     Start position: the horizontal position of the center of mass is kept from it;
    ///     default the mesh frame at the world origin.
    /// axis : array_like, shape (3,), optional
    ///     The body's longitudinal axis, mesh frame, default ``(1, 0, 0)``: heel is about it.
    /// keel : array_like, shape (3,), optional
    ///     The point the draft is measured to, mesh frame; default the lowest vertex.
    /// tolerance : float, optional
    ///     Relative tolerance on the residuals, in (0, 0.1); default about 3.7e-11.
    /// max_iterations : int, optional
    ///     Newton iterations allowed, default 100; ``RuntimeError`` when they do not reach the
    ///     tolerance (never a silent return).
    ///
    /// Returns
    /// -------
    /// Equilibrium
    ///
    /// Examples
    /// --------
    /// A square log 1 m across (x along it), half as dense as the water: upright is unstable,
    /// it floats corner-down, heeled 45°:
    ///
    /// >>> log = buoyancy.shapes.cube().scaled((3.0, 1.0, 1.0))
    /// >>> rest = log.equilibrium(mass=1500.0, center_of_mass=(0, 0, 0))
    /// >>> round(abs(rest.heel), 6), rest.stable
    /// (45.0, True)
    #[pyo3(
        signature = (mass, center_of_mass, water=None, rotation=None, position=None, axis=None, keel=None, tolerance=None, max_iterations=None),
        text_signature = "(self, mass, center_of_mass, water=None, rotation=None, position=None, axis=(1, 0, 0), keel=None, tolerance=None, max_iterations=100)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn equilibrium(
        &self,
        py: Python<'_>,
        mass: &Bound<'_, PyAny>,
        center_of_mass: &Bound<'_, PyAny>,
        water: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
        position: Option<&Bound<'_, PyAny>>,
        axis: Option<&Bound<'_, PyAny>>,
        keel: Option<&Bound<'_, PyAny>>,
        tolerance: Option<&Bound<'_, PyAny>>,
        max_iterations: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyEquilibrium> {
        let (water, waves) = PyMesh::water(water)?;
        hydrostatics::still_water(waves)?;
        let loading = stability::loading(mass, center_of_mass, axis, keel)?;
        let options = stability::options(position, rotation, tolerance, max_iterations)?;
        stability::equilibrium(py, self, &water, &loading, &options)
    }

    /// The righting-arm (GZ) curve: at each heel, the body is held at that heel about its
    /// longitudinal axis, its draft solved so that it displaces its mass and its trim solved too
    /// (by continuation from the heel before) or held, and ``GZ``, the lever between the
    /// verticals through the centers of buoyancy and mass, is measured.
    ///
    /// Parameters
    /// ----------
    /// mass, center_of_mass :
    ///     As in :meth:`equilibrium`.
    /// heel_deg : array_like, shape (K,)
    ///     Heel angles, degrees, strictly increasing, from the upright orientation (right-handed
    ///     about ``axis``; see :class:`Equilibrium` for the side that goes down).
    /// axis : array_like, shape (3,), optional
    ///     The body's longitudinal axis, mesh frame, default ``(1, 0, 0)``.
    /// free_trim : bool
    ///     Solve the trim at each heel (default), or hold it at ``trim_deg`` (default 0).
    /// trim_deg : float, optional
    ///     The trim held with ``free_trim=False``, degrees.
    /// water, rotation, position, keel, tolerance, max_iterations :
    ///     As in :meth:`equilibrium`.
    ///
    /// Returns
    /// -------
    /// GzCurve
    ///
    /// Examples
    /// --------
    /// A box 4 m long, 1 m deep and 2 m wide, of 2 t (draft 0.25 m), its center of mass at its
    /// center: wall-sided while the deck edge is dry and the bilge wet (below 14°),
    /// ``GZ = sin φ (GM + BM tan² φ / 2)``.
    ///
    /// >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))
    /// >>> curve = box.gz_curve(2000.0, (0, 0, 0), heel_deg=[0, 4, 8, 12])
    /// >>> kb, bm, kg = 0.125, 2.0**2 / (12 * 0.25), 0.5
    /// >>> phi = np.radians(curve.heel)
    /// >>> wall_sided = np.sin(phi) * (kb + bm - kg + bm * np.tan(phi) ** 2 / 2)
    /// >>> bool(np.allclose(curve.gz, wall_sided, rtol=0, atol=1e-9))
    /// True
    #[pyo3(
        signature = (mass, center_of_mass, heel_deg, axis=None, free_trim=true, trim_deg=None, water=None, rotation=None, position=None, keel=None, tolerance=None, max_iterations=None),
        text_signature = "(self, mass, center_of_mass, heel_deg, axis=(1, 0, 0), free_trim=True, trim_deg=None, water=None, rotation=None, position=None, keel=None, tolerance=None, max_iterations=100)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn gz_curve(
        &self,
        py: Python<'_>,
        mass: &Bound<'_, PyAny>,
        center_of_mass: &Bound<'_, PyAny>,
        heel_deg: &Bound<'_, PyAny>,
        axis: Option<&Bound<'_, PyAny>>,
        free_trim: bool,
        trim_deg: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
        position: Option<&Bound<'_, PyAny>>,
        keel: Option<&Bound<'_, PyAny>>,
        tolerance: Option<&Bound<'_, PyAny>>,
        max_iterations: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyGzCurve> {
        let (water, waves) = PyMesh::water(water)?;
        hydrostatics::still_water(waves)?;
        let loading = stability::loading(mass, center_of_mass, axis, keel)?;
        let options = stability::options(position, rotation, tolerance, max_iterations)?;
        stability::gz_curve(
            py, self, &water, &loading, heel_deg, free_trim, trim_deg, &options,
        )
    }

    /// The hydrostatic table: the body upright at each draft (its keel, the lowest vertex, that
    /// far below the still level), with its displacement, centers, metacentric radii, waterplane,
    /// tonnes per centimetre and moment to change trim.
    ///
    /// Parameters
    /// ----------
    /// drafts : array_like, shape (K,)
    ///     Drafts, m, each between 0 and the body's height.
    /// water : Water, optional
    ///     Still water; default ``Water()``.
    /// rotation : array_like, optional
    ///     The upright orientation, default the mesh frame's own.
    /// axis : array_like, shape (3,), optional
    ///     Mesh frame, default ``(1, 0, 0)``: ``lcb``, ``lcf`` are along it, ``bm_transverse``
    ///     is about it.
    /// center_of_mass : array_like, shape (3,), optional
    ///     Mesh frame: the moment to change trim takes ``GM_L = KB + BM_L - KG`` with it, else
    ///     ``BM_L``.
    /// length : float, optional
    ///     The length of the moment to change trim, m; default the waterline length.
    ///
    /// Returns
    /// -------
    /// HydrostaticTable
    ///
    /// Examples
    /// --------
    /// >>> hull = buoyancy.shapes.wigley_hull()         # 4 m by 0.6 m, design draft 0.25 m
    /// >>> table = hull.hydrostatic_table([0.1, 0.25])
    /// >>> table.waterplane_area.round(2).tolist()      # 2/3 L B = 1.6 m² at the design draft
    /// [1.02, 1.6]
    #[pyo3(
        signature = (drafts, water=None, rotation=None, axis=None, center_of_mass=None, length=None),
        text_signature = "(self, drafts, water=None, rotation=None, axis=(1, 0, 0), center_of_mass=None, length=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn hydrostatic_table(
        &self,
        py: Python<'_>,
        drafts: &Bound<'_, PyAny>,
        water: Option<&Bound<'_, PyAny>>,
        rotation: Option<&Bound<'_, PyAny>>,
        axis: Option<&Bound<'_, PyAny>>,
        center_of_mass: Option<&Bound<'_, PyAny>>,
        length: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyHydrostaticTable> {
        let (water, waves) = PyMesh::water(water)?;
        hydrostatics::still_water(waves)?;
        let options = stability::table_options(rotation, axis, center_of_mass, length)?;
        stability::hydrostatic_table(py, self, &water, drafts, &options)
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

    /// The hash of the vertices (as given) and the faces, consistent with ``==``.
    fn __hash__(&self) -> u64 {
        self.content_hash()
    }

    /// Pickles as the vertices and faces as given: unpickling validates again and gives a
    /// mesh with bit-identical results.
    ///
    /// A hull built by :meth:`close_openings` pickles as its given vertices and faces, closed
    /// again when unpickled.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, MeshArgs<'py>)> {
        let py = slf.py();
        let this = slf.get();
        let (vertices, faces) = (this.vertices(py), this.faces_array(py, true));
        Ok(match this.given {
            None => (slf.get_type().into_any(), (vertices, faces)),
            Some((n_vertices, n_faces)) => {
                let vertices = vertices.call_method1(
                    "__getitem__",
                    (PySlice::new(py, 0, n_vertices as isize, 1),),
                )?;
                let faces = faces
                    .call_method1("__getitem__", (PySlice::new(py, 0, n_faces as isize, 1),))?;
                (
                    slf.get_type().getattr("close_openings")?,
                    (vertices.cast_into()?, faces.cast_into()?),
                )
            }
        })
    }
}
