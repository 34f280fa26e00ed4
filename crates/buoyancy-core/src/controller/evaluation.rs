//! One body's buoyancy and damping at one step: the sum over its parts, the body's angular
//! damping, the semi-implicit solve, and the force and torque to hold in the engine's `f32`.

use nalgebra::{Matrix6, Point3, Vector3};

use super::body::{Evaluation, FloatingBody};
use super::semi_implicit::{GeneralizedMass, implicit_damping, overshoots, semi_implicit_damping};
use super::settings::Settings;
use super::state::Wrench;
use super::state::{BodyState, Motion};
use super::state::{FloatReport, Outcome};
use crate::Error;
use crate::damping::{add_block, angular_damping, angular_damping_stiffness};
use crate::query::{Pressure, Sea};
use crate::water::WaterSurface;

/// A moving free surface at the time of a step.
#[derive(Clone, Copy)]
pub(crate) struct SurfaceAt<'a> {
    pub surface: &'a (dyn WaterSurface<f64> + Send),
    pub time: f64,
    pub pressure: Pressure,
}

/// Buoyancy + damping of `body` in `state` with `settings` (already resolved for it), over a
/// step of `dt` seconds.
pub(crate) fn evaluate(
    body: &FloatingBody,
    state: &BodyState,
    settings: &Settings,
    waves: Option<SurfaceAt>,
    dt: f64,
) -> Evaluation {
    if state.motion != Motion::Dynamic {
        return Evaluation::Inactive;
    }
    // The damping relative to the water: its current, plus the waves' orbital velocity at the
    // center of mass.
    let mut settings = *settings;
    if let Some(waves) = waves
        && let Some(orbital) =
            waves
                .surface
                .water_velocity(&settings.water, &state.center_of_mass, waves.time)
    {
        let current = settings.damping.current() + orbital;
        match settings.damping.with_current(current) {
            Ok(damping) => settings.damping = damping,
            Err(_) => return Evaluation::NotFinite,
        }
    }
    let settings = &settings;
    let mut report = match sum_parts(body, state, settings, waves) {
        Ok(report) => report,
        Err(Outcome::Unsupported) => return Evaluation::Unsupported,
        Err(_) => return Evaluation::NotFinite,
    };
    let water = &settings.water;
    let gravity = -water.normal().into_inner() * (water.gravity() * state.gravity_scale);
    let own_force = (state.applied_force - body.share.force).cast::<f64>();
    let own_torque = (state.applied_torque - body.share.torque).cast::<f64>();
    let others = Wrench {
        force: report.buoyancy_force + gravity * state.mass + own_force,
        torque: report.buoyancy_torque + own_torque,
    };
    let explicit = Wrench {
        force: report.damping_force,
        torque: report.damping_torque,
    };
    let relative_velocity = state.linear_velocity - settings.damping.current();
    let mass = GeneralizedMass::of(state);
    let omega = &state.angular_velocity;
    let mut damping = semi_implicit_damping(explicit, others, &relative_velocity, omega, &mass, dt);
    // Stiff: one rate for the whole wrench would throw a direction of motion back faster than
    // it came; each direction is damped at its own rate through the damping's stiffness
    // instead (a stiffness that overflows leaves the one rate's answer).
    if overshoots(explicit, &relative_velocity, omega, &mass, dt)
        && let Some(stiffness) = damping_stiffness(body, state, settings, report.wetted_area)
    {
        damping = implicit_damping(
            explicit,
            &stiffness,
            others,
            &relative_velocity,
            omega,
            &mass,
            dt,
        );
    }
    (report.damping_force, report.damping_torque) = (damping.force, damping.torque);

    let force = (report.buoyancy_force + report.damping_force).cast::<f32>();
    let torque = (report.buoyancy_torque + report.damping_torque).cast::<f32>();
    let finite = |v: &Vector3<f32>| v.iter().all(|c| c.is_finite());
    if !(finite(&force)
        && finite(&torque)
        && report.center_of_buoyancy.iter().all(|c| c.is_finite()))
    {
        return Evaluation::NotFinite;
    }
    Evaluation::Floating {
        report,
        force,
        torque,
    }
}

