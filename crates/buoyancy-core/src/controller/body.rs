//! One floating body: its meshes, its own settings, and the controller's bookkeeping for it.

use alloc::sync::Arc;
use alloc::vec::Vec;

use super::report::FloatReport;
use super::settings::BodyOptions;
use super::share::AppliedShare;
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
    /// Total volume (m³) and surface area (m²) of the parts, for the body's angular damping.
    pub volume: f64,
    pub surface_area: f64,
    pub share: AppliedShare,
    pub report: FloatReport,
}

impl FloatingBody {
    /// A body of `parts`, nothing applied yet.
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
            parts,
            options,
            volume,
            surface_area,
            share: AppliedShare::default(),
            report: FloatReport::default(),
        })
    }

    /// The body's length scale, m: the cube root of its volume.
    pub fn size(&self) -> f64 {
        libm::cbrt(self.volume.max(0.0))
    }
}
