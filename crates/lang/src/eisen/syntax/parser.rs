//! The parser proper: tokens → [`Script`]. It reads `rule` definitions and
//! their modifiers (`weight`, `maxdepth N > retirement`) and actions (any
//! run of `{ … }` blocks and `N * { … }` loops, then a name; or `set …`), records every call's target by name, and
//! resolves the names once the whole script is read, since a rule may be
//! called before it is defined. Transformation lists are parsed in
//! `transforms.rs` and `set` commands in `settings.rs`.

use super::tokens::{number, Token};
use super::{Action, GuiParam, Loop, Primitive, RuleDef, Script, Target};
use crate::core::{ParseError, Span};
use glam::DVec3;

#[path = "settings.rs"]
mod settings;
#[path = "transforms.rs"]
mod transforms;

use transforms::operator;

/// Primitives the JavaScript ports add (eisenscript.js's `src/Primitive.js`,
/// BrowserSynth's `scripts/eisenscript.js`): refused, with an error naming
/// where they come from, unless the script defines a rule of that name.
const PORT_PRIMITIVES: [&str; 25] = [
    "tube", "squash", "torus", "penta", "hexa", "fpenta", "fhexa", "fbox", "ftpenta", "fthexa", "ftbox", "tetra", "octa", "icosa", "cone",
    "pyra3", "pyra4", "frame", "crossframe", "straightrun", "cornerrun", "uprun", "csg", "ftsquare", "fsquare",
];

/// Parses the tokens of a preprocessed script; `params` are its GUI parameters.
pub(super) fn parse_tokens(tokens: Vec<Token>, params: Vec<GuiParam>) -> Result<Script, ParseError> {
    let mut p = Parser { tokens, pos: 0, script: Script { classes: vec![String::new()], params, ..Script::default() }, site: 0, pending: Vec::new() };
    p.program()?;
    p.resolve()?;
    Ok(p.script)
}

/// The parser's state: the tokens, the script built so far and the calls
/// whose targets are resolved at the end.
struct Parser {
    tokens: Vec<Token>,
    pos: usize,
    script: Script,
    site: u32,
    /// Unresolved targets: (rule index or None for top level, action index, name, span), and retirements.
    pending: Vec<Pending>,
}

struct Pending {
    /// `None` for a top-level action.
    rule: Option<usize>,
    /// Index of the action in its list; `None` for the rule's retirement target.
    action: Option<usize>,
    name: String,
    span: Span,
}

