//! The `NewtonLab` app: build a scene, run it in real time, watch and measure it. One
//! code base for the desktop (eframe with the glow renderer) and the web.
//!
//! The app edits only the [`Document`]'s scene, through undoable changes; Play builds a
//! [`physics::Simulation`] from it, which the app then only reads, and a [`Recording`]
//! of the run for the graphs; Reset throws the simulation away and shows the scene again.
//! Panels live one per file: [`canvas`], [`inspector`], [`toolbar`], [`plots`],
//! [`files`], and the menu bar, status line and time bar in `menu.rs`, `status.rs` and
//! `time_bar.rs`; `opening.rs` opens, saves and exports the document's files, `keeping.rs`
//! keeps settings and unsaved work, `frames.rs` takes
//! pictures and measures frames; [`run_loop`] paces the physics. Every command (a menu item, a button, a
//! shortcut) is an [`Action`] carried out by [`App::perform`]; every message to the user
//! goes through [`App::notify`].
//!
//! Renderer: glow rather than wgpu. Both run under Xvfb and in headless Chromium with no
//! set-up; glow builds in half the time and gives half the WebAssembly (measured, see
//! `docs/platform.md`), and the tests need no renderer at all (they drive the UI through
//! its accessibility tree).

// An application crate: its public items serve its tests and the `newtonlab` binary,
// and are documented where their use is not plain from their names.
#![expect(missing_docs, reason = "an application crate; see above")]

pub mod action;
pub mod analysis;
pub mod announcer;
#[cfg(not(target_arch = "wasm32"))]
pub mod autosave;
pub mod canvas;
pub mod document;
pub mod edit;
mod experiment_files;
pub mod experiments;
#[cfg(not(target_arch = "wasm32"))]
pub mod figure;
pub mod files;
pub mod format;
pub mod help;
pub use newtonlab_i18n as i18n;
pub mod inspector;
pub mod landmarks;
pub mod lesson;
pub mod links;
pub mod picture;
pub mod platform;
pub mod plots;
mod readouts;
pub mod recording;
pub mod run_loop;
pub mod settings;
pub mod share;
pub mod stopwatch;
pub mod timeline;
pub mod toolbar;
pub use physics::units;
pub mod watching;
#[cfg(target_arch = "wasm32")]
pub mod web;
#[cfg(not(target_arch = "wasm32"))]
pub mod worksheet;

mod frames;
mod keeping;
mod menu;
mod opening;
mod status;
mod time_bar;

use egui::Ui;
use physics::Scene;
use web_time::Instant;

pub use action::Action;
pub use canvas::{FieldKind, Instrument, Selection, Tool};
pub use document::Document;
use edit::Edit;
use files::{Choice, Files, Pending, Purpose};
use i18n::{Arg, tr, tr_with};
use plots::Graphs;
pub use recording::Recording;
use run_loop::Runner;

/// The scene the app opens on.
pub const WELCOME: &str = "marble-run";

/// How the app was started, beyond the scene: for measuring it.
#[derive(Clone, Debug, Default)]
pub struct Launch {
    /// Start playing at once.
    pub play: bool,
    /// Measure this many frames while playing, print the frame times and close.
    pub measure_frames: Option<usize>,
    /// Start in projector mode.
    pub projector: bool,
    /// While measuring, also print every this many frames the mean frame time of those
    /// frames and the simulated time (for a soak: growth shows as a trend).
    pub report_every: Option<usize>,
    /// Draw this field as arrows from the start.
    pub field_view: Option<FieldKind>,
    /// Speak this language (the command line's `--lang`), whatever was chosen last time.
    pub language: Option<i18n::Language>,
}

/// Which side panels show, projector mode (no panels, large text), and the list of keys
/// (F1).
#[derive(Clone, Copy, Debug)]
#[expect(clippy::struct_excessive_bools, reason = "independent on/off toggles")]
pub struct Panels {
    pub inspector: bool,
    pub graphs: bool,
    /// The lesson panel, where the scene has a lesson.
    pub lesson: bool,
    pub projector: bool,
    pub help: bool,
    /// The Getting started page (Help), open on the first run.
    pub getting_started: bool,
}

