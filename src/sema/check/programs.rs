//! Programs: which entry points a host links into one program, and the
//! locations and texture units numbered and checked per program, as
//! daslang does (a file may hold a G-buffer pass, an SSAO pass and a
//! lighting pass, each starting at location 0 and texture unit 0).
//!
//! - A vertex and a fragment entry point form a program (a [`Link`]) when
//!   the fragment one reads an `@inout` varying the vertex one writes;
//!   entry points that share no varying with any entry point of the other
//!   stage (a depth-only pass, a transform-feedback step and its dummy
//!   fragment program) are linked with each other.
//! - Locations: an entry point's vertex inputs, and a fragment entry
//!   point's outputs, are numbered per entry point. Varyings (a vertex
//!   entry point's outputs, a fragment entry point's inputs) are numbered
//!   per group of entry points joined by shared varyings, so that both
//!   ends of every varying agree. `@location = N` is kept as written; the
//!   others take the lowest location free in their entry point or group,
//!   in declaration order. Two globals at one location there are an error.
//! - Texture units: a sampler's `@stage = N` is kept as written; the
//!   others take the lowest units free in every program and entry point
//!   that uses them, in declaration order. Two samplers on one unit in one
//!   program (or one entry point) are an error.

use super::stmts::stage_name;
use super::*;

/// The location numbering an interface global of an entry point falls in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
enum Scope {
    /// Vertex inputs or fragment outputs of one entry point.
    Entry(usize),
    /// Varyings of a group of entry points joined by shared varyings.
    Group(usize),
}

fn qualifier(kind: IoKind) -> &'static str {
    match kind {
        IoKind::In => "@in",
        IoKind::Out => "@out",
        IoKind::InOut => "@inout",
    }
}

impl<'a, 'd> Checker<'a, 'd> {
    /// Links the checked entry points into programs and numbers and checks
    /// their locations and texture units (see the module docs).
    pub(super) fn link_programs(&mut self) {
        let n = self.out.entry_points.len();
        let is_vertex = |e: usize, eps: &[EntryPoint]| eps[e].stage == naga::ShaderStage::Vertex;
        // A compute entry point is never linked: it is a program alone.
        let is_fragment = |e: usize, eps: &[EntryPoint]| eps[e].stage == naga::ShaderStage::Fragment;
        let varyings = |ep: &EntryPoint, globals: &[Global]| -> Vec<GlobalId> {
            ep.func.uses.keys().copied().filter(|&g| matches!(globals[g].kind, GlobalKind::Io { kind: IoKind::InOut, .. })).collect()
        };
        let shared: Vec<Vec<GlobalId>> = self.out.entry_points.iter().map(|ep| varyings(ep, &self.out.globals)).collect();
        // Groups for varyings: union-find over shared varyings.
        let mut parent: Vec<usize> = (0..n).collect();
        fn root(parent: &mut [usize], mut e: usize) -> usize {
            while parent[e] != e {
                parent[e] = parent[parent[e]];
                e = parent[e];
            }
            e
        }
        let mut links = self.link_by_location();
        let mut linked = vec![false; n];
        let eps = &self.out.entry_points;
        // The GL dialect's rules, among its own entry points.
        let gl = |e: usize, eps: &[EntryPoint]| eps[e].dialect == ast::Dialect::Gl;
        for v in (0..n).filter(|&e| is_vertex(e, eps) && gl(e, eps)) {
            for f in (0..n).filter(|&e| is_fragment(e, eps) && gl(e, eps)) {
                if shared[v].iter().any(|g| shared[f].contains(g)) {
                    links.push(Link { vertex: v, fragment: f });
                    linked[v] = true;
                    linked[f] = true;
                    let (a, b) = (root(&mut parent, v), root(&mut parent, f));
                    parent[a] = b;
                }
            }
        }
        for v in (0..n).filter(|&e| is_vertex(e, eps) && gl(e, eps) && !linked[e]) {
            for f in (0..n).filter(|&e| is_fragment(e, eps) && gl(e, eps) && !linked[e]) {
                links.push(Link { vertex: v, fragment: f });
            }
        }
        let group: Vec<usize> = (0..n).map(|e| root(&mut parent, e)).collect();
        self.number_locations(&group);
        self.number_texture_units(&links);
        self.assign_bindings(&links);
        self.number_storage_units();
        self.out.links = links;
    }

