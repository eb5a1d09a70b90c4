//! The one expression grammar every front end parses with (MDG arguments,
//! `@define` values and function bodies; L-system arguments, conditions,
//! probabilities and `#define` bodies). Each front end keeps its own lexer
//! and names and implements [`Host`]: it turns its next token into a
//! [`Token`], resolves plain names (parameters, defines, constants) and
//! allocates `rand()` sites; the operators, their precedence, calls of the
//! shared functions, and the bounds on nesting are here, once.
//!
//! From loosest to tightest: `||`, `&&`, comparisons (`<`, `<=`, `>`, `>=`,
//! `==`, `!=`), `+ -`, `* /` (all left-associative), unary `- + !`, then
//! `^` (right-associative; its exponent may carry a unary sign). A primary
//! is a number, a parenthesised expression, a call `name(args…)` or a name.
//! A front end whose lexer has no token for an operator simply never
//! produces it (MDG's lexer has no comparison or logical operators).
//!
//! Every tree is built with its depth and node count ([`Parsed`]): the depth
//! stays at most [`MAX_NESTING`] (evaluation recurses over the tree, so even
//! long left-associative chains are bounded), and the host's nesting
//! counter, entered at every parenthesis, unary operator, exponent and call,
//! bounds the parser's own recursion, so hostile input gets an error, never
//! a stack overflow.

use super::{BinOp, Expr, Func};
use crate::core::{ParseError, Span};

/// The deepest expression tree accepted (and the nesting hosts bound their recursion by).
pub(crate) const MAX_NESTING: u32 = 256;

/// An operator or punctuation token of an expression; front ends map their
/// spellings onto these (an L-system's `=` and `|` are `Eq` and `Or`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Op {
    /// `||`
    Or,
    /// `&&`
    And,
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `==`
    Eq,
    /// `!=`
    Ne,
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
    /// `^`
    Pow,
    /// `!` (logical not: 1 when the operand is 0)
    Not,
    /// `(`
    Open,
    /// `)`
    Close,
    /// `,`
    Comma,
}

/// The next token of an expression, as the grammar sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Token<'a> {
    /// A number literal's value (the host applies units and suffixes).
    Num(f64),
    /// A name: a parameter, define or constant, or a function when `(` follows.
    Name(&'a str),
    /// An operator or punctuation.
    Op(Op),
    /// Anything else: the expression ends before it.
    Other,
}

/// An expression with its tree depth and node count (hosts that copy trees,
/// like MDG's `@define` substitution, charge the node count to a budget).
#[derive(Debug, Clone, PartialEq)]
pub struct Parsed {
    /// The tree.
    pub expr: Expr,
    /// Its depth (a leaf is 1).
    pub depth: u32,
    /// Its node count.
    pub nodes: usize,
}

impl Parsed {
    /// A tree of one node.
    pub fn leaf(expr: Expr) -> Parsed {
        Parsed { expr, depth: 1, nodes: 1 }
    }

    /// Measures a tree built elsewhere (e.g. a define copied with fresh
    /// `rand()` sites). Recursion is bounded: such trees come from this
    /// grammar, whose trees are at most [`MAX_NESTING`] deep.
    pub fn measure(expr: Expr) -> Parsed {
        fn walk(e: &Expr) -> (u32, usize) {
            match e {
                Expr::Num(_) | Expr::Param(_) | Expr::Rand(_) | Expr::Coord(_) => (1, 1),
                Expr::Neg(a) => {
                    let (d, n) = walk(a);
                    (d + 1, n + 1)
                }
                Expr::Binary(_, a, b) => {
                    let ((da, na), (db, nb)) = (walk(a), walk(b));
                    (da.max(db) + 1, na + nb + 1)
                }
                Expr::Func(_, args) => args.iter().map(walk).fold((1, 1), |(d, n), (da, na)| (d.max(da + 1), n + na)),
            }
        }
        let (depth, nodes) = walk(&expr);
        Parsed { expr, depth, nodes }
    }
}

