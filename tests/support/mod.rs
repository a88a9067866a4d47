//! Helpers shared by the integration tests.
//!
//! - [`on_ci`], [`skip`], [`or_skip`] (`ci.rs`): what a test does when a
//!   tool, a device or a browser it needs is missing. With `CI=true` it
//!   fails; otherwise it prints `skipping: ...` and passes. Every test that
//!   needs one goes through these. `ci.rs` uses nothing but std, so that
//!   tests/build_crate.rs, which links nothing of umbrac's, includes it
//!   alone.
//! - [`gpu`]: the Vulkan device, wgpu's GL backend and the EGL GL/GLES
//!   contexts, opened once per process (feature `render`).
//! - [`preview`]: `umbrac preview` on a free port (feature `preview`).
//! - [`fake_lowered`]: a `Lowered` built from WGSL, shaped like the real
//!   lowering's output, so emitter tests do not depend on the front end.
//! - Validator runners: `glslangValidator` (each GLSL file, and each
//!   vertex+fragment pair linked), `spirv-val` and `tint` (the WGSL
//!   compiler inside Chrome, stricter than naga on WGSL's limits).
//!
//! Nothing here changes the process's environment (another test thread may
//! be reading it): what the GPU stack wants set comes from
//! `.cargo/config.toml`.
#![allow(dead_code)]

mod ci;
#[cfg(feature = "render")]
pub mod gpu;
#[cfg(feature = "preview")]
pub mod preview;

pub use ci::*;

use std::path::{Path, PathBuf};
use std::process::Command;

use naga::valid::{Capabilities, ValidationFlags, Validator};
use umbrac::emit::reflect::dsl_name;
use umbrac::lower::{EntryInterface, GlEntry, Interface, IoVar, Resource, ResourceKind};
use umbrac::sema::SamplerKind;
use umbrac::{Artifact, Conventions, Lowered, Reflection, Span};

/// Parses WGSL written in GL conventions into the modules the lowering
/// hands the emitter: `gpu` as written (every resource bound), and per entry
/// point a GL module: a copy with resource bindings cleared, reduced to that
/// entry point and what it reaches, validated without
/// `ValidationFlags::BINDINGS`. Texture `X` pairs with sampler `X_sampler`.
pub fn fake_lowered(src: &str) -> Lowered {
    let gpu = naga::front::wgsl::parse_str(src).unwrap_or_else(|e| panic!("test WGSL does not parse:\n{}", e.emit_to_string(src)));
    let gpu_info = Validator::new(ValidationFlags::all(), Capabilities::default())
        .validate(&gpu)
        .unwrap_or_else(|e| panic!("test WGSL does not validate:\n{}", e.emit_to_string(src)));
    let mut gl = gpu.clone();
    for (_, g) in gl.global_variables.iter_mut() {
        if matches!(g.space, naga::AddressSpace::Uniform | naga::AddressSpace::Handle | naga::AddressSpace::Storage { .. }) {
            g.binding = None;
        }
    }
    let gl = (0..gpu.entry_points.len()).map(|i| gl_entry(&gl, i, src)).collect();
    let interface = interface_of(&gpu, &gpu_info);
    Lowered { gl, gpu, gpu_info, spirv: None, interface }
}

/// `gl` reduced to entry point `index` and what it reaches, as the lowering
/// builds it: unused named constants are dropped too.
fn gl_entry(gl: &naga::Module, index: usize, src: &str) -> GlEntry {
    let mut module = gl.clone();
    let mut i = 0;
    module.entry_points.retain(|_| {
        i += 1;
        i - 1 == index
    });
    naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
    let mut used = std::collections::HashSet::new();
    let functions = module.functions.iter().map(|(_, f)| f).chain(module.entry_points.iter().map(|e| &e.function));
    for f in functions {
        for (_, e) in f.expressions.iter() {
            if let naga::Expression::Constant(c) = *e {
                used.insert(c);
            }
        }
    }
    for (h, c) in module.constants.iter_mut() {
        if !used.contains(&h) {
            c.name = None;
        }
    }
    naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
    let info = Validator::new(ValidationFlags::all() - ValidationFlags::BINDINGS, naga::back::glsl::supported_capabilities())
        .validate(&module)
        .unwrap_or_else(|e| panic!("GL copy does not validate:\n{}", e.emit_to_string(src)));
    GlEntry { module, info, uniforms: Vec::new() }
}

