// The body of the `count`, `count-outputs` and `count-impulse` programs (`include!`d: each
// defines `SET`).

use core::panic::PanicInfo;

use cortex_m as _;
use cortex_m_rt::entry;
use cortex_m_semihosting::debug;

/// Which workloads of `bandnoise_checks::count` a program runs.
#[allow(dead_code, reason = "each program uses one")]
enum Set {
    Noises,
    Outputs,
    Impulse,
}

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
    // Which set is a constant of the program, so the others are not compiled in.
    let run = match SET {
        Set::Noises => bandnoise_checks::count::run,
        Set::Outputs => bandnoise_checks::count::run_outputs,
        Set::Impulse => bandnoise_checks::count::run_impulse,
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
