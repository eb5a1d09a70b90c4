//! Adjustment lists and the context work runs in: the frame-and-colour
//! [`Delta`] of an adjustment list (evaluated once per call site when it is
//! deterministic), the [`Ctx`] a piece of work carries, and the expression
//! environment [`Env`] that binds parameters, the call's random stream and
//! the current position. Kept apart from the machine so that the arithmetic
//! of a transform can be read (and tested) without the stack around it.

use crate::core::frame::Frame;
use crate::core::rng::StreamKey;
use crate::core::Span;
use crate::expr::{Expr, ExprEnv};
use crate::ir::{Adjust, AdjustOp, Axis, Item};
use crate::model::EvalError;
use glam::{DQuat, DVec3};

/// A frame change plus a colour change: the effect of one adjustment list.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Delta {
    frame: Frame,
    colour: [f64; 4],
}

impl Delta {
    const IDENTITY: Delta = Delta { frame: Frame::IDENTITY, colour: [0.0; 4] };

    /// The frame change (applied in the caller's local frame).
    pub(super) fn frame(&self) -> &Frame {
        &self.frame
    }

    /// The colour offsets added.
    pub(super) fn colour(&self) -> [f64; 4] {
        self.colour
    }
}

/// The state a piece of work runs in.
#[derive(Debug, Clone, Copy)]
pub(super) struct Ctx {
    pub(super) frame: Frame,
    /// Colour as offsets: RGB start at 0 (black), alpha is 1 + offset (as in
    /// the `1.0 + color.a` of Andersson 2015's shader listing, Appendix C.1).
    pub(super) colour: [f64; 4],
    pub(super) depth: u32,
    pub(super) key: StreamKey,
    /// The animation bone the work belongs to (0: none; see [`Rig`](crate::model::animation::Rig)).
    pub(super) bone: u32,
    /// The namespace of the call that made this context (its pen and
    /// continuation point; 0 is the global namespace).
    pub(super) ns: u32,
}

/// True when every bit of `a` equals `b`'s: signed zeros differ.
fn same_bits<const N: usize>(a: [f64; N], b: [f64; N]) -> bool {
    a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits())
}

/// No component is −0.0.
fn no_negative_zero<const N: usize>(a: [f64; N]) -> bool {
    a.iter().all(|x| x.to_bits() != (-0.0f64).to_bits())
}

impl Delta {
    /// Exactly the identity: every bit of [`Delta::IDENTITY`] (`BOX {}`).
    fn is_identity(&self) -> bool {
        let (f, i) = (&self.frame, &Frame::IDENTITY);
        same_bits(self.colour, [0.0; 4])
            && same_bits(f.translation.to_array(), i.translation.to_array())
            && same_bits(f.rotation.to_array(), i.rotation.to_array())
            && f.scale.to_bits() == 1.0f64.to_bits()
            && !f.parity
    }
}

impl Ctx {
    /// The frame and colour of this context after `d`.
    pub(super) fn apply(&self, d: &Delta) -> (Frame, [f64; 4]) {
        // `BOX {}` in an axis-aligned frame (a grid's every box): applying the
        // identity gives this context back bit for bit — translation + 0,
        // I·I normalised, colour + 0 — unless a −0.0 would turn into +0.0
        // (with odd parity the added zero is −0.0 and keeps it), so skip the
        // arithmetic that is a fifth of such a grammar's evaluation.
        let axis_aligned = same_bits(self.frame.rotation.to_array(), Frame::IDENTITY.rotation.to_array());
        if axis_aligned && d.is_identity() && (self.frame.parity || no_negative_zero(self.frame.translation.to_array())) && no_negative_zero(self.colour) {
            return (self.frame, self.colour);
        }
        let mut c = self.colour;
        for (a, b) in c.iter_mut().zip(d.colour) {
            *a += b;
        }
        (self.frame.then(&d.frame), c)
    }
}

/// Expression environment for one invocation: bound parameters plus the invocation's stream.
pub(super) struct Env<'a> {
    pub(super) params: &'a [f64],
    pub(super) key: StreamKey,
    /// Position of the current frame, for functions of x, y, z.
    pub(super) pos: DVec3,
}

impl ExprEnv for Env<'_> {
    fn param(&self, index: u32) -> f64 {
        self.params.get(index as usize).copied().unwrap_or(f64::NAN)
    }
    fn rand(&mut self, site: u32) -> f64 {
        self.key.uniform(site)
    }
    fn coord(&self, axis: u8) -> f64 {
        self.pos.to_array().get(usize::from(axis)).copied().unwrap_or(f64::NAN)
    }
}

/// Evaluates one number and rejects NaN and infinities with the adjustment's position.
pub(super) fn finite(e: &Expr, env: &mut Env, span: Span, what: &str) -> Result<f64, EvalError> {
    let v = e.eval(env);
    if v.is_finite() {
        Ok(v)
    } else {
        Err(EvalError::NonFinite { span, what: what.to_string(), value: v.to_string() })
    }
}

