//! Metacentric heights and the hydrostatic stiffness at a pose.

use nalgebra::{Matrix3, Point3, Vector3};

use super::waterplane::{Waterplane, in_plane};
use crate::query::frame::Frame;
use crate::{Error, Mesh, Method, Pose, Real, Water};

/// What the hydrostatic quantities need to know of the body beyond its hull: its center of
/// gravity and mass, and the references they are measured from. Points and axes are in the
/// *mesh frame* (they move with the body).
///
/// Built from the center of gravity with [`LoadingCondition::new`]; the rest defaults to
///
/// * mass: the mass of the water displaced at the pose evaluated, `ρV` (the body floats freely
///   in equilibrium there; Capytaine's default too);
/// * reference point of the stiffness: the center of gravity;
/// * longitudinal axis: the mesh frame's x axis;
/// * keel: the lowest point of the mesh along the up normal at the pose evaluated.
///
/// ```
/// use buoyancy_core::hydrostatics::LoadingCondition;
/// use nalgebra::{Point3, Vector3};
///
/// let loading = LoadingCondition::new(Point3::new(0.0, 0.1, 0.0))?
///     .with_mass(1200.0)?
///     .with_longitudinal_axis(Vector3::z())?;
/// assert_eq!(loading.mass(), Some(1200.0));
/// assert_eq!(loading.reference_point(), Point3::new(0.0, 0.1, 0.0));
/// assert!(loading.with_mass(-1.0).is_err());
/// # Ok::<(), buoyancy_core::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadingCondition<T: Real> {
    center_of_gravity: Point3<T>,
    mass: Option<T>,
    reference_point: Option<Point3<T>>,
    longitudinal_axis: Vector3<T>,
    keel: Option<Point3<T>>,
}

/// [`Error::InvalidLoading`] naming `parameter` unless every component of `p` is finite.
fn finite<T: Real>(p: &Vector3<T>, parameter: &'static str) -> Result<(), Error> {
    if p.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(Error::InvalidLoading {
            parameter,
            reason: "has a NaN or infinite component",
        })
    }
}

impl<T: Real> LoadingCondition<T> {
    /// A body whose center of gravity is `center_of_gravity` (mesh frame, m), the rest by
    /// default (see the type's documentation).
    ///
    /// # Errors
    /// [`Error::InvalidLoading`] if the point has a NaN or infinite component.
    pub fn new(center_of_gravity: Point3<T>) -> Result<Self, Error> {
        finite(&center_of_gravity.coords, "center_of_gravity")?;
        Ok(LoadingCondition {
            center_of_gravity,
            mass: None,
            reference_point: None,
            longitudinal_axis: Vector3::x(),
            keel: None,
        })
    }

    /// The same body with mass `mass` (kg), for the weight's terms of the stiffness.
    ///
    /// # Errors
    /// [`Error::InvalidLoading`] if the mass is negative or not finite.
    pub fn with_mass(mut self, mass: T) -> Result<Self, Error> {
        if !mass.is_finite() || mass < T::zero() {
            return Err(Error::InvalidLoading {
                parameter: "mass",
                reason: "must be finite and non-negative (kg)",
            });
        }
        self.mass = Some(mass);
        Ok(self)
    }

    /// The same body with the stiffness taken about `point` (mesh frame, m) instead of the
    /// center of gravity.
    ///
    /// # Errors
    /// [`Error::InvalidLoading`] if the point has a NaN or infinite component.
    pub fn with_reference_point(mut self, point: Point3<T>) -> Result<Self, Error> {
        finite(&point.coords, "reference_point")?;
        self.reference_point = Some(point);
        Ok(self)
    }