/// What the grammar needs from a front end.
pub trait Host<'a> {
    /// The next token and where it is, without consuming it.
    fn peek(&self) -> (Token<'a>, Span);
    /// Consumes the next token.
    fn bump(&mut self);
    /// The next token as error messages name it (``` `)` ```, `end of input`).
    fn describe(&self) -> String;
    /// Enters one level of nesting at `at`; fails past the host's bound.
    fn enter(&mut self, at: Span) -> Result<(), ParseError>;
    /// Leaves the level [`Host::enter`] entered.
    fn leave(&mut self);
    /// The value of `name` where it is not called: a parameter, define or constant.
    fn name(&mut self, name: &'a str, at: Span) -> Result<Parsed, ParseError>;
    /// A fresh `rand()` site.
    fn rand_site(&mut self, at: Span) -> Result<u32, ParseError>;
    /// A call only this language has (an L-system's `ran(x)`); `None`
    /// leaves `name` to `rand()` and the shared functions.
    fn own_call(&mut self, _name: &str, _args: &mut Vec<Parsed>, _at: Span) -> Option<Result<Parsed, ParseError>> {
        None
    }
    /// Called before a call's arguments are parsed (MDG reads literals there as plain numbers).
    fn begin_args(&mut self) {}
    /// Called after a call's arguments are parsed.
    fn end_args(&mut self) {}
}

fn error(at: Span, msg: impl Into<String>) -> ParseError {
    ParseError::single(at, msg.into())
}

fn deeper(depth: u32, at: Span) -> Result<u32, ParseError> {
    if depth > MAX_NESTING {
        return Err(error(at, format!("nesting deeper than {MAX_NESTING}")));
    }
    Ok(depth)
}

/// `-a`, folding a literal (`-2` is the number −2, exactly as `Neg(2)` evaluates).
pub(crate) fn negate(a: Parsed, at: Span) -> Result<Parsed, ParseError> {
    if let Expr::Num(v) = a.expr {
        return Ok(Parsed::leaf(Expr::Num(-v)));
    }
    let depth = deeper(a.depth + 1, at)?;
    Ok(Parsed { expr: Expr::Neg(Box::new(a.expr)), depth, nodes: a.nodes + 1 })
}

/// `a op b`; `at` locates a depth error.
pub(crate) fn combine(op: BinOp, a: Parsed, b: Parsed, at: Span) -> Result<Parsed, ParseError> {
    let depth = deeper(a.depth.max(b.depth) + 1, at)?;
    Ok(Parsed { expr: Expr::Binary(op, Box::new(a.expr), Box::new(b.expr)), depth, nodes: a.nodes + b.nodes + 1 })
}

/// A full expression.
pub fn expression<'a>(h: &mut impl Host<'a>) -> Result<Parsed, ParseError> {
    binary(h, 0)
}

/// The binary operator `t` is and its precedence (higher binds tighter).
fn binary_op(t: Token<'_>) -> Option<(BinOp, u8)> {
    let Token::Op(op) = t else { return None };
    Some(match op {
        Op::Or => (BinOp::Or, 0),
        Op::And => (BinOp::And, 1),
        Op::Lt => (BinOp::Lt, 2),
        Op::Le => (BinOp::Le, 2),
        Op::Gt => (BinOp::Gt, 2),
        Op::Ge => (BinOp::Ge, 2),
        Op::Eq => (BinOp::Eq, 2),
        Op::Ne => (BinOp::Ne, 2),
        Op::Add => (BinOp::Add, 3),
        Op::Sub => (BinOp::Sub, 3),
        Op::Mul => (BinOp::Mul, 4),
        Op::Div => (BinOp::Div, 4),
        _ => return None,
    })
}

/// Operators of precedence `min` or tighter, left-associative (precedence
/// climbing: the recursion is bounded by the number of levels).
fn binary<'a>(h: &mut impl Host<'a>, min: u8) -> Result<Parsed, ParseError> {
    let mut lhs = unary(h)?;
    loop {
        let (t, at) = h.peek();
        let Some((op, prec)) = binary_op(t).filter(|&(_, p)| p >= min) else { return Ok(lhs) };
        h.bump();
        let rhs = binary(h, prec + 1)?;
        lhs = combine(op, lhs, rhs, at)?;
    }
}

/// Runs `f` one nesting level deeper.
fn nested<'a, H: Host<'a>, T>(h: &mut H, at: Span, f: impl FnOnce(&mut H) -> Result<T, ParseError>) -> Result<T, ParseError> {
    h.enter(at)?;
    let r = f(h)?;
    h.leave();
    Ok(r)
}

fn unary<'a>(h: &mut impl Host<'a>) -> Result<Parsed, ParseError> {
    let (t, at) = h.peek();
    match t {
        Token::Op(Op::Sub) => {
            h.bump();
            let inner = nested(h, at, |h| unary(h))?;
            negate(inner, at)
        }
        Token::Op(Op::Add) => {
            h.bump();
            nested(h, at, |h| unary(h))
        }
        Token::Op(Op::Not) => {
            h.bump();
            let inner = nested(h, at, |h| unary(h))?;
            combine(BinOp::Eq, inner, Parsed::leaf(Expr::Num(0.0)), at)
        }
        _ => {
            let base = primary(h)?;
            let (t, at) = h.peek();
            if t != Token::Op(Op::Pow) {
                return Ok(base);
            }
            h.bump();
            let exp = nested(h, at, |h| unary(h))?;
            combine(BinOp::Pow, base, exp, at)
        }
    }
}

