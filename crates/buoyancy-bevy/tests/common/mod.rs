//! The behaviours both backends are held to, written once against [`Backend`]: each test file
//! (`rapier.rs`, `avian.rs`) implements it for its engine and runs every scenario.
#![allow(dead_code)]

use std::time::Duration;

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use buoyancy_bevy::{FloatReport, Floating, Water};
use buoyancy_core::nalgebra::Vector3;
use buoyancy_core::water::{AiryWaves, SeaState, Spectrum};

/// The physics step of the tests, s: each `App::update` is one step.
pub const DT: f32 = 1.0 / 60.0;
pub const RHO: f64 = 1000.0;
pub const G: f64 = 9.81;

/// What a scenario needs of a backend.
pub trait Backend {
    /// An app of `MinimalPlugins`, the backend's physics at 60 Hz (one step per update, time
    /// advanced by hand) and the buoyancy plugin.
    fn app() -> App;
    /// A dynamic box of half extents `half` and `density`, never asleep unless `can_sleep`.
    fn spawn_box(app: &mut App, half: Vec3, density: f32, at: Transform, can_sleep: bool)
    -> Entity;
    /// A box of half extents `half` whose mass properties are given: `mass`, center of mass
    /// `com` (body frame), principal inertia `inertia`.
    fn spawn_loaded_box(
        app: &mut App,
        half: Vec3,
        mass: f32,
        com: Vec3,
        inertia: Vec3,
        at: Transform,
    ) -> Entity;
    /// Sets the application's own constant force on the body (world frame).
    fn set_thrust(app: &mut App, body: Entity, force: Vec3);
    fn translation(app: &App, body: Entity) -> Vec3;
    fn rotation(app: &App, body: Entity) -> Quat;
    fn linear_velocity(app: &App, body: Entity) -> Vec3;
    fn sleeping(app: &App, body: Entity) -> bool;
}

pub fn base_app(app: &mut App) {
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f32(
            DT,
        )));
}

pub fn run(app: &mut App, seconds: f32) {
    for _ in 0..(seconds / DT).round() as usize {
        app.update();
    }
}

pub fn report(app: &App, body: Entity) -> FloatReport {
    app.world()
        .get::<FloatReport>(body)
        .cloned()
        .unwrap_or_default()
}

/// A 2 m × 0.5 m × 1 m crate of density 500 settles with half its height under water: its
/// center at the surface (within 1 mm), its draft 0.25 m, the water it displaces its weight.
pub fn crate_settles_at_its_draft<B: Backend>() {
    let mut app = B::app();
    let body = B::spawn_box(
        &mut app,
        Vec3::new(1.0, 0.25, 0.5),
        500.0,
        Transform::from_xyz(0.0, 0.6, 0.0),
        false,
    );
    app.world_mut().entity_mut(body).insert(Floating::default());
    run(&mut app, 20.0);
    let y = B::translation(&app, body).y;
    assert!(y.abs() < 1e-3, "center {y} m from the surface");
    let r = report(&app, body);
    assert!((r.draft - 0.25).abs() < 1e-3, "draft {}", r.draft);
    assert!(
        (r.submerged_volume - 0.5).abs() < 1e-3,
        "submerged {}",
        r.submerged_volume
    );
    assert!(r.in_water && r.error.is_none());
    // The wetted fraction: the bottom (2 × 1) and half the sides (2·(2 + 1)·0.25) of 7 m².
    assert!(
        (r.wetted_fraction - 3.5 / 7.0).abs() < 1e-3,
        "{}",
        r.wetted_fraction
    );
}

