//! Which separations the sweep (`sweep.rs`) and the passes (`passes.rs`) visit: those
//! that can be short. A separation that held at the end of the last sweep holds until
//! one of its bodies moves, so the sweep visits the separations of the bodies read
//! changed from the world since, of the hot ones, of those it moves itself, and the ones
//! it left short (conflicts, bodies that do not give way); every one after the arrays
//! were read whole or indexed anew, or while most bodies move (a layout settling: then
//! the list would cost more than it saves, and what is left short is not noted, so the
//! next sweep visits every one too). A drag on a settled 10,000-node flow visits a few
//! thousand of its 25,000 edges a substep instead of all of them four times. They are
//! visited in the same order as all of them, and a separation that holds does nothing,
//! so the bodies end the same to the bit.

use super::local::Local;

/// Bodies that moved, times this, above the bodies there are: the sweep visits every
/// separation, and the passes scan them all for the hot ones.
pub(super) const MOSTLY: usize = 4;

/// The sweep's candidates and what seeds them.
#[derive(Clone, Debug, Default)]
pub(super) struct Watch {
    /// Every separation is a candidate at the next sweep.
    all: bool,
    /// This sweep visits every separation; and whether because most bodies moved.
    full: bool,
    mostly: bool,
    /// Local bodies read changed from the world since the last sweep, once each, and
    /// by local index whether listed.
    touched: Vec<u32>,
    listed: Vec<bool>,
    /// The separations (by place in `links`) the last sweep left short.
    short: Vec<u32>,
    /// The candidates, a bit per separation.
    bits: Vec<u64>,
}

impl Watch {
    /// Every separation a candidate at the next sweep.
    pub(super) fn watch_all(&mut self) {
        self.all = true;
        self.untouch();
        self.short.clear();
    }

    /// Notes local body `l`, read changed from the world, out of `n` bodies.
    pub(super) fn touch(&mut self, l: u32, n: usize) {
        if self.all {
            return;
        }
        if self.listed.len() != n {
            // Bodies indexed anew: what was listed is by the old indices.
            self.touched.clear();
            self.listed.clear();
            self.listed.resize(n, false);
        }
        if !std::mem::replace(&mut self.listed[l as usize], true) {
            self.touched.push(l);
        }
    }

    /// Forgets the touched bodies.
    fn untouch(&mut self) {
        for &l in &self.touched {
            self.listed[l as usize] = false;
        }
        self.touched.clear();
    }

    /// The first candidate at `k` or after, of `count` separations.
    pub(super) fn next_from(&self, k: usize, count: usize) -> Option<usize> {
        if self.full {
            (k < count).then_some(k)
        } else {
            next_set(&self.bits, k)
        }
    }

    /// The last candidate before `k`.
    pub(super) fn last_before(&self, k: usize) -> Option<usize> {
        if self.full {
            k.checked_sub(1)
        } else {
            last_set_before(&self.bits, k)
        }
    }
}

/// Sets bit `k` of `bits`.
pub(super) fn set(bits: &mut [u64], k: u32) {
    bits[k as usize / 64] |= 1 << (k % 64);
}

/// The first bit of `bits` set at `k` or after.
pub(super) fn next_set(bits: &[u64], k: usize) -> Option<usize> {
    let mut w = k / 64;
    let mut word = bits.get(w)? & (u64::MAX << (k % 64));
    loop {
        if word != 0 {
            return Some(w * 64 + word.trailing_zeros() as usize);
        }
        w += 1;
        word = *bits.get(w)?;
    }
}

/// The last bit of `bits` set before `k`.
fn last_set_before(bits: &[u64], k: usize) -> Option<usize> {
    let k = k.checked_sub(1)?;
    let mut w = k / 64;
    let mut word = bits.get(w)? & (u64::MAX >> (63 - k % 64));
    loop {
        if word != 0 {
            return Some(w * 64 + 63 - word.leading_zeros() as usize);
        }
        w = w.checked_sub(1)?;
        word = bits[w];
    }
}

impl Local {
    /// The separations local body `l` is in, by place in `links`, ascending.
    pub(super) fn links_of(&self, l: usize) -> &[u32] {
        &self.adjacent[self.adjacent_start[l] as usize..self.adjacent_start[l + 1] as usize]
    }

