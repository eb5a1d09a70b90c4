//! EisenScript, the language of Structure Synth 1.5 (see `docs/eisenscript.md`).
//!
//! The front end reads a script into a [`Script`]: rule definitions, the
//! top-level actions (Structure Synth's start rule) and, per action, the
//! transformation loops as composed 4×4 affine matrices with their colour
//! changes. It does not lower into the shared rule IR ([`crate::lang::ir`]):
//! EisenScript needs general affine frames (`s x y z`, `m`), HSV colour
//! state with blending and colour pools, per-rule retirement counters
//! carried in the state, and breadth-first generations whose order decides
//! what `maxobjects` keeps — none of which the MDG evaluator's similarity
//! frames and depth-first stack can express. [`crate::eisen`] evaluates it.
//!
//! Tokens follow Structure Synth's tokenizer: whitespace and braces separate
//! them, `[ … ]` is part of the token it is attached to (so `triangle[0,0,0;…]`
//! and `[1 0 0]` are single tokens), names are case-insensitive, and
//! numbers may be written as fractions `a/b`.

pub mod colour;
pub mod preprocess;

use crate::core::{Diagnostic, ParseError, Span};
use glam::{DMat4, DVec3};

pub use preprocess::GuiParam;

/// True when `text` is a Structure Synth JavaScript script (its first
/// non-blank line starts with `#javascript`).
pub fn is_javascript(text: &[u8]) -> bool {
    let start = text.iter().position(|b| !b.is_ascii_whitespace()).unwrap_or(text.len());
    text[start..].get(..11).is_some_and(|p| p.eq_ignore_ascii_case(b"#javascript"))
}

/// Guesses whether `text` is EisenScript (used when no language is named).
/// Looks for what MDG and L-systems never write: `#define`/`#javascript`
/// lines, `set maxdepth|maxobjects|background|…` lines and `md`/`w` rule modifiers.
pub fn looks_like_eisenscript(text: &str) -> bool {
    const SETS: [&str; 10] =
        ["maxdepth", "maxobjects", "background", "colorpool", "seed", "minsize", "maxsize", "translation", "rotation", "raytracer::"];
    text.lines().any(|l| {
        let l = l.trim_start().to_ascii_lowercase();
        if l.starts_with("#define ") || l.starts_with("#javascript") {
            return true;
        }
        if let Some(rest) = l.strip_prefix("set ") {
            return SETS.iter().any(|s| rest.trim_start().starts_with(s));
        }
        let words: Vec<&str> = l.split_whitespace().collect();
        words.first() == Some(&"rule") && words.get(2).is_some_and(|w| ["md", "w", "maxdepth", "weight"].contains(w))
    })
}

/// A built-in drawable of Structure Synth.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Primitive {
    /// The unit cube [0, 1]³ of the local frame.
    Box,
    /// The sphere inscribed in the unit cube.
    Sphere,
    /// A cylinder inscribed in the unit cube, its axis along local x.
    Cylinder,
    /// The segment (0, ½, ½)–(1, ½, ½), drawn as a thin tube.
    Line,
    /// The point (½, ½, ½) (`dot` or `point`), drawn as a small sphere.
    Point,
    /// The twelve edges of the unit cube, drawn as thin tubes.
    Grid,
    /// A solid joining the previous frame's x = 0 face to this frame's.
    Mesh,
    /// Template-export hook: no geometry.
    Template,
}

impl Primitive {
    fn from_name(name: &str) -> Option<Primitive> {
        Some(match name {
            "box" => Primitive::Box,
            "sphere" => Primitive::Sphere,
            "cylinder" => Primitive::Cylinder,
            "line" => Primitive::Line,
            "dot" | "point" => Primitive::Point,
            "grid" => Primitive::Grid,
            "mesh" => Primitive::Mesh,
            "template" => Primitive::Template,
            _ => return None,
        })
    }
}

/// What an action calls, resolved after parsing.
#[derive(Debug, Clone, PartialEq)]
pub enum Target {
    /// A rule name (index into [`Script::names`]); a random definition is chosen by weight.
    Rule(u32),
    /// A primitive with its class (index into [`Script::classes`]; 0 is the default class).
    Primitive(Primitive, u32),
    /// `triangle[x,y,z;x,y,z;x,y,z]`: a triangle in local coordinates, with its class.
    Triangle([DVec3; 3], u32),
}

