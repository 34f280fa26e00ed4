//! Open hulls: planar openings closed by flat lids when the mesh is built, and the check that
//! the water stays below them.

use alloc::vec::Vec;
use core::ops::Range;

use nalgebra::{Point3, Vector3};

use crate::mesh::validation::{self, DefectKind};
use crate::query::frame::Frame;
use crate::{Error, Mesh, Pose, Real, Water};

/// An opening of a hull, closed by a flat lid when the mesh was built
/// ([`Mesh::close_openings`]): a loop of open edges (its *rim*) and the fan of triangles that
/// closes it.
///
/// Openings are numbered in the order of their smallest rim vertex index: opening 0 holds the
/// smallest vertex index of any rim. Indices are zero-based, into the vertices and triangles of
/// the [`Mesh`] (`Mesh::vertex`, `Mesh::triangles`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Opening {
    rim: Vec<u32>,
    center: u32,
    triangles: Range<usize>,
}

impl Opening {
    /// The rim's vertices (input indices), in the order the hull's triangles run along its
    /// open edges, starting from the smallest index.
    pub fn rim(&self) -> &[u32] {
        &self.rim
    }

    /// The vertex added at the lid's center, the mean of the rim's vertices: its index in the
    /// mesh (after the input vertices).
    pub fn center(&self) -> u32 {
        self.center
    }

    /// The lid's triangles, a range of [`Mesh::triangles`] (after the input triangles): one per
    /// rim edge, `[center, b, a]` for the rim edge `a → b`, so that the lid runs along each
    /// edge against the hull's triangle.
    pub fn triangles(&self) -> Range<usize> {
        self.triangles.clone()
    }
}

/// The relative planarity tolerance of a rim: its vertices may lie `PLANARITY · radius` from
/// its mean plane (`radius` the largest distance of a rim vertex from the rim's mean), plus the
/// round-off of the scalar type on the coordinates.
const PLANARITY: f64 = 1e-6;

