//! The hydrostatic pressure of a moving free surface integrated over the wetted surface: see
//! [the guide](crate::query#waves-the-hydrostatic-pressure).

pub(crate) mod vertex_terms;

use alloc::vec::Vec;

use nalgebra::{Point3, Vector3};

use crate::mesh::hierarchy::Visit;
use crate::query::clip::{TriangleClass, classify};
use crate::query::frame::Frame;
use crate::query::reduction::Sums;
#[cfg(test)]
use crate::query::reduction::reduce;
use crate::query::surface_integral::SurfaceSums;
use crate::query::waves::vertex_terms::LinearSums;
use crate::water::WaterSurface;
use crate::{Buoyancy, Error, Mesh, Method, Pose, Real, Water};

impl<T: Real> Mesh<T> {
    /// The buoyancy under `surface` at `time` (s) by the hydrostatic pressure of the waves (see
    /// the [guide](crate::query#waves-the-hydrostatic-pressure)): the hierarchy walked against
    /// the layer the surface lies in, or with `scan` every vertex evaluated and every triangle
    /// integrated on its own; `parallel` splits the vertices in chunks of 16,384 and the
    /// hierarchy as the still-water query does.
    pub(crate) fn hydrostatic_in_waves(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        surface: &dyn WaterSurface<T>,
        time: T,
        scan: bool,
        parallel: bool,
    ) -> Result<Buoyancy<T>, Error> {
        let frame = Frame::new(self, pose, water)?;
        check_time(time)?;
        let layer = if scan {
            None
        } else {
            Layer::of(surface, water, &frame, self.bounding_radius, time)
        };
        if layer.is_some_and(|l| l.mid == T::zero() && l.reach == T::zero()) {
            let frame = frame.nearer_when_submerged(self);
            return self
                .surface(&frame, water, Method::ExactSurface, true, parallel)
                .checked();
        }
        // A body whose bounding sphere lies below the still plane gets its heights relative to
        // its centroid's level: far below the surface, `n·x − level − η` would keep the depth's
        // digits and lose the body's (a 1 m cube 10⁹ m down: its center of buoyancy 0.3 m off).
        let reference = if frame.height + self.bounding_radius < T::zero() {
            frame.height
        } else {
            T::zero()
        };
        let (mut heights, wet) =
            self.heights_in_waves(&frame, water, surface, time, layer, parallel, reference)?;
        if reference != T::zero() {
            if heights.iter().all(|h| *h + reference < T::zero()) {
                return self.submerged_in_waves(&frame, water, &heights).checked();
            }
            for h in &mut heights {
                *h += reference;
            }
        }
        let n = frame.normal_local;
        let infinite = T::from_f64_lossy(f64::INFINITY);
        let walk = self.hierarchy.reduce_in_layer(
            &n,
            layer.map_or(frame.height, |l| frame.height - l.mid),
            layer.map_or(infinite, |l| l.reach),
            parallel,
            &|walk: &mut WaveWalk<T>, visit| match visit {
                Visit::SubmergedNode {
                    node,
                    triangle_count,
                } => {
                    let counts = &mut walk.triangles.counts;
                    counts.full += triangle_count as usize;
                    counts.wetted_area2 += self.node_sums.volume(node).double_area;
                    for i in self.hierarchy.range(node) {
                        walk.quadratic += self.quadratic_term(&n, i, &heights);
                    }
                }
                Visit::CrossedLeaf { triangles } => {
                    for i in triangles {
                        self.crossed_triangle(walk, &n, i, &heights);
                    }
                }
            },
        );
        let [force6, torque24, moment24] = walk.linear.merge(wet).surface_terms(&n);
        let mut sums = walk.triangles;
        sums.force6 += force6;
        sums.torque24 += torque24;
        sums.moment24 += moment24 - n * (walk.quadratic * T::from_f64_lossy(0.5));
        self.wave_result(&frame, water, sums).checked()
    }

