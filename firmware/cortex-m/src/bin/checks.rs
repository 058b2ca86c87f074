//! Computes every checksum of `bandnoise-checks` on the chip and compares it with the host's;
//! exits through semihosting with success only if all match.
#![no_std]
#![no_main]

use core::panic::PanicInfo;

use bandnoise_checks::{COUNT, compare};
use cortex_m as _; // links the critical-section implementation
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};

include!(concat!(env!("OUT_DIR"), "/expected.rs"));

#[entry]
fn main() -> ! {
    let bad = compare(&EXPECTED, |ty, name, got, host| {
        hprintln!("MISMATCH {} {}: {:08x}, host {:08x}", ty, name, got, host);
    });
    hprintln!(
        "{}: {} checksums, {} differ from the host",
        TARGET,
        COUNT,
        bad
    );
    debug::exit(if bad == 0 {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    loop {}
}

/// Cortex-M0 has no atomic read-modify-write; the M4F has.
const TARGET: &str = if cfg!(target_has_atomic = "ptr") {
    "thumbv7em (Cortex-M4F)"
} else {
    "thumbv6m (Cortex-M0)"
};

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    hprintln!("panic");
    debug::exit(debug::EXIT_FAILURE);
    loop {}
}
