//! Cost against mesh size, scan against hierarchy: procedural torus knots from 32 to 10⁶
//! triangles under the paper's protocol (100 poses from almost dry to almost submerged), the
//! mean time per `Exact` and `Exact Surface` evaluation (f64, one thread), with the hierarchy's
//! build time and memory. Prints a Markdown table and writes `benches/scaling.csv` and
//! `benches/scaling.png` (log-log: time per evaluation against triangles; red the scan, blue the
//! hierarchy, thick lines `Exact` and thin lines `Exact Surface`, grey lines at every decade).
//!
//! `cargo bench --bench scaling`
//!
//! With `BUOYANCY_SCALING_REPLOT=1` it measures nothing: it redraws `benches/scaling.png` from
//! the rows of `benches/scaling.csv` (to restyle the plot without the minutes of measurement).
//! With `BUOYANCY_SCALING_MEMORY=1` it times nothing either: it prints the hierarchy's bytes
//! per triangle at every size.

mod common;
#[path = "common/plot_font.rs"]
mod plot_font;

use buoyancy::query::Query;
use std::hint::black_box;
use std::time::Instant;

use buoyancy::{Mesh, Method, Traversal, mesh::primitives};
use plot_font::FAMILY;
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
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("benches");
    if std::env::var_os("BUOYANCY_SCALING_REPLOT").is_some_and(|v| !v.is_empty() && v != "0") {
        let rows = read_csv(&dir.join("scaling.csv"))?;
        plot(&rows, &dir.join("scaling.png"))?;
        eprintln!(
            "redrew {} from {}",
            dir.join("scaling.png").display(),
            dir.join("scaling.csv").display()
        );
        return Ok(());
    }
    let memory_only =
        std::env::var_os("BUOYANCY_SCALING_MEMORY").is_some_and(|v| !v.is_empty() && v != "0");
    let water = common::water::<f64>();
    // (segments, sides): 2·segments·sides triangles.
    let sizes = [
        (4, 4),
        (8, 4),
        (16, 4),
        (32, 4),
        (64, 4),
        (64, 8),
        (120, 13),
        (200, 25),
        (346, 43),
        (632, 79),
        (1096, 137),
        (2000, 250),
    ];
    let mut rows = Vec::new();
    for (segments, sides) in sizes {
        let (v, t) = primitives::torus_knot::<f64>(2, 3, 1.0, 0.25, segments, sides).unwrap();
        if memory_only {
            let mesh = Mesh::new(v, t)?;
            let bytes = mesh.hierarchy_bytes() as f64 / mesh.triangle_count() as f64;
            println!(
                "{} triangles: {bytes:.1} hierarchy bytes per triangle",
                mesh.triangle_count()
            );
            continue;
        }
        let started = Instant::now();
        let mesh = Mesh::new(v, t)?;
        let build_ms = started.elapsed().as_secs_f64() * 1e3;
        let poses = common::poses(&mesh);
        let waterline = poses
            .iter()
            .map(|p| {
                mesh.buoyancy(p, &water, Method::Exact)
                    .map(|b| b.partially_submerged as f64)
            })
            .sum::<Result<f64, _>>()?
            / poses.len() as f64;
        let time = |method, traversal| {
            common::microseconds(poses.len(), || {
                for pose in &poses {
                    black_box(
                        mesh.buoyancy(
                            black_box(pose),
                            &water,
                            Query::new(method).with_traversal(traversal),
                        )
                        .unwrap(),
                    );
                }
            })
        };
        let both = |method| {
            [Traversal::Scan, Traversal::Hierarchy].map(|traversal| time(method, traversal))
        };
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
    if memory_only {
        return Ok(());
    }

    println!(
        "| triangles | waterline triangles (mean) | Exact, scan µs | Exact, hierarchy µs | scan / hierarchy | Exact Surface, scan µs | Exact Surface, hierarchy µs | scan / hierarchy | build ms (validation + precomputation + hierarchy) | hierarchy bytes per triangle |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let mut csv = String::from(
        "triangles,waterline,exact_scan_us,exact_hierarchy_us,surface_scan_us,surface_hierarchy_us,build_ms,hierarchy_bytes_per_triangle\n",
    );
    for r in &rows {
        let ([es, eh], [ss, sh]) = (r.exact, r.surface);
        println!(
            "| {} | {:.1} | {es:.2} | {eh:.2} | {:.1}× | {ss:.2} | {sh:.2} | {:.1}× | {:.2} | {:.1} |",
            r.triangles,
            r.waterline,
            es / eh,
            ss / sh,
            r.build_ms,
            r.bytes_per_triangle
        );
        csv += &format!(
            "{},{},{es},{eh},{ss},{sh},{},{}\n",
            r.triangles, r.waterline, r.build_ms, r.bytes_per_triangle
        );
    }
    std::fs::write(dir.join("scaling.csv"), csv)?;
    let png = dir.join("scaling.png");
    plot(&rows, &png)?;
    eprintln!(
        "wrote {} and {}",
        dir.join("scaling.csv").display(),
        png.display()
    );
    Ok(())
}

