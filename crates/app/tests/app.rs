//! The app driven as a user would, through its accessibility tree (`egui_kittest)`: no GPU,
//! no display. Each test clicks, types and presses keys, then checks the app's state.

#![expect(
    clippy::float_cmp,
    reason = "typed values and paused clocks are compared exactly"
)]

use egui::{Key, Modifiers, Pos2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use newtonlab_app::{Action, App, Recording, Selection, plots};
use physics::{
    DVec2, Follow, Graph, Integrator, Of, Particle, Quantity, Scene, Spring, TieKind, View, World,
};

fn harness(app: App) -> Harness<'static, App> {
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .build_ui_state(|ui, app: &mut App| app.ui(ui), app);
    harness.run();
    harness
}

/// The app on a built-in scene, played for `frames` frames and paused.
fn played(name: &str, frames: usize) -> Harness<'static, App> {
    let mut harness = harness(App::new(example_scene(name)));
    play_frames(&mut harness, frames);
    harness
}

/// A built-in scene.
fn example_scene(name: &str) -> Scene {
    physics::example(name)
        .expect("the example")
        .scene()
        .expect("it loads")
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
    // On the grid of a tenth of the drawn grid's spacing (Alt places freely).
    let step = newtonlab_app::canvas::nice_length(80.0 / app.canvas.view.pixels_per_metre) / 10.0;
    let expected = (app.canvas.view.to_world(rect, at) / step).round() * step;
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
    let mut scene = example_scene("newtons-cradle");
    scene.particles[2].charge = 1.25e-7;
    let mut harness = harness(App::new(scene.clone()));

    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label_contains("Save As…").click();
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
    assert_eq!(
        harness.state().title(),
        "Two-ball collision (paper 4.3) — NewtonLab",
        "titled by the example, not \"untitled\""
    );
}

/// A ball dropped from rest in the uniform field, with a graph of its height.
fn dropped_ball() -> Scene {
    let mut scene = Scene::new()
        .with_world(World::default())
        .with_particle(Particle::new("ball", 1.0).position([0.0, 10.0]));
    scene.world.gravitation = false;
    scene.graphs.push(Graph::against_time(["ball.y"]));
    scene
}

/// Plays `frames` frames (a quarter second each in the harness, 0.1 s of physics).
fn play_frames(harness: &mut Harness<'_, App>, frames: usize) {
    harness.get_by_label("Play").click();
    harness.run_steps(frames);
    harness.get_by_label("Pause").click();
    harness.run();
}

/// The impacts the run's recording holds.
fn impacts_of(harness: &Harness<'_, App>) -> Vec<physics::ImpactRecord> {
    let recording = harness.state().runner.recording.as_ref();
    recording.expect("recorded").impacts().to_vec()
}

/// The rows of a graph's CSV export as numbers, after its header.
fn csv_rows(app: &App, graph: usize) -> (String, Vec<Vec<f64>>) {
    let recording = app.runner.recording.as_ref().expect("a recording");
    let csv = plots::to_csv(recording, &app.document.scene().graphs[graph]);
    let mut lines = csv.lines();
    let header = lines.next().expect("a header").to_owned();
    let rows = lines
        .map(|line| {
            line.split(',')
                .map(|v| v.parse().expect("a number"))
                .collect()
        })
        .collect();
    (header, rows)
}

