//! The hydrostatic table: the hydrostatics of a body at one upright orientation over a list of
//! drafts.

use alloc::vec::Vec;

use nalgebra::{Point3, Translation3, UnitQuaternion, Vector3};

use super::stability::{Hydrostatics, LoadingCondition};
use super::waterplane::in_plane;
use crate::query::frame::Frame;
use crate::{Error, Mesh, Pose, Real, Water};

/// How [`Mesh::hydrostatic_table`] places the body and what it measures from. Points and axes
/// are in the *mesh frame*; the defaults:
///
/// * rotation: the identity (the mesh is modelled upright in the water's frame);
/// * longitudinal axis: the mesh frame's x axis;
/// * center of gravity: none, so that the moment to change trim takes `GM_L ≈ BM_L` (`KG ≈ KB`,
///   the usual approximation);
/// * length of the moment to change trim: the waterline length at each draft.
///
/// ```
/// use buoyancy_core::hydrostatics::TableOptions;
/// use nalgebra::{Point3, UnitQuaternion, Vector3};
///
/// let options = TableOptions::new()
///     .with_rotation(UnitQuaternion::from_scaled_axis(Vector3::x() * -core::f64::consts::FRAC_PI_2))?
///     .with_center_of_gravity(Point3::new(0.0, 0.0, 0.4))?
///     .with_length(12.0)?;
/// assert_eq!(options.length(), Some(12.0));
/// assert!(options.with_length(0.0).is_err());
/// # Ok::<(), buoyancy_core::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableOptions<T: Real> {
    rotation: UnitQuaternion<T>,
    longitudinal_axis: Vector3<T>,
    center_of_gravity: Option<Point3<T>>,
    length: Option<T>,
}

impl<T: Real> Default for TableOptions<T> {
    fn default() -> Self {
        TableOptions {
            rotation: UnitQuaternion::identity(),
            longitudinal_axis: Vector3::x(),
            center_of_gravity: None,
            length: None,
        }
    }
}

/// [`Error::InvalidTableOption`] naming `parameter`.
fn invalid(parameter: &'static str, reason: &'static str) -> Error {
    Error::InvalidTableOption { parameter, reason }
}

impl<T: Real> TableOptions<T> {
    /// The defaults (see the type's documentation).
    pub fn new() -> Self {
        Self::default()
    }

    /// The same options with the body turned by `rotation` (mesh → world) at every draft.
    ///
    /// # Errors
    /// [`Error::InvalidTableOption`] (`rotation`) if it has a NaN or infinite component.
    pub fn with_rotation(mut self, rotation: UnitQuaternion<T>) -> Result<Self, Error> {
        if !rotation.coords.iter().all(|x| x.is_finite()) {
            return Err(invalid("rotation", "has a NaN or infinite component"));
        }
        self.rotation = rotation;
        Ok(self)
    }

    /// The same options with another longitudinal axis (mesh frame, any length): LCB and LCF are
    /// measured along it, `BM_L` is about the transverse axis across it.
    ///
    /// # Errors
    /// [`Error::InvalidTableOption`] (`longitudinal_axis`) if it is zero or not finite.
    pub fn with_longitudinal_axis(mut self, axis: Vector3<T>) -> Result<Self, Error> {
        let norm = axis.norm();
        if !axis.iter().all(|x| x.is_finite()) || norm == T::zero() || !norm.is_finite() {
            return Err(invalid(
                "longitudinal_axis",
                "must be finite and non-zero (mesh frame)",
            ));
        }
        self.longitudinal_axis = axis;
        Ok(self)
    }

    /// The same options with the center of gravity at `point` (mesh frame, m): the moment to
    /// change trim then takes `GM_L = KB + BM_L − KG`.
    ///
    /// # Errors
    /// [`Error::InvalidTableOption`] (`center_of_gravity`) if it is not finite.
    pub fn with_center_of_gravity(mut self, point: Point3<T>) -> Result<Self, Error> {
        if !point.iter().all(|x| x.is_finite()) {
            return Err(invalid(
                "center_of_gravity",
                "has a NaN or infinite component",
            ));
        }
        self.center_of_gravity = Some(point);
        Ok(self)
    }

    /// The same options with the length `L` of the moment to change trim fixed at `length` (m,
    /// e.g. the length between perpendiculars) instead of the waterline length at each draft.
    ///
    /// # Errors
    /// [`Error::InvalidTableOption`] (`length`) unless it is finite and positive.
    pub fn with_length(mut self, length: T) -> Result<Self, Error> {
        if !(length.is_finite() && length > T::zero()) {
            return Err(invalid("length", "must be finite and positive (m)"));
        }
        self.length = Some(length);
        Ok(self)
    }

    /// The rotation (mesh → world).
    pub fn rotation(&self) -> UnitQuaternion<T> {
        self.rotation
    }

