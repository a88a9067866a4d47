//! Constructs only some targets have: refused where a requested target
//! lacks them, at their first use, naming those targets; accepted when
//! only targets that have them are requested.

use super::*;
use crate::target::Target;

impl<'a, 'd> Checker<'a, 'd> {
    /// `half` (a type, a constructor or a `1.5h` literal) at `span`:
    /// WGSL (`enable f16`) and SPIR-V (Float16) have it, GLSL 330 and
    /// GLSL ES 3.00 do not.
    pub(super) fn half_used(&mut self, span: Span) {
        if self.half_refused {
            return;
        }
        // With no target named, the GLSL targets of a program are 330 and
        // ES 3.00 (or 430 and ES 3.10, which have no `half` either).
        let lacking: Vec<&str> = match self.targets_defaulted {
            true => vec![Target::Glsl330.name(), Target::Gles300.name()],
            false => self.targets.iter().filter(|t| t.is_glsl()).map(|t| t.name()).collect(),
        };
        if lacking.is_empty() {
            return;
        }
        self.half_refused = true;
        let (which, s) = if lacking.len() == 1 { (lacking[0].to_string(), "") } else { (lacking.join(" and "), "s") };
        let d = Diagnostic::error(format!("`half` is not supported by the {which} target{s}"), span)
            .with_label("a 16-bit float")
            .with_note("GLSL (330, ES 3.00, 430, ES 3.10) has no 16-bit float type (`mediump` is a precision hint, not a type); WGSL has `f16` (`enable f16`) and SPIR-V the Float16 capability")
            .with_note("help: compile this file for `--target wgsl --target spirv` only, or use `float`");
        self.diags.push(d);
    }

    /// A compute entry point, storage buffer, storage image or workgroup
    /// variable (`what`) at `span`: GLSL 330 and GLSL ES 3.00 have none.
    /// With no target named, the program gets GLSL 430 and ES 3.10
    /// instead (`Target::defaults`).
    pub(super) fn compute_used(&mut self, span: Span, what: &str) {
        if self.compute_refused || self.targets_defaulted {
            return;
        }
        let lacking: Vec<&str> = self.targets.iter().filter(|t| t.is_classic_glsl()).map(|t| t.name()).collect();
        if lacking.is_empty() {
            return;
        }
        self.compute_refused = true;
        let (which, s) = if lacking.len() == 1 { (lacking[0].to_string(), "") } else { (lacking.join(" and "), "s") };
        let d = Diagnostic::error(format!("{what} is not supported by the {which} target{s}"), span)
            .with_note("OpenGL 3.3 and OpenGL ES 3.0 have no compute shaders, storage buffers or images")
            .with_note("help: compile for `--target glsl430` / `--target gles310` (GL 4.3, GLES 3.1), `wgsl` or `spirv`, or leave `--target` out to get every target that runs it");
        self.diags.push(d);
    }

    /// A mesh or task entry point (`[vulkan_mesh_shader]` at `span`): SPIR-V
    /// only. naga 30 writes these stages to SPIR-V 1.4 (VK_EXT_mesh_shader),
    /// which spirv-val checks; it writes WGSL ones only in wgpu's own
    /// `enable wgpu_mesh_shader;`, which no WebGPU has and tint refuses.
    pub(super) fn mesh_stage_used(&mut self, stage: naga::ShaderStage, annotation: &str, span: Span) {
        let (key, what) = match stage {
            naga::ShaderStage::Mesh => ("mesh stage", format!("the mesh stage (`[{annotation}]`)")),
            _ => ("task stage", format!("the task stage (`[{annotation}]`)")),
        };
        self.lacking_targets_used(
            key,
            &what,
            span,
            |t| t != Target::Spirv,
            "SPIR-V 1.4 has mesh and task shaders (VK_EXT_mesh_shader); GLSL 3.30, ES 3.00, 4.30 and ES 3.10 have none, and WebGPU has none (naga's WGSL for them is wgpu's native `enable wgpu_mesh_shader;`, which Chrome refuses)",
            "compile for `--target spirv`",
        );
    }

    /// A stage of dasSpirv's Vulkan dialect umbrac does not compile (ray
    /// tracing), annotated at `a`: refused by name for every target
    /// requested, never skipped.
    pub(super) fn uncompiled_stage(&mut self, a: &ast::Annotation) {
        let what = ast::UNCOMPILED_STAGES.iter().find(|&&(n, _)| n == a.name.name.as_str()).map_or("this", |&(_, w)| w);
        let targets: Vec<&str> = self.targets.iter().map(|t| t.name()).collect();
        let d = Diagnostic::error(format!("the {what} stage (`[{}]`) is not supported by umbrac on {}", a.name.name, targets.join(", ")), a.span)
            .with_note("GLSL 3.30, ES 3.00, GLSL 4.30 and ES 3.10 have no such stage, nor does WebGPU; naga 30 writes ray-tracing stages to SPIR-V, but its trace-ray call has no shader-binding-table offset, stride or miss index (`traceRayEXT`'s 4th to 6th arguments), so umbrac does not lower them")
            .with_note("the vertex, fragment, compute, mesh and task stages of the Vulkan dialect are supported");
        self.diags.push(d);
    }

    /// An array of samplers in the Vulkan dialect: one descriptor array
    /// (one binding, N elements), a binding array in SPIR-V. GLSL has
    /// none, and WebGPU has none either: naga writes wgpu's native
    /// `enable wgpu_binding_array;`, which Chrome's tint refuses.
    pub(super) fn descriptor_array_used(&mut self, span: Span) {
        self.lacking_targets_used(
            "descriptor array",
            "an array of samplers in the Vulkan dialect (a descriptor array at one binding)",
            span,
            |t| t != Target::Spirv,
            "SPIR-V binds it as one descriptor array (indexed with `nonuniformEXT`); GLSL has no descriptor arrays, and WebGPU has no binding arrays (wgpu's native `wgpu_binding_array` extension is not WebGPU: Chrome refuses it)",
            "compile for `--target spirv`, or bind each sampler at its own `@binding`",
        );
    }

