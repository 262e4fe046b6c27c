//! When, within a step, a moving particle first enters a region: another particle's reach,
//! a ramp, a wall.
//!
//! Within a step of length h the integrator gives each particle's position and velocity
//! at both ends; the cubic Hermite curve through them is the path (exact for constant
//! acceleration, error O(h⁴) otherwise). As a Bézier curve its control points are
//! x0, x0 + v0 h/3, x1 − v1 h/3, x1. Each region is described by gap functions that are
//! polynomials along the path (|x − c|² − R² for a disc, of degree 6; signed distances to
//! a line, of degree 3), written in the Bernstein basis, where a polynomial never drops
//! below its smallest coefficient. The search halves the path recursively, earliest half
//! first, and discards every piece in which some gap provably stays positive. The
//! coefficients converge to the polynomial quadratically as pieces shrink, so a path
//! grazing a surface is discarded after a level or two, and nothing is sampled: no speed
//! skips over a thin ramp.
//!
//! Two balls under the same field alone (most pairs in a falling or piling crowd) move on
//! a straight line relative to each other, at constant speed: for such a path the entry
//! into a disc is the root of a quadratic ([`straight_entry`]), found without the
//! subdivision, which costs more.
//!
//! Alternatives weighed: sampling the gap at sub-steps misses thin ramps at high speed; a
//! straight-line swept test ignores acceleration within the step; bounding the distance by
//! the control points' spread converges only linearly and explodes for grazing paths.

use glam::DVec2;

use super::obstacles::Shape;
use crate::tuning::{MAX_DEPTH, STRAIGHT};

/// A region a particle's centre may enter, given as gap functions: the centre is inside
/// when every gap is ≤ 0.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Region {
    /// Within `reach` of `centre`.
    Disc { centre: DVec2, reach: f64 },
    /// Within `reach` of the line through `origin` along unit `direction`, and between
    /// `origin` and `origin + length · direction` along it.
    Slab {
        origin: DVec2,
        direction: DVec2,
        length: f64,
        reach: f64,
    },
    /// Within `reach` of the half-plane behind `point` with outward unit `normal`.
    HalfPlane {
        point: DVec2,
        normal: DVec2,
        reach: f64,
    },
}

impl Region {
    /// The regions a particle of radius `radius` enters when it touches `shape`.
    pub fn around(shape: &Shape, radius: f64) -> ([Option<Self>; 3], usize) {
        match *shape {
            Shape::HalfPlane { point, normal } => (
                [
                    Some(Self::HalfPlane {
                        point,
                        normal,
                        reach: radius,
                    }),
                    None,
                    None,
                ],
                1,
            ),
            Shape::Capsule {
                a,
                b,
                radius: half_thickness,
            } => {
                let reach = radius + half_thickness;
                let length = a.distance(b);
                let slab = (length > 0.0).then(|| Self::Slab {
                    origin: a,
                    direction: (b - a) / length,
                    length,
                    reach,
                });
                (
                    [
                        Some(Self::Disc { centre: a, reach }),
                        Some(Self::Disc { centre: b, reach }),
                        slab,
                    ],
                    3,
                )
            }
        }
    }

    /// The largest of the gaps at `p`: ≤ 0 exactly when `p` is inside.
    fn gap(&self, p: DVec2) -> f64 {
        match *self {
            Self::Disc { centre, reach } => (p - centre).length_squared() - reach * reach,
            Self::Slab {
                origin,
                direction,
                length,
                reach,
            } => {
                let offset = p - origin;
                let along = offset.dot(direction);
                let across = offset.perp_dot(direction).abs();
                (across - reach).max(-along).max(along - length)
            }
            Self::HalfPlane {
                point,
                normal,
                reach,
            } => (p - point).dot(normal) - reach,
        }
    }

