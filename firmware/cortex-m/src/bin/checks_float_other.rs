//! `checks` for the f32 checksums of what the runtime description does not name (the
//! Cortex-M0's second part of them; see `checks-float`).
#![no_std]
#![no_main]

const FIXED: bool = false;
const FLOAT: bool = true;
const PARTS: bandnoise_checks::Parts = bandnoise_checks::OTHERS;

include!("../checks_body.rs");
