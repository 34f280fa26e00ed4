//! The pressure drag integrated over the wetted surface: [`Mesh::damping`] and its variants.

use nalgebra::{Matrix3, Matrix6, Vector3};

use super::stiffness::DragStiffness;
use super::{
    Damping, DampingCoefficients, DampingStiffness, add_block, angular_damping,
    angular_damping_stiffness,
};
use crate::mesh::ReducedMesh;
use crate::mesh::TriangleNormal;
use crate::mesh::hierarchy::Visit;
use crate::query::clip::clip_below;
use crate::query::frame::Frame;
use crate::{Error, Mesh, Pose, Real, Water};

/// The pressure drag of the model, summed over wetted triangles: the body's velocity and the
/// coefficients, and the running sums, all in the mesh frame, about the centroid; with
/// `STIFFNESS`, its stiffness too (a parameter of the type, so that the drag alone carries no
/// test of it in its hot loop).
struct Drag<T: Real, const STIFFNESS: bool> {
    /// Velocity of the centroid relative to the water, and angular velocity.
    velocity: Vector3<T>,
    omega: Vector3<T>,
    /// `c₁` and `½·ρ·C_D`.
    linear: T,
    quadratic: T,
    force: Vector3<T>,
    torque: Vector3<T>,
    /// Twice the wetted area.
    double_area: T,
    /// The stiffness (zero unless `STIFFNESS`).
    stiffness: DragStiffness<T>,
}

impl<T: Real, const STIFFNESS: bool> Drag<T, STIFFNESS> {
    /// Adds the wetted triangle `p` (corners relative to the centroid) of outward unit normal
    /// `normal` and twice the area `double_area`: its area, and the drag on the part of it facing the
    /// flow. A triangle of zero area adds nothing.
    #[inline(always)]
    fn wetted(&mut self, p: [Vector3<T>; 3], normal: &Vector3<T>, double_area: T) {
        let zero = T::zero();
        if double_area <= zero {
            return;
        }
        self.double_area += double_area;
        // u_n(p) = n̂·(v + ω × p) = n̂·v + (n̂ × ω)·p.
        let (base, slope) = (normal.dot(&self.velocity), normal.cross(&self.omega));
        let un = [
            base + slope.dot(&p[0]),
            base + slope.dot(&p[1]),
            base + slope.dot(&p[2]),
        ];
        if un[0] <= zero && un[1] <= zero && un[2] <= zero {
            return;
        }
        let half = T::from_f64_lossy(0.5);
        if un[0] >= zero && un[1] >= zero && un[2] >= zero {
            self.facing(p, un, normal, double_area * half);
        } else {
            // Keep the part where u_n > 0: "under" the level set −u_n = 0.
            clip_below(p, [-un[0], -un[1], -un[2]], |q, minus_u| {
                // The piece lies in the triangle's plane: its area is along `normal`.
                let area = normal.dot(&(q[1] - q[0]).cross(&(q[2] - q[0]))) * half;
                self.facing(q, [-minus_u[0], -minus_u[1], -minus_u[2]], normal, area);
            });
        }
    }

    /// Adds the drag on a flat piece `q` of unit normal `normal` and area `area` where the
    /// normal velocity, `u` at the corners, is non-negative.
    #[inline(always)]
    fn facing(&mut self, q: [Vector3<T>; 3], u: [T; 3], normal: &Vector3<T>, area: T) {
        let (third, twelfth, sixtieth) = (
            T::from_f64_lossy(1.0 / 3.0),
            T::from_f64_lossy(1.0 / 12.0),
            T::from_f64_lossy(1.0 / 60.0),
        );
        let sum_u = u[0] + u[1] + u[2];
        let sum_u2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
        let sum_q = q[0] + q[1] + q[2];
        let sum_uq = q[0] * u[0] + q[1] * u[1] + q[2] * u[2];
        let sum_u2q = q[0] * (u[0] * u[0]) + q[1] * (u[1] * u[1]) + q[2] * (u[2] * u[2]);
        // ∫u, ∫u², ∫u·p, ∫u²·p over the piece.
        let int_u = area * sum_u * third;
        let int_u2 = area * (sum_u2 + sum_u * sum_u) * twelfth;
        let int_uq = (sum_uq + sum_q * sum_u) * (area * twelfth);
        let int_u2q = (sum_q * (sum_u * sum_u + sum_u2)
            + sum_uq * (sum_u + sum_u)
            + sum_u2q * T::from_f64_lossy(2.0))
            * (area * sixtieth);
        let pressure = int_u * self.linear + int_u2 * self.quadratic;
        let moment = int_uq * self.linear + int_u2q * self.quadratic;
        self.force -= normal * pressure;
        // −∫ p × P n̂ dA = n̂ × ∫ P p dA
        self.torque += normal.cross(&moment);
        if STIFFNESS {
            self.stiffness
                .add_piece(&q, &u, normal, area, self.linear, self.quadratic);
        }
    }
}

