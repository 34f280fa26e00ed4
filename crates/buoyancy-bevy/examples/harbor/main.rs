//! The harbor: crates, a buoy, a Wigley hull and the bunny floating with `BuoyancyPlugin`, on
//! bevy_rapier3d or avian3d, in calm water or a JONSWAP sea.
//!
//! ```text
//! cargo run --release --example harbor --features rapier -- --headless
//! cargo run --release --example harbor --features avian -- --headless --hs 1 --tp 6
//! cargo run --release --example harbor --features rapier,render          # a window
//! ```
//!
//! `--headless` steps the physics `--frames` times at 60 Hz without a window and prints each
//! body's draft against its theoretical draft (calm water), or the range of its heave and
//! heel (waves); it exits with status 1 if a body is off its draft by more than 1 cm in calm
//! water, or is lost (not finite, sunk, flown off) in waves. Options:
//! `--backend rapier|avian` (when both features are on), `--frames N` (default 1200),
//! `--hs H` significant height m (0: calm), `--tp T` peak period s, `--direction D` degrees
//! from +x toward −z, `--seed S`.
//!
//! With the `render` feature and without `--headless` it opens a window: the water drawn from
//! `Water::elevation`, the surface the bodies feel; keys change the sea (see the overlay).

mod scene;

#[cfg(feature = "display")]
mod render;

#[cfg(all(feature = "web", target_arch = "wasm32"))]
mod web;

use std::process::ExitCode;
use std::time::Duration;

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use buoyancy_bevy::{BuoyancyPlugin, FloatReport, Water};
use buoyancy_core::nalgebra::Vector3;
use buoyancy_core::water::{AiryWaves, SeaState, Spectrum};
use scene::{Body, BodyMass, HarborBody, Shape};

/// The physics engine of the run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Backend {
    Rapier,
    Avian,
}

/// The sea state: JONSWAP (γ = 3.3), long-crested.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Sea {
    /// Significant wave height, m (0: calm water).
    significant_height: f64,
    /// Peak period, s.
    peak_period: f64,
    /// Direction the waves travel to, degrees from +x toward −z.
    direction_degrees: f64,
    seed: u64,
}

impl Sea {
    /// The waves of this sea in water of `density` (`None` when calm).
    fn waves(&self, density: f64) -> Result<Option<AiryWaves<f64>>, buoyancy_core::Error> {
        if self.significant_height <= 0.0 {
            return Ok(None);
        }
        let angle = self.direction_degrees.to_radians();
        let sea = SeaState {
            spectrum: Spectrum::Jonswap { gamma: 3.3 },
            significant_height: self.significant_height,
            peak_period: self.peak_period,
            direction: Vector3::new(angle.cos(), 0.0, -angle.sin()),
            spreading: None,
            components: 48,
            seed: self.seed,
        };
        let water = buoyancy_core::Water::new(density, 9.81, Vector3::y(), 0.0)?;
        AiryWaves::from_sea_state(&sea, &water, None).map(Some)
    }
}

struct Args {
    backend: Backend,
    headless: bool,
    frames: usize,
    sea: Sea,
}

const USAGE: &str = "usage: harbor [--headless] [--backend rapier|avian] [--frames N] [--hs H] \
                     [--tp T] [--direction DEG] [--seed S]";

