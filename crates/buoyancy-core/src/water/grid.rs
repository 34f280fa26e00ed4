//! Heights on a regular grid, for oceans computed elsewhere.

use alloc::vec::Vec;

use nalgebra::{Matrix2, Point3, Vector3};

use super::WaterSurface;
use crate::{Error, Real, Water};

/// Elevations on a regular grid of `columns × rows` nodes in the still plane, interpolated
/// bilinearly: node `(i, j)` sits at `origin + i·column_step + j·row_step` and has height
/// `heights[j·columns + i]` (m). Periodic grids repeat with periods `columns·column_step` and
/// `rows·row_step`; others hold their edge values beyond their edges.
///
/// The heights do not depend on time: replace them each step with [`HeightGrid::set_heights`],
/// which copies into the grid's own storage and never reallocates.
///
/// ```
/// use buoyancy_core::water::{HeightGrid, WaterSurface};
/// use buoyancy_core::Water;
/// use nalgebra::{Point3, Vector3};
///
/// // 2 × 2 nodes, 1 m apart along x and z (y up), not periodic.
/// let grid = HeightGrid::new(vec![0.0, 1.0, 0.0, 1.0], 2, 2, Point3::origin(), Vector3::x(), Vector3::z(), false)?;
/// let mut eta = [0.0f64];
/// grid.elevations(&Water::default(), &[Point3::new(0.25, 0.0, 0.5)], 0.0, &mut eta)?;
/// assert!((eta[0] - 0.25).abs() < 1e-15);
/// # Ok::<(), buoyancy_core::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct HeightGrid<T: Real> {
    heights: Vec<T>,
    columns: usize,
    rows: usize,
    origin: Point3<T>,
    column_step: Vector3<T>,
    row_step: Vector3<T>,
    /// Maps `(q − origin)·column_step, (q − origin)·row_step` to grid coordinates.
    to_grid: Matrix2<T>,
    periodic: bool,
    /// The largest `|height|`.
    bound: T,
}

