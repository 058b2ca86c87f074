//! Computes the expected checksums on the host, for the bit-identity test in wasm32
//! (`tests/checksums.rs`).
use std::{env, fs, path::PathBuf};

fn main() {
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
