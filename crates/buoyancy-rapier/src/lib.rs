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
//! let (crate_box, _) = world.insert(
//!     RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 1.0, 0.0)),
//!     ColliderBuilder::cuboid(0.5, 0.5, 0.5).density(500.0),
//! );
//! let mut water = FloatingBodies::new(world.gravity);
//! water.register(crate_box, &world.bodies, &world.colliders, FloatOptions::default()).unwrap();
//! for _ in 0..600 {
//!     water.apply(&mut world.bodies, world.integration_parameters.dt);
//!     world.step();
//! }
//! // Half the cube under water: its center sits at the surface.
//! assert!(world.bodies[crate_box].translation().y.abs() < 0.01);
//! ```
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
//! one factor, so its line of action stays. A body moving freely reaches the terminal velocity of
//! the damping model (where `W = −G`). The scheme assumes the body moves under `G` alone: a light
//! body held by contacts (on the bottom, against a dock in a current) feels less drag than the
//! model says, and part of its net weight taken off while it jitters. Gravity is taken as the
//! water's (`g` against its normal, times the body's gravity scale). A body whose pose, velocity
//! or result is not finite gets no force from the adapter (and the previous one is taken back).

mod convert;
mod error;
mod shapes;

use std::collections::HashMap;

use buoyancy_core::nalgebra::{Matrix3, Point3, Vector3};
use buoyancy_core::{DampingCoefficients, Mesh, Method, Pose, Water};
use rapier3d::math::Vector;
use rapier3d::prelude::{
    ColliderHandle, ColliderSet, RigidBody, RigidBodyHandle, RigidBodySet, RigidBodyType,
};

pub use buoyancy_core;
pub use error::Error;

use convert::{point_to_nalgebra, pose_to_nalgebra, vector_to_nalgebra, vector_to_rapier};
use shapes::{FloatingPart, append_meshes};

/// Which colliders of a body float.
#[derive(Debug, Clone, Default, PartialEq)]
pub enum FloatingColliders {
    /// Every collider attached to the body at registration.
    #[default]
    All,
    /// Only these (each must be attached to the body; repeats count once).
    Only(Vec<ColliderHandle>),
}

/// How one body floats: which colliders, how finely round shapes are meshed, and overrides of
/// the world's method, water and damping.
#[derive(Debug, Clone, PartialEq)]
pub struct FloatOptions {
    /// The colliders that float. Default: all of them.
    pub colliders: FloatingColliders,
    /// Segments around a ball, cylinder, capsule or cone (half as many from pole to pole).
    /// Default 32. Cuboids, convex polyhedra and trimeshes are used exactly.
    pub subdivisions: u32,
    /// This body's method; `None`: the world's ([`FloatingBodies::method`]).
    pub method: Option<Method>,
    /// This body's water; `None`: the world's ([`FloatingBodies::water`]).
    pub water: Option<Water<f64>>,
    /// This body's damping; `None`: the world's ([`FloatingBodies::damping`]).
    pub damping: Option<DampingCoefficients<f64>>,
}

impl Default for FloatOptions {
    fn default() -> Self {
        FloatOptions {
            colliders: FloatingColliders::All,
            subdivisions: 32,
            method: None,
            water: None,
            damping: None,
        }
    }
}

impl FloatOptions {
    /// Only these colliders float.
    pub fn colliders(mut self, colliders: impl IntoIterator<Item = ColliderHandle>) -> Self {
        self.colliders = FloatingColliders::Only(colliders.into_iter().collect());
        self
    }
    /// Segments around round shapes.
    pub fn subdivisions(mut self, subdivisions: u32) -> Self {
        self.subdivisions = subdivisions;
        self
    }
    /// This body's method.
    pub fn method(mut self, method: Method) -> Self {
        self.method = Some(method);
        self
    }
    /// This body's water.
    pub fn water(mut self, water: Water<f64>) -> Self {
        self.water = Some(water);
        self
    }
    /// This body's damping ([`DampingCoefficients::off`] for none).
    pub fn damping(mut self, damping: DampingCoefficients<f64>) -> Self {
        self.damping = Some(damping);
        self
    }
}

