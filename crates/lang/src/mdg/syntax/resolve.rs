//! Name resolution at the end of the file, and the [`Program`] it yields.
//!
//! A rule may be called before it is defined, so while parsing, calls,
//! transform-rule paths, line profiles, `linerule`, `camerarule` and
//! `selector` names are only recorded (with the namespace they are written
//! in). Once every rule is known, `Parser::finish` resolves them in a fixed
//! order (call sites in increasing order, for a stable first error), fills the
//! targets into the rule bodies and assembles the program. Namespace
//! bookkeeping lives here too, since it exists only to resolve names.

use super::{err, GroupRef, PResult, Parser, PendingSelector};
use crate::ir::{GroupId, Item, Namespaces, PrimitiveKind, Program, RuleTransform, Selector, Target};
use crate::core::Span;

impl<'a> Parser<'a> {
    /// Resolves the names recorded while parsing and assembles the program.
    pub(super) fn finish(mut self) -> PResult<Program> {
        self.declare_named_solids()?;
        let start = match self.startshape {
            Some((name, span)) => self.resolve(name, span)?,
            // Thesis listings without `startshape` (C.4) start from `START`.
            None if self.group_index.contains_key("START") => Target::Group(self.group_index["START"]),
            None if !self.groups.is_empty() => Target::Group(0),
            None => {
                let span = self.peek().span;
                return Err(err(span, "no rules: expected at least one `rule` or a `startshape`"));
            }
        };
        // Resolve call targets, in site order for a stable first error.
        let mut targets: Vec<Option<Target>> = vec![None; self.site as usize];
        for &(site, name, span, ns) in &self.call_names {
            if let Some(slot) = targets.get_mut(site as usize) {
                *slot = Some(self.resolve_in(ns, name, span)?);
            }
        }
        let mut groups = std::mem::take(&mut self.groups);
        let group_of = |ns: Option<&str>, name: &str, span: Span| match self.group_in(ns, name) {
            Some(g) => Ok(g),
            None => Err(err(span, format!("unknown rule `{name}`"))),
        };
        let mut profiles: Vec<Option<GroupId>> = vec![None; self.site as usize];
        for &(r, name, span, ns) in &self.group_refs {
            let g = group_of(ns, name, span)?;
            match r {
                GroupRef::Path { group, rule, index } => {
                    let slot = groups
                        .get_mut(group as usize)
                        .and_then(|gr| gr.rules.get_mut(rule))
                        .and_then(|ru| match &mut ru.transform {
                            RuleTransform::Convolve(v) | RuleTransform::Animate(v) => v.get_mut(index),
                            RuleTransform::None => None,
                        });
                    if let Some(slot) = slot {
                        *slot = g;
                    }
                }
                GroupRef::Profile { site } => {
                    if let Some(slot) = profiles.get_mut(site as usize) {
                        *slot = Some(g);
                    }
                }
            }
        }
        let linerule = self.linerule.map(|(name, span)| group_of(None, name, span)).transpose()?;
        let camerarule = self.camerarule.map(|(name, span)| group_of(None, name, span)).transpose()?;
        self.directives.linerule = linerule;
        self.directives.camerarule = camerarule;
        let lens = self.directives.camera;
        if lens.far <= lens.near {
            return Err(err(Span::new(1, 1), format!("camerafarplane ({}) must be beyond cameranearplane ({})", lens.far, lens.near)));
        }
        for (name, span, pending) in std::mem::take(&mut self.selectors) {
            let selector = match pending {
                PendingSelector::Ready(s) => s,
                PendingSelector::Named(f, fspan) => match self.functions.get(f) {
                    Some(e) => Selector::Function(e.clone()),
                    None => return Err(err(fspan, format!("unknown function `{f}`"))),
                },
            };
            match self.group_index.get(name).and_then(|&g| groups.get_mut(g as usize)) {
                Some(g) => g.selector = selector,
                None => return Err(err(span, format!("selector names `{name}`, which has no rules"))),
            }
        }
        for g in &mut groups {
            for r in &mut g.rules {
                set_targets(&mut r.body, &targets, &profiles);
            }
        }
        Ok(Program {
            start,
            groups,
            directives: self.directives,
            params: self.params,
            site_count: self.site,
            warnings: self.warnings,
            isosurfaces: self.isosurfaces,
            namespaces: namespace_table(self.namespace_names, &self.site_namespace, self.site),
            meshes: self.meshes,
        })
    }

    /// The group `name` names when written in namespace `ns`: `ns.name`
    /// first, then the global `name` (a qualified `a.B` is looked up as is).
    fn group_in(&self, ns: Option<&str>, name: &str) -> Option<u32> {
        if let Some(ns) = ns.filter(|_| !name.contains('.')) {
            if let Some(&g) = self.group_index.get(&format!("{ns}.{name}")) {
                return Some(g);
            }
        }
        self.group_index.get(name).copied()
    }

    /// [`Self::resolve`] for a call written in namespace `ns`.
    fn resolve_in(&self, ns: Option<&str>, name: &str, span: Span) -> PResult<Target> {
        match self.group_in(ns, name) {
            Some(g) => Ok(Target::Group(g)),
            None => self.resolve(name, span),
        }
    }

    /// The index of namespace `name` (declared or only referenced, as `X.LINETO` may).
    pub(super) fn namespace_id(&mut self, name: &str, span: Span) -> PResult<u32> {
        if let Some(i) = self.namespace_names.iter().position(|n| n == name) {
            return Ok(i as u32);
        }
        let i = u32::try_from(self.namespace_names.len()).map_err(|_| err(span, "too many namespaces"))?;
        self.namespace_names.push(name.to_string());
        Ok(i)
    }

    fn resolve(&self, name: &str, span: Span) -> PResult<Target> {
        if let Some(&g) = self.group_index.get(name) {
            return Ok(Target::Group(g));
        }
        if let Some(&i) = self.isosurface_index.get(name) {
            return Ok(Target::Isosurface(i));
        }
        if let Some(&i) = self.mesh_index.get(name) {
            return Ok(Target::Mesh(i));
        }
        if let Some(k) = PrimitiveKind::from_keyword(name) {
            return Ok(Target::Primitive(k));
        }
        Err(err(span, format!("unknown rule or primitive `{name}`")))
    }
}

/// Fills in resolved call targets (recursion bounded by the nesting limit).
fn set_targets(items: &mut [Item], targets: &[Option<Target>], profiles: &[Option<GroupId>]) {
    for item in items {
        match item {
            Item::Call(c) => {
                if let Some(Some(t)) = targets.get(c.site as usize) {
                    c.target = *t;
                }
                if let (Target::Line(op, _), Some(Some(g))) = (c.target, profiles.get(c.site as usize)) {
                    c.target = Target::Line(op, Some(*g));
                }
            }
            Item::Block(b) => set_targets(b, targets, profiles),
            Item::Iterate(it) => set_targets(std::slice::from_mut(&mut *it.body), targets, profiles),
        }
    }
}

/// The program's namespace table: names, and each call site's namespace
/// (left empty when the source declares and references no namespace).
fn namespace_table(names: Vec<String>, site_namespace: &[(u32, u32)], sites: u32) -> Namespaces {
    if names.len() <= 1 {
        return Namespaces::default();
    }
    let mut of_site = vec![0; sites as usize];
    for &(site, ns) in site_namespace {
        if let Some(slot) = of_site.get_mut(site as usize) {
            *slot = ns;
        }
    }
    Namespaces { names, of_site }
}
