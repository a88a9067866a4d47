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
                Field { name: "a_pos", offset: 0, format: VertexFormat::Float32x3 },
                Field { name: "a_uv", offset: 12, format: VertexFormat::Float32x2 },
                Field { name: "a_normal", offset: 20, format: VertexFormat::Float32x3 },
            ],
            indices,
            position: "a_pos",
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
        depth: Some(Attachment { target: depth, clear: 1.0 }),
        cull,
        depth_bias: false,
        textures: vec![TextureInput { sampler: "tex".into(), target: tex, sampling: Sampling { compare: false, linear: true, border: false } }],
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
    let screen = |i: u32| {
        let p = &pos[i as usize * 8..];
        let c = proj * view * model * Vec4::new(p[0], p[1], p[2], 1.0);
        // Vulkan's viewport: NDC y = -1 is row 0.
        [(c.x / c.w + 1.0) / 2.0 * width as f32, (c.y / c.w + 1.0) / 2.0 * height as f32]
    };
    let p = [x as f32 + 0.5, y as f32 + 0.5];
    let mut near_edge = false;
    for tri in m.indices.chunks_exact(3) {
        let v = [screen(tri[0]), screen(tri[1]), screen(tri[2])];
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
