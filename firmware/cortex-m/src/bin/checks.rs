//! Computes every checksum of `bandnoise-checks` on the chip and compares it with the host's;
//! exits through semihosting with success only if all match. (The Cortex-M0 runs
//! `checks-fixed`, `checks-fixed-other` and `checks-float` instead: its flash holds one number
//! type's code at a time, and fixed point's in two parts.)
#![no_std]
#![no_main]

const FIXED: bool = true;
const FLOAT: bool = true;
const PARTS: bandnoise_checks::Parts = bandnoise_checks::DESCRIPTIONS | bandnoise_checks::OTHERS;

include!("../checks_body.rs");
