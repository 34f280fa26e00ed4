//! Python inputs to Rust values: numbers, counts, names, instances, vectors, rotations and
//! (K, …) arrays, with errors that name the argument (`TypeError` for a wrong type, `ValueError`
//! for a wrong value). Tuples and lists of numbers take a fast path; other array-likes go
//! through `numpy.asarray(…, dtype=float64)`.

use buoyancy_core::nalgebra::{Matrix3, Matrix4, Quaternion, Rotation3, UnitQuaternion, Vector3};
use buoyancy_core::{Method, Traversal};
use numpy::{
    AllowTypeChange, PyArrayDescrMethods, PyArrayLikeDyn, PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::PyTypeInfo;
use pyo3::exceptions::{PyOverflowError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt, PyList, PyString, PyTuple};

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

/// Whether `obj` is a Python or NumPy boolean, which is an `int` to Python but never a number
/// here: `True` as a coordinate, a count or an index is a mistake.
fn is_bool(obj: &Bound<'_, PyAny>) -> bool {
    if obj.is_instance_of::<PyBool>() {
        return true;
    }
    // The common cases first: a Python float or int (not a bool, checked above) is a number.
    if obj.is_instance_of::<PyFloat>() || obj.is_instance_of::<PyInt>() {
        return false;
    }
    obj.get_type()
        .name()
        .is_ok_and(|n| n.to_str().is_ok_and(|n| n == "bool" || n == "bool_"))
}

/// A real number (a Python `int` or `float`, a NumPy scalar, anything with `__float__`; not a
/// `bool`).
pub fn real(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    if is_bool(obj) {
        return Err(type_error(name, "a number", obj));
    }
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

/// A non-negative integer (a Python `int`, a NumPy integer, anything with `__index__`; not a
/// `bool`).
pub fn count(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<usize> {
    if is_bool(obj) {
        return Err(type_error(name, "an integer", obj));
    }
    match obj.extract::<i64>() {
        Ok(n) => usize::try_from(n)
            .map_err(|_| arg_error(name, format!("must be a non-negative integer, got {n}"))),
        Err(e) if e.is_instance_of::<PyOverflowError>(obj.py()) => Err(arg_error(
            name,
            format!("must be at most {}, got {}", i64::MAX, python_str(obj)),
        )),
        Err(_) => Err(type_error(name, "an integer", obj)),
    }
}

/// An integer from 0 to 2⁶⁴ − 1 (a random seed): out of that range is a `ValueError` giving
/// the value, another type a `TypeError`.
pub fn unsigned64(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<u64> {
    if is_bool(obj) {
        return Err(type_error(name, "an integer", obj));
    }
    match obj.extract::<u64>() {
        Ok(n) => Ok(n),
        // An integer out of range (a Python `int`, or a NumPy one through `__index__`).
        Err(_) if obj.is_instance_of::<PyInt>() || obj.hasattr("__index__").unwrap_or(false) => {
            Err(arg_error(
                name,
                format!(
                    "must be an integer from 0 to 2**64 - 1, got {}",
                    python_str(obj)
                ),
            ))
        }
        Err(_) => Err(type_error(name, "an integer from 0 to 2**64 - 1", obj)),
    }
}

/// An index (a Python `int`, a NumPy integer; not a `bool`): `Ok(None)` for an integer beyond
/// the 64-bit range, which the caller reports as out of range; a `TypeError` for another type.
pub fn index(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Option<i64>> {
    if is_bool(obj) {
        return Err(type_error(name, "an integer", obj));
    }
    match obj.extract::<i64>() {
        Ok(i) => Ok(Some(i)),
        Err(e) if e.is_instance_of::<PyOverflowError>(obj.py()) => Ok(None),
        Err(_) => Err(type_error(name, "an integer", obj)),
    }
}

/// `str(obj)`, or `?` when that fails.
pub fn python_str(obj: &Bound<'_, PyAny>) -> String {
    obj.str().map_or_else(|_| "?".into(), |s| s.to_string())
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

/// Converts any array-like of real numbers to float64 (`numpy.asarray` semantics, so ints,
/// float32, nested lists all work), its values in C order whatever its memory layout. Fails
/// with a `ValueError` naming `name`, or a `TypeError` for booleans, complex numbers, strings
/// and other objects (which NumPy would cast, dropping an imaginary part or reading `True` as
/// 1).
pub fn floats(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Floats> {
    // A list or tuple is read by NumPy first: the array it makes says what it holds.
    let array = match obj.cast::<PyUntypedArray>() {
        Ok(array) => array.clone(),
        Err(_) => {
            let asarray = obj.py().import("numpy")?.getattr("asarray")?;
            let array = asarray
                .call1((obj,))
                .map_err(|e| arg_error(name, format!("expected an array of numbers ({e})")))?;
            array
                .cast_into::<PyUntypedArray>()
                .map_err(|_| type_error(name, "an array of numbers", obj))?
        }
    };
    let kind = array.dtype().kind();
    // Objects (`O`) are converted one by one below, which fails for anything but a number.
    let held = match kind {
        b'b' => Some("booleans"),
        b'c' => Some("complex numbers"),
        b'U' | b'S' => Some("strings"),
        b'V' | b'M' | b'm' => Some("structured or date values"),
        _ => None,
    };
    if let Some(held) = held {
        return Err(PyTypeError::new_err(format!(
            "{name}: expected an array of real numbers, got an array of {held}"
        )));
    }
    let array: PyArrayLikeDyn<'_, f64, AllowTypeChange> = array
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

/// `N` numbers from a tuple or list of numbers without going through numpy, or `None` (then
/// [`floats`] reads it). A `bool` among them is a `TypeError` naming `name` (NumPy would make
/// `[1, 0, True]` an array of integers).
#[inline]
fn small_sequence<const N: usize>(
    obj: &Bound<'_, PyAny>,
    name: &str,
) -> PyResult<Option<[f64; N]>> {
    let mut out = [0.0; N];
    let tuple = obj.cast::<PyTuple>().ok();
    let list = obj.cast::<PyList>().ok();
    let len = match (&tuple, &list) {
        (Some(t), _) => t.len(),
        (_, Some(l)) => l.len(),
        _ => return Ok(None),
    };
    if len != N {
        return Ok(None);
    }
    for (k, o) in out.iter_mut().enumerate() {
        let item = match (&tuple, &list) {
            (Some(t), _) => t.get_item(k),
            (_, Some(l)) => l.get_item(k),
            _ => return Ok(None),
        };
        let Ok(item) = item else {
            return Ok(None);
        };
        if is_bool(&item) {
            return Err(PyTypeError::new_err(format!(
                "{name}: expected an array of real numbers, got a bool at [{k}]"
            )));
        }
        match item.extract::<f64>() {
            Ok(x) => *o = x,
            Err(_) => return Ok(None),
        }
    }
    Ok(Some(out))
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
    let v = match small_sequence::<3>(obj, name)? {
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
    if let Some(q) = small_sequence::<4>(obj, name)? {
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

/// The `method` and `traversal` arguments as the core's query (`exact` and `auto` when absent or
/// `None`); whether the water allows them is the core's to say.
pub fn query(
    method: Option<&Bound<'_, PyAny>>,
    traversal: Option<&Bound<'_, PyAny>>,
) -> PyResult<buoyancy_core::query::Query> {
    Ok(buoyancy_core::query::Query::new(self::method(method)?)
        .with_traversal(self::traversal(traversal)?))
}
