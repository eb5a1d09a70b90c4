//! The C preprocessor cpfg runs over an L-system before reading it.
//!
//! cpfg pipes every `.l` file through `vlabcpp`, a copy of GNU cccp
//! (`AlgorithmicBotany/vlab`, `vlabcpp/cccp.c`; `cpfg/utility.c`,
//! `PreprocessFile`), so models use `#define` constants and function-like
//! macros, `#include`, `#if`/`#ifdef`/`#else`/`#endif` and both comment
//! styles (cccp sets `cplusplus_comments` by default, `cccp.c` line 1305).
//! This is the part of cpp those models need, written by hand because no
//! maintained crate offers a C preprocessor over in-memory files without a
//! C toolchain: object-like and function-like macros (rescanned with the
//! macro being expanded hidden), `defined`, integer `#if` expressions,
//! backslash continuations, `#undef`, `#include "x"`/`<x>`.
//!
//! Files are never read from disk: `#include` resolves only against the
//! files sent with the request (by name, then by base name); the C headers
//! some models include out of habit (`math.h`, `stdio.h`, …) are empty.
//! Includes nest at most [`MAX_INCLUDE_DEPTH`] deep and a cycle is an
//! error; expansion is bounded by [`MAX_EXPANSION_DEPTH`] and the output by
//! [`MAX_OUTPUT_BYTES`], each a parse error naming the bound.

use super::cond::eval_condition;
use crate::core::{ParseError, Span};
use std::collections::{BTreeMap, HashMap};

/// Deepest `#include` nesting accepted.
pub(crate) const MAX_INCLUDE_DEPTH: usize = 16;
/// Deepest macro-within-macro expansion accepted.
pub(crate) const MAX_EXPANSION_DEPTH: usize = 64;
/// Largest preprocessed text accepted (macro bombs stop here).
pub(crate) const MAX_OUTPUT_BYTES: usize = 8 << 20;

/// Headers of the C library that models include without using; they are empty.
const SYSTEM_HEADERS: &[&str] = &["math.h", "stdio.h", "stdlib.h", "memory.h", "string.h"];

/// The directives cccp knows (`""`: a `#` alone); a line whose `#` starts
/// anything else (a width module `#(0.06)` at the start of a continued
/// production) is text.
const DIRECTIVES: &[&str] = &["define", "undef", "include", "if", "ifdef", "ifndef", "elif", "else", "endif", "error", "warning", "pragma", "line", "ident", ""];

/// The preprocessed text and, for every output line, where it came from.
#[derive(Debug, Clone, Default)]
pub struct Preprocessed {
    /// The text the L-system parser reads.
    pub text: String,
    /// Per output line (0-based), the file (index into `files`) and 1-based line.
    pub origins: Vec<(u16, u32)>,
    /// File names: 0 is the main source, then included files.
    pub files: Vec<String>,
}

impl Preprocessed {
    /// The source position of output line `line` (1-based) and column.
    pub fn span(&self, line: u32, column: u32) -> Span {
        match self.origins.get(line.saturating_sub(1) as usize) {
            Some(&(_, l)) => Span::new(l, column),
            None => Span::new(line, column),
        }
    }

    /// The file of output line `line` (1-based), when it is not the main source.
    pub(crate) fn included_file(&self, line: u32) -> Option<&str> {
        match self.origins.get(line.saturating_sub(1) as usize) {
            Some(&(f, _)) if f > 0 => self.files.get(f as usize).map(String::as_str),
            _ => None,
        }
    }
}

#[derive(Debug, Clone)]
struct Macro {
    params: Option<Vec<String>>,
    body: String,
}

struct Pp<'a> {
    files: &'a BTreeMap<String, Vec<u8>>,
    macros: HashMap<String, Macro>,
    out: Preprocessed,
    /// Names of the files being included, outermost first.
    stack: Vec<String>,
}

fn err<T>(span: Span, msg: impl Into<String>) -> Result<T, ParseError> {
    Err(ParseError::single(span, msg))
}