    /// The same body with another longitudinal axis (mesh frame, any length): the direction of
    /// the transverse moment `I_T` (about this axis) and the roll axis.
    ///
    /// # Errors
    /// [`Error::InvalidLoading`] if the axis is zero or has a NaN or infinite component.
    pub fn with_longitudinal_axis(mut self, axis: Vector3<T>) -> Result<Self, Error> {
        finite(&axis, "longitudinal_axis")?;
        if axis.norm() == T::zero() || !axis.norm().is_finite() {
            return Err(Error::InvalidLoading {
                parameter: "longitudinal_axis",
                reason: "is zero or too large to normalise",
            });
        }
        self.longitudinal_axis = axis;
        Ok(self)
    }

    /// The same body with heights (KB, KG) measured from `keel` (mesh frame, m) instead of the
    /// lowest point of the mesh.
    ///
    /// # Errors
    /// [`Error::InvalidLoading`] if the point has a NaN or infinite component.
    pub fn with_keel(mut self, keel: Point3<T>) -> Result<Self, Error> {
        finite(&keel.coords, "keel")?;
        self.keel = Some(keel);
        Ok(self)
    }

    /// The center of gravity, mesh frame, m.
    pub fn center_of_gravity(&self) -> Point3<T> {
        self.center_of_gravity
    }

    /// The mass given (kg), `None` for the displaced mass at the pose evaluated.
    pub fn mass(&self) -> Option<T> {
        self.mass
    }

    /// The point the stiffness is taken about, mesh frame, m: the center of gravity unless
    /// another was given.
    pub fn reference_point(&self) -> Point3<T> {
        self.reference_point.unwrap_or(self.center_of_gravity)
    }

    /// The longitudinal axis, mesh frame (as given, not normalised).
    pub fn longitudinal_axis(&self) -> Vector3<T> {
        self.longitudinal_axis
    }

    /// The keel point given (mesh frame, m), `None` for the lowest point of the mesh.
    pub fn keel(&self) -> Option<Point3<T>> {
        self.keel
    }
}

/// The hydrostatics of a body at a pose: displacement, centers, metacentric radii and heights,
/// and the linear hydrostatic stiffness; see the [module documentation](super) for the
/// formulas. Points and vectors are in the *world frame*, SI units.
///
/// The axes: `n` the water's up normal; `e₁ = waterplane.axes[0]`, the body's longitudinal
/// axis projected on the still plane (unit); `e₂ = waterplane.axes[1] = n × e₁`. *Transverse*
/// quantities belong to rolling, about `e₁` (the transverse moment `I_T = ∫η² dA`),
/// *longitudinal* ones to pitching, about `e₂` (`I_L = ∫ξ² dA`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Hydrostatics<T: Real> {
    /// The waterplane, its basis along the body's longitudinal axis.
    pub waterplane: Waterplane<T>,
    /// Displaced volume `V`, m³ ([`Method::Exact`]).
    pub displaced_volume: T,
    /// Center of buoyancy `B`, the centroid of the displaced volume, world frame, m.
    pub center_of_buoyancy: Point3<T>,
    /// Center of gravity `G`, world frame, m.
    pub center_of_gravity: Point3<T>,
    /// The mass `m` of the weight's terms, kg: as given, or `ρV`.
    pub mass: T,
    /// The keel point `K` heights are measured from, world frame, m: the lowest vertex of the
    /// mesh along `n` (or the point given).
    pub keel: Point3<T>,
    /// `KB = n·(B − K)`: height of the center of buoyancy above the keel, m. (When nothing is
    /// under water, `B` is the projection of the mesh's center of volume on the surface, as in
    /// [`Buoyancy`](crate::Buoyancy).)
    pub kb: T,
    /// `KG = n·(G − K)`: height of the center of gravity above the keel, m.
    pub kg: T,
    /// Transverse metacentric radius `BM_T = I_T/V`, m (zero when nothing is under water).
    pub bm_transverse: T,
    /// Longitudinal metacentric radius `BM_L = I_L/V`, m (zero when nothing is under water).
    pub bm_longitudinal: T,
    /// Metacentric radii about the waterplane's principal axes, `principal_moments/V`, least
    /// first, m.
    pub bm_principal: [T; 2],
    /// Transverse metacentric height `GM_T = KB + BM_T − KG`, m: positive is stable in roll.
    pub gm_transverse: T,
    /// Longitudinal metacentric height `GM_L = KB + BM_L − KG`, m.
    pub gm_longitudinal: T,
    /// Metacentric heights about the waterplane's principal axes, least first, m: the least is
    /// positive when the upright pose is stable against every small tilt (for `m = ρV`).
    pub gm_principal: [T; 2],
    /// The point `P` the stiffness is taken about, world frame, m.
    pub reference_point: Point3<T>,
    /// The hydrostatic stiffness `C` about `P`, rows and columns (heave along `n`, roll about
    /// `e₁`, pitch about `e₂`): N/m, N/rad, N·m/m and N·m/rad. Symmetric. A small displacement
    /// `x = (heave, roll, pitch)` (m, rad, rad) changes the vertical force and the moments
    /// about `P` along `e₁`, `e₂` by `−C·x`, to first order (see [`restoring`](Self::restoring)).
    pub stiffness: Matrix3<T>,
}

