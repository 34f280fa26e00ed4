use alloc::vec::Vec;

use nalgebra::{Matrix4, Point3, Vector3};

use crate::mesh::Opening;
use crate::mesh::hierarchy::Hierarchy;
use crate::mesh::node_sums::{NodeSums, TriangleTerms};
use crate::mesh::validation;
use crate::query::surface_integral::moments::SurfaceMoments;
use crate::query::waves::vertex_terms::VertexTerms;
use crate::{Error, Real};

/// The memory [`Mesh::new`] holds at its peak per triangle, bytes, rounded up: 337–341 measured
/// for `f64` on a UV sphere of 2 million triangles (`python benches/mesh_memory.py`).
const PREPARED_BYTES_PER_TRIANGLE: usize = 384;

/// A closed, consistently oriented triangle mesh, validated and prepared for buoyancy queries.
///
/// Built once from vertices and triangle indices; every query afterwards only reads it, so a
/// `Mesh` can be shared between threads. Construction checks that the triangles form a closed
/// 2-manifold with consistent orientation (every edge shared by exactly two triangles that
/// traverse it in opposite directions), and:
///
/// * **fixes** inward winding: if the enclosed signed volume is negative, every triangle is
///   flipped (see [`Mesh::was_reoriented`]);
/// * **accepts** zero-area triangles (coincident vertices with distinct indices) and unused
///   vertices;
/// * **rejects** everything else with a typed [`Error`] naming the vertex, triangle or edge.
///
/// A hull surface with planar openings (a hull without a deck) is closed by flat lids with
/// [`Mesh::close_openings`], which remembers them ([`Mesh::openings`]) so that
/// [`Mesh::check_openings`] can tell whether the water reaches one at a pose.
///
/// It precomputes, in `f64` whatever `T` is, the volume, the centroid, the vertices relative to
/// the centroid, the per-triangle volume elements the [`Fast`](crate::Method::Fast) method
/// sums, the per-triangle unit normals and areas the [damping](crate::damping) integrates, and
/// a bounding-volume hierarchy (see [`Traversal`](crate::Traversal)). All of it is in the *mesh
/// frame*.
///
/// ```
/// use buoyancy_core::{DefectKind, Error, Mesh};
/// use nalgebra::Point3;
///
/// let v: Vec<Point3<f64>> = vec![
///     Point3::new(0.0, 0.0, 0.0),
///     Point3::new(1.0, 0.0, 0.0),
///     Point3::new(0.0, 1.0, 0.0),
///     Point3::new(0.0, 0.0, 1.0),
/// ];
/// let tetrahedron = Mesh::new(v.clone(), vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]).unwrap();
/// assert!((tetrahedron.volume() - 1.0 / 6.0).abs() < 1e-15);
///
/// // Without its last face the surface has a hole: three open edges.
/// let Err(Error::InvalidMesh(defects)) = Mesh::new(v, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2]]) else {
///     panic!("an open mesh is rejected");
/// };
/// assert_eq!(defects.count(DefectKind::OpenEdge), 3);
/// ```
#[derive(Debug, Clone)]
pub struct Mesh<T: Real> {
    /// Vertex positions relative to `centroid`, mesh frame, numbered in the order the leaf-order
    /// triangles first use them (unused vertices last), so that a leaf's vertices lie close
    /// together in memory.
    pub(crate) vertices: Vec<Vector3<T>>,
    /// For each input vertex, its position in `vertices`.
    pub(crate) vertex_slots: Vec<u32>,
    /// Outward-oriented triangles (counter-clockwise seen from outside), in the input order.
    pub(crate) triangles: Vec<[u32; 3]>,
    /// The same triangles in the hierarchy's leaf order, so that a leaf's triangles and their
    /// precomputed sums are contiguous, with indices into `vertices`. The per-triangle arrays
    /// below follow this order.
    pub(crate) leaf_triangles: Vec<[u32; 3]>,
    /// Centroid of the enclosed volume, mesh frame.
    pub(crate) centroid: Point3<T>,
    /// Enclosed volume, m³.
    pub(crate) volume: T,
    /// Σ |V_i(centroid)|: the magnitude of the terms the volume is summed from, used to make
    /// round-off thresholds relative to the mesh.
    pub(crate) volume_scale: T,
    /// Per triangle `6·V_i = v_a·(v_b×v_c)`: six times the signed volume of the tetrahedron
    /// it spans with the centroid.
    pub(crate) tetra_volume6: Vec<T>,
    /// Per triangle `24·V_i·(v_a+v_b+v_c)/4`: twenty-four times that tetrahedron's first
    /// moment about the centroid.
    pub(crate) tetra_moment24: Vec<Vector3<T>>,
    /// Per triangle (leaf order), its outward unit normal and twice its area.
    pub(crate) normals: Vec<TriangleNormal<T>>,
    /// Per triangle (leaf order), twice its area again: what the volume methods, which sum
    /// precomputed terms, add to the wetted area for a triangle under water. On its own, so
    /// that they read one number a triangle for it rather than a normal's four.
    pub(crate) double_areas: Vec<T>,
    /// Largest distance of a vertex from the centroid.
    pub(crate) bounding_radius: T,
    /// Length of the longest edge, m.
    pub(crate) longest_edge: T,
    /// Total surface area, m².
    pub(crate) surface_area: T,
    /// A bounding-volume hierarchy over the triangles.
    pub(crate) hierarchy: Hierarchy<T>,
    /// What the hierarchy's nodes add for each method when entirely under water.
    pub(crate) node_sums: NodeSums<T>,
    /// Per vertex (in `vertices`' order), the coefficients of the pressure integrals linear in
    /// its height, for the parts under water of a non-flat surface.
    pub(crate) vertex_terms: Vec<VertexTerms<T>>,
    /// The openings closed by lids ([`Mesh::close_openings`]); empty for a closed input.
    pub(crate) openings: Vec<Opening>,
    reoriented: bool,
}

