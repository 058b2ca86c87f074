//! The library's C strings cut to the caller's buffer (`src/prefix.rs`, compiled here as a
//! module of this test: its cuts at character boundaries are not reachable from the C
//! interface, whose texts fit or are ASCII).

use std::ffi::c_char;
use std::fmt::Write;

#[path = "../../src/prefix.rs"]
mod source;

use bandnoise_c::BN_MESSAGE_BYTES;
use source::Prefix;

#[test]
fn a_long_message_is_its_longest_prefix_that_fits() {
    let mut out = [0x55 as c_char; BN_MESSAGE_BYTES];
    let mut m = Prefix::new(&mut out);
    // 509 ASCII bytes and "é" (2 bytes) fill bytes 0..511, leaving the last for the NUL;
    // "€" (3 bytes) does not fit, and the "x" after it, which would, is not written.
    let text = format!("{}é€x", "a".repeat(509));
    write!(m, "{text}").expect("never fails");
    assert!(!m.finish(), "the text was cut");
    assert_eq!(out[511], 0);
    let written: Vec<u8> = out[..511].iter().map(|&c| c as u8).collect();
    assert_eq!(written, format!("{}é", "a".repeat(509)).into_bytes());
}

#[test]
fn a_prefix_that_fits_ends_with_its_nul() {
    let mut out = [0x55 as c_char; 6];
    let mut m = Prefix::new(&mut out);
    write!(m, "abcde").expect("never fails");
    assert!(m.finish());
    assert_eq!(out.map(|c| c as u8), *b"abcde\0");
    // One byte more does not fit: the NUL keeps the last byte.
    let mut m = Prefix::new(&mut out);
    write!(m, "abcdef").expect("never fails");
    assert!(!m.finish());
    assert_eq!(out.map(|c| c as u8), *b"abcde\0");
    // An empty buffer takes nothing, not even the NUL.
    let mut m = Prefix::new(&mut []);
    write!(m, "a").expect("never fails");
    assert!(!m.finish());
}
