//! Pure analyses of the checked program that decide what each module holds:
//! which helpers each entry point reaches, and where each entry point
//! keeps its inputs and outputs. Nothing here touches naga's IR.

use crate::sema::{self, GlobalKind, IoKind, Ty};

/// Which helper functions each entry point reaches, and which a vertex or
/// a fragment entry point reaches.
pub(super) struct Reach {
    pub(super) by_entry: Vec<Vec<bool>>,
    pub(super) vertex: Vec<bool>,
    pub(super) fragment: Vec<bool>,
    /// Per entry point, the globals its own body assigns (all or part of)
    /// or passes to a `var p : T&` parameter: found once, for every module
    /// built from the program.
    pub(super) written: Vec<Vec<sema::GlobalId>>,
}

impl Reach {
    pub(super) fn of(p: &sema::Program) -> Reach {
        let n = p.functions.len();
        let (mut vertex, mut fragment) = (vec![false; n], vec![false; n]);
        let by_entry: Vec<Vec<bool>> = p.entry_points.iter().map(|ep| reach(p, ep)).collect();
        for (ep, seen) in p.entry_points.iter().zip(&by_entry) {
            let stage = if ep.stage == naga::ShaderStage::Vertex { &mut vertex } else { &mut fragment };
            for (s, r) in stage.iter_mut().zip(seen) {
                *s |= r;
            }
        }
        let written = p
            .entry_points
            .iter()
            .map(|ep| {
                let mut out = ep.func.ref_writes.clone();
                assigned_globals(&ep.func.body, &mut out);
                out
            })
            .collect();
        Reach { by_entry, vertex, fragment, written }
    }
}

/// Where each entry point keeps its inputs and outputs. One that no helper
/// touches (and, for an input, that the entry point never assigns) lives in
/// the entry function itself: an input is read from its argument, an
/// output is a local variable returned at the end. Only the others get a
/// private global (GLSL's model), which every backend writes as a
/// module-level variable with copies in at the start and out at the end.
pub(super) struct EntryIo {
    /// Per entry point of the program (empty for those the module leaves
    /// out), per global: held by the entry function.
    pub(super) own: Vec<Vec<bool>>,
    /// Per global: declared as a private global.
    pub(super) private: Vec<bool>,
}

impl EntryIo {
    pub(super) fn of(p: &sema::Program, only: Option<usize>, reach: &Reach) -> EntryIo {
        let n = p.globals.len();
        let interface = |gid: usize| matches!(p.globals[gid].kind, GlobalKind::Io { .. } | GlobalKind::Builtin(_));
        let mut private = vec![false; n];
        // What the module's helpers touch: every helper for the whole
        // program, those the entry point reaches for one.
        for (fid, f) in p.functions.iter().enumerate() {
            if only.is_none_or(|i| reach.by_entry[i][fid]) {
                for &gid in f.uses.keys() {
                    private[gid] |= interface(gid);
                }
            }
        }
        let mut own = Vec::with_capacity(p.entry_points.len());
        let (mut touched, mut written) = (vec![false; n], vec![false; n]);
        for (index, ep) in p.entry_points.iter().enumerate() {
            if only.is_some_and(|i| i != index) {
                own.push(Vec::new());
                continue;
            }
            touched.fill(false);
            written.fill(false);
            for (f, _) in p.functions.iter().zip(&reach.by_entry[index]).filter(|(_, r)| **r) {
                for &gid in f.uses.keys() {
                    touched[gid] = true;
                }
            }
            for &gid in &reach.written[index] {
                written[gid] = true;
            }
            let mut mine = vec![false; n];
            for &gid in ep.func.uses.keys() {
                let g = &p.globals[gid];
                let input = is_stage_input(&g.kind, ep.stage) && !written[gid];
                let output = is_stage_output(&g.kind, ep.stage);
                // Interface types are scalars and vectors; anything else
                // keeps the private global, where every access works.
                let plain = matches!(g.ty, Ty::Scalar(_) | Ty::Vector(..));
                mine[gid] = plain && !touched[gid] && (input || output);
                private[gid] |= interface(gid) && !mine[gid];
            }
            own.push(mine);
        }
        EntryIo { own, private }
    }
}