impl<T: Real, const STIFFNESS: bool> Drag<T, STIFFNESS> {
    /// No triangle yet: the velocity of the centroid relative to the water (`linear_velocity`
    /// minus the current) and `angular_velocity`, world frame, brought into the mesh frame by
    /// the transpose of `rotation` (mesh → world).
    fn new(
        rotation: &Matrix3<T>,
        linear_velocity: &Vector3<T>,
        angular_velocity: &Vector3<T>,
        water: &Water<T>,
        coefficients: &DampingCoefficients<T>,
    ) -> Self {
        let rotation_t = rotation.transpose();
        Drag {
            velocity: rotation_t * (linear_velocity - coefficients.current()),
            omega: rotation_t * angular_velocity,
            linear: coefficients.linear_drag(),
            quadratic: T::from_f64_lossy(0.5) * water.density() * coefficients.drag_coefficient(),
            force: Vector3::zeros(),
            torque: Vector3::zeros(),
            double_area: T::zero(),
            stiffness: DragStiffness::zero(),
        }
    }

    /// Adds the triangle of corners `v` (relative to the centroid) at heights `h` above the
    /// surface, of outward unit normal `normal` and twice the area `double_area`: nothing if it
    /// is dry (a triangle lying in the surface, or touching it from above, is), all of it if
    /// it is under water, else its parts under water.
    #[inline(always)]
    fn in_water(&mut self, v: [Vector3<T>; 3], h: [T; 3], normal: &Vector3<T>, double_area: T) {
        let zero = T::zero();
        if !(h[0] < zero || h[1] < zero || h[2] < zero) {
            return;
        }
        if h[0] <= zero && h[1] <= zero && h[2] <= zero {
            self.wetted(v, normal, double_area);
        } else {
            // The pieces lie in the triangle's plane: their area is along its normal.
            clip_below(v, h, |p, _| {
                self.wetted(p, normal, normal.dot(&(p[1] - p[0]).cross(&(p[2] - p[0]))))
            });
        }
    }
}

impl<T: Real> Mesh<T> {
    /// The hydrodynamic damping of this mesh placed by `pose` (mesh → world) in `water`, moving
    /// with `linear_velocity` (of its center of mass, world frame, m/s) and `angular_velocity`
    /// (world frame, rad/s), by the model of the [`damping`](crate::damping) module.
    ///
    /// Walks the mesh's hierarchy, so dry parts cost nothing and submerged parts are not
    /// classified triangle by triangle; every wetted triangle is integrated. No allocation.
    /// With [`DampingCoefficients::off`] it returns zero at once.
    ///
    /// # Errors
    /// [`Error::InvalidPose`] for a non-finite pose; [`Error::InvalidVelocity`] for a non-finite
    /// velocity; [`Error::NonFiniteResult`] if the result overflows.
    pub fn damping(
        &self,
        pose: &Pose<T>,
        linear_velocity: &Vector3<T>,
        angular_velocity: &Vector3<T>,
        water: &Water<T>,
        coefficients: &DampingCoefficients<T>,
    ) -> Result<Damping<T>, Error> {
        let motion = (linear_velocity, angular_velocity);
        self.damping_over::<false>(None, pose, motion, water, coefficients)
            .map(|(damping, _)| damping)
    }

