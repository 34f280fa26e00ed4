//! Prints the paper's Table 1 with this library's figures beside it, and writes it, with a
//! description of the machine, between the markers of `benches/RESULTS.md`.
//!
//! `cargo bench --bench table --features rayon`
//!
//! Each figure is the mean time of one evaluation over the paper's 100 poses (from almost dry to
//! almost submerged), the median of 7 batches of at least 50 ms.

mod common;

use buoyancy::query::Query;
use std::fmt::Write as _;
use std::hint::black_box;

use buoyancy::{Method, Real, Traversal};

const BEGIN: &str = "<!-- table:begin (written by `cargo bench --bench table`) -->";
const END: &str = "<!-- table:end -->";

/// How the timed evaluations run.
#[derive(Clone, Copy, PartialEq)]
enum Mode {
    /// `Mesh::buoyancy`: the default traversal (the hierarchy).
    Default,
    /// One thread, every triangle (`Traversal::Scan`).
    Scan,
    /// `Query::in_parallel`: the default traversal, its subtrees on rayon's pool.
    #[cfg_attr(not(feature = "rayon"), allow(dead_code))]
    Parallel,
    /// `Query::in_parallel` on `Traversal::Scan`: every triangle, in parallel chunks.
    #[cfg_attr(not(feature = "rayon"), allow(dead_code))]
    ParallelScan,
}

/// µs per evaluation of every method on every model.
fn measure<T: Real>(models: &[common::Model<T>], mode: Mode) -> Vec<[f64; 5]> {
    let water = common::water::<T>();
    models
        .iter()
        .map(|model| {
            let poses = common::poses(&model.mesh);
            Method::ALL.map(|method| {
                common::microseconds(poses.len(), || {
                    for pose in &poses {
                        let pose = black_box(pose);
                        let result = match mode {
                            Mode::Default => model.mesh.buoyancy(pose, &water, method),
                            Mode::Scan => model.mesh.buoyancy(
                                pose,
                                &water,
                                Query::new(method).with_traversal(Traversal::Scan),
                            ),
                            #[cfg(feature = "rayon")]
                            Mode::Parallel => {
                                model
                                    .mesh
                                    .buoyancy(pose, &water, Query::new(method).in_parallel())
                            }
                            #[cfg(feature = "rayon")]
                            Mode::ParallelScan => model.mesh.buoyancy(
                                pose,
                                &water,
                                Query::new(method)
                                    .with_traversal(Traversal::Scan)
                                    .in_parallel(),
                            ),
                            #[cfg(not(feature = "rayon"))]
                            Mode::Parallel | Mode::ParallelScan => {
                                unreachable!("parallel figures need --features rayon")
                            }
                        };
                        black_box(result.unwrap());
                    }
                })
            })
        })
        .collect()
}

fn method_label(m: Method) -> &'static str {
    match m {
        Method::Fast => "Fast",
        Method::Improved => "Improved",
        Method::Exact => "Exact",
        Method::FastSurface => "Fast Surface",
        Method::ExactSurface => "Exact Surface",
    }
}

fn table(names: &[String], figures: &[[f64; 5]], paper: Option<&[[f64; 5]]>) -> String {
    let mut out = String::from("| |");
    for name in names {
        let _ = write!(out, " {name} |");
    }
    out += "\n|---|";
    out += &"---|".repeat(names.len());
    out += "\n";
    for (k, method) in Method::ALL.iter().enumerate() {
        let _ = write!(out, "| {} |", method_label(*method));
        for (i, f) in figures.iter().enumerate() {
            match paper {
                Some(p) => {
                    let ms = p[i][k];
                    let _ = write!(out, " {:.2} µs ({ms} ms, {:.0}×) |", f[k], ms * 1e3 / f[k]);
                }
                None => {
                    let _ = write!(out, " {:.2} µs |", f[k]);
                }
            }
        }
        out += "\n";
    }
    out
}

fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism()
        .map(|n| n.get())
        .unwrap_or(1);
    let rustc =
        std::process::Command::new(std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into()))
            .arg("--version")
            .output()
            .ok()
            .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
            .unwrap_or_else(|| "rustc (unknown version)".into());
    format!(
        "{cpu}, {cores} cores available; {rustc}; {} {}",
        std::env::consts::OS,
        std::env::consts::ARCH
    )
}

