//! Puts `memory.x` on the linker path and computes the expected checksums on the host.
use std::{env, fs, path::PathBuf};

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("OUT_DIR"));
    fs::write(out.join("memory.x"), include_bytes!("memory.x")).expect("memory.x");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed=memory.x");
    // This runs on the host: these are the host's numbers the firmware must reproduce.
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
