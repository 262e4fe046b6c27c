//! The inspector: every field of the selected object, the world and the simulation
//! settings, typed as text at full precision with its unit, like the paper's text
//! fields. An entry that is not a number or breaks a rule (mass ≤ 0, restitution 1.5) is
//! shown in red with the reason and not applied; nothing typed is thrown away silently.
//! A valid entry is applied when the field loses focus (or on Enter), as one undoable
//! edit, after the whole scene is checked with the same rules as a scene file.

use std::collections::HashMap;

use egui::{Color32, Id, RichText, Ui};
use physics::fields::{self, Field, Kind, Place, Value};
use physics::{
    Endpoint, FieldRef, ObjectKind, Rule, Scene, Section, SectionKind, Vector, check_value,
};

use crate::action::Action;
use crate::canvas::Selection;
use crate::document::Document;
use crate::edit::{Edit, field_message};
use crate::format;
use crate::i18n::{Arg, tr, tr_with};
use crate::run_loop::Runner;
use crate::units;

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
            .desired_width(118.0)
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
        let value = units::parse(&format::typed(text), unit)
            .map_err(|reason| format!("{field}: {reason}"))?;
        check_value(rule, &field, value)
    };
    let hint = format!("{hint}. {}", tr("inspector-arithmetic-hint"));
    text_field(ui, id, label, unit, &format::field(value), &hint, &check)
        .and_then(|t| units::parse(&format::typed(&t), unit).ok())
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
        let switch = tr(if polar {
            "inspector-use-cartesian"
        } else {
            "inspector-use-polar"
        });
        if ui
            .small_button(switch)
            .on_hover_text(tr("inspector-switch-hint"))
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
                &format!("{label} {}", tr("inspector-polar-angle")),
                "°",
                angle,
                Rule::Finite,
                &tr("inspector-polar-angle-hint"),
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
    edit: Edit,
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
    document.apply(edit, |scene| *scene = candidate);
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
    let editable = runner.is_editing();
    if !editable {
        live(ui, runner, *selection);
        ui.label(RichText::new(tr("inspector-running")).italics());
    }
    if let Some(message) = ui.data(|d| d.get_temp::<String>(Id::unique("inspector problem"))) {
        ui.label(RichText::new(message).color(ERROR));
    }
    if let Some(description) = &document.scene().description {
        egui::CollapsingHeader::new(tr("inspector-about"))
            .id_salt("about")
            .default_open(true)
            .show(ui, |ui| crate::lesson::markdown(ui, description));
    }
    let mut problem = None;
    let mut action = None;
    ui.add_enabled_ui(editable, |ui| {
        let heading = tr(if editable {
            "inspector-selected"
        } else {
            "inspector-selected-at-start"
        });
        egui::CollapsingHeader::new(heading)
            .id_salt("selected")
            .default_open(true)
            .show(ui, |ui| problem = selected(ui, document, selection));
        if selection.is_some()
            && ui
                .button(tr("inspector-delete"))
                .on_hover_text(tr("inspector-delete-hint"))
                .clicked()
        {
            action = Some(Action::Delete);
        }
        egui::CollapsingHeader::new(tr("inspector-world"))
            .id_salt("world")
            .default_open(false)
            .show(ui, |ui| {
                let id = Id::unique("world");
                problem = problem.take().or_else(|| {
                    table(
                        ui,
                        document,
                        id,
                        Section::World,
                        0,
                        fields::WORLD,
                        (|s| &s.world, |s| &mut s.world),
                    )
                });
            });
        egui::CollapsingHeader::new(tr("inspector-simulation"))
            .id_salt("simulation")
            .default_open(false)
            .show(ui, |ui| {
                // The integrator and the time step are in the tool bar.
                let id = Id::unique("settings");
                problem = problem.take().or_else(|| {
                    table(
                        ui,
                        document,
                        id,
                        Section::Simulation,
                        0,
                        fields::SIMULATION,
                        (|s| &s.simulation, |s| &mut s.simulation),
                    )
                });
            });
    });
    ui.data_mut(|d| {
        if let Some(message) = problem {
            d.insert_temp(Id::unique("inspector problem"), message);
        } else {
            d.remove::<String>(Id::unique("inspector problem"));
        }
    });
    action
}