    /// The Vulkan dialect's programs: a vertex and a fragment entry point
    /// link when each input the fragment one reads has an output of the
    /// vertex one at its location, of its type and interpolation (dasSpirv
    /// matches stage I/O by location). A fragment entry point that reads
    /// inputs and links with none, though the file has vertex ones, is an
    /// error at its first input that no vertex entry point matches.
    fn link_by_location(&mut self) -> Vec<Link> {
        let eps = &self.out.entry_points;
        let vulkan = |e: &EntryPoint, stage| e.dialect == ast::Dialect::Vulkan && e.stage == stage;
        // (location, global) of an entry point's `@in`s or `@out`s.
        let io = |ep: &EntryPoint, want: IoKind| -> Vec<(u32, GlobalId)> {
            let mut v: Vec<(u32, GlobalId)> = ep.func.uses.keys().copied().filter_map(|g| match self.out.globals[g].kind {
                GlobalKind::Io { kind, location } if kind == want => Some((location.unwrap_or(0), g)),
                _ => None,
            }).collect();
            v.sort_unstable();
            v
        };
        let same = |a: GlobalId, b: GlobalId| {
            let (ga, gb) = (&self.out.globals[a], &self.out.globals[b]);
            ga.ty == gb.ty && self.out.flat.contains(&a) == self.out.flat.contains(&b)
        };
        let vertices: Vec<(usize, Vec<(u32, GlobalId)>)> =
            eps.iter().enumerate().filter(|(_, e)| vulkan(e, naga::ShaderStage::Vertex)).map(|(i, e)| (i, io(e, IoKind::Out))).collect();
        let mut links = Vec::new();
        let mut errors = Vec::new();
        for (f, ep) in eps.iter().enumerate().filter(|(_, e)| vulkan(e, naga::ShaderStage::Fragment)) {
            let ins = io(ep, IoKind::In);
            // Per vertex entry point: the first input it does not match.
            let mut best: Option<(usize, GlobalId, Option<GlobalId>)> = None;
            for (v, outs) in &vertices {
                let miss = ins.iter().find_map(|&(l, g)| match outs.iter().find(|o| o.0 == l) {
                    Some(&(_, o)) if same(g, o) => None,
                    Some(&(_, o)) => Some((g, Some(o))),
                    None => Some((g, None)),
                });
                match miss {
                    None => links.push(Link { vertex: *v, fragment: f }),
                    // Prefer a vertex entry point that has the location.
                    Some((g, o)) if best.is_none_or(|b| b.2.is_none() && o.is_some()) => best = Some((*v, g, o)),
                    Some(_) => {}
                }
            }
            // A mesh entry point writing every input (one element per
            // vertex) feeds it instead: a mesh pipeline, no link.
            let elem = |g: GlobalId| match &self.out.globals[g].ty {
                Ty::RuntimeArray(e) => Some((**e).clone()),
                _ => None,
            };
            let meshes = eps.iter().filter(|e| vulkan(e, naga::ShaderStage::Mesh)).map(|e| io(e, IoKind::Out));
            let fed_by_mesh = meshes.into_iter().any(|outs| {
                ins.iter().all(|&(l, g)| outs.iter().any(|&(ol, o)| ol == l && elem(o).as_ref() == Some(&self.out.globals[g].ty) && self.out.flat.contains(&o) == self.out.flat.contains(&g)))
            });
            if links.iter().all(|l| l.fragment != f) && !fed_by_mesh {
                if let Some(b) = best {
                    errors.push((f, b));
                }
            }
        }
        // A fragment entry point fed by a stage already refused (a mesh
        // shader) would be reported twice over.
        let errors = if self.diags.has_errors() { Vec::new() } else { errors };
        for (f, (v, g, o)) in errors {
            let (fe, ve) = (&self.out.entry_points[f], &self.out.entry_points[v]);
            let gi = &self.out.globals[g];
            // Locations are numbered after linking: the one written.
            let GlobalKind::Io { location: Some(l), .. } = gi.kind else { continue };
            let span = self.location_spans.get(&g).copied().unwrap_or(gi.span);
            let interp = |g: GlobalId| if self.out.flat.contains(&g) { "flat" } else { "interpolated" };
            let d = match o {
                Some(o) => {
                    let go = &self.out.globals[o];
                    let what = if gi.ty != go.ty { format!("`{}` here, `{}` there", self.show(&gi.ty), self.show(&go.ty)) } else { format!("{} here, {} there", interp(g), interp(o)) };
                    Diagnostic::error(format!("location {l} does not match between vertex entry point `{}` and fragment entry point `{}`: {what}", ve.name, fe.name), span)
                        .with_label(format!("`{}` reads location {l}", gi.name))
                        .with_secondary(self.location_spans.get(&o).copied().unwrap_or(go.span), format!("`{}` writes it", go.name))
                }
                None => Diagnostic::error(format!("no vertex entry point writes location {l}, which fragment entry point `{}` reads", fe.name), span)
                    .with_label(format!("`{}` reads location {l}", gi.name))
                    .with_note(format!("e.g. `{}` writes no `@out @location = {l}`", ve.name)),
            };
            self.diags.push(d.with_note("in the Vulkan dialect a vertex `@out` and a fragment `@in` at one location are one varying: the same type, both `@flat` or neither"));
        }
        links
    }

