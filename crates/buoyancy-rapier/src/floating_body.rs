//! One registered body: its meshes, options, the adapter's share of its force, and what was
//! computed for it last.

use rapier3d::prelude::{ColliderHandle, ColliderSet, RigidBodyHandle, RigidBodySet};

use crate::applied_share::AppliedShare;
use crate::convert::pose_to_nalgebra;
use crate::evaluation::Evaluation;
use crate::shapes::{FloatingPart, append_meshes};
use crate::{Error, FloatOptions, FloatReport, FloatingColliders};

/// One registered body.
#[derive(Debug, Clone)]
pub(crate) struct FloatingBody {
    pub handle: RigidBodyHandle,
    /// One closed mesh per (sub-)shape of its floating colliders, with its place on the body.
    pub parts: Vec<FloatingPart>,
    pub options: FloatOptions,
    /// Total volume (m³) and surface area (m²) of the parts, for the body's angular damping.
    pub volume: f64,
    pub surface_area: f64,
    pub share: AppliedShare,
    /// What the last `apply` computed ([`Evaluation::Inactive`], nothing to hold, until the
    /// first), and what it reported.
    pub evaluation: Evaluation,
    pub report: FloatReport,
}

impl FloatingBody {
    /// Meshes the colliders of `body` that `options` selects (see [`FloatOptions::colliders`]);
    /// nothing applied yet.
    pub fn new(
        body: RigidBodyHandle,
        bodies: &RigidBodySet,
        colliders: &ColliderSet,
        options: FloatOptions,
    ) -> Result<Self, Error> {
        let parts = mesh_colliders(body, bodies, colliders, &options)?;
        let volume = parts.iter().map(|p| p.mesh.volume()).sum();
        let surface_area = parts.iter().map(|p| p.mesh.surface_area()).sum();
        Ok(FloatingBody {
            handle: body,
            parts,
            options,
            volume,
            surface_area,
            share: AppliedShare::default(),
            evaluation: Evaluation::Inactive,
            report: FloatReport::default(),
        })
    }

    /// The body's length scale, m: the cube root of its volume.
    pub fn size(&self) -> f64 {
        self.volume.max(0.0).cbrt()
    }
}

/// The meshes of the colliders of `body` that `options` selects, each listed once.
fn mesh_colliders(
    body: RigidBodyHandle,
    bodies: &RigidBodySet,
    colliders: &ColliderSet,
    options: &FloatOptions,
) -> Result<Vec<FloatingPart>, Error> {
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
        append_meshes(
            handle,
            collider.shape(),
            shape_to_body,
            options.subdivisions,
            &mut parts,
        )?;
    }
    if parts.is_empty() {
        return Err(Error::NothingToFloat(body));
    }
    Ok(parts)
}
