//! What the plugin costs per body per step above the core controller's own step: 100 bodies
//! floating on each backend, in calm water and on a JONSWAP sea (on waves every step evaluates
//! every body; in calm water a body whose inputs repeat exactly takes its last evaluation
//! again), boxes and (when the sample meshes are at hand) Stanford bunnies, never asleep, on a
//! grid 3 m apart so that they never touch. Each app is warmed up before measuring: 5 s of
//! simulated time on waves and without water, 40 s in calm water, where the bunnies come to
//! rest to the bit (and take their last evaluation again: the bench prints how many do; the
//! boxes keep a residual velocity of 1e-15 to 1e-11 m/s and are evaluated every step).
//!
//! Three apps per scene take turns, step by step, for 600 steps (10 s), so that the machine's
//! drift weighs on all three alike (in one order on even steps, the reverse on odd ones, so
//! that what one leaves in the caches favours none), and each step is timed:
//!
//! * (a) one `App::update` of the app with the plugin: one physics step with the buoyancy;
//! * (b) the core [`Controller`]'s step for the same 100 bodies, with the parts the plugin made
//!   of them, on the states of a twin of that app (built and warmed up alike: the plugin is
//!   deterministic) read as the plugin reads them, the twin then stepping on untimed: the
//!   same evaluations the plugin asks for, repeats in calm water included;
//! * (c) one `App::update` of the same bodies without the plugin or `Floating`, gravity scale
//!   0 (else they fall) and a constant drift and spin so that the engine integrates and
//!   re-bounds 100 moving bodies, without contacts, as it does for the floating ones.
//!
//! The plugin's cost per body per step is the mean of `(a − b − c) / 100` over the steps, with
//! its standard error. The table is printed and written between the `bevy-plugin` markers of
//! `benches/RESULTS.md`:
//!
//! ```text
//! cd crates/buoyancy-bevy && cargo bench --features rapier,avian --bench plugin
//! ```

use std::sync::Arc;
use std::time::{Duration, Instant};

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use buoyancy_bevy::{BuoyancyPlugin, FloatReport, Floating, Water};
use buoyancy_core::Mesh;
use buoyancy_core::controller::{BodyOptions, BodyState, Command, Controller, Part, Settings};
use buoyancy_core::nalgebra::{Point3, Vector3};
use buoyancy_core::water::{AiryWaves, SeaState, Spectrum};

const BODIES: usize = 100;
/// The physics step, s: one per `App::update`.
const DT: f64 = 1.0 / 60.0;
/// Steps before measuring on waves (5 s).
const WARM_UP_WAVES: usize = 300;
/// Steps before measuring in calm water (40 s): the bodies come to rest, and those at rest to
/// the bit take their last evaluation again (the bunnies from about 25 s).
const WARM_UP_CALM: usize = 2400;
/// Grid spacing, m: bodies of about 1 m never touch.
const SPACING: f32 = 3.0;

/// The physics engine.
#[derive(Clone, Copy, Debug)]
enum Backend {
    #[cfg(feature = "rapier")]
    Rapier,
    #[cfg(feature = "avian")]
    Avian,
}

impl Backend {
    fn all() -> Vec<Backend> {
        vec![
            #[cfg(feature = "rapier")]
            Backend::Rapier,
            #[cfg(feature = "avian")]
            Backend::Avian,
        ]
    }

    fn name(self) -> &'static str {
        match self {
            #[cfg(feature = "rapier")]
            Backend::Rapier => "rapier",
            #[cfg(feature = "avian")]
            Backend::Avian => "avian",
        }
    }
}

/// The water of a scene.
#[derive(Clone, Copy, Debug)]
enum Sea {
    Calm,
    Jonswap,
}

impl Sea {
    fn name(self) -> &'static str {
        match self {
            Sea::Calm => "calm",
            Sea::Jonswap => "jonswap",
        }
    }

    fn water(self) -> Water {
        match self {
            Sea::Calm => Water::default(),
            Sea::Jonswap => {
                let state = SeaState {
                    spectrum: Spectrum::Jonswap { gamma: 3.3 },
                    significant_height: 1.0,
                    peak_period: 6.0,
                    direction: Vector3::x(),
                    spreading: None,
                    components: 32,
                    seed: 3,
                };
                let waves =
                    AiryWaves::from_sea_state(&state, &buoyancy_core::Water::default(), None)
                        .expect("a valid sea state");
                Water::default().with_waves(waves)
            }
        }
    }
}

