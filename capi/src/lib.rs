//! bandnoise from C: any noise the runtime description names (`bandnoise::spec`, its text
//! form), built into storage the caller provides, sampled in 1–4 dimensions in `float` and in
//! 16.16 fixed point, with gradients, and evaluated over grids. The header is
//! `include/bandnoise.h`, generated from this file by cbindgen (`capi/cbindgen.toml`) and
//! checked against it by `cargo test -p bandnoise-capi`.
//!
//! # Contract
//!
//! - **No allocation.** A `bn_noise` is a plain struct of `BN_NOISE_WORDS` 64-bit words: put
//!   it on the stack, in a static or in your own heap, and [`bn_noise_init`] builds the noise
//!   into it. It needs no freeing and may be copied byte for byte (it holds no pointer into
//!   itself, only to the library's constant tables).
//! - **Every function returns a [`bn_status`]**, and writes its result through a pointer only
//!   on `BN_OK`. Null pointers, a `bn_noise` that [`bn_noise_init`] did not fill (zeroed
//!   memory, or one whose last `bn_noise_init` failed), and buffers of the wrong length are
//!   statuses, not crashes. Coordinates are never errors: every finite, infinite or NaN
//!   coordinate has the value the Rust crate defines for it.
//! - **No panic crosses into C.** The noises are proven panic-free on firmware (the Rust
//!   `nopanic` programs, and this library's C example linked with `prove-no-panic`); on a
//!   host the `std` feature also catches any panic and returns `BN_ERROR_INTERNAL`.
//! - **Values are the Rust crate's, bit for bit**, in `float` and in fixed point, on every
//!   target: the C example prints the same checksums as the crate's `checks`.
//!
//! # Example
//!
//! ```c
//! #include "bandnoise.h"
//!
//! bn_noise noise;
//! bn_error error;
//! if (bn_noise_init(&noise, "perlin seed=7 fbm octaves=5", 2, &error) != BN_OK) {
//!     fprintf(stderr, "%s\n", error.message);  /* "at byte 19: expected ..." */
//!     return 1;
//! }
//! float p[2] = {0.3f, 1.7f}, v;
//! bn_sample_f32(&noise, p, &v);
//! int32_t q[2] = {19661, 111411}, w;  /* 0.3 and 1.7 in 16.16 */
//! bn_sample_fixed(&noise, q, &w);
//! ```
//!
//! # Features
//!
//! `std` (default): a host library; any panic becomes `BN_ERROR_INTERNAL`. Without it the
//! library is `no_std` for firmware (`thumbv6m-none-eabi` and the like). `small-tiles`: the
//! wavelet noises use the quantized tiles (72 KiB of coefficients in flash instead of 144 KiB;
//! slightly different values, those of the crate's `I16Tiles`). `dim1` … `dim4` (default: all):
//! the dimensions a noise can be built for; firmware that needs fewer links less code (each
//! dimension's noises are a separate compilation of every noise), and `bn_noise_init` refuses
//! the others with `BN_ERROR_DIMENSION`. `prove-no-panic` (firmware):
//! the panic handler calls a function that does not exist, so a program in which any panic is
//! reachable fails to link.
#![cfg_attr(not(feature = "std"), no_std)]
#![deny(missing_docs, unsafe_op_in_unsafe_fn)]
#![allow(non_camel_case_types, reason = "C names, as the header spells them")]

use core::ffi::{CStr, c_char};
use core::fmt::{self, Write};
use core::mem::{align_of, size_of};

use bandnoise::batch::Grid;
use bandnoise::spec::{Spec, SpecNoise};
use bandnoise::{Error, I16F16, NoiseGradient, Real};

mod prefix;
use prefix::Prefix;

/// The wavelet tiles the library is built with.
#[cfg(not(feature = "small-tiles"))]
type Tiles = bandnoise::spec::F32Tiles;
/// The wavelet tiles the library is built with.
#[cfg(feature = "small-tiles")]
type Tiles = bandnoise::spec::I16Tiles;

/// The size of a `bn_noise`, in 64-bit words (the largest built noise, 4D, with room for the
/// library's own marker; checked at compile time on every target).
pub const BN_NOISE_WORDS: usize = 176;

/// The size of `bn_error`'s message, in bytes, its terminating NUL included.
pub const BN_MESSAGE_BYTES: usize = 512;

/// Storage for one noise: fill it with [`bn_noise_init`]. Its contents are private.
#[repr(C)]
pub struct bn_noise {
    /// Private.
    pub opaque: [u64; BN_NOISE_WORDS],
}

