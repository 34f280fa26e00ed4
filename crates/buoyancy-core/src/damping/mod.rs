//! Hydrodynamic damping: pressure drag on the wetted surface and angular damping, so that
//! floating bodies settle instead of bobbing forever.
//!
//! The model knows no physics engine: given a mesh, its pose, the velocity of its center of mass
//! and its angular velocity (world frame), the water and the [`DampingCoefficients`], it returns
//! a force and a torque about the center of mass ([`Damping`]), which an engine adapter applies
//! for one step.
//!
//! # The model
//! With `c` the center of mass (the mesh centroid under the pose), `v` its velocity, `ω` the
//! angular velocity and `v_w` the water's velocity (the current), the velocity of a surface point
//! `p` relative to the water is `u(p) = v + ω × (p − c) − v_w`.
//!
//! **Pressure drag.** On the wetted surface (the fully submerged triangles and the parts under
//! water of the triangles the surface cuts, see [`Method::Exact`](crate::Method::Exact)), with
//! `n̂` the outward unit normal, the normal velocity `u_n = n̂·u(p)` is linear over each flat
//! triangle. Where the surface pushes into the water (`u_n > 0`, it faces the flow) it feels the
//! pressure `P = c₁·u_n + ½·ρ·C_D·u_n²` (Pa), against its normal:
//!
//! ```text
//! F = −∫ P n̂ dA,    τ = −∫ (p − c) × P n̂ dA   over { u_n > 0 }.
//! ```
//!
//! Both are integrated exactly: each wetted triangle is clipped where `u_n = 0`, and on the part
//! where `u_n > 0` the polynomials `u_n`, `u_n²`, `u_n·p`, `u_n²·p` are integrated in closed form
//! (with barycentric coordinates, `∫ λᵢλⱼλₖ dA = A/60·(1 + δᵢⱼ + δⱼₖ + δᵢₖ + 2δᵢⱼδⱼₖ)`), so the
//! result does not depend on how a flat face is split into triangles.
//!
//! The surface moving away from the water (`u_n ≤ 0`, the wake side) feels nothing, and neither
//! does anything above the surface, so the force is zero in air and grows with what is
//! submerged.
//!
//! **Angular damping.** A torque against the rotation, scaled by the wetted fraction of the
//! surface `f = A_wet / A_total` and by the body's size through `ρ·V^{5/3}` (kg·m², `V` the mesh
//! volume):
//!
//! ```text
//! τ_ω = −f·ρ·V^{5/3}·(a₁ + a₂·|ω|)·ω
//! ```
//!
//! It stands for what the pressure drag misses: the skin friction that alone damps a spinning
//! sphere, and the waves a rolling hull radiates.
//!
//! The total is `F = Σ F_i`, `τ = Σ τ_i + τ_ω`, in the world frame, in N and N·m, the torque
//! about `c`. The model is explicit: applied unchanged over a step `dt`, a large damping rate
//! overshoots (the impulse `F·dt` exceeds the momentum it damps). An engine should integrate it
//! implicitly: [`Mesh::damping_with_stiffness`] gives its stiffness `K = −∂W/∂q̇` for that
//! ([`DampingStiffness`]). The [`controller`](crate::controller) (under both engine adapters)
//! applies it semi-implicitly, `(W − α·dt·G)/(1 + α·dt)` with `α` the damping rate and `G` the
//! step's other forces, and through `K` where one rate would overshoot.

mod angular;
mod coefficients;
mod drag;
mod result;
mod stiffness;

pub use angular::angular_damping;
pub(crate) use angular::angular_size;
pub use coefficients::DampingCoefficients;
pub use result::Damping;
pub(crate) use stiffness::add_block;
pub use stiffness::{DampingStiffness, angular_damping_stiffness};

#[cfg(doc)]
use crate::Mesh;
