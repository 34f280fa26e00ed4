//! The unit tests of the plots' bitmap font (`benches/common/plot_text.rs`, shared by the
//! `floating` example and the `scaling` benchmark, whose own tests `cargo test` does not run).

#[path = "../benches/common/plot_text.rs"]
mod plot_text;
