//! Buoyancy and hydrodynamic damping for [rapier3d](https://rapier.rs) rigid bodies.
//!
//! [`FloatingBodies`] holds the bodies that float, their colliders turned into closed triangle
//! meshes once, and the water. Call [`FloatingBodies::apply`] once per step, before
//! `PhysicsPipeline::step`: it computes, for every registered body, the exact buoyancy of
//! [`buoyancy_core`] and its hydrodynamic [damping](buoyancy_core::damping), and applies their
//! sum as a force and a torque about the body's world center of mass.
//!
//! ```
//! use buoyancy_rapier::{FloatOptions, FloatingBodies};
//! use rapier3d::prelude::*;
//!
//! let mut world = PhysicsWorld::default(); // gravity (0, −9.81, 0): water y up, level 0
//! let (boat, _) = world.insert(
//!     RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 1.0, 0.0)),
//!     ColliderBuilder::cuboid(1.0, 0.1, 0.25).density(500.0), // 2 × 0.2 × 0.5 m, 100 kg
//! );
//! let mut water = FloatingBodies::new(world.gravity)?;
//! water.register(boat, &world.bodies, &world.colliders, FloatOptions::default())?;
//! for _ in 0..600 {
//!     water.apply(&mut world.bodies, world.integration_parameters.dt);
//!     world.step();
//! }
//! // After 10 s the buoyancy carries the weight: half the box under water.
//! let weight = f64::from(world.bodies[boat].mass()) * 9.81;
//! let buoyancy = water.report(boat).unwrap().buoyancy_force.y;
//! assert!((buoyancy / weight - 1.0).abs() < 0.005, "{buoyancy} N against {weight} N");
//! # Ok::<(), buoyancy_rapier::Error>(())
//! ```
//!
//! # Sleeping bodies
//! A sleeping body is woken when the adapter's force or torque on it has changed by more than
//! 0.1 % (of the force plus the body's weight) since it was last awake, so that slow changes,
//! a rising tide, add up. rapier puts a body to sleep once it has moved slower than its activation
//! thresholds for a while (by default 0.05 m/s for 0.5 s), which a floating body still heaving by millimetres does: a body asleep *out of balance*
//! (its net force above 0.1 % of its weight, or its net torque above that times its size) is
//! woken, and settles on, unless it was woken for that at the same pose before (the ground or a
//! joint holds it). See [the controller](buoyancy_core::controller#sleeping-bodies).
//!
//! # Forces, not impulses
//! The adapter applies buoyancy and damping as forces that rapier keeps, and adds or takes back
//! only its own share, rather than as impulses before each step like rapier's vehicle
//! controller. rapier integrates gravity and forces over its solver substeps, but an impulse
//! changes the velocity for the whole step, so it cannot balance gravity: with the default 4
//! substeps a floating body settles with a false sinking velocity of `g·dt·(n−1)/(2n)` (6 cm/s
//! at 60 Hz), 6.4 mm too high on a 1 m cube of density 100 (its draft 6.4 % short), and never
//! at rest or asleep; 17 of this crate's tests fail that way. Forces settle exactly at any
//! substep count and leave the application's own forces in rapier untouched, at the cost of a
//! small record per body.
//!
//! # Forces the application adds itself
//! rapier keeps the forces and torques added to a body (`RigidBody::add_force`) until
//! `RigidBody::reset_forces`. The adapter never resets them: it remembers the force and torque
//! it added at the previous [`apply`](FloatingBodies::apply) and adds only the difference, so the
//! body's accumulated force is always *the application's own forces + this step's buoyancy and
//! damping*. A constant thrust added once stays. If the application calls `reset_forces` or
//! `reset_torques` on a registered body, it must then call [`FloatingBodies::forget_applied`]
//! for it (the adapter's share was wiped too); [`FloatingBodies::unregister`] takes the
//! adapter's share back off (also from a kinematic or fixed body, which it makes dynamic for the
//! time of the subtraction).
//!
//! * **Kinematic, fixed and disabled bodies.** rapier ignores `add_force` on bodies that are not
//!   dynamic but keeps the force they had; the adapter leaves its share as it is on them (and on
//!   disabled bodies), so that a body made kinematic and then dynamic again gets its buoyancy
//!   once, not twice.
//! * **rapier's NaN quarantine** (`PhysicsWorld::quarantine`) zeroes the force and torque of a
//!   body whose state went non-finite inside the step and disables it. The adapter notices a
//!   dynamic body whose force and torque are both exactly zero while its own share is not, and
//!   forgets its share; re-enabling the body gives it the whole buoyancy again. It cannot notice
//!   a reset followed by new forces of the application: call `forget_applied` then.
//! * **`f32` drift.** rapier stores the force in `f32`, and adding a difference every step rounds
//!   each time: the application's share drifts by about `1e-7·|F|` per step at worst, a random
//!   walk in practice (≈ `1e-7·|F|·√steps`, 0.3 N on 5 kN after a million steps). To start
//!   afresh: `reset_forces`, `reset_torques`, re-add the application's own forces, and call
//!   `forget_applied`.
//!
//! # Frames and units
//! Water, forces and torques are in rapier's world frame, SI units. Meshes are in the frame of
//! their (sub-)shape, placed on the body by the collider's `position_wrt_parent`. Buoyancy and
//! damping are computed in `f64` and applied in `f32`.
//!
//! # Bodies of several parts
//! A body with several floating colliders, or a compound collider, floats with one mesh per
//! (sub-)shape (a collider listed twice in [`FloatingColliders::Only`] counts once). Buoyancy
//! and pressure drag add up over the parts. The angular damping of the core,
//! `−f·ρ·V^{5/3}·(a₁ + a₂|ω|)·ω`, is computed once for the whole body, with `V` the total volume
//! of the parts and `f` their total wetted area over their total surface area (surfaces where
//! parts touch or overlap count), so that splitting a shape into parts does not change it.
//!
//! # Stability
//! The damping is made semi-implicit, so that a light body (large drag for its mass) and a body
//! dropped fast into the water neither overshoot nor oscillate. About the current velocity
//! `q̇ = (v − v_water, ω)`, the damping wrench `W = (F, τ)` of the core is linearised as
//! `W − α·M·Δq̇`, with `M` the body's mass and inertia and `α = √(W·M⁻¹W / q̇·M·q̇)` (1/s), and
//! taken at the end of the step, given the step's other forces `G` (buoyancy, gravity, the
//! application's own forces; not contacts or joints):
//!
//! ```text
//! W' = (W − α·dt·G) / (1 + α·dt)
//! ```
//!
//! When buoyancy, weight and the application's forces balance (`G = 0`), `W'` is `W` scaled by
//! one factor, so its line of action stays. Where that one rate would throw a direction of
//! motion back faster than it came (a direction much stiffer than the motion as a whole, such
//! as a fast spin under a strong angular damping while the body sinks fast), the damping is
//! taken implicitly through its stiffness `K = −∂W/∂q̇` instead, each direction at its own rate
//! (see the core's [`controller`](buoyancy_core::controller) documentation, "Stability"). A body
//! moving freely reaches the terminal velocity of the damping model (where `W = −G`). The scheme assumes the body moves under `G` alone: a light
//! body held by contacts (on the bottom, against a dock in a current) feels less drag than the
//! model says, and part of its net weight taken off while it jitters. Gravity is taken as the
//! water's (`g` against its normal, times the body's gravity scale). A body whose pose, velocity
//! or result is not finite gets no force from the adapter (and the previous one is taken back);
//! its report's [`outcome`](FloatReport::outcome) is [`Outcome::NotFinite`].

mod body_parts;
mod convert;
mod error;
mod floating_bodies;
mod options;
mod shapes;

pub use buoyancy_core;
pub use buoyancy_core::controller::{DampingResolution, FloatReport, Outcome, Rest};
pub use error::Error;
pub use floating_bodies::{FloatingBodies, body_state};
pub use options::{FloatOptions, FloatingColliders};
pub use shapes::{ShapeError, ShapeMeshes};
