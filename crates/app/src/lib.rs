//! The `NewtonLab` app: build a scene, run it in real time, watch and measure it. One
//! code base for the desktop (eframe with the glow renderer) and the web.
//!
//! The app edits only the [`Document`]'s scene, through undoable changes; Play builds a
//! [`physics::Simulation`] from it, which the app then only reads; Reset throws the
//! simulation away and shows the scene again. Panels live one per file: [`canvas`],
//! [`inspector`], [`toolbar`], [`plots`], [`files`]; [`run_loop`] paces the physics.
//!
//! Renderer: glow rather than wgpu. Both run under Xvfb and in headless Chromium with no
//! set-up; glow builds in half the time and gives half the WebAssembly (measured, see
//! `docs/platform.md`), and the tests need no renderer at all (they drive the UI through
//! its accessibility tree).

// An application crate: its public items serve its tests and the `newtonlab` binary,
// and are documented where their use is not plain from their names.
#![expect(missing_docs, reason = "an application crate; see above")]

pub mod canvas;
pub mod document;
pub mod files;
pub mod inspector;
pub mod platform;
pub mod plots;
pub mod run_loop;
pub mod share;
pub mod toolbar;
#[cfg(target_arch = "wasm32")]
pub mod web;

use egui::{Key, KeyboardShortcut, Modifiers, Ui};
use physics::{Scene, SceneFormat};
use web_time::Instant;

pub use canvas::{Selection, Tool};
pub use document::Document;
use files::{Choice, Files, Pending, Purpose};
use plots::Graphs;
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
}

pub struct App {
    pub document: Document,
    pub runner: Runner,
    pub canvas: canvas::Canvas,
    pub graphs: Graphs,
    pub files: Files,
    pub selection: Option<Selection>,
    launch: Launch,
    frame_times: Vec<f64>,
    last_frame: Option<Instant>,
    shown_title: String,
    /// The user agreed to quit with unsaved changes.
    quitting: bool,
}

impl Default for App {
    fn default() -> Self {
        let scene = physics::example(WELCOME)
            .and_then(|e| e.scene().ok())
            .unwrap_or_default();
        Self::new(scene)
    }
}

impl App {
    /// The app on `scene`, unsaved.
    pub fn new(scene: Scene) -> Self {
        let time_scale = scene.simulation.time_scale;
        Self {
            document: Document::new(scene),
            runner: Runner::at_scale(time_scale),
            canvas: canvas::Canvas::default(),
            graphs: Graphs::default(),
            files: Files::default(),
            selection: None,
            launch: Launch::default(),
            frame_times: Vec::new(),
            last_frame: None,
            shown_title: String::new(),
            quitting: false,
        }
    }

    /// How it was launched.
    #[must_use]
    pub fn with_launch(mut self, launch: Launch) -> Self {
        if launch.play {
            self.play_pause();
        }
        self.launch = launch;
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
            .simulation
            .as_ref()
            .map_or(0.0, physics::Simulation::time)
    }

    pub fn play_pause(&mut self) {
        if self.runner.playing {
            self.runner.pause();
            return;
        }
        let fresh = self.runner.simulation.is_none();
        match self.runner.play(self.document.scene()) {
            Ok(()) => {
                if fresh {
                    self.graphs.clear();
                }
            }
            Err(error) => self.files.message = Some(error.report("the scene cannot run")),
        }
    }

    pub fn step(&mut self) {
        let trails = self.canvas.overlays.trails;
        match self.runner.step_once(self.document.scene(), trails) {
            Ok(()) => {
                if let Some(simulation) = &self.runner.simulation {
                    self.graphs.record(simulation);
                }
            }
            Err(error) => self.files.message = Some(error.report("the scene cannot run")),
        }
    }

    pub fn reset(&mut self) {
        self.runner.reset();
        self.graphs.clear();
    }

    pub fn undo(&mut self) {
        if self.runner.simulation.is_none() && self.document.undo() {
            self.selection = None;
        }
    }

    pub fn redo(&mut self) {
        if self.runner.simulation.is_none() && self.document.redo() {
            self.selection = None;
        }
    }

