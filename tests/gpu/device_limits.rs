//! The device-limit policy (`emit::limits`, docs/targets.md "Device
//! limits") against a real driver: the 268-vector skinning palette that
//! GLSL 330 compiles with a warning links on Mesa's GL 3.3 context, and,
//! compiled for the limit the GLES 3.0 context reports, on that one too.
//! The driver's limits are printed (run with `--nocapture`), and a program
//! just past the one umbrac counts must not link there: the driver does
//! enforce it, so the palette's link means something.

use crate::support;

use umbrac::render::Consumer;
use umbrac::{compile_source, Limit, Options, Severity, Target};

const SKINNING: &str = include_str!("../support/skinning_palette.das");

#[test]
fn the_skinning_palette_links_within_the_limits_the_driver_reports() {
    for (consumer, target, ext) in [(Consumer::Gl330, Target::Glsl330, "330"), (Consumer::Gles300, Target::Gles300, "300es")] {
        let Some(gl) = support::gpu::gl(consumer) else { continue };
        let limits = gl.reported_limits().unwrap_or_else(|e| panic!("{}: {e}", consumer.name()));
        println!("{} ({}):", consumer.name(), gl.adapter_name());
        for (name, value) in &limits {
            println!("    {name} = {value}");
        }
        let get = |name: &str| limits.iter().find(|(n, _)| *n == name).map(|&(_, v)| v as u64).unwrap();
        // What the driver offers the vertex stage, in the vectors umbrac counts.
        let vectors = if target == Target::Gles300 { get("GL_MAX_VERTEX_UNIFORM_VECTORS") } else { get("GL_MAX_VERTEX_UNIFORM_COMPONENTS") / 4 };
        // GLSL 330 as by default (a warning); ES 3.00 for the stated limit
        // of this driver (GLES's default is an error, Adreno's 256).
        let opts = match target {
            Target::Gles300 => Options { targets: vec![target], limits: vec![(Limit::UniformVectors, vectors)], ..Options::default() },
            _ => Options { targets: vec![target], ..Options::default() },
        };
        let c = compile_source("skinning_palette.das", SKINNING, &opts);
        if vectors < 268 {
            // umbrac must then refuse it, as the driver would.
            assert!(c.result.is_none(), "{}: the driver has {vectors} vectors, but it compiled", consumer.name());
            support::skip(format!("{} offers {vectors} vertex uniform vectors, under the palette's 268", consumer.name()));
            continue;
        }
        let compiled = c.result.as_ref().unwrap_or_else(|| panic!("{}:\n{}", consumer.name(), c.render_diagnostics()));
        let warned = c.diagnostics.iter().any(|d| d.severity == Severity::Warning && d.message.contains("uses 268 uniform vectors"));
        assert_eq!(warned, target == Target::Glsl330, "{}:\n{}", consumer.name(), c.render_diagnostics());
        let file = |name: String| {
            let text = String::from_utf8(compiled.artifact(&name).unwrap_or_else(|| panic!("no {name}")).contents.clone()).unwrap();
            (name, text)
        };
        let (vs, fs) = (file(format!("skin_vs.{ext}.vert")), file(format!("skin_fs.{ext}.frag")));
        gl.link((&vs.0, &vs.1), (&fs.0, &fs.1)).unwrap_or_else(|e| panic!("{}: {e}", consumer.name()));
        println!("    the 268-vector palette links ({vectors} vertex uniform vectors reported)");
        // The driver does enforce its number: past it, the same kind of
        // program (compiled for a stated limit above it) does not link.
        let over = vectors + 8;
        let src = format!(
            "var @uniform u_palette : float4[{over}]\nvar @uniform u_i : int\nvar @out f_color : float4\n\
             [vertex_program]\ndef big_vs {{\n    gl_Position = u_palette[u_i]\n}}\n\
             [fragment_program]\ndef big_fs {{\n    f_color = float4(1.0)\n}}\n"
        );
        let opts = Options { targets: vec![target], limits: vec![(Limit::UniformVectors, over + 1)], ..Options::default() };
        let c = compile_source("big.das", &src, &opts);
        let compiled = c.result.as_ref().unwrap_or_else(|| panic!("{}:\n{}", consumer.name(), c.render_diagnostics()));
        let file = |name: String| (name.clone(), compiled.artifact(&name).unwrap_or_else(|| panic!("no {name}")).text().into_owned());
        let (vs, fs) = (file(format!("big_vs.{ext}.vert")), file(format!("big_fs.{ext}.frag")));
        let linked = gl.link((&vs.0, &vs.1), (&fs.0, &fs.1));
        assert!(linked.is_err(), "{}: {over} vectors link, over the {vectors} the driver reports", consumer.name());
        println!("    {over} vectors do not link: {}", linked.unwrap_err().to_string().lines().next().unwrap_or(""));
    }
}