impl<T: Real> Mesh<T> {
    /// Validates and prepares a mesh from vertex positions (mesh frame, metres) and triangles
    /// (zero-based indices into `vertices`, wound counter-clockwise seen from outside, or all
    /// clockwise: inward winding is detected and fixed).
    ///
    /// # Errors
    /// [`Error::EmptyMesh`] for no triangles; [`Error::TooManyVertices`] beyond `u32` indices;
    /// [`Error::InvalidMesh`] with every problem found at once (non-finite vertices, indices out
    /// of range, repeated indices, open, non-manifold and inconsistently oriented edges: the
    /// count of each, the first culprits and the usual remedy, see [`MeshDefects`](crate::MeshDefects));
    /// [`Error::ZeroVolume`] for a closed mesh that encloses no volume; [`Error::OutOfMemory`]
    /// (parameter `triangles`) when the memory to prepare it, about 340 bytes a triangle at the
    /// peak, cannot be had.
    pub fn new(vertices: Vec<Point3<T>>, triangles: Vec<[u32; 3]>) -> Result<Self, Error> {
        let mut triangles = triangles;
        // What preparing the mesh holds at its peak, asked for once so that a mesh too large
        // for the memory is an error, not the allocator's abort.
        crate::error::check_memory(triangles.len(), PREPARED_BYTES_PER_TRIANGLE, "triangles")?;
        validation::validate(&vertices, &triangles)?;
        // Everything below in f64, so that f32 meshes and meshes far from their origin keep
        // their digits.
        let points: Vec<Vector3<f64>> = vertices.iter().map(|p| p.coords.map(T::to_f64)).collect();
        let (volume, centroid, reoriented) = enclosed_volume(&points, &mut triangles)?;
        let relative: Vec<Vector3<f64>> = points.iter().map(|p| p - centroid).collect();
        let stored: Vec<Vector3<T>> = relative.iter().map(|v| v.map(T::from_f64_lossy)).collect();
        let (hierarchy, order) = Hierarchy::build(&stored, &triangles);
        let layout = LeafLayout::new(&stored, &triangles, &order);
        // Per triangle, in leaf order: the volume terms, once, for the node sums and the
        // per-triangle arrays alike.
        let volume_terms: Vec<VolumeTerms> = order
            .iter()
            .map(|&i| VolumeTerms::new(triangles[i as usize].map(|k| relative[k as usize])))
            .collect();
        let node_sums = NodeSums::build(&hierarchy, |i| {
            let VolumeTerms {
                volume6,
                moment24,
                area2,
            } = volume_terms[i];
            TriangleTerms {
                volume6,
                moment24,
                area2,
                double_area: area2.norm(),
                surface: SurfaceMoments::triangle(layout.corners(i).map(|v| v.map(T::to_f64))),
            }
        });
        let (mut volume_scale, mut surface_area) = (0.0, 0.0);
        let (mut tetra_volume6, mut tetra_moment24, mut normals, mut double_areas) = (
            Vec::with_capacity(order.len()),
            Vec::with_capacity(order.len()),
            Vec::with_capacity(order.len()),
            Vec::with_capacity(order.len()),
        );
        for terms in &volume_terms {
            let normal = TriangleNormal::new(&terms.area2);
            volume_scale += terms.volume6.abs() / 6.0;
            surface_area += normal.double_area / 2.0;
            tetra_volume6.push(T::from_f64_lossy(terms.volume6));
            tetra_moment24.push(terms.moment24.map(T::from_f64_lossy));
            double_areas.push(T::from_f64_lossy(normal.double_area));
            normals.push(normal.cast());
        }
        let bounding_radius = relative.iter().map(|v| v.norm()).fold(0.0, f64::max);
        let longest_edge = triangles
            .iter()
            .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
            .map(|(a, b)| (relative[a as usize] - relative[b as usize]).norm())
            .fold(0.0, f64::max);
        let vertex_terms = VertexTerms::build(&layout.vertices, &layout.triangles);
        Ok(Mesh {
            vertex_terms,
            vertices: layout.vertices,
            vertex_slots: layout.vertex_slots,
            leaf_triangles: layout.triangles,
            triangles,
            centroid: Point3::from(centroid.map(T::from_f64_lossy)),
            volume: T::from_f64_lossy(volume),
            volume_scale: T::from_f64_lossy(volume_scale),
            tetra_volume6,
            tetra_moment24,
            normals,
            double_areas,
            bounding_radius: T::from_f64_lossy(bounding_radius),
            longest_edge: T::from_f64_lossy(longest_edge),
            surface_area: T::from_f64_lossy(surface_area),
            hierarchy,
            node_sums,
            openings: Vec::new(),
            reoriented,
        })
    }