    /// The longitudinal axis, mesh frame (as given, not normalised).
    pub fn longitudinal_axis(&self) -> Vector3<T> {
        self.longitudinal_axis
    }

    /// The center of gravity given (mesh frame, m), if any.
    pub fn center_of_gravity(&self) -> Option<Point3<T>> {
        self.center_of_gravity
    }

    /// The length of the moment to change trim given (m), `None` for the waterline length.
    pub fn length(&self) -> Option<T> {
        self.length
    }
}

/// One row of a hydrostatic table ([`Mesh::hydrostatic_table`]): the body upright at one draft.
/// SI units but for `tpc` and `mct`; `n` is the water's up normal, `e₁` the body's longitudinal
/// axis projected on the still plane (`hydrostatics.waterplane.axes[0]`), `O` the mesh frame's
/// origin at the row's pose (world frame).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct HydrostaticRow<T: Real> {
    /// Draft `T`: depth of the keel (the lowest vertex along `n`) below the still level, m.
    pub draft: T,
    /// Displaced volume `V`, m³.
    pub displaced_volume: T,
    /// Displacement, the mass of the water displaced `ρV`, kg.
    pub displacement: T,
    /// `KB`, height of the center of buoyancy above the keel, m.
    pub kb: T,
    /// Transverse metacentric radius `BM_T = I_T/V`, m.
    pub bm_transverse: T,
    /// Longitudinal metacentric radius `BM_L = I_L/V`, m.
    pub bm_longitudinal: T,
    /// `KM_T = KB + BM_T`, m.
    pub km_transverse: T,
    /// `KM_L = KB + BM_L`, m.
    pub km_longitudinal: T,
    /// Longitudinal center of buoyancy `LCB = e₁·(B − O)`: the distance along the body's
    /// longitudinal axis from the mesh origin (projected on the still plane) to `B`, m, positive
    /// toward the axis.
    pub lcb: T,
    /// Longitudinal center of flotation `LCF = e₁·(F − O)`, from the same origin, m.
    pub lcf: T,
    /// Waterplane area `A_wp`, m².
    pub waterplane_area: T,
    /// Waterline length: the extent of the waterplane along `e₁`, m (zero without waterplane).
    pub waterline_length: T,
    /// Tonnes per centimetre immersion `TPC = ρ·A_wp·0.01/1000`, t/cm: the mass that sinks the
    /// body one more centimetre (wall-sided there).
    pub tpc: T,
    /// The longitudinal metacentric height the moment to change trim takes, m:
    /// `GM_L = KB + BM_L − KG` with the center of gravity given
    /// ([`TableOptions::with_center_of_gravity`]), else `BM_L` (`KG ≈ KB`, the usual
    /// approximation: `BM_L` is much larger than `KG − KB` for a ship).
    pub gm_longitudinal: T,
    /// The length `L` of the moment to change trim, m: as given ([`TableOptions::with_length`])
    /// or the waterline length.
    pub trim_length: T,
    /// Moment to change trim one centimetre `MCT = ρ·V·GM_L/(100·L)`, kg·m/cm (divide by 1000
    /// for t·m/cm); zero when nothing is under water.
    pub mct: T,
    /// The pose of the row (mesh → world): the table's rotation and the translation along `n`
    /// that puts the keel at the draft.
    pub pose: Pose<T>,
    /// Everything [`Mesh::hydrostatics`] gives at that pose (world frame), with the center of
    /// gravity given (or the mesh centroid, for the stiffness only, when none is).
    pub hydrostatics: Hydrostatics<T>,
}