    /// `(n·2A)·(Σhᵢ² + (Σhᵢ)²)` of leaf-order triangle `i`: the term of its `moment24` that is
    /// quadratic in the heights (see `vertex_terms`).
    #[inline(always)]
    fn quadratic_term(&self, n: &Vector3<T>, i: usize, heights: &[T]) -> T {
        let [a, b, c] = self.leaf_triangles[i];
        let h = [
            heights[a as usize],
            heights[b as usize],
            heights[c as usize],
        ];
        let sum = h[0] + h[1] + h[2];
        let q = h[0] * h[0] + h[1] * h[1] + h[2] * h[2] + sum * sum;
        let normal = &self.normals[i];
        q * n.dot(&normal.unit) * normal.double_area
    }

    /// Leaf-order triangle `i` of a leaf the layer of the waves crosses. Under water all over,
    /// its linear part is in the sums of its corners (all wet): only its quadratic term is
    /// added. Cut by the surface, its wetted part is integrated and its share taken out of the
    /// sums of its wet corners (which sum every triangle around them). Dry, it adds nothing
    /// (a corner of height zero adds nothing to the sums).
    #[inline(always)]
    fn crossed_triangle(&self, walk: &mut WaveWalk<T>, n: &Vector3<T>, i: usize, heights: &[T]) {
        let [a, b, c] = self.leaf_triangles[i];
        let h = [
            heights[a as usize],
            heights[b as usize],
            heights[c as usize],
        ];
        match classify(&h) {
            TriangleClass::Submerged => {
                walk.quadratic += self.quadratic_term(n, i, heights);
                walk.triangles.counts.full += 1;
                walk.triangles.counts.wetted_area2 += self.double_areas[i];
            }
            TriangleClass::Cut => {
                let v = self.corners(i);
                walk.triangles
                    .add_wetted_part(n, v, h, true, &self.double_areas[i]);
                let area2 = (v[1] - v[0]).cross(&(v[2] - v[0]));
                let sum = v[0] + v[1] + v[2];
                for k in 0..3 {
                    if h[k] < T::zero() {
                        walk.linear.remove_share(h[k], &v[k], &sum, &area2);
                    }
                }
            }
            TriangleClass::Dry => {}
        }
    }

    /// Every vertex under the surface (its height `reference + heights[v]` below zero): the
    /// whole surface is wet, and its sums are taken on the heights relative to `reference`. A
    /// constant added to the pressure changes neither the force nor the torque on a closed
    /// surface (`∮ n dA = 0`, `∮ r × n dA = 0`), nor the first moment of the submerged volume
    /// (the whole body's), so the result is the one of the absolute heights, without their
    /// round-off.
    fn submerged_in_waves(
        &self,
        frame: &Frame<T>,
        water: &Water<T>,
        relative: &[T],
    ) -> Buoyancy<T> {
        let n = frame.normal_local;
        let mut linear = LinearSums::zero();
        for (h, terms) in relative.iter().zip(&self.vertex_terms) {
            linear.add(*h, terms);
        }
        let mut quadratic = T::zero();
        let mut wetted_area2 = T::zero();
        for i in 0..self.leaf_triangles.len() {
            quadratic += self.quadratic_term(&n, i, relative);
            wetted_area2 += self.normals[i].double_area;
        }
        let [force6, torque24, moment24] = linear.surface_terms(&n);
        let mut sums = SurfaceSums::zero();
        sums.force6 = force6;
        sums.torque24 = torque24;
        sums.moment24 = moment24 - n * (quadratic * T::from_f64_lossy(0.5));
        sums.counts.full = self.leaf_triangles.len();
        sums.counts.wetted_area2 = wetted_area2;
        self.wave_result(frame, water, sums)
    }

