//! Proof that sampling a runtime description cannot panic: every noise `bandnoise::spec` names
//! (every `Base`, so a noise added there is proved here unasked), with a period, a fractal sum
//! and a dimension the optimiser cannot see, point samples in 1D–4D and gradients in 3D, in
//! I16F16 and f32. Reading and printing the text form are proved in `nopanic-text`. As
//! `nopanic` (which proves the typed noises, batches included: a spec's
//! batch calls are the typed noise's), the panic handler calls a function that does not exist,
//! so any surviving panic path fails the link. Its own program because the two together exceed
//! the 256 KiB flash of the QEMU machines. Built, not run (release, thumbv7em).
#![no_std]
#![no_main]

use core::hint::black_box;
use core::panic::PanicInfo;

use bandnoise::fractal::{Kind, Octaves};
use bandnoise::spec::{Base, I16Tiles, Spec};
use bandnoise::{I16F16, Noise, NoiseGradient, Real};
use cortex_m as _;
use cortex_m_rt::entry;

unsafe extern "C" {
    /// Deliberately undefined: referenced only if a panic is reachable.
    fn bandnoise_sampling_can_panic() -> !;
}

fn described<R: Real>(acc: &mut u32, p: [R; 4]) {
    let mut add = |v: R| *acc = acc.wrapping_add(v.to_f32().to_bits());
    for base in Base::ALL {
        let mut spec = Spec::new(black_box(base), black_box(7));
        if let Ok(periodic) = spec.with_period(black_box(&[3, 65536][..])) {
            if black_box(true) {
                spec = periodic;
            }
        }
        if let Ok(o) = Octaves::new(black_box(3), black_box(2.5), black_box(-0.5)) {
            if black_box(true) {
                spec = spec.with_fractal(black_box(Kind::Turbulence), o);
            }
        }
        if let Ok(n) = spec.build_with::<1, I16Tiles>() {
            add(n.sample([p[0]]));
        }
        if let Ok(n) = spec.build_with::<2, I16Tiles>() {
            add(n.sample([p[0], p[1]]));
        }
        if let Ok(n) = spec.build_with::<3, I16Tiles>() {
            add(n.sample([p[0], p[1], p[2]]));
            add(n.sample_with_gradient([p[0], p[1], p[2]]).1[2]);
        }
        if let Ok(n) = spec.build_with::<4, I16Tiles>() {
            add(n.sample(p));
        }
    }
}

#[entry]
fn main() -> ! {
    let mut acc = 0u32;
    let bits: [i32; 4] = black_box([1, -2, 3, i32::MIN]);
    described::<I16F16>(&mut acc, bits.map(I16F16::from_bits));
    described::<f32>(&mut acc, bits.map(|b| f32::from_bits(b as u32)));
    black_box(acc);
    loop {}
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    // SAFETY: never called when the link succeeds: that is what this program proves.
    unsafe { bandnoise_sampling_can_panic() }
}