    /// The WGSL/SPIR-V group and binding of every uniform and sampler an
    /// entry point uses (see `Global::bind`): the ones written first, then
    /// the others at the lowest free bindings of their group, in
    /// declaration order. The loose uniforms of a group (every uniform
    /// that is not a struct) are members of one uniform buffer, which all
    /// of them are bound at: a `@binding = N` on any of them places the
    /// buffer. The GPU module holds every entry point, so bindings are
    /// unique across the file.
    ///
    /// In the Vulkan dialect each pipeline has its own layout, so bindings
    /// are unique per program (a linked pair, or an entry point alone),
    /// not across the file: two passes may bind different resources at
    /// one binding (WGSL and SPIR-V check bindings per entry point).
    fn assign_bindings(&mut self, links: &[Link]) {
        // Per global in declaration (id) order: the holder it is bound
        // with, `UNUSED` where no entry point uses it (a table, not a set).
        const UNUSED: usize = usize::MAX;
        const USED: usize = usize::MAX - 1;
        let mut holder_of = vec![UNUSED; self.out.globals.len()];
        for ep in &self.out.entry_points {
            for &g in ep.func.uses.keys() {
                holder_of[g] = USED;
            }
        }
        // What takes bindings, in declaration order of its first global:
        // (that global, group, how many bindings, the binding written).
        struct Holder {
            first: GlobalId,
            group: u32,
            slots: u32,
            written: Option<(u32, Span, GlobalId)>,
        }
        let mut holders: Vec<Holder> = Vec::new();
        // The programs whose bindings must differ: one for the whole file
        // in the GL dialect; in the Vulkan one, each link and each entry
        // point in none, as the globals they use.
        let programs: Vec<Vec<GlobalId>> = if self.out.vulkan {
            let eps = &self.out.entry_points;
            let mut in_link = vec![false; eps.len()];
            let mut ps: Vec<Vec<GlobalId>> = Vec::new();
            for l in links {
                in_link[l.vertex] = true;
                in_link[l.fragment] = true;
                ps.push(eps[l.vertex].func.uses.keys().chain(eps[l.fragment].func.uses.keys()).copied().collect());
            }
            for (e, ep) in eps.iter().enumerate().filter(|(e, _)| !in_link[*e]) {
                let _ = e;
                ps.push(ep.func.uses.keys().copied().collect());
            }
            ps
        } else {
            Vec::new()
        };
        let mut buffer_of_group: BTreeMap<u32, usize> = BTreeMap::new();
        for g in 0..holder_of.len() {
            if holder_of[g] == UNUSED {
                continue;
            }
            let global = &self.out.globals[g];
            let slots = match global.kind {
                GlobalKind::Uniform { .. } | GlobalKind::Storage { .. } | GlobalKind::Image { .. } => 1u32,
                // The Vulkan dialect's sampler half is placed after all
                // the others (below): one slot here; a descriptor array
                // too (its N textures at one binding, its N samplers at
                // the half).
                GlobalKind::Sampler { .. } if self.out.vulkan => 1,
                GlobalKind::Sampler { count, .. } => 2 * count.unwrap_or(1),
                _ => {
                    holder_of[g] = UNUSED;
                    continue;
                }
            };
            let loose = global.is_loose_uniform();
            let (set, binding) = self.bind_written.get(&g).copied().unwrap_or((None, None));
            let group = set.map_or(0, |s| s.0);
            let written = binding.map(|(b, span)| (b, span, g));
            let at = if loose { buffer_of_group.get(&group).copied() } else { None };
            let Some(at) = at else {
                if loose {
                    buffer_of_group.insert(group, holders.len());
                }
                holder_of[g] = holders.len();
                holders.push(Holder { first: g, group, slots, written });
                continue;
            };
            holder_of[g] = at;
            let h = &mut holders[at];
            match (h.written, written) {
                (Some((b0, _, g0)), Some((b1, span, _))) if b0 != b1 => {
                    let (a, b) = (&self.out.globals[g0].name, &self.out.globals[g].name);
                    let mut d = Diagnostic::error(format!("`{a}` and `{b}` give group {group}'s uniform buffer two bindings, {b0} and {b1}"), span)
                        .with_label(format!("`{b}` asks for binding {b1}"));
                    if let Some(Some((_, p))) = self.bind_written.get(&g0).map(|w| w.1) {
                        d = d.with_secondary(p, format!("`{a}` asks for binding {b0}"));
                    }
                    self.diags.push(d.with_note("the loose uniforms of a group (those that are not structs) are members of one uniform buffer: give one of them the `@binding`, or all the same one"));
                }
                (None, Some(w)) => h.written = Some(w),
                _ => {}
            }
        }
        // The programs each holder is in (all in program 0 in the GL dialect).
        let mut progs_of: Vec<Vec<usize>> = vec![Vec::new(); holders.len()];
        if programs.is_empty() {
            progs_of.iter_mut().for_each(|p| p.push(0));
        } else {
            for (pi, uses) in programs.iter().enumerate() {
                for &g in uses {
                    if holder_of[g] < USED && progs_of[holder_of[g]].last() != Some(&pi) {
                        progs_of[holder_of[g]].push(pi);
                    }
                }
            }
        }
        // (program, group, binding) -> the holder there.
        let mut taken: BTreeMap<(usize, u32, u32), usize> = BTreeMap::new();
        let mut placed: Vec<Option<u32>> = vec![None; holders.len()];
        for (i, h) in holders.iter().enumerate() {
            let Some((first, span, g)) = h.written else { continue };
            let (group, n) = (h.group, h.slots);
            let clash = progs_of[i].iter().find_map(|&p| (first..first + n).find_map(|b| taken.get(&(p, group, b)).map(|&q| (b, q))));
            if let Some((at, prev)) = clash {
                let prev_g = holders[prev].written.map_or(holders[prev].first, |w| w.2);
                let (a, b) = (&self.out.globals[prev_g].name, &self.out.globals[g].name);
                let mut d = Diagnostic::error(format!("`{a}` and `{b}` are both bound in group {group} at binding {at}"), span)
                    .with_label(format!("`{b}` takes binding {first}{}", if n > 1 { format!("..{}", first + n - 1) } else { String::new() }));
                if let Some(Some((_, p))) = self.bind_written.get(&prev_g).map(|w| w.1) {
                    d = d.with_secondary(p, format!("`{a}` is bound here"));
                }
                let d = d.with_note("a sampler takes two bindings (its texture, then its sampler), an array of N samplers 2N; the loose uniforms of a group share one");
                self.diags.push(d);
                continue;
            }
            for &p in &progs_of[i] {
                for b in first..first + n {
                    taken.insert((p, group, b), i);
                }
            }
            placed[i] = Some(first);
        }
        // Per group, the smallest request that found no room: bindings are
        // only taken, so a request as large fails too, and is not searched
        // for (200 000 samplers would search 1000 bindings each) nor
        // reported again.
        let mut no_room: BTreeMap<u32, u32> = BTreeMap::new();
        for (i, h) in holders.iter().enumerate() {
            if h.written.is_some() {
                continue;
            }
            let (group, n) = (h.group, h.slots);
            if no_room.get(&group).is_some_and(|&m| n >= m) {
                continue;
            }
            let progs = &progs_of[i];
            let free = |b: u32| progs.iter().all(|&p| (b..b + n).all(|k| !taken.contains_key(&(p, group, k))));
            let most = MAX_BINDINGS;
            let Some(first) = (0..most.saturating_sub(n - 1)).find(|&b| free(b)) else {
                self.diags.push(Diagnostic::error(format!("no {n} free bindings left in group {group} (at most {most})"), self.out.globals[h.first].span));
                no_room.insert(group, n);
                continue;
            };
            for &p in progs {
                for b in first..first + n {
                    taken.insert((p, group, b), i);
                }
            }
            placed[i] = Some(first);
        }
        // The Vulkan dialect's sampler halves (naga has no combined
        // image-sampler): in declaration order, each at the lowest binding
        // past every other binding of its group in each of its programs,
        // so that bindings written 0, 1, 2 ... stay gapless (wgpu numbers
        // a passthrough module's descriptors by their place in the layout).
        let mut halves: Vec<(GlobalId, u32)> = Vec::new();
        if self.out.vulkan {
            let mut top: BTreeMap<(usize, u32), u32> = BTreeMap::new();
            for &(p, group, b) in taken.keys() {
                let t = top.entry((p, group)).or_insert(0);
                *t = (*t).max(b + 1);
            }
            for (i, h) in holders.iter().enumerate() {
                if placed[i].is_none() || !matches!(self.out.globals[h.first].kind, GlobalKind::Sampler { .. }) {
                    continue;
                }
                let (group, progs) = (h.group, &progs_of[i]);
                let start = progs.iter().map(|&p| top.get(&(p, group)).copied().unwrap_or(0)).max().unwrap_or(0);
                let Some(b) = (start..MAX_BINDINGS).find(|&b| progs.iter().all(|&p| !taken.contains_key(&(p, group, b)))) else {
                    let g = &self.out.globals[h.first];
                    let d = Diagnostic::error(format!("no binding below {MAX_BINDINGS} is left in group {group} for the sampler half of `{}`", g.name), g.span)
                        .with_note("naga has no combined image-sampler: a Vulkan-dialect sampler's sampler half takes the binding after the highest one of its group");
                    self.diags.push(d);
                    continue;
                };
                for &p in progs {
                    taken.insert((p, group, b), i);
                    top.insert((p, group), b + 1);
                }
                halves.push((h.first, b));
            }
        }
        self.out.sampler_halves.extend(halves);
        for (g, &h) in holder_of.iter().enumerate() {
            if h >= USED {
                continue;
            }
            if let Some(binding) = placed[h] {
                self.out.globals[g].bind = Some(Bind { group: holders[h].group, binding });
            }
        }
    }