/// The time machine bar's height, points: its two rows of controls and the panel's
/// margins, at the default text size.
const TIMELINE_HEIGHT: f32 = 54.0;

impl Default for Panels {
    fn default() -> Self {
        Self {
            inspector: true,
            graphs: true,
            lesson: true,
            projector: false,
            help: false,
            getting_started: false,
        }
    }
}

pub struct App {
    pub document: Document,
    pub runner: Runner,
    pub canvas: canvas::Canvas,
    pub graphs: Graphs,
    /// The stopwatch and its window.
    pub stopwatch: stopwatch::Stopwatch,
    /// Text size, high contrast and language, kept from session to session.
    pub settings: settings::Settings,
    /// The latest impact as a sentence for screen readers, rate-limited.
    pub announcer: announcer::Announcer,
    /// What went well, said in the status line (a file exported, no turning point
    /// there), and since when (stamped by the first frame that shows it).
    pub notice: Option<(String, Option<f64>)>,
    /// The experiment series panel: each series' results and the run in progress.
    pub experiments: experiments::Experiments,
    /// The lesson's answers and what Check said of them.
    pub lesson: lesson::LessonPanel,
    /// The share-link or open-link window, when open.
    pub link: Option<links::LinkWindow>,
    /// A CSV table waiting for the file dialog's answer (an experiment's results).
    table_ready: Option<String>,
    /// Where the desktop keeps them; none: not kept.
    #[cfg(not(target_arch = "wasm32"))]
    settings_file: Option<std::path::PathBuf>,
    /// What Copy last took, as scene-file text: what Paste adds.
    pub clipboard: Option<String>,
    /// Text for the system's clipboard at the end of the frame.
    to_system_clipboard: Option<String>,
    /// F6 (`true`) or Shift+F6 pressed: the focus moves to the next or previous region
    /// at the end of the frame.
    next_region: Option<bool>,
    pub files: Files,
    pub selection: Option<Selection>,
    pub panels: Panels,
    /// Why each typed entry that is invalid is so, as of this frame.
    invalid: Vec<String>,
    launch: Launch,
    frame_times: Vec<f64>,
    last_frame: Option<Instant>,
    /// When the measured frames began, and the simulated time then.
    measured_from: Option<(Instant, f64)>,
    shown_title: String,
    /// The user agreed to quit with unsaved changes.
    quitting: bool,
    /// What the unsaved-changes prompt's Save waits to do once the scene is saved.
    after_save: Option<Pending>,
    /// The scene was replaced: what was typed for the old one goes.
    forget_entries: bool,
    /// A picture asked for: the screenshot is requested at the end of this frame…
    picture_asked: Option<picture::Subject>,
    /// …and arrives in a later one, through this slot.
    picture_awaited: Option<(picture::Subject, picture::Slot)>,
    /// A picture encoded, waiting for the file dialog's path.
    picture_ready: Option<Vec<u8>>,
    /// A graph's SVG figure, waiting for where to save it.
    #[cfg(not(target_arch = "wasm32"))]
    svg_ready: Option<Vec<u8>>,
    /// Copies of unsaved work, for recovery after a crash (desktop).
    #[cfg(not(target_arch = "wasm32"))]
    pub autosave: Option<autosave::Autosave>,
    /// An autosave failed and the user was told; not again until one succeeds.
    #[cfg(not(target_arch = "wasm32"))]
    autosave_failed: bool,
}

/// The stopwatch `scene` keeps, or a new one (its window `shown` or not: a new scene keeps
/// the window, not the reading).
fn stopwatch_of(scene: &Scene, shown: bool) -> stopwatch::Stopwatch {
    scene
        .instruments
        .as_ref()
        .and_then(|i| i.stopwatch.as_ref())
        .map_or_else(
            || stopwatch::Stopwatch::shown_as(shown),
            stopwatch::Stopwatch::from_saved,
        )
}

impl Default for App {
    fn default() -> Self {
        let mut app = Self::new(Scene::new());
        app.load_example(WELCOME);
        app
    }
}