    /// This mesh with every vertex mapped by the affine `matrix` (homogeneous, mesh frame):
    /// `x' = A x + b` for `matrix = [[A, b], [0, 1]]`. A mirroring map (`det A < 0`) keeps the
    /// triangles facing outward; the result is validated and prepared like any new mesh.
    ///
    /// ```
    /// use buoyancy_core::{Mesh, mesh::primitives};
    /// use nalgebra::{Matrix4, Vector3};
    ///
    /// let (v, t) = primitives::cube::<f64>(1)?;
    /// let cube = Mesh::new(v, t)?;
    /// let slab = cube.scaled(&Vector3::new(2.0, 0.5, 1.0))?;
    /// assert!((slab.volume() - 1.0).abs() < 1e-12);
    /// let moved = cube.transformed(&Matrix4::new_translation(&Vector3::new(0.0, 3.0, 0.0)))?;
    /// assert!((moved.centroid().y - 3.0).abs() < 1e-12);
    /// # Ok::<(), buoyancy_core::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidTransform`] if `matrix` has a NaN or infinite entry or its last row is
    /// not `[0, 0, 0, 1]`; [`Error::ZeroVolume`] if it is singular (it flattens the mesh).
    pub fn transformed(&self, matrix: &Matrix4<T>) -> Result<Self, Error> {
        if !matrix.iter().all(|x| x.is_finite()) {
            return Err(Error::InvalidTransform {
                reason: "the matrix has a NaN or infinite entry",
            });
        }
        let (zero, one) = (T::zero(), T::one());
        if matrix.row(3).iter().ne([zero, zero, zero, one].iter()) {
            return Err(Error::InvalidTransform {
                reason: "the last row of an affine matrix must be [0, 0, 0, 1]",
            });
        }
        let vertices = (0..self.vertex_count())
            .map(|i| matrix.transform_point(&self.vertex(i)))
            .collect();
        // The same vertex and triangle numbers: the lids and their rims carry over (an
        // affine map keeps them planar).
        let mut mesh = Mesh::new(vertices, self.triangles.clone())?;
        mesh.openings = self.openings.clone();
        Ok(mesh)
    }

