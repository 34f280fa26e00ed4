//! Evaluation of the five methods for a mesh at a pose in a body of water.
//!
//! # Frames
//! Per evaluation the water plane is brought into the mesh frame, not the mesh into the world:
//! with `R` the pose's rotation, `t` its translation, `c` the mesh centroid and `n` the world up
//! normal,
//!
//! * `n_l = Rᵀ n` is the up normal in the mesh frame,
//! * `w = R c + t` is the center of mass in the world frame,
//! * `h_c = n·w − level` is its height above the surface,
//!
//! and the height of a vertex `x` (stored as `v = x − c`) is `h = n_l·v + h_c`. The sums are
//! taken on `v` (about the centroid) or on `v + h_c n_l` (about `o = −h_c n_l`, the projection of
//! the centroid on the plane), both small numbers even when the body is 10⁶ m from the world
//! origin, and rotated to the world frame once at the end.
//!
//! # Cost
//! `Fast` sums precomputed tetrahedra (centroid to triangle) over the fully submerged
//! triangles. `Exact` adds to the same sums the clipped waterline triangles and the cap: the
//! part of the water plane inside the body, as a fan of tetrahedra from `o` over the waterline
//! segments (and over mesh edges lying exactly in the plane, where a submerged triangle meets a
//! dry one). So `Exact` costs `Fast` plus work on the waterline triangles only. `Improved` is
//! `Exact` about `o` minus the clipped parts, i.e. the tetrahedra from `o` to the fully
//! submerged triangles. The surface methods integrate the pressure triangle by triangle over the
//! fully submerged triangles and, for `ExactSurface`, over the clipped waterline triangles.
//!
//! With the hierarchy (the default from [`Traversal::CROSSOVER`] triangles) the fully
//! submerged triangles are mostly not visited at all: whole nodes under water add stored sums
//! (see `hierarchy` and `surface_moments`), and the cost follows the waterline.
//!
//! # Determinism
//! The scan sums the triangles in fixed chunks of [`CHUNK`] combined pairwise in a fixed tree;
//! the hierarchy sums its top subtrees apart and merges them up the tree (see `hierarchy`).
//! Either way the pieces are the same whether they run on one thread or on rayon's pool: the
//! serial and parallel results are bit-identical and the same input always gives the same
//! output.

use nalgebra::{Matrix3, Point3, UnitQuaternion, Vector3};

use crate::hierarchy::Visit;
use crate::integrals::{Counts, Split, Sums, SurfaceSums, VolumeSums, split};
use crate::parallel::join;
use crate::surface_moments::SurfaceMoments;
use crate::{Error, Mesh, Method, Pose, Real, Water};

/// Number of triangles summed sequentially before the pairwise combination.
pub(crate) const CHUNK: usize = 4096;

/// The buoyancy of a body: force, its point of application and its torque, world frame, SI units.
///
/// For the volume methods ([`Fast`](Method::Fast), [`Improved`](Method::Improved),
/// [`Exact`](Method::Exact)) `submerged_volume` and `center_of_buoyancy` are the volume and
/// centroid of the part found under water, the force is `ρ·g·V·n` and it acts at the center of
/// buoyancy. For the surface methods ([`FastSurface`](Method::FastSurface),
/// [`ExactSurface`](Method::ExactSurface)) the force and torque are the integrals of the pressure
/// over the wetted triangles; `submerged_volume` is the volume implied by the force,
/// `n·F / (ρ·g)`, and `center_of_buoyancy` the centroid implied by the pressure moments,
/// `∫ h r (n·dA) − (n/2)∫ h² (n·dA)` divided by that volume. For a closed mesh under a flat plane
/// the exact methods agree on all of it.
///
/// When (almost) nothing is under water, that is when `|submerged_volume|` is below round-off
/// relative to the mesh's own volume, `center_of_buoyancy` is the projection of the center of
/// mass onto the water plane: the point where buoyancy starts to act as the body enters the
/// water. Volume, force and torque are then as computed (zero, or round-off), never NaN.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Buoyancy<T: Real> {
    /// Volume under water, m³ (may be negative for the approximate methods on non-convex
    /// meshes, whose missing contributions are not sign-definite).
    pub submerged_volume: T,
    /// Point of application of the force, world frame, m.
    pub center_of_buoyancy: Point3<T>,
    /// Buoyant force, world frame, N.
    pub force: Vector3<T>,
    /// Torque of the buoyant force about [`torque_point`](Self::torque_point), world frame, N·m.
    pub torque: Vector3<T>,
    /// The point the torque is taken about: the body's center of mass (the mesh centroid under
    /// the pose), world frame, m. Use [`torque_about`](Self::torque_about) for another point.
    pub torque_point: Point3<T>,
    /// Number of triangles entirely under water (a triangle lying in the surface counts).
    pub fully_submerged: usize,
    /// Number of triangles the surface cuts (some vertex above, some below).
    pub partially_submerged: usize,
}

