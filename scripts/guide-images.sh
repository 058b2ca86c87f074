#!/usr/bin/env bash
# The guide's figures (docs/guide.md): each family's image, radially averaged power spectrum,
# periodogram and histogram, made by the bandnoise command's `analyse` (128² samples every
# 0.15 units from (0.31, 0.57), the periodogram averaged over four 64² blocks).
#   bash scripts/guide-images.sh [OUT]     (OUT: docs/guide by default)
# The test command re-renders them into target/ and compares them with the committed ones.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/guide}
cargo build --release -q -p bandnoise-cli
bin=target/release/bandnoise
while read -r name spec; do
    [ -z "$name" ] && continue
    "$bin" analyse "$spec" --size 128 --step 0.15 --block 64 --out "$out/$name" >/dev/null
done <<'LIST'
perlin perlin seed=1
perlin-fbm perlin seed=1 fbm octaves=5 lacunarity=2 gain=0.5
original original seed=1
value value seed=1
mnoise mnoise seed=1
simplex simplex seed=1
opensimplex2s opensimplex2s seed=1
wavelet wavelet seed=1
multiband multiband seed=1
sparse sparse seed=1
gabor gabor seed=1 frequency=2 bandwidth=1 direction=1,1
wiener wiener seed=1 covariance=band-pass
cellular cellular seed=1
white white seed=1
value-cubic value-cubic seed=1
flow flow seed=1 angle=0.1 fbm octaves=4 lacunarity=2 gain=0.5 advection=0.5
warp perlin seed=1 fbm octaves=4 lacunarity=2 gain=0.5 warp=0.6
LIST