/// What a function did.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum bn_status {
    /// Done; the results were written.
    BN_OK = 0,
    /// The description's text is not one (`bn_error` says at which byte and what was expected
    /// there), or a value in it is out of range.
    BN_ERROR_TEXT = 1,
    /// The description does not build in that many dimensions (wavelet noise is 2D or 3D, a
    /// period names another number of axes), or the dimension is not 1 to 4.
    BN_ERROR_DIMENSION = 2,
    /// A pointer that must not be null was null.
    BN_ERROR_NULL = 3,
    /// The `bn_noise` was not filled by a successful [`bn_noise_init`].
    BN_ERROR_NOT_INITIALISED = 4,
    /// A buffer's length is not what the call needs (a grid's point count, the text's length).
    BN_ERROR_BUFFER = 5,
    /// A panic inside the library (a bug: none is known, and firmware builds prove there is
    /// none); the results were not written.
    BN_ERROR_INTERNAL = 6,
}

use bn_status::*;

/// Why [`bn_noise_init`] failed.
#[repr(C)]
pub struct bn_error {
    /// The status [`bn_noise_init`] returned.
    pub status: bn_status,
    /// For `BN_ERROR_TEXT`, the byte offset in the text where the problem is; otherwise 0.
    pub position: u32,
    /// A NUL-terminated UTF-8 message: "at byte 19: expected a setting (seed=, …)",
    /// "wavelet noise has no 1D form". Empty on success; cut at a character boundary if long.
    pub message: [c_char; BN_MESSAGE_BYTES],
}

#[cfg(not(any(feature = "dim1", feature = "dim2", feature = "dim3", feature = "dim4")))]
compile_error!("bandnoise-capi needs at least one of the features dim1, dim2, dim3, dim4");

/// A noise built for 1 to 4 dimensions (those the features `dim1` … `dim4` keep).
#[derive(Clone, Debug)]
enum Built {
    #[cfg(feature = "dim1")]
    D1(SpecNoise<1, Tiles>),
    #[cfg(feature = "dim2")]
    D2(SpecNoise<2, Tiles>),
    #[cfg(feature = "dim3")]
    D3(SpecNoise<3, Tiles>),
    #[cfg(feature = "dim4")]
    D4(SpecNoise<4, Tiles>),
}

/// What a `bn_noise` holds once initialised: the marker first, so that an uninitialised one
/// is recognised by reading a plain integer.
#[repr(C)]
struct Stored {
    marker: u32,
    built: Built,
}

/// The marker of an initialised `bn_noise` ("bnoi").
const MARKER: u32 = 0x696F_6E62;

// A `Stored` is overwritten without being dropped and may be copied by `memcpy`: the crate
// allocates nothing and holds no resource (`no_std`, no `alloc`; its only pointers are to
// `'static` tables), so no drop is skipped that would free anything.
const _: () = {
    assert!(size_of::<Stored>() <= size_of::<bn_noise>());
    assert!(align_of::<Stored>() <= align_of::<bn_noise>());
};

/// Runs `f`, turning a panic into `BN_ERROR_INTERNAL` when the standard library is there.
fn guard(f: impl FnOnce() -> bn_status) -> bn_status {
    #[cfg(feature = "std")]
    {
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).unwrap_or(BN_ERROR_INTERNAL)
    }
    #[cfg(not(feature = "std"))]
    {
        f()
    }
}

/// The noise in `noise`, if it is an initialised `bn_noise`.
///
/// # Safety
///
/// `noise` is null or points to a readable `bn_noise`.
unsafe fn built<'a>(noise: *const bn_noise) -> Result<&'a Built, bn_status> {
    if noise.is_null() {
        return Err(BN_ERROR_NULL);
    }
    // SAFETY: `noise` is a readable `bn_noise`, aligned to 8, and every bit pattern of its
    // first four bytes is a `u32`.
    let marker = unsafe { noise.cast::<u32>().read() };
    if marker != MARKER {
        return Err(BN_ERROR_NOT_INITIALISED);
    }
    // SAFETY: only `bn_noise_init` writes the marker, together with a valid `Stored` (size and
    // alignment checked above), and it clears the marker before building.
    Ok(unsafe { &(*noise.cast::<Stored>()).built })
}

