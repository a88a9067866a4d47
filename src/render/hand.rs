//! The hand-written WGSL port of the scene (`shaders/hand/shadow.wgsl`) and
//! the reflection that describes it, in the same shape the compiler emits.
//! A peer for benchmarks, a known-good program for the runner's tests, and
//! the source of deliberately broken variants that the tests must reject.

use std::collections::BTreeMap;

use crate::emit::reflect_types::{EntryPoint, Io, Member, ProgramLink, Reflection, Sampler, Uniform, UniformBuffer, REFLECTION_FORMAT};

use super::program::{ShaderCode, ShaderSet};

/// The hand-written WGSL text.
pub const WGSL: &str = include_str!("../../shaders/hand/shadow.wgsl");
pub const FILE_NAME: &str = "shaders/hand/shadow.wgsl";

/// The clip-space adaptation line at the end of every vertex entry point.
const PORTABLE_RETURN: &str = "return vec4<f32>(p.x, -p.y, 0.5 * (p.z + p.w), p.w);";

/// Deliberately wrong versions of the hand shader, for tests that must fail.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variant {
    /// As written.
    Portable,
    /// No y mirror (and the reflection says `native`, so the host does not
    /// flip the image): the picture is upright but the shadow map is stored
    /// top row first while the lookup assumes GL's bottom-first rows, so the
    /// shadow lands mirrored.
    NoYFlip,
    /// No depth remap: GL's [-w, w] clip depth is clipped to [0, w], which
    /// drops every caster in the near half of the sun's box: the shadow
    /// vanishes.
    NoZRemap,
    /// Neither adaptation: what `Conventions::Native` gives for GL-style code.
    Native,
}

impl Variant {
    pub fn wgsl(self) -> String {
        let body = match self {
            Variant::Portable => return WGSL.to_string(),
            Variant::NoYFlip => "return vec4<f32>(p.x, p.y, 0.5 * (p.z + p.w), p.w);",
            Variant::NoZRemap => "return vec4<f32>(p.x, -p.y, p.z, p.w);",
            Variant::Native => "return p;",
        };
        assert!(WGSL.contains(PORTABLE_RETURN), "hand shader's adaptation line changed");
        WGSL.replace(PORTABLE_RETURN, body)
    }

    pub fn conventions(self) -> &'static str {
        match self {
            Variant::Portable | Variant::NoZRemap => "portable",
            Variant::NoYFlip | Variant::Native => "native",
        }
    }

    pub fn shader_set(self) -> ShaderSet {
        let mut reflection = reflection();
        reflection.conventions = self.conventions().to_string();
        ShaderSet::single(format!("{FILE_NAME} ({self:?})"), ShaderCode::Wgsl(self.wgsl()), reflection)
    }
}

/// The hand shader as a ready-to-render set.
pub fn shader_set() -> ShaderSet {
    Variant::Portable.shader_set()
}

/// The uniform values in declaration order: (name, DSL type, size).
const UNIFORMS: [(&str, &str, u32); 7] = [
    ("u_light_vp", "float4x4", 64),
    ("u_model", "float4x4", 64),
    ("u_view", "float4x4", 64),
    ("u_proj", "float4x4", 64),
    ("u_light_dir", "float3", 12),
    ("u_cam_pos", "float3", 12),
    ("u_is_floor", "float", 4),
];

fn io(name: &str, location: u32, ty: &str, vertex_input: bool) -> Io {
    let (format, size) = match ty {
        "float3" => ("Float32x3", 12),
        "float4" => ("Float32x4", 16),
        _ => unreachable!(),
    };
    Io {
        name: name.into(),
        location,
        ty: ty.into(),
        vertex_format: vertex_input.then(|| format.to_string()),
        size,
        interpolation: (!vertex_input).then(|| "perspective".to_string()),
        glsl_name: name.into(),
        glsl_location: vertex_input.then_some(location),
    }
}