impl<T: Real> Buoyancy<T> {
    /// The torque of the same force system about another world point `q`:
    /// `τ_q = τ + (torque_point − q) × F`. Exact for any force system, not only a single force.
    pub fn torque_about(&self, q: &Point3<T>) -> Vector3<T> {
        self.torque + (self.torque_point - q).cross(&self.force)
    }

    /// This result with its torque taken about the world point `q` instead.
    pub fn about(mut self, q: &Point3<T>) -> Self {
        self.torque = self.torque_about(q);
        self.torque_point = *q;
        self
    }

    fn is_finite(&self) -> bool {
        self.submerged_volume.is_finite()
            && self.center_of_buoyancy.iter().all(|c| c.is_finite())
            && self.force.iter().all(|c| c.is_finite())
            && self.torque.iter().all(|c| c.is_finite())
    }
}

/// How an evaluation visits the triangles. Every traversal gives the same result up to the
/// order of summation.
///
/// * `Scan` examines every triangle once: cost proportional to the mesh.
/// * `Hierarchy` walks the mesh's bounding-volume hierarchy and opens only the nodes the water
///   surface crosses, adding the precomputed sums of the nodes entirely under water: cost
///   proportional to the waterline (the triangles the surface cuts) times the depth of the
///   hierarchy, independent of the mesh size when the waterline is not. The volume methods
///   store six-fold volumes and moments per node, the surface methods the coefficients of
///   their pressure integrals as polynomials in the water plane (see `surface_moments`).
/// * `Auto` (the default) takes the hierarchy on meshes of at least [`Traversal::CROSSOVER`]
///   triangles, and the scan otherwise.
///
/// `Mesh::par_buoyancy` (feature `rayon`) always scans, in parallel.
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
            .find(|t| crate::method::names_match(t.name(), s))
            .ok_or_else(|| Error::UnknownTraversal { name: s.into() })
    }
}

/// Sums a volume method accumulates: `VolumeSums`, or a pair whose first member takes the
/// hierarchy's stored sums.
trait VolumeLike<T: Real>: Sums {
    fn exact_mut(&mut self) -> &mut VolumeSums<T>;
}

impl<T: Real> VolumeLike<T> for VolumeSums<T> {
    fn exact_mut(&mut self) -> &mut VolumeSums<T> {
        self
    }
}

impl<T: Real> VolumeLike<T> for [VolumeSums<T>; 2] {
    fn exact_mut(&mut self) -> &mut VolumeSums<T> {
        &mut self[0]
    }
}

/// The water plane seen from the mesh frame, for one evaluation.
pub(crate) struct Frame<T: Real> {
    pub(crate) rotation: Matrix3<T>,
    /// World up normal.
    pub(crate) normal: Vector3<T>,
    /// Up normal in the mesh frame, `Rᵀ n`.
    pub(crate) normal_local: Vector3<T>,
    /// Center of mass, world frame.
    pub(crate) center_of_mass: Point3<T>,
    /// Height of the center of mass above the surface.
    pub(crate) height: T,
}

