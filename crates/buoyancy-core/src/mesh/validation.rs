//! The checks a mesh passes before anything is computed from it, and the report of what fails
//! them: finite vertices, indices in range, triangles of three distinct vertices, and a closed,
//! consistently oriented 2-manifold.
//!
//! Every check runs over the whole mesh: a broken mesh is reported with the number of problems
//! of each kind, the first few culprits of each, and what usually fixes them ([`MeshDefects`]).
//! Indices are zero-based throughout: vertex 0 is the first vertex given to
//! [`Mesh::new`](crate::Mesh::new), triangle 0 the first index triple.

use alloc::vec::Vec;
use core::fmt;

use nalgebra::Point3;

use crate::{Error, Real};

/// A kind of problem that keeps a mesh from being a closed, consistently oriented 2-manifold
/// with finite vertices, in the order [`Mesh::new`](crate::Mesh::new) reports them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum DefectKind {
    /// A vertex with a NaN or infinite coordinate. Counted per vertex.
    NonFiniteVertex,
    /// A triangle with a vertex index not below the vertex count. Counted per triangle.
    IndexOutOfRange,
    /// A triangle that uses one vertex twice, e.g. `[4, 4, 9]`. Counted per triangle.
    RepeatedIndex,
    /// An edge of one triangle only: the surface has a hole there. Counted per edge.
    OpenEdge,
    /// An edge shared by more than two triangles. Counted per edge.
    NonManifoldEdge,
    /// An edge whose two triangles traverse it in the same direction, so that one of them faces
    /// the other way. Counted per edge.
    InconsistentOrientation,
}

impl DefectKind {
    /// Every kind, in the order of reporting.
    pub const ALL: [DefectKind; 6] = [
        DefectKind::NonFiniteVertex,
        DefectKind::IndexOutOfRange,
        DefectKind::RepeatedIndex,
        DefectKind::OpenEdge,
        DefectKind::NonManifoldEdge,
        DefectKind::InconsistentOrientation,
    ];

    /// The kind's name in snake case, e.g. `"open_edge"`.
    pub fn name(self) -> &'static str {
        match self {
            DefectKind::NonFiniteVertex => "non_finite_vertex",
            DefectKind::IndexOutOfRange => "index_out_of_range",
            DefectKind::RepeatedIndex => "repeated_index",
            DefectKind::OpenEdge => "open_edge",
            DefectKind::NonManifoldEdge => "non_manifold_edge",
            DefectKind::InconsistentOrientation => "inconsistent_orientation",
        }
    }

    /// What usually fixes this kind of problem. The message of a [`MeshDefects`] gives a more
    /// specific remedy where the mesh shows the cause (a triangle soup, vertices at the same
    /// position, one-based indices).
    pub fn remedy(self) -> &'static str {
        match self {
            DefectKind::NonFiniteVertex => {
                "fix or remove these vertices (a NaN usually comes from a number that was not \
                 parsed or from a division by zero where the mesh was made)"
            }
            DefectKind::IndexOutOfRange => {
                "check that the vertex array is complete and belongs to these triangles, and that \
                 the indices are 0-based"
            }
            DefectKind::RepeatedIndex => {
                "remove these degenerate triangles: a triangle with a repeated vertex has no area, \
                 and removing it leaves its neighbours joined"
            }
            DefectKind::OpenEdge => {
                "weld duplicate vertices (vertices at the same position with different indices), \
                 then fill the holes that remain"
            }
            DefectKind::NonManifoldEdge => {
                "remove duplicate triangles and internal faces; bodies that touch along an edge \
                 must be separate meshes"
            }
            DefectKind::InconsistentOrientation => {
                "flip the wrongly wound triangles so that every triangle is counter-clockwise seen \
                 from outside, like its neighbours (a mesh wound clockwise throughout is flipped \
                 automatically)"
            }
        }
    }
}

