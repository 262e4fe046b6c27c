//! What every test of the app shares: a harness around the real app, the scenes the
//! tests start from, and the steps a user takes (clicks, frames, Tab).

use egui::{Key, Pos2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use newtonlab_app::{App, plots};
use physics::{Graph, Particle, Scene, World};

/// The real app in a window of a laptop's screen, 1280 × 800, after its first frame.
pub fn harness(app: App) -> Harness<'static, App> {
    harness_of_size(app, [1280.0, 800.0])
}

/// A harness taller than a laptop's screen (1280 × 1200), so that the graph panel's
/// first graph and what it reads are in view without scrolling.
pub fn tall_harness(app: App) -> Harness<'static, App> {
    harness_of_size(app, [1280.0, 1200.0])
}

fn harness_of_size(mut app: App, size: [f32; 2]) -> Harness<'static, App> {
    app.runner.unhurried = true;
    let mut harness = Harness::builder()
        .with_size(size)
        .build_ui_state(|ui, app: &mut App| app.ui(ui), app);
    harness.run();
    harness
}

/// The app on a built-in scene, played for `frames` frames and paused.
pub fn played(name: &str, frames: usize) -> Harness<'static, App> {
    let mut harness = harness(App::new(example_scene(name)));
    play_frames(&mut harness, frames);
    harness
}

/// A built-in scene.
pub fn example_scene(name: &str) -> Scene {
    physics::example(name)
        .expect("the example")
        .scene()
        .expect("it loads")
}

/// A small scene: one ball at the origin, no field.
pub fn one_ball() -> Scene {
    Scene::new()
        .with_world(World::weightless())
        .with_particle(Particle::new("ball", 1.0).velocity([1.0, 0.0]))
}

/// Clicks the canvas at `at` (press and release there).
pub fn click_canvas(harness: &mut Harness<'_, App>, at: Pos2) {
    harness.hover_at(at);
    harness.run();
    harness.drag_at(at);
    harness.run();
    harness.drop_at(at);
    harness.run();
}

/// Replaces the text of the field labelled `label` with `text` and presses Enter, as a
/// user retypes a value.
pub fn type_into(harness: &mut Harness<'_, App>, label: &str, text: &str) {
    harness.get_by_label(label).focus();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, Key::A);
    harness.get_by_label(label).type_text(text);
    harness.key_press(Key::Enter);
    harness.run();
}

/// A drag with the primary button on the canvas from `from` to `to`.
pub fn drag_across(harness: &mut Harness<'_, App>, from: Pos2, to: Pos2) {
    harness.hover_at(from);
    harness.run();
    harness.drag_at(from);
    harness.run();
    harness.hover_at(to);
    harness.run();
    harness.drop_at(to);
    harness.run();
}

/// A ball dropped from rest in the uniform field, with a graph of its height.
pub fn dropped_ball() -> Scene {
    let mut scene = Scene::new()
        .with_world(World::default())
        .with_particle(Particle::new("ball", 1.0).position([0.0, 10.0]));
    scene.world.gravitation = false;
    scene
        .graphs
        .push(Graph::of(["ball.y"]).expect("a quantity"));
    scene
}

/// Plays `frames` frames (a quarter second each in the harness, 0.1 s of physics).
pub fn play_frames(harness: &mut Harness<'_, App>, frames: usize) {
    harness.get_by_label("Play").click();
    harness.run_steps(frames);
    harness.get_by_label("Pause").click();
    harness.run();
}

/// The impacts the run's recording holds.
pub fn impacts_of(harness: &Harness<'_, App>) -> Vec<physics::ImpactRecord> {
    let recording = harness.state().runner.recording.as_ref();
    recording.expect("recorded").impacts().to_vec()
}

/// The rows of a graph's CSV export as numbers, after its header.
pub fn csv_rows(app: &App, graph: usize) -> (String, Vec<Vec<f64>>) {
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

/// A ball of 5 cm moving at 1 m/s, no field: small on the canvas, so that drags can end
/// beside it.
pub fn small_ball() -> Scene {
    Scene::new()
        .with_world(World::weightless())
        .with_particle(Particle::new("ball", 1.0).radius(0.05).velocity([1.0, 0.0]))
}

/// The bits of a simulation's positions and velocities.
pub fn bits(simulation: &physics::Simulation) -> Vec<u64> {
    simulation
        .positions()
        .iter()
        .chain(simulation.velocities())
        .flat_map(|v| [v.x.to_bits(), v.y.to_bits()])
        .collect()
}

/// A run of `scene` from its start, `steps` steps long.
pub fn fresh_run(scene: &Scene, steps: u64) -> physics::Simulation {
    let mut simulation = physics::Simulation::new(scene).expect("a valid scene");
    for _ in 0..steps {
        simulation.step().expect("steps");
    }
    simulation
}

/// Whether the canvas has the keyboard focus (its accessible name starts "Canvas:").
pub fn canvas_focused(harness: &Harness<'_, App>) -> bool {
    use egui_kittest::kittest::NodeT as _;
    harness
        .get_by_label_contains("Canvas:")
        .accesskit_node()
        .is_focused()
}

/// Presses Tab until `done` holds, at most 300 times: what Tab reaches.
pub fn tab_until(
    harness: &mut Harness<'_, App>,
    what: &str,
    done: impl Fn(&Harness<'_, App>) -> bool,
) {
    for _ in 0..300 {
        if done(harness) {
            return;
        }
        harness.key_press(Key::Tab);
        harness.run();
    }
    panic!("Tab never reaches {what}");
}

/// The period of a pendulum of `length` m released at rest `amplitude` degrees from the
/// vertical, g = 9.81: 4 √(L/g) K(sin(θ₀/2)), K by the arithmetic–geometric mean (written
/// apart from the app and the physics, as the theory the tests hold them to).
pub fn pendulum_period(length: f64, amplitude: f64) -> f64 {
    let k = (amplitude.to_radians() / 2.0).sin();
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    for _ in 0..20 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    4.0 * (length / 9.81).sqrt() * std::f64::consts::PI / (2.0 * a)
}