    /// The damping of this mesh as [`Mesh::damping`] gives it, with the pressure drag
    /// integrated over `reduced`, a coarse copy of this mesh's surface (see
    /// [`ReducedMesh`]), built from this mesh: the same model and frame, the torque about this
    /// mesh's centroid, every triangle of `reduced` examined (no hierarchy: it is small). The
    /// wetted area is the reduced surface's times [`ReducedMesh::area_scale`], so that the
    /// wetted fraction `f` and the angular damping are this mesh's up to the reduction. No
    /// allocation.
    ///
    /// # Errors
    /// As [`Mesh::damping`].
    pub fn reduced_damping(
        &self,
        reduced: &ReducedMesh<T>,
        pose: &Pose<T>,
        linear_velocity: &Vector3<T>,
        angular_velocity: &Vector3<T>,
        water: &Water<T>,
        coefficients: &DampingCoefficients<T>,
    ) -> Result<Damping<T>, Error> {
        let motion = (linear_velocity, angular_velocity);
        self.damping_over::<false>(Some(reduced), pose, motion, water, coefficients)
            .map(|(damping, _)| damping)
    }

    /// The damping of [`Mesh::damping`] (or of [`Mesh::reduced_damping`] over `reduced`) and
    /// its stiffness `K = −∂W/∂q̇` (see [`DampingStiffness`]), summed in the same pass: what an
    /// engine needs to integrate a stiff damping implicitly. The stiffness costs about as much
    /// again as the damping over the pieces facing the flow. No allocation.
    ///
    /// ```
    /// use buoyancy_core::{DampingCoefficients, Mesh, Pose, Water, mesh::primitives};
    /// use nalgebra::{Translation3, UnitQuaternion, Vector3};
    ///
    /// let (vertices, triangles) = primitives::cube::<f64>(1)?;
    /// let cube = Mesh::new(vertices, triangles)?;
    /// let under = Pose::from_parts(Translation3::new(0.0, -3.0, 0.0), UnitQuaternion::identity());
    /// // Sinking at 1 m/s: the bottom face (1 m²) alone faces the flow, u = 1 m/s all over it,
    /// // so the heave stiffness is ∫(c₁ + ρC_D·u) dA = 1000 + 1000·1·1 N·s/m.
    /// let (damping, stiffness) = cube.damping_with_stiffness(
    ///     None,
    ///     &under,
    ///     &Vector3::new(0.0, -1.0, 0.0),
    ///     &Vector3::zeros(),
    ///     &Water::default(),
    ///     &DampingCoefficients::default(),
    /// )?;
    /// assert!((stiffness.drag[(1, 1)] - 2000.0).abs() < 1e-9);
    /// assert!((damping.force.y - 1500.0).abs() < 1e-9);
    /// # Ok::<(), buoyancy_core::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Mesh::damping`].
    pub fn damping_with_stiffness(
        &self,
        reduced: Option<&ReducedMesh<T>>,
        pose: &Pose<T>,
        linear_velocity: &Vector3<T>,
        angular_velocity: &Vector3<T>,
        water: &Water<T>,
        coefficients: &DampingCoefficients<T>,
    ) -> Result<(Damping<T>, DampingStiffness<T>), Error> {
        let motion = (linear_velocity, angular_velocity);
        let (damping, stiffness) =
            self.damping_over::<true>(reduced, pose, motion, water, coefficients)?;
        Ok((
            damping,
            stiffness.unwrap_or(DampingStiffness {
                drag: Matrix6::zeros(),
                angular: Matrix3::zeros(),
                torque_point: damping.torque_point,
            }),
        ))
    }

