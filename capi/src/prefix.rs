//! The C strings the library writes (error messages, a noise's text): whatever is printed,
//! cut to the caller's buffer. Its tests are in `tests/capi/prefix.rs`, which includes this
//! file (the library's own test build is off: capi/Cargo.toml).

use core::ffi::c_char;
use core::fmt::{self, Write};

/// Writes into a C string buffer the longest prefix of what is printed that fits with its NUL,
/// cut at a character boundary: after one character did not fit, none after it is written.
/// [`Prefix::finish`] writes the NUL and says whether everything fitted.
pub(crate) struct Prefix<'a> {
    out: &'a mut [c_char],
    len: usize,
    full: bool,
}

impl<'a> Prefix<'a> {
    pub(crate) fn new(out: &'a mut [c_char]) -> Self {
        Self {
            out,
            len: 0,
            full: false,
        }
    }

    /// Ends the string with its NUL (an empty buffer gets none); `true` if nothing was cut.
    pub(crate) fn finish(self) -> bool {
        if let Some(nul) = self.out.get_mut(self.len) {
            *nul = 0;
        }
        !self.full
    }
}

impl Write for Prefix<'_> {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        for c in s.chars() {
            let mut utf8 = [0u8; 4];
            let bytes = c.encode_utf8(&mut utf8).as_bytes();
            let end = self.len + bytes.len();
            // The last byte is the NUL's.
            let room = self.out.len();
            let slots = match self.out.get_mut(self.len..end) {
                Some(slots) if !self.full && end < room => slots,
                _ => {
                    self.full = true;
                    return Ok(());
                }
            };
            for (slot, &b) in slots.iter_mut().zip(bytes) {
                *slot = b as c_char;
            }
            self.len = end;
        }
        Ok(())
    }
}
