//! Compiles the shadow scene's shaders into OUT_DIR with typed bindings.

fn main() {
    umbrac::build::Build::new()
        .file("../../shaders/shadow.das")
        // WGSL for wgpu; the GLSL outputs come along as constants for GL hosts.
        .targets(&[umbrac::Target::Wgsl, umbrac::Target::Glsl330, umbrac::Target::Gles300])
        .run();
}