/// Preprocesses `main` with `predefined` macros (`NAME` → value), resolving
/// `#include` against `files`.
pub fn preprocess(main: &[u8], files: &BTreeMap<String, Vec<u8>>, predefined: &[(String, String)]) -> Result<Preprocessed, ParseError> {
    let mut pp = Pp { files, macros: HashMap::new(), out: Preprocessed { files: vec![String::new()], ..Default::default() }, stack: Vec::new() };
    for (k, v) in predefined {
        pp.macros.insert(k.clone(), Macro { params: None, body: v.clone() });
    }
    pp.file(main, 0)?;
    Ok(pp.out)
}

/// Decodes `bytes` as UTF-8, or an error at the first bad byte.
pub fn utf8(bytes: &[u8]) -> Result<&str, ParseError> {
    std::str::from_utf8(bytes).or_else(|e| {
        let good = &bytes[..e.valid_up_to()];
        let line = good.iter().filter(|&&b| b == b'\n').count() as u32 + 1;
        let col = String::from_utf8_lossy(good.rsplit(|&b| b == b'\n').next().unwrap_or(&[])).chars().count() as u32 + 1;
        err(Span::new(line, col), "the source is not valid UTF-8")
    })
}

/// Lines of `text` with comments blanked and backslash continuations joined:
/// each logical line with its first physical line number, followed by empty
/// lines for the lines it swallowed, so line numbers are kept.
fn logical_lines(text: &str) -> Vec<(u32, String)> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut start = 1u32;
    let mut line = 1u32;
    let mut pending_blank = 0u32;
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    let mut in_block = false;
    let mut in_str: Option<char> = None;
    while i < chars.len() {
        let c = chars[i];
        if in_block {
            if c == '*' && chars.get(i + 1) == Some(&'/') {
                in_block = false;
                cur.push(' ');
                i += 2;
                continue;
            }
            if c == '\n' {
                // A comment spanning lines: the logical line goes on.
                line += 1;
                pending_blank += 1;
            }
            i += 1;
            continue;
        }
        if let Some(q) = in_str {
            cur.push(c);
            if c == '\\' && i + 1 < chars.len() && chars[i + 1] != '\n' {
                cur.push(chars[i + 1]);
                i += 2;
                continue;
            }
            if c == q || c == '\n' {
                in_str = None;
                if c == '\n' {
                    cur.pop();
                    continue;
                }
            }
            i += 1;
            continue;
        }
        match c {
            '/' if chars.get(i + 1) == Some(&'*') => {
                in_block = true;
                i += 2;
            }
            '/' if chars.get(i + 1) == Some(&'/') => {
                while i < chars.len() && chars[i] != '\n' {
                    i += 1;
                }
            }
            '"' => {
                in_str = Some('"');
                cur.push(c);
                i += 1;
            }
            '\\' if chars.get(i + 1) == Some(&'\n') || (chars.get(i + 1) == Some(&'\r') && chars.get(i + 2) == Some(&'\n')) => {
                i += if chars[i + 1] == '\r' { 3 } else { 2 };
                line += 1;
                pending_blank += 1;
            }
            '\r' if chars.get(i + 1) == Some(&'\n') => i += 1,
            '\n' => {
                out.push((start, std::mem::take(&mut cur)));
                for k in 0..pending_blank {
                    out.push((start + k + 1, String::new()));
                }
                pending_blank = 0;
                line += 1;
                start = line;
                i += 1;
            }
            _ => {
                cur.push(c);
                i += 1;
            }
        }
    }
    if !cur.is_empty() || pending_blank > 0 {
        out.push((start, cur));
        for k in 0..pending_blank {
            out.push((start + k + 1, String::new()));
        }
    }
    out
}

