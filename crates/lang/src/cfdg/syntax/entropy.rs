//! The seeds Context Free derives from source text ("entropy"): every
//! adjustment term hashes its arguments' text and a fixed byte string for
//! its kind, then the replacement hashes its shape's name, into a stream
//! started at 0 (`ASTexpression::entropy`, `ASTmodification::addEntropy`,
//! `ASTreplacement::compile`, `astexpression.cpp`/`astreplacement.cpp`,
//! Context Free 3.4; the byte strings are cfdg's, "courtesy of HotBits").

use super::{Adjustment, Expr, TermKind};
use crate::cfdg::rand64::Rand64;

const CONS: &[u8] = b"\xC5\x60\xA5\xC5\xC8\x74";
const PAREN: &[u8] = b"\xE8\xE9\xF6\x7E\x1A\xF1";

fn op_bytes(op: char) -> &'static [u8] {
    match op {
        '*' => b"\x2E\x32\xD9\x2C\x41\xFE",
        '/' => b"\x6B\x15\x23\x41\x9E\xEB",
        '+' => b"\xD7\xB1\xB0\x39\x33\xC8",
        '-' => b"\x5D\xE7\xF0\x94\xC4\x13",
        '^' => b"\x02\x3C\x68\x36\xC5\xA0",
        'N' => b"\x55\x89\x51\x46\xDB\x84",
        'P' => b"\x8E\xAC\x29\x4B\x0E\xDC",
        '!' => b"\x19\x3A\x3E\x53\x14\xEA",
        '<' => b"\xBE\xDB\xC4\xA6\x4E\xAD",
        '>' => b"\xC7\xD9\x57\x32\xD6\x87",
        'L' => b"\xE3\x56\x7E\x44\x57\x80",
        'G' => b"\xB1\x2D\x2A\xCC\x2C\x40",
        '=' => b"\x78\x48\xC2\x95\xA9\xE2",
        'n' => b"\x36\xCC\x01\x3B\x2F\xAD",
        '&' => b"\x28\x9B\xFB\x7F\xDB\x9C",
        '|' => b"\x2E\x40\x1B\x44\x15\x7C",
        'X' => b"\xA7\x2B\x92\xFA\xFC\xF9",
        '_' => b"\x60\x2F\x10\xAD\x10\xFF",
        _ => b"",
    }
}

