//! Floating on waves: a small light buoy follows a long swell; the bodies of the `waves` demo
//! stay at rest in still water and ride ten minutes of an irregular sea without blowing up.

mod common;

use std::sync::Arc;

use buoyancy_core::nalgebra::{Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::water::{AiryComponent, AiryWaves, CalmSurface, SeaState, Spectrum};
use buoyancy_core::{Mesh, Method, Pose, Water, mesh::primitives};
use buoyancy_rapier::{FloatOptions, FloatingBodies, Outcome};
use common::{DT, Pool};
use rapier3d::prelude::*;

/// A ball 0.5 m across, a tenth as dense as water, in a deep-water swell 20 m long (40 of its
/// diameters) and 0.1 m high: linear theory says it rides the surface, its heave the wave's
/// elevation at its place (the hydrostatic response `1/(1 − ω²/ω_n²)` is 1.02 here). Measured
/// over the last 5 periods of 60 s, after the start's transient has died out: the heave's
/// amplitude within 2 % of the wave's and its phase within 5°.
#[test]
fn a_small_light_buoy_follows_a_long_swell() {
    let (amplitude, wavelength) = (0.1, 20.0);
    let swell = AiryWaves::new(
        vec![AiryComponent {
            amplitude,
            wavelength,
            direction: Vector3::x(),
            phase: 0.0,
        }],
        None,
    )
    .unwrap();
    let omega = swell.angular_frequency(0, 9.81);
    let mut world = PhysicsWorld::default();
    let (buoy, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, 0.05, 0.0))
            .can_sleep(false),
        ColliderBuilder::ball(0.25).density(100.0),
    );
    let mut water = FloatingBodies::new(world.gravity).unwrap();
    water.set_surface(Some(Arc::new(swell)));
    water
        .register(
            buoy,
            &world.bodies,
            &world.colliders,
            FloatOptions::default(),
        )
        .unwrap();
    let period = 2.0 * std::f64::consts::PI / omega;
    let (start, end) = (60.0 - 5.0 * period, 60.0);
    // Least squares of y = A cos ωt + B sin ωt + C over [start, end].
    let mut samples = Vec::new();
    while water.time() < end {
        water.apply(&mut world.bodies, world.integration_parameters.dt);
        world.step();
        let t = water.time();
        if t >= start {
            samples.push((t, f64::from(world.bodies[buoy].center_of_mass().y)));
        }
        assert!(world.bodies[buoy].translation().is_finite());
    }
    let basis = |t: f64| [(omega * t).cos(), (omega * t).sin(), 1.0];
    let mut normal = [[0.0; 3]; 3];
    let mut rhs = [0.0; 3];
    for &(t, y) in &samples {
        let b = basis(t);
        for i in 0..3 {
            rhs[i] += b[i] * y;
            for j in 0..3 {
                normal[i][j] += b[i] * b[j];
            }
        }
    }
    let m = buoyancy_core::nalgebra::Matrix3::from_fn(|i, j| normal[i][j]);
    let [a, b, _] = m.lu().solve(&Vector3::from(rhs)).unwrap().into();
    let heave = a.hypot(b);
    // The wave at x = 0 is a·cos(−ωt) = a·cos ωt: phase 0.
    let phase = b.atan2(a).to_degrees();
    eprintln!(
        "heave {:.4} of the wave, phase {phase:.2}°",
        heave / amplitude
    );
    assert!(
        (heave / amplitude - 1.0).abs() < 0.02,
        "heave amplitude {heave} m against {amplitude} m (phase {phase}°)"
    );
    assert!(phase.abs() < 5.0, "phase {phase}° (amplitude {heave} m)");
}

/// The Wigley hull of the `waves` demo: 4 m long, 0.6 m wide, 0.25 m design draft, 0.15 m of
/// freeboard, meshed with `stations` and `waterlines` (the demo's 41 and 17: 2,798 triangles),
/// and the uniform density that floats it at its design draft (its mass ρ times the mesh's
/// volume below y = 0).
fn wigley_hull(stations: usize, waterlines: usize) -> (Mesh<f64>, f64) {
    let (v, t) =
        primitives::wigley_hull::<f64>(4.0, 0.6, 0.25, 0.15, stations, waterlines).unwrap();
    let hull = Mesh::new(v, t).unwrap();
    let water = Water::default();
    let below = hull
        .buoyancy(&Pose::identity(), &water, Method::Exact)
        .unwrap()
        .submerged_volume;
    let density = water.density() * below / hull.volume();
    (hull, density)
}

/// Adds the hull meshed with `stations` and `waterlines` at its design draft (the identity
/// pose, its design waterline at y = 0).
fn add_hull(pool: &mut Pool, stations: usize, waterlines: usize) -> RigidBodyHandle {
    let (hull, density) = wigley_hull(stations, waterlines);
    pool.add(
        RigidBodyBuilder::dynamic(),
        common::trimesh(&hull).density(density as f32),
    )
}

