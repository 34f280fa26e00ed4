//! One floating body: its meshes and own settings ([`Part`], `FloatingBody`), the controller's
//! share of its force and torque (`AppliedShare`: what it added to the engine and has not taken
//! back, see [the controller](super#forces-the-application-adds-itself)), what evaluating it
//! gives (`Evaluation`), and its last evaluation in still water with what it was made from
//! (`LastEvaluation`), so that a step whose inputs are the same (a body asleep, its pose held
//! by the engine) takes it again instead of computing it: the evaluation is deterministic, so
//! the result is the same to the bit.

use alloc::sync::Arc;
use alloc::vec::Vec;

use nalgebra::{Point3, Vector3};

use super::settings::{BodyOptions, DampingResolution, Settings};
use super::state::{BodyState, Command, FloatReport, Motion, Outcome};
use crate::mesh::ReducedMesh;
use crate::{Error, Mesh, Pose};

/// One closed mesh of a body, placed on it: a shape's mesh in the shape's frame, and the pose
/// of that frame in the body's frame. Bodies of the same shape share one mesh.
#[derive(Debug, Clone)]
pub struct Part {
    /// The shape's mesh, in the shape's frame.
    pub mesh: Arc<Mesh<f64>>,
    /// Shape frame → body frame.
    pub shape_to_body: Pose<f64>,
}

/// One registered body.
#[derive(Debug, Clone)]
pub(crate) struct FloatingBody {
    pub parts: Vec<Part>,
    pub options: BodyOptions,
    /// The resolution `reduced` was built with.
    pub resolution: DampingResolution,
    /// Per part, the reduced copy its pressure drag is integrated over, `None`: its own mesh.
    pub reduced: Vec<Option<Arc<ReducedMesh<f64>>>>,
    /// Total volume (m³) and surface area (m²) of the parts, for the body's angular damping.
    pub volume: f64,
    pub surface_area: f64,
    pub share: AppliedShare,
    pub report: FloatReport,
    /// The last evaluation in still water, taken again for the same inputs.
    pub last: Option<LastEvaluation>,
}

impl FloatingBody {
    /// A body of `parts`, nothing applied yet, its pressure drag integrated over the parts'
    /// own meshes until the controller gives it reduced copies.
    ///
    /// # Errors
    /// [`Error::EmptyBody`] for no parts.
    pub fn new(parts: Vec<Part>, options: BodyOptions) -> Result<Self, Error> {
        if parts.is_empty() {
            return Err(Error::EmptyBody);
        }
        let volume = parts.iter().map(|p| p.mesh.volume()).sum();
        let surface_area = parts.iter().map(|p| p.mesh.surface_area()).sum();
        Ok(FloatingBody {
            reduced: alloc::vec![None; parts.len()],
            parts,
            options,
            resolution: DampingResolution::Full,
            volume,
            surface_area,
            share: AppliedShare::default(),
            report: FloatReport::default(),
            last: None,
        })
    }

    /// The body's length scale, m: the cube root of its volume.
    pub fn size(&self) -> f64 {
        libm::cbrt(self.volume.max(0.0))
    }

    /// The wetted fraction `f` of the body's angular damping for its parts' total
    /// `wetted_area` (m²): over their total surface area, at most 1; `None` for a body of no
    /// area.
    pub fn wetted_fraction(&self, wetted_area: f64) -> Option<f64> {
        (self.surface_area > 0.0).then(|| (wetted_area / self.surface_area).min(1.0))
    }
}

/// What evaluating one body at one step gives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Evaluation {
    /// The body is not dynamic: nothing computed, its share stays as it is.
    Inactive,
    /// A pose, velocity or result was not finite: its share becomes zero.
    NotFinite,
    /// The query was refused (a method that assumes a flat surface under waves, the
    /// Froude–Krylov pressure on a surface that is not Airy waves): its share becomes zero.
    Unsupported,
    /// Its share becomes this force and torque (world frame, the torque about the center of
    /// mass); `report` says what was computed.
    Floating {
        report: FloatReport,
        force: Vector3<f32>,
        torque: Vector3<f32>,
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
            Evaluation::Unsupported => {
                FloatReport::without_forces(center_of_mass, Outcome::Unsupported)
            }
            Evaluation::Floating { report, .. } => *report,
        }
    }
}

