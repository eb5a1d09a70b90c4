//! The `rand::` and `randint::` random distributions, drawn from a shape's
//! stream exactly as cfdg 3.4 draws them (John Horigan, Context Free 3.4:
//! `Rand64.cpp` `getNormal` … `getDiscrete`, which build a fresh
//! distribution per draw and clamp the parameters with `prob`, `pos`,
//! `degree` and `nat`; `myrandom.h`, Context Free's copy of LLVM libc++'s
//! `<random>` (Howard Hinnant et al., 2009–2015), whose algorithms are
//! ported here in the same order of draws: Marsaglia's polar method for
//! the normal, libc++'s rejection samplers for the gamma, Ahrens and
//! Dieter's PD algorithm (1982) for the Poisson, inversion from the mode
//! for the binomial).
//!
//! Written by hand because the draws must match cfdg's bit for bit: the
//! `rand` crate's distributions use other algorithms. Every uniform is
//! libc++'s `generate_canonical` over cfdg's xorshift64* (whose range is
//! 1 … 2⁶⁴−1): one 64-bit draw, less one, over 2⁶⁴. Rejection loops are
//! bounded ([`MAX_TRIES`]), so a parameter that makes libc++ loop forever
//! (an infinite mean) is an error here, never a hang.

use crate::cfdg::rand64::Rand64;
use crate::model::EvalError;
use crate::Span;

/// Most rejections a draw may make before it is an error.
pub(crate) const MAX_TRIES: u32 = 100_000;

/// The draw did not end; `what` names the distribution.
fn stuck(span: Span, what: &str) -> EvalError {
    EvalError::NonFinite { span, what: format!("{what}'s draw"), value: "did not converge".into() }
}

/// A draw from one stream, counting rejections.
struct Draw<'r> {
    rand: &'r mut Rand64,
    span: Span,
    tries: u32,
}

