//! The scene format and inference, from programs compiled here.

use super::*;

fn manifest(src: &str) -> crate::Reflection {
    let c = crate::compile_source("t.das", src, &crate::Options::default());
    assert!(!c.has_errors(), "{}", c.render_diagnostics());
    c.result.unwrap().reflection
}

const SCREEN_UV: &str = "var @in @location v_position : float2
var @uniform u_time : float
var @uniform u_res : float2
var @uniform u_tint : float3
var @uniform u_gain : float = 3.0
var @uniform u_on : bool
var @inout f_uv : float2
var @out f_color : float4
[vertex_program]
def vs {
    f_uv = v_position
    gl_Position = float4(v_position, 0.0, 1.0)
}
[fragment_program]
def fs {
    let k = u_on ? 1.0 : 0.5
    f_color = float4(u_tint * u_gain * k * sin(u_time) + float3(f_uv / u_res, 0.0), 1.0)
}
";

#[test]
fn a_fragment_program_over_screen_coordinates_draws_a_fullscreen_triangle() {
    let s = Scene::infer(&manifest(SCREEN_UV)).unwrap();
    assert_eq!(s.passes.len(), 1);
    let p = &s.passes[0];
    assert_eq!((p.vertex.as_str(), p.fragment.as_deref(), p.color.as_ref().and_then(ColorTargets::first), p.depth.as_deref()), ("vs", Some("fs"), Some(SCREEN), None));
    let d = &p.draws[0];
    assert_eq!(d.mesh, MeshKind::FullscreenTriangle);
    assert_eq!(d.attributes["v_position"], Attribute::Position);
    assert_eq!(s.values["u_time"], ValueSpec::Convention(Convention::Time));
    assert_eq!(s.values["u_res"], ValueSpec::Convention(Convention::Resolution));
    assert_eq!(s.values["u_gain"], ValueSpec::Number(3.0), "the manifest's default");
    let kind = |n: &str| infer::control(&s, n).unwrap().kind;
    assert_eq!(kind("u_tint"), ControlKind::Color);
    assert_eq!(kind("u_on"), ControlKind::Checkbox);
    assert_eq!(kind("u_time"), ControlKind::Convention);
    let gain = infer::control(&s, "u_gain").unwrap();
    assert_eq!((gain.kind, gain.min, gain.max), (ControlKind::Slider, Some(0.0), Some(6.0)));
    s.check().unwrap();
}

#[test]
fn a_vertex_program_without_inputs_draws_three_vertices() {
    let src = "var @out f_color : float4
[vertex_program]
def vs {
    let x = float(gl_VertexID & 1) * 4.0 - 1.0
    let y = float(gl_VertexID & 2) * 2.0 - 1.0
    gl_Position = float4(x, y, 0.0, 1.0)
}
[fragment_program]
def fs {
    f_color = float4(gl_FragCoord.xy / 64.0, 0.0, 1.0)
}
";
    let s = Scene::infer(&manifest(src)).unwrap();
    assert_eq!((s.passes[0].draws[0].mesh, s.passes[0].draws[0].vertices), (MeshKind::None, Some(3)));
}

const LIT_MESH: &str = "var @in a_pos : float3
var @in a_normal : float3
var @in a_uv : float2
var @uniform u_model : float4x4
var @uniform u_view : float4x4
var @uniform u_proj : float4x4
var @uniform u_cam_pos : float3
var @uniform @stage = 0 u_albedo : sampler2D
var @uniform @stage = 1 u_normal_map : sampler2D
var @inout w_normal : float3
var @inout w_uv : float2
var @out f_color : float4
[vertex_program]
def vs {
    w_normal = (u_model * float4(a_normal, 0.0)).xyz
    w_uv = a_uv
    gl_Position = u_proj * u_view * u_model * float4(a_pos, 1.0)
}
[fragment_program]
def fs {
    let n = normalize(w_normal + texture(u_normal_map, w_uv).xyz * 0.1)
    f_color = texture(u_albedo, w_uv) * max(dot(n, normalize(u_cam_pos)), 0.1)
}
";