/// An evaluation and its inputs: the body's state, its settings, the step and the controller's
/// share of the body's force and torque (the evaluation takes the application's own forces as
/// the engine's minus the share).
#[derive(Debug, Clone, Copy)]
pub(crate) struct LastEvaluation {
    state: BodyState,
    settings: Settings,
    dt: f64,
    share: (Vector3<f32>, Vector3<f32>),
    evaluation: Evaluation,
}

impl LastEvaluation {
    /// `evaluation`, made from these inputs.
    pub fn new(
        state: &BodyState,
        settings: &Settings,
        dt: f64,
        share: &AppliedShare,
        evaluation: Evaluation,
    ) -> Self {
        LastEvaluation {
            state: *state,
            settings: *settings,
            dt,
            share: (share.force, share.torque),
            evaluation,
        }
    }

    /// The evaluation, if it was made from these inputs (compared exactly: a NaN anywhere
    /// compares unequal, and the body is evaluated again).
    pub fn of(
        &self,
        state: &BodyState,
        settings: &Settings,
        dt: f64,
        share: &AppliedShare,
    ) -> Option<Evaluation> {
        (self.state == *state
            && self.settings == *settings
            && self.dt == dt
            && self.share == (share.force, share.torque))
            .then_some(self.evaluation)
    }
}

#[cfg(test)]
mod last_evaluation_tests {
    use nalgebra::{Matrix3, Point3};

    use super::*;
    use crate::controller::state::FloatReport;
    use crate::controller::state::Motion;
    use crate::{Pose, Water};

    fn state() -> BodyState {
        BodyState {
            pose: Pose::identity(),
            center_of_mass: Point3::origin(),
            linear_velocity: Vector3::zeros(),
            angular_velocity: Vector3::zeros(),
            mass: 500.0,
            inverse_mass: Vector3::repeat(1.0 / 500.0),
            inverse_inertia: Matrix3::identity() * (6.0 / 500.0),
            gravity_scale: 1.0,
            applied_force: Vector3::new(0.0, 4905.0, 0.0),
            applied_torque: Vector3::zeros(),
            motion: Motion::Dynamic,
            sleeping: true,
        }
    }

    /// Taken again for the very same inputs only: any change of the state, the settings, the
    /// step or the share, or a NaN, asks for a new evaluation.
    #[test]
    fn taken_again_for_the_same_inputs_only() {
        let (settings, share) = (Settings::default(), AppliedShare::default());
        let evaluation = Evaluation::Floating {
            report: FloatReport::default(),
            force: Vector3::new(0.0, 4905.0, 0.0),
            torque: Vector3::zeros(),
        };
        let last = LastEvaluation::new(&state(), &settings, 0.1, &share, evaluation);
        assert_eq!(last.of(&state(), &settings, 0.1, &share), Some(evaluation));
        let changed_states = [
            BodyState {
                sleeping: false,
                ..state()
            },
            BodyState {
                linear_velocity: Vector3::new(0.0, 1e-300, 0.0),
                ..state()
            },
            BodyState {
                applied_force: Vector3::new(0.0, 4905.001, 0.0),
                ..state()
            },
            BodyState {
                gravity_scale: f64::NAN,
                ..state()
            },
        ];
        for changed in changed_states {
            assert_eq!(
                last.of(&changed, &settings, 0.1, &share),
                None,
                "{changed:?}"
            );
        }
        let denser = Settings {
            water: Water::default().with_density(1025.0).unwrap(),
            ..settings
        };
        assert_eq!(last.of(&state(), &denser, 0.1, &share), None);
        assert_eq!(last.of(&state(), &settings, 0.2, &share), None);
        let mut held = share;
        held.force.y = 1.0;
        assert_eq!(last.of(&state(), &settings, 0.1, &held), None);
        let nan = LastEvaluation::new(&state(), &settings, f64::NAN, &share, evaluation);
        assert_eq!(nan.of(&state(), &settings, f64::NAN, &share), None);
    }
}

/// A sleeping body is out of balance when its net force (the controller's share, the
/// application's own forces and its weight) exceeds this fraction of its weight, or its net
/// torque this fraction of its weight times its size.
const BALANCE_TOLERANCE: f32 = 1e-3;

/// The force (N) and torque (N·m, about the center of mass) the controller has added to a body
/// and not taken back, in the engine's `f32`, world frame, and what it held the last time the
/// body was awake.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct AppliedShare {
    pub force: Vector3<f32>,
    pub torque: Vector3<f32>,
    /// The buoyancy (the share without damping) when the body was last awake: a sleeping body
    /// is woken when it has changed enough since, so that slow changes (a rising tide) add up.
    awake_force: Vector3<f32>,
    awake_torque: Vector3<f32>,
    /// The pose at which the body was last woken for being asleep out of balance.
    woken_out_of_balance_at: Option<Pose<f64>>,
}

