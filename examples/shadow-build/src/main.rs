//! Renders umbrac's shadow scene headless with wgpu and writes a PNG, using
//! only what build.rs generated: the WGSL, the uniform buffer struct, the
//! binding constants, the bind group layout entries and the vertex layout.
//!
//! Usage: `shadow-build [OUT.png]` (default `shadow.png`). Exit status 2
//! when no adapter can be opened.
#![deny(warnings)]

include!(concat!(env!("OUT_DIR"), "/umbrac/shaders.rs"));

use glam::camera::rh::{proj::opengl, view::look_at_mat4};
use glam::{Mat4, Quat, Vec3};
use shadow::{main_fs, main_vs, samplers, shadow_fs, shadow_vs, uniform_buffers};
use wgpu::util::DeviceExt;

const WIDTH: u32 = 640;
const HEIGHT: u32 = 480;
const SHADOW_SIZE: u32 = 1024;
const DEPTH: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
const COLOR: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// The scene at time `t`, in GL conventions (the shaders adapt clip space).
struct Scene {
    light_vp: Mat4,
    view: Mat4,
    proj: Mat4,
    light_dir: Vec3,
    cam_pos: Vec3,
    cube_model: Mat4,
}

impl Scene {
    fn at(t: f32) -> Scene {
        let yaw = t * 0.6;
        let light_dir = Vec3::new(yaw.cos(), 1.4, yaw.sin()).normalize();
        let light_vp = opengl::orthographic(-4.0, 4.0, -4.0, 4.0, 0.1, 20.0) * look_at_mat4(light_dir * 8.0, Vec3::ZERO, Vec3::Y);
        let a = t * 0.35;
        let cam_pos = Vec3::new(a.cos() * 5.0, 3.2, a.sin() * 5.0);
        let view = look_at_mat4(cam_pos, Vec3::new(0.0, 0.75, 0.0), Vec3::Y);
        let proj = opengl::perspective(50f32.to_radians(), WIDTH as f32 / HEIGHT as f32, 0.1, 50.0);
        let rot = Quat::from_axis_angle(Vec3::new(0.3, 1.0, 0.2).normalize(), t * 0.7);
        let cube_model = Mat4::from_scale_rotation_translation(Vec3::splat(0.55), rot, Vec3::new(0.0, 1.5, 0.0));
        Scene { light_vp, view, proj, light_dir, cam_pos, cube_model }
    }
}

/// The [-1, 1] cube (24 vertices with face normals, CCW from outside) and
/// the 10 x 10 floor at y = 0.
fn meshes() -> [(Vec<main_vs::Vertex>, Vec<u32>); 2] {
    let mut cube = (Vec::new(), Vec::new());
    let faces = [(Vec3::Z, Vec3::X), (Vec3::X, Vec3::Y), (Vec3::Y, Vec3::Z), (-Vec3::X, Vec3::Z), (-Vec3::Y, Vec3::X), (-Vec3::Z, Vec3::Y)];
    for (n, u) in faces {
        let v = n.cross(u);
        let base = cube.0.len() as u32;
        for (su, sv) in [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)] {
            cube.0.push(main_vs::Vertex { a_pos: (n + u * su + v * sv).into(), a_normal: n.into() });
        }
        cube.1.extend([base, base + 1, base + 2, base + 2, base + 3, base]);
    }
    let floor = [[-5.0, 0.0, -5.0], [-5.0, 0.0, 5.0], [5.0, 0.0, 5.0], [5.0, 0.0, -5.0]];
    let floor = (floor.iter().map(|&a_pos| main_vs::Vertex { a_pos, a_normal: [0.0, 1.0, 0.0] }).collect(), vec![0, 1, 2, 2, 3, 0]);
    [cube, floor]
}

