//! Languages, text size and high contrast.

use egui::Key;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use newtonlab_app::{App, Selection};

use crate::common::{harness, one_ball, play_frames, small_ball, type_into};

/// View → Language switches live: the menus and the run controls speak German, then
/// Spanish, the scene is untouched, and English comes back.
#[test]
fn the_language_switches_live_and_keeps_the_scene() {
    let mut harness = harness(App::new(one_ball()));
    let choose = |harness: &mut Harness<'_, App>, view: &str, language: &str, name: &str| {
        harness.get_by_label(view).click();
        harness.run();
        harness.get_by_label(language).click();
        harness.run();
        harness.get_by_label(name).click();
        harness.run();
    };
    choose(&mut harness, "View", "Language", "Deutsch");
    harness.get_by_label("Datei");
    harness.get_by_label("Start");
    assert!(harness.query_by_label("File").is_none(), "no English left");
    choose(&mut harness, "Ansicht", "Sprache", "Español");
    harness.get_by_label("Archivo");
    harness.get_by_label("Reproducir");
    assert_eq!(harness.state().document.scene().particles.len(), 1);
    choose(&mut harness, "Ver", "Idioma", "English");
    harness.get_by_label("File");
    harness.get_by_label("Play");
}

/// Every string of the translation layer on screen follows the language: with a run
/// gone back to (the time machine's bar), the stopwatch open, the particle selected (the
/// inspector's headings), the F1 list and the Measure menu's tools, no accessible name
/// in German or Spanish is an English message that the language words differently
/// (exactly, or within a name for messages of three words or more).
#[test]
fn nothing_on_screen_stays_english_after_a_switch() {
    use egui_kittest::kittest::NodeT as _;
    use newtonlab_app::i18n::{Language, SOURCES, set_language};
    let messages = |source: &str| -> std::collections::HashMap<String, String> {
        source
            .lines()
            .filter_map(|line| line.split_once(" = "))
            .filter(|(id, _)| !id.starts_with([' ', '#']))
            .map(|(id, text)| (id.to_owned(), text.trim().to_owned()))
            .collect()
    };
    let english = messages(SOURCES[0]);
    for (language, source) in [
        (Language::German, SOURCES[1]),
        (Language::Spanish, SOURCES[2]),
    ] {
        let own = messages(source);
        let mut harness = harness(App::new(small_ball()));
        play_frames(&mut harness, 3);
        harness.key_press(Key::Comma);
        harness.key_press(Key::T);
        harness.key_press(Key::F1);
        harness.run();
        harness.state_mut().panels.getting_started = true;
        harness.state_mut().selection = Some(Selection::Particle(0));
        set_language(language);
        harness.run();
        harness.run();
        let names: Vec<String> = harness
            .root()
            .children_recursive()
            .filter_map(|node| node.accesskit_node().label())
            .collect();
        assert!(names.len() > 50, "{} names", names.len());
        for (id, text) in &english {
            if own.get(id) == Some(text) || text.contains('{') {
                continue; // the same word in both (OK, Start), or filled in
            }
            let words = text.split_whitespace().count();
            let left = names
                .iter()
                .find(|name| *name == text || (words >= 3 && name.contains(text.as_str())));
            assert!(
                left.is_none(),
                "{language:?}: '{id}' still in English: {left:?}"
            );
        }
        set_language(Language::English);
    }
}