#[test]
fn a_vertex_program_with_mesh_attributes_draws_the_cube_with_the_orbit_camera() {
    let s = Scene::infer(&manifest(LIT_MESH)).unwrap();
    let p = &s.passes[0];
    assert_eq!(p.draws[0].mesh, MeshKind::Cube);
    assert_eq!(p.depth.as_deref(), Some("depth"));
    assert!(s.targets.iter().any(|t| t.name == "depth" && t.format.is_depth()));
    let a = &p.draws[0].attributes;
    assert_eq!((a["a_pos"], a["a_normal"], a["a_uv"]), (Attribute::Position, Attribute::Normal, Attribute::Uv));
    for (n, c) in [("u_model", Convention::Model), ("u_view", Convention::View), ("u_proj", Convention::Projection), ("u_cam_pos", Convention::CameraPosition)] {
        assert_eq!(s.values[n], ValueSpec::Convention(c), "{n}");
    }
    let tex = |sampler: &str| {
        let name = &p.samplers[sampler].texture;
        s.textures.iter().find(|t| &t.name == name).unwrap().pattern.unwrap()
    };
    assert_eq!((tex("u_albedo"), tex("u_normal_map")), (Pattern::Checker, Pattern::FlatNormal));
    s.check().unwrap();
}

#[test]
fn instanced_attributes_get_an_instance_grid() {
    let src = "var @in a_pos : float3
var @in a_offset : float3
var @in a_color : float3
var @in a_phase : float
var @uniform u_view_proj : float4x4
var @inout w_color : float3
var @out f_color : float4
[vertex_program]
def vs {
    w_color = a_color * a_phase
    gl_Position = u_view_proj * float4(a_pos * 0.5 + a_offset, 1.0)
}
[fragment_program]
def fs {
    f_color = float4(w_color, 1.0)
}
";
    let s = Scene::infer(&manifest(src)).unwrap();
    let d = &s.passes[0].draws[0];
    assert_eq!(d.instances.as_ref().map(|g| g.total()), Some(9));
    let a = &d.attributes;
    assert_eq!((a["a_offset"], a["a_color"], a["a_phase"]), (Attribute::InstanceOffset, Attribute::InstanceColor, Attribute::InstancePhase));
    assert_eq!(s.values["u_view_proj"], ValueSpec::Convention(Convention::ViewProjection));
}

#[test]
fn a_shadow_sampler_reads_a_cleared_depth_target() {
    let src = "var @in a_pos : float3
var @uniform u_mvp : float4x4
var @uniform @stage = 0 shadow_map : sampler2DShadow
var @inout v_ls : float3
var @out f_color : float4
[vertex_program]
def vs {
    v_ls = a_pos * 0.5 + float3(0.5)
    gl_Position = u_mvp * float4(a_pos, 1.0)
}
[fragment_program]
def fs {
    f_color = float4(float3(textureCompare(shadow_map, v_ls.xy, v_ls.z)), 1.0)
}
";
    let s = Scene::infer(&manifest(src)).unwrap();
    assert_eq!(s.passes.len(), 2);
    let clear = &s.passes[0];
    assert!(clear.draws.is_empty() && clear.fragment.is_none());
    assert_eq!(clear.depth.as_deref(), Some(s.passes[1].samplers["shadow_map"].texture.as_str()));
    s.check().unwrap();
}

#[test]
fn a_compute_only_program_has_no_scene() {
    let src = "[compute_program(local_size_x = 1)]\ndef cs {\n}\n";
    let e = Scene::infer(&manifest(src)).unwrap_err();
    assert!(e.0.contains("compute"), "{e}");
}

#[test]
fn a_scene_round_trips_through_json() {
    let s = Scene::infer(&manifest(LIT_MESH)).unwrap();
    let json = serde_json::to_string_pretty(&s.to_json()).unwrap();
    assert_eq!(Scene::parse("s.json", &json).unwrap(), s);
}

