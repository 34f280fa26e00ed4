//! The harbor's bodies, described once and spawned on either backend: three crates, a disc
//! buoy, a Wigley hull and (when the sample meshes are at hand) the Stanford bunny, each with
//! the draft the water should give it in calm water, from an independent computation.

use std::sync::Arc;

use bevy::prelude::*;
use buoyancy_bevy::Floating;
use buoyancy_core::hydrostatics::LoadingCondition;
use buoyancy_core::nalgebra::Point3;
use buoyancy_core::{Mesh, mesh::primitives};

/// Segments around the buoy's cylinder (the plugin's default for round colliders).
const SEGMENTS: u32 = 32;

/// A body's collider.
#[derive(Clone, Debug)]
pub enum Shape {
    /// A box of these half extents, m.
    Cuboid(Vec3),
    /// A cylinder about the body's y axis.
    Cylinder { radius: f32, half_height: f32 },
    /// The convex hull of these points (body frame), for contacts; the body floats with its
    /// exact mesh ([`Body::mesh`]).
    Hull(Vec<Vec3>),
}

/// A body's mass properties.
#[derive(Clone, Debug)]
pub enum BodyMass {
    /// From the collider at this density, kg/m³ (the engine computes them).
    Density(f32),
    /// Given: mass (kg), center of mass (body frame, m) and principal inertia (kg·m², about the
    /// body's axes).
    Given {
        mass: f32,
        center: Vec3,
        inertia: Vec3,
    },
}

/// One body of the harbor.
#[derive(Clone, Debug)]
pub struct Body {
    pub name: &'static str,
    pub shape: Shape,
    pub mass: BodyMass,
    /// The mass the engine will hold, kg (for the table).
    pub mass_kg: f64,
    /// The closed mesh the body floats with and is drawn with (body frame).
    pub mesh: Arc<Mesh<f64>>,
    /// Whether [`Floating`] carries `mesh` (else the plugin meshes the collider).
    pub explicit_mesh: bool,
    /// Depth of the lowest point below the still level at rest in calm water, m.
    pub draft: f64,
    /// How `draft` was computed.
    pub theory: &'static str,
    pub start: Transform,
    /// sRGB, 0 to 1 (drawn with the `render` feature).
    #[cfg_attr(not(feature = "display"), allow(dead_code))]
    pub color: [f32; 3],
}

impl Body {
    /// The body's mean density, kg/m³: its mass over its mesh's volume.
    #[cfg_attr(not(feature = "web"), allow(dead_code))]
    pub fn mean_density(&self) -> f64 {
        self.mass_kg / self.mesh.volume()
    }

    /// The [`Floating`] component of this body.
    pub fn floating(&self) -> Floating {
        if self.explicit_mesh {
            Floating {
                mesh: Some(self.mesh.clone()),
                ..Floating::default()
            }
        } else {
            Floating::default()
        }
    }
}

/// Marks a spawned harbor body: its index in the scene.
#[derive(Component, Clone, Copy, Debug)]
pub struct HarborBody(pub usize);

/// The mesh of a shape of the core.
fn closed(
    shape: Result<primitives::Shape<f64>, buoyancy_core::Error>,
) -> Result<Mesh<f64>, buoyancy_core::Error> {
    let (vertices, triangles) = shape?;
    Mesh::new(vertices, triangles)
}

fn points(mesh: &Mesh<f64>) -> Vec<Vec3> {
    (0..mesh.vertex_count())
        .map(|i| {
            let p = mesh.vertex(i);
            Vec3::new(p.x as f32, p.y as f32, p.z as f32)
        })
        .collect()
}

/// Principal inertia of a solid box of mass `mass` and these full sizes, kg·m².
fn box_inertia(mass: f64, size: Vec3) -> Vec3 {
    let (x, y, z) = (f64::from(size.x), f64::from(size.y), f64::from(size.z));
    let k = mass / 12.0;
    Vec3::new(
        (k * (y * y + z * z)) as f32,
        (k * (x * x + z * z)) as f32,
        (k * (x * x + y * y)) as f32,
    )
}

fn bounds(mesh: &Mesh<f64>) -> (Point3<f64>, Point3<f64>) {
    let mut low = Point3::new(f64::MAX, f64::MAX, f64::MAX);
    let mut high = Point3::new(f64::MIN, f64::MIN, f64::MIN);
    for i in 0..mesh.vertex_count() {
        let p = mesh.vertex(i);
        low = low.inf(&p);
        high = high.sup(&p);
    }
    (low, high)
}

/// A body whose given mass and center of gravity float it: the draft is the equilibrium the
/// core's hydrostatic solver finds (a static solution, not the simulation).
fn mesh_body(
    name: &'static str,
    mesh: Mesh<f64>,
    mass: f64,
    center: Point3<f64>,
    density: f64,
    start: Vec3,
    color: [f32; 3],
) -> Result<Body, buoyancy_core::Error> {
    let water =
        buoyancy_core::Water::new(density, 9.81, buoyancy_core::nalgebra::Vector3::y(), 0.0)?;
    let loading = LoadingCondition::new(center)?.with_mass(mass)?;
    let rest = mesh.equilibrium(&water, &loading)?;
    let (low, high) = bounds(&mesh);
    let size = high - low;
    Ok(Body {
        name,
        shape: Shape::Hull(points(&mesh)),
        mass: BodyMass::Given {
            mass: mass as f32,
            center: Vec3::new(center.x as f32, center.y as f32, center.z as f32),
            // The bounding box's: the rest pose does not depend on it.
            inertia: box_inertia(mass, Vec3::new(size.x as f32, size.y as f32, size.z as f32)),
        },
        mass_kg: mass,
        mesh: Arc::new(mesh),
        explicit_mesh: true,
        draft: rest.draft,
        theory: "hydrostatic equilibrium (core solver)",
        start: Transform::from_translation(start + Vec3::Y * (-low.y as f32 - rest.draft as f32)),
        color,
    })
}

