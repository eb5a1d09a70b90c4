//! The file level of cpfg's grammar (`lsys_input.y`, `Lsystem`, `Header`,
//! `Items`, `Production`): header lines, productions, the decomposition
//! and homomorphism sections and `endlsystem`.

use super::expr::{describe, Cur, Tok};
use super::preprocess::{preprocess, Preprocessed};
use super::{Array, Cpfg, Expr, Group, Module, Pattern, Production};
use crate::core::{Diagnostic, ParseError};
use std::collections::BTreeMap;

/// Largest array accepted (elements), so a declaration cannot exhaust memory.
pub(crate) const MAX_ARRAY_ELEMENTS: usize = 1 << 20;

/// Parses a cpfg L-system with no files beside it.
pub fn parse(source: &[u8]) -> Result<Cpfg, ParseError> {
    parse_with(source, &BTreeMap::new(), &[])
}

/// Parses a cpfg L-system, resolving `#include` against `files`, with
/// macros predefined (the view's function names, as cpfg passes `-D`).
pub(crate) fn parse_with(source: &[u8], files: &BTreeMap<String, Vec<u8>>, predefined: &[(String, String)]) -> Result<Cpfg, ParseError> {
    let pp = preprocess(source, files, predefined)?;
    parse_text(&pp)
}

#[derive(PartialEq, Clone, Copy)]
enum Section {
    Header,
    Productions,
    Decomposition,
    Homomorphism,
    Done,
}

/// Header keywords, lower case, longest first where one begins another.
const KEYWORDS: &[&str] = &[
    "lsystem:",
    "seed:",
    "derivation length:",
    "derivationlength:",
    "maximum depth:",
    "consider:",
    "ignore:",
    "axiom:",
    "define:",
    "ring lsystem",
    "starteach:",
    "start each:",
    "start:",
    "endeach:",
    "end each:",
    "endlsystem",
    "end:",
    "homomorphism",
    "decomposition",
];

fn parse_text(pp: &Preprocessed) -> Result<Cpfg, ParseError> {
    let mut cur = Cur::new(pp);
    let mut sys = Cpfg { homomorphism: Group { depth: 1, ..Default::default() }, decomposition: Group { depth: 1, ..Default::default() }, ..Default::default() };
    let mut section = Section::Header;
    let mut seen_lsystem = false;
    loop {
        while cur.peek().is_some() && cur.at_eol() {
            cur.i += 1;
        }
        if cur.peek().is_none() {
            break;
        }
        let start = cur.i;
        let kw = keyword(&cur);
        if section == Section::Done {
            if kw == Some("lsystem:") {
                sys.warnings.push(Diagnostic::warning(cur.span(), "only the first L-system of the file is read; sub-L-systems are not supported"));
                break;
            }
            return cur.err("text after endlsystem");
        }
        if let Some(k) = kw {
            cur.i += k.chars().count();
            match k {
                "lsystem:" => {
                    if seen_lsystem {
                        return cur.err_at(start, "a second `Lsystem:` before `endlsystem`");
                    }
                    seen_lsystem = true;
                    cur.next_line();
                    continue;
                }
                "seed:" | "derivation length:" | "derivationlength:" | "maximum depth:" => {
                    let v = constant(&mut cur)?;
                    let v = v.ok_or_else(|| ParseError::single(cur.span_at(start), format!("{k} needs a number")))?;
                    match (k, section) {
                        ("seed:", Section::Homomorphism) => sys.homomorphism.seed = Some(v as i64),
                        ("seed:", _) => sys.seed = Some(v as i64),
                        ("maximum depth:", Section::Homomorphism) => sys.homomorphism.depth = non_negative(&cur, start, v)?,
                        ("maximum depth:", Section::Decomposition) => sys.decomposition.depth = non_negative(&cur, start, v)?,
                        ("maximum depth:", _) => return cur.err_at(start, "maximum depth: belongs after homomorphism or decomposition"),
                        _ => sys.derivation_length = Some(non_negative(&cur, start, v)?),
                    }
                }
                "consider:" | "ignore:" => {
                    let mut syms = Vec::new();
                    while !cur.at_eol() {
                        if let Some(ch) = cur.peek() {
                            syms.push(ch);
                        }
                        cur.i += 1;
                    }
                    if k == "ignore:" {
                        sys.ignore.extend(syms);
                    } else {
                        sys.consider.get_or_insert_with(Vec::new).extend(syms);
                    }
                }
                "axiom:" => {
                    cur.names.global_mode = true;
                    sys.axiom = modules(&mut cur)?;
                    cur.names.global_mode = false;
                    if sys.axiom.is_empty() {
                        return cur.err_at(start, "the axiom cannot be blank");
                    }
                    section = Section::Productions;
                }
                "define:" => define(&mut cur, &mut sys)?,
                "ring lsystem" => sys.ring = true,
                "start:" | "end:" | "starteach:" | "start each:" | "endeach:" | "end each:" => {
                    cur.names.global_mode = true;
                    cur.blanks();
                    let b = cur.block()?;
                    cur.names.global_mode = false;
                    match k {
                        "start:" => sys.start = b,
                        "end:" => sys.end = b,
                        "starteach:" | "start each:" => sys.start_each = b,
                        _ => sys.end_each = b,
                    }
                    cur.eat(";")?;
                }
                "homomorphism" | "decomposition" => {
                    cur.eat(":")?;
                    // `warnings` / `no warnings` only choose cpfg's console messages.
                    cur.next_line();
                    section = if k == "homomorphism" { Section::Homomorphism } else { Section::Decomposition };
                    continue;
                }
                _ => {
                    // endlsystem
                    section = Section::Done;
                    cur.next_line();
                    continue;
                }
            }
            if !cur.at_eol() {
                return cur.err(format!("unexpected text after `{}`", k.trim_end_matches(':')));
            }
            continue;
        }
        if section == Section::Header {
            return cur.err("expected a header line such as `Lsystem:`, `derivation length:` or `Axiom:` before the productions");
        }
        let p = production(&mut cur, &sys)?;
        match section {
            Section::Decomposition => sys.decomposition.productions.push(p),
            Section::Homomorphism => sys.homomorphism.productions.push(p),
            _ => sys.productions.push(p),
        }
    }
    if sys.axiom.is_empty() {
        return cur.err_at(0, "the L-system has no `Axiom:`");
    }
    sys.globals = std::mem::take(&mut cur.names.globals);
    sys.block_locals = cur.names.locals.len() as u32;
    Ok(sys)
}