const TWO_PASSES: &str = r#"
output = "screen"

[camera]
distance = 4.0
spin = 20.0

[[textures]]
name = "bricks"
pattern = "checker"

[[targets]]
name = "scene"
format = "rgba8"
size = [128, 128]

[[targets]]
name = "depth"
format = "depth32float"
size = [128, 128]

[[passes]]
name = "scene"
vertex = "vs"
fragment = "fs"
color = "scene"
depth = "depth"
clear = [0.1, 0.1, 0.2, 1.0]
samplers = { u_albedo = { texture = "bricks" } }
[[passes.draws]]
mesh = "sphere"
attributes = { a_pos = "position", a_normal = "normal", a_uv = "uv" }
values = { u_model = "model" }

[[passes]]
name = "post"
vertex = "post_vs"
fragment = "post_fs"
color = "screen"
samplers = { u_src = { texture = "scene", filter = "nearest" } }
[[passes.draws]]
mesh = "fullscreen_triangle"
attributes = { q_pos = "position" }

[values]
u_exposure = 1.5
u_view = "view"
"#;

#[test]
fn a_two_pass_scene_file_parses() {
    let s = Scene::parse("two.toml", TWO_PASSES).unwrap();
    assert_eq!(s.passes.len(), 2);
    assert_eq!(s.passes[1].samplers["u_src"].filter, Filter::Nearest);
    assert_eq!(s.passes[0].draws[0].values["u_model"], ValueSpec::Convention(Convention::Model));
    assert_eq!(s.values["u_exposure"], ValueSpec::Number(1.5));
    assert_eq!(s.camera.distance, 4.0);
    assert_eq!(s.camera.fov_y, 45.0, "unnamed camera fields keep their defaults");
}

#[test]
fn scene_file_errors_name_the_line_or_the_mistake() {
    let e = Scene::parse("bad.toml", "[[passes]]\nname = \"p\"\nvertex = 3\n").unwrap_err();
    assert!(e.starts_with("bad.toml:3:"), "{e}");
    assert!(e.ends_with("vertex = 3\n  |          ^"), "a caret under the value:\n{e}");
    let e = Scene::parse("bad.toml", &TWO_PASSES.replace("texture = \"bricks\"", "texture = \"brick\"")).unwrap_err();
    assert!(e.contains("`brick`"), "{e}");
    let line = TWO_PASSES.lines().position(|l| l.contains("u_albedo")).unwrap() + 1;
    assert!(e.starts_with(&format!("bad.toml:{line}:")), "placed where the name is quoted:\n{e}");
    let e = Scene::parse("bad.toml", &TWO_PASSES.replace("color = \"scene\"", "color = \"depth\"")).unwrap_err();
    assert!(e.contains("depth target"), "{e}");
    let e = Scene::parse("bad.toml", &TWO_PASSES.replace("mesh = \"sphere\"", "mesh = \"teapot\"")).unwrap_err();
    assert!(e.contains("teapot"), "{e}");
    let e = Scene::parse("bad.json", "{\"passes\": []}").unwrap_err();
    assert!(e.contains("at least one pass"), "{e}");
}

#[test]
fn patterns_have_their_documented_texels() {
    let c = Pattern::Checker.texels(16, 16);
    assert_eq!((&c[0..4], &c[8 * 4..8 * 4 + 4]), (&[200, 200, 200, 255][..], &[60, 60, 60, 255][..]));
    let uv = Pattern::Uv.texels(2, 2);
    assert_eq!(&uv[..], &[0, 0, 128, 255, 255, 0, 128, 255, 0, 255, 128, 255, 255, 255, 128, 255]);
    assert_eq!(Pattern::Noise.texels(8, 8), Pattern::Noise.texels(8, 8));
    assert!(Pattern::Noise.texels(32, 32).chunks(4).any(|p| p[0] != Pattern::Noise.texels(32, 32)[0]));
}

