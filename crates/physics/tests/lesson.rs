//! Lessons in the scene format and their answer key: every shipped lesson written and read
//! back the same in TOML and JSON, and its answers from one run agree with theory.

use std::f64::consts::PI;

use physics::{Scene, Verdict, example};

fn lesson_scene(name: &str) -> Scene {
    example(name).expect("a lesson").scene().expect("it loads")
}

const LESSONS: [&str; 5] = [
    "lesson-galileo-incline",
    "lesson-projectile-range",
    "lesson-spring-period",
    "lesson-collisions",
    "lesson-block-slide",
];

#[test]
fn every_lesson_is_written_and_read_back_the_same_in_toml_and_json() {
    for name in LESSONS {
        let scene = lesson_scene(name);
        assert!(scene.lesson.is_some(), "{name}");
        let toml = Scene::from_toml(&scene.to_toml()).expect("TOML reads back");
        assert_eq!(toml, scene, "{name} in TOML");
        let json = Scene::from_json(&scene.to_json()).expect("JSON reads back");
        assert_eq!(json, scene, "{name} in JSON");
    }
}

#[test]
fn the_spring_lesson_measures_theory_s_period_and_top_speed() {
    let scene = lesson_scene("lesson-spring-period");
    let lesson = scene.lesson.as_ref().expect("a lesson");
    let answers = lesson.answers(&scene).expect("a run");
    let (m, k, amplitude) = (0.5_f64, 20.0_f64, 0.2);
    let period = 2.0 * PI * (m / k).sqrt();
    let top = amplitude * (k / m).sqrt();
    // RK4 at 1 ms on ω = 6.3 rad/s: the period's located maxima to 1e-9 s, the top speed
    // (read between steps) to 1e-6 m/s; the tolerance a teacher sets is 0.01.
    let got = answers[0].as_ref().expect("a period");
    assert!((got - period).abs() < 1e-7, "{got} against {period}");
    let got = answers[1].as_ref().expect("a top speed");
    assert!((got - top).abs() < 1e-5, "{got} against {top}");
    assert_eq!(
        Verdict::of(period, answers[0].clone().unwrap_or(0.0), 0.01),
        Verdict::Right
    );
}

#[test]
fn a_question_in_another_unit_is_answered_in_it() {
    let mut scene = lesson_scene("lesson-spring-period");
    let lesson = scene.lesson.as_mut().expect("a lesson");
    lesson.questions[0].unit = "ms".to_owned();
    lesson.questions[1].unit = "cm/s".to_owned();
    assert!(scene.validate().is_empty(), "{:?}", scene.validate());
    let lesson = scene.lesson.as_ref().expect("a lesson");
    let answers = lesson.answers(&scene).expect("a run");
    let period = 2000.0 * PI * (0.5_f64 / 20.0).sqrt();
    let got = answers[0].as_ref().expect("a period");
    assert!((got - period).abs() < 1e-4, "{got} ms against {period}");
    let answer = lesson.questions[0].read_answer("0.9935 s").expect("a time");
    assert!((answer - 993.5).abs() < 1e-9);
}
