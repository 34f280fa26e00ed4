//! Python inputs to Rust values: numbers, counts, names, instances, vectors, rotations and
//! (K, …) arrays, with errors that name the argument (`TypeError` for a wrong type, `ValueError`
//! for a wrong value). Tuples and lists of numbers take a fast path; other array-likes go
//! through `numpy.asarray(…, dtype=float64)`.

use buoyancy_core::nalgebra::{Matrix3, Matrix4, Quaternion, Rotation3, UnitQuaternion, Vector3};
use buoyancy_core::{Method, Traversal};
use numpy::{AllowTypeChange, PyArrayLikeDyn, PyUntypedArrayMethods};
use pyo3::PyTypeInfo;
use pyo3::exceptions::PyOverflowError;
use pyo3::prelude::*;
use pyo3::types::{PyList, PyString, PyTuple};

use crate::errors::{arg_error, to_py, type_error};
use crate::format::g;

/// A quaternion whose norm differs from 1 by more than this is rejected; within it, normalised.
pub const QUATERNION_TOLERANCE: f64 = 1e-5;
/// A 3×3 matrix whose `RᵀR` differs from the identity by more than this (any entry) is rejected.
pub const MATRIX_TOLERANCE: f64 = 1e-5;

/// An optional argument that was given, and not as `None`.
pub fn given<'a, 'py>(obj: Option<&'a Bound<'py, PyAny>>) -> Option<&'a Bound<'py, PyAny>> {
    obj.filter(|o| !o.is_none())
}

/// A real number (a Python `int` or `float`, a NumPy scalar, anything with `__float__`).
pub fn real(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    obj.extract::<f64>()
        .map_err(|_| type_error(name, "a number", obj))
}

/// [`real`], or `default` when the argument is absent or `None`.
pub fn real_or(obj: Option<&Bound<'_, PyAny>>, name: &str, default: f64) -> PyResult<f64> {
    given(obj).map_or(Ok(default), |o| real(o, name))
}

