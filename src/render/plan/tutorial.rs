//! The tutorial's shadow scene as a frame plan: a shadow pass from the sun
//! into a depth texture, then the lit scene sampling it, cube then floor in
//! both, every value by the tutorial's names. The numbers come from
//! [`crate::render::scene`] and [`crate::render::setup`].

use crate::render::scene::{self, Frame, FrameParams, View};
use crate::render::setup::{DepthFormat, Light};

use super::{Attachment, Cull, Draw, Format, FramePlan, Geometry, Pass, Required, Sampling, TextureInput, Value, Values};

/// The sampler the main pass reads the shadow map through.
pub const SHADOW_SAMPLER: &str = "shadow_map";

pub fn depth_format(d: DepthFormat) -> Format {
    match d {
        DepthFormat::Depth16 => Format::Depth16,
        DepthFormat::Depth24Plus => Format::Depth24Plus,
        DepthFormat::Depth32Float => Format::Depth32Float,
    }
}

/// The frame `params` asks for.
pub fn plan(params: &FrameParams) -> FramePlan {
    let frame = Frame::of(params);
    let setup = &params.setup;
    let mut plan = FramePlan {
        scene: "the shadow scene".into(),
        targets: Vec::new(),
        passes: Vec::new(),
        readback: super::TargetId(0),
        required: scene::REQUIRED_UNIFORMS
            .iter()
            .map(|v| Required { value: v.to_string(), why: "the scene cannot place its geometry without it".into() })
            .collect(),
        unset: Default::default(),
    };
    let n = params.shadow_size;
    let shadow_map = plan.add_target("shadow map", n, n, depth_format(setup.shadow.depth));
    let color = plan.add_target("colour", params.width, params.height, Format::Rgba8);
    let depth = plan.add_target("depth", params.width, params.height, Format::Depth32Float);

    let values = Values::new()
        .with("u_light_vp", Value::mat4(frame.light_vp))
        .with("u_view", Value::mat4(frame.view))
        .with("u_proj", Value::mat4(frame.proj))
        .with("u_light_dir", Value::vec3(frame.light_dir))
        .with("u_cam_pos", Value::vec3(frame.cam_pos));
    let draws: Vec<Draw> = frame
        .draws()
        .iter()
        .map(|d| Draw {
            geometry: Geometry::Mesh(scene::mesh(d.object)),
            values: Values::new().with("u_model", Value::mat4(d.model)).with("u_is_floor", Value::float(d.is_floor)),
        })
        .collect();

    // `lit` leaves the map empty (every compare passes); casters only: the
    // floor shadows nothing.
    let shadow_draws = match params.view {
        View::Lit => Vec::new(),
        _ => draws.iter().filter(|d| !(setup.shadow.casters_only && matches!(d.geometry, Geometry::Mesh(m) if m.name == "floor"))).cloned().collect(),
    };
    plan.passes.push(Pass {
        name: "shadow".into(),
        vertex: scene::SHADOW_VS.into(),
        fragment: Some(scene::SHADOW_FS.into()),
        color: None,
        more_colors: Vec::new(),
        depth: Some(Attachment { target: shadow_map, clear: 1.0 }),
        cull: Cull::None,
        depth_bias: true,
        textures: Vec::new(),
        values: values.clone(),
        draws: shadow_draws,
    });
    if params.view == View::ShadowMap {
        plan.readback = shadow_map;
        return plan;
    }
    // Lookups outside a tight box or a spot light's frustum are lit.
    let border = setup.shadow.fit.lit_outside() || matches!(setup.light, Light::Spot { .. });
    let c = scene::CLEAR;
    plan.passes.push(Pass {
        name: "main".into(),
        vertex: scene::MAIN_VS.into(),
        fragment: Some(scene::MAIN_FS.into()),
        color: Some(Attachment { target: color, clear: [c[0], c[1], c[2], 1.0] }),
        more_colors: Vec::new(),
        depth: Some(Attachment { target: depth, clear: 1.0 }),
        cull: Cull::None,
        depth_bias: false,
        textures: vec![TextureInput {
            sampler: SHADOW_SAMPLER.into(),
            target: shadow_map,
            sampling: Sampling { compare: true, linear: setup.shadow.filter.linear(), border, repeat: false },
        }],
        values,
        draws,
    });
    plan.readback = color;
    plan
}

/// The camera's depth pre-pass of [`crate::render::setup::Fit::Visible`]:
/// every object drawn by the shadow program from the camera (its
/// projection * view in place of the light's) into a depth target of the
/// frame's size, which comes back ([`super::super::Readback::Depth`]).
pub fn camera_depth_plan(params: &FrameParams) -> FramePlan {
    let frame = Frame::of(params);
    let mut plan = FramePlan {
        scene: "the shadow scene's camera depth".into(),
        targets: Vec::new(),
        passes: Vec::new(),
        readback: super::TargetId(0),
        required: vec![Required { value: "u_light_vp".into(), why: "the pre-pass cannot place its geometry without it".into() }],
        unset: Default::default(),
    };
    let depth = plan.add_target("camera depth", params.width, params.height, Format::Depth32Float);
    let draws = frame
        .draws()
        .iter()
        .map(|d| Draw {
            geometry: Geometry::Mesh(scene::mesh(d.object)),
            values: Values::new().with("u_model", Value::mat4(d.model)).with("u_is_floor", Value::float(d.is_floor)),
        })
        .collect();
    plan.passes.push(Pass {
        name: "camera depth".into(),
        vertex: scene::SHADOW_VS.into(),
        fragment: Some(scene::SHADOW_FS.into()),
        color: None,
        more_colors: Vec::new(),
        depth: Some(Attachment { target: depth, clear: 1.0 }),
        cull: Cull::None,
        depth_bias: false,
        textures: Vec::new(),
        // The program's uniforms share one buffer: every value is set.
        values: Values::new()
            .with("u_light_vp", Value::mat4(frame.proj * frame.view))
            .with("u_view", Value::mat4(frame.view))
            .with("u_proj", Value::mat4(frame.proj))
            .with("u_light_dir", Value::vec3(frame.light_dir))
            .with("u_cam_pos", Value::vec3(frame.cam_pos)),
        draws,
    });
    plan.readback = depth;
    plan
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn views_shape_the_plan() {
        let p = FrameParams::new(1.0, 8, 6);
        let full = plan(&p);
        assert_eq!(full.passes.len(), 2);
        assert_eq!(full.passes[0].draws.len(), 2);
        assert_eq!(full.readback_size(), (8, 6));
        let lit = plan(&p.with_view(View::Lit));
        assert!(lit.passes[0].draws.is_empty());
        let map = plan(&p.with_view(View::ShadowMap));
        assert_eq!((map.passes.len(), map.readback_size()), (1, (1024, 1024)));
        let mut tuned = p;
        tuned.setup = crate::render::Setup::tuned();
        assert_eq!(plan(&tuned).passes[0].draws.len(), 1, "casters only");
    }
}
