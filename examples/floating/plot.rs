//! The demo's plot: the height of every body's center of mass and its tilt over time, with a
//! legend naming the bodies in the table's order.

use std::error::Error;
use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::plot_font::{self, FAMILY};
use crate::theory::corner_down_tilt;

/// One body's samples over time: (time s, height of the center of mass m, tilt °).
pub struct Track {
    name: String,
    samples: Vec<(f32, f32, f32)>,
}

impl Track {
    /// No samples yet; `name` labels the body in the legend.
    pub fn new(name: String) -> Self {
        Track {
            name,
            samples: Vec::new(),
        }
    }

    /// Adds the sample at time `t` (s): `height` (m) and `tilt` (°).
    pub fn push(&mut self, t: f32, height: f32, tilt: f32) {
        self.samples.push((t, height, tilt));
    }
}

const PALETTE: [(RGBColor, &str); 12] = [
    (RGBColor(230, 25, 75), "red"),
    (RGBColor(60, 180, 75), "green"),
    (RGBColor(0, 130, 200), "blue"),
    (RGBColor(245, 130, 48), "orange"),
    (RGBColor(145, 30, 180), "purple"),
    (RGBColor(70, 240, 240), "cyan"),
    (RGBColor(240, 50, 230), "magenta"),
    (RGBColor(128, 128, 0), "olive"),
    (RGBColor(0, 128, 128), "teal"),
    (RGBColor(170, 110, 40), "brown"),
    (RGBColor(128, 0, 0), "maroon"),
    (RGBColor(0, 0, 128), "navy"),
];

/// The names of the colours of the first `count` bodies (they repeat after 12).
pub fn colour_names(count: usize) -> Vec<&'static str> {
    (0..count).map(|i| PALETTE[i % PALETTE.len()].1).collect()
}

/// The image's size and the legend column's width, pixels.
const SIZE: (u32, u32) = (1400, 880);
const LEGEND_WIDTH: u32 = 280;
const GRID: RGBColor = RGBColor(225, 225, 225);

/// Draws `tracks` over `seconds` into the PNG at `path`: above, the height of each center of
/// mass (the black line is the water surface); below, the tilt, the angle between the vertical
/// and the body axis nearest to it; on the right, the legend.
pub fn plot(path: &Path, tracks: &[Track], seconds: f32) -> Result<(), Box<dyn Error>> {
    plot_font::register()?;
    let root = BitMapBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE)?;
    let (plots, legend) = root.split_horizontally(SIZE.0 - LEGEND_WIDTH);
    // The top margin keeps the title's ascenders in the image (plotters' ab_glyph renderer
    // draws top-anchored text a little above its anchor).
    let plots = plots.margin(10, 0, 0, 0).titled(
        &format!(
            "{} bodies dropped into still water in rapier3d, buoyancy by the Exact method",
            tracks.len()
        ),
        (FAMILY, 28),
    )?;
    let (top, bottom) = plots.split_vertically(plots.dim_in_pixel().1 / 2);

    let heights = tracks.iter().flat_map(|t| t.samples.iter().map(|s| s.1));
    let (lo, hi) = heights.fold((0.0f32, 0.0f32), |(lo, hi), h| (lo.min(h), hi.max(h)));
    panel(
        &top,
        "Height of each body's center of mass (black: the water surface)",
        "height (m)",
        tracks,
        seconds,
        (lo - 0.1)..(hi + 0.1),
        |s| s.1,
        &[(0.0, "")],
    )?;
    panel(
        &bottom,
        "Tilt: the angle between the vertical and the body axis nearest to it",
        "tilt to the nearest body axis (°)",
        tracks,
        seconds,
        -2.0..62.0,
        |s| s.2,
        &[
            (45.0, "45°: a cube edge down"),
            (corner_down_tilt() as f32, "54.7°: a cube corner down"),
        ],
    )?;
    draw_legend(&legend, tracks)?;
    root.present()?;
    Ok(())
}

/// One chart: `value` of every track against time, with a caption, axis titles and labels, and
/// black reference lines at `marks` (each labelled at its right end).
#[allow(clippy::too_many_arguments)]
fn panel(
    area: &DrawingArea<BitMapBackend, Shift>,
    caption: &str,
    y_title: &str,
    tracks: &[Track],
    seconds: f32,
    range: std::ops::Range<f32>,
    value: impl Fn(&(f32, f32, f32)) -> f32,
    marks: &[(f32, &str)],
) -> Result<(), Box<dyn Error>> {
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FAMILY, 21))
        .margin_top(6)
        .margin_right(30)
        .margin_left(10)
        .margin_bottom(6)
        .x_label_area_size(52)
        .y_label_area_size(86)
        .build_cartesian_2d(0.0f32..seconds, range)?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(GRID)
        .x_labels(9)
        .y_labels(8)
        .x_desc("time (s)")
        .y_desc(y_title)
        .label_style((FAMILY, 17))
        .axis_desc_style((FAMILY, 18))
        .x_label_formatter(&|t| format!("{t:.0}"))
        .y_label_formatter(&|v| format!("{v}").replace('-', "−"))
        .draw()?;
    for &(level, label) in marks {
        chart.draw_series(LineSeries::new(
            [(0.0, level), (seconds, level)],
            BLACK.stroke_width(1),
        ))?;
        if !label.is_empty() {
            chart.draw_series(std::iter::once(Text::new(
                label.to_string(),
                (seconds, level),
                (FAMILY, 15)
                    .into_font()
                    .color(&BLACK)
                    .pos(Pos::new(HPos::Right, VPos::Bottom)),
            )))?;
        }
    }
    for (i, track) in tracks.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()].0;
        chart.draw_series(LineSeries::new(
            track.samples.iter().map(|s| (s.0, value(s))),
            colour.stroke_width(2),
        ))?;
    }
    Ok(())
}

/// The legend: a line of each track's colour and its name, wrapped to the column.
fn draw_legend(
    area: &DrawingArea<BitMapBackend, Shift>,
    tracks: &[Track],
) -> Result<(), Box<dyn Error>> {
    let text = (FAMILY, 18).into_font().color(&BLACK);
    let width = area.dim_in_pixel().0 as i32 - 60;
    let (x, mut y) = (10, 70);
    for heading in ["body, relative density", "s = ρ body / ρ water"] {
        area.draw_text(heading, &text, (x, y))?;
        y += 24;
    }
    y += 12;
    for (i, track) in tracks.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()].0;
        area.draw(&PathElement::new(
            [(x, y + 10), (x + 28, y + 10)],
            colour.stroke_width(4),
        ))?;
        for line in wrap(area, &track.name, &text, width)? {
            area.draw_text(&line, &text, (x + 38, y))?;
            y += 22;
        }
        y += 6;
    }
    Ok(())
}

/// `text` broken at spaces into lines at most `width` pixels wide in `style` (a word wider
/// than that gets a line of its own).
fn wrap(
    area: &DrawingArea<BitMapBackend, Shift>,
    text: &str,
    style: &TextStyle,
    width: i32,
) -> Result<Vec<String>, Box<dyn Error>> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        if let Some(last) = lines.last_mut() {
            let joined = format!("{last} {word}");
            if area.estimate_text_size(&joined, style)?.0 as i32 <= width {
                *last = joined;
                continue;
            }
        }
        lines.push(word.to_string());
    }
    Ok(lines)
}
