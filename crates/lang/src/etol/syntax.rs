//! The ETOL token format of Haglund 2009, Appendix A (`language: "etol"`): a
//! whitespace-separated token stream
//!
//! ```text
//! length width iterations angle axiom  n  (pred succ)×n  m  (from to)×m
//! ```
//!
//! e.g. `0.2 0.3 4 25 L 1 L LF&F&FL 1 L F`: segments 0.2 long and 0.3 wide,
//! 4 iterations of `L → LF&F&FL` from `L` at 25°, then every `L` of the final
//! string becomes `F` (the termination table, applied once).
//!
//! It is translated into the L-system language (one setting or production
//! per line) and read by the L-system front end, so derivation, turtle,
//! instancing and budgets are shared. Translation keeps, per generated line,
//! the position of the token it came from, so errors found later still point
//! into the token stream. Tokens cannot contain spaces, so a successor is one
//! word (as in Haglund 2009's worked example, §4.3).

use crate::{Diagnostic, ParseError, Span};

/// One token with its 1-based position.
#[derive(Debug, Clone, Copy)]
struct Token<'a> {
    text: &'a str,
    span: Span,
}

/// Most productions or substitutions a stream may declare (counts are
/// checked against the tokens present, so this only bounds the message).
const MAX_RULES: usize = 4096;

/// An ETOL stream as L-system source, and where each of its lines came from.
#[derive(Debug, Clone, PartialEq)]
pub struct Translated {
    /// L-system source text, one statement per line.
    pub source: String,
    /// For each line of `source` (0-based), the span of the ETOL token it came from.
    pub origins: Vec<Span>,
}

impl Translated {
    /// Moves the positions of `e` (found in [`Translated::source`]) back to
    /// the ETOL tokens the lines came from.
    pub(crate) fn map_error(&self, mut e: ParseError) -> ParseError {
        for d in &mut e.diagnostics {
            remap(d, &self.origins);
        }
        e
    }

    /// [`Translated::map_error`] for warnings.
    pub(crate) fn map_warnings(&self, warnings: &mut [Diagnostic]) {
        for d in warnings {
            remap(d, &self.origins);
        }
    }
}

fn remap(d: &mut Diagnostic, origins: &[Span]) {
    let line = d.span.line as usize;
    if let Some(s) = line.checked_sub(1).and_then(|i| origins.get(i)) {
        d.span = *s;
    }
}

fn tokens(text: &str) -> Vec<Token<'_>> {
    let mut out = Vec::new();
    for (l, line) in text.split('\n').enumerate() {
        let mut col = 0usize;
        let mut rest = line;
        while let Some(start) = rest.find(|c: char| !c.is_whitespace()) {
            col += rest[..start].chars().count();
            rest = &rest[start..];
            let end = rest.find(char::is_whitespace).unwrap_or(rest.len());
            let span = Span::new(u32::try_from(l + 1).unwrap_or(u32::MAX), u32::try_from(col + 1).unwrap_or(u32::MAX));
            out.push(Token { text: &rest[..end], span });
            col += rest[..end].chars().count();
            rest = &rest[end..];
        }
    }
    out
}

/// Reads tokens in order, with messages naming the row of appendix A.
struct Reader<'a> {
    toks: Vec<Token<'a>>,
    at: usize,
    end: Span,
}

impl<'a> Reader<'a> {
    fn next(&mut self, row: &str) -> Result<Token<'a>, ParseError> {
        let t = self.toks.get(self.at).copied().ok_or_else(|| ParseError::single(self.end, format!("the stream ends before {row}")))?;
        self.at += 1;
        Ok(t)
    }

    fn number(&mut self, row: &str, ok: impl Fn(f64) -> bool, must: &str) -> Result<(f64, Token<'a>), ParseError> {
        let t = self.next(row)?;
        match t.text.parse::<f64>() {
            Ok(v) if v.is_finite() && ok(v) => Ok((v, t)),
            _ => Err(ParseError::single(t.span, format!("{row} must be {must}, found `{}`", t.text))),
        }
    }

    fn count(&mut self, row: &str) -> Result<(usize, Token<'a>), ParseError> {
        let left = (self.toks.len() - self.at.min(self.toks.len())).saturating_sub(1) / 2;
        let (v, t) = self.number(row, |v| v >= 0.0 && v.fract() == 0.0, "a whole number ≥ 0")?;
        // A count beyond the pairs that follow is an error, so it never sizes anything.
        if v > left.min(MAX_RULES) as f64 {
            return Err(ParseError::single(t.span, format!("{row} is {v}, but only {left} pairs follow")));
        }
        Ok((v as usize, t))
    }
}