#[test]
fn a_lone_fragment_program_gets_a_fullscreen_vertex_program_to_append() {
    let src = "var @inout v_uv : float2
var @uniform u_time : float
var @out f_color : float4
[fragment_program]
def fs {
    f_color = float4(v_uv, sin(u_time), 1.0)
}
";
    let r = manifest(src);
    assert!(Scene::infer(&r).is_err());
    let vs = infer::fullscreen_vertex(&r).unwrap();
    let whole = manifest(&format!("{src}{vs}"));
    let s = Scene::infer(&whole).unwrap();
    assert_eq!((s.passes[0].vertex.as_str(), s.passes[0].draws[0].vertices), (infer::FULLSCREEN_VS, Some(3)));
    assert_eq!(infer::fullscreen_vertex(&whole), None, "it has a vertex program now");
}

#[test]
fn the_documented_example_parses() {
    let doc = include_str!("../../docs/runner.md");
    let start = doc.find("```toml\n").expect("docs/runner.md has a TOML scene") + "```toml\n".len();
    let text = &doc[start..start + doc[start..].find("```").unwrap()];
    let s = Scene::parse("runner.md", text).unwrap();
    assert_eq!((s.passes.len(), s.textures.len(), s.targets.len()), (2, 1, 2));
    assert_eq!(s.passes[0].draws[0].instances.as_ref().map(InstanceGrid::total), Some(9));
}

const LIT: &str = "[light]
kind = \"spot\"
position = [2.0, 4.0, 1.0]
target = [0.0, 0.5, 0.0]
spin = -20.0
fov_y = 70.0
near = 1.0
far = 20.0