impl fmt::Display for DefectKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One offending vertex, triangle or edge. Indices are zero-based.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Culprit {
    /// A vertex ([`DefectKind::NonFiniteVertex`]).
    Vertex {
        /// Index of the vertex.
        vertex: usize,
    },
    /// A triangle's index that is out of range ([`DefectKind::IndexOutOfRange`]).
    Index {
        /// Index of the triangle.
        triangle: usize,
        /// Its first vertex index that is out of range.
        index: u32,
    },
    /// A triangle ([`DefectKind::RepeatedIndex`]).
    Triangle {
        /// Index of the triangle.
        triangle: usize,
        /// Its three vertex indices.
        indices: [u32; 3],
    },
    /// An edge ([`DefectKind::OpenEdge`], [`DefectKind::NonManifoldEdge`],
    /// [`DefectKind::InconsistentOrientation`]).
    Edge {
        /// The edge's two vertex indices: for an inconsistently oriented edge in the direction
        /// both triangles traverse it, otherwise the smaller first.
        edge: [u32; 2],
        /// Every triangle that has the edge, in increasing order.
        triangles: Vec<usize>,
    },
}

impl fmt::Display for Culprit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Culprit::Vertex { vertex } => write!(f, "vertex {vertex}"),
            Culprit::Index { triangle, index } => {
                write!(f, "triangle {triangle} refers to vertex {index}")
            }
            Culprit::Triangle { triangle, indices } => write!(
                f,
                "triangle {triangle} [{}, {}, {}]",
                indices[0], indices[1], indices[2]
            ),
            Culprit::Edge { edge, triangles } => match triangles.as_slice() {
                [only] => write!(f, "edge ({}, {}) of triangle {only}", edge[0], edge[1]),
                [first, second] => write!(
                    f,
                    "triangles {first} and {second} both traverse edge {} -> {}",
                    edge[0], edge[1]
                ),
                _ => {
                    write!(f, "edge ({}, {}) shared by triangles ", edge[0], edge[1])?;
                    write_list(f, triangles, triangles.len())
                }
            },
        }
    }
}

/// Every problem of one kind found in a mesh.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Defect {
    /// What is wrong.
    pub kind: DefectKind,
    /// How many vertices, triangles or edges have the problem (see [`DefectKind`] for which).
    pub count: usize,
    /// The first [`Defect::MAX_EXAMPLES`] of them: vertices and triangles in increasing order,
    /// edges in the order of their vertex indices.
    pub examples: Vec<Culprit>,
}

impl Defect {
    /// How many culprits a defect lists at most.
    pub const MAX_EXAMPLES: usize = 5;
}

/// What [`Mesh::new`](crate::Mesh::new) found wrong with a mesh: every kind of problem, with
/// its count and first culprits, and what the mesh shows of the cause.
///
/// Edges are checked on the triangles whose indices are valid (in range, three distinct), so
/// the edge counts describe the mesh without the triangles reported for their indices.
///
/// ```
/// use buoyancy_core::{DefectKind, Error, Mesh, mesh::primitives};
///
/// // A cube whose triangles each have their own three vertices, as STL files store them.
/// let (v, t) = primitives::cube::<f64>(1)?;
/// let soup_vertices = t.iter().flat_map(|t| t.map(|i| v[i as usize])).collect();
/// let soup_triangles = (0..t.len() as u32).map(|k| [3 * k, 3 * k + 1, 3 * k + 2]).collect();
/// let Err(Error::InvalidMesh(defects)) = Mesh::new(soup_vertices, soup_triangles) else {
///     panic!("a triangle soup is not a closed mesh");
/// };
/// assert_eq!(defects.count(DefectKind::OpenEdge), 3 * t.len());
/// assert!(defects.triangle_soup);
/// assert!(defects.to_string().contains("weld"));
/// # Ok::<(), Error>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct MeshDefects {
    /// Number of vertices given.
    pub vertex_count: usize,
    /// Number of triangles given.
    pub triangle_count: usize,
    /// One entry per kind of problem found (at least one), in the order of
    /// [`DefectKind::ALL`].
    pub defects: Vec<Defect>,
    /// Whether no two triangles share a vertex (a *triangle soup*, as STL files store a mesh):
    /// every edge is open until the vertices at the same position are welded.
    pub triangle_soup: bool,
    /// How many vertices used by the triangles sit exactly where a vertex of lower index does
    /// (coordinates equal, `-0` equal to `0`): welding them closes the edges they split.
    /// Counted when the mesh has open edges, 0 otherwise.
    pub coincident_vertices: usize,
    /// Whether the indices look one-based: some are out of range, none is 0 and the largest
    /// equals the vertex count. Subtracting 1 from every index fixes that.
    pub one_based_indices: bool,
}

