//! The demo on waves: a ship-like hull, the Stanford bunny and a small buoy float in rapier3d on
//! a regular wave and on an irregular JONSWAP sea. Prints, per body and sea, the heave and
//! pitch against the wave's elevation and slope at the body, the mean draft, the drift and the
//! checks' verdicts, and writes `out/waves.csv` (time series) and `out/waves.png` (heave and
//! pitch over time against the surface at each body, the key figures in the captions).
//!
//! ```sh
//! cargo run --release --example waves
//! ```
//!
//! * **Hull**: a closed Wigley hull ([`primitives::wigley_hull`]), 4 m long, 0.6 m wide, 0.25 m
//!   design draft, 0.15 m of freeboard, of uniform density chosen so that it floats at its
//!   design draft; heading into the waves (its length along x, the waves travelling along +x).
//! * **Bunny**: the Stanford bunny of the sample meshes (`$BUOYANCY_MESHES`, else
//!   `../shared/meshes`), 1.2 m across, half as dense as water; skipped, with a note, when absent.
//! * **Buoy**: a foam cylinder 0.6 m across and 0.5 m tall with a lead ball 0.2 m across at its
//!   bottom (only the cylinder floats; the ball is ballast inside it), floating 0.25 m deep.
//!
//! The bodies first settle in still water; then the waves grow from nothing over 5 s (a smooth
//! ramp of the elevation and the orbital velocity, so that nothing starts with a jolt) and run
//! for 60 s. The statistics are taken over the last 40 s. Words:
//! * **heave**: the rise of the body's center of mass above its rest height in still water;
//! * **pitch**: the angle by which the body's line along the waves' direction (horizontal at
//!   rest) has tilted, bow (+x end) up positive; a body that follows the surface pitches with
//!   the wave's **slope** angle, `atan(∂η/∂x)`;
//! * **η at the body**: the elevation of the surface above the still level at the horizontal
//!   position of the body's center of mass;
//! * **draft**: the depth below the still water level of the body's point that was lowest at
//!   rest (the hull's keel at midship).
//!
//! Checks (also tests, in `crates/buoyancy-rapier/tests/waves.rs`): the hull placed at its
//! design draft in still water stays at rest for 30 s (`a_hull_at_its_design_draft_stays_at_rest`);
//! on the waves every pose stays finite, the heave within two wave heights, the speed within
//! 3 m/s and the spin within 5 rad/s (`three_bodies_ride_ten_minutes_of_a_jonswap_sea`, for ten
//! minutes).

#[path = "../benches/common/plot_font.rs"]
mod plot_font;

use std::error::Error as StdError;
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

