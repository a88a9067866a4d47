//! The frame of a self-checking program: one fullscreen triangle (the
//! vertex program places it from `gl_VertexID`) into a `width` x 1 target
//! of four 32-bit unsigned integers per texel, every uniform at its
//! default (zero where it has none). The fragment program writes what it
//! found at each pixel; `tests/gpu/programs.rs` reads the words back.

use super::{Attachment, Cull, Draw, Format, FramePlan, Geometry, Pass, TargetId, Unset, Values};

pub fn plan(vertex: &str, fragment: &str, width: u32) -> FramePlan {
    let mut plan = FramePlan {
        scene: "a self-checking program".into(),
        targets: Vec::new(),
        passes: Vec::new(),
        readback: TargetId(0),
        required: Vec::new(),
        unset: Unset::Zero,
    };
    let out = plan.add_target("results", width, 1, Format::Rgba32Uint);
    plan.passes.push(Pass {
        name: "checks".into(),
        vertex: vertex.into(),
        fragment: Some(fragment.into()),
        color: Some(Attachment { target: out, clear: [0.0; 4] }),
        more_colors: Vec::new(),
        depth: None,
        cull: Cull::None,
        depth_bias: false,
        textures: Vec::new(),
        values: Values::new(),
        draws: vec![Draw { geometry: Geometry::Vertices(3), values: Values::new() }],
    });
    plan.readback = out;
    plan
}
