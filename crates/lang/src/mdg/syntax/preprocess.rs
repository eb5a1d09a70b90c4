//! The MDG preprocessor (Andersson 2015, Table B.2): conditionals, macros and
//! skipped blocks. It works line by line on already-validated UTF-8 text and
//! produces the text the lexer sees plus a map from output lines back to
//! source positions.
//!
//! `@define` and `@param` lines are passed through unchanged (the parser reads
//! them, because their values are expressions); the preprocessor only records
//! their names so that `@ifdef` can test them.

use crate::core::{Diagnostic, ParseError, Span};
use std::collections::{HashMap, HashSet};

/// Maximum nesting of `@expand` inside macro bodies.
pub(crate) const MAX_EXPAND_DEPTH: usize = 16;

/// How the columns of one output line map back to the source.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColMap {
    /// Source column = output column + shift.
    Shift(u32),
    /// Every column maps to this source column (text produced by a macro expansion).
    Fixed(u32),
}

/// Where one output line came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Origin {
    /// 1-based source line.
    pub line: u32,
    /// Column mapping.
    pub col: ColMap,
}

/// The preprocessed text.
#[derive(Debug, Clone, Default)]
pub struct Preprocessed {
    /// Text for the lexer, one output line per entry of `lines`, separated by `\n`.
    pub text: String,
    /// Origin of each output line (0-based index = output line).
    pub lines: Vec<Origin>,
    /// Non-fatal diagnostics.
    pub warnings: Vec<Diagnostic>,
}

impl Preprocessed {
    /// Maps a 0-based output line and 1-based output column to a source span.
    pub fn span(&self, out_line: usize, out_col: u32) -> Span {
        match self.lines.get(out_line) {
            Some(Origin { line, col: ColMap::Shift(s) }) => Span::new(*line, out_col.saturating_add(*s)),
            Some(Origin { line, col: ColMap::Fixed(c) }) => Span::new(*line, *c),
            None => match self.lines.last() {
                Some(o) => Span::new(o.line, 1),
                None => Span::new(1, 1),
            },
        }
    }
}

struct Macro {
    params: Vec<String>,
    body: Vec<String>,
}

struct State {
    /// Built-in grammars being imported, outermost first (cycle detection).
    imports: Vec<String>,
    names: HashSet<String>,
    macros: HashMap<String, Macro>,
    out: Preprocessed,
    limit: usize,
}

/// One frame of conditional compilation.
struct Cond {
    /// Whether the enclosing context is active.
    parent_active: bool,
    /// Whether the current branch is active.
    active: bool,
    /// Whether `@else` was seen.
    seen_else: bool,
    /// Where the `@ifdef` is.
    span: Span,
}

fn err(span: Span, msg: impl Into<String>) -> ParseError {
    ParseError::single(span, msg)
}

fn is_word_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_' || c == '.'
}

/// Runs the preprocessor over `text`.
pub fn preprocess(text: &str) -> Result<Preprocessed, ParseError> {
    let mut st = State {
        imports: Vec::new(),
        names: HashSet::new(),
        macros: HashMap::new(),
        out: Preprocessed::default(),
        limit: text.len().saturating_mul(4).saturating_add(64 * 1024),
    };
    let lines: Vec<(u32, ColMap, &str)> =
        text.split('\n').enumerate().map(|(i, l)| (line_no(i), ColMap::Shift(0), l)).collect();
    run(&mut st, &lines, 0)?;
    Ok(st.out)
}

fn line_no(i: usize) -> u32 {
    u32::try_from(i + 1).unwrap_or(u32::MAX)
}

/// Span of column `col` (1-based, in characters) of an input line.
fn at(line: u32, map: ColMap, col: u32) -> Span {
    match map {
        ColMap::Shift(s) => Span::new(line, col.saturating_add(s)),
        ColMap::Fixed(c) => Span::new(line, c),
    }
}

fn char_col(s: &str, byte: usize) -> u32 {
    u32::try_from(s.get(..byte).map_or(0, |p| p.chars().count()) + 1).unwrap_or(u32::MAX)
}

