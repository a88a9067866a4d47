//! dasVulkan's single-pass tutorials as frame plans, with the values their
//! host math gives. 01 (triangle): three vertices from `gl_VertexIndex`,
//! no vertex buffers, the spin angle in the push constant `pc.angle`; the
//! tutorial's picture is in Vulkan's framebuffer orientation (NDC y = -1,
//! the red vertex at angle 0, at the top), which every consumer keeps
//! (docs/runner.md, "A host of Vulkan-dialect outputs"). 04 (cube) and
//! 09 (MSAA, drawn here with one sample): a textured cube from a vertex
//! buffer (`a_pos`, `a_uv`, `a_normal`), the camera in the uniform block
//! `cam`, the model matrix in the push constant `pc`, a stand-in texture.

use std::sync::LazyLock;

use glam::{Mat4, Vec3, Vec4};

use super::{Attachment, Cull, Draw, Field, Format, FramePlan, Geometry, Mesh, Pass, Sampling, TargetId, TextureInput, Value, Values, VertexFormat};

pub const TRIANGLE_VS: &str = "tri_spin_vert_spv";
pub const TRIANGLE_FS: &str = "tri_spin_frag_spv";
/// The clear colour of the tutorials' plans.
pub const CLEAR: [f64; 4] = [0.0, 0.0, 0.0, 1.0];

/// 01 triangle at spin `angle` (radians), `width` x `height`.
pub fn triangle(angle: f32, width: u32, height: u32) -> FramePlan {
    let mut plan = FramePlan {
        scene: "dasVulkan's triangle".into(),
        targets: Vec::new(),
        passes: Vec::new(),
        readback: TargetId(0),
        required: Vec::new(),
        unset: Default::default(),
    };
    let color = plan.add_target("colour", width, height, Format::Rgba8);
    plan.passes.push(Pass {
        name: "triangle".into(),
        vertex: TRIANGLE_VS.into(),
        fragment: Some(TRIANGLE_FS.into()),
        color: Some(Attachment { target: color, clear: CLEAR }),
        more_colors: Vec::new(),
        depth: None,
        cull: Cull::None,
        depth_bias: false,
        textures: Vec::new(),
        values: Values::new().with("angle", Value::float(angle)),
        draws: vec![Draw { geometry: Geometry::Vertices(3), values: Values::new() }],
    });
    plan.readback = color;
    plan
}

/// What the triangle's host expects at pixel (`x`, `y`) (row 0 at the
/// top) of a `width` x `height` frame: `Some(rgb)` in [0, 1] inside the
/// triangle by at least `margin` in barycentric weight, `Some(black)`
/// outside by as much, `None` near an edge (rasterisation rules decide).
pub fn triangle_expected(angle: f32, width: u32, height: u32, x: u32, y: u32, margin: f32) -> Option<[f32; 3]> {
    let (c, s) = (angle.cos(), angle.sin());
    let corners = [[0.0f32, -0.6], [0.6, 0.6], [-0.6, 0.6]].map(|[px, py]| [px * c - py * s, px * s + py * c]);
    let colours = [[1.0f32, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    // Vulkan's framebuffer: NDC y = -1 is row 0.
    let p = [(x as f32 + 0.5) / width as f32 * 2.0 - 1.0, (y as f32 + 0.5) / height as f32 * 2.0 - 1.0];
    let [a, b, d] = corners;
    let area = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    let edge = |u: [f32; 2], v: [f32; 2]| ((u[0] - p[0]) * (v[1] - p[1]) - (u[1] - p[1]) * (v[0] - p[0])) / area;
    let w = [edge(b, d), edge(d, a), edge(a, b)];
    if w.iter().all(|&wi| wi > margin) {
        Some([0, 1, 2].map(|ch| (0..3).map(|i| w[i] * colours[i][ch]).sum()))
    } else if w.iter().any(|&wi| wi < -margin) {
        Some([0.0; 3])
    } else {
        None
    }
}

pub const CUBE_VS: &str = "cube_vert_spv";
pub const CUBE_FS: &str = "cube_frag_spv";
pub const MSAA_VS: &str = "msaa_vert_spv";
pub const MSAA_FS: &str = "msaa_frag_spv";

/// The unit cube ([-0.5, 0.5]) of 24 vertices: position, uv over each
/// face, face normal; 32 bytes a vertex.
pub fn uv_cube() -> &'static Mesh {
    static CUBE: LazyLock<Mesh> = LazyLock::new(|| {
        let faces: [([f32; 3], [f32; 3], [f32; 3]); 6] = [
            ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
            ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
            ([0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]),
            ([-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]),
            ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
            ([0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]),
        ];
        let mut vertices: Vec<f32> = Vec::new();
        let mut indices = Vec::new();
        for (i, (n, u, v)) in faces.iter().enumerate() {
            let (n, u, v) = (Vec3::from(*n), Vec3::from(*u), Vec3::from(*v));
            for (su, sv) in [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)] {
                let p = (n + u * su + v * sv) * 0.5;
                vertices.extend_from_slice(&[p.x, p.y, p.z, (su + 1.0) / 2.0, (sv + 1.0) / 2.0, n.x, n.y, n.z]);
            }
            let b = 4 * i as u32;
            indices.extend_from_slice(&[b, b + 1, b + 2, b + 2, b + 3, b]);
        }
        Mesh {
            name: "uv cube",
            vertices: bytemuck::cast_slice(&vertices).to_vec(),
            stride: 32,
            fields: vec![
                Field { name: "a_pos", offset: 0, format: VertexFormat::Float32x3, per_instance: false },
                Field { name: "a_uv", offset: 12, format: VertexFormat::Float32x2, per_instance: false },
                Field { name: "a_normal", offset: 20, format: VertexFormat::Float32x3, per_instance: false },
            ],
            indices,
            position: "a_pos",
            instances: None,
            points: false,
        }
    });
    &CUBE
}