/// The harbor in water of `density`: crates of three densities, a buoy, a hull and, given its
/// OBJ text, the bunny.
pub fn harbor(density: f64, bunny_obj: Option<&str>) -> Result<Vec<Body>, buoyancy_core::Error> {
    let mut bodies = Vec::new();
    // Crates 1.2 m × 0.5 m × 0.8 m, floating flat: draft = h·ρ_crate/ρ.
    let half = Vec3::new(0.6, 0.25, 0.4);
    for (i, (name, crate_density, color)) in [
        ("light crate", 250.0f32, [0.85, 0.65, 0.35]),
        ("crate", 500.0, [0.7, 0.45, 0.2]),
        ("heavy crate", 750.0, [0.5, 0.3, 0.15]),
    ]
    .into_iter()
    .enumerate()
    {
        let height = 2.0 * f64::from(half.y);
        let draft = height * f64::from(crate_density) / density;
        let mesh = closed(primitives::cuboid([
            f64::from(half.x),
            f64::from(half.y),
            f64::from(half.z),
        ]))?;
        bodies.push(Body {
            name,
            shape: Shape::Cuboid(half),
            mass: BodyMass::Density(crate_density),
            mass_kg: f64::from(crate_density) * 8.0 * f64::from(half.x * half.y * half.z),
            mesh: Arc::new(mesh),
            explicit_mesh: false,
            draft,
            theory: "h·ρ_body/ρ",
            start: Transform::from_xyz(
                -5.0 + 2.5 * i as f32,
                f64::from(half.y) as f32 - draft as f32 + 0.3,
                -3.0,
            ),
            color,
        });
    }
    // A disc buoy, radius 0.75 m, 0.6 m high, density 500, upright: the engine's mass is the
    // cylinder's, the displaced water the 32-gon prism's, so draft = m/(ρ·A₃₂) with
    // A₃₂ = (n/2)·r²·sin(2π/n).
    let (radius, half_height, buoy_density) = (0.75f64, 0.3f64, 500.0f64);
    let mass = buoy_density * core::f64::consts::PI * radius * radius * 2.0 * half_height;
    let n = f64::from(SEGMENTS);
    let polygon = n / 2.0 * radius * radius * (core::f64::consts::TAU / n).sin();
    let draft = mass / (density * polygon);
    let mesh = closed(primitives::cylinder(radius, half_height, SEGMENTS as usize))?;
    bodies.push(Body {
        name: "buoy",
        shape: Shape::Cylinder {
            radius: radius as f32,
            half_height: half_height as f32,
        },
        mass: BodyMass::Density(buoy_density as f32),
        mass_kg: mass,
        mesh: Arc::new(mesh),
        explicit_mesh: false,
        draft,
        theory: "m/(ρ·A₃₂), the 32-gon's area",
        start: Transform::from_xyz(4.0, (half_height - draft) as f32 + 0.3, -3.0),
        color: [0.9, 0.2, 0.15],
    });
    // A Wigley hull 6 m long (along x), beam 0.8 m, design draft 0.4 m, freeboard 0.3 m, at
    // 85 % of its design displacement, its center of gravity 0.25 m above the keel.
    let hull = closed(primitives::wigley_hull(6.0, 0.8, 0.4, 0.3, 24, 8))?;
    let design = 4.0 * 6.0 * 0.8 * 0.4 / 9.0 * density;
    bodies.push(mesh_body(
        "Wigley hull",
        hull,
        0.85 * design,
        Point3::new(0.0, -0.15, 0.0),
        density,
        Vec3::new(-2.0, 0.3, 3.0),
        [0.92, 0.92, 0.88],
    )?);
    // The Stanford bunny, scaled to 1.2 m, density 400 with its center of gravity a tenth of
    // its height below its centroid (ballast keeps it upright).
    if let Some(text) = bunny_obj {
        let raw = closed(buoyancy_core::io::parse_obj(text))?;
        let (low, high) = bounds(&raw);
        let scale = 1.2 / (high - low).max();
        let centroid = raw.centroid();
        let bunny = raw
            .translated(&-centroid.coords)?
            .scaled(&buoyancy_core::nalgebra::Vector3::repeat(scale))?;
        let (low, high) = bounds(&bunny);
        let mass = 400.0 * bunny.volume();
        let center = Point3::new(0.0, -0.1 * (high.y - low.y), 0.0);
        bodies.push(mesh_body(
            "bunny",
            bunny,
            mass,
            center,
            density,
            Vec3::new(4.0, 0.3, 3.0),
            [0.75, 0.7, 0.65],
        )?);
    }
    Ok(bodies)
}