    /// The heights of the vertices above the free surface less `reference` (see
    /// [`Mesh::heights_in_chunk`]), and the linear sums of the wet vertices, chunk by chunk (in
    /// parallel with `parallel`), merged in order.
    #[allow(clippy::too_many_arguments)]
    fn heights_in_waves(
        &self,
        frame: &Frame<T>,
        water: &Water<T>,
        surface: &dyn WaterSurface<T>,
        time: T,
        layer: Option<Layer<T>>,
        parallel: bool,
        reference: T,
    ) -> Result<(Vec<T>, LinearSums<T>), Error> {
        let mut heights = alloc::vec![T::zero(); self.vertices.len()];
        let chunk = |(k, out): (usize, &mut [T])| {
            let first = k * VERTEX_CHUNK;
            self.heights_in_chunk(first, out, frame, water, surface, time, layer, reference)
        };
        #[cfg(feature = "rayon")]
        let chunks: Vec<Result<LinearSums<T>, Error>> = if parallel {
            use rayon::prelude::*;
            heights
                .par_chunks_mut(VERTEX_CHUNK)
                .enumerate()
                .map(chunk)
                .collect()
        } else {
            heights
                .chunks_mut(VERTEX_CHUNK)
                .enumerate()
                .map(chunk)
                .collect()
        };
        #[cfg(not(feature = "rayon"))]
        let chunks: Vec<Result<LinearSums<T>, Error>> = {
            let _ = parallel;
            heights
                .chunks_mut(VERTEX_CHUNK)
                .enumerate()
                .map(chunk)
                .collect()
        };
        let mut wet = LinearSums::zero();
        for sums in chunks {
            wet = wet.merge(sums?);
        }
        Ok((heights, wet))
    }

    /// For the vertices from `first` on, one per entry of `heights`: their heights
    /// `n·x − level − η` above the free surface less `reference` (taken out before the sum, so
    /// that a body far below keeps its digits), and the linear sums (see `vertex_terms`) of the
    /// wet ones (below the surface) on the heights themselves. A vertex more than the `layer`'s
    /// reach plus the longest edge above its middle belongs to dry triangles only: it gets a
    /// positive height (its height above the layer) and the surface is not evaluated there.
    /// With no `layer` every vertex is evaluated.
    #[allow(clippy::too_many_arguments)]
    fn heights_in_chunk(
        &self,
        first: usize,
        heights: &mut [T],
        frame: &Frame<T>,
        water: &Water<T>,
        surface: &dyn WaterSurface<T>,
        time: T,
        layer: Option<Layer<T>>,
        reference: T,
    ) -> Result<LinearSums<T>, Error> {
        let n = &frame.normal_local;
        let relative_height = frame.height - reference;
        let vertices = &self.vertices[first..first + heights.len()];
        let count = heights.len();
        let (mut points, mut evaluated) = (Vec::with_capacity(count), Vec::with_capacity(count));
        // The heights above the layer's middle are taken as the walk takes them, `n·x + h_c'`.
        let layer = layer.map(|l| (l.reach + self.longest_edge, l.reach, frame.height - l.mid));
        // The vertex `v` (mesh frame) projected onto the still plane, world frame:
        // `c + R·v − n·(n_l·v + h_c) = (R − n·n_lᵀ)·v + (c − n·h_c)`.
        let onto_plane = frame.rotation - frame.normal * n.transpose();
        let origin = frame.center_of_mass - frame.normal * frame.height;
        for (j, (h, v)) in heights.iter_mut().zip(vertices).enumerate() {
            let local = n.dot(v);
            *h = local + relative_height;
            if let Some((dry_above, reach, layer_height)) = layer {
                let above_middle = local + layer_height;
                if above_middle > dry_above {
                    *h = above_middle - reach - reference;
                    continue;
                }
            }
            points.push(origin + onto_plane * v);
            evaluated.push(j as u32);
        }
        let mut elevations = alloc::vec![T::zero(); points.len()];
        surface.elevations(water, &points, time, &mut elevations)?;
        let mut sums = LinearSums::zero();
        for (&j, eta) in evaluated.iter().zip(&elevations) {
            if !eta.is_finite() {
                return Err(Error::InvalidSurface {
                    parameter: "surface",
                    reason: "the surface gave a NaN or infinite elevation",
                });
            }
            let h = &mut heights[j as usize];
            *h -= *eta;
            let height = *h + reference;
            if height < T::zero() {
                sums.add(height, &self.vertex_terms[first + j as usize]);
            }
        }
        Ok(sums)
    }

