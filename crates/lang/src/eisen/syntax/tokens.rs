//! The tokenizer, after Structure Synth's: whitespace and braces separate
//! tokens, `[ … ]` belongs to the token it is attached to, comments and
//! leftover preprocessor lines are dropped. Also the reading of number
//! tokens, which every part of the parser shares.

use crate::core::{ParseError, Span};

/// A token: its text as written and where it starts.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Token {
    /// The text as written (`[ … ]` included).
    pub(super) text: String,
    /// Where the token starts.
    pub(super) span: Span,
}

/// Splits the preprocessed text into tokens, dropping comments.
pub(super) fn tokenize(text: &str) -> Result<Vec<Token>, ParseError> {
    let mut out = Vec::new();
    let chars: Vec<char> = text.chars().collect();
    let (mut line, mut col) = (1u32, 1u32);
    let mut i = 0;
    let mut cur = String::new();
    let mut start = Span::new(1, 1);
    let mut line_start = true;
    let flush = |cur: &mut String, start: Span, out: &mut Vec<Token>| {
        if !cur.is_empty() {
            out.push(Token { text: std::mem::take(cur), span: start });
        }
    };
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        let here = Span::new(line, col);
        let mut advance = |i: &mut usize| {
            let c = chars[*i];
            *i += 1;
            if c == '\n' {
                line += 1;
                col = 1;
            } else {
                col += 1;
            }
        };
        if c == '#' && line_start {
            // A preprocessor line that is not a define (e.g. `#include`): a comment.
            while i < chars.len() && chars[i] != '\n' {
                advance(&mut i);
            }
            continue;
        }
        if c == '/' && next == Some('/') {
            flush(&mut cur, start, &mut out);
            while i < chars.len() && chars[i] != '\n' {
                advance(&mut i);
            }
            continue;
        }
        if c == '/' && next == Some('*') {
            flush(&mut cur, start, &mut out);
            advance(&mut i);
            advance(&mut i);
            while i < chars.len() && !(chars[i] == '*' && chars.get(i + 1) == Some(&'/')) {
                advance(&mut i);
            }
            if i < chars.len() {
                advance(&mut i);
                advance(&mut i);
            }
            continue;
        }
        if c == '[' {
            if cur.is_empty() {
                start = here;
            }
            while i < chars.len() && chars[i] != ']' {
                cur.push(chars[i]);
                advance(&mut i);
            }
            if i >= chars.len() {
                return Err(ParseError::single(here, "no matching `]` for this `[`"));
            }
            cur.push(']');
            advance(&mut i);
            line_start = false;
            continue;
        }
        if c.is_whitespace() || c == '{' || c == '}' {
            flush(&mut cur, start, &mut out);
            if c == '{' || c == '}' {
                out.push(Token { text: c.to_string(), span: here });
            }
            line_start = c == '\n';
            advance(&mut i);
            continue;
        }
        if cur.is_empty() {
            start = here;
        }
        cur.push(c);
        line_start = false;
        advance(&mut i);
    }
    flush(&mut cur, start, &mut out);
    Ok(out)
}

/// A number token: integer, decimal or fraction `a/b`. Returns (value, is integer).
///
/// Structure Synth reads a token as a number when it starts with a sign or
/// a digit (Tokenizer.cpp:110), and a fraction only of two non-zero
/// integers (Tokenizer.cpp:113-130). The JavaScript ports also write
/// numbers with a leading dot (`.5`, `-.25`) and decimal fractions
/// (`1.5/2`); neither can mean anything else in Structure Synth (a token
/// `.5` would be a rule name, which no script names a rule), so both are
/// read as numbers too.
pub(super) fn number(text: &str) -> Option<(f64, bool)> {
    let unsigned = text.strip_prefix(['+', '-']).unwrap_or(text);
    let leading_dot = unsigned.strip_prefix('.').is_some_and(|r| r.starts_with(|c: char| c.is_ascii_digit()));
    if !(unsigned.starts_with(|c: char| c.is_ascii_digit()) || leading_dot) {
        return None;
    }
    if let Some((a, b)) = text.split_once('/') {
        let (a, b) = (decimal(a)?, decimal(b)?);
        return (b != 0.0).then(|| a / b).filter(|v| v.is_finite()).map(|v| (v, false));
    }
    if let Ok(i) = text.parse::<i64>() {
        return Some((i as f64, true));
    }
    decimal(text).map(|v| (v, false))
}

/// A finite decimal number (no `inf`, `nan` or exponent-only words).
fn decimal(text: &str) -> Option<f64> {
    let t = text.strip_prefix(['+', '-']).unwrap_or(text);
    if !t.starts_with(|c: char| c.is_ascii_digit() || c == '.') {
        return None;
    }
    text.parse::<f64>().ok().filter(|v| v.is_finite())
}
