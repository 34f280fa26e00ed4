//! Best-of-15 timings for A/B comparisons: every method on the paper's models, the peers'
//! 30,000-triangle torus (`benches/peers.py`) and, with `-- large`, the 10⁶-triangle torus knot,
//! by the scan and by the hierarchy, f64, one thread. The last column is the mean number of
//! triangles the surface cuts per pose, what the hierarchy's cost follows. A last row per model
//! times `Mesh::damping` at the same poses, the body moving at 1 m/s down and sideways and
//! turning at 1 rad/s. Each figure is the fastest of 15 rounds of the paper's 100 poses, in µs
//! per evaluation; the minimum is the figure least disturbed by other work on a shared machine.
//!
//! `cargo bench --bench rounds [-- WORD…]`, each word narrowing what runs, for profiling one case:
//!
//! * `large`: add the 10⁶-triangle torus knot;
//! * a word of a model's name (`armadillo`, `torus`): only the models whose name contains it;
//! * a method (`exact`, as in [`Method::name`]) or `damping`: only those rows;
//! * `scan` or `hierarchy`: only that traversal;
//! * `parallel` (with `--features rayon`): `Query::in_parallel` on the same
//!   query.
//!
//! `BUOYANCY_ROUNDS=N` takes the best of N rounds instead of 15. `BUOYANCY_POSES=N` spreads N
//! poses over the same sweep instead of 100: with thousands, each pose is close to the one
//! before, as in a simulation, and the branch predictor and the caches carry over from one
//! evaluation to the next (see "Branches" in `benches/RESULTS.md`).

mod common;

use buoyancy::query::Query;
use std::hint::black_box;
use std::time::Instant;

use buoyancy::nalgebra::Vector3;
use buoyancy::{DampingCoefficients, Method, Traversal};

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let large = args.iter().any(|a| a == "large");
    let methods: Vec<Method> = Method::ALL
        .into_iter()
        .filter(|m| args.iter().any(|a| a == m.name()))
        .collect();
    let named_damping = args.iter().any(|a| a == "damping");
    // The damping row when asked for, or when no method or traversal is named.
    let damping = named_damping
        || (methods.is_empty() && !args.iter().any(|a| a == "scan" || a == "hierarchy"));
    let methods = match (methods.is_empty(), named_damping) {
        (true, false) => Method::ALL.to_vec(),
        _ => methods,
    };
    let only = |t: Traversal| args.iter().any(|a| a == t.name());
    let traversals: Vec<Traversal> = match (only(Traversal::Scan), only(Traversal::Hierarchy)) {
        (true, false) => vec![Traversal::Scan],
        (false, true) => vec![Traversal::Hierarchy],
        _ => vec![Traversal::Scan, Traversal::Hierarchy],
    };
    let parallel = args.iter().any(|a| a == "parallel");
    #[cfg(not(feature = "rayon"))]
    assert!(!parallel, "`parallel` needs --features rayon");
    let keyword = |a: &str| {
        a == "large"
            || a == "parallel"
            || a == "damping"
            || a == "scan"
            || a == "hierarchy"
            || Method::ALL.iter().any(|m| m.name() == a)
    };
    let names: Vec<&String> = args.iter().filter(|a| !keyword(a)).collect();
    let mut models = common::models::<f64>(large);
    let (v, t) = buoyancy::mesh::primitives::torus(1.0, 0.25, 200, 75).unwrap();
    let torus = buoyancy::Mesh::new(v, t).expect("valid mesh");
    models.insert(
        models.len() - usize::from(large),
        common::Model {
            name: "torus 30000".into(),
            paper_ms: None,
            mesh: torus,
        },
    );
    let models: Vec<_> = models
        .into_iter()
        .filter(|m| names.is_empty() || names.iter().any(|n| m.name.contains(n.as_str())))
        .collect();
    let water = common::water::<f64>();
    let rounds: usize = std::env::var("BUOYANCY_ROUNDS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(15);
    let pose_count: usize = std::env::var("BUOYANCY_POSES")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(100);
    assert!(pose_count >= 2, "BUOYANCY_POSES must be at least 2");
    println!("| model | method | scan µs | hierarchy µs | cut triangles |");
    println!("|---|---|---|---|---|");
    for model in &models {
        let poses = common::sweep(&model.mesh, pose_count);
        for &method in &methods {
            let time = |traversal: Traversal| {
                (0..rounds)
                    .map(|_| {
                        let started = Instant::now();
                        for pose in &poses {
                            #[cfg(feature = "rayon")]
                            let result = if parallel {
                                model.mesh.buoyancy(
                                    black_box(pose),
                                    &water,
                                    Query::new(method).with_traversal(traversal).in_parallel(),
                                )
                            } else {
                                model.mesh.buoyancy(
                                    black_box(pose),
                                    &water,
                                    Query::new(method).with_traversal(traversal),
                                )
                            };
                            #[cfg(not(feature = "rayon"))]
                            let result = model.mesh.buoyancy(
                                black_box(pose),
                                &water,
                                Query::new(method).with_traversal(traversal),
                            );
                            black_box(result.unwrap());
                        }
                        started.elapsed().as_secs_f64() * 1e6 / poses.len() as f64
                    })
                    .fold(f64::INFINITY, f64::min)
            };
            let [scan, hierarchy] = [Traversal::Scan, Traversal::Hierarchy].map(|t| {
                if traversals.contains(&t) {
                    format!("{:.2}", time(t))
                } else {
                    "–".into()
                }
            });
            let cut = poses
                .iter()
                .map(|pose| {
                    model
                        .mesh
                        .buoyancy(pose, &water, method)
                        .unwrap()
                        .partially_submerged
                })
                .sum::<usize>() as f64
                / poses.len() as f64;
            println!(
                "| {} | {} | {scan} | {hierarchy} | {cut:.0} |",
                model.name,
                method.name()
            );
        }
        if damping {
            let (velocity, omega) = (
                Vector3::new(1.0, -1.0, 0.0),
                Vector3::new(0.3, 0.5, 0.8).normalize(),
            );
            let coefficients = DampingCoefficients::default();
            let time = (0..rounds)
                .map(|_| {
                    let started = Instant::now();
                    for pose in &poses {
                        black_box(
                            model
                                .mesh
                                .damping(black_box(pose), &velocity, &omega, &water, &coefficients)
                                .unwrap(),
                        );
                    }
                    started.elapsed().as_secs_f64() * 1e6 / poses.len() as f64
                })
                .fold(f64::INFINITY, f64::min);
            let wetted = poses
                .iter()
                .map(|pose| {
                    model
                        .mesh
                        .damping(pose, &velocity, &omega, &water, &coefficients)
                        .unwrap()
                        .wetted_fraction
                })
                .sum::<f64>()
                / poses.len() as f64
                * model.mesh.triangle_count() as f64;
            println!(
                "| {} | damping | – | {time:.2} | {wetted:.0} wetted (area-weighted) |",
                model.name
            );
        }
    }
}
