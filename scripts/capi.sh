#!/usr/bin/env bash
# The C library (capi/): its examples built with the host's cc and, for Cortex-M0 and Cortex-M4F,
# with Debian's arm-none-eabi-gcc and run under QEMU; each recomputes the crate's checksums of
# every runtime description through the C interface (capi/examples/checks.h) and fails on any
# difference. Prints the Cortex-M0 programs' flash cost (capi/README.md). Needs QEMU (the
# firmware step of scripts/test.sh installs it); installs arm-none-eabi-gcc when missing.
set -euo pipefail
cd "$(dirname "$0")/.."

out=target/capi
mkdir -p "$out"
cflags=(-std=c99 -Wall -Wextra -Werror -Icapi/include -Icapi/examples)

# The header is C and C++ (its declarations inside extern "C" for C++).
cc "${cflags[@]}" -pedantic -fsyntax-only -x c capi/include/bandnoise.h
c++ -std=c++11 -Wall -Wextra -Werror -pedantic -fsyntax-only -x c++ capi/include/bandnoise.h

# The firmware libraries (Cortex-M4F, and Cortex-M0's first part) build beside the host's, in a
# build directory of their own (scripts/side.sh): each library is one codegen unit, one core.
. scripts/side.sh
cross=target/capi-cross
m4f=thumbv7em-none-eabihf
m0=thumbv6m-none-eabi
# Cortex-M0's libraries, built for size with only their dimensions (features dim1 … dim4):
# m0_lib DIMS builds $out/libbandnoise_c-m0-DIMS.a in the current build directory.
m0_lib() {
    cargo rustc --profile capi-firmware -p bandnoise-capi --target $m0 --crate-type staticlib \
        --no-default-features --features "small-tiles,dim${1/,/,dim}"
    cp "${CARGO_TARGET_DIR:-target}/$m0/capi-firmware/libbandnoise_c.a" "$out/libbandnoise_c-m0-$1.a"
}
cross_libs() {
    export CARGO_TARGET_DIR=$cross
    # Cortex-M4F: every dimension in both number types, at opt-level 3 with the panic handler
    # that calls an undefined function (below: it links, so no panic is reachable).
    cargo rustc --release -p bandnoise-capi --target $m4f --crate-type staticlib \
        --no-default-features --features small-tiles,prove-no-panic,dim1,dim2,dim3,dim4
    m0_lib 1,2
}
side "$out/cross-build.log" cross_libs
cross_pid=$side_pid

# Host: the static library with the quantized tiles, whose values checks.h holds.
cargo rustc --release -p bandnoise-capi --features small-tiles --crate-type staticlib
lib=target/release/libbandnoise_c.a
cc "${cflags[@]}" -pedantic -O2 capi/examples/checks.c "$lib" -lm -o "$out/checks"
"$out/checks"
cc "${cflags[@]}" -pedantic -O2 capi/examples/hello.c "$lib" -lm -o "$out/hello"
"$out/hello" | tee "$out/hello.txt"
grep -qx 'noise: perlin seed=7 fbm octaves=5 lacunarity=1.99 gain=0.5' "$out/hello.txt"
grep -q '^error 1 at byte 26: expected octave settings in range' "$out/hello.txt"
grep -qx 'sampling it now: status 4' "$out/hello.txt"
# The guide's C program (docs/guide.md), as printed there.
awk '/^```c$/ { on = 1; next } /^```$/ { on = 0 } on' docs/guide.md > "$out/guide.c"
test -s "$out/guide.c"
cc "${cflags[@]}" -O2 "$out/guide.c" "$lib" -lm -o "$out/guide"
"$out/guide"

# Firmware: Cortex-M0's second part here, then the background's libraries.
m0_lib 3,4
side_wait "$cross_pid" "$out/cross-build.log" "building the firmware's C libraries"
if ! command -v arm-none-eabi-gcc >/dev/null; then
    apt-get update
    # The compiler and libgcc only: the examples need no C library (firmware/startup.c).
    apt-get install -y --no-install-recommends gcc-arm-none-eabi
fi
fw=capi/examples/firmware
arm=(-Os -mthumb -ffreestanding -ffunction-sections -fdata-sections -DBN_FIRMWARE -nostdlib
    -Wl,--gc-sections,--no-warn-rwx-segments,--no-warn-execstack)
qemu() { timeout 300 qemu-system-arm -nographic -semihosting-config enable=on,target=native "$@"; }

# Cortex-M4F: every dimension in both number types in one program; it links with the panic
# handler that calls an undefined function, so no panic is reachable.
arm-none-eabi-gcc "${cflags[@]}" "${arm[@]}" -mcpu=cortex-m4 -mfloat-abi=hard -mfpu=fpv4-sp-d16 \
    capi/examples/checks.c $fw/startup.c -T$fw/an386.ld \
    $cross/$m4f/release/libbandnoise_c.a -lgcc -o "$out/checks-m4f.elf"
qemu -cpu cortex-m4 -machine mps2-an386 -kernel "$out/checks-m4f.elf"

# Cortex-M0: 256 KiB of flash hold one number type's noises in two dimensions at a time, so
# four programs: {1D and 2D, 3D and 4D} × {16.16, float}, each with its dimensions' library
# (built above; firmware's panic handler stops).
for dims in 1,2 3,4; do
    mask=$([ $dims = 1,2 ] && echo 3 || echo 12)
    for types in 1 2; do
        elf="$out/checks-m0-$types-$mask.elf"
        arm-none-eabi-gcc "${cflags[@]}" "${arm[@]}" -mcpu=cortex-m0 -DTYPES=$types -DDIMS=$mask \
            capi/examples/checks.c $fw/startup.c -T$fw/microbit.ld \
            "$out/libbandnoise_c-m0-$dims.a" -lgcc -o "$elf"
        qemu -cpu cortex-m0 -machine microbit -kernel "$elf"
        type=$([ $types = 1 ] && echo "16.16" || echo "float")
        echo "flash of the Cortex-M0 C example, ${dims/,/D and }D in $type:" \
            "$(arm-none-eabi-size "$elf" | awk 'NR == 2 { print $1 + $2 }') bytes"
    done
done
