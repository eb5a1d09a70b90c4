//! Exact derivations of the figures of *The Algorithmic Beauty of Plants*
//! (Prusinkiewicz & Lindenmayer, 1990; "ABOP" below) that the vlab manuals
//! reproduce, checked against the book and against the strings printed in
//! vlab's *Getting Started* manual (`docs/GettingStarted.pdf` of
//! `AlgorithmicBotany/vlab`, §3 "Modeling in cpfg"), and against counts
//! worked out here independently of the front end (small integer
//! simulations of each L-system's growth).
//!
//! Figure numbers, checked: ABOP Figure 1.6 (p. 8) "Generating a quadratic
//! Koch island" is ω: F-F-F-F, p: F → F-F+F+FF-F-F+F, δ = 90°, n = 3; the
//! vlab object `01-quadratic-Koch` derives the mirror image of that
//! generator from `-F` (Getting Started §3.1). `03-snowflake` draws von
//! Koch's snowflake curve (F → F+F--F+F at 60°, Getting Started §3.3–3.4),
//! whose construction is ABOP Figure 1.1 (that number from the book's
//! first page of chapter 1, not checked against a copy here); ABOP Figure
//! 1.7b (p. 9) is "a quadratic modification of the snowflake curve"
//! (ω: -F, F → F+F-F-F+F at 90°, n = 4), not the vlab model, and is
//! asserted as well. ABOP Figure 1.24e (p. 25) is X → F[+X][-X]FX,
//! F → FF, n = 7, δ = 25.7°, which `04-compound` derives with A for X
//! (Getting Started §3.5). The fractal ferns (`07-fractal-ferns`, §3.8)
//! are the compound-leaf L-system of ABOP §5.2 (p. 128) with the delay
//! counted up instead of down; the Lychnis (`01-Lychnis`, Getting Started
//! §2) is, in its `description.txt`, "based on the L-system on page 84" of
//! ABOP, rewritten in continuous time.

use super::derive::Deriver;
use super::string::CString;
use super::syntax::{parse_with, Cpfg};
use crate::core::budget::{Budget, Limits, OnLimit};
use std::collections::BTreeMap;

fn system(src: &str) -> Cpfg {
    parse_with(src.as_bytes(), &BTreeMap::new(), &[]).expect("parses")
}

/// The strings after 0, 1, …, `n` steps, parameters printed at the `f32`
/// precision cpfg keeps them in (`1.28`, not `1.2799999713897705`).
fn strings(sys: &Cpfg, n: usize) -> Vec<String> {
    let mut budget = Budget::new(Limits::default());
    let mut d = Deriver::new(sys, None);
    let mut cur = d.axiom(&mut budget).expect("axiom");
    let mut out = vec![text32(&cur)];
    for _ in 0..n {
        cur = d.step(&cur, &mut budget).expect("step");
        out.push(text32(&cur));
    }
    out
}

fn derived(sys: &Cpfg, steps: u32) -> CString {
    let mut budget = Budget::new(Limits::default());
    Deriver::new(sys, None).derive(steps, None, OnLimit::Error, &mut budget).expect("derives").string
}

fn drawn(sys: &Cpfg, steps: u32) -> CString {
    let mut budget = Budget::new(Limits::default());
    let mut d = Deriver::new(sys, None);
    let s = d.derive(steps, None, OnLimit::Error, &mut budget).expect("derives").string;
    d.homomorphism(&s, &mut budget).expect("homomorphism")
}

fn text32(s: &CString) -> String {
    let mut out = String::new();
    for i in 0..s.len() {
        out.push(s.syms[i]);
        let p = s.params_of(i);
        if !p.is_empty() {
            let v: Vec<String> = p.iter().map(|&x| format!("{}", x as f32)).collect();
            out.push_str(&format!("({})", v.join(",")));
        }
    }
    out
}

fn count(s: &CString, c: char) -> usize {
    s.syms.iter().filter(|&&x| x == c).count()
}

/// A plane turtle written here, not the front end's: `F` (length 1 or its
/// parameter) forward, `+`/`-` turn left/right by `delta` or their
/// parameter. Returns the end point, rounded to 1e-6.
fn end_point(s: &CString, delta: f64) -> (i64, i64) {
    let (mut x, mut y, mut a) = (0.0f64, 0.0f64, 90.0f64);
    for i in 0..s.len() {
        let p = s.params_of(i);
        match s.syms[i] {
            'F' => {
                let l = p.first().copied().unwrap_or(1.0);
                x += l * a.to_radians().cos();
                y += l * a.to_radians().sin();
            }
            '+' => a += p.first().copied().unwrap_or(delta),
            '-' => a -= p.first().copied().unwrap_or(delta),
            _ => {}
        }
    }
    ((x * 1e6).round() as i64, (y * 1e6).round() as i64)
}

