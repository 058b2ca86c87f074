//! Names ARMv6-M (`thumbv6m-*`) for the fixed-point kernels: the one target family without a
//! 32 × 32 → 64-bit multiply, which stable Rust's `cfg` cannot tell from ARMv7-M.
fn main() {
    println!("cargo::rustc-check-cfg=cfg(bandnoise_armv6m)");
    println!("cargo::rerun-if-changed=build.rs");
    if std::env::var("TARGET").is_ok_and(|t| t.starts_with("thumbv6m")) {
        println!("cargo::rustc-cfg=bandnoise_armv6m");
    }
}
