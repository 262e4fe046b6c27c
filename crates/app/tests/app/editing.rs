//! Editing: placing, typing, undoing, dragging, tying.

use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use newtonlab_app::edit::Edit;
use newtonlab_app::{Action, App, Selection};
use physics::{DVec2, Graph, Particle, Scene, TieKind, World};

use crate::common::{
    click_canvas, csv_rows, drag_across, harness, one_ball, play_frames, type_into,
};

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

/// Dragging a velocity arrow's tip sets the velocity, even when the pointer moves far
/// at once (the gesture starts where the button went down), as a launcher does: in polar
/// form, to the nearest 0.5 m/s and whole degree (Alt sets it freely).
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
    let velocity = app.document.scene().particles[0].velocity;
    let snapped = physics::Vector::polar(
        (expected.length() / 0.5).round() * 0.5,
        expected.y.atan2(expected.x).to_degrees().round(),
    );
    assert_eq!(velocity, snapped, "drawn {expected}");
    assert_eq!(
        app.document.undo_edit(),
        Some(Edit::SetVelocity),
        "one undo step"
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
        // The fixed end lands on the snapping grid, a tenth of the drawn grid's spacing.
        let step =
            newtonlab_app::canvas::nice_length(80.0 / app.canvas.view.pixels_per_metre) / 10.0;
        let anchor = (app.canvas.view.to_world(rect, end) / step).round() * step;
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
    let pivot = harness
        .state()
        .document
        .scene()
        .end_position(&ties[0].to)
        .expect("a fixed point");
    assert!(
        pivot.distance(anchor) < 1e-12,
        "on the grid: {pivot}, not {anchor}"
    );
    assert!(
        (length - anchor.length()).abs() < 1e-9,
        "as long as the drag: {length}"
    );
    harness.state_mut().document.apply(Edit::AddGraph, |scene| {
        scene
            .graphs
            .push(Graph::of(["rod1.tension"]).expect("a quantity"));
    });
    play_frames(&mut harness, 4);
    let app = harness.state();
    let simulation = app.runner.simulation().expect("running");
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
    type_into(&mut harness, "mass", "250 g");
    type_into(&mut harness, "velocity x", "30 km/h");
    type_into(&mut harness, "radius", "sqrt(2)/2 m");
    type_into(&mut harness, "charge", "5 kg");
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

/// A rod typed 1 m long on a bob placed 0.9 m from its pivot is flagged in the
/// inspector with both numbers (the rod pulls the bob onto its length at the start).
#[test]
fn a_rod_longer_than_its_ends_are_apart_is_flagged() {
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(Particle::new("bob", 1.0).radius(0.05).position([0.0, -0.9]))
        .with_tie(physics::Tie::rod("rod", [0.0, 0.0], "bob", 1.0));
    let mut harness = harness(App::new(scene));
    harness.state_mut().selection = Some(Selection::Tie(0));
    harness.run();
    harness.get_by_label_contains("0.9 m apart at the start, not 1 m");
}

/// The inspector shows what a person typed, not the last bit of a sum: a particle at
/// x = 0.1 + 0.2 and y = −0 reads "0.3" and "0"; the scene keeps its exact value until
/// the user types a new one.
#[test]
fn fields_show_no_last_bit_and_no_negative_zero() {
    let scene = Scene::new()
        .with_world(World::no_forces())
        .with_particle(Particle::new("ball", 1.0).position([0.1 + 0.2, -0.0]));
    let mut harness = harness(App::new(scene));
    harness.state_mut().selection = Some(Selection::Particle(0));
    harness.run();
    let value = |harness: &Harness<'_, App>, label: &str| {
        harness.get_by_label(label).value().unwrap_or_default()
    };
    assert_eq!(value(&harness, "position x"), "0.3");
    assert_eq!(value(&harness, "position y"), "0");
    let x = harness.state().document.scene().particles[0]
        .position
        .to_dvec2()
        .x;
    assert_eq!(
        x.to_bits(),
        (0.1_f64 + 0.2).to_bits(),
        "the scene's value untouched"
    );
}

/// A new scene forgets what was said of the last run: the status line's sentence.
#[test]
fn a_new_scene_forgets_the_last_runs_sentence() {
    let mut harness = crate::common::played("collision", 10);
    assert!(
        !harness.state().announcer.text.is_empty(),
        "an impact was told"
    );
    harness.key_press_modifiers(egui::Modifiers::COMMAND, Key::N);
    harness.run();
    assert!(harness.state().announcer.text.is_empty(), "forgotten");
}

