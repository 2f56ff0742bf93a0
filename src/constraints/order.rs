//! The order the passes and the sweep visit the separations in: a topological order of
//! their ends (Kahn's algorithm, the bodies taken in index order), so that one visit in
//! order carries a push down a chain of any length and one in reverse carries it up.
//! Separations on a cycle (conflicting host constraints) keep their given order after
//! the rest.

use crate::graph::Lists;

/// The visiting order of `ends.len()` separations `(a, b)` between `n` bodies: the
/// separations sorted by the topological ranks of `a` and then `b`, stable.
pub(super) fn topological(n: usize, ends: &[(u32, u32)]) -> Vec<usize> {
    let next = Lists::from_pairs(n, ends);
    let mut indegree = vec![0_u32; n];
    for &(_, b) in ends {
        indegree[b as usize] += 1;
    }
    let mut rank = vec![u32::MAX; n];
    let mut queue: Vec<u32> = (0..n as u32)
        .filter(|&l| indegree[l as usize] == 0)
        .collect();
    let mut head = 0;
    while let Some(&l) = queue.get(head) {
        rank[l as usize] = head as u32;
        head += 1;
        for &m in next.of(l as usize) {
            indegree[m as usize] -= 1;
            if indegree[m as usize] == 0 {
                queue.push(m);
            }
        }
    }
    let mut order: Vec<usize> = (0..ends.len()).collect();
    order.sort_by_key(|&k| (rank[ends[k].0 as usize], rank[ends[k].1 as usize]));
    order
}

#[cfg(test)]
mod tests {
    use super::topological;

    #[test]
    fn a_chain_listed_backwards_is_visited_from_its_head() {
        // 3 -> 2 -> 1 -> 0 listed from the tail: visited 3->2, 2->1, 1->0.
        let ends = [(1, 0), (2, 1), (3, 2)];
        let order = topological(4, &ends);
        assert_eq!(order, vec![2, 1, 0], "{order:?}");
    }

    #[test]
    fn a_cycle_keeps_its_order_after_the_rest() {
        // 0 -> 1 -> 0 is a cycle; 2 -> 3 is not.
        let ends = [(0, 1), (1, 0), (2, 3)];
        assert_eq!(topological(4, &ends), vec![2, 0, 1]);
    }
}