fn main() {
    // `cargo bench` passes `--bench`; ignore arguments.
    let models64 = common::models::<f64>(true);
    let models32 = common::models::<f32>(true);
    let (paper_models, large): (Vec<_>, Vec<_>) = models64
        .iter()
        .enumerate()
        .partition(|(_, m)| m.paper_ms.is_some());
    let paper_idx: Vec<usize> = paper_models.iter().map(|(i, _)| *i).collect();
    let large_idx: Vec<usize> = large.iter().map(|(i, _)| *i).collect();

    let serial64 = measure(&models64, Mode::Default);
    let serial32 = measure(&models32, Mode::Default);
    let names = |idx: &[usize]| {
        idx.iter()
            .map(|&i| models64[i].name.clone())
            .collect::<Vec<_>>()
    };
    let pick = |f: &[[f64; 5]], idx: &[usize]| idx.iter().map(|&i| f[i]).collect::<Vec<_>>();

    let mut report = format!("Machine: {}\n\n", machine());
    report += "Mean time per evaluation over the paper's 100 poses, one thread, f64, `Mesh::buoyancy` (the default traversal: the hierarchy, from 128 triangles); the paper's figure and our speed-up in parentheses:\n\n";
    let paper: Vec<[f64; 5]> = paper_idx
        .iter()
        .map(|&i| models64[i].paper_ms.unwrap())
        .collect();
    report += &table(
        &names(&paper_idx),
        &pick(&serial64, &paper_idx),
        Some(&paper),
    );
    report += "\nThe same in f32:\n\n";
    report += &table(&names(&paper_idx), &pick(&serial32, &paper_idx), None);
    if !large_idx.is_empty() {
        report += "\nThe procedural mesh of 10⁶ triangles, f64 and f32, one thread:\n\n";
        let both: Vec<[f64; 5]> = large_idx
            .iter()
            .flat_map(|&i| [serial64[i], serial32[i]])
            .collect();
        let labels: Vec<String> = large_idx
            .iter()
            .flat_map(|&i| {
                [
                    format!("{} f64", models64[i].name),
                    format!("{} f32", models64[i].name),
                ]
            })
            .collect();
        report += &table(&labels, &both, None);
    }
    let all: Vec<usize> = paper_idx.iter().chain(&large_idx).copied().collect();
    let mut labels = names(&paper_idx);
    labels.extend(names(&large_idx));
    let scan64 = measure(&models64, Mode::Scan);
    report += "\nEvery triangle visited (`Traversal::Scan`), one thread, f64:\n\n";
    report += &table(&labels, &pick(&scan64, &all), None);
    #[cfg(feature = "rayon")]
    {
        let threads = rayon::current_num_threads();
        let parallel = |mode: Mode, serial: &[[f64; 5]], title: String| {
            let timed = measure(&models64, mode);
            let mut out = format!("\n{title}\n\n") + &table(&labels, &pick(&timed, &all), None);
            for (k, method) in Method::ALL.iter().enumerate() {
                let speedups: Vec<String> = all
                    .iter()
                    .map(|&i| format!("{:.2}×", serial[i][k] / timed[i][k]))
                    .collect();
                let _ = writeln!(
                    out,
                    "| speed-up, {} | {} |",
                    method_label(*method),
                    speedups.join(" | ")
                );
            }
            out
        };
        report += &parallel(
            Mode::Parallel,
            &serial64,
            format!(
                "The default traversal split across {threads} threads by rayon (`Query::in_parallel`: the hierarchy's halves from 100,000 triangles, so the paper's models run on one thread), f64, and its speed-up over `Mesh::buoyancy`:"
            ),
        );
        report += &parallel(
            Mode::ParallelScan,
            &scan64,
            format!(
                "The scan split across {threads} threads (`Query::in_parallel` on `Traversal::Scan`: chunks of 4,096 triangles), f64, and its speed-up over the one-thread scan:"
            ),
        );
    }
    #[cfg(not(feature = "rayon"))]
    {
        report += "\n(Run with `--features rayon` for the parallel figures.)\n";
    }

    println!("{report}");
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/RESULTS.md");
    let old = std::fs::read_to_string(&path).unwrap_or_default();
    let new = match (old.find(BEGIN), old.find(END)) {
        (Some(b), Some(e)) if b < e => format!("{}{BEGIN}\n{report}{}", &old[..b], &old[e..]),
        _ => format!("{old}\n{BEGIN}\n{report}{END}\n"),
    };
    std::fs::write(&path, new).expect("writable benches/RESULTS.md");
    eprintln!("written to {}", path.display());
}
