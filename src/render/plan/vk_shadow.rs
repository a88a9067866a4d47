//! dasVulkan's shadow rung (`tutorials/08_shadow/shadow_tut_shaders.das`,
//! the seed tutorial's origin) as a frame plan: the tutorial scene's
//! camera, sun and objects, with a Vulkan host's conventions. Its values
//! are the members of its uniform block `cam` (view, proj, light_vp,
//! light_dir, camera_pos) and of its push constant `op` (model); the
//! shadow pass runs its vertex stage alone, as dasVulkan's depth-only
//! pipeline does. The host `.das` is not in the reference, so the numbers
//! are the GL tutorial's (`super::tutorial`), turned into Vulkan clip
//! space; the four brick images are not either: stand-in textures below.

use glam::{Mat4, Vec4};

use crate::render::scene::{self, Frame, FrameParams, View};

use super::{Attachment, Cull, Draw, Format, FramePlan, Geometry, Pass, Required, Sampling, TextureInput, Value, Values};

pub const SHADOW_VS: &str = "shadow_vert_spv";
pub const MAIN_VS: &str = "main_vert_spv";
pub const MAIN_FS: &str = "main_frag_spv";
/// The stand-in textures' side.
const TEXTURE_SIZE: u32 = 64;

/// GL clip space to a Vulkan host's: z' = (z + w) / 2 (depth in [0, 1]).
const VK_DEPTH: Mat4 = Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::new(0.0, 0.0, 0.5, 0.0), Vec4::new(0.0, 0.0, 0.5, 1.0));
/// The camera's projection is y-flipped as well, so that Vulkan's y-down
/// framebuffer shows the scene upright: with [`VK_DEPTH`], glam's
/// `camera::rh::proj::vulkan::perspective` (tested).
const VK_FLIP_Y: Mat4 = Mat4::from_cols(Vec4::X, Vec4::NEG_Y, Vec4::Z, Vec4::W);

/// The stand-in for `name`'s brick image: a 64 x 64 running-bond brick
/// pattern (bricks 32 x 16 texels, 2-texel mortar), memory row 0 first.
pub fn brick_texture(name: &str) -> Vec<u8> {
    let mut texels = Vec::with_capacity((TEXTURE_SIZE * TEXTURE_SIZE * 4) as usize);
    for y in 0..TEXTURE_SIZE {
        for x in 0..TEXTURE_SIZE {
            let shift = if (y / 16) % 2 == 1 { 16 } else { 0 };
            let mortar = y % 16 < 2 || (x + shift) % 32 < 2;
            let rgb = match (name, mortar) {
                ("brick_albedo", false) => [150, 70, 50],
                ("brick_albedo", true) => [140, 135, 125],
                // A flat tangent-space normal: the stand-in has no relief.
                ("brick_normal", _) => [128, 128, 255],
                ("brick_ao", false) => [255, 255, 255],
                ("brick_ao", true) => [150, 150, 150],
                (_, false) => [140, 140, 140],
                (_, true) => [230, 230, 230],
            };
            texels.extend_from_slice(&[rgb[0], rgb[1], rgb[2], 255]);
        }
    }
    texels
}

