//! The browser demo's wasm layer: it renders one frame of a bandnoise noise into a reusable RGBA
//! buffer and draws it on a canvas, with the frame's power spectrum and value histogram.
//!
//! Everything about noise comes from `bandnoise`; this crate only validates what JavaScript
//! sends (bad parameters become an `Err` with a message, never a panic), picks the noise,
//! maps values to colours, and computes the spectrum (a radix-2 FFT, `fft.rs`).

mod fft;
mod palette;
mod params;
mod render;

pub use params::{Params, kinds};
pub use render::Demo;
