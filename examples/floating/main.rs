//! The main demo: a cube, a sphere and the paper's models dropped into water in rapier3d at
//! several densities. Prints the final submerged fraction, draft and attitude against theory,
//! and writes `out/floating.csv` (trajectories) and `out/floating.png` (height and tilt over time).
//!
//! ```sh
//! cargo run --release --example floating
//! ```
//!
//! The table, the CSV and the plot use one set of words (see `theory.rs`): the **draft** is the
//! depth of the body's lowest point below the surface; the **tilt** is the angle between the
//! vertical and the body axis nearest to it (for a cube 0° face down, 45° edge down, 54.7°
//! corner down). A sphere's tilt drifts: buoyancy acts through its center at every attitude, so
//! no attitude is preferred or restored (neutral equilibrium).
//!
//! The models are read from the sample meshes (`$BUOYANCY_MESHES`, else `../shared/meshes`
//! beside the repository); when absent, a procedural torus knot stands in for them.

mod plot;
#[path = "../../benches/common/plot_font.rs"]
mod plot_font;
mod theory;

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use buoyancy::nalgebra::{Point3, Quaternion, Rotation3, Translation3, UnitQuaternion, Vector3};
use buoyancy::{Mesh, mesh::primitives};
use buoyancy_rapier::{FloatOptions, FloatingBodies};
use rapier3d::prelude::*;

use plot::Track;
use theory::{Theory, cube_attitude};

const WATER_DENSITY: f64 = 1000.0;
const SECONDS: f32 = 40.0;

struct Body {
    name: String,
    density_ratio: f64,
    handle: RigidBodyHandle,
    mesh: Mesh<f64>,
    theory: Theory,
}

/// A sample model scaled to `radius` (bounding radius about its centroid) and centered, with
/// the file's z axis turned to y when `z_up`; the procedural torus knot if the file is absent.
fn model(file: &str, radius: f64, z_up: bool) -> Result<(String, Mesh<f64>), buoyancy::Error> {
    // A file that exists but does not load is an error, not a silent substitute.
    let loaded = buoyancy_samples::mesh_path(file)
        .map(buoyancy::io::load::<f64>)
        .transpose()?;
    let (name, (vertices, triangles)) = match loaded {
        Some(shape) => (file.trim_end_matches(".obj").to_string(), shape),
        None => {
            println!("note: using a procedural torus knot instead of {file}");
            (
                "torus knot (procedural)".to_string(),
                primitives::torus_knot::<f64>(2, 3, 1.0, 0.3, 256, 16)?,
            )
        }
    };
    let mesh = Mesh::new(vertices, triangles)?;
    let (center, scale) = (mesh.centroid(), radius / mesh.bounding_radius());
    let turn = if z_up {
        Rotation3::from_axis_angle(&Vector3::x_axis(), -std::f64::consts::FRAC_PI_2)
    } else {
        Rotation3::identity()
    };
    let vertices = (0..mesh.vertex_count())
        .map(|i| Point3::from(turn * (mesh.vertex(i) - center) * scale))
        .collect();
    Ok((name, Mesh::new(vertices, mesh.triangles().to_vec())?))
}

fn trimesh_collider(mesh: &Mesh<f64>) -> Result<ColliderBuilder, Box<dyn std::error::Error>> {
    let vertices = (0..mesh.vertex_count())
        .map(|i| {
            let p = mesh.vertex(i);
            Vector::new(p.x as f32, p.y as f32, p.z as f32)
        })
        .collect();
    Ok(ColliderBuilder::trimesh(
        vertices,
        mesh.triangles().to_vec(),
    )?)
}

/// The tilt, degrees: the angle between the world vertical (y) and the body axis nearest to it.
fn tilt_degrees(rotation: &Rotation) -> f64 {
    let cos = [Vector::X, Vector::Y, Vector::Z]
        .iter()
        .map(|a| (*rotation * *a).y.abs())
        .fold(0.0f32, f32::max);
    f64::from(cos.min(1.0)).acos().to_degrees()
}

