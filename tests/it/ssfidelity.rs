//! Structure Synth fidelity (issue 18): object counts equal to Structure
//! Synth 1.5's, one small script per construct, each following the lines of
//! Structure Synth's source it cites (the rpavlik/structure-synth mirror:
//! `StructureSynth/Model/Builder.cpp`, `Action.cpp`, `CustomRule.cpp`,
//! `AmbiguousRule.cpp`, `ColorPool.cpp`, `PrimitiveRule.cpp`, `RuleSet.cpp`,
//! `State.cpp`, `StructureSynth/Parser/Tokenizer.cpp`, `EisenParser.cpp`),
//! the six examples and two of Debian's examples.
//!
//! Counts that depend on random choices follow Structure Synth's Mersenne
//! Twister streams; their expected values were also computed with an
//! independent re-reading of the same source lines (a Python model of the
//! builder and of MT19937), which agrees with the builder here.

use rulemesh::core::{Limit, Limits, OnLimit, PrimitiveKind};
use rulemesh::eisen::{build, BuildOptions, Built};
use rulemesh::export::Format;
use rulemesh::lang::eisen::syntax::{parse, ParseOptions};
use rulemesh::lang::Language;
use rulemesh::{render, RenderError, RenderRequest};

/// What the builder makes of `src` with request seed `seed`, under default limits.
fn built(src: &str, seed: u64) -> Built {
    built_under(src, seed, Limits::default())
}

