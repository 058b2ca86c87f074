//! `checks` for the I16F16 checksums of what the runtime description does not name (the
//! Cortex-M0's second part of them; see `checks-fixed`).
#![no_std]
#![no_main]

const FIXED: bool = true;
const FLOAT: bool = false;
const PARTS: bandnoise_checks::Parts = bandnoise_checks::OTHERS;

include!("../checks_body.rs");
