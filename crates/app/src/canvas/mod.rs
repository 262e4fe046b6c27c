//! The world on screen: metres, y up. Zoom (wheel or pinch, around the pointer) and pan,
//! a grid with labelled metre ticks and a scale bar; particles, springs as coils, ramps
//! as thick segments, fixed points as anchors; velocity, acceleration and force arrows
//! and trails. While no simulation runs the scene can be edited here with the tools.
//!
//! In parts: `view.rs` (the transform, fitting and following), `draw.rs` (painting),
//! `tools.rs` (one gesture handler per tool). This file holds the canvas's state and its
//! frame: what to show, where the camera goes, then drawing and input.

// World coordinates are f64 metres, screen coordinates f32 points: the conversions
// narrow on purpose, and pixel counts are small positive numbers.
#![expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "f64 world to f32 screen, see above"
)]

mod draw;
mod instruments;
mod keyboard;
mod palette;
mod shapes;
mod tools;
mod view;

use egui::{Pos2, Rect, Sense, Ui, Vec2};
use physics::{DVec2, Endpoint, Follow, Particle, Scene};

use crate::document::Document;
use crate::i18n::{Arg, tr_with};
use crate::recording::Recording;
use crate::run_loop::Runner;
pub(crate) use draw::object_rgb;
pub use instruments::{
    FieldKind, Instrument, Instruments, Mark, probe_lines, protractor_reading, tape_ends,
    tape_reading,
};
pub use palette::{Palette, contrast};
use tools::Drag;
pub use tools::keep_form;
pub use view::{View, nice_length};

/// What a click or drag on the canvas does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tool {
    Select,
    Particle,
    Spring,
    Rod,
    String,
    Ramp,
    /// A rigid box, drawn corner to corner.
    Box,
    /// A rigid convex polygon, its corners clicked one by one.
    Polygon,
}

impl Tool {
    pub const ALL: [Self; 8] = [
        Self::Select,
        Self::Particle,
        Self::Spring,
        Self::Rod,
        Self::String,
        Self::Ramp,
        Self::Box,
        Self::Polygon,
    ];

    /// The tool's name in the app's language.
    pub fn label(self) -> String {
        crate::i18n::tr(match self {
            Self::Select => "tool-select",
            Self::Particle => "tool-particle",
            Self::Spring => "tool-spring",
            Self::Rod => "tool-rod",
            Self::String => "tool-string",
            Self::Ramp => "tool-ramp",
            Self::Box => "tool-box",
            Self::Polygon => "tool-polygon",
        })
    }

    pub fn hint(self) -> String {
        crate::i18n::tr(match self {
            Self::Select => "tool-select-hint",
            Self::Particle => "tool-particle-hint",
            Self::Spring => "tool-spring-hint",
            Self::Rod => "tool-rod-hint",
            Self::String => "tool-string-hint",
            Self::Ramp => "tool-ramp-hint",
            Self::Box => "tool-box-hint",
            Self::Polygon => "tool-polygon-hint",
        })
    }
}

/// The selected object: the scene's own identity of an object ([`physics::ObjectId`]),
/// so a section, an edit and a selection name it alike. The canvas selects particles,
/// springs, rods and strings, ramps and bodies.
pub type Selection = physics::ObjectId;

