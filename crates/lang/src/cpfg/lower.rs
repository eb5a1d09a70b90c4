//! cpfg's turtle (`AlgorithmicBotany/vlab`, `cpfg/interpret.c`,
//! `InterpretSymbol`; `cpfg/blackbox.c`, `call_blackbox`) read onto
//! rulemesh's L-system turtle (`crate::lsystem::turtle`) instead of a
//! second turtle: this pass walks the string once, keeps the state cpfg
//! adds (colour index, width increments, turtle scale, elasticity, the
//! polygon flag) on its own branch stack, and writes a string of the
//! L-system turtle's own commands with every argument explicit. The two
//! turtles share their frame: both start heading +Y with left −X, and
//! cpfg's `+ - & ^ \ /` rotate exactly as the L-system turtle's (cpfg's up
//! vector is the negative of the L-system turtle's, which only `?U` shows).
//!
//! What the L-system turtle has no command for is drawn here from a
//! shadow pose kept in step with it: spheres and circles (`@O`, `@o`,
//! `@c`) become sphere instances, `$`/`@v` (roll so the left vector is
//! horizontal) becomes a roll by the angle it needs, `@M` a turn, a move
//! and the turn back, `@R` the rotation to the new heading.

use super::string::CString;
use super::view::{LineStyle, View, PIXEL};
use crate::core::budget::Budget;
use crate::core::frame::Frame;
use crate::core::PrimitiveKind;
use crate::lsystem::syntax::{LSystem, Shape};
use crate::lsystem::ModuleString;
use crate::model::scene::Instance;
use crate::model::EvalError;
use glam::{DQuat, DVec3};

/// The L-system turtle's commands this pass writes, in symbol order.
const SHELL: &[&str] = &["[", "]", "F", "f", "+", "&", "\\", "!", "'", "@", "{", ".", "}", "|"];
const PUSH: u32 = 0;
const POP: u32 = 1;
const DRAW: u32 = 2;
const MOVE: u32 = 3;
const TURN: u32 = 4;
const PITCH: u32 = 5;
const ROLL: u32 = 6;
const WIDTH: u32 = 7;
const COLOUR: u32 = 8;
const TROPISM: u32 = 9;
const POLY_START: u32 = 10;
const POLY_VERTEX: u32 = 11;
const POLY_END: u32 = 12;

/// The L-system the turtle is run with: the shell's symbols and the view's settings.
pub fn shell(view: &View) -> LSystem {
    LSystem {
        symbols: SHELL.iter().map(|s| s.to_string()).collect(),
        axiom: Vec::new(),
        productions: Vec::new(),
        terminate: Vec::new(),
        iterations: 0,
        angle: view.angle,
        length: 1.0,
        width: 0.1,
        seed: None,
        ignore: Vec::new(),
        shape: Shape::Tube,
        tropism: view.tropism.map(|t| t.0),
        elasticity: view.tropism.map_or(0.0, |t| t.1),
        variety: None,
        site_count: 0,
        warnings: Vec::new(),
    }
}

#[derive(Debug, Clone, Copy)]
struct State {
    pos: DVec3,
    rot: DQuat,
    width: f64,
    colour: i64,
    scale: f64,
    elasticity: f64,
    /// Width and colour last written to the turtle.
    sent_width: f64,
    sent_colour: i64,
}

/// The lowered string and the spheres drawn beside it.
pub struct Lowered {
    /// The L-system turtle's string.
    pub string: ModuleString,
    /// Spheres and discs (`@O`, `@o`, `@c`) as instances.
    pub spheres: Vec<Instance>,
    /// The environmental queries met (`?P`, `?H`, `?U`, `?L`): the index of
    /// the queried module in the string read and what the turtle saw there.
    pub queries: Vec<(usize, [f64; 3])>,
}

struct Out {
    s: ModuleString,
}

impl Out {
    fn push(&mut self, sym: u32, p: &[f64], budget: &mut Budget) -> Result<(), EvalError> {
        budget.reserve_memory(8 + 8 * p.len() as u64)?;
        self.s.syms.push(sym);
        self.s.params.extend_from_slice(p);
        self.s.starts.push(self.s.params.len() as u32);
        Ok(())
    }
}

/// Lowers `s` for the turtle with `view`, one step per module.
///
/// Pixel lines (`line style: pixel`, cpfg's default) keep their width on
/// the screen whatever the zoom; a mesh has no screen, so a pixel is taken
/// as 1/[`PIXELS_ACROSS`] of the drawing's largest extent (cpfg fits the
/// model to its window), which costs a first walk to measure it.
pub fn lower(s: &CString, view: &View, budget: &mut Budget) -> Result<Lowered, EvalError> {
    if view.line_style != LineStyle::Pixel {
        return walk(s, view, 1.0, budget).map(|w| w.0);
    }
    let (first, extent) = walk(s, view, PIXEL, budget)?;
    if !(extent > 0.0 && extent.is_finite()) {
        return Ok(first);
    }
    budget.release_memory(8 * first.string.syms.len() as u64 + 8 * first.string.params.len() as u64);
    drop(first);
    walk(s, view, extent / PIXELS_ACROSS, budget).map(|w| w.0)
}

