//! The per-body arrays of `Controller.step`: each checked for its shape (one row per body) and
//! taken as a read-only view of the caller's NumPy array when it already has the dtype (a copy
//! converted by `numpy.asarray` otherwise), then read into the core's `BodyState`s with the
//! interpreter lock released.

use std::borrow::Cow;

use buoyancy_core::Pose;
use buoyancy_core::controller::{BodyState, Motion};
use buoyancy_core::nalgebra::{Matrix3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use numpy::{AllowTypeChange, Element, PyArrayLikeDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;

use crate::convert::{QUATERNION_TOLERANCE, shape_str};
use crate::errors::arg_error;

/// One per-body argument of `step`, converted to `T` and of shape `(n, *tail)`.
pub struct Input<'py, T: Element> {
    array: PyArrayLikeDyn<'py, T, AllowTypeChange>,
}

/// `(N, 3)`, `(N,)`: the expected shape as the messages print it.
fn expected(tail: &[usize]) -> String {
    let mut dims = vec!["N".to_string()];
    dims.extend(tail.iter().map(|d| d.to_string()));
    if dims.len() == 1 {
        "(N,)".into()
    } else {
        format!("({})", dims.join(", "))
    }
}

impl<'py, T: Element + Copy + 'py> Input<'py, T> {
    /// `obj` as an array of `T` (`dtype`, its NumPy name) whose shape is one of `shapes` (each
    /// the shape of a row) with one row per body (`n`); a `ValueError` naming `name`, the
    /// expected shape and the shape given otherwise. `what` says what the rows are.
    pub fn parse(
        obj: &Bound<'py, PyAny>,
        name: &str,
        n: usize,
        shapes: &[&[usize]],
        dtype: &str,
        what: &str,
    ) -> PyResult<Self>
    where
        for<'a> Vec<T>: FromPyObject<'a, 'py>,
    {
        let expected: Vec<String> = shapes.iter().map(|s| expected(s)).collect();
        let expected = expected.join(" or ");
        let array: PyArrayLikeDyn<'py, T, AllowTypeChange> = obj.extract().map_err(|e| {
            arg_error(
                name,
                format!(
                    "expected a {dtype} array of shape {expected} ({what}) with N = {n}, the number of bodies: {e}"
                ),
            )
        })?;
        let shape = array.shape();
        let fits = shapes
            .iter()
            .any(|tail| shape.len() == 1 + tail.len() && shape[0] == n && shape[1..] == **tail);
        if !fits {
            return Err(arg_error(
                name,
                format!(
                    "expected shape {expected} ({what}) with N = {n}, the number of bodies, got shape {}",
                    shape_str(shape)
                ),
            ));
        }
        Ok(Input { array })
    }

    /// The number of dimensions.
    pub fn ndim(&self) -> usize {
        self.array.ndim()
    }

    /// The values in C order: the array's own memory when it is C-contiguous, a copy otherwise.
    pub fn values(&self) -> Cow<'_, [T]> {
        match self.array.as_slice() {
            Ok(slice) if self.array.is_c_contiguous() => Cow::Borrowed(slice),
            _ => Cow::Owned(self.array.as_array().iter().copied().collect()),
        }
    }
}

/// The values of every per-body array of one step, in C order.
pub struct Columns<'a> {
    pub positions: Cow<'a, [f64]>,
    pub quaternions: Cow<'a, [f64]>,
    pub centers_of_mass: Cow<'a, [f64]>,
    pub linear_velocities: Cow<'a, [f64]>,
    pub angular_velocities: Cow<'a, [f64]>,
    pub masses: Cow<'a, [f64]>,
    /// One per body (`per_axis == false`) or three.
    pub inverse_masses: Cow<'a, [f64]>,
    pub inverse_masses_per_axis: bool,
    pub inverse_inertias: Cow<'a, [f64]>,
    pub gravity_scales: Cow<'a, [f64]>,
    pub applied_forces: Cow<'a, [f32]>,
    pub applied_torques: Cow<'a, [f32]>,
    pub dynamic: Cow<'a, [bool]>,
    pub sleeping: Cow<'a, [bool]>,
}

