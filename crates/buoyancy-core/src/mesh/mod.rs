//! The closed triangle mesh a body is made of, and what is built once with it.
//!
//! * [`Mesh`]: the mesh, validated when it is built ([`Mesh::new`]; the defects it refuses are
//!   [`MeshDefects`]), its volume, centroid and extent; open hulls closed by flat lids
//!   ([`Mesh::close_openings`], [`Opening`]).
//! * What every evaluation reads and [`Mesh::new`] prepares: a bounding-volume hierarchy of its
//!   triangles (`hierarchy`), the closed-form sums of each node's triangles (`node_sums`) and
//!   the per-vertex coefficients of the pressure under waves.
//! * [`ReducedMesh`]: a coarse copy for the pressure drag of the damping model.
//! * [`primitives`]: procedural meshes (cube, sphere, torus, torus knot, Wigley hull) and the
//!   primitives of physics engines (cuboid, ellipsoid, cylinder, capsule).
//!
//! A mesh lives in its own *mesh frame*; a [`Pose`](crate::Pose) places it in the world.

pub(crate) mod hierarchy;
#[allow(clippy::module_inception)]
mod mesh;
pub(crate) mod node_sums;
mod openings;
pub mod primitives;
mod reduced_mesh;
pub(crate) mod validation;

pub use mesh::Mesh;
pub(crate) use mesh::TriangleNormal;
pub use openings::Opening;
pub use reduced_mesh::{MIN_REDUCED_TRIANGLES, ReducedMesh};
pub use validation::{Culprit, Defect, DefectKind, MeshDefects};
