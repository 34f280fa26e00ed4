//! The equilibrium of a floating body: Newton with a line search on the potential, draft solved
//! at every attitude, restarts along negative curvature. See the [module
//! documentation](super#equilibrium) for the conventions and formulas.

use nalgebra::{Matrix2, Matrix3, Point3, Translation3, Unit, UnitQuaternion, Vector2, Vector3};

use super::waterplane::in_plane;
use super::{Hydrostatics, LoadingCondition};
use crate::query::frame::Frame;
use crate::{Buoyancy, Error, Mesh, Method, Pose, Real, Water};

/// Settings of [`Mesh::equilibrium_with`] and [`Mesh::gz_curve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EquilibriumOptions<T: Real> {
    /// The start pose (mesh → world). Its orientation is the *upright* one, heel and trim zero;
    /// its yaw and the horizontal position of the center of gravity are kept; the height of `G`
    /// starts the draft's solve. `None`: the mesh frame's own orientation (identity rotation),
    /// `G` on the vertical through its mesh-frame position, the draft from a bisection on the
    /// volume.
    pub start: Option<Pose<T>>,
    /// Relative tolerance on the residuals: `|ρV − m|/m` and the tilting moments about `G`
    /// divided by `m·g·L` (`L` the body length, twice [`Mesh::bounding_radius`]). Default
    /// `ε^(2/3)` of the scalar type: about 3.7e-11 for `f64`, 2.4e-5 for `f32`.
    pub tolerance: T,
    /// Newton iterations allowed (over all restarts). Default 100.
    pub max_iterations: usize,
    /// Restarts allowed when the state found is unstable. Default 4.
    pub max_restarts: usize,
}

impl<T: Real> Default for EquilibriumOptions<T> {
    fn default() -> Self {
        EquilibriumOptions {
            start: None,
            tolerance: T::default_epsilon().powf(T::from_f64_lossy(2.0 / 3.0)),
            max_iterations: 100,
            max_restarts: 4,
        }
    }
}

impl<T: Real> EquilibriumOptions<T> {
    /// These options with the start pose `pose` (see [`start`](Self::start)).
    pub fn with_start(mut self, pose: Pose<T>) -> Self {
        self.start = Some(pose);
        self
    }

    /// These options with the relative tolerance `tolerance` (see [`tolerance`](Self::tolerance)).
    pub fn with_tolerance(mut self, tolerance: T) -> Self {
        self.tolerance = tolerance;
        self
    }

    fn check(&self) -> Result<(), Error> {
        if !(self.tolerance.is_finite()
            && self.tolerance > T::zero()
            && self.tolerance < T::from_f64_lossy(0.1))
        {
            return Err(Error::InvalidSolverOption {
                parameter: "tolerance",
                reason: "must be finite, positive and below 0.1 (a relative residual)",
            });
        }
        if self.max_iterations == 0 {
            return Err(Error::InvalidSolverOption {
                parameter: "max_iterations",
                reason: "must be at least 1",
            });
        }
        Ok(())
    }
}

