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

mod common;
#[path = "common/plot_text.rs"]
mod plot_text;

use std::hint::black_box;
use std::time::Instant;

use buoyancy::{Mesh, Method, Traversal, shape};
use plot_text::{Style, draw};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

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
        let (v, t) = shape::torus_knot::<f64>(2, 3, 1.0, 0.25, segments, sides).unwrap();
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
                        mesh.buoyancy_with(black_box(pose), &water, method, traversal)
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

/// Log-log: µs per evaluation against triangles, with the built-in bitmap font for the text.
fn plot(rows: &[Row], png: &std::path::Path) -> Result<(), Box<dyn std::error::Error>> {
    const X: std::ops::Range<f64> = 1.0..6.2;
    const Y: std::ops::Range<f64> = -1.5..4.5;
    let grey = RGBColor(215, 215, 215);
    let text = Style::new(2, BLACK);
    let root = BitMapBackend::new(png, (1000, 680)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .margin_top(96)
        .margin_right(36)
        .margin_bottom(78)
        .margin_left(124)
        .build_cartesian_2d(X, Y)?;
    let (x0, y0) = chart.backend_coord(&(X.start, Y.end));
    let (x1, y1) = chart.backend_coord(&(X.end, Y.start));

    draw(
        &root,
        "Cost per evaluation against mesh size",
        (x0, 14),
        Style::new(3, BLACK),
    )?;
    draw(
        &root,
        "Exact and Exact Surface on torus knots; f64, one thread, 100 poses",
        (x0, 50),
        text,
    )?;

    for decade in 1..=6 {
        let x = decade as f64;
        chart.draw_series(LineSeries::new([(x, Y.start), (x, Y.end)], grey))?;
        let (px, _) = chart.backend_coord(&(x, Y.start));
        root.draw(&PathElement::new([(px, y1), (px, y1 + 5)], BLACK))?;
        let exponent: String = decade.to_string().chars().map(superscript).collect();
        draw(
            &root,
            &format!("10{exponent}"),
            (px, y1 + 12),
            text.anchor(HPos::Center, VPos::Top),
        )?;
    }
    draw(
        &root,
        "triangles",
        ((x0 + x1) / 2, y1 + 44),
        text.anchor(HPos::Center, VPos::Top),
    )?;
    let time = ["0.1 µs", "1 µs", "10 µs", "100 µs", "1 ms", "10 ms"];
    for (decade, label) in (-1..=4).zip(time) {
        let y = decade as f64;
        chart.draw_series(LineSeries::new([(X.start, y), (X.end, y)], grey))?;
        let (_, py) = chart.backend_coord(&(X.start, y));
        root.draw(&PathElement::new([(x0 - 5, py), (x0, py)], BLACK))?;
        draw(
            &root,
            label,
            (x0 - 10, py),
            text.anchor(HPos::Right, VPos::Center),
        )?;
    }
    draw(
        &root,
        "time per evaluation",
        (x0 - 112, (y0 + y1) / 2),
        text.anchor(HPos::Center, VPos::Top).up(),
    )?;

    let series = [(false, 3, "Exact"), (true, 1, "Exact Surface")];
    let traversals = [(0, RED, "scan"), (1, BLUE, "hierarchy")];
    for (surface, width, _) in series {
        for (traversal, colour, _) in traversals {
            let points = rows.iter().map(|r| {
                let t = if surface {
                    r.surface[traversal]
                } else {
                    r.exact[traversal]
                };
                ((r.triangles as f64).log10(), t.log10())
            });
            chart.draw_series(LineSeries::new(points.clone(), colour.stroke_width(width)))?;
            chart.draw_series(points.map(|p| Circle::new(p, width + 1, colour.filled())))?;
        }
    }
    root.draw(&Rectangle::new([(x0, y0), (x1, y1)], BLACK))?;

    // The legend, in the empty top left corner.
    let (lx, ly) = (x0 + 16, y0 + 16);
    root.draw(&Rectangle::new(
        [(lx, ly), (lx + 330, ly + 4 * 28 + 16)],
        WHITE.filled(),
    ))?;
    root.draw(&Rectangle::new(
        [(lx, ly), (lx + 330, ly + 4 * 28 + 16)],
        grey,
    ))?;
    let mut y = ly + 14;
    for (_, width, method) in series {
        for (_, colour, traversal) in traversals {
            root.draw(&PathElement::new(
                [(lx + 12, y + 7), (lx + 52, y + 7)],
                colour.stroke_width(width),
            ))?;
            root.draw(&Circle::new((lx + 32, y + 7), width + 1, colour.filled()))?;
            draw(&root, &format!("{method}, {traversal}"), (lx + 66, y), text)?;
            y += 28;
        }
    }
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
