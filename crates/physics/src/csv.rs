//! A simulation's state as CSV, the format of `newtonlab run` (`docs/cli.md`): the header
//! `t`, then `NAME.x,NAME.y,NAME.vx,NAME.vy,NAME.ax,NAME.ay` per particle in scene order,
//! then `kinetic_energy,potential_energy,total_energy,momentum_x,momentum_y`. Every number
//! is the shortest text that parses back to the same f64, so two rows are equal as text
//! exactly when the states are equal bit for bit.

use std::fmt::Write as _;

use crate::Simulation;

impl Simulation {
    /// The CSV header line (without a line break).
    pub fn csv_header(&self) -> String {
        let mut header = vec!["t".to_owned()];
        for name in self.names() {
            for quantity in ["x", "y", "vx", "vy", "ax", "ay"] {
                header.push(csv_field(&format!("{name}.{quantity}")));
            }
        }
        header.extend(
            [
                "kinetic_energy",
                "potential_energy",
                "total_energy",
                "momentum_x",
                "momentum_y",
            ]
            .map(str::to_owned),
        );
        header.join(",")
    }

    /// The CSV row of this instant (without a line break). Accelerations are those of the
    /// smooth forces at this instant.
    pub fn csv_row(&self) -> String {
        let accelerations = self.accelerations();
        let diagnostics = self.diagnostics();
        let mut row = String::new();
        let _ = write!(row, "{:?}", self.time());
        for i in 0..self.len() {
            let p = self.particle(i, &accelerations);
            for value in [p.position, p.velocity, p.acceleration]
                .iter()
                .flat_map(|v| [v.x, v.y])
            {
                let _ = write!(row, ",{value:?}");
            }
        }
        let energy = diagnostics.energy;
        for value in [
            energy.kinetic,
            energy.potential(),
            energy.total(),
            diagnostics.momentum.x,
            diagnostics.momentum.y,
        ] {
            let _ = write!(row, ",{value:?}");
        }
        row
    }
}

/// A CSV field, quoted when a name holds a comma, quote or line break.
#[must_use]
pub fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}
