//! The inspector: every field of the selected object, the world and the simulation
//! settings, typed as text at full precision with its unit, like the paper's text
//! fields. An entry that is not a number or breaks a rule (mass ≤ 0, restitution 1.5) is
//! shown in red with the reason and not applied; nothing typed is thrown away silently.
//! A valid entry is applied when the field loses focus (or on Enter), as one undoable
//! edit, after the whole scene is checked with the same rules as a scene file.

use std::collections::HashMap;

use egui::{Color32, Id, RichText, Ui};
use physics::{Endpoint, FieldRef, Rule, Scene, Section, Vector, check_value};

use crate::action::Action;
use crate::canvas::Selection;
use crate::document::Document;
use crate::format;
use crate::run_loop::Runner;

const ERROR: Color32 = Color32::from_rgb(200, 30, 30);

/// What the text of a field currently says, when it differs from the scene.
#[derive(Clone, Debug, Default)]
struct Draft {
    text: Option<String>,
    error: Option<String>,
}

/// One text field; returns the text to apply when the user commits a change to it.
fn text_field(
    ui: &mut Ui,
    id: Id,
    label: &str,
    unit: &str,
    current: &str,
    hint: &str,
    check: &dyn Fn(&str) -> Result<(), String>,
) -> Option<String> {
    let mut draft: Draft = ui.data(|d| d.get_temp(id)).unwrap_or_default();
    let mut committed = None;
    ui.horizontal(|ui| {
        let label = ui.add_sized([96.0, 18.0], egui::Label::new(label));
        let mut text = draft.text.clone().unwrap_or_else(|| current.to_owned());
        let mut edit = egui::TextEdit::singleline(&mut text)
            .desired_width(130.0)
            .id(id.with("edit"));
        if draft.error.is_some() {
            edit = edit.text_color(ERROR);
        }
        let response = ui.add(edit).labelled_by(label.id).on_hover_text(hint);
        if !unit.is_empty() {
            ui.label(unit);
        }
        if response.changed() {
            draft.text = Some(text.clone());
            draft.error = check(text.trim()).err();
        }
        let enter = response.lost_focus()
            || (response.has_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)));
        if enter && let Some(typed) = draft.text.clone() {
            match check(typed.trim()) {
                Ok(()) if typed.trim() != current => committed = Some(typed.trim().to_owned()),
                Ok(()) => {}
                Err(reason) => draft.error = Some(reason),
            }
            if draft.error.is_none() {
                draft.text = None;
            }
        }
    });
    if let Some(reason) = &draft.error {
        ui.label(RichText::new(reason.clone()).color(ERROR).small());
    }
    ui.data_mut(|d| {
        let invalid = d.get_temp_mut_or_default::<Invalid>(Id::NULL);
        match &draft.error {
            Some(reason) => {
                invalid.0.insert(id, reason.clone());
            }
            None => {
                invalid.0.remove(&id);
            }
        }
        d.insert_temp(id, draft);
    });
    committed
}

/// The typed entries that are invalid now, by field, wherever they are.
#[derive(Clone, Debug, Default)]
struct Invalid(HashMap<Id, String>);

/// Why each field typed so far is invalid: Play is refused while there is any, since it
/// would run the scene without what the user typed.
pub fn invalid_entries(ctx: &egui::Context) -> Vec<String> {
    let mut reasons: Vec<String> = ctx.data(|d| {
        d.get_temp::<Invalid>(Id::NULL)
            .map(|invalid| invalid.0.into_values().collect())
            .unwrap_or_default()
    });
    reasons.sort();
    reasons
}

/// Forgets every typed entry: the scene they were typed for is gone.
pub fn forget_entries(ctx: &egui::Context) {
    ctx.data_mut(|d| {
        d.remove_by_type::<Draft>();
        d.remove_by_type::<Invalid>();
    });
}

