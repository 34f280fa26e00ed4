//! What the benchmarks share: the paper's models and its timing protocol.
#![allow(dead_code)]

use std::time::{Duration, Instant};

use buoyancy::nalgebra::{Translation3, UnitQuaternion, Vector3};
use buoyancy::{Mesh, Pose, Real, Water, mesh::primitives};

/// A benchmark model: its name in the paper's Table 1 (if any), the paper's times in ms
/// (Fast, Improved, Exact, Fast Surface, Exact Surface), and the mesh.
pub struct Model<T: Real> {
    pub name: String,
    pub paper_ms: Option<[f64; 5]>,
    pub mesh: Mesh<T>,
}

/// The paper's three models from the shared meshes, a procedural torus knot of the same size
/// when they are missing (saying so; under `CI=true` their absence fails), and (with `large`) a
/// procedural torus knot of 1,000,000 triangles.
pub fn models<T: Real>(large: bool) -> Vec<Model<T>> {
    let build = |(v, t): primitives::Shape<T>| Mesh::new(v, t).expect("valid mesh");
    let mut models = Vec::new();
    let table = [
        (
            "torusknot.obj",
            "torus knot",
            [0.09, 0.18, 0.26, 0.22, 0.33],
        ),
        ("bunny.obj", "bunny", [0.23, 0.69, 0.75, 0.76, 0.90]),
        ("armadillo.obj", "armadillo", [0.98, 2.96, 3.05, 3.45, 3.94]),
    ];
    match buoyancy_samples::mesh_or_fallback(None, "a procedural torus knot") {
        Some(dir) => {
            for (file, name, ms) in table {
                let (v, t) = buoyancy::io::load::<T>(dir.join(file)).expect("readable mesh");
                let mesh = build((v, t));
                models.push(Model {
                    name: format!("{name} {}", mesh.triangle_count()),
                    paper_ms: Some(ms),
                    mesh,
                });
            }
        }
        None => {
            let mesh = build(primitives::torus_knot(2, 3, 1.0, 0.25, 80, 11).unwrap());
            models.push(Model {
                name: "procedural torus knot 1760".into(),
                paper_ms: None,
                mesh,
            });
        }
    }
    if large {
        let mesh = build(primitives::torus_knot(2, 3, 1.0, 0.25, 4000, 125).unwrap());
        models.push(Model {
            name: format!("torus knot {}", mesh.triangle_count()),
            paper_ms: None,
            mesh,
        });
    }
    models
}

/// The paper's protocol: 100 poses taking the body from almost entirely above the surface to
/// nearly fully submerged. The body is tilted (so no face is parallel to the water) and lowered
/// until the surface sweeps from 5% to 95% of its vertical extent.
pub fn poses<T: Real>(mesh: &Mesh<T>) -> Vec<Pose<T>> {
    sweep(mesh, 100)
}

/// [`poses`] with `count` poses over the same sweep: with many, each pose is close to the one
/// before, as the steps of a simulation are.
pub fn sweep<T: Real>(mesh: &Mesh<T>, count: usize) -> Vec<Pose<T>> {
    assert!(count >= 2, "a sweep needs at least 2 poses");
    let rotation = UnitQuaternion::from_euler_angles(
        T::from_f64_lossy(0.3),
        T::from_f64_lossy(0.5),
        T::from_f64_lossy(0.2),
    );
    let up = Vector3::y();
    let heights: Vec<T> = (0..mesh.vertex_count())
        .map(|i| up.dot(&(rotation * (mesh.vertex(i) - mesh.centroid()))))
        .collect();
    let lowest = heights
        .iter()
        .copied()
        .fold(T::max_value().unwrap(), T::min);
    let highest = heights
        .iter()
        .copied()
        .fold(T::min_value().unwrap(), T::max);
    (0..count)
        .map(|k| {
            let fraction = T::from_f64_lossy(0.05 + 0.9 * k as f64 / (count - 1) as f64);
            // Water at `lowest + fraction·extent` relative to the centroid, i.e. centroid at minus that.
            let centroid_height = -(lowest + (highest - lowest) * fraction);
            let translation = up * centroid_height - rotation * mesh.centroid().coords;
            Pose::from_parts(Translation3::from(translation), rotation)
        })
        .collect()
}

pub fn water<T: Real>() -> Water<T> {
    Water::default()
}

/// Microseconds per evaluation: `evaluate_all` runs `per_call` evaluations; the figure is the
/// median over 7 batches (each of at least 50 ms) of the mean time of one evaluation.
pub fn microseconds(per_call: usize, mut evaluate_all: impl FnMut()) -> f64 {
    evaluate_all();
    let mut batches: Vec<f64> = (0..7)
        .map(|_| {
            let started = Instant::now();
            let mut calls = 0;
            while started.elapsed() < Duration::from_millis(50) || calls < 2 {
                evaluate_all();
                calls += 1;
            }
            started.elapsed().as_secs_f64() * 1e6 / (calls * per_call) as f64
        })
        .collect();
    batches.sort_by(f64::total_cmp);
    batches[batches.len() / 2]
}