/// The depth of the lowest vertex of `mesh` below the surface (y = 0) at rapier's pose of `rb`.
fn draft(mesh: &Mesh<f64>, rb: &RigidBody) -> f64 {
    let (t, r) = (rb.translation(), rb.rotation());
    let pose = buoyancy::Pose::from_parts(
        Translation3::new(t.x as f64, t.y as f64, t.z as f64),
        UnitQuaternion::from_quaternion(Quaternion::new(
            r.w as f64, r.x as f64, r.y as f64, r.z as f64,
        )),
    );
    (0..mesh.vertex_count())
        .map(|i| -(pose * mesh.vertex(i)).y)
        .fold(f64::MIN, f64::max)
}

/// `value` written by `format`, or "—" when there is none.
fn or_dash(value: Option<f64>, format: impl Fn(f64) -> String) -> String {
    value.map_or_else(|| "—".to_string(), format)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let started = Instant::now();
    let mut world = PhysicsWorld::default();
    let mut water = FloatingBodies::new(world.gravity)?;
    let mut bodies: Vec<Body> = Vec::new();

    let (v, t) = primitives::cube::<f64>(1)?;
    let cube = Mesh::new(v, t)?;
    let sphere_radius = 0.5;
    let (knot_name, knot) = model("torusknot.obj", 0.6, false)?;
    let (bunny_name, bunny) = model("bunny.obj", 0.6, false)?;
    let (armadillo_name, armadillo) = model("armadillo.obj", 0.6, true)?;
    let mut lineup: Vec<(String, f64, ColliderBuilder, Mesh<f64>, Theory, u32)> = Vec::new();
    for s in [0.1, 0.5, 0.9] {
        lineup.push((
            "cube".into(),
            s,
            ColliderBuilder::cuboid(0.5, 0.5, 0.5),
            cube.clone(),
            Theory::Cube { side: 1.0 },
            32,
        ));
    }
    for s in [0.3, 0.7] {
        let ball = ColliderBuilder::ball(sphere_radius as f32);
        let (v, t) = primitives::uv_sphere::<f64>(sphere_radius, 64, 32)?;
        lineup.push((
            "sphere".into(),
            s,
            ball,
            Mesh::new(v, t)?,
            Theory::Sphere {
                radius: sphere_radius,
            },
            64,
        ));
    }
    for s in [0.3, 0.7] {
        lineup.push((
            knot_name.clone(),
            s,
            trimesh_collider(&knot)?,
            knot.clone(),
            Theory::Model,
            0,
        ));
    }
    for s in [0.4, 0.8] {
        lineup.push((
            bunny_name.clone(),
            s,
            trimesh_collider(&bunny)?,
            bunny.clone(),
            Theory::Model,
            0,
        ));
    }
    lineup.push((
        armadillo_name.clone(),
        0.5,
        trimesh_collider(&armadillo)?,
        armadillo.clone(),
        Theory::Model,
        0,
    ));

    for (i, (name, s, collider, mesh, theory, subdivisions)) in lineup.into_iter().enumerate() {
        // In a row 3 m apart, dropped from 1 m with a small tilt so that physics picks the attitude.
        let position = Vector::new(3.0 * i as f32, 1.0, 0.0);
        let tilt = Rotation::from_axis_angle(Vector::new(1.0, 0.0, 0.4).normalize(), 0.05);
        let body = RigidBodyBuilder::dynamic()
            .pose(Pose::from_parts(position, tilt))
            .can_sleep(false);
        let (handle, _) = world.insert(body, collider.density((s * WATER_DENSITY) as f32));
        water.register(
            handle,
            &world.bodies,
            &world.colliders,
            FloatOptions::default().subdivisions(subdivisions.max(3)),
        )?;
        bodies.push(Body {
            name,
            density_ratio: s,
            handle,
            mesh,
            theory,
        });
    }

    // Simulate, recording the height of the center of mass and the tilt at 10 Hz.
    let dt = world.integration_parameters.dt;
    let steps = (SECONDS / dt).round() as usize;
    let mut csv = String::from("time_s,body,relative_density,height_m,tilt_deg\n");
    let mut tracks: Vec<Track> = bodies
        .iter()
        .map(|b| Track::new(format!("{}, s = {}", b.name, b.density_ratio)))
        .collect();
    for step in 0..=steps {
        if step % 6 == 0 {
            let t = step as f32 * dt;
            for (b, track) in bodies.iter().zip(tracks.iter_mut()) {
                let rb = &world.bodies[b.handle];
                let (height, tilt) = (rb.center_of_mass().y, tilt_degrees(rb.rotation()) as f32);
                writeln!(
                    csv,
                    "{t:.3},{},{},{height:.5},{tilt:.3}",
                    b.name, b.density_ratio
                )?;
                track.push(t, height, tilt);
            }
        }
        if step < steps {
            water.apply(&mut world.bodies, dt);
            world.step();
        }
    }
    water.apply(&mut world.bodies, dt);

    println!(
        "{} bodies, {SECONDS} s at {:.0} Hz, method Exact, default damping\n",
        bodies.len(),
        1.0 / dt
    );
    print_table(&bodies, &world, &water);

    // Outputs.
    let out = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("out");
    std::fs::create_dir_all(&out)?;
    std::fs::write(out.join("floating.csv"), csv)?;
    let png = out.join("floating.png");
    plot::plot(&png, &tracks, SECONDS)?;
    println!(
        "wrote {} and {}",
        out.join("floating.csv").display(),
        png.display()
    );
    println!(
        "plot colours, in the table's order: {}",
        plot::colour_names(bodies.len()).join(", ")
    );
    println!("finished in {:.1} s", started.elapsed().as_secs_f64());
    Ok(())
}