impl Draw<'_> {
    fn again(&mut self, what: &str) -> Result<(), EvalError> {
        self.tries += 1;
        if self.tries > MAX_TRIES {
            return Err(stuck(self.span, what));
        }
        Ok(())
    }

    /// `generate_canonical<double, 53>`: (g() − min) / (max − min + 1).
    fn canonical(&mut self) -> f64 {
        (self.rand.next_u64() - 1) as f64 / 18_446_744_073_709_551_616.0
    }

    /// `uniform_real_distribution(a, b)`.
    fn uniform(&mut self, a: f64, b: f64) -> f64 {
        (b - a) * self.canonical() + a
    }

    /// `exponential_distribution(lambda)`.
    fn exponential(&mut self, lambda: f64) -> f64 {
        -(1.0 - self.canonical()).ln() / lambda
    }

    /// `normal_distribution(mean, stddev)`, a fresh one: the polar
    /// method's second value is thrown away with the distribution.
    fn normal(&mut self, mean: f64, stddev: f64) -> Result<f64, EvalError> {
        loop {
            let u = self.uniform(-1.0, 1.0);
            let v = self.uniform(-1.0, 1.0);
            let s = u * u + v * v;
            if !(s > 1.0 || s == 0.0) {
                let f = (-2.0 * s.ln() / s).sqrt();
                return Ok(u * f * stddev + mean);
            }
            self.again("rand::normal")?;
        }
    }

    /// `gamma_distribution(alpha, beta)`.
    fn gamma(&mut self, a: f64, beta: f64) -> Result<f64, EvalError> {
        let x;
        if a == 1.0 {
            x = self.exponential(1.0);
        } else if a > 1.0 {
            let b = a - 1.0;
            let c = 3.0 * a - 0.75;
            loop {
                let u = self.uniform(0.0, 1.0);
                let v = self.uniform(0.0, 1.0);
                let w = u * (1.0 - u);
                if w != 0.0 {
                    let y = (c / w).sqrt() * (u - 0.5);
                    let cand = b + y;
                    if cand >= 0.0 {
                        let z = 64.0 * w * w * w * v * v;
                        if z <= 1.0 - 2.0 * y * y / cand || z.ln() <= 2.0 * (b * (cand / b).ln() - y) {
                            x = cand;
                            break;
                        }
                    }
                }
                self.again("rand::gamma")?;
            }
        } else {
            loop {
                let u = self.uniform(0.0, 1.0);
                let es = self.exponential(1.0);
                if u <= 1.0 - a {
                    let cand = u.powf(1.0 / a);
                    if cand <= es {
                        x = cand;
                        break;
                    }
                } else {
                    let e = -((1.0 - u) / a).ln();
                    let cand = (1.0 - a + a * e).powf(1.0 / a);
                    if cand <= e + es {
                        x = cand;
                        break;
                    }
                }
                self.again("rand::gamma")?;
            }
        }
        Ok(x * beta)
    }

    /// `bernoulli_distribution(p)`.
    fn bernoulli(&mut self, p: f64) -> bool {
        self.uniform(0.0, 1.0) < p
    }

    /// `binomial_distribution(t, p)`: inversion from the mode.
    fn binomial(&mut self, t: i64, p: f64) -> Result<i64, EvalError> {
        if t == 0 || p == 0.0 {
            return Ok(0);
        }
        if p == 1.0 {
            return Ok(t);
        }
        let (r0, pr, odds) = if 0.0 < p && p < 1.0 {
            let tf = t as f64;
            let r0 = ((tf + 1.0) * p) as i64;
            let r0f = r0 as f64;
            let pr = (libm::lgamma(tf + 1.0) - libm::lgamma(r0f + 1.0) - libm::lgamma(tf - r0f + 1.0) + r0f * p.ln() + (tf - r0f) * (1.0 - p).ln()).exp();
            (r0, pr, p / (1.0 - p))
        } else {
            (0, 0.0, 0.0)
        };
        let mut u = self.uniform(0.0, 1.0) - pr;
        if u < 0.0 {
            return Ok(r0);
        }
        let (mut pu, mut pd, mut ru, mut rd) = (pr, pr, r0, r0);
        loop {
            if rd >= 1 {
                pd *= rd as f64 / (odds * (t - rd + 1) as f64);
                u -= pd;
                if u < 0.0 {
                    return Ok(rd - 1);
                }
            }
            rd -= 1;
            ru += 1;
            if ru <= t {
                pu *= (t - ru + 1) as f64 * odds / ru as f64;
                u -= pu;
                if u < 0.0 {
                    return Ok(ru);
                }
            }
            self.again("randint::binomial")?;
        }
    }

    /// `negative_binomial_distribution(k, p)`.
    fn negative_binomial(&mut self, k: i64, p: f64) -> Result<i64, EvalError> {
        if (k as f64) <= 21.0 * p {
            let (mut f, mut s) = (0i64, 0i64);
            while s < k {
                if self.bernoulli(p) {
                    s += 1;
                } else {
                    f += 1;
                }
                self.again("randint::negbinomial")?;
            }
            return Ok(f);
        }
        let mean = self.gamma(k as f64, (1.0 - p) / p)?;
        self.poisson(mean)
    }

    /// `poisson_distribution(mean)`: multiplication of uniforms below 10,
    /// Ahrens and Dieter's PD algorithm above.
    fn poisson(&mut self, mean: f64) -> Result<i64, EvalError> {
        if mean < 10.0 {
            let l = (-mean).exp();
            let mut x = 0i64;
            let mut p = self.uniform(0.0, 1.0);
            while p > l {
                p *= self.uniform(0.0, 1.0);
                x += 1;
                self.again("randint::poisson")?;
            }
            return Ok(x);
        }
        let s = mean.sqrt();
        let d = 6.0 * mean * mean;
        let l = ((mean - 1.1484) as i64) as f64;
        let omega = 0.3989423 / s;
        let b1 = 0.4166667E-1 / mean;
        let b2 = 0.3 * b1 * b1;
        let c3 = 0.1428571 * b1 * b2;
        let c2 = b2 - 15.0 * c3;
        let c1 = b1 - 6.0 * b2 + 45.0 * c3;
        let c0 = 1.0 - b1 + 3.0 * b2 - 15.0 * c3;
        let c = 0.1069 / mean;
        let mut x: i64 = 0;
        let mut difmuk = 0.0;
        let g = mean + s * self.normal(0.0, 1.0)?;
        let mut u = 0.0;
        if g >= 0.0 {
            x = g as i64;
            if x as f64 >= l {
                return Ok(x);
            }
            difmuk = mean - x as f64;
            u = self.uniform(0.0, 1.0);
            if d * u >= difmuk * difmuk * difmuk {
                return Ok(x);
            }
        }
        let mut using_exp = false;
        loop {
            let mut e = 0.0;
            if using_exp || g < 0.0 {
                loop {
                    e = self.exponential(1.0);
                    u = self.uniform(0.0, 1.0);
                    u += u - 1.0;
                    let t = 1.8 + if u < 0.0 { -e } else { e };
                    if t > -0.6744 {
                        x = (mean + s * t) as i64;
                        break;
                    }
                    self.again("randint::poisson")?;
                }
                difmuk = mean - x as f64;
                using_exp = true;
            }
            let (px, py) = if x < 10 {
                const FAC: [i64; 10] = [1, 1, 2, 6, 24, 120, 720, 5040, 40320, 362880];
                let fac = usize::try_from(x).ok().and_then(|i| FAC.get(i)).copied().unwrap_or(1);
                (-mean, mean.powf(x as f64) / fac as f64)
            } else {
                let xf = x as f64;
                let mut del = 0.8333333E-1 / xf;
                del -= 4.8 * del * del * del;
                let v = difmuk / xf;
                let px = if v.abs() > 0.25 {
                    xf * (1.0 + v).ln() - difmuk - del
                } else {
                    xf * v * v * (((((((0.1250060 * v + -0.1384794) * v + 0.1421878) * v + -0.1661269) * v + 0.2000118) * v + -0.2500068) * v + 0.3333333) * v + -0.5) - del
                };
                (px, 0.3989423 / xf.sqrt())
            };
            let r = (0.5 - difmuk) / s;
            let r2 = r * r;
            let fx = -0.5 * r2;
            let fy = omega * (((c3 * r2 + c2) * r2 + c1) * r2 + c0);
            if using_exp {
                if c * u.abs() <= py * (px + e).exp() - fy * (fx + e).exp() {
                    break;
                }
            } else if fy - u * fy <= py * (px - fx).exp() {
                break;
            }
            using_exp = true;
            self.again("randint::poisson")?;
        }
        Ok(x)
    }
}

