//! The water plane seen from the mesh frame, for one evaluation.
//!
//! Per evaluation the water plane is brought into the mesh frame, not the mesh into the world:
//! with `R` the pose's rotation, `t` its translation, `c` the mesh centroid and `n` the world up
//! normal,
//!
//! * `n_l = Rᵀ n` is the up normal in the mesh frame,
//! * `w = R c + t` is the center of mass in the world frame,
//! * `h_c = n·w − level` is its height above the surface,
//!
//! and the height of a vertex `x` (stored as `v = x − c`) is `h = n_l·v + h_c`, computed within
//! `4ε·(M + |h_c|)` of its exact value (`M` the size of the mesh about its centroid, see
//! `hierarchy`). The sums are
//! taken on `v` (about the centroid) or on `v + h_c n_l` (about `o = −h_c n_l`, the projection of
//! the centroid on the plane), both small numbers even when the body is 10⁶ m from the world
//! origin, and rotated to the world frame once at the end.

use nalgebra::{Matrix3, Point3, UnitQuaternion, Vector3};

use crate::{Error, Mesh, Pose, Real, Water};

/// The water plane seen from the mesh frame, for one evaluation.
pub(crate) struct Frame<T: Real> {
    pub(crate) rotation: Matrix3<T>,
    /// World up normal.
    pub(crate) normal: Vector3<T>,
    /// Up normal in the mesh frame, `Rᵀ n`.
    pub(crate) normal_local: Vector3<T>,
    /// Center of mass, world frame.
    pub(crate) center_of_mass: Point3<T>,
    /// Height of the center of mass above the surface.
    pub(crate) height: T,
    /// `4ε·(M + |h_c|)`: a bound on the round-off of every vertex height.
    pub(crate) round_off: T,
}

impl<T: Real> Frame<T> {
    pub(crate) fn new(mesh: &Mesh<T>, pose: &Pose<T>, water: &Water<T>) -> Result<Self, Error> {
        let q = pose.rotation.quaternion().coords;
        if !q.iter().all(|c| c.is_finite()) {
            return Err(Error::InvalidPose {
                reason: "the rotation has a NaN or infinite component",
            });
        }
        if !pose.translation.vector.iter().all(|c| c.is_finite()) {
            return Err(Error::InvalidPose {
                reason: "the translation has a NaN or infinite component",
            });
        }
        // Renormalised here, so a quaternion that drifted from unit length still gives a rotation.
        let unit = UnitQuaternion::try_new(pose.rotation.into_inner(), T::zero()).ok_or(
            Error::InvalidPose {
                reason: "the rotation quaternion is zero",
            },
        )?;
        let rotation = *unit.to_rotation_matrix().matrix();
        let normal = water.normal().into_inner();
        let center_of_mass =
            Point3::from(rotation * mesh.centroid.coords) + pose.translation.vector;
        let height = water.height(&center_of_mass);
        Ok(Frame {
            rotation,
            normal,
            normal_local: rotation.transpose() * normal,
            center_of_mass,
            height,
            round_off: mesh.hierarchy.height_round_off(height),
        })
    }

    /// Heights above the surface of vertices given relative to the centroid, mesh frame.
    /// (Written out: `array::map` does not always optimise away in this hot loop.)
    #[inline(always)]
    pub(crate) fn heights(&self, v: &[Vector3<T>; 3]) -> [T; 3] {
        let n = &self.normal_local;
        [
            n.dot(&v[0]) + self.height,
            n.dot(&v[1]) + self.height,
            n.dot(&v[2]) + self.height,
        ]
    }

    /// For a body whose bounding sphere lies wholly under the plane, the same frame with the
    /// centroid two bounding radii under it; else itself. Every method then finds the body
    /// submerged all over, as it is, and its sums lose no digits to the depth: a constant added
    /// to the pressure changes neither the force nor the torque on a closed surface
    /// (`∮ n dA = 0`, `∮ r × n dA = 0`, which the methods' rules integrate exactly), and the
    /// submerged volume is the whole body. (Kept deep, the surface methods put a 1 m cube 10⁹ m
    /// down with its center of buoyancy 82 m off.)
    pub(crate) fn nearer_when_submerged(self, mesh: &Mesh<T>) -> Self {
        let radius = mesh.bounding_radius;
        let near = -(radius + radius);
        if self.height + radius < T::zero() && self.height < near {
            Frame {
                height: near,
                round_off: mesh.hierarchy.height_round_off(near),
                ..self
            }
        } else {
            self
        }
    }

    /// The projection of the center of mass onto the surface, world frame.
    pub(crate) fn surface_point(&self) -> Point3<T> {
        self.center_of_mass - self.normal * self.height
    }
}