/// One transformation list `{ … }`, composed: a matrix and a colour change.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transform {
    /// Post-multiplied onto the state's matrix.
    pub matrix: DMat4,
    /// Added to the hue (or the absolute hue when `absolute`; > 360 means a random colour).
    pub delta_h: f64,
    /// Multiplies saturation (or is the absolute saturation).
    pub scale_s: f64,
    /// Multiplies brightness (or is the absolute brightness).
    pub scale_v: f64,
    /// Multiplies alpha (or is the absolute alpha).
    pub scale_a: f64,
    /// `color …` was given: the colour fields are absolute.
    pub absolute: bool,
    /// `blend colour strength`: the colour's HSV and the strength (0 = none).
    pub blend: Option<([f64; 3], f64)>,
}

impl Default for Transform {
    fn default() -> Self {
        Transform { matrix: DMat4::IDENTITY, delta_h: 0.0, scale_s: 1.0, scale_v: 1.0, scale_a: 1.0, absolute: false, blend: None }
    }
}

impl Transform {
    /// Appends `t` after `self` (Structure Synth's `Transformation::append`).
    fn append(&mut self, t: &Transform) {
        self.matrix *= t.matrix;
        if t.absolute && self.absolute {
            // Two absolute colours cannot mix: the later one wins.
            (self.delta_h, self.scale_s, self.scale_v, self.scale_a) = (t.delta_h, t.scale_s, t.scale_v, t.scale_a);
        } else {
            self.absolute |= t.absolute;
            self.scale_a *= t.scale_a;
            self.delta_h += t.delta_h;
            self.scale_s *= t.scale_s;
            self.scale_v *= t.scale_v;
        }
        if t.blend.is_some() {
            self.blend = t.blend;
        }
    }
}

/// `count * { transform }`: copies with the transform applied 1..=count times.
#[derive(Debug, Clone, PartialEq)]
pub struct Loop {
    /// Number of copies.
    pub count: u32,
    /// The step.
    pub transform: Transform,
}

/// A colour pool for `color random`.
#[derive(Debug, Clone, PartialEq)]
pub enum ColourPool {
    /// A random hue at full saturation and brightness (the default).
    RandomHue,
    /// Independent random R, G and B.
    RandomRgb,
    /// Random R = G = B.
    Greyscale,
    /// A uniform choice from the list (repeat an entry to weight it).
    List(Vec<[u8; 3]>),
}

/// A `set key value` command, checked at parse time and run when its action runs.
#[derive(Debug, Clone, PartialEq)]
pub enum Setting {
    /// `set maxdepth N`: generations (breadth-first) or the default rule depth (depth-first).
    MaxDepth(i64),
    /// `set maxobjects N`: stop after N objects (or N pending rules).
    MaxObjects(i64),
    /// `set minsize v`: branches whose unit-cube diagonal is shorter are not expanded.
    MinSize(f64),
    /// `set maxsize v`: branches whose unit-cube diagonal is longer are not expanded.
    MaxSize(f64),
    /// `set seed N`, or `set seed initial` (`None`).
    Seed(Option<i64>),
    /// `set background colour`.
    Background([u8; 3]),
    /// `set colorpool …`.
    ColourPool(ColourPool),
    /// `set syncrandom true|false`.
    SyncRandom(bool),
    /// A viewer camera setting, exported as a glTF camera.
    Camera(CameraSetting),
    /// Accepted and ignored (raytracer, `recursion`, `rng`, `opengl`, `template`).
    Ignored,
}

/// Structure Synth's viewer settings (`set translation [x y z]` and so on),
/// as its GUI writes them to a script to save the view.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CameraSetting {
    /// `set translation [x y z]`: the view-space offset of the model.
    Translation(DVec3),
    /// `set rotation [9 numbers]`: the view rotation (rows first).
    Rotation(glam::DMat3),
    /// `set pivot [x y z]`: the world point the view rotates and scales about.
    Pivot(DVec3),
    /// `set scale s`: the view zoom.
    Scale(f64),
    /// `set perspective-angle deg`: the vertical field of view.
    PerspectiveAngle(f64),
}

/// One statement of a rule body or the top level.
#[derive(Debug, Clone, PartialEq)]
pub enum Action {
    /// `[N * { t }]… [{ t }] name`: queue `target` in each transformed state.
    Call {
        /// Loops, outermost first; a plain `{ t } name` is one loop of count 1.
        loops: Vec<Loop>,
        /// What is called.
        target: Target,
        /// Unique per action; seeds the random streams of the states it makes.
        site: u32,
        /// Where the action starts.
        span: Span,
    },
    /// `set key value`.
    Set(Setting, Span),
}