/// A floating body at rest: see [`Mesh::equilibrium`] and the [module
/// documentation](super#equilibrium).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Equilibrium<T: Real> {
    /// The pose (mesh → world) at rest.
    pub pose: Pose<T>,
    /// Depth of the keel below the surface, m: the lowest vertex along the up normal, or the
    /// [`LoadingCondition`]'s keel point.
    pub draft: T,
    /// Heel `φ`, rad: the rotation about the body's longitudinal axis from the upright
    /// orientation, right-handed (positive puts the side towards `−e₂` down).
    pub heel: T,
    /// Trim `θ`, rad: the rotation about the horizontal transverse axis `e₂`, right-handed
    /// (positive puts the end towards `+e₁`, the longitudinal axis's head, down).
    pub trim: T,
    /// The relative residuals at the result: `(ρV − m)/m`, and the moments of buoyancy and
    /// weight about `G` along `e₁` and `e₂` divided by `m·g·L`. Each within the tolerance.
    pub residual: Vector3<T>,
    /// The body length `L` the moments are scaled by, m: twice [`Mesh::bounding_radius`].
    pub length: T,
    /// Newton iterations taken (each a line search on the potential), over all restarts.
    pub iterations: usize,
    /// Restarts from an unstable state along its direction of negative curvature.
    pub restarts: usize,
    /// Whether the equilibrium is stable: every eigenvalue of the heave–roll–pitch stiffness
    /// about `G` (scaled, see [`stiffness_eigenvalues`](Self::stiffness_eigenvalues)) above
    /// `√tolerance` (6.1e-6 for the default `f64` tolerance, 4.9e-3 for `f32`'s: a tilt's
    /// eigenvalue is `GM/L`). `false` for a neutral state (an eigenvalue within `±√tolerance`,
    /// e.g. a uniform cylinder rolling about its axis), when the restarts ran out, or when no
    /// step along the direction of negative curvature lowered the potential.
    pub stable: bool,
    /// Eigenvalues of `S·C·S/(m·g·L)`, least first, dimensionless: `C` the stiffness about `G`
    /// in heave, roll about `e₁` and pitch about `e₂` (the Hessian of the potential),
    /// `S = diag(L, 1, 1)`. Their signs are those of `C`'s eigenvalues; a tilt's eigenvalue is
    /// `GM/L` for a body upright in equilibrium.
    pub stiffness_eigenvalues: [T; 3],
    /// The hydrostatics at the result, for the [`LoadingCondition`] given.
    pub hydrostatics: Hydrostatics<T>,
}

/// The largest moment residual of the `free` angles of `state` (zero when none is free).
fn free_moment<T: Real>(state: &State<T>, free: [bool; 2]) -> T {
    (0..2)
        .filter(|&k| free[k])
        .map(|k| state.moment[k].abs())
        .fold(T::zero(), T::max)
}

/// One evaluation of the body at an attitude with its draft solved.
#[derive(Debug, Clone, Copy)]
pub(crate) struct State<T: Real> {
    pub(crate) heel: T,
    pub(crate) trim: T,
    /// Height of `G` above the surface, m.
    pub(crate) height: T,
    pub(crate) pose: Pose<T>,
    pub(crate) buoyancy: Buoyancy<T>,
    /// `U/(m·g·L) = (z_G − (ρV/m)·z_B)/L`.
    pub(crate) potential: T,
    /// `(ρV − m)/m`.
    pub(crate) heave: T,
    /// Moments about `G` along `e₁`, `e₂`, over `m·g·L`.
    pub(crate) moment: Vector2<T>,
    /// `∂(U/mgL)/∂(heel, trim)`.
    pub(crate) gradient: Vector2<T>,
}

/// The solver's fixed data: the body, the water, the frame of the angles.
pub(crate) struct Solver<'a, T: Real> {
    mesh: &'a Mesh<T>,
    water: &'a Water<T>,
    pub(crate) loading: LoadingCondition<T>,
    mass: T,
    cg: Point3<T>,
    n: Vector3<T>,
    pub(crate) e1: Unit<Vector3<T>>,
    pub(crate) e2: Unit<Vector3<T>>,
    upright: UnitQuaternion<T>,
    g_horizontal: Vector3<T>,
    start_height: Option<T>,
    pub(crate) length: T,
    pub(crate) tolerance: T,
    max_iterations: usize,
    pub(crate) iterations: usize,
}

fn lossy<T: Real>(x: f64) -> T {
    T::from_f64_lossy(x)
}

/// Eigenvalues (least first) and unit eigenvectors of a symmetric 2×2 matrix.
fn eigen2<T: Real>(m: &Matrix2<T>) -> ([T; 2], [Vector2<T>; 2]) {
    let (a, b, c) = (m[(0, 0)], m[(0, 1)], m[(1, 1)]);
    let two = lossy::<T>(2.0);
    let mean = (a + c) / two;
    let radius = ((a - c) / two).hypot(b);
    let low = mean - radius;
    let high = mean + radius;
    if radius == T::zero() {
        return ([low, high], [Vector2::x(), Vector2::y()]);
    }
    // Eigenvector of the least eigenvalue: the better conditioned of two candidate forms.
    let u = Vector2::new(b, low - a);
    let w = Vector2::new(low - c, b);
    let v = if u.norm() >= w.norm() { u } else { w };
    let v = v / v.norm();
    ([low, high], [v, Vector2::new(-v.y, v.x)])
}