/// A barge 1 m wide and 4 m long (along x), 0.6 m high, of 800 kg (draft 0.2 m), its center of
/// mass 5 cm off the centreline at 0.2 m above the keel, heels to the wall-sided formula's
/// angle: `tan φ·(GM + BM·tan²φ/2) = t`.
pub fn off_centre_load_heels_to_the_wall_sided_angle<B: Backend>() {
    let (b, l, h, mass, t, kg) = (1.0f64, 4.0f64, 0.6f64, 800.0f64, 0.05f64, 0.2f64);
    let draft = mass / (RHO * b * l);
    let bm = b * b / (12.0 * draft);
    let gm = draft / 2.0 + bm - kg;
    // Newton on f(x) = x·(GM + BM·x²/2) − t.
    let mut x = t / gm;
    for _ in 0..50 {
        x -= (x * (gm + bm * x * x / 2.0) - t) / (gm + 1.5 * bm * x * x);
    }
    let expected = x.atan().to_degrees();
    let mut app = B::app();
    let body = B::spawn_loaded_box(
        &mut app,
        Vec3::new((l / 2.0) as f32, (h / 2.0) as f32, (b / 2.0) as f32),
        mass as f32,
        Vec3::new(0.0, (kg - h / 2.0) as f32, t as f32),
        Vec3::new(91.0, 1133.0, 1091.0),
        Transform::from_xyz(0.0, 0.2, 0.0),
    );
    app.world_mut().entity_mut(body).insert(Floating::default());
    run(&mut app, 60.0);
    // Heel about x: the body's z axis tips down (the load is on +z).
    let z = B::rotation(&app, body) * Vec3::Z;
    let heel = f64::from((-z.y).atan2(z.z)).to_degrees();
    assert!(
        (heel - expected).abs() < 0.005,
        "heel {heel}° against the wall-sided {expected}°"
    );
}

/// A buoy on a JONSWAP sea (Hs 1 m) for 10 minutes of game time stays on the sea: it never
/// leaves the band of the waves, its speed stays that of the water.
pub fn body_on_waves_stays_bounded<B: Backend>() {
    let mut app = B::app();
    let sea = SeaState {
        spectrum: Spectrum::Jonswap { gamma: 3.3 },
        significant_height: 1.0,
        peak_period: 6.0,
        direction: Vector3::x(),
        spreading: None,
        components: 32,
        seed: 3,
    };
    let waves = AiryWaves::from_sea_state(&sea, &buoyancy_core::Water::default(), None).unwrap();
    app.insert_resource(Water::default().with_waves(waves));
    let body = B::spawn_box(
        &mut app,
        Vec3::splat(0.3),
        300.0,
        Transform::from_xyz(0.0, 0.2, 0.0),
        false,
    );
    app.world_mut().entity_mut(body).insert(Floating::default());
    let (mut low, mut high, mut fastest) = (f32::MAX, f32::MIN, 0.0f32);
    for _ in 0..(600.0 / DT) as usize {
        app.update();
        let p = B::translation(&app, body);
        assert!(p.is_finite(), "the buoy left the numbers: {p}");
        low = low.min(p.y);
        high = high.max(p.y);
        fastest = fastest.max(B::linear_velocity(&app, body).length());
    }
    assert!(low > -1.5 && high < 1.5, "heave from {low} to {high} m");
    assert!(fastest < 5.0, "{fastest} m/s");
    assert!(app.world().resource::<Water>().time() > 599.0);
}

/// The application's own thrust stays: a crate pushed by 100 N along x keeps accelerating
/// along x against the drag, and keeps floating.
pub fn the_users_thrust_survives<B: Backend>() {
    let mut app = B::app();
    let body = B::spawn_box(
        &mut app,
        Vec3::new(1.0, 0.25, 0.5),
        500.0,
        Transform::from_xyz(0.0, 0.0, 0.0),
        false,
    );
    app.world_mut().entity_mut(body).insert(Floating::default());
    run(&mut app, 5.0);
    B::set_thrust(&mut app, body, Vec3::new(100.0, 0.0, 0.0));
    run(&mut app, 10.0);
    let v = B::linear_velocity(&app, body);
    let p = B::translation(&app, body);
    assert!(v.x > 0.1 && p.x > 0.5, "pushed: v {v}, at {p}");
    assert!(p.y.abs() < 0.02, "still afloat: {p}");
    let report = report(&app, body);
    // The damping opposes the motion: its force along x is negative.
    assert!(
        report.report.damping_force.x < 0.0,
        "{:?}",
        report.report.damping_force
    );
}

