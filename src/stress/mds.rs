//! Pivot MDS (Brandes & Pich, GD 2006): a layout from the hop distances to a few pivots,
//! in O(k·n + k²·n) for `k` pivots. It recovers meshes and grids almost exactly; trees
//! and clustered graphs come out compressed, which the stress passes after it mend.

/// Coordinates, in hop units up to a common scale, of the `n` nodes whose squared hop
/// distances to `k` pivots `squared(i, j)` gives (node `i`, pivot `j`): the two leading
/// eigenvectors of the double-centred `n × k` matrix's `BᵀB`, found by power iteration.
pub(crate) fn pivot_mds(
    n: usize,
    k: usize,
    squared: impl Fn(usize, usize) -> f32,
) -> Vec<[f32; 2]> {
    if n == 0 || k == 0 {
        return vec![[0.0; 2]; n];
    }
    // B = -1/2 (C - row means - column means + grand mean), row by row.
    let mut b = vec![0.0_f64; n * k];
    let mut column = vec![0.0_f64; k];
    for i in 0..n {
        for j in 0..k {
            let c = f64::from(squared(i, j));
            b[i * k + j] = c;
            column[j] += c;
        }
    }
    for c in &mut column {
        *c /= n as f64;
    }
    let grand = column.iter().sum::<f64>() / k as f64;
    for i in 0..n {
        let row = &mut b[i * k..(i + 1) * k];
        let mean = row.iter().sum::<f64>() / k as f64;
        for (j, v) in row.iter_mut().enumerate() {
            *v = -0.5 * (*v - mean - column[j] + grand);
        }
    }
    // M = BᵀB (k × k).
    let mut m = vec![0.0_f64; k * k];
    for i in 0..n {
        let row = &b[i * k..(i + 1) * k];
        for a in 0..k {
            let ra = row[a];
            if ra == 0.0 {
                continue;
            }
            let out = &mut m[a * k..(a + 1) * k];
            for (o, rb) in out.iter_mut().zip(row) {
                *o += ra * rb;
            }
        }
    }
    let first = leading_eigenvector(&m, k, None);
    let second = leading_eigenvector(&m, k, Some(&first));
    (0..n)
        .map(|i| {
            let row = &b[i * k..(i + 1) * k];
            let dot = |v: &[f64]| row.iter().zip(v).map(|(x, y)| x * y).sum::<f64>() as f32;
            [dot(&first), dot(&second)]
        })
        .collect()
}

/// The unit eigenvector of the symmetric `k × k` matrix `m` with the largest
/// eigenvalue, orthogonal to `other` when given (deflation), by power iteration from a
/// fixed start.
fn leading_eigenvector(m: &[f64], k: usize, other: Option<&[f64]>) -> Vec<f64> {
    // A start with a part along every eigenvector a symmetric graph may have (one of
    // evenly spread values could be orthogonal to half of them).
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut v: Vec<f64> = (0..k)
        .map(|_| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1_u64 << 53) as f64 - 0.5
        })
        .collect();
    let project = |v: &mut Vec<f64>| {
        if let Some(o) = other {
            let d: f64 = v.iter().zip(o).map(|(a, b)| a * b).sum();
            for (a, b) in v.iter_mut().zip(o) {
                *a -= d * b;
            }
        }
        let norm = v.iter().map(|a| a * a).sum::<f64>().sqrt();
        if norm > 0.0 {
            for a in v.iter_mut() {
                *a /= norm;
            }
        }
    };
    project(&mut v);
    let mut next = vec![0.0; k];
    for _ in 0..200 {
        for (a, out) in next.iter_mut().enumerate() {
            *out = m[a * k..(a + 1) * k]
                .iter()
                .zip(&v)
                .map(|(x, y)| x * y)
                .sum();
        }
        project(&mut next);
        let change: f64 = next.iter().zip(&v).map(|(a, b)| (a - b).abs()).sum();
        std::mem::swap(&mut v, &mut next);
        if change < 1e-10 {
            break;
        }
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_grid_comes_back_as_a_grid() {
        // A 5 x 5 grid, its four corners and centre as pivots: the layout's distances
        // are the grid's (up to one scale for all).
        let at = |i: usize| ((i % 5) as f32, (i / 5) as f32);
        let pivots = [0, 4, 20, 24, 12];
        let hop = |i: usize, p: usize| {
            let ((x, y), (px, py)) = (at(i), at(pivots[p]));
            (x - px).abs() + (y - py).abs()
        };
        let xy = pivot_mds(25, 5, |i, p| hop(i, p).powi(2));
        let d = |a: usize, b: usize| {
            ((xy[a][0] - xy[b][0]).powi(2) + (xy[a][1] - xy[b][1]).powi(2)).sqrt()
        };
        let unit = d(0, 1);
        assert!(unit > 0.0);
        // Neighbours along both axes at one unit, within 15 % (Manhattan distances are
        // not Euclidean, so the fit is close, not exact).
        for (a, b) in [(6, 7), (6, 11), (18, 19), (13, 18)] {
            let r = d(a, b) / unit;
            assert!((r - 1.0).abs() < 0.15, "{a}-{b}: {r}");
        }
        assert!(
            d(0, 24) / unit > 5.0,
            "the grid is not folded: {}",
            d(0, 24) / unit
        );
    }
}
