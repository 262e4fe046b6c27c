//! The canvas's meshes and marks: discs (a square of the same area when tiny), a crowd
//! of dots painted as one picture, trails as strips of quads, a spring's coil, anchors,
//! arrows and a wheel's rim.

use egui::{Color32, Pos2, Rect, Shape, Stroke, Vec2};
use physics::DVec2;

/// Adds a filled disc to `mesh` as a fan of triangles, finer for larger discs; a disc
/// of a few pixels as a square of the same area (two triangles where a fan takes eight:
/// a star cluster's fans were too many to rasterise in software within a frame, and at
/// that size the eye cannot tell a square from a disc).
pub(super) fn disc(mesh: &mut egui::Mesh, centre: Pos2, radius: f32, colour: Color32) {
    if radius <= DOT_RADIUS {
        let half = radius * std::f32::consts::PI.sqrt() / 2.0;
        mesh.add_colored_rect(
            egui::Rect::from_center_size(centre, Vec2::splat(2.0 * half)),
            colour,
        );
        return;
    }
    let segments = (radius * 1.5).clamp(8.0, 32.0) as u32;
    let first = mesh.vertices.len() as u32;
    mesh.colored_vertex(centre, colour);
    for k in 0..segments {
        let angle = std::f32::consts::TAU * k as f32 / segments as f32;
        mesh.colored_vertex(centre + Vec2::angled(angle) * radius, colour);
    }
    for k in 0..segments {
        mesh.add_triangle(first, first + 1 + k, first + 1 + (k + 1) % segments);
    }
}

/// Discs up to this radius, pixels, are drawn as squares of the same area ([`disc`]).
pub(super) const DOT_RADIUS: f32 = 2.5;
/// From this many particles on, the dots among them are painted into one picture of the
/// canvas ([`Dots`]).
pub(super) const DOTS_FROM: usize = 2000;

/// The dots of a large crowd (a star cluster), painted pixel by pixel into a picture of
/// the canvas that is drawn as one textured rectangle: software rendering spends most of
/// a frame on the triangles of many small squares (docs/performance.md, "The app").
pub(super) struct Dots {
    rect: Rect,
    pixels_per_point: f32,
    size: [usize; 2],
    pixels: Vec<Color32>,
}

impl Dots {
    pub(super) fn new(rect: Rect, pixels_per_point: f32) -> Self {
        let size = [
            (rect.width() * pixels_per_point).round().max(1.0) as usize,
            (rect.height() * pixels_per_point).round().max(1.0) as usize,
        ];
        Self {
            rect,
            pixels_per_point,
            size,
            pixels: vec![Color32::TRANSPARENT; size[0] * size[1]],
        }
    }

    /// A square of the area of a disc of `radius` points at `centre`, clipped to the
    /// picture.
    pub(super) fn add(&mut self, centre: Pos2, radius: f32, colour: Color32) {
        let scale = self.pixels_per_point;
        let side = (radius * std::f32::consts::PI.sqrt() * scale)
            .round()
            .max(1.0);
        let at = (centre - self.rect.min) * scale;
        let span = |c: f32, len: usize| {
            let first = (c - side / 2.0).round();
            let clamp = |v: f32| (v.max(0.0) as usize).min(len);
            clamp(first)..clamp(first + side)
        };
        let (columns, rows) = (span(at.x, self.size[0]), span(at.y, self.size[1]));
        for row in rows {
            let line = row * self.size[0];
            self.pixels[line + columns.start..line + columns.end].fill(colour);
        }
    }

    /// Uploads the picture and draws it over the canvas in `slot`.
    pub(super) fn paint(self, painter: &egui::Painter, slot: egui::layers::ShapeIdx) {
        let image = egui::ColorImage::new(self.size, self.pixels);
        let id = egui::Id::unique("canvas dots");
        let ctx = painter.ctx();
        let texture = if let Some(mut texture) = ctx.data(|d| d.get_temp::<egui::TextureHandle>(id))
        {
            texture.set(image, egui::TextureOptions::NEAREST);
            texture
        } else {
            let texture = ctx.load_texture("canvas dots", image, egui::TextureOptions::NEAREST);
            ctx.data_mut(|d| d.insert_temp(id, texture.clone()));
            texture
        };
        let uv = Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0));
        painter.set(
            slot,
            Shape::image(texture.id(), self.rect, uv, Color32::WHITE),
        );
    }
}

/// The least squared distance between the points of a trail drawn, points².
const TRAIL_SPACING: f32 = 1.5 * 1.5;

/// The width of a trail, points.
const TRAIL_WIDTH: f32 = 1.5;