impl<T: Real> Frame<T> {
    pub(crate) fn new(mesh: &Mesh<T>, pose: &Pose<T>, water: &Water<T>) -> Result<Self, Error> {
        let q = pose.rotation.quaternion().coords;
        if !q.iter().all(|c| c.is_finite()) {
            return Err(Error::InvalidPose {
                reason: "the rotation has a NaN or infinite component",
            });
        }
        if !pose.translation.vector.iter().all(|c| c.is_finite()) {
            return Err(Error::InvalidPose {
                reason: "the translation has a NaN or infinite component",
            });
        }
        // Renormalised here, so a quaternion that drifted from unit length still gives a rotation.
        let unit = UnitQuaternion::try_new(pose.rotation.into_inner(), T::zero()).ok_or(
            Error::InvalidPose {
                reason: "the rotation quaternion is zero",
            },
        )?;
        let rotation = *unit.to_rotation_matrix().matrix();
        let normal = water.normal().into_inner();
        let center_of_mass =
            Point3::from(rotation * mesh.centroid.coords) + pose.translation.vector;
        Ok(Frame {
            rotation,
            normal,
            normal_local: rotation.transpose() * normal,
            center_of_mass,
            height: water.height(&center_of_mass),
        })
    }

    /// Heights above the surface of vertices given relative to the centroid, mesh frame.
    /// (Written out: `array::map` does not always optimise away in this hot loop.)
    #[inline(always)]
    pub(crate) fn heights(&self, v: &[Vector3<T>; 3]) -> [T; 3] {
        let n = &self.normal_local;
        [
            n.dot(&v[0]) + self.height,
            n.dot(&v[1]) + self.height,
            n.dot(&v[2]) + self.height,
        ]
    }

    /// The projection of the center of mass onto the surface, world frame.
    fn surface_point(&self) -> Point3<T> {
        self.center_of_mass - self.normal * self.height
    }
}

impl<T: Real> Mesh<T> {
    /// The buoyancy of this mesh placed by `pose` (mesh → world) in `water`, by `method`.
    /// The torque is about the body's center of mass; see [`Buoyancy::about`] for another point.
    ///
    /// Walks the mesh's hierarchy from [`Traversal::CROSSOVER`] triangles up, so the cost follows
    /// the waterline; below that, one pass over the triangles. No allocation.
    ///
    /// # Errors
    /// [`Error::InvalidPose`] if the pose has a NaN or infinite component or a zero quaternion
    /// (a non-unit quaternion is normalised); [`Error::NonFiniteResult`] if the pose or water
    /// is so large that the result overflows.
    pub fn buoyancy(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        method: Method,
    ) -> Result<Buoyancy<T>, Error> {
        self.evaluate(pose, water, method, Traversal::Auto, false)
    }

    /// [`Mesh::buoyancy`] with the work split across rayon's thread pool, bit-identical to it:
    /// the work is cut in pieces fixed by the mesh (chunks of triangles for the scan, subtrees
    /// for the hierarchy), never by the number of threads, and the pieces are merged in a fixed
    /// order.
    ///
    /// Only large meshes are split: the hierarchy's halves from 100,000 triangles (below that a
    /// walk costs tens of microseconds, about what waking a thread does), the scan's chunks of
    /// 4,096. On 2 threads the hierarchy of a 10⁶-triangle mesh runs about 1.3–1.5× faster
    /// (`cargo bench --bench rounds --features rayon -- large parallel hierarchy`): the waterline
    /// is rarely shared evenly between subtrees. For many bodies or poses, parallelise across
    /// them instead.
    #[cfg(feature = "rayon")]
    pub fn par_buoyancy(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        method: Method,
    ) -> Result<Buoyancy<T>, Error> {
        self.evaluate(pose, water, method, Traversal::Auto, true)
    }

    /// [`Mesh::par_buoyancy`] with the traversal chosen explicitly, bit-identical to
    /// [`Mesh::buoyancy_with`] with the same traversal.
    #[cfg(feature = "rayon")]
    pub fn par_buoyancy_with(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        method: Method,
        traversal: Traversal,
    ) -> Result<Buoyancy<T>, Error> {
        self.evaluate(pose, water, method, traversal, true)
    }

