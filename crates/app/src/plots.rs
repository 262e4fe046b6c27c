//! Readouts and graphs. Energies by kind, the relative energy drift since Play and the
//! total momentum; any quantities (per particle x, y, vx, vy, speed, ax, ay, kinetic
//! energy; system energies and momentum) against time or against one another (a phase
//! plot such as x against vx), several series with a legend, recorded once per frame
//! into a bounded history, and exported as CSV.

use std::collections::VecDeque;

use egui::Ui;
use egui_plot::{Legend, Line, Plot, PlotPoints};
use physics::{DVec2, Diagnostics, Scene, Simulation};

/// Samples kept; the oldest go first.
pub const HISTORY: usize = 20_000;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Of {
    X,
    Y,
    Vx,
    Vy,
    Speed,
    Ax,
    Ay,
    KineticEnergy,
}

impl Of {
    pub const ALL: [Self; 8] = [
        Self::X,
        Self::Y,
        Self::Vx,
        Self::Vy,
        Self::Speed,
        Self::Ax,
        Self::Ay,
        Self::KineticEnergy,
    ];

    fn label(self) -> (&'static str, &'static str) {
        match self {
            Self::X => ("x", "m"),
            Self::Y => ("y", "m"),
            Self::Vx => ("vx", "m/s"),
            Self::Vy => ("vy", "m/s"),
            Self::Speed => ("speed", "m/s"),
            Self::Ax => ("ax", "m/s²"),
            Self::Ay => ("ay", "m/s²"),
            Self::KineticEnergy => ("kinetic energy", "J"),
        }
    }
}

/// A quantity that can be plotted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    Time,
    Particle(usize, Of),
    KineticEnergy,
    PotentialEnergy,
    TotalEnergy,
    MomentumX,
    MomentumY,
}

impl Quantity {
    pub const SYSTEM: [Self; 5] = [
        Self::KineticEnergy,
        Self::PotentialEnergy,
        Self::TotalEnergy,
        Self::MomentumX,
        Self::MomentumY,
    ];

    /// "A.vx (m/s)", "total energy (J)".
    pub fn label(self, scene: &Scene) -> String {
        match self {
            Self::Time => "t (s)".to_owned(),
            Self::Particle(i, of) => {
                let name = scene.particles.get(i).map_or("?", |p| p.name.as_str());
                let (what, unit) = of.label();
                format!("{name}.{what} ({unit})")
            }
            Self::KineticEnergy => "kinetic energy (J)".to_owned(),
            Self::PotentialEnergy => "potential energy (J)".to_owned(),
            Self::TotalEnergy => "total energy (J)".to_owned(),
            Self::MomentumX => "momentum x (kg·m/s)".to_owned(),
            Self::MomentumY => "momentum y (kg·m/s)".to_owned(),
        }
    }

    fn needs_accelerations(self) -> bool {
        matches!(self, Self::Particle(_, Of::Ax | Of::Ay))
    }

    fn needs_diagnostics(self) -> bool {
        matches!(
            self,
            Self::KineticEnergy
                | Self::PotentialEnergy
                | Self::TotalEnergy
                | Self::MomentumX
                | Self::MomentumY
        )
    }

    fn value(
        self,
        simulation: &Simulation,
        accelerations: &[DVec2],
        diagnostics: &Diagnostics,
    ) -> f64 {
        match self {
            Self::Time => simulation.time(),
            Self::Particle(i, of) => {
                if i >= simulation.len() {
                    return f64::NAN;
                }
                let p = simulation.particle(i, accelerations);
                match of {
                    Of::X => p.position.x,
                    Of::Y => p.position.y,
                    Of::Vx => p.velocity.x,
                    Of::Vy => p.velocity.y,
                    Of::Speed => p.speed,
                    Of::Ax => p.acceleration.x,
                    Of::Ay => p.acceleration.y,
                    Of::KineticEnergy => p.kinetic_energy,
                }
            }
            Self::KineticEnergy => diagnostics.energy.kinetic,
            Self::PotentialEnergy => diagnostics.energy.potential(),
            Self::TotalEnergy => diagnostics.energy.total(),
            Self::MomentumX => diagnostics.momentum.x,
            Self::MomentumY => diagnostics.momentum.y,
        }
    }
}

