//! The damping made semi-implicit (see [Stability](super#stability)): the damping wrench of the
//! model taken at the end of the step, so that light bodies and bodies dropped fast neither
//! overshoot nor oscillate.

use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

use super::state::BodyState;
use super::state::Wrench;
use crate::damping::add_block;

/// The generalized mass `M` of a rigid body, `f64`, world frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct GeneralizedMass {
    /// Per-axis inverse mass, 1/kg (zero on locked translation axes).
    pub inv_mass: Vector3<f64>,
    /// World inverse inertia, 1/(kg·m²) (zero rows and columns on locked rotation axes).
    pub inv_inertia: Matrix3<f64>,
    /// World inertia, kg·m² (the rows of locked rotation axes are meaningless: their angular
    /// velocity is zero).
    pub inertia: Matrix3<f64>,
}

impl GeneralizedMass {
    /// The engine's effective mass properties of a body.
    pub fn of(state: &BodyState) -> Self {
        let inv_inertia = state.inverse_inertia;
        let mut invertible = inv_inertia;
        for k in 0..3 {
            if invertible[(k, k)] == 0.0 {
                invertible[(k, k)] = 1.0;
            }
        }
        let inertia = invertible.try_inverse().unwrap_or_else(Matrix3::zeros);
        GeneralizedMass {
            inv_mass: state.inverse_mass,
            inv_inertia,
            inertia,
        }
    }
}

/// The damping wrench to apply over a step of `dt` seconds.
///
/// About the current velocity `q̇ = (v − v_water, ω)` (`relative_velocity`, m/s, and `omega`,
/// rad/s), the core's damping wrench `W = (F, τ)` is linearised as `W − α·M·Δq̇`, with `α`
/// (1/s) the damping rate in the metric of the generalized mass `M`,
///
/// ```text
/// α = √(W·M⁻¹W / q̇·M·q̇)        (locked axes left out),
/// ```
///
/// and solved for the end of the step, given the step's other forces `G` (`others`: buoyancy,
/// gravity, the application's own forces; the components on locked translation axes are left
/// out):
///
/// ```text
/// W' = (W − α·dt·G) / (1 + α·dt).
/// ```
///
/// `W` is returned as it is when it or the velocity is zero, or `dt` is not positive. Torques
/// are about the body's center of mass.
pub(crate) fn semi_implicit_damping(
    damping: Wrench,
    others: Wrench,
    relative_velocity: &Vector3<f64>,
    omega: &Vector3<f64>,
    mass: &GeneralizedMass,
    dt: f64,
) -> Wrench {
    let inv_mass = &mass.inv_mass;
    // W·M⁻¹W and q̇·M·q̇.
    let wrench_norm2 = damping.force.dot(&inv_mass.component_mul(&damping.force))
        + damping.torque.dot(&(mass.inv_inertia * damping.torque));
    let linear_momentum_norm2: f64 = (0..3)
        .filter(|&i| inv_mass[i] > 0.0)
        .map(|i| relative_velocity[i] * relative_velocity[i] / inv_mass[i])
        .sum();
    let velocity_norm2 = linear_momentum_norm2 + omega.dot(&(mass.inertia * omega));
    let rate = if wrench_norm2 > 0.0 && velocity_norm2 > 0.0 {
        libm::sqrt(wrench_norm2 / velocity_norm2)
    } else {
        0.0
    };
    if !(rate > 0.0 && dt > 0.0) {
        return damping;
    }
    let mut other_force = others.force;
    for i in 0..3 {
        if inv_mass[i] == 0.0 {
            other_force[i] = 0.0;
        }
    }
    let h = rate * dt;
    Wrench {
        force: (damping.force - other_force * h) / (1.0 + h),
        torque: (damping.torque - others.torque * h) / (1.0 + h),
    }
}