/// View → Text size and High contrast change the whole app at once: the zoom follows the
/// size (times projector mode's 1.6), the theme turns black on white and the canvas
/// draws with its high-contrast palette, and both are kept
/// in the settings file the next session starts with (read back here).
#[test]
fn text_size_and_high_contrast_apply_and_are_kept() {
    let dir = std::env::temp_dir().join(format!("newtonlab-settings-{}", std::process::id()));
    let file = dir.join("settings.toml");
    let mut harness = harness(App::new(one_ball()).with_settings_file(file.clone()));
    harness.get_by_label("View").click();
    harness.run();
    harness.get_by_label("Text size").click();
    harness.run();
    harness.get_by_label("150 %").click();
    harness.run();
    harness.run();
    assert!((harness.ctx.zoom_factor() - 1.5).abs() < 1e-6);
    harness.get_by_label("View").click();
    harness.run();
    harness.get_by_label("High contrast").click();
    harness.run();
    harness.run();
    let text_color = harness.ctx.global_style().visuals.override_text_color;
    assert_eq!(text_color, Some(egui::Color32::BLACK));
    assert_eq!(
        harness.state().canvas.palette,
        newtonlab_app::canvas::Palette::HIGH_CONTRAST,
        "the canvas follows the theme"
    );
    let kept =
        newtonlab_app::settings::Settings::parse(&std::fs::read_to_string(&file).expect("kept"));
    assert!(
        kept.high_contrast && (kept.text_size - 1.5).abs() < 1e-6,
        "{kept:?}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// The Getting started page opens on the first run (settings that never showed it) and
/// not on the next, and Help → Getting started opens it any time; its three tasks are
/// there, in German too.
#[test]
fn getting_started_opens_on_the_first_run_and_from_help() {
    let dir = std::env::temp_dir().join(format!("newtonlab-welcome-{}", std::process::id()));
    let file = dir.join("settings.toml");
    let first = App::new(one_ball())
        .with_settings_file(file.clone())
        .welcome_first_run();
    let shown = harness(first);
    shown.get_by_label("Getting started");
    shown.get_by_label("Place and run");
    shown.get_by_label_contains("tick extremes and zeros");
    shown.get_by_label_contains("Use as x axis: a phase plot");
    let kept =
        newtonlab_app::settings::Settings::parse(&std::fs::read_to_string(&file).expect("kept"));
    assert!(kept.welcomed, "remembered");
    let again = App::new(one_ball())
        .with_settings_file(file.clone())
        .welcome_first_run();
    let mut harness = harness(again);
    assert!(
        harness.query_by_label("Place and run").is_none(),
        "once only"
    );
    harness.get_by_label("Help").click();
    harness.run();
    harness.get_by_label("Getting started").click();
    harness.run();
    harness.get_by_label("Place and run");
    newtonlab_app::i18n::set_language(newtonlab_app::i18n::Language::German);
    harness.run();
    harness.get_by_label("Setzen und laufen lassen");
    newtonlab_app::i18n::set_language(newtonlab_app::i18n::Language::English);
    std::fs::remove_dir_all(&dir).ok();
}

/// In German the inspector speaks German while a run goes (a turning particle's live
/// readouts, a tie's fixed end, how pair forces are summed), writes its fields with the
/// decimal comma its readouts write, and reads a value typed with a comma as well as one
/// typed with a point.
#[test]
fn german_fields_and_live_readouts_speak_german_with_a_decimal_comma() {
    use egui_kittest::kittest::NodeT as _;
    use newtonlab_app::i18n::{Language, set_language};
    use physics::{Particle, Scene, World};
    let scene = Scene::new().with_world(World::weightless()).with_particle(
        Particle::new("ball", 1.5)
            .radius(0.25)
            .turning(0.5, 3.0)
            .velocity([1.0, 0.0]),
    );
    set_language(Language::German);
    let mut harness = harness(App::new(scene));
    harness.state_mut().selection = Some(Selection::Particle(0));
    harness.run();
    let value = |harness: &Harness<'_, App>, label: &str| {
        harness.get_by_label(label).value().unwrap_or_default()
    };
    assert_eq!(value(&harness, "Masse"), "1,5");
    assert_eq!(value(&harness, "Radius"), "0,25");
    type_into(&mut harness, "Masse", "2,75");
    assert_eq!(harness.state().document.scene().particles[0].mass, 2.75);
    type_into(&mut harness, "Radius", "0.5");
    assert_eq!(harness.state().document.scene().particles[0].radius, 0.5);
    harness.get_by_label("Simulation").click();
    harness.run();
    harness.get_by_value("Paarkräfte: direkt (jedes Paar, exakt)");
    harness.get_by_label("Start").click();
    harness.run_steps(3);
    for german in [
        "Geschwindigkeitsbetrag",
        "Winkelgeschwindigkeit",
        "Drehimpuls",
    ] {
        harness.get_by_label(german);
    }
    // Each value within the inspector, left of the canvas: wrapped, not cut off.
    let edge = harness.state().canvas.rect.left();
    for value in harness.query_all_by_label_contains("rad/s") {
        assert!(
            value.rect().right() <= edge,
            "{:?} ends at {} past {edge}",
            value.accesskit_node().label(),
            value.rect().right()
        );
    }
    for english in [
        "position",
        "velocity",
        "spin",
        "angular momentum",
        "kinetic energy",
    ] {
        assert!(
            harness.query_by_label(english).is_none(),
            "'{english}' on screen in German"
        );
    }
    set_language(Language::English);
}
