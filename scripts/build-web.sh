#!/usr/bin/env bash
# Builds the browser demo and the benchmark page into web/: installs what is missing (the
# pinned Rust toolchain and targets, wasm-bindgen-cli at the version Cargo.lock pins, the npm
# tools in tests/e2e), builds the two wasm crates (release, simd128), runs wasm-bindgen
# (--target web) and wasm-opt on each, builds the npm package's module into web/npm (the demo
# samples its plane views through it), and copies the simplex-noise peer for the benchmark
# page. Prints the modules' sizes.
set -euo pipefail
cd "$(dirname "$0")/.."

rustup set auto-self-update disable >/dev/null
rustup toolchain install >/dev/null

want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock)
have=$(wasm-bindgen --version 2>/dev/null | awk '{print $2}' || true)
if [ "$have" != "$want" ]; then
    echo "installing wasm-bindgen-cli $want (a few minutes)"
    # Not --locked: the registry mirror lacks one locked dependency (TOOLCHAIN.md).
    cargo install wasm-bindgen-cli --version "$want"
fi

if ! (cd tests/e2e && npm ls --depth=0 >/dev/null 2>&1); then
    (cd tests/e2e && npm ci --no-audit --no-fund)
fi

# The demo's module (web/pkg), built for size (its budget), and the benchmark page's
# (web/pkg-bench) and the npm package's (web/npm, below), built for speed: those two in one
# build (they enable the same features of bandnoise). Each module is one codegen unit, one
# core: the demo's builds beside them (scripts/side.sh; its profile has its own directories).
. scripts/side.sh
mkdir -p target
side target/web-demo.log cargo build -p bandnoise-wasm --profile web-demo --target wasm32-unknown-unknown
demo_pid=$side_pid
cargo build -p bandnoise-wasm-bench -p bandnoise-js --profile web --target wasm32-unknown-unknown
side_wait "$demo_pid" target/web-demo.log "building the demo's module"
for crate in bandnoise_wasm:pkg:web-demo bandnoise_wasm_bench:pkg-bench:web; do
    name=${crate%%:*} rest=${crate#*:}
    dir=web/${rest%%:*} profile=${rest#*:}
    # The demo's module for size (-Oz, run to a fixed point: its budget), the benchmark
    # page's for speed (-Os keeps its loops as fast as -O3, and smaller).
    if [ "$profile" = web-demo ]; then wasm_opt=(-Oz --converge); else wasm_opt=(-Os); fi
    rm -rf "$dir"
    wasm-bindgen "target/wasm32-unknown-unknown/$profile/$name.wasm" \
        --target web --out-dir "$dir" --no-typescript
    # The features rustc's wasm32 target emits, plus simd128; not -all, which lets wasm-opt use
    # encodings Chromium does not enable by default.
    tests/e2e/node_modules/.bin/wasm-opt "${wasm_opt[@]}" --strip-producers --strip-target-features \
        --enable-simd --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
        --enable-mutable-globals --enable-multivalue --enable-reference-types \
        "$dir/${name}_bg.wasm" -o "$dir/${name}_bg.wasm"
done
# The npm package's module (web/npm: bindings/wasm, the build scripts/npm.sh packs), which the
# demo's plane views sample through by its batch kernels (opt-level 3, no wasm-opt: see
# scripts/npm.sh), loaded after the demo's first frame; built above.
rm -rf web/npm
wasm-bindgen target/wasm32-unknown-unknown/web/bandnoise_js.wasm --target web --out-dir web/npm --no-typescript
cp bindings/wasm/js/index.js web/npm/
mkdir -p web/vendor
cp tests/e2e/node_modules/simplex-noise/dist/esm/simplex-noise.js web/vendor/
echo "web/pkg/bandnoise_wasm_bg.wasm (demo): $(wc -c < web/pkg/bandnoise_wasm_bg.wasm) bytes after wasm-opt"
echo "web/pkg-bench/bandnoise_wasm_bench_bg.wasm (benchmark page): $(wc -c < web/pkg-bench/bandnoise_wasm_bench_bg.wasm) bytes after wasm-opt"
echo "web/npm/bandnoise_js_bg.wasm (the npm package's, for the batch path): $(wc -c < web/npm/bandnoise_js_bg.wasm) bytes"
