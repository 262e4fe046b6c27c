//! The editing gestures, one handler per tool: Select (move particles and ramps, drag a
//! ramp's end or a velocity arrow's tip, pan empty space), Particle (click to place),
//! Spring, Rod and String (drag from a particle to a particle or a fixed point), Ramp
//! (drag to draw).
//! A gesture starts where the pointer went down, not where egui noticed the drag, and
//! places points on a grid step chosen from the zoom (hold Alt to place freely).

use egui::{Pos2, Rect, Ui};
use physics::{DVec2, Endpoint, ObjectKind, Particle, Ramp, Scene, Spring, Tie, Vector};

use super::view::nice_length;
use super::{Canvas, Frame, Selection, Tool, VELOCITY_ARROW_SECONDS};
use crate::document::Document;
use crate::edit::Edit;

/// A drag in progress.
#[derive(Clone, Copy, Debug)]
pub(super) enum Drag {
    Pan,
    Particle {
        index: usize,
        grab: DVec2,
    },
    Ramp {
        index: usize,
        last: DVec2,
    },
    RampEnd {
        index: usize,
        to: bool,
    },
    Velocity {
        index: usize,
    },
    /// A new spring, rod or string (the tool says which).
    NewLink {
        from: usize,
        tip: DVec2,
        tool: Tool,
    },
    NewRamp {
        from: DVec2,
        to: DVec2,
    },
    /// A new box, from one corner to the other.
    NewBox {
        from: DVec2,
        to: DVec2,
    },
    Body {
        index: usize,
        grab: DVec2,
    },
    /// The objects selected together ([`Canvas::group`]), moved by whole snapping steps
    /// from where the pointer was last.
    Group {
        last: DVec2,
    },
    /// A box drawn from empty space with Shift held: what lies in it is selected.
    Select {
        from: DVec2,
        to: DVec2,
    },
}

impl Canvas {
    /// The object under `pointer`, nearest first: particles, then ramps, then springs,
    /// rods and strings.
    pub(super) fn hit(
        &self,
        rect: Rect,
        scene: &Scene,
        frame: &Frame,
        pointer: Pos2,
    ) -> Option<Selection> {
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
        for (i, ends) in frame.spring_ends.iter().enumerate() {
            if let Some((a, b)) = *ends
                && segment_distance(world, a, b) <= 2.0 * tolerance
            {
                return Some(Selection::Spring(i));
            }
        }
        for (i, ends) in frame.tie_ends.iter().enumerate() {
            if let Some((a, b)) = *ends
                && segment_distance(world, a, b) <= 2.0 * tolerance
            {
                return Some(Selection::Tie(i));
            }
        }
        // A body under the pointer, or within a few pixels of its outline; the last
        // drawn (on top) first.
        frame
            .outlines
            .iter()
            .enumerate()
            .rev()
            .find(|(_, outline)| outside_by(outline, world) <= tolerance)
            .map(|(i, _)| Selection::Body(i))
    }

