//! The document's files: opening a scene (a file, a text, an example, a link's), saving
//! it with the camera and the instruments, asking first when unsaved changes would be
//! lost, and exporting a graph's rows as CSV.

use physics::{Scene, SceneFormat};

use crate::files::Pending;
#[cfg(not(target_arch = "wasm32"))]
use crate::files::Purpose;
use crate::i18n::{Arg, tr, tr_with};
use crate::recording::Recording;
use crate::{App, Document, Graphs, announcer, lesson, platform, plots, stopwatch_of};

impl App {
    /// Replaces the document with `scene` from `path` (a file, or `None` for new), shown
    /// as `label` when it has no file.
    pub(crate) fn replace(&mut self, scene: Scene, path: Option<String>, label: Option<String>) {
        let had_lesson = self.document.scene().lesson.is_some();
        self.runner = self.runner.fresh();
        // Measurements, and what was said of the run, are of the scene they were taken in.
        self.announcer = announcer::Announcer::default();
        self.stopwatch = stopwatch_of(&scene, self.stopwatch.shown);
        self.canvas.open(&scene);
        self.document = Document::new(scene);
        self.document.label = label;
        if let Some(path) = path {
            self.document.mark_saved(path);
        }
        self.selection = None;
        self.canvas.group.clear();
        self.graphs = Graphs::default();
        self.experiments.clear();
        self.lesson = lesson::LessonPanel::default();
        // A lesson opens in the student's view; the scene after one, in the teacher's.
        let lesson = self.document.scene().lesson.is_some();
        if lesson != had_lesson {
            self.panels.inspector = !lesson;
            self.panels.lesson = true;
        }
        self.forget_entries = true;
    }

    /// Loads the scene file at `path`, or shows why it cannot (the messages of `newtonlab
    /// check`).
    pub fn open_path(&mut self, path: &str) {
        #[cfg(not(target_arch = "wasm32"))]
        let text = platform::read_text(path);
        #[cfg(target_arch = "wasm32")]
        let text: Result<String, String> = Err(tr_with(
            "notice-cannot-read-in-browser",
            &[("path", Arg::Text(path))],
        ));
        match text {
            Ok(text) => {
                if self.open_text(path, &text) {
                    #[cfg(not(target_arch = "wasm32"))]
                    {
                        self.document.disk = platform::stamp(path);
                    }
                }
            }
            Err(message) => self.notify(message),
        }
    }

    /// Opens a scene from text (a file picked in the browser, a shared link).
    pub fn open_text(&mut self, name: &str, text: &str) -> bool {
        match Scene::parse(text, SceneFormat::from_file_name(name)) {
            Ok(scene) => {
                self.replace(scene, Some(name.to_owned()), None);
                true
            }
            Err(error) => {
                self.notify(error.report(name));
                false
            }
        }
    }

    /// Saves the scene to `path` (TOML, or JSON for a `.json` name), with the camera as
    /// its `[view]` so that it reopens as it was left. A file changed on disk since it was
    /// opened or saved here is not overwritten without asking.
    pub fn save_path(&mut self, path: &str) {
        #[cfg(not(target_arch = "wasm32"))]
        if self.document.path.as_deref() == Some(path)
            && self.document.disk.is_some()
            && platform::stamp(path) != self.document.disk
        {
            self.files.overwrite = Some(path.to_owned());
            return;
        }
        self.write_scene(path);
    }

    /// The scene as it is saved or shared: with the camera as its `[view]` and the
    /// instruments as its `[instruments]`.
    pub(crate) fn laid_out(&self) -> Scene {
        let mut scene = self.document.scene().clone();
        scene.view = Some(self.canvas.scene_view());
        let mut instruments = self.canvas.instruments.kept(&scene);
        instruments.stopwatch = self.stopwatch.saved(&scene, instruments.tape.is_some());
        scene.instruments = Some(instruments).filter(|i| !i.is_empty());
        scene
    }

    /// Puts the camera and the instruments into the document, as it is saved (no undo
    /// step: neither is an edit).
    pub(crate) fn keep_layout(&mut self) {
        let laid_out = self.laid_out();
        if let Some(view) = laid_out.view {
            self.document.set_view(view);
        }
        self.document.set_instruments(laid_out.instruments);
    }

    /// Writes the scene to `path`, whatever is there.
    pub(crate) fn write_scene(&mut self, path: &str) {
        self.keep_layout();
        let text = self
            .document
            .scene()
            .to_text(SceneFormat::from_file_name(path));
        #[cfg(not(target_arch = "wasm32"))]
        let written = platform::write_text(path, &text);
        #[cfg(target_arch = "wasm32")]
        let written = platform::web::download(path, &text, "text/plain");
        match written {
            Ok(()) => {
                self.document.mark_saved(path.to_owned());
                #[cfg(not(target_arch = "wasm32"))]
                {
                    self.document.disk = platform::stamp(path);
                }
                if let Some(pending) = self.after_save.take() {
                    self.proceed(pending);
                }
            }
            Err(message) => {
                // Not saved: what waited on the save does not go ahead.
                self.after_save = None;
                self.notify(message);
            }
        }
    }

