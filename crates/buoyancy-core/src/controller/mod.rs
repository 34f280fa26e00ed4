//! Floating bodies in a physics engine, independent of the engine: one controller for every
//! adapter (the rapier3d crate `buoyancy-rapier` and the Python `buoyancy.rapier`).
//!
//! A [`Controller`] holds the bodies that float, each made of one or more closed meshes
//! ([`Part`]s placed on the body), with the water, method and damping coefficients (the
//! controller's [`Settings`], overridden per body by [`BodyOptions`]). Once per step an adapter
//! reads every body's [`BodyState`] from its engine, calls [`Controller::step`], and applies
//! the returned [`Command`]s: a force and a torque to *add* to what the engine holds for the
//! body, and whether to wake it. The controller computes the exact buoyancy, the hydrodynamic
//! [damping](crate::damping), solves the damping semi-implicitly, and keeps the books of what
//! it has added, so that the engine holds *the application's own forces + this step's
//! buoyancy and damping*.
//!
//! # Forces the application adds itself
//! Engines like rapier keep the forces added to a body until they are reset. The controller
//! never resets them: it remembers the force and torque it added at the previous step (its
//! *share*) and asks to add only the difference. A constant thrust the application added once
//! stays. If the application resets a body's forces it must call
//! [`Controller::forget_applied`] (the share was wiped too); [`Controller::remove`] returns the
//! command that takes the share back off.
//!
//! * **Bodies the engine does not move by forces** ([`Motion::Inactive`]: kinematic, fixed,
//!   disabled) get nothing computed and keep their share, so that a body made kinematic and
//!   then dynamic again gets its buoyancy once, not twice.
//! * **A wiped share.** A dynamic body whose engine force and torque are both exactly zero
//!   while the share is not had them reset (rapier's NaN quarantine does that): the share is
//!   forgotten, and the next step adds it whole.
//! * **`f32`.** The share is kept in `f32`, what engines like rapier store, so that what is
//!   taken back is exactly what was added.
//!
//! # Sleeping bodies
//! A sleeping body is woken when the buoyancy on it (force or torque; a body at rest feels no
//! damping) has changed by more than 0.1 % (of the force plus the body's weight; the torque
//! also by that force times the body's size) since it was last awake, so that slow changes, a
//! rising tide, add up. An awake body is never "woken": that would restart the engine's count
//! towards sleep.
//!
//! It is woken too when the engine put it to sleep *out of balance*: its net force (the
//! controller's share, the application's own forces and its weight) above 0.1 % of its weight,
//! or its net torque above that times its size. Engines put a body to sleep when it has moved
//! slowly for a while (rapier, by default: below 0.05 m/s for 0.5 s), which a floating body still heaving by
//! a few millimetres does; woken, it settles on. A body woken for that at the same pose before
//! (to 1e-4 of its size and 1e-4 rad) is left asleep: something the controller does not see
//! holds it there, the ground or a joint. Such a wake adds nothing: an adapter wakes the body
//! whenever [`Command::wake`] says so.
//!
//! # Bodies at rest
//! In still water, a body whose state, settings, step and share are exactly those of its last
//! evaluation (a sleeping body, its pose held by the engine) is not evaluated again: its last
//! evaluation is taken again, which is the same to the bit. On waves every step is evaluated
//! (the surface moves).
//!
//! # Stability
//! The damping is made semi-implicit, so that a light body (large drag for its mass) and a body
//! dropped fast into the water neither overshoot nor oscillate. About the current velocity
//! `q̇ = (v − v_water, ω)`, the damping wrench `W = (F, τ)` of the model is linearised as
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
//! motion back faster than it came (`W/(1 + α·dt)` alone turning `v − v_water` or `ω` against
//! itself by more than its size over the step, an oscillation that grows: a direction much
//! stiffer than the motion as a whole, such as a fast spin under a strong angular damping while
//! the body sinks fast), the damping is taken at the end of the step through its stiffness
//! `K = −∂W/∂q̇` instead ([`DampingStiffness`](crate::damping::DampingStiffness), exact for the
//! model), each direction at its own rate:
//!
//! ```text
//! (I + dt·M⁻¹K)·Δq̇ = dt·M⁻¹·(G + W),    W' = W − K·Δq̇.
//! ```
//!
//! That costs a second pass over the body's drag surface, for such bodies only. A body moving
//! freely reaches the terminal velocity of the damping model (where `W = −G`). Gravity is taken
//! as the water's (`g` against its normal, times the body's gravity scale). A body whose pose,
//! velocity or result is not finite gets no force (the previous one is taken back); its
//! report's outcome is [`Outcome::NotFinite`].
//!
//! # Bodies of several parts
//! Buoyancy and pressure drag add up over the parts. The angular damping,
//! `−f·ρ·V^{5/3}·(a₁ + a₂|ω|)·ω` ([`angular_damping`](crate::damping::angular_damping)), is
//! the whole body's, with `V` the total volume of the parts and `f` their total wetted area
//! over their total surface area, so that splitting a shape into parts does not change it.
//!
//! # Damping resolution
//! The pressure drag is integrated over every wetted triangle, which for a mesh of thousands of
//! triangles costs many times its buoyancy. By default ([`DampingResolution::DEFAULT`]) the
//! controller integrates it over a reduced copy of each mesh of more than 384 triangles
//! ([`ReducedMesh`]: vertex clustering, scaled to the mesh's
//! volume), built once per mesh when a body is added and shared by the bodies of the same
//! mesh; smaller meshes are taken whole, unchanged. [`Controller::set_damping_resolution`]
//! and [`Controller::set_body_damping_resolution`] choose otherwise
//! ([`DampingResolution::Full`] for the model exactly). The buoyancy always takes the full
//! mesh.
//!
//! # Waves
//! With a moving free surface ([`Controller::set_surface`], any [`WaterSurface`]), the buoyancy
//! is the pressure of the waves ([`Controller::pressure`]: hydrostatic by default, or
//! Froude–Krylov) integrated over each part's wetted surface by
//! [`Mesh::buoyancy`](crate::Mesh::buoyancy) under a [`Sea`](crate::query::Sea), at the
//! controller's [`time`](Controller::time), which every step advances by its `dt`. The method of
//! the settings holds there too: Exact (the default) and Exact Surface integrate the pressure
//! exactly; a method that assumes a flat surface is refused, and the body's report says
//! [`Outcome::Unsupported`]. The damping is taken relative to the water: its current plus the surface's
//! [`water_velocity`](WaterSurface::water_velocity) (the orbital velocity of Airy waves) at the
//! body's center of mass, one velocity for the whole body (a body small against the
//! wavelength).
//!
//! # Frames and units
//! World frame, SI units; a part's mesh is in its shape's frame, placed on the body by
//! [`Part::shape_to_body`]; torques about the body's center of mass. Computed in `f64`, applied
//! in `f32`.
//!
//! ```
//! use buoyancy_core::controller::{BodyOptions, BodyState, Command, Controller, Motion, Part};
//! use buoyancy_core::nalgebra::{Matrix3, Point3, Vector3};
//! use buoyancy_core::{mesh::primitives, Mesh, Pose};
//! use std::sync::Arc;
//!
//! // A 1 m cube of 500 kg, its center at the water level (half under water), at rest.
//! let (v, t) = primitives::cube::<f64>(1)?;
//! let part = Part { mesh: Arc::new(Mesh::new(v, t)?), shape_to_body: Pose::identity() };
//! let mut controller = Controller::default();
//! let cube = controller.add(vec![part], BodyOptions::default())?;
//! let state = BodyState {
//!     pose: Pose::identity(),
//!     center_of_mass: Point3::origin(),
//!     linear_velocity: Vector3::zeros(),
//!     angular_velocity: Vector3::zeros(),
//!     mass: 500.0,
//!     inverse_mass: Vector3::repeat(1.0 / 500.0),
//!     inverse_inertia: Matrix3::identity() * (6.0 / 500.0),
//!     gravity_scale: 1.0,
//!     applied_force: Vector3::zeros(),
//!     applied_torque: Vector3::zeros(),
//!     motion: Motion::Dynamic,
//!     sleeping: false,
//! };
//! let mut commands = [Command::default()];
//! controller.step(&[state], 1.0 / 60.0, &mut commands);
//! // Add this to the engine's force: the buoyancy of half the cube, 4905 N up.
//! assert!((commands[0].add_force.y - 4905.0).abs() < 0.01);
//! assert_eq!(controller.report(cube).unwrap().submerged_volume, 0.5);
//! # Ok::<(), buoyancy_core::Error>(())
//! ```

