//! The main demo: a cube, a sphere and the paper's models dropped into water in rapier3d at
//! several densities. Prints the final submerged fraction, draft and attitude against theory,
//! and writes `out/floating.csv` (trajectories) and `out/floating.png` (height and tilt over time).
//!
//! ```sh
//! cargo run --release --example floating
//! ```
//!
//! The models are read from `../shared/meshes` beside the repository or from `$BUOYANCY_MESHES`;
//! when absent, a procedural torus knot stands in for them.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use buoyancy::nalgebra::{Point3, Rotation3, Vector3};
use buoyancy::{Mesh, shape};
use buoyancy_rapier::{FloatOptions, FloatingBodies};
use plotters::prelude::*;
use rapier3d::prelude::*;

#[path = "../benches/common/plot_text.rs"]
mod plot_text;

const WATER_DENSITY: f64 = 1000.0;
const SECONDS: f32 = 40.0;

/// What theory says about a body's final state.
enum Theory {
    /// A unit-side cube: upright with draft s·side when GM = s/2 + 1/(12s) − 1/2 > 0, else tipped.
    Cube { side: f64 },
    /// A sphere of this radius: the cap of volume s·V, draft d with π d²(3R − d)/3 = s·4πR³/3.
    Sphere { radius: f64 },
    /// Any other body: only the submerged fraction and the vertical alignment are predicted.
    Model,
}

struct Body {
    name: String,
    density_ratio: f64,
    handle: RigidBodyHandle,
    mesh: Mesh<f64>,
    theory: Theory,
}

fn meshes_dir() -> Option<PathBuf> {
    let dir = std::env::var_os("BUOYANCY_MESHES")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/meshes"));
    dir.is_dir().then_some(dir)
}

/// A shared model scaled to `radius` (bounding radius about its centroid) and centered, with
/// `up` the file's up axis turned to y; the procedural torus knot if the file is absent.
fn model(file: &str, radius: f64, z_up: bool) -> (String, Mesh<f64>) {
    let loaded = meshes_dir().and_then(|d| buoyancy::io::load::<f64>(d.join(file)).ok());
    let (name, (vertices, triangles)) = match loaded {
        Some(shape) => (file.trim_end_matches(".obj").to_string(), shape),
        None => {
            println!(
                "note: {file} not found (set BUOYANCY_MESHES); using a procedural torus knot instead"
            );
            (
                "torus knot (procedural)".to_string(),
                shape::torus_knot::<f64>(2, 3, 1.0, 0.3, 256, 16).unwrap(),
            )
        }
    };
    let mesh = Mesh::new(vertices, triangles).expect("a closed mesh");
    let (center, scale) = (mesh.centroid(), radius / mesh.bounding_radius());
    let turn = if z_up {
        Rotation3::from_axis_angle(&Vector3::x_axis(), -std::f64::consts::FRAC_PI_2)
    } else {
        Rotation3::identity()
    };
    let vertices = (0..mesh.vertex_count())
        .map(|i| Point3::from(turn * (mesh.vertex(i) - center) * scale))
        .collect();
    (
        name,
        Mesh::new(vertices, mesh.triangles().to_vec()).expect("a closed mesh"),
    )
}

fn trimesh_collider(mesh: &Mesh<f64>) -> ColliderBuilder {
    let vertices = (0..mesh.vertex_count())
        .map(|i| {
            let p = mesh.vertex(i);
            Vector::new(p.x as f32, p.y as f32, p.z as f32)
        })
        .collect();
    ColliderBuilder::trimesh(vertices, mesh.triangles().to_vec()).expect("a valid trimesh")
}

/// Draft of the analytic sphere: the depth d of the cap holding s of its volume (bisection).
fn sphere_draft(radius: f64, s: f64) -> f64 {
    let target = 4.0 * s * radius.powi(3);
    let (mut lo, mut hi) = (0.0, 2.0 * radius);
    for _ in 0..100 {
        let d = 0.5 * (lo + hi);
        if d * d * (3.0 * radius - d) < target {
            lo = d
        } else {
            hi = d
        }
    }
    0.5 * (lo + hi)
}

/// Angle in degrees between the world vertical and the body axis closest to it.
fn tilt_to_nearest_axis(rotation: &Rotation) -> f64 {
    let cos = [Vector::X, Vector::Y, Vector::Z]
        .iter()
        .map(|a| (*rotation * *a).y.abs())
        .fold(0.0f32, f32::max);
    f64::from(cos.min(1.0)).acos().to_degrees()
}