impl App {
    /// The app on `scene`, unsaved.
    pub fn new(scene: Scene) -> Self {
        let mut canvas = canvas::Canvas::default();
        canvas.open(&scene);
        let stopwatch = stopwatch_of(&scene, false);
        // A lesson opens in the student's view: the lesson beside the canvas, no inspector.
        let panels = Panels {
            inspector: scene.lesson.is_none(),
            ..Panels::default()
        };
        Self {
            document: Document::new(scene),
            runner: Runner::default(),
            canvas,
            graphs: Graphs::default(),
            stopwatch,
            settings: settings::Settings::default(),
            announcer: announcer::Announcer::default(),
            notice: None,
            experiments: experiments::Experiments::default(),
            lesson: lesson::LessonPanel::default(),
            link: None,
            table_ready: None,
            #[cfg(not(target_arch = "wasm32"))]
            settings_file: None,
            clipboard: None,
            to_system_clipboard: None,
            next_region: None,
            files: Files::default(),
            selection: None,
            panels,
            invalid: Vec::new(),
            launch: Launch::default(),
            frame_times: Vec::new(),
            last_frame: None,
            measured_from: None,
            shown_title: String::new(),
            quitting: false,
            after_save: None,
            forget_entries: false,
            picture_asked: None,
            picture_awaited: None,
            picture_ready: None,
            #[cfg(not(target_arch = "wasm32"))]
            svg_ready: None,
            #[cfg(not(target_arch = "wasm32"))]
            autosave: None,
            #[cfg(not(target_arch = "wasm32"))]
            autosave_failed: false,
        }
    }

    /// How it was launched.
    #[must_use]
    pub fn with_launch(mut self, launch: Launch) -> Self {
        if launch.play {
            self.play_pause();
        }
        self.panels.projector = launch.projector;
        self.canvas.instruments.field_view = launch.field_view;
        self.launch = launch;
        self
    }

    /// Keeps copies of unsaved work with `autosave`, and offers to recover what an
    /// earlier session left unsaved.
    #[cfg(not(target_arch = "wasm32"))]
    #[must_use]
    pub fn with_autosave(mut self, autosave: autosave::Autosave) -> Self {
        self.files.recover = autosave.find();
        self.autosave = Some(autosave);
        self
    }

    /// The window title: the file's name, with a dot when there are unsaved changes.
    pub fn title(&self) -> String {
        let dirty = if self.document.is_dirty() { " ●" } else { "" };
        format!("{}{dirty} — NewtonLab", self.document.title())
    }

    /// Simulated time, seconds (0 while editing).
    pub fn time(&self) -> f64 {
        self.runner
            .simulation()
            .map_or(0.0, physics::Simulation::time)
    }

    /// Tells the user something: an error, or the result of a command (an export).
    pub fn notify(&mut self, message: impl Into<String>) {
        self.files.message = Some(message.into());
    }

    /// Says `message` in the status line for a while: news that asks nothing of the
    /// user. A box to dismiss would take the next click (and leave the keys typed after
    /// it to the shortcuts), which a user meant for something else.
    pub fn tell(&mut self, message: impl Into<String>) {
        self.notice = Some((message.into(), None));
    }

