use alloc::string::String;
use core::fmt;

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
    /// More vertices than a `u32` index can address.
    TooManyVertices {
        /// Number of vertices given.
        count: usize,
    },
    /// A vertex coordinate is NaN or infinite.
    NonFiniteVertex {
        /// Index of the vertex.
        vertex: usize,
    },
    /// A triangle refers to a vertex that does not exist.
    IndexOutOfRange {
        /// Index of the triangle.
        triangle: usize,
        /// The offending vertex index.
        index: u32,
        /// Number of vertices in the mesh.
        vertex_count: usize,
    },
    /// A triangle uses the same vertex twice, e.g. `[4, 4, 9]`.
    RepeatedIndex {
        /// Index of the triangle.
        triangle: usize,
        /// Its three vertex indices.
        indices: [u32; 3],
    },
    /// An edge belongs to one triangle only: the mesh has a hole and encloses no volume.
    OpenEdge {
        /// The edge's two vertex indices, smaller first.
        edge: [u32; 2],
        /// The only triangle that has it.
        triangle: usize,
    },
    /// An edge is shared by more than two triangles.
    NonManifoldEdge {
        /// The edge's two vertex indices, smaller first.
        edge: [u32; 2],
        /// How many triangles share it.
        triangle_count: usize,
        /// Two of those triangles.
        triangles: [usize; 2],
    },
    /// Two neighbouring triangles traverse their shared edge in the same direction, so one of
    /// them faces the other way.
    InconsistentOrientation {
        /// The shared edge's two vertex indices, in the direction both triangles use.
        edge: [u32; 2],
        /// The two triangles.
        triangles: [usize; 2],
    },
    /// The mesh is closed but encloses no volume (it is flat, or its parts cancel out).
    ZeroVolume {
        /// The signed volume found.
        volume: f64,
        /// The volume scale of the mesh (sum of the absolute tetrahedron volumes), for comparison.
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
    /// A procedural shape's parameter is out of range (see [`crate::shape`]).
    InvalidShape {
        /// The parameter's name, as in the generator's signature.
        parameter: &'static str,
        /// What is wrong with it.
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
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::EmptyMesh => write!(f, "the mesh has no triangles"),
            Error::TooManyVertices { count } => write!(
                f,
                "the mesh has {count} vertices; at most {} can be indexed with u32",
                u32::MAX
            ),
            Error::NonFiniteVertex { vertex } => {
                write!(f, "vertex {vertex} has a NaN or infinite coordinate")
            }
            Error::IndexOutOfRange {
                triangle,
                index,
                vertex_count,
            } => write!(
                f,
                "triangle {triangle} refers to vertex {index}, but the mesh has only {vertex_count} vertices"
            ),
            Error::RepeatedIndex { triangle, indices } => {
                write!(f, "triangle {triangle} uses a vertex twice: {indices:?}")
            }
            Error::OpenEdge { edge, triangle } => write!(
                f,
                "the mesh is not closed: edge ({}, {}) of triangle {triangle} has no neighbour",
                edge[0], edge[1]
            ),
            Error::NonManifoldEdge {
                edge,
                triangle_count,
                triangles,
            } => write!(
                f,
                "the mesh is not a manifold: edge ({}, {}) is shared by {triangle_count} triangles (e.g. {} and {})",
                edge[0], edge[1], triangles[0], triangles[1]
            ),
            Error::InconsistentOrientation { edge, triangles } => write!(
                f,
                "triangles {} and {} are oriented inconsistently: both traverse edge {} -> {}; flip one of them",
                triangles[0], triangles[1], edge[0], edge[1]
            ),
            Error::ZeroVolume { volume, scale } => write!(
                f,
                "the mesh encloses no volume (signed volume {volume:e} against a scale of {scale:e})"
            ),
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
                "cannot read {path}: unknown format, expected a .obj or .stl file"
            ),
            Error::Parse { line, message } => {
                if *line == 0 {
                    write!(f, "cannot parse the mesh: {message}")
                } else {
                    write!(f, "cannot parse the mesh, line {line}: {message}")
                }
            }
        }
    }
}

impl core::error::Error for Error {}