use buoyancy::nalgebra::{Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use buoyancy::water::{AiryComponent, AiryWaves, SeaState, Spectrum, WaterSurface};
use buoyancy::{Mesh, Method, Water, mesh::primitives};
use buoyancy_rapier::{FloatOptions, FloatingBodies};
use plotters::coord::Shift;
use plotters::prelude::*;
use rapier3d::prelude::*;

use plot_font::FAMILY;

type Result<T> = std::result::Result<T, Box<dyn StdError>>;

const WATER_DENSITY: f64 = 1000.0;
/// Still water before the waves, s: the bodies settle to rest.
const SETTLE: f64 = 20.0;
/// The waves' ramp from still water to full height, s.
const RAMP: f64 = 5.0;
/// The waves' run, s (the ramp included).
const SECONDS: f64 = 60.0;
/// The statistics are taken from this time on, s.
const STATS_FROM: f64 = 20.0;
/// Samples per second in the series.
const SAMPLE_RATE: f64 = 20.0;

/// The hull: Wigley, `L × B × T` with a freeboard (m), meshed with 41 stations and 17
/// waterlines (2,798 triangles).
const HULL: (f64, f64, f64, f64) = (4.0, 0.6, 0.25, 0.15);

/// The regular wave: amplitude (m) and wavelength (m), deep water, along +x.
const REGULAR: (f64, f64) = (0.1, 8.0);
/// The irregular sea: JONSWAP (γ = 3.3), `H_s` (m), `T_p` (s), long-crested along +x, 64
/// components, seed.
const JONSWAP: (f64, f64, usize, u64) = (0.3, 2.5, 64, 7);

/// The rest check (the test `a_hull_at_its_design_draft_stays_at_rest`): the hull placed at
/// its design draft in still water for this long (s) ...
const REST_SECONDS: f64 = 30.0;
/// ... moves slower than these (m/s, rad/s) and ends nearer than these to where it was placed
/// (m, degrees).
const REST_SPEED: f64 = 1e-4;
const REST_SPIN: f64 = 1e-4;
const REST_DRIFT: f64 = 1e-4;
const REST_TURN: f64 = 1e-3;

/// The bounds of the runs on waves (the test `three_bodies_ride_ten_minutes_of_a_jonswap_sea`
/// holds them for ten minutes): every pose finite, the heave within this many wave heights
/// (`H = 2a`, or `H_s`), no speed of the center of mass above this (m/s), no spin above this
/// (rad/s).
const HEAVE_BOUND_HEIGHTS: f64 = 2.0;
const SPEED_BOUND: f64 = 3.0;
const SPIN_BOUND: f64 = 5.0;

/// A smooth ramp in: the elevation and the orbital velocity of `waves` times a smooth step from
/// 0 at `t = 0` to 1 at `t = ramp` (s), so that bodies at rest in still water meet the waves
/// without a jolt. Any [`WaterSurface`] can float the bodies; this one wraps Airy waves.
struct Ramped {
    waves: AiryWaves<f64>,
    ramp: f64,
}

impl Ramped {
    fn factor(&self, time: f64) -> f64 {
        let x = (time / self.ramp).clamp(0.0, 1.0);
        x * x * (3.0 - 2.0 * x)
    }

    /// The elevation (m) and the slope angle along x (°) at the horizontal position of `p`.
    fn elevation_and_slope(&self, water: &Water<f64>, p: &Point3<f64>, time: f64) -> (f64, f64) {
        const DX: f64 = 0.02;
        let points = [
            Point3::new(p.x, 0.0, p.z),
            Point3::new(p.x - DX, 0.0, p.z),
            Point3::new(p.x + DX, 0.0, p.z),
        ];
        let mut eta = [0.0; 3];
        self.elevations(water, &points, time, &mut eta)
            .expect("Airy waves evaluate at any finite point");
        (eta[0], ((eta[2] - eta[1]) / (2.0 * DX)).atan().to_degrees())
    }
}

impl WaterSurface<f64> for Ramped {
    fn elevations(
        &self,
        water: &Water<f64>,
        points: &[Point3<f64>],
        time: f64,
        elevations: &mut [f64],
    ) -> std::result::Result<(), buoyancy::Error> {
        self.waves.elevations(water, points, time, elevations)?;
        let factor = self.factor(time);
        if factor < 1.0 {
            elevations.iter_mut().for_each(|e| *e *= factor);
        }
        Ok(())
    }

    fn elevation_bound(&self) -> Option<f64> {
        self.waves.elevation_bound()
    }

    fn water_velocity(
        &self,
        water: &Water<f64>,
        point: &Point3<f64>,
        time: f64,
    ) -> Option<Vector3<f64>> {
        let factor = self.factor(time);
        self.waves
            .water_velocity(water, point, time)
            .map(|v| v * factor)
    }
}

/// One sea: its name, its waves, and the wave height the bounds are stated in (m).
struct Sea {
    name: &'static str,
    /// The name in a caption: "regular wave", "JONSWAP sea".
    label: &'static str,
    title: String,
    surface: Arc<Ramped>,
    height: f64,
    /// The regular wave's angular frequency (rad/s); `None` for an irregular sea.
    omega: Option<f64>,
}

fn seas(water: &Water<f64>) -> Result<Vec<Sea>> {
    let (amplitude, wavelength) = REGULAR;
    let regular = AiryWaves::new(
        vec![AiryComponent {
            amplitude,
            wavelength,
            direction: Vector3::x(),
            phase: 0.0,
        }],
        None,
    )?;
    let omega = regular.angular_frequency(0, water.gravity());
    let (hs, tp, components, seed) = JONSWAP;
    let jonswap = AiryWaves::from_sea_state(
        &SeaState {
            spectrum: Spectrum::Jonswap { gamma: 3.3 },
            significant_height: hs,
            peak_period: tp,
            direction: Vector3::x(),
            spreading: None,
            components,
            seed,
        },
        water,
        None,
    )?;
    Ok(vec![
        Sea {
            name: "regular",
            label: "regular wave",
            title: format!(
                "regular Airy wave: height {:.2} m, length {wavelength} m, period {:.2} s",
                2.0 * amplitude,
                2.0 * PI / omega
            ),
            surface: Arc::new(Ramped {
                waves: regular,
                ramp: RAMP,
            }),
            height: 2.0 * amplitude,
            omega: Some(omega),
        },
        Sea {
            name: "JONSWAP",
            label: "JONSWAP sea",
            title: format!(
                "JONSWAP sea (γ = 3.3, long-crested): Hs {hs} m, Tp {tp} s, {components} components"
            ),
            surface: Arc::new(Ramped {
                waves: jonswap,
                ramp: RAMP,
            }),
            height: hs,
            omega: None,
        },
    ])
}

/// The meshes the bodies are built from: the hull and, if found, the bunny.
struct Meshes {
    hull: Mesh<f64>,
    /// The hull's uniform density that floats it at its design draft, kg/m³.
    hull_density: f64,
    bunny: Option<Mesh<f64>>,
}

fn meshes(water: &Water<f64>) -> Result<Meshes> {
    let (length, beam, draft, freeboard) = HULL;
    let (v, t) = primitives::wigley_hull::<f64>(length, beam, draft, freeboard, 41, 17)?;
    let hull = Mesh::new(v, t)?;
    // Mass = ρ × the mesh's volume below the design waterline (y = 0 at the identity pose).
    let underwater = hull.buoyancy(&buoyancy::Pose::identity(), water, Method::Exact)?;
    let hull_density = water.density() * underwater.submerged_volume / hull.volume();
    let bunny = match buoyancy_samples::mesh_path("bunny.obj") {
        Some(path) => {
            // A file that exists but does not load is an error, not a silent omission.
            let (v, t) = buoyancy::io::load::<f64>(&path)?;
            let mesh = Mesh::new(v, t)?;
            let (center, scale) = (mesh.centroid(), 0.6 / mesh.bounding_radius());
            let v = (0..mesh.vertex_count())
                .map(|i| Point3::from((mesh.vertex(i) - center) * scale))
                .collect();
            Some(Mesh::new(v, mesh.triangles().to_vec())?)
        }
        None => {
            println!("note: bunny.obj not found among the sample meshes: the bunny is skipped");
            None
        }
    };
    Ok(Meshes {
        hull,
        hull_density,
        bunny,
    })
}

fn trimesh_collider(mesh: &Mesh<f64>) -> Result<ColliderBuilder> {
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

/// A floating body of a run.
struct Body {
    name: &'static str,
    handle: RigidBodyHandle,
}

/// The hull at its design draft (the identity pose, its design waterline at y = 0) at `z`.
fn add_hull(
    world: &mut PhysicsWorld,
    water: &mut FloatingBodies,
    meshes: &Meshes,
    z: f32,
) -> Result<Body> {
    let collider = trimesh_collider(&meshes.hull)?.density(meshes.hull_density as f32);
    let (handle, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, 0.0, z))
            .can_sleep(false),
        collider,
    );
    water.register(
        handle,
        &world.bodies,
        &world.colliders,
        FloatOptions::default(),
    )?;
    Ok(Body {
        name: "hull",
        handle,
    })
}