/// What the builder makes of `src` with request seed `seed` under `limits`.
fn built_under(src: &str, seed: u64, limits: Limits) -> Built {
    let script = parse(src.as_bytes(), &ParseOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let opts = BuildOptions { seed, detail: 8, on_limit: OnLimit::Error, line_radius: 0.01, downstream_bytes: [0; 9], vertex_bytes: 0, per_instance: None };
    let mut budget = rulemesh::core::Budget::new(limits);
    build(&script, &opts, &mut budget).unwrap_or_else(|e| panic!("{e}"))
}

fn objects(src: &str) -> u64 {
    built(src, 0).objects
}

fn kinds(src: &str, seed: u64) -> Vec<PrimitiveKind> {
    built(src, seed).scene.affine.iter().map(|a| a.kind).collect()
}

fn req() -> RenderRequest {
    RenderRequest { language: Some(Language::Eisenscript), format: Format::Stl, ..RenderRequest::default() }
}

fn parse_error(src: &str) -> String {
    parse(src.as_bytes(), &ParseOptions::default()).err().map(|e| e.to_string()).unwrap_or_else(|| panic!("{src:?} parsed"))
}

/// Example 1: a generation limit is not a stack depth. `Builder::recurseBreadthFirst`
/// (Builder.cpp:114) stops at `maxGenerations`, `maxObjects` objects or pending
/// states; nothing recurses, so `set maxdepth 5000` renders, as in Structure Synth.
#[test]
fn example_1_generation_limits_are_not_stack_depth() {
    let out = render(b"set maxdepth 5000\nr\nrule r { { x 1 } r box }\n", &req()).unwrap_or_else(|e| panic!("{e}"));
    // Generation 1 runs the top level, 2 queues the first box, 5000 draws the last.
    assert_eq!(out.primitives, 4998);
    // Debian's Ball.es has `set maxdepth 2000` and NineWorthies.es `set maxdepth 3000`.
    let ball = std::fs::read("/usr/share/structure-synth/Examples/Ball.es").expect("Debian's structure-synth examples (scripts/test installs them)");
    assert!(render(&ball, &req()).is_ok());
    // The guards are the budget's: a generation limit the steps cannot reach ends at the step limit.
    let few = RenderRequest { limits: Limits { max_steps: 10_000, ..Limits::default() }, ..req() };
    match render(b"set maxdepth 100000\nr\nrule r { { x 1 } r box }\n", &few) {
        Err(RenderError::Limit(l)) => assert_eq!(l.limit, Limit::Steps),
        other => panic!("{other:?}"),
    }
}

/// Example 2: with no `set maxdepth`, a rule that recurses forever draws 998
/// boxes: `maxGenerations = 1000` (Builder.cpp:22), generation 1 applies the
/// start rule, and every action — primitives included — is queued for the
/// next generation (Action.cpp:29, 50) and drawn when it runs
/// (PrimitiveRule.cpp:50), so boxes are drawn in generations 3 … 1000.
/// (eisenscript.js's test suite expects 1000; Structure Synth's source decides.)
#[test]
fn example_2_the_default_generation_limit_gives_998() {
    assert_eq!(objects("r\nrule r { { x 1 } r box }\n"), 998);
    assert_eq!(built("r\nrule r { { x 1 } r box }\n", 0).generations, 1000);
    // `set maxdepth N`: N − 2 the same way; `set maxdepth 1` runs only the start rule.
    assert_eq!(objects("set maxdepth 10\nr\nrule r { box { x 1 } r }\n"), 8);
    assert_eq!(objects("set maxdepth 1\nbox"), 0);
}

/// The `maxobjects` default, 100 000 (Builder.cpp:23), is checked before each
/// generation (Builder.cpp:114): the generation that reaches it completes.
#[test]
fn maxobjects_default_stops_after_the_generation_that_reaches_it() {
    // 300 boxes per generation from generation 3 on: 334 generations reach 100 200.
    let b = built("set maxdepth 100000\nr\nrule r { 300 * { y 1 } box { x 1 } r }\n", 0);
    assert_eq!(b.objects, 100_200);
    assert_eq!(b.generations, 336);
    // Pending states count too (`stack.size() < maxObjects`): 36 queued boxes ≥ 10 stop before drawing.
    assert_eq!(objects("set maxobjects 10\n36 * { x 1 } box\n"), 0);
}

/// Example 3: `md` and `w` are the tokenizer's abbreviations (Tokenizer.cpp:162-163),
/// so `set md 20` is `set maxdepth 20`; `set w` is refused, as
/// `EisenParser::setAction` refuses `weight` (EisenParser.cpp:313-315).
#[test]
fn example_3_md_is_maxdepth_after_set_too() {
    assert_eq!(objects("set md 20\nr\nrule r { { x 1 } r box }\n"), 18);
    assert_eq!(objects("set MD 20\nr\nrule r { { x 1 } r box }\n"), 18);
    let e = parse_error("set w 2\nbox\n");
    assert!(e.contains("rule modifier"), "{e}");
    // Rule modifiers: `md`/`maxdepth`, `w`/`weight` in any case.
    assert_eq!(objects("r\nrule r MD 4 W 2 { { x 1 } r box }\n"), 4);
}

/// Example 4: an action is any run of blocks and loops before a rule name
/// (eisenscript.js's grammar, a superset of `EisenParser::action`,
/// EisenParser.cpp:264-307). The block is a loop of count 1 and the steps
/// apply in the order written (Action.cpp:42-46).
#[test]
fn example_4_actions_are_runs_of_blocks_and_loops() {
    assert_eq!(objects("{ y 5 ry 70 s 2 } 6 * { rx 60 } orange\nrule orange { { color orange } box }\n"), 6);
    let s = built("{ x 10 } 3 * { y 1 } box\n", 0).scene;
    let p: Vec<(f32, f32)> = s.affine.iter().map(|a| (a.translation.x, a.translation.y)).collect();
    assert_eq!(p, [(10.5, 1.5), (10.5, 2.5), (10.5, 3.5)]);
    assert_eq!(objects("2 * { y 1 } { x 1 } 3 * { z 1 } { s 0.5 } box\n"), 6);
    let e = parse_error("{ x 1 } }\n");
    assert!(e.contains("after the transformation list"), "{e}");
}

/// Example 5: a rule's `maxdepth` counts per definition. `State::maxDepths`
/// is keyed by the `CustomRule` (State.h:33) — each definition of an
/// ambiguous rule is its own (AmbiguousRule.cpp:40) — counted down at each
/// application (CustomRule.cpp:24-43), inherited by every child state
/// (Action.cpp:26-28, 47-49), and reset only by retirement (CustomRule.cpp:34).
#[test]
fn example_5_rule_maxdepth_counts_per_definition() {
    let branch = "set seed 7\nrule branch md 20 w 3 { { s 0.95 y 1 hue 20 ry 90 } branch box }\nrule branch md 12 { { s 0.85 y 1 rz 25 hue 20 } branch { s 0.85 y 1 rz -25 hue 20 } branch box }\nbranch\n";
    assert_eq!(objects(branch), 1398);
    // `set seed 7` restarts both streams (Builder.cpp:347), so the request's seed does not matter.
    assert_eq!(built(branch, 12345).objects, 1398);
    // Without it, Structure Synth's seed box (the request's seed) decides.
    let unseeded = branch.replacen("set seed 7\n", "", 1);
    let counts: Vec<u64> = (0..5).map(|s| built(&unseeded, s).objects).collect();
    assert_eq!(counts, [1930, 300, 49, 1113, 3960]);
    // The count survives a call through another rule: `p` runs twice in all.
    assert_eq!(objects("p\nrule p md 2 { { x 1 } q box }\nrule q { { x 1 } p }\n"), 2);
    // Two definitions, two counts: ten branches, each ends when one definition is picked a third time.
    let two = "10 * { x 1 } r\nrule r md 2 { { y 1 } r box }\nrule r md 2 { { y 1 } r sphere }\n";
    let counts: Vec<(usize, usize)> = (0..3)
        .map(|s| {
            let k = kinds(two, s);
            (k.len(), k.iter().filter(|&&k| k == PrimitiveKind::Box).count())
        })
        .collect();
    assert_eq!(counts, [(30, 13), (29, 16), (34, 18)]);
}

/// Retirement (CustomRule.cpp:31-38): a retired definition resets its count
/// to its `maxdepth` and runs the substitute in place, in the same generation.
#[test]
fn retirement_resets_the_count_and_runs_in_place() {
    // Cycles of four generations: three boxes queued, then `q` queues `r` afresh.
    assert_eq!(objects("set maxdepth 100\nr\nrule r md 3 > q { { x 1 } r box }\nrule q { { y 1 } r }\n"), 74);
    let with = "r\nrule r md 3 > e { { x 1 } r box }\nrule e { sphere }\n";
    assert_eq!(kinds(with, 0).iter().filter(|&&k| k == PrimitiveKind::Sphere).count(), 1);
    // `md 0` still runs once (the first application only records −1), `md -1` is no limit.
    assert_eq!(objects("r\nrule r md 0 { { x 1 } r box }\n"), 1);
    assert_eq!(objects("set maxdepth 50\nr\nrule r md -1 { { x 1 } r box }\n"), 48);
}

/// Loops (Action.cpp:33-65): N copies at T¹ … Tᴺ, chained loops multiply,
/// the first counter runs fastest, and a count of 0 still makes one copy
/// because the counters are checked only after a copy is queued.
#[test]
fn loops_and_chained_loops_count_as_action_apply() {
    assert_eq!(objects("3 * { x 2 } box\n"), 3);
    assert_eq!(objects("2 * { y 1 } 3 * { x 1 } box\n"), 6);
    assert_eq!(objects("2 * { y 1 } 3 * { x 1 } 4 * { z 1 } box\n"), 24);
    assert_eq!(objects("0 * { x 1 } box\n"), 1);
    assert_eq!(objects("4 * { x 1 } 0 * { y 1 } box\n"), 1);
    assert_eq!(objects("0 * { x 1 } 3 * { y 1 } box\n"), 3);
}

/// Colour pools draw from the colour stream (`ColorPool::drawColor`,
/// ColorPool.cpp:62-84); a loop copy applies its step, and so draws, once
/// per counter value (Action.cpp:42-46), so copy k keeps the k-th of its k draws.
#[test]
fn colour_pools_draw_as_structure_synth_does() {
    let red_blue: String = built("set colorpool list:red,blue\n20 * { x 1 color random } box\n", 0)
        .scene
        .affine
        .iter()
        .map(|a| if a.colour[0] == 1.0 { 'R' } else { 'B' })
        .collect();
    assert_eq!(red_blue, "RBBBRRBBBBRRBRRBRBRR");
    // `randomhue` (the default): integer hues from `getInt(359)` at full saturation and value.
    use rulemesh::lang::eisen::syntax::colour::{hsv_to_rgb, srgb_to_linear};
    let hues = [355.0, 189.0, 8.0, 158.0, 80.0, 30.0, 210.0, 179.0, 245.0, 78.0, 144.0, 135.0];
    let want: Vec<[f32; 4]> = hues
        .iter()
        .map(|&h| {
            let c = hsv_to_rgb([h, 1.0, 1.0]).map(srgb_to_linear);
            [c[0] as f32, c[1] as f32, c[2] as f32, 1.0]
        })
        .collect();
    let got: Vec<[f32; 4]> = built("12 * { x 1 color random } box\n", 5).scene.affine.iter().map(|a| a.colour).collect();
    assert_eq!(got, want);
}

/// Seeds: rule choices draw from the geometry stream (AmbiguousRule.cpp:32),
/// seeded with the seed box (the request's seed) or `set seed N`
/// (Builder.cpp:344-349); `set seed initial` hands every later state the one
/// initial seed, which each restarts the streams from (Builder.cpp:155-158,
/// 337-342), so siblings choose alike.
#[test]
fn seeds_choose_as_structure_synth_chooses() {
    let random = "40 * { x 1 } r\nrule r { box }\nrule r w 2 { sphere }\n";
    let spheres = |seed| kinds(random, seed).iter().filter(|&&k| k == PrimitiveKind::Sphere).count();
    assert_eq!(spheres(3), 23);
    assert_eq!(kinds(random, 3), kinds(random, 3));
    // `set seed 3` restarts both streams after generation 1's draw, so it wins over the request's seed.
    let seeded = format!("set seed 3\n{random}");
    assert_eq!(kinds(&seeded, 99), kinds(&seeded, 1));
    assert_ne!(kinds(&seeded, 1), kinds(&format!("set seed 4\n{random}"), 1));
    let initial = kinds("set seed initial\n10 * { x 1 } r\nrule r { box }\nrule r { sphere }\n", 1);
    assert_eq!(initial.len(), 10);
    assert!(initial.windows(2).all(|w| w[0] == w[1]), "{initial:?}");
}

/// `set recursion depth` (Builder.cpp:37-103): rules get their maxdepth from
/// `RuleSet::setRulesMaxDepth` (RuleSet.cpp:42-48), called with the default
/// 1000 before the script's `set maxdepth` runs, which then reaches only the
/// definitions of rules with several (AmbiguousRule.h:28).
#[test]
fn depth_first_maxdepth_is_set_as_rule_set_sets_it() {
    assert_eq!(objects("set recursion depth\nset maxdepth 5\nr\nrule r { { x 1 } r box }\n"), 1000);
    // (The `w 0` definition is never picked: `random <= accWeight` holds at the first, AmbiguousRule.cpp:39.)
    assert_eq!(objects("set recursion depth\nset maxdepth 5\nr\nrule r { { x 1 } r box }\nrule r w 0 { sphere }\n"), 5);
    assert_eq!(objects("set recursion depth\nr\nrule r md 7 { { x 1 } r box }\n"), 7);
}

/// Example 6: the JavaScript ports' unambiguous additions are read —
/// leading-dot numbers, decimal fractions, arithmetic inside a list,
/// `saturation` and `m` — and their own primitives are refused by name.
#[test]
fn example_6_javascript_port_dialect() {
    let a = built("{ s .5 alpha .8 x -.25 } box\n", 0).scene;
    let b = built("{ s 0.5 alpha 0.8 x -0.25 } box\n", 0).scene;
    assert_eq!(a, b);
    assert_eq!(built("{ x 3/4 y 1.5/3 z 2 * 3 } box\n", 0).scene, built("{ x 0.75 y 0.5 z 6 } box\n", 0).scene);
    assert_eq!(built("{ saturation .5 hue 10 } box\n", 0).scene, built("{ sat 0.5 h 10 } box\n", 0).scene);
    assert_eq!(built("{ m 1 0 0 0 .53 -.85 0 .85 .53 } box\n", 0).scene, built("{ matrix 1 0 0 0 0.53 -0.85 0 0.85 0.53 } box\n", 0).scene);
    assert_eq!(objects("set maxdepth 10\nr\nrule r md 5 w .5 { { x 1 } r box }\n"), 5);
    assert_eq!(built("triangle [0,0,0;1,0,0;0,1,0]\n", 0).scene, built("triangle[0,0,0;1,0,0;0,1,0]\n", 0).scene);
    assert!(parse_error("{ x 2 } triangle\n").contains("corners"));
    let e = parse_error("{ x 1 } tube\n");
    assert!(e.contains("JavaScript port"), "{e}");
    // BrowserSynth's pyramids (its `scripts/eisenscript.js` primitive table).
    assert!(parse_error("pyra4\n").contains("JavaScript port"));
    // A script's own rule of that name is its rule.
    assert_eq!(objects("tube\nrule tube { box }\n"), 1);
    // Refusals that protect the server say why.
    assert!(parse_error("set colorpool image:x.png\nbox\n").contains("cannot read"));
    assert!(parse_error("set background random\nbox\n").contains("not a colour"));
}

/// Loop counts: `EisenParser::action` takes any integer count
/// (EisenParser.cpp:283-287), and `Action::apply` (Action.cpp:33-65) queues
/// a copy before it checks the counters, which start at 1: a count ≤ 0
/// makes one copy as 0 does, and a last loop ≤ 0 ends the action after it.
#[test]
fn negative_loop_counts_make_one_copy_as_action_apply_does() {
    assert_eq!(objects("-2 * { x 1 } box\n"), 1);
    let s = built("-2 * { x 1 } box\n", 0).scene;
    // The one copy has its step applied once (counter 1): the box's centre is at x = 1.5.
    assert_eq!(s.affine.iter().map(|a| a.translation.x).collect::<Vec<_>>(), [1.5]);
    assert_eq!(objects("3 * { x 1 } -1 * { y 1 } box\n"), 1);
    assert_eq!(objects("-1 * { x 1 } 3 * { y 1 } box\n"), 3);
    // Not a whole number: refused, as EisenParser.cpp:285 refuses it.
    assert!(parse_error("1.5 * { x 1 } box\n").contains("whole number"));
}

/// Weights: `ruleModifierList` takes any number (EisenParser.cpp:73-79) and
/// `AmbiguousRule::apply` (AmbiguousRule.cpp:26-44) draws
/// `random = total · getDouble()` and takes the first definition with
/// `random <= accWeight`, else the last. With weights −1 and 1 the total is 0,
/// so `random` is 0 and the second is taken whatever the seed; with −1 and −1
/// the first is taken when the draw is ≥ ½, else the last. (The expected
/// strings were computed with an independent MT19937 in Python: draws 3 … 42
/// of the request's seed, after the two generations' draws, Builder.cpp:118.)
#[test]
fn negative_weights_choose_as_ambiguous_rule_does() {
    for seed in 0..4 {
        assert_eq!(kinds("r\nrule r w -1 { box }\nrule r w 1 { sphere }\n", seed), [PrimitiveKind::Sphere]);
    }
    let both = "40 * { x 1 } r\nrule r w -1 { box }\nrule r w -1 { sphere }\n";
    let letters = |seed| kinds(both, seed).iter().map(|&k| if k == PrimitiveKind::Box { 'B' } else { 'S' }).collect::<String>();
    assert_eq!(letters(0), "BBBBBBSBBSSSBSBSSSBBBSBSBBSSSBSSBBBSBBBS");
    assert_eq!(letters(1), "BBSSSBSSSSSSSBSBBBSSBBSSBSSBBBSSBSSBSBBB");
    assert_eq!(letters(2), "SBBBSSSSSSSBBSSSSBBBBBSSBBSBBSBBSSBSSBBS");
}

/// Names Structure Synth leaves to scripts: its primitives are `box`, `sphere`,
/// `cylinder`, `mesh`, `line`, `dot`, `grid`, `template` (RuleSet.cpp:28-37)
/// and its tokenizer's words are those of Tokenizer.cpp:21. eisenscript.js's
/// `point` (for `dot`) and rulemesh's `colour` (for `color`, inside a list)
/// are neither, so a script's rule of that name is its rule; `dot` is still
/// refused as Structure Synth refuses it (RuleSet.cpp:83-85).
#[test]
fn port_words_stay_rule_names_as_in_structure_synth() {
    assert_eq!(kinds("point\nrule point { sphere }\n", 0), [PrimitiveKind::Sphere]);
    assert_eq!(kinds("3 * { x 1 } point\n", 0).len(), 3);
    assert_eq!(objects("2 * { x 1 } colour\nrule colour { { colour blue } box }\n"), 2);
    assert_eq!(built("{ colour blue } box\n", 0).scene, built("{ color blue } box\n", 0).scene);
    assert!(parse_error("rule dot { box }\ndot\n").contains("cannot be redefined"));
    // `c` is the tokenizer's abbreviation of `color` (Tokenizer.cpp:167), so it names no rule.
    assert_eq!(built("{ c blue } box\n", 0).scene, built("{ color blue } box\n", 0).scene);
    assert!(parse_error("rule c { box }\n").contains("rule name"));
    // `v` is reserved there too (Tokenizer.cpp:21), though its parser refuses it as a
    // transformation (EisenParser.cpp:242-243); rulemesh reads it as `brightness`.
    assert!(parse_error("rule v { box }\n").contains("rule name"));
    assert_eq!(built("{ v 0.5 } box\n", 0).scene, built("{ b 0.5 } box\n", 0).scene);
    assert_ne!(built("{ v 0.5 } box\n", 0).scene, built("box\n", 0).scene);
}

/// Debian's NineWorthies.es (`set maxobjects 52200`, `set maxdepth 3000`)
/// ends as Structure Synth's `recurseBreadthFirst` ends it (Builder.cpp:114):
/// nine `r1` branches each queue `r1` and `r2` every generation and each `r2`
/// three primitives, drawn from generation 4 on, 27 a generation; the check
/// before generation g sees 27·(g − 4) objects, so generation 1937 is the
/// last (27 · 1934 = 52 218 ≥ 52 200), far beyond the default 1000.
/// Its 9 grids a generation are 144 triangles each, 2.92 M triangles in all,
/// more than the request's default 2 M (a limit Structure Synth does not
/// have; `eisen.rs`'s `LIMITED`), so the build runs under a raised triangle limit.
#[test]
fn nine_worthies_ends_at_its_maxobjects_as_in_structure_synth() {
    let src = std::fs::read_to_string("/usr/share/structure-synth/Examples/NineWorthies.es").expect("Debian's structure-synth examples (scripts/test installs them)");
    let roomy = Limits { max_triangles: 4_000_000, max_memory: 8 << 30, ..Limits::default() };
    let b = built_under(&src, 0, roomy);
    assert_eq!(b.objects, 52_218);
    assert_eq!(b.generations, 1937);
    // Under the default limits it ends at the triangle limit, not at a depth.
    let script = parse(src.as_bytes(), &ParseOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    let opts = BuildOptions { seed: 0, detail: 8, on_limit: OnLimit::Error, line_radius: 0.01, downstream_bytes: [0; 9], vertex_bytes: 0, per_instance: None };
    let err = build(&script, &opts, &mut rulemesh::core::Budget::new(Limits::default())).err().map(|e| e.to_string());
    assert!(err.as_deref().is_some_and(|e| e.contains("triangles")), "{err:?}");
    // Ball.es (`set maxdepth 2000`): one `R1` chain queuing itself and a box each
    // generation, whichever definition is drawn, so boxes in generations 3 … 2000.
    let ball = std::fs::read_to_string("/usr/share/structure-synth/Examples/Ball.es").expect("Ball.es");
    let b = built(&ball, 0);
    assert_eq!((b.objects, b.generations), (1998, 2000));
}

/// `mesh` joins the state's frame to its `previous` one, which is null until
/// a loop sets it (State.cpp:10, Action.cpp:38-41; a `{ … }` block is a loop
/// of count 1, Action.cpp:91-95) and is copied to every child state
/// (State.cpp:41-53). With none, `PrimitiveRule::apply` counts the object and
/// draws nothing (PrimitiveRule.cpp:50, 65-83).
#[test]
fn mesh_without_a_previous_frame_counts_and_draws_nothing() {
    let bare = built("mesh\n", 0);
    assert_eq!((bare.objects, bare.scene.vertices.len()), (1, 0));
    let called = built("r\nrule r { mesh }\n", 0);
    assert_eq!((called.objects, called.scene.vertices.len()), (1, 0));
    // A block on the path gives it one, inherited through a rule.
    let drawn = built("{ x 1 } r\nrule r { mesh }\n", 0);
    assert_eq!(drawn.objects, 1);
    assert_eq!(drawn.scene.vertices.len(), built("{ x 1 } mesh\n", 0).scene.vertices.len());
    assert!(!drawn.scene.vertices.is_empty());
}