    /// This mesh scaled by `factors` along the axes of the mesh frame, about its origin; see
    /// [`Mesh::transformed`]. A negative factor mirrors the mesh.
    ///
    /// # Errors
    /// [`Error::InvalidTransform`] if a factor is zero, NaN or infinite.
    pub fn scaled(&self, factors: &Vector3<T>) -> Result<Self, Error> {
        if !factors.iter().all(|f| f.is_finite() && *f != T::zero()) {
            return Err(Error::InvalidTransform {
                reason: "every scale factor must be finite and non-zero",
            });
        }
        self.transformed(&Matrix4::new_nonuniform_scaling(factors))
    }

    /// This mesh moved by `offset` (mesh frame, m); see [`Mesh::transformed`].
    ///
    /// # Errors
    /// [`Error::InvalidTransform`] if `offset` has a NaN or infinite component.
    pub fn translated(&self, offset: &Vector3<T>) -> Result<Self, Error> {
        self.transformed(&Matrix4::new_translation(offset))
    }

    /// Enclosed volume in m³ (positive).
    pub fn volume(&self) -> T {
        self.volume
    }

    /// Centroid of the enclosed volume (the center of mass of a uniform body), mesh frame.
    pub fn centroid(&self) -> Point3<T> {
        self.centroid
    }

    /// Number of vertices, including any that no triangle uses.
    pub fn vertex_count(&self) -> usize {
        self.vertices.len()
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// Position of vertex `i`, mesh frame. Panics if `i >= vertex_count()`.
    pub fn vertex(&self, i: usize) -> Point3<T> {
        self.centroid + self.vertices[self.vertex_slots[i] as usize]
    }

    /// The triangles, oriented outward (flipped from the input if [`Mesh::was_reoriented`]).
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Bytes of memory taken by the bounding-volume hierarchy of
    /// [`Traversal::Hierarchy`](crate::Traversal::Hierarchy): its nodes with the volume and
    /// surface sums and their area (for [`Buoyancy::wetted_area`](crate::Buoyancy::wetted_area):
    /// one number per node beside the volume sums, one per inner node beside the surface sums),
    /// the triangles' copy in leaf order, and the per-vertex terms of the walk under waves (see
    /// [`Mesh::buoyancy`] under waves).
    pub fn hierarchy_bytes(&self) -> usize {
        self.hierarchy.memory()
            + self.node_sums.memory()
            + self.vertex_terms.len() * core::mem::size_of::<VertexTerms<T>>()
            + self.leaf_triangles.len() * core::mem::size_of::<[u32; 3]>()
    }

    /// Whether the input was wound inward (negative signed volume) and every triangle flipped.
    pub fn was_reoriented(&self) -> bool {
        self.reoriented
    }

    /// The longest edge of the triangles, m: under waves sampled at the vertices, a wave shorter
    /// than twice this is not seen between them (see
    /// [`AiryWaves::shortest_wavelength`](crate::water::AiryWaves::shortest_wavelength)).
    pub fn longest_edge(&self) -> T {
        self.longest_edge
    }

    /// Largest distance of a vertex from the centroid, in m: the radius of a ball about the
    /// centroid that holds the mesh.
    pub fn bounding_radius(&self) -> T {
        self.bounding_radius
    }

    /// Total surface area in m² (the sum of the triangle areas).
    pub fn surface_area(&self) -> T {
        self.surface_area
    }
}

/// The enclosed volume and centroid of a closed, consistently oriented mesh, `f64`, mesh frame;
/// every triangle flipped first (and `true` returned) if the mesh is wound inward.
///
/// Summed about the middle of the bounding box, so that a mesh far from its origin keeps its
/// digits: `V = Σ detᵢ/6`, first moment `Σ detᵢ·(aᵢ+bᵢ+cᵢ)/24`, `detᵢ = aᵢ·(bᵢ×cᵢ)`.
///
/// # Errors
/// [`Error::ZeroVolume`] if `|V|` is not above `10⁻¹²·Σ|detᵢ/6|` (or is NaN).
fn enclosed_volume(
    points: &[Vector3<f64>],
    triangles: &mut [[u32; 3]],
) -> Result<(f64, Vector3<f64>, bool), Error> {
    let (lo, hi) = points
        .iter()
        .fold((points[0], points[0]), |(lo, hi), p| (lo.inf(p), hi.sup(p)));
    let middle = (lo + hi) * 0.5;
    let mut volume = 0.0;
    let mut moment = Vector3::zeros();
    let mut scale = 0.0;
    for t in triangles.iter() {
        let [a, b, c] = t.map(|i| points[i as usize] - middle);
        let v = a.dot(&b.cross(&c)) / 6.0;
        volume += v;
        scale += v.abs();
        moment += (a + b + c) * (v / 4.0);
    }
    // Negated so that a NaN volume is rejected too.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    if !(volume.abs() > 1e-12 * scale) {
        return Err(Error::ZeroVolume { volume, scale });
    }
    let reoriented = volume < 0.0;
    if reoriented {
        for t in triangles.iter_mut() {
            t.swap(1, 2);
        }
        // Flipping a triangle negates its determinant exactly.
        (volume, moment) = (-volume, -moment);
    }
    Ok((volume, middle + moment / volume, reoriented))
}

