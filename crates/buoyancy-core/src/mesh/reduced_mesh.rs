//! A coarse copy of a mesh's surface for the damping's pressure drag: [`ReducedMesh`].

use alloc::collections::BTreeMap;
use alloc::vec::Vec;

use nalgebra::{Matrix3, Point3, Vector3};

use crate::mesh::TriangleNormal;
use crate::{Mesh, Real};

/// Fewest triangles a reduction may be asked for: fewer count as this many.
pub const MIN_REDUCED_TRIANGLES: usize = 64;

/// Largest relative difference of the reduced surface's area or enclosed volume from the
/// mesh's for the reduction to be kept (see [`ReducedMesh`]).
const SHAPE_TOLERANCE: f64 = 0.1;

/// A coarse copy of a mesh's surface for its pressure drag: triangles with their outward unit normals and areas, in the
/// mesh frame, vertices relative to the mesh's centroid, built by [`ReducedMesh::new`] and used
/// by [`Mesh::reduced_damping`].
///
/// A coarse copy of a mesh's surface, built once, for the pressure drag of the
/// [damping](crate::damping) model: [`ReducedMesh`].
///
/// The pressure drag is integrated exactly over every wetted triangle, clipped where the normal
/// velocity changes sign, so its cost grows with the wetted triangles (a 5,000-triangle mesh
/// half under water: about 3,000 of them). Its integrand is smooth in the surface (the local
/// normal and position), so a surface of a few hundred triangles that keeps the mesh's shape
/// (its area, the area-weighted normals of each region, its volume) gives nearly the same force
/// and torque at a fraction of the cost. The buoyancy keeps the full mesh: it is exact, and its
/// hierarchy makes it follow the waterline.
///
/// # The reduction: vertex clustering
/// The mesh's box (mesh frame) is cut into cubic cells of side `s = L / r` (`L` the box's
/// longest side, `r` the resolution); the vertices of a cell merge into one representative,
/// the point `x` that minimises the area-weighted squared distances to the planes of the
/// triangles around the cell's vertices (the quadric error of Garland and Heckbert),
/// `Σ Aₜ (n̂ₜ·x − dₜ)²`, plus `λ·|x − m|²` toward the mean `m` of the cell's vertices (`λ`
/// 10⁻³ of the mean eigenvalue of the quadric), so that a flat or creased patch keeps its
/// representative on it; a solution outside the cell grown by one cell on each side is
/// replaced by `m`. Triangles whose corners fall in fewer than three cells vanish; two
/// triangles on the same three representatives with opposite windings (a sheet folded onto
/// itself) cancel. The result is a triangle soup, not necessarily a closed manifold: the drag
/// does not need one. The largest resolution whose result has at most the requested number of
/// triangles is kept (found by bisection over `r` in `[2, 1024)`).
///
/// A reduction that loses too much of the surface (its area or volume more than 10 % off the
/// mesh's, a flat or very thin mesh at a coarse resolution) is refused: the full mesh is used.
#[derive(Debug, Clone)]
pub struct ReducedMesh<T: Real> {
    /// Vertices relative to the source mesh's centroid, mesh frame.
    vertices: Vec<Vector3<T>>,
    triangles: Vec<[u32; 3]>,
    /// Per triangle, the outward unit normal and twice the area.
    pub(crate) normals: Vec<TriangleNormal<T>>,
    /// The source mesh's centroid, mesh frame.
    centroid: Point3<T>,
    /// Total area of the reduced triangles, m².
    surface_area: T,
    /// Signed volume the reduced triangles enclose (divergence theorem), m³.
    volume: T,
    /// The source mesh's area over the reduced one's.
    area_scale: T,
    /// The side of the clustering cells, m.
    cell_size: T,
}

