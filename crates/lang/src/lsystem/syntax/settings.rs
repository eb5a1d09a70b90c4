//! The header settings (`iterations: 5`, `angle: 25.7`, `axiom: F`,
//! `shape: CYLINDER`, `tropism: 0 -1 0`, …) and, in [`Default`] for
//! [`LSystem`], the values of the ones a grammar leaves out. A numeric setting
//! is a constant expression (it may use `#define` names).

use super::statements::{find_top, is_ident, span_of, text_of};
use super::{err, Chars, Parser};
use crate::core::PrimitiveKind;
use crate::lsystem::syntax::{LSystem, Shape};
use crate::core::{ParseError, Span};

/// Most iterations a grammar may ask for (the budget usually binds far earlier).
const MAX_ITERATIONS: f64 = 100_000.0;

/// The settings, each written `name: value`.
pub(super) const SETTINGS: [&str; 13] = [
    "iterations", "angle", "length", "width", "axiom", "ignore", "seed", "shape", "tropism", "elasticity", "terminate", "modules", "variety",
];

/// The largest `variety:` accepted: more variants than this defeat instancing.
const MAX_VARIETY: f64 = 1024.0;

impl Default for LSystem {
    fn default() -> Self {
        LSystem {
            symbols: Vec::new(),
            axiom: Vec::new(),
            productions: Vec::new(),
            terminate: Vec::new(),
            iterations: 0,
            angle: 90.0,
            length: 1.0,
            width: 0.1,
            seed: None,
            ignore: Vec::new(),
            shape: Shape::Tube,
            tropism: None,
            elasticity: 0.2,
            variety: None,
            site_count: 0,
            warnings: Vec::new(),
        }
    }
}

impl Parser {
    fn number(&mut self, value: &Chars, at: Span, what: &str) -> Result<f64, ParseError> {
        if value.is_empty() {
            return err(at, format!("`{what}:` needs a value"));
        }
        let e = self.expr(value, &[], at)?;
        let v = e.eval(&mut ConstEnv);
        if !v.is_finite() {
            return err(value[0].1, format!("`{what}:` is not a finite number ({v})"));
        }
        Ok(v)
    }

    pub(super) fn setting(&mut self, key: &str, value: &Chars, at: Span) -> Result<(), ParseError> {
        let vspan = span_of(value, at);
        match key {
            "iterations" => {
                let v = self.number(value, at, key)?;
                if v < 0.0 || v.fract() != 0.0 || v > MAX_ITERATIONS {
                    return err(vspan, format!("`iterations:` must be a whole number in 0..={MAX_ITERATIONS}, got {v}"));
                }
                self.sys.iterations = v as u32;
            }
            "angle" => self.sys.angle = self.number(value, at, key)?,
            "length" => self.sys.length = self.number(value, at, key)?,
            "width" => self.sys.width = self.number(value, at, key)?,
            "elasticity" => self.sys.elasticity = self.number(value, at, key)?,
            "variety" => {
                let v = self.number(value, at, key)?;
                if v < 1.0 || v.fract() != 0.0 || v > MAX_VARIETY {
                    return err(vspan, format!("`variety:` must be a whole number in 1..={MAX_VARIETY}, got {v}"));
                }
                self.sys.variety = Some(v as u32);
            }
            "seed" => {
                let v = self.number(value, at, key)?;
                if v < 0.0 || v.fract() != 0.0 || v >= 1.8e19 {
                    return err(vspan, format!("`seed:` must be a whole number ≥ 0, got {v}"));
                }
                self.sys.seed = Some(v as u64);
            }
            "axiom" => {
                if self.axiom_set {
                    return err(at, "a second `axiom:`");
                }
                if value.is_empty() {
                    return err(at, "`axiom:` needs at least one module");
                }
                self.sys.axiom = self.modules(value, &[])?;
                self.axiom_set = true;
            }
            "ignore" => {
                for m in self.patterns(value)? {
                    if m.arity != 0 {
                        return err(m.span, "`ignore:` lists symbols without parameters");
                    }
                    self.sys.ignore.push(m.symbol);
                }
            }
            "modules" => {
                for w in value.split(|c| c.0.is_whitespace()).filter(|w| !w.is_empty()) {
                    if !w.iter().all(|c| is_ident(c.0)) || w.len() < 2 {
                        return err(w[0].1, format!("`modules:` declares names of two or more letters, digits or `_`, got `{}`", text_of(w)));
                    }
                    self.long_names.push(w.iter().map(|c| c.0).collect());
                }
                self.long_names.sort_by(|a, b| b.len().cmp(&a.len()).then_with(|| a.cmp(b)));
            }
            "shape" => {
                let name = text_of(value);
                self.sys.shape = if name.eq_ignore_ascii_case("tube") {
                    Shape::Tube
                } else {
                    match PrimitiveKind::ALL.iter().find(|k| format!("{k:?}").eq_ignore_ascii_case(&name)) {
                        Some(k) => Shape::Primitive(*k),
                        None => return err(vspan, format!("unknown shape `{name}` (tube or a built-in primitive such as CYLINDER)")),
                    }
                };
            }
            "tropism" => {
                let parts: Vec<&Chars> =
                    value.split(|c| c.0.is_whitespace() || c.0 == ',').filter(|w| !w.is_empty()).collect();
                if parts.len() != 3 {
                    return err(vspan, "`tropism:` needs three numbers `x y z`");
                }
                let mut t = [0.0; 3];
                for (slot, part) in t.iter_mut().zip(parts) {
                    *slot = self.number(part, at, key)?;
                }
                self.sys.tropism = Some(t);
            }
            "terminate" => {
                if find_top(value, "->").is_none() {
                    return err(vspan, "`terminate:` expects a production such as `L -> F`");
                }
                let p = self.production(value)?;
                self.sys.terminate.push(p);
            }
            _ => return err(at, format!("unknown setting `{key}`")),
        }
        Ok(())
    }

}

/// The environment of a setting's expression: there are no parameters
/// (NaN), and `rand()` reads 0.5.
struct ConstEnv;

impl crate::expr::ExprEnv for ConstEnv {
    fn param(&self, _index: u32) -> f64 {
        f64::NAN
    }
    fn rand(&mut self, _site: u32) -> f64 {
        0.5
    }
}
