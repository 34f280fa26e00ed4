//! With the `serde` feature the results serialise and read back bit for bit (through JSON,
//! which the Python bindings pickle them as).
#![cfg(feature = "serde")]

use buoyancy_core::hydrostatics::{
    Equilibrium, EquilibriumOptions, GzCurve, HydrostaticRow, Hydrostatics, LoadingCondition,
    TableOptions, Trim, Waterplane,
};
use buoyancy_core::nalgebra::{Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::{Buoyancy, Mesh, Method, Pose, Water, mesh::primitives};

fn round_trip<S>(value: &S) -> S
where
    S: serde::Serialize + serde::de::DeserializeOwned,
{
    let json = serde_json::to_string(value).unwrap();
    serde_json::from_str(&json).unwrap()
}

#[test]
fn results_read_back_equal() {
    let (v, t) = primitives::cuboid([1.0, 0.5, 0.25]).unwrap();
    let mesh = Mesh::new(v, t).unwrap();
    let water = Water::default();
    // An irrational pose, so that the values have all their digits.
    let pose = Pose::from_parts(
        Translation3::new(0.1, -0.123_456_789, 0.3),
        UnitQuaternion::from_scaled_axis(Vector3::new(0.1, 0.2, 0.3)),
    );
    let buoyancy: Buoyancy<f64> = mesh.buoyancy(&pose, &water, Method::Exact).unwrap();
    assert_eq!(round_trip(&buoyancy), buoyancy);
    let waterplane: Waterplane<f64> = mesh.waterplane(&pose, &water).unwrap();
    assert_eq!(round_trip(&waterplane), waterplane);

    let loading = LoadingCondition::new(Point3::new(0.0, -0.1, 0.0))
        .unwrap()
        .with_mass(300.0)
        .unwrap();
    let hydrostatics: Hydrostatics<f64> = mesh.hydrostatics(&pose, &water, &loading).unwrap();
    assert_eq!(round_trip(&hydrostatics), hydrostatics);
    let equilibrium: Equilibrium<f64> = mesh.equilibrium(&water, &loading).unwrap();
    assert_eq!(round_trip(&equilibrium), equilibrium);
    let heels = [0.0, 0.1, 0.2, 0.3];
    let curve: GzCurve<f64> = mesh
        .gz_curve(
            &water,
            &loading,
            &heels,
            Trim::Free,
            &EquilibriumOptions::default(),
        )
        .unwrap();
    assert_eq!(round_trip(&curve), curve);
    let rows: Vec<HydrostaticRow<f64>> = mesh
        .hydrostatic_table(&water, &[0.2, 0.4], &TableOptions::default())
        .unwrap();
    assert_eq!(round_trip(&rows), rows);
}