impl<'a, T: Real> Solver<'a, T> {
    pub(crate) fn new(
        mesh: &'a Mesh<T>,
        water: &'a Water<T>,
        loading: &LoadingCondition<T>,
        options: &EquilibriumOptions<T>,
    ) -> Result<Self, Error> {
        options.check()?;
        let mass = loading.mass().ok_or(Error::InvalidMass {
            reason: "is not given; set it with LoadingCondition::with_mass (kg)",
        })?;
        if !mass.is_finite() {
            return Err(Error::InvalidMass {
                reason: "must be finite (kg)",
            });
        }
        if mass <= T::zero() {
            return Err(Error::InvalidMass {
                reason: "must be positive (kg): a massless body has no equilibrium draft",
            });
        }
        if mass < water.density() * mesh.volume() * T::from_f64_lossy(1e-12) {
            return Err(Error::InvalidMass {
                reason: "is less than 1e-12 of the mass of water the body displaces: it floats \
                         at no draft the solver can find (check the units: kg, and a mesh in \
                         metres)",
            });
        }
        if water.gravity() <= T::zero() {
            return Err(Error::InvalidWater {
                parameter: "gravity",
                reason: "must be positive for an equilibrium: without gravity nothing floats",
            });
        }
        // A center of gravity a million body sizes away is a unit or a frame mistake; beyond,
        // the moments of its weight overflow the solver's poses.
        let offset = (loading.center_of_gravity() - mesh.centroid()).norm();
        if !offset.is_finite() || offset > T::from_f64_lossy(1e6) * mesh.bounding_radius() {
            return Err(Error::InvalidLoading {
                parameter: "center_of_gravity",
                reason: "lies more than 10⁶ body sizes (bounding radii) from the mesh's \
                         centroid: check that it is in the mesh frame and in metres",
            });
        }
        let capacity = water.density() * mesh.volume();
        // Within the tolerance of neutral buoyancy, the volume residual is met fully submerged
        // at any depth: no draft to find.
        if mass >= capacity * (T::one() - options.tolerance) {
            return Err(Error::TooHeavyToFloat {
                mass: mass.to_f64(),
                capacity: capacity.to_f64(),
            });
        }
        let start = options.start.unwrap_or_else(Pose::identity);
        // Checks the start pose (finite, non-zero quaternion).
        Frame::new(mesh, &start, water)?;
        let upright = UnitQuaternion::new_normalize(start.rotation.into_inner());
        let n = water.normal().into_inner();
        let axis = upright * loading.longitudinal_axis();
        let e1 = in_plane(&axis, &n, T::default_epsilon().sqrt()).ok_or(Error::InvalidLoading {
            parameter: "longitudinal_axis",
            reason: "is vertical at the start pose: heel and trim need a horizontal axis",
        })?;
        let e1 = Unit::new_normalize(e1);
        let e2 = Unit::new_normalize(n.cross(&e1));
        let g0 = start * loading.center_of_gravity();
        Ok(Solver {
            mesh,
            water,
            loading: *loading,
            mass,
            cg: loading.center_of_gravity(),
            n,
            e1,
            e2,
            upright,
            g_horizontal: g0.coords - n * n.dot(&g0.coords),
            start_height: options.start.map(|_| water.height(&g0)),
            length: mesh.bounding_radius() * lossy(2.0),
            tolerance: options.tolerance,
            max_iterations: options.max_iterations,
            iterations: 0,
        })
    }

    fn rotation(&self, heel: T, trim: T) -> UnitQuaternion<T> {
        UnitQuaternion::from_axis_angle(&self.e2, trim)
            * UnitQuaternion::from_axis_angle(&self.e1, heel)
            * self.upright
    }

    /// The pose at `heel`, `trim` with `G` at `height` above the surface on its vertical.
    pub(crate) fn pose(&self, heel: T, trim: T, height: T) -> Pose<T> {
        let rotation = self.rotation(heel, trim);
        let g = self.g_horizontal + self.n * (self.water.level() + height);
        Pose::from_parts(Translation3::from(g - rotation * self.cg.coords), rotation)
    }

    /// `G` in the world at a pose.
    fn g_world(&self, pose: &Pose<T>) -> Point3<T> {
        pose * self.cg
    }