/// What the adapter computed and applied for one body at the last [`FloatingBodies::apply`],
/// world frame, SI units, torques about the body's world center of mass.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FloatReport {
    /// Volume under water, m³ (all floating parts).
    pub submerged_volume: f64,
    /// Center of buoyancy, m: the volume-weighted mean of the parts' centers (the projection
    /// of the center of mass on the surface when nothing is under water).
    pub center_of_buoyancy: Point3<f64>,
    /// The body's world center of mass (rapier's), m.
    pub center_of_mass: Point3<f64>,
    /// Buoyant force, N.
    pub buoyancy_force: Vector3<f64>,
    /// Torque of the buoyancy about the center of mass, N·m.
    pub buoyancy_torque: Vector3<f64>,
    /// Damping force as applied, after the semi-implicit step (see [Stability](crate#stability)),
    /// N.
    pub damping_force: Vector3<f64>,
    /// Damping torque as applied, after the semi-implicit step, N·m.
    pub damping_torque: Vector3<f64>,
    /// Wetted area, m².
    pub wetted_area: f64,
    /// Whether a pose, velocity or result was not finite, so that no force was applied. (A
    /// kinematic, fixed or disabled body has an all-zero report with `skipped` false, and keeps
    /// the share it had.)
    pub skipped: bool,
}

/// One registered body.
#[derive(Debug, Clone)]
struct FloatingBody {
    handle: RigidBodyHandle,
    parts: Vec<FloatingPart>,
    options: FloatOptions,
    /// Total volume (m³) and surface area (m²) of the parts, for the body's angular damping.
    volume: f64,
    surface_area: f64,
    /// The force and torque the adapter has added to the body and not taken back yet.
    applied_force: Vector,
    applied_torque: Vector,
    /// The force and torque applied the last time the body was awake: a sleeping body is woken
    /// when the adapter's share has changed enough since.
    awake_force: Vector,
    awake_torque: Vector,
    report: FloatReport,
    /// The force and torque to hold from now on, computed in parallel, applied serially;
    /// `None`: leave the share as it is (a body that is not dynamic, or disabled).
    pending: Option<(Vector, Vector)>,
}

/// The bodies that float in one rapier world, and their water.
///
/// The world's settings (water, method, damping) apply to every body without an override in
/// its [`FloatOptions`].
#[derive(Debug, Clone)]
pub struct FloatingBodies {
    water: Water<f64>,
    method: Method,
    damping: DampingCoefficients<f64>,
    bodies: Vec<FloatingBody>,
    index: HashMap<RigidBodyHandle, usize>,
}

impl FloatingBodies {
    /// No bodies yet; fresh water (ρ = 1000 kg/m³) whose surface passes through the world
    /// origin with its up normal opposite to `gravity` (y up if `gravity` is zero), with
    /// `g = |gravity|`; [`Method::Exact`]; the default [`DampingCoefficients`].
    pub fn new(gravity: Vector) -> Self {
        let g = vector_to_nalgebra(gravity);
        let water = Water::default()
            .with_gravity(g.norm())
            .and_then(|w| {
                if g.norm() > 0.0 {
                    w.with_surface(-g, 0.0)
                } else {
                    Ok(w)
                }
            })
            .unwrap_or_default();
        FloatingBodies {
            water,
            method: Method::Exact,
            damping: DampingCoefficients::default(),
            bodies: Vec::new(),
            index: HashMap::new(),
        }
    }

    /// The world's water.
    pub fn water(&self) -> &Water<f64> {
        &self.water
    }
    /// Sets the world's water (level, normal, density, gravity), e.g.
    /// `fb.water().with_surface(normal, 2.0)?`.
    pub fn set_water(&mut self, water: Water<f64>) {
        self.water = water;
    }
    /// The same world with the surface at `level` m along its normal.
    pub fn with_level(mut self, level: f64) -> Result<Self, Error> {
        self.water = self
            .water
            .with_surface(self.water.normal().into_inner(), level)?;
        Ok(self)
    }
    /// The world's method.
    pub fn method(&self) -> Method {
        self.method
    }
    /// Sets the world's method.
    pub fn set_method(&mut self, method: Method) {
        self.method = method;
    }
    /// The world's damping coefficients.
    pub fn damping(&self) -> &DampingCoefficients<f64> {
        &self.damping
    }
    /// Sets the world's damping coefficients ([`DampingCoefficients::off`] for none).
    pub fn set_damping(&mut self, damping: DampingCoefficients<f64>) {
        self.damping = damping;
    }

