//! The bodies that float in one rapier world, and their water.

use std::collections::HashMap;

use buoyancy_core::controller::{
    BodyOptions, BodyState, Command, Controller, DampingResolution, FloatReport, Motion, Part,
    Rest, Settings, SharedSurface,
};
use buoyancy_core::nalgebra::Matrix3;
use buoyancy_core::query::Pressure;
use buoyancy_core::{DampingCoefficients, Mesh, Method, Pose, Water};
use rapier3d::math::Vector;
use rapier3d::prelude::{ColliderSet, RigidBody, RigidBodyHandle, RigidBodySet, RigidBodyType};

use crate::body_parts::mesh_colliders;
use crate::convert::{point_to_nalgebra, pose_from_nalgebra, pose_to_nalgebra, vector_to_nalgebra};
use crate::shapes::ShapeMeshes;
use crate::{Error, FloatOptions};

/// The bodies that float in one rapier world, and their water: rapier's glue over the core's
/// [`Controller`], which keeps the books (see the [crate documentation](crate)).
///
/// The world's settings (water, method, damping) apply to every body without an override in
/// its [`FloatOptions`].
#[derive(Debug, Clone)]
pub struct FloatingBodies {
    controller: Controller,
    /// The body of each of the controller's numbers, and back.
    handles: Vec<RigidBodyHandle>,
    index: HashMap<RigidBodyHandle, usize>,
    /// Each step's states and commands, kept so that a step does not allocate.
    states: Vec<BodyState>,
    commands: Vec<Command>,
    /// One mesh per rapier shape, shared by the bodies whose colliders share it.
    meshes: ShapeMeshes,
}

impl FloatingBodies {
    /// No bodies yet; fresh water (ρ = 1000 kg/m³) whose surface passes through the world
    /// origin with its up normal opposite to `gravity` (m/s², world frame; y up if `gravity`
    /// is zero), with `g = |gravity|`; [`Method::Exact`]; the default [`DampingCoefficients`].
    ///
    /// # Errors
    /// [`Error::InvalidGravity`] when a component of `gravity` is NaN or infinite.
    pub fn new(gravity: Vector) -> Result<Self, Error> {
        if !gravity.is_finite() {
            return Err(Error::InvalidGravity(gravity));
        }
        let g = vector_to_nalgebra(gravity);
        let mut water = Water::default().with_gravity(g.norm())?;
        if g.norm() > 0.0 {
            water = water.with_surface(-g, 0.0)?;
        }
        Ok(FloatingBodies {
            controller: Controller::new(Settings {
                water,
                method: Method::Exact,
                damping: DampingCoefficients::default(),
            }),
            handles: Vec::new(),
            index: HashMap::new(),
            states: Vec::new(),
            commands: Vec::new(),
            meshes: ShapeMeshes::default(),
        })
    }

    /// The world's water.
    pub fn water(&self) -> &Water<f64> {
        &self.controller.settings().water
    }
    /// Sets the world's water (level, normal, density, gravity), e.g.
    /// `fb.water().with_surface(normal, 2.0)?`.
    pub fn set_water(&mut self, water: Water<f64>) {
        self.controller.settings_mut().water = water;
    }
    /// The same world with the surface at `level` m along its normal.
    pub fn with_level(mut self, level: f64) -> Result<Self, Error> {
        let water = self.water();
        let water = water.with_surface(water.normal().into_inner(), level)?;
        self.set_water(water);
        Ok(self)
    }
    /// The world's method.
    pub fn method(&self) -> Method {
        self.controller.settings().method
    }
    /// Sets the world's method.
    pub fn set_method(&mut self, method: Method) {
        self.controller.settings_mut().method = method;
    }
    /// The world's damping coefficients.
    pub fn damping(&self) -> &DampingCoefficients<f64> {
        &self.controller.settings().damping
    }
    /// Sets the world's damping coefficients ([`DampingCoefficients::off`] for none).
    pub fn set_damping(&mut self, damping: DampingCoefficients<f64>) {
        self.controller.settings_mut().damping = damping;
    }

