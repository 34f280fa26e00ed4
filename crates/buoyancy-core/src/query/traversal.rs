//! How an evaluation visits the triangles.

use crate::Error;

/// How an evaluation visits the triangles. Every traversal gives the same result up to the
/// order of summation.
///
/// * `Scan` examines every triangle once: cost proportional to the mesh.
/// * `Hierarchy` walks the mesh's bounding-volume hierarchy and opens only the nodes the water
///   surface crosses, adding the precomputed sums of the nodes entirely under water: cost
///   proportional to the waterline (the triangles the surface cuts) times the depth of the
///   hierarchy, independent of the mesh size when the waterline is not. The volume methods
///   store six-fold volumes, moments and area vectors per node, the surface methods the coefficients of
///   their pressure integrals as polynomials in the water plane (see `surface_moments`).
/// * `Auto` (the default) takes the hierarchy on meshes of at least [`Traversal::CROSSOVER`]
///   triangles, and the scan otherwise.
///
/// A parallel query ([`Query::in_parallel`](crate::query::Query), feature `rayon`) follows the same traversal,
/// split across threads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Traversal {
    /// The hierarchy where it is faster, the scan elsewhere.
    #[default]
    Auto,
    /// Every triangle, once.
    Scan,
    /// Only the nodes of the hierarchy the surface crosses.
    Hierarchy,
}

impl Traversal {
    /// The mesh size, in triangles, from which `Auto` walks the hierarchy (measured: see
    /// `benches/RESULTS.md`).
    pub const CROSSOVER: usize = 128;

    /// All three traversals.
    pub const ALL: [Traversal; 3] = [Traversal::Auto, Traversal::Scan, Traversal::Hierarchy];

    /// The traversal's name: `auto`, `scan` or `hierarchy`.
    pub const fn name(self) -> &'static str {
        match self {
            Traversal::Auto => "auto",
            Traversal::Scan => "scan",
            Traversal::Hierarchy => "hierarchy",
        }
    }
}

impl core::str::FromStr for Traversal {
    type Err = Error;

    /// Parses a name of [`Traversal::name`] (case-insensitive).
    fn from_str(s: &str) -> Result<Self, Error> {
        Traversal::ALL
            .into_iter()
            .find(|t| crate::query::method::names_match(t.name(), s))
            .ok_or_else(|| Error::UnknownTraversal { name: s.into() })
    }
}
