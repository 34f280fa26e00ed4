//! A [Bevy](https://bevyengine.org) plugin that makes game objects float: the exact buoyancy
//! and hydrodynamic damping of [`buoyancy_core`], on
//! [bevy_rapier3d](https://docs.rs/bevy_rapier3d) (feature `rapier`) or
//! [avian3d](https://docs.rs/avian3d) (feature `avian`).
//!
//! Three lines make an entity float: add the plugin (after the physics plugin), and put
//! [`Floating`] on an entity that has a rigid body and a collider.
//!
//! ```no_run
//! # #[cfg(feature = "rapier")] {
//! use bevy::prelude::*;
//! use bevy_rapier3d::prelude::*;
//! use buoyancy_bevy::{BuoyancyPlugin, Floating};
//!
//! App::new()
//!     .add_plugins((MinimalPlugins, RapierPhysicsPlugin::<NoUserData>::default()))
//!     .add_plugins(BuoyancyPlugin::default())
//!     .add_systems(Startup, |mut commands: Commands| {
//!         commands.spawn((
//!             RigidBody::Dynamic,
//!             Collider::cuboid(1.0, 0.25, 0.5),
//!             ColliderMassProperties::Density(500.0),
//!             Transform::from_xyz(0.0, 2.0, 0.0),
//!             Floating::default(),
//!         ));
//!     })
//!     .run();
//! # }
//! ```
//!
//! # What it does
//! * **The water** is the [`Water`] resource: density, still level, up (opposite to the
//!   physics gravity unless set) and waves (any [`WaterSurface`](buoyancy_core::water::WaterSurface)
//!   of the core: Airy waves, a JONSWAP sea, Gerstner waves, a height grid), on the physics clock.
//!   [`Water::elevation`] and [`Water::normal`] give the surface the bodies feel, for drawing the
//!   sea and for gameplay.
//! * **The bodies** are the entities with [`Floating`]: their colliders (child colliders and
//!   compound shapes included) are meshed once, as `buoyancy-rapier` meshes them, or they float
//!   with the component's mesh. Mass, center of mass and inertia are the backend's.
//! * **Each physics step**, before the backend integrates, the core's
//!   [`Controller`](buoyancy_core::controller::Controller) computes every body's buoyancy and
//!   damping from the backend's poses and velocities, semi-implicitly, and the plugin applies
//!   the wrench through the backend: the application's own forces stay. Sleeping bodies stay
//!   asleep until the water moves under them. Removing [`Floating`] or despawning takes the
//!   buoyancy off.
//! * **[`FloatReport`]**, inserted with [`Floating`], says what the water did at the last
//!   step: submerged volume, wetted fraction, draft.
//! * **Bad input** (an entity without a rigid body, a shape that cannot be meshed, an open
//!   mesh, invalid water) is logged once with the entity, written into its [`FloatReport`], and
//!   that entity left alone; never a panic.
//!
//! # Schedules
//! * rapier: bevy_rapier's schedule (`PostUpdate`, or the one given to
//!   `RapierPhysicsPlugin::in_schedule`: give [`BuoyancyPlugin::in_schedule`] the same), after
//!   `PhysicsSet::SyncBackend` and before `PhysicsSet::StepSimulation`.
//! * avian: avian's `PhysicsSchedule`, after `PhysicsStepSystems::First`: once per physics
//!   step, on avian's clock (fixed timestep, pause, time scale).
//!
//! Both in [`BuoyancySystems`].
//!
//! # Frames and units
//! World frame, SI units; a [`Floating::mesh`] is in the rigid body's frame (its `Transform`'s
//! origin, not its center of mass). Computed in `f64`, applied in the engines' `f32`.

mod floating;
mod water;

#[cfg(feature = "avian")]
pub mod avian_backend;
#[cfg(feature = "rapier")]
pub mod rapier_backend;

pub use floating::{FloatReport, Floating};
pub use water::Water;

pub use buoyancy_core;

use bevy::app::{App, Plugin, PostUpdate};
use bevy::ecs::schedule::{InternedScheduleLabel, ScheduleLabel, SystemSet};

/// The plugin's system (one per backend), in the physics schedule before the step: order
/// systems that read [`FloatReport`] or write [`Water`] against it.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct BuoyancySystems;

/// Makes the entities with [`Floating`] float in the [`Water`] resource (inserted with its
/// defaults if the app has none). Add it after the physics plugin.
pub struct BuoyancyPlugin {
    /// The schedule bevy_rapier runs in (default `PostUpdate`, bevy_rapier's); avian's bodies
    /// are stepped in avian's own `PhysicsSchedule` whatever this is.
    pub schedule: InternedScheduleLabel,
}

impl Default for BuoyancyPlugin {
    fn default() -> Self {
        BuoyancyPlugin {
            schedule: PostUpdate.intern(),
        }
    }
}

impl BuoyancyPlugin {
    /// The plugin for a bevy_rapier that runs in `schedule`
    /// (`RapierPhysicsPlugin::in_schedule(schedule)`, e.g. `FixedUpdate`).
    pub fn in_schedule(schedule: impl ScheduleLabel) -> Self {
        BuoyancyPlugin {
            schedule: schedule.intern(),
        }
    }
}

impl Plugin for BuoyancyPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<Water>();
        #[cfg(feature = "rapier")]
        rapier_backend::build(app, self.schedule);
        #[cfg(feature = "avian")]
        avian_backend::build(app);
        #[cfg(not(any(feature = "rapier", feature = "avian")))]
        let _ = app;
    }
}
