//! The words of a modifier stage (`subdivide 2 weight 1.4`) and Haglund
//! 2009's stacking string (`b1.5s1.4w0.1`), turned into [`Modifier`]s.
//!
//! Kept apart from the MDG parser so the MDG side only collects a stage's
//! words (names and constant numbers) and every front end shares one
//! definition of each modifier's parameters and errors.

use super::{Axis, Extrude, FaceSelect, MeshBase, Modifier};
use crate::core::PrimitiveKind;
use glam::DVec3;

/// One word of a stage after the modifier's name.
#[derive(Debug, Clone, PartialEq)]
pub enum Word {
    /// A constant number.
    Num(f64),
    /// A keyword (`weight`, `x`, `random`, …), lower-cased.
    Key(String),
}

/// Reads a stage's words left to right.
struct Cursor<'a> {
    words: &'a [Word],
    pos: usize,
    op: &'a str,
}

impl Cursor<'_> {
    fn num(&mut self) -> Option<f64> {
        match self.words.get(self.pos) {
            Some(Word::Num(v)) => {
                self.pos += 1;
                Some(*v)
            }
            _ => None,
        }
    }

    fn need(&mut self, what: &str) -> Result<f64, String> {
        self.num().ok_or_else(|| format!("`{}` needs a number for {what}", self.op))
    }

    fn key(&mut self) -> Option<String> {
        match self.words.get(self.pos) {
            Some(Word::Key(k)) => {
                self.pos += 1;
                Some(k.clone())
            }
            _ => None,
        }
    }

    fn whole(&mut self, what: &str, max: f64) -> Result<u32, String> {
        let v = self.need(what)?;
        whole(self.op, what, v, max)
    }

    fn seed(&mut self) -> Result<u64, String> {
        Ok(u64::from(self.whole("seed", f64::from(u32::MAX))?))
    }

    fn done(&self) -> Result<(), String> {
        match self.words.get(self.pos) {
            None => Ok(()),
            Some(Word::Num(v)) => Err(format!("`{}`: unexpected number {v}", self.op)),
            Some(Word::Key(k)) => Err(format!("`{}`: unknown option `{k}`", self.op)),
        }
    }
}

fn whole(op: &str, what: &str, v: f64, max: f64) -> Result<u32, String> {
    if v < 0.0 || v.fract() != 0.0 || v > max {
        return Err(format!("`{op}`: {what} must be a whole number in 0..={max}, found {v}"));
    }
    Ok(v as u32)
}

fn axis(op: &str, k: Option<String>) -> Result<Axis, String> {
    match k.as_deref() {
        Some("x") => Ok(Axis::X),
        Some("y") => Ok(Axis::Y),
        Some("z") => Ok(Axis::Z),
        _ => Err(format!("`{op}` needs an axis `x`, `y` or `z`")),
    }
}

/// Most subdivision levels one stage may ask for (20·4¹² is already 335M faces;
/// the budget stops far earlier, this only bounds the size arithmetic).
pub(crate) const MAX_LEVELS: f64 = 12.0;
/// Most stacked extrusion steps per face.
pub(crate) const MAX_STEPS: f64 = 1000.0;

/// Parses one stage: the modifier `name` (case-insensitive) and its words.
pub fn stage(name: &str, words: &[Word]) -> Result<Modifier, String> {
    let op = name.to_ascii_lowercase();
    let mut c = Cursor { words, pos: 0, op: name };
    let m = match op.as_str() {
        "subdivide" | "split" => {
            let levels = match c.num() {
                Some(v) => whole(name, "the level count", v, MAX_LEVELS)?,
                None => 1,
            };
            let (mut weight, mut smooth) = (1.0, op == "subdivide");
            while let Some(k) = c.key() {
                match k.as_str() {
                    "weight" => weight = c.need("the weight")?,
                    "smooth" => smooth = true,
                    "nosmooth" => smooth = false,
                    other => return Err(format!("`{name}`: unknown option `{other}` (weight, smooth, nosmooth)")),
                }
            }
            Modifier::Subdivide { levels, weight, smooth }
        }
        "spikeify" => Modifier::Spikeify { height: c.need("the spike height")? },
        "randomize" => {
            let amount = c.need("the amount")?;
            let seed = if c.key().as_deref() == Some("seed") { c.seed()? } else { 0 };
            Modifier::Randomize { amount, seed }
        }
        "displace" => {
            let amount = c.need("the amount")?;
            let (mut fraction, mut seed) = (1.0, 0);
            while let Some(k) = c.key() {
                match k.as_str() {
                    "fraction" => fraction = c.need("the fraction")?,
                    "seed" => seed = c.seed()?,
                    other => return Err(format!("`{name}`: unknown option `{other}` (fraction, seed)")),
                }
            }
            Modifier::Displace { amount, fraction, seed }
        }
        "extrude" => Modifier::Extrude(extrude(&mut c)?),
        "mirror" => {
            let axis = axis(name, c.key())?;
            Modifier::Mirror { axis, offset: c.num().unwrap_or(0.0) }
        }
        "twist" => {
            let degrees_per_unit = c.need("the degrees per unit")?;
            let axis = match c.key() {
                None => Axis::Y,
                k => axis(name, k)?,
            };
            Modifier::Twist { axis, degrees_per_unit }
        }
        "bend" => Modifier::Bend { degrees: c.need("the angle")? },
        "translate" => Modifier::Translate(DVec3::new(c.need("x")?, c.need("y")?, c.need("z")?)),
        "scale" => {
            let x = c.need("the factor")?;
            let v = match (c.num(), c.num()) {
                (Some(y), Some(z)) => DVec3::new(x, y, z),
                (None, None) => DVec3::splat(x),
                _ => return Err(format!("`{name}` takes one factor or three")),
            };
            Modifier::Scale(v)
        }
        _ => {
            return Err(format!(
                "unknown modifier `{name}` (subdivide, split, spikeify, randomize, extrude, displace, mirror, twist, bend, translate, scale)"
            ))
        }
    };
    c.done()?;
    Ok(m)
}