/// ABOP Figure 1.6: the quadratic Koch island after n = 3 steps has
/// 4·8³ = 2048 sides and closes on itself; the vlab curve (Getting Started
/// §3.1, `01-quadratic-Koch`) gives the strings the manual prints for 0, 1
/// and 2 steps.
#[test]
fn quadratic_koch_island_figure_1_6() {
    let island = system("Lsystem: 1\nderivation length: 3\nAxiom: F-F-F-F\nF --> F-F+F+FF-F-F+F\nendlsystem\n");
    let s = derived(&island, 3);
    assert_eq!(count(&s, 'F'), 2048);
    assert_eq!(end_point(&s, 90.0), (0, 0));
    let curve = system(include_str!("../../../../tests/data/cpfg/01-quadratic-Koch/fractal.l"));
    let g = "F+F-F-FF+F+F-F";
    let one = format!("-{g}");
    // The manual spaces the step-2 string for clarity; the spaces are not modules.
    let two = format!("-{g}+{g}-{g}-{g}{g}+{g}+{g}-{g}");
    assert_eq!(strings(&curve, 2), vec!["-F".to_string(), one, two]);
    let s = derived(&curve, 4);
    assert_eq!(count(&s, 'F'), 4096);
    // Each step multiplies the span by 4: after 4 steps the curve ends 4⁴ to the right.
    assert_eq!(end_point(&s, 90.0), (256_000_000, 0));
}

/// Von Koch's snowflake curve (ABOP Figure 1.1), F → F+F--F+F at 60°, as
/// the vlab object `03-snowflake` and Getting Started §3.3–3.4 write it
/// (axiom `-(90)F`, and the variant with every angle in its module).
#[test]
fn snowflake_curve_figure_1_1() {
    let vlab = system(include_str!("../../../../tests/data/cpfg/03-snowflake/fractal.l"));
    let s = derived(&vlab, 4);
    assert_eq!(count(&s, 'F'), 256);
    // Each step makes the curve 3 times as wide: it ends 3⁴ = 81 to the right.
    assert_eq!(end_point(&s, 60.0), (81_000_000, 0));
    let explicit = system("Lsystem: 1\nderivation length: 4\nAxiom: -(90)F\nF --> F+(60)F-(120)F+(60)F\nendlsystem\n");
    let t = derived(&explicit, 4);
    assert_eq!(count(&t, 'F'), 256);
    // Any angle increment: the modules carry their angles.
    assert_eq!(end_point(&t, 17.0), (81_000_000, 0));
    assert_eq!(strings(&vlab, 1)[1], "-(90)F+F--F+F");
    // ABOP Figure 1.7b: 5⁴ = 625 segments, also 3⁴ = 81 wide.
    let quadratic = system("Lsystem: 1\nderivation length: 4\nAxiom: -F\nF --> F+F-F-F+F\nendlsystem\n");
    let q = derived(&quadratic, 4);
    assert_eq!(count(&q, 'F'), 625);
    assert_eq!(end_point(&q, 90.0), (81_000_000, 0));
}

/// ABOP Figure 1.24e: X → F[+X][-X]FX, F → FF after n = 7 steps. An
/// integer recurrence worked out here: X triples (3ⁿ apices) and
/// F(n+1) = 2·F(n) + 2·X(n), so 4118 segments and 2187 apices; the vlab
/// object `04-compound` (A for X, 4 steps) gives 130. With the
/// homomorphism of `05-compound-homo` every apex draws too.
#[test]
fn compound_leaf_figure_1_24e() {
    let (mut f, mut x) = (0u64, 1u64);
    for _ in 0..7 {
        (f, x) = (2 * f + 2 * x, 3 * x);
    }
    assert_eq!((f, x), (4118, 2187));
    let fig = system("Lsystem: 1\nderivation length: 7\nAxiom: X\nX --> F[+X][-X]FX\nF --> FF\nendlsystem\n");
    let s = derived(&fig, 7);
    assert_eq!((count(&s, 'F') as u64, count(&s, 'X') as u64), (f, x));
    let vlab = system(include_str!("../../../../tests/data/cpfg/04-compound/leaf.l"));
    assert_eq!(count(&derived(&vlab, 4), 'F'), 130);
    let homo = system(include_str!("../../../../tests/data/cpfg/05-compound-homo/leaf.l"));
    assert_eq!(count(&drawn(&homo, 4), 'F'), 130 + 81);
}

/// Getting Started §3.7 (`06-compound-param`): the strings the manual
/// prints for the first three steps. The manual's third string carries two
/// stray `]` (its brackets do not balance); the string here is the
/// manual's without them, and the same as the second string's structure
/// one level up (I doubles, every A becomes the first string).
#[test]
fn compound_leaf_parametric_strings() {
    let sys = system("Lsystem: 1\nderivation length: 4\nAxiom: A\nA --> I(1)[+A][-A]I(1)A\nI(x) --> I(2*x)\nhomomorphism\nA --> F\nI(x) --> F(x)\nendlsystem\n");
    let s1 = "I(1)[+A][-A]I(1)A";
    let s2 = "I(2)[+I(1)[+A][-A]I(1)A][-I(1)[+A][-A]I(1)A]I(2)I(1)[+A][-A]I(1)A";
    let s3 = "I(4)[+I(2)[+I(1)[+A][-A]I(1)A][-I(1)[+A][-A]I(1)A]I(2)I(1)[+A][-A]I(1)A][-I(2)[+I(1)[+A][-A]I(1)A][-I(1)[+A][-A]I(1)A]I(2)I(1)[+A][-A]I(1)A]I(4)I(2)[+I(1)[+A][-A]I(1)A][-I(1)[+A][-A]I(1)A]I(2)I(1)[+A][-A]I(1)A";
    assert_eq!(strings(&sys, 3), vec!["A", s1, s2, s3]);
    assert_eq!(s3, format!("I(4)[+{s2}][-{s2}]I(4){s2}"));
}