/// Adds the globals that `stmts` assign to (all or part of) to `out`.
fn assigned_globals(stmts: &[sema::Stmt], out: &mut Vec<sema::GlobalId>) {
    fn root(e: &sema::Expr) -> Option<sema::GlobalId> {
        match &e.kind {
            sema::ExprKind::Global(g) => Some(*g),
            sema::ExprKind::Field(b, _) | sema::ExprKind::Index(b, _) | sema::ExprKind::Swizzle(b, _) => root(b),
            _ => None,
        }
    }
    for s in stmts {
        match s {
            sema::Stmt::Assign { target, .. } => {
                if let Some(g) = root(target) {
                    out.push(g);
                }
            }
            sema::Stmt::If { then, otherwise, .. } => {
                assigned_globals(then, out);
                assigned_globals(otherwise, out);
            }
            sema::Stmt::While { body, .. } | sema::Stmt::For { body, .. } => assigned_globals(body, out),
            _ => {}
        }
    }
}

/// Which helper functions entry point `ep` reaches.
fn reach(p: &sema::Program, ep: &sema::EntryPoint) -> Vec<bool> {
    let mut seen = vec![false; p.functions.len()];
    let mut stack: Vec<usize> = ep.func.callees.iter().copied().collect();
    while let Some(f) = stack.pop() {
        if f < seen.len() && !seen[f] {
            seen[f] = true;
            stack.extend(p.functions[f].callees.iter().copied());
        }
    }
    seen
}

/// Whether an interface global is read (an input) in this stage.
pub(super) fn is_stage_input(kind: &GlobalKind, stage: naga::ShaderStage) -> bool {
    match kind {
        GlobalKind::Io { kind: IoKind::In, .. } => true,
        GlobalKind::Io { kind: IoKind::InOut, .. } => stage == naga::ShaderStage::Fragment,
        GlobalKind::Builtin(b) => !b.is_output(),
        _ => false,
    }
}