impl<T: Real> HeightGrid<T> {
    /// A grid of `columns × rows` nodes (see the type's documentation). `column_step` and
    /// `row_step` lie in the still plane of the water it is used with (their components along
    /// the up normal are not removed: give them in the plane).
    ///
    /// # Errors
    /// [`Error::InvalidSurface`] if there are fewer than 2 nodes along an axis, `heights` has
    /// not `columns·rows` finite values, or the steps are not finite and independent.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        heights: Vec<T>,
        columns: usize,
        rows: usize,
        origin: Point3<T>,
        column_step: Vector3<T>,
        row_step: Vector3<T>,
        periodic: bool,
    ) -> Result<Self, Error> {
        if columns < 2 || rows < 2 {
            return Err(Error::InvalidSurface {
                parameter: "columns",
                reason: "a height grid needs at least 2 columns and 2 rows",
            });
        }
        let finite = |v: &Vector3<T>| v.iter().all(|x| x.is_finite());
        if !(finite(&origin.coords) && finite(&column_step) && finite(&row_step)) {
            return Err(Error::InvalidSurface {
                parameter: "steps",
                reason: "a height grid's origin and steps must be finite",
            });
        }
        let gram = Matrix2::new(
            column_step.dot(&column_step),
            column_step.dot(&row_step),
            row_step.dot(&column_step),
            row_step.dot(&row_step),
        );
        let to_grid = gram
            .try_inverse()
            .filter(|m| m.iter().all(|x| x.is_finite()))
            .ok_or(Error::InvalidSurface {
                parameter: "steps",
                reason: "a height grid's column and row steps must be non-zero and not parallel",
            })?;
        let mut grid = HeightGrid {
            heights: alloc::vec![T::zero(); columns * rows],
            columns,
            rows,
            origin,
            column_step,
            row_step,
            to_grid,
            periodic,
            bound: T::zero(),
        };
        grid.set_heights(&heights)?;
        Ok(grid)
    }

    /// Replaces the heights (row after row, `columns·rows` values, m) without reallocating.
    ///
    /// # Errors
    /// [`Error::InvalidSurface`] if `heights` has the wrong length or a non-finite value; the
    /// grid is then unchanged.
    pub fn set_heights(&mut self, heights: &[T]) -> Result<(), Error> {
        if heights.len() != self.heights.len() {
            return Err(Error::InvalidSurface {
                parameter: "heights",
                reason: "a height grid needs exactly columns × rows heights",
            });
        }
        if !heights.iter().all(|h| h.is_finite()) {
            return Err(Error::InvalidSurface {
                parameter: "heights",
                reason: "a height grid's heights must be finite (m)",
            });
        }
        self.heights.copy_from_slice(heights);
        self.bound = heights.iter().fold(T::zero(), |m, h| m.max(h.abs()));
        Ok(())
    }

    /// The heights, row after row.
    pub fn heights(&self) -> &[T] {
        &self.heights
    }

    /// The grid coordinates `(s, t) = G·(d·c, d·r)` of a point `q`, `d = q − origin`, as two
    /// dot products: the vectors `∇s` and `∇t`, and the origin, in `f64`.
    fn grid_axes(&self) -> (Vector3<f64>, Vector3<f64>, Vector3<f64>) {
        let g = &self.to_grid;
        let (c, r) = (&self.column_step, &self.row_step);
        let along_s = (c * g[(0, 0)] + r * g[(0, 1)]).map(T::to_f64);
        let along_t = (c * g[(1, 0)] + r * g[(1, 1)]).map(T::to_f64);
        (along_s, along_t, self.origin.coords.map(T::to_f64))
    }

    /// Along an axis of `n` nodes, the nodes of the cells [`HeightGrid::cell`] finds for the
    /// coordinates within `spread` of `x`: the first (in `0..n`) and how many, counted on
    /// with wrapping (at most `n`). Widened by a node's `10⁻⁹` each way against the
    /// round-off of the points' coordinates. `None` for a coordinate that is not finite.
    fn nodes_within(&self, x: f64, spread: f64, n: usize) -> Option<(usize, usize)> {
        let widen = spread + 1e-9 * (1.0 + x.abs());
        let (low, high) = (x - widen, x + widen);
        if !(low.is_finite() && high.is_finite()) {
            return None;
        }
        if self.periodic {
            let (lowest, last) = (floor(low), floor(high) + 1.0);
            if last - lowest + 1.0 >= n as f64 {
                return Some((0, n));
            }
            let (first, _, _) = self.cell(lowest, n);
            Some((first, (last - lowest) as usize + 1))
        } else {
            let (first, _, _) = self.cell(low, n);
            let (last, next, _) = self.cell(high, n);
            Some((first, next.max(last) - first + 1))
        }
    }

    /// The height at the point of grid coordinates `(s, t)` (in steps from the origin),
    /// interpolated in `f64`.
    #[inline(always)]
    fn at(&self, s: f64, t: f64) -> T {
        let (i, i1, fs) = self.cell(s, self.columns);
        let (j, j1, ft) = self.cell(t, self.rows);
        let (row, next_row) = (j * self.columns, j1 * self.columns);
        let h = |k: usize| self.heights.get(k).map_or(0.0, |h| h.to_f64());
        let near = h(row + i) + (h(row + i1) - h(row + i)) * fs;
        let far = h(next_row + i) + (h(next_row + i1) - h(next_row + i)) * fs;
        T::from_f64_lossy(near + (far - near) * ft)
    }

    /// Along an axis of `n` nodes, for coordinate `x`: the cell's first node, the next node
    /// (wrapped round when periodic, the last one repeated beyond the end otherwise) and the
    /// fraction within the cell, in `[0, 1]`. The coordinate is split in `f64`.
    #[inline(always)]
    fn cell(&self, x: f64, n: usize) -> (usize, usize, f64) {
        if self.periodic {
            let whole = floor(x);
            let fraction = (x - whole).min(1.0);
            let index = if whole >= 0.0 && whole < n as f64 {
                whole as usize
            } else {
                // `whole` is an integer below 2⁵³ in magnitude here, or beyond it and even.
                let wrapped = libm::fmod(whole, n as f64);
                let wrapped = if wrapped < 0.0 {
                    wrapped + n as f64
                } else {
                    wrapped
                };
                wrapped as usize % n
            };
            let next = if index + 1 == n { 0 } else { index + 1 };
            (index, next, fraction)
        } else {
            let clamped = x.max(0.0).min((n - 1) as f64);
            let index = (floor(clamped) as usize).min(n - 2);
            (index, index + 1, clamped - index as f64)
        }
    }
}