impl<T: Real> Mesh<T> {
    /// Validates and prepares a hull whose surface may be open, as [`Mesh::new`] does, after
    /// closing each opening with a flat lid: the usual input of naval architecture, a hull
    /// surface without a deck.
    ///
    /// Each loop of open edges (the *rim* of an opening) must be planar: its vertices within
    /// `10⁻⁶·r + 16ε·|p|max` of the plane through their mean `c` normal to the rim's Newell
    /// vector `N = Σ (pᵢ − c) × (pᵢ₊₁ − c)`, where `r` is the largest distance of a rim vertex from
    /// `c`, `ε` the scalar type's epsilon and `|p|max` the largest coordinate magnitude of a rim
    /// vertex (mesh frame, m). The lid is a fan of triangles from a vertex added at `c`, one per
    /// rim edge, wound against the hull's triangles along the rim, so that the closed mesh is
    /// consistently oriented; a fan is exact for any planar rim, convex or not (its triangles
    /// add up signed). The new vertices follow the input's, the lid's triangles the input's
    /// triangles, and [`Mesh::openings`] lists them.
    ///
    /// Everything the closed mesh computes counts the lids as hull: [`Mesh::buoyancy`] and the
    /// hydrostatics are those of the closed body. That is the open hull's only while the water
    /// stays below every rim: [`Mesh::check_openings`] tells, with a typed error, and
    /// [`Mesh::hydrostatic_table`] refuses a draft that reaches a rim. A mesh without opening
    /// is built exactly as [`Mesh::new`] builds it, no lid and no cost.
    ///
    /// ```
    /// use buoyancy_core::{Error, Mesh, Method, Pose, Water, mesh::primitives};
    /// use nalgebra::{Translation3, UnitQuaternion};
    ///
    /// // A unit cube without its top face (y = 1/2): an open box.
    /// let (v, t) = primitives::cube::<f64>(2)?;
    /// let hull: Vec<[u32; 3]> =
    ///     t.into_iter().filter(|t| !t.iter().all(|&i| v[i as usize].y == 0.5)).collect();
    /// assert!(Mesh::new(v.clone(), hull.clone()).is_err());
    /// let open_box = Mesh::close_openings(v, hull)?;
    /// assert_eq!(open_box.openings().len(), 1);
    /// assert!((open_box.volume() - 1.0).abs() < 1e-14);
    ///
    /// // Floating 0.3 m deep, the rim 0.7 m above the water: the closed box's buoyancy.
    /// let pose = Pose::from_parts(Translation3::new(0.0, 0.2, 0.0), UnitQuaternion::identity());
    /// open_box.check_openings(&pose, &Water::default())?;
    /// let b = open_box.buoyancy(&pose, &Water::default(), Method::Exact)?;
    /// assert!((b.submerged_volume - 0.3).abs() < 1e-14);
    /// // Pushed 1.2 m down, the water pours in.
    /// let sunk = Pose::from_parts(Translation3::new(0.0, -0.7, 0.0), UnitQuaternion::identity());
    /// let e = open_box.check_openings(&sunk, &Water::default()).unwrap_err();
    /// assert!(matches!(e, Error::OpeningSubmerged { opening: 0, .. }));
    /// # Ok::<(), Error>(())
    /// ```
    ///
    /// # Errors
    /// What [`Mesh::new`] reports, but for open edges: a mesh with other defects, and a
    /// triangle soup or a mesh with coincident vertices (whose open edges need welding, not
    /// lids), gets [`Error::InvalidMesh`] listing every defect, open edges included;
    /// [`Error::NonPlanarOpening`] naming the first opening whose rim is not planar and its
    /// vertex farthest from the plane; [`Error::InvalidOpening`] for a rim that encloses no area
    /// (`|N| ≤ 10⁻¹²·r²`) or that meets another rim (or itself) at a vertex.
    pub fn close_openings(
        vertices: Vec<Point3<T>>,
        triangles: Vec<[u32; 3]>,
    ) -> Result<Self, Error> {
        match validation::validate(&vertices, &triangles) {
            Ok(()) => return Mesh::new(vertices, triangles),
            Err(Error::InvalidMesh(defects))
                if defects
                    .defects
                    .iter()
                    .all(|d| d.kind == DefectKind::OpenEdge)
                    && !defects.triangle_soup
                    && defects.coincident_vertices == 0 => {}
            Err(e) => return Err(e),
        }
        let rims = rims(&triangles)?;
        let (mut vertices, mut triangles) = (vertices, triangles);
        let epsilon = T::default_epsilon().to_f64();
        let mut openings = Vec::with_capacity(rims.len());
        for (opening, rim) in rims.into_iter().enumerate() {
            let points: Vec<Vector3<f64>> = rim
                .iter()
                .map(|&i| vertices[i as usize].coords.map(T::to_f64))
                .collect();
            let center = points.iter().sum::<Vector3<f64>>() / points.len() as f64;
            let radius = points
                .iter()
                .map(|p| (p - center).norm())
                .fold(0.0, f64::max);
            let magnitude = points.iter().map(|p| p.amax()).fold(0.0, f64::max);
            let newell: Vector3<f64> = (0..points.len())
                .map(|k| (points[k] - center).cross(&(points[(k + 1) % points.len()] - center)))
                .sum();
            let norm = newell.norm();
            // Negated so that a NaN (an overflow) is refused too.
            #[allow(clippy::neg_cmp_op_on_partial_ord)]
            if !(norm > 1e-12 * radius * radius) {
                return Err(Error::InvalidOpening {
                    opening,
                    vertex: rim[0],
                    reason: "its rim encloses no area (its vertices lie on a line, or the rim \
                             doubles back on itself)",
                });
            }
            let normal = newell / norm;
            let (farthest, deviation) = rim
                .iter()
                .zip(&points)
                .map(|(&i, p)| (i, normal.dot(&(p - center)).abs()))
                .fold((rim[0], 0.0), |best, d| if d.1 > best.1 { d } else { best });
            let tolerance = PLANARITY * radius + 16.0 * epsilon * magnitude;
            #[allow(clippy::neg_cmp_op_on_partial_ord)]
            if !(deviation <= tolerance) {
                return Err(Error::NonPlanarOpening {
                    opening,
                    vertex: farthest,
                    deviation,
                    tolerance,
                });
            }
            let c = u32::try_from(vertices.len()).map_err(|_| Error::TooManyVertices {
                count: vertices.len() + 1,
            })?;
            vertices.push(Point3::from(center.map(T::from_f64_lossy)));
            let first = triangles.len();
            for k in 0..rim.len() {
                triangles.push([c, rim[(k + 1) % rim.len()], rim[k]]);
            }
            openings.push(Opening {
                rim,
                center: c,
                triangles: first..triangles.len(),
            });
        }
        let mut mesh = Mesh::new(vertices, triangles)?;
        mesh.openings = openings;
        Ok(mesh)
    }

    /// The openings closed by lids when the mesh was built ([`Mesh::close_openings`]): none for
    /// a mesh built by [`Mesh::new`]. [`Mesh::transformed`] and its kin keep them.
    pub fn openings(&self) -> &[Opening] {
        &self.openings
    }

