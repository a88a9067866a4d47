//! The wgpu runner: renders the shadow scene from compiled shaders.

#[cfg(feature = "cli")]
pub mod cli;