impl<T: Real> ReducedMesh<T> {
    /// A copy of `mesh`'s surface with at most `max_triangles` triangles (at least
    /// [`MIN_REDUCED_TRIANGLES`]), by vertex clustering (see [`ReducedMesh`]).
    ///
    /// `None` when `mesh` has no more triangles than that (it is its own best copy: use
    /// [`Mesh::damping`]), or when no resolution keeps the area and volume within 10 % of the
    /// mesh's. Computed in `f64`; costs a few passes over the mesh (a 5,000-triangle mesh: a
    /// few milliseconds), once per mesh.
    pub fn new(mesh: &Mesh<T>, max_triangles: usize) -> Option<Self> {
        let max_triangles = max_triangles.max(MIN_REDUCED_TRIANGLES);
        if mesh.triangle_count() <= max_triangles {
            return None;
        }
        let centroid = mesh.centroid().coords.map(T::to_f64);
        let points: Vec<Vector3<f64>> = (0..mesh.vertex_count())
            .map(|i| mesh.vertex(i).coords.map(T::to_f64) - centroid)
            .collect();
        let triangles = mesh.triangles();
        // The largest resolution in [2, 1024) whose reduction fits.
        let coarsest = Clustering::new(&points, triangles, 2)?;
        if coarsest.triangles.len() > max_triangles {
            return None;
        }
        let (mut lo, mut hi, mut best) = (2, 1024, coarsest);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            match Clustering::new(&points, triangles, mid) {
                Some(c) if c.triangles.len() <= max_triangles => {
                    lo = mid;
                    best = c;
                }
                _ => hi = mid,
            }
        }
        let full_area = mesh.surface_area().to_f64();
        let full_volume = mesh.volume().to_f64();
        let off = |reduced: f64, full: f64| (reduced - full).abs() > SHAPE_TOLERANCE * full.abs();
        if off(best.area, full_area) || off(best.volume, full_volume) || best.area <= 0.0 {
            return None;
        }
        let normals = best
            .triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|k| best.vertices[k as usize]);
                let area2 = (b - a).cross(&(c - a));
                let double_area = area2.norm();
                TriangleNormal {
                    unit: (area2 / double_area).map(T::from_f64_lossy),
                    double_area: T::from_f64_lossy(double_area),
                }
            })
            .collect();
        Some(ReducedMesh {
            vertices: best
                .vertices
                .iter()
                .map(|v| v.map(T::from_f64_lossy))
                .collect(),
            triangles: best.triangles,
            normals,
            centroid: mesh.centroid(),
            surface_area: T::from_f64_lossy(best.area),
            volume: T::from_f64_lossy(best.volume),
            area_scale: T::from_f64_lossy(full_area / best.area),
            cell_size: T::from_f64_lossy(best.cell_size),
        })
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// Number of vertices (the cells' representatives; a vertex of vanished triangles only is
    /// kept, unused).
    pub fn vertex_count(&self) -> usize {
        self.vertices.len()
    }

    /// Position of vertex `i`, mesh frame. Panics if `i >= vertex_count()`.
    pub fn vertex(&self, i: usize) -> Point3<T> {
        self.centroid + self.vertices[i]
    }

    /// The triangles, wound counter-clockwise seen from outside, indices into the vertices.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Total area of the triangles, m².
    pub fn surface_area(&self) -> T {
        self.surface_area
    }

    /// The signed volume the triangles enclose, `Σ a·(b×c)/6`, m³ (the triangles need not
    /// close: it is what the divergence theorem gives them).
    pub fn volume(&self) -> T {
        self.volume
    }

    /// The source mesh's surface area over this one's: [`Mesh::reduced_damping`] multiplies
    /// the wetted area it finds by it.
    pub fn area_scale(&self) -> T {
        self.area_scale
    }

    /// The side of the clustering cells, m: the size of the details the reduction loses.
    pub fn cell_size(&self) -> T {
        self.cell_size
    }

    /// The corners of triangle `i`, relative to the source mesh's centroid.
    #[inline(always)]
    pub(crate) fn corners(&self, i: usize) -> [Vector3<T>; 3] {
        self.triangles[i].map(|k| self.vertices[k as usize])
    }
}

