//! Workloads for `scripts/count-instructions.sh` (see `bandnoise_checks::count`): the noises
//! (`run`). `count-outputs` runs the others, in a program of its own so that neither set
//! changes how the other is inlined.
#![no_std]
#![no_main]

/// The workloads this program runs.
const SET: Set = Set::Noises;

include!("../count_body.rs");