/// The bunny, half as dense as water, at `z`, at the height where it displaces its weight.
fn add_bunny(
    world: &mut PhysicsWorld,
    water: &mut FloatingBodies,
    mesh: &Mesh<f64>,
    z: f32,
) -> Result<Body> {
    // Bisection on the height for half the volume under water.
    let (mut lo, mut hi) = (-1.0, 1.0);
    for _ in 0..40 {
        let y = 0.5 * (lo + hi);
        let pose =
            buoyancy::Pose::from_parts(Translation3::new(0.0, y, 0.0), UnitQuaternion::identity());
        let b = mesh.buoyancy(&pose, water.water(), Method::Exact)?;
        if b.submerged_volume > 0.5 * mesh.volume() {
            lo = y;
        } else {
            hi = y;
        }
    }
    let (handle, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, (0.5 * (lo + hi)) as f32, z))
            .can_sleep(false),
        trimesh_collider(mesh)?.density((0.5 * WATER_DENSITY) as f32),
    );
    water.register(
        handle,
        &world.bodies,
        &world.colliders,
        FloatOptions::default(),
    )?;
    Ok(Body {
        name: "bunny",
        handle,
    })
}

/// The buoy's cylinder: radius and half height (m), density (kg/m³); its lead ball: radius (m),
/// density, center below the cylinder's center (m).
const BUOY: (f32, f32, f32) = (0.3, 0.25, 160.0);
const BALLAST: (f32, f32, f32) = (0.1, 11340.0, 0.15);

/// The buoy at `z`, at the height where it displaces its weight.
fn add_buoy(world: &mut PhysicsWorld, water: &mut FloatingBodies, z: f32) -> Result<Body> {
    let (radius, half_height, density) = BUOY;
    let (ball, ball_density, ball_depth) = BALLAST;
    let mass = density * PI as f32 * radius * radius * 2.0 * half_height
        + ball_density * 4.0 / 3.0 * PI as f32 * ball.powi(3);
    let draft = mass / (WATER_DENSITY as f32 * PI as f32 * radius * radius);
    let (handle, cylinder) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, half_height - draft, z))
            .can_sleep(false),
        ColliderBuilder::cylinder(half_height, radius).density(density),
    );
    world.insert_collider(
        ColliderBuilder::ball(ball)
            .translation(Vector::new(0.0, -ball_depth, 0.0))
            .density(ball_density),
        Some(handle),
    );
    water.register(
        handle,
        &world.bodies,
        &world.colliders,
        FloatOptions::default().colliders([cylinder]),
    )?;
    Ok(Body {
        name: "buoy",
        handle,
    })
}

