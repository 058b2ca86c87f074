//! bandnoise's integration tests, one module per file beside this one, built as one test
//! binary: one compilation and link of the noises' generic code instead of one per file (this
//! package's test build took 8 min 52 s as 26 binaries, 5 min 48 s as one, on a 2-core CI
//! machine), and one pool of test threads over all of them (`cargo test -p bandnoise-tests -- seams::` runs one file's tests).
//! Optimised (the test profile's opt-level 2): most of them sample millions of points.
//! The tests that instantiate every noise for every number type and dimension but sample few
//! points each (the contract of every entry point, the runtime description against the typed
//! noises) are in `api-tests/`, built unoptimised.
mod bad_input;
mod batch;
mod cellular;
mod derivatives;
mod filtering;
mod fractal;
mod gabor;
mod hash;
mod levels;
mod mixed;
mod opensimplex;
mod periodic;
mod projected_variance;
mod properties;
mod seams;
mod simplex;
mod sparse;
mod statistics;
mod structure;
mod texture;
mod vector;
mod wavelet;
mod white;
mod wiener;