    /// The hydrostatic pressure under waves triangle by triangle, every vertex evaluated: the reference
    /// the walk is tested against.
    #[cfg(test)]
    pub(crate) fn buoyancy_in_waves_scan(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        surface: &dyn WaterSurface<T>,
        time: T,
    ) -> Result<Buoyancy<T>, Error> {
        let (frame, heights) = self.under_waves(pose, water, surface, time)?;
        let n = frame.normal_local;
        let triangle = |s: &mut SurfaceSums<T>, i: usize| {
            let [a, b, c] = self.leaf_triangles[i];
            let h = [
                heights[a as usize],
                heights[b as usize],
                heights[c as usize],
            ];
            s.add_wetted_part(&n, self.corners(i), h, true, &self.double_areas[i]);
        };
        let sums = reduce(self.triangles.len(), false, &triangle);
        self.wave_result(&frame, water, sums).checked()
    }

    /// The frame of the evaluation and the heights of the vertices above the free surface.
    ///
    /// # Errors
    /// As [`Mesh::buoyancy`] under waves.
    pub(crate) fn under_waves(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        surface: &dyn WaterSurface<T>,
        time: T,
    ) -> Result<(Frame<T>, Vec<T>), Error> {
        let frame = Frame::new(self, pose, water)?;
        check_time(time)?;
        let heights = self.heights_below_waves(&frame, water, surface, time)?;
        Ok((frame, heights))
    }

    /// The height of every stored vertex above the free surface, `n·x − level − η(q, time)`.
    /// With a bound `b` on `|η|`, a vertex higher than `b` plus the longest edge above the
    /// still plane belongs to dry triangles only: it gets `n·x − level − b > 0` and the surface
    /// is not evaluated there.
    fn heights_below_waves(
        &self,
        frame: &Frame<T>,
        water: &Water<T>,
        surface: &dyn WaterSurface<T>,
        time: T,
    ) -> Result<Vec<T>, Error> {
        let n = frame.normal_local;
        // Heights above the still plane.
        let mut heights: Vec<T> = self
            .vertices
            .iter()
            .map(|v| n.dot(v) + frame.height)
            .collect();
        let bound = surface_reach(surface);
        let reach = bound.map(|b| b + self.longest_edge);
        let wet = |h: &T| reach.is_none_or(|r| *h <= r);
        // The horizontal positions, world frame, of the vertices that may be wet.
        let points: Vec<Point3<T>> = self
            .vertices
            .iter()
            .zip(&heights)
            .filter(|(_, h)| wet(h))
            .map(|(v, h)| frame.center_of_mass + frame.rotation * v - frame.normal * *h)
            .collect();
        let mut elevations = alloc::vec![T::zero(); points.len()];
        surface.elevations(water, &points, time, &mut elevations)?;
        let mut eta = elevations.iter();
        for h in heights.iter_mut() {
            if wet(h) {
                let eta = *eta.next().unwrap_or(&T::zero());
                if !eta.is_finite() {
                    return Err(Error::InvalidSurface {
                        parameter: "surface",
                        reason: "the surface gave a NaN or infinite elevation",
                    });
                }
                *h -= eta;
            } else if let Some(b) = bound {
                *h -= b;
            }
        }
        Ok(heights)
    }

