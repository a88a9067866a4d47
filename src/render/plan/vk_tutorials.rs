//! dasVulkan's single-pass tutorials as frame plans, with the values their
//! host math gives. 01 (triangle): three vertices from `gl_VertexIndex`,
//! no vertex buffers, the spin angle in the push constant `pc.angle`; the
//! tutorial's picture is in Vulkan's framebuffer orientation (NDC y = -1,
//! the red vertex at angle 0, at the top), which every consumer keeps
//! (docs/runner.md, "A host of Vulkan-dialect outputs").

use super::{Attachment, Cull, Draw, Format, FramePlan, Geometry, Pass, TargetId, Value, Values};

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