/// A number field checked against `rule`.
fn number_field(
    ui: &mut Ui,
    id: Id,
    label: &str,
    unit: &str,
    value: f64,
    rule: Rule,
    hint: &str,
) -> Option<f64> {
    let field = label.to_owned();
    let check = move |text: &str| -> Result<(), String> {
        let value: f64 = text
            .parse()
            .map_err(|_| format!("{field} must be a number, got \"{text}\""))?;
        check_value(rule, &field, value)
    };
    text_field(ui, id, label, unit, &value.to_string(), hint, &check).and_then(|t| t.parse().ok())
}

/// A vector field, Cartesian or polar as typed, with a button to switch the form.
fn vector_field(
    ui: &mut Ui,
    id: Id,
    label: &str,
    unit: &str,
    value: Vector,
    hint: &str,
) -> Option<Vector> {
    let mut result = None;
    ui.horizontal(|ui| {
        ui.label(RichText::new(label).strong());
        let polar = matches!(value, Vector::Polar { .. });
        let switch = if polar { "use x, y" } else { "use polar" };
        if ui
            .small_button(switch)
            .on_hover_text("Show this vector in the other form (the value is kept)")
            .clicked()
        {
            result = Some(if polar {
                value.to_cartesian()
            } else {
                value.to_polar()
            });
        }
    });
    match value {
        Vector::Cartesian(v) => {
            if let Some(x) = number_field(
                ui,
                id.with("x"),
                &format!("{label} x"),
                unit,
                v.x,
                Rule::Finite,
                hint,
            ) {
                result = Some(Vector::cartesian(x, v.y));
            }
            if let Some(y) = number_field(
                ui,
                id.with("y"),
                &format!("{label} y"),
                unit,
                v.y,
                Rule::Finite,
                hint,
            ) {
                result = Some(Vector::cartesian(v.x, y));
            }
        }
        Vector::Polar { magnitude, angle } => {
            if let Some(m) = number_field(
                ui,
                id.with("m"),
                &format!("{label} |v|"),
                unit,
                magnitude,
                Rule::Finite,
                hint,
            ) {
                result = Some(Vector::polar(m, angle));
            }
            if let Some(a) = number_field(
                ui,
                id.with("a"),
                &format!("{label} angle"),
                "°",
                angle,
                Rule::Finite,
                "degrees, counter-clockwise from +x",
            ) {
                result = Some(Vector::polar(magnitude, a));
            }
        }
    }
    result
}

/// Applies `change` if the scene it makes has no problem with `field`; returns the
/// problem's message otherwise.
fn try_apply(
    document: &mut Document,
    label: &str,
    field: FieldRef,
    change: impl FnOnce(&mut Scene),
) -> Result<(), String> {
    let mut candidate = document.scene().clone();
    change(&mut candidate);
    if let Some(problem) = candidate
        .validate()
        .into_iter()
        .find(|p| p.field == Some(field))
    {
        return Err(problem.message);
    }
    document.apply(label, |scene| *scene = candidate);
    Ok(())
}