/// The frame `params` asks for (`View::Lit`: an empty shadow map).
pub fn plan(params: &FrameParams) -> FramePlan {
    let frame = Frame::of(params);
    let mut plan = FramePlan {
        scene: "dasVulkan's shadow scene".into(),
        targets: Vec::new(),
        passes: Vec::new(),
        readback: super::TargetId(0),
        required: ["model", "light_vp", "view", "proj"]
            .iter()
            .map(|v| Required { value: v.to_string(), why: "the scene cannot place its geometry without it".into() })
            .collect(),
        unset: Default::default(),
    };
    let n = params.shadow_size;
    let shadow_map = plan.add_target("shadow map", n, n, Format::Depth32Float);
    let color = plan.add_target("colour", params.width, params.height, Format::Rgba8);
    let depth = plan.add_target("depth", params.width, params.height, Format::Depth32Float);
    let bricks: Vec<TextureInput> = ["brick_albedo", "brick_normal", "brick_ao", "brick_roughness"]
        .iter()
        .map(|&name| TextureInput {
            sampler: name.into(),
            target: plan.add_texture(name, TEXTURE_SIZE, TEXTURE_SIZE, brick_texture(name)),
            sampling: Sampling { compare: false, linear: true, border: false, repeat: false },
        })
        .collect();

    let values = Values::new()
        .with("view", Value::mat4(frame.view))
        .with("proj", Value::mat4(VK_FLIP_Y * VK_DEPTH * frame.proj))
        .with("light_vp", Value::mat4(VK_DEPTH * frame.light_vp))
        .with("light_dir", Value::vec4(frame.light_dir.extend(0.0)))
        .with("camera_pos", Value::vec4(frame.cam_pos.extend(1.0)));
    let draws: Vec<Draw> = frame
        .draws()
        .iter()
        .map(|d| Draw { geometry: Geometry::Mesh(scene::mesh(d.object)), values: Values::new().with("model", Value::mat4(d.model)) })
        .collect();
    plan.passes.push(Pass {
        name: "shadow".into(),
        vertex: SHADOW_VS.into(),
        fragment: None,
        color: None,
        more_colors: Vec::new(),
        depth: Some(Attachment { target: shadow_map, clear: 1.0 }),
        cull: Cull::None,
        depth_bias: true,
        textures: Vec::new(),
        values: values.clone(),
        draws: if params.view == View::Lit { Vec::new() } else { draws.clone() },
    });
    if params.view == View::ShadowMap {
        plan.readback = shadow_map;
        return plan;
    }
    let c = scene::CLEAR;
    let mut textures = vec![TextureInput {
        sampler: "shadow_map".into(),
        target: shadow_map,
        // dasVulkan's shadow sampler: linear compare, white border (lit outside).
        sampling: Sampling { compare: true, linear: true, border: true, repeat: false },
    }];
    textures.extend(bricks);
    plan.passes.push(Pass {
        name: "main".into(),
        vertex: MAIN_VS.into(),
        fragment: Some(MAIN_FS.into()),
        color: Some(Attachment { target: color, clear: [c[0], c[1], c[2], 1.0] }),
        more_colors: Vec::new(),
        depth: Some(Attachment { target: depth, clear: 1.0 }),
        cull: Cull::None,
        depth_bias: false,
        textures,
        values,
        draws,
    });
    plan.readback = color;
    plan
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vulkan_clip_space() {
        let p = FrameParams::new(1.0, 8, 6);
        let f = Frame::of(&p);
        let near = f.proj * glam::Vec4::new(0.0, 0.0, -crate::render::tutorial::CAMERA_NEAR, 1.0);
        let vk = VK_FLIP_Y * VK_DEPTH * f.proj * glam::Vec4::new(0.0, 0.0, -crate::render::tutorial::CAMERA_NEAR, 1.0);
        assert!((near.z / near.w + 1.0).abs() < 1e-4, "GL near plane at z = -1");
        assert!((vk.z / vk.w).abs() < 1e-4, "Vulkan near plane at z = 0");
        let up = VK_FLIP_Y * VK_DEPTH * f.proj * f.view * glam::Vec4::new(0.0, 3.0, 0.0, 1.0);
        let up_gl = f.proj * f.view * glam::Vec4::new(0.0, 3.0, 0.0, 1.0);
        assert!(up.y * up_gl.y < 0.0, "y flipped");
        // What glam's Vulkan-convention helpers give for the same boxes.
        let vk_proj = glam::camera::rh::proj::vulkan::perspective(50f32.to_radians(), 8.0 / 6.0, 0.1, 50.0);
        assert!((VK_FLIP_Y * VK_DEPTH * f.proj).abs_diff_eq(vk_proj, 1e-5), "{vk_proj} vs {}", VK_FLIP_Y * VK_DEPTH * f.proj);
        let plan = plan(&p);
        assert_eq!(plan.passes[0].fragment, None);
        assert_eq!(plan.passes[1].textures.len(), 5);
        assert_eq!(plan.target(plan.passes[1].textures[1].target).contents.as_ref().map(Vec::len), Some(64 * 64 * 4));
    }

}