impl<T: Real> Hydrostatics<T> {
    /// The change of the hydrostatic and gravity load, to first order, for a small
    /// displacement of the body: `heave` (m, along `n`), `roll` and `pitch` (rad, right-handed
    /// about `e₁` and `e₂` through `P`). Returns the force and the moment about `P`, world
    /// frame (N, N·m): `−C·x` along `n`, `e₁`, `e₂`.
    ///
    /// In equilibrium (`m = ρV`), about `P = G` with `F` in the vertical plane of the roll axis
    /// (`η_F = 0`), the roll moment is `−ρgV·GM_T·roll`.
    pub fn restoring(&self, heave: T, roll: T, pitch: T) -> (Vector3<T>, Vector3<T>) {
        let [e1, e2] = self.waterplane.axes;
        let up = e1.cross(&e2);
        let load = -(self.stiffness * Vector3::new(heave, roll, pitch));
        (
            up * load[0],
            e1.into_inner() * load[1] + e2.into_inner() * load[2],
        )
    }
}

impl<T: Real> Mesh<T> {
    /// The hydrostatics of this mesh placed by `pose` (mesh → world) in `water`, for the body
    /// described by `loading`: see [`Hydrostatics`] and the [module
    /// documentation](crate::hydrostatics).
    ///
    /// Costs one [`Mesh::waterplane`], one [`Mesh::buoyancy`] with [`Method::Exact`] and a
    /// search of the hierarchy for the keel: all follow the waterline (or the bottom).
    ///
    /// # Errors
    /// [`Error::InvalidPose`] if the pose has a NaN or infinite component or a zero
    /// quaternion; [`Error::InvalidLoading`] if the longitudinal axis is vertical at this pose
    /// (within `√ε` rad: it has no direction in the waterplane); [`Error::NonFiniteResult`] if
    /// the result overflows; [`Error::OpeningSubmerged`] when the water reaches an opening of a
    /// hull closed by [`Mesh::close_openings`] (its lid is not hull then).
    /// (The loading's own values are checked when it is built, see [`LoadingCondition`].)
    pub fn hydrostatics(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        loading: &LoadingCondition<T>,
    ) -> Result<Hydrostatics<T>, Error> {
        self.openings_dry(&Frame::new(self, pose, water)?)?;
        self.closed_hydrostatics(pose, water, loading)
    }