/// Pixels across the largest extent of a drawing with pixel lines.
pub(crate) const PIXELS_ACROSS: f64 = 250.0;

/// One walk: the lowered string and the largest extent of the positions visited.
fn walk(s: &CString, view: &View, width_unit: f64, budget: &mut Budget) -> Result<(Lowered, f64), EvalError> {
    let mut lo = DVec3::ZERO;
    let mut hi = DVec3::ZERO;
    let mut st = State {
        pos: DVec3::ZERO,
        rot: DQuat::IDENTITY,
        width: view.width,
        colour: view.colour,
        scale: view.scale,
        elasticity: view.tropism.map_or(0.0, |t| t.1),
        sent_width: f64::NAN,
        sent_colour: i64::MIN,
    };
    let tropism = view.tropism.map(|t| DVec3::from_array(t.0));
    let mut stack: Vec<State> = Vec::new();
    let mut out = Out { s: ModuleString { syms: Vec::new(), starts: vec![0], params: Vec::new() } };
    let mut spheres = Vec::new();
    let mut queries = Vec::new();
    let mut polygons = 0u32;
    let mut i = 0;
    while i < s.len() {
        budget.charge_step()?;
        let c = s.syms[i];
        let p = s.params_of(i);
        let arg = |k: usize| p.get(k).copied();
        i += 1;
        match c {
            'F' | 'G' | 'f' | 'g' => {
                let len = arg(0).unwrap_or(1.0) * st.scale;
                let draws = (c == 'F' || c == 'G') && polygons == 0;
                if draws {
                    send_look(&mut out, &mut st, view, width_unit, budget)?;
                }
                out.push(if draws { DRAW } else { MOVE }, &[len], budget)?;
                st.pos += st.rot * DVec3::Y * len;
                lo = lo.min(st.pos);
                hi = hi.max(st.pos);
                if polygons > 0 && (c == 'F' || c == 'f') {
                    out.push(POLY_VERTEX, &[], budget)?;
                }
                if let (Some(t), true) = (tropism, st.elasticity != 0.0) {
                    out.push(TROPISM, &[st.elasticity], budget)?;
                    bend(&mut st, t);
                }
            }
            '+' | '-' | '&' | '^' | '\\' | '/' => {
                let a = arg(0).unwrap_or(view.angle);
                let (sym, axis, sign) = match c {
                    '+' => (TURN, 2, 1.0),
                    '-' => (TURN, 2, -1.0),
                    '&' => (PITCH, 0, -1.0),
                    '^' => (PITCH, 0, 1.0),
                    '\\' => (ROLL, 1, 1.0),
                    _ => (ROLL, 1, -1.0),
                };
                // The shell's `&` and `\` turn by minus/plus their argument as `&`/`\` do.
                let shell_sign = if sym == PITCH { -1.0 } else { 1.0 };
                out.push(sym, &[sign * shell_sign * a], budget)?;
                st.rot = (st.rot * crate::lsystem::turtle::turn_quat(axis, sign, a)).normalize();
            }
            '|' => {
                out.push(TURN, &[180.0], budget)?;
                st.rot = (st.rot * DQuat::from_rotation_z(std::f64::consts::PI)).normalize();
            }
            '$' => roll_horizontal(&mut out, &mut st, budget)?,
            '[' => {
                out.push(PUSH, &[], budget)?;
                budget.reserve_memory(std::mem::size_of::<State>() as u64)?;
                stack.push(st);
            }
            ']' => {
                if let Some(old) = stack.pop() {
                    budget.release_memory(std::mem::size_of::<State>() as u64);
                    out.push(POP, &[], budget)?;
                    // The turtle restores what it had at `[`; so do the sent values.
                    st = old;
                }
            }
            ';' | ',' => {
                st.colour = match arg(0) {
                    Some(v) => v as i64,
                    None if c == ';' => st.colour + view.colour_increment,
                    None => st.colour - view.colour_increment,
                }
                .rem_euclid(256);
            }
            '#' | '!' => {
                st.width = match arg(0) {
                    Some(v) => v * st.scale,
                    None if c == '#' => st.width + view.width_increment * st.scale,
                    None => st.width - view.width_increment * st.scale,
                }
                .max(1e-7);
            }
            '%' if !view.past_cut && p.is_empty() => {
                let mut level = 0usize;
                while i < s.len() {
                    match s.syms[i] {
                        '[' => level += 1,
                        ']' if level == 0 => break,
                        ']' => level -= 1,
                        _ => {}
                    }
                    i += 1;
                }
            }
            '{' if arg(0).unwrap_or(0.0) == 0.0 => {
                polygons += 1;
                out.push(POLY_START, &[], budget)?;
            }
            '}' if arg(0).unwrap_or(0.0) == 0.0 => {
                if polygons > 0 {
                    polygons -= 1;
                    send_look(&mut out, &mut st, view, width_unit, budget)?;
                    out.push(POLY_END, &[], budget)?;
                }
            }
            '.' if polygons > 0 => out.push(POLY_VERTEX, &[], budget)?,
            '~' => {
                // A predefined surface: the next module names it; surfaces (.s) are not drawn yet.
                if i < s.len() {
                    i += 1;
                }
            }
            '?' if p.is_empty() => {
                // `?P(x,y,z)`: the turtle's position, heading, up or left
                // vector (`interpret.c`, `case '?'`); cpfg's up is −Z here.
                if let Some(&q) = s.syms.get(i) {
                    let v = match q {
                        'P' => Some(st.pos),
                        'H' => Some(st.rot * DVec3::Y),
                        'U' => Some(st.rot * DVec3::NEG_Z),
                        'L' => Some(st.rot * DVec3::NEG_X),
                        _ => None,
                    };
                    if let Some(v) = v {
                        queries.push((i, v.to_array()));
                        i += 1;
                    }
                }
            }
            '@' => {
                let Some(&f) = s.syms.get(i) else { break };
                let fp: Vec<f64> = s.params_of(i).to_vec();
                i += 1;
                let mut sub = None;
                if "PTGmDb".contains(f) && fp.is_empty() {
                    if let Some(&g) = s.syms.get(i) {
                        sub = Some((g, s.params_of(i).to_vec()));
                        i += 1;
                    }
                }
                blackbox(f, &fp, sub, &mut out, &mut st, view, &mut spheres, budget)?;
            }
            _ => {}
        }
    }
    let extent = (hi - lo).max_element();
    Ok((Lowered { string: out.s, spheres, queries }, extent))
}