    /// [`Mesh::buoyancy`] with the traversal chosen explicitly; see [`Traversal`]. Every
    /// traversal gives the same result up to the order of summation (round-off).
    pub fn buoyancy_with(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        method: Method,
        traversal: Traversal,
    ) -> Result<Buoyancy<T>, Error> {
        self.evaluate(pose, water, method, traversal, false)
    }

    fn evaluate(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        method: Method,
        traversal: Traversal,
        parallel: bool,
    ) -> Result<Buoyancy<T>, Error> {
        let frame = Frame::new(self, pose, water)?;
        let n = frame.normal_local;
        let hierarchy = match traversal {
            Traversal::Auto => self.triangles.len() >= Traversal::CROSSOVER,
            Traversal::Scan => false,
            Traversal::Hierarchy => true,
        };
        let result = match method {
            Method::Fast => {
                let sums =
                    self.volume_sums(&frame, hierarchy, parallel, |s: &mut VolumeSums<T>, i| {
                        self.fast_triangle(&frame, s, i)
                    });
                // Moments about the centroid.
                self.volume_result(&frame, water, sums, Vector3::zeros())
            }
            Method::Improved | Method::Exact => {
                // Sums about the centroid: the fully submerged triangles contribute the
                // precomputed tetrahedra of `Fast`, the waterline triangles their clipped part,
                // and the cap closing the submerged volume on the water plane a fan of
                // tetrahedra from `apex`, the projection of the centroid on the plane, over the
                // waterline segments. Only the waterline costs more than `Fast`.
                let apex = n * -frame.height;
                let improved = method == Method::Improved;
                let [exact, clipped] = self.volume_sums(
                    &frame,
                    hierarchy,
                    parallel,
                    |s: &mut [VolumeSums<T>; 2], i| {
                        self.exact_triangle(&frame, &apex, improved, s, i)
                    },
                );
                if improved {
                    // Improved = tetrahedra from `apex` over the fully submerged triangles
                    // = the exact volume about `apex` minus the clipped parts about `apex`.
                    let volume6 = exact.volume6 - clipped.volume6;
                    // First moment about apex: Σ det·(a+b+c − 4·apex) = moment24 − 4·apex·volume6.
                    let moment24 = exact.moment24
                        - apex * (T::from_f64_lossy(4.0) * exact.volume6)
                        - clipped.moment24;
                    let sums = VolumeSums {
                        volume6,
                        moment24,
                        counts: exact.counts,
                    };
                    self.volume_result(&frame, water, sums, apex)
                } else {
                    self.volume_result(&frame, water, exact, Vector3::zeros())
                }
            }
            Method::FastSurface | Method::ExactSurface => {
                let exact = method == Method::ExactSurface;
                // Positions relative to the centroid.
                let triangle = |s: &mut SurfaceSums<T>, i: usize| {
                    let v = self.corners(i);
                    let h = frame.heights(&v);
                    match classify(&h) {
                        Side::Below => {
                            s.add_triangle(&n, v, h);
                            s.counts.full += 1;
                        }
                        Side::Crossing => {
                            s.counts.partial += 1;
                            if exact {
                                // The corner at the odd vertex, or the whole triangle minus it.
                                let Split {
                                    odd_is_below,
                                    a,
                                    ab,
                                    ca,
                                    heights,
                                    ..
                                } = split(v, h);
                                if odd_is_below {
                                    s.add_corner(&n, [a, ab, ca], heights[0], T::one());
                                } else {
                                    s.add_triangle(&n, v, h);
                                    s.add_corner(&n, [a, ab, ca], heights[0], -T::one());
                                }
                            }
                        }
                        Side::Above => {}
                    }
                };
                let sums = if hierarchy {
                    self.surface_walk(&frame, parallel, triangle)
                } else {
                    reduce(self.triangles.len(), parallel, &triangle)
                };
                self.surface_result(&frame, water, sums)
            }
        };
        if result.is_finite() {
            Ok(result)
        } else {
            Err(Error::NonFiniteResult)
        }
    }

