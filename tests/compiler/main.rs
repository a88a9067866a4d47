//! The compiler's integration tests, in one binary so that the crate and its
//! dependencies are linked once: front end, checker, emitters, golden
//! outputs, the command line, limits and bad inputs. Nothing here needs a
//! GPU or a browser (that is tests/gpu/); the validator tests need
//! glslangValidator, spirv-val and tint (missing: skipped, or failed with
//! `CI=true`, through `support`).
//!
//!     cargo test --test compiler            # this binary
//!     cargo test --test compiler limits::   # one module
//!
//! Modules are gated on the features they need, so that `cargo test
//! --no-default-features --test compiler limits::` builds: those that run
//! the `umbrac` binary on `cli` (cargo builds the binary only with it),
//! those that read a manifest back on `deserialize`.

#[path = "../support/mod.rs"]
mod support;

#[cfg(feature = "cli")]
mod at_scale;
#[cfg(feature = "cli")]
mod bad_inputs;
#[cfg(feature = "cli")]
mod check;
#[cfg(feature = "cli")]
mod cli;
mod constants;
mod consumers_accept;
mod device_limits;
#[cfg(feature = "deserialize")]
mod emit;
mod features;
mod language_l;
#[cfg(feature = "golden")]
mod golden;
mod language_f;
#[cfg(feature = "cli")]
mod hostile_inputs;
mod limits;
#[cfg(feature = "cli")]
mod project;
#[cfg(feature = "lsp")]
mod lsp;
mod lowering;
mod modules;
#[cfg(feature = "preview")]
mod preview;
#[cfg(feature = "deserialize")]
mod programs;
mod proptest_programs;
#[cfg(feature = "cli")]
mod robustness;
#[cfg(all(feature = "cli", unix))]
mod sandbox;
mod syntax;
#[cfg(feature = "deserialize")]
mod tutorials;
#[cfg(feature = "deserialize")]
mod validate;
mod vulkan_dialect;