    /// The editing gestures of this frame: a press starts the current tool's gesture,
    /// a drag moves it on, a release finishes it, a click places or selects.
    pub(super) fn edit(
        &mut self,
        ui: &Ui,
        response: &egui::Response,
        rect: Rect,
        document: &mut Document,
        frame: &Frame,
        selection: &mut Option<Selection>,
    ) {
        if self.drag.is_some_and(|drag| drag.is_gone(document.scene())) {
            // Its object is gone (undone mid-drag, say): the gesture ends quietly.
            self.drag = None;
            document.end_gesture();
        }
        let (pointer, origin, free, shift) = ui.input(|i| {
            (
                i.pointer.interact_pos(),
                i.pointer.press_origin(),
                i.modifiers.alt,
                i.modifiers.shift,
            )
        });
        let pointer = pointer.unwrap_or(rect.center());
        let world = self.view.to_world(rect, pointer);
        let step = (!free).then(|| self.snap_step());
        let snap = |p: DVec2| step.map_or(p, |step| (p / step).round() * step);

        if response.drag_started_by(egui::PointerButton::Primary) {
            // Where the pointer went down, not where it is once egui calls it a drag.
            let start = origin.unwrap_or(pointer);
            self.drag = match self.tool {
                Tool::Select => {
                    Some(self.press_select(rect, document, frame, (selection, shift), start))
                }
                tool @ (Tool::Spring | Tool::Rod | Tool::String) => {
                    match self.hit(rect, document.scene(), frame, start) {
                        Some(Selection::Particle(from)) => Some(Drag::NewLink {
                            from,
                            tip: self.view.to_world(rect, start),
                            tool,
                        }),
                        _ => None,
                    }
                }
                Tool::Ramp => {
                    let from = snap(self.view.to_world(rect, start));
                    Some(Drag::NewRamp { from, to: from })
                }
                Tool::Box => {
                    let from = snap(self.view.to_world(rect, start));
                    Some(Drag::NewBox { from, to: from })
                }
                Tool::Particle | Tool::Polygon => None,
            };
        }
        if response.dragged_by(egui::PointerButton::Primary) {
            self.drag_to(response.drag_delta(), world, (&snap, free), document, frame);
        }
        if response.drag_stopped_by(egui::PointerButton::Primary) {
            self.release(rect, document, frame, selection, free);
        }
        if response.clicked_by(egui::PointerButton::Primary) {
            let at = response.interact_pointer_pos().unwrap_or(pointer);
            match self.tool {
                Tool::Particle => {
                    let position = self.snapped(rect, document.scene(), at, free);
                    *selection = Some(self.add_particle(document, position));
                }
                Tool::Polygon => {
                    let corner = self.snapped(rect, document.scene(), at, free);
                    let closes = self.corners.len() >= 3
                        && self.view.to_screen(rect, self.corners[0]).distance(at) <= 8.0;
                    if closes {
                        let corners = std::mem::take(&mut self.corners);
                        *selection = add_polygon(document, &corners).or(*selection);
                    } else if self.corners.last() != Some(&corner) {
                        self.corners.push(corner);
                    }
                }
                Tool::Select if shift => {
                    let hit = self.hit(rect, document.scene(), frame, at);
                    self.toggle(hit, selection);
                }
                _ => {
                    self.group.clear();
                    *selection = self.hit(rect, document.scene(), frame, at);
                }
            }
        }
    }

    /// Shift+click: `hit` joins the objects selected together, or leaves them if it was
    /// among them; the selection (what the inspector shows) is the last one added. One
    /// object left is a plain selection.
    fn toggle(&mut self, hit: Option<Selection>, selection: &mut Option<Selection>) {
        let Some(hit) = hit else {
            return;
        };
        if self.group.is_empty() {
            self.group.extend(*selection);
        }
        if let Some(k) = self.group.iter().position(|s| *s == hit) {
            self.group.remove(k);
            *selection = self.group.last().copied();
        } else {
            self.group.push(hit);
            *selection = Some(hit);
        }
        if self.group.len() < 2 {
            self.group.clear();
        }
    }

    /// The snapping grid: a tenth of the drawn grid's spacing.
    pub(super) fn snap_step(&self) -> f64 {
        nice_length(80.0 / self.view.pixels_per_metre) / 10.0
    }

