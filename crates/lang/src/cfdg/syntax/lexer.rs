//! CFDG tokens, as Context Free's scanner reads them (John Horigan, `cfdg.l`,
//! Context Free 3.4): numbers without sign (`-1` is negation of `1`, which
//! matters for the entropy a term contributes), names with `::`, the `|`
//! forms of the target adjustments, comments `#`, `//` and `/* */`.
//!
//! Hand-written: the token set is small and positions (line, column) are
//! needed for every error.

use crate::{ParseError, Span};

/// One token kind.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Tok {
    /// A number, with its text as written (Context Free hashes the text).
    Num(String),
    /// A name, keyword or adjustment word (`shape`, `x`, `CF::Size`, `|hue`).
    Word(String),
    /// A quoted string (`include "file.cfdg"`).
    Str(String),
    /// Punctuation or an operator (`[`, `[[`, `..`, `+/-`, `<=`, `&&`, …).
    Punct(&'static str),
    /// End of input.
    Eof,
}

/// A token and where it starts.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Token {
    /// What it is.
    pub tok: Tok,
    /// Where it starts.
    pub span: Span,
    /// Whether its file is written in the 3.x syntax (each file is read in its own).
    pub v3: bool,
    /// Whether it comes from an `import`ed or `include`d file.
    pub included: bool,
    /// A name from a file imported into a namespace (`import @ns file`)
    /// is read as `ns::name`; this keeps the name as written, which cfdg
    /// hashes into seeds (`syntax/parser/namespace.rs`).
    pub written: Option<Box<str>>,
}

const PUNCTS: &[&str] = &[
    "+/-", "..", "<=", ">=", "==", "<>", "!=", "&&", "||", "^^", "--", "[", "]", "{", "}", "(", ")", ",", "*", "/", "+", "-", "^", "<", ">", "=", "!", "|", ":", ";",
];

/// The Unicode spellings of operators, which end a name.
const UNICODE_OPS: [&str; 6] = ["\u{2026}", "\u{b1}", "\u{2264}", "\u{2265}", "\u{2260}", "\u{221e}"];

