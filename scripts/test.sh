#!/usr/bin/env bash
# Runs every test of bandnoise, on a fresh machine too: installs the pinned toolchain and targets
# (rust-toolchain.toml) when missing, then lints, tests, cross-builds and smoke-runs everything.
set -euo pipefail
cd "$(dirname "$0")/.."

# Each step prints the minutes and seconds since the start (CI's time budget).
step() { printf '\n==> [%d:%02d] %s\n' $((SECONDS / 60)) $((SECONDS % 60)) "$*"; }

step "toolchain (rust-toolchain.toml)"
rustup set auto-self-update disable
rustup toolchain install # installs the pinned channel, components and targets; instant if present

step "format and lints"
cargo fmt --all -- --check
cargo clippy --workspace --all-targets -- -D warnings
cargo clippy -p bandnoise-wasm -p bandnoise-wasm-bench -p bandnoise-js --target wasm32-unknown-unknown --all-targets -- -D warnings
# Core alone on a no_std target without a float unit, with the optional serde feature (no_std
# and allocation-free too). Its default features on every target are built by the firmware
# steps (Cortex-M0, Cortex-M4F, RV32IMC: the same dependency versions, firmware/Cargo.lock) and
# the browser steps (wasm32: the benchmark page's and the npm package's modules).
cargo clippy -p bandnoise --target thumbv6m-none-eabi --features serde -- -D warnings

step "unit, integration and doc tests; benchmarks compile and run once"
# `--tests`: every target with tests, not the examples (clippy above checked that they build);
# the integration tests are one binary (tests/Cargo.toml) and the crates without unit tests
# build no test-mode copy (their manifests' `test = false`): CI's longest step. The benches,
# named (`--benches` would add every library and binary again): criterion's benchmarks run once
# each (test mode), bandnoise's own (tests/benches) and against the peer crates (bench/benches;
# the measured run is scripts/bench-peers.sh), in the same build (a command of their own
# resolves other features and rebuilt the crate and its users).
# The integration tests' binary is built first, alone: it is the build's largest unit, and
# cargo starts the units that nothing depends on late, which left one core idle at the end.
cargo test --workspace --test integration --no-run
cargo test --workspace --tests \
    --bench lattice --bench wavelet --bench peers --bench spec --bench impulse
cargo test --workspace --doc

step "API docs build without warnings (broken links, missing docs)"
RUSTDOCFLAGS="-D warnings" cargo doc -p bandnoise --no-deps

step "compile-time cost and size of wavelet tiles"
bash scripts/measure-tiles.sh

step "browser: Chromium, wasm build, wasm-bindgen tests, end-to-end test, npm package"
if ! command -v chromium >/dev/null || ! command -v chromedriver >/dev/null; then
    apt-get update
    apt-get install -y chromium chromium-driver
fi
bash scripts/build-web.sh
# The module's budget: a page that loads fast (issue 4's 150,000, raised to 190,000 when
# issue 19 put OpenSimplex2/2S and the textures in the demo, to 195,000 for the textures'
# settings and the warp control, to 205,000 for flow noise, to 210,000 for issue 20's
# per-field messages, windowed spectrum and sphere view, to 216,000 for its batch path's
# descriptions, to 217,000 for Gabor noise's harmonic per cell, to 221,000 for the projected
# band's block sums along an axis, to 231,000 for its row sums along oblique normals;
# ARCHITECTURE.md).
size=$(wc -c < web/pkg/bandnoise_wasm_bg.wasm)
if [ "$size" -gt 231000 ]; then
    echo "error: the demo's wasm module is $size bytes, over its budget of 231,000 (README, Browser)" >&2
    exit 1
fi
step "browser: the demo module's wasm-bindgen tests in Chromium"
CHROMEDRIVER=$(command -v chromedriver) cargo test -p bandnoise-wasm --target wasm32-unknown-unknown
step "browser: the npm package"
# The npm package: its SIMD point kernel equals the portable one (Node), then the package packed,
# installed into an empty folder, used from Node, TypeScript and Chromium.
cargo test -p bandnoise-js --target wasm32-unknown-unknown --test kernel
bash scripts/npm.sh

