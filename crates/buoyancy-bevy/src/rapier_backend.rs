//! The bevy_rapier3d backend: the bodies of each rapier context float with
//! [`buoyancy_rapier::FloatingBodies`], the rapier adapter itself, on the context's own body
//! and collider sets.
//!
//! # Where the force goes
//! The system runs in bevy_rapier's schedule after [`PhysicsSet::SyncBackend`] (which has
//! created the rapier bodies and copied the components into them) and before
//! [`PhysicsSet::StepSimulation`]. The rapier adapter adds the change of its share to the
//! rapier body's force and torque, which rapier keeps; an application's `ExternalForce` stays,
//! because bevy_rapier writes it into the body only when it changes, by resetting the body's
//! forces and adding it: the plugin then forgets its share (the reset wiped it) and adds it
//! whole.
//!
//! # Clock
//! The step's `dt` is the one bevy_rapier steps with: `TimestepMode::Fixed`'s `dt`, or
//! `Variable`'s frame time times its time scale (at most `max_dt`); `Interpolated` steps a
//! variable number of times per frame with the buoyancy of the frame's start, `dt` times its
//! time scale each. Nothing happens while the context's `physics_pipeline_active` is false.

use std::collections::{HashMap, HashSet};

use bevy::ecs::schedule::InternedScheduleLabel;
use bevy::log::error;
use bevy::prelude::*;
use bevy_rapier3d::plugin::{PhysicsSet, RapierConfiguration, TimestepMode};
use bevy_rapier3d::prelude::{
    ExternalForce, RapierContextColliders, RapierContextEntityLink, RapierRigidBodyHandle,
    RapierRigidBodySet, RigidBody,
};
use bevy_rapier3d::rapier::prelude::RigidBodyHandle;
use buoyancy_rapier::{FloatOptions, FloatingBodies};

use crate::floating::Outline;
use crate::{BuoyancySystems, FloatReport, Floating, Water};

/// Adds the rapier backend's system to `schedule` (bevy_rapier's).
pub(crate) fn build(app: &mut App, schedule: InternedScheduleLabel) {
    app.init_resource::<RapierFloating>()
        .configure_sets(
            schedule,
            BuoyancySystems
                .after(PhysicsSet::SyncBackend)
                .before(PhysicsSet::StepSimulation),
        )
        .add_systems(schedule, float_rapier_bodies.in_set(BuoyancySystems));
}

/// The plugin's books for the rapier backend: one rapier adapter per context, which body each
/// floating entity is, and the entities that could not float (logged once).
#[derive(Resource, Default)]
pub struct RapierFloating {
    contexts: HashMap<Entity, FloatingBodies>,
    bodies: HashMap<Entity, Registered>,
    failed: HashSet<Entity>,
    water_error: Option<String>,
}

struct Registered {
    context: Entity,
    handle: RigidBodyHandle,
    outline: Outline,
}

impl RapierFloating {
    /// The rapier adapter of the context entity `context`, if a body floats in it.
    pub fn bodies(&self, context: Entity) -> Option<&FloatingBodies> {
        self.contexts.get(&context)
    }

    /// The rapier body of a floating entity, and its context.
    pub fn handle(&self, entity: Entity) -> Option<(Entity, RigidBodyHandle)> {
        self.bodies.get(&entity).map(|r| (r.context, r.handle))
    }

    /// Takes a body's share back off and forgets it.
    fn unregister(&mut self, entity: Entity, sets: &mut Query<ContextSets>) {
        if let Some(registered) = self.bodies.remove(&entity)
            && let Some(floating) = self.contexts.get_mut(&registered.context)
        {
            match sets.get_mut(registered.context) {
                Ok((_, mut set, _, _)) => {
                    floating.unregister(registered.handle, &mut set.bodies);
                }
                Err(_) => {
                    floating.unregister(registered.handle, &mut Default::default());
                }
            }
        }
    }
}

type ContextSets = (
    Entity,
    &'static mut RapierRigidBodySet,
    &'static RapierContextColliders,
    &'static RapierConfiguration,
);

