//! SPIR-V: one module per input file (every entry point), from `Lowered::gpu`.

use naga::back::spv::{BindingInfo, Options, WriterFlags};
use naga::proc::{BoundsCheckPolicies, BoundsCheckPolicy};

use super::guard;
use crate::diag::Diagnostic;
use crate::lower::Lowered;

/// The writer options.
///
/// - No `ADJUST_COORDINATE_SPACE` (naga's default): the lowering has already
///   adapted clip space for Vulkan in portable conventions, and in native
///   conventions the author wants the code as written.
/// - `fake_missing_bindings: false` with an explicit identity binding map
///   (group -> descriptor set, binding -> binding) of the resources that
///   have bindings: a resource without one is a lowering bug and must fail
///   here, not silently take whatever naga would make up.
/// - `DEBUG` names (OpName) keep the source names of globals, functions and
///   struct members for tools and drivers' messages. `LABEL_VARYINGS` is left
///   off: some drivers treat those names as semantic.
/// - Bounds checks: `Restrict` (clamp the index) for arrays, vectors,
///   matrices and buffers; `ReadZeroSkipWrite` for image loads (what WebGPU
///   requires of texel fetches). Out-of-range access is undefined behaviour
///   in Vulkan without robustness features, and these are the cheapest
///   policies that make every target read the same defined value.
/// - SPIR-V 1.0, so any Vulkan 1.0 driver takes it; 1.3 (Vulkan 1.1)
///   where the module uses subgroups, whose GroupNonUniform instructions
///   need it, 1.4 (Vulkan 1.2) with mesh or task entry points (the
///   manifest's `requires`; [`version`]).
pub fn options(module: &naga::Module) -> Options<'static> {
    let binding_map = module
        .global_variables
        .iter()
        .filter_map(|(_, g)| g.binding)
        .map(|rb| (rb, BindingInfo { descriptor_set: rb.group, binding: rb.binding, binding_array_size: None }))
        .collect();
    Options {
        binding_map,
        lang_version: version(module),
        flags: WriterFlags::DEBUG,
        fake_missing_bindings: false,
        bounds_check_policies: BoundsCheckPolicies {
            index: BoundsCheckPolicy::Restrict,
            buffer: BoundsCheckPolicy::Restrict,
            image_load: BoundsCheckPolicy::ReadZeroSkipWrite,
            binding_array: BoundsCheckPolicy::Restrict,
        },
        debug_info: None,
        ..Options::default()
    }
}

/// The SPIR-V version a module needs: 1.4 for mesh and task entry points
/// (SPV_EXT_mesh_shader: Vulkan 1.2 with VK_EXT_mesh_shader), 1.3 for
/// subgroups (Vulkan 1.1), 1.0 otherwise.
pub fn version(module: &naga::Module) -> (u8, u8) {
    if module.entry_points.iter().any(|e| matches!(e.stage, naga::ShaderStage::Mesh | naga::ShaderStage::Task)) {
        (1, 4)
    } else if super::wgsl::uses_subgroups(module) {
        (1, 3)
    } else {
        (1, 0)
    }
}

pub fn write(lowered: &Lowered) -> Result<Vec<u32>, Diagnostic> {
    let mut options = options(&lowered.gpu);
    // The DSL's gl_PointSize is dropped from the GPU module (WGSL has no
    // point size); Vulkan still needs a PointSize output to draw point
    // lists, so the vertex entry points write 1.0, matching WebGPU.
    let points = lowered.interface.entry_points.iter().any(|e| e.builtins.iter().any(|b| b == "gl_PointSize"));
    if points {
        options.flags |= WriterFlags::FORCE_POINT_SIZE;
    }
    guard("the SPIR-V writer", || {
        // `spv::write_vec`, into words reserved ahead.
        let mut words = Vec::with_capacity(super::output_capacity(&lowered.gpu) / 4);
        // Taken out while it runs: a panic in naga drops it instead of
        // leaving one in an unknown state for the next module.
        let mut writer = match WRITER.take() {
            Some(mut w) => w.set_options(&options).map(|()| w),
            None => naga::back::spv::Writer::new(&options),
        }
        .map_err(|e| e.to_string())?;
        // naga 30's SPIR-V writer has no overrides: a program with
        // specialization constants is written from the module that holds
        // each in a private variable, whose initializer then becomes an
        // `OpSpecConstant` (`spirv_spec`; docs/targets.md, "Specialization
        // constants").
        let (module, info) = match (&lowered.spirv, lowered.gpu.overrides.is_empty()) {
            (_, true) => (&lowered.gpu, &lowered.gpu_info),
            (Some((m, i)), false) => (m, i),
            (None, false) => return Err("no SPIR-V module for the specialization constants (lowered without SPIR-V)".to_string()),
        };
        writer.write(module, info, None, &options.debug_info, &mut words).map_err(|e| e.to_string())?;
        if !lowered.gpu.overrides.is_empty() {
            let constants: Vec<(&str, u32)> = lowered.gpu.overrides.iter().filter_map(|(_, o)| Some((o.name.as_deref()?, u32::from(o.id?)))).collect();
            words = super::spirv_spec::specialize(&words, &constants)?;
        }
        WRITER.set(Some(writer));
        Ok(words)
    })
}

thread_local! {
    /// This thread's SPIR-V writer, kept between compilations: naga resets
    /// it per module and keeps its tables' memory, so a thread that compiles
    /// many variants builds them once. Every option [`options`] sets, apart
    /// from the constant ones, is one `Writer::set_options` replaces.
    static WRITER: std::cell::Cell<Option<naga::back::spv::Writer>> = const { std::cell::Cell::new(None) };
}
