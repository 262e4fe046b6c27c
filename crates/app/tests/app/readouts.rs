//! Readouts and graphs: the whole run recorded, impacts marked and listed, the energy ledger.

use egui_kittest::kittest::Queryable;
use newtonlab_app::{App, plots};
use physics::{Of, Particle, Quantity, Scene, World};

use crate::common::{
    csv_rows, dropped_ball, example_scene, harness, impacts_of, play_frames, played, tall_harness,
};

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
    assert_eq!(
        harness.state().document.scene().graphs[0].x.to_string(),
        "ball.y"
    );
    harness.get_by_label("use time").click();
    harness.run();
    // A series added after the run has data from t = 0.
    harness.get_by_label("total energy (J)").click();
    harness.run();
    harness.get_by_label("Reset").click();
    harness.run();
    assert!(harness.state().runner.is_editing(), "reset");

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

/// The readouts keep the energy books while the damped spring plays: damping has taken
/// E₀ − E(t) of the closed form (x − 10 = 5 e^(−γt)(cos ωt + (γ/ω) sin ωt), γ = 0.125,
/// ω² = 1 − γ²), to 1e-9 J, and the panel shows it beside the numerical error.
#[test]
fn the_readouts_show_what_damping_took_and_the_numerical_error() {
    let harness = played("spring-damped-light", 8);
    harness.get_by_label("taken by damping (J)");
    harness.get_by_label("numerical error");
    let simulation = harness.state().runner.simulation().expect("playing");
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

/// A rod's angle and length are plotted from the run: the 60° pendulum's `rod.angle`
/// starts at 60°, never leaves ±60° (energy is kept: 1e-6° allows rounding), and its
/// `rod.length` stays 2 m to 1e-9; the graph's chips offer them (clicking adds them).
#[test]
fn a_rods_angle_and_length_are_plotted() {
    let mut harness =
        crate::common::tall_harness(App::new(crate::common::example_scene("pendulum")));
    play_frames(&mut harness, 30);
    // The first graph's chips (each graph has its own).
    for chip in ["rod.angle (°)", "rod.length (m)"] {
        harness
            .get_all_by_label(chip)
            .next()
            .expect("a chip")
            .click();
        harness.run();
    }
    let graph = &harness.state().document.scene().graphs[0];
    assert!(
        graph.y.iter().any(|y| y.to_string() == "rod.angle"),
        "{:?}",
        graph.y
    );
    let (header, rows) = csv_rows(harness.state(), 0);
    let columns: Vec<&str> = header.split(',').collect();
    let angle = columns
        .iter()
        .position(|c| c.starts_with("rod.angle"))
        .expect("an angle column");
    let length = columns
        .iter()
        .position(|c| c.starts_with("rod.length"))
        .expect("a length column");
    assert!(
        (rows[0][angle] - 60.0).abs() < 1e-9,
        "starts at {}",
        rows[0][angle]
    );
    assert!(rows.len() > 100, "a run of samples");
    for row in &rows {
        assert!(row[angle].abs() <= 60.0 + 1e-6, "{}°", row[angle]);
        assert!((row[length] - 2.0).abs() < 1e-9, "{} m", row[length]);
    }
    assert!(
        rows.iter().any(|r| r[angle] < -59.0),
        "it swings to the other side"
    );
}

/// A graph reads its series: with "extremes and zeros" on, once the run stops, the 60°
/// pendulum's `bob.x` has its maxima located in the run — at whole periods,
/// 4 √(L/g) K(sin 30°) = 3.044625 s, to 1e-8 s (rk4's error over a few periods is some
/// 1e-12 s; a parabola through samples 5 ms apart is good to some 1e-7 s only), at
/// 2 sin 60° m to 1e-9 m — and gives the period from them over their two whole cycles
/// (three maxima: two cycles to compare), to its 6 decimals, saying they were located.
#[test]
fn a_graph_reads_the_period_of_its_series() {
    let mut harness =
        crate::common::tall_harness(App::new(crate::common::example_scene("pendulum")));
    play_frames(&mut harness, 100);
    harness
        .get_all_by_label("extremes and zeros")
        .next()
        .expect("a checkbox")
        .click();
    harness.run();
    let period = crate::common::pendulum_period(2.0, 60.0);
    let app = harness.state();
    let maxima: Vec<(f64, f64, bool)> = app
        .graphs
        .extremes(0)
        .into_iter()
        .filter(|e| e.2 && e.1 > 0.0)
        .collect();
    assert!(maxima.len() >= 2, "{maxima:?}");
    for (k, &(t, x, _)) in maxima.iter().enumerate() {
        let expected = (k + 1) as f64 * period;
        assert!(
            (t - expected).abs() < 1e-8,
            "maximum {k} at {t} s, theory {expected} s"
        );
        assert!(
            (x - 2.0 * 60_f64.to_radians().sin()).abs() < 1e-9,
            "at {x} m"
        );
    }
    let readings = &app.graphs.readings(0);
    let text = readings
        .iter()
        .find(|r| r.starts_with("period of bob.x"))
        .unwrap_or_else(|| panic!("no period among {readings:?}"));
    assert!(
        text.contains("located in the run") && text.contains("2 cycles of 1 maximum"),
        "{text}"
    );
    let number: f64 = text
        .split(": ")
        .nth(1)
        .and_then(|rest| rest.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("a period in {text:?}"));
    assert!(
        (number - period).abs() < 0.6e-6,
        "{text}: theory {period} s"
    );
}

/// A graph exports as a figure to print: a PNG of 1200 × 800 pixels whose plot is drawn
/// (many pixels neither white nor grey: the curves), and an SVG holding the title, the
/// axes' quantities with their units, tick numbers and the legend's entries.
#[test]
fn a_graph_exports_as_a_figure_with_axes_and_units() {
    use newtonlab_app::figure::{self, Format};
    let harness = played("pendulum", 20);
    let app = harness.state();
    let recording = app.runner.recording.as_ref().expect("recorded");
    let graph = &app.document.scene().graphs[0];
    let png =
        figure::graph(recording, graph, None, "Swing of the bob", Format::Png).expect("a PNG");
    let decoder = png::Decoder::new(std::io::Cursor::new(png));
    let mut reader = decoder.read_info().expect("a PNG that reads back");
    let mut pixels = vec![0; reader.output_buffer_size().expect("a size")];
    let info = reader.next_frame(&mut pixels).expect("its pixels");
    assert_eq!((info.width, info.height), figure::SIZE, "printable size");
    let coloured = pixels
        .chunks(3)
        .filter(|p| p[0].abs_diff(p[1]) > 40 || p[1].abs_diff(p[2]) > 40)
        .count();
    assert!(
        coloured > 1000,
        "the curve is drawn: {coloured} coloured pixels"
    );
    let svg =
        figure::graph(recording, graph, None, "Swing of the bob", Format::Svg).expect("an SVG");
    let svg = String::from_utf8(svg).expect("text");
    for expected in [
        "<svg",
        "Swing of the bob",
        "t (s)",
        "bob.x (m)",
        "(m)",
        "1.0",
    ] {
        assert!(svg.contains(expected), "{expected} in the SVG");
    }
    let texts = svg.matches("</text>").count();
    assert!(
        texts >= 12,
        "a title, two axes' names, the legend and tick numbers: {texts}"
    );
}

/// A sine fitted to a spring's motion: a bob of 1 kg on a spring of 4 N/m stretched
/// 0.5 m moves as x = 1 + 0.5 cos 2t (rk4 follows it to 1e-9 m), so the fit reads A =
/// 0.5, ω = 2 rad/s, φ = π/2 and c = 1, each to 1e-6, with tiny uncertainties.
#[test]
fn a_sine_fitted_to_a_spring_reads_its_amplitude_and_frequency() {
    use newtonlab_app::analysis::Model;
    use physics::{Graph, Spring};
    let mut scene = Scene::new()
        .with_world(World::no_forces())
        .with_particle(Particle::new("bob", 1.0).radius(0.05).position([1.5, 0.0]))
        .with_spring(Spring::new("s", "bob", [0.0, 0.0], 4.0, 1.0));
    scene.graphs.push(Graph::of(["bob.x"]).expect("a quantity"));
    let mut harness = crate::common::harness(App::new(scene));
    play_frames(&mut harness, 60);
    harness.state_mut().graphs.set_fit(0, Some(Model::Sine));
    harness.run();
    let app = harness.state();
    let recording = app.runner.recording.as_ref().expect("recorded");
    let column = |q: &str| {
        let c = recording
            .column(&Quantity::parse(q).expect("a quantity"))
            .expect("recorded");
        (0..recording.len())
            .map(|k| recording.at(k, c))
            .collect::<Vec<f64>>()
    };
    let fit =
        newtonlab_app::analysis::fit(Model::Sine, &column("t"), &column("bob.x")).expect("a fit");
    let truth = [0.5, 2.0, std::f64::consts::FRAC_PI_2, 1.0];
    for (k, (got, want)) in fit.parameters.iter().zip(truth).enumerate() {
        assert!(
            (got - want).abs() < 1e-6,
            "{}: {got} against {want}",
            Model::Sine.names()[k]
        );
        assert!(fit.uncertainties[k] < 1e-6, "{}", fit.uncertainties[k]);
    }
    assert!(
        app.graphs
            .readings(0)
            .iter()
            .any(|r| r.starts_with("bob.x, sine")),
        "{:?}",
        app.graphs.readings(0)
    );
}

/// Runs of one scene are compared on its graphs: after a run, Reset, a new height and a
/// second run, the earlier run is kept (drawn greyed) with its own samples, the last run
/// has its own; "forget earlier runs" clears them, and a new scene starts afresh.
#[test]
fn earlier_runs_are_kept_for_the_graphs_until_forgotten() {
    use physics::Quantity;
    let mut harness = harness(App::new(dropped_ball()));
    play_frames(&mut harness, 3);
    harness.get_by_label("Reset").click();
    harness.run();
    harness
        .state_mut()
        .document
        .apply(newtonlab_app::edit::Edit::MoveParticle, |scene| {
            scene.particles[0].position = [0.0, 5.0].into();
        });
    play_frames(&mut harness, 3);
    let runner = &harness.state().runner;
    assert_eq!(runner.earlier.len(), 1, "the first run kept");
    let y = Quantity::parse("ball.y").expect("a quantity");
    let first_y =
        |recording: &newtonlab_app::Recording| recording.value(0, &y).expect("ball.y recorded");
    assert!(
        (first_y(&runner.earlier[0]) - 10.0).abs() < 1e-12,
        "the earlier run from 10 m"
    );
    let last = runner.recording.as_ref().expect("the last run");
    assert!((first_y(last) - 5.0).abs() < 1e-12, "the last run from 5 m");
    harness.get_by_label("forget earlier runs").scroll_to_me();
    harness.run();
    harness.get_by_label("forget earlier runs").click();
    harness.run();
    assert!(harness.state().runner.earlier.is_empty(), "forgotten");
}

/// The buttons that add a system quantity to a graph, and those that take one off it,
/// say it in words of the language, not as the CSV column: "kinetic energy (J)",
/// "× kinetic energy (J)", "kinetische Energie (J)".
#[test]
fn system_quantities_are_offered_in_words() {
    use newtonlab_app::i18n::{Language, set_language};
    let mut harness =
        crate::common::tall_harness(App::new(crate::common::example_scene("pendulum")));
    harness.run();
    harness
        .get_all_by_label("kinetic energy (J)")
        .next()
        .expect("in English");
    assert!(
        harness
            .query_all_by_label("kinetic_energy (J)")
            .next()
            .is_none()
    );
    let mut marbles =
        crate::common::tall_harness(App::new(crate::common::example_scene("marble-run")));
    marbles.run();
    marbles.get_by_label("× kinetic energy (J)");
    assert!(
        marbles
            .query_all_by_label("× kinetic_energy (J)")
            .next()
            .is_none()
    );
    set_language(Language::German);
    harness.run();
    harness.run();
    let found = harness
        .query_all_by_label("kinetische Energie (J)")
        .next()
        .is_some();
    set_language(Language::English);
    assert!(found, "in German");
}

/// "Ask about this" beside a graph's period: a question `period bob.x` added to a new
/// lesson, whose answer key (the run measured as a series measures it) is the elliptic
/// integral's period of the 60° pendulum to 1e-6 s.
#[test]
fn a_graphs_period_becomes_a_lesson_question() {
    let mut harness =
        crate::common::tall_harness(App::new(crate::common::example_scene("pendulum")));
    play_frames(&mut harness, 100);
    harness
        .get_all_by_label("extremes and zeros")
        .next()
        .expect("a checkbox")
        .click();
    harness.run();
    harness.get_by_label("Ask about this").click();
    harness.run();
    let scene = harness.state().document.scene().clone();
    let lesson = scene.lesson.clone().expect("a lesson");
    assert_eq!(lesson.questions[0].measure, "period bob.x");
    let key = lesson.answers(&scene).unwrap()[0].clone().unwrap();
    let period = crate::common::pendulum_period(2.0, 60.0);
    assert!(
        (key - period).abs() < 1e-6,
        "key {key} s, theory {period} s"
    );
}

/// Nothing in the right panel moves when Play fills it in: before Play the readouts
/// have the rows (each value a dash) and the bars they have while the run plays, the
/// impacts' list is there, and a graph has its row of marks and fits and an empty plot
/// of the run's height; so the first graph's heading, and the button below every graph,
/// stand where they stood. In a scene with forces of one's own, one with drag, one with
/// a rod.
#[test]
fn play_does_not_move_the_graphs() {
    for example in ["anharmonic-oscillator", "terminal-speed", "pendulum"] {
        let mut harness = tall_harness(App::new(example_scene(example)));
        let scene = harness.state().document.scene().clone();
        let title = scene.graphs[0].title.clone().expect("a titled graph");
        let tops = |harness: &egui_kittest::Harness<'_, App>| {
            [
                harness.get_by_label(&title).rect().top(),
                harness.get_by_label("Add a graph").rect().top(),
            ]
        };
        let before = tops(&harness);
        assert!(
            harness.query_all_by_label("—").next().is_some(),
            "{example}: no dashes before Play"
        );
        play_frames(&mut harness, 5);
        assert!(
            harness.query_all_by_label("—").next().is_none(),
            "{example}"
        );
        let after = tops(&harness);
        for (what, (before, after)) in ["the first graph's heading", "Add a graph"]
            .into_iter()
            .zip(before.into_iter().zip(after))
        {
            assert!(
                (after - before).abs() < 0.5,
                "{example}: {what} moved from {before} to {after} px on Play"
            );
        }
    }
}