/// The final state of every body against theory, as a Markdown table with its footnotes.
fn print_table(bodies: &[Body], world: &PhysicsWorld, water: &FloatingBodies) {
    println!(
        "| body | s | submerged fraction | theory | error | draft (m) | theory | error (m) | tilt (°) | theory | attitude | theory | CoB–CoM horizontal (mm) |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let mut worst_fraction_error: f64 = 0.0;
    for b in bodies {
        let rb = &world.bodies[b.handle];
        let report = water.report(b.handle).expect("registered");
        let fraction = report.submerged_volume / b.mesh.volume();
        // rapier's mass over the mesh's volume: the realised relative density.
        let s = rb.mass() as f64 / WATER_DENSITY / b.mesh.volume();
        worst_fraction_error = worst_fraction_error.max((fraction - s).abs());
        let draft = draft(&b.mesh, rb);
        let tilt = tilt_degrees(rb.rotation());
        let predicted = b.theory.predict(s);
        let attitude = match b.theory {
            Theory::Cube { .. } => cube_attitude(tilt),
            Theory::Sphere { .. } | Theory::Model => "—",
        };
        let offset = report.center_of_buoyancy - report.center_of_mass;
        let horizontal_mm = Vector3::new(offset.x, 0.0, offset.z).norm() * 1000.0;
        println!(
            "| {} | {:.2} | {fraction:.5} | {s:.5} | {:+.1e} | {draft:.4} | {} | {} | {tilt:.1} | {} | {attitude} | {} | {horizontal_mm:.2} |",
            b.name,
            b.density_ratio,
            fraction - s,
            or_dash(predicted.draft, |d| format!("{d:.4}")),
            or_dash(predicted.draft, |d| format!("{:+.1e}", draft - d)),
            or_dash(predicted.tilt_degrees, |t| format!("{t:.1}")),
            predicted.attitude,
        );
    }
    println!(
        "\nlargest |submerged fraction − relative density|: {worst_fraction_error:.1e}\n\n\
         s: the relative density ρ_body/ρ_water as set. Theory of the submerged fraction (Archimedes): the\n   \
         realised s, rapier's mass over the volume of the mesh the body floats with (a sphere's mesh is\n   \
         inscribed in rapier's ball).\n\
         draft: the depth of the body's lowest point below the surface.\n\
         tilt: the angle between the vertical and the body axis nearest to it, 0° to 54.7° (a cube: 0° face\n   \
         down, 45° edge down, 54.7° corner down); the plot shows the same angle.\n\
         cube, s = 0.5: every plane through its center halves it, so its center sits at the surface in any\n   \
         attitude, and it settles where its center of buoyancy is shallowest: corner down, a body diagonal\n   \
         vertical, draft √3/2 of the side, tilt arccos(1/√3) = 54.7° (cubes with 0.21 < s < 0.79 tip; at\n   \
         s = 0.1 and 0.9 face down is stable, draft s).\n\
         sphere: buoyancy acts through its center at every attitude, so no attitude is preferred or restored\n   \
         (neutral equilibrium): its tilt drifts with the small torques of the faceted mesh it floats with.\n"
    );
}