impl MeshDefects {
    /// The problems of `kind`, if any.
    pub fn get(&self, kind: DefectKind) -> Option<&Defect> {
        self.defects.iter().find(|d| d.kind == kind)
    }

    /// How many vertices, triangles or edges have problems of `kind` (0 if none).
    pub fn count(&self, kind: DefectKind) -> usize {
        self.get(kind).map_or(0, |d| d.count)
    }

    /// The remedy for one kind, specific to this mesh where it shows the cause.
    fn remedy(&self, kind: DefectKind) -> Remedy {
        match kind {
            DefectKind::IndexOutOfRange if self.one_based_indices => Remedy::OneBased,
            DefectKind::OpenEdge if self.triangle_soup && self.coincident_vertices > 0 => {
                Remedy::WeldSoup(self.coincident_vertices)
            }
            DefectKind::OpenEdge if self.triangle_soup => Remedy::Scattered,
            DefectKind::OpenEdge if self.coincident_vertices > 0 => {
                Remedy::Weld(self.coincident_vertices)
            }
            DefectKind::OpenEdge => Remedy::FillHoles,
            kind => Remedy::Usual(kind),
        }
    }
}

/// A remedy for one kind of defect, as the message states it.
enum Remedy {
    Usual(DefectKind),
    OneBased,
    WeldSoup(usize),
    Scattered,
    Weld(usize),
    FillHoles,
}

impl fmt::Display for Remedy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Remedy::Usual(kind) => f.write_str(kind.remedy()),
            Remedy::OneBased => f.write_str(
                "no index is 0 and the largest equals the vertex count: the indices look 1-based \
                 (as in OBJ files); subtract 1 from every index",
            ),
            Remedy::WeldSoup(coincident) => write!(
                f,
                "no two triangles share a vertex: this is a triangle soup (as STL files store \
                 meshes), and {coincident} of its vertices sit exactly where another one is; weld \
                 the vertices at the same position (merge them into one index, e.g. trimesh's \
                 `merge_vertices()`), then build the mesh from the welded indices"
            ),
            Remedy::Scattered => f.write_str(
                "no two triangles share a vertex, and no two vertices share a position: these \
                 triangles do not form a surface",
            ),
            Remedy::Weld(coincident) => write!(
                f,
                "{coincident} {} exactly where another vertex is: weld them (merge vertices at \
                 the same position into one index), then fill the holes that remain",
                plural(*coincident, "vertex sits", "vertices sit")
            ),
            Remedy::FillHoles => f.write_str(
                "fill the holes (close each loop of open edges with triangles), or look for \
                 triangles lost where the mesh was made",
            ),
        }
    }
}

impl fmt::Display for MeshDefects {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "the mesh ({} {}, {} {}) is not a closed, consistently oriented 2-manifold with \
             finite vertices; indices are 0-based (vertex 0 is the first vertex, triangle 0 the \
             first triangle; a vertex numbered n in an OBJ file is vertex n - 1 here):",
            self.vertex_count,
            plural(self.vertex_count, "vertex", "vertices"),
            self.triangle_count,
            plural(self.triangle_count, "triangle", "triangles"),
        )?;
        let bad_indices =
            self.count(DefectKind::IndexOutOfRange) + self.count(DefectKind::RepeatedIndex);
        let mut edges_noted = false;
        for defect in &self.defects {
            let n = defect.count;
            f.write_str("\n- ")?;
            match defect.kind {
                DefectKind::NonFiniteVertex => write!(
                    f,
                    "{n} {} with a NaN or infinite coordinate",
                    plural(n, "vertex", "vertices")
                )?,
                DefectKind::IndexOutOfRange => {
                    write!(
                        f,
                        "{n} {} to a vertex that does not exist ",
                        plural(n, "triangle refers", "triangles refer")
                    )?;
                    match self.vertex_count {
                        0 => f.write_str("(there are no vertices)")?,
                        count => write!(f, "(valid indices are 0 to {})", count - 1)?,
                    }
                }
                DefectKind::RepeatedIndex => write!(
                    f,
                    "{n} {} a vertex twice",
                    plural(n, "triangle uses", "triangles use")
                )?,
                DefectKind::OpenEdge => write!(
                    f,
                    "{n} open {} (of one triangle only: the mesh is not closed)",
                    plural(n, "edge", "edges")
                )?,
                DefectKind::NonManifoldEdge => write!(
                    f,
                    "{n} non-manifold {} (shared by more than two triangles)",
                    plural(n, "edge", "edges")
                )?,
                DefectKind::InconsistentOrientation => write!(
                    f,
                    "{n} inconsistently oriented {} (its two triangles traverse it in the same \
                     direction, so one of them faces the wrong way)",
                    plural(n, "edge", "edges")
                )?,
            }
            f.write_str(": ")?;
            write_list(f, &defect.examples, n)?;
            write!(f, ". Remedy: {}.", self.remedy(defect.kind))?;
            if defect.kind >= DefectKind::OpenEdge && !edges_noted && bad_indices > 0 {
                f.write_str(
                    " Edges are checked without the triangles whose indices are reported above: \
                     fixing those may close edges reported here.",
                )?;
                edges_noted = true;
            }
        }
        Ok(())
    }
}