pub struct Graphs {
    /// The quantities plotted, one series each.
    pub series: Vec<Quantity>,
    /// What they are plotted against: time, or another quantity for a phase plot.
    pub x_axis: Quantity,
    /// Rows of [x, series…], oldest first.
    history: VecDeque<Vec<f64>>,
    /// The choice being made in the "add" row.
    choice: (usize, Of),
}

impl Default for Graphs {
    fn default() -> Self {
        Self {
            series: Vec::new(),
            x_axis: Quantity::Time,
            history: VecDeque::new(),
            choice: (0, Of::Y),
        }
    }
}

impl Graphs {
    pub fn clear(&mut self) {
        self.history.clear();
    }

    /// The number of samples recorded.
    pub fn len(&self) -> usize {
        self.history.len()
    }

    pub fn is_empty(&self) -> bool {
        self.history.is_empty()
    }

    /// Records one sample of every series.
    pub fn record(&mut self, simulation: &Simulation) {
        if self.series.is_empty() {
            return;
        }
        let all = || self.series.iter().chain([&self.x_axis]);
        let accelerations = if all().any(|q| q.needs_accelerations()) {
            simulation.accelerations()
        } else {
            Vec::new()
        };
        let diagnostics = if all().any(|q| q.needs_diagnostics()) {
            simulation.diagnostics()
        } else {
            Diagnostics::default()
        };
        let mut row = vec![self.x_axis.value(simulation, &accelerations, &diagnostics)];
        row.extend(
            self.series
                .iter()
                .map(|q| q.value(simulation, &accelerations, &diagnostics)),
        );
        self.history.push_back(row);
        if self.history.len() > HISTORY {
            self.history.pop_front();
        }
    }

    /// The recorded series as CSV: a header of quantity names, then a row per sample.
    pub fn to_csv(&self, scene: &Scene) -> String {
        let quote = |s: String| {
            if s.contains([',', '"']) {
                format!("\"{}\"", s.replace('"', "\"\""))
            } else {
                s
            }
        };
        let mut header = vec![quote(self.x_axis.label(scene))];
        header.extend(self.series.iter().map(|q| quote(q.label(scene))));
        let mut out = header.join(",");
        out.push('\n');
        for row in &self.history {
            let fields: Vec<String> = row.iter().map(|v| format!("{v:?}")).collect();
            out.push_str(&fields.join(","));
            out.push('\n');
        }
        out
    }