/// Shows the inspector: while a run exists, the selected particle's live values first;
/// then the selection's fields, the world and the simulation settings. Returns an action
/// the user asked for (Delete).
pub fn ui(
    ui: &mut Ui,
    document: &mut Document,
    runner: &Runner,
    selection: &mut Option<Selection>,
) -> Option<Action> {
    let editable = runner.simulation.is_none();
    if !editable {
        live(ui, runner, *selection);
        ui.label(RichText::new("Running: Reset (R) to edit the scene.").italics());
    }
    if let Some(message) = ui.data(|d| d.get_temp::<String>(Id::unique("inspector-problem"))) {
        ui.label(RichText::new(message).color(ERROR));
    }
    let mut problem = None;
    let mut action = None;
    ui.add_enabled_ui(editable, |ui| {
        let heading = if editable {
            "Selected"
        } else {
            "Selected: as the scene starts"
        };
        egui::CollapsingHeader::new(heading)
            .id_salt("selected")
            .default_open(true)
            .show(ui, |ui| match *selection {
                None => {
                    ui.label("Nothing selected: click an object on the canvas.");
                }
                Some(Selection::Particle(i)) if i < document.scene().particles.len() => {
                    problem = particle(ui, document, i);
                }
                Some(Selection::Spring(i)) if i < document.scene().springs.len() => {
                    problem = spring(ui, document, i);
                }
                Some(Selection::Ramp(i)) if i < document.scene().ramps.len() => {
                    problem = ramp(ui, document, i);
                }
                Some(_) => *selection = None,
            });
        if selection.is_some()
            && ui
                .button("Delete")
                .on_hover_text("Remove the selected object (Delete)")
                .clicked()
        {
            action = Some(Action::Delete);
        }
        egui::CollapsingHeader::new("World")
            .default_open(false)
            .show(ui, |ui| {
                problem = problem.take().or_else(|| world(ui, document));
            });
        egui::CollapsingHeader::new("Simulation")
            .default_open(false)
            .show(ui, |ui| {
                problem = problem.take().or_else(|| settings(ui, document));
            });
    });
    ui.data_mut(|d| {
        if let Some(message) = problem {
            d.insert_temp(Id::unique("inspector-problem"), message);
        } else {
            d.remove::<String>(Id::unique("inspector-problem"));
        }
    });
    action
}

/// The selected particle as it is now in the run.
fn live(ui: &mut Ui, runner: &Runner, selection: Option<Selection>) {
    let (Some(simulation), Some(Selection::Particle(i))) = (&runner.simulation, selection) else {
        return;
    };
    if i >= simulation.len() {
        return;
    }
    egui::CollapsingHeader::new(format!("Live: {}", simulation.names()[i]))
        .id_salt("live")
        .default_open(true)
        .show(ui, |ui| {
            let accelerations = simulation.accelerations();
            let p = simulation.particle(i, &accelerations);
            let vector = |v: physics::DVec2, unit: &str| {
                format!("({}, {}) {unit}", format::number(v.x), format::number(v.y))
            };
            egui::Grid::new("live").num_columns(2).show(ui, |ui| {
                for (name, value) in [
                    ("position", vector(p.position, "m")),
                    ("velocity", vector(p.velocity, "m/s")),
                    ("acceleration", vector(p.acceleration, "m/s²")),
                    ("speed", format::with_unit(p.speed, "m/s")),
                    ("kinetic energy", format::with_unit(p.kinetic_energy, "J")),
                    ("momentum", vector(p.momentum, "kg·m/s")),
                ] {
                    ui.label(name);
                    ui.monospace(value);
                    ui.end_row();
                }
            });
        });
}

fn name_field(
    ui: &mut Ui,
    document: &mut Document,
    id: Id,
    section: Section,
    current: &str,
) -> Option<String> {
    let new = text_field(
        ui,
        id,
        "name",
        "",
        current,
        "Unique among all objects",
        &|text: &str| {
            if text.is_empty() {
                Err("name must not be empty".to_owned())
            } else {
                Ok(())
            }
        },
    )?;
    try_apply(
        document,
        "rename",
        FieldRef {
            section,
            field: "name",
        },
        |scene| scene.rename(section, &new),
    )
    .err()
}

