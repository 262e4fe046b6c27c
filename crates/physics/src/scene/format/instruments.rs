//! Reading and writing `[instruments]` and `[instruments.stopwatch]`.

use super::read::Reader;
use super::tree::{Node, Value};
use super::values::{read_bool, read_endpoint, read_number, read_text, read_vector};
use super::write::{Header, Out, OutSection};
use crate::scene::error::Section;
use crate::scene::instruments::{Instruments, Protractor, Stopwatch, Trigger};
use crate::scene::{Endpoint, Vector, say};

pub(super) const INSTRUMENTS_KEYS: &[&str] = &["tape", "protractor", "probe", "stopwatch"];
pub(super) const STOPWATCH_KEYS: &[&str] = &[
    "start",
    "start_count",
    "stop",
    "stop_count",
    "event",
    "laps",
];

impl Reader<'_> {
    pub(super) fn instruments(&mut self, node: &Node) -> Instruments {
        let mut instruments = Instruments::default();
        let label = "[instruments]".to_owned();
        let Some(mut t) = self.table(node, Section::Instruments, label) else {
            return instruments;
        };
        instruments.tape = self.field(&mut t, "tape", |node| {
            let ends = read_ends(node, "tape", 2..=2)?;
            Ok([ends[0].clone(), ends[1].clone()])
        });
        instruments.protractor = self.field(&mut t, "protractor", |node| {
            let mut ends = read_ends(node, "protractor", 2..=3)?.into_iter();
            Ok(Protractor {
                vertex: ends.next().unwrap_or(Endpoint::Point(Vector::ZERO)),
                arm: ends.next().unwrap_or(Endpoint::Point(Vector::ZERO)),
                second_arm: ends.next(),
            })
        });
        instruments.probe = self
            .field(&mut t, "probe", read_vector)
            .map(Vector::to_dvec2);
        if let Some(node) = t.get("stopwatch") {
            instruments.stopwatch = Some(self.stopwatch(node));
        }
        self.close(&t, INSTRUMENTS_KEYS);
        instruments
    }

    fn stopwatch(&mut self, node: &Node) -> Stopwatch {
        let mut watch = Stopwatch::default();
        let label = "[instruments.stopwatch]".to_owned();
        let Some(mut t) = self.table(node, Section::Stopwatch, label) else {
            return watch;
        };
        let trigger = |node: &Node| {
            let text = read_text(node)?;
            Trigger::parse(&text).ok_or_else(|| {
                let words: Vec<&str> = Trigger::STARTS.iter().map(|t| t.as_str()).collect();
                say(
                    "scene-trigger-unknown",
                    &[("got", &text), ("words", &words.join(", "))],
                )
            })
        };
        watch.start = self
            .field(&mut t, "start", trigger)
            .unwrap_or(Trigger::Hand);
        watch.start_count = self.field(&mut t, "start_count", read_count).unwrap_or(1);
        watch.stop = self.field(&mut t, "stop", trigger).unwrap_or(Trigger::Hand);
        watch.stop_count = self.field(&mut t, "stop_count", read_count).unwrap_or(1);
        watch.event = self.field(&mut t, "event", read_text);
        watch.laps = self.field(&mut t, "laps", read_bool).unwrap_or(false);
        self.close(&t, STOPWATCH_KEYS);
        watch
    }
}

/// An array of `counts` ends, each a point `[x, y]` or a particle's name.
fn read_ends(
    node: &Node,
    field: &str,
    counts: std::ops::RangeInclusive<usize>,
) -> Result<Vec<Endpoint>, String> {
    let most = counts.end().to_string();
    let least = counts.start().to_string();
    let wrong = |got: &str| {
        say(
            "scene-instrument-ends",
            &[
                ("field", field),
                ("least", &least),
                ("most", &most),
                ("got", got),
            ],
        )
    };
    let Value::Array(items) = &node.value else {
        return Err(wrong(&node.value.kind()));
    };
    if !counts.contains(&items.len()) {
        return Err(wrong(&items.len().to_string()));
    }
    items.iter().map(read_endpoint).collect()
}

/// A whole count from 1.
fn read_count(node: &Node) -> Result<u32, String> {
    let value = read_number(node)?;
    if value.fract() == 0.0 && (1.0..=f64::from(u32::MAX)).contains(&value) {
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a whole number in u32's range"
        )]
        return Ok(value as u32);
    }
    Err(say("scene-count-not-whole", &[("got", &value.to_string())]))
}

/// Within the table `instruments`: itself, or its stopwatch's table.
pub(super) fn instruments_node<'n>(
    instruments: &'n Node<'n>,
    section: Section,
) -> Option<&'n Node<'n>> {
    match (section, &instruments.value) {
        (Section::Stopwatch, Value::Table(entries)) => entries
            .iter()
            .find(|e| e.key == "stopwatch")
            .map(|e| &e.node),
        _ => Some(instruments),
    }
}

fn out_end(end: &Endpoint) -> Out {
    match end {
        Endpoint::Particle(name) => Out::Text(name.clone()),
        Endpoint::Point(point) => Out::Vector(*point),
    }
}

/// The instruments as sections: `[instruments]`, then `[instruments.stopwatch]`.
pub(super) fn instruments_sections(instruments: &Instruments) -> Vec<OutSection> {
    let mut entries = Vec::new();
    if let Some(tape) = &instruments.tape {
        entries.push(("tape", Out::List(tape.iter().map(out_end).collect())));
    }
    if let Some(p) = &instruments.protractor {
        let ends = [Some(&p.vertex), Some(&p.arm), p.second_arm.as_ref()];
        let ends = ends.into_iter().flatten().map(out_end).collect();
        entries.push(("protractor", Out::List(ends)));
    }
    if let Some(probe) = instruments.probe {
        entries.push(("probe", Out::Vector(Vector::Cartesian(probe))));
    }
    let mut sections = vec![OutSection {
        header: Header::Table("instruments"),
        entries,
    }];
    if let Some(watch) = &instruments.stopwatch {
        let mut entries = vec![
            ("start", Out::Text(watch.start.as_str().to_owned())),
            ("start_count", Out::Integer(i64::from(watch.start_count))),
            ("stop", Out::Text(watch.stop.as_str().to_owned())),
            ("stop_count", Out::Integer(i64::from(watch.stop_count))),
        ];
        if let Some(event) = &watch.event {
            entries.push(("event", Out::Text(event.clone())));
        }
        entries.push(("laps", Out::Bool(watch.laps)));
        sections.push(OutSection {
            header: Header::Sub("instruments", "stopwatch"),
            entries,
        });
    }
    sections
}
