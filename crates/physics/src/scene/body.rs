//! A rigid body of convex shape (`[[body]]`): a box or a convex polygon, with its mass
//! properties computed exactly from the outline.

use glam::DVec2;

use super::{Color, Vector};

/// The outline of a body.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A rectangle centred on the centroid: `width` along the body's x, `height` along its
    /// y, metres. Written with [`Body::width`] and [`Body::height`].
    Box,
    /// A convex polygon, counter-clockwise, in the body's frame as typed (metres); it is
    /// moved so that its centroid is the body's origin.
    Polygon(Vec<DVec2>),
}

impl Shape {
    /// As a scene file writes it: `box` or `polygon`.
    pub const fn as_str(&self) -> &'static str {
        match self {
            Self::Box => "box",
            Self::Polygon(_) => "polygon",
        }
    }
}

/// A rigid body: it moves and turns as one, its state the centroid's position and
/// velocity and the angle and spin about it.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// Unique among all objects of the scene.
    pub name: String,
    /// Its outline.
    pub shape: Shape,
    /// A box's width, metres (0 for a polygon).
    pub width: f64,
    /// A box's height, metres (0 for a polygon).
    pub height: f64,
    /// Kilograms; 0 when the mass comes from [`Self::density`].
    pub mass: f64,
    /// Kilograms per square metre; 0 when [`Self::mass`] is given.
    pub density: f64,
    /// The centroid, metres.
    pub position: Vector,
    /// Degrees, counter-clockwise. Default 0.
    pub angle: f64,
    /// The centroid's velocity, metres per second. Default zero.
    pub velocity: Vector,
    /// Radians per second, counter-clockwise. Default 0.
    pub spin: f64,
    /// Coefficient of restitution, 0..=1. Default 1.
    pub restitution: f64,
    /// Kinetic coefficient of friction, ≥ 0. Default 0.
    pub friction: f64,
    /// Static coefficient of friction, ≥ the kinetic one; `None`: the kinetic one.
    pub static_friction: Option<f64>,
    /// A fixed body never moves.
    pub fixed: bool,
    /// Display colour; `None` lets the app choose.
    pub color: Option<Color>,
}

/// A shape's area and moments: what the mass properties come from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Moments {
    /// Square metres.
    pub area: f64,
    /// The centroid in the frame the outline was given in, metres.
    pub centroid: DVec2,
    /// ∫ r² dA about the centroid, m⁴: the moment of inertia per unit density.
    pub polar: f64,
}

impl Body {
    /// A box `width` × `height` metres of `mass` kilograms, at the origin, at rest.
    #[must_use]
    pub fn rectangle(name: impl Into<String>, width: f64, height: f64, mass: f64) -> Self {
        Self {
            name: name.into(),
            shape: Shape::Box,
            width,
            height,
            mass,
            density: 0.0,
            position: Vector::ZERO,
            angle: 0.0,
            velocity: Vector::ZERO,
            spin: 0.0,
            restitution: 1.0,
            friction: 0.0,
            static_friction: None,
            fixed: false,
            color: None,
        }
    }

    /// A convex polygon of `mass` kilograms, its `vertices` counter-clockwise (metres, in
    /// its own frame; its centroid is put at `position`).
    #[must_use]
    pub fn polygon(name: impl Into<String>, vertices: Vec<DVec2>, mass: f64) -> Self {
        Self {
            shape: Shape::Polygon(vertices),
            width: 0.0,
            height: 0.0,
            ..Self::rectangle(name, 0.0, 0.0, mass)
        }
    }

    /// Sets the position of the centroid, metres.
    #[must_use]
    pub fn position(mut self, position: impl Into<Vector>) -> Self {
        self.position = position.into();
        self
    }

    /// Sets the centroid's velocity (m/s) and the spin (rad/s, counter-clockwise).
    #[must_use]
    pub fn moving(mut self, velocity: impl Into<Vector>, spin: f64) -> Self {
        self.velocity = velocity.into();
        self.spin = spin;
        self
    }

    /// Sets the angle, degrees counter-clockwise.
    #[must_use]
    pub fn angle(mut self, angle: f64) -> Self {
        self.angle = angle;
        self
    }