/// `extrude [all | random P | faces I J …] [length MIN [MAX]] [tilt DEG] [scale S] [steps N] [seed S]`.
fn extrude(c: &mut Cursor) -> Result<Extrude, String> {
    let mut x = Extrude::default();
    while let Some(k) = c.key() {
        match k.as_str() {
            "all" => x.select = FaceSelect::All,
            "random" => x.select = FaceSelect::Random(c.need("the random fraction")?),
            "faces" => {
                let mut list = Vec::new();
                while let Some(v) = c.num() {
                    list.push(whole(c.op, "a face index", v, f64::from(u32::MAX - 1))?);
                }
                if list.is_empty() {
                    return Err("`extrude faces` needs at least one face index".into());
                }
                x.select = FaceSelect::Faces(list);
            }
            "length" => {
                let lo = c.need("the length")?;
                x.length = (lo, c.num().unwrap_or(lo));
            }
            "tilt" => x.tilt = c.need("the tilt")?,
            "scale" => x.scale = c.need("the scale")?,
            "steps" => x.steps = c.whole("the step count", MAX_STEPS)?,
            "seed" => x.seed = c.seed()?,
            other => return Err(format!("`extrude`: unknown option `{other}` (all, random, faces, length, tilt, scale, steps, seed)")),
        }
    }
    x.validate().map_err(|e| format!("`extrude`: {e}"))?;
    Ok(x)
}

/// A parsed stacking string: the primitive, its size and the modifier chain.
#[derive(Debug, Clone, PartialEq)]
pub struct Stack {
    /// The primitive.
    pub base: MeshBase,
    /// The modifiers in order; the first scales the primitive to its size.
    pub modifiers: Vec<Modifier>,
}

/// Parses a stacking string (Haglund 2009, Appendix A): letters each
/// followed by an optional real (default 1). Primitives `b` box, `t`
/// tetrahedron, `o` octahedron, `c` cylinder (Haglund's) and `i` icosahedron,
/// `d` dodecahedron, `p` sphere (ours) take their size (edge for the box,
/// circumradius × 2 otherwise, i.e. a uniform scale of the unit primitive) and
/// must come first, once. Modifiers: `s` subdivide once with the weight,
/// `n` split once (no smoothing), `r` randomize by the amount, `x` set the
/// seed of later random letters, `w` spikeify by the height, `v` displace
/// every vertex by the amount. Whitespace between items is allowed.
pub fn stack(text: &str) -> Result<Stack, String> {
    let mut base: Option<MeshBase> = None;
    let mut modifiers = Vec::new();
    let mut seed = 0u64;
    let mut chars = text.char_indices().peekable();
    while let Some((i, letter)) = chars.next() {
        if letter.is_whitespace() {
            continue;
        }
        let start = i + letter.len_utf8();
        let mut end = start;
        while let Some(&(j, ch)) = chars.peek() {
            if ch.is_ascii_digit() || ch == '.' || ((ch == '-' || ch == '+') && j == start) {
                end = j + ch.len_utf8();
                chars.next();
            } else {
                break;
            }
        }
        let value = if end > start {
            let t = &text[start..end];
            let v: f64 = t.parse().map_err(|_| format!("column {}: `{t}` is not a number", start + 1))?;
            if !v.is_finite() {
                return Err(format!("column {}: `{t}` is not a finite number", start + 1));
            }
            v
        } else {
            1.0
        };
        let at = format!("column {}", i + 1);
        let kind = match letter {
            'b' => Some(PrimitiveKind::Box),
            't' => Some(PrimitiveKind::Tetrahedron),
            'o' => Some(PrimitiveKind::Octahedron),
            'c' => Some(PrimitiveKind::Cylinder),
            'i' => Some(PrimitiveKind::Icosahedron),
            'd' => Some(PrimitiveKind::Dodecahedron),
            'p' => Some(PrimitiveKind::Sphere),
            _ => None,
        };
        if let Some(kind) = kind {
            if base.is_some() {
                return Err(format!("{at}: a stacking string has one primitive; `{letter}` is a second"));
            }
            if value <= 0.0 {
                return Err(format!("{at}: primitive size must be positive, found {value}"));
            }
            base = Some(MeshBase::Primitive(kind));
            modifiers.push(Modifier::Scale(DVec3::splat(value)));
            continue;
        }
        if base.is_none() {
            return Err(format!("{at}: a stacking string starts with a primitive (b, t, o, c, i, d, p), found `{letter}`"));
        }
        let salt = modifiers.len() as u64;
        let m = match letter {
            's' => Modifier::Subdivide { levels: 1, weight: value, smooth: true },
            'n' => Modifier::Subdivide { levels: 1, weight: 1.0, smooth: false },
            'r' => Modifier::Randomize { amount: value, seed: seed.wrapping_mul(0x1_0000).wrapping_add(salt) },
            'w' => Modifier::Spikeify { height: value },
            'v' => Modifier::Displace { amount: value, fraction: 1.0, seed: seed.wrapping_mul(0x1_0000).wrapping_add(salt) },
            'x' => {
                seed = whole("x", "the seed", value, f64::from(u32::MAX))?.into();
                continue;
            }
            other => return Err(format!("{at}: unknown stacking letter `{}`", other.escape_debug())),
        };
        modifiers.push(m);
    }
    let base = base.ok_or("an empty stacking string: expected a primitive letter (b, t, o, c, i, d, p)")?;
    Ok(Stack { base, modifiers })
}
