//! Rigid bodies in the app: the Box tool draws one, a click selects it and the inspector
//! shows its fields, a drag moves it, Play moves it as the physics says, Delete removes it.

use egui_kittest::kittest::Queryable;
use newtonlab_app::App;
use newtonlab_app::canvas::Selection;
use physics::{DVec2, Scene, World};

use crate::common::{drag_across, example_scene, harness, play_frames};

#[test]
fn the_box_tool_draws_a_box_corner_to_corner() {
    let scene = Scene::new().with_world(World::gravity_only());
    let mut harness = harness(App::new(scene));
    harness.get_by_label("Box").click();
    harness.run();
    let app = harness.state();
    let (rect, view) = (app.canvas.rect, app.canvas.view);
    let (from, to) = (DVec2::new(-1.0, 0.0), DVec2::new(1.0, 0.5));
    drag_across(
        &mut harness,
        view.to_screen(rect, from),
        view.to_screen(rect, to),
    );
    let scene = harness.state().document.scene();
    assert_eq!(scene.bodies.len(), 1, "a box was added");
    let body = &scene.bodies[0];
    // The corners land on the snapping grid, a tenth of the drawn grid's spacing.
    let step = newtonlab_app::canvas::nice_length(80.0 / view.pixels_per_metre) / 10.0;
    assert!((body.width - 2.0).abs() <= step && (body.height - 0.5).abs() <= step);
    assert!((body.position.to_dvec2() - DVec2::new(0.0, 0.25)).length() <= step);
    assert_eq!(body.total_mass(), 1.0);
    assert_eq!(harness.state().selection, Some(Selection::Body(0)));
    harness.get_by_label("width");
    harness.get_by_label("density");
}

#[test]
fn a_body_is_selected_edited_moved_played_and_deleted() {
    let mut harness = harness(App::new(example_scene("thrown-board")));
    let app = harness.state();
    let centre = app
        .canvas
        .view
        .to_screen(app.canvas.rect, DVec2::new(0.0, 1.5));
    crate::common::click_canvas(&mut harness, centre);
    assert_eq!(harness.state().selection, Some(Selection::Body(0)));
    harness.get_by_label("angle").focus();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness.get_by_label("angle").type_text("30");
    harness.key_press(egui::Key::Enter);
    harness.run();
    assert_eq!(harness.state().document.scene().bodies[0].angle, 30.0);
    let to = centre + egui::vec2(40.0, 0.0);
    drag_across(&mut harness, centre, to);
    let moved = harness.state().document.scene().bodies[0]
        .position
        .to_dvec2();
    // Moved right; its centroid on the snapping grid, within a step of where it was.
    let step = newtonlab_app::canvas::nice_length(80.0 / app_scale(&harness)) / 10.0;
    assert!(moved.x > 0.1 && (moved.y - 1.5).abs() <= step, "{moved}");
    play_frames(&mut harness, 4);
    let app = harness.state();
    let simulation = app.runner.simulation().expect("a run");
    let t = simulation.time();
    let board = simulation.body(0);
    let expected = moved.y + 6.0 * t - 0.5 * 9.81 * t * t;
    assert!(t > 0.0 && (board.position.y - expected).abs() < 1e-9);
    harness.get_by_label("Reset").click();
    harness.run();
    harness.state_mut().selection = Some(Selection::Body(0));
    harness.key_press(egui::Key::Delete);
    harness.run();
    assert!(harness.state().document.scene().bodies.is_empty());
}

/// The canvas's pixels per metre.
fn app_scale(harness: &egui_kittest::Harness<'_, App>) -> f64 {
    harness.state().canvas.view.pixels_per_metre
}

/// A selected body shows its free-body diagram, before Play and while it runs: the held
/// block's forces sum to nothing, the sliding one's to m a down the slope.
#[test]
fn a_selected_body_shows_its_forces() {
    let mut harness = harness(App::new(example_scene("block-on-incline")));
    harness.state_mut().selection = Some(Selection::Body(0));
    harness.run();
    let scene = harness.state().document.scene().clone();
    let total: DVec2 = scene.body_forces(0).iter().map(|f| f.force).sum();
    assert!(total.length() < 1e-9, "held: {total}");
    harness.state_mut().selection = Some(Selection::Body(1));
    play_frames(&mut harness, 2);
    let app = harness.state();
    let simulation = app.runner.simulation().expect("a run");
    let forces = simulation.body_forces(1);
    assert!(
        forces.iter().any(|f| f.friction),
        "friction acts on the slide"
    );
    let total: DVec2 = forces.iter().map(|f| f.force).sum();
    let a = simulation.body(1).acceleration;
    assert!(
        (total - a * 2.0).length() < 1e-9,
        "{total} against m a = {}",
        a * 2.0
    );
}

/// The Polygon tool: corners clicked one by one, the first clicked again to close; the body
/// is their convex outline, counter-clockwise, its centroid where the outline's is.
#[test]
fn the_polygon_tool_makes_a_body_of_the_corners_clicked() {
    let scene = Scene::new().with_world(World::gravity_only());
    let mut harness = harness(App::new(scene));
    harness.get_by_label("Polygon").click();
    harness.run();
    let app = harness.state();
    let (rect, view) = (app.canvas.rect, app.canvas.view);
    // Clockwise on purpose: the outline is made counter-clockwise.
    let corners = [
        DVec2::new(0.0, 0.0),
        DVec2::new(0.0, 1.0),
        DVec2::new(2.0, 0.0),
    ];
    for corner in corners.iter().chain([&corners[0]]) {
        crate::common::click_canvas(&mut harness, view.to_screen(rect, *corner));
    }
    let scene = harness.state().document.scene();
    assert_eq!(scene.bodies.len(), 1, "a polygon was added");
    let body = &scene.bodies[0];
    let physics::Shape::Polygon(vertices) = &body.shape else {
        panic!("a polygon: {body:?}");
    };
    assert_eq!(vertices.len(), 3);
    assert!(physics::moments(vertices).area > 0.0, "counter-clockwise");
    let step = newtonlab_app::canvas::nice_length(80.0 / view.pixels_per_metre) / 10.0;
    let centroid = body.position.to_dvec2();
    assert!(
        (centroid - DVec2::new(2.0 / 3.0, 1.0 / 3.0)).length() <= 2.0 * step,
        "{centroid}"
    );
    assert!((body.total_mass() - 1.0).abs() < 1e-15);
    assert!(harness.state().canvas.corners.is_empty());
}