/// A floating body: its collider, its density, and the mesh it floats with if not the
/// collider's.
#[derive(Clone)]
struct Body {
    name: &'static str,
    collider: Shape,
    density: f32,
    mesh: Option<Arc<Mesh<f64>>>,
}

#[derive(Clone)]
enum Shape {
    /// Half extents, m.
    Cuboid(Vec3),
    /// The convex hull of these points (body frame).
    Hull(Vec<Vec3>),
}

impl Body {
    /// A 1 m × 0.4 m × 0.8 m box of density 500, floating flat with half its height under water
    /// (metacentric height 0.17 m, upright in both roll and pitch); floats with its collider.
    fn crate_box() -> Body {
        Body {
            name: "box",
            collider: Shape::Cuboid(Vec3::new(0.5, 0.2, 0.4)),
            density: 500.0,
            mesh: None,
        }
    }

    /// The Stanford bunny (5,002 triangles) scaled to 1 m, its centroid at the body's origin,
    /// floating with its mesh (`Floating::mesh`); its collider the convex hull of its vertices,
    /// of density 400. `None` when the sample mesh is absent (saying so; under `CI=true` its
    /// absence fails).
    fn bunny() -> Option<Body> {
        let path = buoyancy_samples::mesh_or_fallback(Some("bunny.obj"), "the box alone")?;
        let (vertices, triangles) = buoyancy_core::io::load::<f64>(&path).expect("the bunny");
        let raw = Mesh::new(vertices, triangles).expect("a closed bunny");
        let points = |mesh: &Mesh<f64>| -> Vec<Point3<f64>> {
            (0..mesh.vertex_count()).map(|i| mesh.vertex(i)).collect()
        };
        let extent = |mesh: &Mesh<f64>| {
            let p = points(mesh);
            (0..3)
                .map(|k| {
                    let (lo, hi) = p.iter().fold((f64::MAX, f64::MIN), |(lo, hi), q| {
                        (lo.min(q[k]), hi.max(q[k]))
                    });
                    hi - lo
                })
                .fold(0.0, f64::max)
        };
        let scale = 1.0 / extent(&raw);
        let mesh = raw
            .translated(&-raw.centroid().coords)
            .and_then(|m| m.scaled(&Vector3::repeat(scale)))
            .expect("the scaled bunny");
        let hull = points(&mesh)
            .iter()
            .map(|p| Vec3::new(p.x as f32, p.y as f32, p.z as f32))
            .collect();
        Some(Body {
            name: "bunny",
            collider: Shape::Hull(hull),
            density: 400.0,
            mesh: Some(Arc::new(mesh)),
        })
    }

    fn floating(&self) -> Floating {
        Floating {
            mesh: self.mesh.clone(),
            ..Floating::default()
        }
    }
}

fn grid(i: usize) -> Vec3 {
    Vec3::new(SPACING * (i % 10) as f32, 0.0, SPACING * (i / 10) as f32)
}

/// The physics-only bodies' drift and spin (the same for all: they never meet).
const DRIFT: Vec3 = Vec3::new(0.1, 0.0, 0.05);
const SPIN: Vec3 = Vec3::new(0.3, 0.2, 0.1);

/// An app of `backend` at one step per update with the 100 bodies, warmed up: floating in
/// `sea` with the plugin, or (`sea` `None`) without the plugin, weightless, drifting.
fn app(backend: Backend, body: &Body, sea: Option<Sea>) -> (App, Vec<Entity>) {
    let step = Duration::from_secs_f64(DT);
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(TimeUpdateStrategy::ManualDuration(step));
    match backend {
        #[cfg(feature = "rapier")]
        Backend::Rapier => {
            use bevy_rapier3d::prelude::*;
            app.add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
                .insert_resource(TimestepMode::Fixed {
                    dt: DT as f32,
                    substeps: 1,
                });
        }
        #[cfg(feature = "avian")]
        Backend::Avian => {
            use avian3d::prelude::*;
            app.add_plugins(PhysicsPlugins::default())
                .insert_resource(Time::<Fixed>::from_duration(step));
        }
    }
    if let Some(sea) = sea {
        app.add_plugins(BuoyancyPlugin::default())
            .insert_resource(sea.water());
    }
    app.finish();
    app.cleanup();
    app.update(); // bevy_rapier's context
    let entities = spawn(&mut app, backend, body, sea.is_some());
    let warm_up = match sea {
        Some(Sea::Calm) => WARM_UP_CALM,
        _ => WARM_UP_WAVES,
    };
    for _ in 0..warm_up {
        app.update();
    }
    if sea.is_some() {
        // One physics step per update (the first one or two once the bodies are in), and
        // the bodies afloat.
        let steps = app.world().resource::<Water>().time() / DT;
        assert!(
            (steps - warm_up as f64).abs() <= 2.0,
            "{steps} physics steps in {warm_up} updates"
        );
        let afloat = entities
            .iter()
            .filter(|&&e| {
                let r = app.world().get::<FloatReport>(e).unwrap();
                assert!(r.error.is_none(), "{:?}", r.error);
                r.in_water
            })
            .count();
        assert!(
            afloat > BODIES / 2,
            "{afloat} of {BODIES} bodies in the water"
        );
    }
    (app, entities)
}

