//! What a screen reader hears while a run plays: the latest impact, as one sentence in
//! the app's language ("At 1.234 s, b1 hit the wall."), at most one every two seconds of
//! real time however many impacts there are, with how many came since the last sentence.
//! The status line shows the sentence in a polite live region, which screen readers read
//! when it changes without moving the focus; rate-limited so that speech keeps up. A spring at full stretch (its length at a maximum between the
//! recording's samples) is an event too: "At 0.785 s, spring s1 is at full stretch,
//! 1.5 m." Whichever came last is said.

use physics::{DVec2, Endpoint, ImpactTarget, Scene};

use crate::i18n::{Arg, tr, tr_with};
use crate::recording::{Column, Recording};

/// Seconds of real time between two sentences.
pub const INTERVAL: f64 = 2.0;

#[derive(Clone, Debug, Default)]
pub struct Announcer {
    /// Impacts of the recording already told (or passed over).
    told: usize,
    /// When the last sentence was made, seconds of real time.
    last: Option<f64>,
    /// The sentence, empty until the first impact.
    pub text: String,
    /// The time of the last sample judged for springs' full stretch.
    scanned: Option<f64>,
    /// The latest full stretch not yet said: (time, spring, length).
    stretch: Option<(f64, usize, f64)>,
}

impl Announcer {
    /// Makes a sentence of the latest impact of `recording` if there are new ones and
    /// the last sentence is at least [`INTERVAL`] old at `now` (seconds of real time).
    pub fn update(&mut self, recording: &Recording, scene: &Scene, now: f64) {
        let impacts = recording.impacts();
        if impacts.len() < self.told {
            // A new run, or the run cut back: start over.
            self.told = 0;
        }
        if recording.last_time() < self.scanned {
            self.scanned = None;
            self.stretch = None;
        }
        self.find_full_stretch(recording, scene);
        let fresh = impacts.len() > self.told || self.stretch.is_some();
        if !fresh || self.last.is_some_and(|t| now - t < INTERVAL) {
            return;
        }
        let latest = impacts.get(self.told..).and_then(<[_]>::last);
        if let Some((time, k, length)) = self.stretch
            && latest.is_none_or(|impact| impact.time < time)
        {
            self.text = tr_with(
                "announce-stretch",
                &[
                    ("time", Arg::Text(&crate::format::number(time))),
                    ("spring", Arg::Text(&scene.springs[k].name)),
                    ("length", Arg::Text(&crate::format::number(length))),
                ],
            );
            self.stretch = None;
            self.told = impacts.len();
            self.last = Some(now);
            return;
        }
        self.stretch = None;
        let Some(latest) = latest else {
            return;
        };
        let names = recording.names();
        let name = |i: usize| names.get(i).map_or("?", String::as_str);
        let other = match latest.other {
            ImpactTarget::Particle(j) => name(j).to_owned(),
            ImpactTarget::Ramp(k) => scene
                .ramps
                .get(k)
                .map_or_else(|| "?".to_owned(), |r| r.name.clone()),
            ImpactTarget::Wall => tr("announce-wall"),
        };
        let time = crate::format::number(latest.time);
        let more = impacts.len() - self.told - 1;
        #[expect(clippy::cast_precision_loss, reason = "a count of impacts")]
        let more = more as f64;
        self.text = tr_with(
            "announce-impact",
            &[
                ("time", Arg::Text(&time)),
                ("particle", Arg::Text(name(latest.particle))),
                ("other", Arg::Text(&other)),
                ("more", Arg::Number(more)),
            ],
        );
        self.told = impacts.len();
        self.last = Some(now);
    }
}

impl Announcer {
    /// Looks through the samples not yet judged for a spring whose length stopped
    /// growing (longer than the sample before, no shorter than the one after), and keeps
    /// the latest as the news.
    fn find_full_stretch(&mut self, recording: &Recording, scene: &Scene) {
        let n = recording.len();
        if n < 3 || scene.springs.is_empty() {
            return;
        }
        let time = |k: usize| recording.at(k, Column::Plain(0));
        // The first centre not judged yet: the sample after the last one judged, found
        // by bisection (the samples are in time order; this runs every frame).
        let first = self.scanned.map_or(1, |t| {
            let (mut lo, mut hi) = (0, n);
            while lo < hi {
                let mid = lo + (hi - lo) / 2;
                if time(mid) <= t {
                    lo = mid + 1;
                } else {
                    hi = mid;
                }
            }
            lo.max(1)
        });
        for (s, spring) in scene.springs.iter().enumerate() {
            let end = |e: &Endpoint| match e {
                Endpoint::Point(p) => Some(End::Fixed(p.to_dvec2())),
                Endpoint::Particle(name) => {
                    let (x, y) = Recording::position_columns(recording.index_of(name)?);
                    Some(End::Moving(x, y))
                }
            };
            let (Some(a), Some(b)) = (end(&spring.from), end(&spring.to)) else {
                continue;
            };
            let length = |k: usize| a.at(recording, k).distance(b.at(recording, k));
            for k in first..n - 1 {
                let here = length(k);
                if here > length(k - 1) && here >= length(k + 1) {
                    let t = time(k);
                    if self.stretch.is_none_or(|(latest, _, _)| latest < t) {
                        self.stretch = Some((t, s, here));
                    }
                }
            }
        }
        self.scanned = Some(time(n - 2));
    }
}