    pub fn load_example(&mut self, name: &str) {
        match physics::example(name).map(physics::Example::scene) {
            Some(Ok(scene)) => {
                let title = scene.name.clone().unwrap_or_else(|| name.to_owned());
                self.replace(scene, None, Some(title));
            }
            Some(Err(error)) => self.notify(error.report(&format!("example:{name}"))),
            None => self.notify(tr_with("notice-no-example", &[("name", Arg::Text(name))])),
        }
    }

    /// Runs `pending` now, or asks first if it would lose unsaved changes.
    pub(crate) fn guard(&mut self, pending: Pending) {
        if self.document.is_dirty() {
            self.files.confirm = Some(pending);
        } else {
            self.proceed(pending);
        }
    }

    pub(crate) fn proceed(&mut self, pending: Pending) {
        match pending {
            // A new scene has no pairwise gravitation: between classroom-sized masses
            // it is a 10⁻¹¹ J row that only confuses. Files keep the format's default.
            Pending::New => {
                let mut scene = Scene::new();
                scene.world.gravitation = false;
                self.replace(scene, None, None);
            }
            #[cfg(not(target_arch = "wasm32"))]
            Pending::Open => self
                .files
                .ask(Purpose::Open, self.document.path.as_deref(), ""),
            #[cfg(target_arch = "wasm32")]
            Pending::Open => platform::web::pick_scene_file(),
            Pending::Example(name) => self.load_example(name),
            Pending::Link(scene) => {
                let title = scene.name.clone().unwrap_or_else(|| tr("link-untitled"));
                self.replace(*scene, None, Some(title));
            }
            Pending::Quit => {
                // Leaving without the changes, on purpose: no copy to recover.
                #[cfg(not(target_arch = "wasm32"))]
                if let Some(autosave) = &mut self.autosave {
                    autosave.clear();
                }
                self.quitting = true;
            }
        }
    }

    pub(crate) fn save(&mut self) {
        match self.document.path.clone() {
            Some(path) => self.save_path(&path),
            None => self.save_as(),
        }
    }

    /// Asks where to save (on the web: downloads the file).
    pub(crate) fn save_as(&mut self) {
        let suggested = self.suggested_file_name();
        #[cfg(not(target_arch = "wasm32"))]
        self.files
            .ask(Purpose::Save, self.document.path.as_deref(), &suggested);
        #[cfg(target_arch = "wasm32")]
        {
            let name = self.document.path.clone().unwrap_or(suggested);
            self.save_path(&name);
        }
    }

    /// The name a scene without a file is offered to be saved as: an example's own file
    /// name (`pendulum.toml`) when it is one, by its title, else `scene.toml`.
    pub(crate) fn suggested_file_name(&self) -> String {
        let Some(title) = self.document.scene().name.as_deref() else {
            return "scene.toml".to_owned();
        };
        physics::EXAMPLES
            .iter()
            .find(|e| {
                e.scene()
                    .ok()
                    .is_some_and(|scene| scene.name.as_deref() == Some(title))
            })
            .map_or_else(|| "scene.toml".to_owned(), |e| format!("{}.toml", e.name))
    }

    /// Asks where to export graph `graph` (on the web: downloads it).
    pub(crate) fn ask_export(&mut self, graph: usize) {
        #[cfg(not(target_arch = "wasm32"))]
        self.files.ask(Purpose::ExportCsv(graph), None, "graph.csv");
        #[cfg(target_arch = "wasm32")]
        self.export_csv("graph.csv", graph);
    }

    /// The run's recording and graph `graph`, to export; `None`, said, when there is
    /// nothing to export.
    pub(crate) fn recorded_graph(&mut self, graph: usize) -> Option<(&Recording, &physics::Graph)> {
        if self.runner.recording.is_none() || self.document.scene().graphs.get(graph).is_none() {
            self.notify(tr("notice-nothing-to-export"));
            return None;
        }
        Some((
            self.runner.recording.as_ref()?,
            self.document.scene().graphs.get(graph)?,
        ))
    }

    /// Writes graph `graph`'s recorded samples to `path` and says how many.
    pub fn export_csv(&mut self, path: &str, graph: usize) {
        let Some((recording, setup)) = self.recorded_graph(graph) else {
            return;
        };
        let csv = plots::to_csv(recording, setup);
        let rows = recording.len();
        self.write_table(path, &csv, rows);
    }

    /// Writes the CSV `text` of `rows` rows to `path` (on the web: downloads it) and says
    /// so.
    pub(crate) fn write_table(&mut self, path: &str, text: &str, rows: usize) {
        #[cfg(not(target_arch = "wasm32"))]
        let written = platform::write_text(path, text);
        #[cfg(target_arch = "wasm32")]
        let written = platform::web::download(path, text, "text/csv");
        match written {
            Ok(()) => self.tell(tr_with(
                "notice-exported",
                &[
                    ("rows", Arg::Number(rows as f64)),
                    ("path", Arg::Text(path)),
                ],
            )),
            Err(message) => self.notify(message),
        }
    }
}