fn sampler_kind(inner: &naga::TypeInner) -> Option<SamplerKind> {
    use naga::{ImageClass as C, ImageDimension as D, ScalarKind as K};
    let naga::TypeInner::Image { dim, arrayed, class } = *inner else { return None };
    Some(match (dim, arrayed, class) {
        (D::D2, false, C::Depth { .. }) => SamplerKind::Sampler2DShadow,
        (D::D2, true, C::Depth { .. }) => SamplerKind::Sampler2DArrayShadow,
        (D::Cube, false, C::Depth { .. }) => SamplerKind::SamplerCubeShadow,
        (D::D2, false, C::Sampled { kind: K::Sint, .. }) => SamplerKind::ISampler2D,
        (D::D2, false, C::Sampled { kind: K::Uint, .. }) => SamplerKind::USampler2D,
        (D::D2, false, C::Sampled { .. }) => SamplerKind::Sampler2D,
        (D::D2, true, C::Sampled { .. }) => SamplerKind::Sampler2DArray,
        (D::D3, false, C::Sampled { .. }) => SamplerKind::Sampler3D,
        (D::Cube, false, C::Sampled { .. }) => SamplerKind::SamplerCube,
        _ => return None,
    })
}

fn builtin_name(b: naga::BuiltIn, output: bool) -> String {
    match b {
        naga::BuiltIn::Position { .. } if output => "gl_Position".into(),
        naga::BuiltIn::Position { .. } => "gl_FragCoord".into(),
        naga::BuiltIn::FrontFacing => "gl_FrontFacing".into(),
        naga::BuiltIn::VertexIndex => "gl_VertexIndex".into(),
        naga::BuiltIn::InstanceIndex => "gl_InstanceIndex".into(),
        naga::BuiltIn::FragDepth => "gl_FragDepth".into(),
        naga::BuiltIn::PointSize => "gl_PointSize".into(),
        other => format!("{other:?}"),
    }
}

/// Every vertex entry point with every fragment one: a WGSL test module
/// states no programs.
fn umbrac_links(eps: &[EntryInterface]) -> Vec<(usize, usize)> {
    let of = |stage| eps.iter().filter(move |e| e.stage == stage).map(|e| e.index);
    of(naga::ShaderStage::Vertex).flat_map(|v| of(naga::ShaderStage::Fragment).map(move |f| (v, f))).collect()
}

fn interface_of(m: &naga::Module, info: &naga::valid::ModuleInfo) -> Interface {
    let mut resources = Vec::new();
    let mut unit = 0;
    for (h, g) in m.global_variables.iter() {
        let name = g.name.clone().unwrap_or_default();
        let (group, binding) = g.binding.as_ref().map(|b| (b.group, b.binding)).unwrap_or((0, 0));
        let kind = match g.space {
            naga::AddressSpace::Uniform => ResourceKind::Uniform { ty: g.ty, dsl_type: dsl_name(m, g.ty), loose: false },
            naga::AddressSpace::Handle => match sampler_kind(&m.types[g.ty].inner) {
                Some(k) => ResourceKind::Sampler(k),
                None => continue,
            },
            _ => continue,
        };
        let mut r = Resource {
            name: name.clone(),
            span: Span::default(),
            kind,
            global: h,
            sampler_global: None,
            group,
            binding,
            sampler_binding: None,
            texture_unit: None,
            default: None,
        };
        if let ResourceKind::Sampler(_) = r.kind {
            let (sh, sg) = m
                .global_variables
                .iter()
                .find(|(_, s)| s.name.as_deref() == Some(&format!("{name}_sampler")))
                .unwrap_or_else(|| panic!("texture `{name}` needs a sampler `{name}_sampler`"));
            r.sampler_global = Some(sh);
            r.sampler_binding = sg.binding.as_ref().map(|b| b.binding);
            r.texture_unit = Some(unit);
            unit += 1;
        }
        resources.push(r);
    }

    let mut entry_points = Vec::new();
    for (index, ep) in m.entry_points.iter().enumerate() {
        let mut e = EntryInterface {
            name: ep.name.clone(),
            stage: ep.stage,
            index,
            inputs: vec![],
            outputs: vec![],
            builtins: vec![],
            resources: vec![],
            loose: vec![],
            workgroup_size: ep.workgroup_size,
            workgroup: vec![],
            span: Default::default(),
            dialect: Default::default(),
        };
        let visit = |name: Option<&String>, ty, binding: Option<&naga::Binding>, output: bool, e: &mut EntryInterface| match binding {
            Some(naga::Binding::Location { location, interpolation, .. }) => {
                let v = IoVar { name: name.cloned().unwrap_or_default(), location: *location, explicit_location: true, span: Default::default(), ty, dsl_type: dsl_name(m, ty), interpolation: *interpolation };
                if output { e.outputs.push(v) } else { e.inputs.push(v) }
            }
            Some(naga::Binding::BuiltIn(b)) => e.builtins.push(builtin_name(*b, output)),
            None => {}
        };
        for arg in &ep.function.arguments {
            if let naga::TypeInner::Struct { members, .. } = &m.types[arg.ty].inner {
                for mem in members {
                    visit(mem.name.as_ref(), mem.ty, mem.binding.as_ref(), false, &mut e);
                }
            } else {
                // As in the lowering's GL modules, the argument holding an
                // input is `in_NAME` and the input is `NAME`.
                let name = arg.name.as_ref().map(|n| n.strip_prefix("in_").unwrap_or(n).to_string());
                visit(name.as_ref(), arg.ty, arg.binding.as_ref(), false, &mut e);
            }
        }
        if let Some(res) = &ep.function.result {
            if let naga::TypeInner::Struct { members, .. } = &m.types[res.ty].inner {
                for mem in members {
                    visit(mem.name.as_ref(), mem.ty, mem.binding.as_ref(), true, &mut e);
                }
            } else {
                visit(None, res.ty, res.binding.as_ref(), true, &mut e);
            }
        }
        let usage = info.get_entry_point(index);
        for (ri, r) in resources.iter().enumerate() {
            if !usage[r.global].is_empty() {
                e.resources.push(ri);
            }
        }
        entry_points.push(e);
    }
    let links = umbrac_links(&entry_points);
    Interface { conventions: Conventions::Portable, push_constants: Vec::new(), gl_uniforms: Default::default(), resources, entry_points, links, gl_block_points: Vec::new(), loose: Vec::new() }
}

