use nalgebra::{Point3, Unit, Vector3};

use crate::{Error, Real};

/// A body of still water: its density, the magnitude of gravity, and its flat free surface.
///
/// The surface is the plane `{ p : n·p = level }` of the world frame, where `n` is the unit
/// *up* normal (pointing out of the water, against gravity) and `level` the signed distance of
/// the plane from the world origin along `n`. The signed height of a world point `p` above the
/// surface is `n·p − level`; points of negative height are under water, where the pressure is
/// `ρ·g·(level − n·p)`.
///
/// The default is fresh water (ρ = 1000 kg/m³, g = 9.81 m/s²) under a y-up surface at y = 0.
///
/// ```
/// use buoyancy_core::Water;
/// use nalgebra::{Point3, Vector3};
///
/// // Sea water with z up, surface at z = 2 m.
/// let sea = Water::new(1025.0, 9.81, Vector3::z(), 2.0).unwrap();
/// assert_eq!(sea.height(&Point3::new(5.0, 1.0, 0.5)), -1.5);
/// assert!(Water::new(-1.0, 9.81, Vector3::y(), 0.0).is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Water<T: Real> {
    density: T,
    gravity: T,
    normal: Unit<Vector3<T>>,
    level: T,
}

impl<T: Real> Default for Water<T> {
    fn default() -> Self {
        Water {
            density: T::from_f64_lossy(1000.0),
            gravity: T::from_f64_lossy(9.81),
            normal: Vector3::y_axis(),
            level: T::zero(),
        }
    }
}

impl<T: Real> Water<T> {
    /// Water of `density` (kg/m³, positive) under gravity of magnitude `gravity` (m/s²,
    /// non-negative) whose surface is the plane `n·p = level` (m) with `n = normal / |normal|`.
    ///
    /// `normal` points up, out of the water; it need not be unit length but must be finite and
    /// non-zero.
    pub fn new(density: T, gravity: T, normal: Vector3<T>, level: T) -> Result<Self, Error> {
        Water::default()
            .with_density(density)?
            .with_gravity(gravity)?
            .with_surface(normal, level)
    }

    /// The same water with another density (kg/m³, finite and positive).
    pub fn with_density(mut self, density: T) -> Result<Self, Error> {
        if !density.is_finite() || density <= T::zero() {
            return Err(Error::InvalidWater {
                parameter: "density",
                reason: "must be finite and positive (kg/m³)",
            });
        }
        self.density = density;
        Ok(self)
    }

    /// The same water under another gravity magnitude (m/s², finite and non-negative).
    pub fn with_gravity(mut self, gravity: T) -> Result<Self, Error> {
        if !gravity.is_finite() || gravity < T::zero() {
            return Err(Error::InvalidWater {
                parameter: "gravity",
                reason: "must be finite and non-negative (m/s², a magnitude)",
            });
        }
        self.gravity = gravity;
        Ok(self)
    }

    /// The same water with another surface plane `n·p = level`, `n = normal / |normal|`.
    pub fn with_surface(mut self, normal: Vector3<T>, level: T) -> Result<Self, Error> {
        if !normal.iter().all(|c| c.is_finite()) {
            return Err(Error::InvalidWater {
                parameter: "normal",
                reason: "has a NaN or infinite component",
            });
        }
        // Divided by its largest component first, so that the norm neither overflows (a
        // normal of 1e300 once became the zero vector) nor underflows (1e-300).
        let largest = normal.amax();
        if largest == T::zero() {
            return Err(Error::InvalidWater {
                parameter: "normal",
                reason: "is the zero vector; give the up direction, e.g. (0, 1, 0)",
            });
        }
        let normal = Unit::new_normalize(normal / largest);
        if !level.is_finite() {
            return Err(Error::InvalidWater {
                parameter: "level",
                reason: "must be finite (m)",
            });
        }
        self.normal = normal;
        self.level = level;
        Ok(self)
    }

    /// Fluid density ρ in kg/m³.
    pub fn density(&self) -> T {
        self.density
    }

    /// Magnitude of gravity g in m/s².
    pub fn gravity(&self) -> T {
        self.gravity
    }

    /// Unit up normal `n` of the surface, world frame.
    pub fn normal(&self) -> &Unit<Vector3<T>> {
        &self.normal
    }

    /// Signed distance of the surface from the world origin along the normal, in m.
    pub fn level(&self) -> T {
        self.level
    }

    /// Specific weight ρ·g in N/m³: the buoyant force per cubic metre displaced.
    pub fn specific_weight(&self) -> T {
        self.density * self.gravity
    }

    /// Signed height of a world point above the surface, `n·p − level`, in m (negative under water).
    pub fn height(&self, point: &Point3<T>) -> T {
        self.normal.dot(&point.coords) - self.level
    }

    /// The orthogonal projection of a world point onto the surface.
    pub fn project(&self, point: &Point3<T>) -> Point3<T> {
        point - self.normal.into_inner() * self.height(point)
    }
}