fn parse_args() -> Result<Args, String> {
    let mut args = Args {
        backend: if cfg!(feature = "rapier") {
            Backend::Rapier
        } else {
            Backend::Avian
        },
        headless: !cfg!(feature = "display"),
        frames: 1200,
        sea: Sea {
            significant_height: if cfg!(feature = "display") { 0.8 } else { 0.0 },
            peak_period: 5.0,
            direction_degrees: 30.0,
            seed: 7,
        },
    };
    let mut hs_given = false;
    let mut it = std::env::args().skip(1);
    while let Some(flag) = it.next() {
        if flag == "--headless" {
            args.headless = true;
            continue;
        }
        if flag == "--help" || flag == "-h" {
            return Err(USAGE.into());
        }
        let value = it
            .next()
            .ok_or_else(|| format!("{flag} needs a value\n{USAGE}"))?;
        let number = |name: &str| -> Result<f64, String> {
            value
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("{name}: `{value}` is not a finite number"))
        };
        match flag.as_str() {
            "--backend" => {
                args.backend = match value.as_str() {
                    "rapier" if cfg!(feature = "rapier") => Backend::Rapier,
                    "avian" if cfg!(feature = "avian") => Backend::Avian,
                    "rapier" | "avian" => {
                        return Err(format!(
                            "--backend {value}: built without the `{value}` feature \
                             (cargo run --example harbor --features {value})"
                        ));
                    }
                    _ => return Err(format!("--backend: `{value}` is not rapier or avian")),
                }
            }
            "--frames" => {
                args.frames = value
                    .parse()
                    .map_err(|_| format!("--frames: `{value}` is not a count"))?;
            }
            "--hs" => {
                let hs = number("--hs")?;
                if !(0.0..=20.0).contains(&hs) {
                    return Err(format!("--hs: {hs} m is outside 0 to 20 m"));
                }
                args.sea.significant_height = hs;
                hs_given = true;
            }
            "--tp" => {
                let tp = number("--tp")?;
                if !(1.0..=30.0).contains(&tp) {
                    return Err(format!("--tp: {tp} s is outside 1 to 30 s"));
                }
                args.sea.peak_period = tp;
            }
            "--direction" => args.sea.direction_degrees = number("--direction")?,
            "--seed" => {
                args.sea.seed = value
                    .parse()
                    .map_err(|_| format!("--seed: `{value}` is not an integer"))?;
            }
            _ => return Err(format!("unknown option {flag}\n{USAGE}")),
        }
    }
    if args.headless && !hs_given {
        args.sea.significant_height = 0.0;
    }
    Ok(args)
}

/// Adds the backend's physics (at 60 Hz when `fixed`) and the buoyancy plugin. In a web page,
/// bevy_rapier steps in the fixed schedule at 60 Hz of the page's clock, as many steps a frame
/// as the frame lasted.
fn add_physics(app: &mut App, backend: Backend, fixed: bool) {
    match backend {
        Backend::Rapier => {
            #[cfg(feature = "rapier")]
            {
                use bevy_rapier3d::prelude::*;
                if cfg!(target_arch = "wasm32") {
                    app.add_plugins(
                        RapierPhysicsPlugin::<NoUserData>::default().in_fixed_schedule(),
                    )
                    .insert_resource(Time::<Fixed>::from_hz(60.0))
                    .insert_resource(TimestepMode::Fixed {
                        dt: 1.0 / 60.0,
                        substeps: 1,
                    })
                    .add_plugins(BuoyancyPlugin::in_schedule(FixedUpdate));
                    return;
                }
                app.add_plugins(RapierPhysicsPlugin::<NoUserData>::default());
                if fixed {
                    app.insert_resource(TimestepMode::Fixed {
                        dt: 1.0 / 60.0,
                        substeps: 1,
                    });
                }
            }
        }
        Backend::Avian => {
            #[cfg(feature = "avian")]
            {
                use avian3d::prelude::*;
                app.add_plugins(PhysicsPlugins::default());
                if fixed {
                    app.insert_resource(Time::<Fixed>::from_hz(60.0));
                }
            }
        }
    }
    let _ = fixed;
    app.add_plugins(BuoyancyPlugin::default());
}

/// Spawns `body` (the `index`-th) on `backend`: rigid body, collider, mass, `Floating`.
fn spawn(
    commands: &mut Commands,
    backend: Backend,
    body: &Body,
    index: usize,
) -> Result<Entity, String> {
    let hull_error = || format!("{}: its convex hull cannot be built", body.name);
    let mut entity = commands.spawn((body.start, body.floating(), HarborBody(index)));
    match backend {
        Backend::Rapier => {
            #[cfg(feature = "rapier")]
            {
                use bevy_rapier3d::prelude::*;
                let collider = match &body.shape {
                    Shape::Cuboid(h) => Collider::cuboid(h.x, h.y, h.z),
                    Shape::Cylinder {
                        radius,
                        half_height,
                    } => Collider::cylinder(*half_height, *radius),
                    Shape::Hull(points) => Collider::convex_hull(points).ok_or_else(hull_error)?,
                };
                let mass = rapier_mass(&body.mass, 1.0);
                entity.insert((RigidBody::Dynamic, collider, mass, Velocity::default()));
            }
        }
        Backend::Avian => {
            #[cfg(feature = "avian")]
            {
                use avian3d::prelude::*;
                let collider = match &body.shape {
                    Shape::Cuboid(h) => Collider::cuboid(2.0 * h.x, 2.0 * h.y, 2.0 * h.z),
                    Shape::Cylinder {
                        radius,
                        half_height,
                    } => Collider::cylinder(*radius, 2.0 * half_height),
                    Shape::Hull(points) => Collider::convex_hull(points).ok_or_else(hull_error)?,
                };
                entity.insert((RigidBody::Dynamic, collider));
                match body.mass {
                    BodyMass::Density(density) => {
                        entity.insert(ColliderDensity(density));
                    }
                    BodyMass::Given {
                        mass,
                        center,
                        inertia,
                    } => {
                        entity.insert((
                            Mass(mass),
                            CenterOfMass(center),
                            AngularInertia::new(inertia),
                            NoAutoMass,
                            NoAutoCenterOfMass,
                            NoAutoAngularInertia,
                        ));
                    }
                }
            }
        }
    }
    let _ = hull_error;
    Ok(entity.id())
}

