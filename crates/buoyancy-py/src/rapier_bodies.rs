//! The Rust side of `buoyancy.rapier`'s glue, one call per step for all bodies:
//!
//! - `_rapier_bodies`: the state of many rigid bodies of rapier3d, rapier's Python binding, read
//!   from their serialisations (`RigidBody.to_bytes`): the bulk read of `buoyancy.rapier`, which
//!   checks it at import against rapier3d's getters, bit for bit, and reads with the getters
//!   should it differ. Thin: the numbers as the getters return them, nothing computed but what
//!   the getters compute.
//! - `_world_inverse_inertias`: the bodies' world inverse inertias `R·I⁻¹·Rᵀ` from those in
//!   their own frames (NumPy's stacked 3×3 products cost about a microsecond a body).

use buoyancy_core::nalgebra::{Matrix3, Quaternion, UnitQuaternion};
use numpy::ndarray::{Array2, Array3};
use numpy::{Element, IntoPyArray, PyArray2, PyArray3};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyList};

use crate::arrays::read_only;
use crate::errors::type_error;
use crate::step_inputs::Input;

// rapier's `RigidBody` as rapier3d serialises it: an 8-byte header, then the fields in their
// declared order, packed. The bytes before the mass properties' optional additional mass and
// those after the list of colliders have fixed sizes. From the start:
/// `pos.position`: the rotation (x, y, z, w), then the translation.
const ROTATION: usize = 24;
const TRANSLATION: usize = 40;
/// `vels`: the linear, then the angular velocity.
const LINVEL: usize = 96;
const ANGVEL: usize = 108;
/// `forces`: the gravity scale, then the user force and torque.
const GRAVITY_SCALE: usize = 144;
const USER_FORCE: usize = 148;
const USER_TORQUE: usize = 160;
/// `mprops`: the world center of mass, ..., the mass properties in the body's frame (local
/// center of mass, inverse mass, inverse principal inertia, principal frame), the locked axes.
const WORLD_COM: usize = 173;
const MASS_PROPERTIES: usize = 221;
const MASS_PROPERTIES_LEN: usize = 44;
const INVERSE_MASS: usize = 233;
const LOCKED_AXES: usize = 265;
const HEAD: usize = 266;
// From the end:
/// `activation.sleeping`.
const SLEEPING: usize = 91;
/// `body_type`, a little-endian u32: 0 dynamic, 1 fixed, 2 and 3 kinematic.
const BODY_TYPE: usize = 54;
/// `enabled`.
const ENABLED: usize = 49;

/// The columns of the values array.
const VALUES: usize = 18;

fn four(bytes: &[u8], at: usize) -> [u8; 4] {
    [bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]
}

fn f32_at(bytes: &[u8], at: usize) -> f32 {
    f32::from_le_bytes(four(bytes, at))
}

fn f32s<const N: usize>(bytes: &[u8], at: usize) -> [f32; N] {
    std::array::from_fn(|k| f32_at(bytes, at + 4 * k))
}

/// A read-only (n, width) array of `values`, row by row.
fn array<'py, T: Element>(
    py: Python<'py>,
    n: usize,
    width: usize,
    values: Vec<T>,
) -> Bound<'py, PyArray2<T>> {
    let array = Array2::from_shape_vec((n, width), values)
        .unwrap_or_else(|_| unreachable!("n rows of `width` values fill an (n, width) array"));
    read_only(array.into_pyarray(py))
}

/// One body's rows of the values, wrench and flags arrays, and its mass properties' bytes.
type Body<'b> = ([f64; VALUES], [f32; 6], [u8; 3], &'b [u8]);

/// The state of one body, or `None` if `bytes` does not look like a serialised body whose
/// header is `header`.
fn body<'b>(bytes: &'b [u8], header: &[u8]) -> Option<Body<'b>> {
    let len = bytes.len();
    if len < HEAD + SLEEPING || bytes.get(..header.len())? != header {
        return None;
    }
    let sleeping = bytes[len - SLEEPING];
    let body_type = u32::from_le_bytes(four(bytes, len - BODY_TYPE));
    let enabled = bytes[len - ENABLED];
    let locked = bytes[LOCKED_AXES];
    if sleeping > 1 || enabled > 1 || body_type > 3 || locked >= 64 {
        return None;
    }
    let dynamic = body_type == 0;
    // The rotation as rapier3d's getters return it: normalised in float32, the squares summed
    // in this order.
    let [x, y, z, w] = f32s::<4>(bytes, ROTATION);
    let norm = ((x * x + z * z) + (y * y + w * w)).sqrt();
    let rotation = [x / norm, y / norm, z / norm, w / norm];
    // The mass as rapier computes it (parry's `utils::inv`): zero for a zero inverse mass.
    let inverse_mass = f32_at(bytes, INVERSE_MASS);
    let mass = if inverse_mass == 0.0 {
        0.0
    } else {
        1.0 / inverse_mass
    };
    let mut values = [0.0; VALUES];
    let columns = rotation
        .into_iter()
        .chain(f32s::<3>(bytes, TRANSLATION))
        .chain(f32s::<3>(bytes, WORLD_COM))
        .chain(f32s::<3>(bytes, LINVEL))
        .chain(f32s::<3>(bytes, ANGVEL))
        .chain([mass, f32_at(bytes, GRAVITY_SCALE)]);
    for (value, column) in values.iter_mut().zip(columns) {
        *value = f64::from(column);
    }
    // rapier's getters read no user force or torque on a body that is not dynamic.
    let wrench = if dynamic {
        let [fx, fy, fz] = f32s::<3>(bytes, USER_FORCE);
        let [tx, ty, tz] = f32s::<3>(bytes, USER_TORQUE);
        [fx, fy, fz, tx, ty, tz]
    } else {
        [0.0; 6]
    };
    let flags = [u8::from(dynamic && enabled == 1), sleeping, locked];
    let mass_properties = &bytes[MASS_PROPERTIES..MASS_PROPERTIES + MASS_PROPERTIES_LEN];
    Some((values, wrench, flags, mass_properties))
}

