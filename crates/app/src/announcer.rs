//! What a screen reader hears while a run plays: the latest impact, as one sentence in
//! the app's language ("At 1.234 s, b1 hit the wall."), at most one every two seconds of
//! real time however many impacts there are, with how many came since the last sentence.
//! The status line shows the sentence in a polite live region, which screen readers read
//! when it changes without moving the focus (the issue on accessibility: events while
//! playing, rate-limited).

use physics::{ImpactTarget, Scene};

use crate::i18n::{Arg, tr, tr_with};
use crate::recording::Recording;

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
        if impacts.len() == self.told || self.last.is_some_and(|t| now - t < INTERVAL) {
            return;
        }
        let Some(latest) = impacts.last() else {
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
}
