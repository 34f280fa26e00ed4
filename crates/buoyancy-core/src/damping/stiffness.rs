//! The stiffness of the damping model: [`DampingStiffness`], [`angular_damping_stiffness`].

use nalgebra::{Matrix3, Matrix6, Point3, Vector3};

use super::DampingCoefficients;
use crate::Real;

/// The stiffness of the damping model: how its wrench changes with the body's velocity, what an
/// engine needs to integrate a stiff damping implicitly.
///
/// With `q̇ = (v − v_w, ω)` the velocity of the center of mass `c` relative to the water and the
/// angular velocity, and `W(q̇) = (F, τ)` the damping wrench (torque about `c`), the stiffness is
/// `K = −∂W/∂q̇`, a symmetric 6×6 matrix (rows and columns in the order `v`, `ω`; blocks in
/// N·s/m, N·s and N·m·s), world frame.
///
/// **Pressure drag.** `W = −∫ P(u) a dA` over the wetted surface, with `a = (n̂, (p − c) × n̂)`,
/// `u = a·q̇` the normal velocity and `P = c₁·u + ½ρC_D·u²` where `u > 0`, zero elsewhere. `P`
/// vanishes where `u` does, so moving the edge of the region that faces the flow changes
/// nothing to first order, and
///
/// ```text
/// K_drag = ∫ (c₁ + ρ·C_D·u) a aᵀ dA   over { u > 0 },
/// ```
///
/// positive semi-definite. Over each flat piece facing the flow, `w = c₁ + ρC_D·u` is linear, so
/// `∫w`, `∫w·p` and `∫w·p pᵀ` are integrated exactly (barycentric coordinates, as the drag
/// itself is).
///
/// **Angular damping.** `τ_ω = −s·(a₁ + a₂|ω|)·ω` with `s = f·ρ·V^{5/3}` gives, on `ω` alone,
///
/// ```text
/// K_ω = s·((a₁ + a₂|ω|)·I + a₂·ω ωᵀ/|ω|)          (s·a₁·I at ω = 0).
/// ```
///
/// Given by [`Mesh::damping_with_stiffness`](crate::Mesh::damping_with_stiffness) for one mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DampingStiffness<T: Real> {
    /// The pressure drag's, 6×6, torques and angular velocities about
    /// [`torque_point`](Self::torque_point).
    pub drag: Matrix6<T>,
    /// The angular damping's, 3×3, on `ω` alone (N·m·s).
    pub angular: Matrix3<T>,
    /// The mesh's centroid, world frame, m.
    pub torque_point: Point3<T>,
}

impl<T: Real> DampingStiffness<T> {
    /// The whole stiffness, pressure drag plus angular damping, about the world point `q`
    /// (the velocity taken at `q`, the torque about it): [`drag_about`](Self::drag_about) with
    /// [`angular`](Self::angular) added to its `ω` block, which moving the point leaves as it is.
    pub fn about(&self, q: &Point3<T>) -> Matrix6<T> {
        let mut k = self.drag_about(q);
        add_block(&mut k, 3, 3, &self.angular);
        k
    }

    /// The pressure drag's stiffness about another world point `q`: with `d = c − q`
    /// (`c` the [`torque_point`](Self::torque_point)), the velocity at `c` is `T·q̇_q`, and the
    /// wrench about `q` is `Tᵀ·W`, for `T = [[I, −[d]×], [0, I]]`: `K_q = Tᵀ·K·T`.
    pub fn drag_about(&self, q: &Point3<T>) -> Matrix6<T> {
        let d = self.torque_point - q;
        let mut shift = Matrix6::identity();
        add_block(&mut shift, 0, 3, &-d.cross_matrix());
        shift.transpose() * self.drag * shift
    }
}

/// The angular damping's stiffness `K_ω = s·((a₁ + a₂|ω|)·I + a₂·ω ωᵀ/|ω|)`, `s = f·ρ·V^{5/3}`
/// (N·m·s, world frame), for the arguments of [`angular_damping`](super::angular_damping): its
/// derivative with respect to `ω`, negated.
pub fn angular_damping_stiffness<T: Real>(
    omega: &Vector3<T>,
    wetted_fraction: T,
    volume: T,
    density: T,
    coefficients: &DampingCoefficients<T>,
) -> Matrix3<T> {
    let size = super::angular_size(wetted_fraction, volume, density);
    let (a1, a2) = (
        coefficients.angular_drag_linear(),
        coefficients.angular_drag_quadratic(),
    );
    let speed = omega.norm();
    let mut k = Matrix3::identity() * (a1 + a2 * speed);
    if speed > T::zero() {
        k += omega * omega.transpose() * (a2 / speed);
    }
    k * size
}

