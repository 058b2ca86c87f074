#!/usr/bin/env bash
# Builds, packs and tests the npm package (bindings/wasm): the module (profile web, as the
# benchmark page's; wasm-bindgen --target web) with js/ into target/npm/package, `npm pack` into a tarball,
# installed into an empty folder (target/npm/app) and used from there: node --test, tsc on a
# TypeScript example (type-checked, compiled and run), the guide's JavaScript, and a page in
# Chromium. Prints the packed module's size. Needs what scripts/build-web.sh installs
# (wasm-bindgen-cli, tests/e2e's npm tools) and Chromium; the test command runs it after them.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
bin=$root/tests/e2e/node_modules/.bin

# Opt-level 3, not the demo's "s": at "s" the batch kernels are not inlined and fillGrid is 5
# times slower (1.17 MB instead of 2.0 MB; bindings/wasm/README.md).
cargo build -p bandnoise-js --profile web --target wasm32-unknown-unknown
rm -rf target/npm
mkdir -p target/npm/app
pkg=target/npm/package
# No wasm-opt: npm's binaryen (compiled to JavaScript) takes over 20 minutes on this module.
wasm-bindgen target/wasm32-unknown-unknown/web/bandnoise_js.wasm --target web --out-dir "$pkg" --no-typescript
cp bindings/wasm/js/{package.json,index.js,index.d.ts,README.md} "$pkg/"
tarball=$(cd "$pkg" && npm pack --silent --pack-destination ..)
echo "packed target/npm/$tarball: $(wc -c < "target/npm/$tarball") bytes;" \
    "bandnoise_js_bg.wasm $(tar -xOzf "target/npm/$tarball" package/bandnoise_js_bg.wasm | wc -c) bytes" \
    "($(tar -xOzf "target/npm/$tarball" package/bandnoise_js_bg.wasm | gzip -9 | wc -c) gzipped)"

# An empty folder, as a user's: the tarball installed from the file (no registry needed).
cd target/npm/app
echo '{ "name": "app", "private": true, "type": "module" }' > package.json
npm install --no-audit --no-fund --silent "../$tarball"
cp "$root"/bindings/wasm/tests/{node.test.mjs,checks.mjs,example.ts,page.html} .
cp "$root/tests/e2e/node_modules/simplex-noise/dist/esm/simplex-noise.js" .
BANDNOISE_ROOT=$root node --test node.test.mjs

# The TypeScript example: strict type check against index.d.ts, then compiled and run.
tsc=(--strict --target es2022 --module nodenext --moduleResolution nodenext --lib es2022,dom)
"$bin/tsc" --noEmit "${tsc[@]}" example.ts
"$bin/tsc" "${tsc[@]}" --outDir ts-out example.ts
node ts-out/example.js | grep -q '^25 noises; height '

# The JavaScript of the guide and of the package's README runs as written.
for doc in docs/guide.md bindings/wasm/js/README.md; do
    awk '/^```js$/ { on = 1; next } /^```$/ { on = 0 } on' "$root/$doc" > doc.mjs
    test -s doc.mjs
    node doc.mjs > /dev/null
done

cd "$root"
node tests/e2e/npm.test.mjs target/npm/app capi/examples/checks.h