/// Whether `sys` queries the turtle, so every step is followed by an
/// interpretation that fills the queries in (manual §6.9).
pub(crate) fn has_queries(sys: &super::syntax::Cpfg) -> bool {
    let q = |m: &[super::syntax::Module]| m.windows(2).any(|w| w[0].sym == '?' && w[0].args.is_empty() && "PHUL".contains(w[1].sym));
    q(&sys.axiom) || sys.productions.iter().any(|p| q(&p.succ))
}

/// Writes into every query module of `s` what the turtle sees there: the
/// first parameters get x, y (and z); extra parameters are kept.
pub(crate) fn fill_queries(s: &mut CString, view: &View, budget: &mut Budget) -> Result<(), EvalError> {
    let l = lower(s, view, budget)?;
    budget.release_memory(8 * l.string.syms.len() as u64 + 8 * l.string.params.len() as u64);
    for (i, v) in l.queries {
        let (a, b) = (s.starts[i] as usize, s.starts[i + 1] as usize);
        for (slot, x) in s.params[a..b].iter_mut().zip(v) {
            *slot = f64::from(x as f32);
        }
    }
    Ok(())
}

/// Writes the width and colour when they changed since last written.
fn send_look(out: &mut Out, st: &mut State, view: &View, unit: f64, budget: &mut Budget) -> Result<(), EvalError> {
    if st.width != st.sent_width {
        out.push(WIDTH, &[st.width * unit], budget)?;
        st.sent_width = st.width;
    }
    if st.colour != st.sent_colour {
        let c = view.rgba(st.colour);
        out.push(COLOUR, &c, budget)?;
        st.sent_colour = st.colour;
    }
    Ok(())
}

/// The L-system turtle's tropism (rotation by e·|H×T| about H×T), mirrored.
fn bend(st: &mut State, t: DVec3) {
    let h = st.rot * DVec3::Y;
    let axis = h.cross(t);
    let len = axis.length();
    if len < 1e-12 || !len.is_finite() || !st.elasticity.is_finite() {
        return;
    }
    st.rot = (DQuat::from_axis_angle(axis / len, st.elasticity * len) * st.rot).normalize();
}

