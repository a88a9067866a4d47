//! Semantic analysis: name resolution and type checking.
//!
//! Input: the parser's [`ast::Program`](crate::syntax::ast::Program).
//! Output: a [`Program`] in which every name is resolved, every expression
//! typed, and every rule of the language checked, so that lowering cannot
//! meet a user error.

pub mod builtin_docs;
pub mod builtins;
mod check;
pub mod consts;
pub(crate) mod fold;
pub mod limits;
pub mod tree;
pub mod types;

pub use check::{check, check_for_targets, op_text};
pub use limits::{MAX_ARRAY_LEN, MAX_DEPTH, MAX_LOCATIONS};
pub use tree::*;
pub use types::{SamplerKind, Scalar, Ty};
