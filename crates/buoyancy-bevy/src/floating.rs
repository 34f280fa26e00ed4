//! The components a game puts on and reads off a floating entity: [`Floating`] and
//! [`FloatReport`].

use std::sync::Arc;

use bevy::math::Vec3;
use bevy::prelude::Component;
use buoyancy_core::controller::{self, DampingResolution, Outcome, Part};
use buoyancy_core::nalgebra::{Point3, Vector3};
use buoyancy_core::{DampingCoefficients, Mesh, Method, Pose};

/// Makes the entity's rigid body float in the [`Water`](crate::Water).
///
/// The entity needs the backend's rigid body and, unless `mesh` is given, colliders: the
/// body's own collider and its child colliders (compound shapes included) are meshed as
/// `buoyancy-rapier` meshes them ([`ShapeMeshes`](buoyancy_rapier::ShapeMeshes): cuboids,
/// convex hulls and trimeshes exactly; balls, capsules, cylinders and cones with
/// `subdivisions` segments around). Changing the component re-registers the body; removing it
/// (or despawning the entity) takes the buoyancy off.
///
/// ```
/// use buoyancy_bevy::Floating;
/// use buoyancy_core::Method;
///
/// let floating = Floating { method: Some(Method::Fast), ..Floating::default() };
/// assert_eq!(floating.subdivisions, 32);
/// ```
#[derive(Component, Clone, Debug)]
#[require(FloatReport)]
pub struct Floating {
    /// The buoyancy method; `None`: exact ([`Method::Exact`]).
    pub method: Option<Method>,
    /// The hydrodynamic damping; `None`: the core's defaults ([`DampingCoefficients::default`]).
    pub damping: Option<DampingCoefficients<f64>>,
    /// How finely the pressure drag is integrated; `None`: a reduced copy of at most 384
    /// triangles of each larger mesh ([`DampingResolution::DEFAULT`]).
    pub damping_resolution: Option<DampingResolution>,
    /// A closed mesh in the rigid body's frame (its `Transform`'s, not its center of mass's) to
    /// float with instead of the colliders.
    pub mesh: Option<Arc<Mesh<f64>>>,
    /// Segments around balls, capsules, cylinders and cones (half as many from pole to pole).
    pub subdivisions: u32,
}

impl Default for Floating {
    fn default() -> Self {
        Floating {
            method: None,
            damping: None,
            damping_resolution: None,
            mesh: None,
            subdivisions: 32,
        }
    }
}

impl Floating {
    /// Floats with `mesh` (closed, in the rigid body's frame) instead of the colliders.
    pub fn with_mesh(mesh: Mesh<f64>) -> Self {
        Floating {
            mesh: Some(Arc::new(mesh)),
            ..Floating::default()
        }
    }

    /// The explicit mesh as the controller's one part, if any.
    pub(crate) fn mesh_part(&self) -> Option<Part> {
        self.mesh.as_ref().map(|mesh| Part {
            mesh: mesh.clone(),
            shape_to_body: Pose::identity(),
        })
    }
}

/// What the water did to the entity at the last physics step, for HUDs and game logic
/// (splashes, "is swimming"); inserted with [`Floating`]. World frame, SI units.
#[derive(Component, Clone, Debug, Default)]
pub struct FloatReport {
    /// Volume under water, m³.
    pub submerged_volume: f64,
    /// Wetted area over the whole surface area of the body's meshes, 0 to 1.
    pub wetted_fraction: f64,
    /// Depth of the body's lowest point below the still water level, m (negative when it is
    /// clear of the water).
    pub draft: f64,
    /// Whether the body is under water at all.
    pub in_water: bool,
    /// Everything the controller computed: forces, torques, centers, the outcome.
    pub report: controller::FloatReport,
    /// Why the entity does not float, when it cannot (the message logged once).
    pub error: Option<String>,
}

impl FloatReport {
    /// The report of a step: the controller's, with the wetted fraction over `total_area` and
    /// the draft of `lowest` (the lowest point, world frame) below the still plane of `water`.
    pub(crate) fn of(
        report: &controller::FloatReport,
        total_area: f64,
        lowest: Option<Point3<f64>>,
        water: &buoyancy_core::Water<f64>,
    ) -> Self {
        FloatReport {
            submerged_volume: report.submerged_volume,
            wetted_fraction: if total_area > 0.0 {
                (report.wetted_area / total_area).clamp(0.0, 1.0)
            } else {
                0.0
            },
            draft: lowest.map_or(0.0, |p| -water.height(&p)),
            in_water: report.submerged_volume > 0.0,
            report: *report,
            error: None,
        }
    }

    /// The report of an entity that cannot float, saying why.
    pub(crate) fn failed(message: String) -> Self {
        FloatReport {
            report: controller::FloatReport {
                outcome: Outcome::NotEvaluated,
                ..Default::default()
            },
            error: Some(message),
            ..Default::default()
        }
    }
}

/// What the plugin keeps of a body's parts for its report: their total surface area and the
/// vertices of their convex hulls in the body frame (the lowest point of a mesh along any
/// direction is one of them).
#[derive(Clone, Debug, Default)]
pub(crate) struct Outline {
    pub area: f64,
    pub hull: Vec<Point3<f64>>,
}

impl Outline {
    pub fn of<'a>(parts: impl IntoIterator<Item = (&'a Mesh<f64>, &'a Pose<f64>)>) -> Self {
        let mut area = 0.0;
        let mut points: Vec<Point3<f64>> = Vec::new();
        for (mesh, shape_to_body) in parts {
            area += mesh.surface_area();
            points.extend((0..mesh.vertex_count()).map(|i| shape_to_body * mesh.vertex(i)));
        }
        // parry's hull (in f32) picks the vertices; they are kept in f64.
        let rounded: Vec<Vec3> = points
            .iter()
            .map(|p| Vec3::new(p.x as f32, p.y as f32, p.z as f32))
            .collect();
        let hull = if rounded.len() >= 4 {
            let (vertices, _) = rapier3d::parry::transformation::convex_hull(&rounded);
            let mut hull: Vec<Point3<f64>> = vertices
                .iter()
                .filter_map(|v| rounded.iter().position(|r| r == v).map(|i| points[i]))
                .collect();
            if hull.is_empty() {
                hull = points;
            }
            hull
        } else {
            points
        };
        Outline { area, hull }
    }

    /// The lowest hull vertex along `up` at `pose` (world frame): the vertex `p` (body frame)
    /// of least `(R⁻¹ up) · p`, `R` the pose's rotation, so that only `up` and the one vertex
    /// found are transformed.
    pub fn lowest(&self, pose: &Pose<f64>, up: &Vector3<f64>) -> Option<Point3<f64>> {
        let local_up = pose.rotation.inverse_transform_vector(up);
        let (first, rest) = self.hull.split_first()?;
        let mut lowest = (first, local_up.dot(&first.coords));
        for p in rest {
            let height = local_up.dot(&p.coords);
            if height < lowest.1 {
                lowest = (p, height);
            }
        }
        Some(pose * lowest.0)
    }
}