/// Whether an interface global is written (an output) in this stage.
pub(super) fn is_stage_output(kind: &GlobalKind, stage: naga::ShaderStage) -> bool {
    match kind {
        GlobalKind::Io { kind: IoKind::Out, .. } => true,
        GlobalKind::Io { kind: IoKind::InOut, .. } => stage == naga::ShaderStage::Vertex,
        GlobalKind::Builtin(b) => b.is_output(),
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::Diagnostics;
    use crate::source::SourceMap;

    fn checked(src: &str) -> sema::Program {
        let mut sources = SourceMap::new();
        let root = sources.add("reach.das", None, src.to_string(), None);
        let mut diags = Diagnostics::new();
        let ast = crate::syntax::parse(&mut sources, root, &Default::default(), &mut diags);
        let program = sema::check(&ast, &mut diags);
        assert!(!diags.has_errors(), "{}", diags.into_vec().iter().map(|d| d.render(&sources)).collect::<String>());
        program.expect("checked")
    }

    fn function(p: &sema::Program, name: &str) -> usize {
        p.functions.iter().position(|f| f.name == name).unwrap_or_else(|| panic!("no function `{name}`"))
    }

    fn global(p: &sema::Program, name: &str) -> usize {
        p.globals.iter().position(|g| g.name == name).unwrap_or_else(|| panic!("no global `{name}`"))
    }

    const TWO_STAGES: &str = "
var @in @location = 0 a_pos : float3
var @inout v_uv : float2
var @out f_color : float4
var @uniform tint : float4
def leaf(x : float) : float {
    return x * 2.0
}
def shared(x : float) : float {
    return leaf(x) + 1.0
}
def fragment_only(c : float4) : float4 {
    return c * tint
}
def unused() : float {
    return 3.0
}
[vertex_program]
def vs {
    v_uv = a_pos.xy
    gl_Position = float4(a_pos * shared(1.0), 1.0)
}
[fragment_program]
def fs {
    f_color = fragment_only(float4(v_uv, shared(0.5), 1.0))
}
";

    #[test]
    fn reach_follows_calls_transitively_per_entry_and_per_stage() {
        let p = checked(TWO_STAGES);
        let r = Reach::of(&p);
        let (vs, fs) = (0, 1);
        assert_eq!(p.entry_points[vs].stage, naga::ShaderStage::Vertex);
        let [leaf, shared, frag_only] = ["leaf", "shared", "fragment_only"].map(|n| function(&p, n));
        // `unused` is never checked, so sema does not even keep it.
        assert!(p.functions.iter().all(|f| f.name != "unused"));
        assert!(r.by_entry[vs][shared] && r.by_entry[vs][leaf] && !r.by_entry[vs][frag_only]);
        assert!(r.by_entry[fs][shared] && r.by_entry[fs][leaf] && r.by_entry[fs][frag_only]);
        assert!(r.vertex[leaf] && r.fragment[leaf]);
        assert!(!r.vertex[frag_only] && r.fragment[frag_only]);
    }

    #[test]
    fn untouched_inputs_and_outputs_live_in_the_entry_point() {
        let p = checked(TWO_STAGES);
        let io = EntryIo::of(&p, None, &Reach::of(&p));
        let [pos, uv, color] = ["a_pos", "v_uv", "f_color"].map(|n| global(&p, n));
        // No helper touches them, so each entry point holds them itself
        // and no private global is declared.
        assert!(io.own[0][pos] && io.own[0][uv]);
        assert!(io.own[1][uv] && io.own[1][color]);
        assert!(!io.private[pos] && !io.private[uv] && !io.private[color]);
    }

    #[test]
    fn inputs_a_helper_touches_or_the_entry_assigns_get_a_private_global() {
        let p = checked(
            "
var @in @location = 0 a_pos : float3
var @inout v_uv : float2
var @inout v_shade : float
var @out f_color : float4
def scaled() : float3 {
    return a_pos * 2.0
}
[vertex_program]
def vs {
    v_uv = a_pos.xy
    v_shade = a_pos.z
    gl_Position = float4(scaled(), 1.0)
}
[fragment_program]
def fs {
    v_shade = v_shade * 0.5
    f_color = float4(v_uv, v_shade, 1.0)
}
",
        );
        let reach = Reach::of(&p);
        let io = EntryIo::of(&p, None, &reach);
        let [pos, uv, shade] = ["a_pos", "v_uv", "v_shade"].map(|n| global(&p, n));
        assert!(io.private[pos] && !io.own[0][pos], "read by a helper");
        assert!(io.own[0][shade], "an output of the vertex entry point");
        assert!(!io.own[1][shade] && io.private[shade], "assigned by the fragment entry point, which reads it");
        assert!(io.own[0][uv] && io.own[1][uv] && !io.private[uv]);
        // A one-entry module decides the same for its entry point and
        // leaves the others' lists empty.
        let one = EntryIo::of(&p, Some(1), &reach);
        assert_eq!(one.own[1], io.own[1]);
        assert!(one.own[0].is_empty());
    }

    #[test]
    fn assignments_are_found_in_nested_blocks_and_through_places() {
        let p = checked(
            "
var @inout a : float4
var @inout b : float4
var @out f_color : float4
[fragment_program]
def fs {
    if (a.x > 0.0) {
        for (i in range(2)) {
            b.y += 1.0
        }
    }
    f_color = a + b
}
",
        );
        let mut written = Vec::new();
        assigned_globals(&p.entry_points[0].func.body, &mut written);
        let [a, b, color] = ["a", "b", "f_color"].map(|n| global(&p, n));
        assert!(!written.contains(&a) && written.contains(&b) && written.contains(&color));
        assert_eq!(Reach::of(&p).written, [written], "found once per entry point");
    }

    #[test]
    fn stage_direction_of_inout_globals() {
        use naga::ShaderStage::{Fragment, Vertex};
        let inout = GlobalKind::Io { kind: IoKind::InOut, location: None };
        assert!(is_stage_output(&inout, Vertex) && !is_stage_input(&inout, Vertex));
        assert!(is_stage_input(&inout, Fragment) && !is_stage_output(&inout, Fragment));
    }
}