    /// Whether the piece of path with control points `p` certainly stays outside.
    fn clear_of(&self, p: &[DVec2; 4]) -> bool {
        match *self {
            Self::Disc { centre, reach } => disc_clear(&p.map(|q| q - centre), reach),
            Self::Slab {
                origin,
                direction,
                length,
                reach,
            } => {
                let along = p.map(|q| (q - origin).dot(direction));
                let across = p.map(|q| (q - origin).perp_dot(direction));
                along.iter().all(|&u| u > length)
                    || along.iter().all(|&u| u < 0.0)
                    || across.iter().all(|&w| w > reach)
                    || across.iter().all(|&w| w < -reach)
            }
            Self::HalfPlane {
                point,
                normal,
                reach,
            } => p.iter().all(|q| (*q - point).dot(normal) > reach),
        }
    }
}

impl Region {
    /// Whether the piece of path with control points `p` starts outside and certainly
    /// crosses into the region exactly once: the Bernstein coefficients of its gap
    /// change sign once, from positive to negative (a polynomial has no more roots in
    /// the piece than its coefficients have sign changes, and an odd number when its
    /// ends differ in sign). A slab, the largest of three gaps, is left to subdivision.
    fn crosses_once(&self, p: &[DVec2; 4]) -> bool {
        match *self {
            Self::Disc { centre, reach } => {
                let d = p.map(|q| q - centre);
                let r2 = reach * reach;
                let dot = |i: usize, j: usize| d[i].dot(d[j]);
                // C(6, m) times each coefficient, as in `disc_clear`: the same signs.
                one_sign_change(&[
                    d[0].length_squared() - r2,
                    dot(0, 1) - r2,
                    6.0 * dot(0, 2) + 9.0 * d[1].length_squared() - 15.0 * r2,
                    2.0 * dot(0, 3) + 18.0 * dot(1, 2) - 20.0 * r2,
                    6.0 * dot(1, 3) + 9.0 * d[2].length_squared() - 15.0 * r2,
                    dot(2, 3) - r2,
                    d[3].length_squared() - r2,
                ])
            }
            Self::HalfPlane {
                point,
                normal,
                reach,
            } => one_sign_change(&p.map(|q| (q - point).dot(normal) - reach)),
            Self::Slab { .. } => false,
        }
    }
}

/// Whether `c` starts positive, ends negative, and changes sign once, with no zero
/// (a zero coefficient could hide a touching root: left to subdivision).
fn one_sign_change(c: &[f64]) -> bool {
    let Some(first_negative) = c.iter().position(|&x| x < 0.0) else {
        return false;
    };
    c[0] > 0.0
        && c[..first_negative].iter().all(|&x| x > 0.0)
        && c[first_negative..].iter().all(|&x| x < 0.0)
}

/// Whether the cubic D with control points `d` stays farther than `reach` from the
/// origin: every Bernstein coefficient of |D(s)|² − reach² is positive. The product of two
/// cubics is a sextic with coefficients `c[m] = Σ_{i+j=m} C(3,i) C(3,j) D[i]·D[j] / C(6,m)`;
/// the test is made on `C(6,m) c[m]`, which has the same sign and needs no division, from
/// the ten distinct dot products (the sum is symmetric in i and j), lowest degree first so
/// that a piece that starts inside stops at once.
fn disc_clear(d: &[DVec2; 4], reach: f64) -> bool {
    let r2 = reach * reach;
    let dot = |i: usize, j: usize| d[i].dot(d[j]);
    d[0].length_squared() > r2
        && d[3].length_squared() > r2
        && dot(0, 1) > r2
        && dot(2, 3) > r2
        && 6.0 * dot(0, 2) + 9.0 * d[1].length_squared() > 15.0 * r2
        && 6.0 * dot(1, 3) + 9.0 * d[2].length_squared() > 15.0 * r2
        && 2.0 * dot(0, 3) + 18.0 * dot(1, 2) > 20.0 * r2
}

/// The Bézier control points of the Hermite path from (x0, v0) to (x1, v1) over `h`.
pub(crate) fn control_points(x0: DVec2, v0: DVec2, x1: DVec2, v1: DVec2, h: f64) -> [DVec2; 4] {
    [x0, x0 + v0 * (h / 3.0), x1 - v1 * (h / 3.0), x1]
}

