//! Play, pause, step and reset; a refused or failed run; the camera.

use egui::{Key, Modifiers};
use egui_kittest::kittest::Queryable;
use newtonlab_app::{App, Recording, Selection};
use physics::{DVec2, Follow, Integrator, Particle, Scene, Spring, View, World};

use crate::common::{harness, one_ball, play_frames};

#[test]
fn play_advances_time_and_pause_stops_it_and_reset_restores_the_scene() {
    let mut harness = harness(App::new(one_ball()));
    harness.get_by_label("Play").click();
    harness.run_steps(4);
    let t = harness.state().time();
    assert!(t > 0.0, "simulated time advanced: {t}");
    // Real time: each test frame is 1/4 s, capped at 0.1 s of physics per frame.
    assert!((t - 0.4).abs() < 0.11, "about 4 frames' worth: {t}");
    let moved = harness.state().runner.simulation().unwrap().positions()[0].x;
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
    assert!(app.runner.is_editing(), "the simulation is gone");
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
    assert!(harness.state().runner.is_editing(), "nothing built");
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
    assert!(harness.state().runner.is_editing(), "reset");
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
        ..View::default()
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
    let ball = app.runner.simulation().unwrap().positions()[0];
    assert!(ball.x > 50.0, "the ball went far: {ball}");
    assert!(
        app.canvas.view.center.distance(ball) < 3.0,
        "the camera is on it: {} vs {ball}",
        app.canvas.view.center
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
    let now = app.runner.simulation().unwrap().positions()[0];
    let earlier = now - DVec2::new(30.0, 0.0);
    assert!(now.x > 35.0, "the ball went on: {now}");
    for point in [now, earlier] {
        let at = app.canvas.view.to_screen(app.canvas.rect, point);
        assert!(app.canvas.rect.contains(at), "{point} is in view");
    }
}

/// The canvas's toggles are part of the scene's `[view]`: a scene saved with trails on
/// and velocity arrows off opens so (the others as the app's defaults), and the view
/// saved writes every toggle as it is, through the file and back.
#[test]
fn the_canvas_toggles_open_and_save_with_the_scene() {
    let mut scene = one_ball();
    scene.view = Some(View {
        trails: Some(true),
        velocity: Some(false),
        ..View::default()
    });
    let mut harness = harness(App::new(scene));
    harness.run();
    let overlays = harness.state().canvas.overlays;
    assert!(overlays.trails && !overlays.velocity, "as saved");
    assert!(overlays.names && !overlays.force, "the defaults");
    harness.state_mut().canvas.overlays.force = true;
    let view = harness.state().canvas.scene_view();
    assert_eq!(
        (
            view.trails,
            view.velocity,
            view.acceleration,
            view.force,
            view.names
        ),
        (Some(true), Some(false), Some(false), Some(true), Some(true))
    );
    let mut saved = harness.state().document.scene().clone();
    saved.view = Some(view.clone());
    let again = physics::Scene::from_toml(&saved.to_toml()).expect("reads back");
    assert_eq!(again.view, Some(view));
}

/// Play keeps the view as it was: the time machine's bar is there before a run (greyed
/// out), and the readouts' numbers widening their panel by a few points do not rescale
/// the canvas.
#[test]
fn play_does_not_rescale_the_canvas() {
    let mut harness = harness(App::new(crate::common::example_scene("galileo-incline")));
    let before = harness.state().canvas.view;
    play_frames(&mut harness, 30);
    let after = harness.state().canvas.view;
    assert!(
        (after.pixels_per_metre - before.pixels_per_metre).abs() < 1e-9,
        "{} px/m before Play, {} after",
        before.pixels_per_metre,
        after.pixels_per_metre
    );
    assert_eq!(after.center, before.center);
}

/// Projector mode and back keeps the view: the same centre, and the scale it had (the
/// canvas grows when the panels go, and shows more; it never resets to a default zoom).
#[test]
fn projector_mode_and_back_keeps_the_view() {
    let mut harness = harness(App::new(crate::common::example_scene("pendulum")));
    let before = harness.state().canvas.view;
    let shown = |harness: &egui_kittest::Harness<'_, App>| {
        let canvas = &harness.state().canvas;
        DVec2::new(
            f64::from(canvas.rect.width()),
            f64::from(canvas.rect.height()),
        ) / canvas.view.pixels_per_metre
    };
    let box_before = shown(&harness);
    harness.key_press(Key::F11);
    harness.run();
    harness.run();
    let in_projector = shown(&harness);
    assert_eq!(harness.state().canvas.view.center, before.center);
    assert!(
        in_projector.x >= box_before.x * (1.0 - 1e-9)
            && in_projector.y >= box_before.y * (1.0 - 1e-9),
        "all that was shown is shown: {box_before} then {in_projector}"
    );
    assert!(
        in_projector.x <= box_before.x * 1.001 || in_projector.y <= box_before.y * 1.001,
        "and no more than needed: {box_before} then {in_projector}"
    );
    harness.key_press(Key::F11);
    harness.run();
    harness.run();
    let after = harness.state().canvas.view;
    assert_eq!(after.center, before.center);
    assert!(
        (after.pixels_per_metre / before.pixels_per_metre - 1.0).abs() < 1e-9,
        "{} px/m before, {} after",
        before.pixels_per_metre,
        after.pixels_per_metre
    );
}
