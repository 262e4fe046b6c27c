//! The instruments: tape measure, probe, field view, stopwatch, protractor.

use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable};
use newtonlab_app::App;
use physics::{DVec2, Particle, Scene, World};

use crate::common::{
    click_canvas, example_scene, harness, pendulum_period, play_frames, small_ball,
};

/// The tape measure: M takes it up; a drag from empty space to a ball lays it, the end
/// on the ball holding to it; its reading is the distance and direction between its
/// ends, and follows the ball when it moves. P takes up the probe, placed at the view's
/// centre for the keyboard, moved a grid step by an arrow key, and put where clicked.
#[test]
fn the_tape_measure_follows_a_ball_and_the_probe_reads_the_field_where_it_is() {
    use newtonlab_app::canvas::{Instrument, Mark, tape_reading};
    let mut harness = harness(App::new(small_ball()));
    harness.key_press(Key::M);
    harness.run();
    assert_eq!(
        harness.state().canvas.instruments.active,
        Some(Instrument::Tape)
    );
    let app = harness.state();
    let rect = app.canvas.rect;
    let ball = app.canvas.view.to_screen(rect, DVec2::ZERO);
    let start = ball + egui::vec2(-150.0, 100.0);
    let from = app.canvas.view.to_world(rect, start);
    harness.hover_at(start);
    harness.run();
    harness.drag_at(start);
    harness.run();
    harness.hover_at(ball);
    harness.run();
    harness.drop_at(ball);
    harness.run();
    let tape = harness.state().canvas.instruments.tape.expect("laid");
    assert_eq!(
        tape.0,
        Mark::Point(from),
        "the first end where the drag began"
    );
    assert_eq!(tape.1, Mark::Particle(0), "the second end on the ball");
    let (length, angle) = tape_reading(tape, &[DVec2::ZERO]).expect("a reading");
    assert!((length - from.length()).abs() < 1e-12, "{length} m");
    let expected = (-from.y).atan2(-from.x).to_degrees();
    assert!(
        (angle - expected).abs() < 1e-9,
        "{angle}° against {expected}°"
    );
    play_frames(&mut harness, 4);
    let app = harness.state();
    let moved = app
        .runner
        .simulation()
        .expect("running")
        .positions()
        .to_vec();
    let (length, _) = tape_reading(tape, &moved).expect("a reading");
    assert!(
        (length - from.distance(moved[0])).abs() < 1e-12,
        "follows the ball"
    );
    assert!(moved[0].x > 0.3, "the ball moved: {}", moved[0]);
    assert!(tape_reading(tape, &moved).expect("a reading").0 > 0.0);

    harness.key_press(Key::P);
    harness.run();
    let instruments = &harness.state().canvas.instruments;
    assert_eq!(
        instruments.active,
        Some(Instrument::Probe),
        "P takes up the probe"
    );
    let centre = harness.state().canvas.view.center;
    assert_eq!(instruments.probe, Some(centre), "at the view's centre");
    harness.key_press(Key::ArrowRight);
    harness.run();
    let probe = harness.state().canvas.instruments.probe.expect("placed");
    assert!(
        probe.x > centre.x && (probe.y - centre.y).abs() < 1e-12,
        "moved right: {probe}"
    );
    let rect = harness.state().canvas.rect;
    // A point clear of the tape's reading, where a click copies the reading instead
    // (where the reading lies depends on how far the ball has gone).
    let readings = &harness.state().canvas.instruments.readings;
    let at = [(40.0, 30.0), (40.0, -120.0), (-160.0, -120.0)]
        .map(|(x, y)| rect.center() + egui::vec2(x, y))
        .into_iter()
        .find(|p| readings.iter().all(|(r, _)| !r.expand(8.0).contains(*p)))
        .expect("a point clear of the readings");
    let world = harness.state().canvas.view.to_world(rect, at);
    click_canvas(&mut harness, at);
    assert_eq!(
        harness.state().canvas.instruments.probe,
        Some(world),
        "where clicked"
    );
    harness.key_press(Key::P);
    harness.run();
    assert_eq!(
        harness.state().canvas.instruments.active,
        None,
        "P again puts it away"
    );
}

/// The Measure menu turns the electric field view on, and the canvas draws it.
#[test]
fn the_measure_menu_turns_on_the_field_view() {
    let scene = example_scene("charged-pair");
    let mut harness = harness(App::new(scene));
    harness.get_by_label("Measure").click();
    harness.run();
    harness.get_by_label_contains("Electric field view").click();
    harness.run();
    assert_eq!(
        harness.state().canvas.instruments.field_view,
        Some(newtonlab_app::FieldKind::Electric)
    );
}

