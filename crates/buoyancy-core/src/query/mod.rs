//! What the water does to a body: the buoyancy query, its methods and its result.
//!
//! * [`Mesh::buoyancy`](crate::Mesh::buoyancy) (in `buoyancy`): the one entry point, for a mesh
//!   at a pose in a [`Sea`] (a [`Water`] for still water), computed as a [`Query`] (or a
//!   [`Method`]) says. Under a moving surface the hydrostatic pressure of the waves (`waves`) or
//!   the linear Froude–Krylov pressure of Airy seas (`froude_krylov`), [`Pressure`].
//! * [`Method`]: the paper's five methods. The volume methods, Fast, Improved and Exact
//!   (`volume`), and the surface methods, Fast Surface and Exact Surface (`surface_integral`,
//!   with the closed-form moments of the hierarchy's nodes in its `moments`).
//! * [`Traversal`]: a scan of every triangle, or the hierarchy whose cost follows the
//!   waterline.
//! * [`Buoyancy`]: the result, world frame.
//!
//! Inside, every evaluation brings the water plane into the mesh frame (`frame`), classifies and
//! cuts the triangles at the waterline (`clip`), and sums per-triangle terms deterministically
//! (`reduction`).
//!
//! # Waves: the hydrostatic pressure
//! Buoyancy under a moving, non-planar free surface: the hydrostatic pressure of the waves
//! integrated exactly over the wetted surface.
//!
//! ## The model
//! With `η` the elevation of the free surface above the still plane (see [`water`](crate::water)),
//! a vertex `x` lies `h = n·x − level − η(q)` above the surface, `q` its horizontal position.
//! Over each triangle `h` is taken linear between its vertices (the surface is sampled at the
//! vertices, once per vertex per evaluation), the triangle is cut exactly where `h = 0` (both
//! triangles of an edge cut it at the same point: no gaps, no overlaps), and the hydrostatic
//! pressure `p = −ρ·g·h ≥ 0` is integrated in closed form over the part under water, force and
//! moment, as [`Method::ExactSurface`] does under still water:
//!
//! ```text
//! F = −∫ p n̂ dA,    τ = −∫ (r − c) × p n̂ dA   over the wetted surface.
//! ```
//!
//! The horizontal forces from the wave slope are part of it. For the calm surface the result is
//! `ExactSurface`'s.
//!
//! ## The walk
//! With `[low, high]` bounds on `η` over the horizontal disc of the mesh's bounding radius
//! about its centroid ([`WaterSurface::elevation_range`]; `±b` from
//! [`WaterSurface::elevation_bound`] by default), the free surface lies in the layer between
//! them, of middle `m = (low + high)/2` and half thickness `b = (high − low)/2`, and the
//! hierarchy is walked against that layer: a node more than `b` above its middle is dry and
//! skipped; a leaf within reach of the layer has its triangles cut and integrated one by one;
//! a node more than `b` below is under water all over, and is summed without visiting its
//! triangles' corners. For waves long against the body the layer is thin wherever it lies.
//!
//! Every sum of a triangle is linear in its vertex heights but one (see `vertex_terms`): per
//! vertex, twelve coefficients summed over the triangles around it give the linear part of
//! every triangle around a *wet* vertex (below the free surface) in one multiply-add each. The
//! triangles under water all over, in the submerged nodes or in the crossed leaves, then add
//! only their quadratic term, three heights each; the triangles the surface cuts are
//! integrated whole and take their shares back out of their wet corners' sums. The surface is
//! evaluated at every vertex that may be wet: with the pressure `ρg(η − z)` at every depth,
//! every wet vertex's `η` counts.
//!
//! The result is a [`Buoyancy`]: `submerged_volume` is the volume implied by the vertical force,
//! `n·F/(ρ·g)`; `center_of_buoyancy` is a point of the force's line of action (the central axis
//! of the force and torque): the one nearest the still-water center of buoyancy formula applied
//! to the wetted surface, which under still water lies on that line already. `wetted_area` is
//! the area of the wetted pieces, exact: the cut triangles' shares of their area, the whole
//! triangles' areas, and the submerged nodes' stored sums.
//!
//! # Waves: the Froude–Krylov pressure
//! Linear Froude–Krylov pressure under Airy and spectral seas: the pressure of the undisturbed
//! wave, whose wave part decays with depth, integrated over the wetted surface by quadrature.
//!
//! ## The model
//! At a point `z` above the still plane (horizontal position `q`), in units of `ρ·g`,
//!
//! ```text
//! p = −z + Σ aᵢ·P(z)·cos θᵢ,   P(z) = cosh k(z+h)/cosh kh   (e^{kz} in deep water),
//! ```
//!
//! `θᵢ = kᵢ·q − ωᵢ·t + φᵢ`. Above the still plane (in a crest) `P = 1`: the pressure is the
//! hydrostatic one below the local surface (a linear extrapolation of the wave part, no
//! stretching). The pressure is never negative: it is clipped at zero.
//!
//! The wetted surface is the hydrostatic one (each triangle cut where the depth below the
//! surface, interpolated from its vertices, is zero; see `wave_pressure`). Each wetted piece that
//! straddles the still plane is cut along it into three triangles (the two cut points shared by
//! both sides, so that they cover the piece exactly): under a crest the wave part's vertical
//! derivative jumps there, from `a·P′(0)·cos θ` below to zero above, and the cut leaves the
//! pressure smooth over every part. The pressure is integrated over each part by the degree-5,
//! 7-point rule of Dunavant, exact for polynomials of degree 5 over a part.
//!
//! ## Quadrature error
//! Measured against a reference that integrates the same wetted pieces with the same pressure
//! on `4² = 16` congruent sub-triangles each, refined up to 6 times more (to `1/256` of the
//! piece) where the pressure is clipped to zero over part of a sub-triangle, each final
//! sub-triangle that straddles the still plane (or the bottom) cut along it by the waterline's
//! clipping rather than by the production cut, the same rule on each part; so the two differ
//! only by quadrature, and the cut (the waterline interpolated between vertices) and the
//! faceting are not part of this error. Over 240 random poses (the body cut by the surface or
//! submerged, holding at least 5 % of its volume's weight) of a UV sphere (radius 0.5 m, 32×16),
//! a torus (0.6/0.25 m, 32×12) and a unit cube (`n = 4`) in five Airy seas (a long swell, `a`
//! 0.5 m, `λ` 25 m; a moderate sea over 3 m of water, 0.2 m at 4 m and 0.1 m at 6 m; a short
//! steep wave, 0.06 m at 1 m, `k·a` 0.38; a shallow sea, 0.12 m at 2.5 m over 1.2 m of water;
//! five components from 0.15 m at 8 m to 0.025 m at 1.1 m in deep water, spread in direction),
//! the error in force relative to `|F|` and in torque relative to `|F|·R` (`R` the mesh's
//! bounding radius) are, with the bounds the test asserts:
//!
//! ```text
//! sea                   k·L         force: worst  median     torque: worst  median    bounds
//! long, deep            0.03–0.09   6.4e-14       ≤ 1.3e-14  1.8e-12        ≤ 5.4e-13 5e-13, 1e-11
//! moderate, depth 3 m   0.22–0.56   3.2e-7        ≤ 2.4e-9   2.0e-7         ≤ 2.6e-9  2e-6, 1e-6
//! short steep, deep     0.87–2.22   2.4e-5        ≤ 7.6e-7   8.8e-6         ≤ 3.4e-7  1e-4, 5e-5
//! shallow, depth 1.2 m  0.35–0.89   3.8e-7        ≤ 4.6e-9   2.4e-7         ≤ 9.0e-9  2e-6, 1e-6
//! 5 components, deep    0.79–2.02   4.6e-5        ≤ 6.6e-6   1.7e-5         ≤ 1.5e-6  2e-4, 1e-4
//! ```
//!
//! (`k` the largest wavenumber, `L` the mesh's longest edge; the medians are the largest of the
//! three meshes'.) The one-point (centroid) rule, with the same cut, fails every sea's bounds,
//! by 7 times at least; the rule on the uncut pieces fails those of the long, moderate and
//! shallow seas (1.2e-5, 1.1e-4 and 1.2e-4 in force), not those of the other two, whose
//! figures are not the still plane's (below). The reference moves by 3.3 % of the bounds at
//! most from one level less everywhere (4 sub-triangles a piece, refined 5 times). The
//! per-mesh table is printed by
//!
//! ```text
//! cargo test -p buoyancy-core --lib froude_krylov -- --nocapture
//! ```
//!
//! What the error depends on:
//! * Where the pressure is smooth over a part, the rule's error is of order `(k·L)⁶` relative to
//!   the wave part, `L` the size of the part: measured once with `P` made smooth across the
//!   still plane (`e^{kz}` above it too) and the pieces uncut, 1e-9 to 2e-7 on these meshes,
//!   falling by about 2⁷ when `L` halves. The long swell, which neither kink below reaches,
//!   shows it alone: 6e-14 in force, 2e-12 in torque.
//! * The kink at the still plane is cut out. Without the cut (the rule on the whole pieces) it
//!   dominated every sea's figures: on a piece that straddles the still plane under a crest the
//!   pressure is only continuous, and the rule's error on it is of order `k·a·L` times its area
//!   instead of `(k·L)⁶`; summed over the pieces along the waterline, it grows with the slope
//!   `k·a` and is of second order in `L` (halving `L` divided it by about 5): worst 1.2e-5
//!   (long swell) to 1.2e-4 in force, 1.2e-5 to 4.5e-5 in torque, over the same poses.
//! * What remains above the `(k·L)⁶` level comes from two kinks that no planar cut follows.
//!   The clip at zero pressure: in a trough, the waterline interpolated between vertices runs
//!   above the surface where the pressure reaches zero, and over the sliver between them the
//!   pressure is clipped, a kink along a curve inside the piece. It makes the worst figures of
//!   the moderate, short and 5-component seas, largest on the coarsest mesh, the cube: with
//!   it refined away as well (measured once), they fall from 3.2e-7, 2.4e-5 and 4.6e-5 to
//!   1.5e-8, 2.9e-6 and 7.3e-8. The bottom: in finite depth `P` is held at its bottom value
//!   below `z = −h`, a jump of its second derivative (`P′(−h) = 0`); the shallow sea's worst
//!   figure, 3.8e-7, is a pose of the cube reaching 0.15 m below the 1.2 m bottom (a cut along
//!   the bottom as well, measured once, leaves 6.6e-8).

#[allow(clippy::module_inception)]
mod buoyancy;
pub(crate) mod clip;
pub(crate) mod frame;
pub(crate) mod froude_krylov;
mod method;
mod options;
pub(crate) mod reduction;
pub(crate) mod result;
mod sea;
pub(crate) mod surface_integral;
mod traversal;
pub(crate) mod volume;
pub(crate) mod waves;

pub use method::Method;
pub use options::Query;
pub use result::Buoyancy;
pub use sea::{Pressure, Sea};
pub use traversal::Traversal;

#[cfg(doc)]
use crate::water::WaterSurface;
#[cfg(doc)]
use crate::{Mesh, Water};
