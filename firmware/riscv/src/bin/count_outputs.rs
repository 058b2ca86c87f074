//! The output workloads of `scripts/count-instructions.sh` (`bandnoise_checks::count::run_outputs`).
#![no_std]
#![no_main]

use core::panic::PanicInfo;

/// The virt machine's test device: 0x5555 passes.
const TEST_DEVICE: *mut u32 = 0x0010_0000 as *mut u32;

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

fn exit(code: u32) -> ! {
    // SAFETY: the virt machine's test device; the write ends the emulation.
    unsafe { TEST_DEVICE.write_volatile(code) };
    loop {}
}

#[riscv_rt::entry]
fn main() -> ! {
    core::hint::black_box(bandnoise_checks::count::run_outputs(
        bandnoise_mark_begin,
        bandnoise_mark_end,
    ));
    exit(0x5555)
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    exit((1 << 16) | 0x3333)
}
