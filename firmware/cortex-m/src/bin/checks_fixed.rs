//! `checks` for the I16F16 checksums only (the Cortex-M0's half of them; `checks-float` runs
//! the other).
#![no_std]
#![no_main]

const FIXED: bool = true;
const FLOAT: bool = false;

include!("../checks_body.rs");