impl<T: Real> Mesh<T> {
    /// The hydrostatic table of this mesh turned by `options.rotation()` in `water`: one
    /// [`HydrostaticRow`] per draft, in the order given; see the [module
    /// documentation](crate::hydrostatics).
    ///
    /// At draft `T` the body is placed by that rotation and a translation along the water's up
    /// normal `n` that puts its lowest vertex (the keel) `T` below the still level, the mesh
    /// origin on the vertical through the world origin. Each row is [`Mesh::hydrostatics`] at
    /// that pose and a walk of the waterline for its length: the cost of a few buoyancy queries
    /// per draft.
    ///
    /// # Errors
    /// [`Error::InvalidDraft`] naming the first draft that is NaN, infinite, negative or above
    /// the body's height along `n` (highest vertex minus lowest; a draft equal to it is
    /// accepted), checked before anything is computed; [`Error::InvalidTableOption`]
    /// (`longitudinal_axis`) if the axis is vertical at the rotation (within `√ε` rad);
    /// [`Error::OpeningSubmerged`] at the first draft where the water reaches an opening of a
    /// hull closed by [`Mesh::close_openings`]; [`Error::NonFiniteResult`] if a result
    /// overflows.
    pub fn hydrostatic_table(
        &self,
        water: &Water<T>,
        drafts: &[T],
        options: &TableOptions<T>,
    ) -> Result<Vec<HydrostaticRow<T>>, Error> {
        let zero = T::zero();
        let rotation = options.rotation;
        let upright = Pose::from_parts(Translation3::identity(), rotation);
        let frame = Frame::new(self, &upright, water)?;
        let axis = options.longitudinal_axis;
        let e1 =
            in_plane(&axis, &frame.normal_local, T::default_epsilon().sqrt()).ok_or(invalid(
                "longitudinal_axis",
                "is vertical at the table's rotation: it has no direction in the waterplane",
            ))?;
        // Heights of the keel and of the top above the surface with the translation zero: the
        // top is the lowest vertex under the opposite normal.
        let (_, bottom) = self.lowest_vertex(&frame);
        let n = water.normal().into_inner();
        let flipped = Water::new(water.density(), water.gravity(), -n, -water.level())?;
        let (_, below_top) = self.lowest_vertex(&Frame::new(self, &upright, &flipped)?);
        let height = -below_top - bottom;
        for (index, &draft) in drafts.iter().enumerate() {
            let reason = if !draft.is_finite() {
                "is NaN or infinite"
            } else if draft < zero {
                "is negative: the keel would be above the water"
            } else if draft > height {
                "is above the body's height: the body would be under water"
            } else {
                continue;
            };
            return Err(Error::InvalidDraft {
                index,
                draft: draft.to_f64(),
                height: height.to_f64(),
                reason,
            });
        }
        let loading = LoadingCondition::new(options.center_of_gravity.unwrap_or(self.centroid))?
            .with_longitudinal_axis(axis)?;
        let density = water.density();
        let hundred = T::from_f64_lossy(100.0);
        let mut rows = crate::error::vec_with_capacity(drafts.len(), "drafts")?;
        for &draft in drafts {
            let pose = Pose::from_parts(Translation3::from(-n * (bottom + draft)), rotation);
            // Mesh::hydrostatics refuses a pose where the water reaches an opening.
            let h = self.hydrostatics(&pose, water, &loading)?;
            let frame = Frame::new(self, &pose, water)?;
            let wp = &h.waterplane;
            let origin = pose.translation.vector;
            let e1_world = wp.axes[0].into_inner();
            let waterline_length = if wp.area > zero {
                self.waterline_extent(&frame, &e1)
            } else {
                zero
            };
            let volume = h.displaced_volume;
            let gm_longitudinal = if options.center_of_gravity.is_some() {
                h.gm_longitudinal
            } else {
                h.bm_longitudinal
            };
            let trim_length = options.length.unwrap_or(waterline_length);
            let mct = if volume > self.volume_tolerance() && trim_length > zero {
                density * volume * gm_longitudinal / (hundred * trim_length)
            } else {
                zero
            };
            let row = HydrostaticRow {
                draft,
                displaced_volume: volume,
                displacement: density * volume,
                kb: h.kb,
                bm_transverse: h.bm_transverse,
                bm_longitudinal: h.bm_longitudinal,
                km_transverse: h.kb + h.bm_transverse,
                km_longitudinal: h.kb + h.bm_longitudinal,
                lcb: e1_world.dot(&(h.center_of_buoyancy.coords - origin)),
                lcf: e1_world.dot(&(wp.center_of_flotation.coords - origin)),
                waterplane_area: wp.area,
                waterline_length,
                tpc: density * wp.area / T::from_f64_lossy(1e5),
                gm_longitudinal,
                trim_length,
                mct,
                pose,
                hydrostatics: h,
            };
            let finite = [
                row.displacement,
                row.km_transverse,
                row.km_longitudinal,
                row.lcb,
                row.lcf,
                row.waterline_length,
                row.tpc,
                row.mct,
            ]
            .iter()
            .all(|x| x.is_finite());
            if !finite {
                return Err(Error::NonFiniteResult);
            }
            rows.push(row);
        }
        Ok(rows)
    }

    /// The extent along `e1` (mesh frame, unit, in the plane) of the waterline at the frame's
    /// pose: of the ends of its segments, as the waterplane counts them.
    fn waterline_extent(&self, frame: &Frame<T>, e1: &Vector3<T>) -> T {
        let mut range: Option<(T, T)> = None;
        let mut add = |p: &Vector3<T>| {
            let x = p.dot(e1);
            range = Some(range.map_or((x, x), |(lo, hi)| (lo.min(x), hi.max(x))));
        };
        self.waterline_segments(frame, |p, q| {
            add(p);
            add(q);
        });
        range.map_or(T::zero(), |(lo, hi)| hi - lo)
    }
}
