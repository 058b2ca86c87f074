//! `checks` for the f32 checksums of the runtime description only (the Cortex-M0's other
//! half, in two parts as fixed point's; `checks-float-other` runs the rest, see `checks-fixed`).
#![no_std]
#![no_main]

const FIXED: bool = false;
const FLOAT: bool = true;
const PARTS: bandnoise_checks::Parts = bandnoise_checks::DESCRIPTIONS;

include!("../checks_body.rs");
