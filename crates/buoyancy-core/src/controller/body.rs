//! One floating body: its meshes, its own settings, and the controller's bookkeeping for it.

use alloc::sync::Arc;
use alloc::vec::Vec;

use super::last_evaluation::LastEvaluation;
use super::report::FloatReport;
use super::settings::{BodyOptions, DampingResolution};
use super::share::AppliedShare;
use crate::mesh::ReducedMesh;
use crate::{Error, Mesh, Pose};

/// One closed mesh of a body, placed on it: a shape's mesh in the shape's frame, and the pose
/// of that frame in the body's frame. Bodies of the same shape share one mesh.
#[derive(Debug, Clone)]
pub struct Part {
    /// The shape's mesh, in the shape's frame.
    pub mesh: Arc<Mesh<f64>>,
    /// Shape frame → body frame.
    pub shape_to_body: Pose<f64>,
}

/// One registered body.
#[derive(Debug, Clone)]
pub(crate) struct FloatingBody {
    pub parts: Vec<Part>,
    pub options: BodyOptions,
    /// The resolution `reduced` was built with.
    pub resolution: DampingResolution,
    /// Per part, the reduced copy its pressure drag is integrated over, `None`: its own mesh.
    pub reduced: Vec<Option<Arc<ReducedMesh<f64>>>>,
    /// Total volume (m³) and surface area (m²) of the parts, for the body's angular damping.
    pub volume: f64,
    pub surface_area: f64,
    pub share: AppliedShare,
    pub report: FloatReport,
    /// The last evaluation in still water, taken again for the same inputs.
    pub last: Option<LastEvaluation>,
}

impl FloatingBody {
    /// A body of `parts`, nothing applied yet, its pressure drag integrated over the parts'
    /// own meshes until the controller gives it reduced copies.
    ///
    /// # Errors
    /// [`Error::EmptyBody`] for no parts.
    pub fn new(parts: Vec<Part>, options: BodyOptions) -> Result<Self, Error> {
        if parts.is_empty() {
            return Err(Error::EmptyBody);
        }
        let volume = parts.iter().map(|p| p.mesh.volume()).sum();
        let surface_area = parts.iter().map(|p| p.mesh.surface_area()).sum();
        Ok(FloatingBody {
            reduced: alloc::vec![None; parts.len()],
            parts,
            options,
            resolution: DampingResolution::Full,
            volume,
            surface_area,
            share: AppliedShare::default(),
            report: FloatReport::default(),
            last: None,
        })
    }

    /// The body's length scale, m: the cube root of its volume.
    pub fn size(&self) -> f64 {
        libm::cbrt(self.volume.max(0.0))
    }

    /// The wetted fraction `f` of the body's angular damping for its parts' total
    /// `wetted_area` (m²): over their total surface area, at most 1; `None` for a body of no
    /// area.
    pub fn wetted_fraction(&self, wetted_area: f64) -> Option<f64> {
        (self.surface_area > 0.0).then(|| (wetted_area / self.surface_area).min(1.0))
    }
}
