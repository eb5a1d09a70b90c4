//! User-defined functions (`func(id, x)`, manual §5.5): B-spline curves of
//! one variable drawn with vlab's `funcedit`, read from `.func` files and
//! `.fset` galleries the view names, and evaluated as cpfg evaluates them
//! (`AlgorithmicBotany/vlab`, `cpfg/splinefun.cpp`, `SplineFunction`): a
//! clamped uniform cubic B-spline over the control points, y found for x by
//! bisection to within 0.001, and, when the file asks for samples, the
//! samples precomputed and interpolated linearly.

/// Most control points or samples accepted from one file.
pub(crate) const MAX_POINTS: usize = 10_000;

/// One function.
#[derive(Debug, Clone, PartialEq)]
pub struct Function {
    /// Its name (`name:`), for a gallery's `#define`s.
    pub name: String,
    pts: Vec<[f64; 2]>,
    vals: Option<Vec<f64>>,
}

impl Function {
    /// The function at `x`, clamped to [0, 1] (`GetValue`).
    pub fn value(&self, x: f64) -> f64 {
        let x = if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
        match &self.vals {
            Some(v) if v.len() > 2 => {
                let index = x * (v.len() - 1) as f64;
                let i = index.floor() as usize;
                if i >= v.len() - 1 {
                    return v[v.len() - 1];
                }
                let w2 = index - i as f64;
                (1.0 - w2) * v[i] + w2 * v[i + 1]
            }
            _ => self.exact(x),
        }
    }

    fn exact(&self, x: f64) -> f64 {
        let (mut low, mut high) = (0.0, 1.0);
        let mut p = [0.0, 0.0];
        // cpfg loops until within 0.001; 64 halvings exhaust a double.
        for _ in 0..64 {
            let check = (low + high) / 2.0;
            p = self.point(check);
            if p[0] > x {
                high = check;
            } else {
                low = check;
            }
            if (p[0] - x).abs() <= 0.001 {
                break;
            }
        }
        p[1]
    }

    fn uk(&self, j: i64) -> i64 {
        let n = self.pts.len() as i64 - 1;
        if j < 4 {
            0
        } else if j > n {
            n - 2
        } else {
            j - 3
        }
    }

    fn basis(&self, k: i64, t: i64, u: f64) -> f64 {
        if t == 1 {
            return f64::from(self.uk(k) as f64 <= u && u < self.uk(k + 1) as f64);
        }
        let mut sum = 0.0;
        let div = self.uk(k + t - 1) - self.uk(k);
        if div != 0 {
            sum = (u - self.uk(k) as f64) / div as f64 * self.basis(k, t - 1, u);
        }
        let div = self.uk(k + t) - self.uk(k + 1);
        if div != 0 {
            sum += (self.uk(k + t) as f64 - u) / div as f64 * self.basis(k + 1, t - 1, u);
        }
        sum
    }

    /// `SplineFunction::P`: the curve at parameter d in [0, 1].
    fn point(&self, d: f64) -> [f64; 2] {
        let n = self.pts.len() as i64 - 1;
        let u = d * (n - 2) as f64;
        let mut s = [0.0, 0.0];
        for (k, p) in self.pts.iter().enumerate() {
            // Only the four basis functions around u are non-zero.
            if (k as f64) < u - 1.0 || (k as f64) > u + 4.0 {
                continue;
            }
            let b = self.basis(k as i64, 4, u);
            s[0] += p[0] * b;
            s[1] += p[1] * b;
        }
        s
    }

    fn precompute(&mut self, samples: usize) {
        if samples > 2 {
            let v = (0..samples).map(|i| self.exact(i as f64 / (samples - 1) as f64)).collect();
            self.vals = Some(v);
        }
    }
}

fn field<'a>(line: Option<&'a str>, key: &str) -> Result<&'a str, String> {
    line.and_then(|l| l.trim().strip_prefix(key)).map(str::trim).ok_or_else(|| format!("expected `{key}`"))
}

/// Reads one function from `lines` (a `.func` file, or one item of a
/// gallery); `samples` is the view's count for the old format.
fn read_one<'a>(lines: &mut impl Iterator<Item = &'a str>, samples: usize) -> Result<Function, String> {
    let first = lines.next().ok_or("empty function")?;
    let (name, samples, points) = if first.trim().starts_with("fver") {
        let name = field(lines.next(), "name:")?.to_string();
        let samples: usize = field(lines.next(), "samples:")?.parse().map_err(|_| "bad samples:")?;
        let mut line = lines.next();
        // Background image, markers and `flip:` are only for the editor.
        loop {
            let l = line.map(str::trim).unwrap_or("");
            if l.starts_with("points:") {
                break;
            }
            if line.is_none() {
                return Err("expected `points:`".into());
            }
            line = lines.next();
        }
        let points: usize = field(line, "points:")?.parse().map_err(|_| "bad points:")?;
        (name, samples, points)
    } else {
        let points: usize = field(Some(first), "points:")?.parse().map_err(|_| "bad points:")?;
        (String::new(), samples, points)
    };
    if !(4..=MAX_POINTS).contains(&points) || samples > MAX_POINTS {
        return Err(format!("a function needs 4 to {MAX_POINTS} points and at most {MAX_POINTS} samples"));
    }
    let mut pts = Vec::new();
    for _ in 0..points {
        let l = lines.next().ok_or("fewer points than `points:` says")?;
        let v: Vec<f64> = l.split_whitespace().filter_map(|w| w.parse().ok()).collect();
        if v.len() < 2 {
            return Err(format!("bad point `{l}`"));
        }
        let mult = v.get(2).map_or(1, |m| (*m as usize).clamp(1, 16));
        for _ in 0..mult {
            pts.push([v[0], v[1]]);
        }
    }
    let mut f = Function { name, pts, vals: None };
    f.precompute(samples);
    Ok(f)
}

/// A `.func` file.
pub(crate) fn read_function(text: &str, samples: usize) -> Result<Function, String> {
    read_one(&mut text.lines().filter(|l| !l.trim().is_empty()), samples)
}

/// A function gallery (`.fset`): `funcgalleryver`, `items: n`, then the functions.
pub(crate) fn read_set(text: &str) -> Result<Vec<Function>, String> {
    let mut lines = text.lines().filter(|l| !l.trim().is_empty());
    lines.next();
    let items: usize = field(lines.next(), "items:")?.parse().map_err(|_| "bad items:")?;
    (0..items.min(4096)).map(|_| read_one(&mut lines, 0)).collect()
}
