//! The LED-strip example: renders 100 frames of fire for 60 RGB LEDs in fixed point and prints
//! the frames' checksum, which must equal the host's (computed by build.rs).
#![no_std]
#![no_main]

use core::panic::PanicInfo;

use bandnoise_checks::led::{Fire, LEDS};
use cortex_m as _;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};

include!(concat!(env!("OUT_DIR"), "/expected.rs"));

#[entry]
fn main() -> ! {
    let fire = Fire::new();
    let mut strip = [[0u8; 3]; LEDS]; // what a WS2812 driver would shift out
    let mut h = 0x811C_9DC5u32;
    for t in 0..LED_FRAMES {
        fire.render(t, &mut strip);
        for b in strip.iter().flatten() {
            h = (h ^ *b as u32).wrapping_mul(0x0100_0193);
        }
    }
    let ok = h == LED_EXPECTED;
    hprintln!(
        "led strip: {} frames of {} LEDs, checksum {:08x} (host {:08x})",
        LED_FRAMES,
        LEDS,
        h,
        LED_EXPECTED
    );
    debug::exit(if ok {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    loop {}
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    debug::exit(debug::EXIT_FAILURE);
    loop {}
}
