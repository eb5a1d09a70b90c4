//! EisenScript, the language of Structure Synth 1.5 (see `docs/eisenscript.md`).
//!
//! The front end reads a script into a [`Script`]: rule definitions, the
//! top-level actions (Structure Synth's start rule) and, per action, the
//! transformation loops as composed 4×4 affine matrices with their colour
//! changes. It does not lower into the shared rule IR ([`crate::ir`]):
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
//!
//! The parts of the front end, in the order a script meets them:
//! [`preprocess`] (`#define`s and GUI parameters), `tokens.rs` (the
//! tokenizer), `parser.rs` (rules, actions and loops, with `transforms.rs`
//! for transformation lists and `settings.rs` for `set` commands) and
//! [`colour`] (colour names and HSV).

pub mod colour;
pub mod preprocess;

use crate::core::{Diagnostic, ParseError, Span};
use glam::{DMat4, DVec3};

pub(crate) use preprocess::GuiParam;

/// True when `text` is a Structure Synth JavaScript script (its first
/// non-blank line starts with `#javascript`).
pub fn is_javascript(text: &[u8]) -> bool {
    let start = text.iter().position(|b| !b.is_ascii_whitespace()).unwrap_or(text.len());
    text[start..].get(..11).is_some_and(|p| p.eq_ignore_ascii_case(b"#javascript"))
}

mod parser;
mod tokens;

use tokens::tokenize;

/// Guesses whether `text` is EisenScript (used when no language is named).
/// Looks for what MDG and L-systems never write: `#define`/`#javascript`
/// lines, `set maxdepth|maxobjects|background|…` lines and `md`/`w` rule modifiers.
pub(crate) fn looks_like_eisenscript(text: &str) -> bool {
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
    /// True when applying it draws a colour from the pool (`color random`,
    /// which Structure Synth stores as an absolute hue above 360).
    pub(crate) fn draws_colour(&self) -> bool {
        self.absolute && self.delta_h > 360.0
    }

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
    /// `set maxdepth N` (or `set md N`): generations (breadth-first), or the
    /// depth of ambiguous rules' definitions (depth-first, see `crate::eisen::build`).
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
    parser::parse_tokens(tokens, pre.params)
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