step "firmware under QEMU: the host's checksums on Cortex-M0, Cortex-M4F and RV32IMC"
# The gallery and the bandnoise command (the gallery step's build, below) build in the
# background from here: the firmware programs are each linked whole and QEMU runs one program
# at a time, so one core is often idle in these two steps; the build is waited for before the
# fuzz runs, which keep both cores busy.
source scripts/side.sh
mkdir -p target
side target/gallery-build.log cargo build --release -p bandnoise-gallery -p bandnoise-cli
gallery_build=$side_pid
if ! command -v qemu-system-arm >/dev/null || ! command -v qemu-system-riscv32 >/dev/null; then
    apt-get update
    # This machine kind ships qemu-utils from bookworm-backports, which breaks the plain
    # bookworm qemu-system packages: take them from backports too when the plain install fails.
    if ! apt-get install -y qemu-system-arm qemu-system-misc; then
        if ! grep -rqs bookworm-backports /etc/apt/sources.list /etc/apt/sources.list.d/; then
            printf '%s\n' 'Types: deb' 'URIs: http://deb.debian.org/debian' 'Suites: bookworm-backports' \
                'Components: main' 'Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg' \
                > /etc/apt/sources.list.d/bookworm-backports.sources
            apt-get update
        fi
        apt-get install -y -t bookworm-backports qemu-system-arm qemu-system-misc
    fi
fi
(
    cd firmware
    cargo fmt --all -- --check
    # Each program is linked whole (LTO, one codegen unit): built side by side first, two at a
    # time on two cores, then run one by one. The nopanic programs are only built: no reachable
    # panic, the link fails if any panic survives in the noises they sample.
    cargo build --profile m0-checks -p firmware-cortex-m --target thumbv6m-none-eabi \
        --bin checks-fixed --bin checks-fixed-other --bin checks-float --bin checks-float-other
    cargo build --release -p firmware-cortex-m --target thumbv7em-none-eabihf \
        --bin checks --bin led --bin nopanic --bin nopanic-spec --bin nopanic-text
)
# The demo's end-to-end test (printed below, after the instruction counts) runs beside the QEMU
# runs and counts: it drives one Chromium page, mostly one core, as QEMU does. Its printed
# frames per second are then measured beside QEMU; its assertions are pixels and ratios
# measured in the same page.
side target/e2e.log node tests/e2e/demo.test.mjs
e2e=$side_pid
(
    cd firmware
    # The Cortex-M0's 256 KiB of flash hold one part of one number type's checksum code at a
    # time (the descriptions, the others), built for size (firmware/Cargo.toml, m0-checks).
    cargo run --profile m0-checks -p firmware-cortex-m --bin checks-fixed --target thumbv6m-none-eabi
    cargo run --profile m0-checks -p firmware-cortex-m --bin checks-fixed-other --target thumbv6m-none-eabi
    cargo run --profile m0-checks -p firmware-cortex-m --bin checks-float --target thumbv6m-none-eabi
    cargo run --profile m0-checks -p firmware-cortex-m --bin checks-float-other --target thumbv6m-none-eabi
    cargo run --release -p firmware-cortex-m --bin checks --target thumbv7em-none-eabihf
    cargo run --release -p firmware-riscv --bin checks --target riscv32imc-unknown-none-elf
    # The LED-strip example: 100 frames of fire, checksum equal to the host's.
    cargo run --release -p firmware-cortex-m --bin led --target thumbv6m-none-eabi
    cargo run --release -p firmware-cortex-m --bin led --target thumbv7em-none-eabihf
)
step "firmware: instructions per sample and footprint"
bash scripts/count-instructions.sh # instructions per sample and footprint, with their goals

