//! Files: save and open, a broken file, the examples, autosave and recovery, a file changed on disk.

use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use newtonlab_app::App;
use newtonlab_app::edit::Edit;
use physics::Scene;
use physics::{ObjectKind, SectionKind};

use crate::common::{example_scene, harness, one_ball};

/// A mass typed in the inspector.
const MASS: Edit = Edit::Set {
    section: SectionKind::Object(ObjectKind::Particle),
    key: "mass",
};

#[test]
fn save_then_open_round_trips_a_scene() {
    let folder = std::env::temp_dir().join(format!("newtonlab-app-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let folder_text = folder.to_string_lossy().into_owned();
    let mut scene = example_scene("newtons-cradle");
    scene.particles[2].charge = 1.25e-7;
    let mut harness = harness(App::new(scene.clone()));

    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label_contains("Save As…").click();
    harness.run();
    assert!(
        harness.get_by_label("file name").is_focused(),
        "the name has the focus on opening"
    );
    let replace = |harness: &mut Harness<'_, App>, label: &str, text: &str| {
        harness.get_by_label(label).focus();
        harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
        harness.get_by_label(label).type_text(text);
        harness.run();
    };
    replace(&mut harness, "folder", &folder_text);
    replace(&mut harness, "file name", "cradle.toml");
    harness.get_by_label("Save").click();
    harness.run();
    let path = folder.join("cradle.toml");
    assert!(path.exists(), "saved to {}", path.display());
    assert!(
        !harness.state().document.is_dirty(),
        "saved: no unsaved changes"
    );
    assert_eq!(
        harness.state().title(),
        "cradle.toml — NewtonLab",
        "the title names the file"
    );

    // Change the scene, then open the file again: first confirm discarding the change.
    harness
        .state_mut()
        .document
        .apply(Edit::Delete(ObjectKind::Particle), |s| s.particles.clear());
    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label_contains("Open…").click();
    harness.run();
    harness.get_by_label("Discard changes").click();
    harness.run();
    replace(&mut harness, "folder", &folder_text);
    replace(&mut harness, "file name", "cradle.toml");
    harness.get_by_label("Open").click();
    harness.run();
    let mut reopened = harness.state().document.scene().clone();
    assert!(
        reopened.view.is_some(),
        "the camera is saved as the scene's view"
    );
    reopened.view.clone_from(&scene.view);
    assert_eq!(reopened, scene, "the scene came back unchanged");
    std::fs::remove_dir_all(&folder).ok();
}

#[test]
fn a_broken_file_shows_the_same_messages_as_check() {
    let folder = std::env::temp_dir().join(format!("newtonlab-broken-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let path = folder.join("broken.toml");
    std::fs::write(
        &path,
        "version = 1\n[[particle]]\nname = \"B\"\nmass = -2\nposition = [0, 0]\n",
    )
    .unwrap();
    let mut harness = harness(App::new(one_ball()));
    harness.state_mut().open_path(&path.to_string_lossy());
    harness.run();
    let expected = format!(
        "{}:4:8: particle 'B': mass must be greater than 0, got -2",
        path.display()
    );
    harness.get_by_label_contains(&expected);
    assert_eq!(
        harness.state().document.scene(),
        &one_ball(),
        "the open scene is kept"
    );
    std::fs::remove_dir_all(&folder).ok();
}

#[test]
fn the_examples_menu_opens_a_built_in_scene_after_asking_about_unsaved_changes() {
    let mut harness = harness(App::new(one_ball()));
    harness
        .state_mut()
        .document
        .apply(MASS, |s| s.particles[0].mass = 3.0);
    harness.get_by_label("Examples").click();
    harness.run();
    harness
        .get_by_label("Two balls colliding off-centre")
        .click();
    harness.run();
    assert_eq!(
        harness.state().document.scene().particles.len(),
        1,
        "not yet: it asks first"
    );
    harness.get_by_label("Cancel").click();
    harness.run();
    assert_eq!(
        harness.state().document.scene().particles[0].mass,
        3.0,
        "cancelled: the change is kept"
    );
    harness.get_by_label("Examples").click();
    harness.run();
    harness
        .get_by_label("Two balls colliding off-centre")
        .click();
    harness.run();
    harness.get_by_label("Discard changes").click();
    harness.run();
    let scene = harness.state().document.scene();
    assert_eq!(
        scene.name.as_deref(),
        Some("Two balls colliding off-centre"),
        "the example is open"
    );
    assert_eq!(scene.particles.len(), 2, "its two balls");
    assert_eq!(
        harness.state().title(),
        "Two balls colliding off-centre — NewtonLab",
        "titled by the example, not \"untitled\""
    );
}

/// Unsaved work survives a crash: it is copied to the data directory while it has
/// unsaved changes; an app started afterwards (the first one never closed: as after a
/// kill) offers it back, and recovering gives the same scene, unsaved, with its file.
#[test]
fn unsaved_work_is_recovered_after_a_crash() {
    use newtonlab_app::autosave::Autosave;
    let dir = std::env::temp_dir().join(format!("newtonlab-autosave-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    let mut first = harness(App::new(one_ball()).with_autosave(Autosave::in_dir(&dir, 0.0)));
    first
        .state_mut()
        .document
        .apply(MASS, |s| s.particles[0].mass = 7.5);
    first.state_mut().document.path = Some("/lessons/ball.toml".to_owned());
    first.run();
    let edited = first.state().document.scene().clone();
    drop(first); // killed: nothing runs on the way out

    let mut second = harness(App::new(Scene::new()).with_autosave(Autosave::in_dir(&dir, 0.0)));
    second.get_by_label_contains("that were not saved. Recover them?");
    second.get_by_label("Recover").click();
    second.run();
    let app = second.state();
    assert_eq!(app.document.scene(), &edited, "the work is back");
    assert!(app.document.is_dirty(), "and still unsaved");
    assert_eq!(app.document.path.as_deref(), Some("/lessons/ball.toml"));

    // Saving it (here: marking it saved) removes the copy.
    second
        .state_mut()
        .document
        .mark_saved("/tmp/ball.toml".to_owned());
    second.run();
    assert!(
        Autosave::in_dir(&dir, 0.0).find().is_none(),
        "no copy once saved"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// A file changed on disk since it was opened is not overwritten without asking.
#[test]
fn a_file_changed_on_disk_is_not_silently_overwritten() {
    let dir = std::env::temp_dir().join(format!("newtonlab-disk-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("ball.toml");
    std::fs::write(&path, one_ball().to_toml()).unwrap();
    let path_text = path.to_string_lossy().into_owned();
    let mut harness = harness(App::new(Scene::new()));
    harness.state_mut().open_path(&path_text);
    harness.run();
    // Someone else changes the file (a different length, so the change shows at once).
    std::fs::write(
        &path,
        format!("{}\n# edited elsewhere\n", one_ball().to_toml()),
    )
    .unwrap();
    harness
        .state_mut()
        .document
        .apply(MASS, |s| s.particles[0].mass = 2.0);
    harness.key_press_modifiers(Modifiers::COMMAND, Key::S);
    harness.run();
    harness.get_by_label_contains("has changed on disk since it was opened");
    assert!(
        std::fs::read_to_string(&path)
            .unwrap()
            .contains("edited elsewhere"),
        "not overwritten yet"
    );
    harness.get_by_label("Overwrite").click();
    harness.run();
    let saved = Scene::from_toml(&std::fs::read_to_string(&path).unwrap()).unwrap();
    assert_eq!(saved.particles[0].mass, 2.0, "overwritten when asked");
    assert!(!harness.state().document.is_dirty());
    std::fs::remove_dir_all(&dir).ok();
}

/// File → Save the canvas as PNG writes the canvas at twice the screen's resolution (the
/// PNG twice the canvas's size in pixels), drawn: the pendulum's bob and rod darken
/// pixels of the light background.
#[test]
fn the_canvas_prints_at_twice_the_resolution() {
    let folder = std::env::temp_dir().join(format!("newtonlab-canvas-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let mut harness = harness(App::new(example_scene("pendulum")));
    harness.get_by_label("File").click();
    harness.run();
    harness
        .get_by_label_contains("Save the canvas as PNG")
        .click();
    harness.run();
    harness.run();
    for (label, text) in [
        ("folder", folder.to_string_lossy().into_owned()),
        ("file name", "canvas.png".to_owned()),
    ] {
        harness.get_by_label(label).focus();
        harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
        harness.get_by_label(label).type_text(&text);
        harness.run();
    }
    harness.get_by_label("Export").click();
    harness.run();
    let bytes = std::fs::read(folder.join("canvas.png")).expect("the picture was written");
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut reader = decoder.read_info().expect("a PNG");
    let mut pixels = vec![0; reader.output_buffer_size().expect("a size")];
    let info = reader.next_frame(&mut pixels).expect("a frame");
    let rect = harness.state().canvas.rect;
    let scale = 2.0 * harness.ctx.pixels_per_point();
    assert_eq!(
        (f64::from(info.width), f64::from(info.height)),
        (
            f64::from((rect.width() * scale).round()),
            f64::from((rect.height() * scale).round())
        )
    );
    let dark = pixels
        .chunks_exact(3)
        .filter(|p| p.iter().all(|&c| c < 100))
        .count();
    assert!(dark > 200, "{dark} dark pixels: the bob and the rod");
    std::fs::remove_dir_all(&folder).ok();
}

/// The unsaved-changes prompt saves first when asked, then goes on: to the scene's own
/// file when it has one; through the Save dialog when it has none; and a Save dialog
/// closed without a name goes on with nothing (the scene stays, unsaved, and a later
/// save opens no example).
#[test]
fn the_unsaved_prompt_saves_then_goes_on() {
    let folder = std::env::temp_dir().join(format!("newtonlab-save-then-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let path = folder.join("ball.toml");
    std::fs::write(&path, one_ball().to_toml()).unwrap();
    let open_example = |harness: &mut Harness<'_, App>| {
        harness.get_by_label("Examples").click();
        harness.run();
        harness
            .get_by_label("Two balls colliding off-centre")
            .click();
        harness.run();
    };

    // A scene with a file: Save writes the change there, then the example opens.
    let mut harness = harness(App::new(one_ball()));
    harness.state_mut().open_path(&path.to_string_lossy());
    harness
        .state_mut()
        .document
        .apply(MASS, |s| s.particles[0].mass = 3.0);
    open_example(&mut harness);
    harness.get_by_label("Save").click();
    harness.run();
    let saved = Scene::from_toml(&std::fs::read_to_string(&path).unwrap()).unwrap();
    assert_eq!(saved.particles[0].mass, 3.0, "the change is in the file");
    assert_eq!(
        harness.state().document.scene().particles.len(),
        2,
        "then the example is open"
    );

    // A scene without a file: Save asks where, and the example opens once it is saved.
    let save_as = |harness: &mut Harness<'_, App>, name: &str| {
        fill_dialog(harness, &folder, name);
        harness.get_by_label("Save").click();
        harness.run();
    };
    let mut harness = harness_for(one_ball());
    harness
        .state_mut()
        .document
        .apply(MASS, |s| s.particles[0].mass = 4.0);
    open_example(&mut harness);
    harness.get_by_label("Save").click();
    harness.run();
    save_as(&mut harness, "named.toml");
    let saved =
        Scene::from_toml(&std::fs::read_to_string(folder.join("named.toml")).unwrap()).unwrap();
    assert_eq!(saved.particles[0].mass, 4.0, "saved where the dialog said");
    assert_eq!(
        harness.state().document.scene().particles.len(),
        2,
        "then the example is open"
    );

    // The Save dialog closed without a name: the scene stays, and a later save is only
    // a save.
    let mut harness = harness_for(one_ball());
    harness
        .state_mut()
        .document
        .apply(MASS, |s| s.particles[0].mass = 5.0);
    open_example(&mut harness);
    harness.get_by_label("Save").click();
    harness.run();
    harness.get_by_label("Cancel").click();
    harness.run();
    assert_eq!(
        harness.state().document.scene().particles[0].mass,
        5.0,
        "the scene stays"
    );
    harness.key_press_modifiers(Modifiers::COMMAND, Key::S);
    harness.run();
    save_as(&mut harness, "plain.toml");
    assert!(folder.join("plain.toml").exists(), "saved");
    assert_eq!(
        harness.state().document.scene().particles.len(),
        1,
        "and nothing else happened"
    );
    std::fs::remove_dir_all(&folder).ok();
}

/// Types `folder` and `name` into the open file dialog, each replacing what was there.
fn fill_dialog(harness: &mut Harness<'_, App>, folder: &std::path::Path, name: &str) {
    harness.get_by_label("folder").focus();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness
        .get_by_label("folder")
        .type_text(&folder.to_string_lossy());
    harness.run();
    harness.get_by_label("file name").focus();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.get_by_label("file name").type_text(name);
    harness.run();
}

fn harness_for(scene: Scene) -> Harness<'static, App> {
    harness(App::new(scene))
}

/// The first click after a file dialog is not lost: a graph exported (Export CSV…, a
/// name, Enter) says so in the status line, not in a box that the next click only
/// dismissed (and the keys typed after it reached the shortcuts); one click on Reset then
/// resets the run.
#[test]
fn the_first_click_after_a_file_dialog_is_not_lost() {
    let folder = std::env::temp_dir().join(format!("newtonlab-first-click-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let mut harness =
        crate::common::tall_harness(App::new(crate::common::example_scene("pendulum")));
    crate::common::play_frames(&mut harness, 10);
    harness
        .get_all_by_label("Export CSV…")
        .next()
        .expect("a graph to export")
        .click();
    harness.run();
    fill_dialog(&mut harness, &folder, "swing.csv");
    harness.key_press(Key::Enter);
    harness.run();
    assert!(folder.join("swing.csv").exists(), "exported by Enter");
    assert!(
        harness.state().files.message.is_none(),
        "no box to dismiss: {:?}",
        harness.state().files.message
    );
    let notice = harness.state().notice.clone().map(|(text, _)| text);
    assert!(
        notice.as_deref().is_some_and(|n| n.starts_with("Exported")),
        "said in the status line: {notice:?}"
    );
    assert!(!harness.state().runner.is_editing(), "a run to reset");
    harness.get_by_label("Reset").click();
    harness.run();
    assert!(
        harness.state().runner.is_editing(),
        "the first click after the dialog resets the run"
    );
    std::fs::remove_dir_all(&folder).ok();
}

/// Save As offers an example its own file name, not `scene.toml`.
#[test]
fn save_as_offers_an_example_its_own_name() {
    let mut harness = harness_for(example_scene("pendulum"));
    harness.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::S);
    harness.run();
    let name = harness
        .get_by_label("file name")
        .value()
        .unwrap_or_default();
    assert_eq!(name, "pendulum.toml");
    harness.get_by_label("Cancel").click();
    harness.run();
    let mut harness = harness_for(one_ball());
    harness.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::S);
    harness.run();
    let name = harness
        .get_by_label("file name")
        .value()
        .unwrap_or_default();
    assert_eq!(name, "scene.toml", "a scene of one's own");
}
