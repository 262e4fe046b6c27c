//! The world on screen: metres, y up. Zoom (wheel or pinch, around the pointer) and pan,
//! a grid with labelled metre ticks and a scale bar; particles, springs as coils, ramps
//! as thick segments, fixed points as anchors; velocity, acceleration and force arrows
//! and trails. While no simulation runs the scene can be edited here with the tools.

// World coordinates are f64 metres, screen coordinates f32 points: the conversions
// narrow on purpose, and pixel counts are small positive numbers.
#![expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "f64 world to f32 screen, see above"
)]

use egui::{
    Align2, Color32, FontId, Pos2, Rect, Sense, Shape, Stroke, Ui, Vec2, epaint::PathStroke,
};
use physics::{DVec2, Endpoint, Particle, Ramp, Scene, Spring, Vector};

use crate::document::Document;
use crate::run_loop::Runner;

/// What a click or drag on the canvas does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tool {
    Select,
    Particle,
    Spring,
    Ramp,
}

impl Tool {
    pub const ALL: [Self; 4] = [Self::Select, Self::Particle, Self::Spring, Self::Ramp];

    pub fn label(self) -> &'static str {
        match self {
            Self::Select => "Select",
            Self::Particle => "Particle",
            Self::Spring => "Spring",
            Self::Ramp => "Ramp",
        }
    }

    pub fn hint(self) -> &'static str {
        match self {
            Self::Select => {
                "Select and move objects; drag a velocity arrow's tip to set the velocity; drag empty space to pan (1)"
            }
            Self::Particle => "Click the canvas to place a particle (2)",
            Self::Spring => {
                "Drag from a particle to another particle, or to empty space for a fixed point (3)"
            }
            Self::Ramp => "Drag to draw a ramp (4)",
        }
    }
}

/// The selected object.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Selection {
    Particle(usize),
    Spring(usize),
    Ramp(usize),
}

/// Which overlays are drawn.
#[derive(Clone, Copy, Debug)]
#[expect(clippy::struct_excessive_bools, reason = "independent on/off toggles")]
pub struct Overlays {
    pub velocity: bool,
    pub acceleration: bool,
    pub force: bool,
    pub trails: bool,
    pub names: bool,
}

impl Default for Overlays {
    fn default() -> Self {
        Self {
            velocity: true,
            acceleration: false,
            force: false,
            trails: false,
            names: true,
        }
    }
}

/// Where the world is on screen.
#[derive(Clone, Copy, Debug)]
pub struct View {
    /// The world point at the canvas centre, metres.
    pub center: DVec2,
    pub pixels_per_metre: f64,
}

impl View {
    pub fn to_screen(&self, rect: Rect, p: DVec2) -> Pos2 {
        let d = (p - self.center) * self.pixels_per_metre;
        Pos2::new(rect.center().x + d.x as f32, rect.center().y - d.y as f32)
    }

    pub fn to_world(&self, rect: Rect, p: Pos2) -> DVec2 {
        let d = p - rect.center();
        self.center + DVec2::new(f64::from(d.x), -f64::from(d.y)) / self.pixels_per_metre
    }

    /// Zooms by `factor` keeping the world point under `anchor` in place.
    pub fn zoom_at(&mut self, rect: Rect, anchor: Pos2, factor: f64) {
        let before = self.to_world(rect, anchor);
        self.pixels_per_metre = (self.pixels_per_metre * factor).clamp(1e-6, 1e9);
        let after = self.to_world(rect, anchor);
        self.center += before - after;
    }

    /// Shows the box `min`–`max` with a margin.
    pub fn fit(&mut self, rect: Rect, min: DVec2, max: DVec2) {
        let size = (max - min).max(DVec2::splat(1.0));
        self.center = (min + max) / 2.0;
        let scale_x = f64::from(rect.width()) / size.x;
        let scale_y = f64::from(rect.height()) / size.y;
        self.pixels_per_metre = (scale_x.min(scale_y) * 0.85).clamp(1e-6, 1e9);
    }
}

