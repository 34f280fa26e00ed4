//! Hydrostatics at any pose: the waterplane (area, center of flotation, second moments), the
//! metacentric radii and heights, and the linear hydrostatic stiffness.
//!
//! [`Mesh::waterplane`](crate::Mesh::waterplane) gives the [`Waterplane`];
//! [`Mesh::hydrostatics`](crate::Mesh::hydrostatics) the [`Hydrostatics`] of a body described
//! by a [`LoadingCondition`] (center of gravity, mass, references).
//!
//! # Frames
//! Results are in the *world frame*, SI units. `n` is the water's up normal; the in-plane basis
//! `e₁, e₂` has `e₁` along the body's longitudinal axis (mesh x by default) projected on the
//! still plane and `e₂ = n × e₁`, so `(e₁, e₂, n)` is right-handed and counter-clockwise seen
//! from above is positive. Coordinates `(ξ, η, ζ)` are along `(e₁, e₂, n)`. For a ship modelled
//! x forward, z up (`n = z`), `e₂ = y`; modelled x forward, y up (the default [`Water`]),
//! `e₂ = −z`.
//!
//! # The waterplane
//! The waterplane is the part of the still plane inside the mesh, the section the plane cuts
//! through the body. Its boundary, the waterline, is made of one segment per triangle the plane
//! cuts, between the points where it crosses the triangle's edges. Each segment `p → q` is
//! oriented as the *cap* (the waterplane closing the submerged volume, facing up) runs along it:
//! opposite to the submerged part of the triangle, so counter-clockwise around the region seen
//! from above and clockwise around its holes. Green's theorem then turns each integral over the
//! region into a sum over the segments of the signed triangles `(o, p, q)`, positions relative
//! to `o`, the projection of the mesh's centroid on the plane, `d = n·(p × q)`:
//!
//! ```text
//! A = Σ d/2,    ∫ r dA = Σ (d/6)·(p + q),    ∫ r rᵀ dA = Σ (d/24)·(2ppᵀ + 2qqᵀ + pqᵀ + qpᵀ)
//! ```
//!
//! and the center of flotation `F = ∫ r dA / A` and the second moments about it (parallel
//! axes). No polygon is assembled: holes (a torus at its equator has an annulus) and several
//! pieces (a catamaran) come out of the same sum. The result is the exact area and moments of
//! the polygon(s) the plane cuts through the mesh, up to round-off: the mesh's discretisation is
//! the only approximation. Only the triangles near the waterline are visited (the hierarchy's
//! walk).
//!
//! A vertex exactly in the surface (`h = 0`) counts as under water, as in the cut: the answers
//! are those of the surface raised by a hair. A waterline through a row of vertices gives the
//! same waterplane as one 10⁻⁹ above it. The triangles below such a row are not cut but touch
//! the surface along an edge; each such edge is a waterline segment (reversed from the
//! triangle), unless the triangle across it is under water too, and the two cancel. A flat
//! bottom lying in the surface therefore has its whole area as waterplane, a flat deck lying in
//! it none.
//!
//! # Hydrostatics
//! With `V` and `B` the displaced volume and center of buoyancy ([`Method::Exact`]), `G` the
//! center of gravity, `K` the keel (the lowest vertex along `n` at the pose, or a point given),
//! `I_T = ∫η² dA` and `I_L = ∫ξ² dA` the second moments of the waterplane about the lines
//! through `F` along `e₁` and `e₂`:
//!
//! ```text
//! KB = n·(B − K),   KG = n·(G − K),   BM_T = I_T / V,   BM_L = I_L / V,
//! GM_T = KB + BM_T − KG,   GM_L = KB + BM_L − KG.
//! ```
//!
//! The metacentric radii about the waterplane's principal axes (least first) are given too: a
//! body is stable against every small tilt when the least metacentric height is positive.
//!
//! The hydrostatic stiffness about a point `P` (the center of gravity unless given), rows and
//! columns heave (along `n`), roll (about `e₁`), pitch (about `e₂`), with `(ξ, η, ζ)` measured
//! from `P`, the integrals over the waterplane, `m` the body's mass:
//!
//! ```text
//! C₃₃ = ρg A              C₃₄ = ρg ∫η dA                       C₃₅ = −ρg ∫ξ dA
//! C₄₄ = ρg (∫η² dA + V ζ_B) − m g ζ_G     C₄₅ = −ρg ∫ξη dA
//! C₅₅ = ρg (∫ξ² dA + V ζ_B) − m g ζ_G     (symmetric)
//! ```
//!
//! This is the linear hydrostatic restoring matrix of seakeeping codes, e.g. the WAMIT User
//! Manual ("Hydrostatic data": `C(3,3) = ρg∬n₃dS`, …, `C(4,4) = ρg∬y²n₃dS + ρg∀z_b − mgz_g`)
//! and Capytaine's `compute_hydrostatic_stiffness` for rigid-body degrees of freedom, in which
//! the integrals over the wetted hull reduce to these over the waterplane. It is the derivative
//! of the load of buoyancy and weight: a small heave `δ₃` and rotations `δ₄`, `δ₅` about `P`
//! change the vertical force and the moments about `P` along `e₁`, `e₂` by `−C·δ` to first
//! order, at any pose, in equilibrium or not (the tests check it against finite differences of
//! [`Mesh::buoyancy`](crate::Mesh::buoyancy)). Left out are the terms of the full 6×6 matrix
//! outside heave, roll and pitch: yaw's `C₄₆ = −ρgVξ_B + mgξ_G`, `C₅₆ = −ρgVη_B + mgη_G` and,
//! for `m ≠ ρV`, the moment about the fixed `P` of a horizontal translation; all vanish in
//! equilibrium with `P` on the vertical through `G`. There, with `P = G` and `F` under it,
//! `C₄₄ = ρgV·GM_T` and `C₅₅ = ρgV·GM_L`.
//!
//! # Example
//! ```
//! use buoyancy_core::hydrostatics::LoadingCondition;
//! use buoyancy_core::{Mesh, Pose, Water, shape};
//! use nalgebra::{Point3, Vector3};
//!
//! // A box 4 m long (x), 1 m deep (y, up), 2 m wide (z), its center at the surface: draft
//! // T = 0.5 m; its center of gravity at its center.
//! let (v, t) = shape::cube::<f64>(1)?;
//! let hull = Mesh::new(v, t)?.scaled(&Vector3::new(4.0, 1.0, 2.0))?;
//! let water = Water::default();
//! let loading = LoadingCondition::new(Point3::origin())?;
//! let h = hull.hydrostatics(&Pose::identity(), &water, &loading)?;
//!
//! let (length, beam, draft) = (4.0, 2.0, 0.5);
//! assert!((h.waterplane.area - length * beam).abs() < 1e-12);
//! assert!((h.kb - draft / 2.0).abs() < 1e-12);
//! assert!((h.bm_transverse - beam * beam / (12.0 * draft)).abs() < 1e-12);
//! assert!((h.bm_longitudinal - length * length / (12.0 * draft)).abs() < 1e-12);
//! assert!((h.gm_transverse - (0.25 + 2.0 / 3.0 - 0.5)).abs() < 1e-12);
//! // In equilibrium about G: C₄₄ = ρgV·GM_T, a heel of 0.01 rad is resisted by −C₄₄·0.01.
//! let rho_g_v = water.specific_weight() * h.displaced_volume;
//! assert!((h.stiffness[(1, 1)] - rho_g_v * h.gm_transverse).abs() < 1e-8);
//! let (_, moment) = h.restoring(0.0, 0.01, 0.0);
//! assert!((moment.x + 0.01 * h.stiffness[(1, 1)]).abs() < 1e-9);
//! # Ok::<(), buoyancy_core::Error>(())
//! ```
//!
//! # Hydrostatic table
//! [`Mesh::hydrostatic_table`](crate::Mesh::hydrostatic_table) evaluates the hydrostatics of
//! the body at one upright orientation ([`TableOptions`], the identity by default) over a list
//! of drafts `T`, the depth of the keel (the lowest vertex along `n`) below the still level: one
//! [`HydrostaticRow`] per draft with `V`, `ρV`, `KB`, `BM_T`, `BM_L`, `KM_T = KB + BM_T`,
//! `KM_L = KB + BM_L`, the waterplane area `A_wp` and
//!
//! ```text
//! LCB = e₁·(B − O),   LCF = e₁·(F − O),   TPC = ρ·A_wp·0.01/1000 (t/cm),
//! MCT = ρ·V·GM_L/(100·L) (kg·m/cm),
//! ```
//!
//! `O` the mesh origin (projected on the still plane), `L` the waterline length (the extent of
//! the waterplane along `e₁`) unless a length is given, `GM_L = KB + BM_L − KG` with a center of
//! gravity given, else `BM_L` (`KG ≈ KB`). Every figure comes from
//! [`Mesh::hydrostatics`](crate::Mesh::hydrostatics) at the row's pose.
//!
//! ```
//! use buoyancy_core::hydrostatics::TableOptions;
//! use buoyancy_core::{Mesh, Water, shape};
//! use nalgebra::Vector3;
//!
//! // A box 4 m long (x), 1 m deep (y, up), 2 m wide (z).
//! let (v, t) = shape::cube::<f64>(1)?;
//! let hull = Mesh::new(v, t)?.scaled(&Vector3::new(4.0, 1.0, 2.0))?;
//! let water = Water::default();
//! let rows = hull.hydrostatic_table(&water, &[0.25, 0.5, 0.75], &TableOptions::new())?;
//! for row in &rows {
//!     let t = row.draft;
//!     assert!((row.displacement - 1000.0 * 8.0 * t).abs() < 1e-9);
//!     assert!((row.kb - t / 2.0).abs() < 1e-12);
//!     assert!((row.bm_transverse - 4.0 / (12.0 * t)).abs() < 1e-12);
//!     assert!((row.tpc - 1000.0 * 8.0 / 1e5).abs() < 1e-15); // 0.08 t/cm
//!     assert!(row.lcb.abs() < 1e-12 && row.lcf.abs() < 1e-12);
//!     assert!((row.waterline_length - 4.0).abs() < 1e-12);
//! }
//! // A draft beyond the body's depth is an error naming it.
//! let e = hull.hydrostatic_table(&water, &[0.5, 1.5], &TableOptions::new()).unwrap_err();
//! assert!(matches!(e, buoyancy_core::Error::InvalidDraft { index: 1, .. }));
//! # Ok::<(), buoyancy_core::Error>(())
//! ```
//!
//! # Open hulls
//! A hull surface without a deck is closed by flat lids when the mesh is built,
//! [`Mesh::close_openings`](crate::Mesh::close_openings): each planar loop of open edges gets a
//! fan of triangles, the mesh remembers them ([`Opening`]), and
//! [`Mesh::check_openings`](crate::Mesh::check_openings) and the hydrostatic table return
//! [`Error::OpeningSubmerged`](crate::Error::OpeningSubmerged) the moment the water reaches a
//! rim. While the rims are dry, every result is that of the open hull.

mod keel;
mod openings;
mod stability;
mod table;
mod waterplane;

pub use openings::Opening;
pub use stability::{Hydrostatics, LoadingCondition};
pub use table::{HydrostaticRow, TableOptions};
pub use waterplane::Waterplane;

#[cfg(doc)]
use crate::{Method, Water};