/// Adds the demo's buoy floating at its draft: a cylinder 0.6 m across and 0.5 m tall
/// of 160 kg/m³ with a lead ball 0.2 m across inside at its bottom (only the cylinder floats).
fn add_buoy(pool: &mut Pool) -> RigidBodyHandle {
    let (radius, half_height, density) = (0.3f32, 0.25f32, 160.0f32);
    let (ball, ball_density, ball_depth) = (0.1f32, 11340.0f32, 0.15f32);
    let pi = std::f32::consts::PI;
    let mass = density * pi * radius * radius * 2.0 * half_height
        + ball_density * 4.0 / 3.0 * pi * ball.powi(3);
    let draft = mass / (1000.0 * pi * radius * radius);
    let world = &mut pool.world;
    let (buoy, cylinder) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, half_height - draft, 0.0))
            .can_sleep(false),
        ColliderBuilder::cylinder(half_height, radius).density(density),
    );
    world.insert_collider(
        ColliderBuilder::ball(ball)
            .translation(Vector::new(0.0, -ball_depth, 0.0))
            .density(ball_density),
        Some(buoy),
    );
    pool.water
        .register(
            buoy,
            &world.bodies,
            &world.colliders,
            FloatOptions::default().colliders([cylinder]),
        )
        .unwrap();
    buoy
}

/// Adds `mesh` half as dense as water at the height where it displaces its weight in its
/// attitude as given.
fn add_half_density(pool: &mut Pool, mesh: &Mesh<f64>) -> RigidBodyHandle {
    let (mut lo, mut hi) = (-mesh.bounding_radius(), mesh.bounding_radius());
    for _ in 0..40 {
        let y = 0.5 * (lo + hi);
        let pose = Pose::from_parts(Translation3::new(0.0, y, 0.0), UnitQuaternion::identity());
        let below = mesh
            .buoyancy(&pose, &Water::default(), Method::Exact)
            .unwrap()
            .submerged_volume;
        if below > 0.5 * mesh.volume() {
            lo = y;
        } else {
            hi = y;
        }
    }
    pool.add(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, (0.5 * (lo + hi)) as f32, 0.0)),
        common::trimesh(mesh).density(500.0),
    )
}

/// The hull of the `waves` demo placed at its design draft in still water stays there: over
/// 30 s its speed stays below 1e-4 m/s and its spin below 1e-4 rad/s, and it ends within
/// 0.1 mm and 0.001° of where it was placed, both in still water and with a calm surface set
/// (`CalmSurface`, which takes the waves' path). Measured, either way: speed 8.1e-7 m/s, spin
/// 9.0e-7 rad/s, drift 1.5e-7 m, turn 0 (below what rapier's `f32` quaternion resolves).
#[test]
fn a_hull_at_its_design_draft_stays_at_rest() {
    for calm in [false, true] {
        let mut pool = Pool::new();
        if calm {
            pool.water.set_surface(Some(Arc::new(CalmSurface)));
        }
        let hull = add_hull(&mut pool, 41, 17);
        let start = *pool.body(hull).position();
        let (mut speed, mut spin) = (0.0f32, 0.0f32);
        for _ in 0..(30.0 / DT).round() as usize {
            pool.step();
            speed = speed.max(pool.body(hull).linvel().length());
            spin = spin.max(pool.body(hull).angvel().length());
        }
        let end = pool.body(hull).position();
        let drift = (end.translation - start.translation).length();
        let turn = end.rotation.angle_between(start.rotation).to_degrees();
        eprintln!(
            "calm surface {calm}: speed {speed:.2e} m/s, spin {spin:.2e} rad/s, drift {drift:.2e} m, turn {turn:.2e}°"
        );
        assert!(
            speed < 1e-4 && spin < 1e-4,
            "calm surface {calm}: speed {speed} m/s, spin {spin} rad/s"
        );
        assert!(
            drift < 1e-4 && turn < 1e-3,
            "calm surface {calm}: drifted {drift} m, turned {turn}°"
        );
    }
}