/// The cube's host math at time `t`: (projection * view in Vulkan clip
/// space, the camera's position, the model matrix).
pub fn cube_matrices(t: f32, width: u32, height: u32) -> (Mat4, Mat4, Vec3, Mat4) {
    let eye = Vec3::new(1.6, 1.2, 2.0);
    let view = glam::camera::rh::view::look_at_mat4(eye, Vec3::ZERO, Vec3::Y);
    // A Vulkan host's projection: z in [0, 1], y down.
    let proj = glam::camera::rh::proj::vulkan::perspective(45f32.to_radians(), width as f32 / height as f32, 0.1, 20.0);
    let model = Mat4::from_rotation_y(t * 0.7) * Mat4::from_rotation_x(0.4);
    (proj, view, eye, model)
}

/// 04 cube (`vs`/`fs` = [`CUBE_VS`]/[`CUBE_FS`]) or 09 MSAA's pair at
/// time `t`, `width` x `height`, with depth, culling `cull` (the mesh's
/// faces are counter-clockwise seen from outside, as a Vulkan host's
/// `FRONT_FACE_COUNTER_CLOCKWISE` with a y-down projection expects).
pub fn cube(vs: &str, fs: &str, t: f32, width: u32, height: u32, cull: Cull) -> FramePlan {
    let (proj, view, eye, model) = cube_matrices(t, width, height);
    let mut plan = FramePlan {
        scene: "dasVulkan's cube".into(),
        targets: Vec::new(),
        passes: Vec::new(),
        readback: TargetId(0),
        required: Vec::new(),
        unset: Default::default(),
    };
    let color = plan.add_target("colour", width, height, Format::Rgba8);
    let depth = plan.add_target("depth", width, height, Format::Depth32Float);
    let tex = plan.add_texture("tex", 64, 64, super::vk_shadow::brick_texture("brick_albedo"));
    plan.passes.push(Pass {
        name: "cube".into(),
        vertex: vs.into(),
        fragment: Some(fs.into()),
        color: Some(Attachment { target: color, clear: CLEAR }),
        more_colors: Vec::new(),
        depth: Some(Attachment { target: depth, clear: 1.0 }),
        cull,
        depth_bias: false,
        textures: vec![TextureInput { sampler: "tex".into(), target: tex, sampling: Sampling { compare: false, linear: true, border: false, repeat: false } }],
        values: Values::new()
            .with("view", Value::mat4(view))
            .with("proj", Value::mat4(proj))
            .with("cam_time", Value::vec4(Vec4::new(eye.x, eye.y, eye.z, t)))
            .with("model", Value::mat4(model)),
        draws: vec![Draw { geometry: Geometry::Mesh(uv_cube()), values: Values::new() }],
    });
    plan.readback = color;
    plan
}