/// One vertex clustering at one resolution, `f64`, positions relative to the mesh's centroid.
struct Clustering {
    vertices: Vec<Vector3<f64>>,
    triangles: Vec<[u32; 3]>,
    area: f64,
    volume: f64,
    cell_size: f64,
}

/// What a cell gathers: the quadric `Σ Aₜ n̂ₜ n̂ₜᵀ`, `Σ Aₜ dₜ n̂ₜ`, and its vertices' sum and
/// count.
#[derive(Clone, Copy)]
struct Cell {
    quadric: Matrix3<f64>,
    linear: Vector3<f64>,
    sum: Vector3<f64>,
    count: u32,
    /// The cell's grid coordinates.
    at: [u32; 3],
}

impl Clustering {
    /// The clustering of `points` (relative to the centroid) and `triangles` in cells of a
    /// `resolution`-th of the box's longest side; `None` for a box of no size.
    fn new(points: &[Vector3<f64>], triangles: &[[u32; 3]], resolution: u32) -> Option<Self> {
        let used = || triangles.iter().flatten().map(|&k| points[k as usize]);
        let first = used().next()?;
        let (lo, hi) = used().fold((first, first), |(lo, hi), p| (lo.inf(&p), hi.sup(&p)));
        let extent = (hi - lo).max();
        if !(extent > 0.0 && extent.is_finite()) {
            return None;
        }
        let cell_size = extent / f64::from(resolution);
        let top = resolution - 1;
        let grid = |p: &Vector3<f64>| -> [u32; 3] {
            core::array::from_fn(|k| {
                let x = libm::floor((p[k] - lo[k]) / cell_size);
                // In [0, top]: the far faces of the box belong to the last cell.
                if x <= 0.0 { 0 } else { (x as u32).min(top) }
            })
        };
        // The cell of every vertex, numbered by first use.
        let mut numbers: BTreeMap<[u32; 3], u32> = BTreeMap::new();
        let mut cells: Vec<Cell> = Vec::new();
        let mut cell_of = alloc::vec![u32::MAX; points.len()];
        for &k in triangles.iter().flatten() {
            let k = k as usize;
            if cell_of[k] != u32::MAX {
                continue;
            }
            let at = grid(&points[k]);
            let number = *numbers.entry(at).or_insert_with(|| {
                cells.push(Cell {
                    quadric: Matrix3::zeros(),
                    linear: Vector3::zeros(),
                    sum: Vector3::zeros(),
                    count: 0,
                    at,
                });
                (cells.len() - 1) as u32
            });
            cell_of[k] = number;
            let cell = &mut cells[number as usize];
            cell.sum += points[k];
            cell.count += 1;
        }
        // The planes of the triangles around each cell's vertices, weighted by area.
        for t in triangles {
            let [a, b, c] = t.map(|k| points[k as usize]);
            let area2 = (b - a).cross(&(c - a));
            let double_area = area2.norm();
            // Zero (a degenerate triangle) or NaN: no plane.
            if double_area.is_nan() || double_area <= 0.0 {
                continue;
            }
            let n = area2 / double_area;
            let area = 0.5 * double_area;
            let (quadric, linear) = (n * n.transpose() * area, n * (n.dot(&a) * area));
            for &k in t {
                let cell = &mut cells[cell_of[k as usize] as usize];
                cell.quadric += quadric;
                cell.linear += linear;
            }
        }
        let representatives: Vec<Vector3<f64>> = cells
            .iter()
            .map(|cell| representative(cell, &lo, cell_size))
            .collect();
        // Each triangle on three distinct cells, by its set of cells: the windings add up, so
        // that a sheet folded onto itself cancels.
        let mut windings: BTreeMap<[u32; 3], i32> = BTreeMap::new();
        for t in triangles {
            let [a, b, c] = t.map(|k| cell_of[k as usize]);
            if a == b || b == c || c == a {
                continue;
            }
            let mut sorted = [a, b, c];
            sorted.sort_unstable();
            // An even permutation of the sorted cells is the same winding.
            let even = [a, b, c] == sorted || [b, c, a] == sorted || [c, a, b] == sorted;
            *windings.entry(sorted).or_insert(0) += if even { 1 } else { -1 };
        }
        // Only the cells still used, renumbered.
        let mut renumber = alloc::vec![u32::MAX; cells.len()];
        let mut vertices = Vec::new();
        let mut reduced = Vec::new();
        for (sorted, winding) in windings {
            let triangle = if winding > 0 {
                sorted
            } else {
                [sorted[0], sorted[2], sorted[1]]
            };
            let triangle = triangle.map(|c| {
                let slot = &mut renumber[c as usize];
                if *slot == u32::MAX {
                    *slot = vertices.len() as u32;
                    vertices.push(representatives[c as usize]);
                }
                *slot
            });
            for _ in 0..winding.unsigned_abs() {
                reduced.push(triangle);
            }
        }
        let (area, volume6) = area_and_volume6(&vertices, &reduced);
        // Clustering shrinks a curved surface a little: scaled about the centroid to the
        // mesh's volume, the waterline crosses it where it crosses the mesh.
        let target: f64 = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|k| points[k as usize]);
                a.dot(&b.cross(&c))
            })
            .sum();
        if volume6 > 0.0 && target > 0.0 {
            let factor = libm::cbrt(target / volume6);
            for v in &mut vertices {
                *v *= factor;
            }
        }
        let (area, volume6) = if volume6 > 0.0 && target > 0.0 {
            area_and_volume6(&vertices, &reduced)
        } else {
            (area, volume6)
        };
        // A triangle of zero area adds nothing to the drag: left out.
        reduced.retain(|t| {
            let [a, b, c] = t.map(|k| vertices[k as usize]);
            (b - a).cross(&(c - a)).norm() > 0.0
        });
        Some(Clustering {
            vertices,
            triangles: reduced,
            area,
            volume: volume6 / 6.0,
            cell_size,
        })
    }
}

