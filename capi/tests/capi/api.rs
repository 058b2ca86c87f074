//! The C interface called as C calls it (through the `extern "C"` functions and raw
//! pointers): values bit for bit those of the crate's built spec, in `float` and 16.16; every
//! misuse a status.

use std::ffi::{CStr, CString, c_char};
use std::mem::MaybeUninit;

use bandnoise::I16F16;
use bandnoise::batch::Grid;
use bandnoise::spec::{Base, F32Tiles, Spec, SpecNoise};
use bandnoise::{Noise, NoiseGradient};
use bandnoise_c::bn_status::*;
use bandnoise_c::*;

fn noise_storage() -> Box<bn_noise> {
    Box::new(bn_noise {
        opaque: [0; BN_NOISE_WORDS],
    })
}

fn error_storage() -> Box<bn_error> {
    // SAFETY: all zeros is a `bn_error` (status BN_OK, empty message).
    Box::new(unsafe { MaybeUninit::<bn_error>::zeroed().assume_init() })
}

fn message(e: &bn_error) -> String {
    // SAFETY: the library NUL-terminates the message.
    let c = unsafe { CStr::from_ptr(e.message.as_ptr()) };
    c.to_str().expect("UTF-8").to_owned()
}

fn init(n: &mut bn_noise, text: &str, dims: u32) -> (bn_status, Box<bn_error>) {
    let text = CString::new(text).expect("no NUL");
    let mut e = error_storage();
    // SAFETY: valid pointers.
    let s = unsafe { bn_noise_init(n, text.as_ptr(), dims, &mut *e) };
    assert_eq!(s, e.status);
    (s, e)
}

/// A point from a counter, exact in f32 and 16.16.
fn point<const D: usize>(i: u32) -> [i32; D] {
    core::array::from_fn(|a| {
        let h = (i * 7 + a as u32 * 13).wrapping_mul(0x9E37_79B9) >> 8;
        (h % (40 << 16)) as i32 - (20 << 16) + 0x3333
    })
}

fn check<const D: usize>(spec: &Spec, n: &bn_noise)
where
    SpecNoise<D, F32Tiles>: NoiseGradient<f32, D> + NoiseGradient<I16F16, D>,
{
    let typed = spec.build::<D>().expect("builds");
    // SAFETY: valid pointer.
    assert_eq!(unsafe { bn_noise_dims(n) }, D as u32);
    for i in 0..40 {
        let q = point::<D>(i);
        let p: [f32; D] = q.map(|b| b as f32 / 65536.0);
        let (mut v, mut g) = (f32::NAN, [f32::NAN; D]);
        // SAFETY: `p` and `g` hold D values.
        unsafe {
            assert_eq!(bn_sample_f32(n, p.as_ptr(), &mut v), BN_OK);
            assert_eq!(typed.sample(p).to_bits(), v.to_bits(), "{spec} at {p:?}");
            assert_eq!(
                bn_sample_gradient_f32(n, p.as_ptr(), &mut v, g.as_mut_ptr()),
                BN_OK
            );
        }
        let (tv, tg) = typed.sample_with_gradient(p);
        assert_eq!(
            (tv.to_bits(), tg.map(f32::to_bits)),
            (v.to_bits(), g.map(f32::to_bits))
        );
        let (mut w, mut h) = (0i32, [0i32; D]);
        // SAFETY: `q` and `h` hold D values.
        unsafe {
            assert_eq!(bn_sample_fixed(n, q.as_ptr(), &mut w), BN_OK);
            assert_eq!(
                bn_sample_gradient_fixed(n, q.as_ptr(), &mut w, h.as_mut_ptr()),
                BN_OK
            );
        }
        let (tv, tg) = typed.sample_with_gradient(q.map(I16F16::from_bits));
        assert_eq!(
            (tv.to_bits(), tg.map(I16F16::to_bits)),
            (w, h),
            "{spec} at {q:?}"
        );
    }
    // A grid off the lattice, its step not a power-of-two fraction of a cell.
    let size: [usize; D] = core::array::from_fn(|a| [7, 3, 2, 2][a]);
    let origin: [f32; D] = core::array::from_fn(|a| 0.37 - a as f32 * 1.3);
    let step: [f32; D] = core::array::from_fn(|a| 0.173 + a as f32 * 0.05);
    let grid = Grid::new(origin, step, size);
    let mut out = vec![f32::NAN; grid.len()];
    // SAFETY: D values each, `out` has its length.
    let s = unsafe {
        bn_fill_grid_f32(
            n,
            origin.as_ptr(),
            step.as_ptr(),
            size.as_ptr(),
            out.as_mut_ptr(),
            out.len(),
        )
    };
    assert_eq!(s, BN_OK);
    let mut expected = vec![0f32; grid.len()];
    typed.fill_grid(&grid, &mut expected).expect("sized");
    assert_eq!(
        out.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        expected.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        "{spec}"
    );
    let qgrid = Grid::new(
        origin.map(I16F16::from_num),
        step.map(I16F16::from_num),
        size,
    );
    let mut fixed = vec![0i32; grid.len()];
    // SAFETY: D values each, `fixed` has its length.
    let s = unsafe {
        bn_fill_grid_fixed(
            n,
            qgrid.origin.map(I16F16::to_bits).as_ptr(),
            qgrid.step.map(I16F16::to_bits).as_ptr(),
            size.as_ptr(),
            fixed.as_mut_ptr(),
            fixed.len(),
        )
    };
    assert_eq!(s, BN_OK);
    let mut expected = vec![I16F16::ZERO; grid.len()];
    typed.fill_grid(&qgrid, &mut expected).expect("sized");
    assert_eq!(
        fixed,
        expected.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
    );
}