    /// The corners of triangle `i` (in leaf order), relative to the centroid, mesh frame.
    #[inline(always)]
    pub(crate) fn corners(&self, i: usize) -> [Vector3<T>; 3] {
        let [a, b, c] = self.leaf_triangles[i];
        [
            self.vertices[a as usize],
            self.vertices[b as usize],
            self.vertices[c as usize],
        ]
    }

    /// Sums `triangle` over the triangles: over all of them (the scan, in parallel chunks when
    /// `parallel`), or over the leaves of the hierarchy the surface crosses, adding the stored
    /// sums of the nodes entirely under water.
    fn volume_sums<S: VolumeLike<T>>(
        &self,
        frame: &Frame<T>,
        hierarchy: bool,
        parallel: bool,
        triangle: impl Fn(&mut S, usize) + Sync,
    ) -> S {
        if !hierarchy {
            return reduce(self.triangles.len(), parallel, &triangle);
        }
        self.hierarchy.reduce(
            &frame.normal_local,
            frame.height,
            parallel,
            &|sums: &mut S, visit| match visit {
                Visit::Submerged(index, count) => {
                    let (s, node) = (sums.exact_mut(), &self.hierarchy.sums[index]);
                    s.volume6 += node.volume6;
                    s.moment24 += node.moment24;
                    s.counts.full += count as usize;
                }
                Visit::Triangles(triangles) => {
                    for i in triangles {
                        triangle(sums, i);
                    }
                }
            },
        )
    }

    /// The surface sums over the hierarchy: the triangles of the leaves the surface crosses go
    /// through `triangle`; the inner nodes entirely under water add their stored coefficients,
    /// evaluated once at the end (see [`crate::surface_moments`]), and the leaves entirely under
    /// water pass their few triangles through `triangle` too. In parallel as
    /// [`Hierarchy::reduce`](crate::hierarchy::Hierarchy::reduce) says.
    fn surface_walk(
        &self,
        frame: &Frame<T>,
        parallel: bool,
        triangle: impl Fn(&mut SurfaceSums<T>, usize) + Sync,
    ) -> SurfaceSums<T> {
        let n = &frame.normal_local;
        let WalkSums(mut sums, whole) = self.hierarchy.reduce(
            n,
            frame.height,
            parallel,
            &|walk: &mut WalkSums<T>, visit| {
                let WalkSums(sums, whole) = walk;
                let triangles = match visit {
                    Visit::Submerged(index, count) => match self.surface_moments.get(index) {
                        Some(moments) => {
                            whole.add(moments);
                            sums.counts.full += count as usize;
                            return;
                        }
                        // A leaf: no stored coefficients.
                        None => self.hierarchy.range(index),
                    },
                    Visit::Triangles(triangles) => triangles,
                };
                for i in triangles {
                    triangle(sums, i);
                }
            },
        );
        whole.add_to(n, frame.height, &mut sums);
        sums
    }

    /// `Fast`'s contribution of triangle `i`: its precomputed tetrahedron to the centroid if it
    /// is fully under water.
    #[inline(always)]
    fn fast_triangle(&self, frame: &Frame<T>, s: &mut VolumeSums<T>, i: usize) {
        match classify(&frame.heights(&self.corners(i))) {
            Side::Below => {
                s.volume6 += self.tetra_volume6[i];
                s.moment24 += self.tetra_moment24[i];
                s.counts.full += 1;
            }
            Side::Crossing => s.counts.partial += 1,
            Side::Above => {}
        }
    }