fn particle(ui: &mut Ui, document: &mut Document, i: usize) -> Option<String> {
    let p = document.scene().particles[i].clone();
    let id = Id::unique(("particle", i));
    let section = Section::Particle(i);
    let mut problem = name_field(ui, document, id.with("name"), section, &p.name);
    let mut set =
        |document: &mut Document, field: &'static str, change: &dyn Fn(&mut physics::Particle)| {
            if let Err(message) = try_apply(
                document,
                &format!("set {field}"),
                FieldRef { section, field },
                |scene| change(&mut scene.particles[i]),
            ) {
                problem = Some(message);
            }
        };
    if let Some(v) = number_field(
        ui,
        id.with("mass"),
        "mass",
        "kg",
        p.mass,
        Rule::Positive,
        "Mass, kilograms, greater than 0",
    ) {
        set(document, "mass", &|p| p.mass = v);
    }
    if let Some(v) = number_field(
        ui,
        id.with("radius"),
        "radius",
        "m",
        p.radius,
        Rule::Positive,
        "Radius, metres, greater than 0",
    ) {
        set(document, "radius", &|p| p.radius = v);
    }
    if let Some(v) = number_field(
        ui,
        id.with("charge"),
        "charge",
        "C",
        p.charge,
        Rule::Finite,
        "Electric charge, coulombs",
    ) {
        set(document, "charge", &|p| p.charge = v);
    }
    if let Some(v) = vector_field(
        ui,
        id.with("position"),
        "position",
        "m",
        p.position,
        "Position, metres",
    ) {
        set(document, "position", &|p| p.position = v);
    }
    if let Some(v) = vector_field(
        ui,
        id.with("velocity"),
        "velocity",
        "m/s",
        p.velocity,
        "Velocity, metres per second",
    ) {
        set(document, "velocity", &|p| p.velocity = v);
    }
    if let Some(v) = vector_field(
        ui,
        id.with("acceleration"),
        "acceleration",
        "m/s²",
        p.acceleration,
        "A constant applied acceleration on top of all forces, m/s²",
    ) {
        set(document, "acceleration", &|p| p.acceleration = v);
    }
    let mut fixed = p.fixed;
    if ui
        .checkbox(&mut fixed, "fixed")
        .on_hover_text("A fixed particle never moves; it still attracts, repels and is hit")
        .changed()
    {
        set(document, "fixed", &|p| p.fixed = fixed);
    }
    let [r, g, b] = p.color.unwrap_or_else(|| physics::Color::palette(i)).0;
    let mut rgb = [r, g, b];
    ui.horizontal(|ui| {
        ui.label("colour");
        if ui
            .color_edit_button_srgb(&mut rgb)
            .on_hover_text("Display colour")
            .changed()
        {
            set(document, "color", &|p| p.color = Some(physics::Color(rgb)));
        }
    });
    problem
}

fn endpoint_field(
    ui: &mut Ui,
    id: Id,
    label: &str,
    end: &Endpoint,
    names: &[String],
) -> Option<Endpoint> {
    let mut result = None;
    let current = match end {
        Endpoint::Particle(name) => name.clone(),
        Endpoint::Point(_) => "fixed point".to_owned(),
    };
    ui.horizontal(|ui| {
        let label = ui.label(label);
        egui::ComboBox::from_id_salt(id.with("combo"))
            .selected_text(&current)
            .show_ui(ui, |ui| {
                for name in names {
                    if ui.selectable_label(current == *name, name).clicked() {
                        result = Some(Endpoint::Particle(name.clone()));
                    }
                }
                if ui
                    .selectable_label(matches!(end, Endpoint::Point(_)), "fixed point")
                    .clicked()
                    && !matches!(end, Endpoint::Point(_))
                {
                    result = Some(Endpoint::Point(Vector::ZERO));
                }
            })
            .response
            .labelled_by(label.id)
            .on_hover_text("A particle, or a fixed point in the world");
    });
    if let Endpoint::Point(point) = end
        && let Some(v) = vector_field(
            ui,
            id.with("point"),
            &format!("{label} point"),
            "m",
            *point,
            "The fixed point, metres",
        )
    {
        result = Some(Endpoint::Point(v));
    }
    result
}