/// The volume methods' terms of a triangle, `f64`, about the centroid.
#[derive(Clone, Copy)]
struct VolumeTerms {
    /// `det = a·(b×c)`.
    volume6: f64,
    /// `det·(a + b + c)`.
    moment24: Vector3<f64>,
    /// `(b − a)×(c − a)`.
    area2: Vector3<f64>,
}

impl VolumeTerms {
    /// The terms of the triangle of corners `[a, b, c]` (relative to the centroid).
    fn new([a, b, c]: [Vector3<f64>; 3]) -> Self {
        let det = a.dot(&b.cross(&c));
        VolumeTerms {
            volume6: det,
            moment24: (a + b + c) * det,
            area2: (b - a).cross(&(c - a)),
        }
    }
}

/// A triangle's outward unit normal and twice its area (the norm of `(b − a)×(c − a)`); a zero
/// vector and zero for a triangle of zero area.
#[derive(Debug, Clone, Copy)]
pub(crate) struct TriangleNormal<T: Real> {
    /// Outward unit normal, mesh frame.
    pub unit: Vector3<T>,
    /// Twice the area, m².
    pub double_area: T,
}

impl TriangleNormal<f64> {
    /// From twice the area vector, `(b − a)×(c − a)`.
    fn new(area_vector2: &Vector3<f64>) -> Self {
        let double_area = area_vector2.norm();
        let unit = if double_area > 0.0 {
            area_vector2 / double_area
        } else {
            Vector3::zeros()
        };
        TriangleNormal { unit, double_area }
    }

    fn cast<T: Real>(&self) -> TriangleNormal<T> {
        TriangleNormal {
            unit: self.unit.map(T::from_f64_lossy),
            double_area: T::from_f64_lossy(self.double_area),
        }
    }
}

/// The vertices and triangles as the queries read them: triangles in the hierarchy's leaf order,
/// vertices renumbered by first use in that order (unused vertices last), so that a leaf's
/// triangles and vertices lie close together in memory.
struct LeafLayout<T: Real> {
    vertices: Vec<Vector3<T>>,
    /// For each input vertex, its position in `vertices`.
    vertex_slots: Vec<u32>,
    /// The triangles in leaf order, indices into `vertices`.
    triangles: Vec<[u32; 3]>,
}

impl<T: Real> LeafLayout<T> {
    /// Lays out `vertices` and `triangles` by the leaf `order` (indices into `triangles`).
    fn new(vertices: &[Vector3<T>], triangles: &[[u32; 3]], order: &[u32]) -> Self {
        let mut vertex_slots = alloc::vec![u32::MAX; vertices.len()];
        let mut renumbered = Vec::with_capacity(vertices.len());
        for &i in order {
            for &k in &triangles[i as usize] {
                if vertex_slots[k as usize] == u32::MAX {
                    vertex_slots[k as usize] = renumbered.len() as u32;
                    renumbered.push(vertices[k as usize]);
                }
            }
        }
        for (k, slot) in vertex_slots.iter_mut().enumerate() {
            if *slot == u32::MAX {
                *slot = renumbered.len() as u32;
                renumbered.push(vertices[k]);
            }
        }
        let triangles = order
            .iter()
            .map(|&i| triangles[i as usize].map(|k| vertex_slots[k as usize]))
            .collect();
        LeafLayout {
            vertices: renumbered,
            vertex_slots,
            triangles,
        }
    }