/// A rapier pose as the core's.
fn pose_of(rb: &RigidBody) -> buoyancy::Pose<f64> {
    let (t, r) = (rb.translation(), rb.rotation());
    buoyancy::Pose::from_parts(
        Translation3::new(t.x as f64, t.y as f64, t.z as f64),
        UnitQuaternion::from_quaternion(Quaternion::new(
            r.w as f64, r.x as f64, r.y as f64, r.z as f64,
        )),
    )
}

/// The point of the body (body frame) lowest in the world at its pose: its keel at rest.
fn keel(water: &FloatingBodies, handle: RigidBodyHandle, rb: &RigidBody) -> Point3<f64> {
    let pose = pose_of(rb);
    water
        .meshes(handle)
        .flat_map(|(mesh, to_body)| (0..mesh.vertex_count()).map(move |i| to_body * mesh.vertex(i)))
        .min_by(|a, b| (pose * a).y.total_cmp(&(pose * b).y))
        .expect("a floating body has a mesh")
}

/// One sample of a body on waves.
#[derive(Clone, Copy)]
struct Sample {
    /// Time since the waves started, s.
    t: f64,
    heave: f64,
    /// Degrees.
    pitch: f64,
    eta: f64,
    /// The wave's slope angle at the body, degrees.
    slope: f64,
    draft: f64,
    /// The speed of the center of mass, m/s, and the angular speed, rad/s.
    speed: f64,
    spin: f64,
    /// Horizontal distance of the center of mass from its rest position, m.
    drift: f64,
    finite: bool,
    /// The wave pressure's force along the waves' direction (x), N.
    force_x: f64,
}

/// A body's run on one sea.
struct Run {
    body: &'static str,
    sea: usize,
    rest_draft: f64,
    samples: Vec<Sample>,
}

/// The rest state of a body in still water: its center of mass, attitude, and lowest point
/// (body frame).
struct Rest {
    center: Vector,
    rotation: Rotation,
    keel: Point3<f64>,
}

impl Rest {
    fn of(water: &FloatingBodies, handle: RigidBodyHandle, rb: &RigidBody) -> Self {
        Rest {
            center: rb.center_of_mass(),
            rotation: *rb.rotation(),
            keel: keel(water, handle, rb),
        }
    }

    /// The depth below the still level of the body's lowest point at rest, at the body's pose.
    fn draft(&self, rb: &RigidBody) -> f64 {
        -(pose_of(rb) * self.keel).y
    }
}

fn sample(
    water: &FloatingBodies,
    sea: &Sea,
    handle: RigidBodyHandle,
    rb: &RigidBody,
    rest: &Rest,
    t: f64,
) -> Sample {
    let com = rb.center_of_mass();
    let p = Point3::new(com.x as f64, com.y as f64, com.z as f64);
    let (eta, slope) = sea.surface.elevation_and_slope(water.water(), &p, t);
    let turned = (*rb.rotation() * rest.rotation.inverse()) * Vector::X;
    let horizontal = Vector::new(com.x - rest.center.x, 0.0, com.z - rest.center.z);
    Sample {
        t,
        heave: f64::from(com.y - rest.center.y),
        pitch: f64::from(turned.y.clamp(-1.0, 1.0)).asin().to_degrees(),
        eta,
        slope,
        draft: rest.draft(rb),
        speed: f64::from(rb.linvel().length()),
        spin: f64::from(rb.angvel().length()),
        drift: f64::from(horizontal.length()),
        force_x: water
            .report(handle)
            .map_or(f64::NAN, |r| r.buoyancy_force.x),
        finite: rb.translation().is_finite()
            && rb.rotation().is_finite()
            && rb.linvel().is_finite()
            && rb.angvel().is_finite(),
    }
}

/// Runs the three bodies on `sea`: settled in still water, then on the ramped waves.
fn run_sea(meshes: &Meshes, seas: &[Sea], index: usize) -> Result<Vec<Run>> {
    let sea = &seas[index];
    let mut world = PhysicsWorld::default();
    let mut water = FloatingBodies::new(world.gravity)?;
    // In a row across the waves, 15 m apart: they meet the same long-crested waves.
    let mut bodies = vec![add_hull(&mut world, &mut water, meshes, 0.0)?];
    if let Some(bunny) = &meshes.bunny {
        bodies.push(add_bunny(&mut world, &mut water, bunny, 15.0)?);
    }
    bodies.push(add_buoy(&mut world, &mut water, 30.0)?);
    let dt = world.integration_parameters.dt;
    let step = |world: &mut PhysicsWorld, water: &mut FloatingBodies| {
        water.apply(&mut world.bodies, dt);
        world.step();
    };
    for _ in 0..(SETTLE / f64::from(dt)).round() as usize {
        step(&mut world, &mut water);
    }
    let rests: Vec<Rest> = bodies
        .iter()
        .map(|b| Rest::of(&water, b.handle, &world.bodies[b.handle]))
        .collect();
    let mut runs: Vec<Run> = bodies
        .iter()
        .zip(&rests)
        .map(|(b, rest)| Run {
            body: b.name,
            sea: index,
            rest_draft: rest.draft(&world.bodies[b.handle]),
            samples: Vec::new(),
        })
        .collect();
    water.set_surface(Some(sea.surface.clone()));
    water.set_time(0.0);
    let steps = (SECONDS / f64::from(dt)).round() as usize;
    let every = (1.0 / (SAMPLE_RATE * f64::from(dt))).round() as usize;
    for i in 0..=steps {
        if i % every == 0 {
            let t = water.time();
            for ((body, rest), run) in bodies.iter().zip(&rests).zip(&mut runs) {
                let rb = &world.bodies[body.handle];
                run.samples
                    .push(sample(&water, sea, body.handle, rb, rest, t));
            }
        }
        if i < steps {
            step(&mut world, &mut water);
        }
    }
    Ok(runs)
}

