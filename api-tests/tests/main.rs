//! The API's tests over every noise, number type and dimension: the contract of every public
//! sampling entry point (`contract.rs`) and the runtime description sampling the typed noise it
//! describes, its text form and its coverage of the crate (`spec.rs`). One binary.
//!
//! They instantiate the noises' generic code for every combination but sample few points of
//! each, so this package is compiled unoptimised (the workspace's `Cargo.toml`): its test build
//! takes a tenth of the CPU time it took at the test profile's opt-level 2 beside the
//! statistical tests, for a slower run (figures: CHANGELOG). Overflow checks are on, as in every
//! test build (`contract::overflow_checks_are_on` fails otherwise); the values are the same bits
//! at any optimisation level.

mod contract;
mod spec;
