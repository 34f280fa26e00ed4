//! Buoyancy under waves against analytic results: still water through the wave API, a tilted
//! plane surface (divergence theorem), a wall-sided box in a regular Airy wave.

mod common;

use buoyancy_core::nalgebra::{Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::query::{Pressure, Query, Sea};
use buoyancy_core::water::{AiryComponent, AiryWaves, CalmSurface, HeightGrid, SurfaceFn};
use buoyancy_core::{Mesh, Method, Pose, Traversal, Water, mesh::primitives};
use common::{all_meshes, assert_close, assert_close_v};

fn pose(x: f64, y: f64, z: f64, roll: f64, pitch: f64, yaw: f64) -> Pose<f64> {
    Pose::from_parts(
        Translation3::new(x, y, z),
        UnitQuaternion::from_euler_angles(roll, pitch, yaw),
    )
}

/// Calm water through the wave API is Exact Surface, on every test mesh, at poses from dry to
/// submerged.
#[test]
fn calm_water_is_exact_surface() {
    let water = Water::new(1025.0, 9.81, Vector3::new(0.1, 1.0, -0.2), 0.3).unwrap();
    for (name, mesh) in all_meshes() {
        let r = mesh.bounding_radius();
        for k in 0..9 {
            let p = pose(
                0.2,
                r * (k as f64 / 4.0 - 1.0),
                -0.1,
                0.3 * k as f64,
                0.7,
                0.1,
            );
            let waves = mesh
                .buoyancy(
                    &p,
                    Sea::new(&water, &CalmSurface, 1.5),
                    Method::ExactSurface,
                )
                .unwrap();
            let still = mesh
                .buoyancy(
                    &p,
                    &water,
                    Query::new(Method::ExactSurface).with_traversal(Traversal::Scan),
                )
                .unwrap();
            let scale = 1e-12 * (1.0 + still.force.norm());
            assert!((waves.force - still.force).norm() <= scale, "{name} {k}");
            assert!(
                (waves.torque - still.torque).norm() <= scale * (1.0 + r),
                "{name} {k}"
            );
            assert_close(
                name,
                waves.submerged_volume,
                still.submerged_volume,
                1e-12,
                mesh.volume(),
            );
            assert_close_v(
                name,
                &waves.center_of_buoyancy.coords,
                &still.center_of_buoyancy.coords,
                1e-9,
                1.0 + r,
            );
            assert_close(
                &format!("{name} {k}: wetted area"),
                waves.wetted_area,
                still.wetted_area,
                1e-12,
                mesh.surface_area(),
            );
        }
    }
}

/// A plane free surface `η = s·x + b`: the force is `ρ·g·V·(−∂η/∂x, 1, 0)`, `V` the volume
/// under that plane, and it acts through the centroid of that volume (divergence theorem on
/// `p = ρg(η − y)`), whatever the mesh's resolution: exact to round-off.
#[test]
fn a_plane_surface_gives_the_divergence_theorem() {
    let (s, b) = (0.3, 0.1);
    let ramp = SurfaceFn(move |q: &Point3<f64>, _t: f64| s * q.x + b);
    let calm = Water::default();
    // The same plane as a still water surface: y − s·x = b.
    let norm = (1.0 + s * s).sqrt();
    let tilted = Water::new(1000.0, 9.81, Vector3::new(-s, 1.0, 0.0), b / norm).unwrap();
    for (name, mesh) in all_meshes() {
        let r = mesh.bounding_radius();
        for k in 0..7 {
            let p = pose(
                0.4,
                r * (k as f64 / 3.0 - 1.0),
                0.2,
                0.5 * k as f64,
                -0.3,
                0.8,
            );
            let w = mesh
                .buoyancy(&p, Sea::new(&calm, &ramp, 0.0), Method::ExactSurface)
                .unwrap();
            let exact = mesh.buoyancy(&p, &tilted, Method::Exact).unwrap();
            let weight = calm.specific_weight();
            let expected = Vector3::new(-s, 1.0, 0.0) * (weight * exact.submerged_volume);
            let tolerance = 1e-12 * weight * mesh.volume();
            assert!(
                (w.force - expected).norm() <= tolerance,
                "{name} {k}: {:?} vs {expected:?}",
                w.force
            );
            let torque = (exact.center_of_buoyancy - w.torque_point).cross(&expected);
            assert!(
                (w.torque - torque).norm() <= tolerance * (1.0 + r),
                "{name} {k}: {:?} vs {torque:?}",
                w.torque
            );
        }
    }
}

/// A wall-sided box (length L along the wave, beam B, draft T) in a regular Airy wave of
/// amplitude a, hydrostatic pressure: the heave force is
/// `ρgB∫(T + η)dx = ρgBLT + ρgBa·(2/k)·sin(kL/2)·cos(ωt)` for a box centred at x = 0 (the
/// sloping wetted sides add no vertical force). The error falls as the square of the mesh
/// spacing: the surface is sampled at the vertices and interpolated linearly.
#[test]
fn a_wall_sided_box_in_a_regular_wave() {
    let (length, beam, draft, amplitude, wavelength) = (4.0, 1.0, 0.5, 0.1, 10.0);
    let water = Water::default();
    let waves = wave_along_x(amplitude, wavelength, 0.3, None);
    let k = 2.0 * std::f64::consts::PI / wavelength;
    let omega = waves.angular_frequency(0, water.gravity());
    let weight = water.specific_weight();
    let mut errors = Vec::new();
    for n in [8, 16, 32] {
        let (v, t) = primitives::cube::<f64>(n).unwrap();
        let unit = Mesh::new(v, t).unwrap();
        let b = unit.scaled(&Vector3::new(length, 1.0, beam)).unwrap();
        // The box's bottom at y = −T: its center at 0.5 − T.
        let p = pose(0.0, 0.5 - draft, 0.0, 0.0, 0.0, 0.0);
        let mut worst: f64 = 0.0;
        for step in 0..8 {
            let time = step as f64 * 0.37;
            let got = b
                .buoyancy(&p, Sea::new(&water, &waves, time), Method::ExactSurface)
                .unwrap();
            let expected = weight * beam * length * draft
                + weight
                    * beam
                    * amplitude
                    * (2.0 / k)
                    * (k * length / 2.0).sin()
                    * (0.3 - omega * time).cos();
            worst = worst.max((got.force.y - expected).abs() / (weight * beam * length * draft));
        }
        errors.push(worst);
    }
    assert!(errors[2] < 1e-4, "{errors:?}");
    for pair in errors.windows(2) {
        let ratio = pair[0] / pair[1];
        assert!((3.0..5.5).contains(&ratio), "second order: {errors:?}");
    }
}

/// The same wall-sided box in the same wave is wetted on its bottom `LB`, its long sides
/// `2∫(T + η)dx = 2LT + 2a·(2/k)·sin(kL/2)·cos(φ − ωt)` and its ends `B(T + η(±L/2))`. The ends
/// are exact (η is the same at all their vertices); the sides converge at second order in the
/// mesh spacing, as the force does.
#[test]
fn a_wall_sided_box_wetted_area_in_a_regular_wave() {
    let (length, beam, draft, amplitude, wavelength, phase) = (4.0, 1.0, 0.5, 0.1, 10.0, 0.3);
    let water = Water::default();
    let waves = wave_along_x(amplitude, wavelength, phase, None);
    let k = 2.0 * std::f64::consts::PI / wavelength;
    let omega = waves.angular_frequency(0, water.gravity());
    let mut errors = Vec::new();
    for n in [8, 16, 32] {
        let (v, t) = primitives::cube::<f64>(n).unwrap();
        let unit = Mesh::new(v, t).unwrap();
        let b = unit.scaled(&Vector3::new(length, 1.0, beam)).unwrap();
        let p = pose(0.0, 0.5 - draft, 0.0, 0.0, 0.0, 0.0);
        let mut worst: f64 = 0.0;
        for step in 0..8 {
            let time = step as f64 * 0.37;
            let got = b
                .buoyancy(&p, Sea::new(&water, &waves, time), Method::ExactSurface)
                .unwrap();
            let eta = |x: f64| amplitude * (k * x - omega * time + phase).cos();
            let sides = length * draft
                + amplitude * (2.0 / k) * (k * length / 2.0).sin() * (phase - omega * time).cos();
            let expected = length * beam
                + 2.0 * sides
                + beam * (2.0 * draft + eta(-length / 2.0) + eta(length / 2.0));
            worst = worst.max((got.wetted_area - expected).abs() / expected);
        }
        errors.push(worst);
    }
    // Measured: 5.8e-4, 1.5e-4, 3.6e-5 of the wetted area.
    assert!(errors[2] < 5e-5, "{errors:?}");
    for pair in errors.windows(2) {
        let ratio = pair[0] / pair[1];
        assert!((3.0..5.5).contains(&ratio), "second order: {errors:?}");
    }
}

/// The Froude–Krylov pressure acts on the hydrostatic wetted surface: both report its area,
/// to round-off (one scans the triangles, the other walks the hierarchy), from dry to
/// submerged, and in still water (zero amplitude) Exact Surface's.
#[test]
fn froude_krylov_wets_the_hydrostatic_surface() {
    let water = Water::default();
    let calm = wave_along_x(0.0, 4.0, 0.0, None);
    for (name, mesh) in all_meshes() {
        let r = mesh.bounding_radius();
        // A sea the size of the body (a radius-1 body: waves 0.4 m and 0.1 m high, 4 m and
        // 1.5 m long), so that the poses below cut every body whatever its scale.
        let sea = AiryWaves::new(
            vec![
                AiryComponent {
                    amplitude: 0.2 * r,
                    wavelength: 4.0 * r,
                    direction: Vector3::x(),
                    phase: 0.3,
                },
                AiryComponent {
                    amplitude: 0.05 * r,
                    wavelength: 1.5 * r,
                    direction: Vector3::new(0.3, 0.0, 1.0),
                    phase: 1.1,
                },
            ],
            Some(6.0 * r),
        )
        .unwrap();
        let area = mesh.surface_area();
        let mut wetted = 0;
        for k in 0..9 {
            let p = pose(
                0.1,
                r * (1.2 - 0.3 * k as f64),
                -0.2,
                0.4 * k as f64,
                0.3,
                0.1,
            );
            let time = 0.6 * k as f64;
            let hydrostatic = mesh
                .buoyancy(&p, Sea::new(&water, &sea, time), Method::ExactSurface)
                .unwrap();
            let fk = mesh
                .buoyancy(
                    &p,
                    Sea::new(&water, &sea, time).with_pressure(Pressure::FroudeKrylov),
                    Method::ExactSurface,
                )
                .unwrap();
            let what = format!("{name} {k}: wetted area");
            assert_close(&what, fk.wetted_area, hydrostatic.wetted_area, 1e-12, area);
            assert!(fk.wetted_area <= area * (1.0 + 1e-12), "{what}");
            wetted += usize::from(fk.wetted_area > 0.0 && fk.wetted_area < area);
            let still = mesh.buoyancy(&p, &water, Method::ExactSurface).unwrap();
            let fk_calm = mesh
                .buoyancy(
                    &p,
                    Sea::new(&water, &calm, time).with_pressure(Pressure::FroudeKrylov),
                    Method::ExactSurface,
                )
                .unwrap();
            assert_close(&what, fk_calm.wetted_area, still.wetted_area, 1e-12, area);
        }
        assert!(wetted >= 3, "{name}: {wetted} poses cut by the surface");
    }
}

/// A grid that samples a plane reproduces it: the same result as the plane's function.
#[test]
fn a_grid_of_a_plane_is_the_plane() {
    let (s, b) = (-0.2, 0.05);
    let heights: Vec<f64> = (0..21)
        .flat_map(|j| (0..21).map(move |i| s * (i as f64 * 0.5 - 5.0) + b + 0.0 * j as f64))
        .collect();
    let grid = HeightGrid::new(
        heights,
        21,
        21,
        Point3::new(-5.0, 0.0, -5.0),
        Vector3::x() * 0.5,
        Vector3::z() * 0.5,
        false,
    )
    .unwrap();
    let ramp = SurfaceFn(move |q: &Point3<f64>, _t: f64| s * q.x + b);
    let (v, t) = primitives::uv_sphere::<f64>(1.0, 24, 12).unwrap();
    let ball = Mesh::new(v, t).unwrap();
    let p = pose(0.3, 0.2, -0.4, 0.2, 0.1, 0.0);
    let a = ball
        .buoyancy(
            &p,
            Sea::new(&Water::default(), &grid, 0.0),
            Method::ExactSurface,
        )
        .unwrap();
    let b = ball
        .buoyancy(
            &p,
            Sea::new(&Water::default(), &ramp, 0.0),
            Method::ExactSurface,
        )
        .unwrap();
    assert!(
        (a.force - b.force).norm() < 1e-9 * b.force.norm(),
        "{a:?} {b:?}"
    );
    assert!((a.torque - b.torque).norm() < 1e-9 * (1.0 + b.torque.norm()));
}

/// Bad input is a typed error, never a NaN.
#[test]
fn bad_times_and_surfaces_are_errors() {
    let (v, t) = primitives::cube::<f64>(2).unwrap();
    let cube = Mesh::new(v, t).unwrap();
    let w = Water::default();
    let p = Pose::identity();
    assert!(
        cube.buoyancy(
            &p,
            Sea::new(&w, &CalmSurface, f64::NAN),
            Method::ExactSurface
        )
        .is_err()
    );
    let nan = SurfaceFn(|_: &Point3<f64>, _: f64| f64::NAN);
    assert!(
        cube.buoyancy(&p, Sea::new(&w, &nan, 0.0), Method::ExactSurface)
            .is_err()
    );
}

/// Walking the hierarchy against the surface's bound changes nothing but round-off: the same
/// sea without a bound (through a function, so every triangle is integrated on its own) gives
/// the same force, torque and center to 1e-12 of the mesh's weight and size.
#[test]
fn walking_within_the_bound_changes_nothing() {
    let water = Water::default();
    let sea = AiryWaves::from_sea_state(
        &buoyancy_core::water::SeaState {
            spectrum: buoyancy_core::water::Spectrum::Jonswap { gamma: 3.3 },
            significant_height: 0.5,
            peak_period: 3.0,
            direction: Vector3::new(1.0, 0.0, 0.4),
            spreading: Some(5.0),
            components: 16,
            seed: 3,
        },
        &water,
        Some(20.0),
    )
    .unwrap();
    let unbounded = SurfaceFn(|q: &Point3<f64>, t: f64| {
        let mut eta = [0.0];
        buoyancy_core::water::WaterSurface::elevations(&sea, &Water::default(), &[*q], t, &mut eta)
            .unwrap();
        eta[0]
    });
    for (name, mesh) in all_meshes() {
        let r = mesh.bounding_radius();
        for k in 0..5 {
            let p = pose(
                0.3,
                r * (k as f64 / 2.0 - 1.0),
                0.1,
                0.4 * k as f64,
                0.2,
                -0.5,
            );
            let a = mesh
                .buoyancy(
                    &p,
                    Sea::new(&water, &sea, 0.7 * k as f64),
                    Method::ExactSurface,
                )
                .unwrap();
            let b = mesh
                .buoyancy(
                    &p,
                    Sea::new(&water, &unbounded, 0.7 * k as f64),
                    Method::ExactSurface,
                )
                .unwrap();
            let weight = water.specific_weight() * mesh.volume();
            assert!((a.force - b.force).norm() < 1e-12 * weight, "{name} {k}");
            assert!(
                (a.torque - b.torque).norm() < 1e-12 * weight * r,
                "{name} {k}"
            );
            let center = (a.center_of_buoyancy - b.center_of_buoyancy).norm();
            assert!(center < 1e-10 * r, "{name} {k}: {center}");
            assert_close(
                &format!("{name} {k}: wetted area"),
                a.wetted_area,
                b.wetted_area,
                1e-12,
                mesh.surface_area(),
            );
            assert_eq!(
                (a.fully_submerged, a.partially_submerged),
                (b.fully_submerged, b.partially_submerged)
            );
        }
    }
}

/// One Airy component along x, over water 30 m deep.
fn one_wave(amplitude: f64, wavelength: f64, phase: f64) -> AiryWaves<f64> {
    wave_along_x(amplitude, wavelength, phase, Some(30.0))
}

/// One Airy component along x, over water of `depth` (`None`: deep).
fn wave_along_x(amplitude: f64, wavelength: f64, phase: f64, depth: Option<f64>) -> AiryWaves<f64> {
    AiryWaves::new(
        vec![AiryComponent {
            amplitude,
            wavelength,
            direction: Vector3::x(),
            phase,
        }],
        depth,
    )
    .unwrap()
}

/// Moving the body and the wave together changes nothing: a body moved by `Δ` along the wave,
/// in a wave of phase `φ − k·Δ`, or observed `Δt` later, in a wave of phase `φ + ω·Δt`, feels
/// the force and torque it felt.
#[test]
fn moving_body_and_wave_together_agree() {
    let water = Water::default();
    let (wavelength, shift, delay) = (7.0, 2.3, 0.8);
    let k = 2.0 * std::f64::consts::PI / wavelength;
    let base = one_wave(0.2, wavelength, 0.4);
    let omega = base.angular_frequency(0, water.gravity());
    let moved_wave = one_wave(0.2, wavelength, 0.4 - k * shift);
    let delayed_wave = one_wave(0.2, wavelength, 0.4 + omega * delay);
    for (name, mesh) in all_meshes() {
        let p = pose(0.1, -0.2 * mesh.bounding_radius(), 0.3, 0.4, 0.2, 0.9);
        let moved = pose(
            0.1 + shift,
            -0.2 * mesh.bounding_radius(),
            0.3,
            0.4,
            0.2,
            0.9,
        );
        let reference = mesh
            .buoyancy(&p, Sea::new(&water, &base, 1.1), Method::ExactSurface)
            .unwrap();
        let translated = mesh
            .buoyancy(
                &moved,
                Sea::new(&water, &moved_wave, 1.1),
                Method::ExactSurface,
            )
            .unwrap();
        let later = mesh
            .buoyancy(
                &p,
                Sea::new(&water, &delayed_wave, 1.1 + delay),
                Method::ExactSurface,
            )
            .unwrap();
        let scale = 1e-9 * (1.0 + reference.force.norm());
        assert!(
            (translated.force - reference.force).norm() <= scale,
            "{name}"
        );
        assert!(
            (translated.torque - reference.torque).norm() <= scale * (1.0 + mesh.bounding_radius()),
            "{name}"
        );
        assert!((later.force - reference.force).norm() <= scale, "{name}");
        assert!(
            (later.torque - reference.torque).norm() <= scale * (1.0 + mesh.bounding_radius()),
            "{name}"
        );
    }
}

/// The long-wave limit: under a wave much longer than the body, the body feels still water at
/// the local level, `a·cos(φ)` at its position, to first order in `k` times its size.
#[test]
fn long_waves_are_still_water_at_the_local_level() {
    let water = Water::default();
    let (amplitude, phase) = (0.15, 0.9);
    for (name, mesh) in all_meshes() {
        let r = mesh.bounding_radius();
        let wavelength = 1e5 * r;
        let waves = one_wave(amplitude, wavelength, phase);
        let level = amplitude * phase.cos();
        let still = Water::new(1000.0, 9.81, Vector3::y(), level).unwrap();
        let p = pose(0.0, -0.3 * r, 0.0, 0.2, 0.5, 0.1);
        let got = mesh
            .buoyancy(&p, Sea::new(&water, &waves, 0.0), Method::ExactSurface)
            .unwrap();
        let expected = mesh.buoyancy(&p, &still, Method::ExactSurface).unwrap();
        let k_size = 2.0 * std::f64::consts::PI / wavelength * r;
        let tolerance = 10.0 * k_size * water.specific_weight() * mesh.volume();
        assert!(
            (got.force - expected.force).norm() <= tolerance,
            "{name}: {:?} vs {:?}",
            got.force,
            expected.force
        );
    }
}

/// A fully submerged ball under an Airy wave, hydrostatic pressure `p = ρg(η − y)`: by the
/// divergence theorem the force is `ρg∫(−∇η, 1)dV`; for `η = a·cos(k·x + φ)` over the unit
/// ball, `∫∂η/∂x dV = −a·k·sin φ·4π(sin k − k cos k)/k³`. The mesh samples the surface at its
/// vertices, so the horizontal force converges as the square of the mesh spacing.
#[test]
fn a_submerged_ball_gets_the_divergence_theorem() {
    let water = Water::default();
    let (amplitude, wavelength, phase) = (0.3, 6.0, 0.7);
    let waves = one_wave(amplitude, wavelength, phase);
    let k = 2.0 * std::f64::consts::PI / wavelength;
    let weight = water.specific_weight();
    let integral = 4.0 * std::f64::consts::PI * (k.sin() - k * k.cos()) / k.powi(3);
    let expected_x = weight * amplitude * k * phase.sin() * integral;
    let mut errors = Vec::new();
    for (slices, stacks) in [(32, 16), (64, 32), (128, 64)] {
        let (v, t) = primitives::uv_sphere::<f64>(1.0, slices, stacks).unwrap();
        let ball = Mesh::new(v, t).unwrap();
        let b = ball
            .buoyancy(
                &pose(0.0, -5.0, 0.0, 0.0, 0.0, 0.0),
                Sea::new(&water, &waves, 0.0),
                Method::ExactSurface,
            )
            .unwrap();
        assert!(
            (b.force.y / (weight * ball.volume()) - 1.0).abs() < 2e-3,
            "{b:?}"
        );
        assert!(b.force.z.abs() < 1e-9 * weight);
        errors.push((b.force.x - expected_x).abs() / expected_x.abs());
    }
    assert!(errors[2] < 2e-3, "{errors:?}");
    for pair in errors.windows(2) {
        assert!(pair[0] / pair[1] > 3.0, "second order: {errors:?}");
    }
}

mod random_seas {
    use super::*;
    use buoyancy_core::water::{GerstnerWaves, SeaState, Spectrum};
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Random meshes, poses, seas and times: finite results or typed errors, never a panic;
        /// a sea of zero height is calm water.
        #[test]
        fn random_seas_give_finite_results(
            mesh_index in 0usize..4,
            position in (-3.0..3.0f64, -3.0..3.0f64, -3.0..3.0f64),
            angles in (-3.2..3.2f64, -1.6..1.6f64, -3.2..3.2f64),
            hs in prop_oneof![Just(0.0), 0.0..2.0f64],
            tp in 1.0..12.0f64,
            gamma in 1.0..7.0f64,
            seed in any::<u64>(),
            time in -100.0..100.0f64,
            steepness in 0.0..0.9f64,
        ) {
            let meshes = all_meshes();
            let (name, mesh) = meshes[mesh_index % meshes.len()];
            let water = Water::default();
            let p = pose(position.0, position.1, position.2, angles.0, angles.1, angles.2);
            let sea = AiryWaves::from_sea_state(
                &SeaState {
                    spectrum: Spectrum::Jonswap { gamma },
                    significant_height: hs,
                    peak_period: tp,
                    direction: Vector3::new(1.0, 0.0, 0.3),
                    spreading: Some(4.0),
                    components: 12,
                    seed,
                },
                &water,
                None,
            )
            .unwrap();
            let wavelength = 8.0;
            let gerstner = GerstnerWaves::new(vec![AiryComponent {
                amplitude: steepness * wavelength / (2.0 * std::f64::consts::PI),
                wavelength,
                direction: Vector3::z(),
                phase: 0.0,
            }])
            .unwrap();
            for surface in [&sea as &dyn buoyancy_core::water::WaterSurface<f64>, &gerstner] {
                let b = mesh.buoyancy(&p, Sea::new(&water, surface, time), Method::ExactSurface).unwrap();
                let numbers = [b.submerged_volume]
                    .into_iter()
                    .chain(b.center_of_buoyancy.iter().copied())
                    .chain(b.force.iter().copied())
                    .chain(b.torque.iter().copied());
                for x in numbers {
                    prop_assert!(x.is_finite(), "{name}: {b:?}");
                }
            }
            if hs == 0.0 {
                let calm = mesh.buoyancy(&p, Sea::new(&water, &CalmSurface, time), Method::ExactSurface).unwrap();
                prop_assert_eq!(mesh.buoyancy(&p, Sea::new(&water, &sea, time), Method::ExactSurface).unwrap(), calm);
            }
        }
    }
}