    /// A read-write storage image of `format` (neither `@readonly` nor
    /// `@writeonly`, dasGlsl's default) at `span`: GLSL 430 and SPIR-V
    /// have it for every format; GLSL ES 3.10 and WGSL only for `r32f`,
    /// `r32ui` and `r32i`. Refused for those, never made one-way.
    pub(super) fn read_write_image_used(&mut self, format: &str, span: Span) {
        let lacking: Vec<&str> = match self.targets_defaulted {
            true => vec![Target::Gles310.name(), Target::Wgsl.name()],
            false => self.targets.iter().filter(|t| matches!(t, Target::Gles310 | Target::Wgsl)).map(|t| t.name()).collect(),
        };
        if lacking.is_empty() {
            return;
        }
        let (which, s) = if lacking.len() == 1 { (lacking[0].to_string(), "") } else { (lacking.join(" and "), "s") };
        let d = Diagnostic::error(format!("a read-write `{format}` storage image is not supported by the {which} target{s}"), span)
            .with_label("read-write: neither `@readonly` nor `@writeonly`")
            .with_note("GLSL ES 3.10 and WebGPU read and write one storage image only in `r32f`, `r32ui` or `r32i`; GLSL 4.30 and SPIR-V in every format")
            .with_note("help: add `@writeonly` or `@readonly` if the shader only writes or reads it, or compile for `--target glsl430 --target spirv` only");
        self.diags.push(d);
    }

    /// A construct (`what`, e.g. "`gl_DrawID`") that the targets `lacks`
    /// selects do not have, used at `span`: refused once, at its first
    /// use, naming the requested targets that lack it (with no target
    /// named, the default targets that do).
    pub(super) fn lacking_targets_used(&mut self, key: &'static str, what: &str, span: Span, lacks: fn(Target) -> bool, why: &str, help: &str) {
        if self.refused_constructs.contains(key) {
            return;
        }
        let lacking: Vec<&str> = match self.targets_defaulted {
            true => {
                let mut d: Vec<&str> = Vec::new();
                for t in Target::defaults(false).into_iter().chain(Target::defaults(true)).filter(|t| lacks(*t)) {
                    if !d.contains(&t.name()) {
                        d.push(t.name());
                    }
                }
                d
            }
            false => self.targets.iter().filter(|t| lacks(**t)).map(|t| t.name()).collect(),
        };
        if lacking.is_empty() {
            return;
        }
        self.refused_constructs.insert(key);
        let (which, s) = match lacking.split_last() {
            Some((last, [])) => (last.to_string(), ""),
            Some((last, rest)) => (format!("{} and {last}", rest.join(", ")), "s"),
            None => unreachable!("not empty"),
        };
        let d = Diagnostic::error(format!("{what} is not supported by the {which} target{s}"), span).with_note(why.to_string()).with_note(format!("help: {help}"));
        self.diags.push(d);
    }

    /// A subgroup operation or input (`what`) at `span`: WGSL (`enable
    /// subgroups`), SPIR-V (GroupNonUniform) and GLSL 430
    /// (`GL_KHR_shader_subgroup_*`) have them; GLSL 330 and the GLSL ES
    /// targets do not.
    pub(super) fn subgroup_used(&mut self, what: &str, span: Span) {
        self.lacking_targets_used(
            "subgroups",
            what,
            span,
            |t| matches!(t, Target::Glsl330 | Target::Gles300 | Target::Gles310),
            "subgroup operations need Vulkan 1.1 / SPIR-V GroupNonUniform, WebGPU's `subgroups` feature or GLSL 4.30 with GL_KHR_shader_subgroup; OpenGL 3.3 and OpenGL ES have none",
            "compile for `--target glsl430 --target wgsl --target spirv` only",
        );
    }

    /// A builtin input only some targets have (`gl_DrawID`,
    /// `gl_PrimitiveID`, the subgroup inputs) at `span`.
    pub(super) fn builtin_var_used(&mut self, b: crate::sema::tree::BuiltinVar, span: Span) {
        use crate::sema::tree::BuiltinVar as V;
        match b {
            V::DrawId => self.lacking_targets_used(
                "gl_DrawID",
                "`gl_DrawID`",
                span,
                |t| t != Target::Spirv,
                "the draw index of a multi-draw is SPIR-V's DrawIndex (Vulkan 1.1's shaderDrawParameters); WebGPU has none, GLSL has it only from 4.60 (`gl_DrawIDARB` under GL_ARB_shader_draw_parameters before), OpenGL ES not at all",
                "compile for `--target spirv` only, or pass the draw's index in a uniform",
            ),
            V::PrimitiveId => self.lacking_targets_used(
                "gl_PrimitiveID",
                "`gl_PrimitiveID`",
                span,
                |t| matches!(t, Target::Gles300 | Target::Gles310),
                "OpenGL ES has `gl_PrimitiveID` in fragment shaders only from ES 3.2; GLSL 3.30 and 4.30, SPIR-V and WGSL (`enable primitive_index`) have it",
                "compile for `--target glsl330 --target glsl430 --target wgsl --target spirv` only",
            ),
            b if b.is_subgroup() => self.subgroup_used(&format!("`{}`", b.name()), span),
            _ => {}
        }
    }
}
