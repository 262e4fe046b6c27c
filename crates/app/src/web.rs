//! The app in the browser: started on a canvas by `web/index.html`. The scene comes from
//! a shared link in the address (`#scene=…` or `#example=NAME`) when the page was opened
//! with a new one, else from the browser's storage (the scene being edited survives a
//! reload), else the welcome scene. Also exports two functions for the end-to-end test:
//! the app's state as JSON, and a scene's last CSV row after a run, to compare the
//! browser's physics with the desktop's bit for bit.

use std::cell::RefCell;
use std::fmt::Write as _;

use physics::{Scene, SceneFormat, Simulation};
use wasm_bindgen::JsCast as _;
use wasm_bindgen::prelude::*;
use web_time::Instant;

use crate::platform::web as browser;
use crate::{App, share};

/// Where the edited scene is kept between visits.
const SCENE_KEY: &str = "newtonlab.scene";
/// The last link opened, so a reload keeps the edits made to it rather than opening the
/// link afresh.
const LINK_KEY: &str = "newtonlab.link";

thread_local! {
    static STATUS: RefCell<String> = RefCell::new("{}".to_owned());
}

/// The app's state as JSON, for the end-to-end test.
#[wasm_bindgen]
pub fn newtonlab_status() -> String {
    STATUS.with(|s| s.borrow().clone())
}

/// Runs `example:NAME` (or a scene's TOML) to `until` seconds and returns the CSV row of
/// that instant, exactly as `newtonlab run` prints it.
///
/// # Errors
/// An unknown example, an invalid scene, or a simulation failure.
#[wasm_bindgen]
pub fn newtonlab_run_last_row(source: &str, until: f64) -> Result<String, JsValue> {
    let scene = match source.strip_prefix("example:") {
        Some(name) => physics::example(name)
            .ok_or_else(|| JsValue::from_str(&format!("no example '{name}'")))?
            .scene()
            .map_err(|e| JsValue::from_str(&e.to_string()))?,
        None => Scene::parse(source, SceneFormat::Toml)
            .map_err(|e| JsValue::from_str(&e.to_string()))?,
    };
    let mut simulation = Simulation::new(&scene).map_err(|e| JsValue::from_str(&e.to_string()))?;
    simulation
        .step_to(until)
        .map_err(|e| JsValue::from_str(&e.to_string()))?;
    Ok(simulation.csv_row())
}

/// Starts the app on the canvas with id `canvas_id`.
///
/// # Errors
/// No such canvas, or no WebGL.
#[wasm_bindgen]
pub async fn start(canvas_id: String) -> Result<(), JsValue> {
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let canvas = document
        .get_element_by_id(&canvas_id)
        .ok_or_else(|| format!("no element '{canvas_id}'"))?
        .dyn_into::<web_sys::HtmlCanvasElement>()
        .map_err(|_| format!("'{canvas_id}' is not a canvas"))?;
    // The last visit's settings; the browser's language unless one was chosen.
    let app = initial_app()
        .with_settings(crate::settings::Settings::load())
        .welcome_first_run();
    let runner = eframe::WebRunner::new();
    runner
        .start(
            canvas,
            eframe::WebOptions::default(),
            Box::new(|_| Ok(Box::new(WebApp::new(app)))),
        )
        .await
}

/// The app on the scene of a new link, of the browser's storage, or the welcome scene.
fn initial_app() -> App {
    let fragment = browser::fragment();
    let fresh_link =
        !fragment.is_empty() && browser::load(LINK_KEY).as_deref() != Some(fragment.as_str());
    if fresh_link {
        browser::store(LINK_KEY, &fragment);
        match share::decode(&fragment) {
            Ok(Some(scene)) => return App::new(scene),
            Ok(None) => {}
            Err(message) => {
                let mut app = stored_or_welcome();
                app.files.message = Some(message);
                return app;
            }
        }
    }
    stored_or_welcome()
}

fn stored_or_welcome() -> App {
    browser::load(SCENE_KEY)
        .and_then(|text| Scene::from_toml(&text).ok())
        .map_or_else(App::default, App::new)
}

/// The app plus what only the browser needs: storage and the test's status.
struct WebApp {
    app: App,
    stored: Option<Scene>,
    last_store: Instant,
    started: Instant,
    frames: u64,
    first_frame_ms: Option<f64>,
}

impl WebApp {
    fn new(app: App) -> Self {
        Self {
            stored: None,
            last_store: Instant::now(),
            started: Instant::now(),
            frames: 0,
            first_frame_ms: None,
            app,
        }
    }

    /// Keeps the scene in the browser's storage, at most every half second; a change
    /// made sooner asks for a frame when it is due (egui draws only on input otherwise).
    fn persist(&mut self, ctx: &egui::Context) {
        if self.stored.as_ref() == Some(self.app.document.scene()) {
            return;
        }
        let since = self.last_store.elapsed().as_secs_f64();
        if since < 0.5 {
            ctx.request_repaint_after(std::time::Duration::from_secs_f64(0.5 - since));
            return;
        }
        browser::store(SCENE_KEY, &self.app.document.scene().to_toml());
        self.stored = Some(self.app.document.scene().clone());
        self.last_store = Instant::now();
    }

    fn report(&mut self) {
        self.frames += 1;
        if self.first_frame_ms.is_none() {
            self.first_frame_ms = Some(self.started.elapsed().as_secs_f64() * 1000.0);
        }
        let app = &self.app;
        let scene = app.document.scene();
        let status = format!(
            r#"{{"time":{},"playing":{},"particles":{},"name":{},"title":{},"message":{},"frames":{},"first_frame_ms":{},"lesson":{},"student_view":{}}}"#,
            app.time(),
            app.runner.playing,
            scene.particles.len(),
            json_string(scene.name.as_deref().unwrap_or("")),
            json_string(&app.title()),
            json_string(app.files.message.as_deref().unwrap_or("")),
            self.frames,
            self.first_frame_ms.unwrap_or(0.0),
            json_string(scene.lesson.as_ref().map_or("", |l| l.title.as_str())),
            // The lesson beside the canvas, the inspector away: what a student sees.
            scene.lesson.is_some() && app.panels.lesson && !app.panels.inspector,
        );
        STATUS.with(|s| *s.borrow_mut() = status);
    }
}

impl eframe::App for WebApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        match browser::take_picked_file() {
            Some(Ok((name, text))) => {
                self.app.open_text(&name, &text);
            }
            Some(Err(message)) => self.app.files.message = Some(message),
            None => {}
        }
        self.app.ui(ui);
        self.persist(ui.ctx());
        self.report();
    }
}

/// `text` as a JSON string literal.
fn json_string(text: &str) -> String {
    let mut out = String::from('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// Puts a link to `scene` in the address bar and on the clipboard; returns it. The link
/// is remembered as already opened, so reloading the page keeps later edits.
///
/// # Errors
/// A scene too large for a link (the 20,000-star cluster) is refused with the reason,
/// rather than given a link that would not open.
pub fn copy_link(scene: &Scene) -> Result<String, String> {
    let fragment = share::fragment(scene)?;
    browser::store(LINK_KEY, &fragment);
    let url = browser::set_fragment(&fragment);
    browser::copy_to_clipboard(&url);
    Ok(url)
}