    /// The fixed point of the scene nearest the screen point `at`, within 10 pixels: a
    /// rod's, string's or spring's fixed end, or a ramp's end. What a point laid by hand
    /// snaps to before the grid (Alt frees it), so a pivot is met exactly.
    pub(super) fn anchor_near(
        &self,
        rect: Rect,
        scene: &physics::Scene,
        at: Pos2,
    ) -> Option<DVec2> {
        let world = self.view.to_world(rect, at);
        let reach = 10.0 / self.view.pixels_per_metre;
        let fixed = |end: &Endpoint| match end {
            Endpoint::Point(p) => Some(p.to_dvec2()),
            Endpoint::Particle(_) => None,
        };
        let links = scene
            .springs
            .iter()
            .flat_map(|s| [fixed(&s.from), fixed(&s.to)])
            .chain(
                scene
                    .ties
                    .iter()
                    .flat_map(|t| [fixed(&t.from), fixed(&t.to)]),
            )
            .flatten();
        let ramps = scene
            .ramps
            .iter()
            .flat_map(|r| [r.from.to_dvec2(), r.to.to_dvec2()]);
        links
            .chain(ramps)
            .map(|p| (p.distance(world), p))
            .filter(|&(d, _)| d <= reach)
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, p)| p)
    }

    /// Where a point laid by hand at the screen point `at` goes: on a fixed point or a
    /// ramp's end near it, else on the grid; where the pointer is with Alt (`free`).
    pub(super) fn snapped(
        &self,
        rect: Rect,
        scene: &physics::Scene,
        at: Pos2,
        free: bool,
    ) -> DVec2 {
        let world = self.view.to_world(rect, at);
        if free {
            return world;
        }
        self.anchor_near(rect, scene, at).unwrap_or_else(|| {
            let step = self.snap_step();
            (world / step).round() * step
        })
    }

    /// Select: a press on a velocity arrow's tip, a ramp's end, a particle or a ramp
    /// grabs it; on empty space it pans.
    fn press_select(
        &mut self,
        rect: Rect,
        document: &mut Document,
        frame: &Frame,
        (selection, shift): (&mut Option<Selection>, bool),
        start: Pos2,
    ) -> Drag {
        let scene = document.scene();
        let at = self.view.to_world(rect, start);
        let tolerance = 8.0 / self.view.pixels_per_metre;
        let velocity_tip = scene.particles.iter().enumerate().find(|(i, p)| {
            !p.fixed
                && self.overlays.velocity
                && frame.positions[*i].distance(at) > p.radius
                && (frame.positions[*i] + frame.velocities[*i] * VELOCITY_ARROW_SECONDS)
                    .distance(at)
                    <= tolerance
        });
        let ramp_end = scene.ramps.iter().enumerate().find_map(|(i, r)| {
            if r.from.to_dvec2().distance(at) <= tolerance {
                Some((i, false))
            } else if r.to.to_dvec2().distance(at) <= tolerance {
                Some((i, true))
            } else {
                None
            }
        });
        let (drag, edit, selected) = if let Some((index, _)) = velocity_tip {
            (
                Drag::Velocity { index },
                Edit::SetVelocity,
                Selection::Particle(index),
            )
        } else if let Some((index, to)) = ramp_end {
            (
                Drag::RampEnd { index, to },
                Edit::MoveRampEnd,
                Selection::Ramp(index),
            )
        } else {
            let hit = self.hit(rect, scene, frame, start);
            if let Some(grabbed) = hit.filter(|hit| {
                self.group.contains(hit)
                    && matches!(
                        hit,
                        Selection::Particle(_) | Selection::Ramp(_) | Selection::Body(_)
                    )
            }) {
                *selection = Some(grabbed);
                document.begin_gesture(Edit::MoveGroup);
                return Drag::Group { last: at };
            }
            if hit.is_none() && shift {
                return Drag::Select { from: at, to: at };
            }
            self.group.clear();
            match hit {
                Some(Selection::Particle(index)) => (
                    Drag::Particle {
                        index,
                        grab: at - frame.positions[index],
                    },
                    Edit::MoveParticle,
                    Selection::Particle(index),
                ),
                Some(Selection::Ramp(index)) => (
                    Drag::Ramp { index, last: at },
                    Edit::MoveRamp,
                    Selection::Ramp(index),
                ),
                Some(Selection::Body(index)) => (
                    Drag::Body {
                        index,
                        grab: at - scene.bodies[index].position.to_dvec2(),
                    },
                    Edit::MoveBody,
                    Selection::Body(index),
                ),
                _ => return Drag::Pan,
            }
        };
        *selection = Some(selected);
        document.begin_gesture(edit);
        drag
    }

    /// The gesture follows the pointer, at `world`; `snap` puts a point on the grid, and
    /// `free` (Alt held) says it does not.
    fn drag_to(
        &mut self,
        delta: egui::Vec2,
        world: DVec2,
        (snap, free): (&dyn Fn(DVec2) -> DVec2, bool),
        document: &mut Document,
        frame: &Frame,
    ) {
        match &mut self.drag {
            Some(Drag::Pan) => self.pan(delta),
            Some(Drag::Particle { index, grab }) => {
                let (index, target) = (*index, snap(world - *grab));
                document.apply(Edit::MoveParticle, |scene| {
                    let particle = &mut scene.particles[index];
                    particle.position = keep_form(particle.position, target);
                });
            }
            Some(Drag::Ramp { index, last }) => {
                let (index, delta) = (*index, world - *last);
                *last = world;
                document.apply(Edit::MoveRamp, |scene| {
                    let ramp = &mut scene.ramps[index];
                    ramp.from = keep_form(ramp.from, ramp.from.to_dvec2() + delta);
                    ramp.to = keep_form(ramp.to, ramp.to.to_dvec2() + delta);
                });
            }
            Some(Drag::RampEnd { index, to }) => {
                let (index, to) = (*index, *to);
                document.apply(Edit::MoveRampEnd, |scene| {
                    let ramp = &mut scene.ramps[index];
                    let end = if to { &mut ramp.to } else { &mut ramp.from };
                    *end = keep_form(*end, snap(world));
                });
            }
            Some(Drag::Velocity { index }) => {
                let index = *index;
                let velocity = (world - frame.positions[index]) / VELOCITY_ARROW_SECONDS;
                document.apply(Edit::SetVelocity, |scene| {
                    let particle = &mut scene.particles[index];
                    particle.velocity = if free {
                        keep_form(particle.velocity, velocity)
                    } else {
                        launched(velocity)
                    };
                });
            }
            Some(Drag::NewLink { tip, .. }) => *tip = world,
            Some(Drag::NewRamp { to, .. } | Drag::NewBox { to, .. }) => *to = snap(world),
            Some(Drag::Body { index, grab }) => {
                let (index, target) = (*index, snap(world - *grab));
                document.apply(Edit::MoveBody, |scene| {
                    let body = &mut scene.bodies[index];
                    body.position = keep_form(body.position, target);
                });
            }
            Some(Drag::Group { last }) => {
                let delta = snap(world) - snap(*last);
                *last = world;
                if delta != DVec2::ZERO {
                    let group = &self.group;
                    document.apply(Edit::MoveGroup, |scene| move_group(scene, group, delta));
                }
            }
            Some(Drag::Select { to, .. }) => *to = world,
            None => {}
        }
    }

    /// The gesture ends: a new spring, rod, string or ramp is added, a move becomes one
    /// undo step.
    fn release(
        &mut self,
        rect: Rect,
        document: &mut Document,
        frame: &Frame,
        selection: &mut Option<Selection>,
        free: bool,
    ) {
        let tolerance = 8.0 / self.view.pixels_per_metre;
        match self.drag.take() {
            Some(Drag::NewLink { from, tip, tool }) => {
                let scene = document.scene();
                let at = self.view.to_screen(rect, tip);
                let target = match self.hit(rect, scene, frame, at) {
                    Some(Selection::Particle(to)) if to != from => {
                        Endpoint::Particle(scene.particles[to].name.clone())
                    }
                    Some(Selection::Particle(_)) => return,
                    _ => Endpoint::Point(self.snapped(rect, scene, at, free).into()),
                };
                let length = match &target {
                    Endpoint::Particle(name) => scene
                        .particle_index(name)
                        .map_or(1.0, |k| frame.positions[k].distance(frame.positions[from])),
                    Endpoint::Point(p) => p.to_dvec2().distance(frame.positions[from]),
                };
                if let Some(added) = add_link(document, tool, from, target, length) {
                    *selection = Some(added);
                }
            }
            Some(Drag::NewRamp { from, to }) => {
                if from.distance(to) > tolerance {
                    *selection = Some(add_ramp(document, from, to));
                }
            }
            Some(Drag::NewBox { from, to }) => {
                let size = (to - from).abs();
                if size.min_element() > tolerance {
                    *selection = Some(add_box(document, from.midpoint(to), size));
                }
            }
            Some(Drag::Select { from, to }) => {
                self.group = in_box(document.scene(), frame, (from.min(to), from.max(to)));
                *selection = self.group.first().copied();
                if self.group.len() < 2 {
                    self.group.clear();
                }
            }
            _ => document.end_gesture(),
        }
    }
}