    /// The GL units of the storage buffers (binding points) and storage
    /// images (image units) entry points use: `@stage = N` as written
    /// (dasGlsl's `layout(binding = N)`); the others numbered from 0 in
    /// declaration order, per kind, past every unit written in the file.
    /// Two written on one unit in one entry point are an error.
    fn number_storage_units(&mut self) {
        fn unit_of(k: &mut GlobalKind, image: bool) -> Option<&mut u32> {
            match k {
                GlobalKind::Storage { unit, .. } if !image => Some(unit),
                GlobalKind::Image { unit, .. } if image => Some(unit),
                _ => None,
            }
        }
        for image in [false, true] {
            let mut written = FxHashSet::default();
            for (g, global) in self.out.globals.iter_mut().enumerate() {
                if let Some(u) = unit_of(&mut global.kind, image).filter(|_| self.unit_spans.contains_key(&g)) {
                    written.insert(*u);
                }
            }
            let mut next = 0u32;
            for (g, global) in self.out.globals.iter_mut().enumerate() {
                let used = global.bind.is_some();
                let Some(u) = unit_of(&mut global.kind, image) else { continue };
                if !used || self.unit_spans.contains_key(&g) {
                    continue;
                }
                while written.contains(&next) {
                    next += 1;
                }
                *u = next;
                next += 1;
            }
            let what = if image { "image unit" } else { "storage buffer binding point" };
            for e in 0..self.out.entry_points.len() {
                let mut uses: Vec<GlobalId> = self.out.entry_points[e].func.uses.keys().copied().filter(|g| self.unit_spans.contains_key(g)).collect();
                uses.sort_unstable();
                let mut seen: FxHashMap<u32, GlobalId> = FxHashMap::default();
                for g in uses {
                    let Some(u) = unit_of(&mut self.out.globals[g].kind, image).map(|u| *u) else { continue };
                    if let Some(prev) = seen.insert(u, g) {
                        let (a, b) = (&self.out.globals[prev].name, &self.out.globals[g].name);
                        let d = Diagnostic::error(format!("{what} {u} is used twice in {} entry point `{}`", stage_name(self.out.entry_points[e].stage), self.out.entry_points[e].name), self.unit_spans[&g])
                            .with_label(format!("`{b}` is on {what} {u}"))
                            .with_secondary(self.unit_spans[&prev], format!("`{a}` is on it too"))
                            .with_note("give one of them another `@stage = N`, or none to have one assigned");
                        self.diags.push(d);
                    }
                }
            }
        }
    }

