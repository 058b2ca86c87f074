//! Workloads for `scripts/count-instructions.sh` (see `bandnoise_checks::count`): 8-bit outputs
//! and the LED example (`run_outputs`), in a program of its own so that they do not change how
//! `count`'s noises are inlined.
#![no_std]
#![no_main]

/// The workloads this program runs.
const SET: Set = Set::Outputs;

include!("../count_body.rs");