/// The reflection of the hand shader, in the shape the compiler emits:
/// the loose uniforms in one buffer at binding 0, the shadow map at 1 and 2.
pub fn reflection() -> Reflection {
    let mut offset = 0u32;
    let members: Vec<Member> = UNIFORMS
        .iter()
        .map(|&(name, ty, size)| {
            // WGSL's uniform layout: a matrix or a float3 starts on 16 bytes,
            // a float after a float3 shares its slot.
            let align = if size >= 12 { 16 } else { 4 };
            offset = offset.next_multiple_of(align);
            let m = Member {
                name: name.into(),
                ty: ty.into(),
                offset,
                size,
                array_stride: None,
                matrix_stride: (ty == "float4x4").then_some(16),
                storage: None,
                glsl_name: None,
                default: None,
            };
            offset += size;
            m
        })
        .collect();
    let uniform_buffers = vec![UniformBuffer {
        name: "uniforms".into(),
        ty: "Uniforms".into(),
        loose: true,
        size: offset.next_multiple_of(16),
        group: 0,
        binding: 0,
        glsl_block: None,
        glsl_binding: None,
        members,
        push_constant: None,
    }];
    let uniforms: Vec<Uniform> = UNIFORMS
        .iter()
        .map(|&(name, ty, _)| Uniform {
            name: name.into(),
            ty: ty.into(),
            buffer: "uniforms".into(),
            glsl_name: Some(name.into()),
            glsl_type: match ty {
                "float4x4" => "mat4",
                "float3" => "vec3",
                _ => "float",
            }
            .into(),
            default: None,
        })
        .collect();
    let samplers = vec![Sampler {
        name: "shadow_map".into(),
        ty: "sampler2DShadow".into(),
        glsl_name: "shadow_map".into(),
        texture_unit: 0,
        group: 0,
        texture_binding: 1,
        sampler_binding: 2,
        dimension: "2d".into(),
        sample_type: "depth".into(),
        comparison: true,
        count: None,
    }];
    let files = |_: &str| BTreeMap::from([("wgsl".to_string(), "shadow.wgsl".to_string())]);
    let strings = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let varyings = || {
        vec![io("v_world_pos", 0, "float3", false), io("v_world_normal", 1, "float3", false), io("v_light_space", 2, "float4", false)]
    };
    let entry_points = vec![
        EntryPoint {
            name: "shadow_vs".into(),
            stage: "vertex".into(),
            files: files("shadow_vs"),
            inputs: vec![io("a_pos", 0, "float3", true)],
            outputs: vec![],
            builtins: strings(&["gl_Position"]),
            uniform_buffers: strings(&["uniforms"]),
            uniforms: strings(&["u_light_vp", "u_model"]),
            samplers: vec![],
            workgroup_size: None,
            storage_buffers: None,
            storage_images: None,
            dialect: None,
            clip_space: None,
        },
        EntryPoint {
            name: "shadow_fs".into(),
            stage: "fragment".into(),
            files: files("shadow_fs"),
            inputs: vec![],
            outputs: vec![Io { interpolation: None, ..io("f_FragColor", 0, "float4", false) }],
            builtins: vec![],
            uniform_buffers: vec![],
            uniforms: vec![],
            samplers: vec![],
            workgroup_size: None,
            storage_buffers: None,
            storage_images: None,
            dialect: None,
            clip_space: None,
        },
        EntryPoint {
            name: "main_vs".into(),
            stage: "vertex".into(),
            files: files("main_vs"),
            inputs: vec![io("a_pos", 0, "float3", true), io("a_normal", 1, "float3", true)],
            outputs: varyings(),
            builtins: strings(&["gl_Position"]),
            uniform_buffers: strings(&["uniforms"]),
            uniforms: strings(&["u_light_vp", "u_model", "u_view", "u_proj"]),
            samplers: vec![],
            workgroup_size: None,
            storage_buffers: None,
            storage_images: None,
            dialect: None,
            clip_space: None,
        },
        EntryPoint {
            name: "main_fs".into(),
            stage: "fragment".into(),
            files: files("main_fs"),
            inputs: varyings(),
            outputs: vec![Io { interpolation: None, ..io("f_FragColor", 0, "float4", false) }],
            builtins: vec![],
            uniform_buffers: strings(&["uniforms"]),
            uniforms: strings(&["u_light_dir", "u_cam_pos", "u_is_floor"]),
            samplers: strings(&["shadow_map"]),
            workgroup_size: None,
            storage_buffers: None,
            storage_images: None,
            dialect: None,
            clip_space: None,
        },
    ];
    Reflection {
        format: REFLECTION_FORMAT,
        source: FILE_NAME.into(),
        conventions: "portable".into(),
        entry_points,
        programs: vec![
            ProgramLink { vertex: "main_vs".into(), fragment: "main_fs".into() },
            ProgramLink { vertex: "shadow_vs".into(), fragment: "shadow_fs".into() },
        ],
        gl_uniforms: "plain".into(),
        uniform_buffers,
        uniforms,
        structs: vec![],
        required_limits: None,
        requires: None,
        specialization_constants: None,
        samplers,
        storage_buffers: None,
        storage_images: None,
    }
}

/// The hand shader with its bindings renumbered by `new_binding(old)`, and the
/// reflection to match: a program whose resource order differs from the
/// usual one must still render the same picture.
pub fn rebound(new_binding: impl Fn(u32) -> u32) -> ShaderSet {
    let mut text = WGSL.to_string();
    // Rewrite through placeholders so a permutation cannot collide.
    for old in 0..3 {
        text = text.replace(&format!("@binding({old})"), &format!("@binding(#{old}#)"));
    }
    for old in 0..3 {
        text = text.replace(&format!("@binding(#{old}#)"), &format!("@binding({})", new_binding(old)));
    }
    let mut r = reflection();
    for b in &mut r.uniform_buffers {
        b.binding = new_binding(b.binding);
    }
    for s in &mut r.samplers {
        s.texture_binding = new_binding(s.texture_binding);
        s.sampler_binding = new_binding(s.sampler_binding);
    }
    ShaderSet::single(format!("{FILE_NAME} (rebound)"), ShaderCode::Wgsl(text), r)
}
