//! The paper's accuracy test (section 5, Figure 4): a unit cube and a unit sphere lowered
//! through the surface with ρg = 1, their centroid at (0, h, 0); the buoyant force of each
//! method against the analytic curves
//!
//! * cube:   F(h) = 1/2 − h,               h ∈ (−1/2, 1/2)
//! * sphere: F(h) = π/3·(h − 1)²·(h + 2),  h ∈ (−1, 1)
//!
//! Run with `cargo run --release --example accuracy`. Prints, per mesh and method, the largest
//! and the root-mean-square error of F over 199 heights, and a few sample values.

use std::f64::consts::PI;
use std::time::Instant;

use buoyancy::nalgebra::{Translation3, UnitQuaternion, Vector3};
use buoyancy::{Mesh, Method, Pose, Water, mesh::primitives};

struct Case {
    name: String,
    mesh: Mesh<f64>,
    analytic: fn(f64) -> f64,
    /// Half the range of h.
    half_range: f64,
}

fn main() -> Result<(), buoyancy::Error> {
    let water = Water::new(1.0, 1.0, Vector3::y(), 0.0)?;
    let cube = |n: usize| -> Result<Case, buoyancy::Error> {
        let (v, t) = primitives::cube(n)?;
        Ok(Case {
            name: format!("cube {n}² per face ({} triangles)", t.len()),
            mesh: Mesh::new(v, t)?,
            analytic: |h| 0.5 - h,
            half_range: 0.5,
        })
    };
    let sphere = |s: usize| -> Result<Case, buoyancy::Error> {
        let (v, t) = primitives::uv_sphere(1.0, s, s)?;
        Ok(Case {
            name: format!("sphere {s}² segments ({} triangles)", t.len()),
            mesh: Mesh::new(v, t)?,
            analytic: |h| PI / 3.0 * (h - 1.0).powi(2) * (h + 2.0),
            half_range: 1.0,
        })
    };
    let cases = [cube(10)?, cube(100)?, sphere(50)?, sphere(200)?];

    println!("# Buoyant force against the analytic curves (ρg = 1, 199 heights per body)\n");
    println!("| body | method | max abs error | RMS error | max error / max F |");
    println!("|---|---|---|---|---|");
    let started = Instant::now();
    for case in &cases {
        let heights: Vec<f64> = (1..200)
            .map(|k| case.half_range * (k as f64 / 100.0 - 1.0))
            .collect();
        let peak = heights
            .iter()
            .map(|&h| (case.analytic)(h))
            .fold(0.0, f64::max);
        for method in Method::ALL {
            let (mut worst, mut squares) = (0.0f64, 0.0);
            for &h in &heights {
                let pose =
                    Pose::from_parts(Translation3::new(0.0, h, 0.0), UnitQuaternion::identity());
                let b = case.mesh.buoyancy(&pose, &water, method)?;
                let error = b.force.y - (case.analytic)(h);
                worst = worst.max(error.abs());
                squares += error * error;
            }
            let rms = (squares / heights.len() as f64).sqrt();
            println!(
                "| {} | {method} | {worst:.3e} | {rms:.3e} | {:.2e} |",
                case.name,
                worst / peak
            );
        }
    }
    println!("\n(computed in {:.2} s)\n", started.elapsed().as_secs_f64());

    println!("# Sample values, sphere 50² segments\n");
    let sphere = &cases[2];
    print!("| h | analytic |");
    Method::ALL.iter().for_each(|m| print!(" {m} |"));
    println!("\n|---|---|{}", "---|".repeat(Method::ALL.len()));
    for h in [-0.9, -0.5, 0.0, 0.5, 0.9] {
        let pose = Pose::from_parts(Translation3::new(0.0, h, 0.0), UnitQuaternion::identity());
        print!("| {h} | {:.6} |", (sphere.analytic)(h));
        for method in Method::ALL {
            print!(
                " {:.6} |",
                sphere.mesh.buoyancy(&pose, &water, method)?.force.y
            );
        }
        println!();
    }
    println!(
        "\nThe exact methods differ from the sphere curve only because the 50² mesh is a polyhedron \
         inscribed in the unit sphere (volume {:.6} against {:.6}).",
        sphere.mesh.volume(),
        4.0 / 3.0 * PI
    );
    Ok(())
}