mod body;
mod evaluation;
mod rest;
mod semi_implicit;
mod settings;
mod state;

use alloc::sync::Arc;
use alloc::vec::Vec;

pub use body::Part;
pub use rest::Rest;
pub use settings::{BodyOptions, DampingResolution, Settings};
pub use state::{BodyState, Command, FloatReport, Motion, Outcome};

use body::{Evaluation, FloatingBody, LastEvaluation};
use evaluation::{SurfaceAt, evaluate};

use crate::Error;
use crate::mesh::ReducedMesh;
use crate::query::Pressure;
use crate::water::WaterSurface;

/// A free surface shared with the controller (see [`Controller::set_surface`]): any
/// [`WaterSurface`], e.g. `Arc::new(airy_waves)`.
pub type SharedSurface = Arc<dyn WaterSurface<f64> + Send>;

/// The bodies that float, their settings, and the books of what was applied to them (see the
/// [module documentation](self)). Bodies are numbered from 0 in the order they were added;
/// [`remove`](Controller::remove) moves the last one into the freed number.
#[derive(Clone, Default)]
pub struct Controller {
    settings: Settings,
    bodies: Vec<FloatingBody>,
    /// The moving free surface, if any, and its time.
    surface: Option<SharedSurface>,
    pressure: Pressure,
    time: f64,
    /// The damping resolution of the bodies without their own.
    resolution: DampingResolution,
}