/// The bytes of a built-in function (`ASTfunction::entropy`'s table).
fn func_bytes(name: &str) -> &'static [u8] {
    match name {
        "cos" => b"\xA1\xE7\x9C\x1A\xAF\x7D",
        "sin" => b"\xAF\x58\xFE\x2C\xD4\x53",
        "tan" => b"\x95\xFF\x59\x11\x03\x02",
        "cot" => b"\x77\xF5\xB6\x35\x8C\xF0",
        "acos" => b"\x3A\xCD\x79\x3E\xAD\xB4",
        "asin" => b"\x1D\x75\x0B\xBC\x5F\x52",
        "atan" => b"\x0B\xC8\x89\xAB\xF8\xB7",
        "acot" => b"\x69\x7C\xC7\x1A\xF6\x7B",
        "cosh" => b"\x48\x43\x43\x35\x62\x81",
        "sinh" => b"\x51\x62\xFB\x76\xED\x9C",
        "tanh" => b"\xBB\x91\x54\xA9\x63\x84",
        "acosh" => b"\x4F\x28\x48\x20\xB7\x5C",
        "asinh" => b"\x6C\x9B\x32\xAA\x4C\xD0",
        "atanh" => b"\x58\xEC\xBB\x25\xF8\xB6",
        "log" => b"\x8E\xB8\x62\xA1\x75\x0F",
        "log10" => b"\x4A\x6C\xA3\x02\x8B\x80",
        "sqrt" => b"\x86\x7C\xFC\x20\xCB\x97",
        "exp" => b"\x88\xA8\x65\xF0\xC1\x06",
        "abs" => b"\x41\x89\x18\xD1\xAD\x82",
        "floor" => b"\xB7\x28\xD7\xD7\xA3\xCC",
        "ceiling" => b"\xF7\x96\x02\x7C\x27\xE4",
        "infinity" => b"\x2C\x28\x50\xCC\xDE\x44",
        "factorial" => b"\x19\xD7\x83\x29\x47\x99",
        "sg" => b"\xB7\x05\x28\xBA\xCD\x2E",
        "isNatural" => b"\x49\xD6\xF8\x5B\x45\x59",
        "atan2" => b"\x99\x1B\xC9\xE0\x3F\xA4",
        "divides" => b"\x78\x8E\xC8\x2C\x1C\x96",
        "div" => b"\x64\xEC\x5B\x4B\xEE\x2B",
        "mod" => b"\x0F\xE3\xFE\x5F\xBF\xBF",
        "min" => b"\xA2\x42\xA3\x49\xB1\x19",
        "max" => b"\xD3\x55\x5C\x0D\xD8\x51",
        "rand_static" => b"\xC8\xF7\xE5\x3E\x05\xA3",
        "rand" | "rand." => b"\xDA\x18\x5B\xE2\xDB\x79",
        "rand+/-" => b"\xDC\x8D\x09\x15\x8A\xC4",
        "randint" => b"\x48\x14\x4E\x27\x35\x2E",
        "bitnot" => b"\x79\x19\x1A\x9F\x4D\xA0",
        "bitor" => b"\xF2\x77\xAB\x5C\x33\x43",
        "bitand" => b"\xC3\x56\x9E\x75\xE0\x44",
        "bitxor" => b"\xBB\xFA\x2B\xD2\x91\x55",
        "bitleft" => b"\x91\x47\xE5\xE5\x0D\xAA",
        // cfdg appends these as C strings, so this one stops at its zero byte.
        "bitright" => b"\xF1\xAB\x17",
        "vec" => b"\xE1\x75\x95\xC9\x80\xCF",
        "rand::exponential" => b"\x32\xDF\x4A\xFD",
        "rand::gamma" => b"\xC9\xD5\x57\x4F\xE6\x77",
        "rand::weibull" => b"\xE7\xCF\xA2\x01\xCD\x02",
        "rand::extremeV" => b"\xE8\xCF\x86\x0B\xFD\x8E",
        "rand::normal" => b"\xCF\xAC\xD4\x12\x09\xCC",
        "rand::lognormal" => b"\x36\x65\x08\x5C\x49\xAA",
        "rand::chisquared" => b"\x6D\x4B\x49\xA8\x83\xAD",
        "rand::cauchy" => b"\x22\x6C\x9E\x77\x79\x89",
        "rand::fisherF" => b"\x9B\x76\x1B\x51\xCD\xAE",
        "rand::studentT" => b"\xF9\x41\x44\xF2\x63\xA7",
        "randint::bernoulli" => b"\xBE\xD1\x55\x04\xD4\x54",
        "randint::binomial" => b"\x6A\x69\x9A\x94\x36\x6C",
        "randint::negbinomial" => b"\xED\x31\x46\x9C\xA6\xAD",
        "randint::poisson" => b"\x09\x89\xF3\x77\xAE\x67",
        "randint::discrete" => b"\x17\x69\x8D\x61\xFF\x2A",
        "randint::geometric" => b"\xD5\x10\x2E\xA5\x03\xB4",
        "ftime" => b"\x4F\xBE\xA1\x06\x80\x06",
        "frame" => b"\x90\x70\x6A\xBB\xBA\xB0",
        "dot" => b"\x60\xAA\xB7\xE1\xB9\x06",
        "cross" => b"\x39\x38\x40\xE5\x93\xF8",
        "hsb2rgb" => b"\xC3\xD4\x57\x04\xAF\x9F",
        "rgb2hsb" => b"\xD0\x2A\x55\x7A\x53\x97",
        // if() and select() (ASTselect): the selector's list, then these bytes.
        "if" | "select" => b"\xB5\xA2\x4A\x74\xA9\xDF",
        _ => b"",
    }
}

