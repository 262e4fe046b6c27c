//! Measuring instruments on the canvas, usable while a run plays as well as while the
//! scene is edited: a tape measure (the distance and direction between two points; an end
//! dropped on a particle stays on it as it moves), a protractor (the angle between two
//! arms from a vertex), a probe (the gravitational and electric field and potential at a
//! point, `physics::field_at`), and the field view (a grid of arrows of the particles'
//! electric or gravitational field, updated live). The stopwatch is `stopwatch.rs`.
//!
//! While an instrument is chosen, a drag on the canvas works it instead of the editing
//! tool. From the keyboard: **M**, **A** and **P** choose the tape, the protractor and
//! the probe (again to put it away); Enter lays the tape from the selected particle to
//! the next one, or the protractor's vertex on it and its arms to the next two (with
//! nothing selected, at the view's centre); Tab picks which of the tape's ends or the
//! protractor's points the arrow keys move, and the arrows move it, or the probe, by a
//! tenth of a grid step (Shift: a hundredth).

use egui::{Align2, Color32, FontId, Pos2, Rect, Stroke, Vec2};
use physics::{DVec2, Endpoint, Scene, field_at};

use super::View;
use crate::format;
use crate::i18n::{Arg, tr_with};

/// The instruments.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Instrument {
    /// Distance and direction between two points.
    Tape,
    /// The fields at a point.
    Probe,
    /// The angle between two arms from a vertex.
    Protractor,
}

impl Instrument {
    pub fn label(self) -> String {
        crate::i18n::tr(match self {
            Self::Tape => "instrument-tape",
            Self::Probe => "instrument-probe",
            Self::Protractor => "instrument-protractor",
        })
    }

    pub fn hint(self) -> String {
        crate::i18n::tr(match self {
            Self::Tape => "instrument-tape-hint",
            Self::Probe => "instrument-probe-hint",
            Self::Protractor => "instrument-protractor-hint",
        })
    }
}

/// Which field the field view draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FieldKind {
    /// The particles' electric field.
    Electric,
    /// The particles' gravitational attraction (the uniform field left out: it would
    /// draw every arrow the same).
    Gravitational,
}

/// One end of the tape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mark {
    /// A point of the world, metres.
    Point(DVec2),
    /// The centre of the particle with this index, wherever it is.
    Particle(usize),
}

impl Mark {
    fn at(self, positions: &[DVec2]) -> Option<DVec2> {
        match self {
            Self::Point(p) => Some(p),
            Self::Particle(i) => positions.get(i).copied(),
        }
    }

    /// This mark moved by `by` metres: a point of the world where it now is (an end
    /// moved off its particle lets go of it).
    fn moved(self, by: DVec2, positions: &[DVec2]) -> Self {
        Self::Point(self.at(positions).unwrap_or_default() + by)
    }
}

/// The instruments' state.
#[derive(Clone, Debug, Default)]
pub struct Instruments {
    /// The one that drags on the canvas work, if any.
    pub active: Option<Instrument>,
    /// The tape's two ends, once laid.
    pub tape: Option<(Mark, Mark)>,
    /// Where the probe is, metres.
    pub probe: Option<DVec2>,
    /// The field drawn as arrows, if any.
    pub field_view: Option<FieldKind>,
    /// The protractor's vertex and arms, once laid (the second arm after a second drag).
    pub protractor: Option<(Mark, Mark, Option<Mark>)>,
    /// Whether the drag in progress lays the protractor's second arm.
    second_arm: bool,
    /// The point of the tape or protractor the arrow keys move (Tab picks the next):
    /// 0 the tape's first end or the protractor's vertex, 1 and 2 the others.
    pub handle: usize,
    /// The readings drawn last frame: where each label is, and the full value it rounds
    /// (shown on hover, copied on a click).
    pub readings: Vec<(Rect, String)>,
}

impl Instruments {
    /// Whether the probe's reading is drawn beside it: while the probe is the instrument
    /// in hand. Put away (another tool, Escape), the probe keeps its place, marked by its
    /// cross alone, so that its box does not sit over what the next tool works on.
    pub fn shows_probe_reading(&self) -> bool {
        self.probe.is_some() && self.active == Some(Instrument::Probe)
    }

    /// Takes away the tape, the protractor and the probe (a measurement is of the scene
    /// it was taken in).
    pub fn clear(&mut self) {
        self.tape = None;
        self.protractor = None;
        self.probe = None;
    }

