//! Shared build script of the firmware crates: puts the crate's memory map for the target on
//! the linker path and computes the expected values on the host.
use std::{env, fs, path::PathBuf};

/// Frames the LED example renders (2 s at 50 frames per second).
const LED_FRAMES: u32 = 100;

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("OUT_DIR"));
    let manifest = PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
    // A crate may name a target's own memory map `memory-<machine>.x`: the Cortex-M4F runs on
    // mps2-an386, whose code memory is larger than the Cortex-M0's microbit flash.
    let target = env::var("TARGET").unwrap_or_default();
    let an386 = manifest.join("memory-an386.x");
    let memory = if target.starts_with("thumbv7em") && an386.exists() {
        an386
    } else {
        manifest.join("memory.x")
    };
    fs::copy(&memory, out.join("memory.x")).expect("memory.x");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=memory-an386.x");
    // This runs on the host: these are the host's numbers the firmware must reproduce.
    let sums = bandnoise_checks::checksums();
    let led = bandnoise_checks::led::checksum(LED_FRAMES);
    let code = format!(
        "/// Computed on the host by build.rs.\n\
         #[allow(dead_code)]\n\
         const EXPECTED: [u32; {}] = {sums:?};\n\
         /// Frames of the LED example.\n\
         #[allow(dead_code)]\n\
         const LED_FRAMES: u32 = {LED_FRAMES};\n\
         /// The LED example's checksum over those frames, on the host.\n\
         #[allow(dead_code)]\n\
         const LED_EXPECTED: u32 = {led};\n",
        sums.len()
    );
    fs::write(out.join("expected.rs"), code).expect("expected.rs");
}