#[test]
fn every_base_in_each_dimension_samples_as_the_crate() {
    let mut n = noise_storage();
    for base in Base::ALL {
        for dims in 1..=4u32 {
            let spec = Spec::new(base, 11);
            let (s, e) = init(&mut n, &spec.to_string(), dims);
            if !base.has_dimension(dims as usize) {
                assert_eq!(s, BN_ERROR_DIMENSION, "{base} {dims}D");
                assert_eq!(
                    message(&e),
                    format!("{base} noise has no {dims}D form"),
                    "{base} {dims}D"
                );
                // SAFETY: valid pointer.
                assert_eq!(unsafe { bn_noise_dims(&*n) }, 0, "left uninitialised");
                continue;
            }
            assert_eq!(s, BN_OK, "{base} {dims}D: {}", message(&e));
            assert_eq!(message(&e), "");
            match dims {
                1 => check::<1>(&spec, &n),
                2 => check::<2>(&spec, &n),
                3 => check::<3>(&spec, &n),
                _ => check::<4>(&spec, &n),
            }
        }
    }
}

#[test]
fn composed_descriptions_sample_as_the_crate() {
    let mut n = noise_storage();
    for text in [
        "perlin seed=7 period=16,16 fbm octaves=4 lacunarity=2 gain=0.5",
        "multiband seed=5 first=-1 bands=0.5,1,0.5 distribution=uniform",
        "gabor seed=5 frequency=2 bandwidth=0.5 direction=1,1 orientation=anisotropic",
        "cellular seed=2 output=f2-f1 metric=manhattan jitter=0.8",
        "flow seed=3 angle=0.25 fbm octaves=5 spin=2 advection=0.5",
        "perlin seed=2 fbm octaves=5 warp=0.8",
        "marble seed=1 scale=2 variation=0.4",
    ] {
        let spec: Spec = text.parse().expect("valid");
        let (s, e) = init(&mut n, text, 2);
        assert_eq!(s, BN_OK, "{text}: {}", message(&e));
        check::<2>(&spec, &n);
        // Copied byte for byte, it is the same noise.
        let copy = bn_noise { opaque: n.opaque };
        check::<2>(&spec, &copy);
        // Its text is the spec's full form.
        let mut buf = [0 as c_char; 256];
        // SAFETY: `buf` has its length.
        assert_eq!(
            unsafe { bn_noise_text(&*n, buf.as_mut_ptr(), buf.len()) },
            BN_OK
        );
        // SAFETY: NUL-terminated.
        let printed = unsafe { CStr::from_ptr(buf.as_ptr()) }
            .to_str()
            .expect("UTF-8");
        assert_eq!(printed, spec.to_string());
        // Too short: as much as fits, and a status.
        // SAFETY: `buf` has at least 11 bytes.
        assert_eq!(
            unsafe { bn_noise_text(&*n, buf.as_mut_ptr(), 11) },
            BN_ERROR_BUFFER
        );
        // SAFETY: NUL-terminated.
        let cut = unsafe { CStr::from_ptr(buf.as_ptr()) }
            .to_str()
            .expect("UTF-8");
        assert_eq!(cut, &spec.to_string()[..10]);
    }
}