    /// Lays out the tape, protractor and probe `scene` keeps (`[instruments]`), or
    /// clears them.
    pub fn lay_out(&mut self, scene: &Scene) {
        self.clear();
        let Some(saved) = &scene.instruments else {
            return;
        };
        let mark = |end: &Endpoint| match end {
            Endpoint::Point(p) => Some(Mark::Point(p.to_dvec2())),
            Endpoint::Particle(name) => scene
                .particles
                .iter()
                .position(|p| p.name == *name)
                .map(Mark::Particle),
        };
        self.tape = saved
            .tape
            .as_ref()
            .and_then(|[a, b]| Some((mark(a)?, mark(b)?)));
        self.protractor = saved.protractor.as_ref().and_then(|p| {
            let second = p.second_arm.as_ref().and_then(mark);
            Some((mark(&p.vertex)?, mark(&p.arm)?, second))
        });
        self.probe = saved.probe;
    }

    /// The tape, protractor and probe as `scene` keeps them; the stopwatch's part is the
    /// app's to add. An end on a particle the scene no longer has is left out with its
    /// instrument.
    pub fn kept(&self, scene: &Scene) -> physics::Instruments {
        let end = |mark: Mark| match mark {
            Mark::Point(p) => Some(Endpoint::Point(physics::Vector::Cartesian(p))),
            Mark::Particle(i) => scene
                .particles
                .get(i)
                .map(|p| Endpoint::Particle(p.name.clone())),
        };
        physics::Instruments {
            tape: self.tape.and_then(|(a, b)| Some([end(a)?, end(b)?])),
            protractor: self.protractor.and_then(|(vertex, arm, second)| {
                Some(physics::Protractor {
                    vertex: end(vertex)?,
                    arm: end(arm)?,
                    second_arm: second.and_then(end),
                })
            }),
            probe: self.probe,
            stopwatch: None,
        }
    }
}

/// Whether `mark` was laid by hand where nothing fixes it: a point that is no fixed end of
/// a rod, string or spring and no ramp's end (those, and particles, are exact).
fn is_free(mark: Mark, scene: &Scene) -> bool {
    let Mark::Point(p) = mark else {
        return false;
    };
    let fixed =
        |end: &physics::Endpoint| matches!(end, physics::Endpoint::Point(q) if q.to_dvec2() == p);
    let on_link = scene.springs.iter().any(|s| fixed(&s.from) || fixed(&s.to))
        || scene.ties.iter().any(|t| fixed(&t.from) || fixed(&t.to));
    let on_ramp = scene
        .ramps
        .iter()
        .any(|r| r.from.to_dvec2() == p || r.to.to_dvec2() == p);
    !(on_link || on_ramp)
}

/// `value` with as many decimals as `spread` (its uncertainty, same unit) allows: the
/// last digit shown is the first uncertain one.
fn to_precision(value: f64, spread: f64) -> String {
    if !(spread.is_finite() && spread > 0.0) {
        return number(value);
    }
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a small count of decimals"
    )]
    let decimals = (-spread.log10()).ceil().clamp(0.0, 12.0) as usize;
    format::fixed(value, decimals)
}

/// The angle between the protractor's arms, degrees in 0..=180, once both are laid.
pub fn protractor_reading(
    protractor: (Mark, Mark, Option<Mark>),
    positions: &[DVec2],
) -> Option<f64> {
    let (vertex, a, b) = protractor;
    let o = vertex.at(positions)?;
    let (u, v) = (a.at(positions)? - o, b?.at(positions)? - o);
    if u.length_squared() == 0.0 || v.length_squared() == 0.0 {
        return None;
    }
    Some(u.perp_dot(v).atan2(u.dot(v)).abs().to_degrees())
}

/// Where the tape's two ends are, metres.
pub fn tape_ends(tape: (Mark, Mark), positions: &[DVec2]) -> Option<(DVec2, DVec2)> {
    Some((tape.0.at(positions)?, tape.1.at(positions)?))
}

/// What the tape reads: its length (m) and its direction (degrees from +x,
/// counter-clockwise), from its first end to its second.
pub fn tape_reading(tape: (Mark, Mark), positions: &[DVec2]) -> Option<(f64, f64)> {
    let (a, b) = (tape.0.at(positions)?, tape.1.at(positions)?);
    let d = b - a;
    Some((d.length(), d.y.atan2(d.x).to_degrees()))
}

