//! The app's measuring instruments as a scene keeps them (`[instruments]` and
//! `[instruments.stopwatch]`), so that a lesson opens with its tape measure (which is
//! also the stopwatch's light gate), protractor, probe and stopwatch in place. The
//! simulation never reads them; `check` validates them like the rest of the scene: an end
//! on a particle that does not exist, a gate with no tape, an event that does not read.

use glam::DVec2;

use super::{Endpoint, Scene, Section, say};

/// The instruments laid out in a scene.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Instruments {
    /// The tape measure's two ends, each a point or a particle it follows; its segment is
    /// the light gate.
    pub tape: Option<[Endpoint; 2]>,
    /// The protractor: its vertex, its first arm's end and, once laid, its second's.
    pub protractor: Option<Protractor>,
    /// Where the field probe is, metres.
    pub probe: Option<DVec2>,
    /// What starts and stops the stopwatch; the stopwatch is shown, armed, when the scene
    /// opens.
    pub stopwatch: Option<Stopwatch>,
}

/// The protractor's three points.
#[derive(Clone, Debug, PartialEq)]
pub struct Protractor {
    /// Where the arms meet.
    pub vertex: Endpoint,
    /// The first arm's end.
    pub arm: Endpoint,
    /// The second arm's end, once laid: the angle is between the arms.
    pub second_arm: Option<Endpoint>,
}

/// The stopwatch's settings.
#[derive(Clone, Debug, PartialEq)]
pub struct Stopwatch {
    /// What starts it.
    pub start: Trigger,
    /// Which occurrence of `start` starts it, from 1.
    pub start_count: u32,
    /// What stops it.
    pub stop: Trigger,
    /// Which occurrence of `stop` stops it, from 1 (counted from the arming, so that the
    /// 1st and 3rd crossing of a pendulum's vertical are a period).
    pub stop_count: u32,
    /// The event [`Trigger::Event`] waits for: `bob.x crosses 0 up`.
    pub event: Option<String>,
    /// Whether it keeps going, a lap at every stop.
    pub laps: bool,
}

impl Default for Stopwatch {
    fn default() -> Self {
        Self {
            start: Trigger::Hand,
            start_count: 1,
            stop: Trigger::Hand,
            stop_count: 1,
            event: None,
            laps: false,
        }
    }
}

/// What starts or stops the stopwatch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Trigger {
    /// The Start and Stop buttons.
    Hand,
    /// The run starting to play (a start only).
    Play,
    /// An impact of any two things.
    Impact,
    /// A particle's centre crossing the tape measure's segment.
    Gate,
    /// The typed event.
    Event,
}

impl Trigger {
    /// What may start it.
    pub const STARTS: [Self; 5] = [
        Self::Hand,
        Self::Play,
        Self::Impact,
        Self::Gate,
        Self::Event,
    ];
    /// What may stop it.
    pub const STOPS: [Self; 4] = [Self::Hand, Self::Impact, Self::Gate, Self::Event];

    /// As a scene file writes it.
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Hand => "hand",
            Self::Play => "play",
            Self::Impact => "impact",
            Self::Gate => "gate",
            Self::Event => "event",
        }
    }

    /// From a scene file's word.
    pub fn parse(text: &str) -> Option<Self> {
        Self::STARTS.into_iter().find(|t| t.as_str() == text)
    }

    /// Whether it comes in numbered occurrences (the first, the third).
    pub fn counts(self) -> bool {
        matches!(self, Self::Impact | Self::Gate | Self::Event)
    }
}

impl Instruments {
    /// Whether nothing is laid out.
    pub fn is_empty(&self) -> bool {
        self == &Self::default()
    }

    /// Every end that follows a particle, by field.
    fn ends(&self) -> Vec<(&'static str, &Endpoint)> {
        let mut ends = Vec::new();
        if let Some(tape) = &self.tape {
            ends.extend(tape.iter().map(|end| ("tape", end)));
        }
        if let Some(p) = &self.protractor {
            ends.extend([("protractor", &p.vertex), ("protractor", &p.arm)]);
            ends.extend(p.second_arm.iter().map(|end| ("protractor", end)));
        }
        ends
    }

    /// Every end and point of the instruments, mutably.
    fn ends_mut(&mut self) -> Vec<&mut Endpoint> {
        let mut ends: Vec<&mut Endpoint> = Vec::new();
        if let Some(tape) = &mut self.tape {
            ends.extend(tape.iter_mut());
        }
        if let Some(p) = &mut self.protractor {
            ends.extend([&mut p.vertex, &mut p.arm]);
            ends.extend(p.second_arm.iter_mut());
        }
        ends
    }

