//! The limits the checker enforces, so that every later stage (which
//! recurses over the checked program) stays within a bounded stack and
//! every target's fixed tables fit (docs/robustness.md).

/// Largest `T[N]` accepted: the most elements Chrome's WGSL compiler
/// (tint) takes in an array type (its count must be under 65536; the WGSL
/// specification leaves the bound to implementations).
pub const MAX_ARRAY_LEN: u64 = 65_535;
/// Highest `@location` accepted (exclusive): a bound on the checker's
/// tables. What devices guarantee (16 attributes, 15 or 16 varyings) is
/// checked per target by `emit::limits`, which `--limit` can raise.
pub const MAX_LOCATIONS: u32 = 32;
/// Highest `@set` accepted (exclusive), likewise: wgpu's default of 4 bind
/// groups is checked by `emit::limits`.
pub const MAX_SETS: i64 = 32;
/// Nesting depth of expressions and blocks the checker follows. A call of a
/// helper function that is checked on first use starts the callee at the
/// caller's depth plus [`CALL_DEPTH`], so chains of calls count too.
pub const MAX_DEPTH: usize = 256;
/// Depth one level of calls adds (the checker recurses into the callee).
pub const CALL_DEPTH: usize = 4;
/// Longest chain of constants defined in terms of each other.
pub const MAX_CONST_CHAIN: usize = 64;
/// Deepest nesting of struct and array types (`S { t : T[2] }` is 2).
pub const MAX_TYPE_DEPTH: usize = 32;
/// Largest uniform block, in bytes: WebGPU's default (and commonly its
/// only) `maxUniformBufferBindingSize`, and what most GL drivers give
/// (`GL_MAX_UNIFORM_BLOCK_SIZE`; the GL 3.3 and GLES 3.0 minimum is 16384).
pub const MAX_UNIFORM_BLOCK_SIZE: u32 = 65_536;