/// Every trail as one mesh of plain strips, `screen` taking world to screen: a thousand
/// trails of 400 points each as anti-aliased lines would make a software renderer shade
/// three times the pixels (a line's feathered edges) and the tessellator build a
/// thousand paths a frame. Points closer than [`TRAIL_SPACING`] to the last one drawn
/// add nothing to see (a pile at rest jitters its 400 points into one spot).
pub(super) fn trails_mesh<'a>(
    trails: impl Iterator<Item = (Color32, &'a std::collections::VecDeque<DVec2>)>,
    screen: impl Fn(DVec2) -> Pos2,
) -> egui::Mesh {
    let mut mesh = egui::Mesh::default();
    let mut points: Vec<Pos2> = Vec::new();
    for (colour, trail) in trails {
        points.clear();
        for p in trail.iter().map(|p| screen(*p)) {
            if points
                .last()
                .is_none_or(|last| last.distance_sq(p) >= TRAIL_SPACING)
            {
                points.push(p);
            }
        }
        if points.len() < 2 {
            continue;
        }
        // A strip: each point's two corners across the segment from it (the last
        // point's, the segment to it), shared by the quads on either side.
        let first = u32::try_from(mesh.vertices.len()).unwrap_or(u32::MAX);
        for (k, &p) in points.iter().enumerate() {
            let d = if k + 1 < points.len() {
                points[k + 1] - p
            } else {
                p - points[k - 1]
            };
            let side = Vec2::new(-d.y, d.x) * (0.5 * TRAIL_WIDTH / d.length());
            mesh.colored_vertex(p - side, colour);
            mesh.colored_vertex(p + side, colour);
        }
        for k in 0..u32::try_from(points.len() - 1).unwrap_or(0) {
            let at = first + 2 * k;
            mesh.add_triangle(at, at + 1, at + 3);
            mesh.add_triangle(at, at + 3, at + 2);
        }
    }
    mesh
}

/// A straight line from `a` to `b` with `stroke` added to `mesh` as a plain quad (no
/// feathered edges: lines by the thousand, where each line's edges cost as much to
/// shade in software as the line).
pub(super) fn segment(mesh: &mut egui::Mesh, (a, b): (Pos2, Pos2), stroke: Stroke) {
    let d = b - a;
    let length = d.length();
    if length <= 0.0 {
        return;
    }
    let side = Vec2::new(-d.y, d.x) * (0.5 * stroke.width / length);
    let k = u32::try_from(mesh.vertices.len()).unwrap_or(u32::MAX);
    for corner in [a - side, a + side, b + side, b - side] {
        mesh.colored_vertex(corner, stroke.color);
    }
    mesh.add_triangle(k, k + 1, k + 2);
    mesh.add_triangle(k, k + 2, k + 3);
}

/// The least length of one turn of a spring's coil on screen, points.
const COIL_TURN: f32 = 6.0;

/// The zig-zag of a spring from `a` to `b`, with a straight lead at each end.
pub(super) fn coil(a: Pos2, b: Pos2) -> Vec<Pos2> {
    let (d, length) = (b - a, (b - a).length());
    if length < 1.0 {
        return vec![a, b];
    }
    // Up to twelve turns, each at least six points long: a spring a few points long on
    // screen (a cloth of thousands, zoomed out) is a plain line, which is all that can
    // be seen of it there, and a tenth of the triangles to draw.
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a small count of turns from a finite length"
    )]
    let turns = ((length * 0.8 / COIL_TURN).floor() as usize).min(12);
    if turns < 2 {
        return vec![a, b];
    }
    let (along, across) = (d / length, Vec2::new(-d.y, d.x) / length);
    let width = (length * 0.08).clamp(3.0, 9.0);
    let lead = length * 0.1;
    let mut points = vec![a, a + along * lead];
    for k in 1..turns * 2 {
        let t = lead + (length - 2.0 * lead) * k as f32 / (turns * 2) as f32;
        let side = if k % 2 == 0 { -width } else { width };
        points.push(a + along * t + across * side);
    }
    points.push(b - along * lead);
    points.push(b);
    points
}

/// A fixed point's mark: a small hatched triangle.
pub(super) fn anchor(painter: &egui::Painter, at: Pos2, ink: Color32) {
    let stroke = Stroke::new(1.5, ink);
    let (left, right) = (at + Vec2::new(-7.0, 10.0), at + Vec2::new(7.0, 10.0));
    painter.add(Shape::closed_line(vec![at, left, right], stroke));
    for k in 0..4 {
        let x = -7.0 + 4.5 * k as f32;
        painter.line_segment(
            [at + Vec2::new(x, 10.0), at + Vec2::new(x - 3.0, 14.0)],
            stroke,
        );
    }
}

pub(super) fn arrow(painter: &egui::Painter, from: Pos2, to: Pos2, colour: Color32, width: f32) {
    let d = to - from;
    if d.length() < 2.0 {
        return;
    }
    painter.arrow(from, d, Stroke::new(2.0 * width, colour));
}

