//! UniGrafix import (`language: "ug"`, `.ug` files): the safe subset of
//! Berkeley UniGrafix (Séquin (ed.) 1992) as a drawable mesh.
//!
//! Accepted: `v id x y z;`, `f (v1 v2 v3 …) [colour];` (convex polygons,
//! fanned; no holes), `c id r g b;`, `def name; … end;` and
//! `i (name [-tx x] [-ty y] [-tz z] [-rx deg] [-ry deg] [-rz deg] [-sa s]);`
//! with nested `{ … }` comments. Ignored with a warning: `w` (wires), `l`
//! (lights), `cam`. Rejected: `include` and `execute` (they read files and run
//! programs), escapes, 4-D vertices, holes. Instances are expanded under a
//! depth limit, with cycles rejected and the expanded size bounded before it
//! is built. The result lowers to a program drawing one mesh, so it renders
//! in every format and takes modifiers like any `mesh` base.

use crate::ir::{MeshDecl, Program};
use crate::{Diagnostic, ParseError, Span};
use crate::geom::assembly::{Assembly, Part};
use crate::geom::modifiers::MeshBase;
use glam::{DMat4, DVec3};
use std::collections::HashMap;
use std::sync::Arc;

/// Deepest instance nesting accepted.
const MAX_DEPTH: usize = 32;
/// Most triangles the expansion may produce (the render's budget, which
/// admits the expansion before it is built, is usually lower).
const MAX_TRIANGLES: u64 = 10_000_000;
/// Deepest comment nesting accepted.
const MAX_COMMENT_DEPTH: usize = 64;

fn err(line: u32, msg: impl Into<String>) -> ParseError {
    ParseError::single(Span::new(line, 1), msg)
}

/// One definition: vertices by id, faces as vertex-id lists, instances.
#[derive(Default)]
struct Def {
    verts: HashMap<String, DVec3>,
    faces: Vec<(Vec<String>, u32)>,
    instances: Vec<(String, DMat4, u32)>,
}

/// Splits the text into statements (token lists ending at `;`), with their line.
fn statements(text: &str) -> Result<Vec<(Vec<String>, u32)>, ParseError> {
    let mut out = Vec::new();
    let mut cur: Vec<String> = Vec::new();
    let mut word = String::new();
    let (mut line, mut start_line, mut depth) = (1u32, 1u32, 0usize);
    let flush = |word: &mut String, cur: &mut Vec<String>| {
        if !word.is_empty() {
            cur.push(std::mem::take(word));
        }
    };
    for c in text.chars() {
        if c == '\n' {
            line += 1;
        }
        if depth > 0 {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                _ => {}
            }
            if depth > MAX_COMMENT_DEPTH {
                return Err(err(line, "comments nested too deeply"));
            }
            continue;
        }
        match c {
            '{' => {
                flush(&mut word, &mut cur);
                depth = 1;
            }
            '}' => return Err(err(line, "`}` without an open comment")),
            ';' => {
                flush(&mut word, &mut cur);
                if !cur.is_empty() {
                    out.push((std::mem::take(&mut cur), start_line));
                }
            }
            '(' | ')' => {
                flush(&mut word, &mut cur);
                cur.push(c.to_string());
            }
            c if c.is_whitespace() => flush(&mut word, &mut cur),
            '#' | '`' | '\\' => return Err(err(line, format!("`{c}` (preprocessor lines and escapes) is not accepted"))),
            c => {
                if cur.is_empty() && word.is_empty() {
                    start_line = line;
                }
                word.push(c);
            }
        }
    }
    if depth > 0 {
        return Err(err(line, "unclosed `{` comment"));
    }
    flush(&mut word, &mut cur);
    if !cur.is_empty() {
        return Err(err(start_line, format!("statement `{}` is not ended with `;`", cur.join(" "))));
    }
    Ok(out)
}

fn number(s: &str, line: u32) -> Result<f64, ParseError> {
    s.parse::<f64>().ok().filter(|v| v.is_finite()).ok_or_else(|| err(line, format!("`{s}` is not a finite number")))
}

/// The items between `(` and `)` starting at `toks[i]`; returns them and the index after `)`.
fn group(toks: &[String], i: usize, line: u32) -> Result<(&[String], usize), ParseError> {
    if toks.get(i).map(String::as_str) != Some("(") {
        return Err(err(line, "expected `(`"));
    }
    let end = toks[i..].iter().position(|t| t == ")").ok_or_else(|| err(line, "missing `)`"))? + i;
    Ok((&toks[i + 1..end], end + 1))
}

