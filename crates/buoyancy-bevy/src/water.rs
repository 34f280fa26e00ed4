//! The [`Water`] resource: what the bodies float in, and the surface the game draws.

use std::sync::Arc;

use bevy::math::Vec3;
use bevy::prelude::Resource;
use buoyancy_core::controller::SharedSurface;
use buoyancy_core::nalgebra::{Point3, Vector3};
use buoyancy_core::query::Pressure;
use buoyancy_core::water::WaterSurface;

/// The water every [`Floating`](crate::Floating) entity floats in: its density, the height of
/// its still surface, which way is up, and its waves, on the physics clock.
///
/// # Frame
/// World frame, SI units. `up` is opposite to the physics gravity (the backend's) unless set;
/// with no gravity, `+y`. The still surface is the plane `up · x = level`; waves raise it by
/// their elevation `η` along `up` at each horizontal position (see
/// [`buoyancy_core::water`]). The bodies feel exactly the surface [`Water::elevation`] gives.
///
/// # Clock
/// The waves run on the physics clock: the plugin advances [`Water::time`] by each physics
/// step's `dt` (the backend's fixed or variable timestep, its time scale, not while paused), so
/// a frame drawn from [`Water::elevation`] shows the water the bodies are in.
///
/// ```
/// use buoyancy_bevy::Water;
/// use buoyancy_core::nalgebra::Vector3;
/// use buoyancy_core::water::{AiryComponent, AiryWaves};
///
/// let crest = AiryComponent { amplitude: 0.5, wavelength: 40.0, direction: Vector3::x(), phase: 0.0 };
/// let swell = AiryWaves::new(vec![crest], None)?; // deep water
/// let water = Water::default().with_waves(swell);
/// assert_eq!(water.density, 1000.0);
/// // At t = 0 the crest of the cosine wave is at x = 0: 0.5 m above the still level.
/// assert!((water.elevation(0.0, 0.0) - 0.5).abs() < 1e-6);
/// assert!(water.normal(0.0, 0.0).y > 0.999);
/// # Ok::<(), buoyancy_core::Error>(())
/// ```
#[derive(Resource, Clone)]
pub struct Water {
    /// Density ρ, kg/m³ (default 1000, fresh water; 1025 for the sea).
    pub density: f64,
    /// Height of the still surface along `up`, m (default 0).
    pub level: f64,
    /// The unit up direction; `None` (the default): opposite to the physics gravity.
    pub up: Option<Vec3>,
    surface: Option<SharedSurface>,
    /// The pressure of the waves (default hydrostatic; Froude–Krylov for Airy waves, whose
    /// wave part decays with depth).
    pub pressure: Pressure,
    time: f64,
    /// The up direction the plugin last used (from the gravity when `up` is `None`).
    resolved_up: Vec3,
    /// The gravity the plugin last used, m/s².
    gravity: f64,
}

impl Default for Water {
    fn default() -> Self {
        Water {
            density: 1000.0,
            level: 0.0,
            up: None,
            surface: None,
            pressure: Pressure::Hydrostatic,
            time: 0.0,
            resolved_up: Vec3::Y,
            gravity: 9.81,
        }
    }
}

impl std::fmt::Debug for Water {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Water")
            .field("density", &self.density)
            .field("level", &self.level)
            .field("up", &self.up)
            .field("waves", &self.surface.is_some())
            .field("pressure", &self.pressure)
            .field("time", &self.time)
            .finish()
    }
}

impl Water {
    /// Sea water, 1025 kg/m³, still surface at height 0.
    pub fn sea() -> Self {
        Water {
            density: 1025.0,
            ..Water::default()
        }
    }

    /// This water with `waves` (any [`WaterSurface`]: Airy waves, a JONSWAP sea, Gerstner
    /// waves, a height grid).
    pub fn with_waves(mut self, waves: impl WaterSurface<f64> + Send + 'static) -> Self {
        self.surface = Some(Arc::new(waves));
        self
    }

    /// Replaces the waves (`None`: still water), e.g. a height grid recomputed each frame; the
    /// next physics step uses them.
    pub fn set_waves(&mut self, waves: Option<SharedSurface>) {
        self.surface = waves;
    }