/// A number for the probe's box: plain decimals where they read well, else `1.234e-11`
/// (a field's size spans many decades, and the box is drawn in the canvas's font).
fn number(value: f64) -> String {
    let size = value.abs();
    if size == 0.0 || (1e-4..1e6).contains(&size) || !size.is_finite() {
        format::number(value)
    } else {
        format!("{value:.4e}")
    }
}

/// The probe's readout as lines of text, in the user's language.
pub fn probe_lines(scene: &Scene, positions: &[DVec2], at: DVec2) -> Vec<String> {
    let f = field_at(scene, positions, at);
    let pair = |v: DVec2| format::pair_of(&number(v.x), &number(v.y));
    let vector = |v: DVec2, unit: &str| {
        tr_with(
            "instrument-probe-vector",
            &[
                ("vector", Arg::Text(&pair(v))),
                ("size", Arg::Text(&number(v.length()))),
                ("unit", Arg::Text(unit)),
            ],
        )
    };
    vec![
        tr_with("instrument-probe-at", &[("position", Arg::Text(&pair(at)))]),
        format!("g = {}", vector(f.gravity, "N/kg")),
        format!("E = {}", vector(f.electric, "N/C")),
        tr_with(
            "instrument-probe-gravitational-potential",
            &[("value", Arg::Text(&number(f.gravitational_potential)))],
        ),
        tr_with(
            "instrument-probe-electric-potential",
            &[("value", Arg::Text(&number(f.electric_potential)))],
        ),
    ]
}

impl Instruments {
    /// Draws the tape, the probe and the field view, in the colours of `palette`.
    pub fn draw(
        &mut self,
        painter: &egui::Painter,
        (view, palette): (&View, &super::Palette),
        rect: Rect,
        scene: &Scene,
        positions: &[DVec2],
    ) {
        let screen = |p: DVec2| view.to_screen(rect, p);
        let (tape_colour, probe_colour, angle_colour) =
            (palette.tape, palette.probe, palette.angle);
        self.readings.clear();
        if let Some(kind) = self.field_view {
            draw_field(painter, view, rect, scene, positions, kind);
        }
        if let Some(tape) = self.tape
            && let (Some(a), Some(b)) = (tape.0.at(positions), tape.1.at(positions))
            && let Some((length, angle)) = tape_reading(tape, positions)
        {
            let (pa, pb) = (screen(a), screen(b));
            painter.line_segment([pa, pb], Stroke::new(2.0, tape_colour));
            for end in [pa, pb] {
                painter.circle_stroke(end, 4.0, Stroke::new(1.5, tape_colour));
            }
            // A reading is as precise as its ends: a pixel for an end laid by hand, exact
            // for an end on a particle, a fixed point or a ramp's end.
            let pixel = 1.0 / view.pixels_per_metre;
            let loose = [tape.0, tape.1]
                .iter()
                .filter(|m| is_free(**m, scene))
                .count();
            let text = if loose == 0 {
                format!("{} m, {}°", number(length), number(angle))
            } else {
                #[expect(clippy::cast_precision_loss, reason = "one or two ends")]
                let spread = pixel * (loose as f64).sqrt();
                format!(
                    "{} m, {}°",
                    to_precision(length, spread),
                    to_precision(angle, (spread / length.max(spread)).to_degrees())
                )
            };
            let size = label_size(painter, &text);
            let centre = beside_tape((pa, pb), size, &occupied(view, rect, scene, positions));
            let at = label(
                painter,
                centre + Vec2::new(-size.x / 2.0, size.y / 2.0),
                &text,
                tape_colour,
            );
            self.readings.push((at, format!("{length} m, {angle}°")));
        }
        if let Some((vertex, a, b)) = self.protractor
            && let (Some(o), Some(pa)) = (vertex.at(positions), a.at(positions))
        {
            let stroke = Stroke::new(2.0, angle_colour);
            painter.line_segment([screen(o), screen(pa)], stroke);
            if let Some(pb) = b.and_then(|b| b.at(positions)) {
                painter.line_segment([screen(o), screen(pb)], stroke);
                if let Some(angle) = protractor_reading((vertex, a, b), positions) {
                    let arms = [o.distance(pa), o.distance(pb)];
                    let loose = [vertex, a]
                        .iter()
                        .chain(b.as_ref())
                        .any(|m| is_free(*m, scene));
                    let text = if loose {
                        let pixel = 1.0 / view.pixels_per_metre;
                        let spread =
                            (pixel / arms[0].max(pixel) + pixel / arms[1].max(pixel)).to_degrees();
                        format!("{}°", to_precision(angle, spread))
                    } else {
                        format!("{}°", number(angle))
                    };
                    let at = label(
                        painter,
                        screen(o) + Vec2::new(10.0, -10.0),
                        &text,
                        angle_colour,
                    );
                    self.readings.push((at, format!("{angle}°")));
                }
            }
        }
        if let Some(at) = self.probe {
            let p = screen(at);
            let cross = Stroke::new(1.5, probe_colour);
            painter.line_segment([p - Vec2::new(7.0, 0.0), p + Vec2::new(7.0, 0.0)], cross);
            painter.line_segment([p - Vec2::new(0.0, 7.0), p + Vec2::new(0.0, 7.0)], cross);
            if !self.shows_probe_reading() {
                return;
            }
            let lines = probe_lines(scene, positions, at);
            label(
                painter,
                p + Vec2::new(12.0, -10.0),
                &lines.join("\n"),
                probe_colour,
            );
        }
    }
}

