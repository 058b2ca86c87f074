// The body of the `minimal*` programs (`include!`d: each defines `sample`, one call of one
// noise at `point()`): `empty` plus that call, so the footprint script sees what the noise adds.

use core::panic::PanicInfo;

use cortex_m as _;
use cortex_m_rt::entry;
use cortex_m_semihosting::debug;

/// A point the optimiser cannot see, off the lattice.
fn point<const D: usize>() -> [bandnoise::I16F16; D] {
    let bits = [81_920, -40_000, 123_456, 7_777];
    core::hint::black_box(core::array::from_fn(|a| bandnoise::I16F16::from_bits(bits[a])))
}

#[entry]
fn main() -> ! {
    core::hint::black_box(sample());
    debug::exit(debug::EXIT_SUCCESS);
    loop {}
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    loop {}
}