    /// Replaces the document with `scene` from `path` (a file, or `None` for new).
    fn replace(&mut self, scene: Scene, path: Option<String>) {
        self.runner = Runner::at_scale(scene.simulation.time_scale);
        self.document = Document::new(scene);
        if let Some(path) = path {
            self.document.mark_saved(path);
        }
        self.selection = None;
        self.graphs = Graphs::default();
        self.canvas.request_fit();
    }

    /// Loads the scene file at `path`, or shows why it cannot (the messages of `newtonlab
    /// check`).
    pub fn open_path(&mut self, path: &str) {
        #[cfg(not(target_arch = "wasm32"))]
        let text = platform::read_text(path);
        #[cfg(target_arch = "wasm32")]
        let text: Result<String, String> = Err(format!("cannot read '{path}' in the browser"));
        match text.map(|text| (Scene::parse(&text, SceneFormat::from_file_name(path)), text)) {
            Ok((Ok(scene), _)) => self.replace(scene, Some(path.to_owned())),
            Ok((Err(error), _)) => self.files.message = Some(error.report(path)),
            Err(message) => self.files.message = Some(message),
        }
    }

    /// Opens a scene from text (a file picked in the browser, a shared link).
    pub fn open_text(&mut self, name: &str, text: &str) -> bool {
        match Scene::parse(text, SceneFormat::from_file_name(name)) {
            Ok(scene) => {
                self.replace(scene, Some(name.to_owned()));
                true
            }
            Err(error) => {
                self.files.message = Some(error.report(name));
                false
            }
        }
    }

    /// Saves the scene to `path` (TOML, or JSON for a `.json` name).
    pub fn save_path(&mut self, path: &str) {
        let text = self
            .document
            .scene()
            .to_text(SceneFormat::from_file_name(path));
        #[cfg(not(target_arch = "wasm32"))]
        let written = platform::write_text(path, &text);
        #[cfg(target_arch = "wasm32")]
        let written = platform::web::download(path, &text, "text/plain");
        match written {
            Ok(()) => self.document.mark_saved(path.to_owned()),
            Err(message) => self.files.message = Some(message),
        }
    }

    pub fn load_example(&mut self, name: &str) {
        match physics::example(name).map(physics::Example::scene) {
            Some(Ok(scene)) => self.replace(scene, None),
            Some(Err(error)) => self.files.message = Some(error.report(&format!("example:{name}"))),
            None => self.files.message = Some(format!("there is no example '{name}'")),
        }
    }

    /// Runs `pending` now, or asks first if it would lose unsaved changes.
    fn guard(&mut self, pending: Pending) {
        if self.document.is_dirty() {
            self.files.confirm = Some(pending);
        } else {
            self.proceed(pending);
        }
    }

