//! The graph the stress model measures distances on: undirected adjacency in compressed
//! rows (one run of neighbours per node), breadth-first hop distances and connected
//! components. Nodes are numbered `0..n` (the world's slots).

/// Hops to a node no path reaches.
pub(crate) const UNREACHED: u16 = u16::MAX;

/// Undirected adjacency in compressed rows: the neighbours of node `i` are
/// `targets[offsets[i]..offsets[i + 1]]`, in the order the edges were given.
#[derive(Clone, Debug, Default)]
pub(crate) struct Graph {
    offsets: Vec<u32>,
    targets: Vec<u32>,
}

impl Graph {
    /// The graph of `n` nodes with `edges` (each once; self-loops and ends out of range
    /// left out).
    pub(crate) fn new(n: usize, edges: impl Iterator<Item = (usize, usize)> + Clone) -> Self {
        let mut offsets = vec![0_u32; n + 1];
        let usable = |&(a, b): &(usize, usize)| a != b && a < n && b < n;
        for (a, b) in edges.clone().filter(usable) {
            offsets[a + 1] += 1;
            offsets[b + 1] += 1;
        }
        for i in 0..n {
            offsets[i + 1] += offsets[i];
        }
        let mut targets = vec![0_u32; offsets[n] as usize];
        let mut fill = offsets.clone();
        for (a, b) in edges.filter(usable) {
            targets[fill[a] as usize] = b as u32;
            fill[a] += 1;
            targets[fill[b] as usize] = a as u32;
            fill[b] += 1;
        }
        Self { offsets, targets }
    }

    /// The number of nodes.
    pub(crate) fn len(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }

    /// The neighbours of node `i`.
    pub(crate) fn neighbours(&self, i: usize) -> &[u32] {
        &self.targets[self.offsets[i] as usize..self.offsets[i + 1] as usize]
    }

    /// Hops from `source` to every node into `hops` (of length `len()`, [`UNREACHED`]
    /// where no path leads; paths longer than 65,534 hops count as unreached), using
    /// `queue` as the breadth-first queue. Returns the nodes reached, in the order they
    /// were reached (`queue`'s contents).
    pub(crate) fn bfs<'q>(
        &self,
        source: usize,
        hops: &mut [u16],
        queue: &'q mut Vec<u32>,
    ) -> &'q [u32] {
        hops.fill(UNREACHED);
        queue.clear();
        hops[source] = 0;
        queue.push(source as u32);
        let mut next = 0;
        while next < queue.len() {
            let u = queue[next] as usize;
            next += 1;
            let h = hops[u];
            if h + 1 == UNREACHED {
                continue;
            }
            for &v in self.neighbours(u) {
                if hops[v as usize] == UNREACHED {
                    hops[v as usize] = h + 1;
                    queue.push(v);
                }
            }
        }
        queue
    }

    /// The connected components: for each node its component, components numbered in
    /// the order of their first node.
    pub(crate) fn components(&self) -> (Vec<u32>, usize) {
        let n = self.len();
        let mut component = vec![u32::MAX; n];
        let mut queue = Vec::new();
        let mut count = 0;
        for s in 0..n {
            if component[s] != u32::MAX {
                continue;
            }
            component[s] = count;
            queue.clear();
            queue.push(s as u32);
            let mut next = 0;
            while next < queue.len() {
                let u = queue[next] as usize;
                next += 1;
                for &v in self.neighbours(u) {
                    if component[v as usize] == u32::MAX {
                        component[v as usize] = count;
                        queue.push(v);
                    }
                }
            }
            count += 1;
        }
        (component, count as usize)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hops_and_components_of_a_path_and_an_island() {
        // 0 - 1 - 2 - 3, and 4 alone.
        let g = Graph::new(5, [(0, 1), (1, 2), (2, 3), (3, 3)].into_iter());
        let mut hops = vec![0; 5];
        let mut queue = Vec::new();
        let reached = g.bfs(0, &mut hops, &mut queue).len();
        assert_eq!(hops, [0, 1, 2, 3, UNREACHED]);
        assert_eq!(reached, 4);
        assert_eq!(g.components(), (vec![0, 0, 0, 0, 1], 2));
        assert_eq!(g.neighbours(1), [0, 2]);
        assert!(g.neighbours(4).is_empty());
    }
}
