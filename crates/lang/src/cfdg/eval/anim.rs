//! Animation settings in a still picture, as cfdg 3.4 draws one (John
//! Horigan, Context Free 3.4, 2018): `cfdg` without `-a` calls
//! `Renderer::run`, never `animate` (`src-unix/main.cpp`), so
//!
//! - `ftime()` is `CF::FrameTime` when the design sets it, else 0, and
//!   `frame()` is `CF::Frame`, else 0 (`RendererImpl::RendererImpl` reads
//!   both into `mCurrentTime`/`mCurrentFrame`, which start at 0 in
//!   `rendererAST.h`; only `animate` changes them, per frame);
//! - `CF::Time` only has its check: a span that does not run forwards is an
//!   error (`CFDGImpl::isTimed`, "Time specification must have positive
//!   duration."), called by `run`;
//! - `time` and `timescale` terms move each shape's time map
//!   (`agg::trans_affine_time`, `agg-extras/agg_trans_affine_time.h`,
//!   premultiplied as `Modification::operator*=` does); the still's frame
//!   is the whole time line (`mFrameTimeBounds` is −∞…∞), so every shape is
//!   drawn, except that a shape whose span runs backwards (begin after end)
//!   is dropped before it is expanded or finished
//!   (`RendererImpl::processShape`).

use super::expr::Scope;
use super::state::State;
use super::terms_of;
use crate::cfdg::rand64::Rand64;
use crate::cfdg::syntax::{Grammar, Value};
use crate::model::EvalError;

/// The hidden variable `ftime()` reads (no CFDG name holds a NUL).
pub(crate) const FTIME: &str = "\u{0}ftime";
/// The hidden variable `frame()` reads.
pub const FRAME: &str = "\u{0}frame";

/// A `time begin end` term: `trans_affine_time_translation(begin, end)`
/// premultiplied into `time` (scale, begin, end), so the move is scaled by
/// the current time scale.
pub fn shift(time: &mut [f64; 3], begin: f64, end: f64) {
    time[1] += begin * time[0];
    time[2] += end * time[0];
}

/// Whether a shape with this state is dropped (`processShape`: its time
/// span runs backwards).
pub fn dropped(s: &State) -> bool {
    s.time[1] > s.time[2]
}

/// `ftime()` or `frame()` (`ASTfunction::evaluate`'s `Ftime`, `Frame`).
pub fn value(name: &str, scope: &Scope) -> f64 {
    let key = if name == "ftime" { FTIME } else { FRAME };
    scope.get(key).and_then(|v| v.first().copied()).unwrap_or(0.0)
}

/// Checks `CF::Time` and pushes what `ftime()` and `frame()` give onto
/// `scope` (before the globals, which may use them).
pub(crate) fn setup(g: &Grammar, scope: &mut Scope) -> Result<(), EvalError> {
    if let Some(d) = g.defines.iter().rev().find(|d| d.name == "CF::Time") {
        let Value::Adjust(a) = &d.value else {
            return Err(EvalError::BadParam { name: d.name.clone(), message: format!("{}:{}: CF::Time takes an adjustment", d.span.line, d.span.column) });
        };
        let mut s = State::initial();
        super::adjust::apply(&terms_of(a), &mut s, scope, &mut Rand64::default())?;
        if !(s.time[1] < s.time[2]) {
            return Err(EvalError::BadParam { name: d.name.clone(), message: format!("{}:{}: Time specification must have positive duration.", d.span.line, d.span.column) });
        }
    }
    for (setting, key) in [("CF::FrameTime", FTIME), ("CF::Frame", FRAME)] {
        let v = super::setting(g, setting, scope)?.unwrap_or(0.0);
        scope.vars.push((key.to_string(), vec![v]));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_moves_are_scaled_by_the_time_scale() {
        let mut t = [1.0, 0.0, 0.0];
        shift(&mut t, 0.0, f64::INFINITY);
        t[0] *= 0.95;
        shift(&mut t, 0.5, 0.0);
        assert_eq!(t, [0.95, 0.475, f64::INFINITY]);
    }

    #[test]
    fn a_backwards_span_is_dropped() {
        let mut s = State::initial();
        assert!(!dropped(&s));
        shift(&mut s.time, 2.0, 1.0);
        assert!(dropped(&s));
    }
}
