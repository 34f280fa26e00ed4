//! One query for still water and waves: `Mesh::buoyancy` under a `Sea` follows the same rules
//! whatever the surface, refuses what it cannot compute (never ignores it), and the controller
//! reports a refusal instead of a silent zero.

use std::sync::Arc;

use buoyancy_core::controller::{
    BodyOptions, BodyState, Command, Controller, Motion, Outcome, Part,
};
use buoyancy_core::nalgebra::{Matrix3, Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::query::{Pressure, Query, Sea};
use buoyancy_core::water::{
    AiryComponent, AiryWaves, CalmSurface, GerstnerWaves, SurfaceFn, WaterSurface,
};
use buoyancy_core::{Error, Mesh, Method, Pose, Traversal, Water, mesh::primitives};

fn ball() -> Mesh<f64> {
    let (v, t) = primitives::uv_sphere::<f64>(0.5, 32, 16).unwrap();
    Mesh::new(v, t).unwrap()
}

fn tilted(depth: f64) -> Pose<f64> {
    Pose::from_parts(
        Translation3::new(0.3, depth, -0.2),
        UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5),
    )
}

fn swell() -> AiryWaves<f64> {
    AiryWaves::new(
        vec![
            AiryComponent {
                amplitude: 0.2,
                wavelength: 12.0,
                direction: Vector3::x(),
                phase: 0.4,
            },
            AiryComponent {
                amplitude: 0.05,
                wavelength: 5.0,
                direction: Vector3::new(1.0, 0.0, 1.0),
                phase: 0.0,
            },
        ],
        None,
    )
    .unwrap()
}

fn unsupported(result: Result<buoyancy_core::Buoyancy<f64>, Error>) -> &'static str {
    match result {
        Err(Error::Unsupported { parameter, reason }) => {
            assert!(!reason.is_empty());
            parameter
        }
        other => panic!("expected Error::Unsupported, got {other:?}"),
    }
}

/// Under waves the methods that assume a flat surface are refused, naming `method`; Exact and
/// Exact Surface are the same exact integral, to the bit.
#[test]
fn under_waves_a_flat_method_is_an_error_and_the_exact_ones_agree() {
    let ball = ball();
    let water = Water::default();
    let airy = swell();
    let gerstner = GerstnerWaves::new(airy.components().to_vec()).unwrap();
    let ramp = SurfaceFn(|q: &Point3<f64>, _: f64| 0.05 * q.x);
    let surfaces: [&dyn WaterSurface<f64>; 3] = [&airy, &gerstner, &ramp];
    for surface in surfaces {
        let sea = Sea::new(&water, surface, 0.7);
        for method in [Method::Fast, Method::Improved, Method::FastSurface] {
            let e = ball.buoyancy(&tilted(-0.1), sea, method);
            assert_eq!(unsupported(e), "method", "{method}");
        }
        let exact = ball.buoyancy(&tilted(-0.1), sea, Method::Exact).unwrap();
        let surface = ball
            .buoyancy(&tilted(-0.1), sea, Method::ExactSurface)
            .unwrap();
        assert_eq!(exact, surface);
        assert!(exact.force.y > 0.0);
    }
}

/// A calm surface is still water: every method gives what it gives without a surface, and the
/// time is still checked.
#[test]
fn a_calm_sea_is_still_water_for_every_method() {
    let ball = ball();
    let water = Water::default();
    for method in Method::ALL {
        let still = ball.buoyancy(&tilted(0.1), &water, method).unwrap();
        let calm = ball
            .buoyancy(&tilted(0.1), Sea::new(&water, &CalmSurface, 2.0), method)
            .unwrap();
        assert_eq!(still, calm, "{method}");
        assert_eq!(
            ball.buoyancy(&tilted(0.1), Sea::calm(&water), method)
                .unwrap(),
            still
        );
    }
    let nan_time = Sea::new(&water, &CalmSurface, f64::NAN);
    assert!(matches!(
        ball.buoyancy(&tilted(0.1), nan_time, Method::Fast),
        Err(Error::InvalidSurface {
            parameter: "time",
            ..
        })
    ));
}

/// The Froude–Krylov pressure needs Airy waves: any other surface is refused, naming
/// `pressure`; under Airy waves it decays with depth where the hydrostatic one does not.
#[test]
fn froude_krylov_needs_airy_waves_and_decays_with_depth() {
    let ball = ball();
    let water = Water::default();
    let airy = swell();
    let gerstner = GerstnerWaves::new(airy.components().to_vec()).unwrap();
    let fk = |surface: &dyn WaterSurface<f64>, depth: f64| {
        ball.buoyancy(
            &tilted(depth),
            Sea::new(&water, surface, 0.3).with_pressure(Pressure::FroudeKrylov),
            Method::Exact,
        )
    };
    assert_eq!(unsupported(fk(&gerstner, -0.1)), "pressure");
    assert_eq!(unsupported(fk(&CalmSurface, -0.1)), "pressure");
    // Two wavelengths down the wave part of the pressure has all but vanished: the force is the
    // still water's; the hydrostatic pressure still carries the surface's ρg·η.
    let still = ball
        .buoyancy(&tilted(-12.0), &water, Method::Exact)
        .unwrap();
    let deep = fk(&airy, -12.0).unwrap();
    let hydrostatic = ball
        .buoyancy(&tilted(-12.0), Sea::new(&water, &airy, 0.3), Method::Exact)
        .unwrap();
    let weight = still.force.norm();
    assert!(
        (deep.force - still.force).norm() < 1e-3 * weight,
        "{deep:?}"
    );
    assert!((hydrostatic.force - still.force).norm() > 1e-2 * weight);
}

