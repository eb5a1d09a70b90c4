//! Unit tests of the cpfg front end: parse errors with positions, exact
//! derivations of *The Algorithmic Beauty of Plants* figures as the vlab
//! course reproduces them, and limits named when exceeded.

use super::derive::Deriver;
use super::syntax::parse;
use crate::core::budget::{Budget, Limits, OnLimit};

fn derive_text(src: &str, seed: Option<u64>) -> String {
    let sys = parse(src.as_bytes()).expect("parses");
    let mut budget = Budget::new(Limits::default());
    let mut d = Deriver::new(&sys, seed);
    let n = sys.derivation_length.unwrap_or(0);
    d.derive(n, OnLimit::Error, &mut budget).expect("derives").string.to_text()
}

#[test]
fn koch_one_step() {
    let s = derive_text("Lsystem: 1\nderivation length: 1\nAxiom: -F\nF --> F+F-F-FF+F+F-F\nendlsystem\n", None);
    assert_eq!(s, "-F+F-F-FF+F+F-F");
}