/// Whether the canvas selects `id`: its particles, springs, rods and strings, ramps and
/// bodies; a joint or a force is reached through what it holds or acts on.
pub const fn selectable(id: Selection) -> bool {
    !matches!(id, Selection::Joint(_) | Selection::Force(_))
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

/// Seconds of motion a velocity arrow shows: its tip is where the particle would be.
pub const VELOCITY_ARROW_SECONDS: f64 = 0.5;

/// Seconds of recent motion that Fit keeps in view.
const RECENT_SECONDS: f64 = 2.0;

/// How the view is to be set at the next frame, once the canvas's size is known.
#[derive(Clone, Debug, PartialEq)]
enum Framing {
    /// Everything in the scene, with the recent paths.
    Fit,
    /// The scene file's `[view]`: a centre and a width, each defaulting to the fit's.
    Scene(physics::View),
    /// The world box that was in view (centre, size in metres), fitted to the canvas
    /// as it settles after a change of layout (projector mode on).
    Keep(DVec2, DVec2),
    /// Exactly this view, as the canvas settles (projector mode off: the view before).
    Restore(View),
}

/// A canvas shrunk below this fraction of the size its scale was set for rescales the
/// view to keep showing all it showed; less shrinking keeps the scale.
const SHRINK_RESCALES: f32 = 0.97;

pub struct Canvas {
    pub view: View,
    pub tool: Tool,
    pub overlays: Overlays,
    /// What the camera keeps in view while a run plays.
    pub follow: Option<Follow>,
    /// Where the followed particle was at the last frame.
    followed: Option<DVec2>,
    drag: Option<Drag>,
    /// The objects selected together (Shift+click, or a box drawn with Shift held), two
    /// or more, the selection among them; empty otherwise. Moved, deleted, copied and
    /// duplicated together.
    pub group: Vec<Selection>,
    /// The corners of a polygon being drawn (the Polygon tool), in the world.
    pub corners: Vec<DVec2>,
    framing: Option<Framing>,
    /// The canvas rectangle of the last frame, for fitting from menus.
    pub rect: Rect,
    /// The canvas's size when the scale last followed it (see [`Self::ui`]).
    scaled_for: Vec2,
    /// The view before projector mode, given back when it ends.
    before_projector: Option<View>,
    /// The tape measure, the probe and the field view.
    pub instruments: Instruments,
    /// The canvas's widget id, once drawn: the keys it keeps while focused.
    pub id: Option<egui::Id>,
    /// The colours of this frame (the usual ones or high contrast, as the theme is).
    pub palette: Palette,
    /// A reading's full value just copied to the clipboard, for the status line to say.
    pub copied: Option<String>,
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
            follow: None,
            followed: None,
            drag: None,
            group: Vec::new(),
            corners: Vec::new(),
            framing: Some(Framing::Fit),
            rect: Rect::from_min_size(Pos2::ZERO, Vec2::new(800.0, 600.0)),
            scaled_for: Vec2::ZERO,
            before_projector: None,
            instruments: Instruments::default(),
            id: None,
            palette: Palette::USUAL,
            copied: None,
        }
    }
}

/// Positions and velocities to draw: the simulation's while one exists, else the scene's.
struct Frame {
    positions: Vec<DVec2>,
    velocities: Vec<DVec2>,
    accelerations: Option<Vec<DVec2>>,
    /// Where each spring's ends are, and each rod's or string's: `None` for an end
    /// naming no particle. Found once a frame, every name looked up in one table (a
    /// search by name for each end cost springs × particles comparisons a frame).
    spring_ends: Vec<Option<(DVec2, DVec2)>>,
    tie_ends: Vec<Option<(DVec2, DVec2)>>,
    /// Each particle's orientation, degrees counter-clockwise (drawn for those that
    /// turn).
    angles: Vec<f64>,
    /// Each rigid body's outline in the world, counter-clockwise.
    outlines: Vec<Vec<DVec2>>,
    /// Each pin's and hinge's point in the world.
    joints: Vec<DVec2>,
    /// The selected body's free-body diagram: each force (N) and where it acts.
    free_body: Vec<(DVec2, physics::Applied)>,
}

impl Frame {
    /// A frame of `positions` and `velocities` of `scene`'s particles, its ends found.
    fn new(
        scene: &Scene,
        positions: Vec<DVec2>,
        velocities: Vec<DVec2>,
        accelerations: Option<Vec<DVec2>>,
    ) -> Self {
        let names = scene.particle_indices();
        let ends = |from, to| draw::ends(&names, from, to, &positions);
        let spring_ends = scene.springs.iter().map(|s| ends(&s.from, &s.to)).collect();
        let tie_ends = scene.ties.iter().map(|t| ends(&t.from, &t.to)).collect();
        Self {
            positions,
            velocities,
            accelerations,
            spring_ends,
            tie_ends,
            angles: scene.particles.iter().map(|p| p.angle).collect(),
            outlines: scene
                .bodies
                .iter()
                .map(physics::Body::world_outline)
                .collect(),
            joints: scene.joints.iter().map(|j| j.at.to_dvec2()).collect(),
            free_body: Vec::new(),
        }
    }
}