impl core::fmt::Debug for Controller {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Controller")
            .field("settings", &self.settings)
            .field("bodies", &self.bodies)
            .field("waves", &self.surface.is_some())
            .field("time", &self.time)
            .field("resolution", &self.resolution)
            .finish()
    }
}

impl Controller {
    /// No bodies, these settings, still water at time 0.
    pub fn new(settings: Settings) -> Self {
        Controller {
            settings,
            bodies: Vec::new(),
            surface: None,
            pressure: Pressure::Hydrostatic,
            time: 0.0,
            resolution: DampingResolution::DEFAULT,
        }
    }

    /// The moving free surface the bodies float on, if any.
    pub fn surface(&self) -> Option<&SharedSurface> {
        self.surface.as_ref()
    }

    /// Makes the bodies float on `surface` (see [waves](self#waves)), or on still water with
    /// `None`.
    pub fn set_surface(&mut self, surface: Option<SharedSurface>) {
        self.surface = surface;
    }

    /// The pressure of the surface's waves on the bodies: [`Pressure::Hydrostatic`] (the
    /// default) or [`Pressure::FroudeKrylov`], whose wave part decays with depth (for
    /// [`AiryWaves`](crate::water::AiryWaves) only: on another surface a body's report is
    /// [`Outcome::Unsupported`]).
    pub fn pressure(&self) -> Pressure {
        self.pressure
    }

    /// Sets the pressure of the surface's waves on the bodies (see [`pressure`](Self::pressure)).
    pub fn set_pressure(&mut self, pressure: Pressure) {
        self.pressure = pressure;
    }

    /// The surface's time, s: advanced by `dt` at every [`step`](Self::step).
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Sets the surface's time, s.
    pub fn set_time(&mut self, time: f64) {
        self.time = time;
    }

    /// The controller's settings (a body's [`BodyOptions`] override them).
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The controller's settings, to change.
    pub fn settings_mut(&mut self) -> &mut Settings {
        &mut self.settings
    }

    /// Number of bodies.
    pub fn len(&self) -> usize {
        self.bodies.len()
    }

    /// Whether there is no body.
    pub fn is_empty(&self) -> bool {
        self.bodies.is_empty()
    }

    /// Adds a body made of `parts`, with `options` (its overrides; the reduced copies its
    /// damping resolution asks for are built here, once per mesh); returns its number (the
    /// count of bodies before it).
    ///
    /// # Errors
    /// [`Error::EmptyBody`] for no parts.
    pub fn add(&mut self, parts: Vec<Part>, options: BodyOptions) -> Result<usize, Error> {
        let mut body = FloatingBody::new(parts, options)?;
        (body.reduced, body.resolution) = self.reduced_for(&body);
        self.bodies.push(body);
        Ok(self.bodies.len() - 1)
    }

    /// The damping resolution of the bodies without their own (see [`DampingResolution`]);
    /// [`DampingResolution::DEFAULT`] unless set.
    pub fn damping_resolution(&self) -> DampingResolution {
        self.resolution
    }