/// The stiffness `K = −∂W/∂q̇` of the body's damping about its center of mass (world frame):
/// each part's pressure drag (over its reduced copy if it has one), as [`sum_parts`] sums it,
/// and the angular damping of the whole body for the parts' total `wetted_area`. `None` when
/// the core rejects a pose or velocity (not finite) or the stiffness overflows.
fn damping_stiffness(
    body: &FloatingBody,
    state: &BodyState,
    settings: &Settings,
    wetted_area: f64,
) -> Option<Matrix6<f64>> {
    let Settings { water, damping, .. } = settings;
    let center_of_mass = state.center_of_mass;
    let (velocity, omega) = (state.linear_velocity, state.angular_velocity);
    let mut stiffness = Matrix6::zeros();
    for (part, reduced) in body.parts.iter().zip(&body.reduced) {
        let pose = state.pose * part.shape_to_body;
        let centroid = pose * part.mesh.centroid();
        let centroid_velocity = velocity + omega.cross(&(centroid - center_of_mass));
        let (_, part_stiffness) = part
            .mesh
            .damping_with_stiffness(
                reduced.as_deref(),
                &pose,
                &centroid_velocity,
                &omega,
                water,
                damping,
            )
            .ok()?;
        stiffness += part_stiffness.drag_about(&center_of_mass);
    }
    if let Some(wetted_fraction) = body.wetted_fraction(wetted_area) {
        let angular = angular_damping_stiffness(
            &omega,
            wetted_fraction,
            body.volume,
            water.density(),
            damping,
        );
        add_block(&mut stiffness, 3, 3, &angular);
    }
    Some(stiffness)
}

/// The body's buoyancy and (explicit) damping: the sums over its parts, torques about the
/// world center of mass, the pressure drag of each part (over its reduced copy if it has one)
/// and the angular damping of the whole
/// body ([`angular_damping`] with the parts' total wetted fraction and volume). The error is
/// [`Outcome::Unsupported`] when the core refuses the query, [`Outcome::NotFinite`] when it
/// rejects a pose or velocity (not finite).
fn sum_parts(
    body: &FloatingBody,
    state: &BodyState,
    settings: &Settings,
    waves: Option<SurfaceAt>,
) -> Result<FloatReport, Outcome> {
    let Settings {
        water,
        method,
        damping,
    } = settings;
    let center_of_mass = state.center_of_mass;
    let (velocity, omega) = (state.linear_velocity, state.angular_velocity);
    let mut report = FloatReport {
        center_of_mass,
        outcome: Outcome::Applied,
        ..Default::default()
    };
    let mut weighted_center = Vector3::zeros();
    for (part, reduced) in body.parts.iter().zip(&body.reduced) {
        let pose = state.pose * part.shape_to_body;
        let sea = match waves {
            Some(waves) => Sea::new(water, waves.surface, waves.time).with_pressure(waves.pressure),
            None => Sea::calm(water),
        };
        let buoyancy = part
            .mesh
            .buoyancy(&pose, sea, *method)
            .map_err(|e| match e {
                Error::Unsupported { .. } => Outcome::Unsupported,
                _ => Outcome::NotFinite,
            })?;
        // The core takes the velocity of the mesh's own centroid.
        let centroid_velocity = velocity + omega.cross(&(buoyancy.torque_point - center_of_mass));
        let drag = match reduced {
            Some(reduced) => part.mesh.reduced_damping(
                reduced,
                &pose,
                &centroid_velocity,
                &omega,
                water,
                damping,
            ),
            None => part
                .mesh
                .damping(&pose, &centroid_velocity, &omega, water, damping),
        }
        .map_err(|_| Outcome::NotFinite)?;
        report.submerged_volume += buoyancy.submerged_volume;
        weighted_center += buoyancy.center_of_buoyancy.coords * buoyancy.submerged_volume;
        report.buoyancy_force += buoyancy.force;
        report.buoyancy_torque += buoyancy.torque_about(&center_of_mass);
        report.damping_force += drag.force;
        // The pressure drag's moment; the angular damping is the whole body's, below.
        report.damping_torque += drag.torque_about(&center_of_mass) - drag.angular_torque;
        report.wetted_area += drag.wetted_area;
    }
    if let Some(wetted_fraction) = body.wetted_fraction(report.wetted_area) {
        report.damping_torque += angular_damping(
            &omega,
            wetted_fraction,
            body.volume,
            water.density(),
            damping,
        );
    }
    report.center_of_buoyancy = if report.submerged_volume.abs() > 0.0 {
        Point3::from(weighted_center / report.submerged_volume)
    } else {
        water.project(&center_of_mass)
    };
    Ok(report)
}