    /// Indexes each body's separations (after `links` is ordered).
    pub(super) fn index_adjacent(&mut self) {
        let n = self.points_count();
        self.adjacent_start.clear();
        self.adjacent_start.resize(n + 1, 0);
        for c in &self.links {
            self.adjacent_start[c.a as usize + 1] += 1;
            self.adjacent_start[c.b as usize + 1] += 1;
        }
        for l in 0..n {
            self.adjacent_start[l + 1] += self.adjacent_start[l];
        }
        let mut fill = self.adjacent_start.clone();
        self.adjacent.clear();
        self.adjacent.resize(2 * self.links.len(), 0);
        for (k, c) in self.links.iter().enumerate() {
            for l in [c.a as usize, c.b as usize] {
                self.adjacent[fill[l] as usize] = k as u32;
                fill[l] += 1;
            }
        }
        self.watch.watch_all();
    }

    /// The candidates of a sweep: the separations of the touched and hot bodies and
    /// those left short, or all (`full`).
    pub(super) fn seed_watch(&mut self) {
        let mut watch = std::mem::take(&mut self.watch);
        let listed = |l: &&u32| watch.listed.get(**l as usize).is_some_and(|&t| t);
        let hot_untouched = self.hot_list.iter().filter(|l| !listed(l)).count();
        watch.mostly = (watch.touched.len() + hot_untouched) * MOSTLY > self.points_count();
        watch.full = watch.all || watch.mostly;
        watch.all = false;
        watch.bits.clear();
        if !watch.full {
            watch.bits.resize(self.links.len().div_ceil(64), 0);
            for &l in watch.touched.iter().chain(&self.hot_list) {
                for &k in self.links_of(l as usize) {
                    set(&mut watch.bits, k);
                }
            }
            for &k in &watch.short {
                set(&mut watch.bits, k);
            }
        }
        watch.untouch();
        self.watch = watch;
        #[cfg(debug_assertions)]
        self.check_watch();
    }

    /// In debug builds: every separation that is short is a candidate (what the sweep
    /// leaves out holds).
    #[cfg(debug_assertions)]
    fn check_watch(&self) {
        if self.watch.full {
            return;
        }
        for (k, c) in self.links.iter().enumerate() {
            let watched = self.watch.bits[k / 64] & (1 << (k % 64)) != 0;
            let short = self.shortfall(c);
            debug_assert!(
                watched || short.is_nan() || short <= 0.0,
                "separation {k} is {short} short and the sweep would not visit it"
            );
        }
    }

    /// Makes the separations of local body `l`, which a sweep moved, candidates.
    pub(super) fn watch_body(&mut self, l: usize) {
        if self.watch.full {
            return;
        }
        let (from, to) = (self.adjacent_start[l], self.adjacent_start[l + 1]);
        for &k in &self.adjacent[from as usize..to as usize] {
            set(&mut self.watch.bits, k);
        }
    }

    /// After a sweep: notes the candidates it left short; after a sweep of all because
    /// most bodies moved, that the next visits all.
    pub(super) fn keep_short(&mut self) {
        if self.watch.mostly {
            self.watch.watch_all();
            return;
        }
        let mut short = std::mem::take(&mut self.watch.short);
        short.clear();
        let mut k = 0;
        while let Some(j) = self.watch.next_from(k, self.links.len()) {
            if self.shortfall(&self.links[j]) > 0.0 {
                short.push(j as u32);
            }
            k = j + 1;
        }
        self.watch.short = short;
    }
}

#[cfg(test)]
mod tests {
    use super::{last_set_before, next_set, set};

    #[test]
    fn candidates_are_found_both_ways_across_words() {
        let mut bits = vec![0; 3];
        for k in [0, 63, 64, 130] {
            set(&mut bits, k);
        }
        let mut up = Vec::new();
        let mut k = 0;
        while let Some(j) = next_set(&bits, k) {
            up.push(j);
            k = j + 1;
        }
        assert_eq!(up, vec![0, 63, 64, 130]);
        let mut down = Vec::new();
        let mut k = 192;
        while let Some(j) = last_set_before(&bits, k) {
            down.push(j);
            k = j;
        }
        assert_eq!(down, vec![130, 64, 63, 0]);
    }
}