/// One `rule name [modifiers] { … }` definition.
#[derive(Debug, Clone, PartialEq)]
pub struct RuleDef {
    /// Index into [`Script::names`].
    pub name: u32,
    /// `w`/`weight` (default 1).
    pub weight: f64,
    /// `md`/`maxdepth N`: the rule retires after N nested applications.
    pub maxdepth: Option<i64>,
    /// `maxdepth N > other`: what runs instead once retired.
    pub retirement: Option<Target>,
    /// The body.
    pub actions: Vec<Action>,
    /// Where the definition starts.
    pub span: Span,
}

/// A parsed script.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Script {
    /// Rule names (lower case); [`Target::Rule`] indexes this.
    pub names: Vec<String>,
    /// Per name, the indices of its definitions in [`Script::rules`].
    pub groups: Vec<Vec<u32>>,
    /// Every rule definition.
    pub rules: Vec<RuleDef>,
    /// The top-level actions (Structure Synth's start rule).
    pub top: Vec<Action>,
    /// Primitive classes (`box::shiny`); index 0 is the default class `""`.
    pub classes: Vec<String>,
    /// `set recursion depth` was given: expand depth-first.
    pub depth_first: bool,
    /// `#define … (float:a-b)` parameters.
    pub params: Vec<GuiParam>,
    /// Notes about ignored settings.
    pub warnings: Vec<Diagnostic>,
}

/// Parse-time inputs: request values for GUI parameters, by name.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ParseOptions {
    /// Values for `#define … (float:a-b)` parameters; checked by [`crate::eisen`].
    pub params: std::collections::BTreeMap<String, f64>,
    /// Seed of the preprocessor's `random[a,b]` expressions.
    pub seed: u64,
}

/// Parses EisenScript `source`.
pub fn parse(source: &[u8], opts: &ParseOptions) -> Result<Script, ParseError> {
    let text = match std::str::from_utf8(source) {
        Ok(t) => t,
        Err(e) => {
            let before = &source[..e.valid_up_to()];
            let line = before.iter().filter(|&&b| b == b'\n').count() as u32 + 1;
            let col = String::from_utf8_lossy(&before[before.iter().rposition(|&b| b == b'\n').map_or(0, |p| p + 1)..]).chars().count();
            return Err(ParseError::single(Span::new(line, col as u32 + 1), "the source is not valid UTF-8"));
        }
    };
    if is_javascript(source) {
        return Err(ParseError::single(
            Span::new(1, 1),
            "this is a Structure Synth JavaScript script (#javascript): it is run, not parsed, when rendered (see docs/eisenscript.md)",
        ));
    }
    let pre = preprocess::preprocess(text, opts.seed, &|n| opts.params.get(n).copied())?;
    let tokens = tokenize(&pre.text)?;
    let mut p = Parser { tokens, pos: 0, script: Script { classes: vec![String::new()], params: pre.params, ..Script::default() }, site: 0, pending: Vec::new() };
    p.program()?;
    p.resolve()?;
    Ok(p.script)
}

#[derive(Debug, Clone, PartialEq)]
struct Token {
    text: String,
    span: Span,
}

/// Splits the preprocessed text into tokens, dropping comments.
fn tokenize(text: &str) -> Result<Vec<Token>, ParseError> {
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
fn number(text: &str) -> Option<(f64, bool)> {
    if !text.starts_with(|c: char| c == '+' || c == '-' || c.is_ascii_digit()) {
        return None;
    }
    if let Some((a, b)) = text.split_once('/') {
        let (a, b) = (a.parse::<i64>().ok()?, b.parse::<i64>().ok()?);
        return (b != 0).then(|| (a as f64 / b as f64, false));
    }
    if let Ok(i) = text.parse::<i64>() {
        return Some((i as f64, true));
    }
    text.parse::<f64>().ok().filter(|v| v.is_finite()).map(|v| (v, false))
}

/// Parses a viewer setting's value: `[x y z]`, `[9 numbers]` or a number.
fn camera_setting(key: &str, value: &str, span: Span) -> Result<CameraSetting, ParseError> {
    let nums: Vec<f64> = value
        .trim_matches(|c| c == '[' || c == ']')
        .split(|c: char| c.is_whitespace() || c == ',')
        .filter(|w| !w.is_empty())
        .map(|w| number(w).map(|n| n.0))
        .collect::<Option<_>>()
        .ok_or_else(|| ParseError::single(span, format!("`set {key}`: `{value}` is not a list of numbers")))?;
    let want = match key {
        "rotation" => 9,
        "translation" | "pivot" => 3,
        _ => 1,
    };
    if nums.len() != want {
        return Err(ParseError::single(span, format!("`set {key}` expects {want} number(s), found `{value}`")));
    }
    Ok(match key {
        "translation" => CameraSetting::Translation(DVec3::from_slice(&nums)),
        "pivot" => CameraSetting::Pivot(DVec3::from_slice(&nums)),
        "rotation" => CameraSetting::Rotation(glam::DMat3::from_cols_slice(&nums).transpose()),
        "scale" => CameraSetting::Scale(nums[0]),
        _ => CameraSetting::PerspectiveAngle(nums[0]),
    })
}

/// Transformation operator names and their long forms.
fn operator(word: &str) -> Option<&'static str> {
    Some(match word {
        "x" => "x",
        "y" => "y",
        "z" => "z",
        "rx" => "rx",
        "ry" => "ry",
        "rz" => "rz",
        "s" => "s",
        "matrix" => "matrix",
        "fx" => "fx",
        "fy" => "fy",
        "fz" => "fz",
        "reflect" => "reflect",
        "h" | "hue" => "hue",
        "sat" => "sat",
        "b" | "brightness" | "v" => "brightness",
        "a" | "alpha" => "alpha",
        "c" | "color" | "colour" => "color",
        "blend" => "blend",
        "md" | "maxdepth" => "maxdepth",
        "w" | "weight" => "weight",
        _ => return None,
    })
}