/// The stopwatch (T), set to start at the first impact and stop at the second, times a ball's
/// bounce on the floor: between two elastic impacts it flies 2 √(2h/g) (0.5997 s for a
/// drop of h = 0.441 m; impacts are located to 1e-9 s, and 1e-8 s allows the rounding).
#[test]
fn the_stopwatch_times_a_bounce_between_two_impacts() {
    use newtonlab_app::stopwatch::{State, Trigger};
    let world = World {
        gravitation: false,
        electrostatics: false,
        bounds: Some(physics::Bounds {
            min: [-5.0, 0.0].into(),
            max: [5.0, 10.0].into(),
            friction: 0.0,
            static_friction: None,
        }),
        ..World::default()
    };
    let scene = Scene::new().with_world(world).with_particle(
        Particle::new("ball", 1.0)
            .radius(0.1)
            .position([0.0, 0.541]),
    );
    let mut harness = harness(App::new(scene));
    harness.key_press(Key::T);
    harness.run();
    assert!(harness.state().stopwatch.shown, "T shows it");
    {
        let watch = &mut harness.state_mut().stopwatch;
        watch.start_on = Trigger::Impact;
        watch.stop_on = Trigger::Impact;
        watch.stop_nth = 2;
    }
    harness.get_by_label("Start").click();
    harness.run();
    assert_eq!(harness.state().stopwatch.state, State::Armed);
    play_frames(&mut harness, 12);
    let watch = &harness.state().stopwatch;
    assert_eq!(watch.state, State::Stopped, "stopped by the second impact");
    let flight = 2.0 * (2.0 * 0.441 / 9.81_f64).sqrt();
    assert!(
        (watch.reading - flight).abs() < 1e-8,
        "{} s, theory {flight} s",
        watch.reading
    );
}

/// The 60° pendulum on its 2 m rod (the example): a light gate laid down from the pivot
/// (the tape's line) is crossed twice a period, so the stopwatch started on its 1st
/// crossing and stopped on its 3rd reads a full period, 4 √(L/g) K(sin 30°) = 3.0446 s,
/// to 1e-6 s (the crossings are located inside the step, not between frames); armed
/// before Play.
#[test]
fn a_gate_through_the_pivot_times_a_full_period() {
    use newtonlab_app::canvas::Mark;
    use newtonlab_app::stopwatch::Trigger;
    let mut harness = harness(App::new(example_scene("pendulum")));
    harness.key_press(Key::T);
    harness.run();
    {
        let app = harness.state_mut();
        app.canvas.instruments.tape =
            Some((Mark::Point(DVec2::ZERO), Mark::Point(DVec2::new(0.0, -3.0))));
        let watch = &mut app.stopwatch;
        watch.start_on = Trigger::Gate;
        watch.stop_on = Trigger::Gate;
        watch.stop_nth = 3;
    }
    start_and_read_the_period(&mut harness);
}

/// Start pressed before Play (the watch armed), then a swing and a half played: the
/// stopwatch has stopped on the gate's third crossing and reads the 60° pendulum's
/// period, 4 √(L/g) K(sin 30°) with L = 2 m, to 1e-6 s.
fn start_and_read_the_period(harness: &mut Harness<'_, App>) {
    use newtonlab_app::stopwatch::State;
    harness.get_by_label("Start").click();
    harness.run();
    assert_eq!(
        harness.state().stopwatch.state,
        State::Armed,
        "armed before Play"
    );
    play_the_period(harness);
}

/// A swing and a half played: the stopwatch has stopped on the gate's third crossing and
/// reads the 60° pendulum's period, 4 √(L/g) K(sin 30°) with L = 2 m, to 1e-6 s.
fn play_the_period(harness: &mut Harness<'_, App>) {
    use newtonlab_app::stopwatch::State;
    play_frames(harness, 45);
    let watch = &harness.state().stopwatch;
    assert_eq!(watch.state, State::Stopped, "stopped by the third crossing");
    let period = pendulum_period(2.0, 60.0);
    assert!(
        (watch.reading - period).abs() < 1e-6,
        "{} s, theory {period} s",
        watch.reading
    );
}

