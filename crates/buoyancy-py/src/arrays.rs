//! NumPy arrays handed to Python: read-only (their `writeable` flag cleared), so that writing to
//! an attribute's array raises instead of changing a copy that nothing reads.

use numpy::ndarray::{Array1, Array2};
use numpy::{Element, IntoPyArray, PyArray, PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;

/// `array` with its `writeable` flag cleared.
pub fn read_only<'py, T: Element, D: numpy::ndarray::Dimension>(
    array: Bound<'py, PyArray<T, D>>,
) -> Bound<'py, PyArray<T, D>> {
    // A new array has no borrows, so taking the read-write borrow succeeds; clearing the flag
    // consumes it.
    array.readwrite().make_nonwriteable();
    array
}

/// A read-only array of shape (n,) holding `values`.
pub fn vector<'py, T: Element>(py: Python<'py>, values: &[T]) -> Bound<'py, PyArray1<T>> {
    read_only(PyArray1::from_slice(py, values))
}

/// A read-only array of shape (n,) holding the items of `values`.
pub fn column<'py, T: Element>(
    py: Python<'py>,
    values: impl IntoIterator<Item = T>,
) -> Bound<'py, PyArray1<T>> {
    read_only(Array1::from_iter(values).into_pyarray(py))
}

/// A read-only array of shape (n, 3) holding the rows of `rows`.
pub fn rows3<'py, T: Element>(
    py: Python<'py>,
    rows: impl IntoIterator<Item = [T; 3]>,
) -> Bound<'py, PyArray2<T>> {
    let flat: Vec<T> = rows.into_iter().flatten().collect();
    let n = flat.len() / 3;
    let array = Array2::from_shape_vec((n, 3), flat)
        .unwrap_or_else(|_| unreachable!("rows of three values fill an (n, 3) array"));
    read_only(array.into_pyarray(py))
}