    /// How finely the pressure drag of the bodies without their own
    /// [`FloatOptions::damping_resolution`] is integrated: by default over a reduced copy of
    /// each mesh of more than 384 triangles, built once per mesh (see [`DampingResolution`]).
    pub fn damping_resolution(&self) -> DampingResolution {
        self.controller.damping_resolution()
    }
    /// Sets the damping resolution of the bodies without their own (their reduced meshes are
    /// built, once per mesh, now), e.g. [`DampingResolution::Full`] for the model exactly.
    pub fn set_damping_resolution(&mut self, resolution: DampingResolution) {
        self.controller.set_damping_resolution(resolution);
    }

    /// The moving free surface the bodies float on, if any (see the core's
    /// [controller](buoyancy_core::controller#waves)).
    pub fn surface(&self) -> Option<&SharedSurface> {
        self.controller.surface()
    }
    /// Makes the bodies float on `surface`, e.g. `Some(Arc::new(airy_waves))`, or on still water
    /// with `None`. Its time advances with every [`apply`](Self::apply) by the step's `dt`.
    pub fn set_surface(&mut self, surface: Option<SharedSurface>) {
        self.controller.set_surface(surface);
    }
    /// The pressure of the surface's waves (see the core's
    /// [`Controller::pressure`](buoyancy_core::controller::Controller::pressure)): hydrostatic
    /// by default.
    pub fn pressure(&self) -> Pressure {
        self.controller.pressure()
    }
    /// Sets the pressure of the surface's waves: [`Pressure::FroudeKrylov`] for Airy waves
    /// whose wave part decays with depth.
    pub fn set_pressure(&mut self, pressure: Pressure) {
        self.controller.set_pressure(pressure);
    }
    /// The surface's time, s.
    pub fn time(&self) -> f64 {
        self.controller.time()
    }
    /// Sets the surface's time, s.
    pub fn set_time(&mut self, time: f64) {
        self.controller.set_time(time);
    }

    /// Number of registered bodies.
    pub fn len(&self) -> usize {
        self.handles.len()
    }
    /// Whether no body is registered.
    pub fn is_empty(&self) -> bool {
        self.handles.is_empty()
    }
    /// Whether `body` is registered.
    pub fn contains(&self, body: RigidBodyHandle) -> bool {
        self.index.contains_key(&body)
    }