/// The tape measure is a tool like the others, and its ends snap to the scene's fixed
/// points: laid by a drag from 4 pixels off the pendulum's pivot, its first end is the
/// pivot exactly, and as a light gate from there straight down it times a full period
/// (the 1st to the 3rd crossing) to 1e-6 s of the elliptic integral's. Choosing the
/// Particle tool puts the tape measure away; so does Escape.
#[test]
fn a_tape_laid_by_hand_snaps_to_the_pivot_and_times_a_period() {
    use newtonlab_app::canvas::Mark;
    use newtonlab_app::stopwatch::Trigger;
    let mut harness = harness(App::new(example_scene("pendulum")));
    harness.get_by_label("Tape measure").click();
    harness.run();
    assert_eq!(
        harness.state().canvas.instruments.active,
        Some(newtonlab_app::Instrument::Tape),
        "the tool bar chooses it"
    );
    let (rect, view) = (harness.state().canvas.rect, harness.state().canvas.view);
    let pivot = view.to_screen(rect, DVec2::ZERO);
    let below = view.to_screen(rect, DVec2::new(0.0, -3.0));
    let (from, to) = (pivot + egui::vec2(3.0, -2.5), below);
    crate::common::drag_across(&mut harness, from, to);
    let tape = harness.state().canvas.instruments.tape.expect("laid");
    assert_eq!(tape.0, Mark::Point(DVec2::ZERO), "snapped to the pivot");
    harness.key_press(Key::T);
    harness.run();
    assert_eq!(
        harness.state().canvas.instruments.active,
        Some(newtonlab_app::Instrument::Tape),
        "still measuring"
    );
    harness.get_by_label("period at the gate").click();
    harness.run();
    let watch = &harness.state().stopwatch;
    assert_eq!(
        (
            watch.start_on,
            watch.start_nth,
            watch.stop_on,
            watch.stop_nth
        ),
        (Trigger::Gate, 1, Trigger::Gate, 3)
    );
    start_and_read_the_period(&mut harness);
    harness.get_by_label("Reset").click();
    harness.run();
    harness.get_by_label("Particle").click();
    harness.run();
    assert_eq!(
        harness.state().canvas.instruments.active,
        None,
        "a tool leaves the tape"
    );
    assert_eq!(harness.state().canvas.tool, newtonlab_app::Tool::Particle);
    harness.get_by_label("Tape measure").click();
    harness.run();
    harness.key_press(Key::Escape);
    harness.run();
    assert_eq!(
        harness.state().canvas.instruments.active,
        None,
        "Escape leaves it"
    );
}

/// Lap mode with a typed event: `rod.angle crosses 0 down` happens once a period, so
/// every lap is a period and so is their mean (to 1e-6 s), while the watch runs on.
#[test]
fn laps_of_an_event_are_periods() {
    use newtonlab_app::stopwatch::{State, Trigger};
    let mut harness = harness(App::new(example_scene("pendulum")));
    {
        let watch = &mut harness.state_mut().stopwatch;
        watch.shown = true;
        watch.start_on = Trigger::Event;
        watch.stop_on = Trigger::Event;
        watch.stop_nth = 2;
        watch.event = "rod.angle crosses 0 down".to_owned();
        watch.lap_mode = true;
    }
    harness.run();
    harness.get_by_label("Start").click();
    harness.run();
    play_frames(&mut harness, 100);
    let watch = &harness.state().stopwatch;
    assert!(matches!(watch.state, State::Running(_)), "laps run on");
    assert!(watch.laps.len() >= 2, "{:?}", watch.laps);
    let period = pendulum_period(2.0, 60.0);
    for lap in watch.laps.iter().chain(watch.mean_lap().as_ref()) {
        assert!((lap - period).abs() < 1e-6, "{lap} s, theory {period} s");
    }
}

/// A typo in the event is said in the window as it is typed, before Play, and the watch
/// does not start on it (it would run on past an event it never sees); the typo
/// corrected, the words go at once and it starts. The value takes arithmetic, as the
/// inspector's fields do.
#[test]
fn a_bad_event_is_named_in_the_stopwatch_as_it_is_typed() {
    use newtonlab_app::stopwatch::{State, Trigger};
    let mut harness = harness(App::new(example_scene("pendulum")));
    {
        let watch = &mut harness.state_mut().stopwatch;
        watch.shown = true;
        watch.start_on = Trigger::Event;
        watch.event = "Bob.vx crosses 0".to_owned();
    }
    harness.run();
    harness.get_by_label_contains("no particle named 'Bob'");
    assert!(
        harness.get_by_label("Start").accesskit_node().is_disabled(),
        "no start on a typo"
    );
    harness.get_by_label("event").focus();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness
        .get_by_label("event")
        .type_text("bob.vx crosses 2*0 down");
    harness.run();
    assert!(
        harness
            .query_by_label_contains("no particle named")
            .is_none(),
        "the words go with the typo"
    );
    harness.get_by_label("Start").click();
    harness.run();
    assert_eq!(harness.state().stopwatch.state, State::Armed);
    play_frames(&mut harness, 30);
    let watch = &harness.state().stopwatch;
    assert!(
        matches!(watch.state, State::Running(_)),
        "started at the turn"
    );
    assert!(watch.problem.is_none());
}