/// Where a tape's reading of `size` goes: beside the tape, not on it — on either side
/// of its middle (or a third of the way along), the first place clear of `occupied`.
fn beside_tape((pa, pb): (Pos2, Pos2), size: Vec2, occupied: &[Rect]) -> Pos2 {
    let along = (pb - pa).normalized();
    let side = if along == Vec2::ZERO {
        Vec2::new(0.0, -1.0)
    } else {
        along.rot90()
    };
    // The box's half-extent across the tape, and a gap.
    let away = 6.0 + f32::midpoint(size.x * side.x.abs(), size.y * side.y.abs());
    let candidates: Vec<Pos2> = [0.5, 0.3, 0.7]
        .into_iter()
        .flat_map(|t| {
            let middle = pa.lerp(pb, t);
            [middle + side * away, middle - side * away]
        })
        .collect();
    clear_spot(&candidates, size, occupied)
}

/// The size of [`label`]'s box for `text`, points.
fn label_size(painter: &egui::Painter, text: &str) -> Vec2 {
    let galley =
        painter.layout_no_wrap(text.to_owned(), FontId::proportional(12.0), Color32::BLACK);
    galley.size() + Vec2::splat(6.0)
}

/// What a reading's label should not cover, on the screen: each particle's disc and the
/// scale bar in the canvas's lower right corner.
fn occupied(view: &View, rect: Rect, scene: &Scene, positions: &[DVec2]) -> Vec<Rect> {
    let mut boxes: Vec<Rect> = scene
        .particles
        .iter()
        .zip(positions)
        .map(|(particle, &x)| {
            let r = (particle.radius * view.pixels_per_metre) as f32;
            Rect::from_center_size(view.to_screen(rect, x), Vec2::splat(2.0 * r.max(2.0) + 4.0))
        })
        .collect();
    boxes.push(Rect::from_min_max(
        Pos2::new(rect.right() - 280.0, rect.bottom() - 50.0),
        rect.right_bottom(),
    ));
    boxes
}

/// The first of `candidates` (centres) where a box of `size` covers none of `occupied`,
/// or the first when none is clear.
fn clear_spot(candidates: &[Pos2], size: Vec2, occupied: &[Rect]) -> Pos2 {
    candidates
        .iter()
        .copied()
        .find(|&c| {
            let spot = Rect::from_center_size(c, size);
            !occupied.iter().any(|o| o.intersects(spot))
        })
        .or_else(|| candidates.first().copied())
        .unwrap_or_default()
}

/// Text on a pale box, so that it reads over the grid and the particles. Returns the box.
fn label(painter: &egui::Painter, at: Pos2, text: &str, colour: Color32) -> Rect {
    let galley = painter.layout_no_wrap(text.to_owned(), FontId::proportional(12.0), colour);
    let rect = Align2::LEFT_BOTTOM
        .anchor_size(at, galley.size())
        .expand(3.0);
    painter.rect_filled(
        rect,
        3.0,
        Color32::from_rgba_unmultiplied(255, 255, 255, 220),
    );
    painter.galley(rect.min + Vec2::splat(3.0), galley, colour);
    rect
}