[[passes]]
name = \"p\"
vertex = \"vs\"
color = \"screen\"
values = { u_vp = { convention = \"light_view_projections\", index = 0 } }
[[passes.draws]]
mesh = \"cube\"
transform = { translate = [0.0, 1.5, 0.0], axis = [0.3, 1.0, 0.2], angle = 10.0, spin = 40.0, scale = 1.1 }
[[passes.draws]]
mesh = \"plane\"
transform = { scale = [5.0, 1.0, 5.0] }
";

#[test]
fn lights_transforms_and_array_elements_parse_and_round_trip() {
    let s = Scene::parse("lit.toml", LIT).unwrap();
    let l = s.light.as_ref().unwrap();
    assert_eq!((l.kind, l.position, l.spin, l.fov_y), (LightKind::Spot, [2.0, 4.0, 1.0], -20.0, 70.0));
    assert_eq!(l.boxes(), vec![l.half_size], "a spot has one frustum");
    let t = s.passes[0].draws[0].transform.as_ref().unwrap();
    assert_eq!((t.translate, t.angle, t.spin, t.scale.axes()), ([0.0, 1.5, 0.0], 10.0, 40.0, [1.1; 3]));
    let floor = s.passes[0].draws[1].transform.as_ref().unwrap();
    assert_eq!((floor.scale.axes(), floor.axis, floor.spin), ([5.0, 1.0, 5.0], [0.0, 1.0, 0.0], 0.0), "defaults");
    assert_eq!(s.passes[0].values["u_vp"], ValueSpec::Element(ConventionElement { convention: Convention::LightViewProjections, index: 0 }));
    let json = s.to_json().to_string();
    assert_eq!(Scene::parse("lit.json", &json).unwrap(), s, "the JSON a page reads parses back the same");
    let sun = Scene::parse("sun.toml", "[light]\ncascades = [2.0, 4.0]\n[[passes]]\nname = \"p\"\nvertex = \"vs\"\ncolor = \"screen\"\ndraws = []\n").unwrap();
    assert_eq!(sun.light.unwrap().boxes(), vec![2.0, 4.0]);
    assert!(Scene::infer(&manifest(SCREEN_UV)).unwrap().light.is_none(), "an inferred scene has the default light");
    for c in ["light_position", "spot_direction", "light_view_projections", "shadow_matrix"] {
        assert!(Convention::ALL.iter().any(|x| serde_json::to_value(x).unwrap() == c), "{c}");
    }
}

#[test]
fn light_and_transform_mistakes_are_located() {
    // The parser places each at the table or the value it is about.
    let bad = |from: &str, to: &str| Scene::parse("lit.toml", &LIT.replacen(from, to, 1)).unwrap_err();
    let on = |e: &str, needle: &str| {
        let lines: Vec<usize> = LIT.lines().enumerate().filter(|(_, l)| l.contains(needle)).map(|(i, _)| i + 1).collect();
        assert!(lines.iter().any(|n| e.starts_with(&format!("lit.toml:{n}:"))), "placed on a line with `{needle}` ({lines:?}):\n{e}");
        assert!(e.contains(" | ") && e.contains('^'), "with the line and a caret:\n{e}");
    };
    let light = |e: &str| {
        let n = LIT.lines().position(|l| l == "[light]").unwrap() + 1;
        let line: usize = e.split(':').nth(1).unwrap().parse().unwrap();
        assert!((n..n + 9).contains(&line), "placed in the [light] table (lines {n}..):\n{e}");
    };
    let e = bad("kind = \"spot\"", "kind = \"lamp\"");
    assert!(e.contains("lamp"), "{e}");
    on(&e, "kind =");
    let e = bad("spin = -20.0", "spinn = -20.0");
    assert!(e.contains("spinn"), "unknown keys are refused:\n{e}");
    light(&e);
    let e = bad("fov_y = 70.0", "fov_y = 200.0");
    assert!(e.contains("fov_y = 200") && e.contains("between 0 and 180"), "{e}");
    light(&e);
    let e = bad("near = 1.0", "near = 0.0");
    assert!(e.contains("`near = 0` is not above 0"), "{e}");
    light(&e);
    let e = bad("far = 20.0", "far = 0.5");
    assert!(e.contains("far = 0.5"), "{e}");
    let e = bad("position = [2.0, 4.0, 1.0]", "position = [0.0, 0.5, 0.0]");
    assert!(e.contains("aims nowhere"), "{e}");
    light(&e);
    let e = bad("far = 20.0", "far = 20.0\ncascades = [1.0]");
    assert!(e.contains("cascades"), "{e}");
    let e = bad("axis = [0.3, 1.0, 0.2]", "axis = [0.0, 0.0, 0.0]");
    assert!(e.contains("axis = [0, 0, 0]"), "{e}");
    on(&e, "axis =");
    let e = bad("scale = [5.0, 1.0, 5.0]", "scale = [5.0, 0.0, 5.0]");
    assert!(e.contains("scale"), "{e}");
    on(&e, "scale = [5.0, 1.0, 5.0]");
    let e = bad("spin = 40.0", "spin = 40.0, twist = 1.0");
    assert!(e.contains("twist"), "unknown transform keys are refused:\n{e}");
    on(&e, "spin = 40.0");
    let e = bad("index = 0 }", "index = 0, of = 1 }");
    on(&e, "index = 0");
    let sun = |extra: &str| Scene::parse("sun.toml", &format!("[light]\n{extra}\n[[passes]]\nname = \"p\"\nvertex = \"vs\"\ncolor = \"screen\"\ndraws = []\n")).unwrap_err();
    assert!(sun("direction = [0.0, 0.0, 0.0]").contains("points nowhere"));
    assert!(sun("half_size = -1.0").contains("half_size = -1"));
    assert!(sun("cascades = [2.0, 0.0]").contains("half-size 0"));
    assert!(sun("cascades = [1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0]").contains("at most 8"));
    let e = Scene::parse("sun.json", "{\"light\": {\"near\": -1}, \"passes\": [{\"name\": \"p\", \"vertex\": \"vs\", \"color\": \"screen\", \"draws\": []}]}").unwrap_err();
    assert!(e.starts_with("sun.json:1:") && e.contains("not above 0"), "JSON too:\n{e}");
}

#[test]
fn the_projects_scene_files_parse() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders/scenes");
    let mut n = 0;
    for e in std::fs::read_dir(&dir).unwrap() {
        let path = e.unwrap().path();
        if !path.extension().is_some_and(|x| x == "toml" || x == "json") {
            continue; // an image a scene names
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let s = Scene::parse(&path.display().to_string(), &text).unwrap_or_else(|e| panic!("{e}"));
        // The shadow scene and the technique scenes are the built-in ones
        // as files (tests/gpu/scene_files.rs): lit and moving.
        let stem = path.file_stem().unwrap().to_string_lossy();
        if ["shadow", "spot", "pcf", "cascades", "proj", "cull", "rgba8-depth"].contains(&stem.as_ref()) {
            assert!(s.light.is_some() && s.passes.iter().all(|p| p.draws.iter().all(|d| d.transform.is_some())), "{}: animated", path.display());
            n += 1;
        }
    }
    assert_eq!(n, 7, "shadow.toml and the six technique scenes");
}

#[test]
fn the_documented_light_and_transform_parse() {
    let doc = include_str!("../../docs/runner.md");
    let at = doc.find("### Lights and transforms").expect("docs/runner.md says how lights and transforms are written");
    let start = at + doc[at..].find("```toml\n").unwrap() + "```toml\n".len();
    let text = &doc[start..start + doc[start..].find("```").unwrap()];
    let s = Scene::parse("runner.md", text).unwrap();
    let l = s.light.unwrap();
    assert_eq!((l.kind, l.boxes()), (LightKind::Sun, vec![2.0, 4.0, 7.5]));
    assert_eq!(s.passes[0].draws[0].transform.as_ref().map(|t| t.spin), Some(40.0));
}

#[test]
fn every_convention_is_in_the_documented_table() {
    let doc = include_str!("../../docs/runner.md");
    for c in Convention::ALL {
        let name = serde_json::to_value(c).unwrap();
        assert!(doc.contains(&format!("| `{}` |", name.as_str().unwrap())), "docs/runner.md's conventions table lacks {name}");
    }
}

const EVERY_SAMPLER: &str = "var @in a_pos : float3
var @uniform u_view_rot : float4x4
var @uniform u_proj : float4x4
var @uniform u_sky : samplerCube
var @uniform u_volume : sampler3D
var @uniform u_layers : sampler2DArray
var @inout v_dir : float3
var @out f_color : float4
[vertex_program]
def vs {
    v_dir = a_pos
    gl_Position = u_proj * u_view_rot * float4(a_pos, 1.0)
}
[fragment_program]
def fs {
    f_color = texture(u_sky, v_dir) + texture(u_volume, v_dir) + texture(u_layers, v_dir)
}
";

#[test]
fn cube_3d_and_array_samplers_read_textures_of_their_kind() {
    let s = Scene::infer(&manifest(EVERY_SAMPLER)).unwrap();
    let p = &s.passes[0];
    let tex = |sampler: &str| s.textures.iter().find(|t| t.name == p.samplers[sampler].texture).unwrap().clone();
    let (sky, volume, layers) = (tex("u_sky"), tex("u_volume"), tex("u_layers"));
    assert_eq!((sky.kind, sky.pattern, sky.size, sky.layers), (TextureKind::Cube, Some(Pattern::Sky), [64, 64], 1));
    assert_eq!((volume.kind, volume.layers), (TextureKind::D3, 32));
    assert_eq!((layers.kind, layers.layers), (TextureKind::D2Array, 4));
    // A skybox (a rotation-only view): no depth test, the camera looking up.
    assert_eq!(p.depth, None);
    assert!(s.camera.pitch < 0.0);
    // The format's keys round-trip, and a 2D texture writes neither.
    let back: Scene = serde_json::from_value(s.to_json()).unwrap();
    assert_eq!(back, s);
    assert!(s.to_json()["textures"].as_array().unwrap().iter().all(|t| t.get("kind").is_some()));
    let (texels, n) = sky.pattern_texels(Pattern::Sky);
    assert_eq!((texels.len(), n), (64 * 64 * 4 * 6, 6));
    let (texels, n) = volume.pattern_texels(Pattern::Checker);
    assert_eq!((texels.len(), n), (32 * 32 * 4 * 32, 32));
}

#[test]
fn the_sky_is_blue_above_the_horizon_and_coloured_by_direction_below() {
    let at = |face: usize, x: usize, y: usize| {
        let t = Texture { name: "s".into(), pattern: Some(Pattern::Sky), image: None, size: [16, 16], kind: TextureKind::Cube, layers: 1 };
        let (texels, _) = t.pattern_texels(Pattern::Sky);
        let i = 4 * (face * 256 + y * 16 + x);
        [texels[i], texels[i + 1], texels[i + 2]]
    };
    // +y (face 2): the zenith, deep blue; -y (3): the ground's darkest.
    let zenith = at(2, 8, 8);
    assert!(zenith[2] > 200 && zenith[0] < 60, "{zenith:?}");
    assert!(at(3, 8, 8).iter().all(|&c| c < 40), "{:?}", at(3, 8, 8));
    // The side faces: pale near the horizon (t = 0.5), ground below it
    // (t > 0.5, rows further down), each face its compass colour.
    for (face, strongest) in [(0, 0), (1, 1), (4, 2), (5, 0)] {
        let horizon = at(face, 8, 7);
        assert!(horizon.iter().all(|&c| c > 180), "face {face} horizon {horizon:?}");
        let ground = at(face, 8, 10);
        assert_eq!(ground.iter().enumerate().max_by_key(|(_, c)| **c).unwrap().0, strongest, "face {face} ground {ground:?}");
    }
}

#[test]
fn texture_kinds_are_checked() {
    let scene = |texture: &str| format!("[[textures]]\nname = \"t\"\n{texture}\n[[passes]]\nname = \"p\"\nvertex = \"vs\"\ncolor = \"screen\"\ndraws = []\n");
    for (texture, want) in [
        ("pattern = \"sky\"", "cube map's"),
        ("pattern = \"checker\"\nkind = \"cube\"\nsize = [8, 4]", "square"),
        ("pattern = \"checker\"\nlayers = 3", "layers = 3"),
        ("image = \"a.png\"\nkind = \"3d\"", "image file makes a 2D texture only"),
        ("pattern = \"checker\"\nkind = \"2d_array\"\nlayers = 0", "1 to 256"),
        ("pattern = \"checker\"\nkind = \"sphere\"", "unknown variant"),
    ] {
        let err = Scene::parse("s.toml", &scene(texture)).unwrap_err();
        assert!(err.contains(want) && err.contains("s.toml:"), "{texture}: {err}");
    }
    Scene::parse("s.toml", &scene("pattern = \"checker\"\nkind = \"2d_array\"\nlayers = 3")).unwrap();
}

#[test]
fn a_uniform_table_of_structs_is_filled_from_the_instance_grid_by_path() {
    let src = "struct Instance {
    offset_scale : float4
    color : float4
    weight : float
}
var @uniform u_view_proj : float4x4
var @uniform u_instances : Instance[12]
var @in a_position : float3
var @inout v_color : float4
var @out f_color : float4
[vertex_program]
def vs {
    let inst = u_instances[gl_InstanceID % 12]
    v_color = inst.color * inst.weight
    gl_Position = u_view_proj * float4(a_position * inst.offset_scale.w + inst.offset_scale.xyz, 1.0)
}
[fragment_program]
def fs {
    f_color = v_color
}
";
    let r = manifest(src);
    let s = Scene::infer(&r).unwrap();
    let grid = s.passes.last().unwrap().draws[0].instances.clone().expect("gl_InstanceID: a grid");
    // Element 10 is cell 10 mod 9 = 1.
    let (offset, colour, _) = grid.instance(1);
    let f = |v: [f32; 3], w: f64| ValueSpec::Numbers(vec![v[0] as f64, v[1] as f64, v[2] as f64, w]);
    assert_eq!(s.values["u_instances[10].offset_scale"], f(offset, 0.45));
    assert_eq!(s.values["u_instances[10].color"], f(colour, 1.0));
    assert_eq!(s.values["u_instances[0].weight"], ValueSpec::Number(0.5));
    assert!(!s.values.contains_key("u_instances"));
    let leaves = infer::leaves(&r, "u_instances", "Instance[12]");
    assert_eq!(leaves.len(), 36);
    let stride = r.uniform_buffers[0].members.iter().find(|m| m.name == "u_instances").unwrap().array_stride.unwrap();
    assert_eq!((leaves[4].path.as_str(), leaves[4].offset), ("u_instances[1].color", stride + 16));
}

#[test]
fn a_point_sprite_draws_the_spheres_vertices_as_points() {
    let src = "var @uniform u_view_proj : float4x4
var @in a_pos : float3
var @out f_color : float4
[vertex_program]
def vs {
    gl_PointSize = 8.0
    gl_Position = u_view_proj * float4(a_pos, 1.0)
}
[fragment_program]
def fs {
    f_color = float4(gl_PointCoord, 1.0, 1.0)
}
";
    let s = Scene::infer(&manifest(src)).unwrap();
    let d = &s.passes.last().unwrap().draws[0];
    assert_eq!((d.mesh, d.primitive), (MeshKind::Sphere, Primitive::Points));
    assert_eq!(s.to_json()["passes"][0]["draws"][0]["primitive"], "points");
    let bad = "[[passes]]\nname = \"p\"\nvertex = \"vs\"\ncolor = \"screen\"\n[[passes.draws]]\nmesh = \"none\"\nvertices = 3\nprimitive = \"points\"\n";
    let err = Scene::parse("s.toml", bad).unwrap_err();
    assert!(err.contains("has none") && err.contains("s.toml:"), "{err}");
}

/// TWO_PASSES with its first pass drawing into `albedo` and `normal` too.
fn gbuffer(color: &str, normal_size: &str) -> String {
    TWO_PASSES.replace("color = \"scene\"", &format!("color = {color}")).replace(
        "[[targets]]\nname = \"depth\"",
        &format!("[[targets]]\nname = \"normal\"\nformat = \"rgba8\"\nsize = {normal_size}\n\n[[targets]]\nname = \"depth\""),
    )
}

#[test]
fn a_pass_may_draw_into_a_list_of_colour_targets() {
    let s = Scene::parse("g.toml", &gbuffer(r#"["scene", "normal"]"#, "[128, 128]")).unwrap();
    let c = s.passes[0].color.as_ref().unwrap();
    assert_eq!(c.names(), ["scene", "normal"]);
    assert_eq!(c.first(), Some("scene"));
    assert_eq!(s.passes[1].color, Some(ColorTargets::One(SCREEN.into())), "the single form stays");
    assert_eq!(s.to_json()["passes"][0]["color"], serde_json::json!(["scene", "normal"]));
    assert_eq!(s.to_json()["passes"][1]["color"], "screen");
}

#[test]
fn a_list_of_colour_targets_is_checked() {
    let err = |color: &str, size: &str| Scene::parse("g.toml", &gbuffer(color, size)).unwrap_err();
    let square = "[128, 128]";
    let e = err(r#"["scene", "scene"]"#, square);
    assert!(e.contains("`scene` twice"), "{e}");
    let e = err(r#"["scene", "screen"]"#, square);
    assert!(e.contains("cannot hold `screen`"), "{e}");
    let e = err(r#"["scene", "depth"]"#, square);
    assert!(e.contains("depth target `depth`"), "{e}");
    let e = err(r#"["scene", "normals"]"#, square);
    assert!(e.contains("`normals` names no render target") && e.contains('^'), "located:\n{e}");
    let e = err(r#"["scene", "normal"]"#, "[64, 64]");
    assert!(e.contains("differ in size") && e.contains("128x128") && e.contains("64x64"), "{e}");
    let e = err("[]", square);
    assert!(e.contains("`color = []`"), "{e}");
    let e = err("3", square);
    assert!(e.starts_with("g.toml:") && e.contains("a target name or a list of target names"), "{e}");
}