/// The hull at its design draft in still water for [`REST_SECONDS`]: its largest speed (m/s)
/// and spin (rad/s), and its final drift (m) and turn (°) from where it was placed.
fn rest_check(meshes: &Meshes) -> Result<(f64, f64, f64, f64)> {
    let mut world = PhysicsWorld::default();
    let mut water = FloatingBodies::new(world.gravity)?;
    let hull = add_hull(&mut world, &mut water, meshes, 0.0)?.handle;
    let start = *world.bodies[hull].position();
    let dt = world.integration_parameters.dt;
    let (mut speed, mut spin) = (0.0f64, 0.0f64);
    for _ in 0..(REST_SECONDS / f64::from(dt)).round() as usize {
        water.apply(&mut world.bodies, dt);
        world.step();
        let rb = &world.bodies[hull];
        speed = speed.max(f64::from(rb.linvel().length()));
        spin = spin.max(f64::from(rb.angvel().length()));
    }
    let end = world.bodies[hull].position();
    let drift = f64::from((end.translation - start.translation).length());
    let turn = f64::from(end.rotation.angle_between(start.rotation)).to_degrees();
    Ok((speed, spin, drift, turn))
}

/// Least squares of `y = A cos ωt + B sin ωt + C` over `samples` `(t, y)`: the harmonic's
/// amplitude `R` and phase lag `φ` (°), `y ≈ R·cos(ωt − φ) + C`.
fn harmonic(samples: &[(f64, f64)], omega: f64) -> (f64, f64) {
    let mut normal = [[0.0; 3]; 3];
    let mut rhs = [0.0; 3];
    for &(t, y) in samples {
        let b = [(omega * t).cos(), (omega * t).sin(), 1.0];
        for i in 0..3 {
            rhs[i] += b[i] * y;
            for j in 0..3 {
                normal[i][j] += b[i] * b[j];
            }
        }
    }
    let m = buoyancy::nalgebra::Matrix3::from_fn(|i, j| normal[i][j]);
    let [a, b, _]: [f64; 3] = m
        .lu()
        .solve(&Vector3::from(rhs))
        .map(Into::into)
        .unwrap_or([f64::NAN; 3]);
    (a.hypot(b), b.atan2(a).to_degrees())
}

/// Wraps an angle difference (°) into (−180, 180].
fn wrap_degrees(a: f64) -> f64 {
    let a = a.rem_euclid(360.0);
    if a > 180.0 { a - 360.0 } else { a }
}

/// What the table and the plot say of a run, over the statistics' window (the largest speed
/// and the bounds over the whole run).
struct Stats {
    /// Standard deviations of the elevation at the body and of the heave, m.
    eta_std: f64,
    heave_std: f64,
    /// The heave over the elevation at the body: amplitudes at the regular wave's frequency,
    /// else standard deviations.
    heave_ratio: f64,
    /// The heave's phase lag behind the elevation at the body (°), on a regular wave.
    heave_phase: Option<f64>,
    /// Ranges, °.
    pitch: (f64, f64),
    slope: (f64, f64),
    /// Means: the draft, the heave and the elevation at the body (m), the wave force along x (N).
    draft: f64,
    heave: f64,
    eta: f64,
    force_x: f64,
    /// The largest speed of the center of mass (m/s) and its horizontal drift at the end (m).
    max_speed: f64,
    drift: f64,
    /// Whether the run stayed finite and within the bounds, or what broke them.
    verdict: String,
}