/// Getting Started §3.8 (`07-fractal-ferns`, D = 3, R = 1.28): the five
/// strings the manual prints, then the model's own 18 steps against an
/// integer simulation of its apices and internodes.
#[test]
fn fractal_ferns_strings_and_counts() {
    let sys = system(include_str!("../../../../tests/data/cpfg/07-fractal-ferns/leaf.l"));
    let got = strings(&sys, 5);
    assert_eq!(
        got[1..],
        ["A(1)", "A(2)", "A(3)", "I(1)[+A(0)][-A(0)]I(1)A(3)", "I(1.28)[+A(1)][-A(1)]I(1.28)I(1)[+A(0)][-A(0)]I(1)A(3)"]
    );
    // Apices by age 0..=3 and internodes: A(t<3) ages, A(3) stays and
    // makes two internodes and two new apices each step.
    let (mut ages, mut internodes) = ([1u64, 0, 0, 0], 0u64);
    for _ in 0..18 {
        let mature = ages[3];
        ages = [2 * mature, ages[0], ages[1], ages[2] + mature];
        internodes += 2 * mature;
    }
    let s = derived(&sys, 18);
    assert_eq!(count(&s, 'A') as u64, ages.iter().sum::<u64>());
    assert_eq!(count(&s, 'I') as u64, internodes);
    assert_eq!((ages.iter().sum::<u64>(), internodes), (1207, 1206));
    // The homomorphism draws one F per apex and per internode.
    assert_eq!(count(&drawn(&sys, 18), 'F') as u64, 1207 + 1206);
}

/// The flowers, leaves and apices of a dichasium with apical delays `d1`
/// and `d2` after `steps` steps, time counted in whole ticks: an apex
/// ages one tick a step and, once its age is above 0, becomes a flower
/// with two lateral apices of age −d1 and −d2 (the decomposition of
/// `01-Lychnis`'s `A(t)`), worked out here without the front end.
fn dichasium(steps: u32, d1: i64, d2: i64) -> (u64, usize) {
    let (mut apices, mut flowers) = (vec![0i64], 0u64);
    for _ in 0..steps {
        let mut next = Vec::with_capacity(apices.len() * 2);
        for t in apices {
            let t = t + 1;
            if t > 0 {
                flowers += 1;
                next.extend([t - d1, t - d2]);
            } else {
                next.push(t);
            }
        }
        apices = next;
    }
    (flowers, apices.len())
}

/// The Lychnis coronaria of Getting Started §2 (`01-Lychnis`, "based on the
/// L-system on page 84" of ABOP): its dichasial branching, derived with the
/// object's own files. With `dt` 0.125 (exact in binary, so no rounding
/// decides when an apex's time passes 0) and 240 steps (the manual's
/// 30 time units), the flowers, leaves and apices are the dichasium's of
/// delays 4 and 7 (32 and 56 ticks). The unchanged model (dt 0.1, 300
/// steps) derives too, and its counts are checked against the same
/// simulation in tenths.
#[test]
fn lychnis_dichasium() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/cpfg/01-Lychnis/");
    let mut files = BTreeMap::new();
    for f in ["plant.v", "plant.a", "functions.fset", "calyx.con", "leaf.s", "petal.s"] {
        files.insert(f.to_string(), std::fs::read(format!("{dir}{f}")).expect("vlab file"));
    }
    let source = std::fs::read_to_string(format!("{dir}plant.l")).expect("plant.l");
    let view = super::read_view(&files, &mut Vec::new());
    let predefined = super::predefined(&view);
    for (src, steps, d1, d2) in [
        (source.replace("#define dt 0.1", "#define dt 0.125").replace("#define STEPS 300", "#define STEPS 240"), 240, 32, 56),
        (source.clone(), 300, 40, 70),
    ] {
        let sys = parse_with(src.as_bytes(), &files, &predefined).expect("parses");
        assert_eq!(sys.derivation_length, Some(steps));
        let s = derived(&sys, steps);
        let (flowers, apices) = dichasium(steps, d1, d2);
        assert_eq!(count(&s, 'K') as u64, flowers, "flowers, {steps} steps");
        assert_eq!(count(&s, 'L') as u64, 2 * flowers, "leaves, {steps} steps");
        assert_eq!(count(&s, 'A'), apices, "apices, {steps} steps");
        assert_eq!((count(&s, 'I') as u64, count(&s, 'J') as u64), (flowers, flowers));
    }
    // The counts, for the record: 65 flowers and 66 growing apices at 30 time units.
    assert_eq!((dichasium(240, 32, 56), dichasium(300, 40, 70)), ((65, 66), (65, 66)));
}