/// The rows of a `scaling.csv` written by [`main`], its columns found by name.
fn read_csv(path: &std::path::Path) -> Result<Vec<Row>, Box<dyn std::error::Error>> {
    let text = std::fs::read_to_string(path)?;
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or_default().split(',').collect();
    let column = |name: &str| {
        header.iter().position(|h| *h == name).ok_or_else(|| {
            format!("{} has no column {name}: written by an older version? Run `cargo bench --bench scaling`", path.display())
        })
    };
    let names = [
        "triangles",
        "waterline",
        "exact_scan_us",
        "exact_hierarchy_us",
        "surface_scan_us",
        "surface_hierarchy_us",
        "build_ms",
        "hierarchy_bytes_per_triangle",
    ];
    let columns = names.map(column);
    let columns: Vec<usize> = columns.into_iter().collect::<Result<_, _>>()?;
    let mut rows = Vec::new();
    for line in lines.filter(|l| !l.trim().is_empty()) {
        let fields: Vec<&str> = line.split(',').collect();
        let value = |k: usize| -> Result<f64, Box<dyn std::error::Error>> {
            let field = fields
                .get(columns[k])
                .ok_or_else(|| format!("short line in {}: {line}", path.display()))?;
            Ok(field.trim().parse::<f64>()?)
        };
        rows.push(Row {
            triangles: value(0)? as usize,
            waterline: value(1)?,
            exact: [value(2)?, value(3)?],
            surface: [value(4)?, value(5)?],
            build_ms: value(6)?,
            bytes_per_triangle: value(7)?,
        });
    }
    Ok(rows)
}

/// Log-log: µs per evaluation against triangles (both axes in decades, `log10` of the value),
/// with the legend in the empty top left corner.
fn plot(rows: &[Row], png: &std::path::Path) -> Result<(), Box<dyn std::error::Error>> {
    const X: std::ops::Range<f64> = 1.0..6.2;
    const Y: std::ops::Range<f64> = -1.5..4.5;
    plot_font::register()?;
    let root = BitMapBackend::new(png, (1000, 680)).into_drawing_area();
    root.fill(&WHITE)?;
    // The top margin keeps the title's ascenders in the image (plotters' ab_glyph renderer
    // draws top-anchored text a little above its anchor).
    let root = root
        .margin(10, 0, 0, 0)
        .titled("Cost per evaluation against mesh size", (FAMILY, 30))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Exact and Exact Surface on torus knots; f64, one thread, 100 poses",
            (FAMILY, 20),
        )
        .margin_right(36)
        .margin_left(10)
        .margin_bottom(10)
        .x_label_area_size(64)
        .y_label_area_size(110)
        .build_cartesian_2d(X, Y)?;
    let time = ["0.1 µs", "1 µs", "10 µs", "100 µs", "1 ms", "10 ms"];
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(RGBColor(215, 215, 215))
        .x_labels(6)
        .y_labels(7)
        .x_desc("triangles")
        .y_desc("time per evaluation")
        .label_style((FAMILY, 18))
        .axis_desc_style((FAMILY, 20))
        .x_label_formatter(&|decade| {
            if decade.fract() != 0.0 {
                return String::new();
            }
            let exponent: String = format!("{decade:.0}").chars().map(superscript).collect();
            format!("10{exponent}")
        })
        .y_label_formatter(&|decade| {
            if decade.fract() != 0.0 {
                return String::new();
            }
            let k = *decade as i32 + 1;
            usize::try_from(k)
                .ok()
                .and_then(|k| time.get(k))
                .map_or_else(String::new, |label| label.to_string())
        })
        .draw()?;

    let series = [(false, 3, "Exact"), (true, 1, "Exact Surface")];
    let traversals = [(0, RED, "scan"), (1, BLUE, "hierarchy")];
    for (surface, width, method) in series {
        for (traversal, colour, traversal_name) in traversals {
            let points = rows.iter().map(|r| {
                let t = if surface {
                    r.surface[traversal]
                } else {
                    r.exact[traversal]
                };
                ((r.triangles as f64).log10(), t.log10())
            });
            chart
                .draw_series(LineSeries::new(points.clone(), colour.stroke_width(width)))?
                .label(format!("{method}, {traversal_name}"))
                .legend(move |(x, y)| {
                    EmptyElement::at((x, y))
                        + PathElement::new([(0, 0), (28, 0)], colour.stroke_width(width))
                        + Circle::new((14, 0), width + 1, colour.filled())
                });
            chart.draw_series(points.map(|p| Circle::new(p, width + 1, colour.filled())))?;
        }
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .margin(16)
        .legend_area_size(40)
        .label_font((FAMILY, 18))
        .background_style(WHITE)
        .border_style(RGBColor(215, 215, 215))
        .draw()?;
    root.present()?;
    Ok(())
}

/// The superscript of a decimal digit (other characters unchanged).
fn superscript(digit: char) -> char {
    match digit {
        '0' => '⁰',
        '1' => '¹',
        '2' => '²',
        '3' => '³',
        '4' => '⁴',
        '5' => '⁵',
        '6' => '⁶',
        '7' => '⁷',
        '8' => '⁸',
        '9' => '⁹',
        c => c,
    }
}