/// The two halves of a path.
fn split(p: &[DVec2; 4]) -> ([DVec2; 4], [DVec2; 4]) {
    let q0 = p[0].midpoint(p[1]);
    let q1 = p[1].midpoint(p[2]);
    let q2 = p[2].midpoint(p[3]);
    let r0 = q0.midpoint(q1);
    let r1 = q1.midpoint(q2);
    let m = r0.midpoint(r1);
    ([p[0], q0, r0, m], [m, r1, q2, p[3]])
}

/// The earliest parameter s in (0, 1] at which the path, which starts outside, is inside
/// `region`; `None` if it stays outside.
pub(crate) fn earliest_entry(region: &Region, path: &[DVec2; 4]) -> Option<f64> {
    if let Region::Disc { centre, reach } = *region
        && let Some(entry) = straight_entry(&path.map(|p| p - centre), reach)
    {
        return entry;
    }
    search(region, path, 0.0, 1.0, 0)
}

/// The earliest entry into the disc of `reach` about the origin of a path that is a
/// straight line travelled at constant speed to within [`STRAIGHT`] of the reach (two
/// balls under the same field alone: their accelerations cancel), as the root of a
/// quadratic; `None` for any other path, and for one that the rounding of the root
/// leaves a hair outside (the search then finds it). The line is tested against the
/// reach less how far the path can be from it, so the path is inside at the instant
/// returned (checked, as the search's is), at most twice that distance over the approach
/// speed after it entered.
#[expect(
    clippy::option_option,
    reason = "not straight (search), or straight with or without an entry"
)]
fn straight_entry(path: &[DVec2; 4], reach: f64) -> Option<Option<f64>> {
    let (start, chord) = (path[0], path[3] - path[0]);
    // The curve less the line is the cubic with control points 0, d1, d2, 0: never
    // farther from the line than 3/4 of the larger.
    let d1 = path[1] - (start + chord / 3.0);
    let d2 = path[2] - (start + chord * (2.0 / 3.0));
    let bend_squared = d1.length_squared().max(d2.length_squared());
    if bend_squared > (STRAIGHT * reach).powi(2) {
        return None;
    }
    // Less a hair for the rounding of the root and of the point at it (without it a
    // quarter of the entries came out a hair outside, and went to the search).
    let inner = reach * (1.0 - 1e-14) - 0.75 * bend_squared.sqrt();
    // |start + chord s|² = inner², from outside: a s² + 2 b s + c = 0, c > 0.
    let (a, b, c) = (
        chord.length_squared(),
        start.dot(chord),
        start.length_squared() - inner * inner,
    );
    if c <= 0.0 {
        return None; // starts inside: the search's
    }
    let discriminant = b * b - a * c;
    if b >= 0.0 || discriminant < 0.0 {
        return Some(None); // moving apart, or passing by
    }
    // The smaller root, without cancellation.
    let s = c / (-b + discriminant.sqrt());
    if s > 1.0 {
        return Some(None);
    }
    let region = Region::Disc {
        centre: DVec2::ZERO,
        reach,
    };
    (region.gap(point_at(path, s)) <= 0.0).then_some(Some(s))
}

fn search(region: &Region, path: &[DVec2; 4], s0: f64, s1: f64, depth: u32) -> Option<f64> {
    if region.clear_of(path) {
        return None;
    }
    if depth == MAX_DEPTH {
        return (region.gap(path[3]) <= 0.0).then_some(s1);
    }
    if region.crosses_once(path) {
        return Some(s0 + (s1 - s0) * crossing(region, path, s1 - s0));
    }
    let (left, right) = split(path);
    let mid = 0.5 * (s0 + s1);
    search(region, &left, s0, mid, depth + 1).or_else(|| search(region, &right, mid, s1, depth + 1))
}

