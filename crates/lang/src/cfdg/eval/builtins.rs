//! Built-in functions added with cfdg 3's vectors and random
//! distributions, as `ASTfunction` evaluates them (`astexpression.cpp`,
//! John Horigan, Context Free 3.4, 2018): `vec()` here, the `rand::` and
//! `randint::` draws in `distributions.rs`.

use crate::model::EvalError;
use crate::Span;

/// cfdg's largest vector (`AST::MaxVectorSize`).
pub(crate) const MAX_VECTOR: usize = 99;

fn bad(span: Span, name: &str, message: &str) -> EvalError {
    EvalError::BadParam { name: name.to_string(), message: format!("{}:{}: {message}", span.line, span.column) }
}

/// `vec(n, a, b, …)`: a vector of `n` numbers repeating the numbers after
/// `n` (`ASTfunction::evaluate`'s `Vec`: `res[i] = l[i % (lc - 1) + 1]`
/// over the flattened arguments). `n` must be a natural number from 2 to
/// 99 and at least one number must follow it (cfdg checks both when it
/// compiles: "vec() function length argument must be >= 2 and <= 99").
pub fn vec(args: &[Vec<f64>], span: Span, out: &mut Vec<f64>) -> Result<(), EvalError> {
    let Some([n]) = args.first().map(Vec::as_slice) else {
        return Err(bad(span, "vec", "vec() function length argument must be a scalar constant"));
    };
    let flat: Vec<f64> = args.iter().flatten().copied().collect();
    if args.len() < 2 || flat.len() < 2 {
        return Err(bad(span, "vec", "vec() function at least two arguments"));
    }
    if !(2.0..(MAX_VECTOR + 1) as f64).contains(&n.floor()) {
        return Err(bad(span, "vec", "vec() function length argument must be >= 2 and <= 99"));
    }
    let len = n.floor() as usize;
    out.extend((0..len).map(|i| flat[i % (flat.len() - 1) + 1]));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vec_repeats_its_numbers() {
        let mut out = Vec::new();
        vec(&[vec![5.0], vec![1.0, 2.0]], Span::new(1, 1), &mut out).expect("vec");
        assert_eq!(out, [1.0, 2.0, 1.0, 2.0, 1.0]);
        out.clear();
        vec(&[vec![2.0], vec![0.25]], Span::new(1, 1), &mut out).expect("vec");
        assert_eq!(out, [0.25, 0.25]);
    }

    #[test]
    fn vec_refuses_bad_lengths() {
        let mut out = Vec::new();
        for args in [vec![vec![1.0], vec![3.0]], vec![vec![100.0], vec![3.0]], vec![vec![2.0]], vec![vec![f64::NAN], vec![1.0]], vec![vec![2.0, 3.0], vec![1.0]]] {
            assert!(vec(&args, Span::new(2, 3), &mut out).is_err(), "{args:?}");
        }
        assert!(out.is_empty());
    }
}
