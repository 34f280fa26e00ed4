//! Text for plots drawn without a font: a built-in 5×7 bitmap font (with two rows of
//! descenders) whose pixels are drawn as squares of `scale` × `scale` backend pixels.
//!
//! plotters is built here without its font features (no font can be relied on where the plots
//! are drawn), so the example and the benchmarks label their plots with this module. It is
//! shared by path: `#[path = "…/benches/common/plot_text.rs"] mod plot_text;`.
//!
//! The glyphs cover printable ASCII letters and digits, the punctuation the labels use
//! (` .,:;-+/()[]=%'^_<>`), and `µ ρ × − ° · ⁰–⁹ ⁻` (superscripts for exponents: `10⁶`). Any
//! other character is drawn as a hollow box.
#![allow(dead_code)]

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

/// Height of capitals and digits in font pixels; descenders reach [`DESCENT`] rows below.
pub const HEIGHT: i32 = 7;
/// Rows below the baseline (g, j, p, q, y, µ, comma).
pub const DESCENT: i32 = 2;
/// Columns between two glyphs.
pub const SPACING: i32 = 1;

/// How to draw a string: pixel size, colour, which point of the text is placed at the given
/// position, and whether the text reads left to right or bottom to top.
#[derive(Clone, Copy)]
pub struct Style {
    pub scale: i32,
    pub colour: RGBColor,
    /// Along the text: its start, middle or end.
    pub h: HPos,
    /// Across the text: the top of the capitals, their middle, or the baseline.
    pub v: VPos,
    /// Turned a quarter turn counter-clockwise (reads bottom to top; for y axis titles).
    pub up: bool,
}

impl Style {
    /// `scale` × `scale` pixels per font pixel, anchored at the top left.
    pub fn new(scale: i32, colour: RGBColor) -> Self {
        Style { scale, colour, h: HPos::Left, v: VPos::Top, up: false }
    }

    pub fn anchor(self, h: HPos, v: VPos) -> Self {
        Style { h, v, ..self }
    }

    pub fn up(self) -> Self {
        Style { up: true, ..self }
    }

    /// Width of `text` in backend pixels (its length along the text when turned).
    pub fn width(&self, text: &str) -> i32 {
        width(text) * self.scale
    }

    /// Height of capitals in backend pixels.
    pub fn height(&self) -> i32 {
        HEIGHT * self.scale
    }
}

/// Width of `text` in font pixels: the glyphs' widths with [`SPACING`] between them.
pub fn width(text: &str) -> i32 {
    let total: i32 = text.chars().map(|c| glyph(c).map_or(BOX[0].len(), |g| g[0].len()) as i32 + SPACING).sum();
    (total - SPACING).max(0)
}

/// `text` broken at spaces into lines at most `max` font pixels wide (a word wider than `max`
/// gets a line of its own).
pub fn wrap(text: &str, max: i32) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(line) if width(&format!("{line} {word}")) <= max => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

/// The rows of a character's glyph, top first: [`HEIGHT`] rows, or more with descenders.
pub fn glyph(c: char) -> Option<&'static [&'static str]> {
    GLYPHS.iter().find(|(g, _)| *g == c).map(|(_, rows)| *rows)
}

/// Draws `text` on `area` (pixel coordinates) with the point chosen by `style.h`/`style.v` at `at`.
pub fn draw<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    at: (i32, i32),
    style: Style,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let s = style.scale;
    // In the text's own frame: u along it, v downwards, both from the anchor.
    let u0 = match style.h {
        HPos::Left => 0,
        HPos::Center => width(text) * s / 2,
        HPos::Right => width(text) * s,
    };
    let v0 = match style.v {
        VPos::Top => 0,
        VPos::Center => HEIGHT * s / 2,
        VPos::Bottom => HEIGHT * s,
    };
    let mut column = 0;
    for c in text.chars() {
        let rows = glyph(c).unwrap_or(BOX);
        for (row, line) in rows.iter().enumerate() {
            for (col, bit) in line.bytes().enumerate() {
                if bit != b'#' {
                    continue;
                }
                let (u, v) = ((column + col as i32) * s - u0, row as i32 * s - v0);
                for du in 0..s {
                    for dv in 0..s {
                        let (u, v) = (u + du, v + dv);
                        let p = if style.up { (at.0 + v, at.1 - 1 - u) } else { (at.0 + u, at.1 + v) };
                        area.draw_pixel(p, &style.colour)?;
                    }
                }
            }
        }
        column += rows[0].len() as i32 + SPACING;
    }
    Ok(())
}

