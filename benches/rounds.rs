//! Best-of-15 timings for A/B comparisons: every method on the paper's models (and, with
//! `-- large`, the 10⁶-triangle torus knot), by the scan and by the hierarchy, f64, one thread.
//! Each figure is the fastest of 15 rounds of the paper's 100 poses, in µs per evaluation; the
//! minimum is the figure least disturbed by other work on a shared machine.
//!
//! `cargo bench --bench rounds [-- large]`

mod common;

use std::hint::black_box;
use std::time::Instant;

use buoyancy::{Method, Traversal};

fn main() {
    let large = std::env::args().any(|a| a == "large");
    let water = common::water::<f64>();
    println!("| model | method | scan µs | hierarchy µs |");
    println!("|---|---|---|---|");
    for model in common::models::<f64>(large) {
        let poses = common::poses(&model.mesh);
        for method in Method::ALL {
            let [scan, hierarchy] = [Traversal::Scan, Traversal::Hierarchy].map(|traversal| {
                (0..15)
                    .map(|_| {
                        let started = Instant::now();
                        for pose in &poses {
                            black_box(model.mesh.buoyancy_with(black_box(pose), &water, method, traversal).unwrap());
                        }
                        started.elapsed().as_secs_f64() * 1e6 / poses.len() as f64
                    })
                    .fold(f64::INFINITY, f64::min)
            });
            println!("| {} | {} | {scan:.2} | {hierarchy:.2} |", model.name, method.name());
        }
    }
}