    /// The state at `heel`, `trim` with the draft solved (`ρV = m`): Newton on the height of
    /// `G` with the waterplane area as derivative, safeguarded by bisection of the bracket from
    /// fully submerged to dry.
    pub(crate) fn solve(&self, heel: T, trim: T, guess: Option<T>) -> Result<State<T>, Error> {
        let rotation = self.rotation(heel, trim);
        let r = self.mesh.bounding_radius() * lossy(1.001) + self.length * lossy(1e-6);
        // Height of the centroid above G.
        let offset = self.n.dot(&(rotation * (self.mesh.centroid() - self.cg)));
        let (mut low, mut high) = (-r - offset, r - offset);
        let target = self.mass / self.water.density();
        let fraction = target / self.mesh.volume();
        let mut z = match guess.or(self.start_height) {
            Some(z) if z > low && z < high => z,
            _ => high - (high - low) * fraction,
        };
        let round_off = T::default_epsilon() * lossy(8.0) * (self.length + low.abs() + high.abs());
        let goal = self.tolerance * lossy(0.25);
        let mut pose;
        let mut buoyancy;
        let mut count = 0;
        loop {
            pose = self.pose(heel, trim, z);
            buoyancy = self.mesh.buoyancy(&pose, self.water, Method::Exact)?;
            let excess = buoyancy.submerged_volume / target - T::one();
            count += 1;
            if excess.abs() <= goal || high - low <= round_off || count >= 200 {
                break;
            }
            if excess > T::zero() {
                low = z;
            } else {
                high = z;
            }
            let area = self.mesh.closed_waterplane(&pose, self.water)?.area;
            let step = excess * target / area;
            let next = z + step;
            z = if area > T::zero() && next.is_finite() && next > low && next < high {
                next
            } else {
                (low + high) / lossy(2.0)
            };
        }
        Ok(self.state(heel, trim, z, pose, buoyancy))
    }

    fn state(&self, heel: T, trim: T, z: T, pose: Pose<T>, buoyancy: Buoyancy<T>) -> State<T> {
        let g = self.g_world(&pose);
        let mg = self.mass * self.water.gravity();
        let mgl = mg * self.length;
        let ratio = self.water.density() * buoyancy.submerged_volume / self.mass;
        let zb = self.water.height(&buoyancy.center_of_buoyancy);
        let moment = buoyancy.torque_about(&g);
        let (cos, sin) = (trim.cos(), trim.sin());
        let heel_axis = self.e1.into_inner() * cos - self.n * sin;
        State {
            heel,
            trim,
            height: z,
            pose,
            buoyancy,
            potential: (z - ratio * zb) / self.length,
            heave: ratio - T::one(),
            moment: Vector2::new(moment.dot(&self.e1), moment.dot(&self.e2)) / mgl,
            gradient: Vector2::new(-moment.dot(&heel_axis), -moment.dot(&self.e2)) / mgl,
        }
    }

    /// The loading the stiffness is taken with: about `G`, the axes `e₁`, `e₂` of the angles.
    fn internal_loading(&self, pose: &Pose<T>) -> Result<LoadingCondition<T>, Error> {
        LoadingCondition::new(self.cg)?
            .with_mass(self.mass)?
            .with_longitudinal_axis(pose.rotation.inverse() * self.e1.into_inner())
    }

    /// The stiffness about `G` in heave (along `n`), roll about `e₁`, pitch about `e₂`.
    pub(crate) fn stiffness(&self, state: &State<T>) -> Result<Matrix3<T>, Error> {
        let loading = self.internal_loading(&state.pose)?;
        Ok(self
            .mesh
            .closed_hydrostatics(&state.pose, self.water, &loading)?
            .stiffness)
    }

    /// The Hessian of `U/(m·g·L)` in (heel, trim) with the draft solved: the Schur complement
    /// of heave in the stiffness, with `∂/∂heel` a rotation about the trimmed body axis
    /// (`cos θ` along `e₁`).
    fn reduced_hessian(&self, state: &State<T>) -> Result<Matrix2<T>, Error> {
        let c = self.stiffness(state)?;
        let mut h = Matrix2::new(c[(1, 1)], c[(1, 2)], c[(2, 1)], c[(2, 2)]);
        if c[(0, 0)] > T::zero() {
            let coupling = Vector2::new(c[(0, 1)], c[(0, 2)]);
            h -= coupling * coupling.transpose() / c[(0, 0)];
        }
        let j = Matrix2::new(state.trim.cos(), T::zero(), T::zero(), T::one());
        Ok(j * h * j / (self.mass * self.water.gravity() * self.length))
    }

