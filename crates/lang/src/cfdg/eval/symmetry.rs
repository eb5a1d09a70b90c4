//! `CF::Symmetry`: the list of transforms every finished primitive and path
//! is drawn under, as Context Free 3.4 builds it (John Horigan, `ast.cpp`:
//! `getTransforms`, `processSymmSpec`, `processDihedral`, `addUnique`;
//! `cfdgimpl.cpp` `CFDGImpl::getSymmetry`; `renderimpl.cpp`
//! `processPrimShape`, which finishes one copy per transform).
//!
//! Read: adjustments (each one transform), `CF::Cyclic` and `CF::Dihedral`
//! (order, mirror angle, centre) and the frieze groups `CF::p11g`, `p11m`,
//! `p1m1`, `p2`, `p2mg`, `p2mm`; the wallpaper groups (`CF::pm` …
//! `CF::p6m`) are in [`super::wallpaper`]. Each transform made is a step and each comparison
//! of cfdg's de-duplication is a step, so a huge order ends at the step
//! limit, typed, rather than in a quadratic hang.

use super::expr::Scope;
use super::state::{Affine, State};
use super::tile::{Frieze, Tiling};
use crate::cfdg::rand64::Rand64;
use crate::cfdg::syntax::{Adjustment, Expr, Grammar, SymmetryItem, TermKind, Value};
use crate::core::budget::Budget;
use crate::model::EvalError;
use crate::Span;

/// Bytes accounted per transform kept.
const TRANSFORM_BYTES: u64 = 48;

/// The groups a symmetry list names (`AST::FlagTypes`, `builder.cpp` `FlagNames`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Group {
    Cyclic,
    Dihedral,
    P11g,
    P11m,
    P1m1,
    P2,
    P2mg,
    P2mm,
    Wallpaper(super::wallpaper::Wall),
}

fn group(name: &str) -> Option<Group> {
    Some(match name {
        "CF::Cyclic" => Group::Cyclic,
        "CF::Dihedral" => Group::Dihedral,
        "CF::p11g" => Group::P11g,
        "CF::p11m" => Group::P11m,
        "CF::p1m1" => Group::P1m1,
        "CF::p2" => Group::P2,
        "CF::p2mg" => Group::P2mg,
        "CF::p2mm" => Group::P2mm,
        _ => return super::wallpaper::Wall::named(name).map(Group::Wallpaper),
    })
}

fn flag(e: &Expr) -> Option<Group> {
    match e {
        Expr::Var(v, _) => group(v),
        Expr::Paren(a) => flag(a),
        _ => None,
    }
}

pub(super) fn bad(span: Span, message: impl std::fmt::Display) -> EvalError {
    EvalError::BadParam { name: "CF::Symmetry".into(), message: format!("{}:{}: {message}", span.line, span.column) }
}

/// The transforms of the design's `CF::Symmetry`, empty when it has none.
pub fn symmetry(g: &Grammar, scope: &Scope, tiling: Option<&Tiling>, budget: &mut Budget) -> Result<Vec<Affine>, EvalError> {
    let Some(d) = g.defines.iter().rev().find(|d| d.name == "CF::Symmetry") else { return Ok(Vec::new()) };
    let items: Vec<SymmetryItem> = match &d.value {
        Value::Symmetry(items) => items.clone(),
        Value::Adjust(a) => vec![SymmetryItem::Adjust(a.clone())],
        Value::Expr(e) => vec![SymmetryItem::Expr(e.clone(), d.span)],
        Value::Shape(_) => return Err(bad(d.span, "expected transforms or a symmetry group")),
    };
    // cfdg passes the tile map with its translation (`mTileMod.m_transform`),
    // identity when the design is not tiled.
    let tile = tiling.map_or(Affine::default(), |t| Affine { tx: t.offset.0, ty: t.offset.1, ..t.transform });
    let tiled = tiling.is_some_and(|t| t.frieze == Frieze::None);
    let mut rand = Rand64::default();
    let (mods, syms) = list(&items, scope, &tile, tiled, &mut rand, budget)?;
    if let Some(t) = mods.first().and_then(|a| a.terms.iter().find(|t| !is_geometric(t.kind))) {
        return Err(bad(t.span, "At least one term was invalid"));
    }
    Ok(syms)
}

