//! Issue 36: daslang's Vulkan dialect (dasSpirv's stages, resources at
//! `@set`/`@binding`, `@push_constant`, stage I/O by `@location`, Vulkan
//! conventions). dasVulkan's 15 tutorials (17 shader files, two of them
//! in `02_mandelbrot/window/`) are compiled
//! where they stand, with the daslang tree as `--daslang-root`, to every
//! target that can express them; every output is validated (naga inside
//! the compiler, glslangValidator per file and per linked vertex/fragment
//! pair, spirv-val, tint). The files that need what umbrac does not have
//! are expected refusals, each named with the errors it gives, so that a
//! change either way fails here. Skipped without `../shared/reference`
//! (failed with `CI=true`).

use std::path::PathBuf;

use crate::support;
use umbrac::{Options, Target};

fn daslang_tree() -> Option<PathBuf> {
    let dir = support::repo().join("../shared/reference/daslang");
    if dir.join("modules/dasVulkan/tutorials").is_dir() {
        Some(dir)
    } else {
        support::skip(format!("no daslang tree with dasVulkan's tutorials at {}", dir.display()));
        None
    }
}

/// What each shader file is expected to do.
enum Expect {
    /// Compiles for `targets` (empty: umbrac's defaults) and validates;
    /// `programs` vertex/fragment pairs are linked.
    Compiles { targets: &'static [Target], programs: usize },
    /// Refused: these errors (each a substring of one error message, all
    /// located in the file) are among those it gives.
    Refused(&'static [&'static str]),
}

const STORAGE_IMAGE_TARGETS: &[Target] = &[Target::Glsl430, Target::Spirv];

const FILES: &[(&str, Expect)] = &[
    ("01_triangle/triangle_tut_shaders.das", Expect::Compiles { targets: &[], programs: 1 }),
    // A read-write image (no `@readonly`/`@writeonly`, as dasSpirv writes
    // it): GLSL ES 3.10 and WGSL have those only for r32 formats.
    ("02_mandelbrot/mandelbrot_tut_shaders.das", Expect::Compiles { targets: STORAGE_IMAGE_TARGETS, programs: 0 }),
    ("02_mandelbrot/window/mandelbrot_view_shaders.das", Expect::Compiles { targets: &[], programs: 1 }),
    ("02_mandelbrot/window/mandelbrot_zoom_shaders.das", Expect::Compiles { targets: STORAGE_IMAGE_TARGETS, programs: 0 }),
    ("03_sdf/sdf_tut_shaders.das", Expect::Compiles { targets: STORAGE_IMAGE_TARGETS, programs: 0 }),
    ("04_cube/cube_tut_shaders.das", Expect::Compiles { targets: &[], programs: 1 }),
    ("05_instancing/instancing_tut_shaders.das", Expect::Compiles { targets: &[], programs: 1 }),
    ("06_skybox/skybox_tut_shaders.das", Expect::Compiles { targets: &[], programs: 3 }),
    ("07_particles/particles_tut_shaders.das", Expect::Compiles { targets: &[], programs: 1 }),
    ("08_shadow/shadow_tut_shaders.das", Expect::Compiles { targets: &[], programs: 1 }),
    ("09_msaa/msaa_tut_shaders.das", Expect::Compiles { targets: &[], programs: 1 }),
    // The SSAO and lighting passes draw one full-screen triangle each, with
    // one varying: either vertex entry point feeds either fragment one.
    ("10_deferred/deferred_tut_shaders.das", Expect::Compiles { targets: &[], programs: 5 }),
    ("11_hdr/hdr_tut_shaders.das", Expect::Compiles { targets: &[], programs: 5 }),
    // `gl_DrawID` and the descriptor array `sampler2D[6]` (indexed with
    // `nonuniformEXT`): SPIR-V has both; with the default targets, both
    // are refused by name.
    ("12_gpu_driven/gpu_driven_tut_shaders.das", Expect::Compiles { targets: &[Target::Spirv], programs: 9 }),
    // The task and mesh stages: SPIR-V 1.4 (VK_EXT_mesh_shader) only; with
    // the default targets each is refused naming the stage and targets
    // (`mesh_and_task_stages_are_spirv_only`). 14 links its floor and sky
    // passes (one `float3` at location 0 each) every way: 4 programs.
    ("13_mesh/mesh_tut_shaders.das", Expect::Compiles { targets: &[Target::Spirv], programs: 0 }),
    ("14_teapot/teapot_tut_shaders.das", Expect::Compiles { targets: &[Target::Spirv], programs: 4 }),
    (
        "15_raytracing/raytracing_tut_shaders.das",
        Expect::Refused(&[
            "the ray generation stage (`[vulkan_raygen_shader]`) is not supported by umbrac on",
            "the miss stage (`[vulkan_miss_shader]`) is not supported by umbrac on",
            "the closest-hit stage (`[vulkan_closest_hit_shader]`) is not supported by umbrac on",
            "`@ray_payload` (of ray-tracing shaders) is not supported by umbrac on",
        ]),
    ),
];