/// Scans a line for comment state: returns the byte index where a `//`
/// comment starts (if any, outside block comments) and whether a block
/// comment is open at the end of the line.
fn scan_comments(line: &str, mut in_block: bool) -> (Option<usize>, bool) {
    let b = line.as_bytes();
    let mut i = 0;
    while i < b.len() {
        if in_block {
            if b[i] == b'*' && b.get(i + 1) == Some(&b'/') {
                in_block = false;
                i += 2;
                continue;
            }
        } else if b[i] == b'/' && b.get(i + 1) == Some(&b'/') {
            return (Some(i), false);
        } else if b[i] == b'/' && b.get(i + 1) == Some(&b'*') {
            in_block = true;
            i += 2;
            continue;
        }
        i += 1;
    }
    (None, in_block)
}

fn emit(st: &mut State, line: u32, col: ColMap, text: &str, at_span: Span) -> Result<(), ParseError> {
    if !st.out.lines.is_empty() {
        st.out.text.push('\n');
    }
    st.out.text.push_str(text);
    st.out.lines.push(Origin { line, col });
    if st.out.text.len() > st.limit {
        return Err(err(at_span, "macro expansion too large"));
    }
    Ok(())
}

/// Processes `lines`; `depth` is the macro expansion depth.
fn run(st: &mut State, lines: &[(u32, ColMap, &str)], depth: usize) -> Result<(), ParseError> {
    let mut conds: Vec<Cond> = Vec::new();
    let mut in_block = false;
    let mut i = 0;
    while i < lines.len() {
        let (ln, map, raw) = lines[i];
        i += 1;
        let active = conds.last().map_or(true, |c| c.active);
        let starts_in_comment = in_block;
        let (comment_at, end_block) = scan_comments(raw, in_block);
        in_block = end_block;
        let code = &raw[..comment_at.unwrap_or(raw.len())];
        let trimmed = code.trim_start();
        let indent = code.len() - trimmed.len();
        if starts_in_comment || !trimmed.starts_with('@') {
            if active {
                expand_inline(st, ln, map, raw, comment_at, depth)?;
            } else {
                emit(st, ln, map, "", at(ln, map, 1))?;
            }
            continue;
        }
        let dspan = at(ln, map, char_col(raw, indent));
        let mut words = trimmed[1..].split_whitespace();
        let word = words.next().unwrap_or("");
        let directive = word
            .split(|c: char| !c.is_alphanumeric())
            .next()
            .unwrap_or("")
            .to_ascii_lowercase();
        // Conditionals are tracked even inside inactive branches.
        match directive.as_str() {
            "ifdef" | "ifndef" => {
                let name = words.next().ok_or_else(|| err(dspan, format!("expected a name after `@{directive}`")))?;
                let defined = st.names.contains(name);
                let want = if directive == "ifdef" { defined } else { !defined };
                conds.push(Cond { parent_active: active, active: active && want, seen_else: false, span: dspan });
                emit(st, ln, map, "", dspan)?;
                continue;
            }
            "else" => {
                let c = conds.last_mut().ok_or_else(|| err(dspan, "`@else` without `@ifdef`"))?;
                if c.seen_else {
                    return Err(err(dspan, "second `@else` for the same `@ifdef`"));
                }
                c.seen_else = true;
                c.active = c.parent_active && !c.active;
                emit(st, ln, map, "", dspan)?;
                continue;
            }
            "endif" => {
                conds.pop().ok_or_else(|| err(dspan, "`@endif` without `@ifdef`"))?;
                emit(st, ln, map, "", dspan)?;
                continue;
            }
            _ => {}
        }
        // Block directives consume lines up to their terminator, active or not.
        match directive.as_str() {
            "macro" => {
                let header = trimmed.get(1 + directive.len()..).unwrap_or("");
                let (name, params) = parse_macro_header(header.trim(), dspan)?;
                let mut body = Vec::new();
                let mut closed = false;
                emit(st, ln, map, "", dspan)?;
                while i < lines.len() {
                    let (l2, m2, r2) = lines[i];
                    i += 1;
                    let t = r2.trim_start();
                    if starts_with_ignore_case(t, "@endmacro") {
                        closed = true;
                        emit(st, l2, m2, "", dspan)?;
                        break;
                    }
                    body.push(r2.to_string());
                    emit(st, l2, m2, "", dspan)?;
                }
                if !closed {
                    return Err(err(dspan, format!("`@macro {name}` is not closed by `@endmacro`")));
                }
                if active {
                    st.macros.insert(name, Macro { params, body });
                }
                continue;
            }
            "fragmentshader" | "vertexshader" => {
                let mut closed = false;
                emit(st, ln, map, "", dspan)?;
                while i < lines.len() {
                    let (l2, m2, r2) = lines[i];
                    i += 1;
                    emit(st, l2, m2, "", dspan)?;
                    let t = r2.trim_start();
                    if starts_with_ignore_case(t, "@endshader") {
                        closed = true;
                        break;
                    }
                }
                if !closed {
                    return Err(err(dspan, format!("`@{directive}` is not closed by `@endshader`")));
                }
                if active {
                    st.out.warnings.push(Diagnostic::warning(dspan, format!("`@{directive}` ignored: shaders do not affect geometry")));
                }
                continue;
            }
            _ => {}
        }
        if !active {
            emit(st, ln, map, "", dspan)?;
            continue;
        }
        match directive.as_str() {
            "define" | "param" => {
                let name = if directive == "define" { words.next() } else { words.nth(1) };
                if let Some(n) = name {
                    st.names.insert(n.to_string());
                }
                // Passed through for the parser; columns stay exact.
                emit(st, ln, map, code, dspan)?;
            }
            "presets" => emit(st, ln, map, code, dspan)?,
            "import" => {
                emit(st, ln, map, "", dspan)?;
                let names: Vec<&str> = words.collect();
                if names.is_empty() {
                    return Err(err(dspan, "expected a built-in grammar name after `@import`"));
                }
                for name in names {
                    import(st, name, dspan, depth)?;
                }
            }
            "expand" => expand_inline(st, ln, map, raw, comment_at, depth)?,
            "endmacro" => return Err(err(dspan, "`@endmacro` without `@macro`")),
            "endshader" => return Err(err(dspan, "`@endshader` without a shader")),
            _ => return Err(err(dspan, format!("unknown preprocessor directive `@{word}`"))),
        }
    }
    if let Some(c) = conds.last() {
        return Err(err(c.span, "`@ifdef` is not closed by `@endif`"));
    }
    Ok(())
}