/// A time, s: a finite number, or 0 when the argument is absent or `None`.
pub fn time(obj: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<f64> {
    let t = real_or(obj, name, 0.0)?;
    if !t.is_finite() {
        return Err(arg_error(name, "must be finite (s)"));
    }
    Ok(t)
}

/// A non-negative integer (a Python `int`, a NumPy integer, anything with `__index__`).
pub fn count(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<usize> {
    match obj.extract::<i64>() {
        Ok(n) => usize::try_from(n)
            .map_err(|_| arg_error(name, format!("must be a non-negative integer, got {n}"))),
        Err(e) if e.is_instance_of::<PyOverflowError>(obj.py()) => {
            Err(arg_error(name, "is too large"))
        }
        Err(_) => Err(type_error(name, "an integer", obj)),
    }
}

/// [`count`], or `default` when the argument is absent or `None`.
pub fn count_or(obj: Option<&Bound<'_, PyAny>>, name: &str, default: usize) -> PyResult<usize> {
    given(obj).map_or(Ok(default), |o| count(o, name))
}

/// A string argument.
fn text(obj: &Bound<'_, PyAny>, name: &str, expected: &str) -> PyResult<String> {
    let s = obj
        .cast::<PyString>()
        .map_err(|_| type_error(name, expected, obj))?;
    Ok(s.to_str()?.to_owned())
}

/// A method name in any spelling the core accepts (`"exact_surface"`, `"ExactSurface"`,
/// `"exact-surface"`), or [`Method::Exact`] when absent or `None`.
pub fn method(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Method> {
    let Some(obj) = given(obj) else {
        return Ok(Method::Exact);
    };
    text(obj, "method", "a method name such as 'exact'")?
        .parse()
        .map_err(|e| to_py(e, Some("method")))
}

/// A traversal name in any spelling the core accepts, or [`Traversal::Auto`] when absent or
/// `None`.
pub fn traversal(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Traversal> {
    let Some(obj) = given(obj) else {
        return Ok(Traversal::Auto);
    };
    text(obj, "traversal", "a traversal name such as 'auto'")?
        .parse()
        .map_err(|e| to_py(e, Some("traversal")))
}

/// An instance of the class `T` (`water`, `coefficients`), or `None` when absent or `None`.
pub fn instance<'a, 'py, T: PyTypeInfo>(
    obj: Option<&'a Bound<'py, PyAny>>,
    name: &str,
) -> PyResult<Option<&'a Bound<'py, T>>> {
    let Some(obj) = given(obj) else {
        return Ok(None);
    };
    match obj.cast::<T>() {
        Ok(value) => Ok(Some(value)),
        Err(_) => {
            let class = T::type_object(obj.py()).name()?;
            Err(type_error(name, format!("a buoyancy.{class}"), obj))
        }
    }
}

/// An array-like converted to float64, as (shape, values in C order).
pub struct Floats {
    pub shape: Vec<usize>,
    pub values: Vec<f64>,
}

/// Converts any array-like to float64 (`numpy.asarray` semantics, so ints, float32, nested
/// lists all work), its values in C order whatever its memory layout. Fails with a
/// `ValueError` naming `name`.
pub fn floats(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Floats> {
    let array: PyArrayLikeDyn<'_, f64, AllowTypeChange> = obj
        .extract()
        .map_err(|e| arg_error(name, format!("expected an array of numbers ({e})")))?;
    let shape = array.shape().to_vec();
    // `as_slice` also accepts a Fortran-ordered array, in its memory order.
    let values = match array.as_slice() {
        Ok(slice) if array.is_c_contiguous() => slice.to_vec(),
        _ => array.as_array().iter().copied().collect(),
    };
    Ok(Floats { shape, values })
}

/// Shape as Python prints it: `(5, 4)`, `(3,)`, `()`.
pub fn shape_str(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(|n| n.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// `N` numbers from a tuple or list of numbers without going through numpy, or `None`.
#[inline]
fn small_sequence<const N: usize>(obj: &Bound<'_, PyAny>) -> Option<[f64; N]> {
    let mut out = [0.0; N];
    if let Ok(t) = obj.cast::<PyTuple>() {
        if t.len() != N {
            return None;
        }
        for (i, o) in out.iter_mut().enumerate() {
            *o = t.get_borrowed_item(i).ok()?.extract::<f64>().ok()?;
        }
        Some(out)
    } else if let Ok(l) = obj.cast::<PyList>() {
        if l.len() != N {
            return None;
        }
        for (i, o) in out.iter_mut().enumerate() {
            *o = l.get_item(i).ok()?.extract::<f64>().ok()?;
        }
        Some(out)
    } else {
        None
    }
}

/// Checks that every value is finite, naming the argument.
pub fn finite(values: &[f64], name: &str) -> PyResult<()> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(arg_error(name, "has a NaN or infinite component"))
    }
}

/// A finite 3-vector from any array-like of shape (3,).
pub fn vector3(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vector3<f64>> {
    let v = match small_sequence::<3>(obj) {
        Some(v) => v,
        None => {
            let a = floats(obj, name)?;
            if a.shape != [3] {
                return Err(arg_error(
                    name,
                    format!(
                        "expected 3 numbers (shape (3,)), got shape {}",
                        shape_str(&a.shape)
                    ),
                ));
            }
            [a.values[0], a.values[1], a.values[2]]
        }
    };
    finite(&v, name)?;
    Ok(Vector3::from(v))
}

/// A rotation from a quaternion `(x, y, z, w)` or a 3×3 rotation matrix (row-major values).
pub fn rotation(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<UnitQuaternion<f64>> {
    if let Some(q) = small_sequence::<4>(obj) {
        return quaternion(&q, name);
    }
    let a = floats(obj, name)?;
    match a.shape.as_slice() {
        [4] => quaternion(&a.values, name),
        [3, 3] => matrix(&a.values, name),
        _ => Err(arg_error(
            name,
            format!(
                "expected a quaternion (x, y, z, w) of shape (4,) or a rotation matrix of shape (3, 3), got shape {}",
                shape_str(&a.shape)
            ),
        )),
    }
}

/// A unit quaternion from `(x, y, z, w)`: non-finite or non-unit (beyond
/// [`QUATERNION_TOLERANCE`]) is an error; within the tolerance it is normalised.
pub fn quaternion(q: &[f64], name: &str) -> PyResult<UnitQuaternion<f64>> {
    finite(q, name)?;
    let q = Quaternion::new(q[3], q[0], q[1], q[2]);
    let norm = q.norm();
    if (norm - 1.0).abs() > QUATERNION_TOLERANCE {
        return Err(arg_error(
            name,
            format!(
                "the quaternion (x, y, z, w) has norm {norm}, not 1; normalise it (q / |q|) first"
            ),
        ));
    }
    Ok(UnitQuaternion::new_normalize(q))
}

/// A rotation from a row-major 3×3 matrix: it must be orthonormal (within
/// [`MATRIX_TOLERANCE`]) with determinant +1.
pub fn matrix(m: &[f64], name: &str) -> PyResult<UnitQuaternion<f64>> {
    finite(m, name)?;
    let m = Matrix3::from_row_slice(m);
    let gram = m.transpose() * m - Matrix3::identity();
    let worst = gram.iter().fold(0.0f64, |w, x| w.max(x.abs()));
    if worst > MATRIX_TOLERANCE {
        return Err(arg_error(
            name,
            format!(
                "the 3×3 matrix is not a rotation: RᵀR differs from the identity by {}",
                g(worst)
            ),
        ));
    }
    if m.determinant() <= 0.0 {
        return Err(arg_error(
            name,
            "the 3×3 matrix is a reflection (determinant −1), not a rotation",
        ));
    }
    Ok(UnitQuaternion::from_rotation_matrix(
        &Rotation3::from_matrix_unchecked(m),
    ))
}

/// Rows of a (K, 3) array-like, finite.
pub fn rows3(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<Vector3<f64>>> {
    let a = floats(obj, name)?;
    if a.shape.len() != 2 || a.shape[1] != 3 {
        return Err(arg_error(
            name,
            format!("expected shape (K, 3), got shape {}", shape_str(&a.shape)),
        ));
    }
    if let Some(k) = a
        .values
        .chunks_exact(3)
        .position(|r| !r.iter().all(|x| x.is_finite()))
    {
        return Err(arg_error(
            &format!("{name}[{k}]"),
            "has a NaN or infinite component",
        ));
    }
    Ok(a.values
        .chunks_exact(3)
        .map(Vector3::from_column_slice)
        .collect())
}

/// Rotations from a (K, 4) array of quaternions `(x, y, z, w)` or a (K, 3, 3) array of matrices.
pub fn rotations(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<UnitQuaternion<f64>>> {
    let a = floats(obj, name)?;
    match a.shape.as_slice() {
        [_, 4] => a
            .values
            .chunks_exact(4)
            .enumerate()
            .map(|(k, q)| quaternion(q, &format!("{name}[{k}]")))
            .collect(),
        [_, 3, 3] => a
            .values
            .chunks_exact(9)
            .enumerate()
            .map(|(k, m)| matrix(m, &format!("{name}[{k}]")))
            .collect(),
        _ => Err(arg_error(
            name,
            format!(
                "expected quaternions (x, y, z, w) of shape (K, 4) or rotation matrices of shape (K, 3, 3), got shape {}",
                shape_str(&a.shape)
            ),
        )),
    }
}

/// An affine map as a 4×4 homogeneous matrix (row-major values), finite.
pub fn matrix4(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Matrix4<f64>> {
    let a = floats(obj, name)?;
    if a.shape != [4, 4] {
        return Err(arg_error(
            name,
            format!(
                "expected a 4×4 homogeneous matrix [[A, b], [0, 0, 0, 1]], got shape {}",
                shape_str(&a.shape)
            ),
        ));
    }
    finite(&a.values, name)?;
    Ok(Matrix4::from_row_slice(&a.values))
}