step "browser: the demo end to end (run beside the firmware steps)"
side_wait "$e2e" target/e2e.log "the demo's end-to-end test"
cat target/e2e.log

side_wait "$gallery_build" target/gallery-build.log "the gallery's and the command line's build"

step "fuzzing: every target for 20 s (pinned nightly, cargo-fuzz)"
rustup toolchain install nightly-2026-05-20 --profile minimal # instant when present
if ! cargo fuzz --version >/dev/null 2>&1; then
    cargo install cargo-fuzz --version 0.13.1
fi
step "fuzzing: the targets' runs"
(
    cd fuzz
    cargo fmt --all -- --check
    # All targets in one build: their binaries compile side by side (one by one, inside each
    # run, they took 5.3 of the step's 7.5 minutes); each run below then finds its binary built.
    # No sanitizer: the crate forbids unsafe code and the targets assert properties (values,
    # bounds, no panic), which AddressSanitizer does not check; without it the build takes a
    # quarter less time and a run executes about three times as many inputs in its 20 s.
    cargo +nightly-2026-05-20 fuzz build --sanitizer none
    # Each run is one process on one core: two at a time, three targets each. A run's output
    # goes to target/fuzz-logs/; its last line is printed, all of it when it fails.
    mkdir -p ../target/fuzz-logs
    runs() {
        for target in "$@"; do
            # New inputs go to a scratch corpus; the committed seeds stay as they are.
            mkdir -p "../target/fuzz-corpus/$target"
            log=../target/fuzz-logs/$target.log
            if cargo +nightly-2026-05-20 fuzz run --sanitizer none "$target" "../target/fuzz-corpus/$target" \
                "corpus/$target" -- -max_total_time=20 >"$log" 2>&1; then
                echo "fuzz target $target: $(tail -n 1 "$log")"
            else
                cat "$log"
                echo "error: fuzz target $target failed (its log: target/fuzz-logs/$target.log)" >&2
                return 1
            fi
        done
    }
    runs hash wavelet spec &
    first=$!
    runs lattice fractal impulse &
    second=$!
    wait "$first"
    wait "$second"
)

step "gallery renders"
# The gallery and the bandnoise command (the guide's figures, below) were built side by side
# (in the background, from the firmware step): each is one codegen unit, and built together
# they are the same units as alone (the same features and link-time optimisation of what they
# share), so each later build of one finds it fresh. (Not the C library: a static library's
# dependencies are built for another kind of LTO.) Fresh: this only checks.
cargo build --release -p bandnoise-gallery -p bandnoise-cli
cargo run --release -p bandnoise-gallery -- --size 64 --out target/gallery-smoke
test -s target/gallery-smoke/perlin-2d.png

step "the README's texture images are what the code renders"
cargo run --release -p bandnoise-gallery -- --textures --size 128 --out target/gallery-textures
for f in docs/textures/*.png; do
    cmp "$f" "target/gallery-textures/$(basename "$f")" || {
        echo "error: $f differs from the gallery's rendering; re-render with" \
            "cargo run --release -p bandnoise-gallery -- --textures --size 128 --out docs/textures" >&2
        exit 1
    }
done
test "$(ls docs/textures/*.png | wc -l)" = "$(ls target/gallery-textures/*.png | wc -l)"

step "the guide's figures are what the bandnoise command makes"
rm -rf target/guide
bash scripts/guide-images.sh target/guide
for f in docs/guide/*/*.png; do
    cmp "$f" "target/guide/${f#docs/guide/}" || {
        echo "error: $f differs from what the bandnoise command makes; re-render with" \
            "bash scripts/guide-images.sh" >&2
        exit 1
    }
done
test "$(ls docs/guide/*/*.png | wc -l)" = "$(ls target/guide/*/*.png | wc -l)"

step "C library: header, examples on the host, Cortex-M0 and Cortex-M4F (QEMU), no-panic link"
bash scripts/capi.sh

echo
echo "all bandnoise tests passed in $((SECONDS / 60)) min $((SECONDS % 60)) s"
