//! The graph the layout walks: undirected adjacency in compressed rows (one run of
//! neighbours per node) and one breadth-first search over it ([`Graph::search`]), from
//! one node or many, bounded or not, with hops held as `u16` (the stress model's
//! tables, [`UNREACHED`]) or `u32`. The stress model (`stress/`), the heat spread by a
//! disturbance (`adapter/heat/spread.rs`) and the quality measures (`quality.rs`) all
//! walk it. Nodes are numbered `0..n` (the world's slots, or the scene's order).

/// Hops to a node no path reaches, in the stress model's `u16` tables.
pub(crate) const UNREACHED: u16 = u16::MAX;

/// A hop count a search can hold: `u16` (paths longer than 65,534 hops count as
/// unreached) or `u32`.
pub(crate) trait Hops: Copy + Eq + Ord {
    /// Not reached.
    const UNREACHED: Self;
    /// The start of a search.
    const ZERO: Self;
    /// One hop further, or `None` where the count would reach [`Hops::UNREACHED`].
    fn next(self) -> Option<Self>;
}

impl Hops for u16 {
    const UNREACHED: Self = u16::MAX;
    const ZERO: Self = 0;
    fn next(self) -> Option<Self> {
        (self + 1 < u16::MAX).then_some(self + 1)
    }
}

impl Hops for u32 {
    const UNREACHED: Self = u32::MAX;
    const ZERO: Self = 0;
    fn next(self) -> Option<Self> {
        (self + 1 < u32::MAX).then_some(self + 1)
    }
}

/// Lists of items by owner in compressed rows (the directed counterpart of [`Graph`]):
/// owner `o`'s items are `items[start[o]..start[o + 1]]`, in the order they were given.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Lists {
    start: Vec<u32>,
    items: Vec<u32>,
}

impl Lists {
    /// Lists from `(owner, item)` pairs for `owners` owners, each list in pair order.
    pub(crate) fn from_pairs(owners: usize, pairs: &[(u32, u32)]) -> Self {
        let mut start = vec![0_u32; owners + 1];
        for &(o, _) in pairs {
            start[o as usize + 1] += 1;
        }
        for k in 0..owners {
            start[k + 1] += start[k];
        }
        let mut next = start.clone();
        let mut items = vec![0_u32; pairs.len()];
        for &(o, item) in pairs {
            items[next[o as usize] as usize] = item;
            next[o as usize] += 1;
        }
        Self { start, items }
    }

    /// Whether no owner has an item.
    pub(crate) fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// The list of `owner` (empty beyond the owners).
    pub(crate) fn of(&self, owner: usize) -> &[u32] {
        match (self.start.get(owner), self.start.get(owner + 1)) {
            (Some(&a), Some(&b)) => &self.items[a as usize..b as usize],
            _ => &[],
        }
    }
}

/// Undirected adjacency in compressed rows: the neighbours of node `i` are
/// `targets[offsets[i]..offsets[i + 1]]`, in the order the edges were given.
#[derive(Clone, Debug, Default)]
pub(crate) struct Graph {
    offsets: Vec<u32>,
    targets: Vec<u32>,
}

impl Graph {
    /// The graph of `n` nodes with `edges` (each once; self-loops and ends out of range
    /// left out), each node's neighbours in the order of its edges.
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

    /// The one breadth-first search: from every node of `sources` at once (each at hop
    /// 0; a source given twice counts once), marks each node it reaches with its
    /// hops in `hops` and appends it to `queue` (cleared first) in the order reached,
    /// neighbours in the order their edges were given. It goes on past a node only when
    /// `go_on(node, hops)` says so and one more hop fits in `H`. `hops` must hold
    /// [`Hops::UNREACHED`] for every node the search may reach; it is left marked, so
    /// that successive searches can share it (the components). Returns the nodes
    /// reached (`queue`'s contents).
    pub(crate) fn search<'q, H: Hops>(
        &self,
        sources: impl IntoIterator<Item = usize>,
        hops: &mut [H],
        queue: &'q mut Vec<u32>,
        mut go_on: impl FnMut(usize, H) -> bool,
    ) -> &'q [u32] {
        queue.clear();
        for s in sources {
            if hops[s] != H::ZERO {
                hops[s] = H::ZERO;
                queue.push(s as u32);
            }
        }
        let mut next = 0;
        while next < queue.len() {
            let u = queue[next] as usize;
            next += 1;
            let h = hops[u];
            let Some(further) = h.next() else {
                continue;
            };
            if !go_on(u, h) {
                continue;
            }
            for &v in self.neighbours(u) {
                if hops[v as usize] == H::UNREACHED {
                    hops[v as usize] = further;
                    queue.push(v);
                }
            }
        }
        queue
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
        self.search([source], hops, queue, |_, _| true)
    }

    /// The connected components: for each node its component, components numbered in
    /// the order of their first node.
    pub(crate) fn components(&self) -> (Vec<u32>, usize) {
        let n = self.len();
        let mut hops = vec![u32::MAX; n];
        let mut component = vec![u32::MAX; n];
        let mut queue = Vec::new();
        let mut count = 0;
        for s in 0..n {
            if hops[s] != u32::MAX {
                continue;
            }
            for &v in self.search([s], &mut hops, &mut queue, |_, _| true) {
                component[v as usize] = count;
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

    #[test]
    fn a_bounded_search_from_two_nodes_stops_where_told() {
        // 0 - 1 - 2 - 3 - 4 - 5 - 6, searched from 0 and 6, going on past hop 1 nowhere
        // and past node 6 not at all.
        let g = Graph::new(7, (0..6).map(|i| (i, i + 1)));
        let mut hops = vec![u32::MAX; 7];
        let mut queue = Vec::new();
        let reached = g.search([0, 6, 0], &mut hops, &mut queue, |node, hop| {
            hop < 1 && node != 6
        });
        assert_eq!(reached, [0, 6, 1], "sources first, then by hop");
        assert_eq!(hops, [0, 1, u32::MAX, u32::MAX, u32::MAX, u32::MAX, 0]);
    }
}