/// The pressure drag's stiffness summed piece by piece, mesh frame, about the mesh centroid.
#[derive(Debug, Clone, Copy)]
pub(crate) struct DragStiffness<T: Real> {
    pub matrix: Matrix6<T>,
}

impl<T: Real> DragStiffness<T> {
    pub fn zero() -> Self {
        DragStiffness {
            matrix: Matrix6::zeros(),
        }
    }

    /// Adds the flat piece `q` (corners relative to the centroid) of unit normal `normal` and
    /// area `area`, facing the flow with normal velocity `u ≥ 0` at its corners, for the drag
    /// coefficients `linear` (`c₁`) and `quadratic` (`½ρC_D`): `∫ w a aᵀ`, `w = c₁ + 2·quadratic·u`.
    pub fn add_piece(
        &mut self,
        q: &[Vector3<T>; 3],
        u: &[T; 3],
        normal: &Vector3<T>,
        area: T,
        linear: T,
        quadratic: T,
    ) {
        let two = T::from_f64_lossy(2.0);
        let w = u.map(|u| linear + two * quadratic * u);
        let sum_w = w[0] + w[1] + w[2];
        let sum_q = q[0] + q[1] + q[2];
        let sum_wq = q[0] * w[0] + q[1] * w[1] + q[2] * w[2];
        // ∫w, ∫w·p and ∫w·p pᵀ over the piece (∫λᵢλⱼλₖ = A/60·(1 + δᵢⱼ + δⱼₖ + δᵢₖ + 2δᵢⱼδⱼₖ)).
        let int_w = area * sum_w * T::from_f64_lossy(1.0 / 3.0);
        let int_wp = (sum_wq + sum_q * sum_w) * (area * T::from_f64_lossy(1.0 / 12.0));
        let mut second = sum_q * sum_q.transpose() * sum_w
            + sum_q * sum_wq.transpose()
            + sum_wq * sum_q.transpose();
        for (p, w) in q.iter().zip(w) {
            second += p * p.transpose() * (sum_w + two * w);
        }
        let int_wpp = second * (area * T::from_f64_lossy(1.0 / 60.0));
        // a = (n̂, p × n̂), p × n̂ = −[n̂]× p.
        let cross = normal.cross_matrix();
        let moment = int_wp.cross(normal);
        let coupling = normal * moment.transpose();
        add_block(
            &mut self.matrix,
            0,
            0,
            &(normal * normal.transpose() * int_w),
        );
        add_block(&mut self.matrix, 0, 3, &coupling);
        add_block(&mut self.matrix, 3, 0, &coupling.transpose());
        add_block(
            &mut self.matrix,
            3,
            3,
            &(cross * int_wpp * cross.transpose()),
        );
    }
}

