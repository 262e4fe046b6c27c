//! Drawing the canvas: the grid with its metre labels, the scale bar, every object in
//! drawing order (bounds, ramps, trails, springs, particles with their arrows), names
//! placed so they do not collide, and the preview of a gesture in progress.

use egui::{Align2, Color32, FontId, Pos2, Rect, Shape, Stroke, Vec2};
use physics::{DVec2, Endpoint, Ramp, Scene, TieKind};

use super::shapes::{
    DOT_RADIUS, DOTS_FROM, Dots, anchor, arrow, coil, disc, rim, segment, trails_mesh,
};
use super::tools::Drag;
use super::view::{format_metres, nice_length};
use super::{Canvas, Frame, Selection, VELOCITY_ARROW_SECONDS};
use crate::run_loop::Runner;

impl Canvas {
    pub(super) fn draw_grid(&self, painter: &egui::Painter, rect: Rect) {
        let spacing = nice_length(80.0 / self.view.pixels_per_metre);
        let (lo, hi) = (
            self.view.to_world(rect, rect.left_bottom()),
            self.view.to_world(rect, rect.right_top()),
        );
        let p = &self.palette;
        let line = Stroke::new(p.width, p.grid);
        let axis = Stroke::new(1.2 * p.width, p.axis);
        let font = FontId::proportional(11.0);
        let count = ((hi.x - lo.x) / spacing).ceil() + ((hi.y - lo.y) / spacing).ceil();
        if !(count.is_finite() && count < 400.0) {
            return;
        }
        // Every line first, then every label on its patch: a line drawn after a label
        // (a horizontal one through an x label near the bottom) would hide its minus.
        let mut labels = Vec::new();
        let mut x = (lo.x / spacing).floor() * spacing;
        while x <= hi.x {
            let sx = self.view.to_screen(rect, DVec2::new(x, 0.0)).x;
            let stroke = if x.abs() < spacing * 1e-6 { axis } else { line };
            painter.line_segment(
                [Pos2::new(sx, rect.top()), Pos2::new(sx, rect.bottom())],
                stroke,
            );
            // Not in the corner, where the y axis's labels are.
            if sx > rect.left() + 56.0 {
                labels.push((Pos2::new(sx + 2.0, rect.bottom() - 2.0), x));
            }
            x += spacing;
        }
        let mut y = (lo.y / spacing).floor() * spacing;
        while y <= hi.y {
            let sy = self.view.to_screen(rect, DVec2::new(0.0, y)).y;
            let stroke = if y.abs() < spacing * 1e-6 { axis } else { line };
            painter.line_segment(
                [Pos2::new(rect.left(), sy), Pos2::new(rect.right(), sy)],
                stroke,
            );
            if sy < rect.bottom() - 16.0 {
                labels.push((Pos2::new(rect.left() + 2.0, sy - 2.0), y));
            }
            y += spacing;
        }
        for (at, value) in labels {
            self.grid_label(painter, at, format_metres(value, spacing), &font);
        }
    }

    /// A grid label on a patch of the background, so that no grid line crosses it (a
    /// horizontal line through "−2 m" would hide its minus sign).
    fn grid_label(&self, painter: &egui::Painter, at: Pos2, label: String, font: &FontId) {
        let p = &self.palette;
        let galley = painter.layout_no_wrap(label, font.clone(), p.grid_text);
        let place = Align2::LEFT_BOTTOM.anchor_size(at, galley.size());
        painter.rect_filled(place.expand(1.0), 2.0, p.background);
        painter.galley(place.min, galley, p.grid_text);
    }

    pub(super) fn draw_scale_bar(&self, painter: &egui::Painter, rect: Rect) {
        let metres = nice_length(120.0 / self.view.pixels_per_metre);
        let length = (metres * self.view.pixels_per_metre) as f32;
        let start = Pos2::new(rect.right() - length - 20.0, rect.bottom() - 22.0);
        let end = start + Vec2::new(length, 0.0);
        let ink = self.palette.ink;
        let stroke = Stroke::new(2.0 * self.palette.width, ink);
        // On a backing, so that it reads over whatever is under it.
        painter.rect_filled(
            Rect::from_min_max(start - Vec2::new(8.0, 24.0), end + Vec2::new(8.0, 10.0)),
            4.0,
            self.palette.background.gamma_multiply(0.86),
        );
        painter.line_segment([start, end], stroke);
        painter.line_segment(
            [start - Vec2::new(0.0, 5.0), start + Vec2::new(0.0, 5.0)],
            stroke,
        );
        painter.line_segment(
            [end - Vec2::new(0.0, 5.0), end + Vec2::new(0.0, 5.0)],
            stroke,
        );
        painter.text(
            start + Vec2::new(length / 2.0, -6.0),
            Align2::CENTER_BOTTOM,
            format_metres(metres, metres),
            FontId::proportional(12.0),
            ink,
        );
    }