    /// Makes `body` float: turns its selected colliders into closed meshes (once per rapier
    /// shape and per set of triangles: bodies whose colliders share a `SharedShape`, or whose
    /// shapes give the same triangles, share one mesh) and remembers them
    /// with `options`. Registering a body again replaces its meshes and options
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
        self.meshes.prune();
        let parts = mesh_colliders(body, bodies, colliders, &options, &mut self.meshes)?;
        self.hold(body, parts, &options)
    }

    /// Makes `body` float with `parts` (closed meshes placed on the body by their
    /// `shape_to_body`, in the frame of `RigidBody::position`) instead of its colliders, with
    /// the overrides of `options` (its collider selection and subdivisions are not used).
    /// Registering a body again replaces its meshes and options.
    ///
    /// # Errors
    /// [`Error::UnknownBody`] if `body` is not in `bodies`, [`Error::NothingToFloat`] for no
    /// parts, [`Error::Core`] for overrides the core rejects.
    pub fn register_parts(
        &mut self,
        body: RigidBodyHandle,
        bodies: &RigidBodySet,
        parts: Vec<Part>,
        options: FloatOptions,
    ) -> Result<(), Error> {
        if !bodies.contains(body) {
            return Err(Error::UnknownBody(body));
        }
        if parts.is_empty() {
            return Err(Error::NothingToFloat(body));
        }
        self.hold(body, parts, &options)
    }

    /// Adds `body` to the controller with `parts`, or replaces its parts.
    fn hold(
        &mut self,
        body: RigidBodyHandle,
        parts: Vec<Part>,
        options: &FloatOptions,
    ) -> Result<(), Error> {
        let overrides = BodyOptions {
            method: options.method,
            water: options.water,
            damping: options.damping,
            damping_resolution: options.damping_resolution,
        };
        // The reduced meshes are shared: a mesh already reduced at this resolution is not again.
        if let Some(&i) = self.index.get(&body) {
            self.controller.replace(i, parts, overrides)?;
        } else {
            let i = self.controller.add(parts, overrides)?;
            self.index.insert(body, i);
            self.handles.push(body);
        }
        Ok(())
    }

    /// Stops `body` from floating and takes back the force and torque the adapter added to it.
    /// Returns whether it was registered.
    pub fn unregister(&mut self, body: RigidBodyHandle, bodies: &mut RigidBodySet) -> bool {
        let Some(take_back) = self.remove(body) else {
            return false;
        };
        if let Some(rb) = bodies.get_mut(body) {
            apply_regardless_of_type(rb, &take_back);
        }
        true
    }

    /// Forgets `body` and returns the command that takes its share back off, `None` if it was
    /// not registered.
    fn remove(&mut self, body: RigidBodyHandle) -> Option<Command> {
        let i = self.index.remove(&body)?;
        let take_back = self.controller.remove(i)?;
        self.handles.swap_remove(i);
        if let Some(&moved) = self.handles.get(i) {
            self.index.insert(moved, i);
        }
        Some(take_back)
    }

    /// Tells the adapter that the application reset the forces and torques of `body`
    /// (`RigidBody::reset_forces` / `reset_torques`), so that its own share is zero now.
    ///
    /// Also the cure for the `f32` drift of the body's accumulated force (see the
    /// [crate documentation](crate)): `reset_forces`, `reset_torques`, re-add the application's own
    /// forces, `forget_applied`; the next [`apply`](Self::apply) adds the whole share again.
    pub fn forget_applied(&mut self, body: RigidBodyHandle) {
        if let Some(&i) = self.index.get(&body) {
            self.controller.forget_applied(i);
        }
    }

    /// The last report of `body`: what was computed and applied at the last
    /// [`apply`](Self::apply).
    pub fn report(&self, body: RigidBodyHandle) -> Option<&FloatReport> {
        self.index
            .get(&body)
            .and_then(|&i| self.controller.report(i))
    }

    /// Places `body` where it floats at rest in the still water (the still level under
    /// [waves](Self::set_surface)), for its mass and center of mass as rapier has them: the
    /// pose where the water it displaces weighs what it weighs and its center of buoyancy lies
    /// on the vertical through its center of mass, the stable attitude
    /// ([`Controller::rest`](buoyancy_core::controller::Controller::rest)). Heel and trim are
    /// measured from its current orientation, whose yaw and the horizontal position of its
    /// center of mass are kept. Its velocities are set to zero. Call it after registering a
    /// body and before the first step, so that a spawned boat does not bob.
    ///
    /// Returns the core's [`Rest`]: the pose and the equilibrium (draft, heel, trim, GM,
    /// residuals, whether it is stable). `colliders` are the body's, for its mass properties
    /// (rapier computes them at the next step; they are computed here).
    ///
    /// # Errors
    /// [`Error::UnknownBody`] if `body` is not registered or not in `bodies`;
    /// [`Error::Core`] with [`TooHeavyToFloat`](buoyancy_core::Error::TooHeavyToFloat) for a
    /// body that sinks, or another error of the solver
    /// ([`Mesh::equilibrium_with`](buoyancy_core::Mesh::equilibrium_with)).
    pub fn place_at_rest(
        &mut self,
        body: RigidBodyHandle,
        bodies: &mut RigidBodySet,
        colliders: &ColliderSet,
    ) -> Result<Rest, Error> {
        let (Some(&i), Some(rb)) = (self.index.get(&body), bodies.get_mut(body)) else {
            return Err(Error::UnknownBody(body));
        };
        // rapier brings a new body's mass properties (its colliders', and the additional ones
        // of its builder) up to date at the next step, and its world center of mass with them:
        // both now, from the colliders and the local center of mass.
        rb.recompute_mass_properties_from_colliders(colliders);
        let state = BodyState {
            center_of_mass: pose_to_nalgebra(rb.position())
                * point_to_nalgebra(rb.mass_properties().local_mprops.local_com),
            ..body_state(rb)
        };
        let rest = self
            .controller
            .rest(i, &state)
            .ok_or(Error::UnknownBody(body))?
            .map_err(Error::Core)?;
        rb.set_position(pose_from_nalgebra(&rest.pose), true);
        rb.set_linvel(Vector::ZERO, true);
        rb.set_angvel(Vector::ZERO, true);
        Ok(rest)
    }

    /// The meshes a body floats with (one per shape, in the shape's frame) and their
    /// shape → body poses.
    pub fn meshes(&self, body: RigidBodyHandle) -> impl Iterator<Item = (&Mesh<f64>, &Pose<f64>)> {
        self.index
            .get(&body)
            .and_then(|&i| self.controller.parts(i))
            .into_iter()
            .flatten()
            .map(|p| (p.mesh.as_ref(), &p.shape_to_body))
    }

    /// Computes buoyancy and damping for every registered body at its current pose and
    /// velocity, and sets the body's share of the applied force and torque to it (see the
    /// [crate documentation](crate) on forces the application adds itself). Call it once per
    /// step, before `PhysicsPipeline::step`, with the step's `dt` (s), which the damping's
    /// stability scheme needs (see [Stability](crate#stability)). Bodies removed from `bodies`
    /// are forgotten. Fixed, kinematic and disabled bodies get nothing new: their share is left
    /// as it is (rapier ignores `add_force` on bodies that are not dynamic but keeps their stored
    /// force), and holds again when they are dynamic and enabled again. With the `rayon` feature
    /// the bodies are computed in parallel. On a moving [surface](Self::set_surface), the
    /// bodies are evaluated at the surface's [time](Self::time), which then advances by `dt`.
    ///
    /// Under still water, no allocation once every body has been seen (the meshes are prepared
    /// at registration); on waves, each part's evaluation allocates its buffers.
    pub fn apply(&mut self, bodies: &mut RigidBodySet, dt: f32) {
        self.forget_removed(bodies);
        self.states.clear();
        self.states
            .extend(self.handles.iter().map(|&h| body_state(&bodies[h])));
        self.commands.resize(self.handles.len(), Command::default());
        self.controller
            .step(&self.states, f64::from(dt), &mut self.commands);
        for (&handle, command) in self.handles.iter().zip(&self.commands) {
            if command.adds_anything() {
                let rb = &mut bodies[handle];
                rb.add_force(Vector::from(command.add_force), command.wake);
                rb.add_torque(Vector::from(command.add_torque), command.wake);
            } else if command.wake {
                // Asleep out of balance: woken with nothing to add.
                bodies[handle].wake_up(true);
            }
        }
    }

    /// Forgets the bodies no longer in `bodies` (nothing to take back from them).
    fn forget_removed(&mut self, bodies: &RigidBodySet) {
        while let Some(&gone) = self.handles.iter().find(|h| !bodies.contains(**h)) {
            self.remove(gone);
        }
    }
}

