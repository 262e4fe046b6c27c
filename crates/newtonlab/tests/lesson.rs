//! `newtonlab lesson` and a lesson in `check`: answers with units judged against the run
//! (theory's value right, near it close, far not yet), the exit codes of the contract, and
//! a bad lesson refused with each problem's line and column.

mod common;

use common::{assert_refused, newtonlab, scene_file, stderr, stdout};

/// A ball dropped from 4.905 m: it falls 4.905 m in exactly 1 s (g = 9.81).
const DROP: &str = r#"version = 1

[world]
gravity = [0.0, -9.81]

[simulation]
integrator = "rk4"
time_step = 0.001

[[particle]]
name = "ball"
mass = 1.0
radius = 0.1
position = [0.0, 4.905]

[lesson]
title = "A drop"
text = "Drop the ball. **How long** does it fall?"
until = 2.0

[[lesson.slider]]
field = "ball.mass"
min = 0.5
max = 5.0
step = 0.5

[[lesson.question]]
id = "fall_time"
prompt = "How long does the ball take to reach the ground?"
measure = "time at ball.y crosses 0 down"
unit = "s"
tolerance = 0.01

[[lesson.question]]
id = "impact_speed"
prompt = "How fast is it going then?"
measure = "ball.speed at ball.y crosses 0 down"
unit = "m/s"
tolerance = 0.05
reveal = true
"#;

fn answers(path: &str, answers: &[&str]) -> std::process::Output {
    let mut args = vec!["lesson", path];
    for answer in answers {
        args.extend(["--answer", answer]);
    }
    newtonlab(&args)
}

