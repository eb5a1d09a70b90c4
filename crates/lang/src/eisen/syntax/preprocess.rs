//! The EisenScript preprocessor: `#define` substitution and GUI parameters.
//!
//! Structure Synth substitutes every `#define name value` into the lines
//! after it (the value may contain spaces, e.g. `#define shrink s 0.996`). A
//! trailing `(float:min-max)` or `(int:min-max)` makes the define a GUI
//! slider; here such defines are parameters a request may set by name.
//! Substitution is by whole word (Structure Synth replaces substrings, which
//! turns `angle1` into `61` when `angle` is defined as 6; no shipped example
//! relies on that) and repeats, so a define may use earlier ones, up to 100
//! substitutions a line as in Structure Synth. After substitution every
//! `random[a,b]` expression becomes a number drawn uniformly from [a, b] as
//! Structure Synth draws it (Parser/Preprocessor.cpp:19-21, 134-140): one
//! Mersenne Twister seeded with the request's seed for the whole script, a
//! draw per distinct expression of a line in order (identical expressions on
//! one line get the same number; `#define` lines draw too), written with six
//! significant digits like `QString::number`.
//! Define lines become empty lines, so line numbers of later diagnostics
//! stay those of the source.

use crate::core::mtrand::MtRand;
use crate::core::{ParseError, Span};

/// Most substitutions in one line (Structure Synth's guard against recursive defines).
const MAX_SUBSTITUTIONS: usize = 100;
/// Longest a line may grow by substitution: defines that expand each other
/// can grow a line exponentially, so the growth is capped.
const MAX_EXPANDED_LINE: usize = 1 << 20;

/// A `#define name value (float:min-max)` GUI parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct GuiParam {
    /// The name, as written in the script and given in requests.
    pub name: String,
    /// The default value written in the define.
    pub default: f64,
    /// Inclusive slider range.
    pub range: (f64, f64),
    /// True for `(int:…)` sliders: only whole numbers are accepted.
    pub integer: bool,
    /// Where it is defined.
    pub span: Span,
}

/// The preprocessed text and what the defines declared.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Preprocessed {
    /// The source with defines substituted and define lines blanked.
    pub text: String,
    /// GUI parameters in definition order.
    pub params: Vec<GuiParam>,
}

fn is_word(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Replaces whole-word occurrences of `name` in `line` by `value`.
fn substitute(line: &str, name: &str, value: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let mut rest = line;
    while let Some(at) = rest.find(name) {
        let before_ok = rest[..at].chars().next_back().is_none_or(|c| !is_word(c));
        let after = &rest[at + name.len()..];
        let after_ok = after.chars().next().is_none_or(|c| !is_word(c));
        out.push_str(&rest[..at]);
        out.push_str(if before_ok && after_ok { value } else { name });
        rest = after;
    }
    out.push_str(rest);
    out
}

/// Whether `line` holds `name` as a whole word.
fn has_word(line: &str, name: &str) -> bool {
    line.match_indices(name).any(|(at, _)| {
        line[..at].chars().next_back().is_none_or(|c| !is_word(c)) && line[at + name.len()..].chars().next().is_none_or(|c| !is_word(c))
    })
}

/// Replaces each `random[a,b]` in `line` by a number drawn from [a, b]
/// (`rg.getDouble(d1, d2)`), every occurrence of the same text by the same
/// number (`QString::replace`, Preprocessor.cpp:134-140).
fn expand_random(line: &str, rng: &mut MtRand, span_line: u32) -> Result<String, ParseError> {
    let mut l = line.to_string();
    let mut from = 0;
    while let Some(found) = l[from..].find("random[") {
        let at = from + found;
        let after = &l[at + "random[".len()..];
        let Some(close) = after.find(']') else { break };
        let bad = || ParseError::single(Span::new(span_line, at as u32 + 1), format!("`random[{}]` needs two numbers `a,b`", &after[..close]));
        let (a, b) = after[..close].split_once(',').ok_or_else(bad)?;
        let (a, b) = (a.trim().parse::<f64>().map_err(|_| bad())?, b.trim().parse::<f64>().map_err(|_| bad())?);
        if !(a.is_finite() && b.is_finite()) {
            return Err(bad());
        }
        let text = l[at..at + "random[".len() + close + 1].to_string();
        let value = qt_number(rng.double() * (b - a) + a);
        l = format!("{}{}", &l[..at], l[at..].replace(&text, &value));
        from = at + value.len();
    }
    Ok(l)
}

/// `QString::number(v)`: `%g` with six significant digits, as Qt writes it
/// (`1.5`, `0.333333`, `1.23457e+06`).
fn qt_number(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return if v.is_finite() { "0".into() } else { format!("{v}") };
    }
    let sci = format!("{v:.5e}");
    let (mantissa, exp) = sci.split_once('e').unwrap_or((&sci, "0"));
    let exp: i32 = exp.parse().unwrap_or(0);
    let trim = |t: &str| if t.contains('.') { t.trim_end_matches('0').trim_end_matches('.').to_string() } else { t.to_string() };
    if !(-4..6).contains(&exp) {
        return format!("{}e{}{:02}", trim(mantissa), if exp < 0 { '-' } else { '+' }, exp.abs());
    }
    trim(&format!("{:.*}", (5 - exp).max(0) as usize, v))
}

