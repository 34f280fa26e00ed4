//! The adapter in a rapier world: equilibrium, attitude, robustness, user forces, energy.

mod common;

use buoyancy_core::nalgebra::Vector3;
use buoyancy_rapier::FloatOptions;
use common::{Pool, model, tilt_degrees, trimesh};
use rapier3d::prelude::*;

const WATER_DENSITY: f32 = 1000.0;

fn unit_cube(s: f32) -> ColliderBuilder {
    ColliderBuilder::cuboid(0.5, 0.5, 0.5).density(s * WATER_DENSITY)
}

/// Cubes whose upright attitude is stable (GM = s/2 + 1/(12 s) − 1/2 > 0) float upright with
/// draft s and satisfy the equilibrium conditions.
#[test]
fn cube_upright_when_stable() {
    for s in [0.1f32, 0.9] {
        let mut pool = Pool::new();
        // Dropped from just above, slightly tilted: it must right itself.
        let tilt = Rotation::from_axis_angle(Vector::new(1.0, 0.0, 1.0).normalize(), 0.1);
        let h = pool.add(
            RigidBodyBuilder::dynamic().pose(Pose::from_parts(Vector::new(0.0, 0.8, 0.0), tilt)),
            unit_cube(s),
        );
        pool.run(40.0);
        let rb = pool.body(h);
        let gm = s / 2.0 + 1.0 / (12.0 * s) - 0.5;
        assert!(gm > 0.0);
        assert!(
            tilt_degrees(rb) < 0.5,
            "s = {s}: tilt {}°",
            tilt_degrees(rb)
        );
        let draft = 0.5 - rb.translation().y;
        assert!(
            (draft - s).abs() < 0.005 * s.max(0.1) + 1e-4,
            "s = {s}: draft {draft}"
        );
        pool.assert_equilibrium(h, 1.0, &format!("cube s = {s}"));
    }
}

/// For s = 0.25, 0.5, 0.75 the upright cube is unstable (GM < 0): started upright with a small
/// tilt it must tip, and still end in equilibrium.
#[test]
fn cube_tips_when_upright_is_unstable() {
    for s in [0.25f32, 0.5, 0.75] {
        let gm = s / 2.0 + 1.0 / (12.0 * s) - 0.5;
        assert!(gm < 0.0);
        let mut pool = Pool::new();
        let tilt =
            Rotation::from_axis_angle(Vector::new(1.0, 0.0, 0.3).normalize(), 3f32.to_radians());
        let h = pool.add(
            RigidBodyBuilder::dynamic()
                .pose(Pose::from_parts(Vector::new(0.0, 0.5 - s, 0.0), tilt)),
            unit_cube(s),
        );
        pool.run(60.0);
        let rb = pool.body(h);
        assert!(
            tilt_degrees(rb) > 10.0,
            "s = {s}: still upright, tilt {}°",
            tilt_degrees(rb)
        );
        pool.assert_equilibrium(h, 1.0, &format!("tipped cube s = {s}"));
    }
}

/// The analytic cap: a sphere of radius R and relative density s floats with draft d,
/// π d² (3R − d)/3 = s·4πR³/3.
#[test]
fn sphere_at_the_analytic_cap_height() {
    let radius = 0.5f32;
    for s in [0.25f32, 0.5, 0.8] {
        let mut pool = Pool::new();
        let h = pool.add_with(
            RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 1.0, 0.0)),
            ColliderBuilder::ball(radius).density(s * WATER_DENSITY),
            FloatOptions::default().subdivisions(96),
        );
        pool.run(60.0);
        let r = radius as f64;
        let target = 4.0 * s as f64 * r * r * r;
        let (mut lo, mut hi) = (0.0, 2.0 * r);
        for _ in 0..100 {
            let d = (lo + hi) / 2.0;
            if d * d * (3.0 * r - d) < target {
                lo = d
            } else {
                hi = d
            }
        }
        let center_height = r - lo;
        let y = pool.body(h).translation().y as f64;
        assert!(
            (y - center_height).abs() < 0.01 * r,
            "s = {s}: center at {y} m, analytic {center_height} m"
        );
        pool.assert_equilibrium(h, 2.0 * r, &format!("sphere s = {s}"));
    }
}

