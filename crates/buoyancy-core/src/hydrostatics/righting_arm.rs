//! The righting-arm (GZ) curve: the equilibrium in draft (and trim) at imposed heels. See the
//! [module documentation](super#the-righting-arm-curve).

use alloc::vec::Vec;

use nalgebra::Vector3;

use super::LoadingCondition;
use super::equilibrium::{EquilibriumOptions, Solver};
use crate::{Error, Mesh, Pose, Real, Water};

/// How the trim is found at each heel of a [`GzCurve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Trim<T: Real> {
    /// Free: solved at each heel so that the pitching moment about `G` vanishes, by
    /// continuation from the previous heel.
    Free,
    /// Held at this angle (rad, about `e₂`, positive puts the head of the longitudinal axis
    /// down), measured from the upright orientation.
    Fixed(T),
}

/// One point of a [`GzCurve`]: the body at an imposed heel, its draft (and trim) solved.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GzPoint<T: Real> {
    /// The heel imposed, rad (right-handed about the body's longitudinal axis).
    pub heel: T,
    /// The trim, rad: solved ([`Trim::Free`]) or held.
    pub trim: T,
    /// Depth of the keel below the surface, m (the lowest vertex, or the loading's keel).
    pub draft: T,
    /// The righting arm `GZ = −(B − G)·e₂`, m: the horizontal lever between the vertical through
    /// `B` and `G`, perpendicular to the heel axis. Positive turns the body towards negative
    /// heel: righting at positive heel. The moment of buoyancy and weight about the heel axis
    /// through `G` is `−m·g·GZ·cos θ`.
    pub gz: T,
    /// The pose (mesh → world).
    pub pose: Pose<T>,
    /// Relative residuals `(ρV − m)/m` and the moments about `G` along `e₁`, `e₂` over `m·g·L`
    /// (the roll moment is the heeling moment the curve measures, not a residual; the pitch
    /// moment is one for [`Trim::Free`]).
    pub residual: Vector3<T>,
}

/// Where the range of positive stability of a [`GzCurve`] ends
/// ([`GzCurve::positive_stability`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum PositiveStability<T: Real> {
    /// GZ goes from positive to zero or negative at this heel, rad: the angle of vanishing
    /// stability ([`GzCurve::vanishing_angle`]).
    VanishesAt(T),
    /// GZ is still positive at the curve's last heel: the angle of vanishing stability lies
    /// beyond the curve.
    BeyondLastHeel,
    /// GZ is not positive at any heel of the curve above zero: no range of positive stability
    /// (the body is unstable or neutral upright and its heels lie outside the curve).
    NotPositive,
}

/// A righting-arm curve: see [`Mesh::gz_curve`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GzCurve<T: Real> {
    /// The points, in the order of the heels given (increasing), up to the last before the
    /// water reaches an opening (see [`flooding`](Self::flooding)).
    pub points: Vec<GzPoint<T>>,
    /// For a hull closed by [`Mesh::close_openings`]: the first heel given at which the water
    /// reaches one of its openings (rad), where the curve stops (the hull floods; past it the
    /// lid is no hull). `None` when every heel keeps them dry, and for a closed mesh.
    pub flooding: Option<T>,
    /// Newton iterations taken for the trim, over all points.
    pub iterations: usize,
}

impl<T: Real> GzCurve<T> {
    /// The area under the curve from the first heel to the last, `∫ GZ dφ`, m·rad, by the
    /// trapezoidal rule on the points (error `O(h²)` in the spacing `h`). For the dynamic
    /// stability `∫ GZ cos θ dφ = ΔU/(m·g)` the trim must stay small or be zero.
    pub fn area(&self) -> T {
        self.area_up_to(self.points.last().map_or(T::zero(), |p| p.heel))
    }

    /// The area under the curve from the first heel to `heel` (clamped to the range),
    /// trapezoidal, the last piece cut at `heel` with `GZ` interpolated linearly, m·rad.
    pub fn area_up_to(&self, heel: T) -> T {
        let half = T::from_f64_lossy(0.5);
        let mut area = T::zero();
        for pair in self.points.windows(2) {
            let (a, b) = (&pair[0], &pair[1]);
            if heel <= a.heel {
                break;
            }
            if heel >= b.heel {
                area += (b.heel - a.heel) * (a.gz + b.gz) * half;
            } else {
                let gz = a.gz + (b.gz - a.gz) * (heel - a.heel) / (b.heel - a.heel);
                area += (heel - a.heel) * (a.gz + gz) * half;
            }
        }
        area
    }

    /// The angle of maximum GZ and that maximum `(φ, GZ)`, rad and m: the greatest point,
    /// refined by the parabola through it and its neighbours when it is not at an end.
    /// `None` for an empty curve.
    pub fn max_gz(&self) -> Option<(T, T)> {
        let (i, best) = self.points.iter().enumerate().fold(
            None,
            |best: Option<(usize, &GzPoint<T>)>, (i, p)| match best {
                Some((_, b)) if b.gz >= p.gz => best,
                _ => Some((i, p)),
            },
        )?;
        if i == 0 || i + 1 == self.points.len() {
            return Some((best.heel, best.gz));
        }
        let (a, c) = (&self.points[i - 1], &self.points[i + 1]);
        // Divided differences of the parabola through the three points.
        let d1 = (best.gz - a.gz) / (best.heel - a.heel);
        let d2 = (c.gz - best.gz) / (c.heel - best.heel);
        let curvature = (d2 - d1) / (c.heel - a.heel);
        if curvature >= T::zero() {
            return Some((best.heel, best.gz));
        }
        // p(φ) = gz_a + d1 (φ − φ_a) + curvature (φ − φ_a)(φ − φ_b).
        let two = T::from_f64_lossy(2.0);
        let heel = (a.heel + best.heel) / two - d1 / (two * curvature);
        let heel = heel.max(a.heel).min(c.heel);
        let gz = a.gz + d1 * (heel - a.heel) + curvature * (heel - a.heel) * (heel - best.heel);
        Some((heel, gz.max(best.gz)))
    }

