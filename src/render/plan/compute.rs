//! A compute dispatch described once, for every consumer that runs
//! compute (wgpu from WGSL or SPIR-V; GL 4.3 / GLES 3.1 from GLSL): which
//! entry point, how many workgroups, what each storage buffer and image
//! holds at the start (by its DSL name), and what comes back. Bindings
//! come from the manifest ([`crate::render::bind::compute`]).

/// The starting contents of a storage buffer: its bytes, as the manifest's
/// std430 layout places them (the fixed part, then the run-time array).
#[derive(Clone, Debug, PartialEq)]
pub struct BufferInput {
    pub name: String,
    pub bytes: Vec<u8>,
}

/// A storage image: its size (`layers` is the depth of a 3D image or the
/// layer count of an array; 1 for a 2D image) and starting texels (zeros
/// when `None`), rows of texels in coordinate order (y = 0 first) in the
/// manifest's format.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageInput {
    pub name: String,
    pub width: u32,
    pub height: u32,
    pub layers: u32,
    pub texels: Option<Vec<u8>>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct ComputePlan {
    /// Names it in messages.
    pub name: String,
    pub entry: String,
    /// Workgroups along x, y, z (`glDispatchCompute`'s arguments).
    pub workgroups: [u32; 3],
    pub buffers: Vec<BufferInput>,
    pub images: Vec<ImageInput>,
    /// The buffers and images whose contents come back, by name.
    pub readback: Vec<String>,
    /// Specialization constants set by `@constant_id` (the others keep
    /// their defaults): WGSL's overrides and SPIR-V's `OpSpecConstant`s.
    /// GLSL holds the defaults: the GL consumers refuse a plan that sets
    /// any (docs/targets.md).
    pub constants: Vec<(u32, f64)>,
}

impl ComputePlan {
    /// Whether the plan asks nothing impossible: workgroups and image sizes
    /// of at least 1, something read back that the plan binds.
    pub fn check(&self) -> Result<(), String> {
        if self.workgroups.contains(&0) {
            return Err(format!("{}: {:?} workgroups: every count must be at least 1", self.name, self.workgroups));
        }
        for i in &self.images {
            if i.width == 0 || i.height == 0 || i.layers == 0 {
                return Err(format!("{}: image `{}` is {}x{}x{}: every size must be at least 1", self.name, i.name, i.width, i.height, i.layers));
            }
        }
        for r in &self.readback {
            if !self.buffers.iter().any(|b| &b.name == r) && !self.images.iter().any(|i| &i.name == r) {
                return Err(format!("{}: reads back `{r}`, which it binds no buffer or image to", self.name));
            }
        }
        Ok(())
    }
}