/// `$` and `@v`: rolls about the heading so the left vector is horizontal
/// (ABOP p.57), with the up vector on the upper side.
fn roll_horizontal(out: &mut Out, st: &mut State, budget: &mut Budget) -> Result<(), EvalError> {
    let h = st.rot * DVec3::Y;
    let v = DVec3::Y;
    let l = v.cross(h);
    if l.length() < 1e-9 {
        return Ok(());
    }
    let l = l.normalize();
    let cur_left = st.rot * DVec3::NEG_X;
    let angle = libm::atan2(cur_left.cross(l).dot(h), cur_left.dot(l));
    if angle.abs() > 1e-12 {
        let deg = angle.to_degrees();
        // A roll `\` by +a turns about +H... in the turtle's local frame the
        // heading is +Y, and `\`(a) is a rotation about local +Y by a.
        out.push(ROLL, &[deg], budget)?;
        st.rot = (st.rot * DQuat::from_rotation_y(angle)).normalize();
    }
    Ok(())
}

/// The `@` commands (`cpfg/blackbox.c`).
#[allow(clippy::too_many_arguments)]
fn blackbox(f: char, p: &[f64], sub: Option<(char, Vec<f64>)>, out: &mut Out, st: &mut State, view: &View, spheres: &mut Vec<Instance>, budget: &mut Budget) -> Result<(), EvalError> {
    let unit = if view.line_style == LineStyle::Pixel { PIXEL } else { 1.0 };
    match f {
        'O' | 'o' | 'c' => {
            let d = p.first().map_or(st.width * unit, |d| d * st.scale);
            budget.charge_primitive(crate::geom::primitives::triangle_count(PrimitiveKind::Sphere, 8))?;
            budget.reserve_memory(crate::model::scene::INSTANCE_BYTES)?;
            let frame = Frame { translation: st.pos, rotation: st.rot, scale: d.abs().max(1e-9), parity: false };
            spheres.push(Instance::new(PrimitiveKind::Sphere, &frame, view.rgba(st.colour)));
        }
        'v' => roll_horizontal(out, st, budget)?,
        'M' if p.len() >= 3 => {
            let to = DVec3::new(p[0], p[1], p[2]);
            let d = to - st.pos;
            let len = d.length();
            if len > 1e-12 {
                // Turn the heading onto the move, move, turn back.
                let h = st.rot * DVec3::Y;
                let q = DQuat::from_rotation_arc(h, d / len);
                let local = st.rot.inverse() * q * st.rot;
                let (axis, angle) = local.to_axis_angle();
                push_rotation(out, axis, angle, budget)?;
                out.push(MOVE, &[len], budget)?;
                push_rotation(out, axis, -angle, budget)?;
                st.pos = to;
            }
        }
        'R' if p.len() >= 3 => {
            let h = DVec3::new(p[0], p[1], p[2]);
            if h.length() > 1e-12 {
                let cur = st.rot * DVec3::Y;
                let q = DQuat::from_rotation_arc(cur, h.normalize());
                let local = st.rot.inverse() * q * st.rot;
                let (axis, angle) = local.to_axis_angle();
                push_rotation(out, axis, angle, budget)?;
                st.rot = (q * st.rot).normalize();
            }
        }
        ';' | ',' => {}
        'D' => match sub {
            None => {
                if let Some(s) = p.first() {
                    st.scale = *s;
                }
            }
            Some(('i', sp)) => st.scale = sp.first().copied().unwrap_or(st.scale * view.scale_multiplier),
            Some(('d', sp)) => st.scale = sp.first().copied().unwrap_or(st.scale / view.scale_multiplier),
            Some((_, sp)) => {
                if let Some(s) = sp.first() {
                    st.scale = *s;
                }
            }
        },
        'T' => {
            if let Some((g, sp)) = sub {
                let value = sp.get(1).copied();
                match g {
                    's' => st.elasticity = value.unwrap_or(st.elasticity),
                    'i' => st.elasticity += value.unwrap_or(0.0),
                    'd' => st.elasticity -= value.unwrap_or(0.0),
                    _ => {}
                }
            }
        }
        _ => {}
    }
    Ok(())
}

/// A local rotation about `axis` by `angle` radians as the shell's turns:
/// decomposed into Euler angles about local Z, X, Y.
fn push_rotation(out: &mut Out, axis: DVec3, angle: f64, budget: &mut Budget) -> Result<(), EvalError> {
    let q = DQuat::from_axis_angle(axis.normalize_or_zero(), angle);
    let (z, x, y) = q.to_euler(glam::EulerRot::ZXY);
    if z != 0.0 {
        out.push(TURN, &[z.to_degrees()], budget)?;
    }
    if x != 0.0 {
        out.push(PITCH, &[-x.to_degrees()], budget)?;
    }
    if y != 0.0 {
        out.push(ROLL, &[y.to_degrees()], budget)?;
    }
    Ok(())
}
