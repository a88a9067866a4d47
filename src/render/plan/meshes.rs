//! The scenes' built-in meshes (docs/runner.md, "Meshes") laid out for one
//! draw: each vertex input the draw maps gets its attribute's components,
//! interleaved, then the instance records of its grid. A plan refers to
//! meshes that live for the whole process, so each layout is built once
//! and kept (a program has a handful).

use std::collections::HashMap;
use std::sync::{LazyLock, Mutex};

use super::{Field, Instances, Mesh, VertexFormat};
use crate::scene::{Attribute, InstanceGrid, MeshKind};

/// Positions, normals, tangents, uvs and triangles of a built-in mesh.
struct Geometry {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    tangents: Vec<[f32; 3]>,
    uvs: Vec<[f32; 2]>,
    indices: Vec<u32>,
}

fn fullscreen_triangle() -> Geometry {
    Geometry {
        positions: vec![[-1.0, -1.0, 0.0], [3.0, -1.0, 0.0], [-1.0, 3.0, 0.0]],
        normals: vec![[0.0, 0.0, 1.0]; 3],
        tangents: vec![[1.0, 0.0, 0.0]; 3],
        uvs: vec![[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]],
        indices: vec![0, 1, 2],
    }
}

fn cube() -> Geometry {
    let m = super::vk_tutorials::uv_cube();
    let f: &[f32] = bytemuck::cast_slice(&m.vertices);
    let mut g = Geometry { positions: Vec::new(), normals: Vec::new(), tangents: Vec::new(), uvs: Vec::new(), indices: m.indices.clone() };
    for v in f.chunks_exact(8) {
        g.positions.push([v[0], v[1], v[2]]);
        g.uvs.push([v[3], v[4]]);
        g.normals.push([v[5], v[6], v[7]]);
    }
    // Each face's u runs along one edge: the tangent is that edge's direction.
    for face in 0..6 {
        let (a, b) = (4 * face, 4 * face + 1);
        let (pa, pb, ua, ub) = (g.positions[a], g.positions[b], g.uvs[a][0], g.uvs[b][0]);
        let s = if ub > ua { 1.0 } else { -1.0 };
        let d = [(pb[0] - pa[0]) * s, (pb[1] - pa[1]) * s, (pb[2] - pa[2]) * s];
        g.tangents.extend([d; 4]);
    }
    g
}

fn sphere() -> Geometry {
    const SEGMENTS: u32 = 24;
    const RINGS: u32 = 16;
    let mut g = Geometry { positions: Vec::new(), normals: Vec::new(), tangents: Vec::new(), uvs: Vec::new(), indices: Vec::new() };
    for r in 0..=RINGS {
        let theta = std::f32::consts::PI * r as f32 / RINGS as f32;
        for s in 0..=SEGMENTS {
            let phi = std::f32::consts::TAU * s as f32 / SEGMENTS as f32;
            let n = [theta.sin() * phi.sin(), theta.cos(), theta.sin() * phi.cos()];
            g.positions.push(n.map(|c| c * 0.5));
            g.normals.push(n);
            g.tangents.push([phi.cos(), 0.0, -phi.sin()]);
            g.uvs.push([s as f32 / SEGMENTS as f32, r as f32 / RINGS as f32]);
        }
    }
    let row = SEGMENTS + 1;
    for r in 0..RINGS {
        for s in 0..SEGMENTS {
            let (a, b, c, d) = (r * row + s, (r + 1) * row + s, (r + 1) * row + s + 1, r * row + s + 1);
            // Counter-clockwise seen from outside.
            g.indices.extend_from_slice(&[a, b, c, a, c, d]);
        }
    }
    g
}

fn plane() -> Geometry {
    let positions = vec![[-1.0, 0.0, 1.0], [1.0, 0.0, 1.0], [1.0, 0.0, -1.0], [-1.0, 0.0, -1.0]];
    let uvs = positions.iter().map(|p: &[f32; 3]| [(p[0] + 1.0) / 2.0, (p[2] + 1.0) / 2.0]).collect();
    Geometry { positions, normals: vec![[0.0, 1.0, 0.0]; 4], tangents: vec![[1.0, 0.0, 0.0]; 4], uvs, indices: vec![0, 1, 2, 0, 2, 3] }
}