/// Arrows of the field on a grid across the canvas: each points along the field, its
/// opacity says how strong it is against the strongest arrow drawn (on a logarithmic
/// scale over four decades), so weak regions stay visible beside strong ones.
fn draw_field(
    painter: &egui::Painter,
    view: &View,
    rect: Rect,
    scene: &Scene,
    positions: &[DVec2],
    kind: FieldKind,
) {
    const SPACING: f32 = 40.0;
    // The particles' field alone: the uniform field would draw every arrow the same.
    let uniform = scene.world.gravity.to_dvec2();
    let mut arrows = Vec::new();
    let columns = (rect.width() / SPACING).floor() as usize;
    let rows = (rect.height() / SPACING).floor() as usize;
    for row in 0..rows {
        for column in 0..columns {
            let at = rect.min + Vec2::new(column as f32 + 0.5, row as f32 + 0.5) * SPACING;
            let f = field_at(scene, positions, view.to_world(rect, at));
            let v = match kind {
                FieldKind::Electric => f.electric,
                FieldKind::Gravitational => f.gravity - uniform,
            };
            if v.length() > 0.0 && v.is_finite() {
                arrows.push((at, v));
            }
        }
    }
    let strongest = arrows.iter().map(|(_, v)| v.length()).fold(0.0, f64::max);
    let colour = match kind {
        FieldKind::Electric => Color32::from_rgb(170, 60, 60),
        FieldKind::Gravitational => Color32::from_rgb(60, 90, 170),
    };
    for (at, v) in arrows {
        let strength = (1.0 + (v.length() / strongest).log10() / 4.0).clamp(0.08, 1.0);
        let direction = v.normalize();
        // y up in the world, down on the screen.
        let step = Vec2::new(direction.x as f32, -direction.y as f32) * (SPACING * 0.35);
        let tint = colour.gamma_multiply(strength as f32);
        painter.arrow(at - step, step * 2.0, Stroke::new(1.5, tint));
    }
}

/// Whether the keys are the instruments': the canvas has the focus, or nothing has.
fn keys_are_free(ui: &egui::Ui, canvas_focused: bool) -> bool {
    canvas_focused || !ui.ctx().egui_wants_keyboard_input()
}

