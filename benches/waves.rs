//! Buoyancy on waves (`Mesh::buoyancy` under a `Sea`): µs per evaluation on the paper's models under
//! a calm surface, a 512² periodic height grid, 8 Airy components, a 64-component JONSWAP sea
//! and 3 Gerstner components, and the Froude–Krylov pressure of the 8 Airy components, f64, one
//! thread, at the paper's 100 poses (the wave's time
//! advancing 0.05 s per pose). Each figure is the median over 7 batches (see
//! `common::microseconds`); the last column is Exact Surface under still water, for scale.
//!
//! With `--features rayon`, a column of `Query::in_parallel` on the Airy sea.
//!
//! `cargo bench --bench waves [--features rayon] [-- large] [WORD...]` (`large` adds the 10⁶-triangle torus knot;
//! other words keep the models and columns whose names contain one of them, e.g. `bunny airy`).

mod common;

use buoyancy::query::{Pressure, Query, Sea};
use std::hint::black_box;

use buoyancy::nalgebra::{Point3, Vector3};
use buoyancy::water::{
    AiryComponent, AiryWaves, CalmSurface, GerstnerWaves, HeightGrid, SeaState, Spectrum,
    WaterSurface,
};
use buoyancy::{Mesh, Method, Pose, Traversal};

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .map(|a| a.to_lowercase())
        .collect();
    let large = args.iter().any(|a| a == "large");
    let words: Vec<&String> = args.iter().filter(|a| *a != "large").collect();
    let kept = |name: &str, all: &[&str]| {
        let name = name.to_lowercase();
        // A word that names no entry of this list does not filter it.
        let here: Vec<&&String> = words
            .iter()
            .filter(|w| all.iter().any(|n| n.to_lowercase().contains(w.as_str())))
            .collect();
        here.is_empty() || here.iter().any(|w| name.contains(w.as_str()))
    };
    let water = common::water::<f64>();
    let n = 512;
    // A smooth periodic field over 128 m: two crossing swells, 0.3 m high.
    let heights: Vec<f64> = (0..n * n)
        .map(|k| {
            let (i, j) = ((k % n) as f64, (k / n) as f64);
            let t = 2.0 * std::f64::consts::PI / n as f64;
            0.2 * (3.0 * t * i).cos() + 0.1 * (5.0 * t * (i + j)).sin()
        })
        .collect();
    let spacing = 128.0 / n as f64;
    let grid = HeightGrid::new(
        heights,
        n,
        n,
        Point3::new(-64.0, 0.0, -64.0),
        Vector3::x() * spacing,
        Vector3::z() * spacing,
        true,
    )
    .unwrap();
    let airy = AiryWaves::new(
        (0..8)
            .map(|i| AiryComponent {
                amplitude: 0.05,
                wavelength: 3.0 + 1.7 * i as f64,
                direction: Vector3::new((i as f64).cos(), 0.0, (i as f64).sin()),
                phase: 0.7 * i as f64,
            })
            .collect(),
        None,
    )
    .unwrap();
    let jonswap = AiryWaves::from_sea_state(
        &SeaState {
            spectrum: Spectrum::Jonswap { gamma: 3.3 },
            significant_height: 0.4,
            peak_period: 3.0,
            direction: Vector3::x(),
            spreading: Some(10.0),
            components: 64,
            seed: 1,
        },
        &water,
        None,
    )
    .unwrap();
    let gerstner = GerstnerWaves::new(airy.components()[..3].to_vec()).unwrap();
    let surfaces: [(&str, &dyn WaterSurface<f64>); 5] = [
        ("calm", &CalmSurface),
        ("grid 512²", &grid),
        ("Airy ×8", &airy),
        ("JONSWAP ×64", &jonswap),
        ("Gerstner ×3", &gerstner),
    ];
    // One evaluation at a pose and time.
    type Column<'a> = (String, Box<dyn Fn(&Mesh<f64>, &Pose<f64>, f64) + 'a>);
    let mut columns: Vec<Column> = surfaces
        .iter()
        .map(|&(name, surface)| -> Column {
            let water = &water;
            (
                name.to_string(),
                Box::new(move |mesh, pose, time| {
                    black_box(
                        mesh.buoyancy(pose, Sea::new(water, surface, time), Method::ExactSurface)
                            .unwrap(),
                    );
                }),
            )
        })
        .collect();
    columns.push((
        "Froude–Krylov, Airy ×8".into(),
        Box::new(|mesh, pose, time| {
            black_box(
                mesh.buoyancy(
                    pose,
                    Sea::new(&water, &airy, time).with_pressure(Pressure::FroudeKrylov),
                    Method::ExactSurface,
                )
                .unwrap(),
            );
        }),
    ));
    #[cfg(feature = "rayon")]
    columns.push((
        format!("Airy ×8, {} threads", rayon::current_num_threads()),
        Box::new(|mesh, pose, time| {
            black_box(
                mesh.buoyancy(
                    pose,
                    Sea::new(&water, &airy, time),
                    Query::new(Method::ExactSurface).in_parallel(),
                )
                .unwrap(),
            );
        }),
    ));
    columns.push((
        "still water, Exact Surface".into(),
        Box::new(|mesh, pose, _| {
            black_box(
                mesh.buoyancy(
                    pose,
                    &water,
                    Query::new(Method::ExactSurface).with_traversal(Traversal::Auto),
                )
                .unwrap(),
            );
        }),
    ));
    let names: Vec<String> = columns.iter().map(|(name, _)| name.clone()).collect();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    columns.retain(|(name, _)| kept(name, &names));
    print!("| model |");
    for (name, _) in &columns {
        print!(" {name} |");
    }
    println!("\n|---|{}", "---|".repeat(columns.len()));
    let models = common::models::<f64>(large);
    let model_names: Vec<&str> = models.iter().map(|m| m.name.as_str()).collect();
    for model in models.iter().filter(|m| kept(&m.name, &model_names)) {
        let poses = common::poses(&model.mesh);
        print!("| {} |", model.name);
        for (_, evaluate) in &columns {
            let us = common::microseconds(poses.len(), || {
                for (k, pose) in poses.iter().enumerate() {
                    evaluate(&model.mesh, pose, 0.05 * k as f64);
                }
            });
            print!(" {us:.1} |");
        }
        println!();
    }
}