    /// The angle of vanishing stability, rad: the first heel above zero where GZ goes from
    /// positive to zero or negative, interpolated linearly between the points around it.
    /// `None` if GZ does not vanish within the curve: either it stays positive or it is never
    /// positive; [`positive_stability`](Self::positive_stability) tells which.
    ///
    /// Positive means above the round-off of the curve, `√ε·max |GZ|`: the `GZ` of `4e-18` m
    /// an upright hull can have is zero here, not a range of stability.
    pub fn vanishing_angle(&self) -> Option<T> {
        let positive = self.round_off();
        self.points.windows(2).find_map(|pair| {
            let (a, b) = (&pair[0], &pair[1]);
            (b.heel > T::zero() && a.gz > positive && b.gz <= positive)
                .then(|| (a.heel + a.gz * (b.heel - a.heel) / (a.gz - b.gz)).max(T::zero()))
        })
    }

    /// Where the range of positive stability ends: at the angle of vanishing stability, beyond
    /// the last heel (GZ positive there), or nowhere, when GZ is not positive at any heel
    /// above zero.
    pub fn positive_stability(&self) -> PositiveStability<T> {
        if let Some(angle) = self.vanishing_angle() {
            return PositiveStability::VanishesAt(angle);
        }
        match self.points.last() {
            Some(last) if last.heel > T::zero() && last.gz > self.round_off() => {
                PositiveStability::BeyondLastHeel
            }
            _ => PositiveStability::NotPositive,
        }
    }

    /// The `GZ` below which a point counts as zero: `√ε` of the greatest `|GZ|`, m.
    fn round_off(&self) -> T {
        let largest = self
            .points
            .iter()
            .fold(T::zero(), |largest, p| largest.max(p.gz.abs()));
        T::default_epsilon().sqrt() * largest
    }
}

impl<T: Real> Mesh<T> {
    /// The righting-arm curve of this body in `water` for the mass and center of gravity of
    /// `loading`: at each of `heels` (rad, strictly increasing, about the body's longitudinal
    /// axis from the upright orientation of [`EquilibriumOptions::start`]), the draft solved
    /// so that `ρV = m`, the trim solved by continuation from the previous heel
    /// ([`Trim::Free`]) or held ([`Trim::Fixed`]), and `GZ` measured. See [`GzCurve`] for the
    /// derived figures and the [module documentation](super#the-righting-arm-curve) for the
    /// conventions.
    ///
    /// # Errors
    /// As [`Mesh::equilibrium_with`]; [`Error::InvalidSolverOption`] for `heels` empty, not
    /// finite or not strictly increasing, or a fixed trim that is not finite;
    /// [`Error::OpeningSubmerged`] when the water reaches an opening at the first heel (at a
    /// later one the curve stops there, see [`GzCurve::flooding`]).
    pub fn gz_curve(
        &self,
        water: &Water<T>,
        loading: &LoadingCondition<T>,
        heels: &[T],
        trim: Trim<T>,
        options: &EquilibriumOptions<T>,
    ) -> Result<GzCurve<T>, Error> {
        if heels.is_empty() {
            return Err(Error::InvalidSolverOption {
                parameter: "heels",
                reason: "is empty: give at least one heel angle (rad)",
            });
        }
        if !heels.iter().all(|h| h.is_finite()) || heels.windows(2).any(|w| w[1] <= w[0]) {
            return Err(Error::InvalidSolverOption {
                parameter: "heels",
                reason: "must be finite and strictly increasing (rad)",
            });
        }
        let (mut theta, free) = match trim {
            Trim::Free => (T::zero(), [false, true]),
            Trim::Fixed(t) if t.is_finite() => (t, [false, false]),
            Trim::Fixed(_) => {
                return Err(Error::InvalidSolverOption {
                    parameter: "trim",
                    reason: "a fixed trim must be finite (rad)",
                });
            }
        };
        let mut solver = Solver::new(self, water, loading, options)?;
        let mut points = crate::error::vec_with_capacity(heels.len(), "heels")?;
        let mut height = None;
        let mut flooding = None;
        for &heel in heels {
            let start = solver.solve(heel, theta, height)?;
            let state = solver.minimize(start, free)?;
            match self.check_openings(&state.pose, water) {
                Ok(()) => {}
                // The first heel: the hull floods upright; no curve.
                Err(e @ Error::OpeningSubmerged { .. }) if points.is_empty() => return Err(e),
                Err(Error::OpeningSubmerged { .. }) => {
                    flooding = Some(heel);
                    break;
                }
                Err(e) => return Err(e),
            }
            theta = state.trim;
            height = Some(state.height);
            let g = state.pose * solver.loading.center_of_gravity();
            let gz = -(state.buoyancy.center_of_buoyancy - g).dot(&solver.e2);
            let draft = solver.draft(&state.pose)?;
            if !(gz.is_finite() && draft.is_finite()) {
                return Err(Error::NonFiniteResult);
            }
            points.push(GzPoint {
                heel,
                trim: state.trim,
                draft,
                gz,
                pose: state.pose,
                residual: Vector3::new(state.heave, state.moment.x, state.moment.y),
            });
        }
        Ok(GzCurve {
            points,
            flooding,
            iterations: solver.iterations,
        })
    }
}
