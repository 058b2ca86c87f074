//! Shared helpers for bandnoise's integration tests and benchmarks.