/// Switching the x axis, adding a series after the run and resetting all keep the whole
/// run: the export has a row at t = 0 and rows at the simulation's own instants (every
/// 5 ms at dt = 1 ms), each on the closed-form free fall y = 10 − g t²/2 (rk4 is exact
/// for constant acceleration: 1e-9 m is rounding).
#[test]
fn graphs_keep_the_whole_run_through_axis_changes_late_series_and_reset() {
    let mut harness = harness(App::new(dropped_ball()));
    play_frames(&mut harness, 5);
    let samples = harness.state().runner.recording.as_ref().unwrap().len();
    assert!(samples > 50, "recorded while running: {samples}");

    // A phase plot against y, then back to time: nothing is lost.
    harness.get_by_label("Use as x axis").click();
    harness.run();
    assert_eq!(harness.state().document.scene().graphs[0].x, "ball.y");
    harness.get_by_label("use time").click();
    harness.run();
    // A series added after the run has data from t = 0.
    harness.get_by_label("total_energy (J)").click();
    harness.run();
    harness.get_by_label("Reset").click();
    harness.run();
    assert!(harness.state().runner.simulation.is_none(), "reset");

    let (header, rows) = csv_rows(harness.state(), 0);
    assert_eq!(header, "t (s),ball.y (m),total_energy (J)");
    assert_eq!(rows.len(), samples, "every sample, after reset too");
    let start_energy = 1.0 * 9.81 * 10.0;
    for (k, row) in rows.iter().enumerate() {
        let t = row[0];
        assert!(
            (t - 0.005 * k as f64).abs() < 1e-9,
            "row {k} at the instant {t}"
        );
        let y = 10.0 - 0.5 * 9.81 * t * t;
        assert!(
            (row[1] - y).abs() < 1e-9,
            "y({t}) = {}, expected {y}",
            row[1]
        );
        assert!((row[2] - start_energy).abs() < 1e-9, "energy at {t}");
    }
    assert!(
        harness.query_by_label("Export CSV…").is_some(),
        "export stays available after Reset"
    );

    // The next Play starts a new recording.
    play_frames(&mut harness, 2);
    let again = harness.state().runner.recording.as_ref().unwrap().len();
    assert!(again < samples, "a new run: {again} samples");
}

/// Dragging a velocity arrow's tip sets the velocity, even when the pointer moves far
/// at once (the gesture starts where the button went down).
#[test]
fn dragging_the_arrow_tip_sets_the_velocity() {
    let mut harness = harness(App::new(one_ball()));
    let app = harness.state();
    let rect = app.canvas.rect;
    let tip = app.canvas.view.to_screen(rect, DVec2::new(0.5, 0.0));
    let end = tip + egui::vec2(60.0, -40.0);
    // Where the pointer ends, in the view before the gesture (a pan would move it).
    let expected = app.canvas.view.to_world(rect, end) / 0.5;
    harness.hover_at(tip);
    harness.run();
    harness.drag_at(tip);
    harness.run();
    harness.hover_at(end);
    harness.run();
    harness.drop_at(end);
    harness.run();
    let app = harness.state();
    let velocity = app.document.scene().particles[0].velocity.to_dvec2();
    assert!(
        velocity.distance(expected) < 1e-6,
        "velocity {velocity}, expected {expected}"
    );
    assert_eq!(
        app.document.undo_label(),
        Some("set velocity"),
        "one undo step"
    );
}

/// With a typed value still invalid (red), Play is refused and says why.
#[test]
fn play_is_refused_while_a_field_is_invalid() {
    let mut harness = harness(App::new(one_ball()));
    harness.state_mut().selection = Some(Selection::Particle(0));
    harness.run();
    harness.get_by_label("mass").focus();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.get_by_label("mass").type_text("-2");
    harness.run();
    harness.get_by_label("Play").click();
    harness.run();
    assert!(!harness.state().runner.playing, "not playing");
    assert!(harness.state().runner.simulation.is_none(), "nothing built");
    let message = harness.state().files.message.clone().unwrap_or_default();
    assert!(
        message.contains("mass must be greater than 0, got -2"),
        "says why: {message}"
    );
}

/// A run that fails (a spring far too stiff for explicit Euler at this step) stops,
/// says so, and still shows its last good state rather than a blank canvas.
#[test]
fn a_failed_run_shows_its_last_good_state_and_offers_reset() {
    let scene = Scene::new()
        .with_world(World::weightless())
        .with_integrator(Integrator::Euler, 0.001)
        .with_particle(Particle::new("bob", 1.0).position([1.0, 0.0]))
        .with_spring(Spring::new("s1", "bob", [0.0, 0.0], 1e9, 0.5));
    let mut harness = harness(App::new(scene));
    harness.get_by_label("Play").click();
    harness.run_steps(8);
    let app = harness.state();
    assert!(app.runner.failure.is_some(), "the run failed");
    let (positions, _) = app
        .runner
        .recording
        .as_ref()
        .and_then(Recording::last_state)
        .expect("a last good sample");
    assert!(positions[0].is_finite(), "the last good state is finite");
    harness.get_by_label_contains("showing the last good state");
    harness.get_by_label_contains("The run failed: the values of its last good sample.");
    harness.get_by_label("Reset the scene").click();
    harness.run();
    assert!(harness.state().runner.simulation.is_none(), "reset");
}