    /// The result from the surface sums about the centroid (mesh frame): the force and torque
    /// as `ExactSurface`'s, the center moved onto the force's line of action.
    fn wave_result(&self, frame: &Frame<T>, water: &Water<T>, sums: SurfaceSums<T>) -> Buoyancy<T> {
        let weight = water.specific_weight();
        let force_local = sums.force6 / T::from_f64_lossy(6.0);
        let volume = frame.normal_local.dot(&force_local);
        let force = frame.rotation * force_local * weight;
        let torque = frame.rotation * sums.torque24 * (weight / T::from_f64_lossy(24.0));
        let center_of_buoyancy = if volume.abs() > self.volume_tolerance() {
            let still_water_center = frame.center_of_mass
                + frame.rotation * (sums.moment24 / (T::from_f64_lossy(24.0) * volume));
            on_line_of_action(&frame.center_of_mass, &force, &torque, &still_water_center)
        } else {
            frame.surface_point()
        };
        self.finish(
            frame,
            sums.counts,
            volume,
            center_of_buoyancy,
            force,
            torque,
        )
    }
}

/// Vertices per chunk of the vertex pass under waves: the surface is evaluated
/// once per chunk, and a parallel query evaluates the chunks concurrently.
const VERTEX_CHUNK: usize = 16_384;

/// [`Error::InvalidSurface`] for a time that is not finite.
pub(crate) fn check_time<T: Real>(time: T) -> Result<(), Error> {
    if time.is_finite() {
        Ok(())
    } else {
        Err(Error::InvalidSurface {
            parameter: "time",
            reason: "the time must be finite (s)",
        })
    }
}

/// The layer the free surface lies in over a body: `η ∈ [mid − reach, mid + reach]` over the
/// horizontal disc of the body's bounding radius about its centroid.
#[derive(Clone, Copy, Debug)]
struct Layer<T: Real> {
    mid: T,
    reach: T,
}

impl<T: Real> Layer<T> {
    /// From the surface's [`elevation_range`](WaterSurface::elevation_range) over the disc of
    /// `radius` about the centroid of `frame` at `time` (when it gives a finite one), its
    /// half thickness widened by `64ε` of the larger end to cover the round-off of the
    /// surface's own sums: every evaluated elevation lies within it.
    fn of(
        surface: &dyn WaterSurface<T>,
        water: &Water<T>,
        frame: &Frame<T>,
        radius: T,
        time: T,
    ) -> Option<Self> {
        let (low, high) = surface.elevation_range(water, &frame.center_of_mass, radius, time)?;
        if !(low.is_finite() && high.is_finite() && low <= high) {
            return None;
        }
        let half = T::from_f64_lossy(0.5);
        let widen = low.abs().max(high.abs()) * T::default_epsilon() * T::from_f64_lossy(64.0);
        Some(Layer {
            mid: (low + high) * half,
            reach: (high - low) * half + widen,
        })
    }
}

/// The surface's bound on `|η|` (when it gives a finite one), widened by `64ε` of itself to
/// cover the round-off of the surface's own sums: every evaluated elevation lies within it.
fn surface_reach<T: Real>(surface: &dyn WaterSurface<T>) -> Option<T> {
    surface
        .elevation_bound()
        .filter(|b| b.is_finite() && *b >= T::zero())
        .map(|b| b + b * T::default_epsilon() * T::from_f64_lossy(64.0))
}

/// The walk's running sums under waves: the cut triangles of the crossed leaves integrated one
/// by one, the linear terms taken back from the wet vertices for them, and the quadratic term
/// of the triangles under water all over.
#[derive(Clone, Copy)]
struct WaveWalk<T: Real> {
    triangles: SurfaceSums<T>,
    linear: LinearSums<T>,
    /// `Σ (n·2A)·(Σhᵢ² + (Σhᵢ)²)` over the triangles of the submerged nodes.
    quadratic: T,
}

impl<T: Real> Sums for WaveWalk<T> {
    fn zero() -> Self {
        WaveWalk {
            triangles: SurfaceSums::zero(),
            linear: LinearSums::zero(),
            quadratic: T::zero(),
        }
    }

    fn merge(self, other: Self) -> Self {
        WaveWalk {
            triangles: self.triangles.merge(other.triangles),
            linear: self.linear.merge(other.linear),
            quadratic: self.quadratic + other.quadratic,
        }
    }
}