impl Canvas {
    /// Adds a particle of 1 kg at `position`, its radius about 12 pixels at this zoom
    /// (at most 0.5 m).
    pub(super) fn add_particle(&self, document: &mut Document, position: DVec2) -> Selection {
        let name = document.unused_name("p");
        let mut particle = Particle::new(name, 1.0).position(position);
        particle.radius = nice_length(12.0 / self.view.pixels_per_metre).min(0.5);
        document.apply(Edit::Add(ObjectKind::Particle), |scene| {
            scene.particles.push(particle);
        });
        Selection::Particle(document.scene().particles.len() - 1)
    }
}

/// Adds the spring, rod or string of `tool` from particle `from` to `target`, `length`
/// long (a spring's natural length; a rod or string holds the scene as drawn). A rod or
/// string of no length is not added.
pub(super) fn add_link(
    document: &mut Document,
    tool: Tool,
    from: usize,
    target: Endpoint,
    length: f64,
) -> Option<Selection> {
    let from = document.scene().particles[from].name.clone();
    let from = from.as_str();
    if tool == Tool::Spring {
        let spring = Spring::new(document.unused_name("s"), from, target, 10.0, length);
        document.apply(Edit::Add(ObjectKind::Spring), |scene| {
            scene.springs.push(spring);
        });
        return Some(Selection::Spring(document.scene().springs.len() - 1));
    }
    if length <= 0.0 {
        return None;
    }
    let (tie, edit) = if tool == Tool::Rod {
        (
            Tie::rod(document.unused_name("rod"), from, target, length),
            Edit::Add(ObjectKind::Rod),
        )
    } else {
        let name = document.unused_name("string");
        (
            Tie::string(name, from, target, length),
            Edit::Add(ObjectKind::String),
        )
    };
    document.apply(edit, |scene| scene.ties.push(tie));
    Some(Selection::Tie(document.scene().ties.len() - 1))
}

