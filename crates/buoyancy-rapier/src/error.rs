use core::fmt;

use rapier3d::math::Vector;
use rapier3d::prelude::{ColliderHandle, RigidBodyHandle};

/// Everything that can go wrong when creating [`FloatingBodies`](crate::FloatingBodies) or
/// registering a body with it.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// The gravity given to [`FloatingBodies::new`](crate::FloatingBodies::new) has a NaN or
    /// infinite component.
    InvalidGravity(Vector),
    /// The rigid body handle is not in the `RigidBodySet`.
    UnknownBody(RigidBodyHandle),
    /// The collider handle is not in the `ColliderSet`.
    UnknownCollider(ColliderHandle),
    /// The collider is not attached to the body being registered.
    NotAttached {
        /// The collider.
        collider: ColliderHandle,
        /// The body it was expected on.
        body: RigidBodyHandle,
    },
    /// The body has no collider to float (none attached, or an empty selection).
    NothingToFloat(RigidBodyHandle),
    /// The collider's shape cannot be turned into a closed triangle mesh (a half-space, a
    /// heightfield, a polyline, a segment, a triangle, voxels, a rounded shape, a custom shape).
    UnsupportedShape {
        /// The collider.
        collider: ColliderHandle,
        /// The shape's type, as parry names it.
        shape: String,
    },
    /// The collider's triangle mesh is not a closed, consistently oriented manifold, or another
    /// error of the core.
    Mesh {
        /// The collider.
        collider: ColliderHandle,
        /// What the core found.
        source: buoyancy_core::Error,
    },
    /// A setting was rejected by the core (a water or damping parameter out of range).
    Core(buoyancy_core::Error),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::InvalidGravity(g) => write!(
                f,
                "gravity ({}, {}, {}) m/s² has a NaN or infinite component: pass the world's \
                 finite gravity vector (e.g. PhysicsWorld::gravity, (0, −9.81, 0))",
                g.x, g.y, g.z
            ),
            Error::UnknownBody(h) => write!(f, "rigid body {h:?} is not in the RigidBodySet"),
            Error::UnknownCollider(h) => write!(f, "collider {h:?} is not in the ColliderSet"),
            Error::NotAttached { collider, body } => {
                write!(
                    f,
                    "collider {collider:?} is not attached to rigid body {body:?}"
                )
            }
            Error::NothingToFloat(h) => write!(
                f,
                "rigid body {h:?} has no collider to float: attach one, or select at least one"
            ),
            Error::UnsupportedShape { collider, shape } => write!(
                f,
                "collider {collider:?} has a {shape} shape, which encloses no volume buoyancy can use; \
                 supported: trimesh, cuboid, ball, cylinder, capsule, cone, convex polyhedron, compound"
            ),
            Error::Mesh { collider, source } => {
                write!(f, "collider {collider:?} cannot float: {source}")
            }
            Error::Core(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Mesh { source, .. } | Error::Core(source) => Some(source),
            _ => None,
        }
    }
}

impl From<buoyancy_core::Error> for Error {
    fn from(e: buoyancy_core::Error) -> Self {
        Error::Core(e)
    }
}
