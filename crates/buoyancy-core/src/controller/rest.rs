//! Placing a body at rest before the first step: the pose where its buoyancy balances its
//! weight, so that a boat spawned there does not bob.

use alloc::borrow::Cow;
use alloc::vec::Vec;

use nalgebra::{Point3, Vector3};

use super::{BodyState, Controller, Part};
use crate::hydrostatics::{Equilibrium, EquilibriumOptions, LoadingCondition};
use crate::{Error, Mesh, Pose};

/// A body at rest: see [`Controller::rest`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rest {
    /// The body's pose at rest (body frame → world): what to give the engine.
    pub pose: Pose<f64>,
    /// The equilibrium found, of the body's mesh in the frame of its (only) part, or of its
    /// parts merged in the body frame ([`Equilibrium::pose`] is that mesh's pose): draft, heel,
    /// trim, metacentric heights, residuals, whether it is stable.
    pub equilibrium: Equilibrium<f64>,
}

/// The mesh the equilibrium is solved for and its frame in the body's: the only part as it
/// is, or the parts' meshes merged into one in the body frame.
fn body_mesh(parts: &[Part]) -> Result<(Cow<'_, Mesh<f64>>, Pose<f64>), Error> {
    if let [part] = parts {
        return Ok((Cow::Borrowed(&*part.mesh), part.shape_to_body));
    }
    let (mut vertices, mut triangles) = (Vec::new(), Vec::new());
    for part in parts {
        let first = u32::try_from(vertices.len()).map_err(|_| Error::TooManyVertices {
            count: vertices.len(),
        })?;
        let mesh = &part.mesh;
        vertices.extend((0..mesh.vertex_count()).map(|i| part.shape_to_body * mesh.vertex(i)));
        triangles.extend(mesh.triangles().iter().map(|t| t.map(|v| v + first)));
    }
    Ok((
        Cow::Owned(Mesh::new(vertices, triangles)?),
        Pose::identity(),
    ))
}

impl Controller {
    /// Where body `index` comes to rest in the still water of its settings (with waves, the
    /// still level under them), given its mass, gravity scale and center of mass in `state`
    /// (the engine's, at its current pose): the body pose at which the water it displaces
    /// weighs what it weighs (`m·s`, `s` the gravity scale)
    /// and its center of buoyancy lies on the vertical through its center of mass, the stable
    /// attitude (see [`Mesh::equilibrium_with`]). Heel and trim are measured from the current
    /// orientation, whose yaw and horizontal position of the center of mass are kept. `None`
    /// for an unknown `index`.
    ///
    /// An adapter sets the body there, at rest, before the first step.
    ///
    /// A body of several parts is solved as one mesh, its parts merged in the body frame (their
    /// buoyancy adds up as the controller's does).
    ///
    /// # Errors
    /// As [`Mesh::equilibrium_with`]: [`Error::TooHeavyToFloat`] for a body that sinks,
    /// [`Error::InvalidMass`] for a zero mass or a gravity scale that is not positive and
    /// finite, [`Error::NoConvergence`]; and
    /// [`Error::InvalidLoading`] for a mass or center of mass that is negative or not finite,
    /// [`Error::InvalidPose`] for a pose that is not finite; [`Error::InvalidMesh`] when the
    /// parts of a body of several cannot be merged into one closed mesh (they touch along an
    /// edge).
    pub fn rest(&self, index: usize, state: &BodyState) -> Option<Result<Rest, Error>> {
        let body = self.bodies.get(index)?;
        Some((|| {
            let water = self.settings.resolve(&body.options).water;
            // The engine weighs the body at m·g·s (s its gravity scale), as the step does.
            let scale = state.gravity_scale;
            if !(scale.is_finite() && scale > 0.0) {
                return Err(Error::InvalidMass {
                    reason: "the body's gravity scale is not positive and finite: it does not \
                             sink to a rest",
                });
            }
            let (mesh, shape_to_body) = body_mesh(&body.parts)?;
            let world_to_shape = (state.pose * shape_to_body).inverse();
            let center: Point3<f64> = world_to_shape * state.center_of_mass;
            // Heel about the mesh's x axis, or its z axis when x is within 30° of the vertical
            // (as the waterplane's axes are chosen): any horizontal axis finds the same rest.
            let up = world_to_shape.rotation * water.normal().into_inner();
            let axis = if up.x.abs() > 0.866 {
                Vector3::z()
            } else {
                Vector3::x()
            };
            let loading = LoadingCondition::new(center)?
                .with_mass(state.mass * scale)?
                .with_longitudinal_axis(axis)?;
            let options = EquilibriumOptions::default().with_start(state.pose * shape_to_body);
            let equilibrium = mesh.equilibrium_with(&water, &loading, &options)?;
            Ok(Rest {
                pose: equilibrium.pose * shape_to_body.inverse(),
                equilibrium,
            })
        })())
    }
}

#[cfg(test)]
mod tests {
    use alloc::sync::Arc;
    use alloc::vec;

    use nalgebra::{Matrix3, Translation3, UnitQuaternion, Vector3};

    use super::*;
    use crate::controller::{BodyOptions, Command, Motion};
    use crate::mesh::primitives;