    /// `Exact`'s contribution of triangle `i`, about the centroid, in `sums[0]`; with
    /// `improved`, its clipped part about `apex` in `sums[1]` too.
    #[inline(always)]
    fn exact_triangle(
        &self,
        frame: &Frame<T>,
        apex: &Vector3<T>,
        improved: bool,
        [exact, clipped]: &mut [VolumeSums<T>; 2],
        i: usize,
    ) {
        let v = self.corners(i);
        let h = frame.heights(&v);
        match classify(&h) {
            Side::Below => {
                exact.volume6 += self.tetra_volume6[i];
                exact.moment24 += self.tetra_moment24[i];
                exact.counts.full += 1;
                // An edge lying in the surface bounds the cap too, unless the neighbour across
                // it is submerged and cancels it.
                let zero = T::zero();
                if h[0] == zero || h[1] == zero || h[2] == zero {
                    for k in 0..3 {
                        let j = (k + 1) % 3;
                        if h[k] == zero && h[j] == zero {
                            exact.add_tetrahedron([*apex, v[j], v[k]]);
                        }
                    }
                }
            }
            Side::Crossing => {
                exact.counts.partial += 1;
                // The submerged part and its share of the cap from one small tetrahedron at the
                // odd vertex: with `x = ab × ca`, the part (a, ab, ca) and the cap's triangle
                // (apex, ca, ab) give `det = a·x − apex·x`. When `a` is the one vertex above,
                // the submerged part is the whole triangle (its precomputed tetrahedron) minus
                // (a, ab, ca), and the cap's triangle is reversed: the same terms, negated.
                let Split {
                    odd_is_below,
                    a,
                    b,
                    c,
                    ab,
                    ca,
                    ..
                } = split(v, h);
                let x = ab.cross(&ca);
                let (part, cap) = (a.dot(&x), apex.dot(&x));
                let rim = ab + ca;
                let volume6 = part - cap;
                let moment24 = (a + rim) * part - (apex + rim) * cap;
                if odd_is_below {
                    exact.volume6 += volume6;
                    exact.moment24 += moment24;
                } else {
                    exact.volume6 += self.tetra_volume6[i] - volume6;
                    exact.moment24 += self.tetra_moment24[i] - moment24;
                }
                if improved {
                    // Improved leaves the submerged part out; remember it about `apex`:
                    // (a, ab, ca), or the whole triangle minus it.
                    let (a, b, c, ab, ca) = (a - apex, b - apex, c - apex, ab - apex, ca - apex);
                    let part = a.dot(&ab.cross(&ca));
                    let part_moment = (a + ab + ca) * part;
                    if odd_is_below {
                        clipped.volume6 += part;
                        clipped.moment24 += part_moment;
                    } else {
                        let whole = a.dot(&b.cross(&c));
                        clipped.volume6 += whole - part;
                        clipped.moment24 += (a + b + c) * whole - part_moment;
                    }
                }
            }
            Side::Above => {}
        }
    }

    /// Below this |volume|, the center of buoyancy is round-off and is replaced by the surface point.
    fn volume_tolerance(&self) -> T {
        self.volume_scale * T::default_epsilon() * T::from_f64_lossy(64.0)
    }

    /// Builds the result of a volume method from sums about `origin` (mesh frame, relative to
    /// the centroid).
    ///
    /// With `M` the first moment about `origin`, `C − w = R(origin + M/V)` and
    /// `τ = (C − w) × ρgV n = ρg R(origin×n_l·V + M × n_l)`; `origin` is either 0 or along
    /// `n_l`, so `τ = ρg R(M × n_l)`, with no division by V.
    fn volume_result(
        &self,
        frame: &Frame<T>,
        water: &Water<T>,
        sums: VolumeSums<T>,
        origin: Vector3<T>,
    ) -> Buoyancy<T> {
        let volume = sums.volume6 / T::from_f64_lossy(6.0);
        let moment = sums.moment24 / T::from_f64_lossy(24.0);
        let weight = water.specific_weight();
        let center_of_buoyancy = if volume.abs() > self.volume_tolerance() {
            frame.center_of_mass + frame.rotation * (origin + moment / volume)
        } else {
            frame.surface_point()
        };
        self.finish(
            frame,
            sums.counts,
            volume,
            center_of_buoyancy,
            frame.normal * (weight * volume),
            frame.rotation * moment.cross(&frame.normal_local) * weight,
        )
    }