    /// The readouts and the graph. Returns true when the user asked to export CSV.
    #[expect(clippy::too_many_lines, reason = "the graph panel, laid out in order")]
    pub fn ui(
        &mut self,
        ui: &mut Ui,
        scene: &Scene,
        simulation: Option<&Simulation>,
        start_energy: f64,
    ) -> bool {
        readouts(ui, simulation, start_energy);
        ui.separator();
        ui.heading("Graph");
        let mut changed = false;
        ui.horizontal_wrapped(|ui| {
            let names: Vec<String> = scene.particles.iter().map(|p| p.name.clone()).collect();
            let (mut particle, mut of) = self.choice;
            particle = particle.min(names.len().saturating_sub(1));
            let label = ui.label("particle");
            egui::ComboBox::from_id_salt("graph-particle")
                .selected_text(names.get(particle).map_or("—", String::as_str))
                .show_ui(ui, |ui| {
                    for (i, name) in names.iter().enumerate() {
                        ui.selectable_value(&mut particle, i, name);
                    }
                })
                .response
                .labelled_by(label.id)
                .on_hover_text("The particle whose quantity to add");
            let label = ui.label("quantity");
            egui::ComboBox::from_id_salt("graph-quantity")
                .selected_text(of.label().0)
                .show_ui(ui, |ui| {
                    for q in Of::ALL {
                        ui.selectable_value(&mut of, q, q.label().0);
                    }
                })
                .response
                .labelled_by(label.id)
                .on_hover_text("The quantity to add");
            self.choice = (particle, of);
            if ui
                .add_enabled(!names.is_empty(), egui::Button::new("Add"))
                .on_hover_text("Plot this quantity")
                .clicked()
            {
                self.series.push(Quantity::Particle(particle, of));
                changed = true;
            }
            if ui
                .button("Add as x axis")
                .on_hover_text("Plot everything against this quantity (a phase plot)")
                .clicked()
                && !names.is_empty()
            {
                self.x_axis = Quantity::Particle(particle, of);
                changed = true;
            }
        });
        ui.horizontal_wrapped(|ui| {
            for q in Quantity::SYSTEM {
                if ui
                    .small_button(q.label(scene))
                    .on_hover_text("Plot this system quantity")
                    .clicked()
                {
                    self.series.push(q);
                    changed = true;
                }
            }
        });
        let mut remove = None;
        ui.horizontal_wrapped(|ui| {
            if self.x_axis != Quantity::Time {
                ui.label(format!("x axis: {}", self.x_axis.label(scene)));
                if ui
                    .small_button("use time")
                    .on_hover_text("Plot against time again")
                    .clicked()
                {
                    self.x_axis = Quantity::Time;
                    changed = true;
                }
            }
            for (k, q) in self.series.iter().enumerate() {
                if ui
                    .small_button(format!("× {}", q.label(scene)))
                    .on_hover_text("Remove this series")
                    .clicked()
                {
                    remove = Some(k);
                }
            }
        });
        if let Some(k) = remove {
            self.series.remove(k);
            changed = true;
        }
        if changed {
            self.clear();
        }
        let export = ui
            .add_enabled(!self.history.is_empty(), egui::Button::new("Export CSV…"))
            .on_hover_text("Save the recorded series as a CSV file")
            .clicked();
        let x_label = self.x_axis.label(scene);
        Plot::new("graph")
            .legend(Legend::default())
            .x_axis_label(x_label)
            .height(ui.available_height().max(160.0))
            .show(ui, |plot| {
                for (k, q) in self.series.iter().enumerate() {
                    let points: PlotPoints = self
                        .history
                        .iter()
                        .map(|row| [row[0], row[k + 1]])
                        .collect();
                    plot.line(Line::new(q.label(scene), points));
                }
            });
        export
    }
}

/// Energies by kind, drift since Play, momentum.
fn readouts(ui: &mut Ui, simulation: Option<&Simulation>, start_energy: f64) {
    ui.heading("Energy and momentum");
    let Some(simulation) = simulation else {
        ui.label("Press Play to see the energies and momentum.");
        return;
    };
    let d = simulation.diagnostics();
    let drift = if start_energy == 0.0 {
        d.energy.total() - start_energy
    } else {
        (d.energy.total() - start_energy) / start_energy.abs()
    };
    egui::Grid::new("readouts")
        .num_columns(2)
        .striped(true)
        .show(ui, |ui| {
            for (name, value) in [
                ("kinetic (J)", format!("{:.9e}", d.energy.kinetic)),
                ("potential: field (J)", format!("{:.9e}", d.energy.uniform)),
                ("potential: springs (J)", format!("{:.9e}", d.energy.spring)),
                (
                    "potential: gravitation (J)",
                    format!("{:.9e}", d.energy.gravitation),
                ),
                (
                    "potential: electrostatic (J)",
                    format!("{:.9e}", d.energy.electrostatic),
                ),
                ("total (J)", format!("{:.9e}", d.energy.total())),
                ("drift since Play", format!("{drift:.3e}")),
                (
                    "momentum (kg·m/s)",
                    format!("({:.6e}, {:.6e})", d.momentum.x, d.momentum.y),
                ),
            ] {
                ui.label(name);
                ui.monospace(value);
                ui.end_row();
            }
        });
}