/// Splits `src` into tokens; an unknown character or an unterminated
/// comment or string is a [`ParseError`] at its position.
pub fn lex(src: &str) -> Result<Vec<Token>, ParseError> {
    let b = src.as_bytes();
    let (mut i, mut line, mut col) = (0usize, 1u32, 1u32);
    let mut out = Vec::new();
    let adv = |i: &mut usize, line: &mut u32, col: &mut u32, n: usize| {
        for k in 0..n {
            if b.get(*i + k) == Some(&b'\n') {
                *line += 1;
                *col = 1;
            } else if b.get(*i + k).is_some_and(|c| c & 0xC0 != 0x80) {
                *col += 1;
            }
        }
        *i += n;
    };
    while i < b.len() {
        let c = b[i];
        let span = Span::new(line, col);
        if c.is_ascii_whitespace() {
            adv(&mut i, &mut line, &mut col, 1);
            continue;
        }
        if c == b'#' || b[i..].starts_with(b"//") {
            let n = b[i..].iter().position(|&c| c == b'\n' || c == b'\r').unwrap_or(b.len() - i);
            adv(&mut i, &mut line, &mut col, n);
            continue;
        }
        if b[i..].starts_with(b"/*") {
            let Some(n) = src[i + 2..].find("*/") else {
                return Err(ParseError::single(span, "unterminated comment"));
            };
            adv(&mut i, &mut line, &mut col, n + 4);
            continue;
        }
        if c == b'"' {
            let Some(n) = b[i + 1..].iter().position(|&c| c == b'"' || c == b'\n') else {
                return Err(ParseError::single(span, "unterminated string"));
            };
            if b[i + 1 + n] != b'"' {
                return Err(ParseError::single(span, "unterminated string"));
            }
            out.push(Token { v3: false, included: false, written: None, tok: Tok::Str(src[i + 1..i + 1 + n].to_string()), span });
            adv(&mut i, &mut line, &mut col, n + 2);
            continue;
        }
        if c.is_ascii_digit() || (c == b'.' && b.get(i + 1).is_some_and(u8::is_ascii_digit)) {
            let n = number_len(&b[i..]);
            out.push(Token { v3: false, included: false, written: None, tok: Tok::Num(src[i..i + n].to_string()), span });
            adv(&mut i, &mut line, &mut col, n);
            continue;
        }
        if c.is_ascii_alphabetic() || (c >= 0x80 && !UNICODE_OPS.iter().any(|op| b[i..].starts_with(op.as_bytes()))) || (c == b'|' && b.get(i + 1).is_some_and(u8::is_ascii_alphabetic)) {
            let start = i;
            let mut j = i + 1;
            loop {
                while j < b.len() && (b[j].is_ascii_alphanumeric() || b[j] == b'_' || b[j] >= 0x80) {
                    // cfdg's scanner splits a name at the Unicode operators (… ± ≤ ≥ ≠ ∞).
                    if b[j] >= 0x80 && UNICODE_OPS.iter().any(|op| b[j..].starts_with(op.as_bytes())) {
                        break;
                    }
                    j += 1;
                }
                if b[j..].starts_with(b"::") && b.get(j + 2).is_some_and(|c| c.is_ascii_alphabetic()) {
                    j += 2;
                    continue;
                }
                break;
            }
            // `name.cfdg` after include/import is a file name.
            if b[j..].starts_with(b".cfdg") {
                j += 5;
            }
            let word = &src[start..j];
            // `|hue` etc. are single tokens only for the adjustment words.
            if c == b'|' && !matches!(word, "|hue" | "|h" | "|saturation" | "|sat" | "|brightness" | "|b" | "|alpha" | "|a") {
                out.push(Token { v3: false, included: false, written: None, tok: Tok::Punct("|"), span });
                adv(&mut i, &mut line, &mut col, 1);
                continue;
            }
            out.push(Token { v3: false, included: false, written: None, tok: Tok::Word(word.to_string()), span });
            adv(&mut i, &mut line, &mut col, j - start);
            continue;
        }
        if let Some(p) = PUNCTS.iter().find(|p| b[i..].starts_with(p.as_bytes())) {
            out.push(Token { v3: false, included: false, written: None, tok: Tok::Punct(p), span });
            adv(&mut i, &mut line, &mut col, p.len());
            continue;
        }
        // Unicode spellings Context Free accepts: … ± ≤ ≥ ≠ ∞.
        let uni: &[(&str, Tok)] = &[
            ("\u{2026}", Tok::Punct("..")),
            ("\u{b1}", Tok::Punct("+/-")),
            ("\u{2264}", Tok::Punct("<=")),
            ("\u{2265}", Tok::Punct(">=")),
            ("\u{2260}", Tok::Punct("<>")),
            ("\u{221e}", Tok::Word("infinity".into())),
        ];
        if let Some((s, t)) = uni.iter().find(|(s, _)| src[i..].starts_with(s)) {
            out.push(Token { v3: false, included: false, written: None, tok: t.clone(), span });
            adv(&mut i, &mut line, &mut col, s.len());
            continue;
        }
        let ch = src[i..].chars().next().unwrap_or('?');
        if ch == '@' {
            // `import @ns file` (cfdg.ypp's fileNameSpace).
            out.push(Token { v3: false, included: false, written: None, tok: Tok::Punct("@"), span });
            adv(&mut i, &mut line, &mut col, 1);
            continue;
        }
        return Err(ParseError::single(span, format!("unexpected character `{ch}`")));
    }
    out.push(Token { v3: false, included: false, written: None, tok: Tok::Eof, span: Span::new(line, col) });
    Ok(out)
}

/// Length of the number at the start of `b` (`cfdg.l`'s INTEGER, RATIONAL,
/// FLOAT; a trailing `..` is the range operator, not part of the number).
fn number_len(b: &[u8]) -> usize {
    let mut j = 0;
    while j < b.len() && b[j].is_ascii_digit() {
        j += 1;
    }
    if j < b.len() && b[j] == b'.' && !b[j..].starts_with(b"..") {
        j += 1;
        while j < b.len() && b[j].is_ascii_digit() {
            j += 1;
        }
    }
    if j < b.len() && (b[j] == b'e' || b[j] == b'E') {
        let mut k = j + 1;
        if k < b.len() && (b[k] == b'+' || b[k] == b'-') {
            k += 1;
        }
        if k < b.len() && b[k].is_ascii_digit() {
            while k < b.len() && b[k].is_ascii_digit() {
                k += 1;
            }
            j = k;
        }
    }
    if j < b.len() && b[j] == b'%' {
        j += 1;
    }
    j
}