/// `⌊x⌋` by truncation where it is exact (`|x| < 2⁵²`), without a call.
#[inline(always)]
fn floor(x: f64) -> f64 {
    if x.abs() < 4_503_599_627_370_496.0 {
        let truncated = x as i64 as f64;
        if truncated > x {
            truncated - 1.0
        } else {
            truncated
        }
    } else {
        libm::floor(x)
    }
}

impl<T: Real> WaterSurface<T> for HeightGrid<T> {
    fn elevations(
        &self,
        _: &Water<T>,
        points: &[Point3<T>],
        _: T,
        elevations: &mut [T],
    ) -> Result<(), Error> {
        let (along_s, along_t, origin) = self.grid_axes();
        for (eta, q) in elevations.iter_mut().zip(points) {
            let d = q.coords.map(T::to_f64) - origin;
            *eta = self.at(d.dot(&along_s), d.dot(&along_t));
        }
        Ok(())
    }

    /// The largest `|height|` of the grid: bilinear interpolation stays within the nodes' range.
    fn elevation_bound(&self) -> Option<T> {
        Some(self.bound)
    }

    /// The least and the greatest height of the nodes of the cells the disc can reach (its
    /// grid coordinates lie within `s₀ ± R·|∇s|`, `t₀ ± R·|∇t|`): bilinear interpolation stays
    /// within the range of its cell's four nodes. Up to 4,096 nodes are read; for a disc
    /// wider than that, `±` the grid's bound.
    fn elevation_range(
        &self,
        water: &Water<T>,
        center: &Point3<T>,
        radius: T,
        _: T,
    ) -> Option<(T, T)> {
        let whole = Some((-self.bound, self.bound));
        let (along_s, along_t, origin) = self.grid_axes();
        let d = water.project(center).coords.map(T::to_f64) - origin;
        let r = radius.to_f64().abs();
        let columns = self.nodes_within(d.dot(&along_s), r * along_s.norm(), self.columns)?;
        let rows = self.nodes_within(d.dot(&along_t), r * along_t.norm(), self.rows)?;
        if columns.1 * rows.1 > 4096 {
            return whole;
        }
        let (mut low, mut high) = (
            T::from_f64_lossy(f64::INFINITY),
            -T::from_f64_lossy(f64::INFINITY),
        );
        for j in 0..rows.1 {
            let row = (rows.0 + j) % self.rows * self.columns;
            for i in 0..columns.1 {
                let h = self.heights[row + (columns.0 + i) % self.columns];
                low = low.min(h);
                high = high.max(h);
            }
        }
        Some((low, high))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec;

    fn grid(periodic: bool) -> HeightGrid<f64> {
        // 3 × 2 nodes, 2 m along x, 1 m along z: heights 0, 1, 2 on the first row, 3, 4, 5 on
        // the second: η = x/2 + 3z inside.
        let heights = vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
        HeightGrid::new(
            heights,
            3,
            2,
            Point3::origin(),
            Vector3::x() * 2.0,
            Vector3::z(),
            periodic,
        )
        .unwrap()
    }

    fn eta(g: &HeightGrid<f64>, x: f64, z: f64) -> f64 {
        let mut e = [0.0];
        g.elevations(&Water::default(), &[Point3::new(x, 0.0, z)], 0.0, &mut e)
            .unwrap();
        e[0]
    }

    #[test]
    fn bilinear_inside_clamped_outside() {
        let g = grid(false);
        for (x, z) in [(0.0, 0.0), (1.0, 0.5), (3.9, 0.25), (4.0, 1.0)] {
            assert!(
                (eta(&g, x, z) - (x / 2.0 + 3.0 * z)).abs() < 1e-14,
                "{x} {z}"
            );
        }
        assert!((eta(&g, -5.0, 0.0) - 0.0).abs() < 1e-15);
        assert!((eta(&g, 10.0, 7.0) - 5.0).abs() < 1e-15);
    }

    #[test]
    fn periodic_grids_repeat() {
        let g = grid(true);
        for (x, z) in [(0.3, 0.2), (5.1, 0.7), (-1.0, 0.4)] {
            let shifted = eta(&g, x + 6.0 * 3.0, z - 2.0 * 5.0);
            assert!((eta(&g, x, z) - shifted).abs() < 1e-12, "{x} {z}");
        }
        // Between the last column and the first: halfway from 2 back to 0.
        assert!((eta(&g, 5.0, 0.0) - 1.0).abs() < 1e-14);
    }

    #[test]
    fn heights_are_replaced_in_place() {
        let mut g = grid(false);
        let before = g.heights().as_ptr();
        g.set_heights(&[1.0; 6]).unwrap();
        assert_eq!(before, g.heights().as_ptr());
        assert!((eta(&g, 1.3, 0.4) - 1.0).abs() < 1e-15);
        assert!(g.set_heights(&[1.0; 5]).is_err());
        assert!(g.set_heights(&[f64::NAN; 6]).is_err());
        assert!((eta(&g, 1.3, 0.4) - 1.0).abs() < 1e-15);
    }

    /// The range over a disc holds every elevation sampled in it, on periodic and clamped
    /// grids, across the wrap and beyond the edges; a small disc on a smooth field gets a thin
    /// range, a disc wider than the grid its whole range.
    #[test]
    fn elevation_range_holds_the_disc() {
        let n = 48;
        let heights: Vec<f64> = (0..n * n)
            .map(|k| {
                // Smooth across the wrap too.
                let t = 2.0 * core::f64::consts::PI / n as f64;
                let (i, j) = ((k % n) as f64, (k / n) as f64);
                0.3 * (t * i).sin() + 0.2 * (t * (j + i)).cos()
            })
            .collect();
        let water = Water::<f64>::default();
        for periodic in [true, false] {
            let g = HeightGrid::new(
                heights.clone(),
                n,
                n,
                Point3::new(-3.0, 0.0, -2.0),
                Vector3::new(0.25, 0.0, 0.05),
                Vector3::new(-0.03, 0.0, 0.2),
                periodic,
            )
            .unwrap();
            for k in 0..40 {
                let center = Point3::new(-9.0 + 0.61 * k as f64, 0.4, -7.0 + 0.47 * k as f64);
                let radius = [0.0, 0.1, 0.7, 2.5][k % 4];
                let (low, high) = g.elevation_range(&water, &center, radius, 0.0).unwrap();
                let points: Vec<Point3<f64>> = (0..800)
                    .map(|j| {
                        let (r, a) = (radius * ((j % 20) as f64 / 19.0), j as f64 * 0.77);
                        Point3::new(center.x + r * a.cos(), 0.0, center.z + r * a.sin())
                    })
                    .collect();
                let mut eta = vec![0.0; points.len()];
                g.elevations(&water, &points, 0.0, &mut eta).unwrap();
                for e in &eta {
                    assert!(low <= *e && *e <= high, "{periodic} {k}: {low} {e} {high}");
                }
                if radius <= 0.1 {
                    assert!(high - low < 0.2, "{periodic} {k}: {low} {high}");
                }
            }
            let everything = g
                .elevation_range(&water, &Point3::origin(), 100.0, 0.0)
                .unwrap();
            assert_eq!(everything, (-g.bound, g.bound));
        }
    }
}
