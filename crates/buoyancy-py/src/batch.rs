//! `Mesh.buoyancy_batch`'s evaluation: K poses on rayon's threads, without the interpreter lock
//! (a Python surface function takes it back around each call).

use buoyancy_core::nalgebra::Point3;
use buoyancy_core::query::Query;
use buoyancy_core::{Mesh, Pose, Water};
use pyo3::prelude::*;
use rayon::prelude::*;

use crate::convert::{self, floats, shape_str};
use crate::errors::arg_error;
use crate::result::Row;
use crate::water_waves::{Failure, WaterWaves};

/// The `times` argument of a batch of `k` poses, s: absent (0 for every pose), one number for
/// every pose, or shape (k,); finite.
pub fn batch_times(times: Option<&Bound<'_, PyAny>>, k: usize) -> PyResult<Vec<f64>> {
    let Some(times) = convert::given(times) else {
        return Ok(vec![0.0; k]);
    };
    let f = floats(times, "times")?;
    let values = match f.shape.as_slice() {
        [] => vec![f.values[0]; k],
        [n] if *n == k => f.values,
        _ => {
            return Err(arg_error(
                "times",
                format!(
                    "expected one time () or one per pose ({k},), got shape {}",
                    shape_str(&f.shape)
                ),
            ));
        }
    };
    if let Some(i) = values.iter().position(|t| !t.is_finite()) {
        return Err(arg_error(&format!("times[{i}]"), "must be finite (s)"));
    }
    Ok(values)
}

/// The point a batch's torques are taken about.
pub enum About {
    /// Each pose's center of mass (the mesh centroid moved by the pose).
    CenterOfMass,
    /// One world point for every pose.
    Point(Point3<f64>),
    /// One world point per pose.
    PerPose(Vec<Point3<f64>>),
}

impl About {
    /// The `about` argument of a batch of `k` poses: absent, shape (3,) or shape (k, 3).
    pub fn parse(about: Option<&Bound<'_, PyAny>>, k: usize) -> PyResult<Self> {
        let Some(about) = convert::given(about) else {
            return Ok(About::CenterOfMass);
        };
        let f = floats(about, "about")?;
        convert::finite(&f.values, "about")?;
        match f.shape.as_slice() {
            [3] => Ok(About::Point(Point3::from_slice(&f.values))),
            [n, 3] if *n == k => Ok(About::PerPose(
                f.values.chunks_exact(3).map(Point3::from_slice).collect(),
            )),
            _ => Err(arg_error(
                "about",
                format!(
                    "expected one point (3,) or one per pose ({k}, 3), got shape {}",
                    shape_str(&f.shape)
                ),
            )),
        }
    }
}

/// What one batch computes: the mesh at each pose (and time, on waves), in one water, by one
/// method and traversal.
pub struct Batch<'a> {
    pub mesh: &'a Mesh<f64>,
    pub poses: Vec<Pose<f64>>,
    pub water: Water<f64>,
    /// The water's waves; `None` for still water.
    pub waves: Option<&'a WaterWaves>,
    /// The time of each pose, s.
    pub times: Vec<f64>,
    pub query: Query,
    pub about: About,
}

impl Batch<'_> {
    /// The result of every pose, in order, computed in parallel on `pool` (rayon's global pool
    /// when `None`); the first failing pose's index and error otherwise. Each pose gives exactly
    /// what a single evaluation gives, whatever the thread count.
    pub fn run(&self, pool: Option<&rayon::ThreadPool>) -> Result<Vec<Row>, (usize, Failure)> {
        let run = || {
            self.poses
                .par_iter()
                .enumerate()
                .map(|(i, pose)| {
                    let b = match self.waves {
                        None => self
                            .mesh
                            .buoyancy(pose, &self.water, self.query)
                            .map_err(Failure::Core),
                        Some(waves) => {
                            waves.buoyancy(self.mesh, pose, &self.water, self.times[i], self.query)
                        }
                    }
                    .map_err(|f| (i, f))?;
                    let b = match &self.about {
                        About::CenterOfMass => b,
                        About::Point(q) => b.about(q),
                        About::PerPose(q) => b.about(&q[i]),
                    };
                    Ok(Row::new(&b))
                })
                .collect()
        };
        match pool {
            Some(p) => p.install(run),
            None => run(),
        }
    }
}