/// Drawn for characters without a glyph.
const BOX: &[&str] = &["#####", "#...#", "#...#", "#...#", "#...#", "#...#", "#####"];

/// `#` is ink. Every glyph has at least [`HEIGHT`] rows (row 6 is on the baseline), all rows
/// of one glyph have the same width, and rows past the seventh are descenders.
#[rustfmt::skip]
const GLYPHS: &[(char, &[&str])] = &[
    (' ', &["...", "...", "...", "...", "...", "...", "..."]),
    ('0', &[".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."]),
    ('1', &["..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."]),
    ('2', &[".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"]),
    ('3', &["#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."]),
    ('4', &["...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."]),
    ('5', &["#####", "#....", "####.", "....#", "....#", "#...#", ".###."]),
    ('6', &["..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."]),
    ('7', &["#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."]),
    ('8', &[".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."]),
    ('9', &[".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."]),
    ('A', &[".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"]),
    ('B', &["####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."]),
    ('C', &[".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."]),
    ('D', &["###..", "#..#.", "#...#", "#...#", "#...#", "#..#.", "###.."]),
    ('E', &["#####", "#....", "#....", "####.", "#....", "#....", "#####"]),
    ('F', &["#####", "#....", "#....", "####.", "#....", "#....", "#...."]),
    ('G', &[".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####"]),
    ('H', &["#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"]),
    ('I', &["###", ".#.", ".#.", ".#.", ".#.", ".#.", "###"]),
    ('J', &["..###", "...#.", "...#.", "...#.", "...#.", "#..#.", ".##.."]),
    ('K', &["#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"]),
    ('L', &["#....", "#....", "#....", "#....", "#....", "#....", "#####"]),
    ('M', &["#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"]),
    ('N', &["#...#", "#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#"]),
    ('O', &[".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."]),
    ('P', &["####.", "#...#", "#...#", "####.", "#....", "#....", "#...."]),
    ('Q', &[".###.", "#...#", "#...#", "#...#", "#.#.#", "#..#.", ".##.#"]),
    ('R', &["####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"]),
    ('S', &[".####", "#....", "#....", ".###.", "....#", "....#", "####."]),
    ('T', &["#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."]),
    ('U', &["#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."]),
    ('V', &["#...#", "#...#", "#...#", "#...#", "#...#", ".#.#.", "..#.."]),
    ('W', &["#...#", "#...#", "#...#", "#.#.#", "#.#.#", "#.#.#", ".#.#."]),
    ('X', &["#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"]),
    ('Y', &["#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#.."]),
    ('Z', &["#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"]),
    ('a', &[".....", ".....", ".###.", "....#", ".####", "#...#", ".####"]),
    ('b', &["#....", "#....", "####.", "#...#", "#...#", "#...#", "####."]),
    ('c', &["....", "....", ".###", "#...", "#...", "#...", ".###"]),
    ('d', &["....#", "....#", ".####", "#...#", "#...#", "#...#", ".####"]),
    ('e', &[".....", ".....", ".###.", "#...#", "#####", "#....", ".###."]),
    ('f', &["..##", ".#..", "###.", ".#..", ".#..", ".#..", ".#.."]),
    ('g', &[".....", ".....", ".####", "#...#", "#...#", "#...#", ".####", "....#", ".###."]),
    ('h', &["#....", "#....", "####.", "#...#", "#...#", "#...#", "#...#"]),
    ('i', &[".#.", "...", "##.", ".#.", ".#.", ".#.", "###"]),
    ('j', &["...#", "....", "..##", "...#", "...#", "...#", "...#", "#..#", ".##."]),
    ('k', &["#...", "#...", "#..#", "#.#.", "##..", "#.#.", "#..#"]),
    ('l', &["##.", ".#.", ".#.", ".#.", ".#.", ".#.", "###"]),
    ('m', &[".....", ".....", "##.#.", "#.#.#", "#.#.#", "#.#.#", "#.#.#"]),
    ('n', &[".....", ".....", "####.", "#...#", "#...#", "#...#", "#...#"]),
    ('o', &[".....", ".....", ".###.", "#...#", "#...#", "#...#", ".###."]),
    ('p', &[".....", ".....", "####.", "#...#", "#...#", "#...#", "####.", "#....", "#...."]),
    ('q', &[".....", ".....", ".####", "#...#", "#...#", "#...#", ".####", "....#", "....#"]),
    ('r', &[".....", ".....", "#.##.", "##..#", "#....", "#....", "#...."]),
    ('s', &[".....", ".....", ".####", "#....", ".###.", "....#", "####."]),
    ('t', &[".#..", ".#..", "###.", ".#..", ".#..", ".#..", "..##"]),
    ('u', &[".....", ".....", "#...#", "#...#", "#...#", "#..##", ".##.#"]),
    ('v', &[".....", ".....", "#...#", "#...#", "#...#", ".#.#.", "..#.."]),
    ('w', &[".....", ".....", "#...#", "#...#", "#.#.#", "#.#.#", ".#.#."]),
    ('x', &[".....", ".....", "#...#", ".#.#.", "..#..", ".#.#.", "#...#"]),
    ('y', &[".....", ".....", "#...#", "#...#", "#...#", "#...#", ".####", "....#", ".###."]),
    ('z', &[".....", ".....", "#####", "...#.", "..#..", ".#...", "#####"]),
    ('.', &[".", ".", ".", ".", ".", ".", "#"]),
    (',', &["..", "..", "..", "..", "..", ".#", ".#", "#."]),
    (':', &[".", ".", "#", ".", ".", ".", "#"]),
    (';', &["..", "..", ".#", "..", "..", "..", ".#", "#."]),
    ('\'', &["#", "#", ".", ".", ".", ".", "."]),
    ('-', &["....", "....", "....", "####", "....", "....", "...."]),
    ('_', &[".....", ".....", ".....", ".....", ".....", ".....", ".....", "#####"]),
    ('+', &[".....", "..#..", "..#..", "#####", "..#..", "..#..", "....."]),
    ('=', &[".....", ".....", "#####", ".....", "#####", ".....", "....."]),
    ('<', &["...#", "..#.", ".#..", "#...", ".#..", "..#.", "...#"]),
    ('>', &["#...", ".#..", "..#.", "...#", "..#.", ".#..", "#..."]),
    ('/', &["....#", "....#", "...#.", "..#..", ".#...", "#....", "#...."]),
    ('(', &["..#", ".#.", "#..", "#..", "#..", ".#.", "..#"]),
    (')', &["#..", ".#.", "..#", "..#", "..#", ".#.", "#.."]),
    ('[', &["###", "#..", "#..", "#..", "#..", "#..", "###"]),
    (']', &["###", "..#", "..#", "..#", "..#", "..#", "###"]),
    ('%', &["##...", "##..#", "...#.", "..#..", ".#...", "#..##", "...##"]),
    ('^', &["..#..", ".#.#.", "#...#", ".....", ".....", ".....", "....."]),
    ('−', &[".....", ".....", ".....", "#####", ".....", ".....", "....."]),
    ('×', &[".....", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "....."]),
    ('·', &[".", ".", ".", "#", ".", ".", "."]),
    ('°', &[".##.", "#..#", "#..#", ".##.", "....", "....", "...."]),
    ('ρ', &[".....", ".....", ".###.", "#...#", "#...#", "#...#", "####.", "#....", "#...."]),
    ('µ', &[".....", ".....", "#...#", "#...#", "#...#", "#..##", "###.#", "#....", "#...."]),
    ('⁰', &[".#.", "#.#", "#.#", "#.#", ".#.", "...", "..."]),
    ('¹', &[".#.", "##.", ".#.", ".#.", "###", "...", "..."]),
    ('²', &["##.", "..#", ".#.", "#..", "###", "...", "..."]),
    ('³', &["##.", "..#", ".#.", "..#", "##.", "...", "..."]),
    ('⁴', &["#.#", "#.#", "###", "..#", "..#", "...", "..."]),
    ('⁵', &["###", "#..", "##.", "..#", "##.", "...", "..."]),
    ('⁶', &[".##", "#..", "##.", "#.#", ".#.", "...", "..."]),
    ('⁷', &["###", "..#", ".#.", ".#.", ".#.", "...", "..."]),
    ('⁸', &[".#.", "#.#", ".#.", "#.#", ".#.", "...", "..."]),
    ('⁹', &[".#.", "#.#", ".##", "..#", "##.", "...", "..."]),
    ('⁻', &["...", "...", "###", "...", "...", "...", "..."]),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn glyphs_are_well_formed() {
        for (i, (c, rows)) in GLYPHS.iter().enumerate() {
            assert!((HEIGHT as usize..=(HEIGHT + DESCENT) as usize).contains(&rows.len()), "{c:?}: {} rows", rows.len());
            let w = rows[0].len();
            assert!((1..=5).contains(&w), "{c:?}: width {w}");
            for row in *rows {
                assert_eq!(row.chars().count(), w, "{c:?}: row {row:?}");
                assert!(row.chars().all(|b| b == '#' || b == '.'), "{c:?}: row {row:?}");
            }
            assert!(c.is_whitespace() || rows.iter().any(|r| r.contains('#')), "{c:?} is blank");
            assert!(GLYPHS[..i].iter().all(|(d, _)| d != c), "{c:?} twice");
        }
    }

    #[test]
    fn covers_letters_and_digits() {
        for c in ('0'..='9').chain('A'..='Z').chain('a'..='z') {
            assert!(glyph(c).is_some(), "{c:?}");
        }
    }

    #[test]
    fn widths() {
        assert_eq!(width(""), 0);
        assert_eq!(width("1"), 5);
        assert_eq!(width("10"), 11);
        assert_eq!(width("10⁶ µs"), 5 + 1 + 5 + 1 + 3 + 1 + 3 + 1 + 5 + 1 + 5);
        assert_eq!(width("\u{2603}"), 5); // no glyph: a box as wide as a digit
    }

    #[test]
    fn wraps_at_spaces() {
        let w = width("torus knot");
        assert_eq!(wrap("torus knot (procedural), s = 0.3", w), ["torus knot", "(procedural),", "s = 0.3"]);
        assert_eq!(wrap("cube, s = 0.1", 1000), ["cube, s = 0.1"]);
        assert_eq!(wrap("", 10), [""]);
    }

    /// The ink drawn fills exactly the measured box: from the anchor, `width` across and
    /// `HEIGHT` down (plus `DESCENT` for descenders), upright and turned.
    #[test]
    fn ink_fills_the_measured_box() {
        let (w, h) = (200u32, 200u32);
        for (text, up, descends) in [("Hello, 10⁶ µs", false, true), ("EH", false, false), ("Tilt (°)", true, false)] {
            let mut buffer = vec![255u8; (w * h * 3) as usize];
            {
                let root = BitMapBackend::with_buffer(&mut buffer, (w, h)).into_drawing_area();
                let style = Style::new(2, BLACK).anchor(HPos::Center, VPos::Bottom);
                let style = if up { style.up() } else { style };
                draw(&root, text, (100, 100), style).unwrap();
                root.present().unwrap();
            }
            let ink: Vec<(i32, i32)> = (0..w * h)
                .filter(|i| buffer[*i as usize * 3] == 0)
                .map(|i| ((i % w) as i32, (i / w) as i32))
                .collect();
            let (x0, x1) = (ink.iter().map(|p| p.0).min().unwrap(), ink.iter().map(|p| p.0).max().unwrap() + 1);
            let (y0, y1) = (ink.iter().map(|p| p.1).min().unwrap(), ink.iter().map(|p| p.1).max().unwrap() + 1);
            let (along, across) = (width(text) * 2, (HEIGHT + if descends { DESCENT } else { 0 }) * 2);
            if up {
                assert_eq!((x0, x1), (100 - HEIGHT * 2, 100 - HEIGHT * 2 + across), "{text}");
                assert_eq!((y0, y1), (100 - along / 2, 100 + along / 2), "{text}");
            } else {
                assert_eq!((x0, x1), (100 - along / 2, 100 + along / 2), "{text}");
                assert_eq!((y0, y1), (100 - HEIGHT * 2, 100 - HEIGHT * 2 + across), "{text}");
            }
        }
    }
}
