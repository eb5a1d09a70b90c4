//! The MDG lexer: turns preprocessed text into tokens with source spans.
//!
//! `//` line comments (also after `\`), `/* */` block comments, numbers with
//! an optional leading dot, exponent and `t`/`d` suffix, identifiers that may
//! contain `.` and `_`, `@word` preprocessor words, and single-character
//! punctuation. A `-` is always its own token; the parser handles signs.

use super::preprocess::Preprocessed;
use crate::core::{ParseError, Span};

/// A token kind.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Tok<'a> {
    /// A name or keyword.
    Ident(&'a str),
    /// A number literal with its optional suffix (`t` or `d`).
    Num {
        /// The value without the suffix applied.
        value: f64,
        /// `Some('t')`, `Some('d')` or `None`.
        suffix: Option<char>,
        /// The literal as written.
        text: &'a str,
    },
    /// `@word` (only `@define` and `@param` reach the lexer).
    At(&'a str),
    /// One of `{ } [ ] ( ) * / + - ^ , : \ |` (`|` chains mesh modifiers).
    Punct(char),
    /// End of input.
    Eof,
}

impl std::fmt::Display for Tok<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Tok::Ident(s) => write!(f, "`{s}`"),
            Tok::Num { text, .. } => write!(f, "number `{text}`"),
            Tok::At(s) => write!(f, "`@{s}`"),
            Tok::Punct(c) => write!(f, "`{c}`"),
            Tok::Eof => write!(f, "end of input"),
        }
    }
}

/// A token with its position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Token<'a> {
    /// What it is.
    pub tok: Tok<'a>,
    /// Where it is in the original source.
    pub span: Span,
    /// 0-based line of the preprocessed text (for line-oriented constructs).
    pub line: u32,
}

fn ident_start(c: char) -> bool {
    c.is_alphabetic() || c == '_'
}

fn ident_continue(c: char) -> bool {
    c.is_alphanumeric() || c == '_' || c == '.'
}