/// bevy_rapier's mass properties for `mass`, its mass and inertia scaled by `factor` (the
/// center of mass kept): a density times `factor`, or the given ones.
#[cfg(feature = "rapier")]
pub fn rapier_mass(mass: &BodyMass, factor: f32) -> bevy_rapier3d::prelude::ColliderMassProperties {
    use bevy_rapier3d::prelude::{ColliderMassProperties, MassProperties};
    match *mass {
        BodyMass::Density(density) => ColliderMassProperties::Density(density * factor),
        BodyMass::Given {
            mass,
            center,
            inertia,
        } => ColliderMassProperties::MassProperties(MassProperties {
            local_center_of_mass: center,
            mass: mass * factor,
            principal_inertia_local_frame: Quat::IDENTITY,
            principal_inertia: inertia * factor,
        }),
    }
}

/// The harbor's bodies, as a resource for the systems that draw and report them.
#[derive(Resource, Clone)]
struct Harbor {
    bodies: Vec<Body>,
    backend: Backend,
}

fn spawn_harbor(mut commands: Commands, harbor: Res<Harbor>) {
    for (i, body) in harbor.bodies.iter().enumerate() {
        if let Err(message) = spawn(&mut commands, harbor.backend, body, i) {
            error!("{message}");
        }
    }
}

/// What the headless run saw of one body.
#[derive(Clone, Debug)]
struct Track {
    heave: (f32, f32),
    heel: (f32, f32),
    finite: bool,
}

impl Default for Track {
    fn default() -> Self {
        Track {
            heave: (f32::MAX, f32::MIN),
            heel: (f32::MAX, f32::MIN),
            finite: true,
        }
    }
}

/// The angle between the body's up and the world's, degrees.
fn heel_degrees(rotation: Quat) -> f32 {
    (rotation * Vec3::Y)
        .dot(Vec3::Y)
        .clamp(-1.0, 1.0)
        .acos()
        .to_degrees()
}