    /// What is wrong with them on `scene`, each with its section and key.
    pub fn problems(&self, scene: &Scene) -> Vec<(Section, &'static str, String)> {
        let mut problems = Vec::new();
        for (field, end) in self.ends() {
            match end {
                Endpoint::Particle(name) if !scene.particles.iter().any(|p| p.name == *name) => {
                    let why = say(
                        "scene-instrument-no-particle",
                        &[("field", field), ("name", name)],
                    );
                    problems.push((Section::Instruments, field, why));
                }
                Endpoint::Point(point) if !point.to_dvec2().is_finite() => {
                    let why = say("scene-vector-not-finite", &[("field", field)]);
                    problems.push((Section::Instruments, field, why));
                }
                _ => {}
            }
        }
        if let Some(probe) = self.probe
            && !probe.is_finite()
        {
            let why = say("scene-vector-not-finite", &[("field", "probe")]);
            problems.push((Section::Instruments, "probe", why));
        }
        if let Some(watch) = &self.stopwatch {
            problems.extend(
                watch
                    .problems(scene, self.tape.is_some())
                    .into_iter()
                    .map(|(field, why)| (Section::Stopwatch, field, why)),
            );
        }
        problems
    }

    /// An end on the particle `name`, which is going, stays where the particle was.
    pub(super) fn unpin(&mut self, name: &str, at: super::Vector) {
        for end in self.ends_mut() {
            if matches!(end, Endpoint::Particle(n) if n == name) {
                *end = Endpoint::Point(at);
            }
        }
    }

    /// Ends on the particle `old` follow it under its new name.
    pub(super) fn rename(&mut self, old: &str, new: &str) {
        for end in self.ends_mut() {
            if let Endpoint::Particle(name) = end
                && name == old
            {
                new.clone_into(name);
            }
        }
    }
}

