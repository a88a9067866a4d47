//! `umbrac render`: arguments and the command itself.

/// Arguments of `umbrac render`.
#[derive(Debug, Clone, clap::Args)]
pub struct RenderArgs {}

/// Runs `umbrac render`; returns the process exit code.
pub fn run(_args: &RenderArgs) -> i32 {
    eprintln!("error: the renderer is not written yet");
    1
}
