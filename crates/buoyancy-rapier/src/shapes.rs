//! Parry shapes to closed triangle meshes, once, at registration: the meshing every adapter
//! whose engine speaks parry shares (this crate's colliders, and avian's, whose `Collider`
//! holds a parry `SharedShape` of the same parry version).

use std::collections::HashMap;
use std::hash::{DefaultHasher, Hash, Hasher};
use std::sync::Arc;

use buoyancy_core::controller::Part;
use buoyancy_core::nalgebra::Point3;
use buoyancy_core::{Mesh, Pose};
use rapier3d::parry::shape::{SharedShape, TypedShape};

use crate::convert::{pose_to_nalgebra, vector_to_nalgebra};

/// Closed meshes of parry shapes ([`ShapeMeshes::append`]), made once: one per shape (a
/// `SharedShape`, told apart by the address of its data) and number of subdivisions, so that
/// bodies whose colliders share a shape share one mesh. Each entry holds the shape too, so that its address stays its own. Shapes of their
/// own that give the same triangles (a ball of the same radius built for each body) share one
/// mesh too: the meshes are also found by their vertices and triangles.
#[derive(Clone, Default)]
pub struct ShapeMeshes {
    entries: HashMap<MeshKey, (SharedShape, Arc<Mesh<f64>>)>,
    /// The meshes by the hash of the vertices and triangles they were made of, with those.
    by_content: HashMap<u64, Vec<MadeOf>>,
}

/// The address of a shape's data and a number of subdivisions.
type MeshKey = (usize, u32);

/// A mesh, and the vertices and triangles it was made of (before any reorientation).
#[derive(Clone)]
struct MadeOf {
    points: Vec<Point3<f64>>,
    triangles: Vec<[u32; 3]>,
    mesh: Arc<Mesh<f64>>,
}

impl ShapeMeshes {
    /// Forgets the meshes of shapes nothing else holds any more (only these meshes do) and that
    /// no body floats with.
    pub fn prune(&mut self) {
        // The holders of each mesh within the cache: its content entry and its shape entries;
        // any other holder is a body.
        let mut held: HashMap<*const Mesh<f64>, usize> = HashMap::new();
        for (_, mesh) in self.entries.values() {
            *held.entry(Arc::as_ptr(mesh)).or_insert(1) += 1;
        }
        let gone: Vec<MeshKey> = self
            .entries
            .iter()
            .filter(|(_, (shape, mesh))| {
                Arc::strong_count(&shape.0) == 1
                    && Arc::strong_count(mesh) <= held[&Arc::as_ptr(mesh)]
            })
            .map(|(key, _)| *key)
            .collect();
        for key in gone {
            self.entries.remove(&key);
        }
        // A mesh no shape entry and no body holds any more: its content entry alone.
        for meshes in self.by_content.values_mut() {
            meshes.retain(|made| Arc::strong_count(&made.mesh) > 1);
        }
        self.by_content.retain(|_, meshes| !meshes.is_empty());
    }

    /// The mesh of `points` and `triangles` made already, or a new one (remembered).
    fn mesh(
        &mut self,
        points: Vec<Point3<f64>>,
        triangles: Vec<[u32; 3]>,
    ) -> Result<Arc<Mesh<f64>>, buoyancy_core::Error> {
        let mut hasher = DefaultHasher::new();
        for p in &points {
            // `+ 0.0` makes -0.0 hash as 0.0, which it equals.
            [p.x + 0.0, p.y + 0.0, p.z + 0.0]
                .map(f64::to_bits)
                .hash(&mut hasher);
        }
        triangles.hash(&mut hasher);
        let held = self.by_content.entry(hasher.finish()).or_default();
        if let Some(made) = held
            .iter()
            .find(|made| made.points == points && made.triangles == triangles)
        {
            return Ok(made.mesh.clone());
        }
        let mesh = Arc::new(Mesh::new(points.clone(), triangles.clone())?);
        held.push(MadeOf {
            points,
            triangles,
            mesh: mesh.clone(),
        });
        Ok(mesh)
    }
}

impl std::fmt::Debug for ShapeMeshes {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ShapeMeshes")
            .field("meshes", &self.entries.len())
            .finish()
    }
}