    /// The largest residual of the free coordinates (the heave always).
    pub(crate) fn residual(&self, state: &State<T>, free: [bool; 2]) -> T {
        state.heave.abs().max(free_moment(state, free))
    }

    fn no_convergence(&self, residual: T) -> Error {
        Error::NoConvergence {
            iterations: self.iterations,
            residual: residual.to_f64(),
            tolerance: self.tolerance.to_f64(),
        }
    }

    /// Newton with a line search on the potential over the `free` angles, from `state`.
    pub(crate) fn minimize(
        &mut self,
        mut state: State<T>,
        free: [bool; 2],
    ) -> Result<State<T>, Error> {
        let floor = T::default_epsilon().sqrt();
        let max_step = lossy::<T>(0.5);
        loop {
            let residual = self.residual(&state, free);
            if residual <= self.tolerance {
                return Ok(state);
            }
            if !free[0] && !free[1] {
                // Only the draft: solved already, within round-off.
                return Err(self.no_convergence(residual));
            }
            if self.iterations >= self.max_iterations {
                return Err(self.no_convergence(residual));
            }
            self.iterations += 1;
            let mut h = self.reduced_hessian(&state)?;
            let mut g = state.gradient;
            for k in 0..2 {
                if !free[k] {
                    g[k] = T::zero();
                    for j in 0..2 {
                        h[(k, j)] = T::zero();
                        h[(j, k)] = T::zero();
                    }
                    h[(k, k)] = T::one();
                }
            }
            // Newton on |H|: a descent direction whatever the curvature.
            let (values, vectors) = eigen2(&h);
            let mut d = Vector2::zeros();
            for k in 0..2 {
                d -= vectors[k] * (g.dot(&vectors[k]) / values[k].abs().max(floor));
            }
            let size = d.amax();
            if size > max_step {
                d *= max_step / size;
            }
            let slope = g.dot(&d);
            let moment_residual = free_moment(&state, free);
            let mut alpha = T::one();
            let mut accepted = None;
            for _ in 0..40 {
                let trial = self.solve(
                    state.heel + d.x * alpha,
                    state.trim + d.y * alpha,
                    Some(state.height),
                )?;
                let trial_moment = free_moment(&trial, free);
                let c = lossy::<T>(1e-4);
                if trial.potential <= state.potential + c * alpha * slope
                    || trial_moment <= (T::one() - c * alpha) * moment_residual
                {
                    accepted = Some(trial);
                    break;
                }
                alpha /= lossy(2.0);
            }
            match accepted {
                Some(trial) => state = trial,
                None => return Err(self.no_convergence(residual)),
            }
        }
    }

    /// A step from a converged state along the direction of its least curvature, if negative
    /// beyond `threshold`, to a lower potential: `None` if the state is not unstable or no step
    /// lowers the potential.
    fn escape(&mut self, state: &State<T>, threshold: T) -> Result<Option<State<T>>, Error> {
        let h = self.reduced_hessian(state)?;
        let (values, vectors) = eigen2(&h);
        if values[0] >= -threshold {
            return Ok(None);
        }
        let mut v = vectors[0];
        let along = state.gradient.dot(&v);
        if along > T::zero()
            || (along == T::zero() && (v.x < T::zero() || (v.x == T::zero() && v.y < T::zero())))
        {
            v = -v;
        }
        let mut alpha = lossy::<T>(0.5);
        for _ in 0..12 {
            let trial = self.solve(
                state.heel + v.x * alpha,
                state.trim + v.y * alpha,
                Some(state.height),
            )?;
            let drop = lossy::<T>(5e-3) * values[0].abs() * alpha * alpha;
            if trial.potential < state.potential - drop {
                return Ok(Some(trial));
            }
            alpha /= lossy(2.0);
        }
        Ok(None)
    }

    /// Keel depth below the surface at a pose.
    pub(crate) fn draft(&self, pose: &Pose<T>) -> Result<T, Error> {
        Ok(match self.loading.keel() {
            Some(k) => -self.water.height(&(pose * k)),
            None => {
                let frame = Frame::new(self.mesh, pose, self.water)?;
                -self.mesh.lowest_vertex(&frame).1
            }
        })
    }
}