/// The traversal changes the cost only: under waves a scan (every vertex, every triangle on its
/// own) gives the hierarchy's walk to round-off.
#[test]
fn under_waves_the_scan_and_the_walk_agree() {
    let ball = ball();
    let water = Water::default();
    let airy = swell();
    for depth in [0.4, 0.0, -0.3, -0.8] {
        let sea = Sea::new(&water, &airy, 1.1);
        let walk = ball.buoyancy(&tilted(depth), sea, Method::Exact).unwrap();
        let scan = ball
            .buoyancy(
                &tilted(depth),
                sea,
                Query::new(Method::Exact).with_traversal(Traversal::Scan),
            )
            .unwrap();
        let scale = 1.0 + walk.force.norm();
        assert!((walk.force - scan.force).norm() < 1e-10 * scale, "{depth}");
        assert!(
            (walk.torque - scan.torque).norm() < 1e-10 * scale,
            "{depth}"
        );
        assert!((walk.submerged_volume - scan.submerged_volume).abs() < 1e-12);
    }
}

fn floating_state() -> BodyState {
    let mass = 100.0;
    BodyState {
        pose: tilted(-0.1),
        center_of_mass: Point3::new(0.3, -0.1, -0.2),
        linear_velocity: Vector3::zeros(),
        angular_velocity: Vector3::zeros(),
        mass,
        inverse_mass: Vector3::repeat(1.0 / mass),
        inverse_inertia: Matrix3::identity() * (10.0 / mass),
        gravity_scale: 1.0,
        applied_force: Vector3::zeros(),
        applied_torque: Vector3::zeros(),
        motion: Motion::Dynamic,
        sleeping: false,
    }
}

fn step(controller: &mut Controller) -> (Outcome, Vector3<f64>) {
    let mut commands = [Command::default()];
    controller.step(&[floating_state()], 1.0 / 60.0, &mut commands);
    let report = controller.report(0).unwrap();
    (report.outcome, report.buoyancy_force)
}

/// The controller asks the same query: a flat method under waves is reported as
/// `Outcome::Unsupported` with no force; the Froude–Krylov pressure is taken when asked.
#[test]
fn the_controller_reports_a_refused_query_and_takes_the_pressure() {
    let mesh = Arc::new(ball());
    let mut controller = Controller::default();
    let part = Part {
        mesh: mesh.clone(),
        shape_to_body: Pose::identity(),
    };
    controller
        .add(
            vec![part],
            BodyOptions {
                method: Some(Method::Fast),
                ..Default::default()
            },
        )
        .unwrap();
    assert_eq!(step(&mut controller).0, Outcome::Applied);
    controller.set_surface(Some(Arc::new(swell())));
    let (outcome, force) = step(&mut controller);
    assert_eq!(outcome, Outcome::Unsupported);
    assert_eq!(force, Vector3::zeros());

    let mut controller = Controller::default();
    let part = Part {
        mesh: mesh.clone(),
        shape_to_body: Pose::identity(),
    };
    controller.add(vec![part], BodyOptions::default()).unwrap();
    controller.set_surface(Some(Arc::new(swell())));
    controller.set_time(0.3);
    let (outcome, hydrostatic) = step(&mut controller);
    assert_eq!(outcome, Outcome::Applied);
    controller.set_time(0.3);
    controller.set_pressure(Pressure::FroudeKrylov);
    assert_eq!(controller.pressure(), Pressure::FroudeKrylov);
    let (outcome, froude_krylov) = step(&mut controller);
    assert_eq!(outcome, Outcome::Applied);
    let expected = mesh
        .buoyancy(
            &tilted(-0.1),
            Sea::new(&Water::default(), &swell(), 0.3).with_pressure(Pressure::FroudeKrylov),
            Method::Exact,
        )
        .unwrap();
    assert!((froude_krylov - expected.force).norm() < 1e-9 * expected.force.norm());
    assert!((froude_krylov - hydrostatic).norm() > 1e-6 * expected.force.norm());
    controller.set_surface(Some(Arc::new(
        GerstnerWaves::new(swell().components().to_vec()).unwrap(),
    )));
    assert_eq!(step(&mut controller).0, Outcome::Unsupported);
}

/// Names of the pressures read back.
#[test]
fn pressures_parse_by_name() {
    for p in Pressure::ALL {
        assert_eq!(p.name().parse::<Pressure>().unwrap(), p);
    }
    assert_eq!(
        "Froude-Krylov".parse::<Pressure>().unwrap(),
        Pressure::FroudeKrylov
    );
    assert!(matches!(
        "linear".parse::<Pressure>(),
        Err(Error::Unsupported {
            parameter: "pressure",
            ..
        })
    ));
}
