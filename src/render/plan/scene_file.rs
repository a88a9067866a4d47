//! A [`Scene`] (a scene file, or the one inferred for a program) as a
//! frame plan: its textures made once ([`ScenePlanner::new`]: patterns,
//! image files), then per frame its targets at the output's size, its
//! passes, the built-in meshes laid out for each draw's inputs and every
//! value resolved against the manifest's types, conventions computed from
//! the time, the size and the orbit camera (docs/runner.md, "Scene files").

use std::path::Path;

use glam::{Mat3, Mat4, Quat, Vec3};

use super::meshes::{self, Input};
use super::{Attachment, Cull, Dim, Draw, Format, FramePlan, Geometry, Pass, Sampling, TargetId, TextureInput, Unset, Value, Values};
use crate::emit::reflect_types::Reflection;
use crate::scene::{self, Convention, Light, LightKind, MeshKind, OrbitCamera, Scene, TargetFormat, TextureKind, Transform, ValueSpec, SCREEN};

/// A scene ready to be planned each frame for one program.
#[derive(Clone, Debug)]
pub struct ScenePlanner {
    pub scene: Scene,
    reflection: Reflection,
    /// Each texture's size, kind and texels, in `scene.textures`' order.
    textures: Vec<(u32, u32, Dim, Vec<u8>)>,
    /// Names the scene in messages.
    pub label: String,
}

/// What a frame's conventions are computed from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameInputs {
    pub time: f32,
    pub frame: u32,
    pub width: u32,
    pub height: u32,
}

impl ScenePlanner {
    /// Makes the textures (an `image` relative to `base`, the scene file's
    /// directory) and checks that the scene fits the program: its entry
    /// points, its values' names and shapes, each draw's vertex inputs.
    pub fn new(label: &str, scene: Scene, reflection: &Reflection, base: Option<&Path>) -> Result<ScenePlanner, String> {
        scene.check().map_err(|e| format!("{label}: {e}"))?;
        let mut textures = Vec::new();
        for t in &scene.textures {
            textures.push(match (&t.pattern, &t.image) {
                (Some(p), _) => {
                    let (texels, layers) = t.pattern_texels(*p);
                    let dim = match t.kind {
                        TextureKind::D2 => Dim::D2,
                        TextureKind::Cube => Dim::Cube,
                        TextureKind::D3 => Dim::D3(layers),
                        TextureKind::D2Array => Dim::D2Array(layers),
                    };
                    (t.size[0], t.size[1], dim, texels)
                }
                (None, Some(file)) => {
                    let path = base.map_or_else(|| Path::new(file).to_path_buf(), |b| b.join(file));
                    let img = image::open(&path).map_err(|e| format!("{label}: texture `{}`: {}: {e}", t.name, path.display()))?.to_rgba8();
                    (img.width(), img.height(), Dim::D2, img.into_raw())
                }
                (None, None) => unreachable!("checked: a texture has a pattern or an image"),
            });
        }
        let planner = ScenePlanner { scene, reflection: reflection.clone(), textures, label: label.to_string() };
        planner.plan(&FrameInputs { time: 0.0, frame: 0, width: 4, height: 4 })?;
        Ok(planner)
    }