/// A particle is made a solid disc by its preset, its spin typed in rpm is stored in
/// rad/s, and undo brings the point back.
#[test]
fn a_preset_makes_a_particle_turn_and_its_spin_is_typed_in_rpm() {
    let mut harness = harness(App::new(one_ball()));
    harness.state_mut().selection = Some(Selection::Particle(0));
    harness.run();
    harness.get_by_label("a solid disc").click();
    harness.run();
    assert!((harness.state().document.scene().particles[0].inertia - 0.5).abs() < 1e-15);
    harness.get_by_label("spin").focus();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.get_by_label("spin").type_text("60 rpm");
    harness.key_press(Key::Enter);
    harness.run();
    let spin = harness.state().document.scene().particles[0].spin;
    assert!(
        (spin - std::f64::consts::TAU).abs() < 1e-12,
        "60 rpm is 2π rad/s: {spin}"
    );
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert!(
        harness.state().document.scene().particles[0].inertia.abs() < 1e-15,
        "undone"
    );
}

/// Duplicate (Ctrl+D) adds a copy of the selected particle beside it, renamed and
/// selected, and undo takes it away; Copy (the system's Ctrl+C) and Paste (its Ctrl+V,
/// here the text another window copied) add a pendulum's rod with its bob to another
/// scene; text that is no scene is refused with a message and changes nothing.
#[test]
fn duplicate_copy_and_paste_add_objects_beside_their_originals() {
    let mut harness = harness(App::new(one_ball()));
    harness.state_mut().selection = Some(Selection::Particle(0));
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::D);
    harness.run();
    let scene = harness.state().document.scene().clone();
    assert_eq!(scene.particles.len(), 2);
    assert_eq!(scene.particles[1].name, "ball 2");
    assert_eq!(harness.state().selection, Some(Selection::Particle(1)));
    let (a, b) = (
        scene.particles[0].position.to_dvec2(),
        scene.particles[1].position.to_dvec2(),
    );
    assert!(b.x > a.x && b.y < a.y, "beside it, down and right: {a} {b}");
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert_eq!(
        harness.state().document.scene().particles.len(),
        1,
        "undone"
    );

    let mut pendulum = crate::common::harness(App::new(crate::common::example_scene("pendulum")));
    pendulum.state_mut().selection = Some(Selection::Tie(0));
    pendulum.run();
    pendulum.event(egui::Event::Copy);
    pendulum.run();
    let copied = pendulum.state().clipboard.clone().expect("copied");
    assert!(
        copied.contains("[[rod]]") && copied.contains("name = \"bob\""),
        "{copied}"
    );
    harness.event(egui::Event::Paste(copied));
    harness.run();
    let scene = harness.state().document.scene();
    assert_eq!(scene.particles.len(), 2, "the bob came with its rod");
    assert_eq!(scene.ties.len(), 1);
    assert!(scene.validate().is_empty());
    harness.event(egui::Event::Paste("no scene at all [".to_owned()));
    harness.run();
    assert_eq!(
        harness.state().document.scene().particles.len(),
        2,
        "nothing pasted"
    );
    harness.get_by_label_contains("Nothing pasted");
}

/// Three balls on a weightless stage at `x` = −4, 0 and 4 m, where the screen shows them.
fn three_balls() -> (Harness<'static, App>, [egui::Pos2; 3]) {
    let mut scene = Scene::new().with_world(World::weightless());
    for (name, x) in [("a", -4.0), ("b", 0.0), ("c", 4.0)] {
        scene = scene.with_particle(Particle::new(name, 1.0).position([x, 0.0]));
    }
    let harness = harness(App::new(scene));
    let app = harness.state();
    let at = |x: f64| {
        app.canvas
            .view
            .to_screen(app.canvas.rect, DVec2::new(x, 0.0))
    };
    let places = [at(-4.0), at(0.0), at(4.0)];
    (harness, places)
}

