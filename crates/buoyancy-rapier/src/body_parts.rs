//! A registered body's colliders turned into the controller's parts, once.

use buoyancy_core::controller::Part;
use rapier3d::prelude::{ColliderHandle, ColliderSet, RigidBodyHandle, RigidBodySet};

use crate::convert::pose_to_nalgebra;
use crate::shapes::{ShapeError, ShapeMeshes};
use crate::{Error, FloatOptions, FloatingColliders};

/// The meshes of the colliders of `body` that `options` selects, each listed once.
pub(crate) fn mesh_colliders(
    body: RigidBodyHandle,
    bodies: &RigidBodySet,
    colliders: &ColliderSet,
    options: &FloatOptions,
    cache: &mut ShapeMeshes,
) -> Result<Vec<Part>, Error> {
    let rigid_body = bodies.get(body).ok_or(Error::UnknownBody(body))?;
    let selected: Vec<ColliderHandle> = match &options.colliders {
        FloatingColliders::All => rigid_body.colliders().to_vec(),
        FloatingColliders::Only(list) => {
            let mut unique = Vec::with_capacity(list.len());
            for &handle in list {
                if !unique.contains(&handle) {
                    unique.push(handle);
                }
            }
            unique
        }
    };
    let mut parts = Vec::new();
    for handle in selected {
        let collider = colliders
            .get(handle)
            .ok_or(Error::UnknownCollider(handle))?;
        let shape_to_body = match (collider.parent(), collider.position_wrt_parent()) {
            (Some(parent), Some(pose)) if parent == body => pose_to_nalgebra(pose),
            _ => {
                return Err(Error::NotAttached {
                    collider: handle,
                    body,
                });
            }
        };
        cache
            .append(
                collider.shared_shape(),
                shape_to_body,
                options.subdivisions,
                &mut parts,
            )
            .map_err(|e| match e {
                ShapeError::Unsupported(shape) => Error::UnsupportedShape {
                    collider: handle,
                    shape,
                },
                ShapeError::Mesh(source) => Error::Mesh {
                    collider: handle,
                    source,
                },
            })?;
    }
    if parts.is_empty() {
        return Err(Error::NothingToFloat(body));
    }
    Ok(parts)
}
