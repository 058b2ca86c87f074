#!/usr/bin/env bash
# Builds the browser demo into web/: installs what is missing (the pinned Rust toolchain and
# targets, wasm-bindgen-cli at the version Cargo.lock pins, the npm tools in tests/e2e), builds
# the wasm crate (release, simd128), runs wasm-bindgen (--target web) and wasm-opt, and copies
# the simplex-noise peer for the benchmark page. Prints the module's size.
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

cargo build -p bandnoise-wasm --profile web --target wasm32-unknown-unknown
rm -rf web/pkg
wasm-bindgen target/wasm32-unknown-unknown/web/bandnoise_wasm.wasm \
    --target web --out-dir web/pkg --no-typescript
# The features rustc's wasm32 target emits, plus simd128; not -all, which lets wasm-opt use
# encodings Chromium does not enable by default.
tests/e2e/node_modules/.bin/wasm-opt -Os --strip-producers --strip-target-features \
    --enable-simd --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
    --enable-mutable-globals --enable-multivalue --enable-reference-types \
    web/pkg/bandnoise_wasm_bg.wasm -o web/pkg/bandnoise_wasm_bg.wasm
mkdir -p web/vendor
cp tests/e2e/node_modules/simplex-noise/dist/esm/simplex-noise.js web/vendor/
echo "web/pkg/bandnoise_wasm_bg.wasm: $(wc -c < web/pkg/bandnoise_wasm_bg.wasm) bytes after wasm-opt"
