//! The wgpu runner: renders the tutorial's shadow scene from compiled
//! shaders, headless, and checks it against a CPU reference.
//!
//! - [`tutorial`]: the tutorial scene's numbers (sizes, the sun's orbit, the camera);
//! - [`scene`]: the host side (meshes, GL-convention matrices, uniform values);
//! - [`interface`]: fits a program's reflection to the scene (every binding,
//!   offset and attribute location the renderer uses comes from there);
//! - [`gpu`]: the wgpu renderer ([`Renderer`], [`ShaderSet`]);
//! - [`reference`]: the CPU ray-cast reference with exact sun visibility;
//! - [`image_ops`]: comparisons, shadow masks, PNG and GIF output;
//! - [`hand`]: the hand-written WGSL port and its reflection;
//! - `cli`: the `umbrac render` command (feature `cli`).
//!
//! ```no_run
//! use umbrac::render::{hand, reference, image_ops, FrameParams, Renderer, Backend};
//! let renderer = Renderer::new(Backend::Vulkan)?;
//! let params = FrameParams::new(2.0, 160, 120);
//! let gpu = renderer.render(&hand::shader_set(), &params)?;
//! let cpu = reference::render(&params);
//! println!("{}", image_ops::diff(&gpu, &cpu, 24));
//! # Ok::<(), umbrac::render::RenderError>(())
//! ```

pub mod consumers;
#[cfg(feature = "gl")]
pub mod gl;
pub mod glsl_set;
pub mod gpu;
pub mod hand;
pub mod image_ops;
pub mod interface;
pub mod reference;
pub mod scene;
pub mod setup;
mod setup_gpu;
pub mod techniques;
pub mod tutorial;
pub mod webgl;

#[cfg(feature = "cli")]
pub mod cli;

pub use gpu::{Backend, Program, RenderError, Renderer, ShaderCode, ShaderSet, Via};
pub use scene::{FrameParams, View};
pub use setup::{DepthFormat, Filter, Fit, Light, Quality, Setup, ShadowOptions, World};