    /// Where a scope's globals live, for diagnostics.
    fn scope_text(&self, scope: Scope, group: &[usize]) -> String {
        let eps = &self.out.entry_points;
        let describe = |e: usize| format!("{} entry point `{}`", stage_name(eps[e].stage), eps[e].name);
        match scope {
            Scope::Entry(e) => describe(e),
            Scope::Group(g) => {
                let members: Vec<usize> = (0..eps.len()).filter(|&e| group[e] == g).collect();
                match members.as_slice() {
                    [one] => describe(*one),
                    _ => {
                        let names: Vec<String> = members.iter().map(|&e| format!("`{}`", eps[e].name)).collect();
                        format!("the program of {}", join_and(&names))
                    }
                }
            }
        }
    }

    fn number_locations(&mut self, group: &[usize]) {
        // (scope, global, entry point) of every interface global an entry
        // point uses; sorted, each scope's globals are a run in
        // declaration order. A flat list: a program has a few dozen.
        let mut placed: Vec<(Scope, GlobalId, usize)> = Vec::with_capacity(self.out.entry_points.iter().map(|ep| ep.func.uses.len()).sum());
        for (e, ep) in self.out.entry_points.iter().enumerate() {
            let vertex = ep.stage == naga::ShaderStage::Vertex;
            for &g in ep.func.uses.keys() {
                let GlobalKind::Io { kind, .. } = self.out.globals[g].kind else { continue };
                let varying = match kind {
                    IoKind::In => !vertex,
                    IoKind::Out => vertex,
                    IoKind::InOut => true,
                };
                let scope = if varying { Scope::Group(group[e]) } else { Scope::Entry(e) };
                placed.push((scope, g, e));
            }
        }
        placed.sort_unstable();
        // Per scope, reused: the scope's globals, each once, with the
        // location each gets; (location, global) taken, at most
        // `MAX_LOCATIONS`.
        let mut globals: Vec<(GlobalId, Option<u32>)> = Vec::new();
        let mut taken: Vec<(u32, GlobalId)> = Vec::new();
        let mut start = 0;
        while start < placed.len() {
            let scope = placed[start].0;
            let end = start + placed[start..].iter().take_while(|p| p.0 == scope).count();
            let run = &placed[start..end];
            globals.clear();
            taken.clear();
            for &(_, g, _) in run {
                if globals.last().is_none_or(|&(last, _)| last != g) {
                    globals.push((g, None));
                }
            }
            for (g, at) in globals.iter_mut() {
                let g = *g;
                let GlobalKind::Io { kind, location: Some(l) } = self.out.globals[g].kind else { continue };
                if let Some(&(_, prev)) = taken.iter().find(|(at, _)| *at == l) {
                    let GlobalKind::Io { kind: prev_kind, .. } = self.out.globals[prev].kind else { continue };
                    let (a, b) = (&self.out.globals[prev].name, &self.out.globals[g].name);
                    let what = if prev_kind == kind {
                        format!("duplicate location {l} for `{}` variables `{a}` and `{b}`", qualifier(kind))
                    } else {
                        format!("duplicate location {l} for `{}` variable `{a}` and `{}` variable `{b}`", qualifier(prev_kind), qualifier(kind))
                    };
                    let span = self.location_spans.get(&g).copied().unwrap_or(self.out.globals[g].span);
                    let mut d = Diagnostic::error(format!("{what} in {}", self.scope_text(scope, group)), span).with_label(format!("`{b}` uses location {l}"));
                    if let Some(&p) = self.location_spans.get(&prev) {
                        d = d.with_secondary(p, format!("`{a}` uses it too"));
                    }
                    self.diags.push(d.with_note("locations are per program: give one of them another `@location = N`, or none to have one assigned"));
                    continue;
                }
                taken.push((l, g));
                *at = Some(l);
            }
            for (g, at) in globals.iter_mut() {
                let GlobalKind::Io { location: None, .. } = self.out.globals[*g].kind else { continue };
                let Some(l) = (0..MAX_LOCATIONS).find(|l| !taken.iter().any(|(at, _)| at == l)) else {
                    let msg = format!("no free location left (at most {MAX_LOCATIONS}) in {}", self.scope_text(scope, group));
                    self.diags.push(Diagnostic::error(msg, self.out.globals[*g].span));
                    break;
                };
                taken.push((l, *g));
                *at = Some(l);
            }
            for &(_, g, e) in run {
                let at = globals.binary_search_by_key(&g, |&(g, _)| g).ok().and_then(|i| globals[i].1);
                if let Some(l) = at {
                    self.out.entry_points[e].locations.push((g, l));
                }
            }
            start = end;
        }
        for ep in &mut self.out.entry_points {
            ep.locations.sort_unstable();
        }
    }