/// Adds a ramp from `from` to `to`.
/// Adds a polygon of 1 kg whose outline is the convex hull of `corners` (world), its
/// centroid where the hull's is; `None` when they enclose no area.
pub(super) fn add_polygon(document: &mut Document, corners: &[DVec2]) -> Option<Selection> {
    let hull = convex_hull(corners);
    let moments = physics::moments(&hull);
    if hull.len() < 3 || moments.area <= 0.0 {
        return None;
    }
    let local: Vec<DVec2> = hull.iter().map(|&v| v - moments.centroid).collect();
    let name = document.unused_name("polygon");
    let body = physics::Body::polygon(name, local, 1.0).position(moments.centroid);
    document.apply(Edit::Add(ObjectKind::Body), |scene| scene.bodies.push(body));
    Some(Selection::Body(document.scene().bodies.len() - 1))
}

/// The convex hull of `points`, counter-clockwise, without points on its edges (Andrew's
/// monotone chain).
pub(super) fn convex_hull(points: &[DVec2]) -> Vec<DVec2> {
    let mut sorted = points.to_vec();
    sorted.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    sorted.dedup();
    if sorted.len() < 3 {
        return sorted;
    }
    let turn = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    let mut hull: Vec<DVec2> = Vec::with_capacity(2 * sorted.len());
    for pass in 0..2 {
        let start = hull.len();
        let points: Box<dyn Iterator<Item = &DVec2>> = if pass == 0 {
            Box::new(sorted.iter())
        } else {
            Box::new(sorted.iter().rev())
        };
        for &p in points {
            while hull.len() >= start + 2
                && turn(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

/// Adds a box of 1 kg, `size` metres wide and high, centred at `at`.
pub(super) fn add_box(document: &mut Document, at: DVec2, size: DVec2) -> Selection {
    let name = document.unused_name("box");
    let body = physics::Body::rectangle(name, size.x, size.y, 1.0).position(at);
    document.apply(Edit::Add(ObjectKind::Body), |scene| scene.bodies.push(body));
    Selection::Body(document.scene().bodies.len() - 1)
}

pub(super) fn add_ramp(document: &mut Document, from: DVec2, to: DVec2) -> Selection {
    let name = document.unused_name("r");
    document.apply(Edit::Add(ObjectKind::Ramp), |scene| {
        scene.ramps.push(Ramp::new(name, from, to));
    });
    Selection::Ramp(document.scene().ramps.len() - 1)
}

impl Drag {
    /// Whether the object this drag holds no longer exists.
    fn is_gone(self, scene: &Scene) -> bool {
        match self {
            Self::Particle { index, .. }
            | Self::Velocity { index }
            | Self::NewLink { from: index, .. } => index >= scene.particles.len(),
            Self::Ramp { index, .. } | Self::RampEnd { index, .. } => index >= scene.ramps.len(),
            Self::Body { index, .. } => index >= scene.bodies.len(),
            Self::Pan
            | Self::NewRamp { .. }
            | Self::NewBox { .. }
            | Self::Group { .. }
            | Self::Select { .. } => false,
        }
    }
}

/// Moves the particles and ramps of `group` by `delta` metres (the springs, rods and
/// strings among them go with their particles); objects no longer in the scene are
/// passed over.
fn move_group(scene: &mut Scene, group: &[Selection], delta: DVec2) {
    for selected in group {
        match *selected {
            Selection::Particle(i) => {
                if let Some(particle) = scene.particles.get_mut(i) {
                    particle.position =
                        keep_form(particle.position, particle.position.to_dvec2() + delta);
                }
            }
            Selection::Ramp(i) => {
                if let Some(ramp) = scene.ramps.get_mut(i) {
                    ramp.from = keep_form(ramp.from, ramp.from.to_dvec2() + delta);
                    ramp.to = keep_form(ramp.to, ramp.to.to_dvec2() + delta);
                }
            }
            Selection::Body(i) => {
                if let Some(body) = scene.bodies.get_mut(i) {
                    body.position = keep_form(body.position, body.position.to_dvec2() + delta);
                }
            }
            Selection::Spring(_)
            | Selection::Tie(_)
            | Selection::Joint(_)
            | Selection::Force(_) => {}
        }
    }
}

/// What lies wholly in the box from `min` to `max` (world): particles by their centres,
/// ramps by both ends, springs, rods and strings by both ends, in that order.
fn in_box(scene: &Scene, frame: &Frame, (min, max): (DVec2, DVec2)) -> Vec<Selection> {
    let inside = |p: DVec2| p.cmpge(min).all() && p.cmple(max).all();
    let both = |ends: &Option<(DVec2, DVec2)>| ends.is_some_and(|(a, b)| inside(a) && inside(b));
    let particles = (0..scene.particles.len())
        .filter(|&i| frame.positions.get(i).is_some_and(|p| inside(*p)))
        .map(Selection::Particle);
    let ramps = (0..scene.ramps.len())
        .filter(|&i| inside(scene.ramps[i].from.to_dvec2()) && inside(scene.ramps[i].to.to_dvec2()))
        .map(Selection::Ramp);
    let springs = (0..frame.spring_ends.len())
        .filter(|&i| both(&frame.spring_ends[i]))
        .map(Selection::Spring);
    let ties = (0..frame.tie_ends.len())
        .filter(|&i| both(&frame.tie_ends[i]))
        .map(Selection::Tie);
    let bodies = (0..frame.outlines.len())
        .filter(|&i| frame.outlines[i].iter().all(|&p| inside(p)))
        .map(Selection::Body);
    particles
        .chain(ramps)
        .chain(springs)
        .chain(ties)
        .chain(bodies)
        .collect()
}

/// A new value for a vector, in the form (Cartesian or polar) it was typed in.
pub fn keep_form(old: Vector, new: DVec2) -> Vector {
    match old {
        Vector::Cartesian(_) => Vector::Cartesian(new),
        Vector::Polar { .. } => Vector::Cartesian(new).to_polar(),
    }
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

/// A velocity drawn by its arrow's tip, as a launcher sets it: in polar form, the speed
/// to the nearest [`LAUNCH_SPEED_STEP`] and the angle to the nearest degree (Alt held
/// sets it freely).
fn launched(velocity: DVec2) -> physics::Vector {
    let speed = (velocity.length() / LAUNCH_SPEED_STEP).round() * LAUNCH_SPEED_STEP;
    let angle = velocity.y.atan2(velocity.x).to_degrees().round();
    // −180° and 180° are one direction: written as 180.
    let angle = if angle <= -180.0 { 180.0 } else { angle };
    physics::Vector::polar(speed, if speed > 0.0 { angle } else { 0.0 })
}

/// The speed a launched velocity snaps to, m/s.
pub const LAUNCH_SPEED_STEP: f64 = 0.5;

/// How far `point` lies outside the convex outline (counter-clockwise), metres: the
/// largest distance past any edge's line; 0 or less inside.
fn outside_by(outline: &[DVec2], point: DVec2) -> f64 {
    (0..outline.len())
        .filter_map(|k| {
            let (a, b) = (outline[k], outline[(k + 1) % outline.len()]);
            let normal = DVec2::new(b.y - a.y, a.x - b.x).try_normalize()?;
            Some((point - a).dot(normal))
        })
        .fold(f64::NEG_INFINITY, f64::max)
}