fn is_ident_start(c: char) -> bool {
    c.is_ascii_alphabetic() || c == '_'
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// The directive of a line starting with `#`: its name and the rest.
fn directive(line: &str) -> Option<(&str, &str)> {
    let t = line.trim_start();
    let rest = t.strip_prefix('#')?.trim_start();
    let end = rest.find(|c: char| !c.is_ascii_alphanumeric()).unwrap_or(rest.len());
    Some((&rest[..end], rest[end..].trim()))
}

/// One level of `#if` nesting.
#[derive(Clone, Copy)]
struct Cond {
    /// Lines here are emitted.
    active: bool,
    /// A branch of this `#if` has been taken already.
    taken: bool,
    /// The enclosing region is active.
    parent: bool,
}

impl Pp<'_> {
    fn file(&mut self, bytes: &[u8], file: u16) -> Result<(), ParseError> {
        let text = utf8(bytes)?;
        let mut conds: Vec<Cond> = Vec::new();
        let mut last_line = 0;
        for (line, content) in logical_lines(text) {
            last_line = line;
            let span = Span::new(line, 1);
            let active = conds.last().is_none_or(|c| c.active);
            if let Some((name, rest)) = directive(&content).filter(|(n, r)| (r.is_empty() || !n.is_empty()) && DIRECTIVES.contains(n)) {
                match name {
                    "if" | "ifdef" | "ifndef" => {
                        let v = if !active {
                            false
                        } else {
                            match name {
                                "ifdef" => self.macros.contains_key(first_word(rest)),
                                "ifndef" => !self.macros.contains_key(first_word(rest)),
                                _ => self.condition(rest, span)?,
                            }
                        };
                        conds.push(Cond { active: active && v, taken: v, parent: active });
                    }
                    "elif" => {
                        let Some(c) = conds.last().copied() else { return err(span, "#elif without #if") };
                        let v = c.parent && !c.taken && self.condition(rest, span)?;
                        conds.pop();
                        conds.push(Cond { active: v, taken: c.taken || v, parent: c.parent });
                    }
                    "else" => {
                        let Some(c) = conds.pop() else { return err(span, "#else without #if") };
                        conds.push(Cond { active: c.parent && !c.taken, taken: true, parent: c.parent });
                    }
                    "endif" => {
                        if conds.pop().is_none() {
                            return err(span, "#endif without #if");
                        }
                    }
                    _ if !active => {}
                    "define" => self.define(rest, span)?,
                    "undef" => {
                        self.macros.remove(first_word(rest));
                    }
                    "include" => {
                        self.emit(file, line, "")?;
                        self.include(rest, span)?;
                        continue;
                    }
                    "error" => return err(span, format!("#error {rest}")),
                    // #pragma, #line, #ident and the null directive change nothing here.
                    _ => {}
                }
                self.emit(file, line, "")?;
                continue;
            }
            if active {
                let expanded = self.expand_line(&content, span)?;
                self.emit(file, line, &expanded)?;
            } else {
                self.emit(file, line, "")?;
            }
        }
        if !conds.is_empty() {
            return err(Span::new(last_line.max(1), 1), "#if without #endif");
        }
        Ok(())
    }

    fn emit(&mut self, file: u16, line: u32, text: &str) -> Result<(), ParseError> {
        if self.out.text.len() + text.len() + 1 > MAX_OUTPUT_BYTES {
            return err(Span::new(line, 1), format!("the preprocessed source exceeds {MAX_OUTPUT_BYTES} bytes"));
        }
        self.out.text.push_str(text);
        self.out.text.push('\n');
        self.out.origins.push((file, line));
        Ok(())
    }

    fn define(&mut self, rest: &str, span: Span) -> Result<(), ParseError> {
        let name_end = rest.find(|c: char| !is_ident(c)).unwrap_or(rest.len());
        let name = &rest[..name_end];
        if name.is_empty() || !name.starts_with(is_ident_start) {
            return err(span, "#define needs a macro name");
        }
        let after = &rest[name_end..];
        let (params, body) = if let Some(p) = after.strip_prefix('(') {
            let Some(close) = p.find(')') else { return err(span, format!("#define {name}(: missing )")) };
            let params: Vec<String> = p[..close].split(',').map(|s| s.trim().to_string()).filter(|s| !s.is_empty()).collect();
            (Some(params), p[close + 1..].trim().to_string())
        } else {
            (None, after.trim().to_string())
        };
        self.macros.insert(name.to_string(), Macro { params, body });
        Ok(())
    }

    fn include(&mut self, rest: &str, span: Span) -> Result<(), ParseError> {
        let rest = rest.trim();
        let name = match (rest.chars().next(), rest.get(1..)) {
            (Some('"'), Some(r)) => r.split('"').next().unwrap_or(""),
            (Some('<'), Some(r)) => r.split('>').next().unwrap_or(""),
            _ => return err(span, "#include needs \"file\" or <file>"),
        };
        let base = name.rsplit(['/', '\\']).next().unwrap_or(name);
        let found = self.files.get_key_value(name).or_else(|| self.files.get_key_value(base));
        let Some((key, bytes)) = found else {
            if SYSTEM_HEADERS.contains(&base) {
                return Ok(());
            }
            return err(span, format!("#include \"{name}\": no file of that name was sent with the request"));
        };
        if self.stack.iter().any(|f| f == key) {
            return err(span, format!("#include \"{name}\": the file includes itself (an include cycle)"));
        }
        if self.stack.len() >= MAX_INCLUDE_DEPTH {
            return err(span, format!("#include \"{name}\": includes nest more than {MAX_INCLUDE_DEPTH} deep"));
        }
        if self.out.files.len() >= u16::MAX as usize {
            return err(span, "too many #include directives");
        }
        let id = self.out.files.len() as u16;
        self.out.files.push(key.clone());
        self.stack.push(key.clone());
        let r = self.file(bytes, id).map_err(|e| in_file(e, key));
        self.stack.pop();
        r
    }

    fn condition(&self, rest: &str, span: Span) -> Result<bool, ParseError> {
        // `defined X` and `defined(X)` first, then macros, then the arithmetic.
        let mut s = String::new();
        let chars: Vec<char> = rest.chars().collect();
        let mut i = 0;
        while i < chars.len() {
            if is_ident_start(chars[i]) {
                let st = i;
                while i < chars.len() && is_ident(chars[i]) {
                    i += 1;
                }
                let word: String = chars[st..i].iter().collect();
                if word == "defined" {
                    let mut j = i;
                    while j < chars.len() && chars[j] == ' ' {
                        j += 1;
                    }
                    let paren = chars.get(j) == Some(&'(');
                    if paren {
                        j += 1;
                    }
                    while j < chars.len() && chars[j] == ' ' {
                        j += 1;
                    }
                    let ns = j;
                    while j < chars.len() && is_ident(chars[j]) {
                        j += 1;
                    }
                    let name: String = chars[ns..j].iter().collect();
                    if paren {
                        while j < chars.len() && chars[j] != ')' {
                            j += 1;
                        }
                        j += 1;
                    }
                    s.push_str(if self.macros.contains_key(&name) { " 1 " } else { " 0 " });
                    i = j;
                } else {
                    s.push_str(&word);
                }
            } else {
                s.push(chars[i]);
                i += 1;
            }
        }
        let expanded = self.expand_line(&s, span)?;
        eval_condition(&expanded).map(|v| v != 0).map_err(|m| ParseError::single(span, format!("#if: {m}")))
    }

    /// Expands the macros of one line.
    fn expand_line(&self, line: &str, span: Span) -> Result<String, ParseError> {
        if !line.chars().any(is_ident_start) || self.macros.is_empty() {
            return Ok(line.to_string());
        }
        let chars: Vec<char> = line.chars().collect();
        let mut hidden = Vec::new();
        let mut out = String::new();
        self.expand(&chars, &mut hidden, 0, span, &mut out)?;
        Ok(out)
    }

    fn expand(&self, chars: &[char], hidden: &mut Vec<String>, depth: usize, span: Span, out: &mut String) -> Result<(), ParseError> {
        if depth > MAX_EXPANSION_DEPTH {
            return err(span, format!("macros expand more than {MAX_EXPANSION_DEPTH} levels deep"));
        }
        let mut i = 0;
        while i < chars.len() {
            if out.len() > MAX_OUTPUT_BYTES {
                return err(span, format!("a macro expands to more than {MAX_OUTPUT_BYTES} bytes"));
            }
            let c = chars[i];
            if c == '"' {
                let st = i;
                i += 1;
                while i < chars.len() && chars[i] != '"' {
                    i += if chars[i] == '\\' { 2 } else { 1 };
                }
                i = (i + 1).min(chars.len());
                out.extend(&chars[st..i]);
                continue;
            }
            if c.is_ascii_digit() || (c == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit)) {
                // A number (pp-number): its letters are not identifiers.
                while i < chars.len() && (is_ident(chars[i]) || chars[i] == '.' || ((chars[i] == '+' || chars[i] == '-') && matches!(chars[i - 1], 'e' | 'E'))) {
                    out.push(chars[i]);
                    i += 1;
                }
                continue;
            }
            if !is_ident_start(c) {
                out.push(c);
                i += 1;
                continue;
            }
            let st = i;
            while i < chars.len() && is_ident(chars[i]) {
                i += 1;
            }
            let word: String = chars[st..i].iter().collect();
            let Some(m) = self.macros.get(&word).filter(|_| !hidden.contains(&word)) else {
                out.push_str(&word);
                continue;
            };
            let body: Vec<char> = match &m.params {
                None => m.body.chars().collect(),
                Some(params) => {
                    let mut j = i;
                    while j < chars.len() && chars[j].is_whitespace() {
                        j += 1;
                    }
                    if chars.get(j) != Some(&'(') {
                        out.push_str(&word);
                        continue;
                    }
                    let (args, end) = split_args(chars, j + 1).ok_or_else(|| ParseError::single(span, format!("macro {word}(: missing )")))?;
                    i = end;
                    let mut expanded_args = Vec::new();
                    for a in &args {
                        let mut s = String::new();
                        self.expand(&a.chars().collect::<Vec<_>>(), hidden, depth + 1, span, &mut s)?;
                        expanded_args.push(s);
                    }
                    substitute(&m.body, params, &expanded_args).chars().collect()
                }
            };
            hidden.push(word);
            let r = self.expand(&body, hidden, depth + 1, span, out);
            hidden.pop();
            r?;
        }
        Ok(())
    }
}