/// `Rand64::prob`: clamped to [0, 1].
fn prob(p: f64) -> f64 {
    if p < 0.0 {
        0.0
    } else if p > 1.0 {
        1.0
    } else {
        p
    }
}

/// `Rand64::pos`: positive, else the smallest step.
fn pos(p: f64) -> f64 {
    if p > 0.0 {
        p
    } else {
        f64::EPSILON
    }
}

/// `Rand64::degree`: a whole number of degrees of freedom, at least 1.
fn degree(n: f64) -> f64 {
    if n >= 1.0 {
        n.floor()
    } else {
        1.0
    }
}

/// `Rand64::nat` of a count converted as cfdg converts it (through an
/// unsigned 64-bit integer).
fn nat(v: f64) -> i64 {
    let i = (v as u64) as i64;
    i.max(1)
}

/// Whether `name` is one of the distributions.
pub(crate) fn is_distribution(name: &str) -> bool {
    matches!(
        name,
        "rand::exponential" | "rand::gamma" | "rand::weibull" | "rand::extremeV" | "rand::normal" | "rand::lognormal" | "rand::chisquared" | "rand::cauchy" | "rand::fisherF" | "rand::studentT" | "randint::bernoulli" | "randint::binomial" | "randint::negbinomial" | "randint::poisson" | "randint::discrete" | "randint::geometric"
    )
}

