//! Workloads for `scripts/count-instructions.sh` (see `bandnoise_checks::count`): sparse
//! convolution noise (`run_impulse`), in a program of its own so that it does not change how
//! the other programs' noises are inlined.
#![no_std]
#![no_main]

/// The workloads this program runs.
const SET: Set = Set::Impulse;

include!("../count_body.rs");