/// A scene's `[view]` follows a particle while it plays.
#[test]
fn the_camera_follows_a_particle() {
    let mut scene = one_ball();
    scene.particles[0].velocity = [20.0, 0.0].into();
    scene.view = Some(View {
        center: Some(DVec2::ZERO),
        width: Some(10.0),
        follow: Some(Follow::Particle("ball".to_owned())),
    });
    let mut harness = harness(App::new(scene));
    let width = f64::from(harness.state().canvas.rect.width());
    assert!(
        (harness.state().canvas.view.pixels_per_metre - width / 10.0).abs() < 1e-6,
        "10 m across, as the file says"
    );
    harness.get_by_label("Play").click();
    harness.run_steps(40);
    let app = harness.state();
    let ball = app.runner.simulation.as_ref().unwrap().positions()[0];
    assert!(ball.x > 50.0, "the ball went far: {ball}");
    assert!(
        app.canvas.view.center.distance(ball) < 3.0,
        "the camera is on it: {} vs {ball}",
        app.canvas.view.center
    );
}

/// A new scene has no pairwise gravitation; every action is reachable from the menus
/// with its shortcut shown.
#[test]
fn a_new_scene_has_no_pairwise_gravitation() {
    let mut harness = harness(App::new(one_ball()));
    harness.state_mut().perform(Action::New);
    harness.run();
    assert!(!harness.state().document.scene().world.gravitation);
    assert_eq!(harness.state().title(), "untitled — NewtonLab");
}

/// An impact is marked on the graphs of the particles it involves, at its instant: two
/// balls of radius 0.5 m, 5 m apart, one at 2 m/s, touch at t = (5 − 1)/2 = 2 s (the
/// impact is located to 1e-9 s); a graph of a third ball has no mark.
#[test]
fn impacts_are_marked_on_the_graphs_of_the_particles_they_involve() {
    let ball = |name: &str, x: f64| {
        let mut p = Particle::new(name, 1.0).position([x, 0.0]);
        p.radius = 0.5;
        p
    };
    let scene = Scene::new()
        .with_world(World::weightless())
        .with_particle(ball("A", 0.0).velocity([2.0, 0.0]))
        .with_particle(ball("B", 5.0))
        .with_particle(ball("C", 0.0).position([0.0, 10.0]));
    let mut harness = harness(App::new(scene));
    play_frames(&mut harness, 30);
    let recording = harness.state().runner.recording.as_ref().unwrap();
    let of = |name: &str| vec![Quantity::Particle(name.to_owned(), Of::Vx)];
    for involved in ["A", "B"] {
        let marks = plots::impact_marks(recording, &of(involved));
        assert_eq!(marks.len(), 1, "one impact for {involved}: {marks:?}");
        assert!((marks[0] - 2.0).abs() < 1e-9, "at t = 2 s: {}", marks[0]);
    }
    assert!(
        plots::impact_marks(recording, &of("C")).is_empty(),
        "C is not involved"
    );
}

