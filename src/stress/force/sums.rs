//! The stress force's inner loop: one node's pull toward its component's pivots, summed
//! in eight lanes so the processor works on eight terms at once (the sums are still in a
//! fixed order, so the bits are the same run to run).

/// Terms summed side by side.
const LANES: usize = 8;

/// One node's pull toward the pivots: `(force x, force y, stiffness)`.
pub(super) struct Pull {
    pub(super) x: f32,
    pub(super) y: f32,
    pub(super) stiffness: f32,
}

/// The pull on the node at `(x, y)` of a spring to each pivot at `(xs[t], ys[t])`,
/// resting at `hop × hops[t]` with stiffness `k × weights[t]`. The four lists are padded
/// to whole lanes (with weight 0).
///
/// NOTE: written for the vectoriser of the baseline x86-64 target (SSE2), as
/// Barnes–Hut's sum is: whole lanes from `chunks_exact`, no index to check, and the
/// division taken for every term with its result selected after.
#[inline]
pub(super) fn pivot_pull(
    (x, y): (f32, f32),
    xs: &[f32],
    ys: &[f32],
    hops: &[f32],
    weights: &[f32],
    hop: f32,
    k: f32,
) -> Pull {
    let (mut fx, mut fy, mut st) = ([0.0_f32; LANES], [0.0_f32; LANES], [0.0_f32; LANES]);
    let chunks = xs
        .chunks_exact(LANES)
        .zip(ys.chunks_exact(LANES))
        .zip(hops.chunks_exact(LANES).zip(weights.chunks_exact(LANES)));
    for ((qx, qy), (d, w)) in chunks {
        for l in 0..LANES {
            let kw = k * w[l];
            let (dx, dy) = (qx[l] - x, qy[l] - y);
            let length = (dx * dx + dy * dy).sqrt();
            let c = kw * (length - hop * d[l]) / length.max(1e-3);
            // A pivot on the node itself pulls nothing.
            let c = if length > 1e-3 { c } else { 0.0 };
            fx[l] += c * dx;
            fy[l] += c * dy;
            st[l] += kw;
        }
    }
    Pull {
        x: fx.iter().sum(),
        y: fy.iter().sum(),
        stiffness: st.iter().sum(),
    }
}

/// Lists padded to a whole number of lanes.
pub(super) fn padded(count: usize) -> usize {
    count.div_ceil(LANES) * LANES
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_node_too_far_from_its_pivots_is_pulled_toward_them() {
        // Node at the origin, pivots at 300 along x (2 hops: rest 200) and 100 along
        // y (3 hops: rest 300, pushed away).
        let pad = |v: &[f32]| {
            let mut v = v.to_vec();
            v.resize(padded(v.len()), 0.0);
            v
        };
        let pull = pivot_pull(
            (0.0, 0.0),
            &pad(&[300.0, 0.0]),
            &pad(&[0.0, 100.0]),
            &pad(&[2.0, 3.0]),
            &pad(&[0.25, 1.0 / 9.0]),
            100.0,
            1.0,
        );
        assert!((pull.x - 100.0 / 4.0).abs() < 1e-4, "{}", pull.x);
        assert!((pull.y + 200.0 / 9.0).abs() < 1e-4, "{}", pull.y);
        assert!((pull.stiffness - (0.25 + 1.0 / 9.0)).abs() < 1e-6);
    }
}