    /// Paths drawn faintly under the scene (an experiment series' runs).
    pub(super) fn draw_paths(&self, painter: &egui::Painter, rect: Rect, paths: &[&[DVec2]]) {
        let faint = self.palette.ink.gamma_multiply(0.3);
        for path in paths {
            let points: Vec<Pos2> = path.iter().map(|&p| self.view.to_screen(rect, p)).collect();
            painter.add(egui::Shape::line(points, Stroke::new(1.0, faint)));
        }
    }

    #[expect(
        clippy::too_many_lines,
        reason = "one pass over every kind of object, in drawing order"
    )]
    #[expect(
        clippy::too_many_arguments,
        reason = "what is drawn, where, and what the user points at"
    )]
    pub(super) fn draw_scene(
        &self,
        painter: &egui::Painter,
        rect: Rect,
        scene: &Scene,
        frame: &Frame,
        runner: &Runner,
        selection: Option<Selection>,
        hovered: Option<Selection>,
    ) {
        let view = &self.view;
        // Names are placed after everything is drawn, the selected and hovered first,
        // each only where it overlaps no name already placed.
        let mut labels: Vec<(bool, Pos2, &str)> = Vec::new();
        let screen = |p: DVec2| view.to_screen(rect, p);
        let scale = view.pixels_per_metre as f32;
        let p = &self.palette;
        let (highlight, w) = (p.highlight, p.width);
        // Selected: the selection, or one of the objects selected together.
        let chosen = |s: Selection| selection == Some(s) || self.group.contains(&s);
        if let Some(bounds) = scene.world.bounds {
            let box_rect =
                Rect::from_two_pos(screen(bounds.min.to_dvec2()), screen(bounds.max.to_dvec2()));
            painter.rect_stroke(
                box_rect,
                0.0,
                Stroke::new(2.0 * w, p.ink),
                egui::StrokeKind::Outside,
            );
        }
        for (i, ramp) in scene.ramps.iter().enumerate() {
            let (a, b) = (screen(ramp.from.to_dvec2()), screen(ramp.to.to_dvec2()));
            let width = (ramp.thickness as f32 * scale).max(2.0);
            let colour = p.ramp;
            if chosen(Selection::Ramp(i)) {
                painter.line_segment([a, b], Stroke::new(width + 6.0, highlight));
            }
            painter.line_segment([a, b], Stroke::new(width, colour));
            painter.circle_filled(a, width / 2.0, colour);
            painter.circle_filled(b, width / 2.0, colour);
            let pointed = [selection, hovered].contains(&Some(Selection::Ramp(i)));
            if self.overlays.names || pointed {
                labels.push((
                    pointed,
                    a.lerp(b, 0.5) + Vec2::new(0.0, -width / 2.0 - 4.0),
                    &ramp.name,
                ));
            }
        }
        // A joint off a body it holds (a hook above a hanging block, a lever arm) is tied
        // to the body's centroid by a thin line, drawn under the bodies.
        for (joint, &at) in scene.joints.iter().zip(&frame.joints) {
            if let physics::JointKind::Pulley { radius, .. } = joint.kind {
                self.draw_pulley(painter, (rect, scene, frame), (joint, at, radius));
                continue;
            }
            for name in std::iter::once(joint.body.as_str()).chain(joint.other()) {
                let Some(i) = scene.bodies.iter().position(|b| b.name == name) else {
                    continue;
                };
                let Some(outline) = frame.outlines.get(i) else {
                    continue;
                };
                if !inside_outline(outline, at) {
                    let centre = screen(outline_centroid(outline));
                    painter.line_segment([screen(at), centre], Stroke::new(1.2 * w, p.ink));
                }
            }
        }
        for (i, (body, outline)) in scene.bodies.iter().zip(&frame.outlines).enumerate() {
            let points: Vec<Pos2> = outline.iter().map(|&v| screen(v)).collect();
            let colour = body_colour(scene, i);
            if chosen(Selection::Body(i)) {
                painter.add(Shape::closed_line(
                    points.clone(),
                    Stroke::new(6.0 * w, highlight),
                ));
            }
            let fill = if body.fixed {
                colour.gamma_multiply(0.5)
            } else {
                colour
            };
            painter.add(Shape::convex_polygon(
                points.clone(),
                fill,
                Stroke::new(1.5 * w, p.ink),
            ));
            // The centroid, marked as a drawing marks it: a small cross.
            let centre = screen(outline_centroid(outline));
            let arm = 4.0 * w;
            let ink =
                if super::contrast(fill, Color32::BLACK) >= super::contrast(fill, Color32::WHITE) {
                    Color32::BLACK
                } else {
                    Color32::WHITE
                };
            let mark = Stroke::new(1.2 * w, ink);
            painter.line_segment([centre - Vec2::X * arm, centre + Vec2::X * arm], mark);
            painter.line_segment([centre - Vec2::Y * arm, centre + Vec2::Y * arm], mark);
            let pointed = [selection, hovered].contains(&Some(Selection::Body(i)));
            if self.overlays.names || pointed {
                let top = points.iter().map(|p| p.y).fold(f32::INFINITY, f32::min);
                labels.push((pointed, Pos2::new(centre.x, top - 4.0), &body.name));
            }
        }
        // Joints as a teacher draws them: a pin a ring with a cross (a nail in the
        // world), a hinge a ring with a dot (an axle between two bodies).
        for (joint, &at) in scene.joints.iter().zip(&frame.joints) {
            if joint.is_pulley() {
                continue;
            }
            let centre = screen(at);
            let radius = 5.0 * w;
            painter.circle(centre, radius, p.background, Stroke::new(1.5 * w, p.ink));
            let ink = Stroke::new(1.2 * w, p.ink);
            if joint.other().is_none() {
                let arm = radius * std::f32::consts::FRAC_1_SQRT_2;
                painter.line_segment([centre - Vec2::splat(arm), centre + Vec2::splat(arm)], ink);
                painter.line_segment(
                    [centre + Vec2::new(-arm, arm), centre + Vec2::new(arm, -arm)],
                    ink,
                );
            } else {
                painter.circle_filled(centre, 1.8 * w, p.ink);
            }
            if self.overlays.names {
                labels.push((false, centre + Vec2::new(0.0, -radius - 4.0), &joint.name));
            }
        }
        self.draw_free_body(painter, rect, frame);
        if self.overlays.trails {
            painter.add(trails_mesh(
                runner
                    .trails
                    .iter()
                    .enumerate()
                    .map(|(i, trail)| (particle_colour(scene, i).gamma_multiply(0.45), trail)),
                screen,
            ));
        }
        // Springs too short on screen for a coil are plain lines, gathered into one mesh
        // (a cloth's thousands), laid where the springs go, under their anchors.
        let (plain_springs, mut plain) = (painter.add(Shape::Noop), egui::Mesh::default());
        for (i, (spring, ends)) in scene.springs.iter().zip(&frame.spring_ends).enumerate() {
            let Some((a, b)) = *ends else {
                continue;
            };
            let selected = chosen(Selection::Spring(i));
            let stroke = Stroke::new(
                w * if selected { 3.0 } else { 1.6 },
                if selected { highlight } else { p.spring },
            );
            let points = coil(screen(a), screen(b));
            if let [a, b] = points[..] {
                segment(&mut plain, (a, b), stroke);
            } else {
                painter.add(Shape::line(points, stroke));
            }
            for (e, p) in [(&spring.from, a), (&spring.to, b)] {
                if matches!(e, Endpoint::Point(_)) {
                    anchor(painter, screen(p), self.palette.ink);
                }
            }
        }
        painter.set(plain_springs, plain);
        for (i, (tie, ends)) in scene.ties.iter().zip(&frame.tie_ends).enumerate() {
            let Some((a, b)) = *ends else {
                continue;
            };
            let selected = chosen(Selection::Tie(i));
            let colour = if selected { highlight } else { p.tie };
            match tie.kind {
                TieKind::Rod => {
                    painter.line_segment(
                        [screen(a), screen(b)],
                        Stroke::new(w * if selected { 5.0 } else { 3.5 }, colour),
                    );
                }
                TieKind::String => {
                    let points = string_points(a, b, tie.length)
                        .into_iter()
                        .map(screen)
                        .collect();
                    painter.add(Shape::line(
                        points,
                        Stroke::new(w * if selected { 2.5 } else { 1.2 }, colour),
                    ));
                }
            }
            for (e, p) in [(&tie.from, a), (&tie.to, b)] {
                if matches!(e, Endpoint::Point(_)) {
                    anchor(painter, screen(p), self.palette.ink);
                }
            }
        }
        let many = scene.particles.len() > 150;
        let mut dots = (scene.particles.len() > DOTS_FROM)
            .then(|| Dots::new(rect, painter.ctx().pixels_per_point()));
        // A crowd is drawn as one mesh of plain discs: egui's anti-aliased, outlined
        // circles cost ten times as many triangles, which software rendering feels.
        let mut crowd = egui::Mesh::default();
        let dots_slot = painter.add(Shape::Noop);
        let crowd_slot = painter.add(Shape::Noop);
        for (i, particle) in scene.particles.iter().enumerate() {
            let Some(&position) = frame.positions.get(i) else {
                continue;
            };
            let centre = screen(position);
            let radius = (particle.radius as f32 * scale).max(2.0);
            if !rect.expand(radius).contains(centre) {
                continue;
            }
            let colour = particle_colour(scene, i);
            if chosen(Selection::Particle(i)) {
                painter.circle_filled(centre, radius + 4.0, highlight);
            }
            if let Some(dots) = dots.as_mut().filter(|_| radius <= DOT_RADIUS) {
                dots.add(centre, radius, colour);
            } else if many {
                disc(&mut crowd, centre, radius, colour);
            } else if let Some(rim) = rim(radius, particle.inertia) {
                // Hollow as its inertia says: a ring is a rim, a tube a thick one.
                painter.circle_stroke(centre, radius - rim / 2.0, Stroke::new(rim, colour));
                painter.circle_stroke(
                    centre,
                    radius,
                    Stroke::new(w, p.outline.unwrap_or(colour.gamma_multiply(0.6))),
                );
            } else {
                painter.circle(
                    centre,
                    radius,
                    colour,
                    Stroke::new(w, p.outline.unwrap_or(colour.gamma_multiply(0.6))),
                );
            }
            if particle.turns() && !many {
                // The marked radius that shows it turning.
                let angle = frame
                    .angles
                    .get(i)
                    .copied()
                    .unwrap_or(particle.angle)
                    .to_radians();
                let rim = centre + Vec2::new(angle.cos() as f32, -angle.sin() as f32) * radius;
                painter.line_segment([centre, rim], Stroke::new(w * 1.5, p.ink));
            }
            if particle.fixed {
                anchor(painter, centre, p.ink);
            }
            let pointed = [selection, hovered].contains(&Some(Selection::Particle(i)));
            if (self.overlays.names && !many) || pointed {
                labels.push((
                    pointed,
                    centre - Vec2::new(0.0, radius + 2.0),
                    &particle.name,
                ));
            }
            if self.overlays.velocity && (!many || selection == Some(Selection::Particle(i))) {
                let v = frame.velocities[i];
                if v.length() > 0.0 {
                    arrow(
                        painter,
                        centre,
                        screen(position + v * VELOCITY_ARROW_SECONDS),
                        p.velocity,
                        w,
                    );
                }
            }
            if let Some(accelerations) = &frame.accelerations {
                let a = accelerations[i];
                if self.overlays.acceleration && a.length() > 0.0 {
                    let tip =
                        position + a * (0.5 * VELOCITY_ARROW_SECONDS * VELOCITY_ARROW_SECONDS);
                    arrow(painter, centre, screen(tip), p.acceleration, w);
                }
                if self.overlays.force && a.length() > 0.0 && !particle.fixed {
                    let force = a * particle.mass;
                    let pixels = (force.length().log10() + 2.0).clamp(0.5, 6.0) * 14.0;
                    let direction = force.normalize();
                    let tip =
                        centre + Vec2::new(direction.x as f32, -direction.y as f32) * pixels as f32;
                    arrow(painter, centre, tip, p.force, w);
                }
            }
        }
        painter.set(crowd_slot, Shape::mesh(crowd));
        if let Some(dots) = dots {
            dots.paint(painter, dots_slot);
        }
        place_labels(painter, labels, p.ink);
    }

    /// A pulley as a teacher draws it: its wheel, an axle, and the string from each body's
    /// centroid to where it meets the wheel, over the wheel's top.
    fn draw_pulley(
        &self,
        painter: &egui::Painter,
        (rect, scene, frame): (Rect, &Scene, &Frame),
        (joint, at, radius): (&physics::Joint, DVec2, f64),
    ) {
        let screen = |p: DVec2| self.view.to_screen(rect, p);
        let p = &self.palette;
        let w = p.width;
        let centroid = |name: &str| {
            let i = scene.bodies.iter().position(|b| b.name == name)?;
            frame
                .outlines
                .get(i)
                .map(|outline| outline_centroid(outline))
        };
        let scale = self.view.pixels_per_metre as f32;
        let rim = (radius as f32 * scale).max(4.0 * w);
        let centre = screen(at);
        painter.circle(centre, rim, p.background, Stroke::new(2.0 * w, p.ink));
        painter.circle_filled(centre, 1.8 * w, p.ink);
        let (Some(a), Some(b)) = (joint.other().and_then(centroid), centroid(&joint.body)) else {
            return;
        };
        let [touch_a, touch_b] = physics::pulley_path(at, radius, a, b);
        let string = Stroke::new(1.4 * w, p.ink);
        painter.line_segment([screen(a), screen(touch_a)], string);
        painter.line_segment([screen(b), screen(touch_b)], string);
        // The arc over the top, from a's side round to b's.
        let (from, to) = ((touch_a - at).to_angle(), (touch_b - at).to_angle());
        let sweep = (from - to).rem_euclid(std::f64::consts::TAU);
        let arc: Vec<Pos2> = (0..=24)
            .map(|k| {
                let angle = from - sweep * f64::from(k) / 24.0;
                screen(at + DVec2::from_angle(angle) * radius)
            })
            .collect();
        painter.add(egui::Shape::line(arc, string));
    }

    /// The selected body's free-body diagram: each force an arrow from where it acts, its
    /// length in proportion (the largest 80 pixels), its size beside its tip.
    fn draw_free_body(&self, painter: &egui::Painter, rect: Rect, frame: &Frame) {
        let largest = frame
            .free_body
            .iter()
            .map(|(_, f)| f.force.length())
            .fold(0.0, f64::max);
        if largest <= 0.0 {
            return;
        }
        let p = &self.palette;
        for (at, applied) in &frame.free_body {
            let size = applied.force.length();
            if size <= 1e-9 * largest {
                continue;
            }
            let from = self.view.to_screen(rect, *at);
            let along = applied.force / largest * 80.0;
            let to = from + Vec2::new(along.x as f32, -along.y as f32);
            let colour = if applied.friction {
                p.velocity
            } else if applied.arm == DVec2::ZERO {
                p.force
            } else {
                p.acceleration
            };
            arrow(painter, from, to, colour, p.width * 1.2);
            painter.text(
                to + Vec2::new(4.0, -4.0),
                Align2::LEFT_BOTTOM,
                format!("{} N", crate::i18n::decimal(size, 2)),
                FontId::proportional(12.0),
                colour,
            );
        }
    }

    pub(super) fn draw_drag_preview(&self, painter: &egui::Painter, rect: Rect, frame: &Frame) {
        let screen = |p: DVec2| self.view.to_screen(rect, p);
        if !self.corners.is_empty() {
            // The polygon being drawn: its convex outline so far, and each corner clicked.
            let hull: Vec<Pos2> = super::tools::convex_hull(&self.corners)
                .into_iter()
                .map(screen)
                .collect();
            let colour = Color32::from_rgba_unmultiplied(80, 120, 200, 120);
            if hull.len() >= 3 {
                painter.add(Shape::convex_polygon(
                    hull,
                    colour,
                    Stroke::new(self.palette.width, self.palette.ink),
                ));
            } else if let [a, b] = hull[..] {
                painter.line_segment([a, b], Stroke::new(self.palette.width, self.palette.ink));
            }
            for &corner in &self.corners {
                painter.circle_filled(screen(corner), 3.0, self.palette.ink);
            }
        }
        match self.drag {
            Some(Drag::NewLink { from, tip, tool }) => {
                if let Some(&a) = frame.positions.get(from) {
                    let stroke = Stroke::new(1.6, Color32::from_rgb(70, 70, 200));
                    if tool == super::Tool::Spring {
                        painter.add(Shape::line(coil(screen(a), screen(tip)), stroke));
                    } else {
                        painter.line_segment([screen(a), screen(tip)], stroke);
                    }
                }
            }
            Some(Drag::Velocity { index }) => {
                // The launcher's reading beside the tip: speed and angle as it moves.
                if let (Some(&x), Some(&v)) =
                    (frame.positions.get(index), frame.velocities.get(index))
                {
                    let tip = screen(x + v * VELOCITY_ARROW_SECONDS);
                    let angle = v.y.atan2(v.x).to_degrees();
                    let speed = crate::format::with_unit(v.length(), "m/s");
                    let angle = crate::format::number(angle);
                    let text = crate::i18n::tr_with(
                        "canvas-launch",
                        &[
                            ("speed", crate::i18n::Arg::Text(&speed)),
                            ("angle", crate::i18n::Arg::Text(&angle)),
                        ],
                    );
                    let colour = self.palette.ink;
                    painter.text(
                        tip + Vec2::new(10.0, -10.0),
                        Align2::LEFT_BOTTOM,
                        text,
                        FontId::proportional(13.0),
                        colour,
                    );
                }
            }
            Some(Drag::Select { from, to }) => {
                let area = Rect::from_two_pos(screen(from), screen(to));
                let p = &self.palette;
                painter.rect_filled(area, 0.0, p.highlight.gamma_multiply(0.2));
                painter.rect_stroke(
                    area,
                    0.0,
                    Stroke::new(p.width, p.highlight),
                    egui::StrokeKind::Inside,
                );
            }
            Some(Drag::NewBox { from, to }) => {
                let area = Rect::from_two_pos(screen(from), screen(to));
                painter.rect_filled(
                    area,
                    0.0,
                    Color32::from_rgba_unmultiplied(80, 120, 200, 120),
                );
            }
            Some(Drag::NewRamp { from, to }) => {
                painter.line_segment(
                    [screen(from), screen(to)],
                    Stroke::new(
                        (Ramp::DEFAULT_THICKNESS * self.view.pixels_per_metre).max(2.0) as f32,
                        Color32::from_rgba_unmultiplied(150, 120, 90, 160),
                    ),
                );
            }
            _ => {}
        }
    }
}