/// Fit frames the objects and their recent paths: after a ball crosses 40 m in 2 s, the
/// view holds where it was a second and a half ago as well as where it is.
#[test]
fn fit_frames_the_recent_path() {
    let mut scene = one_ball();
    scene.particles[0].velocity = [20.0, 0.0].into();
    let mut harness = harness(App::new(scene));
    play_frames(&mut harness, 20);
    harness.key_press(Key::F);
    harness.run();
    let app = harness.state();
    let now = app.runner.simulation.as_ref().unwrap().positions()[0];
    let earlier = now - DVec2::new(30.0, 0.0);
    assert!(now.x > 35.0, "the ball went on: {now}");
    for point in [now, earlier] {
        let at = app.canvas.view.to_screen(app.canvas.rect, point);
        assert!(app.canvas.rect.contains(at), "{point} is in view");
    }
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
        .apply("change", |s| s.particles[0].mass = 7.5);
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
        .apply("change", |s| s.particles[0].mass = 2.0);
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

/// The readouts keep the energy books while the damped spring plays: damping has taken
/// E₀ − E(t) of the closed form (x − 10 = 5 e^(−γt)(cos ωt + (γ/ω) sin ωt), γ = 0.125,
/// ω² = 1 − γ²), to 1e-9 J, and the panel shows it beside the numerical error.
#[test]
fn the_readouts_show_what_damping_took_and_the_numerical_error() {
    let harness = played("spring-damped-light", 8);
    harness.get_by_label("taken by damping (J)");
    harness.get_by_label("numerical error");
    let simulation = harness.state().runner.simulation.as_ref().expect("playing");
    let t = simulation.time();
    assert!(t > 0.5, "it played: t = {t}");
    let (gamma, omega) = (0.125_f64, (1.0_f64 - 0.125 * 0.125).sqrt());
    let decay = 5.0 * (-gamma * t).exp();
    let stretch = decay * ((omega * t).cos() + gamma / omega * (omega * t).sin());
    let v = -decay * (gamma * gamma + omega * omega) / omega * (omega * t).sin();
    let lost = 12.5 - 0.5 * v * v - 0.5 * stretch * stretch;
    let ledger = simulation.ledger().expect("the app keeps the ledger");
    assert!(
        (ledger.damping - lost).abs() < 1e-9,
        "t = {t}: damping took {} J, theory {lost} J",
        ledger.damping
    );
    harness.get_by_label("Energy bars");
}

/// The impact list: after the paper's 4.3 collision (equal 1 kg masses, A at 20 m/s,
/// impact parameter 0.53 × the sum of the radii: approach u = 20 √(1 − 0.53²) along the normal,
/// impulse μ (1 + e) u = u with μ = ½ kg and e = 1, nothing lost) the list has one row,
/// which shows that impulse; a click on its time goes back to it.
#[test]
fn the_impact_list_shows_each_impact_with_its_impulse() {
    let mut harness = played("collision", 4);
    harness.get_by_label("Impacts (1)").click();
    harness.run();
    let impulse = 20.0 * (1.0_f64 - 0.53 * 0.53).sqrt();
    let impacts = impacts_of(&harness);
    assert_eq!(impacts.len(), 1);
    assert!((impacts[0].impulse - impulse).abs() < 1e-9, "{impacts:?}");
    harness.get_by_label(&newtonlab_app::format::number(impacts[0].impulse));
    harness.get_by_label("impulse (N·s)");
    // A click on its time shows the run at the step the impact ends, its instant within.
    let time = impacts[0].time;
    harness
        .get_by_label(&newtonlab_app::format::number(time))
        .click();
    harness.run();
    let shown = harness.state().time();
    let step = harness.state().document.scene().simulation.time_step;
    assert!(
        shown >= time && shown - time < step,
        "shown at {shown} s, the impact at {time} s"
    );
}

/// The Rod tool makes a pendulum: a drag from a ball to empty space above it ties the
/// ball to a fixed point there with a rod as long as the drag, and Play swings it on
/// that length; the rod's tension can be graphed. The String tool makes a string the
/// same way.
#[test]
fn the_rod_and_string_tools_tie_a_particle_to_a_point() {
    let scene = Scene::new()
        .with_world(World {
            gravitation: false,
            ..World::default()
        })
        .with_particle(Particle::new("ball", 1.0).radius(0.2).velocity([1.0, 0.0]));
    let mut harness = harness(App::new(scene));
    let drag = |harness: &mut Harness<'_, App>, tool: &str, offset: egui::Vec2| {
        harness.get_by_label(tool).click();
        harness.run();
        let app = harness.state();
        let rect = app.canvas.rect;
        let ball = app.canvas.view.to_screen(rect, DVec2::ZERO);
        let end = ball + offset;
        let anchor = app.canvas.view.to_world(rect, end);
        harness.hover_at(ball);
        harness.run();
        harness.drag_at(ball);
        harness.run();
        harness.hover_at(end);
        harness.run();
        harness.drop_at(end);
        harness.run();
        anchor
    };
    let anchor = drag(&mut harness, "Rod", egui::vec2(30.0, -120.0));
    let ties = &harness.state().document.scene().ties;
    assert_eq!(ties.len(), 1, "a rod was added");
    assert_eq!(
        (ties[0].name.as_str(), ties[0].kind),
        ("rod1", TieKind::Rod)
    );
    let length = ties[0].length;
    assert!(
        (length - anchor.length()).abs() < 1e-9,
        "as long as the drag: {length}"
    );
    harness.state_mut().document.apply("graph", |scene| {
        scene.graphs.push(Graph::against_time(["rod1.tension"]));
    });
    play_frames(&mut harness, 4);
    let app = harness.state();
    let simulation = app.runner.simulation.as_ref().expect("running");
    let swung = simulation.positions()[0];
    assert!(swung.length() > 0.0, "it moved: {swung}");
    let pivot = app
        .document
        .scene()
        .end_position(&app.document.scene().ties[0].to)
        .expect("a fixed point");
    assert!(
        (swung.distance(pivot) - length).abs() < 1e-9,
        "on the rod's length: {} m of {length} m",
        swung.distance(pivot)
    );
    let (header, rows) = csv_rows(app, 0);
    assert!(header.contains("rod1.tension"), "{header}");
    assert!(rows.iter().all(|row| row[1] > 0.0), "the rod pulls");
    harness.get_by_label("Reset").click();
    harness.run();
    drag(&mut harness, "String", egui::vec2(-150.0, -150.0));
    let ties = &harness.state().document.scene().ties;
    assert_eq!(ties.len(), 2, "a string was added");
    assert_eq!(
        (ties[1].name.as_str(), ties[1].kind),
        ("string1", TieKind::String)
    );
}

