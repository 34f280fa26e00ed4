//! Floating on waves: a small light buoy follows a long swell.

use std::sync::Arc;

use buoyancy_core::nalgebra::Vector3;
use buoyancy_core::waves::{AiryComponent, AiryWaves};
use buoyancy_rapier::{FloatOptions, FloatingBodies};
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