/// Draws each name centred above its point, the pointed-at ones first, skipping any
/// that would overlap a name already drawn: a crowded scene shows some names, never a
/// smear of them (the rest appear on hover).
fn place_labels(painter: &egui::Painter, mut labels: Vec<(bool, Pos2, &str)>, ink: Color32) {
    labels.sort_by_key(|(pointed, _, _)| !pointed);
    let mut placed: Vec<Rect> = Vec::new();
    for (pointed, at, name) in labels {
        let colour = if pointed { Color32::from_gray(10) } else { ink };
        let galley = painter.layout_no_wrap(name.to_owned(), FontId::proportional(12.0), colour);
        let rect = Align2::CENTER_BOTTOM.anchor_size(at, galley.size());
        if placed.iter().any(|r| r.intersects(rect)) {
            continue;
        }
        placed.push(rect.expand(1.0));
        painter.galley(rect.min, galley, colour);
    }
}

/// Where two ends (of a spring, rod or string) are, given the particles' positions and
/// their indices by name ([`Scene::particle_indices`]).
pub(super) fn ends(
    names: &std::collections::HashMap<&str, usize>,
    from: &Endpoint,
    to: &Endpoint,
    positions: &[DVec2],
) -> Option<(DVec2, DVec2)> {
    let end = |e: &Endpoint| match e {
        Endpoint::Particle(name) => names
            .get(name.as_str())
            .and_then(|&k| positions.get(k).copied()),
        Endpoint::Point(p) => Some(p.to_dvec2()),
    };
    Some((end(from)?, end(to)?))
}