    /// Number of registered bodies.
    pub fn len(&self) -> usize {
        self.bodies.len()
    }
    /// Whether no body is registered.
    pub fn is_empty(&self) -> bool {
        self.bodies.is_empty()
    }
    /// Whether `body` is registered.
    pub fn contains(&self, body: RigidBodyHandle) -> bool {
        self.index.contains_key(&body)
    }

    /// Makes `body` float: turns its selected colliders into closed meshes (once) and
    /// remembers them with `options`. Registering a body again replaces its meshes and options
    /// (the force already applied is kept track of).
    ///
    /// # Errors
    /// [`Error::UnknownBody`], [`Error::UnknownCollider`], [`Error::NotAttached`],
    /// [`Error::NothingToFloat`], [`Error::UnsupportedShape`], [`Error::Mesh`] (a trimesh that
    /// is not closed and consistently oriented).
    pub fn register(
        &mut self,
        body: RigidBodyHandle,
        bodies: &RigidBodySet,
        colliders: &ColliderSet,
        options: FloatOptions,
    ) -> Result<(), Error> {
        let rigid_body = bodies.get(body).ok_or(Error::UnknownBody(body))?;
        let selected: Vec<ColliderHandle> = match &options.colliders {
            FloatingColliders::All => rigid_body.colliders().to_vec(),
            FloatingColliders::Only(list) => {
                let mut unique = Vec::with_capacity(list.len());
                for &handle in list {
                    if !unique.contains(&handle) {
                        unique.push(handle);
                    }
                }
                unique
            }
        };
        let mut parts = Vec::new();
        for handle in selected {
            let collider = colliders
                .get(handle)
                .ok_or(Error::UnknownCollider(handle))?;
            let shape_to_body = match (collider.parent(), collider.position_wrt_parent()) {
                (Some(parent), Some(pose)) if parent == body => pose_to_nalgebra(pose),
                _ => {
                    return Err(Error::NotAttached {
                        collider: handle,
                        body,
                    });
                }
            };
            append_meshes(
                handle,
                collider.shape(),
                shape_to_body,
                options.subdivisions,
                &mut parts,
            )?;
        }
        if parts.is_empty() {
            return Err(Error::NothingToFloat(body));
        }
        let volume = parts.iter().map(|p| p.mesh.volume()).sum();
        let surface_area = parts.iter().map(|p| p.mesh.surface_area()).sum();
        if let Some(&i) = self.index.get(&body) {
            let b = &mut self.bodies[i];
            (b.parts, b.options, b.volume, b.surface_area) = (parts, options, volume, surface_area);
        } else {
            self.index.insert(body, self.bodies.len());
            self.bodies.push(FloatingBody {
                handle: body,
                parts,
                options,
                volume,
                surface_area,
                applied_force: Vector::ZERO,
                applied_torque: Vector::ZERO,
                awake_force: Vector::ZERO,
                awake_torque: Vector::ZERO,
                report: FloatReport::default(),
                pending: None,
            });
        }
        Ok(())
    }

    /// Stops `body` from floating and takes back the force and torque the adapter added to it.
    /// Returns whether it was registered.
    pub fn unregister(&mut self, body: RigidBodyHandle, bodies: &mut RigidBodySet) -> bool {
        let Some(i) = self.index.remove(&body) else {
            return false;
        };
        let removed = self.bodies.swap_remove(i);
        if let Some(moved) = self.bodies.get(i) {
            self.index.insert(moved.handle, i);
        }
        if let Some(rb) = bodies.get_mut(body) {
            take_back(rb, removed.applied_force, removed.applied_torque);
        }
        true
    }