    /// Sets the damping resolution of the bodies without their own, and builds the reduced
    /// copies of their meshes it asks for (once per mesh).
    pub fn set_damping_resolution(&mut self, resolution: DampingResolution) {
        self.resolution = resolution;
        for i in 0..self.bodies.len() {
            if self.bodies[i].options.damping_resolution.is_none() {
                self.rebuild(i);
            }
        }
    }

    /// The damping resolution of body `index`: its own, else the controller's; `None` when
    /// there is no such body.
    pub fn body_damping_resolution(&self, index: usize) -> Option<DampingResolution> {
        self.bodies.get(index).map(|b| b.resolution)
    }

    /// Gives body `index` its own damping resolution (`None`: the controller's), and builds
    /// the reduced copies of its meshes it asks for. Returns `false` when there is no such
    /// body.
    pub fn set_body_damping_resolution(
        &mut self,
        index: usize,
        resolution: Option<DampingResolution>,
    ) -> bool {
        let Some(body) = self.bodies.get_mut(index) else {
            return false;
        };
        body.options.damping_resolution = resolution;
        self.rebuild(index);
        true
    }

    /// Builds the reduced copies of body `index`'s meshes for its resolution.
    fn rebuild(&mut self, index: usize) {
        let copies = self.reduced_for(&self.bodies[index]);
        let body = &mut self.bodies[index];
        (body.reduced, body.resolution) = copies;
        // Other copies, another damping: evaluate the body afresh.
        body.last = None;
    }

    /// The reduced copies of `body`'s meshes for its own resolution, else the controller's,
    /// and that resolution.
    fn reduced_for(
        &self,
        body: &FloatingBody,
    ) -> (Vec<Option<Arc<ReducedMesh<f64>>>>, DampingResolution) {
        let resolution = body.options.damping_resolution.unwrap_or(self.resolution);
        (self.reduced_copies(&body.parts, resolution), resolution)
    }

    /// Per part, the reduced copy of its mesh at `resolution` (`None`: the mesh itself): the
    /// one a body already holds for the same mesh and resolution, else a new one.
    fn reduced_copies(
        &self,
        parts: &[Part],
        resolution: DampingResolution,
    ) -> Vec<Option<Arc<ReducedMesh<f64>>>> {
        let DampingResolution::Reduced { max_triangles } = resolution else {
            return alloc::vec![None; parts.len()];
        };
        parts
            .iter()
            .map(|part| {
                let held = self
                    .bodies
                    .iter()
                    .filter(|b| b.resolution == resolution)
                    .flat_map(|b| b.parts.iter().zip(&b.reduced))
                    .find(|(p, _)| Arc::ptr_eq(&p.mesh, &part.mesh));
                match held {
                    Some((_, reduced)) => reduced.clone(),
                    None => ReducedMesh::new(&part.mesh, max_triangles).map(Arc::new),
                }
            })
            .collect()
    }

    /// Replaces the parts and options of body `index` (its damping resolution among them),
    /// keeping the books of what was applied to it. Returns `Ok(false)` when there is no such
    /// body.
    ///
    /// # Errors
    /// [`Error::EmptyBody`] for no parts.
    pub fn replace(
        &mut self,
        index: usize,
        parts: Vec<Part>,
        options: BodyOptions,
    ) -> Result<bool, Error> {
        let mut replacement = FloatingBody::new(parts, options)?;
        if index >= self.bodies.len() {
            return Ok(false);
        }
        (replacement.reduced, replacement.resolution) = self.reduced_for(&replacement);
        let body = &mut self.bodies[index];
        *body = FloatingBody {
            share: body.share,
            report: body.report,
            ..replacement
        };
        Ok(true)
    }

    /// Removes body `index` (the last body takes its number) and returns the command that
    /// takes its share back off it; `None` when there is no such body. The engine must apply
    /// the command even to a body it does not move by forces (the share is there).
    pub fn remove(&mut self, index: usize) -> Option<Command> {
        (index < self.bodies.len()).then(|| self.bodies.swap_remove(index).share.take_back())
    }

    /// Tells the controller that the forces and torques of body `index` were reset in the
    /// engine, so that its share is zero now; the next step adds the whole share again.
    pub fn forget_applied(&mut self, index: usize) {
        if let Some(body) = self.bodies.get_mut(index) {
            body.share.forget();
        }
    }

