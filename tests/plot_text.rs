//! The plots' bitmap font (`benches/common/plot_text.rs`, shared by the `floating` example
//! and the `scaling` benchmark, whose own tests `cargo test` does not run).

#[path = "../benches/common/plot_text.rs"]
mod plot_text;

use plot_text::*;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

#[test]
fn glyphs_are_well_formed() {
    for (i, (c, rows)) in GLYPHS.iter().enumerate() {
        assert!(
            (HEIGHT as usize..=(HEIGHT + DESCENT) as usize).contains(&rows.len()),
            "{c:?}: {} rows",
            rows.len()
        );
        let w = rows[0].len();
        assert!((1..=5).contains(&w), "{c:?}: width {w}");
        for row in *rows {
            assert_eq!(row.chars().count(), w, "{c:?}: row {row:?}");
            assert!(
                row.chars().all(|b| b == '#' || b == '.'),
                "{c:?}: row {row:?}"
            );
        }
        assert!(
            c.is_whitespace() || rows.iter().any(|r| r.contains('#')),
            "{c:?} is blank"
        );
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
    assert_eq!(
        wrap("torus knot (procedural), s = 0.3", w),
        ["torus knot", "(procedural),", "s = 0.3"]
    );
    assert_eq!(wrap("cube, s = 0.1", 1000), ["cube, s = 0.1"]);
    assert_eq!(wrap("", 10), [""]);
}

/// The ink drawn fills exactly the measured box: from the anchor, `width` across and
/// `HEIGHT` down (plus `DESCENT` for descenders), upright and turned.
#[test]
fn ink_fills_the_measured_box() {
    let (w, h) = (200u32, 200u32);
    for (text, up, descends) in [
        ("Hello, 10⁶ µs", false, true),
        ("EH", false, false),
        ("Tilt (°)", true, false),
    ] {
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
        let (x0, x1) = (
            ink.iter().map(|p| p.0).min().unwrap(),
            ink.iter().map(|p| p.0).max().unwrap() + 1,
        );
        let (y0, y1) = (
            ink.iter().map(|p| p.1).min().unwrap(),
            ink.iter().map(|p| p.1).max().unwrap() + 1,
        );
        let (along, across) = (
            width(text) * 2,
            (HEIGHT + if descends { DESCENT } else { 0 }) * 2,
        );
        if up {
            assert_eq!(
                (x0, x1),
                (100 - HEIGHT * 2, 100 - HEIGHT * 2 + across),
                "{text}"
            );
            assert_eq!((y0, y1), (100 - along / 2, 100 + along / 2), "{text}");
        } else {
            assert_eq!((x0, x1), (100 - along / 2, 100 + along / 2), "{text}");
            assert_eq!(
                (y0, y1),
                (100 - HEIGHT * 2, 100 - HEIGHT * 2 + across),
                "{text}"
            );
        }
    }
}