/// Angle in degrees between the world vertical and the body's own y axis.
fn tilt_of_y_axis(rotation: &Rotation) -> f64 {
    f64::from((*rotation * Vector::Y).y.clamp(-1.0, 1.0))
        .acos()
        .to_degrees()
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let started = Instant::now();
    let mut world = PhysicsWorld::default();
    let mut water = FloatingBodies::new(world.gravity)?;
    let mut bodies: Vec<Body> = Vec::new();

    let (v, t) = shape::cube::<f64>(1)?;
    let cube = Mesh::new(v, t)?;
    let sphere_radius = 0.5;
    let (knot_name, knot) = model("torusknot.obj", 0.6, false);
    let (bunny_name, bunny) = model("bunny.obj", 0.6, false);
    let (armadillo_name, armadillo) = model("armadillo.obj", 0.6, true);
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
        let (v, t) = shape::uv_sphere::<f64>(sphere_radius, 64, 32)?;
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
            trimesh_collider(&knot),
            knot.clone(),
            Theory::Model,
            0,
        ));
    }
    for s in [0.4, 0.8] {
        lineup.push((
            bunny_name.clone(),
            s,
            trimesh_collider(&bunny),
            bunny.clone(),
            Theory::Model,
            0,
        ));
    }
    lineup.push((
        armadillo_name.clone(),
        0.5,
        trimesh_collider(&armadillo),
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

    // Simulate, recording height of the center of mass and tilt at 10 Hz.
    let dt = world.integration_parameters.dt;
    let steps = (SECONDS / dt).round() as usize;
    let mut csv = String::from("time_s,body,relative_density,height_m,tilt_deg\n");
    let mut series: Vec<Vec<(f32, f32, f32)>> = vec![Vec::new(); bodies.len()];
    for step in 0..=steps {
        if step % 6 == 0 {
            let t = step as f32 * dt;
            for (b, points) in bodies.iter().zip(series.iter_mut()) {
                let rb = &world.bodies[b.handle];
                let (height, tilt) = (rb.center_of_mass().y, tilt_of_y_axis(rb.rotation()) as f32);
                writeln!(
                    csv,
                    "{t:.3},{},{},{height:.5},{tilt:.3}",
                    b.name, b.density_ratio
                )?;
                points.push((t, height, tilt));
            }
        }
        if step < steps {
            water.apply(&mut world.bodies, dt);
            world.step();
        }
    }
    water.apply(&mut world.bodies, dt);

    // The table.
    println!(
        "{} bodies, {SECONDS} s at {:.0} Hz, method Exact, default damping\n",
        bodies.len(),
        1.0 / dt
    );
    println!(
        "| body | s = ρ_body/ρ | submerged fraction | theory | error | draft (m) | theory draft (m) | error (m) | CoB–CoM horizontal (mm) | tilt (°) | attitude | theory |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|");
    let mut worst_fraction_error: f64 = 0.0;
    for b in &bodies {
        let rb = &world.bodies[b.handle];
        let report = water.report(b.handle).expect("registered");
        let fraction = report.submerged_volume / b.mesh.volume();
        // rapier's mass over the mesh's volume: the realised relative density.
        let s = rb.mass() as f64 / WATER_DENSITY / b.mesh.volume();
        worst_fraction_error = worst_fraction_error.max((fraction - s).abs());
        let pose = buoyancy::Pose::from_parts(
            buoyancy::nalgebra::Translation3::new(
                rb.translation().x as f64,
                rb.translation().y as f64,
                rb.translation().z as f64,
            ),
            buoyancy::nalgebra::UnitQuaternion::from_quaternion(
                buoyancy::nalgebra::Quaternion::new(
                    rb.rotation().w as f64,
                    rb.rotation().x as f64,
                    rb.rotation().y as f64,
                    rb.rotation().z as f64,
                ),
            ),
        );
        let draft = (0..b.mesh.vertex_count())
            .map(|i| -(pose * b.mesh.vertex(i)).y)
            .fold(f64::MIN, f64::max);
        let offset = report.center_of_buoyancy - report.center_of_mass;
        let horizontal_mm = Vector3::new(offset.x, 0.0, offset.z).norm() * 1000.0;
        let tilt = tilt_to_nearest_axis(rb.rotation());
        let attitude = match (&b.theory, tilt < 1.0) {
            (Theory::Cube { .. }, true) => "upright",
            (Theory::Cube { .. }, false) => "tipped",
            _ => "—",
        };
        let (theory_draft, theory_attitude) = match b.theory {
            Theory::Cube { side } => {
                let gm = s / 2.0 + 1.0 / (12.0 * s) - 0.5;
                if gm > 0.0 {
                    (Some(s * side), "upright")
                } else {
                    (None, "tipped")
                }
            }
            Theory::Sphere { radius } => (Some(sphere_draft(radius, s)), "—"),
            Theory::Model => (None, "—"),
        };
        let (theory_draft_text, draft_error_text) = match theory_draft {
            Some(d) => (format!("{d:.4}"), format!("{:+.1e}", draft - d)),
            None => ("—".to_string(), "—".to_string()),
        };
        println!(
            "| {} | {:.2} | {:.5} | {:.5} | {:+.1e} | {:.4} | {} | {} | {:.2} | {:.1} | {} | {} |",
            b.name,
            b.density_ratio,
            fraction,
            s,
            fraction - s,
            draft,
            theory_draft_text,
            draft_error_text,
            horizontal_mm,
            tilt,
            attitude,
            theory_attitude
        );
    }
    println!("\nlargest |submerged fraction − relative density|: {worst_fraction_error:.1e}");

    // Outputs.
    let out = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("out");
    std::fs::create_dir_all(&out)?;
    std::fs::write(out.join("floating.csv"), csv)?;
    let png = out.join("floating.png");
    let names: Vec<String> = bodies
        .iter()
        .map(|b| format!("{}, s = {}", b.name, b.density_ratio))
        .collect();
    plot(&png, &series, &names)?;
    println!(
        "wrote {} and {}",
        out.join("floating.csv").display(),
        png.display()
    );
    println!(
        "plot colours, in the table's order: {}",
        PALETTE_NAMES[..bodies.len().min(PALETTE_NAMES.len())].join(", ")
    );
    println!("finished in {:.1} s", started.elapsed().as_secs_f64());
    Ok(())
}

const PALETTE: [RGBColor; 12] = [
    RGBColor(230, 25, 75),
    RGBColor(60, 180, 75),
    RGBColor(0, 130, 200),
    RGBColor(245, 130, 48),
    RGBColor(145, 30, 180),
    RGBColor(70, 240, 240),
    RGBColor(240, 50, 230),
    RGBColor(128, 128, 0),
    RGBColor(0, 128, 128),
    RGBColor(170, 110, 40),
    RGBColor(128, 0, 0),
    RGBColor(0, 0, 128),
];
const PALETTE_NAMES: [&str; 12] = [
    "red", "green", "blue", "orange", "purple", "cyan", "magenta", "olive", "teal", "brown",
    "maroon", "navy",
];

/// Pixel sizes of the plot: the image, the legend column on the right, the title band and
/// each panel's margins around its chart (for its caption, tick labels and axis titles).
const SIZE: (u32, u32) = (1400, 880);
const LEGEND_WIDTH: u32 = 270;
const TITLE_HEIGHT: u32 = 44;
const MARGIN: (i32, i32, i32, i32) = (34, 44, 40, 112); // top, right, bottom, left

/// Two panels sharing the time axis: top, the height of each center of mass over time (the
/// black line is the water surface); bottom, the tilt of each body's y axis, 0–180°. The legend
/// names the bodies in the table's order. Text is drawn with the built-in bitmap font.
fn plot(
    path: &std::path::Path,
    series: &[Vec<(f32, f32, f32)>],
    names: &[String],
) -> Result<(), Box<dyn std::error::Error>> {
    use plot_text::{Style, draw};
    use plotters::style::text_anchor::{HPos, VPos};

    let root = BitMapBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE)?;
    let (plots, legend) = root.split_horizontally(SIZE.0 - LEGEND_WIDTH);
    let (_, panels) = plots.split_vertically(TITLE_HEIGHT);
    let (top, bottom) = panels.split_vertically((SIZE.1 - TITLE_HEIGHT) / 2 - 10);
    let text = Style::new(2, BLACK);
    let grey = RGBColor(220, 220, 220);

    let heights = series.iter().flatten().map(|p| p.1);
    let (lo, hi) = heights.fold((0.0f32, 0.0f32), |(lo, hi), h| (lo.min(h), hi.max(h)));
    let panels = [
        (
            &top,
            (lo - 0.1)..(hi + 0.1),
            1usize,
            "Height of each body's center of mass (black: the water surface)",
            "height (m)",
        ),
        (
            &bottom,
            -5.0f32..185.0,
            2usize,
            "Tilt of each body's own y axis from the vertical",
            "tilt (°)",
        ),
    ];
    let mut plot_left = 0;
    for (area, range, pick, caption, y_title) in panels {
        let (top_margin, right, bottom_margin, left) = MARGIN;
        let bottom_margin = if pick == 2 {
            bottom_margin + 26
        } else {
            bottom_margin
        };
        let mut chart = ChartBuilder::on(area)
            .margin_top(top_margin)
            .margin_right(right)
            .margin_bottom(bottom_margin)
            .margin_left(left)
            .build_cartesian_2d(0.0f32..SECONDS, range.clone())?;
        let (x0, y0) = chart.backend_coord(&(0.0, range.end));
        let (x1, y1) = chart.backend_coord(&(SECONDS, range.start));
        plot_left = x0;

        // Grid, ticks and their labels: every 5 s; heights every "nice" step, tilt every 45°.
        let (y_ticks, decimals) = if pick == 1 {
            nice_ticks(range.clone(), 7)
        } else {
            ((0..=4).map(|i| 45.0 * i as f32).collect(), 0)
        };
        for t in (0..=SECONDS as i32).step_by(5) {
            let t = t as f32;
            chart.draw_series(LineSeries::new([(t, range.start), (t, range.end)], grey))?;
            let (x, _) = chart.backend_coord(&(t, range.start));
            root.draw(&PathElement::new([(x, y1), (x, y1 + 5)], BLACK))?;
            draw(
                &root,
                &format!("{t}"),
                (x, y1 + 10),
                text.anchor(HPos::Center, VPos::Top),
            )?;
        }
        for &v in &y_ticks {
            chart.draw_series(LineSeries::new([(0.0, v), (SECONDS, v)], grey))?;
            let (_, y) = chart.backend_coord(&(0.0, v));
            root.draw(&PathElement::new([(x0 - 5, y), (x0, y)], BLACK))?;
            let label = format!("{v:.decimals$}").replace('-', "−");
            let label = if pick == 2 {
                format!("{label}°")
            } else {
                label
            };
            draw(
                &root,
                &label,
                (x0 - 10, y),
                text.anchor(HPos::Right, VPos::Center),
            )?;
        }
        draw(
            &root,
            caption,
            (x0, y0 - 12),
            text.anchor(HPos::Left, VPos::Bottom),
        )?;
        draw(
            &root,
            y_title,
            (x0 - 78, (y0 + y1) / 2),
            text.anchor(HPos::Center, VPos::Top).up(),
        )?;
        if pick == 2 {
            draw(
                &root,
                "time (s)",
                ((x0 + x1) / 2, y1 + 36),
                text.anchor(HPos::Center, VPos::Top),
            )?;
        }

        let zero = if pick == 1 { 0.0 } else { 90.0 };
        chart.draw_series(LineSeries::new(
            [(0.0, zero), (SECONDS, zero)],
            BLACK.stroke_width(1),
        ))?;
        for (i, points) in series.iter().enumerate() {
            let colour = PALETTE[i % PALETTE.len()];
            chart.draw_series(LineSeries::new(
                points
                    .iter()
                    .map(|p| (p.0, if pick == 1 { p.1 } else { p.2 })),
                colour.stroke_width(2),
            ))?;
        }
        root.draw(&Rectangle::new([(x0, y0), (x1, y1)], BLACK))?;
    }

    draw(
        &root,
        &format!(
            "{} bodies dropped into still water in rapier3d, buoyancy by the Exact method",
            series.len()
        ),
        (plot_left, TITLE_HEIGHT as i32 - 6),
        Style::new(3, BLACK).anchor(HPos::Left, VPos::Bottom),
    )?;

    // The legend: a line of each colour and the body's name and relative density.
    let (lx, ly) = legend.get_base_pixel();
    let (lx, mut y) = (lx + 10, ly + TITLE_HEIGHT as i32 + MARGIN.0);
    draw(&root, "body, relative density", (lx, y), text)?;
    draw(&root, "s = ρ body / ρ water", (lx, y + 24), text)?;
    y += 58;
    for (i, name) in names.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        root.draw(&PathElement::new(
            [(lx, y + 7), (lx + 28, y + 7)],
            colour.stroke_width(4),
        ))?;
        for line in plot_text::wrap(name, (LEGEND_WIDTH as i32 - 58) / text.scale) {
            draw(&root, &line, (lx + 38, y), text)?;
            y += 22;
        }
        y += 6;
    }
    root.present()?;
    Ok(())
}

/// Tick values inside `range`: multiples of the smallest of 0.1, 0.2, 0.25, 0.5, 1, 2, 2.5, 5…
/// giving at most `most` ticks, and the decimals they need.
fn nice_ticks(range: std::ops::Range<f32>, most: usize) -> (Vec<f32>, usize) {
    let steps = [
        (0.1, 1),
        (0.2, 1),
        (0.25, 2),
        (0.5, 1),
        (1.0, 0),
        (2.0, 0),
        (2.5, 1),
        (5.0, 0),
        (10.0, 0),
    ];
    for (step, decimals) in steps {
        let ticks: Vec<f32> = ((range.start / step).ceil() as i32
            ..=(range.end / step).floor() as i32)
            .map(|k| k as f32 * step)
            .collect();
        if ticks.len() <= most {
            return (ticks, decimals);
        }
    }
    (vec![range.start, range.end], 1)
}