/// A value typed with a unit or as arithmetic is converted to SI: 250 g is a mass of
/// 0.25 kg, 30 km/h a velocity of 8.33 m/s, 2*pi a number; a unit of the wrong kind is
/// refused with the units that fit.
#[test]
fn typed_units_and_arithmetic_become_si_numbers() {
    let mut harness = harness(App::new(one_ball()));
    harness.state_mut().selection = Some(Selection::Particle(0));
    harness.run();
    let mut type_into = |label: &str, text: &str| {
        harness.get_by_label(label).focus();
        harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
        harness.get_by_label(label).type_text(text);
        harness.key_press(Key::Enter);
        harness.run();
    };
    type_into("mass", "250 g");
    type_into("velocity x", "30 km/h");
    type_into("radius", "sqrt(2)/2 m");
    type_into("charge", "5 kg");
    let particle = &harness.state().document.scene().particles[0];
    assert!(
        (particle.mass - 0.25).abs() < 1e-15,
        "mass {}",
        particle.mass
    );
    let v = particle.velocity.to_dvec2();
    assert!((v.x - 30.0 / 3.6).abs() < 1e-12, "velocity {v}");
    assert!((particle.radius - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-15);
    assert_eq!(
        particle.charge.to_bits(),
        0.0_f64.to_bits(),
        "5 kg is no charge"
    );
    harness.get_by_label_contains("µC");
}

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
        .simulation
        .as_ref()
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
    let at = rect.center() + egui::vec2(40.0, 30.0);
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

/// The stopwatch (T), set to start at one impact and stop at the next, times a ball's
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

/// A ball of 5 cm moving at 1 m/s, no field: small on the canvas, so that drags can end
/// beside it.
fn small_ball() -> Scene {
    Scene::new()
        .with_world(World::weightless())
        .with_particle(Particle::new("ball", 1.0).radius(0.05).velocity([1.0, 0.0]))
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
    let drag = |harness: &mut Harness<'_, App>, from: Pos2, to: Pos2| {
        harness.hover_at(from);
        harness.run();
        harness.drag_at(from);
        harness.run();
        harness.hover_at(to);
        harness.run();
        harness.drop_at(to);
        harness.run();
    };
    drag(&mut harness, vertex, first);
    drag(&mut harness, vertex, second);
    let protractor = harness.state().canvas.instruments.protractor.expect("laid");
    assert!(protractor.2.is_some(), "both arms");
    let angle = protractor_reading(protractor, &[DVec2::ZERO]).expect("a reading");
    assert!((angle - 45.0).abs() < 1e-9, "{angle}°");
}