    /// Does what the user asked.
    pub fn perform(&mut self, action: Action) {
        match action {
            Action::New => self.guard(Pending::New),
            Action::Open => self.guard(Pending::Open),
            Action::Save => self.save(),
            Action::SaveAs => self.save_as(),
            Action::ExportGraph(graph) => self.ask_export(graph),
            Action::ExportPicture(subject) => self.picture_asked = Some(subject),
            Action::ExportWorksheet(key) => self.ask_worksheet(key),
            Action::ExportFigure(graph, format) => self.export_figure(graph, format),
            Action::RunExperiment(index) => {
                if let Err(why) = self.experiments.start(self.document.scene(), index) {
                    self.notify(why);
                }
            }
            Action::ExportExperiment(index, format) => self.export_experiment(index, format),
            Action::Example(name) => self.guard(Pending::Example(name)),
            Action::Quit => self.guard(Pending::Quit),
            Action::Undo => self.undo(),
            Action::Redo => self.redo(),
            Action::Delete => self.delete(),
            Action::Copy | Action::Cut | Action::Paste | Action::Duplicate => {
                self.clipboard_action(action);
            }
            Action::PlayPause => self.play_pause(),
            Action::Step => self.step(),
            Action::Reset => self.reset(),
            Action::Fit => self.canvas.request_fit(),
            Action::Tool(tool) => {
                // A tool is chosen instead of the instrument, as one tool replaces another.
                self.canvas.instruments.active = None;
                if self.runner.is_editing() {
                    self.canvas.tool = tool;
                    // A polygon half drawn is left behind with its tool.
                    self.canvas.corners.clear();
                }
            }
            Action::ToggleInspector => self.panels.inspector = !self.panels.inspector,
            Action::ToggleGraphs => self.panels.graphs = !self.panels.graphs,
            Action::ToggleLesson => self.panels.lesson = !self.panels.lesson,
            Action::ToggleProjector => {
                self.panels.projector = !self.panels.projector;
                self.canvas.projector(self.panels.projector);
            }
            Action::Instrument(instrument) => {
                let instruments = &mut self.canvas.instruments;
                if instruments.active == Some(instrument) {
                    instruments.active = None;
                } else {
                    instruments.active = Some(instrument);
                    // From the keyboard alone the probe starts where the view is.
                    if instrument == Instrument::Probe && instruments.probe.is_none() {
                        instruments.probe = Some(self.canvas.view.center);
                    }
                }
            }
            Action::FieldView(kind) => self.canvas.instruments.field_view = kind,
            Action::ToggleStopwatch => self.stopwatch.shown = !self.stopwatch.shown,
            Action::ToggleHelp => self.panels.help = !self.panels.help,
            Action::NextRegion => self.next_region = Some(true),
            Action::PreviousRegion => self.next_region = Some(false),
            Action::ToggleGettingStarted => {
                self.panels.getting_started = !self.panels.getting_started;
            }
            Action::StepBack => self.runner.step_back(),
            Action::GoTo(step) => self.runner.go_to(step),
            Action::TurningPoint(forward) => {
                let particle = match self.selection {
                    Some(Selection::Particle(i)) => Some(i),
                    // With one particle, it is the one.
                    _ => (self.document.scene().particles.len() == 1).then_some(0),
                };
                let found = particle.is_some_and(|i| self.runner.go_to_turning_point(i, forward));
                if !found {
                    self.tell(tr("timeline-no-turn"));
                }
            }
            Action::ForgetEarlierRuns => self.runner.earlier.clear(),
            Action::GoToImpact(k) => {
                let time = self
                    .runner
                    .recording
                    .as_ref()
                    .and_then(|r| r.impacts().get(k));
                if let Some(time) = time.map(|impact| impact.time) {
                    self.runner.go_to_time(time);
                }
            }
            Action::Impact(forward) => {
                if !self.runner.go_to_impact(forward) {
                    self.tell(tr("timeline-no-impact"));
                }
            }
            Action::EditFromHere => self.edit_from_here(),
            Action::ClearMeasurements => self.canvas.instruments.clear(),
            Action::ShareLink => self.open_link_window(true),
            Action::OpenLink => self.open_link_window(false),
        }
    }

    /// Plays or pauses. Play is refused, with the reasons, while a typed entry is
    /// invalid: the run would silently use the old value.
    pub fn play_pause(&mut self) {
        if self.runner.playing {
            self.runner.pause();
            return;
        }
        if self.refuse_while_invalid() {
            return;
        }
        match self.runner.play(self.document.scene()) {
            Ok(()) => {
                let now = self.time();
                self.stopwatch.played(now);
            }
            Err(error) => self.notify(error.report("the scene cannot run")),
        }
    }

    fn refuse_while_invalid(&mut self) -> bool {
        if self.invalid.is_empty() || !self.runner.is_editing() {
            return false;
        }
        let reasons = self.invalid.join("\n");
        self.notify(tr_with(
            "notice-invalid-values",
            &[("reasons", Arg::Text(&reasons))],
        ));
        true
    }

    pub fn step(&mut self) {
        if self.refuse_while_invalid() {
            return;
        }
        let trails = self.canvas.overlays.trails;
        if let Err(error) = self.runner.step_once(self.document.scene(), trails) {
            self.notify(error.report("the scene cannot run"));
        }
    }

    /// Back to the scene; the last run's graphs stay until the next Play.
    pub fn reset(&mut self) {
        self.runner.reset();
    }