/// One step of every floating body of every context.
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
fn float_rapier_bodies(
    mut books: ResMut<RapierFloating>,
    mut water: ResMut<Water>,
    timestep: Option<Res<TimestepMode>>,
    time: Res<Time>,
    mut contexts: Query<ContextSets>,
    mut floating: Query<(
        Entity,
        Ref<Floating>,
        Has<RigidBody>,
        Option<&RapierRigidBodyHandle>,
        Option<&RapierContextEntityLink>,
        &mut FloatReport,
    )>,
    changed_forces: Query<Entity, (With<Floating>, Changed<ExternalForce>)>,
    mut removed_floating: RemovedComponents<Floating>,
    mut removed_forces: RemovedComponents<ExternalForce>,
) {
    let books = &mut *books;
    // Removed (or despawned): take the share back off while the rapier body is there.
    for entity in removed_floating.read() {
        books.unregister(entity, &mut contexts);
        books.failed.remove(&entity);
    }
    // The water of this step, from the first active context's gravity.
    let Some(gravity) = contexts
        .iter()
        .next()
        .map(|(_, _, _, config)| config.gravity)
    else {
        return;
    };
    water.follow_gravity(gravity);
    let Some(still) = water.core_or_log(&mut books.water_error) else {
        return;
    };
    // New and changed floating entities.
    for (entity, settings, has_body, handle, link, mut report) in &mut floating {
        let registered = books.bodies.get(&entity);
        let moved = match (registered, handle, link) {
            (Some(r), Some(h), Some(l)) => r.handle != h.0 || r.context != l.0,
            _ => false,
        };
        if registered.is_some() && !settings.is_changed() && !moved {
            continue;
        }
        if !settings.is_changed() && books.failed.contains(&entity) && !moved {
            continue;
        }
        let (Some(handle), Some(link)) = (handle, link) else {
            if !has_body && !books.failed.contains(&entity) {
                let message = format!(
                    "buoyancy: entity {entity} has Floating but no bevy_rapier3d RigidBody; it does not float"
                );
                error!("{message}");
                *report = FloatReport::failed(message);
                books.failed.insert(entity);
            }
            // A body bevy_rapier has not created yet: next frame.
            continue;
        };
        if registered.is_some() {
            books.unregister(entity, &mut contexts);
        }
        let Ok((_, set, colliders, _)) = contexts.get(link.0) else {
            continue;
        };
        let options = FloatOptions {
            subdivisions: settings.subdivisions,
            method: settings.method,
            damping: settings.damping,
            damping_resolution: settings.damping_resolution,
            ..FloatOptions::default()
        };
        if let std::collections::hash_map::Entry::Vacant(slot) = books.contexts.entry(link.0) {
            match FloatingBodies::new(gravity) {
                Ok(mut bodies) => {
                    bodies.set_time(water.time());
                    slot.insert(bodies);
                }
                Err(e) => {
                    let message = format!("buoyancy: entity {entity} cannot float: {e}");
                    error!("{message}");
                    *report = FloatReport::failed(message);
                    books.failed.insert(entity);
                    continue;
                }
            }
        }
        let Some(bodies) = books.contexts.get_mut(&link.0) else {
            continue;
        };
        let result = match settings.mesh_part() {
            Some(part) => bodies.register_parts(handle.0, &set.bodies, vec![part], options),
            None => bodies.register(handle.0, &set.bodies, &colliders.colliders, options),
        };
        match result {
            Ok(()) => {
                let outline = Outline::of(bodies.meshes(handle.0));
                books.bodies.insert(
                    entity,
                    Registered {
                        context: link.0,
                        handle: handle.0,
                        outline,
                    },
                );
                books.failed.remove(&entity);
                *report = FloatReport::default();
            }
            Err(e) => {
                let message = format!("buoyancy: entity {entity} cannot float: {e}");
                error!("{message}");
                *report = FloatReport::failed(message);
                books.failed.insert(entity);
            }
        }
    }
    // bevy_rapier reset the forces of the bodies whose ExternalForce changed or went.
    for entity in changed_forces.iter().chain(removed_forces.read()) {
        if let Some(r) = books.bodies.get(&entity)
            && let Some(bodies) = books.contexts.get_mut(&r.context)
        {
            bodies.forget_applied(r.handle);
        }
    }
    // The step.
    let mut advanced = None;
    for (context, mut set, _, config) in &mut contexts {
        let Some(bodies) = books.contexts.get_mut(&context) else {
            continue;
        };
        let dt = step_dt(timestep.as_deref().copied().unwrap_or_default(), &time);
        if !config.physics_pipeline_active || dt <= 0.0 {
            continue;
        }
        bodies.set_water(still);
        bodies.set_surface(water.waves().cloned());
        bodies.set_pressure(water.pressure);
        bodies.set_time(water.time());
        bodies.apply(&mut set.bodies, dt);
        advanced = Some(f64::from(dt));
    }
    if let Some(dt) = advanced {
        water.advance(dt);
    }
    // The reports.
    let up = still.normal().into_inner();
    for (entity, _, _, _, _, mut report) in &mut floating {
        let Some(r) = books.bodies.get(&entity) else {
            continue;
        };
        let (Some(bodies), Ok((_, set, _, _))) =
            (books.contexts.get(&r.context), contexts.get(r.context))
        else {
            continue;
        };
        let (Some(last), Some(rb)) = (bodies.report(r.handle), set.bodies.get(r.handle)) else {
            continue;
        };
        let pose = pose_of(rb.position());
        *report = FloatReport::of(last, r.outline.area, r.outline.lowest(&pose, &up), &still);
    }
}

/// The `dt` bevy_rapier steps with this frame (see the module documentation).
fn step_dt(mode: TimestepMode, time: &Time) -> f32 {
    match mode {
        TimestepMode::Fixed { dt, .. } => dt,
        TimestepMode::Variable {
            max_dt, time_scale, ..
        } => (time.delta_secs() * time_scale).min(max_dt),
        TimestepMode::Interpolated { dt, time_scale, .. } => dt * time_scale,
    }
}

fn pose_of(pose: &bevy_rapier3d::rapier::math::Pose) -> buoyancy_core::Pose<f64> {
    use buoyancy_core::nalgebra::{Quaternion, Translation3, UnitQuaternion};
    let (t, q) = (pose.translation, pose.rotation);
    buoyancy_core::Pose::from_parts(
        Translation3::new(f64::from(t.x), f64::from(t.y), f64::from(t.z)),
        UnitQuaternion::new_normalize(Quaternion::new(
            f64::from(q.w),
            f64::from(q.x),
            f64::from(q.y),
            f64::from(q.z),
        )),
    )
}