impl super::Canvas {
    /// The gestures of the chosen instrument this frame: a drag lays the tape (an end on
    /// a particle holds to it), a click or drag places the probe; the arrow keys move the
    /// probe and Enter stretches the tape from the selected particle to the next.
    pub(super) fn measure(
        &mut self,
        ui: &egui::Ui,
        response: &egui::Response,
        rect: Rect,
        scene: &Scene,
        positions: &[DVec2],
        selection: Option<super::Selection>,
    ) {
        let Some(instrument) = self.instruments.active else {
            return;
        };
        let pointer = response.interact_pointer_pos();
        let world = pointer.map(|p| self.view.to_world(rect, p));
        // An end laid on a particle holds to it; elsewhere it snaps to a fixed point or a
        // ramp's end near it (a pivot is met exactly), unless Alt is held.
        let free = ui.input(|i| i.modifiers.alt);
        let mark = |canvas: &Self, at: Pos2| match canvas.particle_at(rect, scene, positions, at) {
            Some(i) if !free => Mark::Particle(i),
            _ => Mark::Point(
                canvas
                    .anchor_near(rect, scene, at)
                    .filter(|_| !free)
                    .unwrap_or_else(|| canvas.view.to_world(rect, at)),
            ),
        };
        match instrument {
            Instrument::Tape => {
                if response.drag_started_by(egui::PointerButton::Primary) {
                    let start = ui.input(|i| i.pointer.press_origin()).or(pointer);
                    if let Some(start) = start {
                        let first = mark(self, start);
                        self.instruments.tape = Some((first, first));
                    }
                }
                if let (true, Some((first, _)), Some(world)) = (
                    response.dragged_by(egui::PointerButton::Primary),
                    self.instruments.tape,
                    world,
                ) {
                    self.instruments.tape = Some((first, Mark::Point(world)));
                }
                if response.drag_stopped_by(egui::PointerButton::Primary)
                    && let (Some((first, _)), Some(end)) = (self.instruments.tape, pointer)
                {
                    self.instruments.tape = Some((first, mark(self, end)));
                }
            }
            Instrument::Protractor => {
                if response.drag_started_by(egui::PointerButton::Primary) {
                    let start = ui.input(|i| i.pointer.press_origin()).or(pointer);
                    let second = matches!(self.instruments.protractor, Some((_, _, None)));
                    self.instruments.second_arm = second;
                    if !second && let Some(start) = start {
                        let vertex = mark(self, start);
                        self.instruments.protractor = Some((vertex, vertex, None));
                    }
                }
                let second = self.instruments.second_arm;
                let place = |protractor: (Mark, Mark, Option<Mark>), end: Mark| {
                    let (vertex, a, _) = protractor;
                    if second {
                        (vertex, a, Some(end))
                    } else {
                        (vertex, end, None)
                    }
                };
                if let (true, Some(protractor), Some(world)) = (
                    response.dragged_by(egui::PointerButton::Primary),
                    self.instruments.protractor,
                    world,
                ) {
                    self.instruments.protractor = Some(place(protractor, Mark::Point(world)));
                }
                if response.drag_stopped_by(egui::PointerButton::Primary)
                    && let (Some(protractor), Some(end)) = (self.instruments.protractor, pointer)
                {
                    self.instruments.protractor = Some(place(protractor, mark(self, end)));
                }
            }
            Instrument::Probe => self.place_probe(ui, response, world),
        }
        // Escape puts the instrument away, as it leaves any mode, where no text field
        // takes the key.
        let focused = response.has_focus();
        if keys_are_free(ui, focused) && ui.input(|i| i.key_pressed(egui::Key::Escape)) {
            self.instruments.active = None;
            return;
        }
        // The keyboard while the canvas has the focus, in the first pass only (a pass egui
        // discards sees the same keys again): Enter in a field elsewhere, which gives up
        // its focus as it is pressed, must not lay the tape.
        if focused && ui.ctx().current_pass_index() == 0 {
            self.instrument_keys(ui, (instrument, focused), positions, selection);
        }
    }

    /// The tape and the protractor from the keyboard. Enter lays the tape from the
    /// selected particle to the next (the protractor's vertex on it and its arms to the
    /// next two), or with no particle selected at the view's centre (the tape a grid step
    /// long; the protractor's arms a grid step right and up). Tab picks the point the
    /// arrow keys move (the tape's ends; the vertex and the arms) while the canvas has the
    /// focus; the arrows move it a tenth of a grid step
    /// a press (Shift: a hundredth); an end moved off a particle lets go of it.
    fn instrument_keys(
        &mut self,
        ui: &egui::Ui,
        (instrument, focused): (Instrument, bool),
        positions: &[DVec2],
        selection: Option<super::Selection>,
    ) {
        let points = match instrument {
            Instrument::Tape => 2,
            Instrument::Protractor => 3,
            Instrument::Probe => return,
        };
        let (enter, tab) = ui.input(|i| {
            (
                i.key_pressed(egui::Key::Enter),
                i.key_pressed(egui::Key::Tab),
            )
        });
        if enter {
            let grid = super::view::nice_length(80.0 / self.view.pixels_per_metre);
            let n = positions.len();
            let on = |k: usize| match selection {
                Some(super::Selection::Particle(i)) if n >= points => Mark::Particle((i + k) % n),
                _ => Mark::Point(self.view.center + [DVec2::ZERO, DVec2::X, DVec2::Y][k] * grid),
            };
            match instrument {
                Instrument::Tape => self.instruments.tape = Some((on(0), on(1))),
                _ => self.instruments.protractor = Some((on(0), on(1), Some(on(2)))),
            }
            self.instruments.handle = points - 1;
        }
        // Tab while the canvas has the focus (elsewhere it moves the focus).
        if tab && focused {
            self.instruments.handle = (self.instruments.handle + 1) % points;
        }
        let by = self.arrow_move(ui);
        if by == DVec2::ZERO {
            return;
        }
        let handle = self.instruments.handle;
        match instrument {
            Instrument::Tape => {
                if let Some((a, b)) = &mut self.instruments.tape {
                    let end = if handle == 0 { a } else { b };
                    *end = end.moved(by, positions);
                }
            }
            _ => {
                if let Some((vertex, a, b)) = &mut self.instruments.protractor {
                    match handle {
                        0 => *vertex = vertex.moved(by, positions),
                        1 => *a = a.moved(by, positions),
                        _ => {
                            if let Some(b) = b {
                                *b = b.moved(by, positions);
                            }
                        }
                    }
                }
            }
        }
    }