/// Whether the cube covers pixel (`x`, `y`) (row 0 at the top) at time
/// `t`: `Some(true)` inside a face's triangle by `margin` pixels,
/// `Some(false)` outside every triangle by as much, `None` in between.
pub fn cube_covers(t: f32, width: u32, height: u32, x: u32, y: u32, margin: f32) -> Option<bool> {
    let (proj, view, _, model) = cube_matrices(t, width, height);
    let m = uv_cube();
    let pos: &[f32] = bytemuck::cast_slice(&m.vertices);
    let clip = |i: u32| {
        let p = &pos[i as usize * 8..];
        proj * view * model * Vec4::new(p[0], p[1], p[2], 1.0)
    };
    let tris: Vec<[Vec4; 3]> = m.indices.chunks_exact(3).map(|t| [clip(t[0]), clip(t[1]), clip(t[2])]).collect();
    covers(&tris, width, height, x, y, margin)
}

/// Whether triangles given in Vulkan clip space cover pixel (`x`, `y`)
/// (see [`cube_covers`]).
fn covers(tris: &[[Vec4; 3]], width: u32, height: u32, x: u32, y: u32, margin: f32) -> Option<bool> {
    // Vulkan's viewport: NDC y = -1 is row 0.
    let screen = |c: Vec4| [(c.x / c.w + 1.0) / 2.0 * width as f32, (c.y / c.w + 1.0) / 2.0 * height as f32];
    let p = [x as f32 + 0.5, y as f32 + 0.5];
    let mut near_edge = false;
    for tri in tris {
        let v = tri.map(screen);
        let area = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0]);
        if area.abs() < 1e-6 {
            continue;
        }
        // Signed distance of p from each edge, positive inside.
        let d = [0, 1, 2].map(|k| {
            let (a, b) = (v[k], v[(k + 1) % 3]);
            let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
            ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) * area.signum() / len
        });
        if d.iter().all(|&e| e > margin) {
            return Some(true);
        }
        if d.iter().all(|&e| e > -margin) {
            near_edge = true;
        }
    }
    if near_edge {
        None
    } else {
        Some(false)
    }
}

pub const INSTANCING_VS: &str = "instancing_vert_spv";
pub const INSTANCING_FS: &str = "instancing_frag_spv";
/// 05's instances: a 3 x 3 grid, 1.6 apart.
const GRID: u32 = 3;

/// One instance record of 05: offset, colour, phase (28 bytes).
fn instance(i: u32) -> [f32; 7] {
    let (gx, gz) = ((i % GRID) as f32 - 1.0, (i / GRID) as f32 - 1.0);
    [gx * 1.6, 0.0, gz * 1.6, 0.3 + 0.3 * (gx + 1.0), 0.8 - 0.25 * (gz + 1.0), 0.5, i as f32 / (GRID * GRID) as f32]
}

/// 05's mesh: the [-0.5, 0.5] cube with `a_pos` and `a_normal` per vertex
/// and `a_offset`, `a_color`, `a_phase` per instance.
pub fn instanced_cubes() -> &'static Mesh {
    static MESH: LazyLock<Mesh> = LazyLock::new(|| {
        let cube = uv_cube();
        let src: &[f32] = bytemuck::cast_slice(&cube.vertices);
        let mut floats: Vec<f32> = src.chunks_exact(8).flat_map(|v| [v[0], v[1], v[2], v[5], v[6], v[7]]).collect();
        let base = (floats.len() * 4) as u32;
        floats.extend((0..GRID * GRID).flat_map(instance));
        let field = |name, offset, format, per_instance| Field { name, offset, format, per_instance };
        Mesh {
            name: "instanced cubes",
            vertices: bytemuck::cast_slice(&floats).to_vec(),
            stride: 24,
            fields: vec![
                field("a_pos", 0, VertexFormat::Float32x3, false),
                field("a_normal", 12, VertexFormat::Float32x3, false),
                field("a_offset", 0, VertexFormat::Float32x3, true),
                field("a_color", 12, VertexFormat::Float32x3, true),
                field("a_phase", 24, VertexFormat::Float32, true),
            ],
            indices: cube.indices.clone(),
            position: "a_pos",
            instances: Some(super::Instances { base, stride: 28, count: GRID * GRID }),
            points: false,
        }
    });
    &MESH
}