/// Fills `error` (if not null) with `status`, `position` and the message `what` prints.
///
/// # Safety
///
/// `error` is null or points to a writable `bn_error`.
unsafe fn report(
    error: *mut bn_error,
    status: bn_status,
    position: usize,
    what: &dyn fmt::Display,
) -> bn_status {
    // SAFETY: the caller's contract.
    if let Some(error) = unsafe { error.as_mut() } {
        error.status = status;
        error.position = u32::try_from(position).unwrap_or(u32::MAX);
        let mut m = Prefix::new(&mut error.message);
        // `Prefix` never fails; a failing `Display` leaves what it wrote. A message too long
        // for the buffer is its longest prefix.
        let _ = write!(m, "{what}");
        m.finish();
    }
    status
}

/// Builds the noise described by `text` (the runtime description's text form, e.g.
/// `"perlin seed=7 fbm octaves=5"`; its grammar and settings are in capi/README.md and the
/// Rust crate's `bandnoise::spec` documentation) for `dims` dimensions into `noise`.
///
/// Returns `BN_OK`, or `BN_ERROR_TEXT` (bad text or a value out of range),
/// `BN_ERROR_DIMENSION` (the noise has no `dims`-dimensional form, `dims` not 1–4), or
/// `BN_ERROR_NULL` (`noise` or `text` null). On failure `noise` is left uninitialised (every
/// other function refuses it) and, if `error` is not null, `*error` says why; on success
/// `*error` holds `BN_OK` and an empty message.
///
/// # Safety
///
/// `noise` is null or points to a writable `bn_noise`; `text` is null or a NUL-terminated
/// string; `error` is null or points to a writable `bn_error`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn bn_noise_init(
    noise: *mut bn_noise,
    text: *const c_char,
    dims: u32,
    error: *mut bn_error,
) -> bn_status {
    guard(|| {
        if noise.is_null() || text.is_null() {
            // SAFETY: the caller's contract.
            return unsafe { report(error, BN_ERROR_NULL, 0, &"a null pointer") };
        }
        // SAFETY: `noise` is a writable `bn_noise`, aligned for a `u32`.
        unsafe { noise.cast::<u32>().write(0) };
        // SAFETY: `text` is a NUL-terminated string.
        let text = unsafe { CStr::from_ptr(text) };
        let text = match text.to_str() {
            Ok(text) => text,
            Err(e) => {
                let at = e.valid_up_to();
                let what = format_args!("at byte {at}: the text is not UTF-8");
                // SAFETY: the caller's contract.
                return unsafe { report(error, BN_ERROR_TEXT, at, &what) };
            }
        };
        let spec: Spec = match text.parse() {
            Ok(spec) => spec,
            // SAFETY: the caller's contract.
            Err(e) => return unsafe { report(error, BN_ERROR_TEXT, e.position(), &e) },
        };
        let built = match dims {
            #[cfg(feature = "dim1")]
            1 => spec.build_with::<1, Tiles>().map(Built::D1),
            #[cfg(feature = "dim2")]
            2 => spec.build_with::<2, Tiles>().map(Built::D2),
            #[cfg(feature = "dim3")]
            3 => spec.build_with::<3, Tiles>().map(Built::D3),
            #[cfg(feature = "dim4")]
            4 => spec.build_with::<4, Tiles>().map(Built::D4),
            #[allow(
                unreachable_patterns,
                reason = "reached when a dimension's feature is off"
            )]
            1..=4 => {
                let what = format_args!("this library was built without {dims}D noise");
                // SAFETY: the caller's contract.
                return unsafe { report(error, BN_ERROR_DIMENSION, 0, &what) };
            }
            _ => {
                let what = format_args!("the dimension must be 1 to 4, not {dims}");
                // SAFETY: the caller's contract.
                return unsafe { report(error, BN_ERROR_DIMENSION, 0, &what) };
            }
        };
        match built {
            Ok(built) => {
                let stored = Stored {
                    marker: MARKER,
                    built,
                };
                // SAFETY: `noise` is writable, large and aligned enough (checked above); the
                // old contents need no drop.
                unsafe { noise.cast::<Stored>().write(stored) };
                // SAFETY: the caller's contract.
                unsafe { report(error, BN_OK, 0, &"") }
            }
            // SAFETY: the caller's contract.
            Err(e) => unsafe { report(error, dimension_or_text(e), 0, &e) },
        }
    })
}

/// The status of a build error: the spec's dimensions, or (never from parsed text) a
/// setting.
fn dimension_or_text(e: Error) -> bn_status {
    match e {
        Error::Dimension { .. } | Error::PeriodAxes { .. } => BN_ERROR_DIMENSION,
        _ => BN_ERROR_TEXT,
    }
}