/// `one` or `many`, as `n` asks.
fn plural(n: usize, one: &'static str, many: &'static str) -> &'static str {
    if n == 1 { one } else { many }
}

/// `a, b, c` and, when `items` holds fewer than `total`, `and N more`.
fn write_list<D: fmt::Display>(
    f: &mut fmt::Formatter<'_>,
    items: &[D],
    total: usize,
) -> fmt::Result {
    for (k, item) in items.iter().enumerate() {
        if k > 0 {
            f.write_str(", ")?;
        }
        write!(f, "{item}")?;
    }
    if total > items.len() {
        write!(f, " and {} more", total - items.len())?;
    }
    Ok(())
}

/// Collects the culprits of each kind while the checks run.
struct Findings {
    /// Per kind, in the order of [`DefectKind::ALL`]: the count and the first culprits.
    by_kind: [(usize, Vec<Culprit>); 6],
}

impl Findings {
    fn new() -> Self {
        Findings {
            by_kind: Default::default(),
        }
    }

    fn add(&mut self, kind: DefectKind, culprit: impl FnOnce() -> Culprit) {
        let (count, examples) = &mut self.by_kind[kind as usize];
        *count += 1;
        if examples.len() < Defect::MAX_EXAMPLES {
            examples.push(culprit());
        }
    }

    fn is_empty(&self) -> bool {
        self.by_kind.iter().all(|(count, _)| *count == 0)
    }

    fn count(&self, kind: DefectKind) -> usize {
        self.by_kind[kind as usize].0
    }

    fn into_defects(self) -> Vec<Defect> {
        DefectKind::ALL
            .into_iter()
            .zip(self.by_kind)
            .filter(|(_, (count, _))| *count > 0)
            .map(|(kind, (count, examples))| Defect {
                kind,
                count,
                examples,
            })
            .collect()
    }
}

