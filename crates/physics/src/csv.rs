//! A simulation's state as CSV, the format of `newtonlab run` (`docs/cli.md`): the header
//! `t`, then `NAME.x,NAME.y,NAME.vx,NAME.vy,NAME.ax,NAME.ay` per particle in scene order
//! (and `NAME.angle,NAME.spin` after them for a particle that turns), then
//! `NAME.x,NAME.y,NAME.vx,NAME.vy,NAME.ax,NAME.ay,NAME.angle,NAME.spin` per rigid body, then
//! `kinetic_energy,potential_energy,total_energy,momentum_x,momentum_y` (and
//! `angular_momentum` when any particle turns or there are bodies). Every number
//! is the shortest text that parses back to the same f64, so two rows are equal as text
//! exactly when the states are equal bit for bit.

use std::fmt::Write as _;

use crate::Simulation;

impl Simulation {
    /// The CSV header's column names, unquoted: `t`, six per particle, then the system's.
    pub fn csv_columns(&self) -> Vec<String> {
        let mut columns = vec!["t".to_owned()];
        for (i, name) in self.names().iter().enumerate() {
            for quantity in ["x", "y", "vx", "vy", "ax", "ay"] {
                columns.push(format!("{name}.{quantity}"));
            }
            if self.particle_turns(i) {
                columns.extend([format!("{name}.angle"), format!("{name}.spin")]);
            }
        }
        for name in self.body_names() {
            for quantity in ["x", "y", "vx", "vy", "ax", "ay", "angle", "spin"] {
                columns.push(format!("{name}.{quantity}"));
            }
        }
        for (j, name) in self.joint_names().iter().enumerate() {
            if self.joint_is_pulley(j) {
                columns.extend([format!("{name}.tension_a"), format!("{name}.tension_b")]);
                continue;
            }
            columns.push(format!("{name}.angle"));
            if self.joint_is_pin(j) {
                columns.extend([format!("{name}.force_x"), format!("{name}.force_y")]);
            }
        }
        columns.extend(
            [
                "kinetic_energy",
                "potential_energy",
                "total_energy",
                "momentum_x",
                "momentum_y",
            ]
            .map(str::to_owned),
        );
        if self.has_angular_momentum_column() {
            columns.push("angular_momentum".to_owned());
        }
        columns
    }

    /// Whether the rows carry the system's angular momentum: when something turns.
    fn has_angular_momentum_column(&self) -> bool {
        self.turns() || !self.body_names().is_empty()
    }

    /// The CSV header line (without a line break).
    pub fn csv_header(&self) -> String {
        let columns: Vec<String> = self.csv_columns().iter().map(|c| csv_field(c)).collect();
        columns.join(",")
    }

    /// This instant's values in the order of [`Self::csv_columns`], appended to `out`.
    /// Accelerations are those of the smooth forces at this instant.
    pub fn csv_values(&self, out: &mut Vec<f64>) {
        let accelerations = self.accelerations();
        let diagnostics = self.diagnostics();
        out.push(self.time());
        for i in 0..self.len() {
            let p = self.particle(i, &accelerations);
            out.extend(
                [p.position, p.velocity, p.acceleration]
                    .iter()
                    .flat_map(|v| [v.x, v.y]),
            );
            if self.particle_turns(i) {
                out.extend([p.angle, p.spin]);
            }
        }
        for i in 0..self.body_names().len() {
            let b = self.body(i);
            out.extend([
                b.position.x,
                b.position.y,
                b.velocity.x,
                b.velocity.y,
                b.acceleration.x,
                b.acceleration.y,
                b.angle,
                b.spin,
            ]);
        }
        for j in 0..self.joint_names().len() {
            let joint = self.joint(j);
            if self.joint_is_pulley(j) {
                out.extend(joint.tensions);
                continue;
            }
            out.push(joint.angle);
            if self.joint_is_pin(j) {
                out.extend([joint.force.x, joint.force.y]);
            }
        }
        let energy = diagnostics.energy;
        out.extend([
            energy.kinetic,
            energy.potential(),
            energy.total(),
            diagnostics.momentum.x,
            diagnostics.momentum.y,
        ]);
        if self.has_angular_momentum_column() {
            out.push(diagnostics.angular_momentum);
        }
    }

    /// The CSV row of this instant (without a line break): [`Self::csv_values`], each
    /// the shortest text that parses back to the same f64.
    pub fn csv_row(&self) -> String {
        let mut values = Vec::new();
        self.csv_values(&mut values);
        let mut row = String::new();
        for (k, value) in values.iter().enumerate() {
            let comma = if k == 0 { "" } else { "," };
            let _ = write!(row, "{comma}{value:?}");
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
