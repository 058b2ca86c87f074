// The body of the `count` and `count-outputs` programs (`include!`d: each defines `OUTPUTS`).

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
    // Which set is a constant of the program, so the other is not compiled in.
    let run = if OUTPUTS {
        bandnoise_checks::count::run_outputs
    } else {
        bandnoise_checks::count::run
    };
    core::hint::black_box(run(bandnoise_mark_begin, bandnoise_mark_end));
    debug::exit(debug::EXIT_SUCCESS);
    loop {}
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    debug::exit(debug::EXIT_FAILURE);
    loop {}
}