fn non_negative(cur: &Cur<'_>, at: usize, v: f64) -> Result<u32, ParseError> {
    if !(0.0..=u32::MAX as f64).contains(&v) || !v.is_finite() {
        return cur.err_at(at, format!("expected a whole number ≥ 0, got {v}"));
    }
    Ok(v as u32)
}

/// The header keyword at the cursor, if any (case-insensitively; cpfg
/// accepts an upper- or lower-case first letter).
fn keyword(cur: &Cur<'_>) -> Option<&'static str> {
    let ahead: String = cur.c[cur.i..(cur.i + 20).min(cur.c.len())].iter().collect::<String>().to_lowercase();
    KEYWORDS.iter().copied().find(|k| ahead.starts_with(k))
}

/// A constant expression (defines already expanded), evaluated now as cpfg
/// does (`Eval($2)` in the grammar's actions).
fn constant(cur: &mut Cur<'_>) -> Result<Option<f64>, ParseError> {
    cur.names.global_mode = true;
    let at = cur.i;
    let e = cur.expr()?;
    cur.names.global_mode = false;
    let v = super::pure::constant(&e).ok_or_else(|| ParseError::single(cur.span_at(at), "expected a constant (numbers and #define names only)"))?;
    Ok(Some(v))
}

/// `define: { array a[2,3] = {…}, b[4]; }` (manual §2.2.2).
fn define(cur: &mut Cur<'_>, sys: &mut Cpfg) -> Result<(), ParseError> {
    cur.blanks();
    cur.expect("{")?;
    cur.braces += 1;
    loop {
        if cur.eat("}")? {
            break;
        }
        if cur.eat(";")? {
            continue;
        }
        let at = cur.i;
        match cur.tok()? {
            Tok::Name(n) if n == "array" => {}
            Tok::Name(n) if n == "external" => return cur.err_at(at, "external arrays are not supported"),
            t => return cur.err_at(at, format!("expected `array`, found {}", describe(&t))),
        }
        loop {
            let at = cur.i;
            let Tok::Name(name) = cur.tok()? else { return cur.err_at(at, "expected an array name") };
            let mut dims = Vec::new();
            while cur.eat("[")? {
                loop {
                    let e = cur.expr()?;
                    let v = super::pure::constant(&e).filter(|v| *v >= 1.0 && v.is_finite()).ok_or_else(|| ParseError::single(cur.span_at(at), "an array dimension must be a constant ≥ 1"))?;
                    dims.push(v as usize);
                    if !cur.eat(",")? {
                        break;
                    }
                }
                cur.expect("]")?;
            }
            let size = dims.iter().try_fold(1usize, |a, &d| a.checked_mul(d)).filter(|&s| s <= MAX_ARRAY_ELEMENTS);
            let Some(size) = size.filter(|_| !dims.is_empty()) else { return cur.err_at(at, format!("array `{name}` needs dimensions with at most {MAX_ARRAY_ELEMENTS} elements")) };
            let mut init = Vec::new();
            if cur.eat("=")? {
                cur.expect("{")?;
                loop {
                    let e = cur.expr()?;
                    init.push(super::pure::constant(&e).ok_or_else(|| ParseError::single(cur.span_at(at), "array values must be constants"))?);
                    if !cur.eat(",")? {
                        break;
                    }
                }
                cur.expect("}")?;
                if init.len() > size {
                    return cur.err_at(at, format!("array `{name}` has {size} elements but {} values", init.len()));
                }
            }
            cur.names.arrays.push(name.clone());
            sys.arrays.push(Array { name, dims, init });
            if !cur.eat(",")? {
                break;
            }
        }
        cur.expect(";")?;
    }
    cur.braces -= 1;
    Ok(())
}

/// Modules with argument expressions up to the end of the line or a `:`
/// (an axiom or successor; `*` alone is the empty string).
fn modules(cur: &mut Cur<'_>) -> Result<Vec<Module>, ParseError> {
    let mut out = Vec::new();
    loop {
        cur.blanks();
        let Some(ch) = cur.peek() else { break };
        if ch == '\n' || ch == ':' {
            break;
        }
        if ch == '*' {
            cur.i += 1;
            continue;
        }
        if ch == '(' {
            return cur.err("`(` without a module before it");
        }
        let span = cur.span();
        cur.i += 1;
        let mut args = Vec::new();
        cur.blanks();
        if cur.peek() == Some('(') {
            cur.i += 1;
            if !cur.eat(")")? {
                loop {
                    args.push(cur.expr()?);
                    if cur.eat(")")? {
                        break;
                    }
                    cur.expect(",")?;
                }
            }
        }
        out.push(Module { sym: ch, args, span });
    }
    Ok(out)
}

/// Formal modules up to a separator (`<`, `>`, `:`, `-->`).
fn patterns(cur: &mut Cur<'_>) -> Result<Vec<Pattern>, ParseError> {
    let mut out = Vec::new();
    loop {
        cur.blanks();
        let Some(ch) = cur.peek() else { return cur.err("a production ends before `-->`") };
        if ch == '\n' {
            return cur.err("a production needs `-->` on its line");
        }
        if ch == '<' || ch == '>' || ch == ':' || cur.at("-->") || cur.at("-o>") {
            break;
        }
        if ch == '*' {
            cur.i += 1;
            continue;
        }
        if ch == '(' || ch == ')' {
            return cur.err(format!("unexpected `{ch}` in a predecessor"));
        }
        cur.i += 1;
        let mut params = Vec::new();
        cur.blanks();
        if cur.peek() == Some('(') {
            cur.i += 1;
            loop {
                let at = cur.i;
                match cur.tok()? {
                    Tok::Name(n) => {
                        cur.names.locals.push(n);
                        params.push(cur.names.locals.len() as u32 - 1);
                    }
                    t => return cur.err_at(at, format!("a formal parameter must be a name, found {}", describe(&t))),
                }
                if cur.eat(")")? {
                    break;
                }
                cur.expect(",")?;
            }
        }
        out.push(Pattern { sym: ch, params });
    }
    Ok(out)
}

/// One production (`lsys_input.y`, `Production`).
fn production(cur: &mut Cur<'_>, sys: &Cpfg) -> Result<Production, ParseError> {
    let span = cur.span();
    let start = cur.i;
    cur.names.locals.clear();
    cur.names.global_mode = false;
    let _ = sys;
    let first = patterns(cur)?;
    let (mut left, mut pred, mut right) = (Vec::new(), first, Vec::new());
    if cur.peek() == Some('<') {
        cur.i += 1;
        left = std::mem::take(&mut pred);
        pred = patterns(cur)?;
    }
    if cur.peek() == Some('>') {
        cur.i += 1;
        right = patterns(cur)?;
    }
    if pred.is_empty() {
        return cur.err_at(start, "a production needs a predecessor");
    }
    let (mut pre, mut cond, mut post) = (Vec::new(), None, Vec::new());
    if cur.peek() == Some(':') {
        cur.i += 1;
        cur.blanks();
        if cur.peek() == Some('{') {
            pre = cur.block()?;
            cur.blanks();
        }
        if cur.peek() == Some('*') {
            cur.i += 1;
        } else if !cur.at("-->") && !cur.at("-o>") && cur.peek() != Some('{') {
            cond = Some(cur.expr()?);
        }
        cur.blanks();
        if cur.peek() == Some('{') {
            post = cur.block()?;
        }
    }
    cur.blanks();
    if cur.at("-o>") {
        return cur.err("the `-o>` (rayshade object) production is no longer supported by cpfg");
    }
    if !cur.at("-->") {
        return match cur.peek() {
            Some('\n') | None => cur.err("a production needs `-->`"),
            Some(ch) => cur.err(format!("expected `-->`, found `{ch}`")),
        };
    }
    cur.i += 3;
    let succ = modules(cur)?;
    let mut prob = None;
    if cur.peek() == Some(':') {
        cur.i += 1;
        prob = Some(cur.expr()?);
    }
    if !cur.at_eol() {
        return cur.err("unexpected text after the production");
    }
    let prob = prob.or_else(|| sys.seed.map(|_| Expr::Num(1.0)));
    Ok(Production { left, pred, right, pre, cond, post, succ, prob, locals: cur.names.locals.len() as u32, span })
}