/// A drag in progress.
#[derive(Clone, Copy, Debug)]
enum Drag {
    Pan,
    Particle { index: usize, grab: DVec2 },
    Ramp { index: usize, last: DVec2 },
    RampEnd { index: usize, to: bool },
    Velocity { index: usize },
    NewSpring { from: usize, tip: DVec2 },
    NewRamp { from: DVec2, to: DVec2 },
}

/// Seconds of motion a velocity arrow shows: its tip is where the particle would be.
pub const VELOCITY_ARROW_SECONDS: f64 = 0.5;

pub struct Canvas {
    pub view: View,
    pub tool: Tool,
    pub overlays: Overlays,
    drag: Option<Drag>,
    fit_pending: bool,
    /// The canvas rectangle of the last frame, for fitting from menus.
    pub rect: Rect,
}

impl Default for Canvas {
    fn default() -> Self {
        Self {
            view: View {
                center: DVec2::ZERO,
                pixels_per_metre: 30.0,
            },
            tool: Tool::Select,
            overlays: Overlays::default(),
            drag: None,
            fit_pending: true,
            rect: Rect::from_min_size(Pos2::ZERO, Vec2::new(800.0, 600.0)),
        }
    }
}

/// Positions and velocities to draw: the simulation's while one exists, else the scene's.
struct Frame {
    positions: Vec<DVec2>,
    velocities: Vec<DVec2>,
    accelerations: Option<Vec<DVec2>>,
}

impl Canvas {
    /// Fits the view to the scene at the next frame.
    pub fn request_fit(&mut self) {
        self.fit_pending = true;
    }

    /// The box around everything in the scene.
    pub fn scene_box(scene: &Scene, positions: &[DVec2]) -> Option<(DVec2, DVec2)> {
        let mut points: Vec<DVec2> = Vec::new();
        for (p, x) in scene.particles.iter().zip(positions) {
            points.push(*x - DVec2::splat(p.radius));
            points.push(*x + DVec2::splat(p.radius));
        }
        for ramp in &scene.ramps {
            points.push(ramp.from.to_dvec2());
            points.push(ramp.to.to_dvec2());
        }
        for spring in &scene.springs {
            for end in [&spring.from, &spring.to] {
                if let Endpoint::Point(p) = end {
                    points.push(p.to_dvec2());
                }
            }
        }
        if let Some(bounds) = scene.world.bounds {
            points.push(bounds.min.to_dvec2());
            points.push(bounds.max.to_dvec2());
        }
        let first = *points.first()?;
        Some(
            points
                .iter()
                .fold((first, first), |(lo, hi), p| (lo.min(*p), hi.max(*p))),
        )
    }

    /// Draws the canvas and handles its input. Returns the new selection if it changed.
    pub fn ui(
        &mut self,
        ui: &mut Ui,
        document: &mut Document,
        runner: &Runner,
        selection: &mut Option<Selection>,
    ) {
        let (response, painter) = ui.allocate_painter(ui.available_size(), Sense::click_and_drag());
        let rect = response.rect;
        self.rect = rect;
        let scene = document.scene();
        let frame = self.frame(scene, runner);
        if self.fit_pending {
            if let Some((min, max)) = Self::scene_box(scene, &frame.positions) {
                self.view.fit(rect, min, max);
            }
            self.fit_pending = false;
        }
        let editable = runner.simulation.is_none();

        // Zoom around the pointer, and pinch.
        if let Some(pointer) = response.hover_pos() {
            let (scroll, pinch) = ui.input(|i| (i.smooth_scroll_delta.y, i.zoom_delta()));
            let factor = f64::from(pinch) * (f64::from(scroll) * 0.0025).exp();
            if (factor - 1.0).abs() > 1e-6 {
                self.view.zoom_at(rect, pointer, factor);
            }
        }
        if response.dragged_by(egui::PointerButton::Secondary)
            || response.dragged_by(egui::PointerButton::Middle)
        {
            self.pan(response.drag_delta());
        }

        painter.rect_filled(rect, 0.0, Color32::from_rgb(250, 250, 247));
        self.draw_grid(&painter, rect);
        self.draw_scene(&painter, rect, scene, &frame, runner, *selection);
        self.draw_scale_bar(&painter, rect);

        if editable {
            self.edit(ui, &response, rect, document, &frame, selection);
        } else if response.clicked() {
            let pointer = response.interact_pointer_pos().unwrap_or(rect.center());
            *selection = self.hit(rect, document.scene(), &frame, pointer);
        } else if response.dragged_by(egui::PointerButton::Primary) {
            self.pan(response.drag_delta());
        }
        self.draw_drag_preview(&painter, rect, &frame);
    }