impl Canvas {
    /// Projector mode switched on (`true`) or off: the view shows the same world box
    /// in the new layout, and leaving gives back the view from before.
    pub fn projector(&mut self, on: bool) {
        if on {
            let size = DVec2::new(f64::from(self.rect.width()), f64::from(self.rect.height()))
                / self.view.pixels_per_metre;
            self.before_projector = Some(self.view);
            self.framing = Some(Framing::Keep(self.view.center, size));
        } else if let Some(view) = self.before_projector.take() {
            self.framing = Some(Framing::Restore(view));
        }
    }

    /// Fits the view to the scene and the recent paths at the next frame.
    pub fn request_fit(&mut self) {
        self.framing = Some(Framing::Fit);
    }

    /// Frames a scene that was just opened as its file says (`[view]`), or fits it.
    pub fn open(&mut self, scene: &Scene) {
        self.instruments.lay_out(scene);
        self.follow = scene.view.as_ref().and_then(|v| v.follow.clone());
        // The toggles as the scene was saved; those it does not say, as they were.
        if let Some(view) = &scene.view {
            let o = &mut self.overlays;
            for (saved, toggle) in [
                (view.trails, &mut o.trails),
                (view.velocity, &mut o.velocity),
                (view.acceleration, &mut o.acceleration),
                (view.force, &mut o.force),
                (view.names, &mut o.names),
            ] {
                if let Some(on) = saved {
                    *toggle = on;
                }
            }
        }
        self.framing = Some(scene.view.clone().map_or(Framing::Fit, Framing::Scene));
    }

    /// The camera and the toggles as a scene's `[view]`, to save with it: the centre on a
    /// step of a hundredth of the grid, the width to four digits, so the file reads
    /// cleanly.
    pub fn scene_view(&self) -> physics::View {
        let step = nice_length(80.0 / self.view.pixels_per_metre) / 100.0;
        let width = f64::from(self.rect.width()) / self.view.pixels_per_metre;
        let digits = 10_f64.powf(width.log10().floor() - 3.0);
        let o = &self.overlays;
        physics::View {
            center: Some((self.view.center / step).round() * step),
            width: Some((width / digits).round() * digits),
            follow: self.follow.clone(),
            trails: Some(o.trails),
            velocity: Some(o.velocity),
            acceleration: Some(o.acceleration),
            force: Some(o.force),
            names: Some(o.names),
        }
    }