/// The bytes of an adjustment kind (`ASTmodTerm::entropy`'s table).
fn term_bytes(kind: TermKind) -> &'static [u8] {
    match kind {
        TermKind::X => b"\x95\xE7\x48\x5E\xCC\x06",
        TermKind::Y => b"\x84\x2B\xF3\xBB\x93\x59",
        TermKind::Z => b"\xC8\x3A\x12\x32\x36\x71",
        TermKind::Transform => b"\x88\x90\x54\xC5\xD3\x20",
        TermKind::Size | TermKind::ZSize => b"\x64\xEC\x5B\x4B\xEE\x2B",
        TermKind::Rotate => b"\x84\xB0\x92\x26\x59\xE2",
        TermKind::Skew => b"\xFF\x2D\x84\x01\xA0\x0A",
        TermKind::Flip => b"\x43\x5A\x17\xEA\x12\x05",
        TermKind::Hue => b"\x02\xDE\x2B\x2C\x25\xA1",
        TermKind::Sat => b"\x18\x4F\xCF\x04\x3F\xE5",
        TermKind::Bright => b"\x1F\x3F\xEB\xA2\xA2\x7E",
        TermKind::Alpha => b"\xB4\xFF\x9E\x45\xEE\x7E",
        TermKind::HueTarg => b"\xAF\xE5\x58\x33\x20\xF8",
        TermKind::SatTarg => b"\x98\x80\xED\x44\x2F\xF2",
        TermKind::BrightTarg => b"\x68\xD6\xCB\x8A\x96\x20",
        TermKind::AlphaTarg => b"\x24\x4C\xCC\x41\x09\xC7",
        TermKind::TargHue => b"\xDB\x3F\xA1\xDA\xE7\x45",
        TermKind::TargSat => b"\xDA\x75\x13\xD3\x30\xEA",
        TermKind::TargBright => b"\x8F\x01\x2B\x75\xC3\x25",
        TermKind::TargAlpha => b"\xE7\xCD\x5E\xE3\x88\xF4",
        TermKind::Time => b"\x20\xC6\xE8\x02\xED\x27",
        TermKind::TimeScale => b"\x78\x8E\xC8\x2C\x1C\x96",
        TermKind::Ignored => b"\xBE\x9F\x5F\x7F\x4A\x7E",
    }
}

/// Appends `e`'s entropy to `out` (`ASTexpression::entropy` and its overrides).
pub(crate) fn expr_entropy(e: &Expr, out: &mut Vec<u8>) {
    match e {
        Expr::Num(_, text) => out.extend_from_slice(text.as_bytes()),
        Expr::Var(name, _) => out.extend_from_slice(name.as_bytes()),
        Expr::Unary(op, a) => {
            expr_entropy(a, out);
            out.extend_from_slice(op_bytes(*op));
        }
        Expr::Binary(op, a, b) => {
            expr_entropy(a, out);
            expr_entropy(b, out);
            out.extend_from_slice(op_bytes(*op));
        }
        Expr::Paren(a) => {
            expr_entropy(a, out);
            out.extend_from_slice(PAREN);
        }
        Expr::Cons(v) => {
            for a in v {
                expr_entropy(a, out);
            }
            out.extend_from_slice(CONS);
        }
        Expr::Call(name, args, _) => {
            if let Some(a) = args.as_ref() {
                expr_entropy(a, out);
            }
            let f = func_bytes(name);
            // A user function hashes its definition's name instead.
            out.extend_from_slice(if f.is_empty() { name.as_bytes() } else { f });
        }
        // ASTarray: the name, then the index list (`ASTarray::compile`).
        Expr::Index(name, args, _) => {
            out.extend_from_slice(name.as_bytes());
            expr_entropy(args, out);
        }
        // ASTruleSpecifier: its name, then its arguments (`compile`).
        Expr::Shape(name, _, args, _) => {
            out.extend_from_slice(name.as_bytes());
            if let Some(a) = args.as_ref() {
                expr_entropy(a, out);
            }
        }
        // ASTmodification has no entropy of its own (the base's, empty).
        Expr::Adjust(..) => {}
        // ASTlet is a user function named `let` whose arguments are its
        // non-constant definitions, appended into one list (`ASTlet::compile`,
        // `ASTexpression::Append`, which flattens lists); a constant let is
        // folded into a number whose text is that same entropy.
        Expr::Let(defs, _, _) => {
            let mut consts: Vec<&str> = Vec::new();
            let mut args: Vec<&Expr> = Vec::new();
            for (name, e) in defs {
                if constant_with(e, &consts) {
                    consts.push(name);
                } else {
                    args.push(e);
                }
            }
            match args.as_slice() {
                [] => {}
                [one] => expr_entropy(one, out),
                many => {
                    for e in many {
                        match e {
                            Expr::Cons(v) => v.iter().for_each(|c| expr_entropy(c, out)),
                            e => expr_entropy(e, out),
                        }
                    }
                    out.extend_from_slice(CONS);
                }
            }
            out.extend_from_slice(b"let");
        }
    }
}

/// Whether `name` is one of cfdg's built-in functions (`ASTfunction::GetFuncType`),
/// not a user function.
pub(crate) fn is_builtin(name: &str) -> bool {
    !func_bytes(name).is_empty()
}

/// Whether cfdg folds `e` at compile time (`isConstant`): numbers and pure
/// built-ins of them; never a variable, a random draw or a user function
/// (`ASTuserFunction::compile` sets `isConstant = false`).
pub(crate) fn is_constant(e: &Expr) -> bool {
    constant_with(e, &[])
}

