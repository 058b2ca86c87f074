// The body of the `count`, `count-outputs` and `count-impulse` programs (`include!`d: each
// defines `SET`).

use core::panic::PanicInfo;

/// The virt machine's test device: 0x5555 passes.
const TEST_DEVICE: *mut u32 = 0x0010_0000 as *mut u32;

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

fn exit(code: u32) -> ! {
    // SAFETY: the virt machine's test device; the write ends the emulation.
    unsafe { TEST_DEVICE.write_volatile(code) };
    loop {}
}

#[riscv_rt::entry]
fn main() -> ! {
    // Which set is a constant of the program, so the others are not compiled in.
    let run = match SET {
        Set::Noises => bandnoise_checks::count::run,
        Set::Outputs => bandnoise_checks::count::run_outputs,
        Set::Impulse => bandnoise_checks::count::run_impulse,
    };
    core::hint::black_box(run(bandnoise_mark_begin, bandnoise_mark_end));
    exit(0x5555)
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    exit((1 << 16) | 0x3333)
}
