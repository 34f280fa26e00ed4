//! The avian3d backend: the core's [`Controller`] on avian's bodies, their colliders meshed by
//! [`ShapeMeshes`] (avian's `Collider` holds a parry shape, of the parry version of rapier).
//!
//! # Where the force goes
//! The system runs in avian's `PhysicsSchedule`, after `PhysicsStepSystems::First` and before
//! `PhysicsStepSystems::BroadPhase` ([`BuoyancySystems`]): once per
//! physics step, before the solver, with avian's clock (`Time` is `Time<Physics>` there: the
//! fixed timestep, its pause and time scale). avian clears the forces applied through its
//! [`Forces`] helper after each step, so the plugin applies its whole share every step: the
//! controller's books (the share it adds changes to) are kept here, as an engine that keeps
//! forces would keep them. The application's `ConstantForce` and `ConstantTorque` stay
//! untouched and count as its own forces in the damping's semi-implicit step.
//!
//! # What is read
//! `Position` and `Rotation` (the body frame), `ComputedCenterOfMass`, `LinearVelocity` (of
//! the center of mass) and `AngularVelocity`, `ComputedMass` and `ComputedAngularInertia`
//! (turned to the world, locked axes taken out), `GravityScale`; a body that is not
//! `RigidBody::Dynamic`, or has `RigidBodyDisabled`, gets nothing new; a `Sleeping` one is
//! not woken unless the controller says so.

use std::collections::{HashMap, HashSet};