/// Translates an ETOL token stream into L-system source.
pub fn translate(source: &[u8]) -> Result<Translated, ParseError> {
    let text = std::str::from_utf8(source).map_err(|e| ParseError::single(Span::new(1, 1), format!("the ETOL stream is not UTF-8 ({e})")))?;
    let toks = tokens(text);
    let last_line = u32::try_from(text.split('\n').count()).unwrap_or(u32::MAX);
    let mut r = Reader { toks, at: 0, end: Span::new(last_line, 1) };
    let mut lines: Vec<(String, Span)> = Vec::new();
    let (length, t) = r.number("row I (segment length)", |v| v > 0.0, "a number > 0")?;
    lines.push((format!("length: {length}"), t.span));
    let (width, t) = r.number("row II (segment width)", |v| v >= 0.0, "a number ≥ 0")?;
    lines.push((format!("width: {width}"), t.span));
    let (n, t) = r.number("row III (iterations)", |v| v >= 0.0 && v.fract() == 0.0, "a whole number ≥ 0")?;
    lines.push((format!("iterations: {n}"), t.span));
    let (angle, t) = r.number("row IV (rotation angle)", |_| true, "a number (degrees)")?;
    lines.push((format!("angle: {angle}"), t.span));
    let t = r.next("row V (the axiom)")?;
    lines.push((format!("axiom: {}", t.text), t.span));
    let (rules, _) = r.count("row VI (number of production rules)")?;
    for k in 1..=rules {
        let pred = symbol(r.next(&format!("row VII of rule {k} (predecessor)"))?)?;
        let succ = r.next(&format!("row VIII of rule {k} (successor)"))?;
        lines.push((format!("{} -> {}", pred.text, succ.text), pred.span));
    }
    let (subs, _) = r.count("row IX (number of substitutions)")?;
    for k in 1..=subs {
        let from = symbol(r.next(&format!("row X of substitution {k}"))?)?;
        let to = r.next(&format!("row XI of substitution {k}"))?;
        lines.push((format!("terminate: {} -> {}", from.text, to.text), from.span));
    }
    if let Some(extra) = r.toks.get(r.at) {
        return Err(ParseError::single(extra.span, format!("unexpected `{}` after the last substitution", extra.text)));
    }
    let mut out = Translated { source: String::new(), origins: Vec::with_capacity(lines.len()) };
    for (line, span) in lines {
        out.source.push_str(&line);
        out.source.push('\n');
        out.origins.push(span);
    }
    Ok(out)
}

/// A predecessor is one letter (Haglund 2009, Appendix A: "predecessor letter").
fn symbol(t: Token<'_>) -> Result<Token<'_>, ParseError> {
    if t.text.chars().count() == 1 {
        Ok(t)
    } else {
        Err(ParseError::single(t.span, format!("a predecessor is one symbol, found `{}`", t.text)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_appendix_a_example_translates_row_by_row() {
        let t = translate(b"0.2 0.3 4 25 L 1 L LF&F&FL 1 L F").expect("translates");
        assert_eq!(
            t.source,
            "length: 0.2\nwidth: 0.3\niterations: 4\nangle: 25\naxiom: L\nL -> LF&F&FL\nterminate: L -> F\n"
        );
        assert_eq!(t.origins[5], Span::new(1, 18));
    }

    #[test]
    fn errors_point_at_tokens() {
        let e = |s: &str| translate(s.as_bytes()).expect_err("fails").diagnostics[0].clone();
        let d = e("0.2 0.3 four 25 L 0 0");
        assert_eq!((d.span, d.message.as_str()), (Span::new(1, 9), "row III (iterations) must be a whole number ≥ 0, found `four`"));
        let d = e("0.2 0.3 4 25 L 9 L F 0");
        assert!(d.message.contains("only 1 pairs follow"), "{}", d.message);
        let d = e("0.2 0.3 4 25\nL 1 LL F 0");
        assert_eq!(d.span, Span::new(2, 5));
        let d = e("0.2 0.3 4 25 L 0 0 extra");
        assert!(d.message.contains("unexpected `extra`"));
        let d = e("0.2 0.3 4");
        assert!(d.message.contains("ends before row IV"));
    }
}