    fn pan(&mut self, delta: Vec2) {
        self.view.center -=
            DVec2::new(f64::from(delta.x), -f64::from(delta.y)) / self.view.pixels_per_metre;
    }

    fn frame(&self, scene: &Scene, runner: &Runner) -> Frame {
        if let Some(simulation) = &runner.simulation {
            let needs_acceleration = self.overlays.acceleration || self.overlays.force;
            Frame {
                positions: simulation.positions().to_vec(),
                velocities: simulation.velocities().to_vec(),
                accelerations: needs_acceleration.then(|| simulation.accelerations()),
            }
        } else {
            Frame {
                positions: scene
                    .particles
                    .iter()
                    .map(|p| p.position.to_dvec2())
                    .collect(),
                velocities: scene
                    .particles
                    .iter()
                    .map(Particle::initial_velocity)
                    .collect(),
                accelerations: None,
            }
        }
    }

    fn draw_grid(&self, painter: &egui::Painter, rect: Rect) {
        let spacing = nice_length(80.0 / self.view.pixels_per_metre);
        let (lo, hi) = (
            self.view.to_world(rect, rect.left_bottom()),
            self.view.to_world(rect, rect.right_top()),
        );
        let line = Stroke::new(1.0, Color32::from_gray(228));
        let axis = Stroke::new(1.2, Color32::from_gray(170));
        let font = FontId::proportional(11.0);
        let text = Color32::from_gray(120);
        let count = ((hi.x - lo.x) / spacing).ceil() + ((hi.y - lo.y) / spacing).ceil();
        if !(count.is_finite() && count < 400.0) {
            return;
        }
        let mut x = (lo.x / spacing).floor() * spacing;
        while x <= hi.x {
            let sx = self.view.to_screen(rect, DVec2::new(x, 0.0)).x;
            let stroke = if x.abs() < spacing * 1e-6 { axis } else { line };
            painter.line_segment(
                [Pos2::new(sx, rect.top()), Pos2::new(sx, rect.bottom())],
                stroke,
            );
            painter.text(
                Pos2::new(sx + 2.0, rect.bottom() - 2.0),
                Align2::LEFT_BOTTOM,
                format_metres(x, spacing),
                font.clone(),
                text,
            );
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
            painter.text(
                Pos2::new(rect.left() + 2.0, sy - 2.0),
                Align2::LEFT_BOTTOM,
                format_metres(y, spacing),
                font.clone(),
                text,
            );
            y += spacing;
        }
    }