fn spring(ui: &mut Ui, document: &mut Document, i: usize) -> Option<String> {
    let s = document.scene().springs[i].clone();
    let id = Id::unique(("spring", i));
    let section = Section::Spring(i);
    let names: Vec<String> = document
        .scene()
        .particles
        .iter()
        .map(|p| p.name.clone())
        .collect();
    let mut problem = name_field(ui, document, id.with("name"), section, &s.name);
    let mut set =
        |document: &mut Document, field: &'static str, change: &dyn Fn(&mut physics::Spring)| {
            if let Err(message) = try_apply(
                document,
                &format!("set {field}"),
                FieldRef { section, field },
                |scene| change(&mut scene.springs[i]),
            ) {
                problem = Some(message);
            }
        };
    if let Some(end) = endpoint_field(ui, id.with("from"), "from", &s.from, &names) {
        set(document, "from", &|s| s.from = end.clone());
    }
    if let Some(end) = endpoint_field(ui, id.with("to"), "to", &s.to, &names) {
        set(document, "to", &|s| s.to = end.clone());
    }
    if let Some(v) = number_field(
        ui,
        id.with("k"),
        "stiffness",
        "N/m",
        s.stiffness,
        Rule::NonNegative,
        "k, newtons per metre, 0 or more",
    ) {
        set(document, "stiffness", &|s| s.stiffness = v);
    }
    if let Some(v) = number_field(
        ui,
        id.with("l0"),
        "natural length",
        "m",
        s.natural_length,
        Rule::NonNegative,
        "The length at which the spring exerts no force, metres",
    ) {
        set(document, "natural_length", &|s| s.natural_length = v);
    }
    if let Some(v) = number_field(
        ui,
        id.with("b"),
        "damping",
        "N·s/m",
        s.damping,
        Rule::NonNegative,
        "b: force −b·(relative velocity along the spring)",
    ) {
        set(document, "damping", &|s| s.damping = v);
    }
    problem
}

fn ramp(ui: &mut Ui, document: &mut Document, i: usize) -> Option<String> {
    let r = document.scene().ramps[i].clone();
    let id = Id::unique(("ramp", i));
    let section = Section::Ramp(i);
    let mut problem = name_field(ui, document, id.with("name"), section, &r.name);
    let mut set =
        |document: &mut Document, field: &'static str, change: &dyn Fn(&mut physics::Ramp)| {
            if let Err(message) = try_apply(
                document,
                &format!("set {field}"),
                FieldRef { section, field },
                |scene| change(&mut scene.ramps[i]),
            ) {
                problem = Some(message);
            }
        };
    if let Some(v) = vector_field(
        ui,
        id.with("from"),
        "from",
        "m",
        r.from,
        "One end of the ramp, metres",
    ) {
        set(document, "from", &|r| r.from = v);
    }
    if let Some(v) = vector_field(ui, id.with("to"), "to", "m", r.to, "The other end, metres") {
        set(document, "to", &|r| r.to = v);
    }
    if let Some(v) = number_field(
        ui,
        id.with("t"),
        "thickness",
        "m",
        r.thickness,
        Rule::NonNegative,
        "The ramp is every point within half this of its segment",
    ) {
        set(document, "thickness", &|r| r.thickness = v);
    }
    if let Some(v) = number_field(
        ui,
        id.with("e"),
        "restitution",
        "",
        r.restitution,
        Rule::Fraction,
        "0 (no bounce) to 1 (perfectly elastic)",
    ) {
        set(document, "restitution", &|r| r.restitution = v);
    }
    if let Some(v) = number_field(
        ui,
        id.with("mu"),
        "friction",
        "",
        r.friction,
        Rule::NonNegative,
        "Coefficient of static and kinetic friction",
    ) {
        set(document, "friction", &|r| r.friction = v);
    }
    problem
}

