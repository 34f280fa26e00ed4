//! The plugin on avian3d: the scenarios of `common`, headless.
#![cfg(feature = "avian")]

mod common;

use avian3d::prelude::*;
use bevy::prelude::*;
use buoyancy_bevy::BuoyancyPlugin;
use common::{Backend, DT, base_app};

struct Avian;

impl Backend for Avian {
    fn app() -> App {
        let mut app = App::new();
        base_app(&mut app);
        app.add_plugins(PhysicsPlugins::default())
            .insert_resource(Time::<Fixed>::from_seconds(f64::from(DT)))
            .add_plugins(BuoyancyPlugin::default());
        app.finish();
        app.cleanup();
        app.update();
        app
    }

    fn spawn_box(
        app: &mut App,
        half: Vec3,
        density: f32,
        at: Transform,
        can_sleep: bool,
    ) -> Entity {
        let mut body = app.world_mut().spawn((
            RigidBody::Dynamic,
            Collider::cuboid(2.0 * half.x, 2.0 * half.y, 2.0 * half.z),
            ColliderDensity(density),
            at,
        ));
        if !can_sleep {
            body.insert(SleepingDisabled);
        }
        body.id()
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
                Collider::cuboid(2.0 * half.x, 2.0 * half.y, 2.0 * half.z),
                Mass(mass),
                CenterOfMass(com),
                AngularInertia::new(inertia),
                NoAutoMass,
                NoAutoCenterOfMass,
                NoAutoAngularInertia,
                SleepingDisabled,
                at,
            ))
            .id()
    }

    fn set_thrust(app: &mut App, body: Entity, force: Vec3) {
        app.world_mut()
            .entity_mut(body)
            .insert(ConstantForce(force));
    }

    fn translation(app: &App, body: Entity) -> Vec3 {
        app.world().get::<Position>(body).unwrap().0
    }

    fn rotation(app: &App, body: Entity) -> Quat {
        app.world().get::<Rotation>(body).unwrap().0
    }

    fn linear_velocity(app: &App, body: Entity) -> Vec3 {
        app.world().get::<LinearVelocity>(body).unwrap().0
    }

    fn sleeping(app: &App, body: Entity) -> bool {
        app.world().get::<Sleeping>(body).is_some()
    }
}

#[test]
fn crate_settles_at_its_draft() {
    common::crate_settles_at_its_draft::<Avian>();
}

#[test]
fn off_centre_load_heels_to_the_wall_sided_angle() {
    common::off_centre_load_heels_to_the_wall_sided_angle::<Avian>();
}

#[test]
fn body_on_waves_stays_bounded() {
    common::body_on_waves_stays_bounded::<Avian>();
}

#[test]
fn the_users_thrust_survives() {
    common::the_users_thrust_survives::<Avian>();
}

#[test]
fn removal_and_despawn_leave_no_force() {
    common::removal_and_despawn_leave_no_force::<Avian>();
}

#[test]
fn sleeping_body_wakes_for_a_rising_tide() {
    common::sleeping_body_wakes_for_a_rising_tide::<Avian>();
}

#[test]
fn runs_are_bit_identical() {
    common::runs_are_bit_identical::<Avian>();
}

#[test]
fn floating_without_a_body_is_reported() {
    common::floating_without_a_body_is_reported::<Avian>();
}