    /// Where the arrow keys pressed this frame move a point, metres: a tenth of a grid
    /// step a press (Shift: a hundredth), x right and y up.
    fn arrow_move(&self, ui: &egui::Ui) -> DVec2 {
        let step = super::view::nice_length(80.0 / self.view.pixels_per_metre)
            / if ui.input(|i| i.modifiers.shift) {
                100.0
            } else {
                10.0
            };
        let moved = ui.input(|i| {
            let mut d = DVec2::ZERO;
            for (key, by) in [
                (egui::Key::ArrowLeft, DVec2::NEG_X),
                (egui::Key::ArrowRight, DVec2::X),
                (egui::Key::ArrowUp, DVec2::Y),
                (egui::Key::ArrowDown, DVec2::NEG_Y),
            ] {
                if i.key_pressed(key) {
                    d += by;
                }
            }
            d
        });
        moved * step
    }

    /// The probe goes where the canvas is clicked or dragged, and a grid step (Shift: a
    /// tenth of one) along an arrow key.
    fn place_probe(&mut self, ui: &egui::Ui, response: &egui::Response, world: Option<DVec2>) {
        let keys_free = keys_are_free(ui, response.has_focus());
        if (response.clicked_by(egui::PointerButton::Primary)
            || response.dragged_by(egui::PointerButton::Primary))
            && let Some(world) = world
        {
            self.instruments.probe = Some(world);
        }
        if keys_free {
            let moved = self.arrow_move(ui);
            if moved != DVec2::ZERO {
                let from = self.instruments.probe.unwrap_or(self.view.center);
                self.instruments.probe = Some(from + moved);
            }
        }
    }

    /// The particle under the screen point `at`, if any.
    fn particle_at(
        &self,
        rect: Rect,
        scene: &Scene,
        positions: &[DVec2],
        at: Pos2,
    ) -> Option<usize> {
        let world = self.view.to_world(rect, at);
        let tolerance = 6.0 / self.view.pixels_per_metre;
        scene
            .particles
            .iter()
            .zip(positions)
            .enumerate()
            .filter(|(_, (p, x))| x.distance(world) <= p.radius + tolerance)
            .min_by(|(_, (_, a)), (_, (_, b))| a.distance(world).total_cmp(&b.distance(world)))
            .map(|(i, _)| i)
    }
}

#[cfg(test)]
mod precision_tests {
    use super::*;

    /// A reading keeps the decimals its uncertainty allows: a protractor laid by hand on
    /// a 60° pendulum reads 64.9°, not 64.9138°, when a pixel is half a degree.
    #[test]
    fn readings_keep_only_the_digits_their_placement_means() {
        assert_eq!(to_precision(64.913_84, 0.5), "64.9");
        assert_eq!(to_precision(64.913_84, 0.05), "64.91");
        assert_eq!(to_precision(64.913_84, 2.0), "65");
        assert_eq!(to_precision(1.234_567, 0.001), "1.235");
        let scene = Scene::new();
        assert!(is_free(Mark::Point(DVec2::new(0.3, 0.1)), &scene));
        assert!(!is_free(Mark::Particle(0), &scene));
    }
}

#[cfg(test)]
mod label_tests {
    use super::*;

    /// A label goes to the first candidate clear of what is drawn, and to the first
    /// when none is.
    #[test]
    fn a_label_takes_the_first_clear_spot() {
        let ball = Rect::from_center_size(Pos2::new(100.0, 100.0), Vec2::splat(20.0));
        let candidates = [Pos2::new(100.0, 95.0), Pos2::new(100.0, 140.0)];
        let size = Vec2::new(60.0, 16.0);
        assert_eq!(clear_spot(&candidates, size, &[ball]), candidates[1]);
        assert_eq!(clear_spot(&candidates, size, &[]), candidates[0]);
        let everywhere = Rect::from_min_max(Pos2::ZERO, Pos2::new(500.0, 500.0));
        assert_eq!(clear_spot(&candidates, size, &[everywhere]), candidates[0]);
    }
}
