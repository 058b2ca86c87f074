//! `checks` for the I16F16 checksums of the runtime description only (the Cortex-M0's first
//! part of them; `checks-fixed-other` runs the rest, `checks-float` the f32 ones).
#![no_std]
#![no_main]

const FIXED: bool = true;
const FLOAT: bool = false;
const PARTS: bandnoise_checks::Parts = bandnoise_checks::DESCRIPTIONS;

include!("../checks_body.rs");