/// The point of the central axis of the force system (`force`, `torque` about `about`) nearest
/// to `near`: the axis passes through `about + force × torque / |force|²` along `force`.
pub(crate) fn on_line_of_action<T: Real>(
    about: &Point3<T>,
    force: &Vector3<T>,
    torque: &Vector3<T>,
    near: &Point3<T>,
) -> Point3<T> {
    let f2 = force.norm_squared();
    if f2 <= T::zero() || !f2.is_finite() {
        return *near;
    }
    let on_axis = about + force.cross(torque) / f2;
    on_axis + force * (force.dot(&(near - on_axis)) / f2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;
    use crate::query::{Query, Sea};
    use crate::water::{AiryComponent, AiryWaves, CalmSurface, HeightGrid, SurfaceFn};
    use nalgebra::{Point3, Translation3, UnitQuaternion};

    fn mesh(shape: Result<primitives::Shape<f64>, Error>) -> Mesh<f64> {
        let (vertices, triangles) = shape.unwrap();
        Mesh::new(vertices, triangles).unwrap()
    }

    /// A surface that is calm but says it may be 0.3 m off the still plane: the walk with
    /// deep vertices and crossed leaves, against the still-water answer.
    struct FlatWithBound;

    impl WaterSurface<f64> for FlatWithBound {
        fn elevations(
            &self,
            _: &Water<f64>,
            _: &[Point3<f64>],
            _: f64,
            elevations: &mut [f64],
        ) -> Result<(), Error> {
            elevations.fill(0.0);
            Ok(())
        }
        fn elevation_bound(&self) -> Option<f64> {
            Some(0.3)
        }
    }

    fn close(a: &Buoyancy<f64>, b: &Buoyancy<f64>, scale: f64) {
        let tol = 1e-11 * scale;
        assert!(
            (a.force - b.force).norm() < tol,
            "{:?} {:?}",
            a.force,
            b.force
        );
        assert!(
            (a.torque - b.torque).norm() < tol,
            "{:?} {:?}",
            a.torque,
            b.torque
        );
        assert!(
            (a.submerged_volume - b.submerged_volume).abs() < tol,
            "{} {}",
            a.submerged_volume,
            b.submerged_volume
        );
        assert!(
            (a.center_of_buoyancy - b.center_of_buoyancy).norm() < 1e-9,
            "{:?} {:?}",
            a.center_of_buoyancy,
            b.center_of_buoyancy
        );
        assert_eq!(
            (a.fully_submerged, a.partially_submerged),
            (b.fully_submerged, b.partially_submerged)
        );
        // Areas to 1e-12 of 1 m² plus the wetted area (these meshes have a few m²).
        assert!(
            (a.wetted_area - b.wetted_area).abs() < 1e-12 * (1.0 + a.wetted_area),
            "{} {}",
            a.wetted_area,
            b.wetted_area
        );
    }

    /// In `f32`, the layer over the body (its round-off margins in `f32`) still holds every
    /// wet vertex: the walk agrees with the scan to `f32` round-off, under a long swell far off
    /// the still plane and under a short sea, at poses across the waterline.
    #[test]
    fn walk_equals_scan_in_f32() {
        let (v, t) = primitives::torus::<f32>(1.0, 0.4, 48, 24).unwrap();
        let torus = Mesh::new(v, t).unwrap();
        let seas = [(0.5_f32, 40.0_f32), (0.08, 1.7)].map(|(amplitude, wavelength)| {
            AiryWaves::new(
                (0..3)
                    .map(|i| AiryComponent {
                        amplitude: amplitude / (1.0 + i as f32),
                        wavelength: wavelength * (1.0 + 0.3 * i as f32),
                        direction: Vector3::new((i as f32).cos(), 0.0, (i as f32).sin()),
                        phase: 0.5 * i as f32,
                    })
                    .collect(),
                None,
            )
            .unwrap()
        });
        let water = Water::<f32>::default();
        let scale = water.specific_weight() * torus.volume();
        for sea in &seas {
            for k in 0..12 {
                let angle = 0.37 * k as f32;
                let pose = Pose::from_parts(
                    Translation3::new(0.3 * angle.sin(), 0.9 - 0.15 * k as f32, 0.2),
                    UnitQuaternion::from_euler_angles(angle, 0.5 * angle, 0.2),
                );
                let time = 0.3 * angle;
                let walk = torus
                    .buoyancy(&pose, Sea::new(&water, sea, time), Method::ExactSurface)
                    .unwrap();
                let scan = torus
                    .buoyancy_in_waves_scan(&pose, &water, sea, time)
                    .unwrap();
                let tolerance = 2e-5 * scale;
                assert!(
                    (walk.force - scan.force).norm() < tolerance,
                    "{k}: {:?} {:?}",
                    walk.force,
                    scan.force
                );
                assert!(
                    (walk.torque - scan.torque).norm() < tolerance,
                    "{k}: {:?} {:?}",
                    walk.torque,
                    scan.torque
                );
            }
        }
    }

    #[test]
    fn walk_equals_scan_under_every_kind_of_surface() {
        let meshes = [
            mesh(primitives::torus(1.0, 0.4, 48, 24)),
            mesh(primitives::uv_sphere(0.8, 40, 20)),
            mesh(primitives::cube(6)),
        ];
        let airy = AiryWaves::new(
            (0..4)
                .map(|i| AiryComponent {
                    amplitude: 0.06,
                    wavelength: 1.5 + i as f64,
                    direction: Vector3::new((i as f64).cos(), 0.0, (i as f64).sin()),
                    phase: 0.4 * i as f64,
                })
                .collect(),
            None,
        )
        .unwrap();
        let grid = HeightGrid::new(
            (0..64 * 64)
                .map(|k| 0.1 * ((k % 64) as f64 * 0.3).sin() * ((k / 64) as f64 * 0.2).cos())
                .collect(),
            64,
            64,
            Point3::new(-4.0, 0.0, -4.0),
            Vector3::x() * 0.125,
            Vector3::z() * 0.125,
            true,
        )
        .unwrap();
        let unbounded = SurfaceFn(|q: &Point3<f64>, t: f64| 0.05 * (1.3 * q.x - t).cos());
        // Long and high against the bodies: a thin layer far off the still plane.
        let swell = AiryWaves::new(
            alloc::vec![
                AiryComponent {
                    amplitude: 0.5,
                    wavelength: 40.0,
                    direction: Vector3::x(),
                    phase: 0.0,
                },
                AiryComponent {
                    amplitude: 0.2,
                    wavelength: 25.0,
                    direction: Vector3::new(0.6, 0.0, 0.8),
                    phase: 1.0,
                },
            ],
            Some(30.0),
        )
        .unwrap();
        let surfaces: [&dyn WaterSurface<f64>; 5] =
            [&airy, &grid, &FlatWithBound, &unbounded, &swell];
        let water = Water::default();
        for mesh in &meshes {
            let mesh: &Mesh<f64> = mesh;
            for k in 0..12 {
                let angle = 0.37 * k as f64;
                let pose = Pose::from_parts(
                    Translation3::new(0.1 * angle.sin(), 0.9 - 0.15 * k as f64, 0.2),
                    UnitQuaternion::from_euler_angles(angle, 0.5 * angle, 0.2),
                );
                let scale = water.specific_weight() * mesh.volume();
                for surface in surfaces {
                    let walk = mesh.buoyancy(
                        &pose,
                        Sea::new(&water, surface, 0.3 * angle),
                        Method::ExactSurface,
                    );
                    let scan = mesh.buoyancy_in_waves_scan(&pose, &water, surface, 0.3 * angle);
                    close(&walk.unwrap(), &scan.unwrap(), scale);
                }
                let calm = mesh
                    .buoyancy(
                        &pose,
                        Sea::new(&water, &CalmSurface, 0.0),
                        Method::ExactSurface,
                    )
                    .unwrap();
                let flat = mesh
                    .buoyancy(
                        &pose,
                        Sea::new(&water, &FlatWithBound, 0.0),
                        Method::ExactSurface,
                    )
                    .unwrap();
                close(&calm, &flat, scale);
            }
        }
    }

    /// The wetted area of the walk: Exact Surface's in calm water, whether the walk takes the
    /// still-water path (a calm surface) or walks the layer of a surface that says it may be
    /// 0.3 m off (deep vertices, crossed leaves, submerged nodes adding their stored area);
    /// under waves, the scan's, triangle by triangle. And it is the area: between that of the
    /// fully submerged triangles and the mesh's.
    #[test]
    fn wetted_area_of_the_walk() {
        let sphere = mesh(primitives::uv_sphere(0.8, 40, 20));
        let airy = AiryWaves::new(
            alloc::vec![AiryComponent {
                amplitude: 0.15,
                wavelength: 2.5,
                direction: Vector3::new(0.6, 0.0, 0.8),
                phase: 0.2,
            }],
            None,
        )
        .unwrap();
        let water = Water::default();
        for k in 0..16 {
            let angle = 0.41 * k as f64;
            let pose = Pose::from_parts(
                Translation3::new(0.2, 1.0 - 0.13 * k as f64, -0.1),
                UnitQuaternion::from_euler_angles(angle, 0.3, 0.5 * angle),
            );
            let exact = sphere
                .buoyancy(&pose, &water, Method::ExactSurface)
                .unwrap();
            let fast = sphere.buoyancy(&pose, &water, Method::FastSurface).unwrap();
            for surface in [&CalmSurface as &dyn WaterSurface<f64>, &FlatWithBound] {
                let calm = sphere
                    .buoyancy(&pose, Sea::new(&water, surface, 0.0), Method::ExactSurface)
                    .unwrap();
                let tol = 1e-12 * sphere.surface_area();
                assert!(
                    (calm.wetted_area - exact.wetted_area).abs() < tol,
                    "{k}: {} vs {}",
                    calm.wetted_area,
                    exact.wetted_area
                );
            }
            assert!(fast.wetted_area <= exact.wetted_area);
            assert!(exact.wetted_area <= sphere.surface_area() * (1.0 + 1e-12));
            let time = 0.3 * k as f64;
            let walk = sphere
                .buoyancy(&pose, Sea::new(&water, &airy, time), Method::ExactSurface)
                .unwrap();
            let scan = sphere
                .buoyancy_in_waves_scan(&pose, &water, &airy, time)
                .unwrap();
            let tol = 1e-12 * sphere.surface_area();
            assert!(
                (walk.wetted_area - scan.wetted_area).abs() < tol,
                "{k}: {} vs {}",
                walk.wetted_area,
                scan.wetted_area
            );
            assert!(walk.wetted_area <= sphere.surface_area() * (1.0 + 1e-12));
        }
    }

    #[cfg(feature = "rayon")]
    #[test]
    fn parallel_walk_is_bit_identical() {
        use alloc::vec;
        use alloc::vec::Vec;
        let mesh = mesh(primitives::torus(1.0, 0.4, 400, 60));
        let airy = AiryWaves::new(
            vec![AiryComponent {
                amplitude: 0.1,
                wavelength: 2.0,
                direction: Vector3::x(),
                phase: 0.0,
            }],
            None,
        )
        .unwrap();
        let water = Water::default();
        let poses: Vec<Pose<f64>> = (0..5)
            .map(|k| {
                Pose::from_parts(
                    Translation3::new(0.0, 0.3 - 0.15 * k as f64, 0.0),
                    UnitQuaternion::from_euler_angles(0.3 * k as f64, 0.2, 0.1),
                )
            })
            .collect();
        for pose in &poses {
            let serial = mesh
                .buoyancy(pose, Sea::new(&water, &airy, 1.0), Method::ExactSurface)
                .unwrap();
            let parallel = mesh
                .buoyancy(
                    pose,
                    Sea::new(&water, &airy, 1.0),
                    Query::new(Method::ExactSurface).in_parallel(),
                )
                .unwrap();
            assert_eq!(serial, parallel);
        }
    }
}