fn spawn(app: &mut App, backend: Backend, body: &Body, floating: bool) -> Vec<Entity> {
    #[cfg(feature = "rapier")]
    let rapier_collider = match (&body.collider, backend) {
        (Shape::Cuboid(h), Backend::Rapier) => {
            Some(bevy_rapier3d::prelude::Collider::cuboid(h.x, h.y, h.z))
        }
        (Shape::Hull(points), Backend::Rapier) => {
            bevy_rapier3d::prelude::Collider::convex_hull(points)
        }
        #[allow(unreachable_patterns)]
        _ => None,
    };
    #[cfg(feature = "avian")]
    let avian_collider = match (&body.collider, backend) {
        (Shape::Cuboid(h), Backend::Avian) => Some(avian3d::prelude::Collider::cuboid(
            2.0 * h.x,
            2.0 * h.y,
            2.0 * h.z,
        )),
        (Shape::Hull(points), Backend::Avian) => avian3d::prelude::Collider::convex_hull(points),
        #[allow(unreachable_patterns)]
        _ => None,
    };
    (0..BODIES)
        .map(|i| {
            let mut entity = app.world_mut().spawn(Transform::from_translation(grid(i)));
            match backend {
                #[cfg(feature = "rapier")]
                Backend::Rapier => {
                    use bevy_rapier3d::prelude::*;
                    entity.insert((
                        RigidBody::Dynamic,
                        rapier_collider.clone().expect("a collider"),
                        ColliderMassProperties::Density(body.density),
                        Sleeping::disabled(),
                    ));
                    if floating {
                        entity.insert(Velocity::default());
                    } else {
                        entity.insert((
                            GravityScale(0.0),
                            Velocity {
                                linear: DRIFT,
                                angular: SPIN,
                            },
                        ));
                    }
                }
                #[cfg(feature = "avian")]
                Backend::Avian => {
                    use avian3d::prelude::*;
                    entity.insert((
                        RigidBody::Dynamic,
                        avian_collider.clone().expect("a collider"),
                        ColliderDensity(body.density),
                        SleepingDisabled,
                    ));
                    if !floating {
                        entity.insert((
                            GravityScale(0.0),
                            LinearVelocity(DRIFT),
                            AngularVelocity(SPIN),
                        ));
                    }
                }
            }
            if floating {
                entity.insert(body.floating());
            }
            entity.id()
        })
        .collect()
}

/// The core controller with the plugin's bodies (their parts, as the plugin made them, in
/// `entities`' order), its water and waves.
fn controller(app: &App, backend: Backend, entities: &[Entity]) -> Controller {
    let world = app.world();
    let (parts, water): (Vec<Vec<Part>>, buoyancy_core::Water<f64>) = match backend {
        #[cfg(feature = "rapier")]
        Backend::Rapier => {
            let books = world.resource::<buoyancy_bevy::rapier_backend::RapierFloating>();
            let mut water = None;
            // One copy of each mesh the plugin's bodies share, shared as they share it.
            let mut copies: Vec<(&Mesh<f64>, Arc<Mesh<f64>>)> = Vec::new();
            let parts = entities
                .iter()
                .map(|&e| {
                    let (context, handle) = books.handle(e).expect("a floating body");
                    let bodies = books.bodies(context).expect("its context");
                    water = Some(*bodies.water());
                    bodies
                        .meshes(handle)
                        .map(|(mesh, shape_to_body)| {
                            let copy = match copies.iter().find(|(m, _)| std::ptr::eq(*m, mesh)) {
                                Some((_, copy)) => copy.clone(),
                                None => {
                                    let copy = Arc::new(mesh.clone());
                                    copies.push((mesh, copy.clone()));
                                    copy
                                }
                            };
                            Part {
                                mesh: copy,
                                shape_to_body: *shape_to_body,
                            }
                        })
                        .collect()
                })
                .collect();
            eprintln!(
                "rapier: {} distinct meshes for {BODIES} bodies",
                copies.len()
            );
            (parts, water.expect("bodies"))
        }
        #[cfg(feature = "avian")]
        Backend::Avian => {
            let books = world.resource::<buoyancy_bevy::avian_backend::AvianFloating>();
            let plugin = books.controller();
            let parts = entities
                .iter()
                .map(|&e| {
                    let i = books.index(e).expect("a floating body");
                    plugin.parts(i).expect("its parts").to_vec()
                })
                .collect();
            (parts, plugin.settings().water)
        }
    };
    let mut controller = Controller::new(Settings {
        water,
        ..Settings::default()
    });
    controller.set_surface(world.resource::<Water>().waves().cloned());
    for body in parts {
        controller.add(body, BodyOptions::default()).unwrap();
    }
    controller
}

