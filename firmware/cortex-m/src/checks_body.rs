// The body of the `checks`, `checks-fixed`, `checks-fixed-other`, `checks-float` and
// `checks-float-other` programs
// (`include!`d: each defines `FIXED` and `FLOAT`, the number types whose checksums it
// compares, and `PARTS`, which of them: bandnoise_checks::Parts).

use core::panic::PanicInfo;

use bandnoise_checks::compare_part;
use cortex_m as _; // links the critical-section implementation
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};

include!(concat!(env!("OUT_DIR"), "/expected.rs"));

#[entry]
fn main() -> ! {
    let (compared, bad) = compare_part::<FIXED, FLOAT, PARTS>(&EXPECTED, |ty, name, got, host| {
        hprintln!("MISMATCH {} {}: {:08x}, host {:08x}", ty, name, got, host);
    });
    let types = match (FIXED, FLOAT, PARTS) {
        (true, true, _) => "I16F16 and f32",
        (true, false, bandnoise_checks::DESCRIPTIONS) => "I16F16, the descriptions",
        (true, false, bandnoise_checks::OTHERS) => "I16F16, the others",
        (true, false, _) => "I16F16",
        (false, true, bandnoise_checks::DESCRIPTIONS) => "f32, the descriptions",
        (false, true, bandnoise_checks::OTHERS) => "f32, the others",
        _ => "f32",
    };
    hprintln!(
        "{}: {} checksums ({}), {} differ from the host",
        TARGET,
        compared,
        types,
        bad
    );
    debug::exit(if bad == 0 && compared > 0 {
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
