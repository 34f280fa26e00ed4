//! Collider shapes to closed triangle meshes, once, at registration.

use std::collections::HashMap;
use std::hash::{DefaultHasher, Hash, Hasher};
use std::sync::Arc;

use buoyancy_core::controller::Part;
use buoyancy_core::nalgebra::Point3;
use buoyancy_core::{Mesh, Pose};
use rapier3d::parry::shape::{SharedShape, TypedShape};
use rapier3d::prelude::ColliderHandle;

use crate::Error;
use crate::convert::{pose_to_nalgebra, vector_to_nalgebra};

/// The meshes made so far, one per rapier shape (a `SharedShape`, told apart by the address of
/// its data) and number of subdivisions, so that bodies whose colliders share a shape share
/// one mesh. Each entry holds the shape too, so that its address stays its own. Shapes of their
/// own that give the same triangles (a ball of the same radius built for each body) share one
/// mesh too: the meshes are also found by their vertices and triangles.
#[derive(Clone, Default)]
pub(crate) struct MeshCache {
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

impl MeshCache {
    /// Forgets the meshes of shapes no collider holds any more (only the cache does) and that
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

impl std::fmt::Debug for MeshCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MeshCache")
            .field("meshes", &self.entries.len())
            .finish()
    }
}

/// Appends the meshes of `shape` (placed on the body by `shape_to_body`) to `parts`, made once
/// per shape and number of subdivisions (see [`MeshCache`]).
///
/// Trimeshes are used as they are; cuboids and convex polyhedra exactly; balls, cylinders,
/// capsules and cones with `subdivisions` segments around (and half as many from pole to pole);
/// compounds part by part.
pub(crate) fn append_meshes(
    collider: ColliderHandle,
    shared: &SharedShape,
    shape_to_body: Pose<f64>,
    subdivisions: u32,
    cache: &mut MeshCache,
    parts: &mut Vec<Part>,
) -> Result<(), Error> {
    let shape = shared.as_ref();
    let key = (Arc::as_ptr(&shared.0) as *const () as usize, subdivisions);
    if let Some((_, mesh)) = cache.entries.get(&key) {
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
                append_meshes(
                    collider,
                    sub,
                    shape_to_body * pose_to_nalgebra(pose),
                    subdivisions,
                    cache,
                    parts,
                )?;
            }
            return Ok(());
        }
        _ => {
            return Err(Error::UnsupportedShape {
                collider,
                shape: format!("{:?}", shape.shape_type()),
            });
        }
    };
    let points: Vec<Point3<f64>> = vertices
        .iter()
        .map(|v| Point3::from(vector_to_nalgebra(*v)))
        .collect();
    let mut triangles = triangles;
    if weld {
        buoyancy_core::shape::weld(&points, &mut triangles);
    }
    let mesh = cache
        .mesh(points, triangles)
        .map_err(|source| Error::Mesh { collider, source })?;
    cache.entries.insert(key, (shared.clone(), mesh.clone()));
    parts.push(Part {
        mesh,
        shape_to_body,
    });
    Ok(())
}

fn with_weld<V>((v, t): (Vec<V>, Vec<[u32; 3]>)) -> (Vec<V>, Vec<[u32; 3]>, bool) {
    (v, t, true)
}
