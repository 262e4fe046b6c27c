//! A thousand balls settling in a box: resting contact at scale.

use physics::{Simulation, example, generated};

/// The example file is the generator's output, so the benchmark (which generates pits of
/// any size) and the example measure the same scene.
#[test]
fn the_example_is_the_generated_pit() {
    let scene = example("ball-pit").unwrap().scene().unwrap();
    assert_eq!(
        scene,
        generated::ball_pit(1000),
        "regenerate examples/scenes/ball-pit.toml"
    );
}

/// With restitution 0.5 the 1,000-ball pit settles: the total energy never rises above
/// its initial value (impacts and resting contacts only take energy away), after 10 s no
/// pair overlaps by more than 1 % of the smaller radius, and the pile has come to rest.
#[test]
fn the_ball_pit_settles() {
    let scene = example("ball-pit").unwrap().scene().unwrap();
    let mut simulation = Simulation::new(&scene).unwrap();
    let initial = simulation.diagnostics().energy.total();
    for k in 1..=200 {
        simulation.step_to(f64::from(k) * 0.05).unwrap();
        let energy = simulation.diagnostics().energy.total();
        assert!(
            energy <= initial,
            "t = {}: energy {energy} above the initial {initial}",
            simulation.time()
        );
    }
    let (x, r) = (simulation.positions(), simulation.radii());
    let mut worst: f64 = 0.0;
    for i in 0..x.len() {
        for j in i + 1..x.len() {
            let overlap = r[i] + r[j] - x[i].distance(x[j]);
            worst = worst.max(overlap / r[i].min(r[j]));
        }
    }
    assert!(
        worst < 0.01,
        "largest overlap {:.3} % of the smaller radius",
        worst * 100.0
    );
    let kinetic = simulation.diagnostics().energy.kinetic;
    assert!(
        kinetic < 1e-3 * initial,
        "still moving: kinetic energy {kinetic} J"
    );
}