/// The selected particle, rod or string as it is now in the run.
fn live(ui: &mut Ui, runner: &Runner, selection: Option<Selection>) {
    if let (Some(simulation), Some(Selection::Tie(k))) = (runner.simulation(), selection) {
        live_tie(ui, simulation, k);
        return;
    }
    let (Some(simulation), Some(Selection::Particle(i))) = (runner.simulation(), selection) else {
        return;
    };
    if i >= simulation.len() {
        return;
    }
    egui::CollapsingHeader::new(tr_with(
        "inspector-live",
        &[("name", Arg::Text(&simulation.names()[i]))],
    ))
    .id_salt("live")
    .default_open(true)
    .show(ui, |ui| {
        let accelerations = simulation.accelerations();
        let p = simulation.particle(i, &accelerations);
        let vector = |v: physics::DVec2, unit: &str| format!("{} {unit}", format::pair(v.x, v.y));
        let mut rows = vec![
            ("inspector-live-position", vector(p.position, "m")),
            ("inspector-live-velocity", vector(p.velocity, "m/s")),
            (
                "inspector-live-acceleration",
                vector(p.acceleration, "m/s²"),
            ),
            ("inspector-live-speed", format::with_unit(p.speed, "m/s")),
            (
                "inspector-live-kinetic-energy",
                format::with_unit(p.kinetic_energy, "J"),
            ),
            ("inspector-live-momentum", vector(p.momentum, "kg·m/s")),
        ];
        if simulation.particle_turns(i) {
            let rpm = p.spin * 60.0 / std::f64::consts::TAU;
            rows.extend([
                (
                    "inspector-live-spin",
                    format!(
                        "{} ({})",
                        format::with_unit(p.spin, "rad/s"),
                        format::with_unit(rpm, "rpm")
                    ),
                ),
                ("inspector-live-angle", format::with_unit(p.angle, "°")),
                (
                    "inspector-live-rotational",
                    format::with_unit(p.rotational_energy, "J"),
                ),
                (
                    "inspector-live-angular-momentum",
                    format::with_unit(p.angular_momentum, "kg·m²/s"),
                ),
            ]);
        }
        egui::Grid::new("live").num_columns(2).show(ui, |ui| {
            for (name, value) in rows {
                ui.label(tr(name));
                // Wrapped within the panel: a vector with powers of ten is wider than a
                // narrow inspector, and its end would be cut off.
                ui.add(egui::Label::new(RichText::new(value).monospace()).wrap());
                ui.end_row();
            }
        });
    });
}

/// A rod's or string's tension now, and whether a string is slack.
fn live_tie(ui: &mut Ui, simulation: &physics::Simulation, k: usize) {
    let Some(name) = simulation.tie_names().get(k) else {
        return;
    };
    let tension = simulation.tensions().get(k).copied().unwrap_or(0.0);
    egui::CollapsingHeader::new(tr_with("inspector-live", &[("name", Arg::Text(name))]))
        .id_salt("live")
        .default_open(true)
        .show(ui, |ui| {
            egui::Grid::new("live").num_columns(2).show(ui, |ui| {
                ui.label(tr("inspector-tension"));
                ui.monospace(format::with_unit(tension, "N"))
                    .on_hover_text(tr("inspector-tension-hint"));
                ui.end_row();
                ui.label(tr("inspector-work-done"));
                ui.monospace(tr("inspector-no-work"));
                ui.end_row();
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
        &tr("inspector-name"),
        "",
        current,
        &tr("inspector-name-hint"),
        &|text: &str| {
            if text.is_empty() {
                Err(tr("scene-name-empty"))
            } else {
                Ok(())
            }
        },
    )?;
    try_apply(
        document,
        Edit::Rename,
        FieldRef {
            section,
            field: "name",
        },
        |scene| scene.rename(section, &new),
    )
    .err()
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
        Endpoint::Point(_) => tr("inspector-fixed-point"),
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
                    .selectable_label(
                        matches!(end, Endpoint::Point(_)),
                        tr("inspector-fixed-point"),
                    )
                    .clicked()
                    && !matches!(end, Endpoint::Point(_))
                {
                    result = Some(Endpoint::Point(Vector::ZERO));
                }
            })
            .response
            .labelled_by(label.id)
            .on_hover_text(tr("inspector-end-hint"));
    });
    if let Endpoint::Point(point) = end
        && let Some(v) = vector_field(
            ui,
            id.with("point"),
            &tr_with("inspector-end-point", &[("end", Arg::Text(label))]),
            "m",
            *point,
            &tr("inspector-end-point-hint"),
        )
    {
        result = Some(Endpoint::Point(v));
    }
    result
}

