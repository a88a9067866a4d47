//! The GPU consumers the tests draw on. Each is opened once per process and
//! shared by every test in it (lavapipe is slow to start); a missing one
//! goes through [`super::skip`].

use std::path::{Path, PathBuf};
use std::sync::Once;

#[cfg(feature = "gl")]
use umbrac::render::exec::gl::GlExecutor;
use umbrac::render::exec::wgpu::WgpuExecutor;
#[cfg(feature = "gl")]
use umbrac::render::{Consumer, ExecError};
use umbrac::render::consumers;

/// The process's Vulkan device (`consumers::vulkan`, the one the consumer
/// tests draw on too).
#[track_caller]
pub fn vulkan() -> Option<&'static WgpuExecutor> {
    check_environment();
    super::or_skip(consumers::vulkan(), "no Vulkan renderer")
}

/// wgpu's GL backend, one per process (`consumers::wgpu_gl`): dropping a
/// GL device would terminate the EGL display the GL contexts share.
#[track_caller]
pub fn wgpu_gl() -> Option<&'static WgpuExecutor> {
    check_environment();
    super::or_skip(consumers::wgpu_gl(), "no wgpu GL renderer")
}

/// An OpenGL 3.3 or OpenGL ES 3.0 context on EGL surfaceless. Not
/// installed: [`super::skip`]; any other error fails the test.
#[cfg(feature = "gl")]
#[track_caller]
pub fn gl(consumer: Consumer) -> Option<GlExecutor> {
    check_environment();
    // wgpu's GL backend shares the EGL display and must be open before any
    // context (see `consumers::wgpu_gl`).
    let _ = consumers::wgpu_gl();
    match GlExecutor::new(consumer) {
        Ok(r) => Some(r),
        Err(e @ ExecError::Unavailable { .. }) => {
            super::skip(format!("no {} context: {e}", consumer.name()));
            None
        }
        Err(e) => panic!("no {} context: {e}", consumer.name()),
    }
}

/// `CARGO_TARGET_TMPDIR/NAME`, created: where a test leaves its images.
pub fn artifacts_dir(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Says so (once) when the test binary runs without the environment
/// `.cargo/config.toml` gives it: run directly, not by cargo. Tests do not
/// set it themselves (see the module docs of `support`).
pub fn check_environment() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        if std::env::var("MESA_SHADER_CACHE_DISABLE").as_deref() != Ok("true") {
            eprintln!("note: MESA_SHADER_CACHE_DISABLE is not `true` (cargo sets it from .cargo/config.toml): Mesa's shader cache can hide a compile failure until link");
        }
    });
}