/// The time machine: after a run of the collision, Step back (,) shows the step before
/// exactly (the same bits as a fresh run stopped there), the slider's far left the
/// start, Step walks forward through the run as it was; Edit from here makes the moment
/// shown the scene's start, time included, and Undo takes it back.
#[test]
fn the_timeline_goes_back_to_any_step_exactly_and_edits_from_there() {
    let scene = example_scene("collision");
    let fresh = |steps: u64| fresh_run(&scene, steps);
    let mut harness = harness(App::new(scene.clone()));
    play_frames(&mut harness, 6);
    let end = harness.state().runner.timeline.as_ref().expect("kept").end;
    assert!(end > 100, "{end} steps");
    harness.key_press(Key::Comma);
    harness.run();
    let app = harness.state();
    let shown = app.runner.simulation.as_ref().expect("shown");
    assert_eq!(app.runner.timeline.as_ref().unwrap().shown, Some(end - 1));
    assert!(
        bits(shown) == bits(&fresh(end - 1)),
        "the step before, exactly"
    );
    harness.state_mut().perform(Action::GoTo(0));
    harness.run();
    assert_eq!(harness.state().time(), 0.0, "the start");
    harness.key_press(Key::Period);
    harness.run();
    let walked = harness.state().runner.simulation.as_ref().unwrap();
    assert!(
        bits(walked) == bits(&fresh(1)),
        "Step walks forward through the run"
    );
    harness.get_by_label("Edit from here").click();
    harness.run();
    let app = harness.state();
    assert!(app.runner.simulation.is_none(), "back to editing");
    let edited = app.document.scene();
    let expected = fresh(1);
    assert_eq!(
        edited.simulation.start_time,
        expected.time(),
        "the time kept"
    );
    for (particle, x) in edited.particles.iter().zip(expected.positions()) {
        assert_eq!(particle.position.to_dvec2(), *x, "{}", particle.name);
    }
    assert_eq!(app.document.undo_label(), Some("edit from here"));
    harness.state_mut().perform(Action::Undo);
    harness.run();
    assert_eq!(harness.state().document.scene(), &scene, "undone");
}

/// The bits of a simulation's positions and velocities.
fn bits(simulation: &physics::Simulation) -> Vec<u64> {
    simulation
        .positions()
        .iter()
        .chain(simulation.velocities())
        .flat_map(|v| [v.x.to_bits(), v.y.to_bits()])
        .collect()
}

/// A run of `scene` from its start, `steps` steps long.
fn fresh_run(scene: &Scene, steps: u64) -> physics::Simulation {
    let mut simulation = physics::Simulation::new(scene).expect("a valid scene");
    for _ in 0..steps {
        simulation.step().expect("steps");
    }
    simulation
}

/// Branching: gone back to the middle of a run, Play goes on from there and forgets
/// what came after; with nothing changed, the new future is the old one bit for bit (a
/// deterministic step from the same state). Then Edit from here, Play: the run starts
/// at the moment's time from the moment's state and, for this fixed-step scene
/// without resting contact, is still the original run bit for bit (the issue's
/// exactness of a saved state, here in the app).
#[test]
fn play_from_a_moment_gone_back_to_branches_the_run() {
    let scene = example_scene("collision");
    let mut harness = harness(App::new(scene.clone()));
    play_frames(&mut harness, 6);
    let end = harness.state().runner.timeline.as_ref().expect("kept").end;
    let middle = end / 2;
    harness.state_mut().perform(Action::GoTo(middle));
    harness.run();
    play_frames(&mut harness, 2);
    let runner = &harness.state().runner;
    let timeline = runner.timeline.as_ref().expect("kept");
    assert_eq!(timeline.shown, None, "playing, not looking back");
    let now = timeline.end;
    assert!(
        now > middle && now < end,
        "went on from the middle ({middle}), the old end ({end}) forgotten: {now} steps"
    );
    let shown = runner.simulation.as_ref().expect("running");
    assert!(
        bits(shown) == bits(&fresh_run(&scene, now)),
        "the same future"
    );

    harness.state_mut().perform(Action::GoTo(middle));
    harness.run();
    harness.get_by_label("Edit from here").click();
    harness.run();
    let edited = harness.state().document.scene().clone();
    let start = edited.simulation.start_time;
    assert_eq!(start, fresh_run(&scene, middle).time(), "from the moment");
    play_frames(&mut harness, 2);
    let runner = &harness.state().runner;
    let steps = runner.timeline.as_ref().expect("kept").end;
    let shown = runner.simulation.as_ref().expect("running");
    assert!(
        steps > 0 && shown.time() > start,
        "played on from {start} s"
    );
    assert!(
        bits(shown) == bits(&fresh_run(&scene, middle + steps)),
        "the branch goes on as the run did, bit for bit"
    );
}

