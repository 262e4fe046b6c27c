//! A thousand balls settling in a box: resting contact at scale.

mod common;

use common::example_scene;
use physics::{Simulation, generated};

/// The example file is the generator's output, so the benchmark (which generates pits of
/// any size) and the example measure the same scene.
#[test]
fn the_example_is_the_generated_pit() {
    let scene = example_scene("ball-pit");
    assert_eq!(
        scene,
        generated::ball_pit(1000),
        "regenerate examples/scenes/ball-pit.toml"
    );
}

/// The largest overlap of any two balls, as a fraction of the smaller radius.
fn largest_overlap(simulation: &Simulation) -> f64 {
    let (x, r) = (simulation.positions(), simulation.radii());
    let mut worst: f64 = 0.0;
    for i in 0..x.len() {
        for j in i + 1..x.len() {
            let overlap = r[i] + r[j] - x[i].distance(x[j]);
            worst = worst.max(overlap / r[i].min(r[j]));
        }
    }
    worst
}

/// With restitution 0.5 the 1,000-ball pit settles. Impacts and resting contacts only
/// take energy away, but the position correction of overlaps moves balls without
/// changing their velocities, so the total energy may tick up between samples by the
/// potential energy of a correction (measured: up to 1.1 J between these samples 0.05 s
/// apart); it never climbs above its initial value. No pair overlaps by more than 2.5 %
/// of the smaller radius at any sample (measured: 1.22 % during the crash), nor by more
/// than 1 % after 10 s (measured: 0.48 %); and the pile has come to rest.
#[test]
fn the_ball_pit_settles() {
    let scene = example_scene("ball-pit");
    let mut simulation = Simulation::new(&scene).unwrap();
    let initial = simulation.diagnostics().energy.total();
    let (mut worst_rise, mut previous, mut worst_during): (f64, f64, f64) = (0.0, initial, 0.0);
    for k in 1..=200 {
        simulation.step_to(f64::from(k) * 0.05).unwrap();
        let energy = simulation.diagnostics().energy.total();
        assert!(
            energy <= initial,
            "t = {}: energy {energy} above the initial {initial}",
            simulation.time()
        );
        worst_rise = worst_rise.max(energy - previous);
        previous = energy;
        worst_during = worst_during.max(largest_overlap(&simulation));
    }
    let at_rest = largest_overlap(&simulation);
    eprintln!(
        "largest rise between samples {worst_rise} J; overlap during {:.2} %, at rest {:.2} %",
        worst_during * 100.0,
        at_rest * 100.0
    );
    assert!(
        worst_during < 0.025,
        "largest overlap during the run {:.3} % of the smaller radius",
        worst_during * 100.0
    );
    assert!(
        at_rest < 0.01,
        "largest overlap at rest {:.3} % of the smaller radius",
        at_rest * 100.0
    );
    let kinetic = simulation.diagnostics().energy.kinetic;
    assert!(
        kinetic < 1e-3 * initial,
        "still moving: kinetic energy {kinetic} J"
    );
    // The balls on the floor press into it by about 0.1 mm; the state saved here (what
    // `--save-state` and the app's "edit from here" write) is still a scene that opens.
    let saved = simulation.saved_state(&scene);
    assert_eq!(
        saved.validate(),
        [],
        "the settled pit saved is not a valid scene"
    );
}