/// An instance's transform from its `-tx … -sa` options.
fn transform(opts: &[String], line: u32) -> Result<DMat4, ParseError> {
    let mut m = DMat4::IDENTITY;
    let mut k = 0;
    while k < opts.len() {
        let v = number(opts.get(k + 1).ok_or_else(|| err(line, format!("`{}` needs a value", opts[k])))?, line)?;
        let step = match opts[k].as_str() {
            "-tx" => DMat4::from_translation(DVec3::X * v),
            "-ty" => DMat4::from_translation(DVec3::Y * v),
            "-tz" => DMat4::from_translation(DVec3::Z * v),
            "-rx" => DMat4::from_rotation_x(v.to_radians()),
            "-ry" => DMat4::from_rotation_y(v.to_radians()),
            "-rz" => DMat4::from_rotation_z(v.to_radians()),
            "-sa" if v > 0.0 => DMat4::from_scale(DVec3::splat(v)),
            "-sa" => return Err(err(line, "`-sa` must be positive")),
            other => return Err(err(line, format!("unknown instance option `{other}` (-tx -ty -tz -rx -ry -rz -sa)"))),
        };
        // Options apply in the order written, each to the result so far.
        m = step * m;
        k += 2;
    }
    Ok(m)
}

/// Parses UniGrafix text into the world (top-level) definition and named ones.
fn read(text: &str, warnings: &mut Vec<Diagnostic>) -> Result<(Def, HashMap<String, Def>), ParseError> {
    let mut world = Def::default();
    let mut defs: HashMap<String, Def> = HashMap::new();
    let mut open: Option<(String, Def)> = None;
    for (toks, line) in statements(text)? {
        let cur = match &mut open {
            Some((_, d)) => d,
            None => &mut world,
        };
        match toks[0].as_str() {
            "v" => {
                if toks.len() == 6 {
                    return Err(err(line, "4-D vertices are not accepted"));
                }
                if toks.len() != 5 {
                    return Err(err(line, "expected `v id x y z;`"));
                }
                let p = DVec3::new(number(&toks[2], line)?, number(&toks[3], line)?, number(&toks[4], line)?);
                cur.verts.insert(toks[1].clone(), p);
            }
            "f" => {
                let (ids, next) = group(&toks, 1, line)?;
                if toks.get(next).map(String::as_str) == Some("(") {
                    return Err(err(line, "faces with holes are not accepted"));
                }
                if ids.len() < 3 {
                    return Err(err(line, "a face needs at least 3 vertices"));
                }
                cur.faces.push((ids.to_vec(), line));
            }
            "c" => {
                if toks.len() < 5 {
                    return Err(err(line, "expected `c id r g b;`"));
                }
            }
            "def" => {
                if open.is_some() {
                    return Err(err(line, "`def` inside `def`"));
                }
                let name = toks.get(1).ok_or_else(|| err(line, "`def` needs a name"))?;
                open = Some((name.clone(), Def::default()));
            }
            "end" => {
                let (name, d) = open.take().ok_or_else(|| err(line, "`end` without `def`"))?;
                defs.insert(name, d);
            }
            "i" => {
                let start = if toks.get(1).map(String::as_str) == Some("(") { 1 } else { 2 };
                let (body, _) = group(&toks, start, line)?;
                let name = body.first().ok_or_else(|| err(line, "an instance names a definition"))?;
                let m = transform(&body[1..], line)?;
                cur.instances.push((name.clone(), m, line));
            }
            "w" | "l" | "cam" => warnings.push(Diagnostic::warning(Span::new(line, 1), format!("`{}` statement ignored", toks[0]))),
            "include" | "execute" => return Err(err(line, format!("`{}` is not accepted: it would read files or run programs", toks[0]))),
            other => return Err(err(line, format!("unknown statement `{other}` (v, f, c, def, end, i, w)"))),
        }
    }
    if let Some((name, _)) = open {
        return Err(err(1, format!("`def {name}` is not closed with `end`")));
    }
    Ok((world, defs))
}

/// Definitions resolved into [`Part`]s: vertex names into positions,
/// instance names into part indices, in the order the expansion meets them.
struct Resolver<'a> {
    defs: &'a HashMap<String, Def>,
    parts: Vec<Part>,
    /// Part index and instance height (deepest nesting below) of each resolved definition.
    resolved: HashMap<&'a str, (usize, usize)>,
    /// Names being resolved, outermost first (for cycles and the depth limit).
    stack: Vec<&'a str>,
}