    pub fn undo(&mut self) {
        if self.runner.is_editing() && self.document.undo() {
            self.selection = None;
            self.canvas.group.clear();
        }
    }

    pub fn redo(&mut self) {
        if self.runner.is_editing() && self.document.redo() {
            self.selection = None;
            self.canvas.group.clear();
        }
    }

    /// Removes the selected object (and, for a particle, what refers to it).
    /// Copy, Cut, Paste or Duplicate.
    fn clipboard_action(&mut self, action: Action) {
        match action {
            Action::Copy | Action::Cut => {
                if let Some(text) = self.copy() {
                    self.to_system_clipboard = Some(text);
                    if action == Action::Cut {
                        self.delete();
                    }
                }
            }
            Action::Paste => {
                if let Some(text) = self.clipboard.clone() {
                    self.paste_text(&text);
                }
            }
            Action::Duplicate => {
                if let Some(text) = self.copy() {
                    self.paste_text(&text);
                }
            }
            _ => {}
        }
    }

    /// The selected object as scene-file text (a link with the particles it ties),
    /// kept for Paste; `None` without a selection.
    fn copy(&mut self) -> Option<String> {
        let scene = self.document.scene();
        let part = if self.canvas.group.is_empty() {
            scene.extract(self.selection?.section())?
        } else {
            let sections: Vec<_> = self
                .canvas
                .group
                .iter()
                .copied()
                .map(Selection::section)
                .collect();
            scene.extract_all(&sections)?
        };
        let text = part.to_toml();
        self.clipboard = Some(text.clone());
        Some(text)
    }

    /// Adds the objects of scene-file `text` to the scene, beside where they were (a
    /// step down and to the right, so that a copy does not hide its original), renamed
    /// where their names are taken, and selects the first; text that is no scene says
    /// why and changes nothing.
    fn paste_text(&mut self, text: &str) {
        if !self.runner.is_editing() {
            return;
        }
        let part = match Scene::from_toml(text).or_else(|_| Scene::from_json(text)) {
            Ok(part) => part,
            Err(error) => {
                self.notify(tr_with(
                    "notice-paste-no-scene",
                    &[("reason", Arg::Text(&error.to_string()))],
                ));
                return;
            }
        };
        let step = 20.0 / self.canvas.view.pixels_per_metre;
        let offset = physics::DVec2::new(step, -step);
        let mut added = Vec::new();
        self.document.apply(Edit::Paste, |scene| {
            added = scene.paste(&part, offset);
        });
        self.selection = added
            .first()
            .and_then(|&section| Selection::of(section).filter(|&id| canvas::selectable(id)));
        // Several objects pasted are selected together, to be moved as one.
        self.canvas.group = added
            .iter()
            .filter_map(|&s| Selection::of(s).filter(|&id| canvas::selectable(id)))
            .collect();
        if self.canvas.group.len() < 2 {
            self.canvas.group.clear();
        }
    }

    fn delete(&mut self) {
        if !self.runner.is_editing() {
            return;
        }
        if !self.canvas.group.is_empty() {
            let sections: Vec<_> = self
                .canvas
                .group
                .drain(..)
                .map(Selection::section)
                .collect();
            self.selection = None;
            self.document
                .apply(Edit::DeleteGroup, |scene| scene.remove_all(&sections));
            return;
        }
        if let Some(selected) = self.selection.take() {
            let Some(kind) = self.document.scene().kind_of(selected) else {
                return;
            };
            let edit = Edit::Delete(kind);
            self.document
                .apply(edit, |scene| scene.remove(selected.section()));
        }
    }

