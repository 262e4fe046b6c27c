//! The shipped lessons as a student uses them: each question answered in the lesson panel
//! with the value theory (or an integration written apart from the simulation) gives, and
//! checked right; a wrong answer checked "not yet"; a slider moved, and the answer key
//! moving with it.

use std::f64::consts::PI;

use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable};
use newtonlab_app::App;

use crate::common::{example_scene, tall_harness};

const G: f64 = 9.81;

/// The lesson example `name` open in the app.
fn open(name: &str) -> Harness<'static, App> {
    let harness = tall_harness(App::new(example_scene(name)));
    assert!(
        !harness.state().panels.inspector,
        "a lesson opens in the student's view"
    );
    harness
}

/// Types `answer` to question `number` (from 1) and presses Enter: Check.
fn answer(harness: &mut Harness<'_, App>, number: usize, answer: &str) {
    let lesson = harness.state().document.scene().lesson.clone();
    let question = &lesson.expect("a lesson").questions[number - 1];
    let prompt = format!("{number}. {}", question.prompt);
    harness.get_by_label(&prompt).focus();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness.get_by_label(&prompt).type_text(answer);
    harness.key_press(egui::Key::Enter);
    harness.run();
}

/// What Check said of each question, in order (`None`: not checked).
fn verdicts(harness: &Harness<'_, App>) -> Vec<Option<String>> {
    harness
        .state()
        .lesson
        .checked
        .iter()
        .map(|c| c.as_ref().map(|c| format!("{c:?}")))
        .collect()
}

/// Every answer right: the panel says so, once per question.
fn all_right(harness: &Harness<'_, App>, count: usize) {
    let said = verdicts(harness);
    assert_eq!(said.len(), count, "one result per question");
    for verdict in &said {
        let verdict = verdict.as_deref().unwrap_or("unchecked");
        assert!(verdict.starts_with("Verdict(Right"), "{said:?}");
    }
    assert_eq!(
        harness.get_all_by_label("Right").count(),
        count,
        "each shown"
    );
}

#[test]
fn galileo_incline_rolling_times_from_theory_are_right() {
    let mut harness = open("lesson-galileo-incline");
    let slope = 20_f64.to_radians().sin() * G;
    let (disc, ring) = (slope / 1.5, slope / 2.0);
    answer(&mut harness, 1, &format!("{:.3} s", (4.0 / disc).sqrt()));
    answer(
        &mut harness,
        2,
        &format!("{:.0} ms", 1000.0 * (4.0 / ring).sqrt()),
    );
    answer(&mut harness, 3, &format!("{:.3} m/s", (4.0 * disc).sqrt()));
    all_right(&harness, 3);
    // The disc's speed is revealed; its times are not.
    harness.get_by_label_contains("The simulation measures 2.99");
    assert_eq!(
        harness
            .query_all_by_label_contains("The simulation measures")
            .count(),
        1,
        "only the revealed value"
    );
    // A ring's time for the disc is not yet right; the verdict never shows the number.
    answer(&mut harness, 1, &format!("{:.3}", (4.0 / ring).sqrt()));
    harness.get_by_label_contains("Not yet");
}

#[test]
fn a_spring_period_and_top_speed_from_theory_are_right() {
    let mut harness = open("lesson-spring-period");
    let (m, k, amplitude) = (0.5_f64, 20.0_f64, 0.2);
    answer(
        &mut harness,
        1,
        &format!("{:.4}", 2.0 * PI * (m / k).sqrt()),
    );
    answer(
        &mut harness,
        2,
        &format!("{:.1} cm/s", 100.0 * amplitude * (k / m).sqrt()),
    );
    all_right(&harness, 2);
    // Half the period is not yet right; within ten tolerances it is close.
    answer(&mut harness, 1, &format!("{:.4}", PI * (m / k).sqrt()));
    harness.get_by_label_contains("Not yet");
    answer(
        &mut harness,
        1,
        &format!("{:.4}", 2.0 * PI * (m / k).sqrt() + 0.05),
    );
    let said = verdicts(&harness);
    assert!(
        said[0]
            .as_deref()
            .is_some_and(|v| v.starts_with("Verdict(Close")),
        "{said:?}"
    );
}

/// The velocities after a collision of restitution `e`: cart 1 of mass `m1` at `v` into
/// cart 2 of mass `m2` at rest.
fn after(m1: f64, m2: f64, v: f64, e: f64) -> (f64, f64) {
    (
        (m1 - e * m2) * v / (m1 + m2),
        (1.0 + e) * m1 * v / (m1 + m2),
    )
}

