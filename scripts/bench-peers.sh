#!/usr/bin/env bash
# bandnoise against the peer crates (noise 0.9, fastnoise-lite 1.1, noise-functions 0.8,
# libnoise 1.2) over the same 1024² grid, on each grid layout (bench/src/lib.rs, LAYOUTS), in
# one run:
#   1. criterion: ns/sample of every workload, then a table of ratios to the fastest peer;
#   2. paired: each ratio to the fastest peer, median of interleaved rounds (peers.rs docs);
#   3. tilted: 4D Perlin over the grids tilted out of the benchmark's (z, w) plane, by
#      bandnoise and the 4D peers, paired (bench/src/bin/tilted.rs);
#   4. callgrind: instructions per sample of every workload (a figure that does not depend on
#      the machine's load): each runs at 16 and 48 rows and the difference is divided by the
#      32·1024 extra samples, so start-up work cancels out.
# The workloads are in bench/src/lib.rs. Takes about 15 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v valgrind >/dev/null; then
    apt-get update -qq && apt-get install -y -qq valgrind
fi

cargo bench -p bandnoise-bench --bench peers

cargo build -q -p bandnoise-bench --release --bin callgrind --bin tilted
echo
target/release/tilted

bin=target/release/callgrind
functions=$(sed -n '/^pub const FUNCTIONS/,/\];/p' bench/src/lib.rs | grep -o '"[^"]*"' | tr -d '"')
implementations=$(sed -n '/^pub const IMPLEMENTATIONS/,/\];/p' bench/src/lib.rs | grep -o '"[^"]*"' | tr -d '"')
layouts=$(sed -n '/^pub const LAYOUTS/,/^\];/p' bench/src/lib.rs | grep -o 'name: "[^"]*"' | cut -d'"' -f2)

instructions() { # function implementation rows layout → total instructions, or nothing
    local out
    out=$(mktemp)
    if valgrind --tool=callgrind --callgrind-out-file="$out" "$bin" "$1" "$2" "$3" "$4" >/dev/null 2>&1; then
        awk '/^summary:/ { print $2 }' "$out"
    fi
    rm -f "$out"
}

for layout in $layouts; do
    echo
    echo "instructions per sample (callgrind), layout $layout"
    printf '| function |'
    for i in $implementations; do printf ' %s |' "$i"; done
    printf '\n|---|'
    for _ in $implementations; do printf -- '---|'; done
    printf '\n'
    for f in $functions; do
        printf '| %s |' "$f"
        for i in $implementations; do
            lo=$(instructions "$f" "$i" 16 "$layout")
            hi=$(instructions "$f" "$i" 48 "$layout")
            if [ -n "$lo" ] && [ -n "$hi" ]; then
                awk -v lo="$lo" -v hi="$hi" 'BEGIN { printf " %.0f |", (hi - lo) / (32 * 1024) }'
            else
                printf ' – |'
            fi
        done
        printf '\n'
    done
done