use avian3d::prelude::*;
use bevy::log::error;
use bevy::prelude::*;
use buoyancy_core::Pose;
use buoyancy_core::controller::{BodyOptions, BodyState, Command, Controller, Motion, Part};
use buoyancy_core::nalgebra::{Matrix3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use buoyancy_rapier::ShapeMeshes;

use crate::floating::Outline;
use crate::{BuoyancySystems, FloatReport, Floating, Water};

/// Adds the avian backend's system to avian's physics step.
pub(crate) fn build(app: &mut App) {
    app.init_resource::<AvianFloating>()
        .configure_sets(
            PhysicsSchedule,
            BuoyancySystems
                .after(PhysicsStepSystems::First)
                .before(PhysicsStepSystems::BroadPhase),
        )
        .add_systems(PhysicsSchedule, float_avian_bodies.in_set(BuoyancySystems));
}

/// The plugin's books for the avian backend: the controller, which entity each of its bodies
/// is, the share each holds, and the entities that could not float (logged once).
#[derive(Resource, Default)]
pub struct AvianFloating {
    controller: Controller,
    entities: Vec<Entity>,
    index: HashMap<Entity, usize>,
    /// The controller's share of each body's force and torque, applied anew every step.
    held: Vec<(Vector3<f32>, Vector3<f32>)>,
    outlines: Vec<Outline>,
    meshes: ShapeMeshes,
    failed: HashSet<Entity>,
    water_error: Option<String>,
    states: Vec<BodyState>,
    commands: Vec<Command>,
}

impl AvianFloating {
    /// The controller (its settings, its bodies' reports by [`AvianFloating::index`]).
    pub fn controller(&self) -> &Controller {
        &self.controller
    }

    /// The controller's number of a floating entity.
    pub fn index(&self, entity: Entity) -> Option<usize> {
        self.index.get(&entity).copied()
    }

    fn remove(&mut self, entity: Entity) {
        let Some(i) = self.index.remove(&entity) else {
            return;
        };
        self.controller.remove(i);
        self.entities.swap_remove(i);
        self.held.swap_remove(i);
        self.outlines.swap_remove(i);
        if let Some(&moved) = self.entities.get(i) {
            self.index.insert(moved, i);
        }
    }

    /// Registers (or re-registers) `entity` with `parts`.
    fn hold(
        &mut self,
        entity: Entity,
        parts: Vec<Part>,
        settings: &Floating,
    ) -> Result<(), String> {
        let options = BodyOptions {
            method: settings.method,
            water: None,
            damping: settings.damping,
            damping_resolution: settings.damping_resolution,
        };
        let outline = Outline::of(parts.iter().map(|p| (p.mesh.as_ref(), &p.shape_to_body)));
        if let Some(&i) = self.index.get(&entity) {
            self.controller
                .replace(i, parts, options)
                .map_err(|e| e.to_string())?;
            self.outlines[i] = outline;
        } else {
            let i = self
                .controller
                .add(parts, options)
                .map_err(|e| e.to_string())?;
            debug_assert_eq!(i, self.entities.len());
            self.index.insert(entity, i);
            self.entities.push(entity);
            self.held.push((Vector3::zeros(), Vector3::zeros()));
            self.outlines.push(outline);
        }
        Ok(())
    }
}

/// What the step reads of a body.
type BodyRead = (
    &'static RigidBody,
    &'static Position,
    &'static Rotation,
    &'static ComputedCenterOfMass,
    &'static LinearVelocity,
    &'static AngularVelocity,
    &'static ComputedMass,
    &'static ComputedAngularInertia,
    Option<&'static GravityScale>,
    Option<&'static LockedAxes>,
    Option<&'static ConstantForce>,
    Option<&'static ConstantTorque>,
    Has<Sleeping>,
    Has<RigidBodyDisabled>,
);

/// One step of every floating body.
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
fn float_avian_bodies(
    mut books: ResMut<AvianFloating>,
    mut water: ResMut<Water>,
    gravity: Option<Res<Gravity>>,
    time: Res<Time>,
    mut floating: Query<(
        Entity,
        Ref<Floating>,
        Has<RigidBody>,
        Option<&RigidBodyColliders>,
        &mut FloatReport,
    )>,
    colliders: Query<(&Collider, &ColliderTransform)>,
    mut bodies: ParamSet<(Query<BodyRead>, Query<Forces>)>,
    mut removed: RemovedComponents<Floating>,
) {
    let books = &mut *books;
    for entity in removed.read() {
        books.remove(entity);
        books.failed.remove(&entity);
    }
    water.follow_gravity(gravity.map_or(Vec3::ZERO, |g| g.0));
    let Some(still) = water.core_or_log(&mut books.water_error) else {
        return;
    };
    // New and changed floating entities.
    for (entity, settings, has_body, body_colliders, mut report) in &mut floating {
        let registered = books.index.contains_key(&entity);
        if !settings.is_changed() && (registered || books.failed.contains(&entity)) {
            continue;
        }
        let parts = if !has_body {
            Err(format!(
                "entity {entity} has Floating but no avian3d RigidBody"
            ))
        } else if let Some(part) = settings.mesh_part() {
            Ok(vec![part])
        } else {
            collider_parts(
                entity,
                body_colliders,
                &colliders,
                &mut books.meshes,
                settings.subdivisions,
            )
        };
        match parts.and_then(|parts| books.hold(entity, parts, &settings)) {
            Ok(()) => {
                books.failed.remove(&entity);
                *report = FloatReport::default();
            }
            Err(e) => {
                let message = format!("buoyancy: {e}; it does not float");
                error!("{message}");
                books.remove(entity);
                books.failed.insert(entity);
                *report = FloatReport::failed(message);
            }
        }
    }
    let dt = time.delta_secs_f64();
    if books.entities.is_empty() || dt <= 0.0 {
        return;
    }
    // Read every body.
    books.states.clear();
    {
        let read = bodies.p0();
        for (i, &entity) in books.entities.iter().enumerate() {
            let state = match read.get(entity) {
                Ok(body) => body_state(body, books.held[i]),
                // Not a whole rigid body this step (components removed): nothing new.
                Err(_) => BodyState {
                    motion: Motion::Inactive,
                    ..body_state_default()
                },
            };
            books.states.push(state);
        }
    }
    books.controller.settings_mut().water = still;
    books.controller.set_surface(water.waves().cloned());
    books.controller.set_pressure(water.pressure);
    books.controller.set_time(water.time());
    books
        .commands
        .resize(books.entities.len(), Command::default());
    books
        .controller
        .step(&books.states, dt, &mut books.commands);
    water.advance(dt);
    // Apply each share whole (avian forgets the forces after every step).
    let mut forces = bodies.p1();
    for (i, &entity) in books.entities.iter().enumerate() {
        let command = books.commands[i];
        let held = &mut books.held[i];
        held.0 += command.add_force;
        held.1 += command.add_torque;
        let state = &books.states[i];
        if state.motion == Motion::Inactive {
            continue;
        }
        let Ok(mut item) = forces.get_mut(entity) else {
            continue;
        };
        let (force, torque) = (vec3(held.0), vec3(held.1));
        // Waking resets avian's sleep timer: only when the controller says so (the force
        // changed by more than 0.1 %), so that a body at rest can fall asleep.
        if !command.wake {
            let mut quiet = item.non_waking();
            quiet.apply_force(force);
            quiet.apply_torque(torque);
        } else {
            item.apply_force(force);
            item.apply_torque(torque);
        }
    }
    // The reports.
    let up = still.normal().into_inner();
    for (entity, _, _, _, mut report) in &mut floating {
        let Some(&i) = books.index.get(&entity) else {
            continue;
        };
        if let Some(last) = books.controller.report(i) {
            let lowest = books.outlines[i].lowest(&books.states[i].pose, &up);
            *report = FloatReport::of(last, books.outlines[i].area, lowest, &still);
        }
    }
}

/// The meshes of a body's colliders, each placed by its `ColliderTransform`.
fn collider_parts(
    entity: Entity,
    body_colliders: Option<&RigidBodyColliders>,
    colliders: &Query<(&Collider, &ColliderTransform)>,
    meshes: &mut ShapeMeshes,
    subdivisions: u32,
) -> Result<Vec<Part>, String> {
    let mut parts = Vec::new();
    for collider in body_colliders.into_iter().flat_map(|c| c.iter()) {
        let Ok((shape, transform)) = colliders.get(collider) else {
            continue;
        };
        meshes
            .append(
                shape.shape_scaled(),
                pose(transform.translation, transform.rotation),
                subdivisions,
                &mut parts,
            )
            .map_err(|e| format!("entity {entity}'s collider {collider}: {e}"))?;
    }
    meshes.prune();
    if parts.is_empty() {
        return Err(format!(
            "entity {entity} has Floating but no collider (and no Floating::mesh)"
        ));
    }
    Ok(parts)
}

/// What the controller reads of an avian body.
fn body_state(
    (
        rb,
        position,
        rotation,
        com,
        v,
        w,
        mass,
        inertia,
        gravity_scale,
        locked,
        force,
        torque,
        sleeping,
        disabled,
    ): bevy::ecs::query::ROQueryItem<'_, '_, BodyRead>,
    held: (Vector3<f32>, Vector3<f32>),
) -> BodyState {
    let pose = pose(position.0, rotation.0);
    let locked = locked.copied().unwrap_or_default();
    let free = |is_locked: bool| if is_locked { 0.0 } else { 1.0 };
    let translation = Vector3::new(
        free(locked.is_translation_x_locked()),
        free(locked.is_translation_y_locked()),
        free(locked.is_translation_z_locked()),
    );
    let rotation_free = Matrix3::from_diagonal(&Vector3::new(
        free(locked.is_rotation_x_locked()),
        free(locked.is_rotation_y_locked()),
        free(locked.is_rotation_z_locked()),
    ));
    let s = inertia.inverse();
    let local = Matrix3::new(
        s.m00, s.m01, s.m02, //
        s.m01, s.m11, s.m12, //
        s.m02, s.m12, s.m22,
    )
    .cast::<f64>();
    let r = pose.rotation.to_rotation_matrix().into_inner();
    let world = rotation_free * (r * local * r.transpose()) * rotation_free;
    let own_force = force.map_or(Vec3::ZERO, |f| f.0);
    let own_torque = torque.map_or(Vec3::ZERO, |t| t.0);
    BodyState {
        pose,
        center_of_mass: pose * Point3::from(vector(com.0)),
        linear_velocity: vector(v.0),
        angular_velocity: vector(w.0),
        mass: f64::from(mass.value()),
        inverse_mass: translation * f64::from(mass.inverse()),
        inverse_inertia: world,
        gravity_scale: f64::from(gravity_scale.map_or(1.0, |g| g.0)),
        applied_force: nalgebra_f32(own_force) + held.0,
        applied_torque: nalgebra_f32(own_torque) + held.1,
        motion: if rb.is_dynamic() && !disabled {
            Motion::Dynamic
        } else {
            Motion::Inactive
        },
        sleeping,
    }
}

fn body_state_default() -> BodyState {
    BodyState {
        pose: Pose::identity(),
        center_of_mass: Point3::origin(),
        linear_velocity: Vector3::zeros(),
        angular_velocity: Vector3::zeros(),
        mass: 0.0,
        inverse_mass: Vector3::zeros(),
        inverse_inertia: Matrix3::zeros(),
        gravity_scale: 1.0,
        applied_force: Vector3::zeros(),
        applied_torque: Vector3::zeros(),
        motion: Motion::Inactive,
        sleeping: false,
    }
}

fn vector(v: Vec3) -> Vector3<f64> {
    Vector3::new(f64::from(v.x), f64::from(v.y), f64::from(v.z))
}

fn nalgebra_f32(v: Vec3) -> Vector3<f32> {
    Vector3::new(v.x, v.y, v.z)
}

fn vec3(v: Vector3<f32>) -> Vec3 {
    Vec3::new(v.x, v.y, v.z)
}

fn pose(translation: Vec3, rotation: Quat) -> Pose<f64> {
    Pose::from_parts(
        Translation3::from(vector(translation)),
        UnitQuaternion::new_normalize(Quaternion::new(
            f64::from(rotation.w),
            f64::from(rotation.x),
            f64::from(rotation.y),
            f64::from(rotation.z),
        )),
    )
}