/// Ten minutes (36,000 steps) of the `waves` demo's JONSWAP sea (γ = 3.3, H_s = 0.3 m,
/// T_p = 2.5 s, seed 7, long-crested along x), started at once on three bodies at rest at their
/// still-water drafts, each in a world (and a thread) of its own: the demo's Wigley hull and
/// buoy, and, for its bunny, a procedural torus knot of the same size and density (1.2 m across,
/// half as dense as water). So that the test takes seconds, not minutes, in the test profile,
/// the sea has 32 components (the demo's 64), the hull is meshed coarser (21 stations,
/// 9 waterlines: 758 triangles against 2,798) and the knot has 576 triangles (the bunny 5,002).
/// At every step every pose and velocity is finite and every body's forces are applied; no
/// center of mass rises or sinks more than 2·H_s = 0.6 m from its rest height, none moves
/// faster than 3 m/s, none spins faster than 5 rad/s. Measured (largest |heave|, speed, spin;
/// drift down-wave at the end):
///
/// | body | heave (m) | speed (m/s) | spin (rad/s) | drift (m) |
/// |---|---|---|---|---|
/// | hull | 0.189 | 0.75 | 0.61 | 124 |
/// | torus knot | 0.292 | 1.13 | 2.79 | 26 |
/// | buoy | 0.357 | 1.50 | 2.04 | 40 |
///
/// The bounds are 1.7 to 2 times the largest values. The hull drifts down-wave at 0.21 m/s on
/// average, as fast as in the demo's first minute: the mean wave force on it (4 N in the demo)
/// against its drag.
#[test]
fn three_bodies_ride_ten_minutes_of_a_jonswap_sea() {
    let sea = AiryWaves::from_sea_state(
        &SeaState {
            spectrum: Spectrum::Jonswap { gamma: 3.3 },
            significant_height: 0.3,
            peak_period: 2.5,
            direction: Vector3::x(),
            spreading: None,
            components: 32,
            seed: 7,
        },
        &Water::default(),
        None,
    )
    .unwrap();
    let bodies: [(&str, AddBody); 3] = [
        ("hull", |pool| add_hull(pool, 21, 9)),
        ("torus knot", |pool| add_half_density(pool, &coarse_knot())),
        ("buoy", |pool| add_buoy(pool)),
    ];
    std::thread::scope(|scope| {
        let rides: Vec<_> = bodies
            .into_iter()
            .map(|(name, add)| {
                let sea = sea.clone();
                scope.spawn(move || ride(name, add, sea, 0.3, 600.0))
            })
            .collect();
        for ride in rides {
            ride.join()
                .unwrap_or_else(|panic| std::panic::resume_unwind(panic));
        }
    });
}

/// Puts a body in a pool, returning its handle.
type AddBody = fn(&mut Pool) -> RigidBodyHandle;

/// The procedural torus knot 1.2 m across (576 triangles), centered on its centroid.
fn coarse_knot() -> Mesh<f64> {
    let (v, t) = primitives::torus_knot::<f64>(2, 3, 1.0, 0.3, 48, 6).unwrap();
    let knot = Mesh::new(v, t).unwrap();
    let (center, scale) = (knot.centroid(), 0.6 / knot.bounding_radius());
    let v = (0..knot.vertex_count())
        .map(|i| Point3::from((knot.vertex(i) - center) * scale))
        .collect();
    Mesh::new(v, knot.triangles().to_vec()).unwrap()
}

/// The body `add` puts in a world of its own, on `sea` for `seconds` from its rest: asserts at
/// every step that its pose and velocity are finite, its forces applied, its heave within
/// `2·hs` of its rest height, its speed within 3 m/s and its spin within 5 rad/s.
fn ride(name: &str, add: AddBody, sea: AiryWaves<f64>, hs: f64, seconds: f32) {
    let mut pool = Pool::new();
    pool.water.set_surface(Some(Arc::new(sea)));
    let h = add(&mut pool);
    let rest = pool.body(h).center_of_mass();
    let (mut heave, mut speed, mut spin) = (0.0f32, 0.0f32, 0.0f32);
    for step in 1..=(seconds / DT).round() as usize {
        pool.step();
        let rb = pool.body(h);
        let t = step as f32 * DT;
        assert!(
            rb.translation().is_finite()
                && rb.rotation().is_finite()
                && rb.linvel().is_finite()
                && rb.angvel().is_finite(),
            "{name} at {t} s: pose {:?}, velocity {:?} {:?}",
            rb.position(),
            rb.linvel(),
            rb.angvel()
        );
        assert_eq!(
            pool.water.report(h).unwrap().outcome,
            Outcome::Applied,
            "{name} at {t} s"
        );
        heave = heave.max((rb.center_of_mass().y - rest.y).abs());
        speed = speed.max(rb.linvel().length());
        spin = spin.max(rb.angvel().length());
        assert!(heave <= 2.0 * hs as f32, "{name} at {t} s: heave {heave} m");
        assert!(speed <= 3.0, "{name} at {t} s: speed {speed} m/s");
        assert!(spin <= 5.0, "{name} at {t} s: spin {spin} rad/s");
    }
    let drift = pool.body(h).center_of_mass() - rest;
    eprintln!(
        "{name}: largest |heave| {heave:.3} m, speed {speed:.2} m/s, spin {spin:.2} rad/s; drifted {:.1} m along x, {:.1} m across; tilt {:.1}° at the end",
        drift.x,
        drift.z,
        common::tilt_degrees(pool.body(h)),
    );
}