    /// What the last [`step`](Self::step) computed and applied for body `index`.
    pub fn report(&self, index: usize) -> Option<&FloatReport> {
        self.bodies.get(index).map(|b| &b.report)
    }

    /// The parts of body `index`.
    pub fn parts(&self, index: usize) -> Option<&[Part]> {
        self.bodies.get(index).map(|b| b.parts.as_slice())
    }

    /// The settings of body `index`: the controller's, with the body's overrides.
    pub fn body_settings(&self, index: usize) -> Option<Settings> {
        self.bodies
            .get(index)
            .map(|b| self.settings.resolve(&b.options))
    }

    /// One step of `dt` seconds (a `dt` that is not finite and non-negative does not advance the
    /// surface's time): for every body `i`, its buoyancy and damping in `states[i]`,
    /// and in `commands[i]` what to add to the engine's force and torque for it (see the
    /// [module documentation](self)). With the `rayon` feature the bodies are computed in
    /// parallel. No allocation.
    ///
    /// # Panics
    /// When `states` or `commands` do not have one entry per body: an adapter's bug, not a
    /// user's input.
    pub fn step(&mut self, states: &[BodyState], dt: f64, commands: &mut [Command]) {
        assert!(
            states.len() == self.bodies.len() && commands.len() == self.bodies.len(),
            "Controller::step: {} states and {} commands for {} bodies",
            states.len(),
            commands.len(),
            self.bodies.len()
        );
        let settings = &self.settings;
        let sea = self.surface.as_deref().map(|surface| SurfaceAt {
            surface,
            time: self.time,
            pressure: self.pressure,
        });
        let one = |(body, (state, command)): (&mut FloatingBody, (&BodyState, &mut Command))| {
            body.share.forget_if_wiped(state);
            let resolved = settings.resolve(&body.options);
            // In still water, the same inputs as the last step's give the same evaluation.
            let evaluation = match sea {
                Some(_) => evaluate(body, state, &resolved, sea, dt),
                None => body
                    .last
                    .and_then(|last| last.of(state, &resolved, dt, &body.share))
                    .unwrap_or_else(|| {
                        let evaluation = evaluate(body, state, &resolved, None, dt);
                        body.last = Some(LastEvaluation::new(
                            state,
                            &resolved,
                            dt,
                            &body.share,
                            evaluation,
                        ));
                        evaluation
                    }),
            };
            body.report = evaluation.report(state.center_of_mass);
            let zero = nalgebra::Vector3::zeros();
            let (share, buoyancy) = match evaluation {
                Evaluation::Inactive => {
                    *command = Command::default();
                    return;
                }
                // Not finite: the share goes back to zero.
                Evaluation::NotFinite | Evaluation::Unsupported => ((zero, zero), (zero, zero)),
                Evaluation::Floating {
                    force,
                    torque,
                    report,
                } => (
                    (force, torque),
                    (
                        report.buoyancy_force.cast::<f32>(),
                        report.buoyancy_torque.cast::<f32>(),
                    ),
                ),
            };
            let gravity =
                (resolved.water.normal().into_inner() * -resolved.water.gravity()).cast::<f32>();
            *command = body
                .share
                .hold(state, share, buoyancy, gravity, body.size() as f32);
        };
        #[cfg(feature = "rayon")]
        {
            use rayon::prelude::*;
            self.bodies
                .par_iter_mut()
                .zip(states.par_iter().zip(commands.par_iter_mut()))
                .for_each(one);
        }
        #[cfg(not(feature = "rayon"))]
        self.bodies
            .iter_mut()
            .zip(states.iter().zip(commands.iter_mut()))
            .for_each(one);
        // A step of no finite, non-negative length leaves the surface's time where it was
        // (the semi-implicit damping takes the damping as it is for it).
        if dt.is_finite() && dt >= 0.0 {
            self.time += dt;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::water::{AiryComponent, AiryWaves, CalmSurface};
    use crate::{Mesh, Pose, Water, mesh::primitives};
    use nalgebra::{Matrix3, Point3, Translation3, UnitQuaternion, Vector3};

    /// A body held by the engine in the same state (asleep, still) for steps on end, while the
    /// controller's water, the body's damping resolution and the waves change between some of
    /// them: every step's report and command are those of a fresh evaluation of its inputs, and
    /// the steps whose inputs repeat the last ones' take its evaluation again.
    #[test]
    fn the_same_inputs_take_the_last_evaluation_again() {
        let (v, t) = primitives::uv_sphere::<f64>(0.5, 40, 20).unwrap();
        let sphere = Arc::new(Mesh::new(v, t).unwrap());
        let mut controller = Controller::default();
        let part = Part {
            mesh: sphere,
            shape_to_body: Pose::identity(),
        };
        controller
            .add(alloc::vec![part], BodyOptions::default())
            .unwrap();
        let pose = Pose::from_parts(
            Translation3::new(0.1, -0.1, 0.2),
            UnitQuaternion::from_euler_angles(0.2, 0.1, -0.3),
        );
        let mut state = BodyState {
            pose,
            center_of_mass: pose * Point3::origin(),
            linear_velocity: Vector3::zeros(),
            angular_velocity: Vector3::zeros(),
            mass: 200.0,
            inverse_mass: Vector3::repeat(1.0 / 200.0),
            inverse_inertia: Matrix3::identity() / 20.0,
            gravity_scale: 1.0,
            applied_force: Vector3::zeros(),
            applied_torque: Vector3::zeros(),
            motion: state::Motion::Dynamic,
            sleeping: true,
        };
        let sea = Arc::new(
            AiryWaves::new(
                alloc::vec![AiryComponent {
                    amplitude: 0.1,
                    wavelength: 12.0,
                    direction: Vector3::x(),
                    phase: 0.0,
                }],
                None,
            )
            .unwrap(),
        );
        let dt = 1.0 / 60.0;
        let mut commands = [Command::default()];
        let mut taken_again = 0;
        for step in 0..14 {
            match step {
                4 => {
                    controller.settings_mut().water = Water::default().with_density(1025.0).unwrap()
                }
                7 => {
                    controller.set_body_damping_resolution(0, Some(DampingResolution::Full));
                }
                9 => controller.set_surface(Some(sea.clone())),
                11 => controller.set_surface(None),
                _ => {}
            }
            let body = &controller.bodies[0];
            let resolved = controller.settings.resolve(&body.options);
            let fresh = evaluate(
                body,
                &state,
                &resolved,
                controller.surface.as_deref().map(|surface| SurfaceAt {
                    surface,
                    time: controller.time,
                    pressure: controller.pressure,
                }),
                dt,
            );
            // (On waves the time moves on: never taken again.)
            let repeats = controller.surface.is_none()
                && body
                    .last
                    .is_some_and(|last| last.of(&state, &resolved, dt, &body.share).is_some());
            taken_again += usize::from(repeats);
            controller.step(&[state], dt, &mut commands);
            assert_eq!(
                controller.bodies[0].report,
                fresh.report(state.center_of_mass),
                "{step}"
            );
            // The engine adds the command.
            state.applied_force += commands[0].add_force;
            state.applied_torque += commands[0].add_torque;
        }
        // Steps 2, 3, 6, 8 and 13 repeat the inputs of the step before. Steps 1, 5 and 12
        // follow a command that changed the engine's force, steps 4, 7 and 11 a change of the
        // water, the resolution or the surface, and steps 9 and 10 are on waves.
        assert_eq!(taken_again, 5);
        // And the step does take it: a remembered evaluation of these very inputs is what the
        // next step reports.
        let body = &mut controller.bodies[0];
        let resolved = controller.settings.resolve(&body.options);
        let marked = FloatReport {
            submerged_volume: 123.0,
            ..body.report
        };
        let remembered = Evaluation::Floating {
            report: marked,
            force: Vector3::zeros(),
            torque: Vector3::zeros(),
        };
        body.last = Some(LastEvaluation::new(
            &state,
            &resolved,
            dt,
            &body.share,
            remembered,
        ));
        controller.step(&[state], dt, &mut commands);
        assert_eq!(controller.bodies[0].report, marked);
    }

    #[test]
    fn only_a_finite_non_negative_step_advances_the_time() {
        let mut controller = Controller::default();
        controller.set_surface(Some(Arc::new(CalmSurface)));
        controller.set_time(2.0);
        for dt in [f64::NAN, f64::INFINITY, -0.5] {
            controller.step(&[], dt, &mut []);
            assert_eq!(controller.time(), 2.0, "dt = {dt}");
        }
        controller.step(&[], 0.25, &mut []);
        assert_eq!(controller.time(), 2.25);
    }
}
