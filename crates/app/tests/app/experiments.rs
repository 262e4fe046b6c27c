//! The experiment series panel: an example opens with its series, Run runs it, and the
//! results follow the law; a series is added for the selected particle and edited in
//! place; its results export as the command line writes them.

use egui_kittest::kittest::Queryable;
use newtonlab_app::App;

use crate::common::{example_scene, tall_harness};

/// The range example: "Run the series" runs its 15 angles and each range is
/// v₀² sin 2a / g to 1e-9 relative; every run's paths are kept for the canvas; the CSV
/// is `sweep`'s.
#[test]
fn the_range_series_runs_and_follows_the_sine_law() {
    let harness = range_series_run();
    let results = harness.state().experiments.results[0]
        .clone()
        .expect("results");
    assert_eq!(results.rows.len(), 15, "10° to 80° by 5°");
    for row in &results.rows {
        let a = row.values[0].to_radians();
        let range = 900.0 * (2.0 * a).sin() / 9.81;
        let measured = row.measured.as_ref().unwrap()[0].as_ref().unwrap();
        assert!(
            (measured - range).abs() < 1e-9 * range,
            "{}°: {measured} against {range}",
            row.values[0]
        );
    }
    // Each run's paths, for the canvas to draw over the scene: both balls, each run.
    let paths = harness.state().experiments.paths();
    assert_eq!(paths.len(), 30, "2 balls × 15 runs");
    let landing = paths[0].iter().rev().find(|p| p.y.abs() < 0.3).copied();
    assert!(
        landing.is_some_and(|p| p.x > 0.0),
        "the 10° ball's path comes down ahead"
    );
    let csv = newtonlab_app::experiments::to_csv(&results);
    assert!(csv.starts_with("Ball.velocity.angle,Ball.x at Ball.y crosses 0 down\n10,"));
    assert_eq!(csv.lines().count(), 16);
}

/// The range example with its series run to the end.
fn range_series_run() -> egui_kittest::Harness<'static, App> {
    let mut harness = tall_harness(App::new(example_scene("projectile-range")));
    let run = harness
        .get_all_by_label("Run the series")
        .next()
        .expect("a run button");
    // Below the readouts and the graphs, past the window's height: scrolled to first.
    run.scroll_to_me();
    harness.run();
    harness
        .get_all_by_label("Run the series")
        .next()
        .expect("a run button")
        .click();
    harness.step();
    let ctx = harness.ctx.clone();
    harness.state_mut().experiments.finish(&ctx);
    harness.step();
    harness
}

/// Clicks the control labelled `label`, scrolled into view first as a user would: the
/// series are below the graphs, past the window's height.
fn click_in_view(harness: &mut egui_kittest::Harness<'_, App>, label: &str) {
    harness.get_by_label(label).scroll_to_me();
    harness.run();
    harness.get_by_label(label).click();
    harness.run();
}

/// "Add an experiment series" adds one for the selected particle; a field typed in it
/// changes the scene's series (undoably), a bad one is shown in red words, "choose…"
/// offers the particle's numbers to vary and "add a measure…" measures of it.
#[test]
fn a_series_is_added_and_edited_in_place() {
    let mut harness = tall_harness(App::new(example_scene("projectile")));
    // Below the graph's plot, out of the window's height: scrolled to, as a user would.
    harness
        .get_by_label("Add an experiment series")
        .scroll_to_me();
    harness.run();
    harness.get_by_label("Add an experiment series").click();
    harness.run();
    let series = &harness.state().document.scene().series;
    assert_eq!(series.len(), 1);
    assert_eq!(series[0].vary, "Ball.velocity.angle");
    let field = harness.get_by_label("step");
    field.focus();
    harness.run();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness.get_by_label("step").type_text("15");
    harness.key_press(egui::Key::Enter);
    harness.run();
    assert_eq!(harness.state().document.scene().series[0].step, 15.0);
    harness.get_by_label("vary").focus();
    harness.run();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness.get_by_label("vary").type_text("Ball.weight");
    harness.key_press(egui::Key::Enter);
    harness.run();
    harness.get_by_label_contains("no number of that name");
    harness.state_mut().undo();
    harness.run();
    assert_eq!(
        harness.state().document.scene().series[0].vary,
        "Ball.velocity.angle"
    );
    click_in_view(&mut harness, "choose…");
    harness.get_by_label("Ball.quadratic_drag").click();
    harness.run();
    assert_eq!(
        harness.state().document.scene().series[0].vary,
        "Ball.quadratic_drag",
        "chosen from the particle's numbers"
    );
    click_in_view(&mut harness, "add a measure…");
    harness.get_by_label("t at Ball.y crosses 0 down").click();
    harness.run();
    assert_eq!(
        harness.state().document.scene().series[0].measure,
        ["max Ball.y", "t at Ball.y crosses 0 down"],
        "added from the menu"
    );
}

/// A series exports as a figure that says what it shows: titled by its measure against
/// its setting, the x axis with the setting's unit, the y axis with the measure's, and
/// the legend's long label inside the page (1200 px wide) rather than cut off at its edge.
#[test]
fn a_series_figure_is_titled_labelled_and_keeps_its_legend_on_the_page() {
    use newtonlab_app::figure::Format;
    let harness = range_series_run();
    let app = harness.state();
    let results = app.experiments.results[0].clone().expect("results");
    let svg =
        newtonlab_app::figure::series(app.document.scene(), &results, Format::Svg).expect("an SVG");
    let svg = String::from_utf8(svg).expect("text");
    let label = "Ball.x at Ball.y crosses 0 down";
    for expected in [
        format!("{label} against Ball.velocity.angle"),
        "Ball.velocity.angle (°)".to_owned(),
        format!("{label} (m)"),
    ] {
        assert!(svg.contains(&expected), "{expected} in the SVG");
    }
    assert!(!svg.contains("Series 1"), "a title that says what it is");
    // The legend's entry: where it starts, and its width in the figure's font.
    let entry = svg
        .split("<text")
        .find(|t| {
            t.split_once('>')
                .and_then(|(_, rest)| rest.split_once("</text>"))
                .is_some_and(|(content, _)| content.trim() == label)
        })
        .expect("the legend's entry");
    let x: f64 = entry
        .split("x=\"")
        .nth(1)
        .and_then(|rest| rest.split('"').next())
        .and_then(|n| n.parse().ok())
        .expect("its x");
    let width = newtonlab_app::figure::text_width(label);
    assert!(
        x + f64::from(width) <= 1200.0,
        "the entry ends at {} px",
        x + f64::from(width)
    );
}
