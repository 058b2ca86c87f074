//! Computes every checksum of `bandnoise-checks` on RV32IMC and compares it with the host's;
//! prints through the virt machine's ns16550 UART and exits through its test device.
#![no_std]
#![no_main]

use core::fmt::Write;
use core::panic::PanicInfo;

use bandnoise_checks::{COUNT, compare};

include!(concat!(env!("OUT_DIR"), "/expected.rs"));

/// The virt machine's UART transmit register.
const UART: *mut u8 = 0x1000_0000 as *mut u8;
/// The virt machine's test device: 0x5555 passes, `(code << 16) | 0x3333` fails.
const TEST_DEVICE: *mut u32 = 0x0010_0000 as *mut u32;

struct Uart;

impl Write for Uart {
    fn write_str(&mut self, s: &str) -> core::fmt::Result {
        for b in s.bytes() {
            // SAFETY: the virt machine maps a 16550 UART here; writing THR sends a byte.
            unsafe { UART.write_volatile(b) };
        }
        Ok(())
    }
}

fn exit(success: bool) -> ! {
    let code = if success { 0x5555 } else { (1 << 16) | 0x3333 };
    // SAFETY: the virt machine's test device; the write ends the emulation.
    unsafe { TEST_DEVICE.write_volatile(code) };
    loop {}
}

#[riscv_rt::entry]
fn main() -> ! {
    let bad = compare(&EXPECTED, |ty, name, got, host| {
        let _ = writeln!(Uart, "MISMATCH {ty} {name}: {got:08x}, host {host:08x}");
    });
    let _ = writeln!(
        Uart,
        "riscv32imc: {COUNT} checksums, {bad} differ from the host"
    );
    exit(bad == 0)
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    let _ = writeln!(Uart, "panic");
    exit(false)
}