/// Draws `name` with arguments `a` from `rand` (`ASTfunction::evaluate`'s
/// `Rand…` cases; the argument counts are cfdg's compile-time checks).
pub fn draw(name: &str, a: &[f64], rand: &mut Rand64, span: Span) -> Result<f64, EvalError> {
    let want = |n: usize| -> Result<(), EvalError> {
        if a.len() == n {
            Ok(())
        } else {
            Err(EvalError::BadParam { name: name.to_string(), message: format!("{}:{}: {}", span.line, span.column, if n == 1 { "Function takes one argument" } else { "Function takes two arguments" }) })
        }
    };
    let mut d = Draw { rand, span, tries: 0 };
    Ok(match name {
        "rand::exponential" => {
            want(1)?;
            d.exponential(pos(a[0]))
        }
        "rand::gamma" => {
            want(2)?;
            d.gamma(pos(a[0]), pos(a[1]))?
        }
        "rand::weibull" => {
            want(2)?;
            pos(a[1]) * d.exponential(1.0).powf(1.0 / pos(a[0]))
        }
        "rand::extremeV" => {
            want(2)?;
            a[0] - pos(a[1]) * (-(1.0 - d.uniform(0.0, 1.0)).ln()).ln()
        }
        "rand::normal" => {
            want(2)?;
            d.normal(a[0], a[1])?
        }
        "rand::lognormal" => {
            want(2)?;
            d.normal(a[0], a[1])?.exp()
        }
        "rand::chisquared" => {
            want(1)?;
            d.gamma(degree(a[0]) / 2.0, 2.0)?
        }
        "rand::cauchy" => {
            want(2)?;
            a[0] + pos(a[1]) * (std::f64::consts::PI * d.uniform(0.0, 1.0)).tan()
        }
        "rand::fisherF" => {
            want(2)?;
            let (m, n) = (degree(a[0]), degree(a[1]));
            let top = n * d.gamma(m * 0.5, 1.0)?;
            top / (m * d.gamma(n * 0.5, 1.0)?)
        }
        "rand::studentT" => {
            want(1)?;
            let n = degree(a[0]);
            let z = d.normal(0.0, 1.0)?;
            z * (n / d.gamma(n * 0.5, 2.0)?).sqrt()
        }
        "randint::bernoulli" => {
            want(1)?;
            f64::from(u8::from(d.bernoulli(prob(a[0]))))
        }
        "randint::binomial" => {
            want(2)?;
            d.binomial(nat(a[0]), prob(a[1]))? as f64
        }
        "randint::negbinomial" => {
            want(2)?;
            d.negative_binomial(nat(a[0]), prob(a[1]))? as f64
        }
        "randint::geometric" => {
            want(1)?;
            d.negative_binomial(1, prob(a[0]))? as f64
        }
        "randint::poisson" => {
            want(1)?;
            d.poisson(pos(a[0]))? as f64
        }
        _ => discrete(a, &mut d) as f64,
    })
}

/// `Rand64::getDiscrete`: the weights' absolute values, normalised and
/// summed, and the first partial sum above one uniform draw (none is
/// drawn for no weights; one weight still draws).
fn discrete(w: &[f64], d: &mut Draw) -> usize {
    if w.is_empty() {
        return 0;
    }
    let mut cum = Vec::new();
    if w.len() > 1 {
        let p: Vec<f64> = w.iter().map(|v| v.abs()).collect();
        let s: f64 = p.iter().sum();
        let mut acc = 0.0;
        for v in &p[..p.len() - 1] {
            acc += v / s;
            cum.push(acc);
        }
    }
    let u = d.uniform(0.0, 1.0);
    cum.partition_point(|&c| c <= u)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn draws_are_reproducible_and_in_range() {
        let mut r = Rand64::seeded(7);
        let mut again = Rand64::seeded(7);
        for name in ["rand::normal", "rand::gamma", "rand::fisherF", "randint::binomial", "randint::negbinomial"] {
            let a = draw(name, &[10.0, 0.5], &mut r, Span::new(1, 1)).expect("draws");
            assert_eq!(a.to_bits(), draw(name, &[10.0, 0.5], &mut again, Span::new(1, 1)).expect("draws").to_bits(), "{name}");
        }
        for _ in 0..200 {
            let b = draw("randint::binomial", &[10.0, 0.5], &mut r, Span::new(1, 1)).expect("draws");
            assert!((0.0..=10.0).contains(&b) && b.fract() == 0.0);
            let k = draw("randint::discrete", &[1.0, 0.0, 3.0], &mut r, Span::new(1, 1)).expect("draws");
            assert!(k == 0.0 || k == 2.0, "{k}");
            assert!(draw("randint::poisson", &[10.0], &mut r, Span::new(1, 1)).expect("draws") >= 0.0);
        }
        assert!(draw("rand::normal", &[1.0], &mut r, Span::new(2, 3)).is_err());
    }

    #[test]
    fn hostile_parameters_end() {
        let mut r = Rand64::seeded(3);
        for (name, a) in [("randint::poisson", vec![f64::INFINITY]), ("randint::negbinomial", vec![1e18, 1e-300]), ("rand::gamma", vec![f64::NAN, 1.0]), ("randint::binomial", vec![1e18, 0.5])] {
            let _ = draw(name, &a, &mut r, Span::new(1, 1));
        }
    }
}
