//! The runner: renders the tutorial's shadow scene, the technique scenes
//! and self-checking programs from compiled shaders on every consumer,
//! headless, and checks them against CPU references.
//!
//! Data flows one way: a scene describes its frame once as a
//! [`plan::FramePlan`]; [`bind`] fits a program's manifest to it (every
//! binding, offset and location comes from there); an executor in
//! [`exec`] runs it on a consumer ([`consumer::Consumer`]):
//!
//! - [`tutorial`], [`scene`], [`setup`]: the tutorial scene's numbers and
//!   host math (meshes, GL-convention matrices);
//! - [`plan`]: frame plans, and the tutorial's ([`plan::tutorial`]);
//!   [`techniques`]: the technique scenes' plans;
//! - [`program`]: a program in the form one consumer takes ([`ShaderSet`]);
//! - [`bind`]: plan + manifest -> what each pass binds, per target family;
//! - [`exec`]: the wgpu, GL and WebGL2 executors, one error type;
//! - [`consumers`]: the consumers side by side;
//! - [`reference`]: the CPU ray-cast reference with exact sun visibility;
//! - [`image_ops`]: comparisons, shadow masks, labels, PNG and GIF output;
//! - [`hand`]: the hand-written WGSL port and its reflection;
//! - [`visible`]: `--fit visible`, the light box fitted to what a compute
//!   pass measures in the camera's depth buffer;
//! - [`command`]: `umbrac render` (its options; the binary parses them).
//!
//! ```no_run
//! use umbrac::render::{consumers, hand, reference, image_ops, FrameParams, SceneExecutor};
//! let vulkan = consumers::vulkan()?;
//! let params = FrameParams::new(2.0, 160, 120);
//! let gpu = vulkan.render_scene(&hand::shader_set(), &params)?;
//! let cpu = reference::render(&params);
//! println!("{}", image_ops::diff(&gpu, &cpu, 24));
//! # Ok::<(), umbrac::render::ExecError>(())
//! ```

pub mod bind;
pub mod command;
pub mod consumer;
pub mod consumers;
pub mod exec;
pub mod hand;
pub mod image_ops;
pub mod plan;
pub mod program;
pub mod reference;
pub mod scene;
pub mod setup;
pub mod techniques;
pub mod tutorial;
pub mod visible;

pub use consumer::Consumer;
pub use exec::{ExecError, Executor, Readback, SceneExecutor};
pub use program::{ShaderCode, ShaderSet};
pub use scene::{FrameParams, View};
pub use setup::{DepthFormat, Filter, Fit, Light, Quality, Setup, ShadowOptions, World};