/// `m[row.., column..] += block` for a 3×3 block.
#[inline(always)]
pub(crate) fn add_block<T: Real>(
    m: &mut Matrix6<T>,
    row: usize,
    column: usize,
    block: &Matrix3<T>,
) {
    for i in 0..3 {
        for j in 0..3 {
            m[(row + i, column + j)] += block[(i, j)];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::ReducedMesh;
    use crate::{Damping, Mesh, Pose, Water, mesh::primitives};
    use nalgebra::{Translation3, UnitQuaternion, Vector6};

    /// The damping wrench about `q` for the velocity `q̇` taken at `q`.
    fn wrench_about(
        mesh: &Mesh<f64>,
        reduced: Option<&ReducedMesh<f64>>,
        pose: &Pose<f64>,
        q: &Point3<f64>,
        velocity: &Vector6<f64>,
        coefficients: &DampingCoefficients<f64>,
    ) -> Vector6<f64> {
        let (v, omega) = (
            velocity.fixed_rows::<3>(0).into_owned(),
            velocity.fixed_rows::<3>(3).into_owned(),
        );
        let centroid = pose * mesh.centroid();
        let at_centroid = v + omega.cross(&(centroid - q));
        let water = Water::default();
        let d: Damping<f64> = match reduced {
            Some(r) => mesh.reduced_damping(r, pose, &at_centroid, &omega, &water, coefficients),
            None => mesh.damping(pose, &at_centroid, &omega, &water, coefficients),
        }
        .unwrap();
        let torque = d.torque_about(q);
        Vector6::new(
            d.force.x, d.force.y, d.force.z, torque.x, torque.y, torque.z,
        )
    }

    /// `K` against central differences of the damping wrench, on a torus (curved, so the
    /// region facing the flow moves with the velocity), a sphere's reduced copy and a cube,
    /// half submerged and tilted, about the centroid and about another point.
    #[test]
    fn stiffness_is_the_derivative_of_the_wrench() {
        let mesh = |s: Result<primitives::Shape<f64>, crate::Error>| {
            let (v, t) = s.unwrap();
            Mesh::new(v, t).unwrap()
        };
        let torus = mesh(primitives::torus(1.0, 0.4, 48, 24));
        let sphere = mesh(primitives::uv_sphere(0.8, 48, 24));
        let cube = mesh(primitives::cube(3));
        let reduced = ReducedMesh::new(&sphere, 200).unwrap();
        let coefficients = DampingCoefficients::default()
            .with_angular_drag(0.3, 0.2)
            .unwrap();
        let pose = Pose::from_parts(
            Translation3::new(0.3, 0.15, -0.2),
            UnitQuaternion::from_euler_angles(0.4, -0.2, 0.7),
        );
        let velocity = Vector6::new(0.4, -0.9, 0.25, 0.6, -0.3, 1.1);
        let water = Water::default();
        for (name, mesh, reduced) in [
            ("torus", &torus, None),
            ("reduced sphere", &sphere, Some(&reduced)),
            ("cube", &cube, None),
        ] {
            let centroid = pose * mesh.centroid();
            let at_centroid_v = velocity.fixed_rows::<3>(0).into_owned();
            let omega = velocity.fixed_rows::<3>(3).into_owned();
            let (damping, stiffness) = mesh
                .damping_with_stiffness(
                    reduced,
                    &pose,
                    &at_centroid_v,
                    &omega,
                    &water,
                    &coefficients,
                )
                .unwrap();
            let other = centroid + Vector3::new(0.7, -0.4, 0.2);
            // About the centroid and another point; `about` adds the angular damping's, which
            // the drag's shift leaves alone: it is the wrench's minus the angular term's.
            let angular = angular_damping_stiffness(
                &omega,
                damping.wetted_fraction,
                mesh.volume(),
                water.density(),
                &coefficients,
            );
            let mut drag_only = stiffness.about(&other);
            for i in 0..3 {
                for j in 0..3 {
                    drag_only[(3 + i, 3 + j)] -= angular[(i, j)];
                }
            }
            assert!((drag_only - stiffness.drag_about(&other)).norm() < 1e-12 * drag_only.norm());
            for (q, k) in [
                (centroid, stiffness.about(&centroid)),
                (other, stiffness.about(&other)),
            ] {
                // The same motion, its linear velocity taken at `q`.
                let v_q = at_centroid_v - omega.cross(&(centroid - q));
                let velocity = Vector6::new(v_q.x, v_q.y, v_q.z, omega.x, omega.y, omega.z);
                let h = 1e-6;
                let mut worst: f64 = 0.0;
                for j in 0..6 {
                    let step = Vector6::from_fn(|i, _| if i == j { h } else { 0.0 });
                    let column =
                        (wrench_about(mesh, reduced, &pose, &q, &(velocity - step), &coefficients)
                            - wrench_about(
                                mesh,
                                reduced,
                                &pose,
                                &q,
                                &(velocity + step),
                                &coefficients,
                            ))
                            / (2.0 * h);
                    worst = worst.max((column - k.column(j)).norm());
                }
                assert!(
                    worst < 1e-6 * k.norm(),
                    "{name}, about {q}: {worst:e} of {:e}",
                    k.norm()
                );
                assert!(
                    (k - k.transpose()).norm() < 1e-12 * k.norm(),
                    "{name}: not symmetric"
                );
                let smallest = k.symmetric_eigenvalues().min();
                assert!(
                    smallest > -1e-9 * k.norm(),
                    "{name}: eigenvalue {smallest:e}"
                );
            }
        }
    }

    #[test]
    fn angular_stiffness_is_the_derivative_of_the_angular_damping() {
        let coefficients = DampingCoefficients::default()
            .with_angular_drag(0.3, 0.7)
            .unwrap();
        let omega = Vector3::new(0.5, -1.2, 0.8);
        let k = angular_damping_stiffness(&omega, 0.6, 2.0, 1000.0, &coefficients);
        let h = 1e-6;
        for j in 0..3 {
            let step = Vector3::from_fn(|i, _| if i == j { h } else { 0.0 });
            let column =
                (super::super::angular_damping(&(omega - step), 0.6, 2.0, 1000.0, &coefficients)
                    - super::super::angular_damping(
                        &(omega + step),
                        0.6,
                        2.0,
                        1000.0,
                        &coefficients,
                    ))
                    / (2.0 * h);
            assert!((column - k.column(j)).norm() < 1e-7 * k.norm(), "{j}");
        }
        // At rest: s·a₁·I.
        let at_rest = angular_damping_stiffness(&Vector3::zeros(), 0.6, 2.0, 1000.0, &coefficients);
        let s = 0.6 * 1000.0 * 2.0_f64.powf(5.0 / 3.0);
        assert!((at_rest - Matrix3::identity() * (s * 0.3)).norm() < 1e-9);
    }
}