impl Parser {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.pos)
    }

    fn end_span(&self) -> Span {
        self.tokens.last().map_or(Span::new(1, 1), |t| t.span)
    }

    fn next(&mut self, what: &str) -> Result<Token, ParseError> {
        match self.tokens.get(self.pos) {
            Some(t) => {
                self.pos += 1;
                Ok(t.clone())
            }
            None => Err(ParseError::single(self.end_span(), format!("unexpected end of script: expected {what}"))),
        }
    }

    fn lower(&self) -> Option<String> {
        self.peek().map(|t| t.text.to_ascii_lowercase())
    }

    fn num(&mut self, what: &str) -> Result<f64, ParseError> {
        let t = self.next(what)?;
        number(&t.text).map(|(v, _)| v).ok_or_else(|| ParseError::single(t.span, format!("{what}: expected a number, found `{}`", t.text)))
    }

    fn program(&mut self) -> Result<(), ParseError> {
        while let Some(word) = self.lower() {
            if word == "rule" {
                self.rule()?;
            } else {
                let a = self.statement(None)?;
                self.script.top.push(a);
            }
        }
        Ok(())
    }

    fn rule(&mut self) -> Result<(), ParseError> {
        let start = self.next("rule")?.span;
        let name_tok = self.next("a rule name")?;
        let name = name_tok.text.to_ascii_lowercase();
        if name == "{" || operator(&name).is_some() || number(&name).is_some() {
            return Err(ParseError::single(name_tok.span, format!("expected a rule name after `rule`, found `{}`", name_tok.text)));
        }
        // `point` is eisenscript.js's word for `dot`, not a primitive of Structure
        // Synth (RuleSet.cpp:28-37), whose scripts may define a rule `point`.
        if (name != "point" && Primitive::from_name(&name).is_some()) || name.starts_with("triangle[") {
            return Err(ParseError::single(name_tok.span, format!("`{name}` is a built-in primitive and cannot be redefined")));
        }
        let id = self.name_id(&name);
        let index = self.script.rules.len();
        let mut def = RuleDef { name: id, weight: 1.0, maxdepth: None, retirement: None, actions: Vec::new(), span: start };
        loop {
            let Some(t) = self.peek().cloned() else {
                return Err(ParseError::single(self.end_span(), format!("rule `{name}`: expected `{{`")));
            };
            if t.text == "{" {
                self.pos += 1;
                break;
            }
            match operator(&t.text.to_ascii_lowercase()) {
                Some("weight") => {
                    self.pos += 1;
                    // Any number, negative too: Structure Synth checks none
                    // (EisenParser.cpp:73-79) and its draw (AmbiguousRule.cpp:26-44),
                    // followed in the builder, picks a definition whatever the signs.
                    def.weight = self.num("rule modifier `weight`")?;
                }
                Some("maxdepth") => {
                    self.pos += 1;
                    let n = self.next("a maxdepth")?;
                    match number(&n.text) {
                        Some((v, true)) => def.maxdepth = Some(v as i64),
                        _ => return Err(ParseError::single(n.span, format!("rule modifier `maxdepth` expects a whole number, found `{}`", n.text))),
                    }
                    if self.peek().is_some_and(|t| t.text == ">") {
                        self.pos += 1;
                        let r = self.next("a retirement rule name")?;
                        self.pending.push(Pending { rule: Some(index), action: None, name: r.text.to_ascii_lowercase(), span: r.span });
                    }
                }
                _ => {
                    return Err(ParseError::single(t.span, format!("rule `{name}`: expected `maxdepth`, `weight` or `{{`, found `{}`", t.text)));
                }
            }
        }
        self.script.rules.push(def);
        self.script.groups[id as usize].push(index as u32);
        loop {
            match self.peek() {
                None => return Err(ParseError::single(start, format!("rule `{name}` is not closed with `}}`"))),
                Some(t) if t.text == "}" => {
                    self.pos += 1;
                    break;
                }
                Some(t) if t.text.eq_ignore_ascii_case("rule") => {
                    return Err(ParseError::single(t.span, format!("rule `{name}` is not closed with `}}` before the next rule")));
                }
                Some(_) => {
                    let a = self.statement(Some(index))?;
                    self.script.rules[index].actions.push(a);
                }
            }
        }
        Ok(())
    }

    fn name_id(&mut self, name: &str) -> u32 {
        if let Some(i) = self.script.names.iter().position(|n| n == name) {
            return i as u32;
        }
        self.script.names.push(name.to_string());
        self.script.groups.push(Vec::new());
        (self.script.names.len() - 1) as u32
    }

    /// One `set` or action, inside rule `rule` (or at the top level).
    fn statement(&mut self, rule: Option<usize>) -> Result<Action, ParseError> {
        let first = self.peek().cloned().ok_or_else(|| ParseError::single(self.end_span(), "unexpected end of script"))?;
        if first.text.eq_ignore_ascii_case("set") {
            self.pos += 1;
            return self.set(first.span);
        }
        let mut loops = Vec::new();
        loop {
            let t = self.peek().cloned().ok_or_else(|| ParseError::single(self.end_span(), "unexpected end of script: expected a rule name"))?;
            if t.text == "{" {
                // `{ t }` is one loop of count 1 (Action.cpp:91-95). Structure
                // Synth wants a rule name right after it (EisenParser.cpp:270-274);
                // eisenscript.js reads an action as any run of blocks and loops
                // before the name (`{ y 5 } 6 * { rx 60 } orange`), which
                // Structure Synth refuses, so accepting it changes no script of its.
                let transform = self.transform_list()?;
                loops.push(Loop { count: 1, transform });
                continue;
            }
            if let Some((v, integer)) = number(&t.text) {
                // Any whole number (EisenParser.cpp:283-287). A count ≤ 0 makes
                // one copy, as 0 does: `Action::apply` checks its counters, which
                // start at 1, only after queuing a copy (Action.cpp:52-63), so
                // a negative count is read as 0.
                if !integer {
                    return Err(ParseError::single(t.span, format!("a loop count must be a whole number, found `{}`", t.text)));
                }
                self.pos += 1;
                let star = self.next("`*` after the loop count")?;
                if star.text != "*" {
                    return Err(ParseError::single(star.span, format!("expected `*` after the loop count, found `{}`", star.text)));
                }
                if self.peek().is_none_or(|t| t.text != "{") {
                    return Err(ParseError::single(star.span, "expected `{` after `*`"));
                }
                let transform = self.transform_list()?;
                loops.push(Loop { count: v.clamp(0.0, f64::from(u32::MAX)) as u32, transform });
                continue;
            }
            if t.text == "}" || t.text == "*" || t.text == ">" || operator(&t.text.to_ascii_lowercase()).is_some() {
                let message = if loops.is_empty() {
                    format!("an action must start with a number, a rule name or `{{`, found `{}`", t.text)
                } else {
                    format!("expected a rule name (or another loop) after the transformation list, found `{}`", t.text)
                };
                return Err(ParseError::single(t.span, message));
            }
            self.pos += 1;
            let mut t = t;
            // eisenscript.js also writes `triangle [x,y,z;…]` with a space, which
            // Structure Synth cannot resolve (RuleSet.cpp:151-180): joined.
            if t.text.eq_ignore_ascii_case("triangle") && self.peek().is_some_and(|n| n.text.starts_with('[')) {
                if let Some(corners) = self.tokens.get(self.pos).map(|n| n.text.clone()) {
                    self.pos += 1;
                    t.text.push_str(&corners);
                }
            }
            return self.call(rule, loops, t, first.span);
        }
    }

    fn call(&mut self, rule: Option<usize>, loops: Vec<Loop>, name: Token, span: Span) -> Result<Action, ParseError> {
        let lower = name.text.to_ascii_lowercase();
        if lower == "{" || lower == "}" || number(&lower).is_some() || operator(&lower).is_some() {
            return Err(ParseError::single(name.span, format!("expected a rule name, found `{}`", name.text)));
        }
        let action_index = match rule {
            Some(r) => self.script.rules[r].actions.len(),
            None => self.script.top.len(),
        };
        self.pending.push(Pending { rule, action: Some(action_index), name: lower, span: name.span });
        let site = self.site;
        self.site += 1;
        // The target is filled in by `resolve` once every rule is known.
        Ok(Action::Call { loops, target: Target::Rule(u32::MAX), site, span })
    }

    /// Fills in every call's target now that every rule name is known.
    fn resolve(&mut self) -> Result<(), ParseError> {
        let pending = std::mem::take(&mut self.pending);
        for p in pending {
            let target = self.target(&p.name, p.span)?;
            match (p.rule, p.action) {
                (Some(r), None) => self.script.rules[r].retirement = Some(target),
                (rule, Some(a)) => {
                    let list = match rule {
                        Some(r) => &mut self.script.rules[r].actions,
                        None => &mut self.script.top,
                    };
                    if let Some(Action::Call { target: t, .. }) = list.get_mut(a) {
                        *t = target;
                    }
                }
                (None, None) => {}
            }
        }
        Ok(())
    }

    fn class_id(&mut self, class: &str) -> u32 {
        if let Some(i) = self.script.classes.iter().position(|c| c == class) {
            return i as u32;
        }
        self.script.classes.push(class.to_string());
        (self.script.classes.len() - 1) as u32
    }

    fn target(&mut self, name: &str, span: Span) -> Result<Target, ParseError> {
        let (base, class) = match name.split_once("::") {
            Some((b, c)) => (b, c),
            None => (name, ""),
        };
        if let Some(inner) = base.strip_prefix("triangle[").and_then(|r| r.strip_suffix(']')) {
            let pts: Vec<Option<DVec3>> = inner
                .split(';')
                .map(|p| {
                    let v: Vec<f64> = p.split(',').filter_map(|x| number(x.trim()).map(|n| n.0)).collect();
                    (v.len() == 3 && p.split(',').count() == 3).then(|| DVec3::new(v[0], v[1], v[2]))
                })
                .collect();
            return match pts.as_slice() {
                [Some(a), Some(b), Some(c)] => Ok(Target::Triangle([*a, *b, *c], self.class_id(class))),
                _ => Err(ParseError::single(span, format!("`{name}`: a triangle needs three points `x,y,z` separated by `;`"))),
            };
        }
        // The script's own rules first: Structure Synth's primitives cannot be
        // redefined (see `rule`), so only the ports' names (`point`, `tube`, …)
        // can be both, and for those the script's rule is the one Structure Synth runs.
        let own = self.script.names.iter().position(|n| n == name).filter(|&i| !self.script.groups[i].is_empty());
        if let Some(i) = own {
            return Ok(Target::Rule(i as u32));
        }
        if let Some(p) = Primitive::from_name(base) {
            return Ok(Target::Primitive(p, self.class_id(class)));
        }
        if base == "triangle" {
            Err(ParseError::single(span, "`triangle` needs its corners: `triangle[x,y,z;x,y,z;x,y,z]`"))
        } else if PORT_PRIMITIVES.contains(&base) {
            Err(ParseError::single(
                span,
                format!("`{base}` is a primitive of a JavaScript port (eisenscript.js or BrowserSynth), not of Structure Synth; define `rule {base} {{ … }}` to draw it from Structure Synth's primitives"),
            ))
        } else {
            Err(ParseError::single(span, format!("no rule or primitive named `{name}`")))
        }
    }
}