fn stats(run: &Run, sea: &Sea) -> Stats {
    let window: Vec<&Sample> = run.samples.iter().filter(|s| s.t >= STATS_FROM).collect();
    let values = |f: fn(&Sample) -> f64| window.iter().map(move |s| f(s));
    let mean = |f: fn(&Sample) -> f64| values(f).sum::<f64>() / window.len() as f64;
    let std = |f: fn(&Sample) -> f64| {
        let m = mean(f);
        (values(f).map(|v| (v - m) * (v - m)).sum::<f64>() / window.len() as f64).sqrt()
    };
    let range = |f: fn(&Sample) -> f64| {
        values(f).fold((f64::MAX, f64::MIN), |(lo, hi), v| (lo.min(v), hi.max(v)))
    };
    let (eta_std, heave_std) = (std(|s| s.eta), std(|s| s.heave));
    let (heave_ratio, heave_phase) = match sea.omega {
        Some(omega) => {
            let fit = |f: fn(&Sample) -> f64| {
                harmonic(
                    &window.iter().map(|s| (s.t, f(s))).collect::<Vec<_>>(),
                    omega,
                )
            };
            let ((heave, heave_phase), (eta, eta_phase)) = (fit(|s| s.heave), fit(|s| s.eta));
            (heave / eta, Some(wrap_degrees(heave_phase - eta_phase)))
        }
        None => (heave_std / eta_std, None),
    };
    let max_heave = run
        .samples
        .iter()
        .map(|s| s.heave.abs())
        .fold(0.0, f64::max);
    let max_speed = run.samples.iter().map(|s| s.speed).fold(0.0, f64::max);
    let max_spin = run.samples.iter().map(|s| s.spin).fold(0.0, f64::max);
    let verdict = if !run.samples.iter().all(|s| s.finite) {
        "FAIL: not finite".into()
    } else if max_heave > HEAVE_BOUND_HEIGHTS * sea.height {
        format!("FAIL: heave {max_heave:.2} m")
    } else if max_speed > SPEED_BOUND {
        format!("FAIL: speed {max_speed:.2} m/s")
    } else if max_spin > SPIN_BOUND {
        format!("FAIL: spin {max_spin:.2} rad/s")
    } else {
        "ok".into()
    };
    Stats {
        eta_std,
        heave_std,
        heave_ratio,
        heave_phase,
        pitch: range(|s| s.pitch),
        slope: range(|s| s.slope),
        draft: mean(|s| s.draft),
        heave: mean(|s| s.heave),
        eta: mean(|s| s.eta),
        force_x: mean(|s| s.force_x),
        max_speed,
        drift: run.samples.last().map_or(f64::NAN, |s| s.drift),
        verdict,
    }
}

/// A signed number with a true minus sign.
fn signed(value: f64, decimals: usize) -> String {
    format!("{value:+.decimals$}").replace('-', "−")
}

fn print_table(runs: &[Run], seas: &[Sea]) {
    println!(
        "| sea | body | η at the body, std (m) | heave, std (m) | heave / η | heave lag (°) | pitch range (°) | slope range (°) | mean draft (rest) (m) | mean heave, η (mm) | largest speed (m/s) | drift (m) | mean wave force along x (N) | bounded |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for run in runs {
        let sea = &seas[run.sea];
        let s = stats(run, sea);
        println!(
            "| {} | {} | {:.4} | {:.4} | {:.3} | {} | {} to {} | {} to {} | {:.4} ({:.4}) | {}, {} | {:.2} | {:.2} | {} | {} |",
            sea.name,
            run.body,
            s.eta_std,
            s.heave_std,
            s.heave_ratio,
            s.heave_phase.map_or_else(|| "—".into(), |p| signed(p, 1)),
            signed(s.pitch.0, 1),
            signed(s.pitch.1, 1),
            signed(s.slope.0, 1),
            signed(s.slope.1, 1),
            s.draft,
            run.rest_draft,
            signed(s.heave * 1e3, 1),
            signed(s.eta * 1e3, 1),
            s.max_speed,
            s.drift,
            signed(s.force_x, 2),
            s.verdict,
        );
    }
}

