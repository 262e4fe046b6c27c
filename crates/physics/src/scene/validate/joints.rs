//! The rules of `[[pin]]` and `[[hinge]]`: each holds bodies of the scene that can move, a
//! hinge two different ones, at a point that is where its anchors say, with a motor whose
//! torque is finite.

use super::{Checker, Rule};
use crate::scene::error::Section;
use crate::scene::{Joint, JointKind, Motor, in_frame, say};

/// How far a joint's anchor may lie from its point `at` at the start, metres: a saved
/// state's rounding (the joint is held to 1e-12 m), never a joint a person placed apart.
const ANCHOR_SLACK: f64 = 1e-6;

impl Checker<'_> {
    pub(super) fn is_joint(&self, name: &str) -> bool {
        self.scene.joints.iter().any(|j| j.name == name)
    }

    pub(super) fn joints(&mut self) {
        for (i, joint) in self.scene.joints.iter().enumerate() {
            let s = Section::Joint(i);
            if joint.is_pulley() {
                self.pulley(s, joint);
                continue;
            }
            let b = self.joined(s, joint, joint.body.as_str(), field_b(joint));
            let a = match &joint.kind {
                JointKind::Pin | JointKind::Pulley { .. } => None,
                JointKind::Hinge { a, .. } => {
                    let found = self.joined(s, joint, a, "a");
                    if a == &joint.body {
                        self.report(s, "b", &say("scene-hinge-itself", &[("body", a)]));
                    }
                    found
                }
            };
            if let Some(reason) = self.scene.joints[..i]
                .iter()
                .find(|other| same_joint(other, joint))
                .map(|other| say("scene-joint-twice", &[("other", &other.name)]))
            {
                self.report(s, field_b(joint), &reason);
            }
            let fixed = |k: Option<usize>| k.is_none_or(|k| self.scene.bodies[k].fixed);
            if b.is_some() && fixed(b) && fixed(a) {
                self.report(s, field_b(joint), &say("scene-joint-fixed", &[]));
            }
            self.vector(s, "at", joint.at);
            self.anchor(s, "anchor", joint, b, joint.anchor);
            if let JointKind::Hinge { anchor_a, .. } = &joint.kind {
                self.anchor(s, "anchor_a", joint, a, *anchor_a);
            }
            if let Some(reference) = joint.reference_angle {
                self.number(s, "reference_angle", Rule::Finite, reference);
            }
            if let Some(limits) = joint.limits {
                self.limits(s, joint, limits, (a, b));
            }
            match joint.motor {
                None => {}
                Some(Motor::Torque(torque)) => self.number(s, "motor", Rule::Finite, torque),
                Some(Motor::Spin { spin, max_torque }) => {
                    self.number(s, "motor", Rule::Finite, spin);
                    self.number(s, "motor", Rule::Positive, max_torque);
                }
            }
        }
    }

    /// The index of the body `name` a joint holds; reported when there is none (a
    /// particle, or nothing of that name).
    fn joined(
        &mut self,
        s: Section,
        joint: &Joint,
        name: &str,
        field: &'static str,
    ) -> Option<usize> {
        let found = self.scene.bodies.iter().position(|b| b.name == name);
        if found.is_none() {
            let id = if self.particle_index(name).is_some() {
                "scene-joint-particle"
            } else {
                "scene-joint-no-body"
            };
            let kind = joint.kind_str();
            self.report(s, field, &say(id, &[("name", name), ("kind", kind)]));
        }
        found
    }

    /// A pulley hangs two different bodies, at least one free to move, from a wheel of
    /// positive radius and no negative mass, each end outside the wheel.
    fn pulley(&mut self, s: Section, joint: &Joint) {
        let JointKind::Pulley {
            a,
            radius,
            mass,
            inertia,
            spin,
            length,
        } = &joint.kind
        else {
            return;
        };
        let found_b = self.joined(s, joint, &joint.body, "b");
        let found_a = self.joined(s, joint, a, "a");
        if a == &joint.body {
            self.report(s, "b", &say("scene-pulley-same", &[("body", a)]));
        }
        self.vector(s, "position", joint.at);
        self.number(s, "radius", Rule::Positive, *radius);
        self.number(s, "mass", Rule::NonNegative, *mass);
        self.number(s, "inertia", Rule::NonNegative, *inertia);
        self.number(s, "spin", Rule::Finite, *spin);
        if let Some(length) = length {
            self.number(s, "length", Rule::Positive, *length);
        }
        let (Some(b), Some(a)) = (found_b, found_a) else {
            return;
        };
        let bodies = &self.scene.bodies;
        if bodies[a].fixed && bodies[b].fixed {
            self.report(s, "b", &say("scene-joint-fixed", &[]));
        }
        let centre = joint.at.to_dvec2();
        for (field, body) in [("a", a), ("b", b)] {
            let distance = bodies[body].position.to_dvec2().distance(centre);
            let reach = bodies[body]
                .local_outline()
                .iter()
                .fold(0.0, |r: f64, v| r.max(v.length()));
            if distance.is_finite() && radius.is_finite() && distance <= *radius + reach {
                let name = bodies[body].name.as_str();
                self.report(s, field, &say("scene-pulley-inside", &[("body", name)]));
            }
        }
    }

    /// Limits must be finite, the lower below the upper, and hold the joint's angle at
    /// the start.
    fn limits(
        &mut self,
        s: Section,
        joint: &Joint,
        (lower, upper): (f64, f64),
        (a, b): (Option<usize>, Option<usize>),
    ) {
        if !(lower.is_finite() && upper.is_finite() && lower < upper) {
            let (lower, upper) = (lower.to_string(), upper.to_string());
            let words = [("lower", lower.as_str()), ("upper", upper.as_str())];
            self.report(s, "limits", &say("scene-limits-order", &words));
            return;
        }
        let Some(b) = b else {
            return;
        };
        let angle_a = match (&joint.kind, a) {
            (JointKind::Hinge { .. }, Some(a)) => self.scene.bodies[a].angle,
            (JointKind::Hinge { .. }, None) => return,
            (JointKind::Pin | JointKind::Pulley { .. }, _) => 0.0,
        };
        let start = self.scene.bodies[b].angle - angle_a;
        let angle = start - joint.reference_angle.unwrap_or(start);
        // A saved state may stand on its limit to rounding.
        let slack = 1e-9 * (1.0 + start.abs());
        if angle < lower - slack || angle > upper + slack {
            let angle = angle.to_string();
            self.report(
                s,
                "limits",
                &say("scene-limits-start", &[("angle", &angle)]),
            );
        }
    }

    /// An anchor given in the file must lie at the joint's point.
    fn anchor(
        &mut self,
        s: Section,
        field: &'static str,
        joint: &Joint,
        body: Option<usize>,
        anchor: Option<glam::DVec2>,
    ) {
        let (Some(anchor), Some(body)) = (anchor, body) else {
            return;
        };
        let body = &self.scene.bodies[body];
        let at = joint.at.to_dvec2();
        let there = in_frame(at, body.position.to_dvec2(), body.angle);
        if !anchor.is_finite() || !at.is_finite() {
            self.report(
                s,
                field,
                &say("scene-vector-not-finite", &[("field", field)]),
            );
        } else if there.distance(anchor) > ANCHOR_SLACK {
            self.report(s, field, &say("scene-joint-anchor", &[("field", field)]));
        }
    }
}

/// The key naming the body a joint holds: a pin's `body`, a hinge's `b`.
fn field_b(joint: &Joint) -> &'static str {
    match joint.kind {
        JointKind::Pin => "body",
        JointKind::Hinge { .. } | JointKind::Pulley { .. } => "b",
    }
}

/// Two joints holding the same bodies (in either order) at the same point.
fn same_joint(one: &Joint, other: &Joint) -> bool {
    fn bodies(j: &Joint) -> [Option<&str>; 2] {
        let mut pair = [Some(j.body.as_str()), j.other()];
        pair.sort_unstable();
        pair
    }
    bodies(one) == bodies(other) && one.at == other.at
}
