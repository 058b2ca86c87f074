//! No library: the tests are in `tests/` (one binary, `tests/main.rs`). A package needs a
//! target; this one is empty.
