//! The canvas from the keyboard, and as a screen reader hears it.
//!
//! The canvas takes the keyboard focus when clicked, or with Tab like any other control.
//! While it has the focus it keeps Tab and the arrow keys (Escape gives the focus back,
//! and Tab then moves on to the next control):
//! - **Tab** / **Shift+Tab** select the next / previous object: particles, springs, rods
//!   and strings, ramps, in the scene's order (also while a run plays, to read an
//!   object's live values in the inspector);
//! - **arrow keys** move the selected particle or ramp by one grid step, with **Shift**
//!   by a tenth of one (while editing);
//! - **Enter** adds an object of the current tool at the view's centre: a particle; a
//!   ramp; or a spring, rod or string from the selected particle to a fixed point at the
//!   view's centre (one grid spacing above the particle when it is at the centre).
//!
//! Its accessible description names what the scene holds and what is selected, where it
//! is and how fast it moves, so a screen reader says it when the canvas has the focus.

use std::fmt::Write as _;

use egui::{Key, Response, Ui};
use physics::{DVec2, Endpoint, Scene};

use super::tools::{add_box, add_link, add_polygon, add_ramp};
use super::view::nice_length;
use super::{Canvas, Frame, Selection, Tool};
use crate::document::Document;
use crate::edit::Edit;

/// Keys read this frame while the canvas has the focus.
#[derive(Clone, Copy, Debug, Default)]
struct Keys {
    /// +1 for Tab, −1 for Shift+Tab.
    cycle: i32,
    /// Grid steps, x right and y up.
    arrows: DVec2,
    fine: bool,
    enter: bool,
}

impl Keys {
    fn read(ui: &Ui) -> Self {
        ui.input(|i| {
            let count = |key| i32::from(i.key_pressed(key));
            let cycle = if i.key_pressed(Key::Tab) {
                if i.modifiers.shift { -1 } else { 1 }
            } else {
                0
            };
            let arrows = DVec2::new(
                f64::from(count(Key::ArrowRight) - count(Key::ArrowLeft)),
                f64::from(count(Key::ArrowUp) - count(Key::ArrowDown)),
            );
            Self {
                cycle,
                arrows,
                fine: i.modifiers.shift,
                enter: i.key_pressed(Key::Enter),
            }
        })
    }
}

impl Canvas {
    /// Focus, the keys of the module doc, and the accessible description.
    pub(super) fn keyboard(
        &mut self,
        ui: &Ui,
        response: &Response,
        document: &mut Document,
        frame: &Frame,
        selection: &mut Option<Selection>,
        editable: bool,
    ) {
        if response.clicked_by(egui::PointerButton::Primary) || response.drag_started() {
            response.request_focus();
        }
        // Made only when asked for (a screen reader listening, or the focus moving here).
        let (scene, selected) = (document.scene(), *selection);
        response.widget_info(|| {
            egui::WidgetInfo::labeled(egui::Role::Canvas, true, describe(scene, frame, selected))
        });
        if !response.has_focus() {
            return;
        }
        ui.memory_mut(|m| {
            m.set_focus_lock_filter(
                response.id,
                egui::EventFilter {
                    tab: true,
                    horizontal_arrows: true,
                    vertical_arrows: true,
                    escape: false,
                },
            );
        });
        // A pass egui discards (to lay out again) sees the same keys once more: they
        // act in the first pass only.
        // An instrument takes the keys while it is chosen (`instruments.rs`).
        if ui.ctx().current_pass_index() > 0 || self.instruments.active.is_some() {
            return;
        }
        let keys = Keys::read(ui);
        if keys.cycle != 0 {
            *selection = cycle(document.scene(), *selection, keys.cycle);
        }
        if !editable {
            return;
        }
        if keys.arrows != DVec2::ZERO {
            let step = self.snap_step() * if keys.fine { 0.1 } else { 1.0 };
            nudge(document, *selection, keys.arrows * step);
        }
        if keys.enter {
            self.add_at_centre(document, frame, selection);
        }
    }

    /// Enter: an object of the current tool at the view's centre.
    fn add_at_centre(
        &mut self,
        document: &mut Document,
        frame: &Frame,
        selection: &mut Option<Selection>,
    ) {
        let step = self.snap_step();
        let centre = (self.view.center / step).round() * step;
        let grid = nice_length(80.0 / self.view.pixels_per_metre);
        let added = match self.tool {
            Tool::Select => None,
            Tool::Particle => Some(self.add_particle(document, centre)),
            Tool::Ramp => Some(add_ramp(
                document,
                centre - DVec2::new(2.0 * grid, 0.0),
                centre + DVec2::new(2.0 * grid, 0.0),
            )),
            Tool::Box => Some(add_box(document, centre, DVec2::new(2.0 * grid, grid))),
            // Enter closes a polygon being drawn, or adds a triangle at the centre.
            Tool::Polygon => {
                let corners = if self.corners.len() >= 3 {
                    std::mem::take(&mut self.corners)
                } else {
                    [
                        DVec2::new(-grid, 0.0),
                        DVec2::new(grid, 0.0),
                        DVec2::new(0.0, grid),
                    ]
                    .map(|v| centre + v)
                    .to_vec()
                };
                add_polygon(document, &corners)
            }
            tool @ (Tool::Spring | Tool::Rod | Tool::String) => {
                let Some(Selection::Particle(from)) = *selection else {
                    return;
                };
                let at = frame.positions[from];
                let point = if at.distance(centre) < grid {
                    at + DVec2::new(0.0, grid)
                } else {
                    centre
                };
                add_link(
                    document,
                    tool,
                    from,
                    Endpoint::Point(point.into()),
                    at.distance(point),
                )
            }
        };
        if added.is_some() {
            *selection = added;
        }
    }
}

