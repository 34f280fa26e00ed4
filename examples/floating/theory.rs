//! What statics predicts for the final state of a uniform cube and a uniform ball of relative
//! density `s` (body over water) floating in still water: draft, tilt and attitude.
//!
//! Words (also the table's and the plot's):
//! * **draft**: the depth of the body's lowest point below the surface, m;
//! * **tilt**: the angle between the vertical and the body axis nearest to it, 0° to 54.7°
//!   (for a cube: 0° face down, 45° edge down, 54.7° = arccos(1/√3) corner down).

/// What is known of a body's final state.
pub enum Theory {
    /// A uniform cube of this side (m).
    Cube { side: f64 },
    /// A uniform ball of this radius (m).
    Sphere { radius: f64 },
    /// Any other body: only its submerged fraction, `s`, is predicted.
    Model,
}

/// The predicted final state of one body; `None` where statics gives no closed form.
pub struct Prediction {
    pub draft: Option<f64>,
    pub tilt_degrees: Option<f64>,
    pub attitude: &'static str,
}

/// The tilt of a cube floating corner down (a body diagonal vertical), degrees:
/// arccos(1/√3) ≈ 54.74°.
pub fn corner_down_tilt() -> f64 {
    (1.0 / 3f64.sqrt()).acos().to_degrees()
}

impl Theory {
    /// The final state of this body at relative density `s`.
    ///
    /// **Cube** of side `a`. Upright (face down) its draft is `s·a` and its metacentric height
    /// `GM = BM − BG = a/(12 s) − (1 − s)·a/2 = a·(s/2 + 1/(12 s) − 1/2)`: the attitude is
    /// stable when `GM > 0`, i.e. `s < (3 − √3)/6 ≈ 0.211` or `s > (3 + √3)/6 ≈ 0.789`. In
    /// between it tips. At `s = 1/2` the tipped attitude has a closed form: every plane through
    /// the center halves the cube (it is centrally symmetric), so the center of mass sits on
    /// the surface in any attitude, and the potential energy, `ρ·g·(V/2)·d` with `d` the depth
    /// of the center of buoyancy, is least where the half-cube below the surface has its
    /// centroid shallowest. `d = (mean of |n·x| over the cube)`, `n` the vertical in the
    /// cube's frame: `a/4` face down, `a/(3√2) ≈ 0.2357·a` edge down, `13·a/(32√3) ≈ 0.2345·a`
    /// corner down, the least over all `n`. So the cube floats corner down, a body diagonal
    /// vertical and the waterline a regular hexagon, with draft `√3/2·a` (half the diagonal)
    /// and tilt arccos(1/√3) ≈ 54.74°.
    ///
    /// **Ball** of radius `R`: its draft `d` makes the submerged cap hold `s` of its volume,
    /// `π·d²·(3R − d)/3 = s·4πR³/3`. Its attitude is neutral: buoyancy acts through the center
    /// at every attitude, so no attitude is preferred and none is restored.
    pub fn predict(&self, s: f64) -> Prediction {
        match *self {
            Theory::Cube { side } => {
                let metacentric_height = side * (s / 2.0 + 1.0 / (12.0 * s) - 0.5);
                if metacentric_height > 0.0 {
                    Prediction {
                        draft: Some(s * side),
                        tilt_degrees: Some(0.0),
                        attitude: "face down",
                    }
                } else if (s - 0.5).abs() < 1e-6 {
                    Prediction {
                        draft: Some(3f64.sqrt() / 2.0 * side),
                        tilt_degrees: Some(corner_down_tilt()),
                        attitude: "corner down",
                    }
                } else {
                    Prediction {
                        draft: None,
                        tilt_degrees: None,
                        attitude: "tipped",
                    }
                }
            }
            Theory::Sphere { radius } => Prediction {
                draft: Some(sphere_draft(radius, s)),
                tilt_degrees: None,
                attitude: "any (neutral)",
            },
            Theory::Model => Prediction {
                draft: None,
                tilt_degrees: None,
                attitude: "—",
            },
        }
    }
}

/// The attitude of a cube from its tilt (degrees): face, edge or corner down within 1°, else
/// tilted.
pub fn cube_attitude(tilt_degrees: f64) -> &'static str {
    if tilt_degrees < 1.0 {
        "face down"
    } else if (tilt_degrees - 45.0).abs() < 1.0 {
        "edge down"
    } else if (tilt_degrees - corner_down_tilt()).abs() < 1.0 {
        "corner down"
    } else {
        "tilted"
    }
}

/// The draft of a ball of radius `radius` at relative density `s`: the depth `d` of the cap
/// holding `s` of its volume, `d²·(3R − d) = 4·s·R³`, by bisection.
fn sphere_draft(radius: f64, s: f64) -> f64 {
    let target = 4.0 * s * radius.powi(3);
    let (mut lo, mut hi) = (0.0, 2.0 * radius);
    for _ in 0..100 {
        let d = 0.5 * (lo + hi);
        if d * d * (3.0 * radius - d) < target {
            lo = d
        } else {
            hi = d
        }
    }
    0.5 * (lo + hi)
}
