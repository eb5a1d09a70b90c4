//! The exact Euclidean distance transform of a voxel grid: for every voxel,
//! the squared distance (in voxels) to the nearest seed voxel.
//!
//! Felzenszwalb and Huttenlocher's algorithm ("Distance Transforms of
//! Sampled Functions", Theory of Computing 8, 2012): the lower envelope of
//! parabolas along each axis in turn, linear in the voxel count. Written by
//! hand because the crates that do this (`distance-transform`, `edt`) work
//! on 2D images or on `ndarray` arrays, and this is thirty lines over the
//! flat grids the print stage already holds.

/// A value larger than any squared distance on a grid of at most 2³² voxels
/// a side, standing for "no seed".
const FAR: f64 = 1e30;

/// Replaces every value of `grid` (dims `n`, x fastest) by the squared
/// distance in voxels from that voxel to the nearest voxel whose value was
/// 0: seeds are 0, everything else must be [`f32::INFINITY`] on entry. A
/// grid without seeds comes back all infinite.
pub(super) fn squared_distances(grid: &mut [f32], n: [usize; 3]) {
    let longest = n.iter().copied().max().unwrap_or(0);
    let mut line = vec![0.0f64; longest];
    let mut out = vec![0.0f64; longest];
    let mut parabolas = vec![0usize; longest];
    let mut bounds = vec![0.0f64; longest + 1];
    let strides = [1, n[0], n[0] * n[1]];
    for axis in 0..3 {
        let (len, stride) = (n[axis], strides[axis]);
        if len == 0 {
            continue;
        }
        // Every line along `axis`: its first voxel runs over the other two axes.
        let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
        for i in 0..n[a] {
            for j in 0..n[b] {
                let start = i * strides[a] + j * strides[b];
                for (k, v) in line[..len].iter_mut().enumerate() {
                    let g = grid[start + k * stride];
                    *v = if g.is_finite() { f64::from(g) } else { FAR };
                }
                envelope(&line[..len], &mut out[..len], &mut parabolas, &mut bounds);
                for (k, v) in out[..len].iter().enumerate() {
                    grid[start + k * stride] = if *v >= FAR / 2.0 { f32::INFINITY } else { *v as f32 };
                }
            }
        }
    }
}

/// One line: `out[q] = min over p of (q - p)² + f[p]`, by the lower
/// envelope of the parabolas rooted at each `p` (`parabolas` holds the
/// envelope's roots, `bounds` where each takes over).
fn envelope(f: &[f64], out: &mut [f64], parabolas: &mut [usize], bounds: &mut [f64]) {
    let n = f.len();
    let mut k = 0usize;
    parabolas[0] = 0;
    bounds[0] = f64::NEG_INFINITY;
    bounds[1] = f64::INFINITY;
    for q in 1..n {
        let fq = f[q] + (q * q) as f64;
        // Pop the parabolas that the one at q hides; bounds[0] is -inf, so
        // the first always stays.
        let mut s;
        loop {
            let p = parabolas[k];
            // Where the parabola at q overtakes the one at p.
            s = (fq - (f[p] + (p * p) as f64)) / (2.0 * (q as f64 - p as f64));
            if s > bounds[k] || k == 0 {
                break;
            }
            k -= 1;
        }
        k += 1;
        parabolas[k] = q;
        bounds[k] = s;
        bounds[k + 1] = f64::INFINITY;
    }
    let mut k = 0usize;
    for (q, o) in out.iter_mut().enumerate() {
        while bounds[k + 1] < q as f64 {
            k += 1;
        }
        let p = parabolas[k];
        let d = q as f64 - p as f64;
        *o = d * d + f[p];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The transform equals the brute-force nearest seed on a small grid.
    #[test]
    fn squared_distances_are_the_nearest_seeds() {
        let n = [7, 5, 4];
        let seeds: [[usize; 3]; 3] = [[0, 0, 0], [6, 4, 3], [3, 2, 1]];
        let mut grid = vec![f32::INFINITY; n[0] * n[1] * n[2]];
        for s in seeds {
            grid[s[0] + n[0] * (s[1] + n[1] * s[2])] = 0.0;
        }
        squared_distances(&mut grid, n);
        for z in 0..n[2] {
            for y in 0..n[1] {
                for x in 0..n[0] {
                    let want = seeds.iter().map(|s: &[usize; 3]| (x as i64 - s[0] as i64).pow(2) + (y as i64 - s[1] as i64).pow(2) + (z as i64 - s[2] as i64).pow(2)).min().unwrap_or(0);
                    assert_eq!(grid[x + n[0] * (y + n[1] * z)], want as f32, "at {x} {y} {z}");
                }
            }
        }
        let mut empty = vec![f32::INFINITY; 8];
        squared_distances(&mut empty, [2, 2, 2]);
        assert!(empty.iter().all(|v| v.is_infinite()));
    }
}
