//! The library half of the `bandnoise` command: the survey's §6 analysis of a noise image
//! ([`analysis`]) and PNG output with small plots ([`image`]). The command itself is
//! `src/main.rs`; the test helpers (`bandnoise-tests`) take their 2D power spectrum from
//! [`analysis::power`].

pub mod analysis;
pub mod image;
