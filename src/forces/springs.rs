//! The edge springs' pull, d3-force's `link`: springs applied as forces of the layout's
//! own ([`SpringModel::Forces`](crate::config::SpringModel::Forces)), and d3's link bias, the
//! uneven share of a spring's pull between its two ends.
//!
//! A spring pulls both ends with the same force `k x`. d3-force's link instead moves its
//! source by `(1 - b)` and its target by `b` of the correction, `b` being the source's
//! share of the two degrees, so the end with fewer neighbours moves more. With
//! [`RapierLayoutConfig::springs.link_bias`](crate::config::Springs::link_bias) `g`, end `a`
//! of a spring takes `(1 + g s) k x` toward `b` and end `b` takes `(1 - g s) k x` toward
//! `a`, with `s = (d_b - d_a) / (d_a + d_b)`: at `g = 1` end `a` feels
//! `2 d_b / (d_a + d_b) · k x`, d3's share of twice the spring force. Springs that are
//! rapier joints pull evenly themselves; this force then adds only the uneven part.
//!
//! Springs applied as forces also report their stiffness per body, so that
//! the step can take an implicit step on it (`simulate/combine.rs`).

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};

use super::targets::NodeTargets;
use super::{BodyForce, ForceContext, ForceSums, Lane};
use crate::config::{RapierLayoutConfig, SpringModel};
use crate::parallel;
use crate::sanitize::{finite_or, positive_or};
use crate::world::slot::SpringView;
use crate::world::RapierSceneWorld;

/// One spring, as this force reads it.
#[derive(Clone, Copy, Debug)]
struct Link {
    a: u32,
    b: u32,
    /// `(d_b - d_a) / (d_a + d_b)`: the extra share end `a` takes (end `b` takes its
    /// negative).
    share: f32,
    rest_length: f32,
    stiffness: f32,
    damping: f32,
    /// What the timestep resolves ([`max_resolved_stiffness`](crate::world::max_resolved_stiffness)),
    /// as a rapier spring joint is capped.
    cap: f32,
}

/// The springs of a world with their degree shares, rebuilt when the world's bodies or
/// joints change.
#[derive(Clone, Debug, Default)]
pub(crate) struct SpringForce {
    version: Option<u64>,
    links: Vec<Link>,
    degrees: Vec<u32>,
    /// Each slot's links, by index into `links` in ascending order: slot `s`'s are
    /// `incident[starts[s]..starts[s + 1]]`.
    starts: Vec<u32>,
    incident: Vec<u32>,
    /// The links a substep with few pushed bodies visits, in ascending order.
    visit: Vec<u32>,
    /// Each link's pull on its two ends, by link (the `parallel` path).
    pulls: Vec<[EndPull; 2]>,
}

/// From this many links on, `parallel` builds work the pulls out link by link and then
/// sum them body by body, both side by side (fewer are not worth the pool's start).
const BY_BODY_LINKS: usize = 8_192;
/// Links, or bodies, a piece of that work takes (fixed, so no sum depends on the pool).
const RUN: usize = 512;

/// Below one pushed body in this many, a substep visits only the pushed bodies' links
/// (in the order of all links, so every sum is the same) instead of checking every link.
const FEW_PUSHED: usize = 16;

impl<N: Clone + Eq + Hash> BodyForce<N> for SpringForce {
    fn is_active(&self, config: &RapierLayoutConfig, _: &NodeTargets) -> bool {
        config.springs.model == SpringModel::Forces
            || finite_or(config.springs.link_bias, 0.0) > 0.0
    }

    /// Reads the world and writes only the springs' sums: on the calling thread,
    /// beside the spare lane.
    fn lane(&self) -> Lane {
        Lane::Springs
    }

