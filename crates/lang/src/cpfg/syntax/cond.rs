//! The integer arithmetic of a preprocessor `#if` (C99 §6.10.1, as GNU
//! cccp's `cexp.y` evaluates it): after `defined` and macro expansion, an
//! expression over integer (and, leniently, decimal) numbers with C's
//! operators; an identifier left over counts as 0.

/// Evaluates `s`; an error message when it is not an expression.
pub(crate) fn eval_condition(s: &str) -> Result<i64, String> {
    let toks = tokens(s)?;
    let mut p = P { t: &toks, i: 0, depth: 0 };
    let v = p.ternary()?;
    if p.i != toks.len() {
        return Err(format!("unexpected `{}`", toks[p.i]));
    }
    Ok(v)
}

fn tokens(s: &str) -> Result<Vec<String>, String> {
    let c: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < c.len() {
        let ch = c[i];
        if ch.is_whitespace() {
            i += 1;
        } else if ch.is_ascii_alphanumeric() || ch == '_' || ch == '.' {
            let st = i;
            while i < c.len() && (c[i].is_ascii_alphanumeric() || c[i] == '_' || c[i] == '.') {
                i += 1;
            }
            out.push(c[st..i].iter().collect());
        } else {
            let two: String = c[i..(i + 2).min(c.len())].iter().collect();
            if ["&&", "||", "==", "!=", "<=", ">=", "<<", ">>"].contains(&two.as_str()) {
                out.push(two);
                i += 2;
            } else if "+-*/%()<>!?:~&|^".contains(ch) {
                out.push(ch.to_string());
                i += 1;
            } else {
                return Err(format!("unexpected `{ch}`"));
            }
        }
    }
    Ok(out)
}

struct P<'a> {
    t: &'a [String],
    i: usize,
    depth: u32,
}

const LEVELS: &[&[&str]] = &[&["||"], &["&&"], &["|"], &["^"], &["&"], &["==", "!="], &["<", ">", "<=", ">="], &["<<", ">>"], &["+", "-"], &["*", "/", "%"]];

impl P<'_> {
    fn peek(&self) -> Option<&str> {
        self.t.get(self.i).map(String::as_str)
    }

    fn ternary(&mut self) -> Result<i64, String> {
        self.depth += 1;
        if self.depth > 200 {
            return Err("expression nests too deep".into());
        }
        let c = self.binary(0)?;
        let r = if self.peek() == Some("?") {
            self.i += 1;
            let a = self.ternary()?;
            if self.peek() != Some(":") {
                return Err("expected `:`".into());
            }
            self.i += 1;
            let b = self.ternary()?;
            Ok(if c != 0 { a } else { b })
        } else {
            Ok(c)
        };
        self.depth -= 1;
        r
    }

    fn binary(&mut self, level: usize) -> Result<i64, String> {
        if level == LEVELS.len() {
            return self.unary();
        }
        let mut a = self.binary(level + 1)?;
        while let Some(op) = self.peek().filter(|o| LEVELS[level].contains(o)).map(str::to_string) {
            self.i += 1;
            let b = self.binary(level + 1)?;
            a = match op.as_str() {
                "||" => ((a != 0) || (b != 0)) as i64,
                "&&" => ((a != 0) && (b != 0)) as i64,
                "|" => a | b,
                "^" => a ^ b,
                "&" => a & b,
                "==" => (a == b) as i64,
                "!=" => (a != b) as i64,
                "<" => (a < b) as i64,
                ">" => (a > b) as i64,
                "<=" => (a <= b) as i64,
                ">=" => (a >= b) as i64,
                "<<" => a.wrapping_shl(b as u32),
                ">>" => a.wrapping_shr(b as u32),
                "+" => a.wrapping_add(b),
                "-" => a.wrapping_sub(b),
                "*" => a.wrapping_mul(b),
                "/" | "%" if b == 0 => return Err("division by zero".into()),
                "/" => a.wrapping_div(b),
                _ => a.wrapping_rem(b),
            };
        }
        Ok(a)
    }

    fn unary(&mut self) -> Result<i64, String> {
        let t = self.t;
        match t.get(self.i).map(String::as_str) {
            Some("-") => {
                self.i += 1;
                Ok(self.unary()?.wrapping_neg())
            }
            Some("+") => {
                self.i += 1;
                self.unary()
            }
            Some("!") => {
                self.i += 1;
                Ok((self.unary()? == 0) as i64)
            }
            Some("~") => {
                self.i += 1;
                Ok(!self.unary()?)
            }
            Some("(") => {
                self.i += 1;
                let v = self.ternary()?;
                if self.peek() != Some(")") {
                    return Err("expected `)`".into());
                }
                self.i += 1;
                Ok(v)
            }
            Some(w) => {
                self.i += 1;
                if w.starts_with(|c: char| c.is_ascii_digit() || c == '.') {
                    let w = w.trim_end_matches(['u', 'U', 'l', 'L']);
                    if let Some(h) = w.strip_prefix("0x").or_else(|| w.strip_prefix("0X")) {
                        return i64::from_str_radix(h, 16).map_err(|_| format!("bad number `{w}`"));
                    }
                    // cccp reads integers; models compare decimals too, which count by their whole part.
                    return w.parse::<i64>().or_else(|_| w.parse::<f64>().map(|f| f as i64)).map_err(|_| format!("bad number `{w}`"));
                }
                Ok(0)
            }
            None => Err("expression ends too soon".into()),
        }
    }
}