/// Most nested `@import`s (a grammar importing one that imports …).
pub(crate) const MAX_IMPORT_DEPTH: usize = 8;

/// `@import NAME`: the built-in grammar `grammars/NAME.mdg`, preprocessed in
/// place, without its `startshape` lines (the importer's start applies).
/// Only the embedded library can be imported, never a path: a request must
/// not read the server's files; any other name is ignored with a warning.
/// Every line it adds reports the `@import`'s position in errors.
fn import(st: &mut State, name: &str, span: Span, depth: usize) -> Result<(), ParseError> {
    let stem = name.strip_suffix(".mdg").unwrap_or(name);
    let builtin = (!stem.is_empty() && stem.chars().all(|c| c.is_alphanumeric() || c == '-' || c == '_'))
        .then(|| crate::core::library::source(stem, "mdg"))
        .flatten();
    let Some(source) = builtin else {
        // The thesis imports its own projects (C.5: `@import projects/basic-shaders`,
        // shader libraries): not geometry, and never read from disk here.
        st.out.warnings.push(Diagnostic::warning(
            span,
            format!("`@import {name}` ignored: only built-in grammars (GET /v1/grammars, e.g. `gem`) can be imported"),
        ));
        return Ok(());
    };
    if st.imports.iter().any(|i| i == stem) {
        return Err(err(span, format!("`@import {stem}` imports itself (through {})", st.imports.join(" → "))));
    }
    if st.imports.len() >= MAX_IMPORT_DEPTH {
        return Err(err(span, format!("imports nested deeper than {MAX_IMPORT_DEPTH}")));
    }
    let map = ColMap::Fixed(span.column);
    let lines: Vec<(u32, ColMap, &str)> = source
        .split('\n')
        .map(|l| {
            let starts = l.trim_start().get(..10).is_some_and(|w| w.eq_ignore_ascii_case("startshape"));
            (span.line, map, if starts { "" } else { l })
        })
        .collect();
    st.imports.push(stem.to_string());
    let result = run(st, &lines, depth);
    st.imports.pop();
    result
}

/// Whether `line` starts with the ASCII word `prefix`, ignoring case. Compares
/// bytes, so a multi-byte character straddling `prefix.len()` is simply not a
/// match (slicing the `str` there panicked: issue 17).
fn starts_with_ignore_case(line: &str, prefix: &str) -> bool {
    line.as_bytes().get(..prefix.len()).is_some_and(|b| b.eq_ignore_ascii_case(prefix.as_bytes()))
}

