//! The bodies that float in one rapier world, and their water.

use std::collections::HashMap;

use buoyancy_core::{DampingCoefficients, Mesh, Method, Pose, Water};
use rapier3d::math::Vector;
use rapier3d::prelude::{ColliderSet, RigidBodyHandle, RigidBodySet};

use crate::convert::{point_to_nalgebra, vector_to_nalgebra};
use crate::evaluation::{Evaluation, evaluate};
use crate::floating_body::FloatingBody;
use crate::settings::Settings;
use crate::{Error, FloatOptions, FloatReport};

/// The bodies that float in one rapier world, and their water.
///
/// The world's settings (water, method, damping) apply to every body without an override in
/// its [`FloatOptions`].
#[derive(Debug, Clone)]
pub struct FloatingBodies {
    settings: Settings,
    bodies: Vec<FloatingBody>,
    index: HashMap<RigidBodyHandle, usize>,
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
            settings: Settings {
                water,
                method: Method::Exact,
                damping: DampingCoefficients::default(),
            },
            bodies: Vec::new(),
            index: HashMap::new(),
        })
    }

    /// The world's water.
    pub fn water(&self) -> &Water<f64> {
        &self.settings.water
    }
    /// Sets the world's water (level, normal, density, gravity), e.g.
    /// `fb.water().with_surface(normal, 2.0)?`.
    pub fn set_water(&mut self, water: Water<f64>) {
        self.settings.water = water;
    }
    /// The same world with the surface at `level` m along its normal.
    pub fn with_level(mut self, level: f64) -> Result<Self, Error> {
        let water = &self.settings.water;
        self.settings.water = water.with_surface(water.normal().into_inner(), level)?;
        Ok(self)
    }
    /// The world's method.
    pub fn method(&self) -> Method {
        self.settings.method
    }
    /// Sets the world's method.
    pub fn set_method(&mut self, method: Method) {
        self.settings.method = method;
    }
    /// The world's damping coefficients.
    pub fn damping(&self) -> &DampingCoefficients<f64> {
        &self.settings.damping
    }
    /// Sets the world's damping coefficients ([`DampingCoefficients::off`] for none).
    pub fn set_damping(&mut self, damping: DampingCoefficients<f64>) {
        self.settings.damping = damping;
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
        let registered = FloatingBody::new(body, bodies, colliders, options)?;
        if let Some(&i) = self.index.get(&body) {
            let b = &mut self.bodies[i];
            (b.parts, b.options, b.volume, b.surface_area) = (
                registered.parts,
                registered.options,
                registered.volume,
                registered.surface_area,
            );
        } else {
            self.index.insert(body, self.bodies.len());
            self.bodies.push(registered);
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
            removed.share.take_back(rb);
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
            self.bodies[i].share.forget();
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
        self.forget_removed(bodies);
        let world = &self.settings;
        let shared: &RigidBodySet = bodies;
        let compute = |b: &mut FloatingBody| {
            let rb = &shared[b.handle];
            b.share.forget_if_wiped(rb);
            b.evaluation = evaluate(b, rb, &world.resolve(&b.options), f64::from(dt));
            b.report = b.evaluation.report(point_to_nalgebra(rb.center_of_mass()));
        };
        #[cfg(feature = "rayon")]
        {
            use rayon::prelude::*;
            self.bodies.par_iter_mut().for_each(compute);
        }
        #[cfg(not(feature = "rayon"))]
        self.bodies.iter_mut().for_each(compute);

        for b in &mut self.bodies {
            let (force, torque) = match b.evaluation {
                Evaluation::Inactive => continue,
                Evaluation::NotFinite => (Vector::ZERO, Vector::ZERO),
                Evaluation::Floating { force, torque, .. } => (force, torque),
            };
            let gravity = self.settings.resolve(&b.options).water.gravity() as f32;
            let size = b.size() as f32;
            b.share
                .hold(&mut bodies[b.handle], force, torque, gravity, size);
        }
    }

    /// Forgets the bodies no longer in `bodies`.
    fn forget_removed(&mut self, bodies: &RigidBodySet) {
        if self.bodies.iter().all(|b| bodies.contains(b.handle)) {
            return;
        }
        self.bodies.retain(|b| bodies.contains(b.handle));
        self.index = self
            .bodies
            .iter()
            .enumerate()
            .map(|(i, b)| (b.handle, i))
            .collect();
    }
}