    /// The waves, if any.
    pub fn waves(&self) -> Option<&SharedSurface> {
        self.surface.as_ref()
    }

    /// The physics clock the waves run on, s.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Sets the clock (a replay, a seek); the plugin advances it from there.
    pub fn set_time(&mut self, time: f64) {
        self.time = time;
    }

    /// The up direction in use: `up`, or the one opposite to the physics gravity.
    pub fn resolved_up(&self) -> Vec3 {
        self.up.unwrap_or(self.resolved_up)
    }

    /// The core's still water: density, gravity `g`, normal and level; `Err` naming what is not
    /// finite or out of range.
    pub(crate) fn core(&self) -> Result<buoyancy_core::Water<f64>, buoyancy_core::Error> {
        let up = self.resolved_up();
        buoyancy_core::Water::new(
            self.density,
            self.gravity,
            Vector3::new(f64::from(up.x), f64::from(up.y), f64::from(up.z)),
            self.level,
        )
    }

    /// The core's still water, or `None` after logging why not: once per distinct error, which
    /// `last_error` remembers (cleared when the water is valid again).
    pub(crate) fn core_or_log(
        &self,
        last_error: &mut Option<String>,
    ) -> Option<buoyancy_core::Water<f64>> {
        match self.core() {
            Ok(still) => {
                *last_error = None;
                Some(still)
            }
            Err(e) => {
                let message =
                    format!("buoyancy: the Water resource is invalid ({e}); nothing floats");
                if last_error.as_deref() != Some(&message) {
                    bevy::log::error!("{message}");
                }
                *last_error = Some(message);
                None
            }
        }
    }

    /// Takes the up direction and `g` from the backend's gravity (`+y`, 9.81 m/s² without one).
    pub(crate) fn follow_gravity(&mut self, gravity: Vec3) {
        let g = gravity.length();
        if g.is_finite() && g > 0.0 {
            self.resolved_up = -gravity / g;
            self.gravity = f64::from(g);
        } else {
            self.resolved_up = Vec3::Y;
        }
    }

    pub(crate) fn advance(&mut self, dt: f64) {
        self.time += dt;
    }

    /// The height of the water surface above the world origin along `up` at the horizontal
    /// position `(x, z)` (a y-up world: the surface's `y`), at [`Water::time`], m: the still
    /// level plus the waves' elevation there. The surface the bodies feel. `level` when the
    /// waves cannot be evaluated there (a point off a height grid that does not wrap).
    pub fn elevation(&self, x: f32, z: f32) -> f32 {
        (self.level + self.eta(f64::from(x), f64::from(z))) as f32
    }

    /// The unit normal of the water surface at `(x, z)` at [`Water::time`] (up for still
    /// water), from the slope of the elevation over ±1 cm.
    pub fn normal(&self, x: f32, z: f32) -> Vec3 {
        let (x, z, h) = (f64::from(x), f64::from(z), 0.01);
        let dx = (self.eta(x + h, z) - self.eta(x - h, z)) / (2.0 * h);
        let dz = (self.eta(x, z + h) - self.eta(x, z - h)) / (2.0 * h);
        let up = self.resolved_up();
        // In the frame of the still plane (y up): (−∂η/∂x, 1, −∂η/∂z), turned onto `up`.
        let n = Vec3::new(-dx as f32, 1.0, -dz as f32).normalize();
        bevy::math::Quat::from_rotation_arc(Vec3::Y, up) * n
    }

    /// η at the horizontal position of `(x, ·, z)` on the still plane, m (0 without waves or
    /// where they cannot be evaluated).
    fn eta(&self, x: f64, z: f64) -> f64 {
        let (Some(surface), Ok(water)) = (&self.surface, self.core()) else {
            return 0.0;
        };
        let point = water.project(&Point3::new(x, 0.0, z));
        let mut eta = [0.0];
        match surface.elevations(&water, &[point], self.time, &mut eta) {
            Ok(()) if eta[0].is_finite() => eta[0],
            _ => 0.0,
        }
    }
}
