//! Criterion benchmarks of the five methods on the paper's models, following its protocol (one
//! iteration = 100 evaluations, the body going from almost dry to almost submerged), f32 and f64,
//! serial and (with `--features rayon`) parallel.
//!
//! `cargo bench --bench methods [--features rayon] [-- FILTER]`

mod common;

use buoyancy::query::Query;
use std::hint::black_box;

use buoyancy::{Method, Real};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

fn bench_scalar<T: Real>(c: &mut Criterion, scalar: &str) {
    let water = common::water::<T>();
    for model in common::models::<T>(true) {
        let poses = common::poses(&model.mesh);
        let mut group = c.benchmark_group(format!("{}/{scalar}", model.name));
        group.throughput(Throughput::Elements(poses.len() as u64));
        if model.mesh.triangle_count() > 100_000 {
            group.sample_size(10);
        }
        for method in Method::ALL {
            group.bench_function(BenchmarkId::new("serial", method), |b| {
                b.iter(|| {
                    for pose in &poses {
                        black_box(
                            model
                                .mesh
                                .buoyancy(black_box(pose), &water, method)
                                .unwrap(),
                        );
                    }
                })
            });
            #[cfg(feature = "rayon")]
            group.bench_function(BenchmarkId::new("rayon", method), |b| {
                b.iter(|| {
                    for pose in &poses {
                        black_box(
                            model
                                .mesh
                                .buoyancy(black_box(pose), &water, Query::new(method).in_parallel())
                                .unwrap(),
                        );
                    }
                })
            });
        }
        group.finish();
    }
}

fn methods(c: &mut Criterion) {
    bench_scalar::<f64>(c, "f64");
    bench_scalar::<f32>(c, "f32");
}

criterion_group!(benches, methods);
criterion_main!(benches);