#[test]
fn bad_text_is_an_error_with_the_parsers_position_and_message() {
    let mut n = noise_storage();
    for text in [
        "",
        "perlin seed=-1",
        "perlin fbm octaves=0",
        "perlni",
        "wavelet period=4,4",
    ] {
        let (s, e) = init(&mut n, text, 2);
        let parsed = text.parse::<Spec>().expect_err("invalid");
        assert_eq!(s, BN_ERROR_TEXT, "{text}");
        assert_eq!(e.position as usize, parsed.position(), "{text}");
        assert_eq!(message(&e), parsed.to_string(), "{text}");
    }
    // Not UTF-8.
    let mut e = error_storage();
    let bytes = b"perlin seed=\xff\0";
    // SAFETY: NUL-terminated.
    let s = unsafe { bn_noise_init(&mut *n, bytes.as_ptr().cast(), 2, &mut *e) };
    assert_eq!((s, e.position), (BN_ERROR_TEXT, 12));
    assert_eq!(message(&e), "at byte 12: the text is not UTF-8");
    // Dimensions.
    for dims in [0, 5, u32::MAX] {
        let (s, e) = init(&mut n, "perlin", dims);
        assert_eq!(s, BN_ERROR_DIMENSION);
        assert_eq!(
            message(&e),
            format!("the dimension must be 1 to 4, not {dims}")
        );
    }
    let (s, e) = init(&mut n, "perlin period=4,4", 3);
    assert_eq!(s, BN_ERROR_DIMENSION);
    assert_eq!(message(&e), "2 periods given for 3 axes");
    // A null error pointer is allowed.
    let text = CString::new("perlin seed=x").expect("no NUL");
    // SAFETY: valid pointers, a null error.
    let s = unsafe { bn_noise_init(&mut *n, text.as_ptr(), 2, std::ptr::null_mut()) };
    assert_eq!(s, BN_ERROR_TEXT);
}