/// Whether [`semi_implicit_damping`]'s one rate would throw a direction of motion back faster
/// than it came: with the other forces balanced (`G = 0`), whether its wrench `W/(1 + α·dt)`
/// alone, applied over the step, turns the relative velocity or the angular velocity `q`
/// against itself by more than it was, `q·(q + dt·M⁻¹W/(1 + α·dt)) < −|q|²` for the linear or
/// the angular part: an oscillation that grows from step to step. That happens to a direction
/// much stiffer than the body's motion as a whole (a fast spin under a strong angular damping
/// while the body also moves fast, a long flat box rocking on its flat bottom);
/// [`implicit_damping`] damps each direction at its own rate instead. A reversal smaller than
/// that decays by itself and is left to the one rate, which costs no second pass.
pub(crate) fn overshoots(
    damping: Wrench,
    relative_velocity: &Vector3<f64>,
    omega: &Vector3<f64>,
    mass: &GeneralizedMass,
    dt: f64,
) -> bool {
    let balanced = Wrench {
        force: Vector3::zeros(),
        torque: Vector3::zeros(),
    };
    let alone = semi_implicit_damping(damping, balanced, relative_velocity, omega, mass, dt);
    let linear = relative_velocity + mass.inv_mass.component_mul(&alone.force) * dt;
    let angular = omega + mass.inv_inertia * alone.torque * dt;
    let back = |q: &Vector3<f64>, after: &Vector3<f64>| q.dot(after) < -q.norm_squared();
    back(relative_velocity, &linear) || back(omega, &angular)
}

