//! The output workloads of `scripts/count-instructions.sh` (`bandnoise_checks::count::run_outputs`).
#![no_std]
#![no_main]

use core::panic::PanicInfo;

use cortex_m as _;
use cortex_m_rt::entry;
use cortex_m_semihosting::debug;

#[inline(never)]
#[unsafe(no_mangle)]
fn bandnoise_mark_begin() {
    core::hint::black_box(1);
}

#[inline(never)]
#[unsafe(no_mangle)]
fn bandnoise_mark_end() {
    core::hint::black_box(2);
}

#[entry]
fn main() -> ! {
    core::hint::black_box(bandnoise_checks::count::run_outputs(
        bandnoise_mark_begin,
        bandnoise_mark_end,
    ));
    debug::exit(debug::EXIT_SUCCESS);
    loop {}
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    debug::exit(debug::EXIT_FAILURE);
    loop {}
}