    /// Tells the adapter that the application reset the forces and torques of `body`
    /// (`RigidBody::reset_forces` / `reset_torques`), so that its own share is zero now.
    ///
    /// Also the cure for the `f32` drift of the body's accumulated force (see the
    /// [crate documentation](crate)): `reset_forces`, `reset_torques`, re-add the application's own
    /// forces, `forget_applied`; the next [`apply`](Self::apply) adds the whole share again.
    pub fn forget_applied(&mut self, body: RigidBodyHandle) {
        if let Some(&i) = self.index.get(&body) {
            let b = &mut self.bodies[i];
            (b.applied_force, b.applied_torque) = (Vector::ZERO, Vector::ZERO);
        }
    }

    /// The last report of `body`: what was computed and applied at the last
    /// [`apply`](Self::apply).
    pub fn report(&self, body: RigidBodyHandle) -> Option<&FloatReport> {
        self.index.get(&body).map(|&i| &self.bodies[i].report)
    }

    /// The meshes a body floats with (one per shape, in the shape's frame) and their
    /// shape → body poses.
    pub fn meshes(&self, body: RigidBodyHandle) -> impl Iterator<Item = (&Mesh<f64>, &Pose<f64>)> {
        self.index.get(&body).into_iter().flat_map(move |&i| {
            self.bodies[i]
                .parts
                .iter()
                .map(|p| (&p.mesh, &p.shape_to_body))
        })
    }

    /// Computes buoyancy and damping for every registered body at its current pose and
    /// velocity, and sets the body's share of the applied force and torque to it (see the
    /// [crate documentation](crate) on forces the application adds itself). Call it once per
    /// step, before `PhysicsPipeline::step`, with the step's `dt` (s), which the damping's
    /// stability scheme needs (see [Stability](crate#stability)). Bodies removed from `bodies`
    /// are forgotten. Fixed, kinematic and disabled bodies get nothing new: their share is left
    /// as it is (rapier ignores `add_force` on bodies that are not dynamic but keeps their stored
    /// force), and holds again when they are dynamic and enabled again. With the `rayon` feature
    /// the bodies are computed in parallel.
    ///
    /// No allocation once every body has been seen (the meshes are prepared at registration).
    pub fn apply(&mut self, bodies: &mut RigidBodySet, dt: f32) {
        // Forget removed bodies.
        if self.bodies.iter().any(|b| !bodies.contains(b.handle)) {
            self.bodies.retain(|b| bodies.contains(b.handle));
            self.index = self
                .bodies
                .iter()
                .enumerate()
                .map(|(i, b)| (b.handle, i))
                .collect();
        }
        let world = (&self.water, self.method, &self.damping);
        let shared: &RigidBodySet = bodies;
        let compute = |b: &mut FloatingBody| {
            let rb = &shared[b.handle];
            // Force and torque both exactly zero while the adapter's share is not: rapier wiped
            // them (its NaN quarantine does, or `reset_forces` + `reset_torques`).
            let ours = b.applied_force != Vector::ZERO || b.applied_torque != Vector::ZERO;
            if ours
                && rb.is_dynamic()
                && rb.user_force() == Vector::ZERO
                && rb.user_torque() == Vector::ZERO
            {
                (b.applied_force, b.applied_torque) = (Vector::ZERO, Vector::ZERO);
            }
            let (report, wrench) = evaluate(b, rb, world, f64::from(dt));
            b.report = report;
            b.pending = wrench;
        };
        #[cfg(feature = "rayon")]
        {
            use rayon::prelude::*;
            self.bodies.par_iter_mut().for_each(compute);
        }
        #[cfg(not(feature = "rayon"))]
        self.bodies.iter_mut().for_each(compute);

        for b in &mut self.bodies {
            let Some((force, torque)) = b.pending.take() else {
                continue;
            };
            let rb = &mut bodies[b.handle];
            let sleeping = rb.is_sleeping();
            // Wake a sleeping body only for a change that matters (say the water moved), measured
            // from what it felt when it was last awake, so that slow changes add up.
            let g = b.options.water.as_ref().unwrap_or(&self.water).gravity() as f32;
            let weight = rb.mass() * g;
            let size = b.volume.max(0.0).cbrt() as f32;
            let (changed_force, changed_torque) = (force - b.awake_force, torque - b.awake_torque);
            let force_scale = b.awake_force.length() + weight + f32::MIN_POSITIVE;
            let wake = changed_force.length() > 1e-3 * force_scale
                || changed_torque.length() > 1e-3 * (b.awake_torque.length() + force_scale * size);
            let (delta_force, delta_torque) = (force - b.applied_force, torque - b.applied_torque);
            if delta_force != Vector::ZERO || delta_torque != Vector::ZERO {
                rb.add_force(delta_force, wake);
                rb.add_torque(delta_torque, wake);
                (b.applied_force, b.applied_torque) = (force, torque);
            }
            if !sleeping || wake {
                (b.awake_force, b.awake_torque) = (force, torque);
            }
        }
    }
}

