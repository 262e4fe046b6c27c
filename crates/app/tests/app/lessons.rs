//! The three lessons a teacher prepares, each measured to its theory's digits in under
//! ten actions from a fresh app: every click and key press is counted.

use egui::Key;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use newtonlab_app::App;
use physics::{DVec2, Scene};

use crate::common::{harness, pendulum_period};

/// A fresh app and the actions taken in it.
struct Lesson {
    harness: Harness<'static, App>,
    actions: usize,
}

impl Lesson {
    fn new() -> Self {
        Self {
            harness: harness(App::new(Scene::default())),
            actions: 0,
        }
    }

    /// Clicks the widget labelled `label` (the first, where a label repeats).
    fn click(&mut self, label: &str) {
        self.harness
            .get_all_by_label(label)
            .next()
            .unwrap_or_else(|| panic!("no {label:?}"))
            .click();
        self.harness.run();
        self.actions += 1;
    }

    /// Opens the example titled `title` from the Examples menu.
    fn open_example(&mut self, title: &str) {
        self.click("Examples");
        self.click(title);
    }

    /// Presses Play and lets `frames` frames pass (0.1 s of physics each).
    fn play(&mut self, frames: usize) {
        self.harness.get_by_label("Play").click();
        self.harness.run_steps(frames);
        self.actions += 1;
    }

    /// Presses a key.
    fn key(&mut self, key: Key) {
        self.harness.key_press(key);
        self.harness.run();
        self.actions += 1;
    }

    /// Drags on the canvas from `from` to `to` (one action).
    fn drag(&mut self, from: egui::Pos2, to: egui::Pos2) {
        crate::common::drag_across(&mut self.harness, from, to);
        self.actions += 1;
    }

    fn shown(&self) -> &physics::Simulation {
        self.harness
            .state()
            .runner
            .simulation()
            .expect("a run shown")
    }
}

/// The projectile: Examples → Projectile, Play, Pause (once it has landed), "« impact" —
/// five actions — and
/// the ball is shown at its landing, located: x = v² sin 2θ / g = 10.19368 m for 10 m/s
/// at 45° (g = 9.81), at t = 2 v sin θ / g = 1.44160 s, each to 1e-9 (rk4 is exact for
/// a constant acceleration; the landing is located to 1e-12 s).
#[test]
fn the_projectiles_range_in_five_actions() {
    let mut lesson = Lesson::new();
    lesson.open_example("Projectile: range against launch angle");
    lesson.play(15);
    lesson.click("Pause");
    lesson.click("« impact");
    let (v, angle, g) = (10.0_f64, 45_f64.to_radians(), 9.81);
    let (range, flight) = (v * v * (2.0 * angle).sin() / g, 2.0 * v * angle.sin() / g);
    let shown = lesson.shown();
    let x = shown.positions()[0].x;
    assert!(
        (x - range).abs() < 1e-9,
        "landed at {x} m, theory {range} m"
    );
    assert!((shown.time() - flight).abs() < 1e-9, "{} s", shown.time());
    assert!(lesson.actions < 10, "{} actions", lesson.actions);
}

/// The collision: Examples → Two-ball collision, Play, Pause, "« impact" — five actions —
/// and the balls are shown leaving the impact as the impulse formula says: for equal masses and
/// restitution 1 the impulse is along the line of centres n = (√(1 − 0.53²), 0.53) at
/// contact, so A' = v − (v·n) n = (5.618, −8.989) m/s and B' = (v·n) n, to 1e-9 m/s.
#[test]
fn the_collisions_velocities_in_five_actions() {
    let mut lesson = Lesson::new();
    lesson.open_example("Two balls colliding off-centre");
    lesson.play(5);
    lesson.click("Pause");
    lesson.click("« impact");
    let n = DVec2::new((1.0_f64 - 0.53 * 0.53).sqrt(), 0.53);
    let v = DVec2::new(20.0, 0.0);
    let (a, b) = (v - v.dot(n) * n, v.dot(n) * n);
    let shown = lesson.shown().velocities().to_vec();
    assert!(
        (shown[0] - a).length() < 1e-9,
        "A' = {} against {a}",
        shown[0]
    );
    assert!(
        (shown[1] - b).length() < 1e-9,
        "B' = {} against {b}",
        shown[1]
    );
    assert!(lesson.actions < 10, "{} actions", lesson.actions);
}

/// The pendulum: Examples → Pendulum, the tape measure laid from the pivot straight down
/// (it snaps to the pivot), T for the stopwatch, "period at the gate", Start, Play —
/// eight actions —
/// and the stopwatch reads a full period of the 60° swing, 4 √(L/g) K(sin 30°) for
/// L = 2 m, to 1e-6 s.
#[test]
fn the_pendulums_period_in_eight_actions() {
    let mut lesson = Lesson::new();
    lesson.open_example("Pendulum on a rod, released at 60°");
    lesson.click("Tape measure");
    let (rect, view) = {
        let canvas = &lesson.harness.state().canvas;
        (canvas.rect, canvas.view)
    };
    let pivot = view.to_screen(rect, DVec2::ZERO) + egui::vec2(3.0, -2.0);
    let below = view.to_screen(rect, DVec2::new(0.0, -3.0));
    lesson.drag(pivot, below);
    lesson.key(Key::T);
    lesson.click("period at the gate");
    lesson.click("Start");
    lesson.play(45);
    let reading = lesson.harness.state().stopwatch.reading;
    let period = pendulum_period(2.0, 60.0);
    assert!(
        (reading - period).abs() < 1e-6,
        "{reading} s, theory {period} s"
    );
    assert!(lesson.actions < 10, "{} actions", lesson.actions);
}
