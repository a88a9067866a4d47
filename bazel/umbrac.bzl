"""Bazel rules for umbrac (docs/scale.md, "Beyond one machine").

umbrac_shader compiles one `.das` program; umbrac_variants compiles one
program's variant spec. Each is one hermetic action: its inputs are the
program, the `#include`/`require` files it reads (`deps`, declared: the
sandbox holds nothing else, so a missing declaration fails the build) and
the umbrac binary (a tool, part of the action's key); its outputs are
declared up front. No absolute path reaches an output, and umbrac reads no
environment variable that changes what it writes, so the action's bytes
are the same on any machine: what a shared remote cache needs.

Loads on Bazel 4.2 (Debian's bazel-bootstrap, WORKSPACE) and current Bazel.
"""

# The infix umbrac puts in a GLSL file's name (ENTRY.INFIX.STAGE), per target.
_GLSL_INFIX = {
    "glsl330": "330",
    "gles300": "300es",
    "glsl430": "430",
    "gles310": "310es",
}

_STAGES = ["vert", "frag", "comp"]

def umbrac_output_names(stem, targets, entries):
    """The files `umbrac compile` writes for one program, by umbrac's rule.

    The same rule as src/emit (STEM.wgsl, STEM.spv, ENTRY.INFIX.STAGE per
    GLSL target and entry point, STEM.reflect.json); each action checks it
    against `umbrac outputs`, so a drift fails the build, not the consumer.

    Args:
      stem: the program's file name without `.das`.
      targets: umbrac target names.
      entries: entry point name -> stage ("vert", "frag" or "comp").

    Returns:
      The file names, sorted.
    """
    names = [stem + ".reflect.json"]
    for t in targets:
        if t == "wgsl":
            names.append(stem + ".wgsl")
        elif t == "spirv":
            names.append(stem + ".spv")
        elif t in _GLSL_INFIX:
            if not entries:
                fail("target %s writes one file per entry point: give `entries` (name -> vert/frag/comp)" % t)
            for e, stage in entries.items():
                if stage not in _STAGES:
                    fail("entry %s: stage %s is not one of %s" % (e, stage, _STAGES))
                names.append("%s.%s.%s" % (e, _GLSL_INFIX[t], stage))
        else:
            fail("unknown umbrac target %s" % t)
    return sorted(names)

def _common_args(ctx):
    args = []
    for t in ctx.attr.targets:
        args += ["--target", t]
    for d in ctx.attr.include_dirs:
        # Relative to the package, as the files are (execroot paths).
        parts = [p for p in [ctx.label.workspace_root, ctx.label.package, d] if p]
        args += ["-I", "/".join(parts)]
    for k, v in sorted(ctx.attr.defines.items()):
        args += ["-D", k + "=" + v if v else k]
    return args

def _stem(f):
    if not f.basename.endswith(".das"):
        fail("%s: an umbrac program ends in .das" % f.short_path)
    return f.basename[:-len(".das")]

def _umbrac_shader_impl(ctx):
    src = ctx.file.src
    names = umbrac_output_names(_stem(src), ctx.attr.targets, ctx.attr.entries)
    outs = [ctx.actions.declare_file(ctx.attr.name + "/" + n) for n in names]
    out_dir = outs[0].dirname
    args = [src.path, "-o", out_dir, "--no-cache"] + _common_args(ctx)
    expected = "\n".join([out_dir + "/" + n for n in names])

    # `umbrac outputs` first: exactly the declared files, or the action
    # fails with the difference (no undeclared output is left behind).
    ctx.actions.run_shell(
        outputs = outs,
        inputs = [src] + ctx.files.deps,
        tools = [ctx.executable.umbrac],
        command = """set -eu
listed=$("$1" outputs "${@:3}")
if [ "$listed" != "$2" ]; then
  printf 'umbrac_shader: the rule declares\\n%s\\nbut `umbrac outputs` lists\\n%s\\n' "$2" "$listed" >&2
  exit 1
fi
exec "$1" compile "${@:3}"
""",
        arguments = [ctx.executable.umbrac.path, expected] + args,
        mnemonic = "Umbrac",
        progress_message = "umbrac %s" % src.short_path,
    )
    return [DefaultInfo(files = depset(outs))]

_COMMON_ATTRS = {
    "src": attr.label(allow_single_file = [".das"], mandatory = True, doc = "The program."),
    "deps": attr.label_list(allow_files = [".das"], doc = "Every file its #include and require read."),
    "targets": attr.string_list(default = ["wgsl", "spirv"], doc = "umbrac targets."),
    "include_dirs": attr.string_list(doc = "-I directories, relative to the package."),
    "defines": attr.string_dict(doc = "-D NAME=VALUE (an empty value: -D NAME)."),
    "umbrac": attr.label(
        default = Label("@umbrac_tool//:umbrac"),
        executable = True,
        allow_single_file = True,
        cfg = "exec",
        doc = "The umbrac binary (scripts/release.sh builds a reproducible one).",
    ),
}

umbrac_shader = rule(
    implementation = _umbrac_shader_impl,
    attrs = dict(_COMMON_ATTRS, entries = attr.string_dict(doc = "GLSL targets: entry point -> vert/frag/comp.")),
    doc = "One umbrac program: one action, every output declared.",
)

def _umbrac_variants_impl(ctx):
    # Variant directory names come from the spec's contents, which Bazel
    # cannot read at analysis: the variants are one directory output, and
    # one action compiles them all (umbrac shares the parse and spreads
    # the variants over --jobs).
    out = ctx.actions.declare_directory(ctx.attr.name)
    args = ctx.actions.args()
    args.add_all(["compile", ctx.file.src.path, "--variants", ctx.file.spec.path, "-o", out.path, "--no-cache"])
    args.add_all(_common_args(ctx))
    ctx.actions.run(
        outputs = [out],
        inputs = [ctx.file.src, ctx.file.spec] + ctx.files.deps,
        executable = ctx.executable.umbrac,
        arguments = [args],
        mnemonic = "UmbracVariants",
        progress_message = "umbrac variants %s" % ctx.file.src.short_path,
    )
    return [DefaultInfo(files = depset([out]))]

umbrac_variants = rule(
    implementation = _umbrac_variants_impl,
    attrs = dict(_COMMON_ATTRS, spec = attr.label(allow_single_file = [".toml"], mandatory = True, doc = "The variant spec.")),
    doc = "Every variant of one program: one action, one directory output.",
)