impl AppliedShare {
    /// The share is zero from now on (the body's forces were reset).
    pub fn forget(&mut self) {
        (self.force, self.torque) = (Vector3::zeros(), Vector3::zeros());
    }

    /// Forgets the share if the engine wiped it: a dynamic body whose force and torque are both
    /// exactly zero while the share is not (rapier's NaN quarantine, or a reset of both).
    pub fn forget_if_wiped(&mut self, state: &BodyState) {
        let ours = self.force != Vector3::zeros() || self.torque != Vector3::zeros();
        if ours
            && state.motion == Motion::Dynamic
            && state.applied_force == Vector3::zeros()
            && state.applied_torque == Vector3::zeros()
        {
            self.forget();
        }
    }

    /// Makes the share `force` and `torque`: the command adds the difference.
    ///
    /// Whether a sleeping body is woken is decided on `buoyancy` (force and torque), the share
    /// without the damping: what the water does to a body at rest. It is woken when that
    /// differs from what it was when the body was last awake by more than 0.1 % of that force
    /// plus the body's weight (`gravity`, m/s², world frame, times its mass), or the torque by
    /// more than 0.1 % of that torque plus the same force scale times `size` (m, the body's
    /// length scale).
    ///
    /// It is woken too when the engine put it to sleep out of balance (see
    /// [the controller](super#sleeping-bodies)), unless it was woken for that at the same pose
    /// before: then something the controller does not see holds it (the ground, a joint).
    pub fn hold(
        &mut self,
        state: &BodyState,
        (force, torque): (Vector3<f32>, Vector3<f32>),
        buoyancy: (Vector3<f32>, Vector3<f32>),
        gravity: Vector3<f32>,
        size: f32,
    ) -> Command {
        let weight = state.mass as f32 * gravity.norm();
        let mut command = Command {
            add_force: force - self.force,
            add_torque: torque - self.torque,
            wake: false,
        };
        if state.sleeping && state.motion == Motion::Dynamic {
            let (changed_force, changed_torque) = (
                buoyancy.0 - self.awake_force,
                buoyancy.1 - self.awake_torque,
            );
            let force_scale = self.awake_force.norm() + weight + f32::MIN_POSITIVE;
            // Changed (and something to add: nothing to wake the body for otherwise).
            command.wake = command.adds_anything()
                && (changed_force.norm() > 1e-3 * force_scale
                    || changed_torque.norm()
                        > 1e-3 * (self.awake_torque.norm() + force_scale * size));
            if !command.wake {
                // Out of balance: the engine's forces besides the share are the application's.
                let net_force = buoyancy.0
                    + (state.applied_force - self.force)
                    + gravity * (state.mass * state.gravity_scale) as f32;
                let net_torque = buoyancy.1 + (state.applied_torque - self.torque);
                let scale = weight + f32::MIN_POSITIVE;
                let out_of_balance = net_force.norm() > BALANCE_TOLERANCE * scale
                    || net_torque.norm() > BALANCE_TOLERANCE * scale * size;
                let held_there = self
                    .woken_out_of_balance_at
                    .is_some_and(|pose| same_pose(&pose, &state.pose, f64::from(size)));
                if out_of_balance && !held_there {
                    command.wake = true;
                    self.woken_out_of_balance_at = Some(state.pose);
                }
            }
        }
        if command.adds_anything() {
            (self.force, self.torque) = (force, torque);
        }
        if !state.sleeping || command.wake {
            (self.awake_force, self.awake_torque) = buoyancy;
        }
        command
    }

    /// The command that takes the share back off the body (the engine must apply it even to a
    /// body that is not dynamic: rapier's adapter makes the body dynamic for that time).
    pub fn take_back(&self) -> Command {
        Command {
            add_force: -self.force,
            add_torque: -self.torque,
            wake: false,
        }
    }
}

/// Whether `a` and `b` are the same pose to 1e-4 of `size` (m) and 1e-4 rad.
fn same_pose(a: &Pose<f64>, b: &Pose<f64>, size: f64) -> bool {
    (a.translation.vector - b.translation.vector).norm() <= 1e-4 * size
        && a.rotation.angle_to(&b.rotation) <= 1e-4
}