#[test]
fn answers_are_judged_against_the_run_in_any_unit_of_their_kind() {
    let (_dir, path) = scene_file("drop.toml", DROP);
    // Theory: t = 1 s, v = g t = 9.81 m/s.
    let output = answers(&path, &["fall_time=1.00 s", "impact_speed=981 cm/s"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(stdout(&output), "fall_time: right\nimpact_speed: right\n");
    // 0.05 s off is close (within ten tolerances), 0.2 s not yet; a bare number is in the
    // question's unit, and the order is the answers'.
    let output = answers(
        &path,
        &[
            "impact_speed=30 km/h",
            "fall_time=1.05",
            "fall_time=1200 ms",
        ],
    );
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(
        stdout(&output),
        "impact_speed: not yet\nfall_time: close\nfall_time: not yet\n"
    );
}

#[test]
fn without_answers_the_questions_are_listed_and_check_names_the_lesson() {
    let (_dir, path) = scene_file("drop.toml", DROP);
    let output = newtonlab(&["lesson", &path]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let text = stdout(&output);
    assert!(
        text.starts_with("A drop\nfall_time [s]: How long"),
        "{text}"
    );
    let output = newtonlab(&["check", &path]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(
        stdout(&output).contains("lesson 'A drop': 1 slider(s), 2 question(s)"),
        "{}",
        stdout(&output)
    );
}

#[test]
fn a_bad_answer_an_unknown_id_and_a_scene_without_a_lesson_exit_2() {
    let (_dir, path) = scene_file("drop.toml", DROP);
    for (answer, words) in [
        ("fall_time=2 kg", "must be a quantity in s"),
        (
            "fall=1",
            "no question of that id; its 2 question(s): fall_time, impact_speed",
        ),
        ("fall_time", "must be ID=VALUE"),
        ("fall_time=", "is not a number"),
    ] {
        assert_refused(&answers(&path, &[answer]), words, &answer);
    }
    let (_dir2, plain) = scene_file("plain.toml", DROP.split("[lesson]").next().unwrap_or(""));
    assert_refused(&answers(&plain, &["a=1"]), "has no [lesson]", &"no lesson");
}

#[test]
fn an_answer_the_run_cannot_give_exits_1_in_words() {
    // Until 0.5 s: the ball has not landed.
    let short = DROP.replace("until = 2.0", "until = 0.5");
    let (_dir, path) = scene_file("short.toml", &short);
    let output = answers(&path, &["fall_time=1"]);
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    assert!(
        stderr(&output).contains("cannot answer question 'fall_time'"),
        "{}",
        stderr(&output)
    );
}

#[test]
fn a_bad_lesson_is_refused_by_check_with_every_problem_at_its_place() {
    let bad = DROP
        .replace("Drop the ball.", "Drop the ball. <script>alert(1)</script>")
        .replace("min = 0.5", "min = -1.0")
        .replace("measure = \"time at ball.y", "measure = \"time at bal.y")
        .replace("unit = \"m/s\"", "unit = \"kg\"")
        .replace("tolerance = 0.01\n", "");
    let (_dir, path) = scene_file("bad.toml", &bad);
    let output = newtonlab(&["check", &path]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    let text = stderr(&output);
    for words in [
        "bad.toml:18:8: [lesson]: the text holds HTML",
        "slider #1: at -1 the scene breaks a rule: particle 'ball': mass must be greater than 0",
        "bad.toml:30:11: question 'fall_time': 'bal.y': there is no particle named 'bal'",
        "question 'impact_speed': the unit 'kg' does not fit the measure, which is in m/s",
        "bad.toml:27:1: question #1: tolerance is required",
    ] {
        assert!(text.contains(words), "{words:?} in {text}");
    }
}

/// The number of pages a PDF says it has (its page tree's `/Count`).
fn pages(pdf: &[u8]) -> Option<usize> {
    let text = String::from_utf8_lossy(pdf);
    let at = text.find("/Count ")? + "/Count ".len();
    let digits: String = text[at..]
        .chars()
        .take_while(char::is_ascii_digit)
        .collect();
    digits.parse().ok()
}

#[test]
fn the_worksheet_is_a_pdf_and_the_key_adds_a_page_of_its_own() {
    let dir = std::env::temp_dir().join(format!("newtonlab-worksheet-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a folder");
    let sheet = dir.join("sheet.pdf");
    let keyed = dir.join("keyed.pdf");
    let sheet_path = sheet.to_string_lossy().into_owned();
    let keyed_path = keyed.to_string_lossy().into_owned();
    let scene = "example:lesson-spring-period";
    let output = newtonlab(&["lesson", scene, "--worksheet", &sheet_path]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(
        stdout(&output).is_empty(),
        "nothing listed: {}",
        stdout(&output)
    );
    let args = ["lesson", scene, "--worksheet", &keyed_path, "--key"];
    let output = newtonlab(&args);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let (sheet, keyed) = (
        std::fs::read(&sheet).expect("the worksheet"),
        std::fs::read(&keyed).expect("the worksheet with its key"),
    );
    assert!(
        sheet.starts_with(b"%PDF-") && keyed.starts_with(b"%PDF-"),
        "PDFs"
    );
    let (plain, with_key) = (pages(&sheet), pages(&keyed));
    assert_eq!(
        with_key,
        plain.map(|n| n + 1),
        "the key on a page of its own"
    );
    // Answers are still checked beside the worksheet.
    let output = newtonlab(&[
        "lesson",
        scene,
        "--worksheet",
        &sheet_path,
        "--answer",
        "period=0.9935",
    ]);
    assert_eq!(stdout(&output), "period: right\n", "{}", stderr(&output));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_worksheet_that_cannot_be_written_or_has_no_lesson_exits_2() {
    let (_dir, plain) = scene_file("plain.toml", DROP.split("[lesson]").next().unwrap_or(""));
    let output = newtonlab(&["lesson", &plain, "--worksheet", "w.pdf"]);
    assert_refused(&output, "has no [lesson]", &"no lesson");
    let output = newtonlab(&[
        "lesson",
        "example:lesson-spring-period",
        "--worksheet",
        "/nonexistent-folder/w.pdf",
    ]);
    assert_refused(&output, "cannot create the output file", &"no such folder");
    let output = newtonlab(&["lesson", "example:lesson-spring-period", "--key"]);
    assert_eq!(output.status.code(), Some(2), "--key needs --worksheet");
}

/// `newtonlab link` gives the link File → Share link gives; every command takes one where
/// it takes a scene file, and reads the same scene from it; a scene too large is refused.
#[test]
fn a_lesson_travels_in_a_link_that_every_command_opens() {
    let (_dir, path) = scene_file("drop.toml", DROP);
    let made = newtonlab(&["link", &path, "--address", "https://school.example/lab/"]);
    assert!(made.status.success(), "{}", stderr(&made));
    let link = stdout(&made).trim().to_owned();
    assert!(
        link.starts_with("https://school.example/lab/#scene="),
        "{link}"
    );
    let from_file = newtonlab(&["run", &path, "--until", "1", "--every", "0.5"]);
    let from_link = newtonlab(&["run", &link, "--until", "1", "--every", "0.5"]);
    assert_eq!(stdout(&from_link), stdout(&from_file), "the same rows");
    let judged = answers(&link, &["fall_time=1 s"]);
    assert_eq!(stdout(&judged).trim(), "fall_time: right");

    let big = newtonlab(&["link", "example:star-cluster"]);
    assert_refused(&big, "save it as a file instead", &"the star cluster");
    let damaged = newtonlab(&["check", &link[..link.len() / 2]]);
    assert_refused(&damaged, "damaged", &"a link cut in half");
}