/// The repository root.
pub fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Runs the `umbrac` binary with `args` in `cwd`.
#[cfg(feature = "cli")]
pub fn umbrac(args: &[&str], cwd: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_umbrac")).args(args).current_dir(cwd).output().expect("run umbrac")
}

/// Whether `tool` can run; when it cannot, [`skip`].
pub fn require_tool(tool: &str) -> bool {
    if Command::new(tool).arg("--version").output().is_ok() {
        return true;
    }
    skip(format!("`{tool}` cannot be run (apt-get install glslang-tools spirv-tools)"));
    false
}

fn run(cmd: &mut Command) -> Result<(), String> {
    let out = cmd.output().map_err(|e| format!("cannot run {cmd:?}: {e}"))?;
    if out.status.success() {
        Ok(())
    } else {
        Err(format!("{cmd:?} failed:\n{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr)))
    }
}

/// `glslangValidator FILE` (stage from the extension, profile from `#version`).
pub fn glslang(path: &Path) -> Result<(), String> {
    run(Command::new("glslangValidator").arg(path))
}

/// `glslangValidator -l VERT FRAG`: compiles and links one program.
pub fn glslang_link(vert: &Path, frag: &Path) -> Result<(), String> {
    run(Command::new("glslangValidator").arg("-l").arg(vert).arg(frag))
}

/// `spirv-val --target-env vulkan1.0 FILE` (vulkan1.1 for a SPIR-V 1.3 module).
pub fn spirv_val(path: &Path) -> Result<(), String> {
    // The version word: 1.3 modules (subgroups) are Vulkan 1.1's.
    let words = std::fs::read(path).unwrap_or_default();
    let env = match words.get(4..8) {
        Some(v) if u32::from_le_bytes([v[0], v[1], v[2], v[3]]) >= 0x0001_0300 => "vulkan1.1",
        _ => "vulkan1.0",
    };
    run(Command::new("spirv-val").args(["--target-env", env]).arg(path))
}

/// Whether `tint` can run (it has no `--version`: `--help` exits 1 but
/// proves it starts); when it cannot, [`skip`].
pub fn require_tint() -> bool {
    if Command::new("tint").arg("--help").output().is_ok() {
        return true;
    }
    skip("`tint` cannot be run (build Dawn's tint and put it on PATH, /usr/local/bin/tint)");
    false
}

/// `tint --format wgsl -o /dev/null FILE`: what Chrome's WebGPU does with
/// the WGSL.
pub fn tint(path: &Path) -> Result<(), String> {
    run(Command::new("tint").args(["--format", "wgsl", "-o", "/dev/null"]).arg(path))
}

/// Writes artifacts into `dir` (plainly; atomicity is tested elsewhere).
pub fn write_all(dir: &Path, artifacts: &[Artifact]) -> Vec<PathBuf> {
    artifacts
        .iter()
        .map(|a| {
            let p = dir.join(&a.file_name);
            std::fs::write(&p, &a.contents).unwrap();
            p
        })
        .collect()
}

/// The programs of a manifest: (vertex, fragment) entry point names.
pub fn link_pairs(r: &Reflection) -> Vec<(String, String)> {
    r.programs.iter().map(|p| (p.vertex.clone(), p.fragment.clone())).collect()
}

/// Runs every validator on outputs written to `dir`: glslangValidator on
/// each GLSL file and on each linkable pair per profile, spirv-val on each
/// .spv, tint on each .wgsl. Returns the number of validator runs (0 when tools are missing
/// outside CI).
pub fn validate_dir(dir: &Path, r: &Reflection) -> usize {
    let mut runs = 0;
    let mut failures = Vec::new();
    let files: Vec<PathBuf> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    if require_tool("glslangValidator") {
        for f in files.iter().filter(|p| matches!(p.extension().and_then(|e| e.to_str()), Some("vert" | "frag" | "comp"))) {
            runs += 1;
            if let Err(e) = glslang(f) {
                failures.push(e);
            }
        }
        for (v, f) in link_pairs(r) {
            for infix in ["330", "300es", "430", "310es"] {
                let (vp, fp) = (dir.join(format!("{v}.{infix}.vert")), dir.join(format!("{f}.{infix}.frag")));
                if vp.exists() && fp.exists() {
                    runs += 1;
                    if let Err(e) = glslang_link(&vp, &fp) {
                        failures.push(e);
                    }
                }
            }
        }
    }
    if require_tool("spirv-val") {
        for f in files.iter().filter(|p| p.extension().and_then(|e| e.to_str()) == Some("spv")) {
            runs += 1;
            if let Err(e) = spirv_val(f) {
                failures.push(e);
            }
        }
    }
    if require_tint() {
        for f in files.iter().filter(|p| p.extension().and_then(|e| e.to_str()) == Some("wgsl")) {
            runs += 1;
            if let Err(e) = tint(f) {
                failures.push(e);
            }
        }
    }
    assert!(failures.is_empty(), "validator failures:\n{}", failures.join("\n"));
    runs
}

/// `shaders/shadow.das` with its PCF helper taking the shadow map as a
/// sampler parameter instead of reading the global: lowered to a copy
/// specialised for `shadow_map`, it must draw the very same picture.
pub fn shadow_scene_with_sampler_parameter() -> String {
    let scene = include_str!("../../shaders/shadow.das");
    let text = scene
        .replace("def sun_visibility(uv : float2; depth : float)", "def sun_visibility(map : sampler2DShadow; uv : float2; depth : float)")
        .replace("textureCompare(shadow_map, uv", "textureCompare(map, uv")
        .replace("sun_visibility(uv, depth - bias)", "sun_visibility(shadow_map, uv, depth - bias)");
    for edited in ["(map : sampler2DShadow", "textureCompare(map, uv", "sun_visibility(shadow_map, uv"] {
        assert_eq!(text.matches(edited).count(), 1, "shaders/shadow.das changed: update shadow_scene_with_sampler_parameter");
    }
    text
}

/// `shaders/shadow.das` with its 3x3 PCF loop (`uv + float2(x, y) * step`,
/// one texel a step) unrolled into nine `textureCompareOffset` calls: the
/// same taps, found by the sampler's offset instead of the coordinate.
pub fn shadow_scene_with_texel_offsets() -> String {
    let scene = include_str!("../../shaders/shadow.das");
    let start = scene.find("def sun_visibility(").expect("shaders/shadow.das has sun_visibility");
    let end = start + scene[start..].find("\n}\n").expect("sun_visibility ends") + 3;
    assert!(scene.contains("#define PCF_TAPS_RADIUS 1\n"), "shaders/shadow.das changed: update shadow_scene_with_texel_offsets");
    let mut body = String::from("def sun_visibility(uv : float2; depth : float) : float {\n    var lit = 0.0\n");
    for y in -1..=1 {
        for x in -1..=1 {
            body.push_str(&format!("    lit += textureCompareOffset(shadow_map, uv, depth, int2({x}, {y}))\n"));
        }
    }
    body.push_str("    return lit / 9.0\n}\n");
    format!("{}{body}{}", &scene[..start], &scene[end..])
}

/// `shaders/shadow.das` with two uniforms the scene does not set, whose
/// defaults (`= 2.0`, `= float3(0.5)`) scale the colour back to what it
/// was: the picture is the same only if every host uploads the defaults.
pub fn shadow_scene_with_uniform_defaults() -> String {
    let scene = include_str!("../../shaders/shadow.das");
    let out = "    f_FragColor = float4(color, 1.0)\n}";
    assert!(scene.contains(out), "shaders/shadow.das changed: update shadow_scene_with_uniform_defaults");
    let scene = scene.replace(out, "    f_FragColor = float4(color * u_gain * u_balance, 1.0)\n}");
    let first_uniform = scene.find("var @uniform").expect("a uniform");
    format!("{}var @uniform u_gain : float = 2.0\nvar @uniform u_balance : float3 = float3(0.5)\n{}", &scene[..first_uniform], &scene[first_uniform..])
}