/// The area and six times the signed volume (`Σ a·(b×c)`) of `triangles`.
fn area_and_volume6(vertices: &[Vector3<f64>], triangles: &[[u32; 3]]) -> (f64, f64) {
    let (mut area, mut volume6) = (0.0, 0.0);
    for t in triangles {
        let [a, b, c] = t.map(|k| vertices[k as usize]);
        area += 0.5 * (b - a).cross(&(c - a)).norm();
        volume6 += a.dot(&b.cross(&c));
    }
    (area, volume6)
}

/// The point of least area-weighted squared distance to the planes gathered by `cell`, pulled
/// toward the mean of its vertices by `λ` (10⁻³ of the quadric's mean eigenvalue): the mean
/// when the solution leaves the cell grown by one cell on each side (cells of side `size` from
/// `lo`).
fn representative(cell: &Cell, lo: &Vector3<f64>, size: f64) -> Vector3<f64> {
    let mean = cell.sum / f64::from(cell.count.max(1));
    let lambda = 1e-3 * cell.quadric.trace() / 3.0;
    if lambda.is_nan() || lambda <= 0.0 {
        return mean;
    }
    let system = cell.quadric + Matrix3::identity() * lambda;
    let Some(solution) = system
        .cholesky()
        .map(|c| c.solve(&(cell.linear + mean * lambda)))
    else {
        return mean;
    };
    let inside = (0..3).all(|k| {
        let start = lo[k] + f64::from(cell.at[k]) * size;
        solution[k] >= start - size && solution[k] <= start + 2.0 * size
    });
    if inside && solution.iter().all(|x| x.is_finite()) {
        solution
    } else {
        mean
    }
}