    /// [`hydrostatics`](Self::hydrostatics) of the closed mesh, its lids counted as hull
    /// wherever the water is: for the equilibrium solver's iterates, which may wet a lid on the
    /// way to a rest that does not.
    pub(crate) fn closed_hydrostatics(
        &self,
        pose: &Pose<T>,
        water: &Water<T>,
        loading: &LoadingCondition<T>,
    ) -> Result<Hydrostatics<T>, Error> {
        let frame = Frame::new(self, pose, water)?;
        let e1 = in_plane(
            &loading.longitudinal_axis,
            &frame.normal_local,
            T::default_epsilon().sqrt(),
        )
        .ok_or(Error::InvalidLoading {
            parameter: "longitudinal_axis",
            reason: "is vertical at this pose: it has no direction in the waterplane",
        })?;
        let waterplane = self.waterplane_in(&frame, &e1)?;
        let buoyancy = self.buoyancy(pose, water, Method::Exact)?;
        let volume = buoyancy.submerged_volume;
        let b = buoyancy.center_of_buoyancy;
        // Mesh frame to world, and heights above the surface of mesh-frame points, as the
        // frame computes them.
        let world = |p: &Point3<T>| frame.center_of_mass + frame.rotation * (p - self.centroid);
        let height = |p: &Point3<T>| frame.normal_local.dot(&(p - self.centroid)) + frame.height;
        let (keel, keel_height) = match loading.keel {
            Some(k) => (world(&k), height(&k)),
            None => {
                let (v, h) = self.lowest_vertex(&frame);
                (frame.center_of_mass + frame.rotation * v, h)
            }
        };
        let n = frame.normal;
        let g = world(&loading.center_of_gravity);
        let kb = n.dot(&(b - frame.center_of_mass)) + frame.height - keel_height;
        let kg = height(&loading.center_of_gravity) - keel_height;
        let i = &waterplane.second_moments;
        let per_volume = |moment: T| {
            if volume > self.volume_tolerance() {
                moment / volume
            } else {
                T::zero()
            }
        };
        let (bm_transverse, bm_longitudinal) = (per_volume(i[(0, 0)]), per_volume(i[(1, 1)]));
        let bm_principal = waterplane.principal_moments.map(per_volume);
        let mass = loading.mass.unwrap_or(water.density() * volume);

        // The stiffness about P: in-plane offsets of F from P, heights of B and G above P.
        let p = world(&loading.reference_point());
        let [e1w, e2w] = waterplane.axes;
        let d = waterplane.center_of_flotation - p;
        let (dx, dy) = (d.dot(&e1w), d.dot(&e2w));
        let (zb, zg) = (n.dot(&(b - p)), n.dot(&(g - p)));
        let (rho_g, m_g) = (water.specific_weight(), mass * water.gravity());
        let area = waterplane.area;
        let c33 = rho_g * area;
        let c34 = rho_g * area * dy;
        let c35 = -rho_g * area * dx;
        let c44 = rho_g * (i[(0, 0)] + area * dy * dy + volume * zb) - m_g * zg;
        let c45 = rho_g * (i[(0, 1)] - area * dx * dy);
        let c55 = rho_g * (i[(1, 1)] + area * dx * dx + volume * zb) - m_g * zg;
        let stiffness = Matrix3::new(c33, c34, c35, c34, c44, c45, c35, c45, c55);

        let result = Hydrostatics {
            waterplane,
            displaced_volume: volume,
            center_of_buoyancy: b,
            center_of_gravity: g,
            mass,
            keel,
            kb,
            kg,
            bm_transverse,
            bm_longitudinal,
            bm_principal,
            gm_transverse: kb + bm_transverse - kg,
            gm_longitudinal: kb + bm_longitudinal - kg,
            gm_principal: bm_principal.map(|bm| kb + bm - kg),
            reference_point: p,
            stiffness,
        };
        let finite = [
            result.kb,
            result.kg,
            result.mass,
            result.gm_transverse,
            result.gm_longitudinal,
            result.gm_principal[0],
            result.gm_principal[1],
        ]
        .iter()
        .all(|x| x.is_finite())
            && result.stiffness.iter().all(|x| x.is_finite())
            && result.keel.iter().all(|x| x.is_finite())
            && result.center_of_gravity.iter().all(|x| x.is_finite())
            && result.reference_point.iter().all(|x| x.is_finite());
        if finite {
            Ok(result)
        } else {
            Err(Error::NonFiniteResult)
        }
    }
}