    fn apply(&mut self, frame: &ForceContext<'_, N>, out: &mut ForceSums) {
        let as_forces = frame.world.springs_as_forces();
        // Clamped: higher gains are explicit forces stiffer than the step resolves.
        let gain = finite_or(frame.config.springs.link_bias, 0.0).clamp(0.0, 1.0);
        if !as_forces && gain == 0.0 {
            return;
        }
        if self.version != Some(frame.world.version()) {
            self.rebuild(frame.world);
        }
        let pull = Pull {
            scale: frame.world.applied_spring_scale(),
            gain,
            as_forces,
        };
        let bodies = LinkBodies {
            points: frame.points,
            velocities: frame.velocities,
            pushed: frame.pushed,
            dt: frame.dt,
        };
        let pushed = frame.pushed;
        let few = pushed.iter().filter(|&&p| p).count() * FEW_PUSHED < pushed.len();
        if few && self.starts.len() == pushed.len() + 1 {
            // A settled graph disturbed in one place: the pushed bodies' links, each
            // once, in the order of all links.
            self.visit.clear();
            for (s, _) in pushed.iter().enumerate().filter(|(_, &p)| p) {
                let (from, to) = (self.starts[s] as usize, self.starts[s + 1] as usize);
                self.visit.extend_from_slice(&self.incident[from..to]);
            }
            self.visit.sort_unstable();
            self.visit.dedup();
            #[cfg(debug_assertions)]
            self.check_subset(&pull, bodies);
            for &k in &self.visit {
                pull.apply(&self.links[k as usize], bodies, out);
            }
        } else if cfg!(feature = "parallel")
            && self.links.len() >= BY_BODY_LINKS
            && self.starts.len() == pushed.len() + 1
        {
            self.apply_by_body(&pull, bodies, out);
        } else {
            for link in &self.links {
                pull.apply(link, bodies, out);
            }
        }
    }

    fn reset(&mut self) {
        // A new world counts its versions from 0 again.
        *self = Self::default();
    }
}

impl SpringForce {
    fn rebuild<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>) {
        self.set_links(world.slot_count(), world.springs());
        self.version = Some(world.version());
    }

    /// The links of `springs` between `slots` bodies, with their degree shares and
    /// each body's links.
    fn set_links(&mut self, slots: usize, springs: impl Iterator<Item = SpringView>) {
        self.degrees.clear();
        self.degrees.resize(slots, 0);
        self.links.clear();
        for spring in springs {
            self.degrees[spring.a] += 1;
            self.degrees[spring.b] += 1;
            self.links.push(Link {
                a: spring.a as u32,
                b: spring.b as u32,
                share: 0.0,
                // What a rapier spring joint would be built with.
                rest_length: positive_or(spring.rest_length, 0.0),
                stiffness: positive_or(spring.stiffness, 0.0),
                damping: positive_or(spring.damping, 0.0),
                cap: spring.cap,
            });
        }
        // By their first end, so a pass reads that end's position and velocity in order
        // (the other end's at random): on a large graph the bodies' arrays outgrow the
        // cache. Two springs never join the same two bodies.
        self.links.sort_unstable_by_key(|link| (link.a, link.b));
        // Shares once every degree is counted.
        for link in &mut self.links {
            let da = self.degrees[link.a as usize] as f32;
            let db = self.degrees[link.b as usize] as f32;
            link.share = (db - da) / (da + db);
        }
        // Each slot's links in ascending order (a counting sort by end).
        let n = self.degrees.len();
        self.starts.clear();
        self.starts.push(0);
        for s in 0..n {
            self.starts.push(self.starts[s] + self.degrees[s]);
        }
        self.incident.clear();
        self.incident.resize(self.links.len() * 2, 0);
        let mut next: Vec<u32> = self.starts[..n].to_vec();
        for (k, link) in self.links.iter().enumerate() {
            for end in [link.a, link.b] {
                self.incident[next[end as usize] as usize] = k as u32;
                next[end as usize] += 1;
            }
        }
    }
}