/// The damping wrench to apply over a step of `dt` seconds, taken at the end of the step
/// through its stiffness `K = −∂W/∂q̇` (6×6, world frame, about the center of mass, see
/// [`DampingStiffness`](crate::damping::DampingStiffness)): linearised as `W − K·Δq̇` and
/// solved with the step's other forces `G` (`others`, as for [`semi_implicit_damping`]),
///
/// ```text
/// (I + dt·M⁻¹K)·Δq̇ = dt·M⁻¹·(G + W),    W' = W − K·Δq̇,
/// ```
///
/// backward Euler for the damping: each direction of motion is damped at its own rate, so a
/// stiff direction stops without overshooting while a soft one keeps its motion. Locked axes
/// (zero rows of `M⁻¹`) take no part. `W` is returned as it is when `dt` is not positive or
/// `K` is zero; [`semi_implicit_damping`]'s answer if the system is singular (it is not for a
/// positive semi-definite `K`).
pub(crate) fn implicit_damping(
    damping: Wrench,
    stiffness: &Matrix6<f64>,
    others: Wrench,
    relative_velocity: &Vector3<f64>,
    omega: &Vector3<f64>,
    mass: &GeneralizedMass,
    dt: f64,
) -> Wrench {
    if !(dt > 0.0 && stiffness.iter().any(|k| *k != 0.0)) {
        return damping;
    }
    let mut inverse_mass = Matrix6::zeros();
    add_block(
        &mut inverse_mass,
        0,
        0,
        &Matrix3::from_diagonal(&mass.inv_mass),
    );
    add_block(&mut inverse_mass, 3, 3, &mass.inv_inertia);
    let total = |w: &Wrench| {
        Vector6::new(
            w.force.x, w.force.y, w.force.z, w.torque.x, w.torque.y, w.torque.z,
        )
    };
    let system = Matrix6::identity() + inverse_mass * stiffness * dt;
    let right = inverse_mass * (total(&others) + total(&damping)) * dt;
    let Some(change) = system.lu().solve(&right) else {
        return semi_implicit_damping(damping, others, relative_velocity, omega, mass, dt);
    };
    let solved = total(&damping) - stiffness * change;
    Wrench {
        force: solved.fixed_rows::<3>(0).into_owned(),
        torque: solved.fixed_rows::<3>(3).into_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit mass and inertia, nothing locked.
    fn unit_mass() -> GeneralizedMass {
        GeneralizedMass {
            inv_mass: Vector3::repeat(1.0),
            inv_inertia: Matrix3::identity(),
            inertia: Matrix3::identity(),
        }
    }

    #[test]
    fn balanced_forces_scale_the_whole_wrench_by_one_factor() {
        // Linear drag −c·v with c = 4 on a unit mass: α = 4; G = 0 gives W/(1 + α·dt).
        let velocity = Vector3::new(0.5, 0.0, 0.0);
        let damping = Wrench {
            force: velocity * -4.0,
            torque: Vector3::new(0.0, 0.0, -1.0),
        };
        let zero = Wrench {
            force: Vector3::zeros(),
            torque: Vector3::zeros(),
        };
        let omega = Vector3::new(0.0, 0.0, 0.25);
        let solved = semi_implicit_damping(damping, zero, &velocity, &omega, &unit_mass(), 0.1);
        let rate = (damping.force.norm_squared() + damping.torque.norm_squared()).sqrt()
            / (velocity.norm_squared() + omega.norm_squared()).sqrt();
        let factor = 1.0 / (1.0 + rate * 0.1);
        assert!((solved.force - damping.force * factor).norm() < 1e-15);
        assert!((solved.torque - damping.torque * factor).norm() < 1e-15);
    }

    #[test]
    fn terminal_velocity_is_a_fixed_point() {
        // At the terminal velocity the drag balances the other forces (W = −G): W' = W.
        let velocity = Vector3::new(0.0, -2.0, 0.0);
        let damping = Wrench {
            force: Vector3::new(0.0, 30.0, 0.0),
            torque: Vector3::zeros(),
        };
        let others = Wrench {
            force: -damping.force,
            torque: Vector3::zeros(),
        };
        let solved = semi_implicit_damping(
            damping,
            others,
            &velocity,
            &Vector3::zeros(),
            &unit_mass(),
            1.0 / 60.0,
        );
        assert!((solved.force - damping.force).norm() < 1e-12, "{solved:?}");
    }

    #[test]
    fn locked_axes_take_no_part() {
        // Translation along y locked: its velocity and other force do not enter.
        let mass = GeneralizedMass {
            inv_mass: Vector3::new(1.0, 0.0, 1.0),
            ..unit_mass()
        };
        let damping = Wrench {
            force: Vector3::new(-2.0, 0.0, 0.0),
            torque: Vector3::zeros(),
        };
        let others = Wrench {
            force: Vector3::new(0.0, -1000.0, 0.0),
            torque: Vector3::zeros(),
        };
        let velocity = Vector3::new(1.0, 50.0, 0.0);
        let solved =
            semi_implicit_damping(damping, others, &velocity, &Vector3::zeros(), &mass, 0.5);
        // α = |F| / |v_x| = 2: W' = W / (1 + 1).
        assert!(
            (solved.force - Vector3::new(-1.0, 0.0, 0.0)).norm() < 1e-15,
            "{solved:?}"
        );
    }

    /// A linear damping `W = −K·q̇` of very different rates per direction, on a unit mass:
    /// the implicit step is backward Euler in each, `W'ᵢ = Wᵢ/(1 + kᵢ·dt)`, so no direction
    /// turns back, where the one rate of `semi_implicit_damping` (set by the fast, soft
    /// translation) throws the slow, stiff spin back 11 times faster than it was.
    #[test]
    fn implicit_damping_takes_each_direction_at_its_own_rate() {
        let rates = [2.0, 3.0, 1.0, 0.5, 7e5, 1.0];
        let stiffness = Matrix6::from_diagonal(&Vector6::from_row_slice(&rates));
        let (v, omega) = (Vector3::new(30.0, -40.0, 5.0), Vector3::new(0.0, 4.0, 0.0));
        let q = Vector6::new(v.x, v.y, v.z, omega.x, omega.y, omega.z);
        let w = -(stiffness * q);
        let damping = Wrench {
            force: w.fixed_rows::<3>(0).into_owned(),
            torque: w.fixed_rows::<3>(3).into_owned(),
        };
        let zero = Wrench {
            force: Vector3::zeros(),
            torque: Vector3::zeros(),
        };
        let dt = 1.0 / 60.0;
        let solved = implicit_damping(damping, &stiffness, zero, &v, &omega, &unit_mass(), dt);
        let solved = Vector6::new(
            solved.force.x,
            solved.force.y,
            solved.force.z,
            solved.torque.x,
            solved.torque.y,
            solved.torque.z,
        );
        for i in 0..6 {
            let expected = w[i] / (1.0 + rates[i] * dt);
            assert!((solved[i] - expected).abs() <= 1e-12 * w[i].abs(), "{i}");
            // The velocity after the step keeps its sign.
            assert!(q[i] * (q[i] + solved[i] * dt) >= 0.0, "{i}");
        }
        assert!(overshoots(damping, &v, &omega, &unit_mass(), dt));
        let scalar = semi_implicit_damping(damping, zero, &v, &omega, &unit_mass(), dt);
        assert!(omega.y + scalar.torque.y * dt < -10.0 * omega.y);
        // A spin of 100/s instead: the one rate turns it back by less than it was, which
        // decays by itself.
        let mut mild = rates;
        mild[4] = 100.0;
        let w = -(Matrix6::from_diagonal(&Vector6::from_row_slice(&mild)) * q);
        let mild_damping = Wrench {
            force: w.fixed_rows::<3>(0).into_owned(),
            torque: w.fixed_rows::<3>(3).into_owned(),
        };
        let scalar = semi_implicit_damping(mild_damping, zero, &v, &omega, &unit_mass(), dt);
        let after = omega.y + scalar.torque.y * dt;
        assert!(after < 0.0 && after > -omega.y, "{after}");
        assert!(!overshoots(mild_damping, &v, &omega, &unit_mass(), dt));
        // Isotropic, the one rate is right and nothing overshoots.
        let isotropic = Wrench {
            force: v * -50.0,
            torque: omega * -50.0,
        };
        assert!(!overshoots(isotropic, &v, &omega, &unit_mass(), dt));
    }

    #[test]
    fn implicit_damping_keeps_the_terminal_velocity_and_locked_axes() {
        let stiffness = Matrix6::from_fn(|i, j| if i == j { 40.0 } else { 3.0 });
        let velocity = Vector3::new(0.0, -2.0, 0.0);
        let damping = Wrench {
            force: Vector3::new(0.5, 30.0, -0.2),
            torque: Vector3::new(0.1, 0.0, 0.3),
        };
        let others = Wrench {
            force: -damping.force,
            torque: -damping.torque,
        };
        let solved = implicit_damping(
            damping,
            &stiffness,
            others,
            &velocity,
            &Vector3::zeros(),
            &unit_mass(),
            1.0 / 60.0,
        );
        assert!((solved.force - damping.force).norm() < 1e-12, "{solved:?}");
        assert!(
            (solved.torque - damping.torque).norm() < 1e-12,
            "{solved:?}"
        );
        // Every axis locked: nothing moves, the wrench stays.
        let locked = GeneralizedMass {
            inv_mass: Vector3::zeros(),
            inv_inertia: Matrix3::zeros(),
            inertia: Matrix3::zeros(),
        };
        let solved = implicit_damping(
            damping,
            &stiffness,
            Wrench {
                force: Vector3::new(0.0, -1000.0, 0.0),
                torque: Vector3::zeros(),
            },
            &velocity,
            &Vector3::zeros(),
            &locked,
            0.1,
        );
        assert_eq!(solved, damping);
    }

    #[test]
    fn no_motion_or_no_step_leaves_the_wrench() {
        let damping = Wrench {
            force: Vector3::new(1.0, 2.0, 3.0),
            torque: Vector3::new(-1.0, 0.0, 0.5),
        };
        let others = Wrench {
            force: Vector3::new(0.0, -9.81, 0.0),
            torque: Vector3::zeros(),
        };
        let at_rest = semi_implicit_damping(
            damping,
            others,
            &Vector3::zeros(),
            &Vector3::zeros(),
            &unit_mass(),
            0.1,
        );
        assert_eq!(at_rest, damping);
        let no_step = semi_implicit_damping(
            damping,
            others,
            &Vector3::x(),
            &Vector3::zeros(),
            &unit_mass(),
            0.0,
        );
        assert_eq!(no_step, damping);
    }
}