/// Splits `value (float:0-90)` into the value and the GUI range.
fn gui_suffix(value: &str) -> Option<(&str, bool, &str)> {
    let open = value.rfind('(')?;
    let inner = value[open + 1..].trim_end().strip_suffix(')')?;
    let (kind, range) = inner.split_once(':')?;
    let integer = match kind.trim().to_ascii_lowercase().as_str() {
        "float" => false,
        "int" => true,
        _ => return None,
    };
    Some((value[..open].trim(), integer, range))
}

/// Parses `min-max` where either bound may itself be negative.
fn parse_range(range: &str) -> Option<(f64, f64)> {
    let r = range.trim();
    // The separator is the first '-' that is not a leading sign.
    let cut = r.char_indices().skip(1).find(|&(_, c)| c == '-').map(|(i, _)| i)?;
    let lo = r[..cut].trim().parse::<f64>().ok()?;
    let hi = r[cut + 1..].trim().parse::<f64>().ok()?;
    (lo.is_finite() && hi.is_finite() && lo <= hi).then_some((lo, hi))
}

/// Runs the preprocessor. `overrides` gives request values for GUI parameters
/// by name (already checked against their ranges by the caller).
pub fn preprocess(text: &str, seed: u64, overrides: &dyn Fn(&str) -> Option<f64>) -> Result<Preprocessed, ParseError> {
    // Structure Synth's seeds are C ints: the request's seed is cut to 32 bits.
    let mut rng = MtRand::new(seed as u32);
    let mut defines: Vec<(String, String)> = Vec::new();
    let mut params = Vec::new();
    let mut out = String::with_capacity(text.len());
    for (i, line) in text.lines().enumerate() {
        let lineno = u32::try_from(i + 1).unwrap_or(u32::MAX);
        let trimmed = line.trim_start();
        if let Some(rest) = trimmed.strip_prefix("#define") {
            // Structure Synth expands `random[…]` on a define line too, after
            // storing its value: the draws are spent, the numbers unused.
            if line.contains("random[") {
                expand_random(line, &mut rng, lineno)?;
            }
            let span = Span::new(lineno, (line.len() - trimmed.len()) as u32 + 1);
            let rest = rest.trim();
            let (name, value) = rest.split_once(char::is_whitespace).unwrap_or((rest, ""));
            if name.is_empty() || !name.chars().all(is_word) {
                return Err(ParseError::single(span, format!("#define needs a name made of letters, digits and `_`, found `{name}`")));
            }
            let mut value = value.trim().to_string();
            if has_word(&value, name) {
                return Err(ParseError::single(span, format!("#define {name} refers to itself, so it would never stop expanding")));
            }
            if let Some((v, integer, range)) = gui_suffix(&value) {
                let Some(range) = parse_range(range) else {
                    return Err(ParseError::single(span, format!("#define {name}: the slider range must read `min-max` with min ≤ max, found `{range}`")));
                };
                let Ok(default) = v.parse::<f64>() else {
                    return Err(ParseError::single(span, format!("#define {name}: a slider parameter needs a numeric value, found `{v}`")));
                };
                let chosen = overrides(name).unwrap_or(default);
                value = if integer { format!("{}", chosen.round() as i64) } else { format!("{chosen}") };
                params.push(GuiParam { name: name.to_string(), default, range, integer, span });
            }
            // Later defines of the same name win, as in Structure Synth.
            defines.retain(|(n, _)| n != name);
            defines.push((name.to_string(), value));
            // Longest names first, so a define never clobbers part of a longer one.
            defines.sort_by(|a, b| b.0.len().cmp(&a.0.len()).then_with(|| a.0.cmp(&b.0)));
            out.push('\n');
            continue;
        }
        let mut l = line.to_string();
        let mut done = 0;
        while done < MAX_SUBSTITUTIONS {
            let Some((name, value)) = defines.iter().find(|(n, _)| has_word(&l, n)) else { break };
            l = substitute(&l, name, value);
            done += 1;
            if l.len() > MAX_EXPANDED_LINE {
                return Err(ParseError::single(
                    Span::new(lineno, 1),
                    format!("#define substitutions grow this line beyond {MAX_EXPANDED_LINE} bytes"),
                ));
            }
        }
        if l.contains("random[") {
            l = expand_random(&l, &mut rng, lineno)?;
        }
        out.push_str(&l);
        out.push('\n');
    }
    Ok(Preprocessed { text: out, params })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defines_substitute_whole_words_and_gui_params_bind() {
        let src = "#define angle 6\n#define shrink s 0.9\n#define steps 3 (int:1-90)\n{ rz angle shrink } angle1\nsteps * { x 1 } box\n";
        let p = preprocess(src, 0, &|n| (n == "steps").then_some(5.0)).unwrap();
        let lines: Vec<&str> = p.text.lines().collect();
        assert_eq!(lines[3], "{ rz 6 s 0.9 } angle1");
        assert_eq!(lines[4], "5 * { x 1 } box");
        assert_eq!(p.params.len(), 1);
        assert_eq!((p.params[0].default, p.params[0].range, p.params[0].integer), (3.0, (1.0, 90.0), true));
        assert!(preprocess("#define x 1 (float:5-1)\n", 0, &|_| None).is_err());
        // Defines may use earlier defines; self-reference and runaway growth are errors.
        let p = preprocess("#define a 2\n#define b a a\nb\n", 0, &|_| None).unwrap();
        assert_eq!(p.text.lines().nth(2), Some("2 2"));
        assert!(preprocess("#define r r r\nr\n", 0, &|_| None).is_err());
        let chain: String = (0..40).map(|i| format!("#define d{} d{} d{}\n", i + 1, i, i)).collect::<String>() + "d40\n";
        assert!(preprocess(&chain, 0, &|_| None).unwrap_err().to_string().contains("beyond"));
        // random[a,b] expressions: in range, reproducible per seed.
        let r = |seed| preprocess("{ x random[2,3] y random[-1,1] } box\n", seed, &|_| None).unwrap().text;
        assert_eq!(r(1), r(1));
        assert_ne!(r(1), r(2));
        let nums: Vec<f64> = r(1).split_whitespace().filter_map(|w| w.parse().ok()).collect();
        assert!((2.0..=3.0).contains(&nums[0]) && (-1.0..=1.0).contains(&nums[1]), "{nums:?}");
        assert!(preprocess("random[a,1]\n", 0, &|_| None).is_err());
        // Structure Synth's draws: seed 0's first MT19937 double is 0.548814 (2 357 136 044 / (2³² − 1)),
        // and the same expression twice on a line is one number.
        let p = preprocess("{ x random[0,1] y random[0,1] z random[0,2] } box\n", 0, &|_| None).unwrap();
        assert_eq!(p.text.lines().next(), Some("{ x 0.548814 y 0.548814 z 1.18569 } box"));
        assert_eq!([qt_number(1.5), qt_number(1.0 / 3.0), qt_number(1_234_567.0), qt_number(-0.000_012_345_67), qt_number(100_000.0)], ["1.5", "0.333333", "1.23457e+06", "-1.23457e-05", "100000"]);
        assert_eq!(parse_range("-10--2"), Some((-10.0, -2.0)));
    }
}