/// Checks `vertices` and `triangles` as [`Mesh::new`](crate::Mesh::new) documents; the enclosed
/// volume is checked afterwards, by the caller.
///
/// # Errors
/// [`Error::EmptyMesh`] and [`Error::TooManyVertices`] alone; everything else together, as
/// [`Error::InvalidMesh`].
pub(crate) fn validate<T: Real>(
    vertices: &[Point3<T>],
    triangles: &[[u32; 3]],
) -> Result<(), Error> {
    if triangles.is_empty() {
        return Err(Error::EmptyMesh);
    }
    if u32::try_from(vertices.len()).is_err() {
        return Err(Error::TooManyVertices {
            count: vertices.len(),
        });
    }
    let mut findings = Findings::new();
    for (vertex, p) in vertices.iter().enumerate() {
        if !p.iter().all(|c| c.is_finite()) {
            findings.add(DefectKind::NonFiniteVertex, || Culprit::Vertex { vertex });
        }
    }
    // (smaller vertex, larger vertex, triangle, whether the triangle goes smaller -> larger)
    let mut edges: Vec<(u32, u32, u32, bool)> = Vec::with_capacity(triangles.len() * 3);
    for (triangle, t) in triangles.iter().enumerate() {
        if let Some(&index) = t.iter().find(|&&i| i as usize >= vertices.len()) {
            findings.add(DefectKind::IndexOutOfRange, || Culprit::Index {
                triangle,
                index,
            });
        } else if t[0] == t[1] || t[1] == t[2] || t[2] == t[0] {
            findings.add(DefectKind::RepeatedIndex, || Culprit::Triangle {
                triangle,
                indices: *t,
            });
        } else {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                edges.push((a.min(b), a.max(b), triangle as u32, a < b));
            }
        }
    }
    check_edges(&mut edges, &mut findings);
    if findings.is_empty() {
        return Ok(());
    }
    let valid = |t: &&[u32; 3]| {
        t.iter().all(|&i| (i as usize) < vertices.len())
            && t[0] != t[1]
            && t[1] != t[2]
            && t[2] != t[0]
    };
    let mut uses = alloc::vec![0u32; vertices.len()];
    for t in triangles.iter().filter(valid) {
        for &i in t {
            uses[i as usize] = uses[i as usize].saturating_add(1);
        }
    }
    let open = findings.count(DefectKind::OpenEdge) > 0;
    let triangle_soup = open && uses.iter().all(|&n| n <= 1);
    let coincident_vertices = if open {
        count_coincident(vertices, &uses)
    } else {
        0
    };
    let one_based_indices = findings.count(DefectKind::IndexOutOfRange) > 0 && {
        let all = triangles.iter().flatten();
        all.clone().all(|&i| i > 0) && all.max().is_some_and(|&i| i as usize == vertices.len())
    };
    Err(Error::InvalidMesh(MeshDefects {
        vertex_count: vertices.len(),
        triangle_count: triangles.len(),
        defects: findings.into_defects(),
        triangle_soup,
        coincident_vertices,
        one_based_indices,
    }))
}

/// Checks that every edge is shared by exactly two triangles traversing it in opposite
/// directions. Runs in O(n log n) with one sort, no hashing (no_std).
fn check_edges(edges: &mut [(u32, u32, u32, bool)], findings: &mut Findings) {
    edges.sort_unstable();
    let triangles_of = |run: &[(u32, u32, u32, bool)]| run.iter().map(|e| e.2 as usize).collect();
    for run in edges.chunk_by(|a, b| (a.0, a.1) == (b.0, b.1)) {
        let (lo, hi, _, forward) = run[0];
        match run.len() {
            1 => findings.add(DefectKind::OpenEdge, || Culprit::Edge {
                edge: [lo, hi],
                triangles: triangles_of(run),
            }),
            2 if forward == run[1].3 => {
                findings.add(DefectKind::InconsistentOrientation, || Culprit::Edge {
                    edge: if forward { [lo, hi] } else { [hi, lo] },
                    triangles: triangles_of(run),
                })
            }
            2 => {}
            _ => findings.add(DefectKind::NonManifoldEdge, || Culprit::Edge {
                edge: [lo, hi],
                triangles: triangles_of(run),
            }),
        }
    }
}

