//! Source text → statements, and the helpers on positioned characters that
//! every part of the parser uses: comments are blanked (keeping every
//! character's line and column), lines are joined into statements, and
//! statements are cut at top-level (parenthesis depth 0) separators.

use super::settings::SETTINGS;
use super::{err, Chars};
use crate::core::{ParseError, Span};

/// The characters of `text` with their positions, comments replaced by spaces.
pub(super) fn blank_comments(text: &str) -> Result<Vec<(char, Span)>, ParseError> {
    let mut out = Vec::with_capacity(text.len());
    let (mut line, mut col) = (1u32, 1u32);
    for c in text.chars() {
        out.push((c, Span::new(line, col)));
        if c == '\n' {
            line += 1;
            col = 1;
        } else {
            col += 1;
        }
    }
    // `/` is also the roll symbol, so `//` and `/*` open a comment only at the
    // start of a line or after whitespace, and `//` only before whitespace or
    // the end of the line: `F//F` rolls twice, `F // note` is a comment.
    let mut i = 0;
    while i < out.len() {
        let next = out.get(i + 1).map(|c| c.0);
        let after_space = i == 0 || out[i - 1].0.is_whitespace();
        let before_space = !out.get(i + 2).is_some_and(|c| !c.0.is_whitespace());
        match (out[i].0, next) {
            ('/', Some('/')) if after_space && before_space => {
                while i < out.len() && out[i].0 != '\n' {
                    out[i].0 = ' ';
                    i += 1;
                }
            }
            ('/', Some('*')) if after_space => {
                let start = out[i].1;
                out[i].0 = ' ';
                out[i + 1].0 = ' ';
                i += 2;
                loop {
                    if i >= out.len() {
                        return err(start, "unterminated comment: `/*` has no closing `*/`");
                    }
                    if out[i].0 == '*' && out.get(i + 1).is_some_and(|c| c.0 == '/') {
                        out[i].0 = ' ';
                        out[i + 1].0 = ' ';
                        i += 2;
                        break;
                    }
                    if out[i].0 != '\n' {
                        out[i].0 = ' ';
                    }
                    i += 1;
                }
            }
            _ => i += 1,
        }
    }
    Ok(out)
}

/// True when a line (already trimmed at the start) starts a statement of its own.
fn starts_statement(line: &Chars) -> bool {
    let word_len = line.iter().take_while(|c| is_ident(c.0)).count();
    let word = text_of(&line[..word_len]);
    let setting = SETTINGS.contains(&word.as_str()) && trim(&line[word_len..]).first().is_some_and(|c| c.0 == ':');
    setting || line.first().is_some_and(|c| c.0 == '#') || find_top(line, "->").is_some()
}

/// Splits into statements: a line, plus the indented lines that follow it
/// (an indented line that is itself a setting, directive or production starts a new one).
pub(super) fn split_statements(chars: &Chars) -> Result<Vec<Vec<(char, Span)>>, ParseError> {
    let mut out: Vec<Vec<(char, Span)>> = Vec::new();
    for line in chars.split(|c| c.0 == '\n') {
        let line: Vec<(char, Span)> = line.iter().copied().filter(|c| c.0 != '\r').collect();
        let Some(first) = line.iter().position(|c| !c.0.is_whitespace()) else { continue };
        if first > 0 && !starts_statement(&line[first..]) {
            if let Some(prev) = out.last_mut() {
                prev.push((' ', line[0].1));
                prev.extend_from_slice(&line[first..]);
                continue;
            }
        }
        out.push(line[first..].to_vec());
    }
    for st in &mut out {
        while st.last().is_some_and(|c| c.0.is_whitespace()) {
            st.pop();
        }
    }
    Ok(out)
}

/// `s` without leading and trailing whitespace.
pub(super) fn trim(mut s: &Chars) -> &Chars {
    while s.first().is_some_and(|c| c.0.is_whitespace()) {
        s = &s[1..];
    }
    while s.last().is_some_and(|c| c.0.is_whitespace()) {
        s = &s[..s.len() - 1];
    }
    s
}

/// The text of `s`, without positions.
pub(super) fn text_of(s: &Chars) -> String {
    s.iter().map(|c| c.0).collect()
}

/// Index of the first `pat` at parenthesis depth 0.
pub(super) fn find_top(s: &Chars, pat: &str) -> Option<usize> {
    let pat: Vec<char> = pat.chars().collect();
    let mut depth = 0i32;
    for i in 0..s.len() {
        match s[i].0 {
            '(' => depth += 1,
            ')' => depth -= 1,
            _ => {}
        }
        if depth == 0 && s[i..].iter().map(|c| c.0).take(pat.len()).eq(pat.iter().copied()) {
            return Some(i);
        }
    }
    None
}

/// The position of the first character of `s`, or `fallback` when it is empty.
pub(super) fn span_of(s: &Chars, fallback: Span) -> Span {
    s.first().map_or(fallback, |c| c.1)
}

/// Whether `c` may start a name (a `#define`, a parameter, a label).
pub(super) fn is_ident_start(c: char) -> bool {
    c.is_ascii_alphabetic() || c == '_'
}

/// Whether `c` may continue a name.
pub(super) fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Splits at commas of parenthesis depth 0.
pub(super) fn split_commas(s: &Chars) -> Vec<&Chars> {
    let mut out = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, c) in s.iter().enumerate() {
        match c.0 {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => {
                out.push(&s[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(&s[start..]);
    out
}