#[expect(
    clippy::too_many_lines,
    reason = "every field of the world, in the scene format's order"
)]
fn world(ui: &mut Ui, document: &mut Document) -> Option<String> {
    let w = document.scene().world.clone();
    let id = Id::unique("world");
    let mut problem = None;
    let mut set =
        |document: &mut Document, field: &'static str, change: &dyn Fn(&mut physics::World)| {
            if let Err(message) = try_apply(
                document,
                &format!("set {field}"),
                FieldRef {
                    section: Section::World,
                    field,
                },
                |scene| change(&mut scene.world),
            ) {
                problem = Some(message);
            }
        };
    if let Some(v) = vector_field(
        ui,
        id.with("g"),
        "gravity",
        "m/s²",
        w.gravity,
        "The uniform field, m/s²",
    ) {
        set(document, "gravity", &|w| w.gravity = v);
    }
    let mut on = w.gravitation;
    if ui
        .checkbox(&mut on, "gravitation between particles")
        .on_hover_text("Newton's inverse-square attraction between every pair")
        .changed()
    {
        set(document, "gravitation", &|w| w.gravitation = on);
    }
    if let Some(v) = number_field(
        ui,
        id.with("G"),
        "G",
        "N·m²/kg²",
        w.gravitational_constant,
        Rule::Finite,
        "The gravitational constant (the paper: 6.6742e-11)",
    ) {
        set(document, "gravitational_constant", &|w| {
            w.gravitational_constant = v;
        });
    }
    let mut on = w.electrostatics;
    if ui
        .checkbox(&mut on, "electrostatics")
        .on_hover_text("Coulomb's law between charged particles")
        .changed()
    {
        set(document, "electrostatics", &|w| w.electrostatics = on);
    }
    if let Some(v) = number_field(
        ui,
        id.with("k"),
        "k",
        "N·m²/C²",
        w.coulomb_constant,
        Rule::Finite,
        "The Coulomb constant (8.988e9)",
    ) {
        set(document, "coulomb_constant", &|w| w.coulomb_constant = v);
    }
    if let Some(v) = number_field(
        ui,
        id.with("e"),
        "restitution",
        "",
        w.restitution,
        Rule::Fraction,
        "Particle–particle impacts: 0 (sticky) to 1 (elastic)",
    ) {
        set(document, "restitution", &|w| w.restitution = v);
    }
    let mut boxed = w.bounds.is_some();
    if ui
        .checkbox(&mut boxed, "bounds")
        .on_hover_text("A reflecting box around the world")
        .changed()
    {
        let bounds = boxed.then(|| physics::Bounds {
            min: Vector::cartesian(-20.0, -20.0),
            max: Vector::cartesian(20.0, 20.0),
        });
        set(document, "bounds", &|w| w.bounds = bounds);
    }
    if let Some(bounds) = w.bounds {
        if let Some(v) = vector_field(
            ui,
            id.with("min"),
            "min",
            "m",
            bounds.min,
            "The box's lower-left corner",
        ) {
            set(document, "bounds", &|w| {
                w.bounds = Some(physics::Bounds {
                    min: v,
                    max: bounds.max,
                });
            });
        }
        if let Some(v) = vector_field(
            ui,
            id.with("max"),
            "max",
            "m",
            bounds.max,
            "The box's upper-right corner",
        ) {
            set(document, "bounds", &|w| {
                w.bounds = Some(physics::Bounds {
                    min: bounds.min,
                    max: v,
                });
            });
        }
    }
    problem
}

fn settings(ui: &mut Ui, document: &mut Document) -> Option<String> {
    let s = document.scene().simulation.clone();
    let id = Id::unique("settings");
    let mut problem = None;
    // The integrator and the time step are chosen in the tool bar.
    let mut set =
        |document: &mut Document, field: &'static str, change: &dyn Fn(&mut physics::Settings)| {
            if let Err(message) = try_apply(
                document,
                &format!("set {field}"),
                FieldRef {
                    section: Section::Simulation,
                    field,
                },
                |scene| change(&mut scene.simulation),
            ) {
                problem = Some(message);
            }
        };
    if let Some(v) = number_field(
        ui,
        id.with("tol"),
        "tolerance",
        "",
        s.tolerance,
        Rule::Positive,
        "dopri5 only: error allowed per step, relative and absolute",
    ) {
        set(document, "tolerance", &|s| s.tolerance = v);
    }
    if let Some(v) = number_field(
        ui,
        id.with("scale"),
        "time scale",
        "×",
        s.time_scale,
        Rule::Positive,
        "Simulated seconds per real second when playing",
    ) {
        set(document, "time_scale", &|s| s.time_scale = v);
    }
    problem
}
