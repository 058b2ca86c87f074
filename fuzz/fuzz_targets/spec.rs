//! The text form of `bandnoise::spec`: any bytes either parse to a spec whose printed text
//! parses back to it, or give an error whose position lies within the text; whatever parses
//! builds (or is refused) and samples a finite value within its bound.

#![no_main]

use bandnoise::spec::Spec;
use bandnoise::{Noise, NoiseGradient};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = core::str::from_utf8(data) else {
        return;
    };
    match text.parse::<Spec>() {
        Err(e) => {
            assert!(e.position() <= text.len(), "{text:?}: {e}");
            assert!(text.is_char_boundary(e.position()), "{text:?}: {e}");
        }
        Ok(spec) => {
            let printed = spec.to_string();
            assert_eq!(
                printed.parse::<Spec>(),
                Ok(spec),
                "{text:?} printed {printed:?}"
            );
            let p = [0.3f32, -7.7, 1.5e3];
            if let Ok(n) = spec.build::<2>() {
                let v: f32 = n.sample([p[0], p[1]]);
                assert!(v.is_finite() && v.abs() <= Noise::<f32, 2>::amplitude_bound(&n));
            }
            if let Ok(n) = spec.build::<3>() {
                let (v, g) = n.sample_with_gradient(p);
                assert!(v.is_finite() && g.iter().all(|c| c.is_finite()), "{text:?}");
            }
        }
    }
});