    fn draw_scale_bar(&self, painter: &egui::Painter, rect: Rect) {
        let metres = nice_length(120.0 / self.view.pixels_per_metre);
        let length = (metres * self.view.pixels_per_metre) as f32;
        let start = Pos2::new(rect.right() - length - 20.0, rect.bottom() - 22.0);
        let end = start + Vec2::new(length, 0.0);
        let stroke = Stroke::new(2.0, Color32::from_gray(60));
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
            Color32::from_gray(60),
        );
    }

    #[expect(
        clippy::too_many_lines,
        reason = "one pass over every kind of object, in drawing order"
    )]
    fn draw_scene(
        &self,
        painter: &egui::Painter,
        rect: Rect,
        scene: &Scene,
        frame: &Frame,
        runner: &Runner,
        selection: Option<Selection>,
    ) {
        let view = &self.view;
        let screen = |p: DVec2| view.to_screen(rect, p);
        let scale = view.pixels_per_metre as f32;
        let highlight = Color32::from_rgb(255, 196, 0);
        if let Some(bounds) = scene.world.bounds {
            let box_rect =
                Rect::from_two_pos(screen(bounds.min.to_dvec2()), screen(bounds.max.to_dvec2()));
            painter.rect_stroke(
                box_rect,
                0.0,
                Stroke::new(2.0, Color32::from_gray(90)),
                egui::StrokeKind::Outside,
            );
        }
        for (i, ramp) in scene.ramps.iter().enumerate() {
            let (a, b) = (screen(ramp.from.to_dvec2()), screen(ramp.to.to_dvec2()));
            let width = (ramp.thickness as f32 * scale).max(2.0);
            let colour = Color32::from_rgb(150, 120, 90);
            if selection == Some(Selection::Ramp(i)) {
                painter.line_segment([a, b], Stroke::new(width + 6.0, highlight));
            }
            painter.line_segment([a, b], Stroke::new(width, colour));
            painter.circle_filled(a, width / 2.0, colour);
            painter.circle_filled(b, width / 2.0, colour);
            if self.overlays.names {
                painter.text(
                    a.lerp(b, 0.5) + Vec2::new(0.0, -width / 2.0 - 4.0),
                    Align2::CENTER_BOTTOM,
                    &ramp.name,
                    FontId::proportional(11.0),
                    Color32::from_gray(90),
                );
            }
        }
        if self.overlays.trails {
            for (i, trail) in runner.trails.iter().enumerate() {
                let colour = particle_colour(scene, i).gamma_multiply(0.45);
                let points: Vec<Pos2> = trail.iter().map(|p| screen(*p)).collect();
                if points.len() > 1 {
                    painter.add(Shape::line(points, PathStroke::new(1.5, colour)));
                }
            }
        }
        for (i, spring) in scene.springs.iter().enumerate() {
            let Some((a, b)) = spring_ends(scene, spring, &frame.positions) else {
                continue;
            };
            let selected = selection == Some(Selection::Spring(i));
            let stroke = Stroke::new(
                if selected { 3.0 } else { 1.6 },
                if selected {
                    highlight
                } else {
                    Color32::from_rgb(70, 70, 90)
                },
            );
            painter.add(Shape::line(coil(screen(a), screen(b)), stroke));
            for (e, p) in [(&spring.from, a), (&spring.to, b)] {
                if matches!(e, Endpoint::Point(_)) {
                    anchor(painter, screen(p));
                }
            }
        }
        let many = scene.particles.len() > 150;
        // A crowd is drawn as one mesh of plain discs: egui's anti-aliased, outlined
        // circles cost ten times as many triangles, which software rendering feels.
        let mut crowd = egui::Mesh::default();
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
            if selection == Some(Selection::Particle(i)) {
                painter.circle_filled(centre, radius + 4.0, highlight);
            }
            if many {
                disc(&mut crowd, centre, radius, colour);
            } else {
                painter.circle(
                    centre,
                    radius,
                    colour,
                    Stroke::new(1.0, colour.gamma_multiply(0.6)),
                );
            }
            if particle.fixed {
                anchor(painter, centre);
            }
            if self.overlays.names && (!many || selection == Some(Selection::Particle(i))) {
                painter.text(
                    centre + Vec2::new(radius + 3.0, -radius - 1.0),
                    Align2::LEFT_BOTTOM,
                    &particle.name,
                    FontId::proportional(12.0),
                    Color32::from_gray(40),
                );
            }
            if self.overlays.velocity && (!many || selection == Some(Selection::Particle(i))) {
                let v = frame.velocities[i];
                if v.length() > 0.0 {
                    arrow(
                        painter,
                        centre,
                        screen(position + v * VELOCITY_ARROW_SECONDS),
                        Color32::from_rgb(40, 150, 70),
                    );
                }
            }
            if let Some(accelerations) = &frame.accelerations {
                let a = accelerations[i];
                if self.overlays.acceleration && a.length() > 0.0 {
                    let tip =
                        position + a * (0.5 * VELOCITY_ARROW_SECONDS * VELOCITY_ARROW_SECONDS);
                    arrow(
                        painter,
                        centre,
                        screen(tip),
                        Color32::from_rgb(230, 130, 30),
                    );
                }
                if self.overlays.force && a.length() > 0.0 && !particle.fixed {
                    let force = a * particle.mass;
                    let pixels = (force.length().log10() + 2.0).clamp(0.5, 6.0) * 14.0;
                    let direction = force.normalize();
                    let tip =
                        centre + Vec2::new(direction.x as f32, -direction.y as f32) * pixels as f32;
                    arrow(painter, centre, tip, Color32::from_rgb(200, 40, 40));
                }
            }
        }
        painter.set(crowd_slot, Shape::mesh(crowd));
    }

    fn draw_drag_preview(&self, painter: &egui::Painter, rect: Rect, frame: &Frame) {
        let screen = |p: DVec2| self.view.to_screen(rect, p);
        match self.drag {
            Some(Drag::NewSpring { from, tip }) => {
                if let Some(&a) = frame.positions.get(from) {
                    painter.add(Shape::line(
                        coil(screen(a), screen(tip)),
                        Stroke::new(1.6, Color32::from_rgb(70, 70, 200)),
                    ));
                }
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

    /// The object under `pointer`, nearest first: particles, then ramps, then springs.
    fn hit(&self, rect: Rect, scene: &Scene, frame: &Frame, pointer: Pos2) -> Option<Selection> {
        let world = self.view.to_world(rect, pointer);
        let tolerance = 6.0 / self.view.pixels_per_metre;
        let particle = scene
            .particles
            .iter()
            .enumerate()
            .filter_map(|(i, p)| {
                frame
                    .positions
                    .get(i)
                    .map(|x| (i, x.distance(world) - p.radius))
            })
            .filter(|(_, d)| *d <= tolerance)
            .min_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((i, _)) = particle {
            return Some(Selection::Particle(i));
        }
        for (i, ramp) in scene.ramps.iter().enumerate() {
            if segment_distance(world, ramp.from.to_dvec2(), ramp.to.to_dvec2())
                <= ramp.thickness / 2.0 + tolerance
            {
                return Some(Selection::Ramp(i));
            }
        }
        for (i, spring) in scene.springs.iter().enumerate() {
            if let Some((a, b)) = spring_ends(scene, spring, &frame.positions)
                && segment_distance(world, a, b) <= 2.0 * tolerance
            {
                return Some(Selection::Spring(i));
            }
        }
        None
    }

    #[expect(
        clippy::too_many_lines,
        reason = "the four tools' gestures in one place"
    )]
    fn edit(
        &mut self,
        ui: &Ui,
        response: &egui::Response,
        rect: Rect,
        document: &mut Document,
        frame: &Frame,
        selection: &mut Option<Selection>,
    ) {
        let scene = document.scene().clone();
        // A drag whose object is gone (undone mid-drag, say) ends quietly.
        let gone = match self.drag {
            Some(
                Drag::Particle { index, .. }
                | Drag::Velocity { index }
                | Drag::NewSpring { from: index, .. },
            ) => index >= scene.particles.len(),
            Some(Drag::Ramp { index, .. } | Drag::RampEnd { index, .. }) => {
                index >= scene.ramps.len()
            }
            _ => false,
        };
        if gone {
            self.drag = None;
            document.end_gesture();
        }
        let pointer = ui
            .input(|i| i.pointer.interact_pos())
            .unwrap_or(rect.center());
        let world = self.view.to_world(rect, pointer);
        let tolerance = 8.0 / self.view.pixels_per_metre;

        if response.drag_started_by(egui::PointerButton::Primary) {
            let start = response
                .interact_pointer_pos()
                .map_or(world, |p| self.view.to_world(rect, p));
            let hit = self.hit(
                rect,
                &scene,
                frame,
                response.interact_pointer_pos().unwrap_or(pointer),
            );
            self.drag = match self.tool {
                Tool::Select => {
                    let velocity_tip = scene.particles.iter().enumerate().find(|(i, p)| {
                        !p.fixed
                            && self.overlays.velocity
                            && frame.positions[*i].distance(world) > p.radius
                            && (frame.positions[*i] + frame.velocities[*i] * VELOCITY_ARROW_SECONDS)
                                .distance(start)
                                <= tolerance
                    });
                    let ramp_end = scene.ramps.iter().enumerate().find_map(|(i, r)| {
                        if r.from.to_dvec2().distance(start) <= tolerance {
                            Some((i, false))
                        } else if r.to.to_dvec2().distance(start) <= tolerance {
                            Some((i, true))
                        } else {
                            None
                        }
                    });
                    if let Some((index, _)) = velocity_tip {
                        *selection = Some(Selection::Particle(index));
                        document.begin_gesture("set velocity");
                        Some(Drag::Velocity { index })
                    } else if let Some((index, to)) = ramp_end {
                        *selection = Some(Selection::Ramp(index));
                        document.begin_gesture("move ramp end");
                        Some(Drag::RampEnd { index, to })
                    } else {
                        match hit {
                            Some(Selection::Particle(index)) => {
                                *selection = hit;
                                document.begin_gesture("move particle");
                                Some(Drag::Particle {
                                    index,
                                    grab: start - frame.positions[index],
                                })
                            }
                            Some(Selection::Ramp(index)) => {
                                *selection = hit;
                                document.begin_gesture("move ramp");
                                Some(Drag::Ramp { index, last: start })
                            }
                            _ => Some(Drag::Pan),
                        }
                    }
                }
                Tool::Spring => match hit {
                    Some(Selection::Particle(from)) => Some(Drag::NewSpring { from, tip: start }),
                    _ => None,
                },
                Tool::Ramp => Some(Drag::NewRamp {
                    from: start,
                    to: start,
                }),
                Tool::Particle => None,
            };
        }

        if response.dragged_by(egui::PointerButton::Primary) {
            match &mut self.drag {
                Some(Drag::Pan) => self.pan(response.drag_delta()),
                Some(Drag::Particle { index, grab }) => {
                    let (index, target) = (*index, world - *grab);
                    document.apply("move particle", |scene| {
                        let particle = &mut scene.particles[index];
                        particle.position = keep_form(particle.position, target);
                    });
                }
                Some(Drag::Ramp { index, last }) => {
                    let (index, delta) = (*index, world - *last);
                    *last = world;
                    document.apply("move ramp", |scene| {
                        let ramp = &mut scene.ramps[index];
                        ramp.from = keep_form(ramp.from, ramp.from.to_dvec2() + delta);
                        ramp.to = keep_form(ramp.to, ramp.to.to_dvec2() + delta);
                    });
                }
                Some(Drag::RampEnd { index, to }) => {
                    let (index, to) = (*index, *to);
                    document.apply("move ramp end", |scene| {
                        let ramp = &mut scene.ramps[index];
                        let end = if to { &mut ramp.to } else { &mut ramp.from };
                        *end = keep_form(*end, world);
                    });
                }
                Some(Drag::Velocity { index }) => {
                    let index = *index;
                    let velocity = (world - frame.positions[index]) / VELOCITY_ARROW_SECONDS;
                    document.apply("set velocity", |scene| {
                        let particle = &mut scene.particles[index];
                        particle.velocity = keep_form(particle.velocity, velocity);
                    });
                }
                Some(Drag::NewSpring { tip, .. }) => *tip = world,
                Some(Drag::NewRamp { to, .. }) => *to = world,
                None => {}
            }
        }

        if response.drag_stopped_by(egui::PointerButton::Primary) {
            match self.drag.take() {
                Some(Drag::NewSpring { from, tip }) => {
                    let target = match self.hit(rect, &scene, frame, self.view.to_screen(rect, tip))
                    {
                        Some(Selection::Particle(to)) if to != from => {
                            Endpoint::Particle(scene.particles[to].name.clone())
                        }
                        Some(Selection::Particle(_)) => return,
                        _ => Endpoint::Point(tip.into()),
                    };
                    let natural_length = match &target {
                        Endpoint::Particle(name) => scene
                            .particle_index(name)
                            .map_or(1.0, |k| frame.positions[k].distance(frame.positions[from])),
                        Endpoint::Point(p) => p.to_dvec2().distance(frame.positions[from]),
                    };
                    let name = document.unused_name("s");
                    let spring = Spring::new(
                        name,
                        scene.particles[from].name.as_str(),
                        target,
                        10.0,
                        natural_length,
                    );
                    document.apply("add spring", |scene| scene.springs.push(spring));
                    *selection = Some(Selection::Spring(document.scene().springs.len() - 1));
                }
                Some(Drag::NewRamp { from, to }) => {
                    if from.distance(to) > tolerance {
                        let name = document.unused_name("r");
                        document.apply("add ramp", |scene| {
                            scene.ramps.push(Ramp::new(name, from, to));
                        });
                        *selection = Some(Selection::Ramp(document.scene().ramps.len() - 1));
                    }
                }
                _ => document.end_gesture(),
            }
        }

        if response.clicked() {
            let at = response.interact_pointer_pos().unwrap_or(pointer);
            match self.tool {
                Tool::Particle => {
                    let name = document.unused_name("p");
                    let position = self.view.to_world(rect, at);
                    let mut particle = Particle::new(name, 1.0).position(position);
                    particle.radius = nice_length(12.0 / self.view.pixels_per_metre).min(0.5);
                    document.apply("add particle", |scene| scene.particles.push(particle));
                    *selection = Some(Selection::Particle(document.scene().particles.len() - 1));
                }
                _ => *selection = self.hit(rect, &scene, frame, at),
            }
        }
    }
}

