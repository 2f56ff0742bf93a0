//! Seats for nodes added to a world that already exists. A host that adds a node on top
//! of another (at its neighbour's position, the natural place for a node created from
//! it) would otherwise drop a disk inside a disk, and the contact that parts them flings
//! both. A new node whose position overlaps a body is seated instead: beside its
//! neighbours (at one edge length from a single neighbour, in the freest direction or
//! the one the host's position points to; at the centre of several), never inside
//! another disk. A new node put in free space keeps the host's position. The body
//! starts at its seat and the first call reports the way from the host's position to it
//! as the node's delta.

use std::collections::HashMap;
use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};

use crate::input::layout::IdHasher;
use crate::world::RapierSceneWorld;

/// The gap, in world units, a seat leaves between its disk and every other.
const MARGIN: f32 = 1.0;
/// Rings searched around a seat's centre before the host's position is taken as it is.
const MAX_RINGS: usize = 64;

/// A disk in place: its centre and radius.
type Disk = (Point2D<f32>, f32);

/// The disks already in place (the world's bodies and the nodes seated so far) on a
/// uniform grid, to find a free seat near a point.
#[derive(Debug)]
pub(super) struct Seating {
    cell: f32,
    cells: HashMap<(i32, i32), Vec<Disk>, IdHasher>,
    /// The largest radius in place, which bounds how far a query looks.
    largest: f32,
    /// The length an edge rests at: how far a leaf is seated from its neighbour.
    edge_length: f32,
}

impl Seating {
    /// The disks of `world`, and seats an edge of `edge_length` from a neighbour.
    pub(super) fn new<N: Clone + Eq + Hash>(world: &RapierSceneWorld<N>, edge_length: f32) -> Self {
        let mut largest = 0.0_f32;
        for s in 0..world.slot_count() {
            largest = largest.max(world.shape_at(s).bounding_radius());
        }
        let mut seating = Self {
            cell: (4.0 * largest).max(16.0),
            cells: HashMap::with_hasher(IdHasher::default()),
            largest,
            edge_length: if edge_length.is_finite() && edge_length > 0.0 {
                edge_length
            } else {
                100.0
            },
        };
        for s in 0..world.slot_count() {
            let p = world.position_at(s);
            if p.is_finite() {
                seating.occupy(p, world.shape_at(s).bounding_radius());
            }
        }
        seating
    }

    fn key(&self, p: Point2D<f32>) -> (i32, i32) {
        // Saturating casts: a point far out lands in the edge cells, which only costs
        // the query some candidates.
        (
            (p.x / self.cell).floor() as i32,
            (p.y / self.cell).floor() as i32,
        )
    }

    /// Records a disk of `radius` at `p` in place (also a new node that is not seated).
    pub(super) fn occupy(&mut self, p: Point2D<f32>, radius: f32) {
        self.largest = self.largest.max(radius);
        let key = self.key(p);
        self.cells.entry(key).or_default().push((p, radius));
    }

    /// How far a disk of `radius` at `p` is from touching the nearest disk in place
    /// (negative in an overlap), looking no further than `reach` beyond touching.
    fn clearance(&self, p: Point2D<f32>, radius: f32, reach: f32) -> f32 {
        let look = radius + self.largest + reach;
        let (lo, hi) = (
            self.key(p - Vector2D::new(look, look)),
            self.key(p + Vector2D::new(look, look)),
        );
        let mut clearance = reach;
        let mut nearer = |&(q, r): &Disk| clearance = clearance.min((q - p).length() - radius - r);
        let span = |lo: i32, hi: i32| i64::from(hi) - i64::from(lo) + 1;
        // A reach wider than the disks' extent (a far seat in a wide layout) reads the
        // occupied cells rather than walk every empty one: the least of the same
        // distances, in any order.
        if span(lo.0, hi.0).saturating_mul(span(lo.1, hi.1)) > self.cells.len() as i64 {
            self.cells.values().flatten().for_each(&mut nearer);
            return clearance;
        }
        for x in lo.0..=hi.0 {
            for y in lo.1..=hi.1 {
                self.cells
                    .get(&(x, y))
                    .into_iter()
                    .flatten()
                    .for_each(&mut nearer);
            }
        }
        clearance
    }

    /// Where a new disk of `radius` that the host put at `host` sits, given its
    /// neighbours' positions, and records it in place: `Some` seat when the host's
    /// position overlaps another disk, `None` when the host's position is free (or no
    /// seat was found) and the node starts there.
    pub(super) fn seat(
        &mut self,
        host: Point2D<f32>,
        radius: f32,
        neighbours: &[Point2D<f32>],
    ) -> Option<Point2D<f32>> {
        let seat = self.find(host, radius, neighbours);
        self.occupy(seat.unwrap_or(host), radius);
        seat
    }

    fn find(
        &self,
        host: Point2D<f32>,
        radius: f32,
        neighbours: &[Point2D<f32>],
    ) -> Option<Point2D<f32>> {
        if self.clearance(host, radius, MARGIN) >= MARGIN {
            return None;
        }
        let step = 2.0 * radius + MARGIN;
        let (centre, first) = match neighbours {
            [] => (host, step),
            [one] => (*one, self.edge_length.max(step)),
            many => {
                let sum = many
                    .iter()
                    .fold(Vector2D::zero(), |sum, p| sum + p.to_vector());
                ((sum / many.len() as f32).to_point(), 0.0)
            }
        };
        // The direction the host's position points to from the centre, if any.
        let toward = host - centre;
        let aim = (toward.length() > 1e-3).then(|| toward.y.atan2(toward.x));
        for ring in 0..MAX_RINGS {
            let rho = first + ring as f32 * step;
            if rho == 0.0 {
                if self.clearance(centre, radius, MARGIN) >= MARGIN {
                    return Some(centre);
                }
                continue;
            }
            // Seats a radius apart around the ring.
            let count =
                ((std::f32::consts::TAU * rho / radius.max(1.0)).ceil() as usize).clamp(12, 720);
            let mut best: Option<(f32, Point2D<f32>)> = None;
            for k in 0..count {
                let angle = k as f32 * std::f32::consts::TAU / count as f32;
                let p = centre + Vector2D::new(angle.cos(), angle.sin()) * rho;
                let clearance = self.clearance(p, radius, rho);
                if clearance < MARGIN {
                    continue;
                }
                // The host's direction when it gave one, else the most room.
                let score = match aim {
                    Some(aim) => -angular_gap(angle, aim),
                    None => clearance,
                };
                if best.is_none_or(|(s, _)| score > s) {
                    best = Some((score, p));
                }
            }
            if let Some((_, p)) = best {
                return Some(p);
            }
        }
        None
    }
}

/// The angle between two directions, in `[0, π]`.
fn angular_gap(a: f32, b: f32) -> f32 {
    let d = (a - b).rem_euclid(std::f32::consts::TAU);
    d.min(std::f32::consts::TAU - d)
}
