//! `--fit visible` (sample-distribution shadow maps): before each frame,
//! a camera depth pre-pass ([`plan::tutorial::camera_depth_plan`]), then
//! the DSL compute program `shaders/compute/depth_bounds.das`, compiled by
//! umbrac, reduces that depth buffer to the light-space bounds of the
//! receivers the camera sees; the frame's light box is fitted to them
//! ([`crate::render::setup::visible_box`]).
//!
//! The depth buffer makes one trip through the host (read back, uploaded
//! as the compute program's `r32f` image) and the six bounds come back to
//! the host, which makes the projection: the plans stay what they are
//! (a frame plan, a compute plan), at the price of two read-backs a frame
//! (docs/performance.md measures it). Runs where compute and frames run on
//! one device ([`ComputeExecutor`]): wgpu on Vulkan, from the WGSL or the
//! SPIR-V, and an OpenGL 4.3 core context, from the GLSL 430.

use glam::{Mat4, Vec3};

use super::exec::wgpu::WgpuExecutor;
use super::exec::{ComputeReadback, ExecError, Executor, Readback};
use super::plan::compute::{BufferInput, ComputePlan, ImageInput};
use super::plan::tutorial;
use super::program::ShaderSet;
use super::scene::{Frame, FrameParams};
use super::Consumer;
use crate::Target;

/// The reduction's source, built into the binary: it is part of the
/// renderer, like the scene's fixed passes.
pub const PROGRAM_NAME: &str = "shaders/compute/depth_bounds.das";
const PROGRAM: &str = include_str!("../../shaders/compute/depth_bounds.das");
const ENTRY: &str = "depth_bounds_cs";
/// The program's `local_size_x` and `local_size_y`.
const GROUP: u32 = 8;

/// An executor that runs frames and compute plans on one device.
pub trait ComputeExecutor: Executor {
    fn dispatch(&self, set: &ShaderSet, plan: &ComputePlan) -> Result<ComputeReadback, ExecError>;
}

impl ComputeExecutor for WgpuExecutor {
    fn dispatch(&self, set: &ShaderSet, plan: &ComputePlan) -> Result<ComputeReadback, ExecError> {
        self.run_compute(set, plan)
    }
}

#[cfg(feature = "gl")]
impl ComputeExecutor for super::exec::gl::GlExecutor {
    fn dispatch(&self, set: &ShaderSet, plan: &ComputePlan) -> Result<ComputeReadback, ExecError> {
        self.run_compute(set, plan)
    }
}

/// Whether `consumer` can run `--fit visible`, and if not, why not.
pub fn check_consumer(consumer: Consumer) -> Result<(), String> {
    match consumer {
        Consumer::VulkanWgsl | Consumer::VulkanSpirv | Consumer::Gl430 => Ok(()),
        Consumer::Gles310 => Err("--fit visible reads the camera's depth buffer back, which OpenGL ES cannot (glReadPixels of DEPTH_COMPONENT): gles310 does not run it; use --backend gl430 or vulkan".into()),
        other => Err(format!(
            "--fit visible measures the visible receivers with a compute pass, and {} runs no compute programs with its frames \
             (WebGL2, OpenGL 3.3 / ES 3.0 and wgpu's GL backend have no compute); use --backend vulkan (--via wgsl or spirv) or gl430",
            other.name()
        )),
    }
}

/// The reduction compiled for `target` (WGSL, SPIR-V or GLSL 430).
pub fn program(target: Target) -> Result<ShaderSet, String> {
    let opts = crate::Options { targets: vec![target], ..Default::default() };
    let c = crate::compile_source(PROGRAM_NAME, PROGRAM, &opts);
    if c.has_errors() {
        return Err(format!("{PROGRAM_NAME} does not compile:\n{}", c.render_diagnostics()));
    }
    ShaderSet::from_compiled(PROGRAM_NAME, c.result.as_ref().expect("compiled without errors"), target)
}

