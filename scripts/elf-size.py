#!/usr/bin/env python3
"""Flash and RAM of 32-bit little-endian ELF firmware, from its section headers: flash holds the
allocated sections below the RAM origin plus the initial values of .data; RAM holds the
allocated sections at or above it (the stack is not counted). Prints a table and, for a first
file named 'empty', what each other file adds to it."""
import struct, sys, os

RAM_ORIGIN = 0x2000_0000
SHF_ALLOC, SHT_NOBITS = 0x2, 8

def sizes(path):
    data = open(path, "rb").read()
    shoff, = struct.unpack_from("<I", data, 0x20)
    shentsize, shnum = struct.unpack_from("<HH", data, 0x2E)
    flash = ram = 0
    for i in range(shnum):
        _, typ, flags, addr, _, size = struct.unpack_from("<IIIIII", data, shoff + i * shentsize)
        if not flags & SHF_ALLOC or size == 0:
            continue
        if addr >= RAM_ORIGIN:
            ram += size
            if typ != SHT_NOBITS:  # .data: initial values live in flash too
                flash += size
        else:
            flash += size
    return flash, ram

rows = [(os.path.basename(p), *sizes(p)) for p in sys.argv[1:]]
print(f"{'firmware':<12} {'flash':>8} {'RAM':>8}")
for name, flash, ram in rows:
    print(f"{name:<12} {flash:>8} {ram:>8}")
if rows and rows[0][0] == "empty":
    _, f0, r0 = rows[0]
    for name, flash, ram in rows[1:]:
        print(f"{name} adds {flash - f0} bytes of flash and {ram - r0} of RAM to an empty firmware")