/// `getTransforms`: the adjustments of `items` that are not purely
/// geometric, kept to be applied one by one, and the transforms of the
/// geometric ones and of the groups, de-duplicated, in order. Random terms
/// of the geometric adjustments draw from `rand` now, as cfdg evaluates
/// them while building the list.
pub fn list<'i>(items: &'i [SymmetryItem], scope: &Scope, tile: &Affine, tiled: bool, rand: &mut Rand64, budget: &mut Budget) -> Result<(Vec<&'i Adjustment>, Vec<Affine>), EvalError> {
    let mut mods = Vec::new();
    let tile = *tile;
    let mut b = Builder { syms: Vec::new(), budget };
    let mut spec: Option<(Group, Span, Vec<f64>)> = None;
    for item in items {
        match item {
            SymmetryItem::Expr(e, span) => {
                if let Some(grp) = flag(e) {
                    if let Some((grp, at, data)) = spec.take() {
                        b.group(grp, at, &data, &tile, tiled)?;
                    }
                    spec = Some((grp, *span, Vec::new()));
                } else if let Some((_, _, data)) = spec.as_mut() {
                    let mut v = Vec::new();
                    super::expr::eval(e, scope, rand, &mut v)?;
                    if v.is_empty() {
                        return Err(bad(*span, "Could not evaluate this"));
                    }
                    data.extend(v);
                } else {
                    return Err(bad(*span, "Symmetry flag expected here"));
                }
            }
            SymmetryItem::Adjust(a) => {
                if let Some((grp, at, data)) = spec.take() {
                    b.group(grp, at, &data, &tile, tiled)?;
                }
                // Only geometric terms make a transform (`getTransforms`: GeomClass).
                if a.terms.iter().any(|t| !is_geometric(t.kind)) {
                    mods.push(a);
                    continue;
                }
                let mut s = State::initial();
                super::adjust::apply(&super::terms_of(a), &mut s, scope, rand)?;
                b.add(s.transform)?;
            }
        }
    }
    if let Some((grp, at, data)) = spec.take() {
        b.group(grp, at, &data, &tile, tiled)?;
    }
    Ok((mods, b.syms))
}

fn is_geometric(k: TermKind) -> bool {
    matches!(k, TermKind::X | TermKind::Y | TermKind::Z | TermKind::Size | TermKind::ZSize | TermKind::Rotate | TermKind::Flip | TermKind::Skew | TermKind::Transform)
}

pub(super) struct Builder<'b> {
    syms: Vec<Affine>,
    budget: &'b mut Budget,
}

/// `agg::trans_affine::operator==`: every entry within `affine_epsilon`.
fn same(a: &Affine, b: &Affine) -> bool {
    const EPS: f64 = 1e-14;
    (a.sx - b.sx).abs() <= EPS && (a.shy - b.shy).abs() <= EPS && (a.shx - b.shx).abs() <= EPS && (a.sy - b.sy).abs() <= EPS && (a.tx - b.tx).abs() <= EPS && (a.ty - b.ty).abs() <= EPS
}

pub(super) fn translate(t: &mut Affine, x: f64, y: f64) {
    t.tx += x;
    t.ty += y;
}
pub(super) fn flip_x(t: &mut Affine) {
    t.sx = -t.sx;
    t.shy = -t.shy;
    t.tx = -t.tx;
}
pub(super) fn flip_y(t: &mut Affine) {
    t.shx = -t.shx;
    t.sy = -t.sy;
    t.ty = -t.ty;
}