    /// The frame plan at `f`.
    pub fn plan(&self, f: &FrameInputs) -> Result<FramePlan, String> {
        let s = &self.scene;
        let label = &self.label;
        let mut plan = FramePlan {
            scene: label.clone(),
            targets: Vec::new(),
            passes: Vec::new(),
            readback: TargetId(0),
            required: Vec::new(),
            unset: Unset::Zero,
        };
        let mut ids: Vec<(&str, TargetId)> = vec![(SCREEN, plan.add_target(SCREEN, f.width, f.height, Format::Rgba8))];
        for (t, (w, h, dim, texels)) in s.textures.iter().zip(&self.textures) {
            ids.push((&t.name, plan.add_layered(&t.name, *w, *h, *dim, texels.clone())));
        }
        for t in &s.targets {
            let [w, h] = t.size.unwrap_or([f.width, f.height]);
            let format = match t.format {
                TargetFormat::Rgba8 => Format::Rgba8,
                TargetFormat::Depth32float => Format::Depth32Float,
                TargetFormat::Depth24plus => Format::Depth24Plus,
                TargetFormat::Depth16 => Format::Depth16,
            };
            ids.push((&t.name, plan.add_target(&t.name, w, h, format)));
        }
        let id = |n: &str| ids.iter().find(|(name, _)| *name == n).map(|(_, id)| *id).expect("checked: every name is declared");
        for p in &s.passes {
            let vs = self.entry(&p.vertex, "vertex")?;
            let colors = p.color.as_ref().map_or(&[][..], |c| c.names());
            if let Some(fs) = &p.fragment {
                let fs = self.entry(fs, "fragment")?;
                // A target with no output to fill is invalid on WebGPU; an
                // output with no target is discarded on every API.
                if let Some(i) = (0..colors.len()).find(|&i| colors.len() > 1 && !fs.outputs.iter().any(|o| o.location as usize == i)) {
                    return Err(format!("{label}: pass `{}`: `color` target `{}` is for output location {i}, which fragment `{}` does not write", p.name, colors[i], fs.name));
                }
            }
            let mut textures = Vec::new();
            for (sampler, input) in &p.samplers {
                let decl = self.reflection.samplers.iter().find(|d| &d.name == sampler).or_else(|| self.array_element(sampler));
                let Some(decl) = decl else {
                    return Err(format!("{label}: pass `{}` binds sampler `{sampler}`, which the program does not declare", p.name));
                };
                let linear = input.filter == scene::Filter::Linear;
                let dim = plan.target(id(&input.texture)).dim;
                if dim.name() != decl.dimension {
                    return Err(format!("{label}: pass `{}`: sampler `{sampler}` is a {} and reads `{}`, a {} texture", p.name, decl.ty, input.texture, dim.name()));
                }
                // A texture (pattern or image) repeats, as on the page; a target clamps.
                let repeat = s.textures.iter().any(|t| t.name == input.texture);
                textures.push(TextureInput { sampler: sampler.clone(), target: id(&input.texture), sampling: Sampling { compare: decl.comparison, linear, border: false, repeat } });
            }
            let mut draws = Vec::new();
            for d in &p.draws {
                let mut values = Values::new();
                // A model convention the pass or the scene sets follows each
                // draw's own transform.
                let inherited = s.values.iter().chain(&p.values).filter(|(n, v)| !d.values.contains_key(*n) && d.transform.is_some() && per_draw(v));
                for (name, spec) in inherited.chain(&d.values) {
                    values.set(name, self.value(name, spec, d.transform.as_ref(), f)?);
                }
                draws.push(Draw { geometry: self.geometry(vs, d, &p.name)?, values });
            }
            let mut values = Values::new();
            for (name, spec) in s.values.iter().filter(|(n, _)| !p.values.contains_key(*n)).chain(&p.values) {
                values.set(name, self.value(name, spec, None, f)?);
            }
            plan.passes.push(Pass {
                name: p.name.clone(),
                vertex: p.vertex.clone(),
                fragment: p.fragment.clone(),
                color: colors.first().map(|c| Attachment { target: id(c), clear: p.clear.map(f64::from) }),
                more_colors: colors.iter().skip(1).map(|c| Attachment { target: id(c), clear: p.clear.map(f64::from) }).collect(),
                depth: p.depth.as_deref().map(|d| Attachment { target: id(d), clear: 1.0 }),
                cull: match p.cull {
                    scene::Cull::None => Cull::None,
                    scene::Cull::Front => Cull::Front,
                    scene::Cull::Back => Cull::Back,
                },
                depth_bias: p.depth_bias,
                textures,
                values,
                draws,
            });
        }
        plan.readback = id(&s.output);
        plan.check().map_err(|e| format!("{label}: {e}"))?;
        Ok(plan)
    }

    fn entry(&self, name: &str, stage: &str) -> Result<&crate::emit::reflect_types::EntryPoint, String> {
        self.reflection
            .entry_points
            .iter()
            .find(|e| e.name == name && e.stage == stage)
            .ok_or_else(|| format!("{}: the program has no {stage} entry point `{name}`", self.label))
    }