mod froude_krylov {
    use super::*;

    /// A fully submerged ball in deep water, Froude–Krylov pressure: the force is `ρgV` up plus
    /// `ρV` times the water's acceleration at the center (each component of the acceleration is
    /// harmonic, so its mean over the ball is its value there); converges with the resolution.
    #[test]
    fn a_submerged_ball_feels_the_water_acceleration() {
        let water = Water::default();
        let waves = AiryWaves::new(
            vec![
                AiryComponent {
                    amplitude: 0.4,
                    wavelength: 8.0,
                    direction: Vector3::x(),
                    phase: 0.3,
                },
                AiryComponent {
                    amplitude: 0.2,
                    wavelength: 5.0,
                    direction: Vector3::new(0.6, 0.0, 0.8),
                    phase: 2.0,
                },
            ],
            None,
        )
        .unwrap();
        let center = Point3::new(0.4, -2.5, -0.3);
        let acceleration = waves
            .water_motion(&water, &center, 1.3)
            .unwrap()
            .acceleration;
        let mut errors = Vec::new();
        for (slices, stacks) in [(24, 12), (48, 24), (96, 48)] {
            let (v, t) = primitives::uv_sphere::<f64>(1.0, slices, stacks).unwrap();
            let ball = Mesh::new(v, t).unwrap();
            let p = pose(center.x, center.y, center.z, 0.0, 0.0, 0.0);
            let b = ball
                .buoyancy(
                    &p,
                    Sea::new(&water, &waves, 1.3).with_pressure(Pressure::FroudeKrylov),
                    Method::ExactSurface,
                )
                .unwrap();
            let expected = Vector3::y() * water.specific_weight() * ball.volume()
                + acceleration * (water.density() * ball.volume());
            errors.push(
                (b.force - expected).norm()
                    / (acceleration.norm() * water.density() * ball.volume()),
            );
        }
        // Second order in the mesh spacing (the faceted ball and the sampled surface).
        assert!(errors[2] < 2e-4, "{errors:?}");
        for pair in errors.windows(2) {
            assert!(pair[0] / pair[1] > 3.0, "second order: {errors:?}");
        }
    }