impl<T: Real> Mesh<T> {
    /// The equilibrium of this body in `water` for the mass and center of gravity of `loading`,
    /// from the default [`EquilibriumOptions`]: see [`equilibrium_with`](Self::equilibrium_with).
    ///
    /// # Errors
    /// As [`equilibrium_with`](Self::equilibrium_with).
    pub fn equilibrium(
        &self,
        water: &Water<T>,
        loading: &LoadingCondition<T>,
    ) -> Result<Equilibrium<T>, Error> {
        self.equilibrium_with(water, loading, &EquilibriumOptions::default())
    }

    /// The stable pose at rest of this body in `water` for the mass `m` and center of gravity
    /// `G` of `loading` (mesh frame): draft, heel and trim such that `ρV = m` and the center of
    /// buoyancy lies on the vertical through `G`. Yaw and the horizontal position of `G` are
    /// those of the start pose (see [`EquilibriumOptions::start`]); heel and trim are measured
    /// from its orientation, about the body's longitudinal axis (`loading`'s) and the
    /// horizontal transverse axis. See the [module documentation](super#equilibrium) for the
    /// method, the frame and the signs.
    ///
    /// # Errors
    /// [`Error::InvalidMass`] if `loading` has no mass or a zero one;
    /// [`Error::TooHeavyToFloat`] if `m ≥ ρ·V·(1 − tolerance)` of the whole mesh (at neutral
    /// buoyancy, within the tolerance, a submerged body has no draft);
    /// [`Error::InvalidWater`] for zero gravity; [`Error::InvalidPose`] for a start pose that
    /// is not finite; [`Error::InvalidLoading`] if the longitudinal axis is vertical at the
    /// start; [`Error::InvalidSolverOption`] for a tolerance outside `(0, 0.1)` or no
    /// iterations; [`Error::NoConvergence`] if the residuals do not reach the tolerance;
    /// [`Error::OpeningSubmerged`] if the water reaches an opening of a hull closed by
    /// [`Mesh::close_openings`] at rest (the hull would flood).
    pub fn equilibrium_with(
        &self,
        water: &Water<T>,
        loading: &LoadingCondition<T>,
        options: &EquilibriumOptions<T>,
    ) -> Result<Equilibrium<T>, Error> {
        let mut solver = Solver::new(self, water, loading, options)?;
        let threshold = solver.tolerance.sqrt();
        let free = [true, true];
        let start = solver.solve(T::zero(), T::zero(), None)?;
        let mut state = solver.minimize(start, free)?;
        let mut restarts = 0;
        while restarts < options.max_restarts {
            match solver.escape(&state, threshold)? {
                Some(moved) => {
                    restarts += 1;
                    state = solver.minimize(moved, free)?;
                }
                None => break,
            }
        }
        let hydrostatics = self.hydrostatics(&state.pose, water, loading)?;
        let c = solver.stiffness(&state)?;
        let mgl = solver.mass * water.gravity() * solver.length;
        let s = Matrix3::from_diagonal(&Vector3::new(solver.length, T::one(), T::one()));
        let scaled = s * c * s / mgl;
        let mut eigenvalues: [T; 3] = scaled.symmetric_eigenvalues().into();
        eigenvalues.sort_by(|a, b| a.partial_cmp(b).unwrap_or(core::cmp::Ordering::Equal));
        let result = Equilibrium {
            pose: state.pose,
            draft: solver.draft(&state.pose)?,
            heel: state.heel,
            trim: state.trim,
            residual: Vector3::new(state.heave, state.moment.x, state.moment.y),
            length: solver.length,
            iterations: solver.iterations,
            restarts,
            stable: eigenvalues[0] > threshold,
            stiffness_eigenvalues: eigenvalues,
            hydrostatics,
        };
        let finite = result.draft.is_finite()
            && result.heel.is_finite()
            && result.trim.is_finite()
            && result.residual.iter().all(|x| x.is_finite())
            && result.stiffness_eigenvalues.iter().all(|x| x.is_finite());
        if finite {
            Ok(result)
        } else {
            Err(Error::NonFiniteResult)
        }
    }
}
