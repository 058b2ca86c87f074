//! wasm32 in headless Chromium computes the same checksums as the host (and as the firmware
//! under QEMU), bit for bit, in I16F16 and f32.
#![cfg(target_arch = "wasm32")]

use bandnoise_checks::{checksums, is_fixed, names};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

include!(concat!(env!("OUT_DIR"), "/expected.rs"));

#[wasm_bindgen_test]
fn wasm32_matches_the_host_bit_for_bit() {
    let got = checksums();
    let differ: Vec<String> = got
        .iter()
        .zip(EXPECTED.iter())
        .enumerate()
        .filter(|(_, (g, e))| g != e)
        .map(|(i, (g, e))| {
            let ty = if is_fixed(i) { "I16F16" } else { "f32" };
            format!("{ty} {}: {g:08x}, host {e:08x}", names()[i])
        })
        .collect();
    assert!(differ.is_empty(), "differ from the host: {differ:?}");
}