    /// The Smith effect: under Froude–Krylov pressure the wave's heave force on a wall-sided box
    /// is that of the hydrostatic pressure at its bottom scaled by `e^{−kT}`, `T` the draft:
    /// `ρgB·[LT + a·e^{−kT}·(2/k)·sin(kL/2)·cos(ωt − φ)]` in deep water.
    #[test]
    fn the_heave_force_decays_with_the_draft() {
        let (length, beam, draft, amplitude, wavelength) = (4.0, 1.0, 0.8, 0.05, 10.0);
        let water = Water::default();
        let waves = wave_along_x(amplitude, wavelength, 0.3, None);
        let k = 2.0 * std::f64::consts::PI / wavelength;
        let omega = waves.angular_frequency(0, water.gravity());
        let weight = water.specific_weight();
        let (v, t) = primitives::cube::<f64>(16).unwrap();
        let b = Mesh::new(v, t)
            .unwrap()
            .scaled(&Vector3::new(length, 1.0, beam))
            .unwrap();
        let p = pose(0.0, 0.5 - draft, 0.0, 0.0, 0.0, 0.0);
        let mut worst: f64 = 0.0;
        for step in 0..8 {
            let time = step as f64 * 0.29;
            let got = b
                .buoyancy(
                    &p,
                    Sea::new(&water, &waves, time).with_pressure(Pressure::FroudeKrylov),
                    Method::ExactSurface,
                )
                .unwrap();
            let wave = amplitude
                * (-k * draft).exp()
                * (2.0 / k)
                * (k * length / 2.0).sin()
                * (0.3 - omega * time).cos();
            let expected = weight * beam * (length * draft + wave);
            worst =
                worst.max((got.force.y - expected).abs() / (weight * beam * amplitude * length));
        }
        // The bottom is flat and the quadrature of degree 5: exact to round-off here.
        assert!(worst < 1e-9, "{worst}");
    }
}