#[cfg(test)]
mod tests {
    use alloc::sync::Arc;

    use nalgebra::{Matrix3, Translation3, UnitQuaternion, Vector6};

    use super::*;
    use crate::controller::body::Part;
    use crate::controller::settings::BodyOptions;
    use crate::controller::state::Motion;
    use crate::mesh::ReducedMesh;
    use crate::{DampingCoefficients, Mesh, Pose, mesh::primitives};

    /// The stiffness of a body of two parts (a cube and a sphere's reduced copy, off its center
    /// of mass, half under water) against central differences of the damping its parts sum,
    /// velocity taken at the center of mass.
    #[test]
    fn a_bodys_stiffness_is_the_derivative_of_its_damping() {
        let (v, t) = primitives::cube::<f64>(3).unwrap();
        let cube = Arc::new(Mesh::new(v, t).unwrap());
        let (v, t) = primitives::uv_sphere::<f64>(0.5, 32, 16).unwrap();
        let sphere = Arc::new(Mesh::new(v, t).unwrap());
        let reduced = ReducedMesh::new(&sphere, 150).map(Arc::new);
        assert!(reduced.is_some());
        let at = |x: f64, z: f64| {
            Pose::from_parts(Translation3::new(x, 0.1, z), UnitQuaternion::identity())
        };
        let mut body = FloatingBody::new(
            alloc::vec![
                Part {
                    mesh: cube,
                    shape_to_body: at(-0.6, 0.0),
                },
                Part {
                    mesh: sphere,
                    shape_to_body: at(0.7, 0.3),
                },
            ],
            BodyOptions::default(),
        )
        .unwrap();
        body.reduced = alloc::vec![None, reduced];
        let settings = Settings {
            damping: DampingCoefficients::default()
                .with_angular_drag(0.4, 0.3)
                .unwrap(),
            ..Settings::default()
        };
        let state = |velocity: &Vector6<f64>| BodyState {
            pose: Pose::from_parts(
                Translation3::new(0.2, -0.15, 0.1),
                UnitQuaternion::from_euler_angles(0.3, -0.5, 0.2),
            ),
            center_of_mass: Point3::new(0.3, -0.1, 0.05),
            linear_velocity: velocity.fixed_rows::<3>(0).into_owned(),
            angular_velocity: velocity.fixed_rows::<3>(3).into_owned(),
            mass: 400.0,
            inverse_mass: Vector3::repeat(1.0 / 400.0),
            inverse_inertia: Matrix3::identity() / 60.0,
            gravity_scale: 1.0,
            applied_force: Vector3::zeros(),
            applied_torque: Vector3::zeros(),
            motion: Motion::Dynamic,
            sleeping: false,
        };
        let wrench = |velocity: &Vector6<f64>| {
            let r = sum_parts(&body, &state(velocity), &settings, None).unwrap();
            let (f, t) = (r.damping_force, r.damping_torque);
            Vector6::new(f.x, f.y, f.z, t.x, t.y, t.z)
        };
        let velocity = Vector6::new(0.5, -0.8, 0.3, 0.7, 1.1, -0.6);
        let report = sum_parts(&body, &state(&velocity), &settings, None).unwrap();
        let k = damping_stiffness(&body, &state(&velocity), &settings, report.wetted_area).unwrap();
        let h = 1e-6;
        for j in 0..6 {
            let step = Vector6::from_fn(|i, _| if i == j { h } else { 0.0 });
            let column = (wrench(&(velocity - step)) - wrench(&(velocity + step))) / (2.0 * h);
            assert!(
                (column - k.column(j)).norm() < 1e-6 * k.norm(),
                "column {j}: {column:?} vs {:?}",
                k.column(j)
            );
        }
    }
}
