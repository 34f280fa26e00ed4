//! The world's water made from rapier's gravity by `FloatingBodies::new`.

use buoyancy_rapier::{Error, FloatingBodies};
use rapier3d::prelude::*;

/// The surface's up normal is opposite to gravity and `g` is its length, whatever its direction.
#[test]
fn water_is_up_against_gravity() {
    let water = FloatingBodies::new(Vector::new(0.0, 0.0, -3.0)).unwrap();
    let (normal, g) = (water.water().normal().into_inner(), water.water().gravity());
    assert_eq!((normal.x, normal.y, normal.z, g), (0.0, 0.0, 1.0, 3.0));
    let water = FloatingBodies::new(Vector::new(0.0, -9.81, 0.0)).unwrap();
    assert_eq!(water.water().normal().y, 1.0);
    assert!((water.water().gravity() - 9.81).abs() < 1e-6);
}

/// Zero gravity: water y up, no weight to carry (`g` = 0).
#[test]
fn zero_gravity_keeps_y_up() {
    let water = FloatingBodies::new(Vector::ZERO).unwrap();
    assert_eq!(water.water().normal().y, 1.0);
    assert_eq!(water.water().gravity(), 0.0);
}

/// A NaN or infinite gravity is an error naming the argument, not the default water.
#[test]
fn non_finite_gravity_is_an_error() {
    for gravity in [
        Vector::new(0.0, f32::NAN, 0.0),
        Vector::new(f32::INFINITY, -9.81, 0.0),
        Vector::new(0.0, -9.81, f32::NEG_INFINITY),
    ] {
        let error = FloatingBodies::new(gravity).unwrap_err();
        assert!(matches!(error, Error::InvalidGravity(_)), "{error:?}");
        let message = error.to_string();
        assert!(
            message.starts_with("gravity (") && message.contains("NaN or infinite"),
            "{message}"
        );
    }
}