/// A 2 × 0.5 × 0.2 m box of density 500 kg/m³ floats flat, half its 0.2 m under water.
#[test]
fn long_flat_box_floats_flat() {
    let mut pool = Pool::new();
    let start =
        Rotation::from_axis_angle(Vector::X, 0.2) * Rotation::from_axis_angle(Vector::Z, 0.1);
    let h = pool.add(
        RigidBodyBuilder::dynamic().pose(Pose::from_parts(Vector::new(0.0, 0.5, 0.0), start)),
        ColliderBuilder::cuboid(1.0, 0.1, 0.25).density(500.0),
    );
    pool.run(60.0);
    let rb = pool.body(h);
    let up = *rb.rotation() * Vector::Y;
    assert!(
        up.y > 0.9999f32.min(1.0f32.to_radians().cos()) || up.y < -0.9998,
        "the thin axis is not vertical: {up:?}"
    );
    assert!(
        rb.translation().y.abs() < 0.002,
        "center {} m from the surface, expected 0",
        rb.translation().y
    );
    pool.assert_equilibrium(h, 2.0, "flat box");
}

/// The paper's models (or the procedural torus knot) settle in equilibrium.
#[test]
fn bunny_and_torus_knot_equilibrium() {
    for (file, s) in [("bunny.obj", 0.6f32), ("torusknot.obj", 0.4)] {
        let (name, mesh) = model(file, 0.4);
        let mut pool = Pool::new();
        let h = pool.add(
            RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.5, 0.0)),
            trimesh(&mesh).density(s * WATER_DENSITY),
        );
        pool.run(60.0);
        pool.assert_equilibrium(h, 0.8, &name);
    }
}

/// A body denser than water sinks (and keeps sinking at a finite speed).
#[test]
fn denser_body_sinks() {
    let mut pool = Pool::new();
    let h = pool.add(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 1.0, 0.0)),
        unit_cube(1.5),
    );
    pool.run(10.0);
    let rb = pool.body(h);
    assert!(rb.translation().y < -5.0, "at {}", rb.translation().y);
    assert!(rb.linvel().y < 0.0 && rb.linvel().is_finite());
    // Terminal velocity: the drag balances the net weight, (s − 1)ρgV = (c₁u + ½ρC_D u²)·1 m².
    let net = 0.5 * 1000.0 * 9.81;
    let (c1, c2) = (1000.0f32, 500.0f32);
    let u = (-c1 + (c1 * c1 + 4.0 * c2 * net).sqrt()) / (2.0 * c2);
    assert!(
        (rb.linvel().y + u).abs() < 0.05 * u,
        "sinks at {} m/s, terminal {u} m/s",
        -rb.linvel().y
    );
}

/// A body spawned 10 m deep rises, breaks the surface and settles.
#[test]
fn spawned_deep_rises_and_settles() {
    let mut pool = Pool::new();
    let h = pool.add(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, -10.0, 0.0)),
        unit_cube(0.9),
    );
    let mut highest = f32::MIN;
    for _ in 0..60 * 60 {
        pool.step();
        highest = highest.max(pool.body(h).translation().y);
        assert!(pool.body(h).translation().is_finite());
    }
    assert!(
        highest > -0.5 + 0.1,
        "never reached the surface: highest {highest}"
    );
    let y = pool.body(h).translation().y;
    assert!(
        (y - (0.5 - 0.9)).abs() < 0.005,
        "settled at {y}, tilt {}°",
        tilt_degrees(pool.body(h))
    );
    pool.assert_equilibrium(h, 1.0, "cube spawned deep");
}

/// Dropped fast, spawned far above, spawned very deep: never NaN, never exploding.
#[test]
fn extreme_spawns_stay_finite() {
    let mut pool = Pool::new();
    let fast = pool.add(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, 2.0, 0.0))
            .linvel(Vector::new(3.0, -80.0, 0.0)),
        unit_cube(0.1),
    );
    let light_deep = pool.add(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(5.0, -200.0, 0.0))
            .angvel(Vector::new(20.0, 0.0, 5.0)),
        ColliderBuilder::ball(0.05).density(10.0),
    );
    let above = pool.add(
        RigidBodyBuilder::dynamic().translation(Vector::new(-5.0, 1000.0, 0.0)),
        unit_cube(0.5),
    );
    for step in 0..60 * 20 {
        pool.step();
        if step == 60 {
            // Still far above the water: no force at all.
            let r = pool.water.report(above).unwrap();
            assert_eq!(
                (r.buoyancy_force, r.damping_force),
                (Vector3::zeros(), Vector3::zeros())
            );
        }
        for h in [fast, light_deep, above] {
            let rb = pool.body(h);
            assert!(
                rb.translation().is_finite() && rb.linvel().is_finite() && rb.angvel().is_finite()
            );
            // Never faster than the free fall from the highest start, or the deep body's rise.
            assert!(rb.linvel().length() < 200.0, "{:?}", rb.linvel());
        }
    }
    assert!(pool.body(fast).translation().y.abs() < 1.0);
}

