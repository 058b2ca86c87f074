#!/usr/bin/env bash
# Instructions per sample of mNoise (2D–4D, computed and from Olano's table, and 4-octave
# turbulence), 2D and 3D Perlin, 2D wavelet, 2D and 3D sparse convolution, Wiener, Gabor,
# simplex and cellular noise, in I16F16 and f32, of 8-bit outputs (`levels`), and per frame of
# the LED example, on Cortex-M0 (soft float), Cortex-M4F and RV32IMC, counted in QEMU's
# instruction trace (deterministic, unlike time). Also the footprint of the LED example and of
# minimal firmware that calls only fixed-point 2D mNoise, 2D Perlin noise, or 3D mNoise
# computed or from the table. Needs QEMU (scripts/test.sh installs it).
set -euo pipefail
cd "$(dirname "$0")/../firmware"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The workloads of checks/src/count.rs: `count` runs NAMES, `count-outputs` OUTPUT_NAMES,
# `count-impulse` IMPULSE_NAMES.
names=(baseline "mnoise 2D I16F16" "mnoise 2D f32" "perlin 2D I16F16" "perlin 2D f32"
    "perlin 3D I16F16" "perlin 3D f32" "wavelet 2D I16F16 varied" "wavelet 2D f32 varied")
output_names=("baseline u8" "perlin 2D I16F16 u8" "mnoise 2D I16F16 u8" "perlin 2D f32 u8" "led frame"
    "wavelet 2D I16F16 varied spread" "wavelet 2D I16F16 spread")
impulse_names=("baseline impulse" "sparse 2D I16F16" "sparse 2D f32" "sparse 3D I16F16" "sparse 3D f32"
    "sparse 3D I16F16 3 per cell" "wiener 2D I16F16" "wiener 2D f32" "wiener band-pass 2D I16F16"
    "wiener 3D I16F16" "gabor 2D I16F16" "gabor 2D f32" "gabor 3D I16F16" "gabor 2D I16F16 isotropic"
    "simplex 2D I16F16" "simplex 2D f32" "simplex 3D I16F16" "cellular 2D I16F16" "cellular 2D f32"
    "mnoise 3D I16F16" "mixed mnoise 3D I16F16" "mnoise 4D I16F16" "mixed mnoise 4D I16F16"
    "mnoise 3D f32" "mixed mnoise 3D f32" "turbulence4 mnoise 3D I16F16" "turbulence4 mixed 3D I16F16")
samples=16
trace="-accel tcg,one-insn-per-tb=on -d exec,nochain -D $work/exec.log"

cargo build -q --release -p firmware-cortex-m --bin count --bin count-outputs --bin count-impulse --target thumbv6m-none-eabi
cargo build -q --release -p firmware-cortex-m --bin count --bin count-outputs --bin count-impulse --target thumbv7em-none-eabihf
cargo build -q --release -p firmware-riscv --bin count --bin count-outputs --bin count-impulse --target riscv32imc-unknown-none-elf

run() { # target, qemu command...
    local target=$1; shift
    timeout 300 "$@" $trace -kernel "target/$target/release/count" >/dev/null
    python3 ../scripts/count-instructions.py "$work/exec.log" "$samples" "${names[@]}" > "$work/$target.tsv"
    timeout 300 "$@" $trace -kernel "target/$target/release/count-outputs" >/dev/null
    python3 ../scripts/count-instructions.py "$work/exec.log" "$samples" "${output_names[@]}" >> "$work/$target.tsv"
    timeout 300 "$@" $trace -kernel "target/$target/release/count-impulse" >/dev/null
    python3 ../scripts/count-instructions.py "$work/exec.log" "$samples" "${impulse_names[@]}" >> "$work/$target.tsv"
    rm -f "$work/exec.log"
}
run thumbv6m-none-eabi qemu-system-arm -cpu cortex-m0 -machine microbit -nographic \
    -semihosting-config enable=on,target=native
run thumbv7em-none-eabihf qemu-system-arm -cpu cortex-m4 -machine mps2-an386 -nographic \
    -semihosting-config enable=on,target=native
run riscv32imc-unknown-none-elf qemu-system-riscv32 -machine virt \
    -cpu rv32,a=false,f=false,d=false,zawrs=false,zfa=false -bios none -nographic

echo "instructions per sample (QEMU trace, $samples samples, baseline subtracted)"
printf '%-32s %16s %16s %16s\n' "" "Cortex-M0" "Cortex-M4F" "RV32IMC"
paste "$work/thumbv6m-none-eabi.tsv" "$work/thumbv7em-none-eabihf.tsv" "$work/riscv32imc-unknown-none-elf.tsv" |
    awk -F'\t' '{ printf "%-32s %16s %16s %16s\n", $1, $2, $4, $6 }'
python3 - "$work/thumbv6m-none-eabi.tsv" <<'PY'
import sys
rows = dict(line.rstrip("\n").split("\t") for line in open(sys.argv[1]))
fixed, flt = float(rows["mnoise 2D I16F16"]), float(rows["mnoise 2D f32"])
ratio = fixed / flt
print(f"Cortex-M0: fixed-point 2D mNoise takes {ratio:.2f} of the instructions of soft-float f32 (goal: at most 0.20)")
failed = ratio > 0.20
# Issue 16's goals on the Cortex-M0 (FastLED 3.10.3 inoise16 at gcc -O2: 2D 217, 3D 462;
# Gustavson's armnoise8 258; mNoise's goal is 260). Goals met are asserted so that they stay
# met; goals still open are reported. The wavelet goal was set for `Tiling::Varied` when it was
# the default, at points in one block; the default (blended) tiling's cost is reported below.
goals = [("perlin 2D I16F16", 217, True), ("perlin 3D I16F16", 462, True),
         ("mnoise 2D I16F16", 260, True), ("wavelet 2D I16F16 varied", 700, True)]
