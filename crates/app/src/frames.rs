//! Pictures of the canvas, the window's title, and the frame-rate measurement of
//! `--measure-frames`.

use crate::App;
#[cfg(not(target_arch = "wasm32"))]
use crate::figure;
use crate::files::Pending;
#[cfg(not(target_arch = "wasm32"))]
use crate::files::Purpose;
use crate::i18n::{Arg, tr_with};
use crate::{picture, platform};
use egui::Ui;
use web_time::Instant;

impl App {
    /// Asks for a screenshot when a picture was asked for (but the desktop's canvas), and
    /// turns the screenshot into a PNG of the part wanted when it arrives.
    pub(crate) fn take_picture(&mut self, ui: &Ui) {
        // On the desktop the canvas prints itself at the next frame (`print_canvas`).
        let printed =
            !cfg!(target_arch = "wasm32") && self.picture_asked == Some(picture::Subject::Canvas);
        if let Some(subject) = self.picture_asked.take_if(|_| !printed) {
            self.picture_awaited = Some((subject, picture::request(ui.ctx())));
        }
        let Some((subject, slot)) = &self.picture_awaited else {
            return;
        };
        let (subject, Some(image)) = (*subject, picture::take(slot)) else {
            return;
        };
        self.picture_awaited = None;
        let rect = match subject {
            picture::Subject::Canvas => self.canvas.rect,
            picture::Subject::Graph(g) => self.graphs.rect(g),
        };
        match picture::png_of(&image, rect, ui.ctx().pixels_per_point()) {
            Ok(bytes) => {
                self.picture_ready = Some(bytes);
                #[cfg(not(target_arch = "wasm32"))]
                self.files
                    .ask(Purpose::ExportPng, None, subject.file_name());
                #[cfg(target_arch = "wasm32")]
                self.save_picture(subject.file_name());
            }
            Err(message) => self.notify(message),
        }
    }

    /// The canvas as drawn so far this frame, at twice the resolution, as a PNG to save.
    #[cfg(not(target_arch = "wasm32"))]
    pub(crate) fn print_canvas(&mut self, ui: &Ui) {
        let rect = self.canvas.rect;
        // The canvas's painter clips to the canvas: every shape clipped within it is its.
        let shapes: Vec<egui::epaint::ClippedShape> = ui.ctx().graphics(|layers| {
            layers
                .get(ui.layer_id())
                .map(|list| {
                    list.all_entries()
                        .filter(|s| rect.expand(0.5).contains_rect(s.clip_rect))
                        .cloned()
                        .collect()
                })
                .unwrap_or_default()
        });
        match figure::canvas::png(&shapes, rect, ui.ctx().pixels_per_point()) {
            Ok(bytes) => {
                self.picture_ready = Some(bytes);
                self.files.ask(
                    Purpose::ExportPng,
                    None,
                    picture::Subject::Canvas.file_name(),
                );
            }
            Err(message) => self.notify(message),
        }
    }

    /// Draws graph `graph` as a figure to print and asks where to save it (on the web:
    /// downloads it).
    pub(crate) fn export_figure(&mut self, graph: usize, format: picture::Format) {
        #[cfg(target_arch = "wasm32")]
        {
            let _ = format;
            self.picture_asked = Some(picture::Subject::Graph(graph));
        }
        #[cfg(not(target_arch = "wasm32"))]
        self.draw_figure(graph, format);
    }

    /// [`Self::export_figure`] on the desktop: plotters draws the figure.
    #[cfg(not(target_arch = "wasm32"))]
    fn draw_figure(&mut self, graph: usize, format: picture::Format) {
        let colours = self
            .document
            .scene()
            .graphs
            .get(graph)
            .and_then(|setup| crate::plots::object_colours(self.document.scene(), &setup.y));
        let Some((recording, setup)) = self.recorded_graph(graph) else {
            return;
        };
        let title = setup
            .title
            .clone()
            .unwrap_or_else(|| crate::plots::describe(setup));
        match figure::graph(recording, setup, colours.as_deref(), &title, format) {
            Ok(bytes) => match format {
                picture::Format::Png => {
                    self.picture_ready = Some(bytes);
                    self.files.ask(Purpose::ExportPng, None, "graph.png");
                }
                picture::Format::Svg => {
                    self.svg_ready = Some(bytes);
                    self.files.ask(Purpose::ExportSvg, None, "graph.svg");
                }
            },
            Err(message) => self.notify(message),
        }
    }

    /// Writes the SVG figure waiting to `path`.
    #[cfg(not(target_arch = "wasm32"))]
    pub(crate) fn save_figure_svg(&mut self, path: &str) {
        let Some(bytes) = self.svg_ready.take() else {
            return;
        };
        let text = String::from_utf8_lossy(&bytes).into_owned();
        let written = platform::write_text(path, &text);
        match written {
            Ok(()) => self.tell(tr_with(
                "notice-picture-saved",
                &[("path", Arg::Text(path))],
            )),
            Err(message) => self.notify(message),
        }
    }

    /// Writes the picture waiting to `path` (on the web: downloads it).
    pub(crate) fn save_picture(&mut self, path: &str) {
        let Some(bytes) = self.picture_ready.take() else {
            return;
        };
        #[cfg(not(target_arch = "wasm32"))]
        let written = platform::write_bytes(path, &bytes);
        #[cfg(target_arch = "wasm32")]
        let written = platform::web::download_bytes(path, &bytes, "image/png");
        match written {
            Ok(()) => self.tell(tr_with(
                "notice-picture-saved",
                &[("path", Arg::Text(path))],
            )),
            Err(message) => self.notify(message),
        }
    }

    /// The window's title, and closing it: never with unsaved changes unconfirmed.
    pub(crate) fn window(&mut self, ui: &Ui) {
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
        } else {
            // The frame is built: the physics steps on while it is drawn.
            let time_scale = self.document.scene().simulation.time_scale;
            self.runner.step_ahead(time_scale);
        }
    }

    /// In measuring mode, records frame times and, when enough are in, reports and closes.
    pub(crate) fn measure_frame(&mut self, ui: &Ui) {
        let Some(frames) = self.launch.measure_frames else {
            return;
        };
        let now = Instant::now();
        if let Some(last) = self.last_frame.replace(now)
            && self.runner.playing
        {
            self.frame_times
                .push(now.duration_since(last).as_secs_f64());
            // The speed over the whole measurement, from its first frame.
            self.measured_from.get_or_insert((now, self.time()));
        }
        ui.ctx().request_repaint();
        if let Some(every) = self.launch.report_every.filter(|&e| e > 0)
            && !self.frame_times.is_empty()
            && self.frame_times.len().is_multiple_of(every)
        {
            let window = &self.frame_times[self.frame_times.len() - every..];
            let mean = window.iter().sum::<f64>() / window.len() as f64;
            #[expect(
                clippy::print_stdout,
                reason = "the measurement is the output of this mode"
            )]
            {
                println!(
                    "frames {}-{}: mean {:.1} ms; t = {:.1} s simulated, physics {:.2}× real time",
                    self.frame_times.len() - every + 1,
                    self.frame_times.len(),
                    mean * 1000.0,
                    self.time(),
                    self.runner.achieved.unwrap_or(f64::NAN),
                );
            }
        }
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
            let speed = self
                .measured_from
                .map_or(self.runner.achieved.unwrap_or(f64::NAN), |(from, t)| {
                    (self.time() - t) / now.duration_since(from).as_secs_f64()
                });
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
                    speed,
                );
            }
            self.launch.measure_frames = None;
            self.quitting = true;
        }
    }
}
