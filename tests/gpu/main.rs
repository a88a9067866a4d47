//! The integration tests that draw: on wgpu (Vulkan, and its GL backend),
//! on OpenGL 3.3 and OpenGL ES 3.0 contexts, in WebGL2 (headless chromium),
//! against the CPU reference. One binary, so that the crate, wgpu, glow and
//! image are linked once, and one Vulkan device (`support::gpu`) serves
//! every test in it. A consumer that is not installed is skipped with a
//! message, except with `CI=true`, where the test fails.
//!
//!     cargo test --test gpu                 # this binary
//!     cargo test --test gpu consumers::     # one module

#[path = "../support/mod.rs"]
mod support;

#[cfg(all(feature = "render", feature = "gl"))]
mod any_program;
#[cfg(all(feature = "render", feature = "gl"))]
mod compute;
#[cfg(feature = "gl")]
mod consumers;
#[cfg(feature = "gl")]
mod device_limits;
#[cfg(feature = "render")]
mod differential;
#[cfg(feature = "gl")]
mod gl_interop;
#[cfg(feature = "render")]
mod language_f;
mod features_l;
#[cfg(feature = "render")]
mod numerics;
#[cfg(all(feature = "preview", feature = "render"))]
mod page_vs_render;
#[cfg(feature = "preview")]
mod preview;
#[cfg(all(feature = "preview", feature = "render"))]
mod preview_passes;
#[cfg(feature = "render")]
mod programs;
#[cfg(feature = "render")]
mod render;
#[cfg(all(feature = "render", feature = "gl"))]
mod scene_files;
#[cfg(all(feature = "render", feature = "gl"))]
mod techniques;
#[cfg(feature = "render")]
mod uniforms;
#[cfg(feature = "render")]
mod visible_fit;
#[cfg(all(feature = "render", feature = "gl"))]
mod vk_shadow;
#[cfg(all(feature = "render", feature = "gl"))]
mod vk_tutorials;
