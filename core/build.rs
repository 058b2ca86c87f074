//! Names two things stable Rust's `cfg` cannot express in one word:
//!
//! * `bandnoise_armv6m`: ARMv6-M (`thumbv6m-*`) for the fixed-point kernels, the one target
//!   family without a 32 × 32 → 64-bit multiply, which `cfg` cannot tell from ARMv7-M.
//! * `bandnoise_vector`: a 4-lane `f32` vector for Perlin's point kernels (`src/arch/`):
//!   x86-64 with SSE2, or wasm32 with `simd128` in a build without the `small` feature.
fn main() {
    println!("cargo::rustc-check-cfg=cfg(bandnoise_armv6m, bandnoise_vector)");
    println!("cargo::rerun-if-changed=build.rs");
    let var = |name: &str| std::env::var(name).unwrap_or_default();
    if var("TARGET").starts_with("thumbv6m") {
        println!("cargo::rustc-cfg=bandnoise_armv6m");
    }
    let features = var("CARGO_CFG_TARGET_FEATURE");
    let has = |feature: &str| features.split(',').any(|f| f == feature);
    let vector = match var("CARGO_CFG_TARGET_ARCH").as_str() {
        "x86_64" => has("sse2"),
        "wasm32" => has("simd128") && std::env::var_os("CARGO_FEATURE_SMALL").is_none(),
        _ => false,
    };
    if vector {
        println!("cargo::rustc-cfg=bandnoise_vector");
    }
}