/// The dispatch over a `width` x `height` camera depth buffer (`depths`,
/// top row first as frames come back) for the frame `params` describes.
pub fn compute_plan(params: &FrameParams, depths: &[f32]) -> ComputePlan {
    let (w, h) = (params.width, params.height);
    let frame = Frame::of(params);
    let inv_view_proj: Mat4 = (frame.proj * frame.view).inverse();
    // std430 `View`: two column-major mat4, an int2, padded to 16 bytes.
    let mut view: Vec<u8> = [inv_view_proj.to_cols_array(), frame.light_view.to_cols_array()].concat().iter().flat_map(|f| f.to_le_bytes()).collect();
    view.extend([w as i32, h as i32].iter().flat_map(|v| v.to_le_bytes()));
    view.resize(144, 0);
    // `Bounds` starts empty: lows at the largest key, highs at the smallest.
    let start: Vec<u8> = [i32::MAX, i32::MAX, i32::MAX, i32::MIN, i32::MIN, i32::MIN, 0].iter().flat_map(|v| v.to_le_bytes()).collect();
    // The image's rows go y = 0 first, the bottom of the GL picture.
    let texels: Vec<u8> = depths.chunks_exact(w as usize).rev().flatten().flat_map(|d| d.to_le_bytes()).collect();
    ComputePlan {
        name: "visible receivers' light-space bounds".into(),
        entry: ENTRY.into(),
        workgroups: [w.div_ceil(GROUP), h.div_ceil(GROUP), 1],
        buffers: vec![BufferInput { name: "view".into(), bytes: view }, BufferInput { name: "bounds".into(), bytes: start }],
        images: vec![ImageInput { name: "depth".into(), width: w, height: h, layers: 1, texels: Some(texels) }],
        readback: vec!["bounds".into()],
        constants: vec![],
    }
}

/// The bounds the dispatch computed: `None` when no pixel shows geometry.
pub fn bounds_of(r: &ComputeReadback) -> Result<Option<(Vec3, Vec3)>, ExecError> {
    let words = r.words("bounds").filter(|w| w.len() >= 7).ok_or_else(|| ExecError::Program("the bounds buffer did not come back whole".into()))?;
    // The inverse of the program's `key`: order-preserving int -> float.
    let unkey = |k: u32| -> f32 {
        let k = k as i32;
        f32::from_bits((if k >= 0 { k } else { k ^ 0x7FFF_FFFF }) as u32)
    };
    if words[6] == 0 {
        return Ok(None);
    }
    let lo = Vec3::new(unkey(words[0]), unkey(words[1]), unkey(words[2]));
    let hi = Vec3::new(unkey(words[3]), unkey(words[4]), unkey(words[5]));
    Ok(Some((lo, hi)))
}

/// Measures what `params`' frame needs: the pre-pass with the scene
/// program `scene`, the reduction with `reduction` ([`program`]); `params`
/// with its [`FrameParams::visible_bounds`] set.
pub fn measure<E: ComputeExecutor>(e: &E, scene: &E::Prepared, reduction: &ShaderSet, params: &FrameParams) -> Result<FrameParams, ExecError> {
    let depths = match e.run(scene, &tutorial::camera_depth_plan(params))? {
        Readback::Depth { depths, .. } => depths,
        _ => return Err(ExecError::Program("the camera depth pre-pass returned no depths".into())),
    };
    let bounds = bounds_of(&e.dispatch(reduction, &compute_plan(params, &depths))?)?;
    Ok(FrameParams { visible_bounds: bounds, ..*params })
}

/// One `--fit visible` frame: [`measure`], then the frame.
pub fn render<E: ComputeExecutor>(e: &E, scene: &E::Prepared, reduction: &ShaderSet, params: &FrameParams) -> Result<Readback, ExecError> {
    let measured = measure(e, scene, reduction, params)?;
    e.run(scene, &tutorial::plan(&measured))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_plan_turns_rows_and_covers_the_frame() {
        let p = FrameParams::new(0.0, 10, 3);
        let depths: Vec<f32> = (0..30).map(|i| (i / 10) as f32).collect();
        let plan = compute_plan(&p, &depths);
        assert_eq!(plan.workgroups, [2, 1, 1]);
        assert!(plan.check().is_ok());
        let texels = plan.images[0].texels.as_ref().unwrap();
        // The top row (depth 0) comes back first; the image starts at y = 0, the bottom (depth 2).
        assert_eq!(f32::from_le_bytes(texels[..4].try_into().unwrap()), 2.0);
        assert_eq!(plan.buffers[0].bytes.len(), 144);
    }

    #[test]
    fn bounds_decode_the_program_keys() {
        let key = |f: f32| {
            let b = f.to_bits() as i32;
            (if b >= 0 { b } else { b ^ 0x7FFF_FFFF }) as u32
        };
        let words = [key(-2.5), key(0.0), key(-9.0), key(3.0), key(1.25), key(-4.0), 17];
        let r = ComputeReadback { resources: [("bounds".to_string(), words.iter().flat_map(|w| w.to_le_bytes()).collect())].into() };
        assert_eq!(bounds_of(&r).unwrap(), Some((Vec3::new(-2.5, 0.0, -9.0), Vec3::new(3.0, 1.25, -4.0))));
        let none = ComputeReadback { resources: [("bounds".to_string(), vec![0; 28])].into() };
        assert_eq!(bounds_of(&none).unwrap(), None, "nothing seen");
        assert!(bounds_of(&ComputeReadback::default()).is_err());
    }
}