/// The number of dimensions `noise` was built for, or 0 if it is null or not initialised.
///
/// # Safety
///
/// `noise` is null or points to a readable `bn_noise`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn bn_noise_dims(noise: *const bn_noise) -> u32 {
    // SAFETY: the caller's contract.
    match unsafe { built(noise) } {
        #[cfg(feature = "dim1")]
        Ok(Built::D1(_)) => 1,
        #[cfg(feature = "dim2")]
        Ok(Built::D2(_)) => 2,
        #[cfg(feature = "dim3")]
        Ok(Built::D3(_)) => 3,
        #[cfg(feature = "dim4")]
        Ok(Built::D4(_)) => 4,
        Err(_) => 0,
    }
}

/// Writes the description of `noise` in its full text form (every setting of each layer, so
/// it keeps its meaning if a default changes), NUL-terminated, into `text[0..len]`.
///
/// Returns `BN_ERROR_BUFFER` if it does not fit in `len` bytes with its NUL (then `text` holds
/// as much as fits, NUL-terminated, when `len > 0`), or the errors of a `bn_noise`.
///
/// # Safety
///
/// `noise` is null or points to a readable `bn_noise`; `text` is null or points to `len`
/// writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn bn_noise_text(
    noise: *const bn_noise,
    text: *mut c_char,
    len: usize,
) -> bn_status {
    guard(|| {
        // SAFETY: the caller's contract.
        let built = match unsafe { built(noise) } {
            Ok(built) => built,
            Err(status) => return status,
        };
        if text.is_null() {
            return BN_ERROR_NULL;
        }
        if len == 0 {
            return BN_ERROR_BUFFER;
        }
        // SAFETY: `text` points to `len > 0` writable bytes.
        let out = unsafe { core::slice::from_raw_parts_mut(text, len) };
        let spec = match built {
            #[cfg(feature = "dim1")]
            Built::D1(n) => n.spec(),
            #[cfg(feature = "dim2")]
            Built::D2(n) => n.spec(),
            #[cfg(feature = "dim3")]
            Built::D3(n) => n.spec(),
            #[cfg(feature = "dim4")]
            Built::D4(n) => n.spec(),
        };
        let mut w = Prefix::new(out);
        let _ = write!(w, "{spec}");
        if w.finish() { BN_OK } else { BN_ERROR_BUFFER }
    })
}

/// A number type of the C interface: its C representation and the crate's type, which has
/// the same layout (a C buffer of `Self` is a buffer of `R`).
///
/// # Safety
///
/// `Self` and `R` have the same size, alignment and valid bit patterns.
unsafe trait CReal: Copy {
    type R: Real;
    fn to_real(self) -> Self::R;
    fn from_real(r: Self::R) -> Self;
}

// SAFETY: the same type.
unsafe impl CReal for f32 {
    type R = f32;
    fn to_real(self) -> f32 {
        self
    }
    fn from_real(r: f32) -> f32 {
        r
    }
}

/// 16.16 fixed point: the bits of an `I16F16`.
// SAFETY: `I16F16` is `#[repr(transparent)]` over an `i32` (the `fixed` crate's documented
// layout), and every `i32` is one.
unsafe impl CReal for i32 {
    type R = I16F16;
    fn to_real(self) -> I16F16 {
        I16F16::from_bits(self)
    }
    fn from_real(r: I16F16) -> i32 {
        r.to_bits()
    }
}

/// Reads `D` coordinates from `p`.
///
/// # Safety
///
/// `p` points to `D` readable values.
unsafe fn read<C: CReal, const D: usize>(p: *const C) -> [C::R; D] {
    // SAFETY: the caller's contract: `p.add(a)` for `a < D` is in the array.
    core::array::from_fn(|a| unsafe { p.add(a).read() }.to_real())
}

/// One operation on the built noise, generic over its dimension.
trait Op<C: CReal> {
    /// # Safety
    ///
    /// As the public function that runs it.
    unsafe fn run<const D: usize, N>(self, n: &N) -> bn_status
    where
        N: NoiseGradient<C::R, D>;
}