/// Why a parry shape could not become meshes.
#[derive(Debug, Clone, PartialEq)]
pub enum ShapeError {
    /// The shape cannot be turned into a closed triangle mesh (a half-space, a heightfield, a
    /// polyline, a segment, a triangle, voxels, a rounded shape, a custom shape): parry's name
    /// of its type.
    Unsupported(String),
    /// Its triangle mesh is not a closed, consistently oriented manifold (an open trimesh).
    Mesh(buoyancy_core::Error),
}

impl std::fmt::Display for ShapeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ShapeError::Unsupported(shape) => write!(
                f,
                "a {shape} cannot be turned into a closed triangle mesh (cuboids, balls, \
                 capsules, cylinders, cones, convex polyhedra, closed trimeshes and compounds of \
                 them can)"
            ),
            ShapeError::Mesh(e) => write!(f, "its triangle mesh cannot float: {e}"),
        }
    }
}

impl std::error::Error for ShapeError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ShapeError::Mesh(e) => Some(e),
            ShapeError::Unsupported(_) => None,
        }
    }
}

impl ShapeMeshes {
    /// Appends the meshes of `shape` (placed on the body by `shape_to_body`) to `parts`, made
    /// once per shape and number of subdivisions.
    ///
    /// Trimeshes are used as they are; cuboids and convex polyhedra exactly; balls, cylinders,
    /// capsules and cones with `subdivisions` segments around (and half as many from pole to
    /// pole, even), their seams welded ([`buoyancy_core::mesh::primitives::weld`]); compounds part by
    /// part. Nothing is appended on an error.
    pub fn append(
        &mut self,
        shape: &SharedShape,
        shape_to_body: Pose<f64>,
        subdivisions: u32,
        parts: &mut Vec<Part>,
    ) -> Result<(), ShapeError> {
        let before = parts.len();
        let result = self.append_all(shape, shape_to_body, subdivisions, parts);
        if result.is_err() {
            parts.truncate(before);
        }
        result
    }

    fn append_all(
        &mut self,
        shared: &SharedShape,
        shape_to_body: Pose<f64>,
        subdivisions: u32,
        parts: &mut Vec<Part>,
    ) -> Result<(), ShapeError> {
        let shape = shared.as_ref();
        let key = (Arc::as_ptr(&shared.0) as *const () as usize, subdivisions);
        if let Some((_, mesh)) = self.entries.get(&key) {
            parts.push(Part {
                mesh: mesh.clone(),
                shape_to_body,
            });
            return Ok(());
        }
        let around = subdivisions.max(3);
        // Pole to pole; even so that a capsule's two hemispheres have whole rings.
        let pole_to_pole = (subdivisions / 2).max(2).next_multiple_of(2);
        let (vertices, triangles, weld) = match shape.as_typed_shape() {
            TypedShape::TriMesh(m) => (m.vertices().to_vec(), m.indices().to_vec(), false),
            TypedShape::Cuboid(c) => with_weld(c.to_trimesh()),
            TypedShape::Ball(b) => with_weld(b.to_trimesh(around, pole_to_pole)),
            TypedShape::Cylinder(c) => with_weld(c.to_trimesh(around)),
            TypedShape::Capsule(c) => with_weld(c.to_trimesh(around, pole_to_pole)),
            TypedShape::Cone(c) => with_weld(c.to_trimesh(around)),
            TypedShape::ConvexPolyhedron(c) => with_weld(c.to_trimesh()),
            TypedShape::Compound(c) => {
                for (pose, sub) in c.shapes() {
                    self.append_all(
                        sub,
                        shape_to_body * pose_to_nalgebra(pose),
                        subdivisions,
                        parts,
                    )?;
                }
                return Ok(());
            }
            _ => return Err(ShapeError::Unsupported(format!("{:?}", shape.shape_type()))),
        };
        let points: Vec<Point3<f64>> = vertices
            .iter()
            .map(|v| Point3::from(vector_to_nalgebra(*v)))
            .collect();
        let mut triangles = triangles;
        if weld {
            buoyancy_core::mesh::primitives::weld(&points, &mut triangles);
        }
        let mesh = self.mesh(points, triangles).map_err(ShapeError::Mesh)?;
        self.entries.insert(key, (shared.clone(), mesh.clone()));
        parts.push(Part {
            mesh,
            shape_to_body,
        });
        Ok(())
    }
}

fn with_weld<V>((v, t): (Vec<V>, Vec<[u32; 3]>)) -> (Vec<V>, Vec<[u32; 3]>, bool) {
    (v, t, true)
}