    /// The file dialog, and what its answer asks for.
    fn file_dialogs(&mut self, ui: &mut Ui) {
        let title = self.document.title();
        match self.files.ui(ui, &title) {
            Some(Choice::Path(Purpose::Open, path)) => self.open_path(&path),
            Some(Choice::Path(Purpose::Save, path)) => self.save_path(&path),
            Some(Choice::Path(Purpose::ExportCsv(graph), path)) => self.export_csv(&path, graph),
            Some(Choice::Path(Purpose::ExportPng, path)) => self.save_picture(&path),
            Some(Choice::Path(Purpose::ExportTable, path)) => self.save_table(&path),
            Some(Choice::Path(Purpose::ExportPdf(key), path)) => {
                // The worksheet's PDF is written on the desktop (no file dialog in the browser).
                #[cfg(not(target_arch = "wasm32"))]
                self.export_worksheet(&path, key);
                #[cfg(target_arch = "wasm32")]
                let _ = (path, key);
            }
            Some(Choice::Path(Purpose::ExportSvg, path)) => {
                // No file dialog in the browser: SVG figures are the desktop's.
                #[cfg(not(target_arch = "wasm32"))]
                self.save_figure_svg(&path);
                #[cfg(target_arch = "wasm32")]
                let _ = path;
            }
            Some(Choice::Discard(pending)) => self.proceed(pending),
            Some(Choice::SaveThen(pending)) => {
                self.after_save = Some(pending);
                self.save();
            }
            Some(Choice::Overwrite(path)) => self.write_scene(&path),
            #[cfg(not(target_arch = "wasm32"))]
            Some(Choice::Recover(recovered)) => self.recover(recovered),
            #[cfg(not(target_arch = "wasm32"))]
            Some(Choice::DropRecovery) => {
                if let Some(autosave) = &mut self.autosave {
                    autosave.clear();
                }
            }
            None => {}
        }
        // A save asked for by the prompt that the user then called off (the Save dialog
        // closed without a name): what waited on it waits no more.
        if self.after_save.is_some() && !self.files.is_asking() {
            self.after_save = None;
        }
    }

    /// The central panel: the canvas, with a series' paths while editing.
    fn central(&mut self, ui: &mut Ui) {
        egui::CentralPanel::default().show(ui, |ui| {
            // A series' runs, drawn faintly while editing: how the varied value fans out.
            let paths = if self.runner.is_editing() {
                self.experiments.paths()
            } else {
                Vec::new()
            };
            self.canvas.ui(
                ui,
                (&mut self.document, &paths),
                &self.runner,
                &mut self.selection,
            );
            if let Some(value) = self.canvas.copied.take() {
                self.announcer.text = tr_with("reading-copied", &[("value", Arg::Text(&value))]);
            }
            // On the desktop the canvas is printed from the shapes it was just drawn
            // with, at twice the resolution (`figure::canvas`); the web takes a screenshot.
            #[cfg(not(target_arch = "wasm32"))]
            if self.picture_asked == Some(picture::Subject::Canvas) {
                self.picture_asked = None;
                self.print_canvas(ui);
            }
        });
    }