fn main() {
    let out = std::env::args().nth(1).unwrap_or_else(|| "shadow.png".into());
    let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
    desc.backends = wgpu::Backends::VULKAN;
    let instance = wgpu::Instance::new(desc);
    let adapter = match pollster::block_on(instance.request_adapter(&Default::default())) {
        Ok(a) => a,
        Err(e) => {
            eprintln!("no Vulkan adapter ({e}); on Debian: apt-get install mesa-vulkan-drivers");
            std::process::exit(2);
        }
    };
    let (device, queue) = pollster::block_on(adapter.request_device(&Default::default())).expect("open a device");
    let scene = Scene::at(0.8);

    // One uniform buffer per draw (cube, floor): the loose uniforms of
    // group 0 in the generated struct; u_model and u_is_floor differ
    // between draws.
    let buffer = |bytes: &[u8], usage| device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: None, contents: bytes, usage });
    let per_draw: Vec<wgpu::Buffer> = [(scene.cube_model, 0.0), (Mat4::IDENTITY, 1.0)]
        .iter()
        .map(|(model, is_floor)| {
            let values = shadow::Uniforms::new(
                scene.light_vp.to_cols_array_2d(),
                model.to_cols_array_2d(),
                scene.view.to_cols_array_2d(),
                scene.proj.to_cols_array_2d(),
                scene.light_dir.into(),
                scene.cam_pos.into(),
                *is_floor,
            );
            buffer(bytemuck::bytes_of(&values), wgpu::BufferUsages::UNIFORM)
        })
        .collect();
    let meshes: Vec<(wgpu::Buffer, wgpu::Buffer, u32)> = meshes()
        .iter()
        .map(|(v, i)| (buffer(bytemuck::cast_slice(v), wgpu::BufferUsages::VERTEX), buffer(bytemuck::cast_slice(i), wgpu::BufferUsages::INDEX), i.len() as u32))
        .collect();

    let texture = |w: u32, h: u32, format, usage| {
        device.create_texture(&wgpu::TextureDescriptor {
            label: None,
            size: wgpu::Extent3d { width: w, height: h, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage,
            view_formats: &[],
        })
    };
    use wgpu::TextureUsages as U;
    let shadow_view = texture(SHADOW_SIZE, SHADOW_SIZE, DEPTH, U::RENDER_ATTACHMENT | U::TEXTURE_BINDING).create_view(&Default::default());
    let color = texture(WIDTH, HEIGHT, COLOR, U::RENDER_ATTACHMENT | U::COPY_SRC);
    let color_view = color.create_view(&Default::default());
    let depth_view = texture(WIDTH, HEIGHT, DEPTH, U::RENDER_ATTACHMENT).create_view(&Default::default());
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        mag_filter: wgpu::FilterMode::Linear,
        min_filter: wgpu::FilterMode::Linear,
        compare: samplers::shadow_map::COMPARISON.then_some(wgpu::CompareFunction::LessEqual),
        ..Default::default()
    });

    // Pipelines: one WGSL module, layouts from the generated entries.
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor { label: Some("shadow.das"), source: wgpu::ShaderSource::Wgsl(shadow::WGSL.into()) });
    let pipeline = |vs: &str, fs: &str, shadow_pass: bool| {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: None, entries: &shadow::bind_group_layout_entries(&[vs, fs]) });
        let targets = [Some(wgpu::ColorTargetState::from(COLOR))];
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(vs),
            layout: Some(&device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor { label: None, bind_group_layouts: &[Some(&layout)], immediate_size: 0 })),
            vertex: wgpu::VertexState { module: &module, entry_point: Some(vs), compilation_options: Default::default(), buffers: &[Some(main_vs::VERTEX_BUFFER_LAYOUT)] },
            primitive: wgpu::PrimitiveState {
                // Portable conventions flip y, so GL's CCW fronts are CW here.
                front_face: if shadow::CONVENTIONS == "portable" { wgpu::FrontFace::Cw } else { wgpu::FrontFace::Ccw },
                ..Default::default()
            },
            depth_stencil: Some(wgpu::DepthStencilState {
                format: DEPTH,
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: Default::default(),
                bias: if shadow_pass { wgpu::DepthBiasState { constant: 4, slope_scale: 2.0, clamp: 0.0 } } else { Default::default() },
            }),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState { module: &module, entry_point: Some(fs), compilation_options: Default::default(), targets: if shadow_pass { &[] } else { &targets } }),
            multiview_mask: None,
            cache: None,
        });
        (pipeline, layout)
    };
    let (shadow_pipeline, shadow_layout) = pipeline(shadow_vs::NAME, shadow_fs::NAME, true);
    let (main_pipeline, main_layout) = pipeline(main_vs::NAME, main_fs::NAME, false);

    // Bind groups per draw: each pass binds exactly the bindings its layout has.
    let bind_group = |layout: &wgpu::BindGroupLayout, used: &[u32], draw: usize| {
        let mut entries = vec![wgpu::BindGroupEntry { binding: uniform_buffers::uniforms::BINDING, resource: per_draw[draw].as_entire_binding() }];
        entries.push(wgpu::BindGroupEntry { binding: samplers::shadow_map::TEXTURE_BINDING, resource: wgpu::BindingResource::TextureView(&shadow_view) });
        entries.push(wgpu::BindGroupEntry { binding: samplers::shadow_map::SAMPLER_BINDING, resource: wgpu::BindingResource::Sampler(&sampler) });
        entries.retain(|e| used.contains(&e.binding));
        device.create_bind_group(&wgpu::BindGroupDescriptor { label: None, layout, entries: &entries })
    };
    let shadow_used = [shadow_vs::BINDINGS, shadow_fs::BINDINGS].concat();
    let main_used = [main_vs::BINDINGS, main_fs::BINDINGS].concat();

    let mut encoder = device.create_command_encoder(&Default::default());
    let depth_attachment = |view| Some(wgpu::RenderPassDepthStencilAttachment { view, depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }), stencil_ops: None });
    for main_pass in [false, true] {
        let color_attachment = [Some(wgpu::RenderPassColorAttachment {
            view: &color_view,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations { load: wgpu::LoadOp::Clear(wgpu::Color { r: 0.04, g: 0.05, b: 0.09, a: 1.0 }), store: wgpu::StoreOp::Store },
        })];
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            color_attachments: if main_pass { &color_attachment } else { &[] },
            depth_stencil_attachment: depth_attachment(if main_pass { &depth_view } else { &shadow_view }),
            ..Default::default()
        });
        let (pipeline, layout, used) = if main_pass { (&main_pipeline, &main_layout, &main_used) } else { (&shadow_pipeline, &shadow_layout, &shadow_used) };
        pass.set_pipeline(pipeline);
        for (draw, (vertices, indices, count)) in meshes.iter().enumerate() {
            pass.set_bind_group(0, &bind_group(layout, used, draw), &[]);
            pass.set_vertex_buffer(0, vertices.slice(..));
            pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..*count, 0, 0..1);
        }
    }

    // Read back; portable conventions put GL's bottom row first, so flip.
    let row = 4 * WIDTH;
    let padded = row.next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
    let readback = device.create_buffer(&wgpu::BufferDescriptor { label: None, size: (padded * HEIGHT) as u64, usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ, mapped_at_creation: false });
    encoder.copy_texture_to_buffer(
        color.as_image_copy(),
        wgpu::TexelCopyBufferInfo { buffer: &readback, layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(padded), rows_per_image: None } },
        wgpu::Extent3d { width: WIDTH, height: HEIGHT, depth_or_array_layers: 1 },
    );
    queue.submit([encoder.finish()]);
    readback.slice(..).map_async(wgpu::MapMode::Read, |r| r.expect("map the readback"));
    device.poll(wgpu::PollType::wait_indefinitely()).expect("wait for the frame");
    let mapped = readback.slice(..).get_mapped_range().expect("mapped");
    let mut pixels = Vec::with_capacity((row * HEIGHT) as usize);
    for y in 0..HEIGHT {
        let src = if shadow::CONVENTIONS == "portable" { HEIGHT - 1 - y } else { y };
        pixels.extend_from_slice(&mapped[(src * padded) as usize..][..row as usize]);
    }
    let image = image::RgbaImage::from_raw(WIDTH, HEIGHT, pixels).expect("w * h * 4 bytes");
    image.save(&out).expect("write the PNG");
    let mean = image.pixels().map(|p| p[0] as u64 + p[1] as u64 + p[2] as u64).sum::<u64>() / (3 * WIDTH as u64 * HEIGHT as u64);
    println!("wrote {out}: {WIDTH}x{HEIGHT}, mean level {mean}, adapter {}", adapter.get_info().name);
}
