use alloc::string::String;
use alloc::vec::Vec;
use core::fmt;

use crate::MeshDefects;

/// Everything that can go wrong in this crate: a mesh that is not a closed, consistently
/// oriented 2-manifold, a water description that is not physical, a pose that is not finite, or
/// a mesh file that cannot be read.
///
/// Indices in the messages are zero-based: `vertex 3` is the fourth vertex given to
/// [`Mesh::new`](crate::Mesh::new), `triangle 7` the eighth index triple.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// The mesh has no triangles.
    EmptyMesh,
    /// A floating body was given no mesh ([`controller`](crate::controller)).
    EmptyBody,
    /// A loading condition's input is out of range
    /// ([`LoadingCondition`](crate::hydrostatics::LoadingCondition)).
    InvalidLoading {
        /// The input's name: `center_of_gravity`, `mass`, `reference_point`,
        /// `longitudinal_axis` or `keel`.
        parameter: &'static str,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// The mass of an equilibrium or righting-arm computation
    /// ([`Mesh::equilibrium`](crate::Mesh::equilibrium)) is missing, zero or not finite.
    InvalidMass {
        /// What is wrong with it.
        reason: &'static str,
    },
    /// The body is too heavy to float: its mass is at least the mass of the water its whole
    /// volume displaces, or within the solver's tolerance of it, where it hangs submerged at
    /// any depth ([`Mesh::equilibrium`](crate::Mesh::equilibrium)).
    TooHeavyToFloat {
        /// The mass given, kg.
        mass: f64,
        /// `ρ·V`, the mass of water the whole body displaces, kg: the largest mass that floats
        /// (at it, the body hangs fully submerged at any depth).
        capacity: f64,
    },
    /// The equilibrium solver did not reach its tolerance
    /// ([`Mesh::equilibrium`](crate::Mesh::equilibrium)).
    NoConvergence {
        /// Newton iterations taken.
        iterations: usize,
        /// The largest relative residual left: force/(m·g) or moment/(m·g·L).
        residual: f64,
        /// The tolerance it had to reach.
        tolerance: f64,
    },
    /// An option of the equilibrium or righting-arm solver is out of range
    /// ([`EquilibriumOptions`](crate::hydrostatics::EquilibriumOptions),
    /// [`Mesh::gz_curve`](crate::Mesh::gz_curve)).
    InvalidSolverOption {
        /// The option's name: `tolerance`, `max_iterations`, `heels` or `trim`.
        parameter: &'static str,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A request whose memory cannot be allocated: a shape's resolution, a sea state's
    /// component count, a table's drafts or a curve's heels that need more memory than the
    /// system gives. Checked before the work (the allocator's failure would abort the process).
    OutOfMemory {
        /// The parameter whose size asked for the memory, as named in the function's signature.
        parameter: &'static str,
        /// The bytes asked for (saturated at `usize::MAX`).
        bytes: usize,
    },
    /// More vertices than a `u32` index can address.
    TooManyVertices {
        /// Number of vertices given.
        count: usize,
    },
    /// The mesh is not a closed, consistently oriented 2-manifold with finite vertices: every
    /// problem found, counted by kind, with the first few culprits of each and what the mesh
    /// shows of the cause (see [`MeshDefects`]).
    InvalidMesh(MeshDefects),
    /// The mesh is closed but encloses no volume: `|volume| ≤ 1e-12·scale` (it is flat, or
    /// parts wound inward cancel parts wound outward), or the volume overflowed.
    ZeroVolume {
        /// The signed volume found, m³ (mesh frame).
        volume: f64,
        /// The volume scale of the mesh, m³: the sum of the absolute volumes of the tetrahedra
        /// that each triangle spans with the middle of the bounding box. Zero when every
        /// triangle lies in a plane through that point, as in a flat mesh.
        scale: f64,
    },
    /// A water parameter is out of its physical range.
    InvalidWater {
        /// The parameter's name: `density`, `gravity`, `normal` or `level`.
        parameter: &'static str,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// The pose has a NaN or infinite component, or a zero rotation quaternion.
    InvalidPose {
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A damping coefficient is negative or not finite, or the current is not finite.
    InvalidDamping {
        /// The coefficient's name, a field of `DampingCoefficients`.
        parameter: &'static str,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A procedural shape's parameter is out of range (see [`crate::mesh::primitives`]).
    InvalidShape {
        /// The parameter's name, as in the generator's signature.
        parameter: &'static str,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A water surface (see [`waves`](crate::water)) that is not physical or cannot be
    /// evaluated: a negative amplitude, a grid of the wrong size, a non-finite elevation or time.
    InvalidSurface {
        /// The parameter at fault, as named in the surface's constructor or query: e.g.
        /// `amplitude`, `significant_height`, `heights`, `time`.
        parameter: &'static str,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A query the water cannot answer as asked ([`Mesh::buoyancy`](crate::Mesh::buoyancy)): a
    /// method that assumes a flat surface asked for under waves, the hierarchy traversal under
    /// the Froude–Krylov pressure, that pressure under a surface that is not Airy waves.
    Unsupported {
        /// The argument at fault: `method`, `traversal` or `pressure`.
        parameter: &'static str,
        /// Why, and what to ask for instead.
        reason: &'static str,
    },
    /// A transform given to [`Mesh::transformed`](crate::Mesh::transformed) or
    /// [`Mesh::scaled`](crate::Mesh::scaled) is not a finite, invertible affine map.
    InvalidTransform {
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A linear or angular velocity has a NaN or infinite component.
    InvalidVelocity,
    /// The result overflowed: the pose or the water parameters are too large for the scalar type.
    NonFiniteResult,
    /// A method name that is not one of [`Method::name`](crate::Method::name).
    UnknownMethod {
        /// The name given.
        name: String,
    },
    /// A traversal name that is not one of [`Traversal::name`](crate::Traversal::name).
    UnknownTraversal {
        /// The name given.
        name: String,
    },
    /// A mesh file could not be read (feature `std`).
    #[cfg(feature = "std")]
    Io {
        /// The file's path.
        path: String,
        /// What the operating system reported, e.g. [`NotFound`](std::io::ErrorKind::NotFound).
        kind: std::io::ErrorKind,
        /// The operating system's message.
        message: String,
    },
    /// A mesh file whose extension names no format [`io::load`](crate::io::load) reads.
    UnknownFormat {
        /// The file's path.
        path: String,
    },
    /// A mesh file could not be parsed.
    Parse {
        /// One-based line number (0 when the problem is not tied to a line).
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// A draft given to [`Mesh::hydrostatic_table`](crate::Mesh::hydrostatic_table) is NaN,
    /// infinite, negative or above the body's height.
    InvalidDraft {
        /// Its zero-based position in the list of drafts.
        index: usize,
        /// The draft given, m.
        draft: f64,
        /// The body's height along the up normal at the table's orientation (highest vertex
        /// minus lowest), m: the largest draft accepted.
        height: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// An option of a hydrostatic table is out of range
    /// ([`TableOptions`](crate::hydrostatics::TableOptions)).
    InvalidTableOption {
        /// The option's name: `rotation`, `longitudinal_axis`, `center_of_gravity` or `length`.
        parameter: &'static str,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// An opening of a hull given to [`Mesh::close_openings`](crate::Mesh::close_openings) (a
    /// loop of open edges) is not planar within the tolerance, so no flat lid closes it.
    NonPlanarOpening {
        /// The opening's number (see [`Opening`](crate::mesh::Opening)).
        opening: usize,
        /// The vertex of its rim farthest from the rim's mean plane (zero-based input index).
        vertex: u32,
        /// That vertex's distance from the plane, m.
        deviation: f64,
        /// The largest distance accepted: the relative tolerance times the rim's radius, m.
        tolerance: f64,
    },
    /// An opening of a hull given to [`Mesh::close_openings`](crate::Mesh::close_openings)
    /// cannot be closed by a lid: its rim encloses no area, or two rims meet at a vertex.
    InvalidOpening {
        /// The opening's number (see [`Opening`](crate::mesh::Opening)).
        opening: usize,
        /// A vertex of its rim (zero-based input index): the one where rims meet, if they do.
        vertex: u32,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// Water reaches an opening of the hull, closed by a lid when the mesh was built
    /// ([`Mesh::close_openings`](crate::Mesh::close_openings)), at the pose queried: the
    /// results would count the lid as hull while the water flows in.
    OpeningSubmerged {
        /// The opening's number (see [`Opening`](crate::mesh::Opening)).
        opening: usize,
        /// The lowest vertex of its rim (zero-based input index).
        vertex: u32,
        /// That vertex's height above the surface, m (zero or negative).
        height: f64,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::EmptyMesh => write!(f, "the mesh has no triangles"),
            Error::EmptyBody => write!(f, "a floating body needs at least one mesh"),
            Error::InvalidLoading { parameter, reason } => {
                write!(f, "invalid loading condition {parameter}: {reason}")
            }
            Error::InvalidMass { reason } => write!(f, "invalid mass: {reason}"),
            Error::TooHeavyToFloat { mass, capacity } => write!(
                f,
                "the body does not float: its mass, {mass:.6e} kg, is at least (or within the \
                 solver's tolerance of) the mass of water its whole volume displaces, \
                 {capacity:.6e} kg; lighten it, or check the mesh's units and the water's \
                 density"
            ),
            Error::NoConvergence {
                iterations,
                residual,
                tolerance,
            } => write!(
                f,
                "the equilibrium solver did not converge: after {iterations} iterations the \
                 relative residual is {residual:.3e}, above the tolerance {tolerance:.3e}; \
                 raise max_iterations or the tolerance, or give a start pose nearer the \
                 equilibrium"
            ),
            Error::InvalidSolverOption { parameter, reason } => {
                write!(f, "invalid solver option {parameter}: {reason}")
            }
            Error::OutOfMemory { parameter, bytes } => write!(
                f,
                "{parameter} asks for {} of memory, more than can be allocated: make it smaller",
                Bytes(*bytes)
            ),
            Error::TooManyVertices { count } => write!(
                f,
                "the mesh has {count} vertices; at most {} can be indexed with u32",
                u32::MAX
            ),
            Error::InvalidMesh(defects) => write!(f, "{defects}"),
            Error::ZeroVolume { volume, scale } => write_zero_volume(f, *volume, *scale),
            Error::InvalidWater { parameter, reason } => {
                write!(f, "invalid water {parameter}: {reason}")
            }
            Error::InvalidPose { reason } => write!(f, "invalid pose: {reason}"),
            Error::InvalidDamping { parameter, reason } => {
                write!(f, "invalid damping coefficient {parameter}: {reason}")
            }
            Error::InvalidShape { parameter, reason } => {
                write!(f, "invalid shape parameter {parameter}: {reason}")
            }
            Error::InvalidTransform { reason } => write!(f, "invalid transform: {reason}"),
            Error::InvalidSurface { reason, .. } => write!(f, "invalid water surface: {reason}"),
            Error::Unsupported { parameter, reason } => write!(f, "{parameter}: {reason}"),
            Error::InvalidVelocity => {
                write!(f, "invalid velocity: a NaN or infinite component")
            }
            Error::NonFiniteResult => write!(
                f,
                "the result overflowed: the pose, density or gravity is too large for this scalar type"
            ),
            Error::UnknownMethod { name } => write!(
                f,
                "unknown method {name:?}; valid methods are fast, improved, exact, fast_surface, exact_surface"
            ),
            Error::UnknownTraversal { name } => write!(
                f,
                "unknown traversal {name:?}; valid traversals are auto, scan, hierarchy"
            ),
            #[cfg(feature = "std")]
            Error::Io { path, message, .. } => write!(f, "cannot read {path}: {message}"),
            Error::UnknownFormat { path } => write!(
                f,
                "cannot read {path}: unknown format, expected a .obj, .stl or .ply file"
            ),
            Error::Parse { line, message } => {
                if *line == 0 {
                    write!(f, "cannot parse the mesh: {message}")
                } else {
                    write!(f, "cannot parse the mesh, line {line}: {message}")
                }
            }
            Error::InvalidDraft {
                index,
                draft,
                height,
                reason,
            } => write!(
                f,
                "invalid draft {index} ({draft} m): {reason} (drafts run from 0 to the body's \
                 height, {height} m)"
            ),
            Error::InvalidTableOption { parameter, reason } => {
                write!(f, "invalid hydrostatic table option {parameter}: {reason}")
            }
            Error::NonPlanarOpening {
                opening,
                vertex,
                deviation,
                tolerance,
            } => write!(
                f,
                "opening {opening} of the hull is not planar: vertex {vertex} of its rim lies \
                 {deviation:.3e} m from the rim's mean plane, more than {tolerance:.3e} m; only a \
                 planar opening is closed by a flat lid (close this one in the mesh)"
            ),
            Error::InvalidOpening {
                opening,
                vertex,
                reason,
            } => write!(
                f,
                "opening {opening} of the hull (at vertex {vertex}) cannot be closed by a lid: \
                 {reason}"
            ),
            Error::OpeningSubmerged {
                opening,
                vertex,
                height,
            } => write!(
                f,
                "water reaches opening {opening} of the hull at this pose: vertex {vertex} of its \
                 rim is {:.3e} m below the surface; the lid closing it is not hull, the water \
                 would flow in",
                -height
            ),
        }
    }
}

impl core::error::Error for Error {}

/// A byte count as a person reads it: `48 GB`, `1.5 TB`, `512 bytes` (decimal units).
struct Bytes(usize);

impl fmt::Display for Bytes {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let bytes = self.0 as f64;
        match ["kB", "MB", "GB", "TB", "PB", "EB"]
            .iter()
            .zip(1..7)
            .rev()
            .find(|&(_, k)| bytes >= libm::pow(1e3, k as f64))
        {
            Some((unit, k)) => write!(f, "{:.3} {unit}", bytes / libm::pow(1e3, k as f64)),
            None => write!(f, "{} bytes", self.0),
        }
    }
}

/// A vector with room for `count` items, or [`Error::OutOfMemory`] naming `parameter` when
/// the memory cannot be had (a `count` whose bytes overflow `usize` included), instead of the
/// allocator's abort.
pub(crate) fn vec_with_capacity<T>(count: usize, parameter: &'static str) -> Result<Vec<T>, Error> {
    let mut vec = Vec::new();
    vec.try_reserve_exact(count)
        .map_err(|_| Error::OutOfMemory {
            parameter,
            bytes: count.saturating_mul(core::mem::size_of::<T>()),
        })?;
    Ok(vec)
}

/// Checks that `count` items of `bytes_each` bytes can be allocated, by asking for them once
/// (and giving them back): for work whose memory is spread over many vectors, such as preparing
/// a mesh. The operating system may promise memory it does not have; this catches what it
/// refuses outright.
pub(crate) fn check_memory(
    count: usize,
    bytes_each: usize,
    parameter: &'static str,
) -> Result<(), Error> {
    let bytes = count.saturating_mul(bytes_each);
    vec_with_capacity::<u8>(bytes, parameter)
        .map(drop)
        .map_err(|_| Error::OutOfMemory { parameter, bytes })
}

/// The message of [`Error::ZeroVolume`]: what the numbers say about the mesh, and what to check.
fn write_zero_volume(f: &mut fmt::Formatter<'_>, volume: f64, scale: f64) -> fmt::Result {
    if !volume.is_finite() || !scale.is_finite() {
        f.write_str(
            "the mesh's volume overflowed: its coordinates are too large for the computation; \
             express them in larger units or move the mesh nearer the origin",
        )
    } else if scale == 0.0 {
        f.write_str(
            "the mesh encloses no volume: it is flat (its triangles span no volume); check \
             that no coordinate was dropped or scaled to zero",
        )
    } else {
        f.write_str("the mesh encloses no volume: its signed volume is ")?;
        if volume == 0.0 {
            f.write_str("0")?;
        } else {
            write!(f, "{volume:.3e}")?;
        }
        write!(
            f,
            " m³ where the tetrahedra of its triangles add up to {scale:.3e} m³ in absolute \
             value: it is flat, or parts of it wound inward cancel parts wound outward; check \
             that no coordinate was dropped or scaled to zero, and that every part is wound the \
             same way (counter-clockwise seen from outside)"
        )
    }
}
