//! The C library's tests, one binary (each test binary links the whole library): the
//! functions called as C calls them, the committed header, the C example's table, the
//! strings cut to the caller's buffer.

mod api;
mod checks;
mod header;
mod prefix;
