#!/usr/bin/env bash
# Measures what a compile-time wavelet tile costs: the extra compile time of a crate that defines
# `static T: Tile… = Tile…::generate(1);` against the same crate without it (bandnoise itself is
# built once beforehand), and the tile's size in bytes. Prints a table; asserts nothing (timings
# depend on the machine's load).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/src"
cp rust-toolchain.toml "$work/"
cat > "$work/Cargo.toml" <<TOML
[package]
name = "tile-cost"
version = "0.0.0"
edition = "2024"
publish = false
[dependencies]
bandnoise = { path = "$root/core" }
[workspace]
TOML
export CARGO_TARGET_DIR="$root/target/tile-cost"

build() { # $1 = the static line (or empty); prints seconds
    printf '#![allow(unused_imports)]\nuse bandnoise::wavelet::*;\n%s\nfn main() { println!("{}", core::hint::black_box(0)); }\n' "$1" \
        > "$work/src/main.rs"
    (cd "$work" && cargo build --release -q 2>/dev/null) # warm: dependencies
    touch "$work/src/main.rs"
    local start end
    start=$(date +%s.%N)
    (cd "$work" && cargo build --release -q)
    end=$(date +%s.%N)
    echo "$end - $start" | bc
}

base=$(build "") || exit 1
printf '%-12s %12s %10s\n' "tile" "compile (s)" "bytes"
for spec in Tile2:64 Tile3:16 Tile3:32; do
    ty=${spec%%:*} n=${spec##*:}
    line="static T: $ty<$n> = $ty::<$n>::generate(1);
#[used] static KEEP: &$ty<$n> = &T;"
    t=$(build "$line") || exit 1
    printf 'use bandnoise::wavelet::*;\nfn main() { println!("{}", core::mem::size_of::<%s<%s>>()); }\n' "$ty" "$n" \
        > "$work/src/main.rs"
    bytes=$(cd "$work" && cargo run --release -q)
    printf '%-12s %12.2f %10s\n' "$ty<$n>" "$(echo "$t - $base" | bc)" "$bytes"
done