/// What the controller reads of a rapier body: its pose and center of mass (world frame), its
/// velocities, mass and effective inverse mass and inertia (world frame), gravity scale, the
/// user force and torque it holds, whether it moves, and whether it sleeps.
pub fn body_state(rb: &RigidBody) -> BodyState {
    let props = rb.mass_properties();
    let i = &props.effective_world_inv_inertia;
    BodyState {
        pose: pose_to_nalgebra(rb.position()),
        center_of_mass: point_to_nalgebra(rb.center_of_mass()),
        linear_velocity: vector_to_nalgebra(rb.linvel()),
        angular_velocity: vector_to_nalgebra(rb.angvel()),
        mass: f64::from(rb.mass()),
        inverse_mass: vector_to_nalgebra(props.effective_inv_mass),
        inverse_inertia: Matrix3::new(
            i.m11, i.m12, i.m13, i.m12, i.m22, i.m23, i.m13, i.m23, i.m33,
        )
        .cast::<f64>(),
        gravity_scale: f64::from(rb.gravity_scale()),
        applied_force: rb.user_force().into(),
        applied_torque: rb.user_torque().into(),
        motion: if rb.is_dynamic() && rb.is_enabled() {
            Motion::Dynamic
        } else {
            Motion::Inactive
        },
        sleeping: rb.is_sleeping(),
    }
}

/// Applies `command` to `rb` even if it is not dynamic: rapier ignores `add_force` on such
/// bodies, so they are made dynamic for the time of the addition.
fn apply_regardless_of_type(rb: &mut RigidBody, command: &Command) {
    if !command.adds_anything() {
        return;
    }
    let body_type = rb.body_type();
    if !body_type.is_dynamic() {
        rb.set_body_type(RigidBodyType::Dynamic, false);
    }
    rb.add_force(Vector::from(command.add_force), false);
    rb.add_torque(Vector::from(command.add_torque), false);
    if !body_type.is_dynamic() {
        rb.set_body_type(body_type, false);
    }
}
