//! The inspector's words for the scene's fields (`physics::fields`) in every language:
//! English says exactly what the field table says (label and help), so the table stays
//! the one source of the English words and the messages follow it; German and Spanish
//! have every one (the key test of `newtonlab_i18n` holds the ids equal).

use newtonlab_app::i18n::SOURCES;
use physics::fields::{self, Field};
use physics::{ObjectKind, SectionKind};

type Words = (SectionKind, &'static str, &'static str, &'static str);

/// (section, key, label, help) of every field.
fn every_field() -> Vec<Words> {
    fn of<T>(section: SectionKind, table: &[Field<T>]) -> Vec<Words> {
        table
            .iter()
            .map(|f| (section, f.key, f.label, f.help))
            .collect()
    }
    let object = SectionKind::Object;
    let mut all = of(SectionKind::World, fields::WORLD);
    all.extend(of(SectionKind::Simulation, fields::SIMULATION));
    all.extend(of(object(ObjectKind::Particle), fields::PARTICLE));
    all.extend(of(object(ObjectKind::Spring), fields::SPRING));
    all.extend(of(object(ObjectKind::Rod), fields::ROD));
    all.extend(of(object(ObjectKind::String), fields::STRING));
    all.extend(of(object(ObjectKind::Ramp), fields::RAMP));
    all.extend(of(object(ObjectKind::Body), fields::BODY));
    all
}

/// The message `id` of a Fluent file, if it has it on one line.
fn message<'a>(source: &'a str, id: &str) -> Option<&'a str> {
    source
        .lines()
        .find_map(|line| line.strip_prefix(id)?.strip_prefix(" = "))
}

#[test]
fn every_field_has_its_words_in_every_language() {
    let mut words = Vec::new();
    for (section, key, label, help) in every_field() {
        let id = newtonlab_app::edit::field_message(section, key);
        words.push((id.clone(), label));
        words.push((format!("{id}-help"), help));
    }
    let wrong: Vec<String> = words
        .iter()
        .filter(|(id, text)| message(SOURCES[0], id) != Some(text))
        .map(|(id, text)| format!("{id} = {text}"))
        .collect();
    assert!(
        wrong.is_empty(),
        "English must say what the field table says:\n{}",
        wrong.join("\n")
    );
    for (id, _) in &words {
        for source in &SOURCES[1..] {
            assert!(
                message(source, id).is_some(),
                "{id} missing in a translation"
            );
        }
    }
}
