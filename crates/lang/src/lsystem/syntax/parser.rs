//! Parsing L-system source into an [`LSystem`].
//!
//! The source is split into statements: one per line, where an indented line
//! continues the statement above it. Comments (`//` to the end of the line,
//! `/* … */`) are blanked first, keeping every other character's line and
//! column. Each statement is a setting (`axiom: …`), a directive
//! (`#define NAME expr`, `#ignore …`) or a production (it contains `->`).
//!
//! This file holds the entry point, the parser's state and the dispatch of
//! one statement; the parts of the notation each have a child module:
//!
//! - `statements.rs`: source text → statements of positioned characters, and
//!   the helpers every part uses on them;
//! - `settings.rs`: the header settings (`iterations:`, `angle:`, `shape:`, …)
//!   and their defaults;
//! - `productions.rs`: productions and the module strings they are made of;
//! - `expressions.rs`: argument, condition and probability expressions.

use super::LSystem;
use crate::expr::Expr;
use crate::core::{ParseError, Span};
use std::collections::HashMap;

#[path = "expressions.rs"]
mod expressions;
#[path = "productions.rs"]
mod productions;
#[path = "settings.rs"]
mod settings;
#[path = "statements.rs"]
mod statements;

use settings::SETTINGS;
use statements::{blank_comments, find_top, is_ident, is_ident_start, span_of, split_statements, text_of, trim};

/// A run of source characters, each with its position.
type Chars = [(char, Span)];

fn err<T>(span: Span, msg: impl Into<String>) -> Result<T, ParseError> {
    Err(ParseError::single(span, msg))
}

/// Parses L-system source.
pub fn parse(source: &[u8]) -> Result<LSystem, ParseError> {
    let text = match std::str::from_utf8(source) {
        Ok(t) => t,
        Err(e) => {
            let good = &source[..e.valid_up_to()];
            let line = good.iter().filter(|&&b| b == b'\n').count() as u32 + 1;
            let col = String::from_utf8_lossy(good.rsplit(|&b| b == b'\n').next().unwrap_or(&[])).chars().count() as u32 + 1;
            return err(Span::new(line, col), "the source is not valid UTF-8");
        }
    };
    let chars = blank_comments(text)?;
    let statements = split_statements(&chars)?;
    let mut p = Parser::default();
    p.sys.symbols = vec!["[".to_string(), "]".to_string()];
    for st in &statements {
        p.statement(st)?;
    }
    p.finish()
}

/// The parser's state while it reads the statements in order.
#[derive(Default)]
struct Parser {
    sys: LSystem,
    defines: HashMap<String, Expr>,
    /// Multi-character module names declared with `modules:`, longest first.
    long_names: Vec<Vec<char>>,
    groups: HashMap<String, u32>,
    axiom_set: bool,
}

impl Parser {
    fn finish(mut self) -> Result<LSystem, ParseError> {
        if !self.axiom_set {
            return err(Span::new(1, 1), "the L-system has no `axiom:`");
        }
        self.sys.ignore.sort_unstable();
        self.sys.ignore.dedup();
        Ok(self.sys)
    }

    fn intern(&mut self, name: &str) -> u32 {
        if let Some(i) = self.sys.symbols.iter().position(|s| s == name) {
            return i as u32;
        }
        self.sys.symbols.push(name.to_string());
        (self.sys.symbols.len() - 1) as u32
    }

    fn statement(&mut self, st: &Chars) -> Result<(), ParseError> {
        let start = st[0].1;
        if st[0].0 == '#' {
            return self.directive(st);
        }
        // A setting: a known word followed by ':'.
        let word_len = st.iter().take_while(|c| is_ident(c.0)).count();
        let word = text_of(&st[..word_len]);
        let rest = trim(&st[word_len..]);
        if SETTINGS.contains(&word.as_str()) && rest.first().is_some_and(|c| c.0 == ':') {
            return self.setting(&word, trim(&rest[1..]), start);
        }
        if find_top(st, "->").is_some() {
            let p = self.production(st)?;
            self.sys.productions.push(p);
            return Ok(());
        }
        if rest.first().is_some_and(|c| c.0 == ':') && word_len > 1 {
            return err(start, format!("unknown setting `{word}` (known: {})", SETTINGS.join(", ")));
        }
        err(start, "expected a setting such as `axiom: F` or a production `pred -> successor`")
    }