    /// `name[i]` of a sampler array `name` that has an element `i`.
    fn array_element(&self, sampler: &str) -> Option<&crate::emit::reflect_types::Sampler> {
        let (base, i) = sampler.strip_suffix(']')?.split_once('[')?;
        let i: u32 = i.parse().ok()?;
        self.reflection.samplers.iter().find(|d| d.name == base && d.count.is_some_and(|n| i < n))
    }

    /// A draw's geometry: its mesh laid out for the vertex program's inputs.
    fn geometry(&self, vs: &crate::emit::reflect_types::EntryPoint, d: &scene::Draw, pass: &str) -> Result<Geometry, String> {
        if d.mesh == MeshKind::None {
            return Ok(Geometry::Vertices(d.vertices.unwrap_or(3)));
        }
        let mut inputs = Vec::new();
        for i in &vs.inputs {
            let Some(attribute) = d.attributes.get(&i.name) else {
                let have: Vec<&str> = d.attributes.keys().map(String::as_str).collect();
                return Err(format!(
                    "{}: pass `{pass}`: vertex input `{}` of `{}` is fed by none of the draw's attributes (it maps {})",
                    self.label,
                    i.name,
                    vs.name,
                    if have.is_empty() { "none".to_string() } else { have.join(", ") }
                ));
            };
            let components = match i.ty.as_str() {
                "float" => 1,
                "float2" => 2,
                "float3" => 3,
                "float4" => 4,
                other => return Err(format!("{}: vertex input `{}` is a {other}: the built-in meshes give floats", self.label, i.name)),
            };
            inputs.push(Input { name: i.name.clone(), attribute: *attribute, components });
        }
        // A program reading gl_VertexID over a mesh (a corner's barycentric
        // from `gl_VertexID % 3`) gets each triangle's vertices its own.
        let unrolled = vs.builtins.iter().any(|b| b == "gl_VertexID" || b == "gl_VertexIndex");
        Ok(Geometry::Mesh(meshes::mesh_of(d.mesh, &inputs, d.instances.as_ref(), unrolled, d.primitive == scene::Primitive::Points).expect("a mesh other than `none`")))
    }

    /// The DSL type of a uniform or uniform block member named `name`, or
    /// of a leaf of a struct one (`u_instances[3].color`).
    fn type_of(&self, name: &str) -> Option<String> {
        let r = &self.reflection;
        let base = name.split(['[', '.']).next().unwrap_or(name);
        let ty = r
            .uniforms
            .iter()
            .find(|u| u.name == base)
            .map(|u| u.ty.as_str())
            .or_else(|| r.uniform_buffers.iter().flat_map(|b| &b.members).find(|m| m.name == base).map(|m| m.ty.as_str()))?;
        if base == name {
            return Some(ty.to_string());
        }
        crate::scene::infer::leaves(r, base, ty).into_iter().find(|l| l.path == name).map(|l| l.ty)
    }

    fn value(&self, name: &str, spec: &ValueSpec, transform: Option<&Transform>, f: &FrameInputs) -> Result<Value, String> {
        let ty = self.type_of(name).ok_or_else(|| format!("{}: the scene sets `{name}`, which is no uniform of the program", self.label))?;
        let light = self.scene.light.clone().unwrap_or_default();
        let cx = Context { camera: &self.scene.camera, light: &light, transform };
        value_in(&ty, spec, &cx, f).map_err(|e| format!("{}: `{name}` ({ty}): {e}", self.label))
    }
}

fn per_draw(v: &ValueSpec) -> bool {
    matches!(v, ValueSpec::Convention(c) if c.per_draw())
}

/// What a value's conventions are computed from besides the frame: the
/// scene's camera and light, and the draw's transform (none: the default
/// slow turn).
#[derive(Clone, Copy, Debug)]
pub struct Context<'a> {
    pub camera: &'a OrbitCamera,
    pub light: &'a Light,
    pub transform: Option<&'a Transform>,
}