/// Runs `op` on the noise in `noise` in its dimension.
///
/// # Safety
///
/// `noise` is null or points to a readable `bn_noise`; `op`'s pointers are valid for the
/// noise's dimension.
unsafe fn dispatch<C: CReal, O: Op<C>>(noise: *const bn_noise, op: O) -> bn_status
where
    SpecNoise<1, Tiles>: NoiseGradient<C::R, 1>,
    SpecNoise<2, Tiles>: NoiseGradient<C::R, 2>,
    SpecNoise<3, Tiles>: NoiseGradient<C::R, 3>,
    SpecNoise<4, Tiles>: NoiseGradient<C::R, 4>,
{
    guard(|| {
        // SAFETY: the caller's contract, passed on.
        unsafe {
            match built(noise) {
                #[cfg(feature = "dim1")]
                Ok(Built::D1(n)) => op.run::<1, _>(n),
                #[cfg(feature = "dim2")]
                Ok(Built::D2(n)) => op.run::<2, _>(n),
                #[cfg(feature = "dim3")]
                Ok(Built::D3(n)) => op.run::<3, _>(n),
                #[cfg(feature = "dim4")]
                Ok(Built::D4(n)) => op.run::<4, _>(n),
                Err(status) => status,
            }
        }
    })
}

/// Samples at a point.
struct Sample<C> {
    point: *const C,
    value: *mut C,
}

impl<C: CReal> Op<C> for Sample<C> {
    unsafe fn run<const D: usize, N: NoiseGradient<C::R, D>>(self, n: &N) -> bn_status {
        if self.point.is_null() || self.value.is_null() {
            return BN_ERROR_NULL;
        }
        // SAFETY: `point` holds `D` values, `value` is writable (the public contract).
        unsafe { self.value.write(C::from_real(n.sample(read(self.point)))) };
        BN_OK
    }
}

/// Samples with the gradient at a point.
struct Gradient<C> {
    point: *const C,
    value: *mut C,
    gradient: *mut C,
}

impl<C: CReal> Op<C> for Gradient<C> {
    unsafe fn run<const D: usize, N: NoiseGradient<C::R, D>>(self, n: &N) -> bn_status {
        if self.point.is_null() || self.value.is_null() || self.gradient.is_null() {
            return BN_ERROR_NULL;
        }
        // SAFETY: `point` holds `D` values.
        let (v, g) = n.sample_with_gradient(unsafe { read(self.point) });
        // SAFETY: `value` is writable, `gradient` has room for `D` values.
        unsafe {
            self.value.write(C::from_real(v));
            for (a, &d) in g.iter().enumerate() {
                self.gradient.add(a).write(C::from_real(d));
            }
        }
        BN_OK
    }
}

/// Fills a grid.
struct FillGrid<C> {
    origin: *const C,
    step: *const C,
    size: *const usize,
    out: *mut C,
    len: usize,
}

impl<C: CReal> Op<C> for FillGrid<C> {
    unsafe fn run<const D: usize, N: NoiseGradient<C::R, D>>(self, n: &N) -> bn_status {
        if self.origin.is_null() || self.step.is_null() || self.size.is_null() {
            return BN_ERROR_NULL;
        }
        if self.out.is_null() && self.len > 0 {
            return BN_ERROR_NULL;
        }
        // SAFETY: `origin`, `step` and `size` hold `D` values each.
        let grid = unsafe {
            Grid::new(
                read(self.origin),
                read(self.step),
                core::array::from_fn(|a| self.size.add(a).read()),
            )
        };
        if grid.len() != self.len {
            return BN_ERROR_BUFFER;
        }
        if self.len == 0 {
            return BN_OK;
        }
        if self.len > isize::MAX as usize / size_of::<C>() {
            return BN_ERROR_BUFFER;
        }
        // SAFETY: `out` points to `len` writable values of `C`, whose layout is `C::R`'s
        // (`CReal`'s contract), and nothing else refers to them during the call.
        let out = unsafe { core::slice::from_raw_parts_mut(self.out.cast::<C::R>(), self.len) };
        match n.fill_grid(&grid, out) {
            Ok(()) => BN_OK,
            Err(_) => BN_ERROR_BUFFER,
        }
    }
}

/// Samples `noise` at `point` (`bn_noise_dims(noise)` coordinates) into `*value`.
///
/// Returns `BN_OK`, `BN_ERROR_NULL` or `BN_ERROR_NOT_INITIALISED`.
///
/// # Safety
///
/// `noise` is null or points to a readable `bn_noise`; `point` is null or points to
/// `bn_noise_dims(noise)` readable floats; `value` is null or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn bn_sample_f32(
    noise: *const bn_noise,
    point: *const f32,
    value: *mut f32,
) -> bn_status {
    // SAFETY: the caller's contract.
    unsafe { dispatch(noise, Sample { point, value }) }
}