/// The protractor (A): a drag lays the vertex and the first arm, a second drag the
/// second arm; it reads the angle between them.
#[test]
fn the_protractor_reads_the_angle_between_its_arms() {
    use newtonlab_app::canvas::protractor_reading;
    let mut harness = harness(App::new(small_ball()));
    harness.key_press(Key::A);
    harness.run();
    let rect = harness.state().canvas.rect;
    let vertex = rect.center() + egui::vec2(-300.0, 200.0);
    let (first, second) = (
        vertex + egui::vec2(200.0, 0.0),
        vertex + egui::vec2(100.0, -100.0),
    );
    crate::common::drag_across(&mut harness, vertex, first);
    crate::common::drag_across(&mut harness, vertex, second);
    let protractor = harness.state().canvas.instruments.protractor.expect("laid");
    assert!(protractor.2.is_some(), "both arms");
    let angle = protractor_reading(protractor, &[DVec2::ZERO]).expect("a reading");
    assert!((angle - 45.0).abs() < 1e-9, "{angle}°");
    // Its label rounds to what hand-laid arms mean; the full value is a click away.
    let (label, full) = harness.state().canvas.instruments.readings[0].clone();
    assert_eq!(full, format!("{angle}°"));
    harness.hover_at(label.center());
    harness.run();
    harness.drag_at(label.center());
    harness.run();
    harness.drop_at(label.center());
    harness.run();
    let said = &harness.state().announcer.text;
    assert!(said.contains(&full) && said.contains("copied"), "{said}");
}