/// Takes the adapter's share back off a body. rapier ignores `add_force` on bodies that are not
/// dynamic, so those are made dynamic for the time of the subtraction.
fn take_back(rb: &mut RigidBody, force: Vector, torque: Vector) {
    if force == Vector::ZERO && torque == Vector::ZERO {
        return;
    }
    let body_type = rb.body_type();
    if !body_type.is_dynamic() {
        rb.set_body_type(RigidBodyType::Dynamic, false);
    }
    rb.add_force(-force, false);
    rb.add_torque(-torque, false);
    if !body_type.is_dynamic() {
        rb.set_body_type(body_type, false);
    }
}

/// The generalized mass of a rigid body, `f64`: per-axis inverse mass (zero on locked axes),
/// world inverse inertia (zero rows on locked axes), and world inertia (the locked axes' rows
/// are meaningless: their angular velocity is zero).
fn mass_matrices(rb: &RigidBody) -> (Vector3<f64>, Matrix3<f64>, Matrix3<f64>) {
    let props = rb.mass_properties();
    let i = &props.effective_world_inv_inertia;
    let inv_inertia = Matrix3::new(
        i.m11, i.m12, i.m13, i.m12, i.m22, i.m23, i.m13, i.m23, i.m33,
    )
    .cast::<f64>();
    let mut invertible = inv_inertia;
    for k in 0..3 {
        if invertible[(k, k)] == 0.0 {
            invertible[(k, k)] = 1.0;
        }
    }
    let inertia = invertible.try_inverse().unwrap_or_else(Matrix3::zeros);
    (
        vector_to_nalgebra(props.effective_inv_mass),
        inv_inertia,
        inertia,
    )
}

