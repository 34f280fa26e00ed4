//! A body far below the surface keeps its digits: its heights are taken relative to its own
//! level, so its result does not depend on the depth (once, a 1 m cube 10⁹ m down had its center
//! of buoyancy 82 m off with the surface methods and 0.3 m off under waves, and 10¹⁵ m down its
//! volume 1.4 % low in still water and 4 % high under waves).
//!
//! Every method in still water, the hydrostatic pressure under Airy waves, a sea state, Gerstner
//! waves and a surface function, and the Froude–Krylov pressure: the cube, tilted, at 10⁹ and
//! 10¹⁵ m gives the result it gives 10 m down (translated), within round-off of the body.

use buoyancy_core::nalgebra::{Translation3, UnitQuaternion, Vector3};
use buoyancy_core::query::{Pressure, Sea};
use buoyancy_core::water::{AiryComponent, AiryWaves, GerstnerWaves, SurfaceFn, WaterSurface};
use buoyancy_core::{Buoyancy, Mesh, Method, Pose, Water, mesh::primitives};

fn cube() -> Mesh<f64> {
    let (v, t) = primitives::cube(3).unwrap();
    Mesh::new(v, t).unwrap()
}

fn at_depth(depth: f64) -> Pose<f64> {
    Pose::from_parts(
        Translation3::new(3.0, -depth, 0.5),
        UnitQuaternion::from_scaled_axis(Vector3::new(0.2, 0.4, 0.1)),
    )
}

/// `deep` equals `near` (10 m down) but for the translation, to `tolerance` of the weight of the
/// body (forces, torques) and of its size (centers; and not closer than a world coordinate
/// `depth` down can be written, 4ε·depth: 0.9 m at 10¹⁵ m).
fn same_as_near(deep: &Buoyancy<f64>, near: &Buoyancy<f64>, depth: f64, what: &str) {
    let weight = 1000.0 * 9.81;
    let tolerance = 1e-9;
    let shift = Vector3::new(0.0, 10.0 - depth, 0.0);
    assert!(
        (deep.submerged_volume - near.submerged_volume).abs() < tolerance,
        "{what} at {depth:e} m: volume {} against {}",
        deep.submerged_volume,
        near.submerged_volume
    );
    assert!(
        (deep.force - near.force).norm() < tolerance * weight,
        "{what} at {depth:e} m: force {} against {}",
        deep.force,
        near.force
    );
    assert!(
        (deep.torque - near.torque).norm() < tolerance * weight,
        "{what} at {depth:e} m: torque {} against {}",
        deep.torque,
        near.torque
    );
    let center = deep.center_of_buoyancy - shift;
    let written = 4.0 * f64::EPSILON * depth;
    assert!(
        (center - near.center_of_buoyancy).norm() < tolerance.max(written),
        "{what} at {depth:e} m: center {} (moved up) against {}",
        center,
        near.center_of_buoyancy
    );
}

#[test]
fn every_method_in_still_water() {
    let mesh = cube();
    let water = Water::default();
    for method in Method::ALL {
        let near = mesh.buoyancy(&at_depth(10.0), &water, method).unwrap();
        for depth in [1e9, 1e15] {
            let deep = mesh.buoyancy(&at_depth(depth), &water, method).unwrap();
            same_as_near(&deep, &near, depth, method.name());
        }
    }
}

#[test]
fn every_surface_under_waves() {
    let mesh = cube();
    let water = Water::default();
    let swell = AiryComponent {
        amplitude: 0.5,
        wavelength: 20.0,
        direction: Vector3::new(1.0, 0.0, 0.3),
        phase: 0.4,
    };
    let airy = AiryWaves::new(vec![swell], None).unwrap();
    let gerstner = GerstnerWaves::new(vec![swell]).unwrap();
    let ramp = SurfaceFn(|q: &buoyancy_core::nalgebra::Point3<f64>, t: f64| 0.1 * q.x + 0.01 * t);
    let surfaces: [(&str, &dyn WaterSurface<f64>); 3] = [
        ("Airy", &airy),
        ("Gerstner", &gerstner),
        ("a surface function", &ramp),
    ];
    for (name, surface) in surfaces {
        let near = mesh
            .buoyancy(
                &at_depth(10.0),
                Sea::new(&water, surface, 1.5),
                Method::ExactSurface,
            )
            .unwrap();
        for depth in [1e9, 1e15] {
            let deep = mesh
                .buoyancy(
                    &at_depth(depth),
                    Sea::new(&water, surface, 1.5),
                    Method::ExactSurface,
                )
                .unwrap();
            same_as_near(&deep, &near, depth, name);
        }
    }
}

#[test]
fn froude_krylov_far_down_is_the_still_water_buoyancy() {
    let mesh = cube();
    let water = Water::default();
    let swell = AiryComponent {
        amplitude: 0.5,
        wavelength: 20.0,
        direction: Vector3::x(),
        phase: 0.0,
    };
    let airy = AiryWaves::new(vec![swell], None).unwrap();
    let still = mesh
        .buoyancy(&at_depth(10.0), &water, Method::Exact)
        .unwrap();
    for depth in [1e3, 1e9, 1e15] {
        // The wave part of the pressure decays as e^{−k·d}: nothing left 1 km down.
        let deep = mesh
            .buoyancy(
                &at_depth(depth),
                Sea::new(&water, &airy, 1.5).with_pressure(Pressure::FroudeKrylov),
                Method::ExactSurface,
            )
            .unwrap();
        same_as_near(&deep, &still, depth, "Froude–Krylov");
    }
}
