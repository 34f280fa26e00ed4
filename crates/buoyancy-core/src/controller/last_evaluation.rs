//! A body's last evaluation in still water and what it was made from, so that a step whose
//! inputs are the same (a body asleep, its pose held by the engine) takes it again instead of
//! computing it: the evaluation is deterministic, so the result is the same to the bit.

use nalgebra::Vector3;

use super::evaluation::Evaluation;
use super::settings::Settings;
use super::share::AppliedShare;
use super::state::BodyState;

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
mod tests {
    use nalgebra::{Matrix3, Point3};

    use super::*;
    use crate::controller::report::FloatReport;
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