/// The selected object's name and fields; a selection whose object is gone is dropped.
fn selected(
    ui: &mut Ui,
    document: &mut Document,
    selection: &mut Option<Selection>,
) -> Option<String> {
    let mut problem = None;
    match *selection {
        None => {
            ui.label(tr("inspector-nothing-selected"));
        }
        Some(Selection::Particle(i)) if i < document.scene().particles.len() => {
            problem = object(
                ui,
                document,
                Section::Particle(i),
                i,
                fields::PARTICLE,
                (move |s| &s.particles[i], move |s| &mut s.particles[i]),
            );
            inertia_presets(ui, document, i);
            problem = onto_ramp(ui, document, i).or(problem);
        }
        Some(Selection::Spring(i)) if i < document.scene().springs.len() => {
            problem = object(
                ui,
                document,
                Section::Spring(i),
                i,
                fields::SPRING,
                (move |s| &s.springs[i], move |s| &mut s.springs[i]),
            );
        }
        Some(Selection::Tie(i)) if i < document.scene().ties.len() => {
            let kind = document.scene().ties[i].kind;
            problem = object(
                ui,
                document,
                Section::Tie(i),
                i,
                fields::tie_fields(kind),
                (move |s| &s.ties[i], move |s| &mut s.ties[i]),
            );
            length_warning(ui, document.scene(), i);
        }
        Some(Selection::Ramp(i)) if i < document.scene().ramps.len() => {
            problem = object(
                ui,
                document,
                Section::Ramp(i),
                i,
                fields::RAMP,
                (move |s| &s.ramps[i], move |s| &mut s.ramps[i]),
            );
            problem = ramp_slope(ui, document, i).or(problem);
        }
        Some(Selection::Body(i)) if i < document.scene().bodies.len() => {
            let scene = document.scene();
            // A polygon's size is its vertices: a box's width and height are not shown.
            let shown = match scene.bodies[i].shape {
                physics::Shape::Box => fields::BODY,
                physics::Shape::Polygon(_) => {
                    let size = fields::BODY.iter().take_while(|f| f.key != "mass").count();
                    &fields::BODY[size..]
                }
            };
            let palette = scene.particles.len() + i;
            problem = object(
                ui,
                document,
                Section::Body(i),
                palette,
                shown,
                (move |s| &s.bodies[i], move |s| &mut s.bodies[i]),
            );
        }
        Some(_) => *selection = None,
    }
    problem
}

/// Ramp `i`'s slope and length, typed: `to` moves so that the ramp has them from `from`
/// (its ends only would need trigonometry).
fn ramp_slope(ui: &mut Ui, document: &mut Document, i: usize) -> Option<String> {
    let ramp = document.scene().ramps[i].clone();
    let id = Id::unique(("ramp slope", i));
    let angle = number_field(
        ui,
        id.with("angle"),
        &tr("inspector-ramp-angle"),
        "°",
        ramp.angle(),
        Rule::Finite,
        &tr("inspector-ramp-angle-hint"),
    );
    let length = number_field(
        ui,
        id.with("length"),
        &tr("inspector-ramp-length"),
        "m",
        ramp.length(),
        Rule::NonNegative,
        &tr("inspector-ramp-length-hint"),
    );
    if angle.is_none() && length.is_none() {
        return None;
    }
    let end = ramp.end_for(
        angle.unwrap_or_else(|| ramp.angle()),
        length.unwrap_or_else(|| ramp.length()),
    );
    try_apply(
        document,
        Edit::MoveRampEnd,
        FieldRef {
            section: Section::Ramp(i),
            field: "to",
        },
        |scene| scene.ramps[i].to = end,
    )
    .err()
}

/// Puts particle `i` on a ramp: touching its upper face at a distance typed along it
/// from its `from` end, without trigonometry.
fn onto_ramp(ui: &mut Ui, document: &mut Document, i: usize) -> Option<String> {
    let ramps: Vec<String> = document
        .scene()
        .ramps
        .iter()
        .map(|r| r.name.clone())
        .collect();
    if ramps.is_empty() {
        return None;
    }
    let id = Id::unique(("onto ramp", i));
    let (mut chosen, mut along): (usize, f64) = ui.data(|d| d.get_temp(id)).unwrap_or((0, 0.0));
    chosen = chosen.min(ramps.len() - 1);
    let mut put = false;
    ui.horizontal(|ui| {
        let label = ui.label(tr("inspector-on-ramp"));
        egui::ComboBox::from_id_salt(id.with("ramp"))
            .selected_text(&ramps[chosen])
            .show_ui(ui, |ui| {
                for (k, name) in ramps.iter().enumerate() {
                    ui.selectable_value(&mut chosen, k, name);
                }
            })
            .response
            .labelled_by(label.id)
            .on_hover_text(tr("inspector-on-ramp-hint"));
        put = ui
            .button(tr("inspector-put-on-ramp"))
            .on_hover_text(tr("inspector-put-on-ramp-hint"))
            .clicked();
    });
    if let Some(typed) = number_field(
        ui,
        id.with("along"),
        &tr("inspector-along-ramp"),
        "m",
        along,
        Rule::Finite,
        &tr("inspector-along-ramp-hint"),
    ) {
        along = typed;
        put = true;
    }
    ui.data_mut(|d| d.insert_temp(id, (chosen, along)));
    if !put {
        return None;
    }
    let scene = document.scene();
    let at = scene.ramps[chosen].touching(along, scene.particles[i].radius);
    try_apply(
        document,
        Edit::MoveParticle,
        FieldRef {
            section: Section::Particle(i),
            field: "position",
        },
        |scene| scene.particles[i].position = Vector::cartesian(at.x, at.y),
    )
    .err()
}