/// A value of DSL type `ty` from a scene's spec, with the default light and
/// no transform.
pub fn value(ty: &str, spec: &ValueSpec, camera: &OrbitCamera, f: &FrameInputs) -> Result<Value, String> {
    value_in(ty, spec, &Context { camera, light: &Light::default(), transform: None }, f)
}

/// A value of DSL type `ty` from a scene's spec.
pub fn value_in(ty: &str, spec: &ValueSpec, cx: &Context, f: &FrameInputs) -> Result<Value, String> {
    let numbers: Vec<f64> = match spec {
        ValueSpec::Bool(b) => vec![*b as u8 as f64],
        ValueSpec::Number(x) => {
            let n = components(ty).ok_or_else(|| format!("a number does not fit a {ty}"))?;
            vec![*x; n]
        }
        ValueSpec::Numbers(v) => v.clone(),
        ValueSpec::Convention(c) => convention(*c, ty, cx, f)?.into_iter().map(f64::from).collect(),
        ValueSpec::Element(e) => {
            let all = elements(e.convention, cx, f).ok_or_else(|| format!("`{}` is no array: it has no `index`", name(e.convention)))?;
            let m = all.get(e.index as usize).ok_or_else(|| format!("`{}` has {} elements: no `index = {}`", name(e.convention), all.len(), e.index))?;
            matrix_for(*m, ty)?.into_iter().map(f64::from).collect()
        }
    };
    let words: Vec<u32> = numbers
        .iter()
        .map(|x| {
            if ty.starts_with("float") {
                (*x as f32).to_bits()
            } else if ty.starts_with("int") {
                *x as i32 as u32
            } else if ty.starts_with("bool") {
                (*x != 0.0) as u32
            } else {
                *x as u32
            }
        })
        .collect();
    Value::from_words(ty, &words).ok_or_else(|| format!("{} numbers do not fit a {ty}", words.len()))
}

/// Components of a scalar or vector type.
fn components(ty: &str) -> Option<usize> {
    let rest = ["float", "uint", "int", "bool"].into_iter().find_map(|s| ty.strip_prefix(s))?;
    match rest {
        "" => Some(1),
        "2" => Some(2),
        "3" => Some(3),
        "4" => Some(4),
        _ => None,
    }
}

/// The orbit camera's matrices at `time`: (view, projection).
pub fn camera_matrices(c: &OrbitCamera, f: &FrameInputs) -> (Mat4, Mat4) {
    let eye = Vec3::from(c.eye(f.time));
    let view = glam::camera::rh::view::look_at_mat4(eye, Vec3::from(c.target), Vec3::Y);
    let aspect = f.width as f32 / f.height.max(1) as f32;
    let proj = glam::camera::rh::proj::opengl::perspective(c.fov_y.to_radians(), aspect, c.near, c.far);
    (view, proj)
}

/// A draw's model matrix at `time`: its transform, else a turn about y of
/// 0.5 rad a second.
pub fn model_matrix(t: Option<&Transform>, time: f32) -> Mat4 {
    let Some(t) = t else {
        return Mat4::from_rotation_y(0.5 * time);
    };
    let turn = Quat::from_axis_angle(Vec3::from(t.axis).normalize(), (t.angle + t.spin * time).to_radians());
    Mat4::from_scale_rotation_translation(Vec3::from(t.scale.axes()), turn, Vec3::from(t.translate))
}

/// Where the light is at `time`: (direction towards it, its position), a
/// sun's position being its eye.
pub fn light_place(l: &Light, time: f32) -> (Vec3, Vec3) {
    let turn = Mat3::from_rotation_y((l.spin * time).to_radians());
    let target = Vec3::from(l.target);
    match l.kind {
        LightKind::Sun => {
            let dir = (turn * Vec3::from(l.direction)).normalize();
            (dir, target + dir * l.distance)
        }
        LightKind::Spot => {
            let pos = turn * Vec3::from(l.position);
            ((pos - target).normalize(), pos)
        }
    }
}

