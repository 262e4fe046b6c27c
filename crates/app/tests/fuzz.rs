//! Fuzzing the app's untrusted inputs. Share links: valid links with characters changed,
//! cut or added, and random fragments, are decoded without a panic, each to a scene, an
//! error in words, or "not a link". Typed fields: random text typed into the mass field
//! and committed is either applied (a valid mass) or refused with a reason; the scene is
//! never left invalid. `NEWTONLAB_FUZZ_INPUTS` scales the link run (default 20,000).

#![expect(
    clippy::float_cmp,
    reason = "a refused entry leaves the mass exactly as it was"
)]

use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use newtonlab_app::{App, Selection, share};
use physics::{EXAMPLES, Particle, Scene, World};
use proptest::prelude::*;
use proptest::strategy::ValueTree as _;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

fn runner(cases: u32) -> TestRunner {
    let config = Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    };
    TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha))
}

#[test]
fn mutated_share_links_never_panic() {
    let inputs: u32 = std::env::var("NEWTONLAB_FUZZ_INPUTS")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(20_000);
    let links: Vec<String> = EXAMPLES
        .iter()
        .filter(|e| !e.name.starts_with("ball-pit") && e.file_text().is_some())
        .map(|e| share::encode(&e.scene().expect("valid")))
        .collect();
    let alphabet: Vec<char> =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_=#%&?+/ \u{e9}"
            .chars()
            .collect();
    let edit = (
        0.0..1.0_f64,
        0usize..6,
        prop::collection::vec(0..alphabet.len(), 0..6),
    );
    let strategy = (
        0..links.len(),
        prop::collection::vec(edit, 0..6),
        any::<bool>(),
    );
    let result = runner(inputs).run(&strategy, |(pick, edits, prefix)| {
        let mut link: Vec<char> = links[pick].chars().collect();
        for (at, cut, insert) in edits {
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                clippy::cast_precision_loss,
                reason = "a fraction of a length"
            )]
            let start = ((link.len() as f64) * at) as usize;
            let end = (start + cut).min(link.len());
            link.splice(start..end, insert.iter().map(|&k| alphabet[k]));
        }
        let mut text: String = link.into_iter().collect();
        if prefix {
            text.insert(0, '#');
        }
        // Any answer is fine; a panic fails the case.
        let _ = share::decode(&text);
        Ok(())
    });
    if let Err(failure) = result {
        panic!("{failure}");
    }
}

#[test]
fn random_text_typed_into_a_field_is_applied_or_refused() {
    let scene = Scene::new()
        .with_world(World::weightless())
        .with_particle(Particle::new("ball", 1.0));
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .build_ui_state(|ui, app: &mut App| app.ui(ui), App::new(scene));
    harness.state_mut().selection = Some(Selection::Particle(0));
    harness.run();
    let texts = prop_oneof![
        "[0-9eE.+-]{0,12}",
        "[ -~]{0,16}",
        Just("1e-300".to_owned()),
        Just("1e100".to_owned()),
        Just("NaN".to_owned()),
        Just("inf".to_owned()),
        Just("-0".to_owned()),
    ];
    let mut generator = runner(300);
    for _ in 0..300 {
        let text = texts.new_tree(&mut generator).expect("generated").current();
        let before = harness.state().document.scene().particles[0].mass;
        harness.get_by_label("mass").focus();
        harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
        harness.get_by_label("mass").type_text(&text);
        harness.key_press(Key::Enter);
        harness.run();
        let scene = harness.state().document.scene();
        assert!(
            scene.validate().is_empty(),
            "typed {text:?}: the scene stays valid"
        );
        let mass = scene.particles[0].mass;
        // What the field reads the text as (numbers, arithmetic, units: `units.rs`,
        // tested against its cases there); here, that the field applies exactly that.
        let accepted = newtonlab_app::units::parse(&text, "kg")
            .ok()
            .filter(|v| physics::check_value(physics::Rule::Positive, "mass", *v).is_ok());
        match accepted {
            Some(value) if value.to_bits() != before.to_bits() => {
                assert_eq!(mass, value, "typed {text:?}: applied");
            }
            _ => assert_eq!(mass, before, "typed {text:?}: refused, unchanged"),
        }
    }
}
