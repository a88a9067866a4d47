//! Argument types of subcommands kept out of `main.rs`.

#[cfg(feature = "render")]
pub mod render;