impl SpringForce {
    /// Every link's pull, as the links in order would add it: the pulls link by link,
    /// then each body's sum over its links in ascending order (the order the links
    /// reach it in), both in fixed runs side by side under `parallel`. Every sum is
    /// the same, bit for bit, as one pass over the links.
    fn apply_by_body(&mut self, pull: &Pull, bodies: LinkBodies, out: &mut ForceSums) {
        let n = self.starts.len() - 1;
        let Self {
            links,
            starts,
            incident,
            pulls,
            ..
        } = self;
        pulls.clear();
        pulls.resize(links.len(), [None; 2]);
        let runs = |len: usize| parallel::runs(len, RUN);
        parallel::for_each_run(pulls, RUN, |range, pulls| {
            for (p, link) in pulls.iter_mut().zip(&links[range]) {
                *p = pull.ends(link, bodies);
            }
        });
        let pulls: &[[EndPull; 2]] = pulls;
        let mut jobs: Vec<_> = parallel::split_ranges(&mut out.springs[..n], runs(n))
            .into_iter()
            .zip(parallel::split_ranges(&mut out.resistance[..n], runs(n)))
            .collect();
        parallel::for_each(
            &mut jobs,
            || (),
            |(), ((range, springs), (_, resistance))| {
                for (i, s) in range.clone().enumerate() {
                    let from = starts[s] as usize..starts[s + 1] as usize;
                    for &k in &incident[from] {
                        // The end this body is (a link from a body to itself pulls nothing).
                        let end = usize::from(links[k as usize].a as usize != s);
                        add(springs, resistance, i, pulls[k as usize][end]);
                    }
                }
            },
        );
    }
}

impl SpringForce {
    /// Debug builds (the tests): the pushed bodies' links give every sum that all
    /// links give, bit for bit.
    #[cfg(debug_assertions)]
    fn check_subset(&self, pull: &Pull, bodies: LinkBodies) {
        let sums = |links: &mut dyn Iterator<Item = &Link>| {
            let n = bodies.pushed.len();
            let mut out = ForceSums {
                springs: vec![euclid::default::Vector2D::zero(); n],
                resistance: vec![0.0; n],
                ..ForceSums::default()
            };
            for link in links {
                pull.apply(link, bodies, &mut out);
            }
            let bits: Vec<[u32; 3]> = (out.springs.iter().zip(&out.resistance))
                .map(|(f, r)| [f.x.to_bits(), f.y.to_bits(), r.to_bits()])
                .collect();
            bits
        };
        let subset = sums(&mut self.visit.iter().map(|&k| &self.links[k as usize]));
        let all = sums(&mut self.links.iter());
        let differ = subset.iter().zip(&all).position(|(a, b)| a != b);
        assert_eq!(
            differ, None,
            "slot whose spring sums differ from all links'"
        );
    }
}

/// What one substep's springs pull with, apart from the links.
struct Pull {
    scale: f32,
    /// The link bias, clamped to 0..=1.
    gain: f32,
    /// Springs are forces of the layout's own (not rapier joints).
    as_forces: bool,
}

/// What the springs read of the bodies, by world slot.
#[derive(Clone, Copy)]
struct LinkBodies<'a> {
    points: &'a [Point2D<f32>],
    velocities: &'a [Vector2D<f32>],
    pushed: &'a [bool],
    /// The substep's length, in seconds.
    dt: f32,
}

/// What a link adds to one end's sums: a force and, for springs applied as forces, a
/// resistance (`None`: nothing).
type EndPull = Option<(Vector2D<f32>, Option<f32>)>;

/// How a link pulls, before it is shared between its ends.
enum Pulled {
    /// Nothing (neither end pushed, no position, no length).
    Nothing,
    /// The link bias's uneven part alone, the same force on both ends' springs.
    Uneven(Vector2D<f32>),
    /// A spring applied as forces: end `a` takes `direction × pull × part` for its
    /// part, end `b` the opposite for its own, each with `resistance × part`.
    Forces {
        direction: Vector2D<f32>,
        pull: f32,
        resistance: f32,
    },
}

