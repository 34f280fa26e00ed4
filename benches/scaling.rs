//! Cost against mesh size, scan against hierarchy: procedural torus knots from 32 to 10⁶
//! triangles under the paper's protocol (100 poses from almost dry to almost submerged), the
//! mean time per `Exact` and `Exact Surface` evaluation (f64, one thread), with the hierarchy's
//! build time and memory. Prints a Markdown table and writes `benches/scaling.csv` and
//! `benches/scaling.png` (log-log: time per evaluation against triangles; red the scan, blue the
//! hierarchy, thick lines `Exact` and thin lines `Exact Surface`, grey lines at every decade).
//!
//! `cargo bench --bench scaling`

mod common;

use std::hint::black_box;
use std::time::Instant;

use buoyancy::{shape, Mesh, Method, Traversal};
use plotters::prelude::*;


struct Row {
    triangles: usize,
    waterline: f64,
    /// µs per evaluation, scan then hierarchy, for `Exact` and `Exact Surface`.
    exact: [f64; 2],
    surface: [f64; 2],
    build_ms: f64,
    bytes_per_triangle: f64,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let water = common::water::<f64>();
    // (segments, sides): 2·segments·sides triangles.
    let sizes = [
        (4, 4), (8, 4), (16, 4), (32, 4), (64, 4), (64, 8), (120, 13), (200, 25), (346, 43),
        (632, 79), (1096, 137), (2000, 250),
    ];
    let mut rows = Vec::new();
    for (segments, sides) in sizes {
        let (v, t) = shape::torus_knot::<f64>(2, 3, 1.0, 0.25, segments, sides);
        let started = Instant::now();
        let mesh = Mesh::new(v, t)?;
        let build_ms = started.elapsed().as_secs_f64() * 1e3;
        let poses = common::poses(&mesh);
        let waterline = poses
            .iter()
            .map(|p| mesh.buoyancy(p, &water, Method::Exact).map(|b| b.partially_submerged as f64))
            .sum::<Result<f64, _>>()?
            / poses.len() as f64;
        let time = |method, traversal| {
            common::microseconds(poses.len(), || {
                for pose in &poses {
                    black_box(mesh.buoyancy_with(black_box(pose), &water, method, traversal).unwrap());
                }
            })
        };
        let both = |method| [Traversal::Scan, Traversal::Hierarchy].map(|traversal| time(method, traversal));
        let row = Row {
            triangles: mesh.triangle_count(),
            waterline,
            exact: both(Method::Exact),
            surface: both(Method::ExactSurface),
            build_ms,
            bytes_per_triangle: mesh.hierarchy_bytes() as f64 / mesh.triangle_count() as f64,
        };
        eprintln!("{} triangles done", row.triangles);
        rows.push(row);
    }

    println!("| triangles | waterline triangles (mean) | Exact, scan µs | Exact, hierarchy µs | scan / hierarchy | Exact Surface, scan µs | Exact Surface, hierarchy µs | scan / hierarchy | build ms (validation + precomputation + hierarchy) | hierarchy bytes per triangle |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let mut csv = String::from(
        "triangles,waterline,exact_scan_us,exact_hierarchy_us,surface_scan_us,surface_hierarchy_us,build_ms,hierarchy_bytes_per_triangle\n",
    );
    for r in &rows {
        let ([es, eh], [ss, sh]) = (r.exact, r.surface);
        println!(
            "| {} | {:.1} | {es:.2} | {eh:.2} | {:.1}× | {ss:.2} | {sh:.2} | {:.1}× | {:.2} | {:.1} |",
            r.triangles, r.waterline, es / eh, ss / sh, r.build_ms, r.bytes_per_triangle
        );
        csv += &format!("{},{},{es},{eh},{ss},{sh},{},{}\n", r.triangles, r.waterline, r.build_ms, r.bytes_per_triangle);
    }
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("benches");
    std::fs::write(dir.join("scaling.csv"), csv)?;

    let png = dir.join("scaling.png");
    let root = BitMapBackend::new(&png, (900, 600)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root).margin(30).build_cartesian_2d(1.0f64..6.2, -1.5f64..4.5)?;
    for decade in 1..=6 {
        let x = decade as f64;
        chart.draw_series(LineSeries::new([(x, -1.5), (x, 4.5)], RGBColor(215, 215, 215)))?;
    }
    for decade in -1..=4 {
        let y = decade as f64;
        chart.draw_series(LineSeries::new([(1.0, y), (6.2, y)], RGBColor(215, 215, 215)))?;
    }
    for (surface, width) in [(false, 3), (true, 1)] {
        for (traversal, colour) in [(0, RED), (1, BLUE)] {
            let points = rows.iter().map(|r| {
                let t = if surface { r.surface[traversal] } else { r.exact[traversal] };
                ((r.triangles as f64).log10(), t.log10())
            });
            chart.draw_series(LineSeries::new(points.clone(), colour.stroke_width(width)))?;
            chart.draw_series(points.map(|p| Circle::new(p, width + 1, colour.filled())))?;
        }
    }
    root.present()?;
    eprintln!("wrote {} and {}", dir.join("scaling.csv").display(), png.display());
    Ok(())
}
