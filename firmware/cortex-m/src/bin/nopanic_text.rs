//! Proof that the text form of a runtime description cannot panic: this program reads any text
//! as a `Spec` (`Spec::from_str`, with its own float reader, since `f32::from_str` keeps bounds
//! checks) and prints what it read or the error, and prints any configuration error
//! (`Display` of `Spec`, `ParseError` and `Error`, with their own float writer, since `f32`'s
//! `Display` keeps bounds checks too). As `nopanic`, the panic handler calls a function that
//! does not exist, so any surviving panic path fails the link. Its own program because
//! `nopanic` and `nopanic-spec` fill the QEMU machines' 256 KiB of flash. Built, not run
//! (release, thumbv7em).
#![no_std]
#![no_main]

use core::fmt::Write;
use core::hint::black_box;
use core::panic::PanicInfo;

use bandnoise::Error;
use bandnoise::spec::Spec;
use cortex_m as _;
use cortex_m_rt::entry;

unsafe extern "C" {
    /// Deliberately undefined: referenced only if a panic is reachable.
    fn bandnoise_sampling_can_panic() -> !;
}

/// A text sink that keeps a running hash of what is written.
struct Sink(u32);

impl Write for Sink {
    fn write_str(&mut self, s: &str) -> core::fmt::Result {
        for b in s.bytes() {
            self.0 = self.0.wrapping_mul(31).wrapping_add(u32::from(b));
        }
        Ok(())
    }
}

#[entry]
fn main() -> ! {
    let mut out = Sink(0);
    // Text the optimiser cannot see: the spec it names (any spec), or the error, printed.
    let text: &str = black_box("multiband seed=7 bands=0.5,1 ridged octaves=3 gain=0.5");
    let _ = match text.parse::<Spec>() {
        Ok(spec) => write!(out, "{spec}"),
        Err(e) => write!(out, "{e}"),
    };
    // Any configuration error (the optimiser cannot see which), printed.
    let _ = write!(
        out,
        "{}",
        black_box(Error::ClampedMean(black_box(f32::NAN)))
    );
    black_box(out.0);
    loop {}
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    // SAFETY: never called when the link succeeds: that is what this program proves.
    unsafe { bandnoise_sampling_can_panic() }
}