/// [`bn_sample_f32`] in 16.16 fixed point: each coordinate and the value are the bits of a
/// signed 16.16 number (`x · 65536`), computed in fixed point throughout (no FPU needed).
///
/// # Safety
///
/// As [`bn_sample_f32`], with `int32_t`s.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn bn_sample_fixed(
    noise: *const bn_noise,
    point: *const i32,
    value: *mut i32,
) -> bn_status {
    // SAFETY: the caller's contract.
    unsafe { dispatch(noise, Sample { point, value }) }
}

/// Samples `noise` at `point` into `*value` and its gradient (`bn_noise_dims(noise)`
/// partial derivatives) into `gradient` (analytic for most noises, central differences for
/// the textures and flow noise's fBm, as in the crate).
///
/// # Safety
///
/// As [`bn_sample_f32`]; `gradient` is null or points to `bn_noise_dims(noise)` writable
/// floats.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn bn_sample_gradient_f32(
    noise: *const bn_noise,
    point: *const f32,
    value: *mut f32,
    gradient: *mut f32,
) -> bn_status {
    // SAFETY: the caller's contract.
    unsafe {
        dispatch(
            noise,
            Gradient {
                point,
                value,
                gradient,
            },
        )
    }
}

/// [`bn_sample_gradient_f32`] in 16.16 fixed point.
///
/// # Safety
///
/// As [`bn_sample_gradient_f32`], with `int32_t`s.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn bn_sample_gradient_fixed(
    noise: *const bn_noise,
    point: *const i32,
    value: *mut i32,
    gradient: *mut i32,
) -> bn_status {
    // SAFETY: the caller's contract.
    unsafe {
        dispatch(
            noise,
            Gradient {
                point,
                value,
                gradient,
            },
        )
    }
}

/// Fills `out[0..len]` with `noise` over a grid: point `(i₀, i₁, …)` is at
/// `origin[a] + iₐ · step[a]` and goes to `out[i₀ + size[0] · (i₁ + size[1] · …)]` (axis 0
/// fastest). `origin`, `step` and `size` hold `bn_noise_dims(noise)` values each. Each value
/// equals [`bn_sample_f32`] at its point, bit for bit, computed by the crate's batch
/// kernels.
///
/// Returns `BN_ERROR_BUFFER` unless `len` is the number of points (`out` is then untouched),
/// `BN_ERROR_NULL`, or `BN_ERROR_NOT_INITIALISED`.
///
/// # Safety
///
/// `noise` is null or points to a readable `bn_noise`; `origin`, `step` and `size` are null or
/// point to `bn_noise_dims(noise)` readable values; `out` is null or points to `len` writable
/// floats.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn bn_fill_grid_f32(
    noise: *const bn_noise,
    origin: *const f32,
    step: *const f32,
    size: *const usize,
    out: *mut f32,
    len: usize,
) -> bn_status {
    let op = FillGrid {
        origin,
        step,
        size,
        out,
        len,
    };
    // SAFETY: the caller's contract.
    unsafe { dispatch(noise, op) }
}

/// [`bn_fill_grid_f32`] in 16.16 fixed point (`origin`, `step` and the values).
///
/// # Safety
///
/// As [`bn_fill_grid_f32`], with `int32_t`s.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn bn_fill_grid_fixed(
    noise: *const bn_noise,
    origin: *const i32,
    step: *const i32,
    size: *const usize,
    out: *mut i32,
    len: usize,
) -> bn_status {
    let op = FillGrid {
        origin,
        step,
        size,
        out,
        len,
    };
    // SAFETY: the caller's contract.
    unsafe { dispatch(noise, op) }
}

/// Firmware's panic handler: never reached (the noises are panic-free), it stops.
#[cfg(all(not(feature = "std"), not(test), not(feature = "prove-no-panic")))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    loop {}
}

/// The no-panic proof's panic handler: a call to a function no program defines, so linking
/// fails if any panic is reachable from the functions a program uses.
#[cfg(all(not(feature = "std"), not(test), feature = "prove-no-panic"))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    unsafe extern "C" {
        /// Not defined anywhere.
        fn bandnoise_c_has_a_reachable_panic() -> !;
    }
    // SAFETY: never linked: a program that reaches this fails to link.
    unsafe { bandnoise_c_has_a_reachable_panic() }
}
