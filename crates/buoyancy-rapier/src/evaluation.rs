//! One body's buoyancy and damping at one step: the sum over its parts, the body's angular
//! damping, the semi-implicit solve, and the force and torque to hold in rapier's `f32`.

use buoyancy_core::nalgebra::{Point3, Vector3};
use rapier3d::math::Vector;
use rapier3d::prelude::RigidBody;

use crate::convert::{point_to_nalgebra, pose_to_nalgebra, vector_to_nalgebra, vector_to_rapier};
use crate::floating_body::FloatingBody;
use crate::report::{FloatReport, Outcome};
use crate::semi_implicit::{GeneralizedMass, semi_implicit_damping};
use crate::settings::Settings;
use crate::wrench::Wrench;

/// What evaluating one body at one step gives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Evaluation {
    /// The body is not dynamic, or disabled: nothing computed, its share stays as it is.
    Inactive,
    /// A pose, velocity or result was not finite: its share becomes zero.
    NotFinite,
    /// Its share becomes this force and torque (world frame, the torque about the world center
    /// of mass); `report` says what was computed.
    Floating {
        report: FloatReport,
        force: Vector,
        torque: Vector,
    },
}

impl Evaluation {
    /// The report of this evaluation, for a body whose world center of mass is
    /// `center_of_mass`.
    pub fn report(&self, center_of_mass: Point3<f64>) -> FloatReport {
        match self {
            Evaluation::Inactive => FloatReport::without_forces(center_of_mass, Outcome::Inactive),
            Evaluation::NotFinite => {
                FloatReport::without_forces(center_of_mass, Outcome::NotFinite)
            }
            Evaluation::Floating { report, .. } => *report,
        }
    }
}

/// Buoyancy + damping of `body` (rapier's `rb`) with `settings` (already resolved for it),
/// over a step of `dt` seconds.
pub(crate) fn evaluate(
    body: &FloatingBody,
    rb: &RigidBody,
    settings: &Settings,
    dt: f64,
) -> Evaluation {
    if !rb.is_dynamic() || !rb.is_enabled() {
        return Evaluation::Inactive;
    }
    let Some(mut report) = sum_parts(body, rb, settings) else {
        return Evaluation::NotFinite;
    };

    let velocity = vector_to_nalgebra(rb.linvel());
    let omega = vector_to_nalgebra(rb.angvel());
    let water = &settings.water;
    let gravity = -water.normal().into_inner() * (water.gravity() * f64::from(rb.gravity_scale()));
    let own_force = vector_to_nalgebra(rb.user_force() - body.share.force);
    let own_torque = vector_to_nalgebra(rb.user_torque() - body.share.torque);
    let others = Wrench {
        force: report.buoyancy_force + gravity * f64::from(rb.mass()) + own_force,
        torque: report.buoyancy_torque + own_torque,
    };
    let damping = semi_implicit_damping(
        Wrench {
            force: report.damping_force,
            torque: report.damping_torque,
        },
        others,
        &(velocity - settings.damping.current()),
        &omega,
        &GeneralizedMass::of(rb),
        dt,
    );
    (report.damping_force, report.damping_torque) = (damping.force, damping.torque);

    let force = vector_to_rapier(&(report.buoyancy_force + report.damping_force));
    let torque = vector_to_rapier(&(report.buoyancy_torque + report.damping_torque));
    if !(force.is_finite()
        && torque.is_finite()
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

/// The body's buoyancy and (explicit) damping: the sums over its parts, torques about the
/// world center of mass, with the angular damping of the whole body (see
/// [`BodyAngularDamping`]). `None` when the core rejects a pose or velocity (not finite).
fn sum_parts(body: &FloatingBody, rb: &RigidBody, settings: &Settings) -> Option<FloatReport> {
    let Settings {
        water,
        method,
        damping,
    } = settings;
    let center_of_mass = point_to_nalgebra(rb.center_of_mass());
    let body_pose = pose_to_nalgebra(rb.position());
    let velocity = vector_to_nalgebra(rb.linvel());
    let omega = vector_to_nalgebra(rb.angvel());
    let angular = (body.parts.len() > 1).then(|| BodyAngularDamping {
        omega,
        rate: damping.angular_drag_linear() + damping.angular_drag_quadratic() * omega.norm(),
        density: water.density(),
    });

    let mut report = FloatReport {
        center_of_mass,
        outcome: Outcome::Applied,
        ..Default::default()
    };
    let mut weighted_center = Vector3::zeros();
    for part in &body.parts {
        let pose = body_pose * part.shape_to_body;
        let buoyancy = part.mesh.buoyancy(&pose, water, *method).ok()?;
        // The core takes the velocity of the mesh's own centroid.
        let centroid_velocity = velocity + omega.cross(&(buoyancy.torque_point - center_of_mass));
        let drag = part
            .mesh
            .damping(&pose, &centroid_velocity, &omega, water, damping)
            .ok()?;
        report.submerged_volume += buoyancy.submerged_volume;
        weighted_center += buoyancy.center_of_buoyancy.coords * buoyancy.submerged_volume;
        report.buoyancy_force += buoyancy.force;
        report.buoyancy_torque += buoyancy.torque_about(&center_of_mass);
        report.damping_force += drag.force;
        report.damping_torque += drag.torque_about(&center_of_mass);
        if let Some(angular) = &angular {
            // Take back the part's own angular term: the body's replaces it below.
            report.damping_torque -= angular.torque(drag.wetted_fraction, part.mesh.volume());
        }
        report.wetted_area += drag.wetted_area;
    }
    if let Some(angular) = &angular
        && body.surface_area > 0.0
    {
        let wetted_fraction = (report.wetted_area / body.surface_area).min(1.0);
        report.damping_torque += angular.torque(wetted_fraction, body.volume);
    }
    report.center_of_buoyancy = if report.submerged_volume.abs() > 0.0 {
        Point3::from(weighted_center / report.submerged_volume)
    } else {
        water.project(&center_of_mass)
    };
    Some(report)
}

/// The core's angular damping, `−f·ρ·V^{5/3}·(a₁ + a₂|ω|)·ω` (N·m), which it computes per mesh.
/// For a body of several parts the adapter takes each part's term back and adds one for the
/// whole body (its total volume `V` and wetted fraction `f`), so that splitting a shape into
/// parts does not change it.
struct BodyAngularDamping {
    /// The angular velocity `ω`, rad/s.
    omega: Vector3<f64>,
    /// `a₁ + a₂|ω|`, 1/s.
    rate: f64,
    /// The water's density `ρ`, kg/m³.
    density: f64,
}

impl BodyAngularDamping {
    /// The torque for wetted fraction `f` of a body of volume `V` (m³; negative counts as 0).
    fn torque(&self, wetted_fraction: f64, volume: f64) -> Vector3<f64> {
        let size = self.density * volume.max(0.0).powf(5.0 / 3.0);
        -(self.omega * (wetted_fraction * size * self.rate))
    }
}