/// Buttons that give particle `i` the moment of inertia of a point (it never turns), a
/// solid disc or a thin ring.
fn inertia_presets(ui: &mut Ui, document: &mut Document, i: usize) {
    ui.horizontal_wrapped(|ui| {
        ui.label(tr("inspector-inertia-presets"));
        for (key, inertia) in [
            ("inspector-inertia-point", 0.0),
            ("inspector-inertia-disc", 0.5),
            ("inspector-inertia-ring", 1.0),
        ] {
            #[expect(clippy::float_cmp, reason = "exactly the preset's value")]
            let chosen = document.scene().particles[i].inertia == inertia;
            if ui
                .selectable_label(chosen, tr(key))
                .on_hover_text(tr(&format!("{key}-hint")))
                .clicked()
                && !chosen
            {
                let field = FieldRef {
                    section: Section::Particle(i),
                    field: "inertia",
                };
                let edit = Edit::Set {
                    section: SectionKind::Object(ObjectKind::Particle),
                    key: "inertia",
                };
                // Every preset is valid for every particle: nothing to report.
                let _ = try_apply(document, edit, field, |scene| {
                    scene.particles[i].inertia = inertia;
                });
            }
        }
    });
}

/// A rod or string whose ends start at another distance than its length pulls them onto
/// its length before the first step: said, with both numbers, so a typed length that
/// does not match the drawing is not a surprise (a string longer than the distance is
/// slack, and says nothing).
fn length_warning(ui: &mut Ui, scene: &Scene, i: usize) {
    let tie = &scene.ties[i];
    let (Some(from), Some(to)) = (scene.end_position(&tie.from), scene.end_position(&tie.to))
    else {
        return;
    };
    let distance = from.distance(to);
    let slack = tie.kind == physics::TieKind::String && distance < tie.length;
    if slack || (distance - tie.length).abs() <= 1e-9 * tie.length.max(1.0) {
        return;
    }
    let id = if tie.kind == physics::TieKind::String {
        "inspector-string-too-short"
    } else {
        "inspector-rod-length-differs"
    };
    ui.label(
        RichText::new(crate::i18n::tr_with(
            id,
            &[
                (
                    "distance",
                    crate::i18n::Arg::Text(&format::number(distance)),
                ),
                (
                    "length",
                    crate::i18n::Arg::Text(&format::number(tie.length)),
                ),
            ],
        ))
        .color(egui::Color32::from_rgb(190, 110, 0))
        .small(),
    );
}

/// An object's name and then its fields from the table.
fn object<T: Clone + 'static>(
    ui: &mut Ui,
    document: &mut Document,
    section: Section,
    index: usize,
    fields: &[Field<T>],
    access: (impl Fn(&Scene) -> &T, impl Fn(&mut Scene) -> &mut T + Copy),
) -> Option<String> {
    let id = Id::unique(("object", section));
    let name = document
        .scene()
        .name_of(section)
        .unwrap_or_default()
        .to_owned();
    let problem = name_field(ui, document, id.with("name"), section, &name);
    table(ui, document, id, section, index, fields, access).or(problem)
}

