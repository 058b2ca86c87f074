//! The browser demo's wasm layer: it renders one frame of a bandnoise noise into a reusable RGBA
//! buffer and draws it on a canvas, with the frame's power spectrum and value histogram.
//!
//! Everything about noise comes from `bandnoise`; this crate only validates what JavaScript
//! sends (bad parameters become a `BadField` naming the field and why, never a panic), picks the noise,
//! maps values to colours, and computes the spectrum (a radix-2 FFT, `fft.rs`).

mod fft;
mod palette;
mod params;
mod render;

pub use params::{BadField, Params, kinds};
pub use render::Demo;

/// A free-list allocator of about 800 bytes instead of the standard library's dlmalloc (about
/// 7 KB with `free` and `realloc`): the module's size has a budget (README, Browser), and the
/// demo allocates a few buffers per setting, not per sample. Locked rather than assumed
/// single-threaded, so no `unsafe` is needed.
#[cfg(target_arch = "wasm32")]
#[global_allocator]
static ALLOCATOR: lol_alloc::LockedAllocator<lol_alloc::FreeListAllocator> =
    lol_alloc::LockedAllocator::new(lol_alloc::FreeListAllocator::new());