fn instancing_camera(width: u32, height: u32) -> (Mat4, Mat4, Vec3) {
    let eye = Vec3::new(3.2, 3.4, 4.4);
    let view = glam::camera::rh::view::look_at_mat4(eye, Vec3::ZERO, Vec3::Y);
    let proj = glam::camera::rh::proj::vulkan::perspective(45f32.to_radians(), width as f32 / height as f32, 0.1, 30.0);
    (proj, view, eye)
}

/// 05 instancing at time `t`: one instanced draw of nine cubes.
pub fn instancing(t: f32, width: u32, height: u32, cull: Cull) -> FramePlan {
    let (proj, view, eye) = instancing_camera(width, height);
    let mut plan = FramePlan {
        scene: "dasVulkan's instanced cubes".into(),
        targets: Vec::new(),
        passes: Vec::new(),
        readback: TargetId(0),
        required: Vec::new(),
        unset: Default::default(),
    };
    let color = plan.add_target("colour", width, height, Format::Rgba8);
    let depth = plan.add_target("depth", width, height, Format::Depth32Float);
    plan.passes.push(Pass {
        name: "instances".into(),
        vertex: INSTANCING_VS.into(),
        fragment: Some(INSTANCING_FS.into()),
        color: Some(Attachment { target: color, clear: CLEAR }),
        more_colors: Vec::new(),
        depth: Some(Attachment { target: depth, clear: 1.0 }),
        cull,
        depth_bias: false,
        textures: Vec::new(),
        values: Values::new()
            .with("view", Value::mat4(view))
            .with("proj", Value::mat4(proj))
            .with("cam_time", Value::vec4(Vec4::new(eye.x, eye.y, eye.z, t))),
        draws: vec![Draw { geometry: Geometry::Mesh(instanced_cubes()), values: Values::new() }],
    });
    plan.readback = color;
    plan
}

/// [`cube_covers`] for 05: each instance placed as its vertex program
/// places it (breathing scale, spin about y, offset).
pub fn instancing_covers(t: f32, width: u32, height: u32, x: u32, y: u32, margin: f32) -> Option<bool> {
    let (proj, view, _) = instancing_camera(width, height);
    let m = instanced_cubes();
    let pos: &[f32] = bytemuck::cast_slice(&m.vertices);
    let mut tris = Vec::new();
    for i in 0..GRID * GRID {
        let r = instance(i);
        // The vertex program's own literal, not TAU: the same rounding.
        #[allow(clippy::approx_constant)]
        let phase = r[6] * 6.2832;
        let breathe = 0.7 + 0.2 * (t * 1.5 + phase).sin();
        let ang = t * 0.25 + phase;
        let (c, s) = (ang.cos(), ang.sin());
        let clip = |v: u32| {
            let p = &pos[v as usize * 6..];
            let l = Vec3::new(p[0], p[1], p[2]) * breathe;
            let w = Vec3::new(c * l.x - s * l.z, l.y, s * l.x + c * l.z) + Vec3::new(r[0], r[1], r[2]);
            proj * view * w.extend(1.0)
        };
        tris.extend(m.indices.chunks_exact(3).map(|t| [clip(t[0]), clip(t[1]), clip(t[2])]));
    }
    covers(&tris, width, height, x, y, margin)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_red_vertex_is_at_the_top_at_angle_zero() {
        // Just below the top vertex (NDC y = -0.6: row 0.2 of the height).
        let top = triangle_expected(0.0, 100, 100, 50, 24, 0.01).unwrap();
        assert!(top[0] > 0.8 && top[1] < 0.2, "{top:?}");
        assert_eq!(triangle_expected(0.0, 100, 100, 50, 90, 0.01), Some([0.0; 3]), "below the base: outside");
        let centre = triangle_expected(0.0, 100, 100, 49, 59, 0.01).unwrap();
        assert!(centre.iter().all(|c| (c - 1.0 / 3.0).abs() < 0.05), "{centre:?}");
    }
}