fn main() -> Result<()> {
    let started = Instant::now();
    let water = Water::<f64>::default();
    let meshes = meshes(&water)?;
    let seas = seas(&water)?;

    let (speed, spin, drift, turn) = rest_check(&meshes)?;
    let rest_ok = speed < REST_SPEED && spin < REST_SPIN && drift < REST_DRIFT && turn < REST_TURN;
    println!(
        "still water: the hull placed at its design draft, after {REST_SECONDS} s: largest speed {speed:.1e} m/s \
         (bound {REST_SPEED:.0e}), spin {spin:.1e} rad/s (bound {REST_SPIN:.0e}), drift {drift:.1e} m \
         (bound {REST_DRIFT:.0e}), turn {turn:.1e}° (bound {REST_TURN}°): {}\n",
        if rest_ok { "at rest" } else { "FAIL" }
    );

    let mut runs = Vec::new();
    for index in 0..seas.len() {
        runs.extend(run_sea(&meshes, &seas, index)?);
    }
    for sea in &seas {
        println!("{}: {}", sea.name, sea.title);
    }
    println!(
        "{} bodies, {SETTLE} s of still water then {SECONDS} s of waves (ramped in over {RAMP} s), \
         rapier at 60 Hz; statistics from {STATS_FROM} s on\n",
        runs.len() / seas.len()
    );
    print_table(&runs, &seas);
    println!(
        "\nheave / η: on the regular wave, the amplitudes of the heave and of the elevation at the body at the\n   \
         wave's frequency (least squares), and the heave's lag; on the JONSWAP sea, their standard deviations.\n\
         pitch: the tilt of the body's line along the waves (bow up +); slope: the wave's slope angle at the body.\n\
         draft: the depth below the still level of the body's lowest point at rest; in brackets, at rest.\n\
         mean heave, η: on waves the bodies ride higher than at rest; the surface at them is higher on average\n   \
         too (they move with the water's orbits, forward under crests and back under troughs: a²k/2 = {:.1} mm\n   \
         for a particle in the regular wave).\n\
         drift: how far the center of mass moved horizontally from its rest position in the {SECONDS} s. The bodies\n   \
         drift down-wave: moving with the water's orbits they drift as the water does (Stokes drift, a²ωk =\n   \
         {:.1} cm/s in the regular wave), and the wave pressure on their moving waterline pushes them on\n   \
         average (the mean wave force along x).\n\
         bounded: every pose finite, |heave| ≤ {HEAVE_BOUND_HEIGHTS} wave heights (H = 2a, or Hs), speed ≤ {SPEED_BOUND} m/s,\n   \
         spin ≤ {SPIN_BOUND} rad/s (the test three_bodies_ride_ten_minutes_of_a_jonswap_sea holds them for 10 minutes).\n",
        1e3 * REGULAR.0 * REGULAR.0 * (2.0 * PI / REGULAR.1) / 2.0,
        1e2 * REGULAR.0 * REGULAR.0 * seas[0].omega.unwrap_or(f64::NAN) * (2.0 * PI / REGULAR.1),
    );

    let out = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("out");
    std::fs::create_dir_all(&out)?;
    let mut csv = String::from("sea,body,time_s,heave_m,pitch_deg,eta_m,slope_deg,draft_m\n");
    for run in &runs {
        for s in &run.samples {
            writeln!(
                csv,
                "{},{},{:.3},{:.5},{:.3},{:.5},{:.3},{:.5}",
                seas[run.sea].name, run.body, s.t, s.heave, s.pitch, s.eta, s.slope, s.draft
            )?;
        }
    }
    std::fs::write(out.join("waves.csv"), csv)?;
    let png = out.join("waves.png");
    plot(&png, &runs, &seas)?;
    println!(
        "wrote {} and {}",
        out.join("waves.csv").display(),
        png.display()
    );
    println!("finished in {:.1} s", started.elapsed().as_secs_f64());
    Ok(())
}

// The plot.

const BODY_COLOUR: RGBColor = RGBColor(0, 110, 200);
const PITCH_COLOUR: RGBColor = RGBColor(220, 80, 20);
const WAVE_COLOUR: RGBColor = RGBColor(0, 0, 0);
const GRID: RGBColor = RGBColor(225, 225, 225);
const HEADER: u32 = 150;

/// Draws a grid: a column per sea, a row per body, each cell the heave over the elevation at
/// the body and, below it, the pitch over the wave's slope, with the key figures in the
/// captions.
fn plot(path: &Path, runs: &[Run], seas: &[Sea]) -> Result<()> {
    plot_font::register()?;
    let bodies = runs.len() / seas.len();
    let size = (900 * seas.len() as u32, HEADER + 580 * bodies as u32);
    let root = BitMapBackend::new(path, size).into_drawing_area();
    root.fill(&WHITE)?;
    let (header, grid) = root.split_vertically(HEADER);
    draw_header(&header, seas)?;
    let cells = grid.split_evenly((bodies, seas.len()));
    for (sea_index, sea) in seas.iter().enumerate() {
        let column: Vec<&Run> = runs.iter().filter(|r| r.sea == sea_index).collect();
        // One scale per column, so that the bodies on a sea compare at a glance.
        let largest = |f: fn(&Sample) -> [f64; 2]| {
            column
                .iter()
                .flat_map(|r| r.samples.iter().flat_map(f))
                .fold(0.0, |m: f64, v| m.max(v.abs()))
                * 1.1
        };
        let heave_max = largest(|s| [s.heave, s.eta]);
        let pitch_max = largest(|s| [s.pitch, s.slope]);
        for (row, run) in column.iter().enumerate() {
            let st = stats(run, sea);
            let cell = cells[row * seas.len() + sea_index].margin(8, 8, 0, 0);
            let (top, bottom) = cell.split_vertically(cell.dim_in_pixel().1 / 2 - 10);
            let name = body_title(run.body);
            let heave = match st.heave_phase {
                Some(lag) => format!("heave {:.2} × η, lag {}°", st.heave_ratio, signed(lag, 0)),
                None => format!("heave std {:.2} × η std", st.heave_ratio),
            };
            chart(
                &top,
                &format!("{name}, {}: {heave}", sea.label),
                "heave, η (m)",
                run,
                heave_max,
                |s| (s.heave, s.eta),
                BODY_COLOUR,
                false,
            )?;
            chart(
                &bottom,
                &format!(
                    "{name}, {}: pitch {}° to {}° (slope {}° to {}°)",
                    sea.label,
                    signed(st.pitch.0, 1),
                    signed(st.pitch.1, 1),
                    signed(st.slope.0, 1),
                    signed(st.slope.1, 1)
                ),
                "pitch, slope (°)",
                run,
                pitch_max,
                |s| (s.pitch, s.slope),
                PITCH_COLOUR,
                row + 1 == bodies,
            )?;
        }
    }
    root.present()?;
    Ok(())
}

