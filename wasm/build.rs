//! Computes the expected checksums on the host, for the bit-identity test in wasm32
//! (`tests/checksums.rs`), and sets the wasm32 stack size.
use std::{env, fs, path::PathBuf};

fn main() {
    // The 3D wavelet tile is generated at its first use (`render.rs`, `WEB_TILE3`), and
    // `Tile3::<32>::generate` holds about 700 KB of `f64` work arrays on the stack: past
    // wasm32's default of 1 MiB with the caller's frames. 4 MiB of the module's linear
    // memory (not of its size).
    if env::var("CARGO_CFG_TARGET_ARCH").as_deref() == Ok("wasm32") {
        println!("cargo:rustc-link-arg=-zstack-size=4194304");
    }
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("OUT_DIR"));
    let sums = bandnoise_checks::checksums();
    fs::write(
        out.join("expected.rs"),
        format!(
            "/// Computed on the host by build.rs.\nconst EXPECTED: [u32; {}] = {:?};\n",
            sums.len(),
            sums
        ),
    )
    .expect("expected.rs");
}
