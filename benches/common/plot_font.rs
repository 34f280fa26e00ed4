//! The font of the plots, so that they get text on a machine without any system font: Ubuntu
//! Light (Ubuntu Font Licence 1.0) as bundled by the `epaint_default_fonts` crate (egui's
//! default fonts), drawn by plotters' `ab_glyph` text renderer.
//!
//! Shared by path by the `floating` example and the `scaling` benchmark:
//! `#[path = "…/benches/common/plot_font.rs"] mod plot_font;`. Call [`register`] once before
//! drawing, then ask plotters for the family [`FAMILY`], e.g. `(FAMILY, 18).into_font()`.

use plotters::style::{FontStyle, register_font};

/// The font family the plots' text is drawn in.
pub const FAMILY: &str = "sans-serif";

/// Registers the bundled font as plotters' [`FAMILY`], for every style (bold and italic fall
/// back to it).
pub fn register() -> Result<(), String> {
    register_font(
        FAMILY,
        FontStyle::Normal,
        epaint_default_fonts::UBUNTU_LIGHT,
    )
    .map_err(|_| {
        "plotters could not read the Ubuntu Light font bundled by epaint_default_fonts".to_string()
    })
}