/// A scene keeps its instruments: the pendulum saved with a light gate down from the
/// pivot, a protractor from the vertical to the bob and the stopwatch set for a period
/// reopens with them laid out, the watch shown and armed, so that Play alone reads the
/// period, 4 √(L/g) K(sin 30°), to 1e-6 s. A share link carries them too.
#[test]
fn a_saved_scene_reopens_with_its_instruments_in_place_and_the_watch_armed() {
    use newtonlab_app::canvas::Mark;
    use newtonlab_app::stopwatch::{State, Trigger};
    let mut teacher = harness(App::new(example_scene("pendulum")));
    let bob = teacher
        .state()
        .document
        .scene()
        .particles
        .iter()
        .position(|p| p.name == "bob")
        .unwrap();
    {
        let app = teacher.state_mut();
        let instruments = &mut app.canvas.instruments;
        instruments.tape = Some((Mark::Point(DVec2::ZERO), Mark::Point(DVec2::new(0.0, -3.0))));
        instruments.protractor = Some((
            Mark::Point(DVec2::ZERO),
            Mark::Point(DVec2::new(0.0, -1.0)),
            Some(Mark::Particle(bob)),
        ));
        app.stopwatch.shown = true;
        app.stopwatch.period_at_the_gate();
    }
    let folder = std::env::temp_dir().join(format!("newtonlab-keep-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let path = folder.join("pendulum.toml");
    teacher.state_mut().save_path(path.to_str().unwrap());
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_dir_all(&folder).ok();
    assert!(
        text.contains("protractor = [[0.0, 0.0], [0.0, -1.0], \"bob\"]"),
        "{text}"
    );
    assert!(
        text.contains("[instruments.stopwatch]\nstart = \"gate\""),
        "{text}"
    );

    let mut student = harness(App::new(Scene::from_toml(&text).unwrap()));
    let app = student.state();
    assert_eq!(
        app.canvas.instruments.tape,
        teacher.state().canvas.instruments.tape
    );
    assert_eq!(
        app.canvas.instruments.protractor.map(|p| p.2),
        Some(Some(Mark::Particle(bob))),
        "the arm follows the bob"
    );
    let watch = &app.stopwatch;
    assert!(watch.shown, "the stopwatch is out");
    assert_eq!(watch.state, State::Armed, "armed: Play is enough");
    assert_eq!(
        (watch.start_on, watch.stop_on, watch.stop_nth),
        (Trigger::Gate, Trigger::Gate, 3)
    );
    play_the_period(&mut student);

    // What cannot be kept is kept as the hand: an event that does not read.
    let app = teacher.state_mut();
    app.stopwatch.stop_on = Trigger::Event;
    app.stopwatch.event = "bob.x crosses".to_owned();
    app.perform(newtonlab_app::Action::ShareLink);
    let Some(newtonlab_app::links::LinkWindow::Share(Ok(fragment))) = app.link.clone() else {
        panic!("a link");
    };
    let shared = newtonlab_app::share::open(&fragment).unwrap();
    let kept = shared.instruments.and_then(|i| i.stopwatch).unwrap();
    assert_eq!(
        (kept.start, kept.stop, kept.event),
        (Trigger::Gate, Trigger::Hand, None)
    );
}

/// "Ask about this": the stopwatch timing the 60° pendulum from Play to the bob's second
/// turning point (`bob.vx crosses 0`, the 2nd: a full period) adds a question to a new
/// lesson whose measure is that instant, and the simulation's answer key is the
/// stopwatch's reading (to 1e-9 s: both are the event located inside its step), and the
/// elliptic integral's period to 1e-6 s. Back in the editor, one undo takes it away.
#[test]
fn ask_about_this_turns_the_stopwatchs_reading_into_a_lesson_question() {
    use newtonlab_app::stopwatch::{State, Trigger};
    let mut harness = harness(App::new(example_scene("pendulum")));
    {
        let watch = &mut harness.state_mut().stopwatch;
        watch.shown = true;
        watch.start_on = Trigger::Play;
        watch.stop_on = Trigger::Event;
        watch.stop_nth = 2;
        watch.event = "bob.vx crosses 0".to_owned();
    }
    harness.run();
    harness.get_by_label("Start").click();
    harness.run();
    play_frames(&mut harness, 45);
    let reading = harness.state().stopwatch.reading;
    assert_eq!(harness.state().stopwatch.state, State::Stopped);
    harness.get_by_label("Ask about this").click();
    harness.run();
    let scene = harness.state().document.scene().clone();
    let lesson = scene
        .lesson
        .clone()
        .expect("a lesson made for the question");
    let question = &lesson.questions[0];
    assert_eq!(
        (
            question.id.as_str(),
            question.measure.as_str(),
            question.unit.as_str()
        ),
        ("q1", "t at bob.vx crosses 0 #2", "s")
    );
    let key = lesson.answers(&scene).unwrap()[0].clone().unwrap();
    assert!(
        (key - reading).abs() < 1e-9,
        "key {key} s, stopwatch {reading} s"
    );
    let period = pendulum_period(2.0, 60.0);
    assert!(
        (key - period).abs() < 1e-6,
        "key {key} s, theory {period} s"
    );
    assert!(scene.validate().is_empty(), "a valid lesson");
    harness.state_mut().reset();
    harness.state_mut().undo();
    assert!(harness.state().document.scene().lesson.is_none(), "undone");
}

/// The probe's box is drawn while the probe is in hand and not once another tool is
/// taken up (its cross stays where it was put); its lines speak the user's language and
/// split a pair as the language does.
#[test]
fn the_probe_reads_while_in_hand_and_in_the_users_language() {
    use newtonlab_app::canvas::probe_lines;
    use newtonlab_app::i18n::{Language, set_language};
    let mut harness = harness(App::new(small_ball()));
    harness.key_press(Key::P);
    harness.run();
    let instruments = &harness.state().canvas.instruments;
    assert!(instruments.shows_probe_reading(), "in hand");
    let put = instruments.probe;
    harness.get_by_label("Spring").click();
    harness.run();
    let instruments = &harness.state().canvas.instruments;
    assert!(
        !instruments.shows_probe_reading(),
        "put away for the spring"
    );
    assert_eq!(instruments.probe, put, "where it was put");
    let scene = harness.state().document.scene().clone();
    let at = physics::DVec2::new(1.5, -2.0);
    set_language(Language::German);
    let lines = probe_lines(&scene, &[physics::DVec2::ZERO], at);
    set_language(Language::English);
    assert_eq!(lines[0], "bei (1,5; -2) m");
    assert!(lines[3].starts_with("Gravitationspotential"), "{lines:?}");
    let english = probe_lines(&scene, &[physics::DVec2::ZERO], at);
    assert_eq!(english[0], "at (1.5, -2) m");
}