fn run_headless(args: &Args, bodies: Vec<Body>, water: Water) -> ExitCode {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
            1.0 / 60.0,
        )));
    add_physics(&mut app, args.backend, true);
    app.insert_resource(water)
        .insert_resource(Harbor {
            bodies: bodies.clone(),
            backend: args.backend,
        })
        .add_systems(Startup, spawn_harbor);
    app.finish();
    app.cleanup();
    let mut tracks = vec![Track::default(); bodies.len()];
    // The last quarter of the run is the one tracked in waves (the start-up transient gone).
    let tracked_from = args.frames - args.frames / 4;
    let started = std::time::Instant::now();
    for frame in 0..args.frames {
        app.update();
        if frame < tracked_from {
            continue;
        }
        let world = app.world_mut();
        let mut query = world.query::<(&HarborBody, &Transform)>();
        for (HarborBody(i), transform) in query.iter(world) {
            let t = &mut tracks[*i];
            let y = transform.translation.y;
            let heel = heel_degrees(transform.rotation);
            t.finite &= transform.translation.is_finite() && transform.rotation.is_finite();
            t.heave = (t.heave.0.min(y), t.heave.1.max(y));
            t.heel = (t.heel.0.min(heel), t.heel.1.max(heel));
        }
    }
    let elapsed = started.elapsed();
    let world = app.world_mut();
    let mut query = world.query::<(&HarborBody, &FloatReport)>();
    let mut reports: Vec<Option<FloatReport>> = vec![None; bodies.len()];
    for (HarborBody(i), report) in query.iter(world) {
        reports[*i] = Some(report.clone());
    }
    let calm = args.sea.significant_height <= 0.0;
    println!(
        "harbor on {:?}: {} bodies, {} frames at 60 Hz ({:.1} s simulated) in {:.2} s of wall time; {}",
        args.backend,
        bodies.len(),
        args.frames,
        args.frames as f64 / 60.0,
        elapsed.as_secs_f64(),
        if calm {
            "calm water".to_string()
        } else {
            format!(
                "JONSWAP Hs {} m, Tp {} s, towards {}°",
                args.sea.significant_height, args.sea.peak_period, args.sea.direction_degrees
            )
        }
    );
    let mut failed = false;
    if calm {
        println!(
            "\n| body | mass kg | draft m (theory) | draft m (simulated) | Δ mm | heel ° | theory |"
        );
        println!("|---|---|---|---|---|---|---|");
    } else {
        println!("\n| body | mass kg | heave m (min … max) | heel ° (min … max) |");
        println!("|---|---|---|---|");
    }
    for (i, body) in bodies.iter().enumerate() {
        let track = &tracks[i];
        let Some(report) = &reports[i] else {
            println!("| {} | not spawned | | | | | |", body.name);
            failed = true;
            continue;
        };
        if let Some(error) = &report.error {
            println!("| {} | error: {error} | | | | | |", body.name);
            failed = true;
            continue;
        }
        if calm {
            let delta = report.draft - body.draft;
            let ok = delta.abs() <= 0.01 && track.finite;
            failed |= !ok;
            println!(
                "| {} | {:.1} | {:.4} | {:.4} | {:+.2}{} | {:.2} | {} |",
                body.name,
                body.mass_kg,
                body.draft,
                report.draft,
                1e3 * delta,
                if ok { "" } else { " (over 10 mm)" },
                track.heel.1,
                body.theory
            );
        } else {
            let lost = !track.finite || track.heave.0 < -5.0 || track.heave.1 > 5.0;
            failed |= lost;
            println!(
                "| {} | {:.1} | {:+.3} … {:+.3}{} | {:.1} … {:.1} |",
                body.name,
                body.mass_kg,
                track.heave.0,
                track.heave.1,
                if lost { " (lost)" } else { "" },
                track.heel.0,
                track.heel.1
            );
        }
    }
    if failed {
        eprintln!("\nharbor: a body is not where the water should hold it (see the table)");
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}

fn main() -> ExitCode {
    if !cfg!(any(feature = "rapier", feature = "avian")) {
        eprintln!(
            "harbor: built without a physics backend; run it with --features rapier or avian"
        );
        return ExitCode::from(2);
    }
    let args = match parse_args() {
        Ok(args) => args,
        Err(message) => {
            eprintln!("harbor: {message}");
            return ExitCode::from(2);
        }
    };
    #[cfg(all(feature = "web", target_arch = "wasm32"))]
    let (bunny, args) = (
        web::bunny_obj(),
        Args {
            sea: web::page_sea(args.sea),
            ..args
        },
    );
    #[cfg(not(all(feature = "web", target_arch = "wasm32")))]
    let bunny = buoyancy_samples::mesh_path("bunny.obj").and_then(|path| {
        std::fs::read_to_string(&path)
            .map_err(|e| eprintln!("harbor: cannot read {}: {e}", path.display()))
            .ok()
    });
    let density = 1000.0;
    let (bodies, waves) = match scene::harbor(density, bunny.as_deref())
        .and_then(|b| Ok((b, args.sea.waves(density)?)))
    {
        Ok(scene) => scene,
        Err(e) => {
            eprintln!("harbor: {e}");
            return ExitCode::FAILURE;
        }
    };
    let mut water = Water::default();
    water.density = density;
    water.set_waves(waves.map(|w| std::sync::Arc::new(w) as _));
    if args.headless {
        return run_headless(&args, bodies, water);
    }
    #[cfg(feature = "display")]
    {
        let mut app = App::new();
        render::add(&mut app, args.sea);
        add_physics(&mut app, args.backend, false);
        #[cfg(all(feature = "web", target_arch = "wasm32"))]
        web::add(&mut app);
        app.insert_resource(water)
            .insert_resource(Harbor {
                bodies,
                backend: args.backend,
            })
            .add_systems(Startup, spawn_harbor);
        app.run();
        ExitCode::SUCCESS
    }
    #[cfg(not(feature = "display"))]
    {
        eprintln!("harbor: the window needs the `render` feature; or pass --headless");
        ExitCode::from(2)
    }
}