/// The states of `entities` as the plugin reads them at the start of the next step.
fn states(app: &mut App, backend: Backend, entities: &[Entity]) -> Vec<BodyState> {
    match backend {
        #[cfg(feature = "rapier")]
        Backend::Rapier => rapier_states(app, entities),
        #[cfg(feature = "avian")]
        Backend::Avian => avian_states(app, entities),
    }
}

#[cfg(feature = "avian")]
fn vector(v: Vec3) -> Vector3<f64> {
    Vector3::new(f64::from(v.x), f64::from(v.y), f64::from(v.z))
}

#[cfg(feature = "avian")]
fn pose(t: Vec3, q: Quat) -> buoyancy_core::Pose<f64> {
    use buoyancy_core::Pose;
    use buoyancy_core::nalgebra::{Quaternion, Translation3, UnitQuaternion};
    Pose::from_parts(
        Translation3::from(vector(t)),
        UnitQuaternion::new_normalize(Quaternion::new(
            f64::from(q.w),
            f64::from(q.x),
            f64::from(q.y),
            f64::from(q.z),
        )),
    )
}

/// What `buoyancy_rapier::FloatingBodies::apply` reads of each rapier body.
#[cfg(feature = "rapier")]
fn rapier_states(app: &mut App, entities: &[Entity]) -> Vec<BodyState> {
    use bevy_rapier3d::prelude::{RapierRigidBodyHandle, RapierRigidBodySet};
    let world = app.world_mut();
    let mut sets = world.query::<&RapierRigidBodySet>();
    let set = sets.single(world).expect("one rapier context");
    entities
        .iter()
        .map(|&e| {
            let handle = world
                .get::<RapierRigidBodyHandle>(e)
                .expect("a rapier body");
            buoyancy_rapier::body_state(&set.bodies[handle.0])
        })
        .collect()
}

/// What the avian backend reads of each avian body; the force it holds is the controller's
/// share (buoyancy and damping as applied: the bodies have no force of their own).
#[cfg(feature = "avian")]
fn avian_states(app: &mut App, entities: &[Entity]) -> Vec<BodyState> {
    use avian3d::prelude::*;
    use buoyancy_core::controller::Motion;
    use buoyancy_core::nalgebra::Matrix3;
    let world = app.world();
    entities
        .iter()
        .map(|&e| {
            let position = world.get::<Position>(e).expect("a Position");
            let rotation = world.get::<Rotation>(e).expect("a Rotation");
            let com = world
                .get::<ComputedCenterOfMass>(e)
                .expect("a center of mass");
            let v = world.get::<LinearVelocity>(e).expect("a velocity");
            let w = world
                .get::<AngularVelocity>(e)
                .expect("an angular velocity");
            let mass = world.get::<ComputedMass>(e).expect("a mass");
            let inertia = world.get::<ComputedAngularInertia>(e).expect("an inertia");
            let report = &world.get::<FloatReport>(e).expect("a report").report;
            let pose = pose(position.0, rotation.0);
            let s = inertia.inverse();
            let local = Matrix3::new(
                s.m00, s.m01, s.m02, //
                s.m01, s.m11, s.m12, //
                s.m02, s.m12, s.m22,
            )
            .cast::<f64>();
            let r = pose.rotation.to_rotation_matrix().into_inner();
            BodyState {
                pose,
                center_of_mass: pose * Point3::from(vector(com.0)),
                linear_velocity: vector(v.0),
                angular_velocity: vector(w.0),
                mass: f64::from(mass.value()),
                inverse_mass: Vector3::repeat(f64::from(mass.inverse())),
                inverse_inertia: r * local * r.transpose(),
                gravity_scale: 1.0,
                applied_force: (report.buoyancy_force + report.damping_force).cast::<f32>(),
                applied_torque: (report.buoyancy_torque + report.damping_torque).cast::<f32>(),
                motion: Motion::Dynamic,
                sleeping: world.get::<Sleeping>(e).is_some(),
            }
        })
        .collect()
}