    fn number_texture_units(&mut self, links: &[Link]) {
        // The programs and the entry points, each with the samplers it uses.
        let eps = &self.out.entry_points;
        let samplers_of = |e: usize| eps[e].func.uses.keys().copied().filter(|&g| matches!(self.out.globals[g].kind, GlobalKind::Sampler { .. }));
        // Each scope is a program (`Some(link)`) or an entry point; it is
        // described only in an error.
        let mut scopes: Vec<(Result<&Link, usize>, Vec<GlobalId>)> = Vec::new();
        for l in links {
            let mut s: Vec<GlobalId> = samplers_of(l.vertex).chain(samplers_of(l.fragment)).collect();
            s.sort_unstable();
            s.dedup();
            scopes.push((Ok(l), s));
        }
        for e in 0..eps.len() {
            scopes.push((Err(e), samplers_of(e).collect()));
        }
        let describe = |scope: &Result<&Link, usize>| match scope {
            Ok(l) => format!("the program of vertex entry point `{}` and fragment entry point `{}`", eps[l.vertex].name, eps[l.fragment].name),
            Err(e) => format!("{} entry point `{}`", stage_name(eps[*e].stage), eps[*e].name),
        };
        let range = |g: GlobalId, globals: &[Global]| match globals[g].kind {
            GlobalKind::Sampler { texture_unit, count, .. } => texture_unit..texture_unit + count.unwrap_or(1),
            _ => 0..0,
        };
        // Units written in the source: clashes.
        let mut reported: FxHashSet<(GlobalId, GlobalId)> = FxHashSet::default();
        // Per scope, bit `u` for each texture unit taken (units 0..32).
        let mut taken: Vec<u32> = vec![0; scopes.len()];
        for (k, (what, samplers)) in scopes.iter().enumerate() {
            let explicit: Vec<GlobalId> = samplers.iter().copied().filter(|g| self.unit_spans.contains_key(g)).collect();
            for (i, &b) in explicit.iter().enumerate() {
                let rb = range(b, &self.out.globals);
                taken[k] |= unit_mask(rb.start as usize, rb.len());
                for &a in &explicit[..i] {
                    let ra = range(a, &self.out.globals);
                    let Some(u) = rb.clone().find(|u| ra.contains(u)) else { continue };
                    if !reported.insert((a, b)) {
                        continue;
                    }
                    let (an, bn) = (&self.out.globals[a].name, &self.out.globals[b].name);
                    let d = Diagnostic::error(format!("texture unit {u} is used twice in {}", describe(what)), self.unit_spans[&b])
                        .with_label(format!("`{bn}` is on unit {u}"))
                        .with_secondary(self.unit_spans[&a], format!("`{an}` is on it too"))
                        .with_note("texture units are per program: give one of them another `@stage = N`, or none to have one assigned");
                    self.diags.push(d);
                }
            }
        }
        // The others: the lowest units free wherever the sampler is used.
        let mut used = vec![false; self.out.globals.len()];
        for &g in scopes.iter().flat_map(|s| &s.1) {
            used[g] = true;
        }
        let mut homes: Vec<usize> = Vec::new();
        for g in 0..self.out.globals.len() {
            let GlobalKind::Sampler { count, .. } = self.out.globals[g].kind else { continue };
            if !used[g] || self.unit_spans.contains_key(&g) {
                continue;
            }
            let count = count.unwrap_or(1) as usize;
            homes.clear();
            homes.extend((0..scopes.len()).filter(|&k| scopes[k].1.contains(&g)));
            let free = |u: usize| count <= 32 && homes.iter().all(|&k| taken[k] & unit_mask(u, count) == 0);
            let Some(unit) = (0..=32 - count.min(32)).find(|&u| free(u)) else {
                let msg = match count {
                    33.. => format!("`{}` needs {count} texture units; a program has at most 32", self.out.globals[g].name),
                    2.. => format!("no {count} consecutive free texture units left (at most 32)"),
                    _ => "no free texture unit left (at most 32)".to_string(),
                };
                self.diags.push(Diagnostic::error(msg, self.out.globals[g].span));
                continue;
            };
            for &k in &homes {
                taken[k] |= unit_mask(unit, count);
            }
            if let GlobalKind::Sampler { texture_unit, .. } = &mut self.out.globals[g].kind {
                *texture_unit = unit as u32;
            }
        }
    }
}

/// The bits of texture units `first..first + count` (within 0..32).
fn unit_mask(first: usize, count: usize) -> u32 {
    let bits = if count >= 32 { u32::MAX } else { (1u32 << count) - 1 };
    bits.checked_shl(first as u32).unwrap_or(0)
}

/// `a`, `a and b`, `a, b and c`.
fn join_and(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}