/// Buoyancy + damping of one body: its report and the force and torque to hold (rapier types,
/// torque about the world center of mass). `None` for bodies that are not dynamic or disabled,
/// zero for anything non-finite.
fn evaluate(
    b: &FloatingBody,
    rb: &RigidBody,
    (world_water, world_method, world_damping): (&Water<f64>, Method, &DampingCoefficients<f64>),
    dt: f64,
) -> (FloatReport, Option<(Vector, Vector)>) {
    let center_of_mass = point_to_nalgebra(rb.center_of_mass());
    let zero = Some((Vector::ZERO, Vector::ZERO));
    let skipped = FloatReport {
        center_of_mass,
        center_of_buoyancy: center_of_mass,
        skipped: true,
        ..Default::default()
    };
    if !rb.is_dynamic() || !rb.is_enabled() {
        return (
            FloatReport {
                skipped: false,
                ..skipped
            },
            None,
        );
    }
    let water = b.options.water.as_ref().unwrap_or(world_water);
    let method = b.options.method.unwrap_or(world_method);
    let damping = b.options.damping.as_ref().unwrap_or(world_damping);
    let body_pose = pose_to_nalgebra(rb.position());
    let velocity = vector_to_nalgebra(rb.linvel());
    let omega = vector_to_nalgebra(rb.angvel());

    // The core's angular damping is per mesh, −f·ρ·V^{5/3}·(a₁ + a₂|ω|)·ω: with several parts,
    // each part's term is replaced by one for the whole body (total volume and wetted fraction).
    let several = b.parts.len() > 1;
    let angular_rate =
        damping.angular_drag_linear() + damping.angular_drag_quadratic() * omega.norm();
    let angular_size = |volume: f64| water.density() * volume.max(0.0).powf(5.0 / 3.0);

    let mut report = FloatReport {
        center_of_mass,
        ..Default::default()
    };
    let mut weighted_center = Vector3::zeros();
    for part in &b.parts {
        let pose = body_pose * part.shape_to_body;
        let Ok(buoyancy) = part.mesh.buoyancy(&pose, water, method) else {
            return (skipped, zero);
        };
        // The core takes the velocity of the mesh's own centroid.
        let centroid_velocity = velocity + omega.cross(&(buoyancy.torque_point - center_of_mass));
        let Ok(drag) = part
            .mesh
            .damping(&pose, &centroid_velocity, &omega, water, damping)
        else {
            return (skipped, zero);
        };
        report.submerged_volume += buoyancy.submerged_volume;
        weighted_center += buoyancy.center_of_buoyancy.coords * buoyancy.submerged_volume;
        report.buoyancy_force += buoyancy.force;
        report.buoyancy_torque += buoyancy.torque_about(&center_of_mass);
        report.damping_force += drag.force;
        report.damping_torque += drag.torque_about(&center_of_mass);
        if several {
            report.damping_torque +=
                omega * (drag.wetted_fraction * angular_size(part.mesh.volume()) * angular_rate);
        }
        report.wetted_area += drag.wetted_area;
    }
    if several && b.surface_area > 0.0 {
        let wetted_fraction = (report.wetted_area / b.surface_area).min(1.0);
        report.damping_torque -= omega * (wetted_fraction * angular_size(b.volume) * angular_rate);
    }
    report.center_of_buoyancy = if report.submerged_volume.abs() > 0.0 {
        Point3::from(weighted_center / report.submerged_volume)
    } else {
        water.project(&center_of_mass)
    };

    // Semi-implicit damping (see the crate documentation): about the current velocity, the
    // damping wrench W = (F, τ) is linearised as W − α·M·Δq̇ (α, 1/s, the damping rate in the
    // metric of the generalized mass M), and solved for the end of the step, with the step's
    // other forces G (buoyancy, gravity, the application's own): W' = (W − α·dt·G)/(1 + α·dt).
    let (inv_mass, inv_inertia, inertia) = mass_matrices(rb);
    let (damping_force, damping_torque) = (report.damping_force, report.damping_torque);
    let relative_velocity = velocity - damping.current();
    // W·M⁻¹W and q̇·M·q̇ (locked axes left out).
    let wrench_norm2 = damping_force.dot(&inv_mass.component_mul(&damping_force))
        + damping_torque.dot(&(inv_inertia * damping_torque));
    let linear_momentum_norm2: f64 = (0..3)
        .filter(|&i| inv_mass[i] > 0.0)
        .map(|i| relative_velocity[i] * relative_velocity[i] / inv_mass[i])
        .sum();
    let velocity_norm2 = linear_momentum_norm2 + omega.dot(&(inertia * omega));
    let rate = if wrench_norm2 > 0.0 && velocity_norm2 > 0.0 {
        (wrench_norm2 / velocity_norm2).sqrt()
    } else {
        0.0
    };
    if rate > 0.0 && dt > 0.0 {
        let gravity =
            -water.normal().into_inner() * (water.gravity() * f64::from(rb.gravity_scale()));
        let own_force = vector_to_nalgebra(rb.user_force() - b.applied_force);
        let own_torque = vector_to_nalgebra(rb.user_torque() - b.applied_torque);
        let mut other_force = report.buoyancy_force + gravity * f64::from(rb.mass()) + own_force;
        for i in 0..3 {
            if inv_mass[i] == 0.0 {
                other_force[i] = 0.0;
            }
        }
        let other_torque = report.buoyancy_torque + own_torque;
        let h = rate * dt;
        report.damping_force = (damping_force - other_force * h) / (1.0 + h);
        report.damping_torque = (damping_torque - other_torque * h) / (1.0 + h);
    }

    let force = report.buoyancy_force + report.damping_force;
    let torque = report.buoyancy_torque + report.damping_torque;
    let (force, torque) = (vector_to_rapier(&force), vector_to_rapier(&torque));
    if !(force.is_finite()
        && torque.is_finite()
        && report.center_of_buoyancy.iter().all(|c| c.is_finite()))
    {
        return (skipped, zero);
    }
    (report, Some((force, torque)))
}