/// The arrays and list that [`rapier_bodies`] returns.
pub type Bodies<'py> = (
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f32>>,
    Bound<'py, PyArray2<u8>>,
    Bound<'py, PyList>,
);

/// _rapier_bodies(blobs, header)
///
/// The state of the rigid bodies whose ``RigidBody.to_bytes`` are ``blobs`` (a list of
/// ``bytes``, each starting with ``header``), as rapier3d's getters return it; ``None`` if one
/// does not look like a serialised body. A tuple of
///
/// - values, float64 (N, 18): the rotation (x, y, z, w), translation, world center of mass,
///   linear and angular velocities, mass and gravity scale;
/// - wrench, float32 (N, 6): the user force and torque (zero unless the body is dynamic);
/// - flags, uint8 (N, 3): dynamic and enabled, sleeping, the locked axes' bits;
/// - the serialised mass properties in each body's frame, a list of ``bytes``.
#[pyfunction(name = "_rapier_bodies")]
pub fn rapier_bodies<'py>(
    py: Python<'py>,
    blobs: &Bound<'py, PyList>,
    header: &[u8],
) -> PyResult<Option<Bodies<'py>>> {
    let n = blobs.len();
    let mut values = Vec::with_capacity(n * VALUES);
    let mut wrenches = Vec::with_capacity(n * 6);
    let mut flags = Vec::with_capacity(n * 3);
    let mut keys = Vec::with_capacity(n);
    for (i, item) in blobs.iter().enumerate() {
        let blob = item
            .cast::<PyBytes>()
            .map_err(|_| type_error(&format!("blobs[{i}]"), "bytes", &item))?;
        let Some((row, wrench, flag, mass_properties)) = body(blob.as_bytes(), header) else {
            return Ok(None);
        };
        values.extend_from_slice(&row);
        wrenches.extend_from_slice(&wrench);
        flags.extend_from_slice(&flag);
        keys.push(PyBytes::new(py, mass_properties));
    }
    Ok(Some((
        array(py, n, VALUES, values),
        array(py, n, 6, wrenches),
        array(py, n, 3, flags),
        PyList::new(py, keys)?,
    )))
}

/// _world_inverse_inertias(quaternions, inverse_inertias)
///
/// The world inverse inertia tensors ``R·I⁻¹·Rᵀ``, float64 (N, 3, 3), 1/(kg·m²), of bodies
/// turned by the unit quaternions ``quaternions`` ``(x, y, z, w)`` (N, 4) from their inverse
/// inertia tensors in their own frames ``inverse_inertias`` (N, 3, 3). A quaternion with a NaN or
/// infinite component counts as no rotation (its body gets no force; its inertia stays finite).
#[pyfunction(name = "_world_inverse_inertias")]
pub fn world_inverse_inertias<'py>(
    py: Python<'py>,
    quaternions: &Bound<'py, PyAny>,
    inverse_inertias: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArray3<f64>>> {
    let n = quaternions.len()?;
    let what = "one quaternion (x, y, z, w) per body";
    let quaternions = Input::<f64>::parse(quaternions, "quaternions", n, &[&[4]], "float64", what)?;
    let what = "one 3×3 inverse inertia tensor per body, in its frame";
    let inverse_inertias = Input::<f64>::parse(
        inverse_inertias,
        "inverse_inertias",
        n,
        &[&[3, 3]],
        "float64",
        what,
    )?;
    let (q, local) = (quaternions.values(), inverse_inertias.values());
    let mut world = Vec::with_capacity(9 * n);
    for i in 0..n {
        let [x, y, z, w] = [q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]];
        let quaternion = Quaternion::new(w, x, y, z);
        let rotation = if quaternion.coords.iter().all(|c| c.is_finite()) {
            UnitQuaternion::new_unchecked(quaternion)
                .to_rotation_matrix()
                .into_inner()
        } else {
            Matrix3::identity()
        };
        // Row-major in, row-major out.
        let inverse_inertia = Matrix3::from_row_slice(&local[9 * i..9 * i + 9]);
        let turned = rotation * inverse_inertia * rotation.transpose();
        world.extend((0..9).map(|k| turned[(k / 3, k % 3)]));
    }
    let array = Array3::from_shape_vec((n, 3, 3), world)
        .unwrap_or_else(|_| unreachable!("nine values per body fill an (n, 3, 3) array"));
    Ok(array.into_pyarray(py))
}