/// One end of a spring in the recording.
#[derive(Clone, Copy)]
enum End {
    Fixed(DVec2),
    Moving(Column, Column),
}

impl End {
    fn at(self, recording: &Recording, k: usize) -> DVec2 {
        match self {
            Self::Fixed(p) => p,
            Self::Moving(x, y) => DVec2::new(recording.at(k, x), recording.at(k, y)),
        }
    }
}

#[cfg(test)]
mod tests {
    use physics::{ImpactRecord, Particle, Scene, Simulation, World};

    use super::*;

    fn impact(time: f64) -> ImpactRecord {
        ImpactRecord {
            time,
            particle: 0,
            other: ImpactTarget::Wall,
            impulse: 1.0,
            normal_speed_before: 1.0,
            normal_speed_after: 1.0,
            kinetic_energy_lost: 0.0,
        }
    }

    /// One sentence every two seconds at most, about the latest impact, counting those
    /// passed over.
    #[test]
    fn impacts_are_told_at_most_every_two_seconds() {
        let scene = Scene::new()
            .with_world(World::weightless())
            .with_particle(Particle::new("ball", 1.0));
        let mut recording = Recording::start(&Simulation::new(&scene).unwrap());
        let mut announcer = Announcer::default();
        announcer.update(&recording, &scene, 0.0);
        assert!(announcer.text.is_empty(), "nothing yet");
        recording.note_impacts(vec![impact(0.25), impact(0.5)]);
        announcer.update(&recording, &scene, 0.1);
        assert_eq!(
            announcer.text,
            "At 0.5 s, ball hit the wall. And 1 more impact since the last message."
        );
        recording.note_impacts(vec![impact(0.75)]);
        announcer.update(&recording, &scene, 1.5);
        assert!(announcer.text.starts_with("At 0.5 s"), "too soon to tell");
        announcer.update(&recording, &scene, 2.2);
        assert_eq!(announcer.text, "At 0.75 s, ball hit the wall.");
    }

    /// A mass on a spring from a fixed point, starting at the natural length L0 = 1 m
    /// with v0 = 2 m/s outward (k = 4 N/m, m = 1 kg, no gravity): its length is
    /// L0 + (v0/ω) sin ωt with ω = 2/s, so the first full stretch is 2 m at t = π/4 s.
    /// Said at the recording's sample nearest the maximum (5 ms apart): within 5 ms and
    /// 1 mm (the length is flat there: within (ω·0.005)²/2 of its maximum).
    #[test]
    fn a_spring_at_full_stretch_is_told() {
        use physics::Spring;
        let scene = Scene::new()
            .with_world(World::weightless())
            .with_particle(
                Particle::new("ball", 1.0)
                    .position([1.0, 0.0])
                    .velocity([2.0, 0.0]),
            )
            .with_spring(Spring::new(
                "s1",
                Endpoint::Point(physics::Vector::cartesian(0.0, 0.0)),
                Endpoint::Particle("ball".into()),
                4.0,
                1.0,
            ));
        let mut simulation = Simulation::new(&scene).unwrap();
        let mut recording = Recording::start(&simulation);
        let mut announcer = Announcer::default();
        while simulation.time() < 1.2 {
            simulation.step().unwrap();
            recording.after_step(&simulation);
        }
        announcer.update(&recording, &scene, 10.0);
        let text = announcer.text.clone();
        let rest = text.strip_prefix("At ").expect("a sentence");
        let (time, rest) = rest
            .split_once(" s, spring s1 is at full stretch, ")
            .expect(&text);
        let length: f64 = rest.strip_suffix(" m.").expect(&text).parse().expect(&text);
        let time: f64 = time.parse().expect(&text);
        assert!(
            (time - std::f64::consts::FRAC_PI_4).abs() <= 0.005,
            "{text}"
        );
        assert!((length - 2.0).abs() < 1e-3, "{text}");
    }
}