/// Lexes the preprocessed text. The last token is always [`Tok::Eof`].
pub fn lex<'a>(pp: &'a Preprocessed) -> Result<Vec<Token<'a>>, ParseError> {
    let text = pp.text.as_str();
    let bytes = text.as_bytes();
    let mut toks = Vec::new();
    let mut line = 0usize;
    let mut col = 1u32;
    let mut i = 0usize;
    // Helper to get the char at byte i.
    let char_at = |i: usize| match bytes.get(i) {
        Some(&b) if b < 0x80 => Some(char::from(b)),
        Some(_) => text.get(i..).and_then(|s| s.chars().next()),
        None => None,
    };
    while let Some(c) = char_at(i) {
        if c == '\n' {
            line += 1;
            col = 1;
            i += 1;
            continue;
        }
        if c.is_whitespace() {
            col += 1;
            i += c.len_utf8();
            continue;
        }
        let span = pp.span(line, col);
        let out_line = u32::try_from(line).unwrap_or(u32::MAX);
        if c == '/' && bytes.get(i + 1) == Some(&b'/') {
            while let Some(c) = char_at(i) {
                if c == '\n' {
                    break;
                }
                i += c.len_utf8();
                col += 1;
            }
            continue;
        }
        if c == '/' && bytes.get(i + 1) == Some(&b'*') {
            i += 2;
            col += 2;
            let mut closed = false;
            while let Some(c) = char_at(i) {
                if c == '*' && bytes.get(i + 1) == Some(&b'/') {
                    i += 2;
                    col += 2;
                    closed = true;
                    break;
                }
                if c == '\n' {
                    line += 1;
                    col = 1;
                } else {
                    col += 1;
                }
                i += c.len_utf8();
            }
            if !closed {
                return Err(ParseError::single(span, "unterminated `/*` comment"));
            }
            continue;
        }
        let next_is_digit = bytes.get(i + 1).is_some_and(u8::is_ascii_digit);
        if c.is_ascii_digit() || (c == '.' && next_is_digit) {
            let start = i;
            while bytes.get(i).is_some_and(u8::is_ascii_digit) {
                i += 1;
            }
            if bytes.get(i) == Some(&b'.') {
                i += 1;
                while bytes.get(i).is_some_and(u8::is_ascii_digit) {
                    i += 1;
                }
            }
            if matches!(bytes.get(i), Some(b'e' | b'E')) {
                let mut j = i + 1;
                if matches!(bytes.get(j), Some(b'+' | b'-')) {
                    j += 1;
                }
                if bytes.get(j).is_some_and(u8::is_ascii_digit) {
                    while bytes.get(j).is_some_and(u8::is_ascii_digit) {
                        j += 1;
                    }
                    i = j;
                }
            }
            let num_end = i;
            let mut suffix = None;
            if let Some(&s @ (b't' | b'd')) = bytes.get(i) {
                if !char_at(i + 1).is_some_and(ident_continue) {
                    suffix = Some(char::from(s));
                    i += 1;
                }
            }
            let lit = &text[start..i];
            if char_at(i).is_some_and(ident_continue) {
                let mut j = i;
                while let Some(c) = char_at(j).filter(|&c| ident_continue(c)) {
                    j += c.len_utf8();
                }
                return Err(ParseError::single(span, format!("invalid number `{}`", &text[start..j])));
            }
            let value: f64 = text[start..num_end]
                .parse()
                .map_err(|_| ParseError::single(span, format!("invalid number `{lit}`")))?;
            if !value.is_finite() {
                return Err(ParseError::single(span, format!("number `{lit}` is too large")));
            }
            col += u32::try_from(i - start).unwrap_or(u32::MAX);
            toks.push(Token { tok: Tok::Num { value, suffix, text: lit }, span, line: out_line });
            continue;
        }
        if ident_start(c) || c == '@' {
            let start = i;
            i += c.len_utf8();
            col += 1;
            while let Some(c) = char_at(i).filter(|&c| ident_continue(c)) {
                i += c.len_utf8();
                col += 1;
            }
            let word = &text[start..i];
            let tok = match word.strip_prefix('@') {
                Some("") => return Err(ParseError::single(span, "expected a word after `@`")),
                Some(w) => Tok::At(w),
                None => Tok::Ident(word),
            };
            toks.push(Token { tok, span, line: out_line });
            continue;
        }
        if "{}[]()*/+-^,:\\|".contains(c) {
            toks.push(Token { tok: Tok::Punct(c), span, line: out_line });
            i += 1;
            col += 1;
            continue;
        }
        return Err(ParseError::single(span, format!("unexpected character `{}`", c.escape_debug())));
    }
    let end_line = u32::try_from(line).unwrap_or(u32::MAX);
    toks.push(Token { tok: Tok::Eof, span: pp.span(line, col), line: end_line });
    Ok(toks)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mdg::syntax::preprocess::preprocess;

    fn kinds(src: &str) -> Vec<String> {
        let pp = preprocess(src).unwrap();
        lex(&pp).unwrap().iter().map(|t| t.tok.to_string()).collect()
    }

    #[test]
    fn lexes_tight_spacing_numbers_and_comments() {
        assert_eq!(
            kinds("12/12*{rz 1}// c\n-.25 1e3 .5t 1d a.b_c /* x\n y */ \\ // after"),
            [
                "number `12`", "`/`", "number `12`", "`*`", "`{`", "`rz`", "number `1`", "`}`", "`-`",
                "number `.25`", "number `1e3`", "number `.5t`", "number `1d`", "`a.b_c`", "`\\`",
                "end of input"
            ]
        );
    }

    #[test]
    fn number_values_and_positions() {
        let pp = preprocess("x\n  -.2376 1e3 2t").unwrap();
        let t = lex(&pp).unwrap();
        assert_eq!(t[1].span, Span::new(2, 3));
        assert_eq!(t[2].tok, Tok::Num { value: 0.2376, suffix: None, text: ".2376" });
        assert_eq!(t[2].span, Span::new(2, 4));
        assert_eq!(t[3].tok, Tok::Num { value: 1000.0, suffix: None, text: "1e3" });
        assert_eq!(t[4].tok, Tok::Num { value: 2.0, suffix: Some('t'), text: "2t" });
    }

    #[test]
    fn lexical_errors_have_positions() {
        let e = lex(&preprocess("a\n é 1e999").unwrap()).unwrap_err();
        assert_eq!(e.diagnostics[0].span, Span::new(2, 4));
        assert_eq!(e.diagnostics[0].message, "number `1e999` is too large");
        let e = lex(&preprocess("a #").unwrap()).unwrap_err();
        assert_eq!((e.diagnostics[0].span, e.diagnostics[0].message.as_str()), (Span::new(1, 3), "unexpected character `#`"));
        let e = lex(&preprocess("a 12abc").unwrap()).unwrap_err();
        assert_eq!(e.diagnostics[0].message, "invalid number `12abc`");
        let e = lex(&preprocess("x /* never").unwrap()).unwrap_err();
        assert_eq!(e.diagnostics[0].span, Span::new(1, 3));
    }
}