/// A string from `a` to `b` (metres) of `length`: straight when taut, else the parabola
/// of that arc length hanging below the chord (sag s with L ≈ c + 8 s² / (3 c)).
fn string_points(a: DVec2, b: DVec2, length: f64) -> Vec<DVec2> {
    let chord = a.distance(b);
    if chord <= 0.0 || length <= chord {
        return vec![a, b];
    }
    let sag = (3.0 * chord * (length - chord) / 8.0)
        .sqrt()
        .min(length / 2.0);
    let along = (b - a) / chord;
    let mut down = along.perp();
    if down.y > 0.0 {
        down = -down;
    }
    (0..=16)
        .map(|k| {
            let s = f64::from(k) / 16.0;
            a + (b - a) * s + down * (4.0 * sag * s * (1.0 - s))
        })
        .collect()
}

/// Body `i`'s colour: its own, or the palette's after the particles'.
fn body_colour(scene: &Scene, i: usize) -> Color32 {
    let [r, g, b] = body_rgb(scene, i);
    Color32::from_rgb(r, g, b)
}

fn body_rgb(scene: &Scene, i: usize) -> [u8; 3] {
    scene.bodies[i]
        .color
        .unwrap_or_else(|| physics::Color::palette(scene.particles.len() + i))
        .0
}