/// How many used, finite vertices sit exactly where a used vertex of lower index does.
/// One sort of the used vertices by their coordinates' bits: O(n log n), no hashing.
fn count_coincident<T: Real>(vertices: &[Point3<T>], uses: &[u32]) -> usize {
    let mut keys: Vec<[u64; 3]> = vertices
        .iter()
        .zip(uses)
        .filter(|(p, n)| **n > 0 && p.iter().all(|c| c.is_finite()))
        .map(|(p, _)| [p.x, p.y, p.z].map(|c| (c.to_f64() + 0.0).to_bits()))
        .collect();
    keys.sort_unstable();
    keys.chunk_by(|a, b| a == b).map(|run| run.len() - 1).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::string::ToString;
    use alloc::vec;

    fn tetrahedron() -> (Vec<Point3<f64>>, Vec<[u32; 3]>) {
        (
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(0.0, 1.0, 0.0),
                Point3::new(0.0, 0.0, 1.0),
            ],
            vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
        )
    }

    fn defects(v: &[Point3<f64>], t: &[[u32; 3]]) -> MeshDefects {
        match validate(v, t) {
            Err(Error::InvalidMesh(defects)) => defects,
            other => panic!("expected InvalidMesh, got {other:?}"),
        }
    }

    /// The mesh's only defect, of `kind`.
    fn only(defects: &MeshDefects, kind: DefectKind) -> &Defect {
        assert_eq!(defects.defects.len(), 1, "{defects}");
        let defect = &defects.defects[0];
        assert_eq!(defect.kind, kind, "{defects}");
        defect
    }

    fn edge(edge: [u32; 2], triangles: &[usize]) -> Culprit {
        Culprit::Edge {
            edge,
            triangles: triangles.to_vec(),
        }
    }

    #[test]
    fn a_valid_mesh_passes() {
        let (v, t) = tetrahedron();
        assert_eq!(validate(&v, &t), Ok(()));
    }

    #[test]
    fn an_empty_mesh_is_its_own_error() {
        let (v, _) = tetrahedron();
        assert_eq!(validate(&v, &[]), Err(Error::EmptyMesh));
    }

    #[test]
    fn each_kind_names_its_culprit() {
        let (v, t) = tetrahedron();

        let mut bad = v.clone();
        bad[2].y = f64::NAN;
        let d = defects(&bad, &t);
        let defect = only(&d, DefectKind::NonFiniteVertex);
        assert_eq!(defect.count, 1);
        assert_eq!(defect.examples, [Culprit::Vertex { vertex: 2 }]);

        // Triangles with a bad index are left out of the edge checks.
        let mut out = t.clone();
        out[3] = [1, 2, 9];
        let d = defects(&v, &out);
        let defect = &d.defects[0];
        assert_eq!(defect.kind, DefectKind::IndexOutOfRange);
        assert_eq!(
            defect.examples,
            [Culprit::Index {
                triangle: 3,
                index: 9
            }]
        );
        assert_eq!(d.count(DefectKind::OpenEdge), 3);
        assert!(!d.one_based_indices);

        let mut repeated = t.clone();
        repeated[1] = [0, 1, 1];
        let d = defects(&v, &repeated);
        assert_eq!(
            d.get(DefectKind::RepeatedIndex).unwrap().examples,
            [Culprit::Triangle {
                triangle: 1,
                indices: [0, 1, 1]
            }]
        );

        let d = defects(&v, &t[..3]);
        let defect = only(&d, DefectKind::OpenEdge);
        assert_eq!(defect.count, 3);
        assert_eq!(
            defect.examples,
            [edge([1, 2], &[0]), edge([1, 3], &[1]), edge([2, 3], &[2])]
        );
        assert!(!d.triangle_soup);
        assert_eq!(d.coincident_vertices, 0);

        let mut flipped = t.clone();
        flipped[3] = [1, 3, 2];
        let d = defects(&v, &flipped);
        let defect = only(&d, DefectKind::InconsistentOrientation);
        assert_eq!(defect.count, 3);
        assert_eq!(
            defect.examples,
            [
                edge([2, 1], &[0, 3]),
                edge([1, 3], &[1, 3]),
                edge([3, 2], &[2, 3])
            ]
        );

        // A fin: a fifth vertex and two triangles sharing edge (1, 2) with the tetrahedron.
        let mut fin_v = v.clone();
        fin_v.push(Point3::new(1.0, 1.0, -1.0));
        let mut fin_t = t.clone();
        fin_t.extend([[1, 2, 4], [2, 1, 4]]);
        let d = defects(&fin_v, &fin_t);
        let defect = only(&d, DefectKind::NonManifoldEdge);
        assert_eq!(defect.count, 1);
        assert_eq!(defect.examples, [edge([1, 2], &[0, 3, 4, 5])]);
    }

    #[test]
    fn every_defect_is_counted_and_the_first_five_named() {
        // Ten separate tetrahedra, each with its last face missing: 30 open edges.
        let (v, t) = tetrahedron();
        let mut vertices = Vec::new();
        let mut triangles = Vec::new();
        for k in 0..10u32 {
            let offset = nalgebra::Vector3::new(3.0 * k as f64, 0.0, 0.0);
            vertices.extend(v.iter().map(|p| p + offset));
            triangles.extend(t[..3].iter().map(|t| t.map(|i| i + 4 * k)));
        }
        vertices[7].x = f64::INFINITY;
        vertices[9].z = f64::NAN;
        let d = defects(&vertices, &triangles);
        assert_eq!(d.count(DefectKind::OpenEdge), 30);
        assert_eq!(d.count(DefectKind::NonFiniteVertex), 2);
        let open = d.get(DefectKind::OpenEdge).unwrap();
        assert_eq!(open.examples.len(), Defect::MAX_EXAMPLES);
        assert_eq!(open.examples[0], edge([1, 2], &[0]));
        // Reported in the order of DefectKind::ALL.
        let kinds: Vec<_> = d.defects.iter().map(|d| d.kind).collect();
        assert_eq!(kinds, [DefectKind::NonFiniteVertex, DefectKind::OpenEdge]);
        let message = d.to_string();
        assert!(message.contains("30 open edges"), "{message}");
        assert!(message.contains("and 25 more"), "{message}");
        assert!(message.contains("2 vertices with a NaN"), "{message}");
        assert!(message.contains("vertex 7, vertex 9."), "{message}");
        assert!(message.contains("0-based"), "{message}");
        assert!(message.contains("fill the holes"), "{message}");
    }

    #[test]
    fn a_triangle_soup_gets_the_weld_hint() {
        let (v, t) = tetrahedron();
        let soup_v: Vec<_> = t.iter().flat_map(|t| t.map(|i| v[i as usize])).collect();
        let soup_t: Vec<_> = (0..4u32).map(|k| [3 * k, 3 * k + 1, 3 * k + 2]).collect();
        let d = defects(&soup_v, &soup_t);
        assert_eq!(only(&d, DefectKind::OpenEdge).count, 12);
        assert!(d.triangle_soup);
        // 12 corners at 4 positions.
        assert_eq!(d.coincident_vertices, 8);
        let message = d.to_string();
        assert!(
            message.contains("triangle soup") && message.contains("weld"),
            "{message}"
        );
    }

    #[test]
    fn split_vertices_get_the_weld_hint() {
        // Vertex 4 is a copy of vertex 3 used by one face: four open edges around the split.
        let (mut v, mut t) = tetrahedron();
        v.push(v[3]);
        t[3] = [1, 2, 4];
        let d = defects(&v, &t);
        assert_eq!(only(&d, DefectKind::OpenEdge).count, 4);
        assert!(!d.triangle_soup);
        assert_eq!(d.coincident_vertices, 1);
        let message = d.to_string();
        assert!(
            message.contains("1 vertex sits exactly where another vertex is: weld them"),
            "{message}"
        );
    }

    #[test]
    fn one_based_indices_are_recognised() {
        let (v, t) = tetrahedron();
        let one_based: Vec<_> = t.iter().map(|t| t.map(|i| i + 1)).collect();
        let d = defects(&v, &one_based);
        assert!(d.one_based_indices);
        assert_eq!(d.count(DefectKind::IndexOutOfRange), 3);
        let message = d.to_string();
        assert!(message.contains("subtract 1 from every index"), "{message}");
        assert!(message.contains("valid indices are 0 to 3"), "{message}");
    }

    #[test]
    fn messages_are_actionable() {
        let (v, mut t) = tetrahedron();
        t[3] = [1, 3, 2];
        let message = defects(&v, &t).to_string();
        assert!(
            message.contains("3 inconsistently oriented edges")
                && message.contains("triangles 0 and 3 both traverse edge 2 -> 1")
                && message.contains("flip the wrongly wound triangles"),
            "{message}"
        );
        let (mut v, mut t) = tetrahedron();
        v.push(Point3::new(1.0, 1.0, -1.0));
        t.extend([[1, 2, 4], [2, 1, 4]]);
        let message = defects(&v, &t).to_string();
        assert!(
            message.contains("1 non-manifold edge (")
                && message.contains("edge (1, 2) shared by triangles 0, 3, 4, 5")
                && message.contains("remove duplicate triangles"),
            "{message}"
        );
        for kind in DefectKind::ALL {
            assert!(!kind.remedy().is_empty() && !kind.name().is_empty());
        }
    }
}