#[test]
fn misuse_is_a_status_not_a_crash() {
    let null = std::ptr::null_mut();
    let p = [0.5f32, 0.25, 0.0, 0.0];
    let mut v = 0f32;
    let mut e = error_storage();
    let text = CString::new("perlin").expect("no NUL");
    // SAFETY: every pointer is valid or null.
    unsafe {
        assert_eq!(
            bn_noise_init(null, text.as_ptr(), 2, &mut *e),
            BN_ERROR_NULL
        );
        assert_eq!(message(&e), "a null pointer");
        let mut n = noise_storage();
        assert_eq!(
            bn_noise_init(&mut *n, std::ptr::null(), 2, &mut *e),
            BN_ERROR_NULL
        );
        // Zeroed storage is not a noise.
        assert_eq!(
            bn_sample_f32(&*n, p.as_ptr(), &mut v),
            BN_ERROR_NOT_INITIALISED
        );
        assert_eq!(bn_noise_dims(&*n), 0);
        assert_eq!(
            bn_sample_f32(std::ptr::null(), p.as_ptr(), &mut v),
            BN_ERROR_NULL
        );
        assert_eq!(bn_noise_init(&mut *n, text.as_ptr(), 2, &mut *e), BN_OK);
        assert_eq!(bn_sample_f32(&*n, std::ptr::null(), &mut v), BN_ERROR_NULL);
        assert_eq!(bn_sample_f32(&*n, p.as_ptr(), null.cast()), BN_ERROR_NULL);
        let mut g = [0f32; 2];
        assert_eq!(
            bn_sample_gradient_f32(&*n, p.as_ptr(), &mut v, std::ptr::null_mut()),
            BN_ERROR_NULL
        );
        assert_eq!(
            bn_sample_gradient_f32(&*n, p.as_ptr(), &mut v, g.as_mut_ptr()),
            BN_OK
        );
        // A grid whose buffer is the wrong length leaves it untouched.
        let mut out = [7f32; 6];
        let size = [2usize, 3];
        let (o, st) = ([0.1f32, 0.2], [0.3f32, 0.3]);
        let fill = |out: *mut f32, len| {
            bn_fill_grid_f32(&*n, o.as_ptr(), st.as_ptr(), size.as_ptr(), out, len)
        };
        assert_eq!(fill(out.as_mut_ptr(), 5), BN_ERROR_BUFFER);
        assert_eq!(out, [7.0; 6]);
        assert_eq!(fill(null.cast(), 6), BN_ERROR_NULL);
        assert_eq!(fill(out.as_mut_ptr(), 6), BN_OK);
        assert!(out.iter().all(|&v| v != 7.0));
        // An empty grid needs no buffer.
        let empty = [0usize, 3];
        let s = bn_fill_grid_f32(&*n, o.as_ptr(), st.as_ptr(), empty.as_ptr(), null.cast(), 0);
        assert_eq!(s, BN_OK);
        // A failed init leaves the storage unusable, not the old noise.
        let bad = CString::new("perlin octaves=2").expect("no NUL");
        assert_eq!(
            bn_noise_init(&mut *n, bad.as_ptr(), 2, &mut *e),
            BN_ERROR_TEXT
        );
        assert_eq!(
            bn_sample_f32(&*n, p.as_ptr(), &mut v),
            BN_ERROR_NOT_INITIALISED
        );
        assert_eq!(bn_noise_text(&*n, null.cast(), 0), BN_ERROR_NOT_INITIALISED);
    }
}

#[test]
fn coordinates_are_never_errors() {
    let mut n = noise_storage();
    for base in Base::ALL {
        let (s, _) = init(&mut n, base.name(), 2);
        assert_eq!(s, BN_OK);
        let typed = Spec::new(base, 0).build::<2>().expect("builds");
        for p in [
            [f32::NAN, 0.5],
            [f32::INFINITY, -1.0],
            [f32::MAX, f32::MIN],
            [-0.0, 1e-40],
        ] {
            let mut v = 0f32;
            // SAFETY: valid pointers.
            assert_eq!(unsafe { bn_sample_f32(&*n, p.as_ptr(), &mut v) }, BN_OK);
            assert_eq!(v.to_bits(), typed.sample(p).to_bits(), "{base} at {p:?}");
        }
        for q in [[i32::MIN, i32::MAX], [i32::MAX, 0]] {
            let mut w = 0i32;
            // SAFETY: valid pointers.
            assert_eq!(unsafe { bn_sample_fixed(&*n, q.as_ptr(), &mut w) }, BN_OK);
            let expected = typed.sample(q.map(I16F16::from_bits)).to_bits();
            assert_eq!(w, expected, "{base} at {q:?}");
        }
    }
}