fn geometry(kind: MeshKind) -> Option<Geometry> {
    Some(match kind {
        MeshKind::FullscreenTriangle => fullscreen_triangle(),
        MeshKind::Cube => cube(),
        MeshKind::Sphere => sphere(),
        MeshKind::Plane => plane(),
        MeshKind::None => return None,
    })
}

/// `v` fitted to `n` components: cut, or padded with zeros and a w of 1.
fn fit(v: &[f32], n: u32) -> Vec<f32> {
    (0..n as usize).map(|i| v.get(i).copied().unwrap_or(if i == 3 { 1.0 } else { 0.0 })).collect()
}

fn format(n: u32) -> VertexFormat {
    match n {
        1 => VertexFormat::Float32,
        2 => VertexFormat::Float32x2,
        3 => VertexFormat::Float32x3,
        _ => VertexFormat::Float32x4,
    }
}

/// One vertex input a draw feeds: its name, the attribute, its components.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Input {
    pub name: String,
    pub attribute: Attribute,
    pub components: u32,
}

/// `kind` laid out for `inputs` (per-instance ones from `grid`). `None`
/// for `MeshKind::None`, which has no vertices.
pub fn mesh(kind: MeshKind, inputs: &[Input], grid: Option<&InstanceGrid>) -> Option<&'static Mesh> {
    mesh_of(kind, inputs, grid, false, false)
}

/// [`mesh`], with `unrolled`: every triangle's three vertices its own, in
/// index order (the indices 0, 1, 2, ...), so that `gl_VertexID % 3` is
/// the corner, as a non-indexed triangle list (the page's) gives it; with
/// `points`, a point list: each vertex once (indices 0, 1, 2, ...).
pub fn mesh_of(kind: MeshKind, inputs: &[Input], grid: Option<&InstanceGrid>, unrolled: bool, points: bool) -> Option<&'static Mesh> {
    static CACHE: LazyLock<Mutex<HashMap<String, &'static Mesh>>> = LazyLock::new(Default::default);
    let key = format!("{kind:?}|{inputs:?}|{grid:?}|{unrolled}|{points}");
    if let Some(m) = CACHE.lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
        return Some(m);
    }
    let mut cache = CACHE.lock().unwrap_or_else(|e| e.into_inner());
    let g = geometry(kind)?;
    let g = if unrolled { unroll(g) } else { g };
    let vertices = g.positions.len() as u32;
    let mut mesh = build(g, kind, inputs, grid);
    if points {
        mesh.indices = (0..vertices).collect();
        mesh.points = true;
    }
    // Executors may key uploads by name: one name per layout.
    mesh.name = leak(&format!("{} #{}", kind.name(), cache.len()));
    let built: &'static Mesh = Box::leak(Box::new(mesh));
    cache.insert(key, built);
    Some(built)
}

/// Each index's vertex copied out, the indices counting up.
fn unroll(g: Geometry) -> Geometry {
    let pick = |v: &[[f32; 3]]| g.indices.iter().map(|&i| v[i as usize]).collect::<Vec<_>>();
    Geometry {
        positions: pick(&g.positions),
        normals: pick(&g.normals),
        tangents: pick(&g.tangents),
        uvs: g.indices.iter().map(|&i| g.uvs[i as usize]).collect(),
        indices: (0..g.indices.len() as u32).collect(),
    }
}

fn leak(s: &str) -> &'static str {
    Box::leak(s.to_string().into_boxed_str())
}