/// A body's input that the controller cannot take: the argument and row, and what is wrong.
pub struct Rejected {
    pub argument: &'static str,
    pub row: usize,
    pub reason: String,
}

impl Rejected {
    pub fn into_py(self) -> PyErr {
        arg_error(&format!("{}[{}]", self.argument, self.row), self.reason)
    }
}

fn v3(values: &[f64], i: usize) -> Vector3<f64> {
    Vector3::new(values[3 * i], values[3 * i + 1], values[3 * i + 2])
}

fn v3f(values: &[f32], i: usize) -> Vector3<f32> {
    Vector3::new(values[3 * i], values[3 * i + 1], values[3 * i + 2])
}

/// A unit quaternion from `(x, y, z, w)`, normalised; one that is not finite is kept as it is
/// (the controller reports the body as not finite). A finite one whose norm differs from 1 by
/// more than [`QUATERNION_TOLERANCE`] is rejected.
fn rotation(q: &[f64]) -> Result<UnitQuaternion<f64>, String> {
    let q = Quaternion::new(q[3], q[0], q[1], q[2]);
    if !q.coords.iter().all(|c| c.is_finite()) {
        return Ok(UnitQuaternion::new_unchecked(q));
    }
    let norm = q.norm();
    if (norm - 1.0).abs() > QUATERNION_TOLERANCE {
        return Err(format!(
            "the quaternion (x, y, z, w) has norm {norm}, not 1; normalise it (q / |q|) first"
        ));
    }
    Ok(UnitQuaternion::new_normalize(q))
}

/// Checks that `values` (one or more per body) are finite and, if `non_negative`, not negative.
fn check(
    values: &[f64],
    per_body: usize,
    argument: &'static str,
    non_negative: bool,
) -> Result<(), Rejected> {
    let bad = |x: &f64| !x.is_finite() || (non_negative && *x < 0.0);
    match values.iter().position(bad) {
        None => Ok(()),
        Some(k) => Err(Rejected {
            argument,
            row: k / per_body,
            reason: if non_negative {
                "must be finite and non-negative".into()
            } else {
                "has a NaN or infinite component".into()
            },
        }),
    }
}

impl Columns<'_> {
    /// The states of the `n` bodies, into `states` (cleared first). The pose, center of mass
    /// and velocities may be non-finite (the controller then reports the body as not finite);
    /// the mass properties and gravity scale must be finite, the masses and inverse masses
    /// non-negative.
    pub fn read(&self, n: usize, states: &mut Vec<BodyState>) -> Result<(), Rejected> {
        check(&self.masses, 1, "masses", true)?;
        let axes = if self.inverse_masses_per_axis { 3 } else { 1 };
        check(&self.inverse_masses, axes, "inverse_masses", true)?;
        check(&self.inverse_inertias, 9, "inverse_inertias", false)?;
        check(&self.gravity_scales, 1, "gravity_scales", false)?;
        states.clear();
        states.reserve(n);
        for i in 0..n {
            let rotation =
                rotation(&self.quaternions[4 * i..4 * i + 4]).map_err(|reason| Rejected {
                    argument: "quaternions",
                    row: i,
                    reason,
                })?;
            let inverse_mass = if self.inverse_masses_per_axis {
                v3(&self.inverse_masses, i)
            } else {
                Vector3::repeat(self.inverse_masses[i])
            };
            states.push(BodyState {
                pose: Pose::from_parts(Translation3::from(v3(&self.positions, i)), rotation),
                center_of_mass: Point3::from(v3(&self.centers_of_mass, i)),
                linear_velocity: v3(&self.linear_velocities, i),
                angular_velocity: v3(&self.angular_velocities, i),
                mass: self.masses[i],
                inverse_mass,
                inverse_inertia: Matrix3::from_row_slice(&self.inverse_inertias[9 * i..9 * i + 9]),
                gravity_scale: self.gravity_scales[i],
                applied_force: v3f(&self.applied_forces, i),
                applied_torque: v3f(&self.applied_torques, i),
                motion: if self.dynamic[i] {
                    Motion::Dynamic
                } else {
                    Motion::Inactive
                },
                sleeping: self.sleeping[i],
            });
        }
        Ok(())
    }
}