/// A constant force the application adds once stays, step after step.
#[test]
fn user_thrust_survives_steps() {
    let mut pool = Pool::new();
    let h = pool.add(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.0, 0.0)),
        unit_cube(0.5),
    );
    pool.run(5.0);
    let thrust = Vector::new(200.0, 0.0, 0.0);
    let torque = Vector::new(0.0, 5.0, 0.0);
    pool.world.bodies[h].add_force(thrust, true);
    pool.world.bodies[h].add_torque(torque, true);
    let x0 = pool.body(h).translation().x;
    for _ in 0..600 {
        pool.step();
        let rb = pool.body(h);
        let r = pool.water.report(h).unwrap();
        let adapter_force = (r.buoyancy_force + r.damping_force).cast::<f32>();
        let own = rb.user_force() - Vector::new(adapter_force.x, adapter_force.y, adapter_force.z);
        assert!(
            (own - thrust).length() < 1e-3 * thrust.length() + 1e-2,
            "the application's force became {own:?}"
        );
        let adapter_torque = (r.buoyancy_torque + r.damping_torque).cast::<f32>();
        let own_torque =
            rb.user_torque() - Vector::new(adapter_torque.x, adapter_torque.y, adapter_torque.z);
        assert!(
            (own_torque - torque).length() < 1e-3 * torque.length() + 1e-2,
            "the application's torque became {own_torque:?}"
        );
    }
    let rb = pool.body(h);
    assert!(
        rb.translation().x - x0 > 2.0,
        "the thrust did not push: moved {}",
        rb.translation().x - x0
    );
    assert!(rb.angvel().y > 0.0, "the torque did not turn it");
    // Taking the body out of the water leaves exactly the application's forces.
    let mut bodies = std::mem::take(&mut pool.world.bodies);
    assert!(pool.water.unregister(h, &mut bodies));
    assert!((bodies[h].user_force() - thrust).length() < 1e-2);
    assert!((bodies[h].user_torque() - torque).length() < 1e-3);
}

/// Per-body overrides and the world settings: water level and method.
#[test]
fn per_body_water_and_errors() {
    let mut pool = Pool::new();
    let raised = pool.water.water().with_surface(Vector3::y(), 2.0).unwrap();
    let high = pool.add_with(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 3.0, 0.0)),
        unit_cube(0.5),
        FloatOptions::default()
            .water(raised)
            .method(buoyancy_core::Method::ExactSurface),
    );
    let low = pool.add(
        RigidBodyBuilder::dynamic().translation(Vector::new(3.0, 1.0, 0.0)),
        unit_cube(0.5),
    );
    pool.run(20.0);
    assert!((pool.body(high).translation().y - 2.0).abs() < 0.005);
    assert!(pool.body(low).translation().y.abs() < 0.005);

    // Errors name the problem.
    let (fixed, _) = pool.world.insert(
        RigidBodyBuilder::fixed(),
        ColliderBuilder::halfspace(rapier3d::na::Unit::new_unchecked(Vector::Y)),
    );
    let e = pool
        .water
        .register(
            fixed,
            &pool.world.bodies,
            &pool.world.colliders,
            FloatOptions::default(),
        )
        .unwrap_err();
    assert!(
        matches!(e, buoyancy_rapier::Error::UnsupportedShape { .. }),
        "{e}"
    );
    let empty = pool.world.bodies.insert(RigidBodyBuilder::dynamic());
    let e = pool
        .water
        .register(
            empty,
            &pool.world.bodies,
            &pool.world.colliders,
            FloatOptions::default(),
        )
        .unwrap_err();
    assert_eq!(e, buoyancy_rapier::Error::NothingToFloat(empty));
}

/// Compound, cylinder, capsule, cone and convex shapes float with the volume rapier gives them.
#[test]
fn every_supported_shape_floats() {
    let hull = ColliderBuilder::convex_hull(&[
        Vector::new(-0.4, -0.3, -0.3),
        Vector::new(0.4, -0.3, -0.3),
        Vector::new(0.0, 0.4, -0.3),
        Vector::new(0.0, 0.0, 0.4),
    ])
    .unwrap();
    let compound = ColliderBuilder::compound(vec![
        (
            Pose::translation(-0.4, 0.0, 0.0),
            SharedShape::cuboid(0.2, 0.2, 0.2),
        ),
        (Pose::translation(0.4, 0.0, 0.0), SharedShape::ball(0.25)),
    ]);
    let shapes: Vec<(&str, ColliderBuilder)> = vec![
        ("cylinder", ColliderBuilder::cylinder(0.3, 0.2)),
        ("capsule", ColliderBuilder::capsule_y(0.3, 0.2)),
        ("cone", ColliderBuilder::cone(0.3, 0.3)),
        ("convex hull", hull),
        ("compound", compound),
    ];
    for (name, collider) in shapes {
        let mut pool = Pool::new();
        let h = pool.add_with(
            RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.5, 0.0)),
            collider.density(600.0),
            FloatOptions::default().subdivisions(64),
        );
        pool.run(40.0);
        pool.water.apply(&mut pool.world.bodies, 1.0 / 60.0);
        let rb = pool.body(h);
        let r = pool.water.report(h).unwrap();
        // rapier's mass uses the exact round volumes, the mesh is inscribed: 1 % here.
        let expected = rb.mass() as f64 / 1000.0;
        assert!(
            (r.submerged_volume - expected).abs() < 0.01 * expected,
            "{name}: {} vs {expected}",
            r.submerged_volume
        );
        assert!(rb.linvel().length() < 0.01, "{name} still moves");
    }
}

