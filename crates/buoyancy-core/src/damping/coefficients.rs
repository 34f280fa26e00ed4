//! The coefficients of the damping model: [`DampingCoefficients`].

use nalgebra::Vector3;

#[cfg(doc)]
use crate::Mesh;
use crate::{Error, Real};

/// The coefficients of the damping model (see the [module documentation](crate::damping)), SI units.
///
/// Every coefficient is finite and non-negative, and the current finite: the constructor and
/// the `with_*` methods check it, so a `DampingCoefficients` is always valid.
/// [`Default`] is a model of a rough body in still water; [`DampingCoefficients::off`] switches
/// damping off.
///
/// ```
/// use buoyancy_core::{DampingCoefficients, Error};
/// use nalgebra::Vector3;
///
/// let calm = DampingCoefficients::<f64>::default().with_current(Vector3::new(0.5, 0.0, 0.0))?;
/// assert_eq!(calm.linear_drag(), 1000.0);
/// assert!(matches!(
///     DampingCoefficients::<f64>::new(-1.0, 1.0, 0.1, 0.1),
///     Err(Error::InvalidDamping { parameter: "linear_drag", .. })
/// ));
/// # Ok::<(), Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DampingCoefficients<T: Real> {
    linear_drag: T,
    drag_coefficient: T,
    angular_drag_linear: T,
    angular_drag_quadratic: T,
    current: Vector3<T>,
}

impl<T: Real> Default for DampingCoefficients<T> {
    fn default() -> Self {
        DampingCoefficients {
            linear_drag: T::from_f64_lossy(1000.0),
            drag_coefficient: T::from_f64_lossy(1.0),
            angular_drag_linear: T::from_f64_lossy(0.1),
            angular_drag_quadratic: T::from_f64_lossy(0.1),
            current: Vector3::zeros(),
        }
    }
}

impl<T: Real> DampingCoefficients<T> {
    /// The coefficients `c₁ = linear_drag` (Pa per m/s), `C_D = drag_coefficient`,
    /// `a₁ = angular_drag_linear` (1/s) and `a₂ = angular_drag_quadratic`, in still water.
    ///
    /// # Errors
    /// [`Error::InvalidDamping`] naming the first coefficient that is negative or not finite.
    pub fn new(
        linear_drag: T,
        drag_coefficient: T,
        angular_drag_linear: T,
        angular_drag_quadratic: T,
    ) -> Result<Self, Error> {
        Ok(DampingCoefficients {
            linear_drag: coefficient(linear_drag, "linear_drag")?,
            drag_coefficient: coefficient(drag_coefficient, "drag_coefficient")?,
            angular_drag_linear: coefficient(angular_drag_linear, "angular_drag_linear")?,
            angular_drag_quadratic: coefficient(angular_drag_quadratic, "angular_drag_quadratic")?,
            current: Vector3::zeros(),
        })
    }

    /// No damping at all: [`Mesh::damping`] returns zero force and torque without looking at the
    /// triangles.
    pub fn off() -> Self {
        DampingCoefficients {
            linear_drag: T::zero(),
            drag_coefficient: T::zero(),
            angular_drag_linear: T::zero(),
            angular_drag_quadratic: T::zero(),
            current: Vector3::zeros(),
        }
    }

    /// `c₁`, the linear pressure-drag coefficient in Pa per m/s (N·s/m³): the pressure on a
    /// wetted face moving into the water at 1 m/s. Default 1000 (≈ ρ·1 m/s for fresh water):
    /// about a fifth of critical damping on the down stroke of the heave of a 1 m cube floating
    /// half submerged.
    pub fn linear_drag(&self) -> T {
        self.linear_drag
    }

    /// `C_D`, the dimensionless pressure drag coefficient: the quadratic pressure is
    /// `½·ρ·C_D·u_n²`. Default 1 (a flat plate face-on is about 1.2, a sphere about 0.5).
    pub fn drag_coefficient(&self) -> T {
        self.drag_coefficient
    }

    /// `a₁`, the linear angular damping rate in 1/s. Default 0.1.
    pub fn angular_drag_linear(&self) -> T {
        self.angular_drag_linear
    }

    /// `a₂`, the dimensionless quadratic angular damping coefficient. Default 0.1.
    pub fn angular_drag_quadratic(&self) -> T {
        self.angular_drag_quadratic
    }

    /// `v_w`, the velocity of the water (a uniform current), world frame, m/s. Default zero.
    pub fn current(&self) -> Vector3<T> {
        self.current
    }

    /// The same coefficients with another `c₁` (Pa per m/s, finite and non-negative).
    pub fn with_linear_drag(mut self, linear_drag: T) -> Result<Self, Error> {
        self.linear_drag = coefficient(linear_drag, "linear_drag")?;
        Ok(self)
    }

    /// The same coefficients with another `C_D` (finite and non-negative).
    pub fn with_drag_coefficient(mut self, drag_coefficient: T) -> Result<Self, Error> {
        self.drag_coefficient = coefficient(drag_coefficient, "drag_coefficient")?;
        Ok(self)
    }

    /// The same coefficients with another angular damping `a₁` (1/s) and `a₂` (finite and
    /// non-negative).
    pub fn with_angular_drag(mut self, linear: T, quadratic: T) -> Result<Self, Error> {
        self.angular_drag_linear = coefficient(linear, "angular_drag_linear")?;
        self.angular_drag_quadratic = coefficient(quadratic, "angular_drag_quadratic")?;
        Ok(self)
    }

    /// The same coefficients in a uniform current `v_w` (world frame, m/s, finite).
    pub fn with_current(mut self, current: Vector3<T>) -> Result<Self, Error> {
        if !current.iter().all(|c| c.is_finite()) {
            return Err(Error::InvalidDamping {
                parameter: "current",
                reason: "has a NaN or infinite component",
            });
        }
        self.current = current;
        Ok(self)
    }

    /// Whether every coefficient is zero (the current alone damps nothing).
    pub fn is_off(&self) -> bool {
        self.linear_drag == T::zero()
            && self.drag_coefficient == T::zero()
            && self.angular_drag_linear == T::zero()
            && self.angular_drag_quadratic == T::zero()
    }
}

/// `value` if it is finite and non-negative, else [`Error::InvalidDamping`] naming `parameter`.
fn coefficient<T: Real>(value: T, parameter: &'static str) -> Result<T, Error> {
    if value.is_finite() && value >= T::zero() {
        Ok(value)
    } else {
        Err(Error::InvalidDamping {
            parameter,
            reason: "must be finite and non-negative",
        })
    }
}
