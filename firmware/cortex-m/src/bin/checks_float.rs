//! `checks` for the f32 checksums only (the Cortex-M0's other half; see `checks-fixed`).
#![no_std]
#![no_main]

const FIXED: bool = false;
const FLOAT: bool = true;

include!("../checks_body.rs");