    /// The outline as typed: a box's four corners, counter-clockwise from the lower
    /// left, or the polygon's vertices.
    pub fn outline(&self) -> Vec<DVec2> {
        match &self.shape {
            Shape::Box => {
                let (x, y) = (0.5 * self.width, 0.5 * self.height);
                vec![
                    DVec2::new(-x, -y),
                    DVec2::new(x, -y),
                    DVec2::new(x, y),
                    DVec2::new(-x, y),
                ]
            }
            Shape::Polygon(vertices) => vertices.clone(),
        }
    }

    /// The outline about the centroid, in the body's frame: what turns with it.
    pub fn local_outline(&self) -> Vec<DVec2> {
        let outline = self.outline();
        let centroid = moments(&outline).centroid;
        outline.into_iter().map(|v| v - centroid).collect()
    }

    /// The outline in the world at the start: turned by the angle about the centroid and
    /// moved to the position.
    pub fn world_outline(&self) -> Vec<DVec2> {
        let turn = DVec2::from_angle(self.angle.to_radians());
        let at = self.position.to_dvec2();
        self.local_outline()
            .into_iter()
            .map(|v| at + turn.rotate(v))
            .collect()
    }

    /// The mass, kilograms: as given, or the density times the area.
    pub fn total_mass(&self) -> f64 {
        if self.mass > 0.0 {
            self.mass
        } else {
            self.density * moments(&self.outline()).area
        }
    }

    /// The moment of inertia about the centroid, kg·m².
    pub fn inertia(&self) -> f64 {
        let m = moments(&self.outline());
        if m.area > 0.0 {
            self.total_mass() * m.polar / m.area
        } else {
            0.0
        }
    }

    /// The static coefficient of friction: as given, or the kinetic one.
    pub fn static_friction(&self) -> f64 {
        self.static_friction.unwrap_or(self.friction)
    }
}

/// The area, centroid and polar second moment of the polygon `vertices`
/// (counter-clockwise; a clockwise one has a negative area) by the shoelace sums over its
/// edges' triangles, taken about its first vertex so that a polygon far from the origin
/// loses no digits to cancellation.
pub fn moments(vertices: &[DVec2]) -> Moments {
    let Some(&origin) = vertices.first() else {
        return Moments {
            area: 0.0,
            centroid: DVec2::ZERO,
            polar: 0.0,
        };
    };
    let (mut twice_area, mut first, mut second) = (0.0, DVec2::ZERO, 0.0);
    for (k, &a) in vertices.iter().enumerate() {
        let (p, q) = (a - origin, vertices[(k + 1) % vertices.len()] - origin);
        let cross = p.perp_dot(q);
        twice_area += cross;
        first += (p + q) * cross;
        second += cross * (p.dot(p) + p.dot(q) + q.dot(q));
    }
    let area = 0.5 * twice_area;
    if area == 0.0 {
        return Moments {
            area,
            centroid: origin,
            polar: 0.0,
        };
    }
    let centroid = first / (3.0 * twice_area);
    Moments {
        area,
        centroid: origin + centroid,
        polar: second / 12.0 - area * centroid.length_squared(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_box_has_the_textbook_inertia() {
        let body = Body::rectangle("b", 0.4, 0.2, 2.0);
        let expected = 2.0 * (0.4_f64.powi(2) + 0.2_f64.powi(2)) / 12.0;
        assert!((body.inertia() - expected).abs() <= 1e-15 * expected);
        assert!((body.total_mass() - 2.0).abs() == 0.0);
    }

    #[test]
    fn a_polygon_far_from_the_origin_keeps_its_digits() {
        let far = DVec2::new(1e6, -3e6);
        let triangle = [DVec2::ZERO, DVec2::new(3.0, 0.0), DVec2::new(0.0, 4.0)];
        let near = moments(&triangle);
        let moved: Vec<DVec2> = triangle.iter().map(|&v| v + far).collect();
        let m = moments(&moved);
        assert!((m.area - 6.0).abs() < 1e-9 && (near.area - 6.0).abs() < 1e-15);
        // A right triangle's legs a, b: I/m = (a² + b²)/18 about the centroid.
        let per_area = (9.0 + 16.0) / 18.0;
        assert!((near.polar / near.area - per_area).abs() < 1e-14);
        assert!((m.polar / m.area - per_area).abs() < 1e-6);
        assert!((m.centroid - far - DVec2::new(1.0, 4.0 / 3.0)).length() < 1e-9);
    }

    #[test]
    fn density_gives_the_mass_by_area() {
        let mut body = Body::rectangle("b", 2.0, 0.5, 0.0);
        body.density = 3.0;
        assert!((body.total_mass() - 3.0).abs() < 1e-15);
    }
}