/// The width of the rim a turning particle is drawn with, pixels, when it is hollow: a
/// tube of outer radius r and inner radius rᵢ has I = ½ m (r² + rᵢ²), so a moment of
/// inertia k m r² with k above ½ (a solid disc) is a tube with rᵢ = r √(2k − 1), and a
/// thin ring (k = 1) a rim of two pixels. `None` for a solid disc or a point.
pub(crate) fn rim(radius: f32, inertia: f64) -> Option<f32> {
    if inertia <= 0.5 || !inertia.is_finite() {
        return None;
    }
    #[expect(
        clippy::cast_possible_truncation,
        reason = "a fraction of a radius on screen"
    )]
    let inner = radius * (2.0 * inertia.min(1.0) - 1.0).sqrt() as f32;
    Some((radius - inner).max(2.0).min(radius))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A dot of radius 2 points at 2 pixels per point covers a square of 2·√π·2 ≈ 7
    /// pixels a side (49 against the disc's 50.3), centred on it; one that reaches over the picture's edge is cut
    /// off there (the canvas draws particles up to a radius beyond its rectangle), and
    /// one wholly outside paints nothing.
    #[test]
    fn a_dot_is_a_square_of_the_discs_area_cut_off_at_the_edges() {
        let rect = Rect::from_min_size(Pos2::new(100.0, 50.0), Vec2::new(40.0, 30.0));
        let mut dots = Dots::new(rect, 2.0);
        assert_eq!(dots.size, [80, 60]);
        let red = Color32::RED;
        dots.add(Pos2::new(120.0, 65.0), 2.0, red);
        let painted: Vec<(usize, usize)> = (0..60)
            .flat_map(|y| (0..80).map(move |x| (x, y)))
            .filter(|&(x, y)| dots.pixels[y * 80 + x] == red)
            .collect();
        assert_eq!(painted.len(), 7 * 7, "{painted:?}");
        assert!(
            painted
                .iter()
                .all(|&(x, y)| (37..44).contains(&x) && (27..34).contains(&y))
        );
        let mut edge = Dots::new(rect, 2.0);
        edge.add(Pos2::new(100.5, 79.5), 2.0, red);
        let count = edge.pixels.iter().filter(|&&p| p == red).count();
        assert_eq!(count, 4 * 4, "cut to the picture's corner");
        let mut outside = Dots::new(rect, 2.0);
        outside.add(Pos2::new(90.0, 40.0), 2.0, red);
        outside.add(Pos2::new(150.0, 90.0), 2.0, red);
        assert!(outside.pixels.iter().all(|&p| p == Color32::TRANSPARENT));
    }

    /// A trail is a strip of two corners a point, half the width either side of its
    /// path: ten points 10 apart along x make nine quads (20 corners, 54 indices) at
    /// y ± 0.75; 400 points jittering within a pixel of one spot (a ball at rest) and a
    /// trail of one point make none.
    #[test]
    fn a_trail_is_a_strip_of_quads_without_the_points_it_cannot_show() {
        use std::collections::VecDeque;
        let straight: VecDeque<DVec2> = (0..10)
            .map(|k| DVec2::new(10.0 * f64::from(k), 5.0))
            .collect();
        let jitter: VecDeque<DVec2> = (0..400)
            .map(|k| DVec2::new(50.0 + 0.4 * (f64::from(k) * 0.7).sin(), 5.0))
            .collect();
        let alone: VecDeque<DVec2> = [DVec2::new(1.0, 1.0)].into();
        let screen = |p: DVec2| Pos2::new(p.x as f32, p.y as f32);
        let red = Color32::RED;
        let mesh = trails_mesh([(red, &straight)].into_iter(), screen);
        assert_eq!((mesh.vertices.len(), mesh.indices.len()), (20, 54));
        for (k, v) in mesh.vertices.iter().enumerate() {
            let x = 10.0 * (k / 2) as f32;
            let y = if k % 2 == 0 { 4.25 } else { 5.75 };
            assert!(
                (v.pos - Pos2::new(x, y)).length() < 1e-5,
                "corner {k}: {:?}",
                v.pos
            );
            assert_eq!(v.color, red);
        }
        let mesh = trails_mesh([(red, &jitter), (red, &alone)].into_iter(), screen);
        assert!(mesh.is_empty(), "{} corners", mesh.vertices.len());
    }

    /// A spring's coil has a turn every six points at least, up to twelve: a spring 10
    /// points long on screen (a cloth zoomed out) is a plain line, one 100 long twelve
    /// turns (a lead, 23 corners, a lead).
    #[test]
    fn a_short_spring_on_screen_is_a_plain_line() {
        let a = Pos2::new(0.0, 0.0);
        assert_eq!(coil(a, Pos2::new(10.0, 0.0)).len(), 2);
        assert_eq!(coil(a, Pos2::new(100.0, 0.0)).len(), 2 + 23 + 2);
        assert_eq!(coil(a, Pos2::new(30.0, 0.0)).len(), 2 + 7 + 2, "four turns");
    }
}