    /// The corners of leaf-order triangle `i`, as stored.
    fn corners(&self, i: usize) -> [Vector3<T>; 3] {
        self.triangles[i].map(|k| self.vertices[k as usize])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
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

    #[test]
    fn tetrahedron_volume_and_centroid() {
        let (v, t) = tetrahedron();
        let m = Mesh::new(v, t).unwrap();
        assert!((m.volume() - 1.0 / 6.0).abs() < 1e-15);
        assert!((m.centroid() - Point3::new(0.25, 0.25, 0.25)).norm() < 1e-15);
        assert!(!m.was_reoriented());
        assert_eq!((m.vertex_count(), m.triangle_count()), (4, 4));
        let sum: f64 = m.tetra_volume6.iter().sum();
        assert!((sum / 6.0 - m.volume()).abs() < 1e-15);
    }

    #[test]
    fn vertices_keep_their_input_numbers() {
        // Vertex 0 unused, the others listed out of the order the triangles use them.
        let (mut v, t) = tetrahedron();
        v.insert(0, Point3::new(5.0, 6.0, 7.0));
        v.swap(1, 4);
        let t: Vec<[u32; 3]> = t
            .iter()
            .map(|t| t.map(|k| [4, 2, 3, 1][k as usize]))
            .collect();
        let m = Mesh::new(v.clone(), t.clone()).unwrap();
        assert_eq!(m.vertex_count(), 5);
        assert_eq!(m.triangles(), &t[..]);
        for (i, p) in v.iter().enumerate() {
            assert!((m.vertex(i) - p).norm() < 1e-15, "vertex {i}");
        }
        // The internal numbering follows first use in leaf order, the unused vertex last.
        assert_eq!(m.leaf_triangles[0], [0, 1, 2]);
        assert_eq!(m.vertex_slots[0], 4);
        // Every leaf-order triangle is an input triangle, corners in the same order.
        for leaf in &m.leaf_triangles {
            let corners = leaf.map(|k| m.centroid + m.vertices[k as usize]);
            let same =
                |t: &[u32; 3]| (0..3).all(|j| (v[t[j] as usize] - corners[j]).norm() < 1e-15);
            assert!(t.iter().any(same), "{leaf:?}");
        }
    }

    #[test]
    fn transformed_copies_move_the_mesh_and_keep_it_outward() {
        let (v, t) = tetrahedron();
        let m = Mesh::new(v, t).unwrap();
        let mirrored = m.scaled(&Vector3::new(-2.0, 1.0, 1.0)).unwrap();
        assert!((mirrored.volume() - 2.0 / 6.0).abs() < 1e-15);
        assert!((mirrored.centroid() - Point3::new(-0.5, 0.25, 0.25)).norm() < 1e-15);
        let moved = m.translated(&Vector3::new(1.0, 2.0, 3.0)).unwrap();
        assert!((moved.centroid() - Point3::new(1.25, 2.25, 3.25)).norm() < 1e-15);
        assert_eq!(moved.triangles(), m.triangles());
        for bad in [0.0, f64::NAN, f64::INFINITY] {
            let e = m.scaled(&Vector3::new(1.0, bad, 1.0)).unwrap_err();
            assert!(matches!(e, Error::InvalidTransform { .. }), "{e}");
        }
        let mut projective = Matrix4::identity();
        projective[(3, 0)] = 0.5;
        let e = m.transformed(&projective).unwrap_err();
        assert!(matches!(e, Error::InvalidTransform { .. }), "{e}");
        let mut flat = Matrix4::identity();
        flat[(1, 1)] = 0.0;
        let e = m.transformed(&flat).unwrap_err();
        assert!(matches!(e, Error::ZeroVolume { .. }), "{e}");
    }

    #[test]
    fn inward_winding_is_flipped() {
        let (v, mut t) = tetrahedron();
        t.iter_mut().for_each(|t| t.swap(0, 1));
        let m = Mesh::new(v, t).unwrap();
        assert!(m.was_reoriented());
        assert!((m.volume() - 1.0 / 6.0).abs() < 1e-15);
        assert_eq!(m.triangles()[0], [2, 1, 0]);
    }
}
