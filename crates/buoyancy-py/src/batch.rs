//! `Mesh.buoyancy_batch`'s evaluation: K poses on rayon's threads, without the interpreter lock.

use buoyancy_core::nalgebra::Point3;
use buoyancy_core::{Error, Mesh, Method, Pose, Traversal, Water};
use pyo3::prelude::*;
use rayon::prelude::*;

use crate::convert::{self, floats, shape_str};
use crate::errors::arg_error;
use crate::result::Row;

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

/// What one batch computes: the mesh at each pose, in one water, by one method and traversal.
pub struct Batch<'a> {
    pub mesh: &'a Mesh<f64>,
    pub poses: Vec<Pose<f64>>,
    pub water: Water<f64>,
    pub method: Method,
    pub traversal: Traversal,
    pub about: About,
}

impl Batch<'_> {
    /// The result of every pose, in order, computed in parallel on `pool` (rayon's global pool
    /// when `None`); the first failing pose's index and error otherwise. Each pose gives exactly
    /// what a single evaluation gives, whatever the thread count.
    pub fn run(&self, pool: Option<&rayon::ThreadPool>) -> Result<Vec<Row>, (usize, Error)> {
        let run = || {
            self.poses
                .par_iter()
                .enumerate()
                .map(|(i, pose)| {
                    let b = self
                        .mesh
                        .buoyancy_with(pose, &self.water, self.method, self.traversal)
                        .map_err(|e| (i, e))?;
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