    /// Adds the pressure drag over this mesh's wetted triangles to `drag`, or over `reduced`'s
    /// triangles: the hierarchy skips the dry nodes and hands over the submerged ones whole, so
    /// only the triangles near the waterline are classified; the drag itself is not linear in
    /// the velocity over a node (only the part facing the flow counts), so every wetted
    /// triangle is still integrated. A reduced copy is small: every triangle is examined.
    fn integrate_drag<const STIFFNESS: bool>(
        &self,
        reduced: Option<&ReducedMesh<T>>,
        frame: &Frame<T>,
        drag: &mut Drag<T, STIFFNESS>,
    ) {
        if let Some(reduced) = reduced {
            for (i, normal) in reduced.normals.iter().enumerate() {
                let v = reduced.corners(i);
                drag.in_water(v, frame.heights(&v), &normal.unit, normal.double_area);
            }
            return;
        }
        self.hierarchy
            .walk(&frame.normal_local, frame.height, |visit| match visit {
                Visit::SubmergedNode { node, .. } => {
                    for i in self.hierarchy.range(node) {
                        let normal = &self.normals[i];
                        drag.wetted(self.corners(i), &normal.unit, normal.double_area);
                    }
                }
                Visit::CrossedLeaf { triangles } => {
                    for i in triangles {
                        let v = self.corners(i);
                        let TriangleNormal { unit, double_area } = &self.normals[i];
                        drag.in_water(v, frame.heights(&v), unit, *double_area);
                    }
                }
            });
    }

