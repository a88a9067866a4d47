// The compiler recurses over a program's nesting (within umbrac's limits)
// and WebAssembly has no threads to give it a bigger stack, so the module
// links with 8 MiB of stack instead of Rust's default 1 MiB (measured need
// of the deepest accepted program in optimised builds: under 0.4 MiB).
fn main() {
    if std::env::var("CARGO_CFG_TARGET_FAMILY").as_deref() == Ok("wasm") {
        println!("cargo:rustc-link-arg=-zstack-size=8388608");
    }
}