/// The one crossing into `region` of a piece of path that [`Region::crosses_once`]: a
/// parameter of the piece at which the centre is inside, within 2⁻⁴⁴ of the step (the
/// piece spans `width` of it) after the crossing, like the subdivision's. Illinois
/// regula falsi on the gap along the piece: superlinear, and the bracket never lost.
fn crossing(region: &Region, piece: &[DVec2; 4], width: f64) -> f64 {
    let tolerance = (-f64::from(MAX_DEPTH)).exp2() / width;
    let (mut outside, mut inside) = (0.0, 1.0);
    let (mut gap_outside, mut gap_inside) = (region.gap(piece[0]), region.gap(piece[3]));
    // Which end moved last: Illinois halves the other end's gap when one end repeats.
    let mut last_side = 0_i8;
    for _ in 0..100 {
        if inside - outside <= tolerance {
            break;
        }
        let mut s = inside - gap_inside * (inside - outside) / (gap_inside - gap_outside);
        if !(s > outside && s < inside) {
            s = 0.5 * (outside + inside);
        }
        let gap = region.gap(point_at(piece, s));
        if gap <= 0.0 {
            (inside, gap_inside) = (s, gap);
            if last_side == -1 {
                gap_outside *= 0.5;
            }
            last_side = -1;
        } else {
            (outside, gap_outside) = (s, gap);
            if last_side == 1 {
                gap_inside *= 0.5;
            }
            last_side = 1;
        }
    }
    inside
}