/// Removing `Floating` takes the buoyancy off (the crate falls as in air), and so does
/// despawning (the others float on).
pub fn removal_and_despawn_leave_no_force<B: Backend>() {
    let mut app = B::app();
    let a = B::spawn_box(
        &mut app,
        Vec3::splat(0.5),
        500.0,
        Transform::from_xyz(0.0, 0.0, 0.0),
        false,
    );
    let b = B::spawn_box(
        &mut app,
        Vec3::splat(0.5),
        500.0,
        Transform::from_xyz(5.0, 0.0, 0.0),
        false,
    );
    app.world_mut().entity_mut(a).insert(Floating::default());
    app.world_mut().entity_mut(b).insert(Floating::default());
    run(&mut app, 5.0);
    app.world_mut().entity_mut(a).remove::<Floating>();
    let before = B::linear_velocity(&app, a).y;
    run(&mut app, 0.5);
    let fall = (B::linear_velocity(&app, a).y - before) / 0.5;
    assert!(
        (fall + 9.81).abs() < 0.05,
        "falls at {fall} m/s² without Floating"
    );
    app.world_mut().entity_mut(b).despawn();
    run(&mut app, 1.0);
    let c = B::spawn_box(
        &mut app,
        Vec3::splat(0.5),
        500.0,
        Transform::from_xyz(9.0, 0.0, 0.0),
        false,
    );
    app.world_mut().entity_mut(c).insert(Floating::default());
    run(&mut app, 5.0);
    assert!(
        B::translation(&app, c).y.abs() < 0.01,
        "a new body floats after a despawn"
    );
}

/// A body asleep on still water wakes when the tide rises under it, and rises with it.
pub fn sleeping_body_wakes_for_a_rising_tide<B: Backend>() {
    let mut app = B::app();
    let body = B::spawn_box(
        &mut app,
        Vec3::new(1.0, 0.25, 0.5),
        500.0,
        Transform::from_xyz(0.0, 0.0, 0.0),
        true,
    );
    app.world_mut().entity_mut(body).insert(Floating::default());
    let mut asleep = false;
    for _ in 0..(30.0 / DT) as usize {
        app.update();
        if B::sleeping(&app, body) {
            asleep = true;
            break;
        }
    }
    assert!(asleep, "the crate never fell asleep");
    let y0 = B::translation(&app, body).y;
    for _ in 0..(20.0 / DT) as usize {
        app.world_mut().resource_mut::<Water>().level += 0.02 * f64::from(DT);
        app.update();
    }
    let risen = B::translation(&app, body).y - y0;
    assert!(risen > 0.3, "rose {risen} m with a 0.4 m tide");
}

/// Two runs of the same scene give the same poses, bit for bit.
pub fn runs_are_bit_identical<B: Backend>() {
    let once = || {
        let mut app = B::app();
        let body = B::spawn_box(
            &mut app,
            Vec3::new(0.4, 0.2, 0.3),
            600.0,
            Transform::from_xyz(0.1, 0.8, 0.0).with_rotation(Quat::from_rotation_x(0.3)),
            false,
        );
        app.world_mut().entity_mut(body).insert(Floating::default());
        run(&mut app, 5.0);
        (B::translation(&app, body), B::rotation(&app, body))
    };
    let (a, b) = (once(), once());
    assert_eq!(
        a.0.to_array().map(f32::to_bits),
        b.0.to_array().map(f32::to_bits)
    );
    assert_eq!(
        a.1.to_array().map(f32::to_bits),
        b.1.to_array().map(f32::to_bits)
    );
}

/// An entity with `Floating` and no rigid body is an error in its report (logged once), and
/// the others float on.
pub fn floating_without_a_body_is_reported<B: Backend>() {
    let mut app = B::app();
    let lonely = app
        .world_mut()
        .spawn((Transform::default(), Floating::default()))
        .id();
    let body = B::spawn_box(
        &mut app,
        Vec3::splat(0.5),
        500.0,
        Transform::from_xyz(0.0, 0.0, 0.0),
        false,
    );
    app.world_mut().entity_mut(body).insert(Floating::default());
    run(&mut app, 3.0);
    let r = report(&app, lonely);
    let message = r.error.expect("an error in the report");
    assert!(
        message.contains("no") && message.contains("RigidBody"),
        "{message}"
    );
    assert!(B::translation(&app, body).y.abs() < 0.02);
    // Invalid water: nothing floats, nothing panics.
    app.world_mut().resource_mut::<Water>().density = f64::NAN;
    run(&mut app, 0.5);
}
