//! Everything by keyboard and for a screen reader.

use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use newtonlab_app::{App, Selection};
use physics::{DVec2, Scene};

use crate::common::{canvas_focused, harness, impacts_of, one_ball, played, small_ball, tab_until};

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

/// The guide's walk-through with the keyboard alone: Tab reaches the canvas; 2 and Enter
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
    let simulation = harness.state().runner.simulation().expect("it plays");
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

/// F6 moves the focus from region to region — the menu bar, the tool bar, the canvas,
/// the inspector, the graphs, and the time bar once a run exists — and Shift+F6 back;
/// from a field it leaves for a region.
#[test]
fn f6_moves_the_focus_from_region_to_region() {
    let mut harness = harness(App::new(one_ball()));
    let press = |harness: &mut Harness<'_, App>, modifiers| {
        harness.key_press_modifiers(modifiers, Key::F6);
        harness.run();
    };
    let focused =
        |harness: &Harness<'_, App>, label: &str| harness.get_by_label(label).is_focused();
    press(&mut harness, Modifiers::NONE);
    assert!(focused(&harness, "File"), "first the menu bar");
    press(&mut harness, Modifiers::NONE);
    assert!(focused(&harness, "Play"), "then the tool bar");
    press(&mut harness, Modifiers::NONE);
    assert!(canvas_focused(&harness), "then the canvas");
    press(&mut harness, Modifiers::NONE);
    assert!(focused(&harness, "Inspector"), "then the inspector");
    press(&mut harness, Modifiers::NONE);
    assert!(focused(&harness, "Energy and momentum"), "then the graphs");
    press(&mut harness, Modifiers::NONE);
    assert!(
        focused(&harness, "File"),
        "no time bar before a run: round to the menu"
    );
    press(&mut harness, Modifiers::SHIFT);
    assert!(
        focused(&harness, "Energy and momentum"),
        "Shift+F6 goes back"
    );
    crate::common::play_frames(&mut harness, 3);
    harness.get_by_label("Energy and momentum").focus();
    harness.run();
    press(&mut harness, Modifiers::NONE);
    assert!(
        focused(&harness, "Step back"),
        "a run's time bar is a region"
    );
    harness.get_by_label("Reset").click();
    harness.run();
    harness.state_mut().selection = Some(Selection::Particle(0));
    harness.run();
    harness.get_by_label("mass").focus();
    harness.run();
    press(&mut harness, Modifiers::NONE);
    assert!(
        !harness.get_by_label("mass").is_focused(),
        "F6 leaves a field"
    );
}