impl Builder<'_> {
    /// `addUnique`, charging a step per comparison.
    pub(super) fn add(&mut self, t: Affine) -> Result<(), EvalError> {
        self.budget.charge_steps(1 + self.syms.len() as u64)?;
        if !self.syms.iter().any(|s| same(s, &t)) {
            self.budget.reserve_memory(TRANSFORM_BYTES)?;
            self.syms.push(t);
        }
        Ok(())
    }

    /// `processDihedral`.
    pub(super) fn dihedral(&mut self, order: f64, x: f64, y: f64, mirrored: bool, angle: f64, at: Span) -> Result<(), EvalError> {
        if order.is_nan() || order < 1.0 || !order.is_finite() || !x.is_finite() || !y.is_finite() || !angle.is_finite() {
            return Err(bad(at, "Rotational symmetry order must be one or larger"));
        }
        let mirror = Affine::reflection(angle);
        let reg = Affine::translation(-x, -y);
        let step = 2.0 * std::f64::consts::PI / order;
        let mut i = 0.0f64;
        while i < order.trunc() {
            let mut tr = reg;
            if i != 0.0 {
                tr.multiply(&Affine::rotation(i * step));
            }
            let mut tr2 = tr;
            tr2.multiply(&mirror);
            translate(&mut tr, x, y);
            translate(&mut tr2, x, y);
            self.add(tr)?;
            if mirrored {
                self.add(tr2)?;
            }
            i += 1.0;
        }
        Ok(())
    }

    /// `processSymmSpec` for the groups read.
    fn group(&mut self, grp: Group, at: Span, data: &[f64], tile: &Affine, tiled: bool) -> Result<(), EvalError> {
        let frieze = (tile.sx != 0.0 || tile.sy != 0.0) && tile.sx * tile.sy == 0.0;
        if matches!(grp, Group::P11g | Group::P11m | Group::P1m1 | Group::P2mg | Group::P2mm) && !frieze {
            return Err(bad(at, "Frieze symmetry only works in frieze designs"));
        }
        if grp == Group::P2 && !frieze && !tiled {
            return Err(bad(at, "p2 symmetry only works in frieze or tiled designs"));
        }
        match grp {
            Group::Cyclic => {
                let (order, x, y) = match data {
                    [o, x, y] => (*o, *x, *y),
                    [o] => (*o, 0.0, 0.0),
                    _ => return Err(bad(at, "Cyclic symmetry requires an order argument and an optional center of rotation")),
                };
                self.dihedral(order, x, y, false, 0.0, at)
            }
            Group::Dihedral => {
                let (order, angle, x, y) = match data {
                    [o, a, x, y] => (*o, *a, *x, *y),
                    [o, a] => (*o, *a, 0.0, 0.0),
                    [o, x, y] => (*o, 0.0, *x, *y),
                    [o] => (*o, 0.0, 0.0, 0.0),
                    _ => return Err(bad(at, "Dihedral symmetry requires an order argument, an optional mirror angle, and an optional center of rotation")),
                };
                self.dihedral(order, x, y, true, angle * std::f64::consts::PI / 180.0, at)
            }
            Group::P11g | Group::P11m | Group::P1m1 => {
                let name = match grp {
                    Group::P11g => "p11g symmetry takes no arguments or an optional glide axis position argument",
                    Group::P11m => "p11m symmetry takes no arguments or an optional mirror axis position argument",
                    _ => "p1m1 symmetry takes no arguments or an optional mirror axis position argument",
                };
                let (mut mx, mut my) = (0.0, 0.0);
                match data {
                    [] => {}
                    [v] => {
                        // p11g and p11m offset across the frieze, p1m1 along it.
                        if (tile.sx != 0.0) == (grp == Group::P1m1) {
                            mx = *v;
                        } else {
                            my = *v;
                        }
                    }
                    _ => return Err(bad(at, name)),
                }
                let mut tr = Affine::default();
                self.add(tr)?;
                translate(&mut tr, -mx, -my);
                if (tile.sx != 0.0) == (grp == Group::P1m1) {
                    flip_x(&mut tr);
                } else {
                    flip_y(&mut tr);
                }
                if grp == Group::P11g {
                    translate(&mut tr, tile.sx * 0.5 + mx, tile.sy * 0.5 + my);
                } else {
                    translate(&mut tr, mx, my);
                }
                self.add(tr)
            }
            Group::P2 | Group::P2mg | Group::P2mm => {
                let (mx, my) = match data {
                    [x, y] => (*x, *y),
                    [] => (0.0, 0.0),
                    _ => return Err(bad(at, "this symmetry takes no arguments or a center of rotation")),
                };
                match grp {
                    Group::P2 => self.dihedral(2.0, mx, my, false, 0.0, at),
                    Group::P2mm => self.dihedral(2.0, mx, my, true, 0.0, at),
                    _ => {
                        let tr1 = Affine::default();
                        let (mut tr2, mut tr3, mut tr4) = (Affine::translation(-mx, -my), Affine::translation(-mx, -my), Affine::translation(-mx, -my));
                        flip_x(&mut tr2);
                        flip_x(&mut tr3);
                        flip_y(&mut tr3);
                        flip_y(&mut tr4);
                        translate(&mut tr2, tile.sx * 0.5 + mx, tile.sy * 0.5 + my);
                        translate(&mut tr3, mx, my);
                        translate(&mut tr4, tile.sx * 0.5 + mx, tile.sy * 0.5 + my);
                        for t in [tr1, tr2, tr3, tr4] {
                            self.add(t)?;
                        }
                        Ok(())
                    }
                }
            }
            Group::Wallpaper(w) => self.wallpaper(w, at, data, tile, tiled),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::cfdg::eval::expr::Scope;
    use crate::cfdg::syntax::parse;
    use crate::core::budget::{Budget, Limits};

    fn count(src: &str) -> usize {
        let g = parse(src.as_bytes()).expect("parses");
        let tiling = super::super::tile::tiling(&g, &Scope::default()).expect("tiling");
        super::symmetry(&g, &Scope::default(), tiling.as_ref(), &mut Budget::new(Limits::default())).expect("symmetry").len()
    }

    #[test]
    fn cfdg_symmetry_groups_have_their_orders() {
        assert_eq!(count("startshape A\nCF::Symmetry = CF::Dihedral, 6\nshape A { SQUARE [] }\n"), 12);
        assert_eq!(count("startshape A\nCF::Symmetry = CF::Cyclic, 5, 1, 1\nshape A { SQUARE [] }\n"), 5);
        // addUnique: the identity given twice is kept once.
        assert_eq!(count("startshape A\nCF::Symmetry = [], [r 90], [], [[s 1]]\nshape A { SQUARE [] }\n"), 2);
        assert_eq!(count("startshape A\nCF::Tile = [s 2 0]\nCF::Symmetry = CF::p2mg\nshape A { SQUARE [] }\n"), 4);
        assert_eq!(count("startshape A\nCF::Tile = [s 2 0]\nCF::Symmetry = CF::p11g, 0.5\nshape A { SQUARE [] }\n"), 2);
    }

    #[test]
    fn cfdg_symmetry_errors_name_the_setting() {
        for src in ["startshape A\nCF::Symmetry = CF::p2mg\nshape A { SQUARE [] }\n", "startshape A\nCF::Symmetry = 3\nshape A { SQUARE [] }\n", "startshape A\nCF::Symmetry = [b 1]\nshape A { SQUARE [] }\n"] {
            let g = parse(src.as_bytes()).expect("parses");
            let e = super::symmetry(&g, &Scope::default(), None, &mut Budget::new(Limits::default())).expect_err(src);
            assert!(e.to_string().contains("CF::Symmetry"), "{e}");
        }
    }
}
