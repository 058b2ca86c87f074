//! `checks` for the f32 checksums only (the Cortex-M0's other half; see `checks-fixed`).
#![no_std]
#![no_main]

const FIXED: bool = false;
const FLOAT: bool = true;
const PARTS: bandnoise_checks::Parts = bandnoise_checks::DESCRIPTIONS | bandnoise_checks::OTHERS;

include!("../checks_body.rs");