/// The point at parameter `s` of a cubic Bézier curve (de Casteljau).
fn point_at(p: &[DVec2; 4], s: f64) -> DVec2 {
    let q0 = p[0].lerp(p[1], s);
    let q1 = p[1].lerp(p[2], s);
    let q2 = p[2].lerp(p[3], s);
    q0.lerp(q1, s).lerp(q1.lerp(q2, s), s)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The root of `gap` between a point outside (`gap > 0`) and one inside, by 200
    /// halvings: the inside end, to rounding.
    fn bisect(gap: impl Fn(f64) -> f64, mut outside: f64, mut inside: f64) -> f64 {
        for _ in 0..200 {
            let mid = 0.5 * (outside + inside);
            if gap(mid) > 0.0 {
                outside = mid;
            } else {
                inside = mid;
            }
        }
        inside
    }

    /// 20,000 cubic paths with control points uniform in [−2, 2]², from a fixed seed.
    fn random_paths(seed: u64) -> impl Iterator<Item = [DVec2; 4]> {
        let mut random = crate::testing::uniform(seed);
        (0..20_000).map(move |_| {
            std::array::from_fn(|_| DVec2::new(4.0 * random() - 2.0, 4.0 * random() - 2.0))
        })
    }

    fn disc(reach: f64) -> Region {
        Region::Disc {
            centre: DVec2::ZERO,
            reach,
        }
    }

    /// Head-on at 2 m/s from 10 m apart, contact at 1 m apart after (10 − 1)/2 = 4.5 s,
    /// s = 0.45 of a 10 s step.
    #[test]
    fn straight_approach_is_found_exactly() {
        let path = control_points(
            DVec2::new(10.0, 0.0),
            DVec2::new(-2.0, 0.0),
            DVec2::new(-10.0, 0.0),
            DVec2::new(-2.0, 0.0),
            10.0,
        );
        let s = earliest_entry(&disc(1.0), &path).unwrap();
        assert!((s - 0.45).abs() < 1e-13, "s = {s}");
    }

    /// Passing 0.5 m beside the origin: never within 0.4 m; within 0.6 m first at
    /// x = −√(0.6² − 0.5²).
    #[test]
    fn a_near_miss_is_no_contact() {
        let path = control_points(
            DVec2::new(-50.0, 0.5),
            DVec2::new(10.0, 0.0),
            DVec2::new(50.0, 0.5),
            DVec2::new(10.0, 0.0),
            10.0,
        );
        assert_eq!(earliest_entry(&disc(0.4), &path), None, "misses by 0.1 m");
        let s = earliest_entry(&disc(0.6), &path).unwrap();
        let x = -50.0 + 100.0 * s;
        assert!(
            (x + (0.6_f64 * 0.6 - 0.25).sqrt()).abs() < 1e-11,
            "first contact at x = {x}"
        );
    }

    /// Constant acceleration is exact: y = 10 − 5t² reaches y = 1 at t = √1.8.
    #[test]
    fn a_parabola_is_exact() {
        let wall = Region::HalfPlane {
            point: DVec2::ZERO,
            normal: DVec2::Y,
            reach: 1.0,
        };
        let h = 2.0;
        let path = control_points(
            DVec2::new(0.0, 10.0),
            DVec2::ZERO,
            DVec2::new(0.0, 10.0 - 5.0 * h * h),
            DVec2::new(0.0, -10.0 * h),
            h,
        );
        let s = earliest_entry(&wall, &path).unwrap();
        assert!((s * h - 1.8_f64.sqrt()).abs() < 1e-12, "t = {}", s * h);
    }

    /// A path parallel to a surface 1e-9 m outside reach is cleared quickly, and a ball
    /// crossing a 0.01 m ramp at 1,000 m/s in one 1 s step is caught.
    #[test]
    fn grazing_and_tunnelling() {
        let path = control_points(
            DVec2::new(-1.0, 1.0 + 1e-9),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 1.0 + 1e-9),
            DVec2::new(1.0, 0.0),
            2.0,
        );
        assert_eq!(
            earliest_entry(&disc(1.0), &path),
            None,
            "a graze 1e-9 outside"
        );
        let ramp = Shape::Capsule {
            a: DVec2::new(-1.0, 0.0),
            b: DVec2::new(1.0, 0.0),
            radius: 0.005,
        };
        let path = control_points(
            DVec2::new(0.3, 500.0),
            DVec2::new(0.0, -1000.0),
            DVec2::new(0.3, -500.0),
            DVec2::new(0.0, -1000.0),
            1.0,
        );
        let (regions, count) = Region::around(&ramp, 0.05);
        let first = regions[..count]
            .iter()
            .flatten()
            .filter_map(|r| earliest_entry(r, &path))
            .fold(f64::INFINITY, f64::min);
        // Contact when y = 0.05 + 0.005: t = (500 − 0.055) / 1000.
        assert!(
            (first - (500.0 - 0.055) / 1000.0).abs() < 1e-12,
            "s = {first}"
        );
    }

    /// A curved path through a disc, entering and leaving within the step: the entry,
    /// not the exit, to 1e-13 of the step, and a point inside. The path is
    /// x = 0.3 t, y = 2 − 2.5 t² over 2 s (constant acceleration, so the Hermite path is
    /// exact); the entry into the unit disc is the first root of
    /// 0.09 t² + (2 − 2.5 t²)² = 1, found here by bisection on that formula.
    #[test]
    fn a_curved_entry_is_the_first_root() {
        let h = 2.0;
        let path = control_points(
            DVec2::new(0.0, 2.0),
            DVec2::new(0.3, 0.0),
            DVec2::new(0.3 * h, 2.0 - 2.5 * h * h),
            DVec2::new(0.3, -5.0 * h),
            h,
        );
        let gap = |t: f64| 0.09 * t * t + (2.0 - 2.5 * t * t).powi(2) - 1.0;
        let inside = bisect(gap, 0.0, 0.8); // gap(0.8) = 0.0576 + 0.16 − 1 < 0
        let s = earliest_entry(&disc(1.0), &path).unwrap();
        assert!(
            (s * h - inside).abs() < 1e-13 * h,
            "t = {} against {inside}",
            s * h
        );
        assert!(gap(s * h) <= 1e-12, "inside at the instant returned");
    }

    /// A parabola that crosses the unit circle four times, ending inside after the
    /// third: x = −0.9 + 1.4 s, y = 3x² − 1.02 (constant acceleration, so the path is
    /// exact). It enters near x = −0.6, leaves and enters again either side of x = 0:
    /// the entry is the first root of x² + y² = 1, found here by scanning and bisection
    /// on that formula, to 1e-12 of the step. A piece judged to cross once when it
    /// crosses three times would give a later root.
    #[test]
    fn a_path_that_enters_leaves_and_enters_again_is_found_at_its_first_entry() {
        let point = |s: f64| {
            let x = -0.9 + 1.4 * s;
            DVec2::new(x, 3.0 * x * x - 1.02)
        };
        let velocity = |s: f64| DVec2::new(1.4, 6.0 * (-0.9 + 1.4 * s) * 1.4);
        let path = control_points(point(0.0), velocity(0.0), point(1.0), velocity(1.0), 1.0);
        let gap = |s: f64| point(s).length_squared() - 1.0;
        let crossings = (1..=1000)
            .filter(|&k| {
                (gap(f64::from(k - 1) / 1000.0) > 0.0) != (gap(f64::from(k) / 1000.0) > 0.0)
            })
            .count();
        assert_eq!(crossings, 3, "the path crosses three times in the step");
        let first_inside = (1..=1000)
            .map(|k| f64::from(k) / 1000.0)
            .find(|&s| gap(s) <= 0.0)
            .unwrap();
        let inside = bisect(gap, first_inside - 1e-3, first_inside);
        let s = earliest_entry(&disc(1.0), &path).unwrap();
        assert!((s - inside).abs() < 1e-12, "s = {s} against {inside}");
    }

    /// Two balls under the same field alone move on straight lines relative to each other:
    /// [`straight_entry`] answers for such a path by a quadratic's root, and must agree
    /// with the subdivision (`search`) to 1e-12 of the step, entries and misses alike, on
    /// 20,000 random straight paths about the unit disc (their control points rounded as
    /// any are). A path bent by more than [`STRAIGHT`] of the reach is left to the search.
    #[test]
    fn a_straight_path_is_answered_by_the_quadratic_as_the_search_answers_it() {
        let region = disc(1.0);
        let mut random = crate::testing::uniform(7);
        let (mut entries, mut misses, mut left) = (0, 0, 0);
        for _ in 0..20_000 {
            let start = DVec2::new(6.0 * random() - 3.0, 6.0 * random() - 3.0);
            let velocity = DVec2::new(8.0 * random() - 4.0, 8.0 * random() - 4.0);
            let (h, field) = (0.7, DVec2::new(0.0, -9.81));
            // Both ends of each of two balls, the same field on both: the difference of
            // their paths is straight to rounding.
            let ball = |x: DVec2, v: DVec2| {
                control_points(x, v, x + v * h + field * (h * h / 2.0), v + field * h, h)
            };
            let other = DVec2::new(random(), random());
            let (a, b) = (ball(other, DVec2::ZERO), ball(other + start, velocity));
            let path: [DVec2; 4] = std::array::from_fn(|k| b[k] - a[k]);
            if path[0].length() <= 1.0 + 1e-9 {
                continue;
            }
            let answer = straight_entry(&path, 1.0);
            let searched = search(&region, &path, 0.0, 1.0, 0);
            match (answer, searched) {
                (Some(Some(s)), Some(t)) => {
                    entries += 1;
                    assert!((s - t).abs() < 1e-12, "{path:?}: {s} against {t}");
                }
                (Some(None), None) => misses += 1,
                (None, _) => left += 1, // rounded a hair outside: the search's
                (answer, searched) => panic!("{path:?}: {answer:?} against {searched:?}"),
            }
        }
        assert!(
            entries > 1_000 && misses > 10_000 && left < 200,
            "{entries} entries, {misses} misses, {left} left to the search"
        );
        // Bent by 1e-9 of the reach, well beyond the rounding: not taken as straight.
        let bent = [
            DVec2::new(3.0, 0.0),
            DVec2::new(1.0, 1e-9),
            DVec2::new(-1.0, 1e-9),
            DVec2::new(-3.0, 0.0),
        ];
        assert_eq!(straight_entry(&bent, 1.0), None);
        // The bound scales with the reach: bent by 1e-12 m, straight for a reach of 2 m
        // (within 2e-12 m), not for one of 0.2 m (within 2e-13 m).
        let slightly = bent.map(|p| DVec2::new(p.x, p.y * 1e-3));
        assert!(straight_entry(&slightly, 2.0).is_some());
        assert_eq!(straight_entry(&slightly, 0.2), None);
        // The same path unbent is.
        let unbent = bent.map(|p| DVec2::new(p.x, 0.0));
        assert!(straight_entry(&unbent, 1.0).is_some());
    }

    /// Against brute force: 20,000 random cubic paths starting outside the unit disc
    /// (many only grazing it, dipping in early, late or in the middle of the step). Where
    /// 4,001 samples of the path find a point inside by more than 1e-9, the search must
    /// find an entry, no later than that first sample and not before the last sample
    /// outside ahead of it; where every sample is outside by 1e-9, it must find none.
    /// Any early-out that calls a dipping piece clear, or a shortcut that takes a later
    /// crossing, fails here.
    #[test]
    fn every_entry_sampling_sees_is_found_and_no_other() {
        let region = disc(1.0);
        let (mut entries, mut misses) = (0, 0);
        for path in random_paths(2_024) {
            if path[0].length() <= 1.0 + 1e-9 {
                continue;
            }
            let samples: Vec<f64> = (0..=4000)
                .map(|k| point_at(&path, f64::from(k) / 4000.0).length() - 1.0)
                .collect();
            let found = earliest_entry(&region, &path);
            match samples.iter().position(|&gap| gap < -1e-9) {
                Some(k) => {
                    entries += 1;
                    let s = found.unwrap_or_else(|| panic!("{path:?}: missed an entry"));
                    let before = (0..k).rev().find(|&m| samples[m] > 1e-9).unwrap();
                    assert!(
                        s <= f64::from(u32::try_from(k).unwrap()) / 4000.0
                            && s >= f64::from(u32::try_from(before).unwrap()) / 4000.0,
                        "{path:?}: entry at {s}, samples say between {before} and {k} / 4000"
                    );
                }
                None if samples.iter().all(|&gap| gap > 1e-9) => {
                    misses += 1;
                    assert_eq!(found, None, "{path:?}: an entry that is not there");
                }
                None => {}
            }
        }
        assert!(
            entries > 1000 && misses > 1000,
            "{entries} entries, {misses} misses"
        );
    }

    /// `crosses_once` is a promise that lets regula falsi replace the halving: on
    /// 20,000 random pieces of path, wherever it says a piece crosses into the disc (or
    /// a half-plane) exactly once, 4,001 samples find the piece starting outside, ending
    /// inside and crossing once. (Saying "no" wrongly costs only time: the piece is
    /// halved.)
    #[test]
    fn crosses_once_is_said_only_of_a_single_crossing() {
        let regions = [
            disc(1.0),
            Region::HalfPlane {
                point: DVec2::ZERO,
                normal: DVec2::Y,
                reach: 0.5,
            },
        ];
        let mut promised = [0, 0];
        for path in random_paths(77) {
            for (k, region) in regions.iter().enumerate() {
                if !region.crosses_once(&path) {
                    continue;
                }
                promised[k] += 1;
                let inside: Vec<bool> = (0..=4000)
                    .map(|m| region.gap(point_at(&path, f64::from(m) / 4000.0)) <= 0.0)
                    .collect();
                let changes = inside.windows(2).filter(|w| w[0] != w[1]).count();
                assert!(
                    !inside[0] && inside[4000] && changes == 1,
                    "{path:?}: said to cross once, sampled {changes} crossings"
                );
            }
        }
        assert!(promised.iter().all(|&n| n > 500), "{promised:?}");
    }

    /// The Bernstein coefficients of the gap's sign on a piece, computed another way: the
    /// control points to the power basis, the product |D(s)|² − r² (or the half-plane's
    /// linear gap) multiplied out there, and back to Bernstein's basis by
    /// `b[m] = Σ_{k≤m} C(m, k) / C(n, k) · a[k]`.
    fn bernstein_of_gap(region: &Region, p: &[DVec2; 4]) -> Vec<f64> {
        let choose = |n: usize, k: usize| -> f64 {
            (0..k).fold(1.0, |c, i| c * (n - i) as f64 / (i + 1) as f64)
        };
        let to_bernstein = |a: &[f64]| -> Vec<f64> {
            let n = a.len() - 1;
            (0..=n)
                .map(|m| (0..=m).map(|k| choose(m, k) / choose(n, k) * a[k]).sum())
                .collect()
        };
        match *region {
            Region::Disc { centre, reach } => {
                let d = p.map(|q| q - centre);
                // D(s) = d0 + 3(d1 − d0)s + 3(d0 − 2d1 + d2)s² + (d3 − 3d2 + 3d1 − d0)s³.
                let power = [
                    d[0],
                    3.0 * (d[1] - d[0]),
                    3.0 * (d[0] - 2.0 * d[1] + d[2]),
                    d[3] - 3.0 * d[2] + 3.0 * d[1] - d[0],
                ];
                let mut squared = [0.0; 7];
                for (i, a) in power.iter().enumerate() {
                    for (j, b) in power.iter().enumerate() {
                        squared[i + j] += a.dot(*b);
                    }
                }
                squared[0] -= reach * reach;
                to_bernstein(&squared)
            }
            Region::HalfPlane {
                point,
                normal,
                reach,
            } => p.iter().map(|q| (*q - point).dot(normal) - reach).collect(),
            Region::Slab { .. } => Vec::new(),
        }
    }

    /// Runs `decides` on 20,000 random pieces against an off-centre disc of reach 0.7
    /// and an offset, tilted half-plane, and requires it to agree with `rule` applied to
    /// the gap's Bernstein coefficients computed independently (`bernstein_of_gap`),
    /// wherever no coefficient is within 1e-9 of zero (where rounding may decide either
    /// way). Returns how often the rule said yes, per region. (The earlier tests used a
    /// disc of reach 1 at the origin and a half-plane through it, where
    /// `reach * reach → reach / reach` and `q − centre → q + centre` change nothing.)
    fn agrees_with_the_bernstein_rule(
        seed: u64,
        decides: impl Fn(&Region, &[DVec2; 4]) -> bool,
        rule: impl Fn(&[f64]) -> bool,
    ) -> [usize; 2] {
        let regions = [
            Region::Disc {
                centre: DVec2::new(0.3, -0.2),
                reach: 0.7,
            },
            Region::HalfPlane {
                point: DVec2::new(0.2, 0.4),
                normal: DVec2::new(0.6, 0.8),
                reach: 0.3,
            },
        ];
        let mut yes = [0; 2];
        for path in random_paths(seed) {
            for (k, region) in regions.iter().enumerate() {
                let exact = bernstein_of_gap(region, &path);
                if exact.iter().any(|c| c.abs() < 1e-9) {
                    continue;
                }
                let expected = rule(&exact);
                yes[k] += usize::from(expected);
                assert_eq!(
                    decides(region, &path),
                    expected,
                    "{path:?} against {exact:?}"
                );
            }
        }
        yes
    }

    /// `crosses_once` says yes exactly when the gap's Bernstein coefficients start
    /// positive and change sign once. So it neither promises a crossing that is not
    /// single nor misses one its rule should see (a "no" costs a subdivision, and a
    /// formula that said it too often would cost time unseen by the other tests).
    #[test]
    fn crosses_once_follows_the_bernstein_rule_on_the_exact_coefficients() {
        let yes = agrees_with_the_bernstein_rule(91, Region::crosses_once, one_sign_change);
        assert!(yes.iter().all(|&n| n > 300), "{yes:?}");
    }

    /// `clear_of` (the disc's seven conditions, the half-plane's four) says a piece stays
    /// outside exactly when every Bernstein coefficient of its gap is positive. A
    /// condition dropped or weakened lets a piece that enters be called clear (a ball
    /// through a ball); one made stricter only costs subdivisions.
    #[test]
    fn clear_of_follows_the_bernstein_rule_on_the_exact_coefficients() {
        let clear =
            agrees_with_the_bernstein_rule(93, Region::clear_of, |c| c.iter().all(|&x| x > 0.0));
        assert!(clear.iter().all(|&n| n > 50), "{clear:?}");
    }

    /// The crossing's bracket: the sign rule counts changes, not ends.
    #[test]
    fn one_sign_change_only() {
        assert!(one_sign_change(&[1.0, 0.5, -0.1, -2.0]));
        assert!(!one_sign_change(&[1.0, -0.5, 0.1, -2.0]), "three changes");
        assert!(!one_sign_change(&[1.0, -0.5, 0.1]), "ends outside");
        assert!(!one_sign_change(&[-1.0, -0.5]), "starts inside");
        assert!(!one_sign_change(&[1.0, 0.0, -1.0]), "a zero");
        assert!(!one_sign_change(&[1.0, 2.0]), "never inside");
    }
}