for name, goal, asserted in goals:
    got = float(rows[name])
    verdict = "met" if got <= goal else ("MISSED" if asserted else "not yet met (open)")
    print(f"Cortex-M0: {name} {got:.0f} instructions per sample, goal at most {goal}: {verdict}")
    failed |= asserted and got > goal
# Issue 16, points 2 and 3: what the 8-bit map adds, and the LED example per LED.
for noise in ("perlin 2D I16F16", "mnoise 2D I16F16", "perlin 2D f32"):
    extra = float(rows[noise + " u8"]) - float(rows[noise])
    print(f"Cortex-M0: {noise} as u8 {float(rows[noise + ' u8']):.0f} per sample ({extra:+.0f} for the map)")
leds = 60
print(f"Cortex-M0: the LED example {float(rows['led frame']):.0f} per frame of {leds} LEDs, "
      f"{float(rows['led frame']) / leds:.0f} per LED")
# Issue 17: the default (blended) tiling's cost over the whole tile, against `Varied` and against
# issue 17's goal of 1.5× fixed-point 2D Perlin (open).
varied, default = float(rows["wavelet 2D I16F16 varied spread"]), float(rows["wavelet 2D I16F16 spread"])
perlin = float(rows["perlin 2D I16F16"])
print(f"Cortex-M0: wavelet 2D I16F16 over a whole 64² tile: default (blended) {default:.0f} "
      f"instructions per sample, {default / varied:.2f}× Varied's {varied:.0f}, "
      f"{default / perlin:.2f}× Perlin 2D (goal at most 1.5×: "
      f"{'met' if default <= 1.5 * perlin else 'not yet met (open)'})")
# Issue 18, point 5: sparse convolution noise on the firmware cores (reported; its x86-64 speed
# goal is measured by the peer benchmark).
for name in ("sparse 2D I16F16", "sparse 3D I16F16"):
    print(f"Cortex-M0: {name} (10 impulses per kernel) {float(rows[name]):.0f} instructions per "
          f"sample, {float(rows[name]) / float(rows[name.replace('sparse', 'perlin')]):.1f}× Perlin")
for name in ("wiener 2D I16F16", "wiener band-pass 2D I16F16", "wiener 3D I16F16"):
    perlin = rows[name.replace("wiener band-pass", "perlin").replace("wiener", "perlin")]
    print(f"Cortex-M0: {name} {float(rows[name]):.0f} instructions per sample, "
          f"{float(rows[name]) / float(perlin):.1f}× Perlin")
for name in ("gabor 2D I16F16", "gabor 2D I16F16 isotropic", "gabor 3D I16F16"):
    perlin = rows[name.replace(" isotropic", "").replace("gabor", "perlin")]
    print(f"Cortex-M0: {name} (16 impulses per kernel) {float(rows[name]):.0f} instructions per "
          f"sample, {float(rows[name]) / float(perlin):.1f}× Perlin")
# Issue 19, point 7: simplex and cellular noise in fixed point on the firmware cores (reported).
for name in ("simplex 2D I16F16", "simplex 3D I16F16", "cellular 2D I16F16"):
    perlin = rows[name.replace("simplex", "perlin").replace("cellular", "perlin")]
    print(f"Cortex-M0: {name} {float(rows[name]):.0f} instructions per sample, "
          f"{float(rows[name]) / float(perlin):.2f}× Perlin")
# Issue 19, point 4: Olano's table evaluation beside computed mNoise (bit-identical: the
# firmware asserts it).
for name in ("mnoise 3D I16F16", "mnoise 4D I16F16", "mnoise 3D f32", "turbulence4 mnoise 3D I16F16"):
    mixed = float(rows[name.replace("mnoise", "mixed") if "turbulence" in name else "mixed " + name])
    print(f"Cortex-M0: {name} computed {float(rows[name]):.0f}, from the table {mixed:.0f} "
          f"instructions per sample ({mixed / float(rows[name]):.2f}×)")
sys.exit("goal missed" if failed else 0)
PY

# Footprint: flash and RAM from the ELF section headers.
cargo build -q --release -p firmware-cortex-m --bin empty --bin minimal --bin minimal-perlin --bin led \
    --bin minimal-mnoise-3d --bin minimal-mixed-3d --target thumbv6m-none-eabi
echo
echo "footprint on thumbv6m (bytes)"
python3 ../scripts/elf-size.py target/thumbv6m-none-eabi/release/{empty,minimal,minimal-perlin,led,minimal-mnoise-3d,minimal-mixed-3d} |
    tee "$work/size.txt"
added=$(awk '/^minimal adds/ { print $3 }' "$work/size.txt")
# Issue 16: at most 1.5 KB for fixed-point 2D mNoise (FastLED's 2D inoise16: about 800 bytes).
if [ "$added" -gt 1536 ]; then
    echo "the minimal firmware adds $added bytes of flash (goal: at most 1536)"
    exit 1
fi