/// Translation by `v`, then `m` about the centre of the unit cube or an axis through it.
fn about(centre: DVec3, m: DMat4) -> DMat4 {
    DMat4::from_translation(centre) * m * DMat4::from_translation(-centre)
}

struct Parser {
    tokens: Vec<Token>,
    pos: usize,
    script: Script,
    site: u32,
    /// Unresolved targets: (rule index or None for top level, action index, name, span), and retirements.
    pending: Vec<Pending>,
}

struct Pending {
    /// `None` for a top-level action.
    rule: Option<usize>,
    /// Index of the action in its list; `None` for the rule's retirement target.
    action: Option<usize>,
    name: String,
    span: Span,
}

impl Parser {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.pos)
    }

    fn end_span(&self) -> Span {
        self.tokens.last().map_or(Span::new(1, 1), |t| t.span)
    }

    fn next(&mut self, what: &str) -> Result<Token, ParseError> {
        match self.tokens.get(self.pos) {
            Some(t) => {
                self.pos += 1;
                Ok(t.clone())
            }
            None => Err(ParseError::single(self.end_span(), format!("unexpected end of script: expected {what}"))),
        }
    }

    fn lower(&self) -> Option<String> {
        self.peek().map(|t| t.text.to_ascii_lowercase())
    }

    fn num(&mut self, what: &str) -> Result<f64, ParseError> {
        let t = self.next(what)?;
        number(&t.text).map(|(v, _)| v).ok_or_else(|| ParseError::single(t.span, format!("{what}: expected a number, found `{}`", t.text)))
    }

    fn program(&mut self) -> Result<(), ParseError> {
        while let Some(word) = self.lower() {
            if word == "rule" {
                self.rule()?;
            } else {
                let a = self.statement(None)?;
                self.script.top.push(a);
            }
        }
        Ok(())
    }

    fn rule(&mut self) -> Result<(), ParseError> {
        let start = self.next("rule")?.span;
        let name_tok = self.next("a rule name")?;
        let name = name_tok.text.to_ascii_lowercase();
        if name == "{" || operator(&name).is_some() || number(&name).is_some() {
            return Err(ParseError::single(name_tok.span, format!("expected a rule name after `rule`, found `{}`", name_tok.text)));
        }
        if Primitive::from_name(&name).is_some() || name.starts_with("triangle[") {
            return Err(ParseError::single(name_tok.span, format!("`{name}` is a built-in primitive and cannot be redefined")));
        }
        let id = self.name_id(&name);
        let index = self.script.rules.len();
        let mut def = RuleDef { name: id, weight: 1.0, maxdepth: None, retirement: None, actions: Vec::new(), span: start };
        loop {
            let Some(t) = self.peek().cloned() else {
                return Err(ParseError::single(self.end_span(), format!("rule `{name}`: expected `{{`")));
            };
            if t.text == "{" {
                self.pos += 1;
                break;
            }
            match operator(&t.text.to_ascii_lowercase()) {
                Some("weight") => {
                    self.pos += 1;
                    let w = self.num("rule modifier `weight`")?;
                    if w < 0.0 {
                        return Err(ParseError::single(t.span, format!("rule `{name}`: weight must be ≥ 0, found {w}")));
                    }
                    def.weight = w;
                }
                Some("maxdepth") => {
                    self.pos += 1;
                    let n = self.next("a maxdepth")?;
                    match number(&n.text) {
                        Some((v, true)) => def.maxdepth = Some(v as i64),
                        _ => return Err(ParseError::single(n.span, format!("rule modifier `maxdepth` expects a whole number, found `{}`", n.text))),
                    }
                    if self.peek().is_some_and(|t| t.text == ">") {
                        self.pos += 1;
                        let r = self.next("a retirement rule name")?;
                        self.pending.push(Pending { rule: Some(index), action: None, name: r.text.to_ascii_lowercase(), span: r.span });
                    }
                }
                _ => {
                    return Err(ParseError::single(t.span, format!("rule `{name}`: expected `maxdepth`, `weight` or `{{`, found `{}`", t.text)));
                }
            }
        }
        self.script.rules.push(def);
        self.script.groups[id as usize].push(index as u32);
        loop {
            match self.peek() {
                None => return Err(ParseError::single(start, format!("rule `{name}` is not closed with `}}`"))),
                Some(t) if t.text == "}" => {
                    self.pos += 1;
                    break;
                }
                Some(t) if t.text.eq_ignore_ascii_case("rule") => {
                    return Err(ParseError::single(t.span, format!("rule `{name}` is not closed with `}}` before the next rule")));
                }
                Some(_) => {
                    let a = self.statement(Some(index))?;
                    self.script.rules[index].actions.push(a);
                }
            }
        }
        Ok(())
    }

    fn name_id(&mut self, name: &str) -> u32 {
        if let Some(i) = self.script.names.iter().position(|n| n == name) {
            return i as u32;
        }
        self.script.names.push(name.to_string());
        self.script.groups.push(Vec::new());
        (self.script.names.len() - 1) as u32
    }

    /// One `set` or action, inside rule `rule` (or at the top level).
    fn statement(&mut self, rule: Option<usize>) -> Result<Action, ParseError> {
        let first = self.peek().cloned().ok_or_else(|| ParseError::single(self.end_span(), "unexpected end of script"))?;
        if first.text.eq_ignore_ascii_case("set") {
            self.pos += 1;
            return self.set(first.span);
        }
        let mut loops = Vec::new();
        loop {
            let t = self.peek().cloned().ok_or_else(|| ParseError::single(self.end_span(), "unexpected end of script: expected a rule name"))?;
            if t.text == "{" {
                let transform = self.transform_list()?;
                loops.push(Loop { count: 1, transform });
                // `{ t } name`: only a rule name may follow.
                let n = self.next("a rule name after the transformation list")?;
                return self.call(rule, loops, n, first.span);
            }
            if let Some((v, integer)) = number(&t.text) {
                if !integer || v < 0.0 {
                    return Err(ParseError::single(t.span, format!("a loop count must be a whole number ≥ 0, found `{}`", t.text)));
                }
                self.pos += 1;
                let star = self.next("`*` after the loop count")?;
                if star.text != "*" {
                    return Err(ParseError::single(star.span, format!("expected `*` after the loop count, found `{}`", star.text)));
                }
                if self.peek().is_none_or(|t| t.text != "{") {
                    return Err(ParseError::single(star.span, "expected `{` after `*`"));
                }
                let transform = self.transform_list()?;
                loops.push(Loop { count: v.min(f64::from(u32::MAX)) as u32, transform });
                continue;
            }
            if t.text == "}" || t.text == "*" || t.text == ">" || operator(&t.text.to_ascii_lowercase()).is_some() {
                return Err(ParseError::single(
                    t.span,
                    format!("an action must start with a number, a rule name or `{{`, found `{}`", t.text),
                ));
            }
            self.pos += 1;
            return self.call(rule, loops, t, first.span);
        }
    }

    fn call(&mut self, rule: Option<usize>, loops: Vec<Loop>, name: Token, span: Span) -> Result<Action, ParseError> {
        let lower = name.text.to_ascii_lowercase();
        if lower == "{" || lower == "}" || number(&lower).is_some() || operator(&lower).is_some() {
            return Err(ParseError::single(name.span, format!("expected a rule name, found `{}`", name.text)));
        }
        let action_index = match rule {
            Some(r) => self.script.rules[r].actions.len(),
            None => self.script.top.len(),
        };
        self.pending.push(Pending { rule, action: Some(action_index), name: lower, span: name.span });
        let site = self.site;
        self.site += 1;
        // The target is filled in by `resolve` once every rule is known.
        Ok(Action::Call { loops, target: Target::Rule(u32::MAX), site, span })
    }

    fn transform_list(&mut self) -> Result<Transform, ParseError> {
        let open = self.next("`{`")?;
        let mut t = Transform::default();
        loop {
            let tok = self.next("a transformation or `}`")?;
            if tok.text == "}" {
                return Ok(t);
            }
            let lower = tok.text.to_ascii_lowercase();
            // `m` is the matrix operator only inside a list: Structure Synth's
            // tokenizer knows only `matrix`, so scripts name rules `m`.
            let Some(op) = operator(&lower).or((lower == "m").then_some("matrix")) else {
                return Err(ParseError::single(
                    tok.span,
                    format!("unknown transformation `{}` (the list opened at {}:{} is not closed?)", tok.text, open.span.line, open.span.column),
                ));
            };
            let step = self.transformation(op, &tok)?;
            t.append(&step);
        }
    }

    fn transformation(&mut self, op: &str, tok: &Token) -> Result<Transform, ParseError> {
        let half = 0.5;
        let mut t = Transform::default();
        match op {
            "x" | "y" | "z" => {
                let v = self.num(&format!("`{op}`"))?;
                let mut d = DVec3::ZERO;
                d[(op.as_bytes()[0] - b'x') as usize] = v;
                t.matrix = DMat4::from_translation(d);
            }
            "rx" | "ry" | "rz" => {
                let a = self.num(&format!("`{op}`"))?.to_radians();
                t.matrix = match op {
                    "rx" => about(DVec3::new(0.0, half, half), DMat4::from_rotation_x(a)),
                    "ry" => about(DVec3::new(half, 0.0, half), DMat4::from_rotation_y(a)),
                    _ => about(DVec3::new(half, half, 0.0), DMat4::from_rotation_z(a)),
                };
            }
            "s" => {
                let a = self.num("`s`")?;
                let s = if self.peek().is_some_and(|t| number(&t.text).is_some()) {
                    let b = self.num("`s` (second factor)")?;
                    let c = self.num("`s` (third factor)")?;
                    DVec3::new(a, b, c)
                } else {
                    DVec3::splat(a)
                };
                t.matrix = about(DVec3::splat(half), DMat4::from_scale(s));
            }
            "matrix" => {
                let mut v = [0.0; 9];
                for (k, slot) in v.iter_mut().enumerate() {
                    *slot = self.num(&format!("`m` (entry {} of 9)", k + 1))?;
                }
                // Arguments are row-major; glam stores columns.
                let m = glam::DMat3::from_cols_array(&v).transpose();
                t.matrix = about(DVec3::splat(half), DMat4::from_mat3(m));
            }
            "fx" | "fy" | "fz" => {
                let mut s = DVec3::ONE;
                s[(op.as_bytes()[1] - b'x') as usize] = -1.0;
                t.matrix = about(DVec3::splat(half), DMat4::from_scale(s));
            }
            "reflect" => {
                let n = DVec3::new(self.num("`reflect`")?, self.num("`reflect`")?, self.num("`reflect`")?);
                let n = n.normalize_or_zero();
                if n == DVec3::ZERO {
                    return Err(ParseError::single(tok.span, "`reflect` needs a non-zero normal"));
                }
                let m = glam::DMat3::IDENTITY - 2.0 * glam::DMat3::from_cols(n * n.x, n * n.y, n * n.z);
                t.matrix = DMat4::from_mat3(m);
            }
            "hue" => t.delta_h = self.num("`hue`")?,
            "sat" => t.scale_s = self.num("`sat`")?,
            "brightness" => t.scale_v = self.num("`brightness`")?,
            "alpha" => t.scale_a = self.num("`alpha`")?,
            "color" => {
                let c = self.next("a colour")?;
                t.absolute = true;
                if c.text.eq_ignore_ascii_case("random") {
                    t.delta_h = 1000.0;
                } else {
                    let rgb = colour::parse(&c.text).ok_or_else(|| ParseError::single(c.span, format!("`color`: `{}` is not a colour", c.text)))?;
                    let [h, s, v] = colour::rgb_to_hsv(rgb);
                    (t.delta_h, t.scale_s, t.scale_v, t.scale_a) = (h, s, v, 1.0);
                }
            }
            "blend" => {
                let c = self.next("a colour")?;
                let rgb = colour::parse(&c.text).ok_or_else(|| ParseError::single(c.span, format!("`blend`: `{}` is not a colour", c.text)))?;
                let strength = self.num("`blend` strength")?;
                t.blend = (strength != 0.0).then_some((colour::rgb_to_hsv(rgb), strength));
            }
            _ => {
                return Err(ParseError::single(tok.span, format!("`{}` is a rule modifier, not a transformation", tok.text)));
            }
        }
        Ok(t)
    }

    fn set(&mut self, span: Span) -> Result<Action, ParseError> {
        let key = self.next("a setting name after `set`")?;
        let value = self.next(&format!("a value for `set {}`", key.text))?;
        let k = key.text.to_ascii_lowercase();
        let v = value.text.as_str();
        let vl = v.to_ascii_lowercase();
        let int = |what: &str| -> Result<i64, ParseError> {
            match number(v) {
                Some((n, true)) => Ok(n as i64),
                _ => Err(ParseError::single(value.span, format!("`set {what}` expects a whole number, found `{v}`"))),
            }
        };
        let float = |what: &str| -> Result<f64, ParseError> {
            number(v).map(|(n, _)| n).ok_or_else(|| ParseError::single(value.span, format!("`set {what}` expects a number, found `{v}`")))
        };
        let setting = match k.as_str() {
            "maxdepth" => Setting::MaxDepth(int("maxdepth")?),
            "maxobjects" => Setting::MaxObjects(int("maxobjects")?),
            "minsize" => Setting::MinSize(float("minsize")?),
            "maxsize" => Setting::MaxSize(float("maxsize")?),
            "seed" if vl == "initial" => Setting::Seed(None),
            "seed" => Setting::Seed(Some(int("seed")?)),
            "background" => Setting::Background(
                colour::parse(v).ok_or_else(|| ParseError::single(value.span, format!("`set background`: `{v}` is not a colour")))?,
            ),
            "colorpool" => Setting::ColourPool(self.pool(v, value.span)?),
            "syncrandom" => match vl.as_str() {
                "true" => Setting::SyncRandom(true),
                "false" => Setting::SyncRandom(false),
                _ => return Err(ParseError::single(value.span, format!("`set syncrandom` expects true or false, found `{v}`"))),
            },
            "recursion" => {
                self.script.depth_first |= vl == "depth";
                Setting::Ignored
            }
            "rng" if vl == "old" || vl == "new" => Setting::Ignored,
            "translation" | "rotation" | "pivot" | "scale" | "perspective-angle" => Setting::Camera(camera_setting(&k, v, value.span)?),
            "opengl" | "template" => Setting::Ignored,
            _ if k.starts_with("raytracer::") => {
                self.script.warnings.push(Diagnostic::warning(key.span, format!("`set {k}` configures Structure Synth's raytracer; it is ignored")));
                Setting::Ignored
            }
            _ => return Err(ParseError::single(key.span, format!("unknown setting `set {}`", key.text))),
        };
        Ok(Action::Set(setting, span))
    }

    fn pool(&self, v: &str, span: Span) -> Result<ColourPool, ParseError> {
        let lower = v.to_ascii_lowercase();
        match lower.as_str() {
            "randomhue" => return Ok(ColourPool::RandomHue),
            "randomrgb" => return Ok(ColourPool::RandomRgb),
            "greyscale" | "grayscale" => return Ok(ColourPool::Greyscale),
            _ => {}
        }
        if lower.starts_with("image:") {
            return Err(ParseError::single(span, "`set colorpool image:…` samples a local image file, which a render service cannot read; use a `list:` pool"));
        }
        if let Some(list) = v.get(5..).filter(|_| lower.starts_with("list:")) {
            let colours = list
                .split(',')
                .map(|c| colour::parse(c.trim()).ok_or_else(|| ParseError::single(span, format!("`set colorpool list:…`: `{c}` is not a colour"))))
                .collect::<Result<Vec<_>, _>>()?;
            if colours.is_empty() {
                return Err(ParseError::single(span, "`set colorpool list:` needs at least one colour"));
            }
            return Ok(ColourPool::List(colours));
        }
        Err(ParseError::single(span, format!("unknown colour pool `{v}` (known: randomhue, randomrgb, greyscale, list:c1,c2,…)")))
    }

    /// Fills in every call's target now that every rule name is known.
    fn resolve(&mut self) -> Result<(), ParseError> {
        let pending = std::mem::take(&mut self.pending);
        for p in pending {
            let target = self.target(&p.name, p.span)?;
            match (p.rule, p.action) {
                (Some(r), None) => self.script.rules[r].retirement = Some(target),
                (rule, Some(a)) => {
                    let list = match rule {
                        Some(r) => &mut self.script.rules[r].actions,
                        None => &mut self.script.top,
                    };
                    if let Some(Action::Call { target: t, .. }) = list.get_mut(a) {
                        *t = target;
                    }
                }
                (None, None) => {}
            }
        }
        Ok(())
    }

    fn class_id(&mut self, class: &str) -> u32 {
        if let Some(i) = self.script.classes.iter().position(|c| c == class) {
            return i as u32;
        }
        self.script.classes.push(class.to_string());
        (self.script.classes.len() - 1) as u32
    }

    fn target(&mut self, name: &str, span: Span) -> Result<Target, ParseError> {
        let (base, class) = match name.split_once("::") {
            Some((b, c)) => (b, c),
            None => (name, ""),
        };
        if let Some(inner) = base.strip_prefix("triangle[").and_then(|r| r.strip_suffix(']')) {
            let pts: Vec<Option<DVec3>> = inner
                .split(';')
                .map(|p| {
                    let v: Vec<f64> = p.split(',').filter_map(|x| number(x.trim()).map(|n| n.0)).collect();
                    (v.len() == 3 && p.split(',').count() == 3).then(|| DVec3::new(v[0], v[1], v[2]))
                })
                .collect();
            return match pts.as_slice() {
                [Some(a), Some(b), Some(c)] => Ok(Target::Triangle([*a, *b, *c], self.class_id(class))),
                _ => Err(ParseError::single(span, format!("`{name}`: a triangle needs three points `x,y,z` separated by `;`"))),
            };
        }
        if let Some(p) = Primitive::from_name(base) {
            return Ok(Target::Primitive(p, self.class_id(class)));
        }
        match self.script.names.iter().position(|n| n == name) {
            Some(i) if !self.script.groups[i].is_empty() => Ok(Target::Rule(i as u32)),
            _ => Err(ParseError::single(span, format!("no rule or primitive named `{name}`"))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(src: &str) -> Result<Script, ParseError> {
        parse(src.as_bytes(), &ParseOptions::default())
    }

    #[test]
    fn parses_the_reference_sample() {
        let s = p("/* torus */\nset maxdepth 100\nr1\n36 * { x -2 ry 10 } r1\nrule r1 maxdepth 10 {\n 2 * { y -1 } 3 * { rz 15 x 1 b 0.9 h -20 } r2\n { y 1 h 12 a 0.9 rx 36 } r1\n}\nrule r2 {\n { s 0.9 0.1 1.1 hue 10 } box // c\n}\nrule r2 w 2 {\n { hue 113 sat 19 a 23 } sphere::shiny\n}\n").unwrap();
        assert_eq!(s.names, ["r1", "r2"]);
        assert_eq!(s.groups[1].len(), 2);
        assert_eq!(s.rules[0].maxdepth, Some(10));
        assert_eq!(s.rules[2].weight, 2.0);
        assert_eq!(s.classes, ["", "shiny"]);
        assert_eq!(s.top.len(), 3);
        match &s.rules[0].actions[0] {
            Action::Call { loops, target, .. } => {
                assert_eq!(loops.iter().map(|l| l.count).collect::<Vec<_>>(), [2, 3]);
                assert_eq!(*target, Target::Rule(1));
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn errors_have_positions() {
        let e = p("rule r {\n  { x 1 foo 2 } box\n}\n").unwrap_err();
        assert_eq!((e.diagnostics[0].span.line, e.diagnostics[0].span.column), (2, 9));
        let e = p("box\nnothere\n").unwrap_err();
        assert_eq!(e.diagnostics[0].span.line, 2);
        assert!(p("set colorpool image:a.png\nbox").unwrap_err().to_string().contains("image"));
        assert!(p("#javascript\nBuilder.build();").is_err());
        assert!(p("rule r {\n box\n").is_err());
        // Transformation names are not rule names, as in Structure Synth.
        assert!(p("rule a { box }\n").is_err());
        assert!(p("3 * x 1 } box").is_err());
    }

    #[test]
    fn triangles_classes_and_retirement() {
        let s = p("rule r md 3 > e { r triangle[0,0,0;1,0,0;0,1,0]::glass }\nrule e { box }\nr\n").unwrap();
        assert_eq!(s.rules[0].retirement, Some(Target::Rule(1)));
        assert!(matches!(&s.rules[0].actions[1], Action::Call { target: Target::Triangle(_, 1), .. }));
        assert!(looks_like_eisenscript("set maxdepth 10\nbox"));
        assert!(looks_like_eisenscript("rule r md 3 { box }"));
        assert!(!looks_like_eisenscript("startshape A\nrule A { BOX {} }"));
    }
}
