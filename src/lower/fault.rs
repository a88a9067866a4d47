//! Fault injection for tests of the internal-error path, in debug builds
//! only (release builds do not contain it).
//!
//! With `UMBRAC_TEST_FAULT=naga-validation` in the environment, the first
//! `Store` in an entry point of the WGSL/SPIR-V module has its pointer and
//! value swapped after lowering, so naga's validator rejects the module the
//! way it would reject a real lowering bug: an internal compiler error
//! located at the statement, carrying naga's message. Nothing else reads
//! the variable.

pub const VAR: &str = "UMBRAC_TEST_FAULT";

pub fn inject(mut module: naga::Module) -> naga::Module {
    if std::env::var(VAR).as_deref() != Ok("naga-validation") {
        return module;
    }
    for ep in &mut module.entry_points {
        for stmt in ep.function.body.iter_mut() {
            if let naga::Statement::Store { pointer, value } = stmt {
                std::mem::swap(pointer, value);
                return module;
            }
        }
    }
    module
}
