//! File → Share link… and File → Open link… on the desktop: the link copied opens the
//! same scene (lesson included) in the student's view; a pasted link goes through the
//! unsaved-changes prompt; what is not a link says so and changes nothing.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use newtonlab_app::edit::Edit;
use newtonlab_app::{App, share};
use physics::ObjectKind;

use crate::common::{example_scene, harness, one_ball};

/// Chooses `item` in the File menu.
fn file_menu(harness: &mut Harness<'_, App>, item: &str) {
    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label(item).click();
    harness.run();
}

/// The text the last frame put on the clipboard, if any.
fn copied(harness: &Harness<'_, App>) -> Option<String> {
    harness
        .output()
        .platform_output
        .commands
        .iter()
        .find_map(|command| match command {
            egui::OutputCommand::CopyText(text) => Some(text.clone()),
            _ => None,
        })
}

/// Pastes `text` into File → Open link… and presses Enter.
fn paste_link(harness: &mut Harness<'_, App>, text: &str) {
    file_menu(harness, "Open link…");
    paste_again(harness, text);
}

/// Replaces the text in the open link window with `text` and presses Enter.
fn paste_again(harness: &mut Harness<'_, App>, text: &str) {
    let field = "Paste a link to a NewtonLab scene:";
    harness.get_by_label(field).focus();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness.get_by_label(field).type_text(text);
    harness.key_press(egui::Key::Enter);
    harness.run();
}

#[test]
fn a_lesson_shared_from_the_desktop_opens_from_its_link_in_the_students_view() {
    let lesson = example_scene("lesson-galileo-incline");
    let mut teacher = harness(App::new(lesson.clone()));
    file_menu(&mut teacher, "Share link…");
    let address = teacher.get_by_label("Address of the browser build your class opens:");
    assert_eq!(address.value().as_deref(), Some(share::DEFAULT_ADDRESS));
    teacher.get_by_label("Copy link").click();
    teacher.step();
    let link = copied(&teacher).expect("the link is on the clipboard");
    assert!(
        link.starts_with("http://127.0.0.1:8080/#scene="),
        "to the browser build the README serves: {link}"
    );
    teacher.run();
    assert!(teacher.state().link.is_none(), "the window closes");
    assert!(
        !teacher.state().document.is_dirty(),
        "sharing is no edit: nothing to save afterwards"
    );

    let mut student = harness(App::new(one_ball()));
    paste_link(&mut student, &link);
    let app = student.state();
    // The scene as the teacher left it: the lesson, the instruments, the camera (which
    // also says the canvas's toggles).
    let mut shared = app.document.scene().clone();
    assert_eq!(shared.view.as_ref().and_then(|v| v.width), Some(14.0));
    shared.view.clone_from(&lesson.view);
    assert_eq!(
        shared, lesson,
        "the same scene, lesson and instruments included"
    );
    assert!(app.canvas.instruments.tape.is_some(), "the tape laid out");
    assert!(
        app.panels.lesson && !app.panels.inspector,
        "in the student's view"
    );
    assert!(
        app.title().starts_with("Lesson: Galileo's incline"),
        "{}",
        app.title()
    );
    assert!(
        app.document.path.is_none(),
        "a link is no file to save over"
    );
}

#[test]
fn a_pasted_link_asks_before_unsaved_changes_go() {
    let mut harness = harness(App::new(one_ball()));
    harness
        .state_mut()
        .document
        .apply(Edit::Delete(ObjectKind::Particle), |s| s.particles.clear());
    paste_link(&mut harness, "http://127.0.0.1:8080/#example=collision");
    assert!(
        harness.state().document.scene().particles.is_empty(),
        "nothing replaced before the word"
    );
    harness.get_by_label("Discard changes").click();
    harness.run();
    assert_eq!(
        harness.state().document.scene(),
        &example_scene("collision")
    );
}

#[test]
fn what_is_no_link_says_why_and_changes_nothing() {
    let mut harness = harness(App::new(one_ball()));
    paste_link(&mut harness, "https://example.org/notes#top");
    harness.get_by_label_contains("not a link to a NewtonLab scene");
    paste_again(&mut harness, "http://127.0.0.1:8080/#scene=AAAA");
    harness.get_by_label_contains("damaged");
    assert_eq!(harness.state().document.scene(), &one_ball(), "unchanged");
    harness.get_by_label("Cancel").click();
    harness.run();
    assert!(harness.state().link.is_none(), "Cancel closes the window");

    // Too large for a link: the reason, and Save as… instead.
    let mut big = harness_of(example_scene("star-cluster"));
    file_menu(&mut big, "Share link…");
    big.get_by_label_contains("save it as a file instead");
    big.get_by_label("Save As…");
}

fn harness_of(scene: physics::Scene) -> Harness<'static, App> {
    harness(App::new(scene))
}
