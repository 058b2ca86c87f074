//! The wrapper in a real browser (headless Chromium through wasm-bindgen-test-runner):
//! `cargo test -p bandnoise-wasm --target wasm32-unknown-unknown`.
#![cfg(target_arch = "wasm32")]

use bandnoise_wasm::{Demo, Params};
use wasm_bindgen::JsCast;
use wasm_bindgen_test::*;
use web_sys::{CanvasRenderingContext2d, HtmlCanvasElement};

wasm_bindgen_test_configure!(run_in_browser);

const BANDS: [f32; 8] = [0.0, 0.0, 0.2, 0.5, 1.0, 0.5, 0.25, 0.12];

fn params(kind: &str, number: &str) -> Result<Params, String> {
    Params::new(
        kind, number, 3.0, 32.0, 0.5, -1.5, 0.25, "none", 6.0, 1.99, 0.5, &BANDS, "gaussian",
        false, "grey",
    )
}

fn canvas() -> CanvasRenderingContext2d {
    let doc = web_sys::window().unwrap().document().unwrap();
    let c: HtmlCanvasElement = doc.create_element("canvas").unwrap().dyn_into().unwrap();
    c.set_width(64);
    c.set_height(64);
    c.get_context("2d").unwrap().unwrap().dyn_into().unwrap()
}

#[wasm_bindgen_test]
fn every_noise_renders_and_draws() {
    let mut demo = Demo::new(64).unwrap();
    let ctx = canvas();
    for kind in ["perlin", "original", "value", "cnoise", "mnoise", "wavelet"] {
        for number in ["f32", "fixed"] {
            demo.render(&params(kind, number).unwrap());
            assert!(demo.std_dev() > 0.01, "{kind} {number} is flat");
            demo.draw(&ctx).unwrap();
            demo.draw_spectrum(&ctx).unwrap();
            let pixels = ctx.get_image_data(0.0, 0.0, 64.0, 64.0).unwrap().data().0;
            assert!(
                pixels.chunks(4).any(|p| p[0] != pixels[0]),
                "{kind}: uniform image"
            );
            // Nearly every value lies within ±4σ of the mean.
            let counted = demo.histogram().iter().sum::<u32>();
            assert!(
                (64 * 64 * 98 / 100..=64 * 64).contains(&counted),
                "{kind}: {counted}"
            );
        }
    }
}

#[wasm_bindgen_test]
fn fixed_point_and_f32_give_nearly_the_same_frame() {
    let (mut a, mut b) = (Demo::new(32).unwrap(), Demo::new(32).unwrap());
    a.render(&params("perlin", "f32").unwrap());
    b.render(&params("perlin", "fixed").unwrap());
    assert!((a.mean() - b.mean()).abs() < 1e-3 && (a.std_dev() - b.std_dev()).abs() < 1e-3);
}

#[wasm_bindgen_test]
fn bad_parameters_are_refused_with_a_message() {
    let bad = |r: Result<Params, String>| r.err().unwrap_or_default();
    let msg = bad(Params::new(
        "nope", "f32", 0.0, 32.0, 0.0, 0.0, 0.0, "none", 6.0, 2.0, 0.5, &BANDS, "gaussian", false,
        "grey",
    ));
    assert!(msg.contains("unknown noise kind"), "{msg}");
    let msg = bad(Params::new(
        "perlin",
        "f32",
        f64::NAN,
        32.0,
        0.0,
        0.0,
        0.0,
        "none",
        6.0,
        2.0,
        0.5,
        &BANDS,
        "gaussian",
        false,
        "grey",
    ));
    assert!(msg.contains("seed"), "{msg}");
    let msg = bad(Params::new(
        "perlin", "f32", 0.0, -1.0, 0.0, 0.0, 0.0, "none", 6.0, 2.0, 0.5, &BANDS, "gaussian",
        false, "grey",
    ));
    assert!(msg.contains("zoom"), "{msg}");
    let msg = bad(Params::new(
        "perlin", "f32", 0.0, 32.0, 1e300, 0.0, 0.0, "none", 6.0, 2.0, 0.5, &BANDS, "gaussian",
        false, "grey",
    ));
    assert!(msg.contains("pan"), "{msg}");
    let msg = bad(Params::new(
        "perlin", "f32", 0.0, 32.0, 0.0, 0.0, 0.0, "fbm", 99.0, 2.0, 0.5, &BANDS, "gaussian",
        false, "grey",
    ));
    assert!(msg.contains("octaves"), "{msg}");
    let msg = bad(Params::new(
        "wavelet", "f32", 0.0, 32.0, 0.0, 0.0, 0.0, "none", 6.0, 2.0, 0.5, &[0.0; 8], "gaussian",
        false, "grey",
    ));
    assert!(msg.contains("band weight is zero"), "{msg}");
    assert!(Demo::new(100).is_err());
}