    fn state(pose: Pose<f64>, center_of_mass: Point3<f64>, mass: f64) -> BodyState {
        BodyState {
            pose,
            center_of_mass,
            linear_velocity: Vector3::zeros(),
            angular_velocity: Vector3::zeros(),
            mass,
            inverse_mass: Vector3::repeat(1.0 / mass),
            inverse_inertia: Matrix3::identity() * (6.0 / mass),
            gravity_scale: 1.0,
            applied_force: Vector3::zeros(),
            applied_torque: Vector3::zeros(),
            motion: Motion::Dynamic,
            sleeping: false,
        }
    }

    fn block() -> Arc<Mesh<f64>> {
        let (v, t) = primitives::cube::<f64>(2).unwrap();
        Arc::new(
            Mesh::new(v, t)
                .unwrap()
                .scaled(&Vector3::new(4.0, 1.0, 2.0))
                .unwrap(),
        )
    }

    /// A box placed at rest feels its weight back from the controller, and no torque.
    #[test]
    fn a_box_at_rest_is_balanced_by_the_controller() {
        let mut controller = Controller::default();
        // The part sits 0.3 m forward of the body origin, turned a quarter about y.
        let shape_to_body = Pose::from_parts(
            Translation3::new(0.3, 0.0, 0.0),
            UnitQuaternion::from_euler_angles(0.0, core::f64::consts::FRAC_PI_2, 0.0),
        );
        let index = controller
            .add(
                vec![Part {
                    mesh: block(),
                    shape_to_body,
                }],
                BodyOptions::default(),
            )
            .unwrap();
        let mass = 2400.0;
        // Dropped from 3 m, tilted, its center of mass off its centerline.
        let start = Pose::from_parts(
            Translation3::new(1.0, 3.0, -2.0),
            UnitQuaternion::from_euler_angles(0.1, 0.4, -0.05),
        );
        let com_body = Point3::new(0.35, -0.1, 0.12);
        let rest = controller
            .rest(index, &state(start, start * com_body, mass))
            .unwrap()
            .unwrap();
        assert!(rest.equilibrium.stable);
        let at_rest = state(rest.pose, rest.pose * com_body, mass);
        let mut command = [Command::default()];
        controller.step(&[at_rest], 1.0 / 60.0, &mut command);
        let weight = mass * 9.81;
        let force = command[0].add_force.cast::<f64>();
        let torque = command[0].add_torque.cast::<f64>();
        assert!((force - Vector3::new(0.0, weight, 0.0)).norm() < 1e-5 * weight);
        assert!(torque.norm() < 1e-5 * weight * 4.0, "{torque}");
        // Yaw and the horizontal position of the center of mass are kept.
        let com = rest.pose * com_body;
        let com_start = start * com_body;
        assert!((com.x - com_start.x).abs() < 1e-9 && (com.z - com_start.z).abs() < 1e-9);
    }

    #[test]
    fn two_parts_rest_as_one_and_errors_are_reported() {
        let mut controller = Controller::default();
        let hull = |z: f64| Part {
            mesh: block(),
            shape_to_body: Pose::translation(0.0, 0.0, z),
        };
        let index = controller
            .add(vec![hull(-1.5), hull(1.5)], BodyOptions::default())
            .unwrap();
        // A catamaran of two 4 × 1 × 2 boxes; 6.4 t floats them 0.4 m deep.
        let pose = Pose::translation(0.0, 2.0, 0.0);
        let rest = controller
            .rest(index, &state(pose, pose * Point3::origin(), 6400.0))
            .unwrap()
            .unwrap();
        assert!((rest.equilibrium.draft - 0.4).abs() < 1e-9);
        assert!(rest.equilibrium.heel.abs() < 1e-9 && rest.equilibrium.trim.abs() < 1e-9);
        let sinks = state(pose, pose * Point3::origin(), 20_000.0);
        assert!(matches!(
            controller.rest(index, &sinks),
            Some(Err(Error::TooHeavyToFloat { .. }))
        ));
        assert!(controller.rest(7, &sinks).is_none());
    }

    /// The weight is the engine's, `m·g·s`; a body whose mesh x axis is vertical rests too.
    #[test]
    fn the_gravity_scale_weighs_and_any_orientation_rests() {
        let mut controller = Controller::default();
        let index = controller
            .add(
                vec![Part {
                    mesh: block(),
                    shape_to_body: Pose::identity(),
                }],
                BodyOptions::default(),
            )
            .unwrap();
        // 1600 kg at half gravity weighs what 800 kg does: 0.1 m deep (4 × 2 m waterplane).
        let pose = Pose::translation(0.0, 2.0, 0.0);
        let mut halved = state(pose, pose * Point3::origin(), 1600.0);
        halved.gravity_scale = 0.5;
        let rest = controller.rest(index, &halved).unwrap().unwrap();
        assert!(
            (rest.equilibrium.draft - 0.1).abs() < 1e-9,
            "{}",
            rest.equilibrium.draft
        );
        halved.gravity_scale = 0.0;
        assert!(matches!(
            controller.rest(index, &halved),
            Some(Err(Error::InvalidMass { .. }))
        ));
        // Stood on its end (mesh x up): it falls flat, the stable rest of a long box.
        let standing = Pose::from_parts(
            Translation3::new(0.0, 3.0, 0.0),
            UnitQuaternion::from_euler_angles(0.0, 0.0, core::f64::consts::FRAC_PI_2),
        );
        let rest = controller
            .rest(index, &state(standing, standing * Point3::origin(), 800.0))
            .unwrap()
            .unwrap();
        assert!(rest.equilibrium.stable);
        let long_axis = rest.pose.rotation * Vector3::x();
        assert!(long_axis.y.abs() < 1e-6, "{long_axis}");
    }
}