impl<'a> Resolver<'a> {
    /// Resolves `d` (reached through `stack`) into a new part; returns its
    /// index and its instance height.
    fn resolve(&mut self, d: &'a Def) -> Result<(usize, usize), ParseError> {
        let mut polygons = Vec::with_capacity(d.faces.len());
        for (ids, line) in &d.faces {
            let corners = ids
                .iter()
                .map(|id| d.verts.get(id).copied().ok_or_else(|| err(*line, format!("face names vertex `{id}`, which this definition does not have"))))
                .collect::<Result<Vec<DVec3>, ParseError>>()?;
            polygons.push(corners);
        }
        let index = self.parts.len();
        self.parts.push(Part::default());
        let mut children = Vec::with_capacity(d.instances.len());
        let mut height = 0;
        for (name, t, line) in &d.instances {
            let level = self.stack.len();
            let too_deep = || err(*line, format!("instances nested deeper than {MAX_DEPTH}"));
            if level >= MAX_DEPTH {
                return Err(too_deep());
            }
            if self.stack.contains(&name.as_str()) {
                return Err(err(*line, format!("instance cycle through `{name}`")));
            }
            let (child, below) = match self.resolved.get(name.as_str()) {
                Some(&(child, below)) => {
                    if below > 0 && level + below >= MAX_DEPTH {
                        return Err(too_deep());
                    }
                    (child, below)
                }
                None => {
                    let (key, sub) = self.defs.get_key_value(name).ok_or_else(|| err(*line, format!("instance of unknown definition `{name}`")))?;
                    self.stack.push(key);
                    let resolved = self.resolve(sub)?;
                    self.stack.pop();
                    self.resolved.insert(key, resolved);
                    resolved
                }
            };
            height = height.max(below + 1);
            children.push((child, *t));
        }
        self.parts[index] = Part { polygons, children };
        Ok((index, height))
    }
}

/// Parses UniGrafix source into a program drawing its geometry as one mesh.
/// The instances stay a tree ([`Assembly`]); meshing expands them under
/// the request's budget and deadline.
pub fn parse(source: &[u8]) -> Result<Program, ParseError> {
    let text = std::str::from_utf8(source).map_err(|_| err(1, "UniGrafix source is not UTF-8"))?;
    let mut warnings = Vec::new();
    let (world, defs) = read(text, &mut warnings)?;
    let mut resolver = Resolver { defs: &defs, parts: Vec::new(), resolved: HashMap::new(), stack: Vec::new() };
    let (root, _) = resolver.resolve(&world)?;
    let assembly = Assembly::new(resolver.parts, root).map_err(|e| err(1, format!("instances: {e}")))?;
    let (_, triangles) = assembly.size();
    if triangles > MAX_TRIANGLES {
        return Err(err(1, format!("instances expand to more than {MAX_TRIANGLES} triangles ({triangles})")));
    }
    if triangles == 0 {
        return Err(err(1, "no faces: nothing to draw (top-level `f` or `i` statements)"));
    }
    let mesh = MeshDecl { name: "ug".into(), base: MeshBase::Assembly(Arc::new(assembly)), modifiers: Vec::new(), span: Span::new(1, 1) };
    Ok(Program::single_mesh(mesh, warnings))
}

#[cfg(test)]
mod tests {
    use super::*;

    const CUBE: &str = "{ unit cube { nested } }
def cube;
v a 0 0 0; v b 1 0 0; v c 1 1 0; v d 0 1 0;
v e 0 0 1; v f 1 0 1; v g 1 1 1; v h 0 1 1;
f (a d c b); f (e f g h); f (a b f e); f (b c g f); f (c d h g); f (d a e h);
end;
c red 1 0 0;
i (cube);
i (cube -sa 0.5 -tx 2);
";

    fn mesh(p: &Program) -> (usize, usize) {
        match &p.meshes[0].base {
            MeshBase::Assembly(a) => {
                let (positions, triangles) = a.expand_until(&|| false).expect("not stopped");
                (positions.len(), triangles.len())
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn cube_definitions_and_instances() {
        let p = parse(CUBE.as_bytes()).expect("parses");
        assert_eq!(mesh(&p), (16, 24));
    }

    #[test]
    fn unsafe_and_malformed_input_is_rejected() {
        for bad in [
            "include \"x.ug\";",
            "execute \"rm -rf /\";",
            "v a 0 0 0 1;",
            "def a; i (a); end; i (a);",
            "i (nope);",
            "f (a b c);",
            "v a 0 0 0; v b 1 0 0; v c 0 1 0; f (a b c) (a b c);",
            "{ open comment",
            "#define X 1",
            "v a 0 0 0",
        ] {
            assert!(parse(bad.as_bytes()).is_err(), "{bad}");
        }
        let p = parse(b"v a 0 0 0; v b 1 0 0; v c 0 1 0; w (a b); f (a b c);").expect("wire ignored");
        assert_eq!(p.warnings.len(), 1);
    }
}