fn expect_close<'a>(h: &mut impl Host<'a>, context: impl FnOnce() -> String) -> Result<(), ParseError> {
    let (t, at) = h.peek();
    if t == Token::Op(Op::Close) {
        h.bump();
        return Ok(());
    }
    Err(error(at, format!("expected `)` {}, found {}", context(), h.describe())))
}

/// A primary: a number, `( expression )`, a call or a name (no operators
/// around it: MDG's arguments outside parentheses are primaries).
pub(crate) fn primary<'a>(h: &mut impl Host<'a>) -> Result<Parsed, ParseError> {
    let (t, at) = h.peek();
    match t {
        Token::Num(v) => {
            h.bump();
            Ok(Parsed::leaf(Expr::Num(v)))
        }
        Token::Op(Op::Open) => {
            h.bump();
            let e = nested(h, at, |h| expression(h))?;
            expect_close(h, || "to close `(`".to_string())?;
            Ok(e)
        }
        Token::Name(name) => {
            h.bump();
            if h.peek().0 == Token::Op(Op::Open) {
                return call(h, name, at);
            }
            h.name(name, at)
        }
        _ => Err(error(at, format!("expected a number, found {}", h.describe()))),
    }
}

/// `name( args… )`, the `(` next.
fn call<'a>(h: &mut impl Host<'a>, name: &'a str, at: Span) -> Result<Parsed, ParseError> {
    h.bump(); // `(`
    h.enter(at)?;
    h.begin_args();
    let mut args = Vec::new();
    if h.peek().0 != Token::Op(Op::Close) {
        loop {
            args.push(expression(h)?);
            if h.peek().0 == Token::Op(Op::Comma) {
                h.bump();
                continue;
            }
            break;
        }
    }
    h.end_args();
    expect_close(h, || format!("to close the arguments of `{name}`"))?;
    h.leave();
    if let Some(own) = h.own_call(name, &mut args, at) {
        return own;
    }
    if name == "rand" {
        if !args.is_empty() {
            return Err(error(at, format!("`rand` takes no arguments, {} given", args.len())));
        }
        return Ok(Parsed::leaf(Expr::Rand(h.rand_site(at)?)));
    }
    let f = Func::from_name(name).ok_or_else(|| error(at, format!("unknown function `{name}`")))?;
    let (lo, hi) = f.arity();
    if args.len() < lo || hi.is_some_and(|h| args.len() > h) {
        let want = match hi {
            Some(h) if h == lo => format!("{lo}"),
            Some(h) => format!("{lo} to {h}"),
            None => format!("at least {lo}"),
        };
        return Err(error(at, format!("`{name}` takes {want} argument(s), {} given", args.len())));
    }
    let depth = deeper(args.iter().map(|a| a.depth).max().unwrap_or(0) + 1, at)?;
    let nodes = args.iter().map(|a| a.nodes).sum::<usize>() + 1;
    Ok(Parsed { expr: Expr::Func(f, args.into_iter().map(|a| a.expr).collect()), depth, nodes })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A host over whitespace-separated tokens: numbers, names (parameters
    /// `a`, `b`, `c`) and operators spelled as in C.
    struct Words<'a> {
        toks: Vec<&'a str>,
        pos: usize,
        nesting: u32,
        sites: u32,
    }

    fn op(t: &str) -> Option<Op> {
        Some(match t {
            "||" => Op::Or,
            "&&" => Op::And,
            "<" => Op::Lt,
            "<=" => Op::Le,
            ">" => Op::Gt,
            ">=" => Op::Ge,
            "==" => Op::Eq,
            "!=" => Op::Ne,
            "+" => Op::Add,
            "-" => Op::Sub,
            "*" => Op::Mul,
            "/" => Op::Div,
            "^" => Op::Pow,
            "!" => Op::Not,
            "(" => Op::Open,
            ")" => Op::Close,
            "," => Op::Comma,
            _ => return None,
        })
    }

    impl<'a> Host<'a> for Words<'a> {
        fn peek(&self) -> (Token<'a>, Span) {
            let at = Span::new(1, self.pos as u32 + 1);
            let Some(&t) = self.toks.get(self.pos) else { return (Token::Other, at) };
            let tok = match (t.parse::<f64>(), op(t)) {
                (Ok(v), _) => Token::Num(v),
                (_, Some(o)) => Token::Op(o),
                _ => Token::Name(t),
            };
            (tok, at)
        }
        fn bump(&mut self) {
            self.pos += 1;
        }
        fn describe(&self) -> String {
            self.toks.get(self.pos).map_or("the end".to_string(), |t| format!("`{t}`"))
        }
        fn enter(&mut self, at: Span) -> Result<(), ParseError> {
            self.nesting += 1;
            if self.nesting > MAX_NESTING {
                return Err(error(at, format!("nesting deeper than {MAX_NESTING}")));
            }
            Ok(())
        }
        fn leave(&mut self) {
            self.nesting -= 1;
        }
        fn name(&mut self, name: &'a str, at: Span) -> Result<Parsed, ParseError> {
            match ["a", "b", "c"].iter().position(|n| *n == name) {
                Some(i) => Ok(Parsed::leaf(Expr::Param(i as u32))),
                None => Err(error(at, format!("unknown name `{name}`"))),
            }
        }
        fn rand_site(&mut self, _at: Span) -> Result<u32, ParseError> {
            self.sites += 1;
            Ok(self.sites - 1)
        }
    }

    fn parse(src: &str) -> Result<Parsed, String> {
        let mut h = Words { toks: src.split_whitespace().collect(), pos: 0, nesting: 0, sites: 0 };
        let e = expression(&mut h).map_err(|e| e.diagnostics[0].message.clone())?;
        match h.toks.get(h.pos) {
            Some(t) => Err(format!("trailing `{t}`")),
            None => Ok(e),
        }
    }

    struct Env;
    impl crate::expr::ExprEnv for Env {
        fn param(&self, i: u32) -> f64 {
            [2.0, 3.0, 4.0][i as usize]
        }
        fn rand(&mut self, _: u32) -> f64 {
            0.5
        }
    }

    fn value(src: &str) -> f64 {
        parse(src).unwrap_or_else(|e| panic!("{src}: {e}")).expr.eval(&mut Env)
    }

    #[test]
    fn precedence_and_associativity() {
        assert_eq!(value("1 + 2 * 3"), 7.0);
        assert_eq!(value("10 - 4 - 3"), 3.0, "left-associative");
        assert_eq!(value("24 / 4 / 2"), 3.0, "left-associative");
        assert_eq!(value("2 ^ 3 ^ 2"), 512.0, "right-associative");
        assert_eq!(value("- 2 ^ 2"), -4.0, "^ binds tighter than unary minus");
        assert_eq!(value("2 ^ - 1"), 0.5, "an exponent may carry a sign");
        assert_eq!(value("1 + 2 < 4 && a == 2 || 0"), 1.0);
        assert_eq!(value("1 < 2 == 1"), 1.0, "comparisons chain left to right");
        assert_eq!(value("! 0 + ! 5"), 1.0);
        assert_eq!(value("+ a * ( b + c )"), 14.0);
        assert_eq!(value("max ( a , b , c ) + atan2 ( 0 , 1 )"), 4.0);
        assert_eq!(value("rand ( ) * 4"), 2.0);
    }

    #[test]
    fn trees_carry_their_depth_and_size_and_literals_fold() {
        let p = parse("- 2").expect("parses");
        assert_eq!(p, Parsed::leaf(Expr::Num(-2.0)));
        let p = parse("a + b * c").expect("parses");
        assert_eq!((p.depth, p.nodes), (3, 5));
        assert_eq!(Parsed::measure(p.expr.clone()), p);
        let p = parse("min ( a , - b ) ").expect("parses");
        assert_eq!((p.depth, p.nodes), (3, 4));
        assert_eq!(Parsed::measure(p.expr.clone()), p);
    }

    #[test]
    fn errors_name_what_went_wrong() {
        assert_eq!(parse("1 +").unwrap_err(), "expected a number, found the end");
        assert_eq!(parse("( 1").unwrap_err(), "expected `)` to close `(`, found the end");
        assert_eq!(parse("sin ( 1 , 2 )").unwrap_err(), "`sin` takes 1 argument(s), 2 given");
        assert_eq!(parse("min ( )").unwrap_err(), "`min` takes at least 1 argument(s), 0 given");
        assert_eq!(parse("rand ( 1 )").unwrap_err(), "`rand` takes no arguments, 1 given");
        assert_eq!(parse("f ( 1 )").unwrap_err(), "unknown function `f`");
        assert_eq!(parse("d").unwrap_err(), "unknown name `d`");
    }

    #[test]
    fn nesting_and_long_chains_are_bounded() {
        let deep = format!("{} 1 {}", "( ".repeat(300), ") ".repeat(300));
        assert_eq!(parse(&deep).unwrap_err(), "nesting deeper than 256");
        let ok = format!("{} 1 {}", "( ".repeat(200), ") ".repeat(200));
        assert_eq!(value(&ok), 1.0);
        // A left-associative chain is a deep tree: bounded too, so evaluation cannot overflow.
        let chain = format!("1{}", " + 1".repeat(300));
        assert_eq!(parse(&chain).unwrap_err(), "nesting deeper than 256");
        let chain = format!("1{}", " + 1".repeat(200));
        assert_eq!(value(&chain), 201.0);
        let signs = format!("{}1", "- ".repeat(300));
        assert_eq!(parse(&signs).unwrap_err(), "nesting deeper than 256");
    }
}