/// Computes the combined effect of an adjustment list, each argument divided by `divisor`
/// (an iterator's `/n`; scale becomes k^(1/n) so that n steps multiply by k).
pub(super) fn eval_adjust(adjust: &[Adjust], env: &mut Env, divisor: f64) -> Result<Delta, EvalError> {
    let mut d = Delta::IDENTITY;
    for a in adjust {
        let op = match &a.op {
            AdjustOp::Translate([x, y, z]) => {
                let v = DVec3::new(
                    finite(x, env, a.span, "translation")?,
                    finite(y, env, a.span, "translation")?,
                    finite(z, env, a.span, "translation")?,
                );
                Frame::from_translation(v / divisor)
            }
            AdjustOp::Rotate { axis, angle } => {
                let t = finite(angle, env, a.span, "angle")? / divisor;
                Frame::from_rotation(match axis {
                    Axis::X => DQuat::from_rotation_x(t),
                    Axis::Y => DQuat::from_rotation_y(t),
                    Axis::Z => DQuat::from_rotation_z(t),
                })
            }
            AdjustOp::Scale(k) => {
                let k = finite(k, env, a.span, "scale")?;
                let k = if divisor == 1.0 { k } else { k.signum() * libm::pow(k.abs(), 1.0 / divisor) };
                Frame::from_scale(k)
            }
            AdjustOp::Reflect([x, y, z]) => Frame::reflection(DVec3::new(
                finite(x, env, a.span, "reflection normal")?,
                finite(y, env, a.span, "reflection normal")?,
                finite(z, env, a.span, "reflection normal")?,
            )),
            AdjustOp::Colour { channel, delta } => {
                let v = finite(delta, env, a.span, "colour")? / divisor;
                if let Some(c) = d.colour.get_mut(usize::from(*channel)) {
                    *c += v;
                }
                continue;
            }
        };
        d.frame = d.frame.then(&op);
        if !d.frame.is_finite() {
            return Err(EvalError::NonFinite { span: a.span, what: "transform".into(), value: "overflow".into() });
        }
    }
    Ok(d)
}

/// Precomputes the deltas of every call whose adjustments are deterministic.
pub(super) fn collect_fixed(items: &[Item], params: &[f64], fixed: &mut [Option<Delta>]) -> Result<(), EvalError> {
    // Iterative walk: bodies can be deeply nested blocks.
    let mut pending: Vec<&[Item]> = vec![items];
    while let Some(items) = pending.pop() {
        for item in items {
            match item {
                Item::Call(c) => {
                    if c.adjust.iter().all(|a| adjust_is_deterministic(&a.op)) {
                        let d = eval_adjust(&c.adjust, &mut Env { params, key: StreamKey(0), pos: DVec3::ZERO }, 1.0)?;
                        if let Some(slot) = fixed.get_mut(c.site as usize) {
                            *slot = Some(d);
                        }
                    }
                }
                Item::Block(b) => pending.push(b),
                Item::Iterate(it) => pending.push(std::slice::from_ref(&*it.body)),
            }
        }
    }
    Ok(())
}

fn adjust_is_deterministic(op: &AdjustOp) -> bool {
    match op {
        AdjustOp::Translate(v) | AdjustOp::Reflect(v) => v.iter().all(Expr::is_deterministic),
        AdjustOp::Rotate { angle, .. } => angle.is_deterministic(),
        AdjustOp::Scale(k) => k.is_deterministic(),
        AdjustOp::Colour { delta, .. } => delta.is_deterministic(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What `apply` computes without its shortcut.
    fn composed(ctx: &Ctx, d: &Delta) -> (Frame, [f64; 4]) {
        let mut c = ctx.colour;
        for (a, b) in c.iter_mut().zip(d.colour) {
            *a += b;
        }
        (ctx.frame.then(&d.frame), c)
    }

    fn bits(f: &Frame, c: &[f64; 4]) -> Vec<u64> {
        let mut v: Vec<u64> = f.translation.to_array().iter().chain(&f.rotation.to_array()).chain(c).map(|x| x.to_bits()).collect();
        v.extend([f.scale.to_bits(), u64::from(f.parity)]);
        v
    }

    /// The identity shortcut gives the composed result bit for bit, signed
    /// zeros and odd parity included, and a −0.0 it would keep takes the long way.
    #[test]
    fn applying_the_identity_is_bit_exact() {
        let mut checked = 0;
        for t in [[1.5, -2.0, 0.0], [-0.0, 3.0, 1e-300], [0.0, -0.0, -0.0], [7.0, 8.0, 9.0]] {
            for parity in [false, true] {
                for rotation in [DQuat::IDENTITY, DQuat::from_xyzw(-0.0, 0.0, 0.0, 1.0), DQuat::from_rotation_z(0.3)] {
                    for colour in [[0.0, 0.5, -0.25, 0.0], [-0.0, 0.0, 0.0, 0.0]] {
                        let frame = Frame { translation: DVec3::from_array(t), rotation, scale: 0.7, parity };
                        let ctx = Ctx { frame, colour, depth: 0, key: StreamKey(1), bone: 0, ns: 0 };
                        for d in [Delta::IDENTITY, Delta { colour: [-0.0, 0.0, 0.0, 0.0], ..Delta::IDENTITY }] {
                            let (f, c) = ctx.apply(&d);
                            let (g, e) = composed(&ctx, &d);
                            assert_eq!(bits(&f, &c), bits(&g, &e), "{t:?} parity {parity} {rotation:?} {colour:?}");
                            checked += 1;
                        }
                    }
                }
            }
        }
        assert_eq!(checked, 96);
    }
}