/// Total mechanical energy of the bodies: kinetic, gravitational, and the hydrostatic potential
/// `−ρ g V_sub h_B` (`h_B` the height of the center of buoyancy above the surface).
fn mechanical_energy(pool: &mut Pool, handles: &[RigidBodyHandle]) -> f64 {
    pool.water
        .apply(&mut pool.world.bodies, pool.world.integration_parameters.dt);
    let water = *pool.water.water();
    handles
        .iter()
        .map(|&h| {
            let rb = pool.body(h);
            let r = pool.water.report(h).unwrap();
            let kinetic = rb.kinetic_energy() as f64;
            let gravity = rb.mass() as f64 * water.gravity() * water.height(&r.center_of_mass);
            let hydrostatic =
                -water.specific_weight() * r.submerged_volume * water.height(&r.center_of_buoyancy);
            kinetic + gravity + hydrostatic
        })
        .sum()
}

/// 100 bodies of every shape, dropped together: 20 s at 60 Hz without a NaN, and the total
/// mechanical energy decays once they are in the water.
#[test]
fn hundred_mixed_bodies_settle() {
    let mut pool = Pool::new();
    let (_, bunny) = model("bunny.obj", 0.3);
    let mut handles = Vec::new();
    let mut seed = 12345u64;
    let mut random = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f32 / (1u64 << 53) as f32
    };
    for i in 0..100 {
        let s = 0.2 + 0.7 * random();
        let collider = match i % 7 {
            0 => ColliderBuilder::cuboid(0.3, 0.2, 0.25),
            1 => ColliderBuilder::ball(0.25),
            2 => ColliderBuilder::cylinder(0.2, 0.2),
            3 => ColliderBuilder::capsule_y(0.15, 0.15),
            4 => ColliderBuilder::cone(0.25, 0.25),
            5 => ColliderBuilder::compound(vec![
                (
                    Pose::translation(-0.2, 0.0, 0.0),
                    SharedShape::cuboid(0.15, 0.15, 0.15),
                ),
                (Pose::translation(0.2, 0.0, 0.0), SharedShape::ball(0.15)),
            ]),
            _ => trimesh(&bunny),
        };
        let position = Vector::new(
            (i % 10) as f32 * 1.5 - 7.0,
            1.0 + 4.0 * random(),
            (i / 10) as f32 * 1.5 - 7.0,
        );
        let rotation = Rotation::from_scaled_axis(Vector::new(random(), random(), random()) * 2.0);
        let body = RigidBodyBuilder::dynamic()
            .pose(Pose::from_parts(position, rotation))
            .linvel(Vector::new(0.0, -3.0 * random(), 0.0));
        handles.push(pool.add_with(
            body,
            collider.density(s * WATER_DENSITY),
            FloatOptions::default().subdivisions(16),
        ));
    }
    let mut energies = Vec::new();
    for second in 1..=20 {
        pool.run(1.0);
        for &h in &handles {
            let rb = pool.body(h);
            assert!(
                rb.translation().is_finite() && rb.linvel().is_finite() && rb.angvel().is_finite(),
                "NaN at {second} s"
            );
        }
        if second >= 5 {
            energies.push(mechanical_energy(&mut pool, &handles));
            // Every body in the water by 5 s, and from then on.
            for &h in &handles {
                assert!(
                    pool.water.report(h).unwrap().submerged_volume > 0.0,
                    "a body is out of the water at {second} s"
                );
            }
        }
    }
    // From 5 s on, the energy goes down second after second.
    for pair in energies.windows(2) {
        assert!(pair[1] < pair[0], "energy rose: {energies:?}");
    }
    assert!(energies[energies.len() - 1] < energies[0]);
}