impl Stopwatch {
    /// What is wrong with the settings: a stop on Play, a gate with no tape to be it, an
    /// event missing or not of this scene, an occurrence below the first.
    fn problems(&self, scene: &Scene, has_tape: bool) -> Vec<(&'static str, String)> {
        let mut problems = Vec::new();
        if self.stop == Trigger::Play {
            problems.push(("stop", say("scene-stopwatch-stop-on-play", &[])));
        }
        for (field, trigger) in [("start", self.start), ("stop", self.stop)] {
            if trigger == Trigger::Gate && !has_tape {
                problems.push((
                    field,
                    say("scene-stopwatch-gate-no-tape", &[("field", field)]),
                ));
            }
        }
        let uses_event = self.start == Trigger::Event || self.stop == Trigger::Event;
        match &self.event {
            None if uses_event => {
                problems.push(("event", say("scene-stopwatch-no-event", &[])));
            }
            Some(text) => {
                let checked = crate::Event::parse(text)
                    .and_then(|event| event.quantity.check_in(scene).map(|()| event));
                if let Err(why) = checked {
                    problems.push(("event", why));
                }
            }
            None => {}
        }
        for (field, count) in [
            ("start_count", self.start_count),
            ("stop_count", self.stop_count),
        ] {
            if count == 0 {
                problems.push((field, say("scene-stopwatch-count", &[("field", field)])));
            }
        }
        problems
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::error::Problem;
    use crate::scene::{FieldRef, Vector};

    const PENDULUM: &str = r#"version = 1

[[particle]]
name = "bob"
mass = 1.0
position = [0.0, -2.0]

[[rod]]
from = [0.0, 0.0]
to = "bob"

[instruments]
tape = [[0.0, 0.0], [0.0, -3.0]]
protractor = [[0.0, 0.0], [0.0, -1.0], "bob"]
probe = [1.0, 0.5]

[instruments.stopwatch]
start = "gate"
stop = "gate"
stop_count = 3
laps = true
"#;

    #[test]
    fn instruments_read_and_write_back_in_both_formats() {
        let scene = Scene::from_toml(PENDULUM).unwrap();
        let instruments = scene.instruments.clone().unwrap();
        assert_eq!(
            instruments.tape,
            Some([
                Endpoint::Point(Vector::cartesian(0.0, 0.0)),
                Endpoint::Point(Vector::cartesian(0.0, -3.0))
            ])
        );
        let protractor = instruments.protractor.clone().unwrap();
        assert_eq!(protractor.second_arm, Some(Endpoint::from("bob")));
        assert_eq!(instruments.probe, Some(DVec2::new(1.0, 0.5)));
        let watch = instruments.stopwatch.clone().unwrap();
        assert_eq!(
            (watch.start, watch.start_count, watch.stop, watch.stop_count),
            (Trigger::Gate, 1, Trigger::Gate, 3),
            "counts default to the first"
        );
        assert!(watch.laps && watch.event.is_none());
        let toml = scene.to_toml();
        assert!(toml.contains("[instruments.stopwatch]"), "{toml}");
        assert_eq!(Scene::from_toml(&toml).unwrap(), scene, "TOML");
        assert_eq!(Scene::from_json(&scene.to_json()).unwrap(), scene, "JSON");
        // A scene without instruments is written as before they existed.
        let bare = Scene::from_toml("version = 1\n").unwrap();
        assert!(!bare.to_toml().contains("instruments"));
    }

    /// The problem in `text` at `field`: its message, line and column.
    fn problem_at(text: &str, field: FieldRef) -> Problem {
        let error = Scene::from_toml(text).unwrap_err();
        error
            .problems
            .into_iter()
            .find(|p| p.field == Some(field))
            .unwrap_or_else(|| panic!("no problem at {field:?}"))
    }

    #[test]
    fn bad_instruments_are_refused_at_their_place() {
        let at = |section, field| FieldRef { section, field };
        let unknown = PENDULUM.replace(r#", "bob"]"#, r#", "rob"]"#);
        let p = problem_at(&unknown, at(Section::Instruments, "protractor"));
        assert!(p.message.contains("no particle named 'rob'"), "{p}");
        assert_eq!((p.line, p.column), (Some(14), Some(14)), "{p}");

        let one_end = PENDULUM.replace("tape = [[0.0, 0.0], [0.0, -3.0]]", "tape = [[0.0, 0.0]]");
        let p = problem_at(&one_end, at(Section::Instruments, "tape"));
        assert!(p.message.contains("takes 2 to 2 ends"), "{p}");

        let no_tape = PENDULUM.replace("tape = [[0.0, 0.0], [0.0, -3.0]]\n", "");
        let p = problem_at(&no_tape, at(Section::Stopwatch, "start"));
        assert!(p.message.contains("light gate is the tape"), "{p}");
        assert_eq!(p.line, Some(17), "{p}");

        let on_play = PENDULUM.replace(r#"stop = "gate""#, r#"stop = "play""#);
        let p = problem_at(&on_play, at(Section::Stopwatch, "stop"));
        assert!(p.message.contains("not stop it"), "{p}");

        let typo = PENDULUM.replace(r#"start = "gate""#, r#"start = "gait""#);
        let p = problem_at(&typo, at(Section::Stopwatch, "start"));
        assert!(p.message.contains("got 'gait'"), "{p}");

        let half = PENDULUM.replace("stop_count = 3", "stop_count = 2.5");
        let p = problem_at(&half, at(Section::Stopwatch, "stop_count"));
        assert!(p.message.contains("whole number from 1"), "{p}");

        let event = PENDULUM.replace(r#"stop = "gate""#, "stop = \"event\"");
        let p = problem_at(&event, at(Section::Stopwatch, "event"));
        assert!(p.message.contains("needs the event"), "{p}");
        let named = event.replace("laps = true", "event = \"rob.x crosses 0\"");
        let p = problem_at(&named, at(Section::Stopwatch, "event"));
        assert!(p.message.contains("rob"), "{p}");
        let fine = event.replace("laps = true", "event = \"bob.x crosses 0 up\"");
        assert!(Scene::from_toml(&fine).is_ok());
    }

    #[test]
    fn ends_follow_a_renamed_particle_and_stay_where_a_removed_one_was() {
        let mut scene = Scene::from_toml(PENDULUM).unwrap();
        scene.rename(Section::Particle(0), "weight");
        let arm = |scene: &Scene| {
            scene
                .instruments
                .as_ref()
                .and_then(|i| i.protractor.as_ref())
                .and_then(|p| p.second_arm.clone())
        };
        assert_eq!(arm(&scene), Some(Endpoint::from("weight")));
        scene.remove(Section::Particle(0));
        assert_eq!(
            arm(&scene),
            Some(Endpoint::Point(Vector::cartesian(0.0, -2.0)))
        );
        assert!(scene.validate().is_empty(), "still a valid scene");
    }
}