fn particle_rgb(scene: &Scene, i: usize) -> [u8; 3] {
    scene.particles[i]
        .color
        .unwrap_or_else(|| physics::Color::palette(i))
        .0
}

/// The colour the canvas draws the particle or body named `name` in, for what shows
/// it elsewhere (its curves on a graph).
pub(crate) fn object_rgb(scene: &Scene, name: &str) -> Option<[u8; 3]> {
    if let Some(i) = scene.particles.iter().position(|p| p.name == name) {
        return Some(particle_rgb(scene, i));
    }
    let i = scene.bodies.iter().position(|b| b.name == name)?;
    Some(body_rgb(scene, i))
}

/// The centroid of a convex outline, metres.
/// Whether `point` lies inside a counter-clockwise convex `outline` (or on it).
fn inside_outline(outline: &[DVec2], point: DVec2) -> bool {
    outline
        .iter()
        .zip(outline.iter().cycle().skip(1))
        .all(|(&a, &b)| (b - a).perp_dot(point - a) >= -1e-9 * (b - a).length())
}

fn outline_centroid(outline: &[DVec2]) -> DVec2 {
    physics::moments(outline).centroid
}

fn particle_colour(scene: &Scene, i: usize) -> Color32 {
    let [r, g, b] = particle_rgb(scene, i);
    Color32::from_rgb(r, g, b)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every grid label is drawn after every grid line, on its patch of background, so
    /// that no line crosses a label (a line through "−2 m" hid its minus sign).
    #[test]
    fn grid_labels_lie_over_every_grid_line() {
        let ctx = egui::Context::default();
        let mut canvas = Canvas::default();
        canvas.view.center = DVec2::new(-3.0, -2.0);
        let output = ctx.run_ui(egui::RawInput::default(), |ui| {
            let rect = Rect::from_min_size(Pos2::new(10.0, 10.0), Vec2::new(400.0, 300.0));
            canvas.draw_grid(ui.painter(), rect);
        });
        let kinds: Vec<bool> = output
            .shapes
            .iter()
            .filter_map(|clipped| match &clipped.shape {
                Shape::LineSegment { .. } => Some(false),
                Shape::Text(_) => Some(true),
                _ => None,
            })
            .collect();
        let lines = kinds.iter().filter(|text| !**text).count();
        assert!(
            lines > 4 && kinds.len() > lines,
            "lines and labels: {kinds:?}"
        );
        assert!(
            kinds.iter().skip(lines).all(|text| *text),
            "every label after every line: {kinds:?}"
        );
    }

    /// A disc is solid, a ring a thin rim, a tube between them as thick as its inertia
    /// says: k = 0.82 is a tube with rᵢ = r √0.64 = 0.8 r, a rim of 0.2 r.
    #[test]
    fn a_ring_is_drawn_hollow_as_its_inertia_says() {
        assert_eq!(super::rim(20.0, 0.5), None, "a solid disc");
        assert_eq!(super::rim(20.0, 0.0), None, "a point");
        assert_eq!(super::rim(20.0, 1.0), Some(2.0), "a thin ring: two pixels");
        let tube = super::rim(20.0, 0.82).expect("hollow");
        assert!((tube - 4.0).abs() < 1e-4, "{tube}");
    }
}