    /// The damping with the pressure drag summed over this mesh or `reduced` (its wetted area
    /// scaled by [`ReducedMesh::area_scale`]), and with `STIFFNESS` its stiffness: the
    /// checks, the early returns and the angular damping of [`Mesh::damping`]. The stiffness
    /// is `None` where the damping returns early.
    fn damping_over<const STIFFNESS: bool>(
        &self,
        reduced: Option<&ReducedMesh<T>>,
        pose: &Pose<T>,
        (linear_velocity, angular_velocity): (&Vector3<T>, &Vector3<T>),
        water: &Water<T>,
        coefficients: &DampingCoefficients<T>,
    ) -> Result<(Damping<T>, Option<DampingStiffness<T>>), Error> {
        let frame = Frame::new(self, pose, water)?;
        if !linear_velocity
            .iter()
            .chain(angular_velocity.iter())
            .all(|c| c.is_finite())
        {
            return Err(Error::InvalidVelocity);
        }
        // Switched off, or entirely above the surface.
        if coefficients.is_off() || frame.height >= self.bounding_radius {
            return Ok((Damping::zero(frame.center_of_mass), None));
        }
        // Everything in the mesh frame, relative to the centroid.
        let mut drag = Drag::<T, STIFFNESS>::new(
            &frame.rotation,
            linear_velocity,
            angular_velocity,
            water,
            coefficients,
        );
        self.integrate_drag(reduced, &frame, &mut drag);

        let zero = T::zero();
        let area_scale = reduced.map_or(T::one(), |r| r.area_scale());
        let wetted_area = drag.double_area * T::from_f64_lossy(0.5) * area_scale;
        let wetted_fraction = if self.surface_area > zero {
            (wetted_area / self.surface_area).min(T::one())
        } else {
            zero
        };
        let angular = angular_damping(
            angular_velocity,
            wetted_fraction,
            self.volume,
            water.density(),
            coefficients,
        );
        let result = Damping {
            force: frame.rotation * drag.force,
            torque: frame.rotation * drag.torque + angular,
            angular_torque: angular,
            torque_point: frame.center_of_mass,
            wetted_area,
            wetted_fraction,
        };
        let stiffness = STIFFNESS.then(|| {
            let k = drag.stiffness;
            // K_world = Q·K·Qᵀ, Q = diag(R, R): both halves of `a` turn with the mesh.
            let mut rotation = Matrix6::zeros();
            add_block(&mut rotation, 0, 0, &frame.rotation);
            add_block(&mut rotation, 3, 3, &frame.rotation);
            DampingStiffness {
                drag: rotation * k.matrix * rotation.transpose(),
                angular: angular_damping_stiffness(
                    angular_velocity,
                    wetted_fraction,
                    self.volume,
                    water.density(),
                    coefficients,
                ),
                torque_point: frame.center_of_mass,
            }
        });
        let finite = |m: &Matrix6<T>| m.iter().all(|c| c.is_finite());
        if result
            .force
            .iter()
            .chain(result.torque.iter())
            .all(|c| c.is_finite())
            && stiffness
                .as_ref()
                .is_none_or(|k| finite(&k.about(&k.torque_point)))
        {
            Ok((result, stiffness))
        } else {
            Err(Error::NonFiniteResult)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Method, mesh::primitives};
    use nalgebra::{Translation3, UnitQuaternion};

    fn cube(side: f64) -> Mesh<f64> {
        let (v, t) = primitives::cube::<f64>(4).unwrap();
        Mesh::new(v.into_iter().map(|p| p * side).collect(), t).unwrap()
    }

    fn at(x: f64, y: f64, z: f64) -> Pose<f64> {
        Pose::from_parts(Translation3::new(x, y, z), UnitQuaternion::identity())
    }

    fn damp(mesh: &Mesh<f64>, pose: &Pose<f64>, v: Vector3<f64>, w: Vector3<f64>) -> Damping<f64> {
        mesh.damping(
            pose,
            &v,
            &w,
            &Water::default(),
            &DampingCoefficients::default(),
        )
        .unwrap()
    }

    /// A fully submerged unit cube spinning at ω about z: each side face pushes on the half where
    /// `u_n = ω|y| > 0`, so `τ_z = −4·(c₁ω/24 + qω²/64)` with `q = ½ρC_D`, whatever the
    /// triangulation of the faces, and nothing else.
    #[test]
    fn spinning_cube_is_exact_for_any_triangulation() {
        let omega = 3.0;
        let expected = -4.0 * (1000.0 * omega / 24.0 + 500.0 * omega * omega / 64.0);
        for n in [1, 2, 5] {
            let (v, t) = primitives::cube::<f64>(n).unwrap();
            let c = Mesh::new(v, t).unwrap();
            let d = damp(
                &c,
                &at(0.0, -3.0, 0.0),
                Vector3::zeros(),
                Vector3::new(0.0, 0.0, omega),
            );
            assert!(d.force.norm() < 1e-9, "{n}: {:?}", d.force);
            let drag_z = d.torque.z - (-(0.1 + 0.1 * omega) * 1000.0 * omega); // minus the angular term (V = 1, f = 1)
            assert!(
                (drag_z - expected).abs() < 1e-9,
                "{n}: {drag_z} vs {expected}"
            );
            assert!(
                d.torque.x.abs() < 1e-9 && d.torque.y.abs() < 1e-9,
                "{n}: {:?}",
                d.torque
            );
        }
        // Half submerged and moving too: the same for every triangulation.
        let results: alloc::vec::Vec<Damping<f64>> = [1, 3, 6]
            .into_iter()
            .map(|n| {
                let (v, t) = primitives::cube::<f64>(n).unwrap();
                let c = Mesh::new(v, t).unwrap();
                let pose = Pose::from_parts(
                    Translation3::new(0.0, 0.1, 0.0),
                    UnitQuaternion::from_euler_angles(0.2, 0.1, 0.3),
                );
                damp(
                    &c,
                    &pose,
                    Vector3::new(0.5, -1.0, 0.3),
                    Vector3::new(0.4, -1.0, 2.0),
                )
            })
            .collect();
        for d in &results[1..] {
            assert!(
                (d.force - results[0].force).norm() < 1e-9 * results[0].force.norm(),
                "{:?} vs {:?}",
                d.force,
                results[0].force
            );
            assert!(
                (d.torque - results[0].torque).norm() < 1e-9 * results[0].torque.norm(),
                "{:?} vs {:?}",
                d.torque,
                results[0].torque
            );
        }
    }

    #[test]
    fn zero_when_dry() {
        let c = cube(1.0);
        let d = damp(
            &c,
            &at(0.0, 2.0, 0.0),
            Vector3::new(1.0, -3.0, 2.0),
            Vector3::new(0.5, 1.0, -2.0),
        );
        assert_eq!(d.force, Vector3::zeros());
        assert_eq!(d.torque, Vector3::zeros());
        assert_eq!(d.wetted_area, 0.0);
        // Touching the surface from above is still dry.
        let d = damp(
            &c,
            &at(0.0, 0.5, 0.0),
            Vector3::new(0.0, -3.0, 0.0),
            Vector3::zeros(),
        );
        assert_eq!(d.force, Vector3::zeros());
    }

    #[test]
    fn zero_at_rest_and_when_off() {
        let c = cube(1.0);
        let d = damp(&c, &at(0.0, -0.2, 0.0), Vector3::zeros(), Vector3::zeros());
        assert_eq!((d.force, d.torque), (Vector3::zeros(), Vector3::zeros()));
        let off = c
            .damping(
                &at(0.0, -5.0, 0.0),
                &Vector3::new(3.0, 1.0, 0.0),
                &Vector3::x(),
                &Water::default(),
                &DampingCoefficients::off(),
            )
            .unwrap();
        assert_eq!(
            (off.force, off.torque),
            (Vector3::zeros(), Vector3::zeros())
        );
    }

    #[test]
    fn heave_drag_of_a_submerged_cube_face_has_the_formula_value() {
        // A 1 m cube fully under water moving down at 2 m/s: only the bottom face (1 m²)
        // faces the flow; the sides are parallel to it.
        let c = cube(1.0);
        let d = damp(
            &c,
            &at(0.0, -3.0, 0.0),
            Vector3::new(0.0, -2.0, 0.0),
            Vector3::zeros(),
        );
        let expected = 1000.0 * 2.0 + 0.5 * 1000.0 * 1.0 * 4.0;
        assert!(
            (d.force - Vector3::new(0.0, expected, 0.0)).norm() < 1e-9 * expected,
            "{d:?}"
        );
        assert!(d.torque.norm() < 1e-9 * expected);
        assert!((d.wetted_area - 6.0).abs() < 1e-12 && (d.wetted_fraction - 1.0).abs() < 1e-12);
    }

    #[test]
    fn opposes_the_velocity() {
        let c = cube(0.7);
        let rotated = Pose::from_parts(
            Translation3::new(0.3, -0.1, 0.2),
            UnitQuaternion::from_euler_angles(0.3, -0.7, 1.1),
        );
        for v in [
            Vector3::new(1.0, 0.0, 0.0),
            Vector3::new(-0.3, 2.0, 0.5),
            Vector3::new(0.0, -4.0, 1.0),
        ] {
            let d = damp(&c, &rotated, v, Vector3::zeros());
            assert!(d.force.dot(&v) < 0.0, "{v:?}: {d:?}");
            // The power of the damping is never positive, whatever the motion.
            let w = Vector3::new(0.4, -1.0, 0.8);
            let d = damp(&c, &rotated, v, w);
            assert!(d.force.dot(&v) + d.torque.dot(&w) < 0.0, "{v:?}: {d:?}");
        }
        // Spinning alone: the torque opposes the spin.
        let w = Vector3::new(0.0, 0.0, 2.0);
        let d = damp(&c, &rotated, Vector3::zeros(), w);
        assert!(d.torque.dot(&w) < 0.0);
    }

    #[test]
    fn the_current_is_relative() {
        // A body at rest in a current feels the same force as one moving against still water.
        let c = cube(1.0);
        let pose = at(0.0, -0.3, 0.0);
        let current = DampingCoefficients::default()
            .with_current(Vector3::new(1.5, 0.0, 0.0))
            .unwrap();
        let drifted = c
            .damping(
                &pose,
                &Vector3::zeros(),
                &Vector3::zeros(),
                &Water::default(),
                &current,
            )
            .unwrap();
        let moving = damp(&c, &pose, Vector3::new(-1.5, 0.0, 0.0), Vector3::zeros());
        assert!((drifted.force - moving.force).norm() < 1e-9 && drifted.force.x > 0.0);
    }

    #[test]
    fn scales_with_the_submerged_area() {
        // Sideways motion of an upright cube: only the wetted part of the front face drags,
        // so the force is proportional to the draft.
        let c = cube(1.0);
        let v = Vector3::new(1.0, 0.0, 0.0);
        let force = |draft: f64| {
            damp(&c, &at(0.0, 0.5 - draft, 0.0), v, Vector3::zeros())
                .force
                .x
        };
        let (f1, f2, f3) = (force(0.2), force(0.4), force(0.8));
        assert!(f1 < 0.0);
        assert!(
            (f2 / f1 - 2.0).abs() < 1e-9 && (f3 / f1 - 4.0).abs() < 1e-9,
            "{f1} {f2} {f3}"
        );
        // The wetted area matches the exact method's picture of the submerged part.
        let d = damp(&c, &at(0.0, 0.5 - 0.4, 0.0), v, Vector3::zeros());
        assert!((d.wetted_area - (1.0 + 4.0 * 0.4)).abs() < 1e-12);
        let b = c
            .buoyancy(&at(0.0, 0.1, 0.0), &Water::default(), Method::Exact)
            .unwrap();
        assert!((b.submerged_volume - 0.4).abs() < 1e-12);
    }

    #[test]
    fn angular_damping_scales_with_the_wetted_fraction() {
        // A sphere spinning about its center: the pressure drag is zero (the surface moves
        // tangentially), the angular damping alone acts, in proportion to what is wet.
        let (v, t) = primitives::uv_sphere::<f64>(1.0, 48, 24).unwrap();
        let s = Mesh::new(v, t).unwrap();
        let w = Vector3::new(0.0, 3.0, 0.0);
        let half = damp(&s, &at(0.0, 0.0, 0.0), Vector3::zeros(), w);
        let full = damp(&s, &at(0.0, -3.0, 0.0), Vector3::zeros(), w);
        assert!(full.torque.y < 0.0 && half.torque.y < 0.0);
        assert!(
            (half.torque.y / full.torque.y - 0.5).abs() < 0.02,
            "{half:?} {full:?}"
        );
        let expected = 1000.0 * s.volume().powf(5.0 / 3.0) * (0.1 + 0.1 * 3.0) * 3.0;
        assert!(
            (full.torque.y + expected).abs() < 0.05 * expected,
            "{full:?} vs {expected}"
        );
    }

    #[test]
    fn no_nan_for_extreme_inputs() {
        let c = cube(1.0);
        for y in [-1e6, -10.0, -0.5, 0.0, 0.5, 1e6] {
            for v in [
                Vector3::zeros(),
                Vector3::new(1e-30, 0.0, 0.0),
                Vector3::new(0.0, -1e6, 0.0),
            ] {
                let d = damp(&c, &at(0.0, y, 0.0), v, v);
                assert!(d.force.iter().chain(d.torque.iter()).all(|x| x.is_finite()));
            }
        }
        let w = Water::default();
        let k = DampingCoefficients::default();
        let nan = Vector3::new(f64::NAN, 0.0, 0.0);
        assert_eq!(
            c.damping(&at(0.0, 0.0, 0.0), &nan, &Vector3::zeros(), &w, &k),
            Err(Error::InvalidVelocity)
        );
        assert!(matches!(
            c.damping(
                &at(f64::NAN, 0.0, 0.0),
                &Vector3::zeros(),
                &Vector3::zeros(),
                &w,
                &k
            ),
            Err(Error::InvalidPose { .. })
        ));
        assert!(matches!(
            k.with_linear_drag(-1.0),
            Err(Error::InvalidDamping {
                parameter: "linear_drag",
                ..
            })
        ));
        assert!(matches!(
            k.with_current(nan),
            Err(Error::InvalidDamping {
                parameter: "current",
                ..
            })
        ));
        // f32 too.
        let (v, t) = primitives::cube::<f32>(2).unwrap();
        let c32 = Mesh::new(v, t).unwrap();
        let pose = Pose::from_parts(
            Translation3::new(0.0f32, -0.2, 0.0),
            UnitQuaternion::identity(),
        );
        let d = c32
            .damping(
                &pose,
                &Vector3::new(0.0, -1.0, 0.0),
                &Vector3::zeros(),
                &Water::default(),
                &DampingCoefficients::default(),
            )
            .unwrap();
        assert!(d.force.y > 0.0 && d.force.y.is_finite());
    }
}