/// Every shader file of dasVulkan's tutorials (`*_shaders.das`, in
/// subfolders too), relative to the tutorials folder: each must be in
/// `FILES`.
fn shader_files(tree: &std::path::Path) -> Vec<String> {
    let root = tree.join("modules/dasVulkan/tutorials");
    let mut out = Vec::new();
    let mut dirs = vec![root.clone()];
    while let Some(dir) = dirs.pop() {
        for p in std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()) {
            if p.is_dir() {
                dirs.push(p);
            } else if p.file_name().unwrap().to_string_lossy().ends_with("_shaders.das") {
                out.push(p.strip_prefix(&root).unwrap().to_string_lossy().replace('\\', "/"));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn dasvulkan_tutorials_compile_where_they_stand_or_are_refused_by_name() {
    let Some(tree) = daslang_tree() else { return };
    let mut listed: Vec<String> = FILES.iter().map(|f| f.0.to_string()).collect();
    listed.sort();
    let found = shader_files(&tree);
    // 15 tutorials, 17 files: the list names those that exist.
    assert_eq!(found.len(), 17, "dasVulkan's tutorials have 17 shader files: {found:?}");
    assert!(found.iter().all(|f| listed.contains(f)), "shader files not in FILES: {found:?}");
    let mut failures = Vec::new();
    let (mut compiled_n, mut runs) = (0, 0);
    for (file, expect) in FILES {
        let path = tree.join("modules/dasVulkan/tutorials").join(file);
        if !path.is_file() {
            failures.push(format!("{file}: not in the daslang tree"));
            continue;
        }
        let targets = match expect {
            Expect::Compiles { targets, .. } => targets.to_vec(),
            Expect::Refused(_) => Vec::new(),
        };
        let c = umbrac::compile_file(&path, &Options { daslang_root: Some(tree.clone()), targets, ..Default::default() });
        match (expect, c.result.as_ref().filter(|_| !c.has_errors())) {
            (Expect::Compiles { programs, .. }, Some(out)) => {
                compiled_n += 1;
                if out.reflection.programs.len() != *programs {
                    failures.push(format!("{file}: {} programs linked, expected {programs}: {:?}", out.reflection.programs.len(), support::link_pairs(&out.reflection)));
                }
                let dir = tempfile::tempdir().unwrap();
                support::write_all(dir.path(), &out.artifacts);
                runs += support::validate_dir(dir.path(), &out.reflection);
            }
            (Expect::Compiles { .. }, None) => failures.push(format!("{file} does not compile:\n{}", c.render_diagnostics())),
            (Expect::Refused(_), Some(_)) => failures.push(format!("{file} compiles, but is expected to be refused")),
            (Expect::Refused(wanted), None) => {
                let rendered = c.render_diagnostics();
                for w in *wanted {
                    if !c.diagnostics.iter().any(|d| d.message.contains(w)) {
                        failures.push(format!("{file}: no error says {w:?}:\n{rendered}"));
                    }
                }
                let stem = file.rsplit('/').next().unwrap();
                if !rendered.contains(&format!("{stem}:")) || rendered.contains("no entry points") {
                    failures.push(format!("{file}: the errors are not located in the file:\n{rendered}"));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    eprintln!("{compiled_n} of {} shader files compile, {runs} validator runs", FILES.len());
}

/// A file with both dialects: each links by its own rule and never with
/// the other's entry points, and each vertex entry point gets its own
/// dialect's clip-space adaptation.
const MIXED: &str = "var @in @location = 0 a_pos : float3
var @inout v_uv : float2
var @out g_color : float4
[vertex_program]
def gl_vs {
    v_uv = a_pos.xy
    gl_Position = float4(a_pos, 1.0)
}
[fragment_program]
def gl_fs {
    g_color = float4(v_uv, 0.0, 1.0)
}
var @out @location = 0 vk_uv_out : float2
[vertex_shader]
def vk_vs {
    vk_uv_out = a_pos.xy
    gl_Position = float4(a_pos, 1.0)
}
var @in @location = 0 vk_uv_in : float2
var @out @location = 0 vk_color : float4
[fragment_shader]
def vk_fs {
    vk_color = float4(vk_uv_in, 0.0, 1.0)
}
";

fn text(c: &umbrac::Compiled, file: &str) -> String {
    c.artifact(file).unwrap_or_else(|| panic!("no {file}")).text().into_owned()
}

#[test]
fn both_dialects_in_one_file_link_by_their_own_rules_and_adapt_by_their_own_conventions() {
    let c = umbrac::compile_source("mixed.das", MIXED, &Options::default());
    let out = c.result.as_ref().unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let mut pairs = support::link_pairs(&out.reflection);
    pairs.sort();
    assert_eq!(pairs, [("gl_vs".to_string(), "gl_fs".to_string()), ("vk_vs".into(), "vk_fs".into())]);
    // GL dialect: GLSL as written; WGSL y flipped and z remapped.
    let gl_vs = text(out, "gl_vs.330.vert");
    assert!(!gl_vs.contains("* 2.0) -"), "{gl_vs}");
    assert!(gl_vs.contains("out vec2 v_uv;"), "{gl_vs}");
    // Vulkan dialect: GLSL z' = 2z - w, y kept; the varying named by location.
    let vk_vs = text(out, "vk_vs.330.vert");
    assert!(vk_vs.contains("* 2.0) - ") && !vk_vs.contains("-(_e"), "{vk_vs}");
    assert!(vk_vs.contains("out vec2 vk_location0;") && text(out, "vk_fs.330.frag").contains("in vec2 vk_location0;"));
    let wgsl = text(out, "mixed.wgsl");
    let ret = |name: &str| wgsl.split(&format!("fn {name}(")).nth(1).and_then(|b| b.split("return ").nth(1)).map(|r| r.lines().next().unwrap().to_string()).unwrap();
    assert!(ret("gl_vs").contains("-(") && ret("gl_vs").contains("0.5f"), "{}", ret("gl_vs"));
    assert!(ret("vk_vs").contains("-(") && !ret("vk_vs").contains("0.5f"), "{}", ret("vk_vs"));
    let ep = |n: &str| out.reflection.entry_points.iter().find(|e| e.name == n).unwrap();
    assert_eq!(ep("gl_vs").dialect, None);
    assert_eq!(ep("vk_fs").dialect.as_deref(), Some("vulkan"));
    let clip = ep("vk_vs").clip_space.clone().unwrap();
    assert_eq!(clip["glsl330"], "z' = 2z - w");
    assert_eq!(clip["wgsl"], "y' = -y");
    let dir = tempfile::tempdir().unwrap();
    support::write_all(dir.path(), &out.artifacts);
    support::validate_dir(dir.path(), &out.reflection);

    // Native conventions adapt neither dialect on any target.
    let native = umbrac::compile_source("mixed.das", MIXED, &Options { conventions: umbrac::Conventions::Native, ..Default::default() });
    let native = native.result.unwrap();
    assert!(!text(&native, "vk_vs.330.vert").contains("* 2.0) - "));
    let wgsl = text(&native, "mixed.wgsl");
    assert!(!wgsl.contains("-(_e"), "{wgsl}");
    assert_eq!(native.reflection.entry_points.iter().find(|e| e.name == "vk_vs").unwrap().clip_space.as_ref().unwrap()["spirv"], "none");
}

/// A push constant is a uniform buffer the manifest marks, and a combined
/// image-sampler's halves are at B and just past the group's highest
/// binding in the GPU module.
#[test]
fn push_constants_and_samplers_are_where_the_manifest_says() {
    let src = "struct P {\n    k : float4\n}\nvar @push_constant pc : P\nvar @set = 1 @binding = 3 tex : sampler2D\nvar @out @location = 0 o : float4\n[fragment_shader]\ndef fs {\n    o = texture(tex, float2(0.5)) * pc.k\n}\n";
    let c = umbrac::compile_source("push.das", src, &Options::default());
    let out = c.result.as_ref().unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let pc = out.reflection.uniform_buffers.iter().find(|u| u.name == "pc").unwrap();
    assert_eq!(pc.push_constant, Some(true));
    assert_eq!(pc.glsl_block.as_deref(), Some("pc_ubo"));
    let wgsl = text(out, "push.wgsl");
    assert!(wgsl.contains(&format!("@group({}) @binding({}) \nvar<uniform> pc", pc.group, pc.binding)), "{wgsl}");
    let bindings = umbrac::bindgen::generate(out, &Default::default()).unwrap();
    let pc_module = bindings.split("pub mod pc {").nth(1).expect("a module for the push constant");
    assert!(pc_module.split("pub mod ").next().unwrap().contains("pub const PUSH_CONSTANT: bool = true;"), "{bindings}");
    let s = &out.reflection.samplers[0];
    assert_eq!((s.group, s.texture_binding, s.sampler_binding), (1, 3, 4));
    assert!(wgsl.contains("@group(1) @binding(4) \nvar tex_sampler"), "{wgsl}");
    let tex = bindings.split("pub mod tex {").nth(1).expect("a module for the sampler");
    assert!(tex.contains("pub const SAMPLER_BINDING: u32 = 4;"), "{bindings}");
}

/// The sampler halves take the bindings after the highest one of their
/// group in each program, in declaration order: the bindings written stay
/// where they are, and bindings written 0, 1, 2 ... stay gapless (what
/// wgpu needs of a passthrough SPIR-V module). Bindings up to 999 may be
/// written; a sampler whose half finds none below 1000 is refused (a
/// bad-input case).
#[test]
fn sampler_halves_follow_the_highest_binding_of_their_group() {
    let src = "\
struct U {
    k : float4
}
var @set = 0 @binding = 2 a : sampler2D
var @set = 0 @binding = 0 b : sampler2D
var @set = 0 @binding = 1 @uniform u : U
var @set = 1 @binding = 998 far : sampler2D
var @set = 2 @binding = 0 other : sampler2D
var @out @location = 0 o : float4
[fragment_shader]
def fs {
    o = texture(a, float2(0.5)) + texture(b, float2(0.5)) * u.k + texture(far, float2(0.5))
}
[fragment_shader]
def fs2 {
    o = texture(other, float2(0.5)) + texture(b, float2(0.5))
}
";
    let c = umbrac::compile_source("halves.das", src, &Options::default());
    let out = c.result.as_ref().unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let at = |n: &str| {
        let s = out.reflection.samplers.iter().find(|s| s.name == n).unwrap_or_else(|| panic!("no sampler {n}"));
        (s.group, s.texture_binding, s.sampler_binding)
    };
    // fs: group 0 holds 0, 1, 2 as written, then a's half, then b's.
    assert_eq!(at("a"), (0, 2, 3));
    assert_eq!(at("b"), (0, 0, 4));
    assert_eq!(at("far"), (1, 998, 999));
    // fs2 alone: other at 0, but b's half (shared with fs) keeps 4.
    assert_eq!(at("other"), (2, 0, 1));
    assert!(out.reflection.uniform_buffers.iter().any(|u| u.name == "u" && (u.group, u.binding) == (0, 1)));
}

/// Found by the fuzz campaign in CI: a Vulkan-dialect varying is named by
/// its location (`vk_location0`) in GLSL, and that name must be checked
/// against naga's names even when no stage input or output starts with
/// its letter (the checked set was narrowed to the stage I/O's initials).
#[test]
fn varyings_named_by_location_when_no_io_name_shares_their_initial() {
    let src = "var @in @location = 0 a_pos : float3
var @out @location = 0 n_out : float2
[vertex_shader]
def main_vs {
    n_out = a_pos.xy
    gl_Position = float4(a_pos, 1.0)
}
var @in @location = 0 f_n : float2
var @out @location = 0 o_color : float4
[fragment_shader]
def main_fs {
    o_color = float4(f_n, 0.0, 1.0)
}
";
    let c = umbrac::compile_source("initials.das", src, &Options::default());
    let out = c.result.as_ref().unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    assert!(text(out, "main_vs.330.vert").contains("out vec2 vk_location0;"));
    assert!(text(out, "main_fs.300es.frag").contains("in vec2 vk_location0;"));
}

/// A descriptor array (tutorial 12's `sampler2D[6]`): one binding array
/// of images and one of samplers in SPIR-V, the index naga finds varying
/// decorated NonUniform (its capability declared), one manifest entry
/// with the count; every other target refuses it by name.
#[test]
fn descriptor_arrays_are_binding_arrays_in_spirv_and_refused_elsewhere() {
    let src = "var @set = 1 @binding = 2 mats : sampler2D[6]
var @in @location = 0 @flat f_mat : int
var @out @location = 0 o : float4
[fragment_shader]
def fs {
    o = texture(mats[nonuniformEXT(f_mat)], float2(0.5)) + texture(mats[5], float2(0.5))
}
";
    let c = umbrac::compile_source("bindless.das", src, &Options { targets: vec![Target::Spirv], ..Default::default() });
    let out = c.result.as_ref().filter(|_| !c.has_errors()).unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let s = &out.reflection.samplers;
    assert_eq!(s.len(), 1, "{s:?}");
    assert_eq!((s[0].name.as_str(), s[0].group, s[0].texture_binding, s[0].sampler_binding, s[0].count), ("mats", 1, 2, 3, Some(6)));
    let words: Vec<u32> = out.artifact("bindless.spv").unwrap().contents.chunks_exact(4).map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]])).collect();
    // OpCapability ShaderNonUniform (5301), OpDecorate _ NonUniform (5300).
    assert!(words.windows(2).any(|w| w == [0x0002_0011, 5301]), "no ShaderNonUniform capability");
    assert!(words.windows(3).any(|w| w[0] == 0x0003_0047 && w[2] == 5300), "nothing decorated NonUniform");
    let dir = tempfile::tempdir().unwrap();
    support::write_all(dir.path(), &out.artifacts);
    support::validate_dir(dir.path(), &out.reflection);
    refused_by_every_other_target("bindless.das", src, &["an array of samplers in the Vulkan dialect (a descriptor array at one binding)"]);
}

/// Compiles `src` for each target but SPIR-V (beside SPIR-V, so that a
/// refusal cannot hide behind another target's) and requires nothing to be
/// written and an error "`construct` is not supported by the `t` target"
/// for every construct.
fn refused_by_every_other_target(file: &str, src: &str, constructs: &[&str]) {
    for t in [Target::Glsl330, Target::Gles300, Target::Wgsl, Target::Glsl430, Target::Gles310] {
        let c = umbrac::compile_source(file, src, &Options { targets: vec![t, Target::Spirv], ..Default::default() });
        assert!(c.result.is_none() || c.has_errors(), "{t:?} takes {file}");
        for construct in constructs {
            let msg = format!("{construct} is not supported by the {} target", t.name());
            assert!(c.diagnostics.iter().any(|d| d.message.contains(&msg)), "{t:?}: no error says {msg:?}:\n{}", c.render_diagnostics());
        }
    }
}

/// A task, a mesh and a fragment entry point (tutorial 13's shape): SPIR-V
/// 1.4 with the TaskEXT and MeshEXT execution models, the payload handed
/// on, the counts set and the mesh tasks emitted; the manifest names the
/// stages, the per-vertex output and what a Vulkan host enables. Every
/// other target refuses each stage by name.
const MESH: &str = "struct Payload {
    count : uint
    ids : uint[4]
}
var @task_payload payload : Payload
var @out @location = 0 m_color : array<float3>
[vulkan_task_shader(local_size_x = 4, name = \"cull\")]
def cull {
    payload.ids[gl_LocalInvocationIndex] = gl_LocalInvocationIndex
    payload.count = 4u
    EmitMeshTasksEXT(payload.count, 1u, 1u)
}
[vulkan_mesh_shader(local_size_x = 2, max_vertices = 3, max_primitives = 1, name = \"tri\")]
def tri {
    SetMeshOutputsEXT(3u, 1u)
    let i = gl_LocalInvocationIndex
    let id = float(payload.ids[gl_WorkGroupID.x])
    gl_MeshVerticesEXT[i].gl_Position = float4(float(i) * 0.5, id * 0.25, 0.0, 1.0)
    m_color[i] = float3(id)
    if (i == 0u) {
        gl_MeshVerticesEXT[2].gl_Position = float4(0.0, 1.0, 0.0, 1.0)
        m_color[2] = float3(1.0)
        gl_PrimitiveTriangleIndicesEXT[0] = uint3(0u, 1u, 2u)
        gl_MeshPrimitivesEXT[0].gl_PrimitiveID = int(id)
    }
}
var @in @location = 0 f_color : float3
var @out @location = 0 o : float4
[vulkan_fragment_shader(name = \"shade\")]
def shade {
    o = float4(f_color, 1.0)
}
";

#[test]
fn mesh_and_task_stages_are_spirv_only() {
    let c = umbrac::compile_source("mesh.das", MESH, &Options { targets: vec![Target::Spirv], ..Default::default() });
    let out = c.result.as_ref().filter(|_| !c.has_errors()).unwrap_or_else(|| panic!("{}", c.render_diagnostics()));
    let ep = |n: &str| out.reflection.entry_points.iter().find(|e| e.name == n).unwrap_or_else(|| panic!("no entry point {n}"));
    assert_eq!((ep("cull").stage.as_str(), ep("tri").stage.as_str(), ep("shade").stage.as_str()), ("task", "mesh", "fragment"));
    assert_eq!(ep("tri").workgroup_size, Some([2, 1, 1]));
    assert_eq!(ep("tri").outputs.iter().map(|o| (o.name.as_str(), o.location)).collect::<Vec<_>>(), [("m_color", 0)]);
    let requires = out.reflection.requires.as_ref().expect("mesh shaders need Vulkan features");
    assert_eq!(requires.spirv_version, "1.4");
    assert!(requires.vulkan.iter().any(|v| v.contains("VK_EXT_mesh_shader")), "{requires:?}");
    let words: Vec<u32> = out.artifact("mesh.spv").unwrap().contents.chunks_exact(4).map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]])).collect();
    assert_eq!(words[1], 0x0001_0400, "SPIR-V 1.4");
    // OpEntryPoint (15) with TaskEXT (5364) and MeshEXT (5365); OpEmitMeshTasksEXT (5294), OpSetMeshOutputsEXT (5295).
    let has_op = |op: u32| words.iter().any(|&w| w & 0xffff == op && w >> 16 >= 1 && w >> 16 < 16);
    for model in [5364, 5365] {
        assert!(words.windows(2).any(|w| w[0] & 0xffff == 15 && w[1] == model), "no entry point of execution model {model}");
    }
    assert!(has_op(5294) && has_op(5295), "no OpEmitMeshTasksEXT / OpSetMeshOutputsEXT");
    let dir = tempfile::tempdir().unwrap();
    support::write_all(dir.path(), &out.artifacts);
    support::validate_dir(dir.path(), &out.reflection);

    // Every other target: each stage refused by name, located at its annotation.
    refused_by_every_other_target("mesh.das", MESH, &["the task stage (`[vulkan_task_shader]`)", "the mesh stage (`[vulkan_mesh_shader]`)"]);
}
