//! `include/bandnoise.h` is what cbindgen makes of `src/lib.rs` (with `cbindgen.toml`):
//! the committed header cannot drift from the code. `BLESS=1` rewrites it.

use std::path::Path;

#[test]
fn the_committed_header_is_generated_from_the_code() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("cbindgen.toml");
    let bindings = cbindgen::Builder::new()
        .with_config(config)
        .with_src(dir.join("src/lib.rs"))
        .generate()
        .expect("cbindgen reads src/lib.rs");
    let mut generated = Vec::new();
    bindings.write(&mut generated);
    let path = dir.join("include/bandnoise.h");
    if std::env::var_os("BLESS").is_some() {
        std::fs::write(&path, &generated).expect("write the header");
    }
    let committed = std::fs::read(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "capi/include/bandnoise.h is not what cbindgen generates from capi/src/lib.rs; \
         regenerate it with BLESS=1 cargo test -p bandnoise-capi --test capi header"
    );
}