/// `harness` with Shift held through `gesture`.
fn with_shift(
    harness: &mut Harness<'static, App>,
    gesture: impl FnOnce(&mut Harness<'static, App>),
) {
    harness.event(egui::Event::ModifiersChanged(Modifiers::SHIFT));
    harness.run();
    gesture(harness);
    harness.event(egui::Event::ModifiersChanged(Modifiers::NONE));
    harness.run();
}

/// The particles' names, in order.
fn particle_names(harness: &Harness<'static, App>) -> Vec<String> {
    let scene = harness.state().document.scene();
    scene.particles.iter().map(|p| p.name.clone()).collect()
}

/// Multi-select: a click selects a ball, Shift+click adds another (and a third in and
/// out again); dragging one of them moves both by the same step, as one undo step;
/// Delete removes both, as one.
#[test]
fn objects_selected_with_shift_move_and_go_together() {
    let (mut harness, [a, b, c]) = three_balls();
    click_canvas(&mut harness, a);
    with_shift(&mut harness, |h| click_canvas(h, b));
    assert_eq!(
        harness.state().canvas.group,
        [Selection::Particle(0), Selection::Particle(1)]
    );
    assert_eq!(harness.state().selection, Some(Selection::Particle(1)));
    with_shift(&mut harness, |h| click_canvas(h, c));
    with_shift(&mut harness, |h| click_canvas(h, c));
    assert_eq!(
        harness.state().canvas.group.len(),
        2,
        "c in, then out again"
    );

    // Dragging b moves a and b together; c stays.
    drag_across(&mut harness, b, b + egui::vec2(0.0, -60.0));
    let scene = harness.state().document.scene().clone();
    let moved = |i: usize, x: f64| scene.particles[i].position.to_dvec2() - DVec2::new(x, 0.0);
    assert!(moved(0, -4.0).y > 0.5, "a moved up: {}", moved(0, -4.0));
    assert_eq!(moved(0, -4.0), moved(1, 0.0), "by the same step");
    assert_eq!(moved(2, 4.0), DVec2::ZERO, "c stays");
    assert_eq!(harness.state().document.undo_edit(), Some(Edit::MoveGroup));

    harness.key_press(Key::Delete);
    harness.run();
    assert_eq!(particle_names(&harness), ["c"], "both deleted");
    assert_eq!(
        harness.state().document.undo_edit(),
        Some(Edit::DeleteGroup)
    );
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert_eq!(particle_names(&harness).len(), 3, "undone as one");
    assert!(harness.state().canvas.group.is_empty());
}

/// A box drawn from empty space with Shift held selects what lies in it; Duplicate
/// copies both, the copies selected together; a plain click leaves one selected.
#[test]
fn a_box_drawn_with_shift_selects_what_lies_in_it() {
    let (mut harness, [a, b, c]) = three_balls();
    let (from, to) = (a + egui::vec2(-30.0, -30.0), b + egui::vec2(20.0, 30.0));
    with_shift(&mut harness, |h| drag_across(h, from, to));
    assert_eq!(
        harness.state().canvas.group,
        [Selection::Particle(0), Selection::Particle(1)]
    );
    harness.key_press_modifiers(Modifiers::COMMAND, Key::D);
    harness.run();
    assert_eq!(
        particle_names(&harness),
        ["a", "b", "c", "a 2", "b 2"],
        "both duplicated"
    );
    assert_eq!(
        harness.state().canvas.group.len(),
        2,
        "the copies selected together"
    );
    click_canvas(&mut harness, c);
    assert!(
        harness.state().canvas.group.is_empty(),
        "a plain click: one selected"
    );
}

/// A ramp's slope and length are typed (no trigonometry on its ends), and a particle is
/// put on it at a distance along it, touching its upper face: a 0.1 m ball on a ramp
/// 0.1 m thick at −30° sits 0.15 m from the segment, 1 m along it, and then slides down
/// it frictionless with a = g sin 30° (½ a t² = 0.6131… m in 0.5 s, to 1e-9 m: the
/// contact holds it on the face from t = 0).
#[test]
fn a_particle_is_put_on_a_ramp_typed_by_slope_and_length() {
    let scene = Scene::new()
        .with_particle(Particle::new("ball", 1.0).radius(0.1).position([3.0, 3.0]))
        .with_ramp(physics::Ramp::new("incline", [0.0, 0.0], [4.0, 0.0]));
    let mut harness = harness(App::new(scene));
    harness.state_mut().selection = Some(Selection::Ramp(0));
    harness.run();
    type_into(&mut harness, "slope", "-30");
    type_into(&mut harness, "length", "3");
    let ramp = harness.state().document.scene().ramps[0].clone();
    let down = DVec2::new(30_f64.to_radians().cos(), -30_f64.to_radians().sin());
    assert!(
        ramp.to.to_dvec2().distance(3.0 * down) < 1e-12,
        "to at 3 m down the slope: {:?}",
        ramp.to
    );

    harness.state_mut().selection = Some(Selection::Particle(0));
    harness.run();
    type_into(&mut harness, "along it", "1");
    let at = harness.state().document.scene().particles[0]
        .position
        .to_dvec2();
    let along = at.dot(down);
    let off = at.perp_dot(down).abs();
    assert!((along - 1.0).abs() < 1e-12, "1 m along: {along}");
    assert!((off - 0.15).abs() < 1e-12, "touching the face: {off} m off");
    assert!(at.y > down.y * along, "on the upper face: {at}");

    let mut run = physics::Simulation::new(harness.state().document.scene()).expect("it runs");
    run.step_to(0.5).expect("finite");
    let slid = run.positions()[0].dot(down) - 1.0;
    let theory = 0.5 * 9.81 * 30_f64.to_radians().sin() * 0.25;
    assert!(
        (slid - theory).abs() < 1e-9,
        "slid {slid} m, theory {theory} m"
    );
    let off = run.positions()[0].perp_dot(down).abs();
    assert!((off - 0.15).abs() < 1e-9, "still on the face: {off}");
}