/// [`is_constant`] where the names in `consts` (a `let`'s constant
/// definitions) are constant too.
fn constant_with(e: &Expr, consts: &[&str]) -> bool {
    let c = |e: &Expr| constant_with(e, consts);
    match e {
        Expr::Num(..) => true,
        Expr::Var(name, _) => consts.contains(&name.as_str()),
        Expr::Index(..) => false,
        Expr::Shape(_, _, args, _) => args.as_ref().as_ref().is_none_or(c),
        Expr::Adjust(a, _) => a.terms.iter().all(|t| c(&t.args)),
        Expr::Unary(_, a) | Expr::Paren(a) => c(a),
        Expr::Binary(_, a, b) => c(a) && c(b),
        Expr::Cons(v) => v.iter().all(c),
        // rand_static() is a constant drawn at parse time (cfdg's RandStaticIsConst).
        Expr::Call(name, args, _) => is_builtin(name) && (name == "rand_static" || !name.starts_with("rand")) && !matches!(name.as_str(), "ftime" | "frame") && args.as_ref().as_ref().is_none_or(c),
        Expr::Let(defs, body, _) => {
            let mut inner = consts.to_vec();
            for (name, e) in defs {
                if !constant_with(e, &inner) {
                    return false;
                }
                inner.push(name);
            }
            constant_with(body, &inner)
        }
    }
}

/// Hashes an adjustment's terms into `seed` from byte index `*index`.
pub(crate) fn adjust_entropy(adj: &Adjustment, seed: &mut Rand64, index: &mut u32) {
    for t in &adj.terms {
        let mut ent = Vec::new();
        expr_entropy(&t.args, &mut ent);
        ent.extend_from_slice(term_bytes(t.kind));
        seed.xor_bytes(&ent, index);
    }
}

/// The seed a replacement of `shape` with `adj` xors into the random state
/// (`mChildChange.modData.mRand64Seed`): its terms, then the shape's name.
/// A shape given arguments hashes them after its name (`ASTruleSpecifier::compile`).
pub(crate) fn term_seed(adj: &Adjustment, shape: &str, args: Option<&Expr>) -> Rand64 {
    let mut seed = Rand64::raw(0);
    let mut index = 0;
    adjust_entropy(adj, &mut seed, &mut index);
    let mut name = shape.as_bytes().to_vec();
    // Reused parent parameters hash nothing (SimpleParentArgs).
    if let Some(a) = args.filter(|a| !matches!(a, Expr::Var(v, _) if v == super::REUSE)) {
        expr_entropy(a, &mut name);
    }
    seed.xor_bytes(&name, &mut index);
    seed
}

/// The seed of a loop: its adjustment's terms, then the index name and the
/// arguments' text (`ASTloop::compile`); a 3.x loop hashes its adjustment
/// apart and the two are combined by xor with their byte indices summed
/// (`ASTmodification::grab`); a 2.x loop's index is the hidden `~~inaccessiblevar~~`.
pub(crate) fn loop_seed(adj: &Adjustment, var: &str, args: &Expr, v2: bool) -> Rand64 {
    let mut ent = var.as_bytes().to_vec();
    expr_entropy(args, &mut ent);
    if v2 {
        // A 2.x loop's adjustment is compiled twice (as a replacement's and
        // again as the loop's), so its terms are hashed twice before the
        // index; found against the seeds `cfdg -J` prints.
        let mut seed = Rand64::raw(0);
        let mut index = 0;
        adjust_entropy(adj, &mut seed, &mut index);
        adjust_entropy(adj, &mut seed, &mut index);
        seed.xor_bytes(&ent, &mut index);
        seed
    } else {
        // The loop's own modification is empty (seeded with the default
        // seed); the written adjustment is held apart, then grabbed.
        let mut seed = Rand64::default();
        let mut index = 0;
        seed.xor_bytes(&ent, &mut index);
        // The held adjustment starts from the default seed too (it was never
        // grabbed into a replacement's zeroed modification); found against
        // the seeds `cfdg -J` prints.
        let mut held = Rand64::default();
        let mut hindex = 0;
        adjust_entropy(adj, &mut held, &mut hindex);
        seed.xor(held);
        seed
    }
}

/// The seed of a definition: its name (`ASTdefine::ASTdefine`), from the default seed.
pub(crate) fn define_seed(name: &str) -> Rand64 {
    let mut seed = Rand64::default();
    let mut index = 0;
    seed.xor_bytes(name.as_bytes(), &mut index);
    seed
}
