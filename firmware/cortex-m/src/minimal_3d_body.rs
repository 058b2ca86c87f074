// The body of `minimal-mnoise-3d` and `minimal-mixed-3d` (`include!`d: each defines `Noise3`):
// `empty` plus one call of fixed-point 3D mNoise, computed or from Olano's table.

use core::panic::PanicInfo;

use bandnoise::{I16F16, Noise};
use cortex_m as _;
use cortex_m_rt::entry;
use cortex_m_semihosting::debug;

#[entry]
fn main() -> ! {
    let p = core::hint::black_box([
        I16F16::from_bits(81_920),
        I16F16::from_bits(-40_000),
        I16F16::from_bits(123_456),
    ]);
    let v: I16F16 = Noise3::new(core::hint::black_box(3)).sample(p);
    core::hint::black_box(v);
    debug::exit(debug::EXIT_SUCCESS);
    loop {}
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    loop {}
}