fn build(g: Geometry, kind: MeshKind, inputs: &[Input], grid: Option<&InstanceGrid>) -> Mesh {
    let mut fields = Vec::new();
    let (mut stride, mut instance_stride) = (0u32, 0u32);
    for i in inputs {
        let offset = if i.attribute.per_instance() { &mut instance_stride } else { &mut stride };
        fields.push(Field { name: leak(&i.name), offset: *offset, format: format(i.components), per_instance: i.attribute.per_instance() });
        *offset += 4 * i.components;
    }
    let mut floats: Vec<f32> = Vec::new();
    for v in 0..g.positions.len() {
        let p = g.positions[v];
        for i in inputs.iter().filter(|i| !i.attribute.per_instance()) {
            let value: Vec<f32> = match i.attribute {
                Attribute::Position => p.to_vec(),
                Attribute::Normal => g.normals[v].to_vec(),
                Attribute::Tangent => vec![g.tangents[v][0], g.tangents[v][1], g.tangents[v][2], 1.0],
                Attribute::Uv => g.uvs[v].to_vec(),
                Attribute::Color if kind == MeshKind::FullscreenTriangle => vec![p[0] * 0.5 + 0.5, p[1] * 0.5 + 0.5, p[2] * 0.5 + 0.5, 1.0],
                Attribute::Color => vec![(p[0] + 0.5).clamp(0.0, 1.0), (p[1] + 0.5).clamp(0.0, 1.0), (p[2] + 0.5).clamp(0.0, 1.0), 1.0],
                _ => unreachable!("per-instance attributes are filtered out"),
            };
            floats.extend(fit(&value, i.components));
        }
    }
    let mut instances = None;
    if let Some(grid) = grid {
        let base = (floats.len() * 4) as u32;
        for k in 0..grid.total() {
            let (offset, colour, phase) = grid.instance(k);
            for i in inputs.iter().filter(|i| i.attribute.per_instance()) {
                let value: Vec<f32> = match i.attribute {
                    Attribute::InstanceOffset => offset.to_vec(),
                    Attribute::InstanceColor => vec![colour[0], colour[1], colour[2], 1.0],
                    _ => vec![phase],
                };
                floats.extend(fit(&value, i.components));
            }
            if instance_stride == 0 {
                // Drawn instanced by `gl_InstanceID` alone: records of one unread float.
                floats.push(0.0);
            }
        }
        instances = Some(Instances { base, stride: instance_stride.max(4), count: grid.total() });
    }
    let position = inputs.iter().find(|i| i.attribute == Attribute::Position).or(inputs.first()).map_or("", |i| leak(&i.name));
    Mesh {
        name: kind.name(),
        vertices: bytemuck::cast_slice(&floats).to_vec(),
        stride: stride.max(4),
        fields,
        indices: g.indices,
        position,
        instances,
        points: false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(name: &str, attribute: Attribute, components: u32) -> Input {
        Input { name: name.into(), attribute, components }
    }

    #[test]
    fn a_mesh_holds_the_mapped_inputs_interleaved_then_its_instances() {
        let grid = InstanceGrid { count: [2, 1, 1], spacing: 2.0 };
        let inputs = [input("a_pos", Attribute::Position, 3), input("a_uv", Attribute::Uv, 2), input("a_off", Attribute::InstanceOffset, 3)];
        let m = mesh(MeshKind::Plane, &inputs, Some(&grid)).unwrap();
        assert_eq!((m.stride, m.position, m.indices.len()), (20, "a_pos", 6));
        assert_eq!(m.field("a_uv").map(|f| (f.offset, f.format)), Some((12, VertexFormat::Float32x2)));
        let inst = m.instances.unwrap();
        assert_eq!((inst.base, inst.stride, inst.count), (4 * 20, 12, 2));
        let f: &[f32] = bytemuck::cast_slice(&m.vertices);
        assert_eq!(&f[20..23], &[-1.0, 0.0, 0.0], "the first cell's centre");
        assert!(std::ptr::eq(m, mesh(MeshKind::Plane, &inputs, Some(&grid)).unwrap()), "built once");
    }

    #[test]
    fn built_in_meshes_face_outwards_counter_clockwise() {
        for kind in [MeshKind::Cube, MeshKind::Sphere, MeshKind::Plane] {
            let g = geometry(kind).unwrap();
            for t in g.indices.chunks_exact(3) {
                let [a, b, c] = [0, 1, 2].map(|k| glam::Vec3::from(g.positions[t[k] as usize]));
                let n = (b - a).cross(c - a);
                if n.length() < 1e-7 {
                    continue; // the sphere's poles
                }
                assert!(n.dot(glam::Vec3::from(g.normals[t[0] as usize])) > 0.0, "{kind:?} triangle {t:?}");
            }
        }
    }

    #[test]
    fn a_float4_input_gets_a_w_of_one() {
        let m = mesh(MeshKind::FullscreenTriangle, &[input("p", Attribute::Position, 4)], None).unwrap();
        let f: &[f32] = bytemuck::cast_slice(&m.vertices);
        assert_eq!(&f[..4], &[-1.0, -1.0, 0.0, 1.0]);
        assert_eq!(m.field("p").unwrap().format, VertexFormat::Float32x4);
    }
}