fn parse_macro_header(h: &str, span: Span) -> Result<(String, Vec<String>), ParseError> {
    let open = h.find('(');
    let name_end = open.unwrap_or(h.len());
    let name = h[..name_end].trim();
    if name.is_empty() || !name.chars().all(is_word_char) {
        return Err(err(span, "expected a macro name after `@macro`"));
    }
    let mut params = Vec::new();
    if let Some(o) = open {
        let rest = &h[o + 1..];
        let close = rest.find(')').ok_or_else(|| err(span, format!("expected `)` in `@macro {name}`")))?;
        if !rest[close + 1..].trim().is_empty() {
            return Err(err(span, format!("unexpected text after `@macro {name}(…)`")));
        }
        let inner = rest[..close].trim();
        if !inner.is_empty() {
            for p in inner.split(',') {
                let p = p.trim();
                if p.is_empty() || !p.chars().all(is_word_char) {
                    return Err(err(span, format!("bad parameter name `{p}` in `@macro {name}`")));
                }
                params.push(p.to_string());
            }
        }
    }
    Ok((name.to_string(), params))
}

/// Emits a code line, expanding every `@expand NAME(args)` in it (outside the
/// trailing `//` comment).
fn expand_inline(
    st: &mut State,
    ln: u32,
    map: ColMap,
    raw: &str,
    comment_at: Option<usize>,
    depth: usize,
) -> Result<(), ParseError> {
    let code_end = comment_at.unwrap_or(raw.len());
    let Some(pos) = find_expand(&raw[..code_end]) else {
        return emit(st, ln, map, raw, at(ln, map, 1));
    };
    let span = at(ln, map, char_col(raw, pos));
    if depth >= MAX_EXPAND_DEPTH {
        return Err(err(span, format!("macro expansion too large (nested deeper than {MAX_EXPAND_DEPTH})")));
    }
    // Text before the expansion keeps its columns.
    if !raw[..pos].trim().is_empty() {
        emit(st, ln, map, &raw[..pos], span)?;
    }
    let after = &raw[pos + "@expand".len()..code_end];
    let open = after.find('(');
    let name_part = &after[..open.unwrap_or(after.len())];
    let name = name_part.trim();
    if name.is_empty() || !name.chars().all(is_word_char) {
        return Err(err(span, "expected a macro name after `@expand`"));
    }
    let mut args: Vec<String> = Vec::new();
    let mut rest_start = pos + "@expand".len() + name_part.len();
    if let Some(o) = open {
        // Split arguments at top-level commas up to the matching `)`.
        let body = &after[o + 1..];
        let mut level = 0usize;
        let mut cur = String::new();
        let mut close = None;
        for (k, c) in body.char_indices() {
            match c {
                '(' => {
                    level += 1;
                    cur.push(c);
                }
                ')' if level == 0 => {
                    close = Some(k);
                    break;
                }
                ')' => {
                    level -= 1;
                    cur.push(c);
                }
                ',' if level == 0 => args.push(std::mem::take(&mut cur).trim().to_string()),
                _ => cur.push(c),
            }
        }
        let close = close.ok_or_else(|| err(span, format!("expected `)` to close `@expand {name}(`")))?;
        if !cur.trim().is_empty() || !args.is_empty() {
            args.push(cur.trim().to_string());
        }
        rest_start = pos + "@expand".len() + o + 1 + close + 1;
    }
    let mac = st.macros.get(name).ok_or_else(|| err(span, format!("unknown macro `{name}`")))?;
    if mac.params.len() != args.len() {
        return Err(err(
            span,
            format!("macro `{name}` takes {} argument(s), {} given", mac.params.len(), args.len()),
        ));
    }
    let mut expanded: Vec<String> = Vec::with_capacity(mac.body.len());
    let mut size = 0usize;
    for line in &mac.body {
        let s = substitute(line, &mac.params, &args);
        size = size.saturating_add(s.len() + 1);
        if st.out.text.len().saturating_add(size) > st.limit {
            return Err(err(span, "macro expansion too large"));
        }
        expanded.push(s);
    }
    let fixed = match map {
        ColMap::Fixed(c) => ColMap::Fixed(c),
        ColMap::Shift(_) => ColMap::Fixed(span.column),
    };
    let sub: Vec<(u32, ColMap, &str)> = expanded.iter().map(|l| (ln, fixed, l.as_str())).collect();
    run(st, &sub, depth + 1)?;
    // The rest of the line (after the closing parenthesis) keeps its columns.
    let rest = &raw[rest_start.min(raw.len())..];
    if !rest.trim().is_empty() {
        let shift = char_col(raw, rest_start.min(raw.len())) - 1;
        let m = match map {
            ColMap::Shift(s) => ColMap::Shift(s.saturating_add(shift)),
            f => f,
        };
        expand_inline(st, ln, m, rest, scan_comments(rest, false).0, depth)?;
    }
    Ok(())
}