#[test]
fn collisions_follow_the_restitution_the_student_sets() {
    let mut harness = open("lesson-collisions");
    let (a, b) = after(1.0, 3.0, 2.0, 0.5);
    answer(&mut harness, 1, &format!("{b}"));
    answer(&mut harness, 2, &format!("{a} m/s"));
    answer(&mut harness, 3, "2 N·s");
    let energy = 0.5 * a * a + 0.5 * 3.0 * b * b;
    answer(&mut harness, 4, &format!("{:.0} mJ", energy * 1000.0));
    all_right(&harness, 4);
    // The restitution slider one step up (the arrow key): the scene changes, one undo step,
    // and the answer key follows the scene as the student set it.
    // The lesson panel's first slider (the panel is at the left; the tool bar's and the
    // time bar's sliders are not in it).
    let slider = harness
        .get_all_by_role(egui::accesskit::Role::Slider)
        .filter(|s| s.rect().left() < newtonlab_app::lesson::WIDTH)
        .min_by(|a, b| a.rect().top().total_cmp(&b.rect().top()))
        .expect("the restitution slider");
    slider.focus();
    harness.run();
    harness.key_press(egui::Key::ArrowRight);
    harness.run();
    let restitution = harness.state().document.scene().world.restitution;
    assert_eq!(restitution, 0.6, "a step of the slider, as typed");
    // 0.75 m/s against 0.8: within ten tolerances.
    answer(&mut harness, 1, &format!("{b}"));
    harness.get_by_label_contains("Close");
    let (_, b) = after(1.0, 3.0, 2.0, 0.6);
    answer(&mut harness, 1, &format!("{b}"));
    assert!(
        verdicts(&harness)[0]
            .as_deref()
            .is_some_and(|v| v.starts_with("Verdict(Right"))
    );
}

#[test]
fn a_block_slides_as_theory_says_and_a_wrong_unit_is_told() {
    let mut harness = open("lesson-block-slide");
    let (sin, cos) = 30_f64.to_radians().sin_cos();
    let a = G * (sin - 0.3 * cos);
    let along = (2.090_063_509_461_097 - 1.18) / cos;
    answer(&mut harness, 1, &format!("{a:.3}"));
    answer(
        &mut harness,
        2,
        &format!("{:.4} s", (2.0 * along / a).sqrt()),
    );
    all_right(&harness, 2);
    answer(&mut harness, 1, "2.3 kg");
    harness.get_by_label_contains("'kg' is no function, constant or unit");
}