/// Rounds measured per scene (10 s of simulated time), after `SETTLE` rounds unmeasured.
const ROUNDS: usize = 600;
const SETTLE: usize = 30;
const BEGIN: &str = "<!-- bevy-plugin:begin (written by `cargo bench --bench plugin`) -->";
const END: &str = "<!-- bevy-plugin:end -->";

/// Mean and standard error of the mean.
fn mean_and_error(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let variance = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (variance / n).sqrt())
}

fn micros(value: f64) -> String {
    if value >= 1e3 {
        format!("{:.2} ms", value / 1e3)
    } else {
        format!("{value:.1} µs")
    }
}

/// How long `f` takes, µs.
fn time_of(f: impl FnOnce()) -> f64 {
    let start = Instant::now();
    f();
    start.elapsed().as_secs_f64() * 1e6
}

/// One row of the table: the three apps of a scene taking turns, step by step.
fn scene(backend: Backend, body: &Body, sea: Sea, physics: &mut App) -> String {
    let (mut with_plugin, _) = app(backend, body, Some(sea));
    let (mut twin, entities) = app(backend, body, Some(sea));
    let mut controller = controller(&twin, backend, &entities);
    let mut commands = vec![Command::default(); BODIES];
    let (mut a, mut b, mut c, mut cost) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let (mut last, mut repeats) = (Vec::new(), 0_usize);
    for round in 0..SETTLE + ROUNDS {
        // Each app runs after a different one on even and odd steps, so that what one leaves
        // in the caches (the twin's step evaluates the very meshes) favours none of them.
        let time = twin.world().resource::<Water>().time();
        let states = states(&mut twin, backend, &entities);
        let mut alone = || {
            time_of(|| {
                controller.set_time(time);
                controller.step(&states, DT, &mut commands);
            })
        };
        let (plugin, alone, bare) = if round % 2 == 0 {
            let plugin = time_of(|| with_plugin.update());
            let alone = alone();
            twin.update();
            (plugin, alone, time_of(|| physics.update()))
        } else {
            let bare = time_of(|| physics.update());
            let alone = alone();
            twin.update();
            (time_of(|| with_plugin.update()), alone, bare)
        };
        if round >= SETTLE {
            a.push(plugin);
            b.push(alone);
            c.push(bare);
            cost.push((plugin - alone - bare) / BODIES as f64);
            repeats += states.iter().zip(&last).filter(|(x, y)| x == y).count();
        }
        last = states;
    }
    let (cost, error) = mean_and_error(&cost);
    let mean = |v: &[f64]| micros(mean_and_error(v).0);
    format!(
        "| {} | {} | {} | {} | {} | {} | {:.0} % | {cost:.2} ± {error:.2} µs |\n",
        backend.name(),
        body.name,
        sea.name(),
        mean(&a),
        mean(&b),
        mean(&c),
        100.0 * repeats as f64 / (ROUNDS * BODIES) as f64,
    )
}

fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    format!(
        "{cpu}, {cores} cores available; {} {}",
        std::env::consts::OS,
        std::env::consts::ARCH
    )
}

fn main() {
    let mut bodies = vec![Body::crate_box()];
    bodies.extend(Body::bunny());
    let mut report = format!(
        "Machine: {}; {BODIES} bodies {SPACING} m apart, never asleep, one physics step of \
         1/60 s per `App::update`; means over {ROUNDS} steps, the cost's standard error from \
         its {ROUNDS} paired differences.\n\n\
         | backend | body | water | (a) with the plugin | (b) controller alone | (c) physics \
         only | states repeated | (a − b − c) / {BODIES} |\n|---|---|---|---|---|---|---|---|\n",
        machine()
    );
    for backend in Backend::all() {
        for body in &bodies {
            let (mut physics, _) = app(backend, body, None);
            for sea in [Sea::Calm, Sea::Jonswap] {
                let row = scene(backend, body, sea, &mut physics);
                eprint!("{row}");
                report += &row;
            }
        }
    }
    println!("{report}");
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../benches/RESULTS.md");
    let old = std::fs::read_to_string(&path).expect("benches/RESULTS.md");
    let new = match (old.find(BEGIN), old.find(END)) {
        (Some(b), Some(e)) if b < e => format!("{}{BEGIN}\n{report}{}", &old[..b], &old[e..]),
        _ => format!("{old}\n{BEGIN}\n{report}{END}\n"),
    };
    std::fs::write(&path, new).expect("writable benches/RESULTS.md");
    eprintln!("written to {}", path.display());
}