    /// The box around everything in the scene, and around `paths` too.
    pub fn scene_box(
        scene: &Scene,
        positions: &[DVec2],
        paths: impl IntoIterator<Item = DVec2>,
    ) -> Option<(DVec2, DVec2)> {
        let mut points: Vec<DVec2> = paths.into_iter().collect();
        for (p, x) in scene.particles.iter().zip(positions) {
            points.push(*x - DVec2::splat(p.radius));
            points.push(*x + DVec2::splat(p.radius));
        }
        for ramp in &scene.ramps {
            points.push(ramp.from.to_dvec2());
            points.push(ramp.to.to_dvec2());
        }
        points.extend(scene.bodies.iter().flat_map(physics::Body::world_outline));
        let spring_ends = scene.springs.iter().flat_map(|s| [&s.from, &s.to]);
        let tie_ends = scene.ties.iter().flat_map(|t| [&t.from, &t.to]);
        for end in spring_ends.chain(tie_ends) {
            if let Endpoint::Point(p) = end {
                points.push(p.to_dvec2());
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
                .filter(|p| p.is_finite())
                .fold((first, first), |(lo, hi), p| (lo.min(*p), hi.max(*p))),
        )
    }

    /// Draws the canvas and handles its input.
    pub fn ui(
        &mut self,
        ui: &mut Ui,
        (document, paths): (&mut Document, &[&[DVec2]]),
        runner: &Runner,
        selection: &mut Option<Selection>,
    ) {
        let (response, painter) = ui.allocate_painter(ui.available_size(), Sense::click_and_drag());
        let rect = response.rect;
        self.id = Some(response.id);
        crate::landmarks::mark(ui, crate::landmarks::Region::Canvas, response.id);
        self.palette = Palette::of(ui);
        // A canvas that shrinks (a panel shown, projector mode left, a resized window)
        // still shows all it showed: the scale follows the dimension that shrank most.
        // By a few points only (a panel widened by its numbers when Play fills them in),
        // it keeps its scale: a view that jumps on Play is what a class notices.
        if self.scaled_for.x > 0.0 && self.scaled_for.y > 0.0 {
            let ratio = (rect.size() / self.scaled_for).min_elem();
            if ratio < SHRINK_RESCALES {
                self.view.pixels_per_metre *= f64::from(ratio);
                self.scaled_for = rect.size();
            } else if ratio > 1.0 {
                self.scaled_for = self.scaled_for.max(rect.size());
            }
        } else {
            self.scaled_for = rect.size();
        }
        let settled = (rect.size() - self.rect.size()).length() <= 0.5;
        self.rect = rect;
        let mut frame = self.frame(document.scene(), runner);
        if let Some(Selection::Body(i)) = *selection {
            frame.free_body = free_body(document.scene(), runner, i);
        }
        self.place_camera(document.scene(), &frame, runner, settled);
        let editable = runner.is_editing();

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

        painter.rect_filled(rect, 0.0, self.palette.background);
        self.draw_grid(&painter, rect);
        self.draw_paths(&painter, rect, paths);
        let hovered = response
            .hover_pos()
            .and_then(|p| self.hit(rect, document.scene(), &frame, p));
        self.draw_scene(
            &painter,
            rect,
            document.scene(),
            &frame,
            runner,
            *selection,
            hovered,
        );
        self.instruments.draw(
            &painter,
            (&self.view, &self.palette),
            rect,
            document.scene(),
            &frame.positions,
        );
        self.draw_scale_bar(&painter, rect);
        // A reading shows the digits its ends mean; the full value is a hover or a click
        // (to the clipboard) away.
        for (k, (at, full)) in self.instruments.readings.iter().enumerate() {
            let reading = ui
                .interact(*at, response.id.with(("reading", k)), Sense::click())
                .on_hover_text(tr_with("reading-full", &[("value", Arg::Text(full))]));
            if reading.clicked() {
                ui.ctx().copy_text(full.clone());
                self.copied = Some(full.clone());
            }
        }

        self.keyboard(ui, &response, document, &frame, selection, editable);
        if response.has_focus() {
            // Visible focus: the keyboard acts on the canvas (Escape leaves it).
            painter.rect_stroke(
                rect,
                0.0,
                self.palette.focus_stroke(),
                egui::StrokeKind::Inside,
            );
        }
        if self.instruments.active.is_some() {
            self.measure(
                ui,
                &response,
                rect,
                document.scene(),
                &frame.positions,
                *selection,
            );
        } else if editable {
            self.edit(ui, &response, rect, document, &frame, selection);
        } else if response.clicked_by(egui::PointerButton::Primary) {
            let pointer = response.interact_pointer_pos().unwrap_or(rect.center());
            *selection = self.hit(rect, document.scene(), &frame, pointer);
        } else if response.dragged_by(egui::PointerButton::Primary) {
            self.pan(response.drag_delta());
            // Panning by hand stops following.
            self.follow = None;
        }
        self.draw_drag_preview(&painter, rect, &frame);
    }

    /// Sets the view as asked (fit, the scene's framing), then follows while running.
    fn place_camera(&mut self, scene: &Scene, frame: &Frame, runner: &Runner, settled: bool) {
        let rect = self.rect;
        if let Some(framing @ (Framing::Keep(..) | Framing::Restore(_))) = &self.framing {
            // Set again every frame until the canvas stops changing size: a change of
            // layout takes a frame or two to settle, and the scale must not follow it.
            match *framing {
                Framing::Keep(center, size) => {
                    self.view.center = center;
                    self.view.pixels_per_metre =
                        (f64::from(rect.width()) / size.x).min(f64::from(rect.height()) / size.y);
                }
                Framing::Restore(view) => self.view = view,
                _ => {}
            }
            self.scaled_for = rect.size();
            if settled {
                self.framing = None;
            }
        } else if let Some(framing) = self.framing.take() {
            // The recent paths: the trails when drawn, and the recording's last seconds.
            let recent = match (runner.simulation(), &runner.recording) {
                (Some(_), Some(recording)) => recording.recent_positions(RECENT_SECONDS),
                _ => Vec::new(),
            };
            let paths = runner.trails.iter().flatten().copied().chain(recent);
            if let Some((min, max)) = Self::scene_box(scene, &frame.positions, paths) {
                self.view.fit(rect, min, max);
            }
            if let Framing::Scene(wanted) = framing {
                if let Some(center) = wanted.center {
                    self.view.center = center;
                }
                if let Some(width) = wanted.width {
                    self.view.pixels_per_metre = f64::from(rect.width()) / width;
                }
            }
            self.scaled_for = rect.size();
        }
        if runner.is_editing() {
            self.followed = None;
            return;
        }
        match &self.follow {
            Some(Follow::Particle(name)) => {
                if let Some(&position) = scene
                    .particle_index(name)
                    .and_then(|i| frame.positions.get(i))
                {
                    // The camera moves with the particle, and closes any offset smoothly.
                    let moved = self.followed.map_or(DVec2::ZERO, |last| position - last);
                    self.view.center += moved;
                    self.view.glide_to(position, self.view.pixels_per_metre);
                    self.followed = Some(position).filter(|p| p.is_finite());
                }
            }
            Some(Follow::All) => {
                if let Some((min, max)) = frame
                    .positions
                    .iter()
                    .zip(&scene.particles)
                    .map(|(x, p)| (*x - DVec2::splat(p.radius), *x + DVec2::splat(p.radius)))
                    .reduce(|(a, b), (c, d)| (a.min(c), b.max(d)))
                {
                    self.view.keep_in_view(rect, min, max);
                }
            }
            None => {}
        }
    }

    fn pan(&mut self, delta: Vec2) {
        self.view.center -=
            DVec2::new(f64::from(delta.x), -f64::from(delta.y)) / self.view.pixels_per_metre;
    }

    /// What to draw: the run's state, the last good state of a run that failed, or the
    /// scene as edited.
    fn frame(&self, scene: &Scene, runner: &Runner) -> Frame {
        if runner.failure.is_some()
            && let Some((positions, velocities)) =
                runner.recording.as_ref().and_then(Recording::last_state)
        {
            return Frame::new(scene, positions, velocities, None);
        }
        if let Some(simulation) = runner.simulation() {
            let needs_acceleration = self.overlays.acceleration || self.overlays.force;
            let mut frame = Frame::new(
                scene,
                simulation.positions().to_vec(),
                simulation.velocities().to_vec(),
                needs_acceleration.then(|| simulation.accelerations()),
            );
            if simulation.turns() {
                frame.angles = simulation.angles();
            }
            frame.outlines = (0..simulation.body_names().len())
                .map(|i| simulation.body_outline(i))
                .collect();
            frame.joints = (0..simulation.joint_names().len())
                .map(|j| simulation.joint(j).at)
                .collect();
            frame
        } else {
            Frame::new(
                scene,
                scene
                    .particles
                    .iter()
                    .map(|p| p.position.to_dvec2())
                    .collect(),
                scene
                    .particles
                    .iter()
                    .map(Particle::initial_velocity)
                    .collect(),
                None,
            )
        }
    }
}

/// Body `i`'s forces, each with the point it acts at (world): from the run while there is
/// one, else from the scene as edited (only body `i` is looked at: no validation of the
/// whole scene every frame).
fn free_body(scene: &Scene, runner: &Runner, i: usize) -> Vec<(DVec2, physics::Applied)> {
    if let Some(simulation) = runner.simulation() {
        if i >= simulation.body_names().len() {
            return Vec::new();
        }
        let centroid = simulation.body(i).position;
        return simulation
            .body_forces(i)
            .into_iter()
            .map(|f| (centroid + f.arm, f))
            .collect();
    }
    let Some(body) = scene.bodies.get(i) else {
        return Vec::new();
    };
    let centroid = body.position.to_dvec2();
    scene
        .body_forces(i)
        .into_iter()
        .map(|f| (centroid + f.arm, f))
        .collect()
}