/// The fields of one section, as the field table describes them: each with its label,
/// unit and help, checked by its rule, applied as one undoable edit. `access` reads and
/// writes the section in a scene; `palette` is the index whose palette colour a particle
/// without one shows.
fn table<T: Clone + 'static>(
    ui: &mut Ui,
    document: &mut Document,
    id: Id,
    section: Section,
    palette: usize,
    fields: &[Field<T>],
    (read, write): (impl Fn(&Scene) -> &T, impl Fn(&mut Scene) -> &mut T + Copy),
) -> Option<String> {
    // Only the section is copied, not the scene, every frame.
    let target = read(document.scene()).clone();
    let names = document.scene().particle_names();
    let kind = document.scene().section_kind(section);
    let mut problem = None;
    for f in fields.iter().filter(|f| f.place == Place::Inspector) {
        let field_id = id.with(f.key);
        let message = field_message(kind, f.key);
        let words = (tr(&message), tr(&format!("{message}-help")));
        let shown = (f.get)(&target);
        let Some(value) = field_ui(ui, (field_id, &words), f, shown, &names, palette) else {
            continue;
        };
        let result = try_apply(
            document,
            Edit::Set {
                section: kind,
                key: f.key,
            },
            FieldRef {
                section,
                field: f.key,
            },
            |scene| (f.set)(write(scene), value),
        );
        if let Err(message) = result {
            problem = Some(message);
        }
    }
    problem
}

/// One field's widget, with its label and help in the user's language; returns a new
/// value the user committed.
fn field_ui<T>(
    ui: &mut Ui,
    (id, (label, help)): (Id, &(String, String)),
    f: &Field<T>,
    value: Value,
    names: &[String],
    palette: usize,
) -> Option<Value> {
    let (label, help) = (label.as_str(), help.as_str());
    match (f.kind, value) {
        (Kind::Number(rule), Value::Number(v)) => {
            number_field(ui, id, label, f.unit, v, rule, help).map(Value::Number)
        }
        (Kind::Vector, Value::Vector(v)) => {
            vector_field(ui, id, label, f.unit, v, help).map(Value::Vector)
        }
        (Kind::Bool, Value::Bool(mut on)) => ui
            .checkbox(&mut on, label)
            .on_hover_text(help)
            .changed()
            .then_some(Value::Bool(on)),
        (Kind::Endpoint, Value::Endpoint(end)) => {
            endpoint_field(ui, id, label, &end, names).map(Value::Endpoint)
        }
        (Kind::Color, Value::Color(color)) => {
            let mut rgb = color.unwrap_or_else(|| physics::Color::palette(palette)).0;
            ui.horizontal(|ui| {
                ui.label(label);
                ui.color_edit_button_srgb(&mut rgb)
                    .on_hover_text(help)
                    .changed()
                    .then_some(Value::Color(Some(physics::Color(rgb))))
            })
            .inner
        }
        (Kind::Bounds, Value::Bounds(bounds)) => bounds_field(ui, id, (label, help), f, bounds),
        (Kind::PairForces, Value::PairForces(mut mode)) => {
            let before = mode;
            egui::ComboBox::from_id_salt(id)
                .selected_text(format!("{label}: {}", pair_forces_words(mode)))
                .show_ui(ui, |ui| {
                    for choice in physics::PairForces::ALL {
                        ui.selectable_value(&mut mode, choice, pair_forces_words(choice));
                    }
                })
                .response
                .on_hover_text(help);
            (mode != before).then_some(Value::PairForces(mode))
        }
        _ => None,
    }
}

/// How pair forces are summed, in the user's language (the file keeps `direct` or `tree`).
fn pair_forces_words(mode: physics::PairForces) -> String {
    tr(match mode {
        physics::PairForces::Direct => "inspector-pair-forces-direct",
        physics::PairForces::Tree => "inspector-pair-forces-tree",
    })
}

/// The world's box: a checkbox, and its corners when there is one.
fn bounds_field<T>(
    ui: &mut Ui,
    id: Id,
    (label, help): (&str, &str),
    f: &Field<T>,
    bounds: Option<physics::Bounds>,
) -> Option<Value> {
    let mut boxed = bounds.is_some();
    if ui.checkbox(&mut boxed, label).on_hover_text(help).changed() {
        return Some(Value::Bounds(boxed.then(|| physics::Bounds {
            min: Vector::cartesian(-20.0, -20.0),
            max: Vector::cartesian(20.0, 20.0),
            friction: 0.0,
            static_friction: None,
        })));
    }
    let bounds = bounds?;
    if let Some(min) = vector_field(
        ui,
        id.with("min"),
        "min",
        f.unit,
        bounds.min,
        &tr("inspector-bounds-min-hint"),
    ) {
        return Some(Value::Bounds(Some(physics::Bounds { min, ..bounds })));
    }
    vector_field(
        ui,
        id.with("max"),
        "max",
        f.unit,
        bounds.max,
        &tr("inspector-bounds-max-hint"),
    )
    .map(|max| Value::Bounds(Some(physics::Bounds { max, ..bounds })))
}