    /// Builds the result of a surface method from sums about the centroid (mesh frame).
    fn surface_result(
        &self,
        frame: &Frame<T>,
        water: &Water<T>,
        sums: SurfaceSums<T>,
    ) -> Buoyancy<T> {
        let weight = water.specific_weight();
        let force = sums.force6 / T::from_f64_lossy(6.0);
        let volume = frame.normal_local.dot(&force);
        let center_of_buoyancy = if volume.abs() > self.volume_tolerance() {
            frame.center_of_mass
                + frame.rotation * (sums.moment24 / (T::from_f64_lossy(24.0) * volume))
        } else {
            frame.surface_point()
        };
        self.finish(
            frame,
            sums.counts,
            volume,
            center_of_buoyancy,
            frame.rotation * force * weight,
            frame.rotation * sums.torque24 * (weight / T::from_f64_lossy(24.0)),
        )
    }

    fn finish(
        &self,
        frame: &Frame<T>,
        counts: Counts,
        submerged_volume: T,
        center_of_buoyancy: Point3<T>,
        force: Vector3<T>,
        torque: Vector3<T>,
    ) -> Buoyancy<T> {
        Buoyancy {
            submerged_volume,
            center_of_buoyancy,
            force,
            torque,
            torque_point: frame.center_of_mass,
            fully_submerged: counts.full,
            partially_submerged: counts.partial,
        }
    }
}

/// The surface walk's running sums: the triangles integrated one by one, and the coefficients
/// of the nodes taken whole.
#[derive(Clone, Copy)]
struct WalkSums<T: Real>(SurfaceSums<T>, SurfaceMoments<T>);

impl<T: Real> Sums for WalkSums<T> {
    fn zero() -> Self {
        WalkSums(SurfaceSums::zero(), SurfaceMoments::zero())
    }

