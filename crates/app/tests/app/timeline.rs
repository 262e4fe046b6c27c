//! The time machine: going back exactly, and branching a new run.

use egui::Key;
use egui_kittest::kittest::Queryable;
use newtonlab_app::edit::Edit;
use newtonlab_app::{Action, App};

use crate::common::{bits, example_scene, fresh_run, harness, play_frames};

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
    let shown = app.runner.simulation().expect("shown");
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
    let walked = harness.state().runner.simulation().unwrap();
    assert!(
        bits(walked) == bits(&fresh(1)),
        "Step walks forward through the run"
    );
    harness.get_by_label("Edit from here").click();
    harness.run();
    let app = harness.state();
    assert!(app.runner.is_editing(), "back to editing");
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
    assert_eq!(app.document.undo_edit(), Some(Edit::EditFromHere));
    harness.state_mut().perform(Action::Undo);
    harness.run();
    assert_eq!(harness.state().document.scene(), &scene, "undone");
}

/// Branching: gone back to the middle of a run, Play goes on from there and forgets
/// what came after; with nothing changed, the new future is the old one bit for bit (a
/// deterministic step from the same state). Then Edit from here, Play: the run starts
/// at the moment's time from the moment's state and, for this fixed-step scene
/// without resting contact, is still the original run bit for bit (as promised:
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
    let shown = runner.simulation().expect("running");
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
    let shown = runner.simulation().expect("running");
    assert!(
        steps > 0 && shown.time() > start,
        "played on from {start} s"
    );
    assert!(
        bits(shown) == bits(&fresh_run(&scene, middle + steps)),
        "the branch goes on as the run did, bit for bit"
    );
}