/// Whether the canvas has the keyboard focus (its accessible name starts "Canvas:").
fn canvas_focused(harness: &Harness<'_, App>) -> bool {
    use egui_kittest::kittest::NodeT as _;
    harness
        .get_by_label_contains("Canvas:")
        .accesskit_node()
        .is_focused()
}

/// Presses Tab until `done` holds, at most 300 times: what Tab reaches.
fn tab_until(harness: &mut Harness<'_, App>, what: &str, done: impl Fn(&Harness<'_, App>) -> bool) {
    for _ in 0..300 {
        if done(harness) {
            return;
        }
        harness.key_press(Key::Tab);
        harness.run();
    }
    panic!("Tab never reaches {what}");
}

/// The tape and the protractor with the keyboard alone: on the focused canvas, M and
/// Enter lay the tape at the view's centre, a grid step long; the arrows move its far
/// end, and after Tab its near end, a tenth of a grid step a press, so the tape reads
/// (1 + 0.3) grid steps less the near end's 0.2 along x, and 0.1 up. A and Enter lay
/// the protractor's arms right and up (90°); Tab picks the vertex (after the second arm),
/// and moving it a grid step left and down closes the angle: seen from there the arms
/// point at (2, 1) and (1, 2) grid steps, cos θ = 4/5 (36.87°).
#[test]
fn the_tape_and_the_protractor_work_from_the_keyboard() {
    use newtonlab_app::canvas::{protractor_reading, tape_reading};
    let mut harness = harness(App::new(small_ball()));
    tab_until(&mut harness, "the canvas", canvas_focused);
    let grid =
        newtonlab_app::canvas::nice_length(80.0 / harness.state().canvas.view.pixels_per_metre);
    let press = |harness: &mut Harness<'_, App>, key: Key, times: usize| {
        for _ in 0..times {
            harness.key_press(key);
            harness.run();
        }
    };
    press(&mut harness, Key::M, 1);
    press(&mut harness, Key::Enter, 1);
    press(&mut harness, Key::ArrowRight, 3);
    press(&mut harness, Key::ArrowUp, 1);
    press(&mut harness, Key::Tab, 1);
    press(&mut harness, Key::ArrowRight, 2);
    assert!(canvas_focused(&harness), "Tab stays on the canvas");
    let tape = harness.state().canvas.instruments.tape.expect("laid");
    let (length, _) = tape_reading(tape, &[]).expect("a reading");
    let expected = DVec2::new(1.1 * grid, 0.1 * grid).length();
    assert!(
        (length - expected).abs() < 1e-12 * grid,
        "{length} m, not {expected}"
    );
    press(&mut harness, Key::A, 1);
    press(&mut harness, Key::Enter, 1);
    let protractor = harness.state().canvas.instruments.protractor.expect("laid");
    let angle = protractor_reading(protractor, &[]).expect("a reading");
    assert!((angle - 90.0).abs() < 1e-9, "{angle}°");
    press(&mut harness, Key::Tab, 1);
    press(&mut harness, Key::ArrowLeft, 10);
    press(&mut harness, Key::ArrowDown, 10);
    let protractor = harness.state().canvas.instruments.protractor.expect("laid");
    let angle = protractor_reading(protractor, &[]).expect("a reading");
    let expected = (0.8_f64).acos().to_degrees();
    assert!((angle - expected).abs() < 1e-9, "{angle}°, not {expected}°");
}