/// The light's `projection * view` per shadow box ([`Light::boxes`]).
pub fn light_matrices(l: &Light, time: f32) -> Vec<Mat4> {
    let (dir, eye) = light_place(l, time);
    // An up vector never parallel to the view.
    let up = if dir.y.abs() > 0.999 { Vec3::Z } else { Vec3::Y };
    let view = glam::camera::rh::view::look_at_mat4(eye, Vec3::from(l.target), up);
    match l.kind {
        LightKind::Sun => l.boxes().iter().map(|&h| glam::camera::rh::proj::opengl::orthographic(-h, h, -h, h, l.near, l.far) * view).collect(),
        LightKind::Spot => vec![glam::camera::rh::proj::opengl::perspective(l.fov_y.to_radians(), 1.0, l.near, l.far) * view],
    }
}

/// An array convention's elements.
fn elements(c: Convention, cx: &Context, f: &FrameInputs) -> Option<Vec<Mat4>> {
    (c == Convention::LightViewProjections).then(|| light_matrices(cx.light, f.time))
}

/// A matrix's floats for a uniform of type `ty` (a `float3x3` gets the
/// upper 3 x 3).
fn matrix_for(m: Mat4, ty: &str) -> Result<Vec<f32>, String> {
    match ty {
        "float4x4" => Ok(m.to_cols_array().to_vec()),
        "float3x3" => Ok(Mat3::from_mat4(m).to_cols_array().to_vec()),
        _ => Err(format!("a matrix convention needs a float4x4 or float3x3, not a {ty}")),
    }
}

/// A convention's floats for a uniform of type `ty`.
fn convention(c: Convention, ty: &str, cx: &Context, f: &FrameInputs) -> Result<Vec<f32>, String> {
    let camera = cx.camera;
    let (w, h) = (f.width as f32, f.height as f32);
    let (view, proj) = camera_matrices(camera, f);
    let model = model_matrix(cx.transform, f.time);
    let (light_dir, light_pos) = light_place(cx.light, f.time);
    let light_vp = || light_matrices(cx.light, f.time)[0];
    let matrix = |m: Mat4| matrix_for(m, ty);
    let vector = |v: &[f32]| -> Result<Vec<f32>, String> {
        let n = components(ty).filter(|_| ty.starts_with("float") || ty.starts_with("int") || ty.starts_with("uint")).ok_or_else(|| format!("`{}` does not fit a {ty}", name(c)))?;
        Ok((0..n).map(|i| v.get(i).copied().unwrap_or(0.0)).collect())
    };
    match c {
        Convention::Time => vector(&[f.time]),
        Convention::Frame => vector(&[f.frame as f32]),
        Convention::Resolution => vector(&[w, h, 1.0, f.time]),
        Convention::Aspect => vector(&[w / h.max(1.0)]),
        Convention::Mouse => vector(&[w / 2.0, h / 2.0, 0.0, 0.0]),
        Convention::TexelSize => vector(&[1.0 / w.max(1.0), 1.0 / h.max(1.0)]),
        Convention::CameraPosition => vector(&[camera.eye(f.time)[0], camera.eye(f.time)[1], camera.eye(f.time)[2], 1.0]),
        Convention::LightDirection => vector(&light_dir.extend(0.0).to_array()),
        Convention::LightPosition => vector(&light_pos.extend(1.0).to_array()),
        Convention::SpotDirection => vector(&(-light_dir).extend(0.0).to_array()),
        Convention::View => matrix(view),
        Convention::ViewRotation => matrix(Mat4::from_mat3(Mat3::from_mat4(view))),
        Convention::Projection => matrix(proj),
        Convention::ViewProjection => matrix(proj * view),
        Convention::Model => matrix(model),
        Convention::ModelViewProjection => matrix(proj * view * model),
        Convention::NormalMatrix => {
            let n = Mat3::from_mat4(model).inverse().transpose();
            matrix(Mat4::from_mat3(n))
        }
        Convention::LightViewProjection => matrix(light_vp()),
        Convention::ShadowMatrix => {
            let bias = Mat4::from_translation(Vec3::splat(0.5)) * Mat4::from_scale(Vec3::splat(0.5));
            matrix(bias * light_vp())
        }
        Convention::LightViewProjections => {
            let all = light_matrices(cx.light, f.time);
            if ty != format!("float4x4[{}]", all.len()) {
                return Err(format!("`light_view_projections` is {} matrices (one per shadow box): it fits a float4x4[{}], not a {ty}", all.len(), all.len()));
            }
            Ok(all.iter().flat_map(|m| m.to_cols_array()).collect())
        }
    }
}