fn find_expand(code: &str) -> Option<usize> {
    let mut from = 0;
    while let Some(k) = code[from..].find('@') {
        let p = from + k;
        let w = &code[p + 1..];
        if w.len() >= 6 && w.is_char_boundary(6) && w[..6].eq_ignore_ascii_case("expand") {
            let next = w[6..].chars().next();
            if next.map_or(true, |c| !is_word_char(c)) {
                return Some(p);
            }
        }
        from = p + 1;
    }
    None
}

/// Replaces whole-word occurrences of `params` in `line` with `args`.
fn substitute(line: &str, params: &[String], args: &[String]) -> String {
    if params.is_empty() {
        return line.to_string();
    }
    let mut out = String::with_capacity(line.len());
    let mut word_start: Option<usize> = None;
    let flush = |out: &mut String, w: &str| match params.iter().position(|p| p == w) {
        Some(k) => out.push_str(args.get(k).map_or("", String::as_str)),
        None => out.push_str(w),
    };
    for (k, c) in line.char_indices() {
        if is_word_char(c) {
            if word_start.is_none() {
                word_start = Some(k);
            }
        } else {
            if let Some(s) = word_start.take() {
                flush(&mut out, &line[s..k]);
            }
            out.push(c);
        }
    }
    if let Some(s) = word_start {
        flush(&mut out, &line[s..]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conditionals_keep_line_numbers() {
        let p = preprocess("@define A 1\n@ifdef A\nx\n@else\ny\n@endif\nz").unwrap();
        assert_eq!(p.text, "@define A 1\n\nx\n\n\n\nz");
        assert_eq!(p.lines.len(), 7);
        assert_eq!(p.span(6, 1), Span::new(7, 1));
    }

    #[test]
    fn macro_substitutes_whole_words() {
        let p = preprocess("@macro M(a, b)\nab a b {a}\n@endmacro\nq @expand M(1, (2+3)) r").unwrap();
        assert_eq!(p.text, "\n\n\nq \nab 1 (2+3) {1}\n r");
        // Expanded text points at the `@expand`.
        assert_eq!(p.span(4, 5), Span::new(4, 3));
        // Text after the expansion keeps its columns.
        assert_eq!(p.span(5, 2), Span::new(4, 23));
    }

    #[test]
    fn runaway_macros_are_bounded() {
        let e = preprocess("@macro M()\n@expand M()\n@endmacro\n@expand M()").unwrap_err();
        assert!(e.diagnostics[0].message.contains("macro expansion too large"));
        let mut src = String::from("@macro M0()\nxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx\n@endmacro\n");
        for k in 1..16 {
            src.push_str(&format!("@macro M{k}()\n@expand M{}()\n@expand M{}()\n@endmacro\n", k - 1, k - 1));
        }
        src.push_str("@expand M15()\n");
        let e = preprocess(&src).unwrap_err();
        assert_eq!(e.diagnostics[0].message, "macro expansion too large");
    }

    #[test]
    fn mdg_preprocessor_multibyte_macro_body() {
        // Issue 17: the ninth byte of a body line inside `é` panicked.
        let e = preprocess("@macro A()\nabcdefgh\u{e9}").unwrap_err();
        assert_eq!(e.diagnostics[0].message, "`@macro A` is not closed by `@endmacro`");
        assert_eq!(e.diagnostics[0].span, Span::new(1, 1));
        // The same for the shader blocks' ten-byte terminator.
        let e = preprocess("@fragmentshader\nabcdefghi\u{e9}").unwrap_err();
        assert_eq!(e.diagnostics[0].message, "`@fragmentshader` is not closed by `@endshader`");
        // And a closed macro whose body has such a line still works.
        let p = preprocess("@macro A()\nabcdefgh\u{e9}\n@ENDMACRO\nx").unwrap();
        assert_eq!(p.text, "\n\n\nx");
    }

    #[test]
    fn unclosed_ifdef_is_an_error() {
        let e = preprocess("\n  @ifdef X\nfoo").unwrap_err();
        assert_eq!(e.diagnostics[0].span, Span::new(2, 3));
    }
}
