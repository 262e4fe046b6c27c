//! Static solids particles can hit: ramps (a segment thickened into a capsule, solid from
//! every side, rounded ends) and the walls of the world's bounding box (half-planes).

use glam::DVec2;

use crate::impact::ImpactTarget;
use crate::scene::Scene;

/// The solid's geometry.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Shape {
    /// Every point within `radius` of the segment `a`–`b`.
    Capsule { a: DVec2, b: DVec2, radius: f64 },
    /// Every point behind the line through `point` with outward unit `normal`.
    HalfPlane { point: DVec2, normal: DVec2 },
}

#[derive(Clone, Debug)]
pub(crate) struct Obstacle {
    pub shape: Shape,
    /// What it is in the scene: a ramp (by its index) or a wall of the bounds.
    pub target: ImpactTarget,
    /// Coefficient of restitution of impacts, 0..=1.
    pub restitution: f64,
    /// Coefficient of friction, kinetic (and static, for particles).
    pub friction: f64,
    /// Coefficient of static friction for rigid bodies: the scene's, or `friction`.
    pub static_friction: f64,
}

impl Shape {
    /// Distance from `p` to the solid's surface (negative inside) and the outward unit
    /// normal of the surface nearest `p`.
    pub fn distance(&self, p: DVec2) -> (f64, DVec2) {
        match *self {
            Self::Capsule { a, b, radius } => {
                let ab = b - a;
                let length_squared = ab.length_squared();
                let s = if length_squared > 0.0 {
                    ((p - a).dot(ab) / length_squared).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let offset = p - (a + ab * s);
                let d = offset.length();
                let normal = if d > 0.0 {
                    offset / d
                } else if length_squared > 0.0 {
                    // On the segment itself: either side is as near; take the left.
                    ab.perp().normalize()
                } else {
                    DVec2::Y
                };
                (d - radius, normal)
            }
            Self::HalfPlane { point, normal } => ((p - point).dot(normal), normal),
        }
    }

    /// Whether the box (min, max) certainly stays clear of the solid: no point of it
    /// lies in a capsule's bounding box, or every point of it lies in front of a
    /// half-plane. A particle whose reach over a step fits in such a box cannot touch.
    pub fn clear_of_box(&self, min: DVec2, max: DVec2) -> bool {
        match *self {
            Self::Capsule { .. } => self.bounding_box().is_some_and(|(lo, hi)| {
                lo.x > max.x || min.x > hi.x || lo.y > max.y || min.y > hi.y
            }),
            Self::HalfPlane { point, normal } => {
                // The corner of the box deepest towards the solid.
                let deepest = DVec2::new(
                    if normal.x > 0.0 { min.x } else { max.x },
                    if normal.y > 0.0 { min.y } else { max.y },
                );
                (deepest - point).dot(normal) > 0.0
            }
        }
    }

    /// The bounding box, or `None` for an unbounded half-plane.
    pub fn bounding_box(&self) -> Option<(DVec2, DVec2)> {
        match *self {
            Self::Capsule { a, b, radius } => Some((
                a.min(b) - DVec2::splat(radius),
                a.max(b) + DVec2::splat(radius),
            )),
            Self::HalfPlane { .. } => None,
        }
    }
}

/// The scene's ramps, then its four walls when it has bounds.
pub(crate) fn obstacles(scene: &Scene) -> Vec<Obstacle> {
    let mut obstacles: Vec<Obstacle> = scene
        .ramps
        .iter()
        .enumerate()
        .map(|(k, ramp)| Obstacle {
            target: ImpactTarget::Ramp(k),
            shape: Shape::Capsule {
                a: ramp.from.to_dvec2(),
                b: ramp.to.to_dvec2(),
                radius: ramp.thickness / 2.0,
            },
            restitution: ramp.restitution,
            friction: ramp.friction,
            static_friction: ramp.static_friction.unwrap_or(ramp.friction),
        })
        .collect();
    if let Some(bounds) = scene.world.bounds {
        let (min, max) = (bounds.min.to_dvec2(), bounds.max.to_dvec2());
        // Each wall is the solid outside the box; its outward normal points into the box.
        for (point, normal) in [
            (min, DVec2::X),
            (min, DVec2::Y),
            (max, DVec2::NEG_X),
            (max, DVec2::NEG_Y),
        ] {
            obstacles.push(Obstacle {
                target: ImpactTarget::Wall,
                shape: Shape::HalfPlane { point, normal },
                restitution: scene.world.restitution,
                friction: bounds.friction,
                static_friction: bounds.static_friction.unwrap_or(bounds.friction),
            });
        }
    }
    obstacles
}