/// Where a spring's ends are, given the particles' positions.
fn spring_ends(scene: &Scene, spring: &Spring, positions: &[DVec2]) -> Option<(DVec2, DVec2)> {
    let end = |e: &Endpoint| match e {
        Endpoint::Particle(name) => scene
            .particle_index(name)
            .and_then(|k| positions.get(k).copied()),
        Endpoint::Point(p) => Some(p.to_dvec2()),
    };
    Some((end(&spring.from)?, end(&spring.to)?))
}

/// Adds a filled disc to `mesh` as a fan of triangles, finer for larger discs.
fn disc(mesh: &mut egui::Mesh, centre: Pos2, radius: f32, colour: Color32) {
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

/// A new value for a vector, in the form (Cartesian or polar) it was typed in.
pub fn keep_form(old: Vector, new: DVec2) -> Vector {
    match old {
        Vector::Cartesian(_) => Vector::Cartesian(new),
        Vector::Polar { .. } => Vector::Cartesian(new).to_polar(),
    }
}

fn particle_colour(scene: &Scene, i: usize) -> Color32 {
    let [r, g, b] = scene.particles[i]
        .color
        .unwrap_or_else(|| physics::Color::palette(i))
        .0;
    Color32::from_rgb(r, g, b)
}

/// The zig-zag of a spring from `a` to `b`, with a straight lead at each end.
fn coil(a: Pos2, b: Pos2) -> Vec<Pos2> {
    let (d, length) = (b - a, (b - a).length());
    if length < 1.0 {
        return vec![a, b];
    }
    let (along, across) = (d / length, Vec2::new(-d.y, d.x) / length);
    let width = (length * 0.08).clamp(3.0, 9.0);
    let turns = 12;
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
fn anchor(painter: &egui::Painter, at: Pos2) {
    let stroke = Stroke::new(1.5, Color32::from_gray(50));
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

fn arrow(painter: &egui::Painter, from: Pos2, to: Pos2, colour: Color32) {
    let d = to - from;
    if d.length() < 2.0 {
        return;
    }
    painter.arrow(from, d, Stroke::new(2.0, colour));
}

/// Distance from `p` to the segment `a`–`b`.
fn segment_distance(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let s = if ab.length_squared() > 0.0 {
        ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + ab * s)
}

/// The 1, 2 or 5 × 10ⁿ nearest above `length`.
pub fn nice_length(length: f64) -> f64 {
    let exponent = length.abs().max(1e-300).log10().floor();
    let base = 10_f64.powf(exponent);
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * base)
        .find(|v| *v >= length)
        .unwrap_or(10.0 * base)
}

/// A length in metres with no more decimals than the grid spacing needs.
fn format_metres(value: f64, spacing: f64) -> String {
    let decimals = (-spacing.log10().floor()).max(0.0) as usize;
    let value = if value.abs() < spacing * 1e-6 {
        0.0
    } else {
        value
    };
    format!("{value:.decimals$} m")
}