fn name(c: Convention) -> String {
    serde_json::to_value(c).ok().and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn f() -> FrameInputs {
        FrameInputs { time: 2.0, frame: 5, width: 200, height: 100 }
    }

    #[test]
    fn conventions_fit_their_types() {
        let cam = OrbitCamera::default();
        let v = |ty: &str, c: Convention| value(ty, &ValueSpec::Convention(c), &cam, &f()).unwrap();
        assert_eq!(v("float", Convention::Time), Value::float(2.0));
        assert_eq!(v("int", Convention::Frame), Value::int(5));
        assert_eq!(v("float2", Convention::Resolution).as_f32(), vec![200.0, 100.0]);
        assert_eq!(v("float3", Convention::Resolution).as_f32(), vec![200.0, 100.0, 1.0]);
        assert_eq!(v("float", Convention::Aspect), Value::float(2.0));
        assert_eq!(v("float3x3", Convention::NormalMatrix).words.len(), 9);
        let eye = Vec3::from(cam.eye(2.0));
        let (view, _) = camera_matrices(&cam, &f());
        assert!(view.transform_point3(eye).length() < 1e-4, "the view puts the eye at the origin");
        assert!(value("float2", &ValueSpec::Convention(Convention::View), &cam, &f()).is_err());
    }

    #[test]
    fn textures_come_from_patterns_and_image_files_relative_to_the_scene() {
        let src = "var @in q_pos : float2\nvar @uniform @stage = 0 u_a : sampler2D\nvar @uniform @stage = 1 u_b : sampler2D\nvar @inout v_uv : float2\nvar @out f_color : float4\n[vertex_program]\ndef vs {\n    v_uv = q_pos\n    gl_Position = float4(q_pos, 0.0, 1.0)\n}\n[fragment_program]\ndef fs {\n    f_color = texture(u_a, v_uv) + texture(u_b, v_uv)\n}\n";
        let c = crate::compile_source("t.das", src, &crate::Options::default());
        let r = c.result.unwrap().reflection;
        let dir = tempfile::tempdir().unwrap();
        let img = image::RgbaImage::from_fn(3, 2, |x, y| image::Rgba([x as u8 * 80, y as u8 * 200, 7, 255]));
        img.save(dir.path().join("tex.png")).unwrap();
        let toml = "[[textures]]\nname = \"a\"\npattern = \"uv\"\nsize = [4, 4]\n[[textures]]\nname = \"b\"\nimage = \"tex.png\"\n[[passes]]\nname = \"p\"\nvertex = \"vs\"\nfragment = \"fs\"\ncolor = \"screen\"\nsamplers = { u_a = { texture = \"a\" }, u_b = { texture = \"b\", filter = \"nearest\" } }\n[[passes.draws]]\nmesh = \"fullscreen_triangle\"\nattributes = { q_pos = \"position\" }\n";
        let scene = Scene::parse("s.toml", toml).unwrap();
        let planner = ScenePlanner::new("s", scene.clone(), &r, Some(dir.path())).unwrap();
        let plan = planner.plan(&f()).unwrap();
        let target = |n: &str| plan.targets.iter().find(|t| t.name == n).unwrap();
        assert_eq!(target("a").contents.as_deref(), Some(&scene::Pattern::Uv.texels(4, 4)[..]));
        assert_eq!((target("b").width, target("b").height, target("b").contents.as_deref()), (3, 2, Some(img.as_raw().as_slice())));
        assert!(!plan.passes[0].textures.iter().find(|t| t.sampler == "u_b").unwrap().sampling.linear);
        let err = ScenePlanner::new("s", scene, &r, Some(Path::new("/nonexistent"))).unwrap_err();
        assert!(err.contains("texture `b`") && err.contains("tex.png"), "{err}");
    }

    /// A `color` list becomes the pass's attachments in location order; a
    /// list reaching a location the fragment does not write is refused.
    #[test]
    fn a_color_list_attaches_each_location_to_its_target() {
        let src = "var @out @location = 0 g_a : float4\nvar @out @location = 1 g_b : float4\n[vertex_program]\ndef vs {\n    gl_Position = float4(0.0, 0.0, 0.0, 1.0)\n}\n[fragment_program]\ndef fs {\n    g_a = float4(1.0)\n    g_b = float4(0.5)\n}\n";
        let c = crate::compile_source("t.das", src, &crate::Options::default());
        let r = c.result.unwrap().reflection;
        let toml = |color: &str| {
            let targets: String = ["a", "b", "c"].iter().map(|n| format!("[[targets]]\nname = \"{n}\"\nformat = \"rgba8\"\n")).collect();
            format!("output = \"b\"\n{targets}[[passes]]\nname = \"g\"\nvertex = \"vs\"\nfragment = \"fs\"\ncolor = {color}\n[[passes.draws]]\nmesh = \"none\"\nvertices = 3\n")
        };
        let plan = ScenePlanner::new("s", Scene::parse("s.toml", &toml(r#"["a", "b"]"#)).unwrap(), &r, None).unwrap().plan(&f()).unwrap();
        let id = |n: &str| TargetId(plan.targets.iter().position(|t| t.name == n).unwrap());
        let p = &plan.passes[0];
        assert_eq!(p.colors().map(|a| a.target).collect::<Vec<_>>(), [id("a"), id("b")]);
        assert!(p.writes(id("b")) && !p.writes(id("c")));
        let err = ScenePlanner::new("s", Scene::parse("s.toml", &toml(r#"["a", "b", "c"]"#)).unwrap(), &r, None).err().unwrap();
        assert!(err.contains("`c` is for output location 2, which fragment `fs` does not write"), "{err}");
    }

    #[test]
    fn numbers_and_bools_take_the_uniforms_type() {
        let (cam, f) = (OrbitCamera::default(), f());
        assert_eq!(value("float3", &ValueSpec::Number(0.5), &cam, &f).unwrap().as_f32(), vec![0.5; 3]);
        assert_eq!(value("bool", &ValueSpec::Bool(true), &cam, &f).unwrap(), Value::bool(true));
        assert_eq!(value("int2", &ValueSpec::Numbers(vec![-1.0, 2.0]), &cam, &f).unwrap().words, vec![(-1i32) as u32, 2]);
        assert!(value("float3", &ValueSpec::Numbers(vec![1.0]), &cam, &f).is_err());
    }

    #[test]
    fn transforms_and_lights_give_the_builtin_scenes_numbers() {
        use crate::render::{scene as tutorial, techniques};
        use crate::scene::Scale;
        let cube = Transform { translate: [0.0, 1.5, 0.0], axis: [0.3, 1.0, 0.2], angle: 0.0, spin: 0.7f32.to_degrees(), scale: Scale::Uniform(1.1) };
        let sun = Light { direction: [1.0, 1.4, 0.0], spin: -0.6f32.to_degrees(), distance: 8.0, ..Light::default() };
        let spot = Light { kind: LightKind::Spot, position: techniques::spot_position(0.0).into(), target: [0.0, 0.3, 0.0], spin: -0.4f32.to_degrees(), ..Light::default() };
        for t in [0.0, 1.0, 4.0] {
            // The file's cube is half the built-in one's size.
            let builtin = tutorial::cube_model(t) * Mat4::from_scale(Vec3::splat(2.0));
            assert!(model_matrix(Some(&cube), t).abs_diff_eq(builtin, 1e-5), "t = {t}");
            assert!(light_place(&sun, t).0.abs_diff_eq(tutorial::light_dir(t), 1e-5), "t = {t}");
            let f = tutorial::Frame::at(t, 1.0);
            assert!(light_matrices(&Light { half_size: 4.0, far: 20.0, ..sun.clone() }, t)[0].abs_diff_eq(f.light_vp, 1e-5), "t = {t}");
            assert!(light_place(&spot, t).1.abs_diff_eq(techniques::spot_position(t), 1e-5), "t = {t}");
        }
        assert_eq!(model_matrix(None, 2.0), Mat4::from_rotation_y(1.0), "no transform: the slow turn");
    }

    #[test]
    fn light_conventions_fit_their_types_and_elements_their_arrays() {
        let light = Light { cascades: vec![2.0, 4.0, 7.5], ..Light::default() };
        let (cam, f) = (OrbitCamera::default(), f());
        let cx = Context { camera: &cam, light: &light, transform: None };
        let all = value_in("float4x4[3]", &ValueSpec::Convention(Convention::LightViewProjections), &cx, &f).unwrap();
        assert_eq!(all.words.len(), 48);
        let one = |i| ValueSpec::Element(scene::ConventionElement { convention: Convention::LightViewProjections, index: i });
        assert_eq!(value_in("float4x4", &one(2), &cx, &f).unwrap().words, all.words[32..]);
        assert_eq!(value_in("float4x4", &ValueSpec::Convention(Convention::LightViewProjection), &cx, &f).unwrap().words, all.words[..16], "the finest box");
        let e = value_in("float4x4", &one(3), &cx, &f).unwrap_err();
        assert!(e.contains("3 elements"), "{e}");
        let e = value_in("float4x4[2]", &ValueSpec::Convention(Convention::LightViewProjections), &cx, &f).unwrap_err();
        assert!(e.contains("float4x4[3]"), "{e}");
        let e = value_in("float4x4", &ValueSpec::Element(scene::ConventionElement { convention: Convention::View, index: 0 }), &cx, &f).unwrap_err();
        assert!(e.contains("no array"), "{e}");
        let pos = value_in("float3", &ValueSpec::Convention(Convention::LightPosition), &cx, &f).unwrap().as_f32();
        let dir = value_in("float3", &ValueSpec::Convention(Convention::LightDirection), &cx, &f).unwrap().as_f32();
        let axis = value_in("float3", &ValueSpec::Convention(Convention::SpotDirection), &cx, &f).unwrap().as_f32();
        assert!((0..3).all(|i| (pos[i] - 10.0 * dir[i]).abs() < 1e-5 && (axis[i] + dir[i]).abs() < 1e-6), "{pos:?} {dir:?} {axis:?}");
        // The shadow matrix takes what the light sees to [0, 1].
        let sm = Mat4::from_cols_array(&value_in("float4x4", &ValueSpec::Convention(Convention::ShadowMatrix), &cx, &f).unwrap().as_f32().try_into().unwrap());
        let p = sm * Vec3::ZERO.extend(1.0);
        assert!((p.x - 0.5).abs() < 1e-5 && (p.y - 0.5).abs() < 1e-5 && p.z > 0.0 && p.z < 1.0, "{p}");
    }

    #[test]
    fn a_scene_wide_model_follows_each_draws_transform() {
        let src = "var @in a_pos : float3\nvar @uniform u_model : float4x4\nvar @out f_color : float4\n[vertex_program]\ndef vs {\n    gl_Position = u_model * float4(a_pos, 1.0)\n}\n[fragment_program]\ndef fs {\n    f_color = float4(1.0)\n}\n";
        let r = crate::compile_source("t.das", src, &crate::Options::default()).result.unwrap().reflection;
        let toml = "[values]\nu_model = \"model\"\n[[passes]]\nname = \"p\"\nvertex = \"vs\"\nfragment = \"fs\"\ncolor = \"screen\"\n[[passes.draws]]\nmesh = \"cube\"\nattributes = { a_pos = \"position\" }\ntransform = { translate = [1.0, 2.0, 3.0] }\n[[passes.draws]]\nmesh = \"cube\"\nattributes = { a_pos = \"position\" }\n";
        let plan = ScenePlanner::new("s", Scene::parse("s.toml", toml).unwrap(), &r, None).unwrap().plan(&f()).unwrap();
        let p = &plan.passes[0];
        assert_eq!(p.value(&p.draws[0], "u_model").unwrap().as_f32()[12..15], [1.0, 2.0, 3.0]);
        assert_eq!(*p.value(&p.draws[1], "u_model").unwrap(), Value::mat4(Mat4::from_rotation_y(1.0)), "no transform: the slow turn");
    }
}