/// The arguments of a macro call whose `(` ends before `start`, and the index after its `)`.
fn split_args(chars: &[char], start: usize) -> Option<(Vec<String>, usize)> {
    let mut args = Vec::new();
    let mut cur = String::new();
    let mut level = 0;
    let mut i = start;
    while i < chars.len() {
        let c = chars[i];
        match c {
            '(' => level += 1,
            ')' if level == 0 => {
                if !cur.trim().is_empty() || !args.is_empty() {
                    args.push(cur.trim().to_string());
                }
                return Some((args, i + 1));
            }
            ')' => level -= 1,
            ',' if level == 0 => {
                args.push(std::mem::take(&mut cur).trim().to_string());
                i += 1;
                continue;
            }
            _ => {}
        }
        cur.push(c);
        i += 1;
    }
    None
}

/// `body` with each parameter name replaced by its argument (`#x` and `##` are not used by models).
fn substitute(body: &str, params: &[String], args: &[String]) -> String {
    let chars: Vec<char> = body.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        if is_ident_start(chars[i]) {
            let st = i;
            while i < chars.len() && is_ident(chars[i]) {
                i += 1;
            }
            let word: String = chars[st..i].iter().collect();
            match params.iter().position(|p| *p == word) {
                Some(k) => out.push_str(args.get(k).map_or("", String::as_str)),
                None => out.push_str(&word),
            }
        } else {
            out.push(chars[i]);
            i += 1;
        }
    }
    out
}

fn first_word(s: &str) -> &str {
    let s = s.trim_start();
    &s[..s.find(|c: char| !is_ident(c)).unwrap_or(s.len())]
}

/// Prefixes the messages of an error raised inside included file `name`.
fn in_file(mut e: ParseError, name: &str) -> ParseError {
    for d in &mut e.diagnostics {
        if !d.message.starts_with("in ") {
            d.message = format!("in {name}: {}", d.message);
        }
    }
    e
}
