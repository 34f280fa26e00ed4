//! `_gather_bytes`: byte ranges of many `bytes` objects, side by side in one NumPy array. The
//! bulk read of `buoyancy.rapier`, which reads every rigid body's state from its serialisation
//! (rapier3d's `RigidBody.to_bytes`) at offsets that it knows and checks: thin, no layout here,
//! only the copy that NumPy makes in several passes (the lengths, a join, a copy per range).

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyList};

use crate::arrays::read_only;
use crate::errors::{arg_error, type_error};

/// _gather_bytes(blobs, ranges)
///
/// The bytes of every ``blob`` of ``blobs`` (a list of ``bytes``) at each ``(offset, length)``
/// of ``ranges``: ``blob[offset:offset + length]``, with a negative ``offset`` counted from the
/// blob's end as in a slice. One row per blob, the ranges side by side in their order: a
/// read-only ``uint8`` array of shape ``(len(blobs), sum of the lengths)``, C-contiguous. A
/// ``ValueError`` names the first blob that a range does not fit in.
#[pyfunction(name = "_gather_bytes")]
pub fn gather_bytes<'py>(
    py: Python<'py>,
    blobs: &Bound<'py, PyList>,
    ranges: Vec<(isize, usize)>,
) -> PyResult<Bound<'py, PyArray2<u8>>> {
    let width = ranges
        .iter()
        .try_fold(0usize, |width, &(_, length)| width.checked_add(length))
        .ok_or_else(|| arg_error("ranges", "the lengths add up to more than a usize holds"))?;
    let n = blobs.len();
    let mut gathered = Vec::new();
    for (i, item) in blobs.iter().enumerate() {
        let blob = item
            .cast::<PyBytes>()
            .map_err(|_| type_error(&format!("blobs[{i}]"), "bytes", &item))?;
        let bytes = blob.as_bytes();
        for &(offset, length) in &ranges {
            let start = if offset < 0 {
                bytes.len().checked_sub(offset.unsigned_abs())
            } else {
                Some(offset.unsigned_abs())
            };
            let Some(part) = start.and_then(|s| bytes.get(s..s.checked_add(length)?)) else {
                return Err(arg_error(
                    &format!("blobs[{i}]"),
                    format!(
                        "{} bytes: no {length} bytes at offset {offset}",
                        bytes.len()
                    ),
                ));
            };
            gathered.extend_from_slice(part);
        }
        if i == 0 {
            // The first row is whole, its ranges in the first blob: the other rows' room.
            gathered.reserve_exact((n - 1) * width);
        }
    }
    let array = Array2::from_shape_vec((n, width), gathered)
        .unwrap_or_else(|_| unreachable!("n rows of `width` bytes fill an (n, width) array"));
    Ok(read_only(array.into_pyarray(py)))
}