    /// Whether the water stays below every opening of the hull ([`Mesh::openings`]) with the
    /// mesh placed by `pose` (mesh → world) in `water`: `Ok(())` when every rim vertex is
    /// strictly above the surface (and always for a mesh without opening).
    ///
    /// The lid is flat and its triangles fan from the rim's mean, so its lowest point is a rim
    /// vertex: the check costs one height per rim vertex, nothing for a mesh without opening. A
    /// rim vertex in the surface (`h = 0`) counts as reached, as a vertex at `h = 0` counts as
    /// under water everywhere in this crate.
    ///
    /// # Errors
    /// [`Error::InvalidPose`] if the pose has a NaN or infinite component or a zero quaternion;
    /// [`Error::OpeningSubmerged`] naming the first opening the water reaches and its lowest rim
    /// vertex.
    pub fn check_openings(&self, pose: &Pose<T>, water: &Water<T>) -> Result<(), Error> {
        if self.openings.is_empty() {
            return Frame::new(self, pose, water).map(|_| ());
        }
        self.openings_dry(&Frame::new(self, pose, water)?)
    }

    /// [`Mesh::check_openings`] in an evaluation's frame: one branch for a mesh without opening.
    #[inline]
    pub(crate) fn openings_dry(&self, frame: &Frame<T>) -> Result<(), Error> {
        if self.openings.is_empty() {
            return Ok(());
        }
        let height = |i: u32| {
            let v = &self.vertices[self.vertex_slots[i as usize] as usize];
            frame.normal_local.dot(v) + frame.height
        };
        for (opening, o) in self.openings.iter().enumerate() {
            let (vertex, lowest) = o.rim.iter().map(|&i| (i, height(i))).fold(
                (o.rim[0], height(o.rim[0])),
                |low, v| {
                    if v.1 < low.1 { v } else { low }
                },
            );
            // Negated so that a NaN height is refused too.
            #[allow(clippy::neg_cmp_op_on_partial_ord)]
            if !(lowest > T::zero()) {
                return Err(Error::OpeningSubmerged {
                    opening,
                    vertex,
                    height: lowest.to_f64(),
                });
            }
        }
        Ok(())
    }
}

/// The rims of a mesh whose only defects are open edges: each a loop of vertex indices in the
/// order the triangles run along their open edges, starting at its smallest vertex, the loops
/// in the order of their smallest vertex.
///
/// # Errors
/// [`Error::InvalidOpening`] where a vertex has more than one open edge leaving it (two rims,
/// or two parts of one, meet there) or none (the rim does not close).
fn rims(triangles: &[[u32; 3]]) -> Result<Vec<Vec<u32>>, Error> {
    // Every directed edge keyed by its undirected one; the edges of one triangle only are open.
    let mut edges: Vec<(u32, u32, u32, u32)> = triangles
        .iter()
        .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
        .map(|(a, b)| (a.min(b), a.max(b), a, b))
        .collect();
    edges.sort_unstable();
    let mut open: Vec<(u32, u32)> = edges
        .chunk_by(|x, y| (x.0, x.1) == (y.0, y.1))
        .filter(|run| run.len() == 1)
        .map(|run| (run[0].2, run[0].3))
        .collect();
    // By the vertex they leave: the one after `a → b` is the open edge leaving `b`.
    open.sort_unstable();
    let mut used = alloc::vec![false; open.len()];
    let mut rims = Vec::new();
    for start in 0..open.len() {
        if used[start] {
            continue;
        }
        let opening = rims.len();
        let mut rim = Vec::new();
        let mut edge = start;
        loop {
            used[edge] = true;
            let (a, b) = open[edge];
            rim.push(a);
            let first = open.partition_point(|e| e.0 < b);
            let leaving = open[first..].iter().take_while(|e| e.0 == b).count();
            let pinched = Error::InvalidOpening {
                opening,
                vertex: b,
                reason: "two open edges leave this vertex: two rims (or two parts of one) meet \
                         there, and a flat lid cannot tell which way to go; split the vertex or \
                         close the openings in the mesh",
            };
            match leaving {
                1 if first == start => break,
                1 if used[first] => return Err(pinched),
                1 => edge = first,
                0 => {
                    return Err(Error::InvalidOpening {
                        opening,
                        vertex: b,
                        reason: "no open edge leaves this vertex: the rim does not close",
                    });
                }
                _ => return Err(pinched),
            }
        }
        rims.push(rim);
    }
    Ok(rims)
}