    fn merge(self, other: Self) -> Self {
        let WalkSums(sums, mut whole) = self;
        whole.add(&other.1);
        WalkSums(sums.merge(other.0), whole)
    }
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Side {
    /// Every vertex at or below the surface.
    Below,
    /// Some vertex strictly below, some strictly above.
    Crossing,
    /// No vertex strictly below.
    Above,
}

/// Where a triangle is, from its vertex heights. A triangle lying in the surface is `Below`
/// (it closes the submerged volume); one touching it from above is `Above`.
#[inline(always)]
fn classify<T: Real>(h: &[T; 3]) -> Side {
    let zero = T::zero();
    if h[0] <= zero && h[1] <= zero && h[2] <= zero {
        Side::Below
    } else if h[0] >= zero && h[1] >= zero && h[2] >= zero {
        Side::Above
    } else {
        Side::Crossing
    }
}

/// Sums `add(&mut sums, i)` over `i in 0..len`, in chunks of [`CHUNK`] combined in a fixed
/// pairwise tree, on rayon's pool when `parallel` (and the `rayon` feature) is on.
fn reduce<S: Sums, F: Fn(&mut S, usize) + Sync>(len: usize, parallel: bool, add: &F) -> S {
    fn range<S: Sums, F: Fn(&mut S, usize) + Sync>(
        lo: usize,
        hi: usize,
        parallel: bool,
        add: &F,
    ) -> S {
        if hi - lo <= CHUNK {
            let mut sums = S::zero();
            for i in lo..hi {
                add(&mut sums, i);
            }
            return sums;
        }
        let mid = lo + (hi - lo).div_ceil(CHUNK) / 2 * CHUNK;
        let (left, right) = join(
            parallel,
            || range(lo, mid, parallel, add),
            || range(mid, hi, parallel, add),
        );
        left.merge(right)
    }
    range(0, len, parallel, add)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape;
    use nalgebra::{Translation3, Vector3};

    fn at(x: f64, y: f64, z: f64) -> Pose<f64> {
        Pose::from_parts(Translation3::new(x, y, z), UnitQuaternion::identity())
    }

    #[test]
    fn half_submerged_cube_all_methods() {
        let (v, t) = shape::cube::<f64>(4).unwrap();
        let cube = Mesh::new(v, t).unwrap();
        let water = Water::default();
        for method in Method::ALL {
            let b = cube.buoyancy(&at(0.0, 0.0, 0.0), &water, method).unwrap();
            assert!(b.force.x.abs() < 1e-9 && b.force.z.abs() < 1e-9, "{method}");
            if method.is_exact() {
                assert!((b.submerged_volume - 0.5).abs() < 1e-14, "{method}: {b:?}");
                assert!((b.center_of_buoyancy - Point3::new(0.0, -0.25, 0.0)).norm() < 1e-14);
                assert!((b.force.y - 0.5 * 9810.0).abs() < 1e-9);
                assert!(b.torque.norm() < 1e-10, "{method}: {:?}", b.torque);
            }
        }
    }

    #[test]
    fn dry_body_has_no_force_and_a_finite_center() {
        let (v, t) = shape::cube::<f64>(2).unwrap();
        let cube = Mesh::new(v, t).unwrap();
        for method in Method::ALL {
            let b = cube
                .buoyancy(&at(1.0, 3.0, 2.0), &Water::default(), method)
                .unwrap();
            assert_eq!(b.submerged_volume, 0.0);
            assert_eq!(b.force, Vector3::zeros());
            assert_eq!(b.torque, Vector3::zeros());
            assert_eq!(b.center_of_buoyancy, Point3::new(1.0, 0.0, 2.0));
            assert_eq!((b.fully_submerged, b.partially_submerged), (0, 0));
        }
    }

    #[test]
    fn invalid_poses_are_errors() {
        let (v, t) = shape::cube::<f64>(1).unwrap();
        let cube = Mesh::new(v, t).unwrap();
        let w = Water::default();
        let e = cube
            .buoyancy(&at(f64::NAN, 0.0, 0.0), &w, Method::Exact)
            .unwrap_err();
        assert!(matches!(e, Error::InvalidPose { .. }), "{e}");
        let mut pose = at(0.0, 0.0, 0.0);
        pose.rotation =
            UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(0.0, 0.0, 0.0, 0.0));
        assert!(matches!(
            cube.buoyancy(&pose, &w, Method::Exact),
            Err(Error::InvalidPose { .. })
        ));
        pose.rotation =
            UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(f64::INFINITY, 0.0, 0.0, 0.0));
        assert!(matches!(
            cube.buoyancy(&pose, &w, Method::Exact),
            Err(Error::InvalidPose { .. })
        ));
        // A drifted quaternion is renormalised.
        pose.rotation =
            UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(2.0, 0.0, 0.0, 0.0));
        let b = cube.buoyancy(&pose, &w, Method::Exact).unwrap();
        assert!((b.submerged_volume - 0.5).abs() < 1e-14);
        // Overflow is reported, not returned as infinity.
        let huge = at(0.0, -1e300, 0.0);
        let big_water = Water::new(1e300, 1e10, Vector3::y(), 0.0).unwrap();
        assert_eq!(
            cube.buoyancy(&huge, &big_water, Method::Exact),
            Err(Error::NonFiniteResult)
        );
    }

    #[test]
    fn reduction_tree_is_fixed() {
        // Sums of indices through the pairwise tree equal the closed form, for lengths around
        // chunk boundaries.
        #[derive(Clone, Copy)]
        struct Count(u64);
        impl Sums for Count {
            fn zero() -> Self {
                Count(0)
            }
            fn merge(self, o: Self) -> Self {
                Count(self.0 + o.0)
            }
        }
        for len in [0, 1, CHUNK - 1, CHUNK, CHUNK + 1, 5 * CHUNK + 7] {
            let s = reduce(len, true, &|s: &mut Count, i| s.0 += i as u64);
            assert_eq!(s.0, (len as u64) * (len as u64).saturating_sub(1) / 2);
        }
    }
}
