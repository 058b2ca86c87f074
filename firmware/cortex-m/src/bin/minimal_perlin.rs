//! `empty` plus one call of fixed-point 2D Perlin noise (improved noise, its 256-byte
//! permutation included): what the noise adds to a firmware.
#![no_std]
#![no_main]

use core::panic::PanicInfo;

use bandnoise::lattice::Perlin;
use bandnoise::{I16F16, Noise};
use cortex_m as _;
use cortex_m_rt::entry;
use cortex_m_semihosting::debug;

#[entry]
fn main() -> ! {
    let p = core::hint::black_box([I16F16::from_bits(81_920), I16F16::from_bits(-40_000)]);
    let v: I16F16 = Perlin::new(core::hint::black_box(3)).sample(p);
    core::hint::black_box(v);
    debug::exit(debug::EXIT_SUCCESS);
    loop {}
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    loop {}
}