/// Every object of the scene, in the order Tab visits them.
fn objects(scene: &Scene) -> Vec<Selection> {
    let particles = (0..scene.particles.len()).map(Selection::Particle);
    let springs = (0..scene.springs.len()).map(Selection::Spring);
    let ties = (0..scene.ties.len()).map(Selection::Tie);
    let ramps = (0..scene.ramps.len()).map(Selection::Ramp);
    let bodies = (0..scene.bodies.len()).map(Selection::Body);
    particles
        .chain(springs)
        .chain(ties)
        .chain(ramps)
        .chain(bodies)
        .collect()
}

/// The object `by` places after (or before, when negative) `selection`, wrapping round;
/// the first (or last) when nothing is selected.
fn cycle(scene: &Scene, selection: Option<Selection>, by: i32) -> Option<Selection> {
    let all = objects(scene);
    let n = i64::try_from(all.len()).ok().filter(|&n| n > 0)?;
    let next = match selection.and_then(|s| all.iter().position(|&o| o == s)) {
        Some(k) => i64::try_from(k).unwrap_or(0) + i64::from(by),
        None if by > 0 => 0,
        None => -1,
    };
    all.get(usize::try_from(next.rem_euclid(n)).unwrap_or(0))
        .copied()
}

/// Moves the selected particle, ramp or body by `offset` metres, one undo step.
fn nudge(document: &mut Document, selection: Option<Selection>, offset: DVec2) {
    match selection {
        Some(Selection::Particle(i)) => document.apply(Edit::MoveParticle, |scene| {
            let particle = &mut scene.particles[i];
            particle.position =
                super::keep_form(particle.position, particle.position.to_dvec2() + offset);
        }),
        Some(Selection::Ramp(i)) => document.apply(Edit::MoveRamp, |scene| {
            let ramp = &mut scene.ramps[i];
            ramp.from = super::keep_form(ramp.from, ramp.from.to_dvec2() + offset);
            ramp.to = super::keep_form(ramp.to, ramp.to.to_dvec2() + offset);
        }),
        Some(Selection::Body(i)) => document.apply(Edit::MoveBody, |scene| {
            let body = &mut scene.bodies[i];
            body.position = super::keep_form(body.position, body.position.to_dvec2() + offset);
        }),
        _ => {}
    }
}

/// What a screen reader says of the canvas: what the scene holds, then the selection.
pub(super) fn describe(scene: &Scene, frame: &Frame, selection: Option<Selection>) -> String {
    let count =
        |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
    let mut text = format!(
        "Canvas: {}, {}, {}, {}.",
        count(scene.particles.len(), "particle", "particles"),
        count(scene.springs.len(), "spring", "springs"),
        count(scene.ties.len(), "rod or string", "rods and strings"),
        count(scene.ramps.len(), "ramp", "ramps"),
    );
    if !scene.bodies.is_empty() {
        text.pop();
        let _ = write!(text, ", {}.", count(scene.bodies.len(), "body", "bodies"));
    }
    let selected = match selection {
        Some(Selection::Particle(i)) => scene.particles.get(i).and_then(|p| {
            let (x, v) = (frame.positions.get(i)?, frame.velocities.get(i)?);
            Some(format!(
                "particle {} at ({:.2}, {:.2}) m moving {:.2} m/s",
                p.name,
                x.x,
                x.y,
                v.length()
            ))
        }),
        Some(Selection::Spring(i)) => scene.springs.get(i).map(|s| format!("spring {}", s.name)),
        Some(Selection::Tie(i)) => scene
            .ties
            .get(i)
            .map(|t| format!("{} {}", t.kind.as_str(), t.name)),
        Some(Selection::Ramp(i)) => scene.ramps.get(i).map(|r| format!("ramp {}", r.name)),
        Some(Selection::Body(i)) => scene.bodies.get(i).and_then(|b| {
            let outline = frame.outlines.get(i)?;
            let centre = outline.iter().copied().sum::<DVec2>() / outline.len().max(1) as f64;
            Some(format!(
                "body {} ({}) near ({:.2}, {:.2}) m",
                b.name,
                b.shape.as_str(),
                centre.x,
                centre.y
            ))
        }),
        Some(Selection::Joint(_) | Selection::Force(_)) | None => None,
    };
    if let Some(selected) = selected {
        text.push_str(" Selected: ");
        text.push_str(&selected);
        text.push('.');
    }
    text
}