/// The walk-through with the keyboard alone: Tab reaches the canvas; 2 and Enter
/// add a particle at the view's centre; the arrow keys move it a grid step (Shift a
/// tenth); 3 and Enter hang it on a spring from a fixed point; Tab on the canvas
/// selects the particle again; Escape, and Tab reaches its mass field, where 2 kg is
/// typed; Escape, Space plays; the readouts show the energy. The
/// spring starts at its natural length with the particle at rest, so the particle
/// falls: its energy stays at the start's (rk4, 1e-6 J), and every control on the way
/// has a name (the harness checks that after every frame).
#[test]
fn a_scene_built_and_run_with_the_keyboard_alone() {
    let mut harness = harness(App::new(Scene::new()));
    tab_until(&mut harness, "the canvas", canvas_focused);
    harness.key_press(Key::Num2);
    harness.run();
    harness.key_press(Key::Enter);
    harness.run();
    let app = harness.state();
    assert_eq!(app.document.scene().particles.len(), 1, "Enter added one");
    assert_eq!(app.selection, Some(Selection::Particle(0)));
    let start = app.document.scene().particles[0].position.to_dvec2();
    let step = newtonlab_app::canvas::nice_length(80.0 / app.canvas.view.pixels_per_metre) / 10.0;
    assert!(
        start.distance((app.canvas.view.center / step).round() * step) < 1e-12,
        "at the view's centre, on the grid: {start}"
    );
    harness.key_press(Key::ArrowRight);
    harness.key_press(Key::ArrowUp);
    harness.run();
    harness.key_press_modifiers(Modifiers::SHIFT, Key::ArrowLeft);
    harness.run();
    let moved = harness.state().document.scene().particles[0]
        .position
        .to_dvec2();
    assert!(
        moved.distance(start + DVec2::new(0.9 * step, step)) < 1e-12,
        "moved by (0.9, 1) grid steps: {moved} from {start}"
    );
    harness.key_press(Key::Num3);
    harness.run();
    harness.key_press(Key::Enter);
    harness.run();
    let scene = harness.state().document.scene().clone();
    assert_eq!(scene.springs.len(), 1, "Enter hung a spring on it");
    assert!(scene.springs[0].natural_length > 0.0);
    assert_eq!(harness.state().selection, Some(Selection::Spring(0)));
    harness.key_press(Key::Tab);
    harness.run();
    assert_eq!(
        harness.state().selection,
        Some(Selection::Particle(0)),
        "Tab on the canvas goes round the objects"
    );
    harness.key_press(Key::Escape);
    harness.run();
    tab_until(&mut harness, "the mass field", |h| {
        use egui_kittest::kittest::NodeT as _;
        h.query_by_label("mass")
            .is_some_and(|n| n.accesskit_node().is_focused())
    });
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.get_by_label("mass").type_text("2");
    harness.key_press(Key::Enter);
    harness.run();
    harness.key_press(Key::Escape);
    harness.run();
    let particle = &harness.state().document.scene().particles[0];
    assert_eq!(particle.mass, 2.0, "typed");
    harness.key_press(Key::Space);
    harness.run_steps(10);
    harness.key_press(Key::Space);
    harness.run();
    let simulation = harness
        .state()
        .runner
        .simulation
        .as_ref()
        .expect("it plays");
    assert!(simulation.time() > 0.0, "Space played it");
    harness.get_by_label("total (J)");
    let energy = simulation.diagnostics().energy.total();
    let start_energy = {
        let mut at_start = physics::Simulation::new(harness.state().document.scene()).unwrap();
        at_start.step_to(0.0).unwrap();
        at_start.diagnostics().energy.total()
    };
    assert!(
        (energy - start_energy).abs() < 1e-6,
        "energy {energy} J against {start_energy} J at the start"
    );
    assert!(harness.unnamed_widgets().is_empty());
}

/// The list of keys (F1) shows every shortcut and the canvas's keys.
#[test]
fn f1_lists_the_keys() {
    let mut harness = harness(App::new(one_ball()));
    harness.key_press(Key::F1);
    harness.run();
    assert!(harness.state().panels.help);
    harness.get_by_label("Play or pause");
    harness.get_by_label("Select the next / previous object");
    harness.get_by_label("This list of keys");
}

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

/// While a run plays, the latest impact is said in a polite live region of the status
/// line, where a screen reader reads it without moving the focus: after the paper's 4.3
/// collision, "At t s, A hit B." with t the impact's located instant.
#[test]
fn an_impact_is_announced_in_a_live_region() {
    use egui_kittest::kittest::NodeT as _;
    let harness = played("collision", 4);
    let impacts = impacts_of(&harness);
    assert_eq!(impacts.len(), 1);
    let sentence = format!(
        "At {} s, A hit B.",
        newtonlab_app::format::number(impacts[0].time)
    );
    let node = harness.get_by_label(&sentence);
    assert_eq!(
        node.accesskit_node().live(),
        egui::accesskit::Live::Polite,
        "a live region"
    );
}