impl Pull {
    /// Adds `link`'s pull on its pushed ends to `out`.
    #[inline]
    fn apply(&self, link: &Link, bodies: LinkBodies, out: &mut ForceSums) {
        let (a, b) = (link.a as usize, link.b as usize);
        match self.pulled(link, bodies) {
            Pulled::Nothing => {}
            Pulled::Uneven(f) => {
                if f.is_finite() {
                    out.springs[a] += f;
                    out.springs[b] += f;
                }
            }
            Pulled::Forces {
                direction,
                pull,
                resistance,
            } => {
                for (end, toward, part) in self.parts(link, direction) {
                    let f = toward * (pull * part);
                    if bodies.pushed[end] && f.is_finite() {
                        out.springs[end] += f;
                        out.resistance[end] += resistance * part;
                    }
                }
            }
        }
    }

    /// What `link` adds to the sums of its ends `a` and `b`, as [`apply`](Self::apply)
    /// adds it.
    fn ends(&self, link: &Link, bodies: LinkBodies) -> [EndPull; 2] {
        match self.pulled(link, bodies) {
            Pulled::Nothing => [None; 2],
            Pulled::Uneven(f) => [f.is_finite().then_some((f, None)); 2],
            Pulled::Forces {
                direction,
                pull,
                resistance,
            } => self.parts(link, direction).map(|(end, toward, part)| {
                let f = toward * (pull * part);
                (bodies.pushed[end] && f.is_finite()).then_some((f, Some(resistance * part)))
            }),
        }
    }

    /// The ends of `link` with the direction each is pulled along and its part.
    #[inline(always)]
    fn parts(&self, link: &Link, direction: Vector2D<f32>) -> [(usize, Vector2D<f32>, f32); 2] {
        [
            (link.a as usize, direction, 1.0 + self.gain * link.share),
            (link.b as usize, -direction, 1.0 - self.gain * link.share),
        ]
    }

    /// How `link` pulls this substep.
    #[inline(always)]
    fn pulled(&self, link: &Link, bodies: LinkBodies) -> Pulled {
        let Self {
            scale,
            gain,
            as_forces,
        } = *self;
        let dt = bodies.dt;
        let (a, b) = (link.a as usize, link.b as usize);
        let (Some(&pa), Some(&pb)) = (bodies.points.get(a), bodies.points.get(b)) else {
            return Pulled::Nothing;
        };
        if !(bodies.pushed[a] || bodies.pushed[b]) {
            // Neither end moves this substep (asleep, held or fixed), and only the
            // pushed bodies' sums are read: a resting graph's springs cost a check.
            return Pulled::Nothing;
        }
        let d = pb - pa;
        let length = d.length();
        if !(length > 1e-3 && length.is_finite()) {
            return Pulled::Nothing;
        }
        let k = (link.stiffness * scale).min(link.cap);
        if !as_forces {
            // The joint pulls evenly: add the uneven part only.
            return Pulled::Uneven(
                d * (gain * link.share * k * (length - link.rest_length) / length),
            );
        }
        let direction = d / length;
        let c = link.damping * scale;
        let closing = (bodies.velocities[b] - bodies.velocities[a]).dot(direction);
        Pulled::Forces {
            direction,
            pull: k * (length - link.rest_length) + c * closing,
            resistance: dt * dt * k + dt * c,
        }
    }
}

/// Adds one end's pull to the sums of body `s`.
#[inline(always)]
fn add(springs: &mut [Vector2D<f32>], resistance: &mut [f32], s: usize, pull: EndPull) {
    if let Some((f, r)) = pull {
        springs[s] += f;
        if let Some(r) = r {
            resistance[s] += r;
        }
    }
}

#[cfg(test)]
mod tests;
