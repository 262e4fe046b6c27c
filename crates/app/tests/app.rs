//! The app driven as a user would, through its accessibility tree (`egui_kittest)`: no GPU,
//! no display. Each test clicks, types and presses keys, then checks the app's state.

#![expect(
    clippy::float_cmp,
    reason = "typed values and paused clocks are compared exactly"
)]

use egui::{Key, Modifiers, Pos2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use newtonlab_app::{App, Selection};
use physics::{Particle, Scene, World};

fn harness(app: App) -> Harness<'static, App> {
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .build_ui_state(|ui, app: &mut App| app.ui(ui), app);
    harness.run();
    harness
}

/// A small scene: one ball at the origin, no field.
fn one_ball() -> Scene {
    Scene::new()
        .with_world(World::weightless())
        .with_particle(Particle::new("ball", 1.0).velocity([1.0, 0.0]))
}

/// Clicks the canvas at `at` (press and release there).
fn click_canvas(harness: &mut Harness<'_, App>, at: Pos2) {
    harness.hover_at(at);
    harness.run();
    harness.drag_at(at);
    harness.run();
    harness.drop_at(at);
    harness.run();
}

#[test]
fn clicking_the_canvas_places_a_particle_where_clicked() {
    let mut harness = harness(App::new(one_ball()));
    harness.get_by_label("Particle").click();
    harness.run();
    let rect = harness.state().canvas.rect;
    let at = rect.center() + egui::vec2(60.0, -40.0);
    click_canvas(&mut harness, at);
    let app = harness.state();
    assert_eq!(
        app.document.scene().particles.len(),
        2,
        "a particle was added"
    );
    let placed = app.document.scene().particles[1].position.to_dvec2();
    let expected = app.canvas.view.to_world(rect, at);
    assert!(
        placed.distance(expected) < 1e-9,
        "placed at {placed}, clicked at {expected}"
    );
    assert_eq!(
        app.selection,
        Some(Selection::Particle(1)),
        "the new particle is selected"
    );
    assert!(app.document.is_dirty(), "the document has unsaved changes");
    assert!(
        app.title().contains('●'),
        "the title marks them: {}",
        app.title()
    );
}

#[test]
fn an_invalid_mass_is_refused_with_a_reason_and_a_valid_one_applied() {
    let mut harness = harness(App::new(one_ball()));
    harness.state_mut().selection = Some(Selection::Particle(0));
    harness.run();
    let field = harness.get_by_label("mass");
    field.focus();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.get_by_label("mass").type_text("-2");
    harness.key_press(Key::Enter);
    harness.run();
    harness.get_by_label_contains("mass must be greater than 0, got -2");
    assert_eq!(
        harness.state().document.scene().particles[0].mass,
        1.0,
        "not applied"
    );

    harness.get_by_label("mass").focus();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.get_by_label("mass").type_text("2.5");
    harness.key_press(Key::Enter);
    harness.run();
    assert_eq!(
        harness.state().document.scene().particles[0].mass,
        2.5,
        "applied"
    );
    assert!(
        harness.query_by_label_contains("mass must be").is_none(),
        "the error is gone"
    );
}

#[test]
fn play_advances_time_and_pause_stops_it_and_reset_restores_the_scene() {
    let mut harness = harness(App::new(one_ball()));
    harness.get_by_label("Play").click();
    harness.run_steps(4);
    let t = harness.state().time();
    assert!(t > 0.0, "simulated time advanced: {t}");
    // Real time: each test frame is 1/4 s, capped at 0.1 s of physics per frame.
    assert!((t - 0.4).abs() < 0.11, "about 4 frames' worth: {t}");
    let moved = harness
        .state()
        .runner
        .simulation
        .as_ref()
        .unwrap()
        .positions()[0]
        .x;
    assert!(
        (moved - t).abs() < 1e-9,
        "x = v t for the free ball: {moved} vs {t}"
    );

    harness.get_by_label("Pause").click();
    harness.run();
    let paused = harness.state().time();
    harness.run_steps(4);
    assert_eq!(harness.state().time(), paused, "paused: time stands still");

    harness.get_by_label("Reset").click();
    harness.run();
    let app = harness.state();
    assert!(app.runner.simulation.is_none(), "the simulation is gone");
    assert_eq!(app.time(), 0.0, "time back to zero");
    assert_eq!(
        app.document.scene(),
        &one_ball(),
        "the scene as last edited"
    );
}