    /// The whole app, one frame.
    pub fn ui(&mut self, ui: &mut Ui) {
        // The run back from the steps taken while the last frame was drawn.
        let stepped_ahead = self.runner.catch_up();
        if std::mem::take(&mut self.forget_entries) {
            inspector::forget_entries(ui.ctx());
        }
        self.invalid = inspector::invalid_entries(ui.ctx());
        let real_dt = f64::from(ui.input(|i| i.unstable_dt));
        self.measure_frame(ui);
        let time_scale = self.document.scene().simulation.time_scale;
        self.watch_for_stopwatch();
        self.runner.advance_after(
            real_dt,
            time_scale,
            self.canvas.overlays.trails,
            stepped_ahead,
        );
        self.time_stopwatch();
        if let Some(recording) = &self.runner.recording {
            let now = ui.input(|i| i.time);
            self.announcer.update(recording, self.document.scene(), now);
        }
        if self.runner.playing {
            ui.ctx().request_repaint();
        }
        self.apply_settings(ui);
        self.age_notice(ui);
        let mut actions = Self::shortcuts(ui, self.canvas.id);
        if let Some(text) = Self::pasted_text(ui, self.canvas.id) {
            self.paste_text(&text);
        }

        egui::Panel::top("menu").show(ui, |ui| actions.extend(self.menu(ui)));
        egui::Panel::top("toolbar").show(ui, |ui| {
            actions.extend(toolbar::ui(
                ui,
                &mut self.canvas,
                &mut self.document,
                &self.runner,
                self.panels.projector,
            ));
        });
        egui::Panel::bottom("status").show(ui, |ui| actions.extend(self.status(ui)));
        // Of a fixed height, before a run as during it: Play does not resize the canvas.
        egui::Panel::bottom("timeline")
            .resizable(false)
            .exact_size(TIMELINE_HEIGHT)
            .show(ui, |ui| actions.extend(self.timeline_bar(ui)));
        let side_panels = !self.panels.projector;
        if side_panels && self.panels.inspector {
            // A fixed width: the canvas does not move when the selection changes.
            egui::Panel::left("inspector")
                .resizable(false)
                .exact_size(290.0)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical().show(ui, |ui| {
                        ui.set_width(ui.available_width());
                        let heading = ui.add(
                            egui::Label::new(egui::RichText::new(tr("inspector-title")).heading())
                                .sense(egui::Sense::focusable_noninteractive()),
                        );
                        landmarks::mark(ui, landmarks::Region::Inspector, heading.id);
                        actions.extend(inspector::ui(
                            ui,
                            &mut self.document,
                            &self.runner,
                            &mut self.selection,
                        ));
                    });
                });
        }
        if side_panels && self.panels.lesson && self.document.scene().lesson.is_some() {
            egui::Panel::left("lesson")
                .resizable(true)
                .default_size(lesson::WIDTH)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical().show(ui, |ui| {
                        ui.set_width(ui.available_width());
                        self.lesson.ui(ui, &mut self.document, &self.runner);
                    });
                });
        }
        if side_panels && self.panels.graphs {
            egui::Panel::right("graphs")
                .resizable(true)
                .default_size(350.0)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical().show(ui, |ui| {
                        ui.set_width(ui.available_width());
                        self.graphs.can_ask = self.panels.inspector;
                        actions.extend(self.graphs.ui(ui, &mut self.document, &self.runner));
                        ui.separator();
                        let selected = self.selected_particle_name();
                        actions.extend(self.experiments.ui(
                            ui,
                            &mut self.document,
                            selected.as_deref(),
                        ));
                    });
                });
        }
        self.central(ui);

        self.file_dialogs(ui);
        self.end_frame(ui, actions);
    }

    /// The frame's end: the actions asked for carried out, then what needs the
    /// context (the clipboard, the focus), the windows, the picture, the autosave.
    fn end_frame(&mut self, ui: &mut Ui, actions: Vec<Action>) {
        if let Some(name) = self.graphs.asked.take() {
            let prompt = tr_with("graph-ask-prompt", &[("quantity", Arg::Text(&name))]);
            self.ask(prompt, format!("period {name}"), "s", 0.01);
        }
        for action in actions {
            self.perform(action);
        }
        if let Some(text) = self.to_system_clipboard.take() {
            ui.ctx().copy_text(text);
        }
        if let Some(forward) = self.next_region.take() {
            landmarks::step(ui.ctx(), forward);
        }
        self.stopwatch_window(ui);
        self.link_window(ui);
        help::window(ui.ctx(), &mut self.panels.help);
        help::getting_started(ui.ctx(), &mut self.panels.getting_started);
        self.take_picture(ui);
        #[cfg(not(target_arch = "wasm32"))]
        self.keep_copy();
        self.window(ui);
    }
}

impl eframe::App for App {
    fn ui(&mut self, ui: &mut Ui, _frame: &mut eframe::Frame) {
        App::ui(self, ui);
    }
}

/// Opens the desktop app on `app`.
///
/// # Errors
/// When no window can be opened (no display, no OpenGL).
#[cfg(not(target_arch = "wasm32"))]
pub fn run_native(app: App) -> eframe::Result {
    // The last session's settings; the system's language (LANG on Linux) unless one was
    // chosen. View → Language switches it live.
    let app = match settings::default_file() {
        Some(path) => app.with_settings_file(path).welcome_first_run(),
        None => app.with_settings(settings::Settings::default()),
    };
    if let Some(language) = app.launch.language {
        i18n::set_language(language);
    }
    let mut app = app;
    app.runner.ahead = true;
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1280.0, 800.0])
            .with_min_inner_size([800.0, 500.0])
            .with_title(app.title()),
        ..Default::default()
    };
    eframe::run_native("NewtonLab", options, Box::new(|_| Ok(Box::new(app))))
}