fn body_title(body: &str) -> &'static str {
    match body {
        "hull" => "Wigley hull 4 × 0.6 m",
        "bunny" => "Stanford bunny 1.2 m",
        _ => "buoy 0.6 m across",
    }
}

fn draw_header(area: &DrawingArea<BitMapBackend, Shift>, seas: &[Sea]) -> Result<()> {
    let title = (FAMILY, 30).into_font().color(&BLACK);
    let text = (FAMILY, 19).into_font().color(&BLACK);
    area.draw_text(
        "Floating on waves in rapier3d: heave and pitch against the surface at each body",
        &title,
        (20, 14),
    )?;
    let column = area.dim_in_pixel().0 as i32 / seas.len() as i32;
    for (i, sea) in seas.iter().enumerate() {
        area.draw_text(&sea.title, &text, (20 + column * i as i32, 58))?;
    }
    area.draw_text(
        &format!(
            "The bodies settle in still water; the waves, travelling along +x, then grow from nothing over the first \
             {RAMP} s. Figures over {STATS_FROM}–{SECONDS} s."
        ),
        &text,
        (20, 84),
    )?;
    let mut x = 20;
    let y = 114;
    for (colour, width, label) in [
        (BODY_COLOUR, 3, "heave of the center of mass"),
        (WAVE_COLOUR, 2, "η: surface elevation at the body"),
        (PITCH_COLOUR, 3, "pitch (bow up +)"),
        (WAVE_COLOUR, 2, "the wave's slope angle at the body"),
    ] {
        area.draw(&PathElement::new(
            [(x, y + 11), (x + 34, y + 11)],
            colour.stroke_width(width),
        ))?;
        area.draw_text(label, &text, (x + 42, y))?;
        x += 70 + area.estimate_text_size(label, &text)?.0 as i32;
    }
    Ok(())
}

/// One chart: the body's value (colour) over the wave's (black) against time.
#[allow(clippy::too_many_arguments)]
fn chart(
    area: &DrawingArea<BitMapBackend, Shift>,
    caption: &str,
    y_title: &str,
    run: &Run,
    max: f64,
    value: impl Fn(&Sample) -> (f64, f64),
    colour: RGBColor,
    time_axis: bool,
) -> Result<()> {
    let max = max.max(1e-6) as f32;
    let decimals = if max >= 5.0 {
        0
    } else if max >= 0.5 {
        1
    } else {
        2
    };
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FAMILY, 20))
        .margin_top(4)
        .margin_right(24)
        .margin_left(10)
        .margin_bottom(4)
        .x_label_area_size(if time_axis { 46 } else { 26 })
        .y_label_area_size(80)
        .build_cartesian_2d(0.0f32..SECONDS as f32, -max..max)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(GRID)
        .x_labels(13)
        .y_labels(5)
        .x_desc(if time_axis {
            "time since the waves started (s)"
        } else {
            ""
        })
        .y_desc(y_title)
        .label_style((FAMILY, 16))
        .axis_desc_style((FAMILY, 17))
        .x_label_formatter(&|t| format!("{t:.0}"))
        .y_label_formatter(&|v| {
            let text = format!("{v:.decimals$}");
            // No "−0.00": a zero is unsigned.
            if text
                .trim_start_matches('-')
                .chars()
                .all(|c| c == '0' || c == '.')
            {
                text.trim_start_matches('-').to_string()
            } else {
                text.replace('-', "−")
            }
        })
        .draw()?;
    chart.draw_series(LineSeries::new(
        run.samples.iter().map(|s| (s.t as f32, value(s).1 as f32)),
        WAVE_COLOUR.stroke_width(1),
    ))?;
    chart.draw_series(LineSeries::new(
        run.samples.iter().map(|s| (s.t as f32, value(s).0 as f32)),
        colour.stroke_width(2),
    ))?;
    Ok(())
}
