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
//! use buoyancy_core::{Mesh, Pose, Water, mesh::primitives};
//! use nalgebra::{Point3, Vector3};
//!
//! // A box 4 m long (x), 1 m deep (y, up), 2 m wide (z), its center at the surface: draft
//! // T = 0.5 m; its center of gravity at its center.
//! let (v, t) = primitives::cube::<f64>(1)?;
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
//! use buoyancy_core::{Mesh, Water, mesh::primitives};
//! use nalgebra::Vector3;
//!
//! // A box 4 m long (x), 1 m deep (y, up), 2 m wide (z).
//! let (v, t) = primitives::cube::<f64>(1)?;
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
//! fan of triangles, the mesh remembers them ([`Opening`](crate::mesh::Opening)), and
//! [`Mesh::check_openings`](crate::Mesh::check_openings), the waterplane and the hydrostatic
//! table return [`Error::OpeningSubmerged`](crate::Error::OpeningSubmerged) the moment the water
//! reaches a rim. While the rims are dry, every result is that of the open hull.
//!
//! # Equilibrium
//! [`Mesh::equilibrium`](crate::Mesh::equilibrium) finds the pose at rest of a body of mass `m`
//! and center of gravity `G` (a [`LoadingCondition`] with a mass): the [`Equilibrium`], where
//! the displacement equals the mass, `ρV = m`, and the center of buoyancy `B` lies on the
//! earth's vertical through `G`.
//!
//! ## Frame and angles
//! `n` is the water's up normal. The start pose ([`EquilibriumOptions::start`], the identity by
//! default) gives the *upright* orientation `R₀`, the yaw, and the vertical through `G` on
//! which `G` stays. `e₁` is the body's longitudinal axis
//! ([`LoadingCondition::longitudinal_axis`], mesh x by default) under `R₀`, projected on the
//! still plane and normalised; `e₂ = n × e₁`. The pose at heel `φ`, trim `θ` (radians) with `G`
//! at height `z` above the surface is, world frame,
//!
//! ```text
//! R = Rot(e₂, θ)·Rot(e₁, φ)·R₀,    G_w = G_h + (level + z)·n,    x_world = R·(x_mesh − G) + G_w
//! ```
//!
//! `Rot(a, α)` the right-handed rotation by `α` about the unit axis `a`, `G_h` the horizontal
//! part of `G` at the start pose. Heel is thus the rotation about the body's longitudinal axis
//! (which trim tilts: intrinsically, trim first, then heel about the body axis), trim the
//! rotation about the horizontal transverse axis `e₂`. Signs, right-hand rule: a **positive
//! heel** lifts the `+e₂` side and puts the `−e₂` side down; a **positive trim** puts the head
//! of the longitudinal axis (the `+e₁` end) down. For a ship modelled x forward, y to port,
//! z up (`n = z`, `e₂ = y`): positive heel is starboard down, positive trim bow down. Modelled
//! x forward and y up (the default [`Water`]), `e₂ = −z`: positive heel puts the `+z` side down.
//!
//! ## Method
//! The potential of weight and buoyancy, heights above the surface, `V` and `B` exact at the
//! pose ([`Method::Exact`]):
//!
//! ```text
//! U = m·g·z_G − ρ·g·V·z_B,    ∂U/∂z = m·g − ρ·g·V,    ∂U/∂α_a = −M_G·a
//! ```
//!
//! for a rotation `α_a` about a horizontal axis `a` through `G`, `M_G` the moment of buoyancy
//! about `G`: its gradient is the residual (heave force and tilting moments), its Hessian the
//! stiffness `C` about `G` ([`Hydrostatics::stiffness`]). An equilibrium is stable when `C` is
//! positive definite. At each attitude `(φ, θ)` the draft is solved first (Newton on `z` with
//! `dV/dz = −A_wp`, safeguarded by bisection between fully submerged and dry), which leaves the
//! reduced potential `Ũ(φ, θ)` with gradient `(−M_G·a₁, −M_G·e₂)`, `a₁ = cos θ·e₁ − sin θ·n`
//! the heel axis, and Hessian the Schur complement `C_rr − C_rz·C_zz⁻¹·C_zr` of heave (in
//! `cos θ·φ` and `θ`). Newton steps on it use the eigenvalues' magnitudes (a descent direction
//! where the curvature is negative too), at most 0.5 rad, with a backtracking line search that
//! accepts a step lowering `Ũ` (Armijo) or the moment residual. A state converged with a
//! negative eigenvalue of the reduced Hessian (below `−√tolerance`) is unstable: the solver
//! restarts from a step along its eigenvector that lowers `Ũ`. An upright box with `GM < 0`
//! heels to its angle of loll, `tan φ = √(−2·GM/BM)` while wall-sided; a square log of
//! relative density between `(3 − √3)/6` and `(3 + √3)/6` tilts, corner down in the middle of
//! the range.
//!
//! The residuals are relative: `(ρV − m)/m` and `M_G·e₁/(m·g·L)`, `M_G·e₂/(m·g·L)` with
//! `L = 2·`[`Mesh::bounding_radius`](crate::Mesh::bounding_radius); the default tolerance is
//! `ε^(2/3)`. A body with `m ≥ ρ·V_total·(1 − tolerance)` is
//! [`Error::TooHeavyToFloat`](crate::Error) (within the tolerance of neutral buoyancy it is
//! submerged at any depth, without a draft), a
//! solve that does not reach the tolerance [`Error::NoConvergence`](crate::Error), never a
//! silent return.
//!
//! # The righting-arm curve
//! [`Mesh::gz_curve`](crate::Mesh::gz_curve) imposes heels `φ_k` (same frame and signs), solves
//! the draft (`ρV = m`) and, with [`Trim::Free`], the trim at each (Newton on `Ũ` in `θ`,
//! continued from the previous heel), or holds it ([`Trim::Fixed`]), and measures
//!
//! ```text
//! GZ = −(B − G)·e₂,    M_G·a₁ = −m·g·GZ·cos θ,    dŨ/dφ = m·g·GZ·cos θ
//! ```
//!
//! the horizontal lever between the verticals through `B` and `G`, perpendicular to the heel
//! axis, positive when righting a positive heel. Hence `∫ GZ cos θ dφ = ΔU/(m·g)` (the dynamic
//! stability; `θ = 0` for a body symmetric fore and aft) and `dGZ/dφ = GM_T` at an upright
//! equilibrium. [`GzCurve`] gives the area under the curve (trapezoidal rule, m·rad), the angle
//! of maximum GZ (the greatest point refined by a parabola) and the angle of vanishing stability
//! (linear interpolation of the first root past the positive part).
//!
//! ```
//! use buoyancy_core::hydrostatics::{EquilibriumOptions, LoadingCondition, Trim};
//! use buoyancy_core::{Mesh, Water, mesh::primitives};
//! use nalgebra::{Point3, Vector3};
//!
//! // A box 4 m long (x), 1 m deep (y, up), 2 m wide (z) of 4000 kg: draft 0.5 m in fresh
//! // water; G 0.25 m above the keel and 2 cm towards +z.
//! let (v, t) = primitives::cube::<f64>(2)?;
//! let hull = Mesh::new(v, t)?.scaled(&Vector3::new(4.0, 1.0, 2.0))?;
//! let water = Water::default();
//! let loading = LoadingCondition::new(Point3::new(0.0, -0.25, 0.02))?.with_mass(4000.0)?;
//! let rest = hull.equilibrium(&water, &loading)?;
//!
//! // Wall-sided: tan φ·(GM + ½·BM·tan²φ) = 0.02 with KB = 0.25, BM = B²/12T, KG = 0.25.
//! let (gm, bm) = (0.25 + 4.0 / 6.0 - 0.25, 4.0 / 6.0);
//! let tan = rest.heel.tan();
//! assert!((tan * (gm + 0.5 * bm * tan * tan) - 0.02).abs() < 1e-10);
//! assert!(rest.heel > 0.0 && rest.trim.abs() < 1e-10 && rest.stable); // +z side down
//! assert!(rest.residual.amax() < 1e-10);
//!
//! // The GZ curve of the same box with G on the centerline: sin φ·(GM + ½·BM·tan²φ).
//! let upright = LoadingCondition::new(Point3::new(0.0, -0.25, 0.0))?.with_mass(4000.0)?;
//! let heels: Vec<f64> = (0..=8).map(|k| 0.05 * k as f64).collect();
//! let curve = hull.gz_curve(&water, &upright, &heels, Trim::Free, &EquilibriumOptions::default())?;
//! for p in &curve.points {
//!     let exact = p.heel.sin() * (gm + 0.5 * bm * p.heel.tan().powi(2));
//!     assert!((p.gz - exact).abs() < 1e-12);
//! }
//! assert!(curve.area() > 0.0 && curve.vanishing_angle().is_none());
//! # Ok::<(), buoyancy_core::Error>(())
//! ```

mod equilibrium;
mod keel;
mod righting_arm;
mod stability;
mod table;
mod units;
mod waterplane;

pub use equilibrium::{Equilibrium, EquilibriumOptions};
pub use righting_arm::{GzCurve, GzPoint, PositiveStability, Trim};
pub use stability::{Hydrostatics, LoadingCondition};
pub use table::{HydrostaticRow, TableOptions};
pub use units::{
    LARGEST_PLAUSIBLE_SIZE, LIGHTEST_PLAUSIBLE_DENSITY, SMALLEST_PLAUSIBLE_LOAD, UnitsWarning,
    units_warnings,
};
pub use waterplane::Waterplane;

#[cfg(doc)]
use crate::{Method, Water};