    fn directive(&mut self, st: &Chars) -> Result<(), ParseError> {
        let word_len = 1 + st[1..].iter().take_while(|c| is_ident(c.0)).count();
        let word = text_of(&st[..word_len]);
        let rest = trim(&st[word_len..]);
        match word.as_str() {
            "#define" => {
                let name_len = rest.iter().take_while(|c| is_ident(c.0)).count();
                if name_len == 0 || !is_ident_start(rest[0].0) {
                    return err(span_of(rest, st[0].1), "`#define` expects a name and an expression");
                }
                let name = text_of(&rest[..name_len]);
                let body = trim(&rest[name_len..]);
                if body.is_empty() {
                    return err(rest[0].1, format!("`#define {name}` has no value"));
                }
                let e = self.expr(body, &[], rest[0].1)?;
                self.defines.insert(name, e);
                Ok(())
            }
            "#ignore" => {
                let rest = if rest.first().is_some_and(|c| c.0 == ':') { trim(&rest[1..]) } else { rest };
                self.setting("ignore", rest, st[0].1)
            }
            _ => err(st[0].1, format!("unknown directive `{word}` (known: #define, #ignore)")),
        }
    }

}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(src: &str) -> LSystem {
        parse(src.as_bytes()).unwrap_or_else(|e| panic!("{e}"))
    }

    fn e(src: &str) -> String {
        parse(src.as_bytes()).expect_err("should fail").to_string()
    }

    #[test]
    fn parses_settings_and_a_production() {
        let s = p("iterations: 5\nangle: 25.7\naxiom: F\nF -> F[+F]F[-F]F\n");
        assert_eq!(s.iterations, 5);
        assert_eq!(s.angle, 25.7);
        assert_eq!(s.productions.len(), 1);
        assert_eq!(s.productions[0].successor.len(), 11);
    }

    #[test]
    fn parses_full_production_form() {
        let s = p("#define R 1.5\naxiom: A(1)\np1: B(a) < A(x) > C(y, z) : x < R && !(y == 2) -> A(x+1) F(x*R, rand()) : 0.5\n");
        let pr = &s.productions[0];
        assert_eq!(pr.label.as_deref(), Some("p1"));
        assert_eq!(pr.left.len(), 1);
        assert_eq!(pr.right[0].arity, 2);
        assert!(pr.condition.is_some() && pr.probability.is_some());
        assert_eq!(s.site_count, 1);
    }

    #[test]
    fn comments_and_continuation_lines() {
        let s = p("axiom: A // start\n/* block\n comment */ A -> F//F\n   [+A]\n");
        assert_eq!(s.productions[0].successor.len(), 8);
    }

    #[test]
    fn errors_have_positions() {
        assert!(e("axiom: F\nF -> F(1+)\n").starts_with("2:"), "{}", e("axiom: F\nF -> F(1+)\n"));
        assert!(e("axiom: F\nfoo: 3\n").contains("unknown setting"));
        assert!(e("F -> FF\n").contains("no `axiom:`"));
        assert!(e("axiom: F\nF(q) -> F(w)\n").contains("unknown name `w`"));
        assert!(e("axiom: F\nA(x,x) -> F\n").contains("bound twice"));
        assert!(e("axiom: F\n/* open\n").contains("unterminated comment"));
        assert!(e("axiom: F(\n").contains("no matching"));
        assert_eq!(e("axiom: F\nF -> F : \n"), "2:1: error: empty probability after `:`");
    }

    #[test]
    fn long_module_names() {
        let s = p("modules: draw rotateZ\naxiom: A(1)\nA(w) : w = 1 -> A(w+1) rotateZ(45) draw(2)\n");
        let names: Vec<&str> = s.productions[0].successor.iter().map(|m| s.symbols[m.symbol as usize].as_str()).collect();
        assert_eq!(names, ["A", "rotateZ", "draw"]);
    }
}