#[test]
fn space_plays_and_pauses() {
    let mut harness = harness(App::new(one_ball()));
    harness.key_press(Key::Space);
    harness.run_steps(2);
    assert!(harness.state().runner.playing, "Space plays");
    harness.key_press(Key::Space);
    harness.run();
    assert!(!harness.state().runner.playing, "Space pauses");
}

#[test]
fn undo_and_redo_with_the_keyboard() {
    let mut harness = harness(App::new(one_ball()));
    harness.get_by_label("Particle").click();
    harness.run();
    let centre = harness.state().canvas.rect.center();
    for k in 0..3 {
        click_canvas(&mut harness, centre + egui::vec2(40.0 * k as f32, 30.0));
    }
    assert_eq!(
        harness.state().document.scene().particles.len(),
        4,
        "three added"
    );
    for expected in [3, 2, 1] {
        harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
        harness.run();
        assert_eq!(
            harness.state().document.scene().particles.len(),
            expected,
            "undo"
        );
    }
    assert!(!harness.state().document.is_dirty(), "back to the original");
    harness.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z);
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Y);
    harness.run();
    assert_eq!(
        harness.state().document.scene().particles.len(),
        3,
        "two redone"
    );
}

#[test]
fn save_then_open_round_trips_a_scene() {
    let folder = std::env::temp_dir().join(format!("newtonlab-app-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let folder_text = folder.to_string_lossy().into_owned();
    let mut scene = physics::example("newtons-cradle").unwrap().scene().unwrap();
    scene.particles[2].charge = 1.25e-7;
    let mut harness = harness(App::new(scene.clone()));

    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label("Save As…").click();
    harness.run();
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
        .apply("test change", |s| s.particles.clear());
    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label("Open…").click();
    harness.run();
    harness.get_by_label("Discard changes").click();
    harness.run();
    replace(&mut harness, "folder", &folder_text);
    replace(&mut harness, "file name", "cradle.toml");
    harness.get_by_label("Open").click();
    harness.run();
    assert_eq!(
        harness.state().document.scene(),
        &scene,
        "the scene came back unchanged"
    );
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
fn choosing_a_graph_quantity_shows_its_series() {
    let mut harness = harness(App::new(one_ball()));
    harness.get_by_label("Add").click();
    harness.run();
    assert_eq!(harness.state().graphs.series.len(), 1, "one series chosen");
    harness.get_by_label("Play").click();
    harness.run_steps(3);
    assert!(
        harness.state().graphs.len() >= 3,
        "samples recorded while running"
    );
    // The legend names the series.
    harness.get_by_label("ball.y (m)");
    let csv = harness
        .state()
        .graphs
        .to_csv(harness.state().document.scene());
    assert!(csv.starts_with("t (s),ball.y (m)\n"), "{csv}");
}

#[test]
fn the_examples_menu_opens_a_built_in_scene_after_asking_about_unsaved_changes() {
    let mut harness = harness(App::new(one_ball()));
    harness
        .state_mut()
        .document
        .apply("change", |s| s.particles[0].mass = 3.0);
    harness.get_by_label("Examples").click();
    harness.run();
    harness
        .get_by_label("Two-ball collision (paper 4.3)")
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
        .get_by_label("Two-ball collision (paper 4.3)")
        .click();
    harness.run();
    harness.get_by_label("Discard changes").click();
    harness.run();
    let scene = harness.state().document.scene();
    assert_eq!(
        scene.name.as_deref(),
        Some("Two-ball collision (paper 4.3)"),
        "the example is open"
    );
    assert_eq!(scene.particles.len(), 2, "its two balls");
}
