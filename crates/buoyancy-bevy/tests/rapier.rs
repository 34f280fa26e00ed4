//! The plugin on bevy_rapier3d: the scenarios of `common`, headless.
#![cfg(feature = "rapier")]

mod common;

use bevy::prelude::*;
use bevy_rapier3d::prelude::*;
use buoyancy_bevy::BuoyancyPlugin;
use common::{Backend, DT, base_app};

struct Rapier;

impl Backend for Rapier {
    fn app() -> App {
        let mut app = App::new();
        base_app(&mut app);
        app.add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
            .insert_resource(TimestepMode::Fixed {
                dt: DT,
                substeps: 1,
            })
            .add_plugins(BuoyancyPlugin::default());
        app.finish();
        app.cleanup();
        app.update(); // the context
        app
    }

    fn spawn_box(
        app: &mut App,
        half: Vec3,
        density: f32,
        at: Transform,
        can_sleep: bool,
    ) -> Entity {
        let sleeping = if can_sleep {
            Sleeping::default()
        } else {
            Sleeping::disabled()
        };
        app.world_mut()
            .spawn((
                RigidBody::Dynamic,
                Collider::cuboid(half.x, half.y, half.z),
                ColliderMassProperties::Density(density),
                ExternalForce::default(),
                sleeping,
                Velocity::default(),
                at,
            ))
            .id()
    }

    fn spawn_loaded_box(
        app: &mut App,
        half: Vec3,
        mass: f32,
        com: Vec3,
        inertia: Vec3,
        at: Transform,
    ) -> Entity {
        app.world_mut()
            .spawn((
                RigidBody::Dynamic,
                Collider::cuboid(half.x, half.y, half.z),
                ColliderMassProperties::MassProperties(MassProperties {
                    local_center_of_mass: com,
                    mass,
                    principal_inertia_local_frame: Quat::IDENTITY,
                    principal_inertia: inertia,
                }),
                Sleeping::disabled(),
                Velocity::default(),
                at,
            ))
            .id()
    }

    fn set_thrust(app: &mut App, body: Entity, force: Vec3) {
        app.world_mut().entity_mut(body).insert(ExternalForce {
            force,
            torque: Vec3::ZERO,
        });
    }

    fn translation(app: &App, body: Entity) -> Vec3 {
        app.world().get::<Transform>(body).unwrap().translation
    }

    fn rotation(app: &App, body: Entity) -> Quat {
        app.world().get::<Transform>(body).unwrap().rotation
    }

    fn linear_velocity(app: &App, body: Entity) -> Vec3 {
        app.world().get::<Velocity>(body).unwrap().linear
    }

    fn sleeping(app: &App, body: Entity) -> bool {
        app.world().get::<Sleeping>(body).unwrap().sleeping
    }
}

#[test]
fn crate_settles_at_its_draft() {
    common::crate_settles_at_its_draft::<Rapier>();
}

#[test]
fn off_centre_load_heels_to_the_wall_sided_angle() {
    common::off_centre_load_heels_to_the_wall_sided_angle::<Rapier>();
}

#[test]
fn body_on_waves_stays_bounded() {
    common::body_on_waves_stays_bounded::<Rapier>();
}

#[test]
fn the_users_thrust_survives() {
    common::the_users_thrust_survives::<Rapier>();
}

#[test]
fn removal_and_despawn_leave_no_force() {
    common::removal_and_despawn_leave_no_force::<Rapier>();
}

#[test]
fn sleeping_body_wakes_for_a_rising_tide() {
    common::sleeping_body_wakes_for_a_rising_tide::<Rapier>();
}

#[test]
fn runs_are_bit_identical() {
    common::runs_are_bit_identical::<Rapier>();
}

#[test]
fn floating_without_a_body_is_reported() {
    common::floating_without_a_body_is_reported::<Rapier>();
}
