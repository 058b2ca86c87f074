#!/usr/bin/env python3
"""Counts instructions per sample from a QEMU trace (-accel tcg,one-insn-per-tb=on
-d exec,nochain): one 'Trace' line per executed instruction, naming its function. Each workload
runs between a call to bandnoise_mark_begin and one to bandnoise_mark_end; the first workload is
the baseline (loop and point, no noise), subtracted from the others.

usage: count-instructions.py LOG SAMPLES NAME...   prints 'name<TAB>instructions per sample'
"""
import sys

log, samples, names = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
counts, current = [], None
with open(log, errors="replace") as f:
    for line in f:
        if not line.startswith("Trace"):
            continue
        symbol = line.rsplit("]", 1)[-1].strip()
        if symbol == "bandnoise_mark_begin":
            current = 0
        elif symbol == "bandnoise_mark_end":
            if current is not None:
                counts.append(current)
            current = None
        elif current is not None:
            current += 1
if len(counts) != len(names):
    sys.exit(f"found {len(counts)} workloads in {log}, expected {len(names)}")
base = counts[0]
for name, c in zip(names[1:], counts[1:]):
    print(f"{name}\t{(c - base) / samples:.0f}")