    #[expect(
        clippy::needless_pass_by_value,
        reason = "a pending action is used up by doing it"
    )]
    fn proceed(&mut self, pending: Pending) {
        match pending {
            Pending::New => self.replace(Scene::new(), None),
            #[cfg(not(target_arch = "wasm32"))]
            Pending::Open => self
                .files
                .ask(Purpose::Open, self.document.path.as_deref(), ""),
            #[cfg(target_arch = "wasm32")]
            Pending::Open => platform::web::pick_scene_file(),
            Pending::Example(name) => self.load_example(name),
            Pending::Quit => self.quitting = true,
        }
    }

    fn save(&mut self) {
        match self.document.path.clone() {
            Some(path) => self.save_path(&path),
            None => self.save_as(),
        }
    }

    /// Asks where to save (on the web: downloads the file).
    fn save_as(&mut self) {
        #[cfg(not(target_arch = "wasm32"))]
        self.files
            .ask(Purpose::Save, self.document.path.as_deref(), "scene.toml");
        #[cfg(target_arch = "wasm32")]
        {
            let name = self
                .document
                .path
                .clone()
                .unwrap_or_else(|| "scene.toml".to_owned());
            self.save_path(&name);
        }
    }

    /// Asks where to export the graph (on the web: downloads it).
    fn ask_export(&mut self) {
        #[cfg(not(target_arch = "wasm32"))]
        self.files.ask(Purpose::ExportCsv, None, "graph.csv");
        #[cfg(target_arch = "wasm32")]
        self.export_csv("graph.csv");
    }

    fn menu(&mut self, ui: &mut Ui) {
        egui::MenuBar::new().ui(ui, |ui| {
            ui.menu_button("File", |ui| {
                if ui
                    .button("New")
                    .on_hover_text("An empty scene (Ctrl+N)")
                    .clicked()
                {
                    self.guard(Pending::New);
                }
                if ui
                    .button("Open…")
                    .on_hover_text("Open a scene file (Ctrl+O)")
                    .clicked()
                {
                    self.guard(Pending::Open);
                }
                if ui
                    .button("Save")
                    .on_hover_text("Save the scene (Ctrl+S)")
                    .clicked()
                {
                    self.save();
                }
                if ui
                    .button("Save As…")
                    .on_hover_text("Save the scene under another name (Ctrl+Shift+S)")
                    .clicked()
                {
                    self.save_as();
                }
                if ui
                    .button("Export graph as CSV…")
                    .on_hover_text("Save the recorded graph series")
                    .clicked()
                {
                    self.ask_export();
                }
                #[cfg(target_arch = "wasm32")]
                if ui
                    .button("Copy link to this scene")
                    .on_hover_text(
                        "A link that opens this scene: in the address bar and the clipboard",
                    )
                    .clicked()
                {
                    web::copy_link(self.document.scene());
                    self.files.message = Some(
                        "A link to this scene is in the address bar and on the clipboard."
                            .to_owned(),
                    );
                }
            })
            .response
            .on_hover_text("New, open, save, export, share");
            ui.menu_button("Edit", |ui| {
                let undo = self
                    .document
                    .undo_label()
                    .map_or("Undo".to_owned(), |l| format!("Undo {l}"));
                if ui
                    .add_enabled(
                        self.document.undo_label().is_some(),
                        egui::Button::new(undo),
                    )
                    .on_hover_text("Ctrl+Z")
                    .clicked()
                {
                    self.undo();
                }
                let redo = self
                    .document
                    .redo_label()
                    .map_or("Redo".to_owned(), |l| format!("Redo {l}"));
                if ui
                    .add_enabled(
                        self.document.redo_label().is_some(),
                        egui::Button::new(redo),
                    )
                    .on_hover_text("Ctrl+Shift+Z or Ctrl+Y")
                    .clicked()
                {
                    self.redo();
                }
            })
            .response
            .on_hover_text("Undo and redo");
            ui.menu_button("Examples", |ui| {
                for (name, title) in example_titles() {
                    if ui
                        .button(title)
                        .on_hover_text(format!("example:{name}"))
                        .clicked()
                    {
                        self.guard(Pending::Example(name));
                    }
                }
            })
            .response
            .on_hover_text("Open a built-in scene (the paper's experiments and more)");
        });
    }

    fn shortcuts(&mut self, ui: &Ui) {
        let shortcut = |modifiers, key| KeyboardShortcut::new(modifiers, key);
        let (redo, undo, save_as, save, open, new) = ui.input_mut(|i| {
            (
                i.consume_shortcut(&shortcut(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z))
                    || i.consume_shortcut(&shortcut(Modifiers::COMMAND, Key::Y)),
                i.consume_shortcut(&shortcut(Modifiers::COMMAND, Key::Z)),
                i.consume_shortcut(&shortcut(Modifiers::COMMAND | Modifiers::SHIFT, Key::S)),
                i.consume_shortcut(&shortcut(Modifiers::COMMAND, Key::S)),
                i.consume_shortcut(&shortcut(Modifiers::COMMAND, Key::O)),
                i.consume_shortcut(&shortcut(Modifiers::COMMAND, Key::N)),
            )
        });
        if redo {
            self.redo();
        }
        if undo {
            self.undo();
        }
        if save_as {
            self.save_as();
        }
        if save {
            self.save();
        }
        if open {
            self.guard(Pending::Open);
        }
        if new {
            self.guard(Pending::New);
        }
        if ui.ctx().egui_wants_keyboard_input() {
            return;
        }
        let pressed = |key| ui.input(|i| i.key_pressed(key) && i.modifiers.is_none());
        if pressed(Key::Space) {
            self.play_pause();
        }
        if pressed(Key::Period) {
            self.step();
        }
        if pressed(Key::R) {
            self.reset();
        }
        if pressed(Key::F) {
            self.canvas.request_fit();
        }
        for (key, tool) in [
            (Key::Num1, Tool::Select),
            (Key::Num2, Tool::Particle),
            (Key::Num3, Tool::Spring),
            (Key::Num4, Tool::Ramp),
        ] {
            if pressed(key) {
                self.canvas.tool = tool;
            }
        }
        if (pressed(Key::Delete) || pressed(Key::Backspace))
            && self.runner.simulation.is_none()
            && let Some(selected) = self.selection.take()
        {
            inspector::delete(&mut self.document, selected);
        }
    }

    fn status(&self, ui: &mut Ui) {
        ui.horizontal(|ui| {
            ui.monospace(format!("t = {:.4} s", self.time()));
            ui.separator();
            if let Some(failure) = &self.runner.failure {
                ui.colored_label(
                    egui::Color32::from_rgb(200, 30, 30),
                    format!("stopped: {failure}"),
                );
                return;
            }
            match (self.runner.playing, self.runner.shortfall()) {
                (true, Some(fraction)) => {
                    ui.colored_label(
                        egui::Color32::from_rgb(190, 110, 0),
                        format!(
                            "running at {fraction:.2}× of the requested speed ({:.2}× real time)",
                            self.runner.achieved
                        ),
                    );
                }
                (true, None) => {
                    ui.label(format!("{:.2}× real time", self.runner.achieved));
                }
                (false, _) if self.runner.simulation.is_some() => {
                    ui.label("paused");
                }
                (false, _) => {
                    ui.label("editing");
                }
            }
            ui.separator();
            ui.label(format!("{:.0} steps/s", self.runner.steps_per_second));
            ui.separator();
            let frame = ui.input(|i| i.stable_dt);
            ui.label(format!("frame {:.1} ms", frame * 1000.0));
            ui.separator();
            let scene = self.document.scene();
            ui.label(format!(
                "{} particles, {} springs, {} ramps",
                scene.particles.len(),
                scene.springs.len(),
                scene.ramps.len()
            ));
        });
    }

    /// The whole app, one frame.
    pub fn ui(&mut self, ui: &mut Ui) {
        let real_dt = f64::from(ui.input(|i| i.unstable_dt));
        self.measure_frame(ui);
        if self.runner.advance(real_dt, self.canvas.overlays.trails)
            && let Some(simulation) = &self.runner.simulation
        {
            self.graphs.record(simulation);
        }
        if self.runner.playing {
            ui.ctx().request_repaint();
        }
        self.shortcuts(ui);

        egui::Panel::top("menu").show(ui, |ui| self.menu(ui));
        egui::Panel::top("toolbar").show(ui, |ui| {
            let scene = self.document.scene();
            let requests = toolbar::ui(
                ui,
                &mut toolbar::State {
                    canvas: &mut self.canvas,
                    playing: self.runner.playing,
                    editable: self.runner.simulation.is_none(),
                    time_scale: &mut self.runner.time_scale,
                    integrator: scene.simulation.integrator,
                    time_step: scene.simulation.time_step,
                },
            );
            if requests.play_pause {
                self.play_pause();
            }
            if requests.step {
                self.step();
            }
            if requests.reset {
                self.reset();
            }
            if requests.fit {
                self.canvas.request_fit();
            }
            if let Some(method) = requests.integrator {
                self.document.apply("set integrator", |scene| {
                    scene.simulation.integrator = method;
                });
            }
            if let Some(step) = requests.time_step {
                self.document
                    .apply("set time step", |scene| scene.simulation.time_step = step);
            }
        });
        egui::Panel::bottom("status").show(ui, |ui| self.status(ui));
        egui::Panel::left("inspector")
            .resizable(true)
            .default_size(330.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    ui.heading("Inspector");
                    inspector::ui(
                        ui,
                        &mut self.document,
                        &mut self.runner,
                        &mut self.selection,
                    );
                });
            });
        egui::Panel::right("graphs")
            .resizable(true)
            .default_size(380.0)
            .show(ui, |ui| {
                let export = self.graphs.ui(
                    ui,
                    self.document.scene(),
                    self.runner.simulation.as_ref(),
                    self.runner.start_energy,
                );
                if export {
                    self.ask_export();
                }
            });
        egui::CentralPanel::default().show(ui, |ui| {
            self.canvas
                .ui(ui, &mut self.document, &self.runner, &mut self.selection);
        });

        let title = self.document.title();
        match self.files.ui(ui, &title) {
            Some(Choice::Path(Purpose::Open, path)) => self.open_path(&path),
            Some(Choice::Path(Purpose::Save, path)) => self.save_path(&path),
            Some(Choice::Path(Purpose::ExportCsv, path)) => self.export_csv(&path),
            Some(Choice::Discard(pending)) => self.proceed(pending),
            None => {}
        }
        self.window(ui);
    }

    fn export_csv(&mut self, path: &str) {
        let csv = self.graphs.to_csv(self.document.scene());
        #[cfg(not(target_arch = "wasm32"))]
        if let Err(message) = platform::write_text(path, &csv) {
            self.files.message = Some(message);
        }
        #[cfg(target_arch = "wasm32")]
        if let Err(message) = platform::web::download(path, &csv, "text/csv") {
            self.files.message = Some(message);
        }
    }

    /// The window's title, and closing it: never with unsaved changes unconfirmed.
    fn window(&mut self, ui: &Ui) {
        let title = self.title();
        if title != self.shown_title {
            ui.ctx()
                .send_viewport_cmd(egui::ViewportCommand::Title(title.clone()));
            self.shown_title = title;
        }
        let close_requested = ui.input(|i| i.viewport().close_requested());
        if close_requested && self.document.is_dirty() && !self.quitting {
            ui.ctx()
                .send_viewport_cmd(egui::ViewportCommand::CancelClose);
            self.files.confirm = Some(Pending::Quit);
        }
        if self.quitting {
            ui.ctx().send_viewport_cmd(egui::ViewportCommand::Close);
        }
    }

    /// In measuring mode, records frame times and, when enough are in, reports and closes.
    fn measure_frame(&mut self, ui: &Ui) {
        let Some(frames) = self.launch.measure_frames else {
            return;
        };
        let now = Instant::now();
        if let Some(last) = self.last_frame.replace(now)
            && self.runner.playing
        {
            self.frame_times
                .push(now.duration_since(last).as_secs_f64());
        }
        ui.ctx().request_repaint();
        if self.frame_times.len() >= frames {
            let mut times = self.frame_times.clone();
            times.sort_by(f64::total_cmp);
            let mean = times.iter().sum::<f64>() / times.len() as f64;
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "an index within the list"
            )]
            let percentile = |p: f64| times[((times.len() - 1) as f64 * p).round() as usize];
            #[expect(
                clippy::print_stdout,
                reason = "the measurement is the output of this mode"
            )]
            {
                println!(
                    "{} frames of {} with {} particles: mean {:.1} ms ({:.1} frames per second), median {:.1} ms, 95th percentile {:.1} ms; physics {:.2}× real time",
                    times.len(),
                    self.document.title(),
                    self.document.scene().particles.len(),
                    mean * 1000.0,
                    1.0 / mean,
                    percentile(0.5) * 1000.0,
                    percentile(0.95) * 1000.0,
                    self.runner.achieved,
                );
            }
            self.launch.measure_frames = None;
            self.quitting = true;
        }
    }
}

impl eframe::App for App {
    fn ui(&mut self, ui: &mut Ui, _frame: &mut eframe::Frame) {
        App::ui(self, ui);
    }
}

/// Every built-in scene's name and title, read once: the menu is drawn every frame it is
/// open, and parsing a thousand-ball scene each time would make it stutter.
fn example_titles() -> &'static [(&'static str, String)] {
    static TITLES: std::sync::OnceLock<Vec<(&'static str, String)>> = std::sync::OnceLock::new();
    TITLES.get_or_init(|| {
        physics::EXAMPLES
            .iter()
            .map(|e| {
                (
                    e.name,
                    e.scene()
                        .ok()
                        .and_then(|s| s.name)
                        .unwrap_or_else(|| e.name.to_owned()),
                )
            })
            .collect()
    })
}

/// Opens the desktop app on `app`.
///
/// # Errors
/// When no window can be opened (no display, no OpenGL).
#[cfg(not(target_arch = "wasm32"))]
pub fn run_native(app: App) -> eframe::Result {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1280.0, 800.0])
            .with_min_inner_size([800.0, 500.0])
            .with_title(app.title()),
        ..Default::default()
    };
    eframe::run_native("NewtonLab", options, Box::new(|_| Ok(Box::new(app))))
}