/// The range of a ball thrown at `speed` and `angle` (degrees) from the ground against a
/// quadratic drag `c` (kg/m) on mass `m`: RK4 at 1e-4 s, the landing found by linear
/// interpolation between the two steps around it.
fn range_in_air(speed: f64, angle: f64, m: f64, c: f64) -> f64 {
    let (sin, cos) = angle.to_radians().sin_cos();
    let mut s = [0.0, 0.0, speed * cos, speed * sin];
    let f = |s: [f64; 4]| {
        let v = s[2].hypot(s[3]);
        [s[2], s[3], -c / m * v * s[2], -G - c / m * v * s[3]]
    };
    let h = 1e-4;
    loop {
        let k1 = f(s);
        let at = |k: [f64; 4], w: f64| std::array::from_fn(|i| s[i] + w * h * k[i]);
        let k2 = f(at(k1, 0.5));
        let k3 = f(at(k2, 0.5));
        let k4 = f(at(k3, 1.0));
        let next: [f64; 4] =
            std::array::from_fn(|i| s[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        if next[1] < 0.0 && next[3] < 0.0 {
            let w = s[1] / (s[1] - next[1]);
            return s[0] + w * (next[0] - s[0]);
        }
        s = next;
    }
}

#[test]
fn ranges_with_and_without_air_from_theory_and_an_integration_apart_are_right() {
    let mut harness = open("lesson-projectile-range");
    let v = 35.0_f64;
    let theta = 45_f64.to_radians();
    answer(
        &mut harness,
        1,
        &format!("{:.2} m", v * v * (2.0 * theta).sin() / G),
    );
    answer(
        &mut harness,
        2,
        &format!("{:.2}", range_in_air(35.0, 45.0, 0.145, 0.00077)),
    );
    answer(
        &mut harness,
        3,
        &format!("{:.3}", (v * theta.sin()).powi(2) / (2.0 * G)),
    );
    all_right(&harness, 3);
}

/// Every example's description (the inspector's *About this scene*) and lesson drawn: a
/// letter the app's fonts lack would stop the frame.
#[test]
fn every_example_opens_with_its_description_and_lesson_drawn() {
    for example in physics::EXAMPLES.iter().filter(|e| e.file_text().is_some()) {
        let mut app = App::new(example_scene(example.name));
        app.panels.inspector = true;
        let harness = tall_harness(app);
        let scene = harness.state().document.scene().clone();
        if let Some(lesson) = &scene.lesson {
            harness.get_by_label(&lesson.title);
        }
        assert!(
            scene.description.is_some(),
            "{} has a description",
            example.name
        );
    }
}

/// File → Export worksheet with answer key writes a PDF with one page more than the
/// worksheet alone; a scene without a lesson has the item greyed.
#[test]
fn the_file_menu_exports_the_worksheet_and_its_key() {
    let folder =
        std::env::temp_dir().join(format!("newtonlab-worksheet-app-{}", std::process::id()));
    std::fs::create_dir_all(&folder).expect("a folder");
    let mut harness = open("lesson-collisions");
    let mut pages = Vec::new();
    for (item, name) in [
        ("Export worksheet…", "sheet.pdf"),
        ("Export worksheet with answer key…", "keyed.pdf"),
    ] {
        harness.get_by_label("File").click();
        harness.run();
        harness.get_by_label(item).click();
        harness.run();
        harness.run();
        for (label, text) in [
            ("folder", folder.to_string_lossy().into_owned()),
            ("file name", name.to_owned()),
        ] {
            harness.get_by_label(label).focus();
            harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
            harness.get_by_label(label).type_text(&text);
            harness.run();
        }
        harness.get_by_label("Export").click();
        harness.run();
        let bytes = std::fs::read(folder.join(name)).expect("the worksheet was written");
        assert!(bytes.starts_with(b"%PDF-"), "a PDF");
        let text = String::from_utf8_lossy(&bytes);
        let count = text.split("/Count ").nth(1).and_then(|rest| {
            let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
            digits.parse::<usize>().ok()
        });
        pages.push(count.expect("a page count"));
    }
    assert_eq!(pages[1], pages[0] + 1, "the key on a page of its own");
    let mut plain = tall_harness(App::new(example_scene("pendulum")));
    plain.get_by_label("File").click();
    plain.run();
    assert!(
        plain
            .get_by_label("Export worksheet…")
            .accesskit_node()
            .is_disabled(),
        "no lesson, no worksheet"
    );
    std::fs::remove_dir_all(&folder).ok();
}

/// The lessons are in Examples → Lessons; one opens in the student's view, and the next
/// scene without a lesson brings the inspector back.
#[test]
fn a_lesson_opens_from_the_examples_menu_in_the_student_s_view() {
    let mut harness = tall_harness(App::new(example_scene("pendulum")));
    assert!(harness.state().panels.inspector, "the teacher's view");
    for label in [
        "Examples",
        "Lessons",
        "Lesson: a spring's period against its mass",
    ] {
        harness.get_by_label(label).click();
        harness.run();
    }
    assert!(
        harness.state().document.scene().lesson.is_some(),
        "the lesson"
    );
    assert!(!harness.state().panels.inspector, "the student's view");
    harness.get_by_label("A spring's period against its mass");
    for label in ["Examples", "Two balls colliding off-centre"] {
        harness.get_by_label(label).click();
        harness.run();
    }
    assert!(harness.state().panels.inspector, "the teacher's view again");
}

/// The rigid bodies' scenes are in Examples → Rigid bodies, out of the main list, which
/// would otherwise run past a laptop's screen.
#[test]
fn rigid_bodies_open_from_their_own_menu() {
    let mut harness = tall_harness(App::new(example_scene("pendulum")));
    for label in ["Examples", "Rigid bodies", "A box dropped on a box"] {
        harness.get_by_label(label).click();
        harness.run();
    }
    assert_eq!(harness.state().document.scene().bodies.len(), 2);
    harness.get_by_label("Examples").click();
    harness.run();
    assert!(
        harness.query_by_label("A box dropped on a box").is_none(),
        "not in the main list"
    );
}

/// The lessons' instruments come with them: Galileo's stopwatch, armed, starts on Play
/// and stops when the disc has rolled 2 m, at √(2 d / a) with a = g sin 20° / 1.5; the
/// spring's takes a lap at each highest point, each a period 2π √(m / k). Both to 1e-6 s
/// (the events are located inside the step; the rolling and the spring are exact to far
/// better).
#[test]
fn the_lessons_stopwatches_time_what_their_questions_ask() {
    use newtonlab_app::stopwatch::State;
    let mut harness = open("lesson-galileo-incline");
    assert!(
        harness.state().canvas.instruments.tape.is_some(),
        "the 2 m tape"
    );
    assert_eq!(harness.state().stopwatch.state, State::Armed);
    crate::common::play_frames(&mut harness, 30);
    let watch = &harness.state().stopwatch;
    assert_eq!(watch.state, State::Stopped, "stopped at 2 m");
    // The event's 2.2297 m is the 2 m mark rounded: the distance it means along the slope.
    let distance = (2.2297 - 0.350_311_814_900_906_24) / 20_f64.to_radians().cos();
    let time = (2.0 * distance / (20_f64.to_radians().sin() * G / 1.5)).sqrt();
    assert!(
        (watch.reading - time).abs() < 1e-6,
        "{} s, theory {time} s",
        watch.reading
    );

    let mut harness = open("lesson-spring-period");
    crate::common::play_frames(&mut harness, 60);
    let watch = &harness.state().stopwatch;
    let period = 2.0 * PI * (0.5_f64 / 20.0).sqrt();
    assert!(watch.laps.len() >= 3, "{:?}", watch.laps);
    for lap in watch.laps.iter().chain(watch.mean_lap().as_ref()) {
        assert!((lap - period).abs() < 1e-6, "{lap} s, theory {period} s");
    }
}
