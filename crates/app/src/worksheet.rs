//! A lesson's worksheet to print, as a PDF (`krilla`, A4): the title, a line for the
//! student's name, the instructions, a picture of the scene as the canvas draws it, what
//! may be changed, and the questions with a line for each answer; with the key, a page
//! after them with the simulation's value of every question and the range it accepts.
//!
//! The picture is the real canvas: the app's canvas drawn once in an egui context with no
//! window, its shapes printed by [`crate::figure::canvas`] as for File → Export picture.
//! Text is laid out here, wrapped by the widths of the bundled font's glyphs (the same
//! font the app and the figures use, embedded in the file).

use ab_glyph::Font as _;
use krilla::Document;
use krilla::geom::{PathBuilder, Point, Size, Transform};
use krilla::page::PageSettings;
use krilla::surface::Surface;
use krilla::text::{Font, TextDirection};
use physics::series::MeasureError;
use physics::{Lesson, Scene};

use crate::document;
use crate::i18n::{Arg, tr, tr_with};
use crate::lesson::{Block, blocks};

/// A4, in points.
const PAGE: (f32, f32) = (595.0, 842.0);
/// The margin on every side, points.
const MARGIN: f32 = 56.0;
const BODY: f32 = 11.0;
const HEADING: f32 = 14.0;
const TITLE: f32 = 20.0;
/// Line height over font size.
const LEADING: f32 = 1.35;
/// The canvas drawn for the picture, in points of the screen (printed at twice that).
const PICTURE: (f32, f32) = (720.0, 380.0);

/// The worksheet of `scene`'s lesson, with the answer key after it when `key` is set.
///
/// # Errors
/// The scene has no lesson, the picture or the font could not be made, or the key's run
/// failed (in words).
pub fn pdf(scene: &Scene, key: bool) -> Result<Vec<u8>, String> {
    let lesson = scene
        .lesson
        .as_ref()
        .ok_or_else(|| tr("worksheet-no-lesson"))?;
    let picture = scene_picture(scene)?;
    let answers = if key {
        Some(lesson.answers(scene).map_err(|why| why.to_string())?)
    } else {
        None
    };
    let mut writer = Writer::new()?;
    writer.worksheet(lesson, scene, picture)?;
    if let Some(answers) = answers {
        writer.key(lesson, &answers);
    }
    writer.finish()
}

/// The scene as the canvas draws it when it opens, as PNG bytes.
///
/// # Errors
/// Drawing or encoding failed (in words).
fn scene_picture(scene: &Scene) -> Result<Vec<u8>, String> {
    let ctx = egui::Context::default();
    let mut canvas = crate::canvas::Canvas::default();
    canvas.open(scene);
    let mut document = document::Document::new(scene.clone());
    let runner = crate::run_loop::Runner::default();
    let mut selection = None;
    let input = egui::RawInput {
        screen_rect: Some(egui::Rect::from_min_size(
            egui::Pos2::ZERO,
            egui::vec2(PICTURE.0, PICTURE.1),
        )),
        ..Default::default()
    };
    // The first pass learns the canvas's size and fits the view to it; the second draws.
    let mut shapes = Vec::new();
    for _ in 0..2 {
        let output = ctx.run_ui(input.clone(), |ui| {
            egui::CentralPanel::default()
                .frame(egui::Frame::NONE)
                .show(ui, |ui| {
                    canvas.ui(ui, (&mut document, &[]), &runner, &mut selection);
                });
        });
        shapes = output.shapes;
    }
    let rect = canvas.rect;
    shapes.retain(|s| rect.expand(0.5).contains_rect(s.clip_rect));
    crate::figure::canvas::png(&shapes, rect, 1.0)
}

/// The document being written and where the next line goes.
struct Writer {
    document: Document,
    font: Font,
    /// The same font, for the widths of its glyphs.
    metrics: ab_glyph::FontRef<'static>,
    /// The lines of the page being filled: (x, baseline y, size, text), and its rules.
    lines: Vec<(f32, f32, f32, String)>,
    rules: Vec<(f32, f32, f32)>,
    images: Vec<(krilla::image::Image, f32, f32, Size)>,
    /// The next line's top, points from the page's top.
    y: f32,
}

impl Writer {
    fn new() -> Result<Self, String> {
        let data = epaint_default_fonts::UBUNTU_LIGHT;
        let font = Font::new(data.into(), 0).ok_or_else(|| tr("worksheet-no-font"))?;
        let metrics =
            ab_glyph::FontRef::try_from_slice(data).map_err(|_| tr("worksheet-no-font"))?;
        Ok(Self {
            document: Document::new(),
            font,
            metrics,
            lines: Vec::new(),
            rules: Vec::new(),
            images: Vec::new(),
            y: MARGIN,
        })
    }

    /// The width of `text` at `size`, points.
    fn width(&self, text: &str, size: f32) -> f32 {
        let per_em = self.metrics.units_per_em().unwrap_or(1000.0);
        text.chars()
            .map(|c| self.metrics.h_advance_unscaled(self.metrics.glyph_id(c)))
            .sum::<f32>()
            * size
            / per_em
    }

    /// Room for `height` more points on this page, or a new page.
    fn room(&mut self, height: f32) {
        if self.y + height > PAGE.1 - MARGIN {
            self.page();
        }
    }

    /// Writes the page gathered so far and starts the next.
    fn page(&mut self) {
        let mut page = self
            .document
            .start_page_with(PageSettings::from_wh(PAGE.0, PAGE.1).unwrap_or_default());
        let mut surface = page.surface();
        for (image, x, y, size) in self.images.drain(..) {
            surface.push_transform(&Transform::from_translate(x, y));
            surface.draw_image(image, size);
            surface.pop();
        }
        for (x, y, size, text) in self.lines.drain(..) {
            let at = Point::from_xy(x, y);
            surface.draw_text(
                at,
                self.font.clone(),
                size,
                &text,
                false,
                TextDirection::Auto,
            );
        }
        for (x, y, width) in self.rules.drain(..) {
            rule(&mut surface, x, y, width);
        }
        surface.finish();
        page.finish();
        self.y = MARGIN;
    }

    /// `text` wrapped to the width from `indent` at `size`; the first line begins with
    /// `first` (a list's mark) and the others under its text.
    fn paragraph(&mut self, first: &str, text: &str, size: f32, indent: f32) {
        let line_height = size * LEADING;
        let hang = self.width(first, size);
        let width = PAGE.0 - 2.0 * MARGIN - indent - hang;
        let mut line = String::new();
        let mut lines = Vec::new();
        for word in text.split_whitespace() {
            let longer = if line.is_empty() {
                word.to_owned()
            } else {
                format!("{line} {word}")
            };
            if self.width(&longer, size) > width && !line.is_empty() {
                lines.push(std::mem::replace(&mut line, word.to_owned()));
            } else {
                line = longer;
            }
        }
        lines.push(line);
        for (i, line) in lines.into_iter().enumerate() {
            self.room(line_height);
            let baseline = self.y + size;
            if i == 0 && !first.is_empty() {
                self.lines
                    .push((MARGIN + indent, baseline, size, first.to_owned()));
            }
            self.lines
                .push((MARGIN + indent + hang, baseline, size, line));
            self.y += line_height;
        }
    }

    fn space(&mut self, points: f32) {
        self.y += points;
    }

    /// The title, the name line, the instructions, the picture, the sliders, the questions.
    fn worksheet(
        &mut self,
        lesson: &Lesson,
        scene: &Scene,
        picture: Vec<u8>,
    ) -> Result<(), String> {
        self.paragraph("", &lesson.title, TITLE, 0.0);
        self.space(6.0);
        self.room(BODY * 2.0);
        let name = tr("worksheet-name");
        self.paragraph("", &name, BODY, 0.0);
        let after = self.width(&name, BODY) + 6.0;
        self.rules
            .push((MARGIN + after, self.y - 3.0, PAGE.0 - 2.0 * MARGIN - after));
        self.space(10.0);
        for block in blocks(&lesson.text) {
            self.block(&block);
        }
        self.image(picture)?;
        if !lesson.sliders.is_empty() {
            self.paragraph("", &tr("worksheet-sliders"), HEADING, 0.0);
            for slider in &lesson.sliders {
                // " m r²" after the number, nothing for a pure number.
                let unit = physics::series::Setting::parse(&slider.field, scene)
                    .map(|s| s.unit())
                    .unwrap_or_default();
                let unit = if unit.is_empty() {
                    String::new()
                } else {
                    format!(" {unit}")
                };
                let words = [
                    ("field", Arg::Text(&slider.field)),
                    ("min", Arg::Number(slider.min)),
                    ("max", Arg::Number(slider.max)),
                    ("step", Arg::Number(slider.step)),
                    ("unit", Arg::Text(&unit)),
                ];
                self.paragraph("• ", &tr_with("worksheet-slider", &words), BODY, 0.0);
            }
            self.space(8.0);
        }
        if !lesson.questions.is_empty() {
            self.room(HEADING * 4.0);
            self.paragraph("", &tr("lesson-questions"), HEADING, 0.0);
        }
        for (i, question) in lesson.questions.iter().enumerate() {
            self.room(BODY * LEADING * 2.0 + 30.0);
            self.paragraph(&format!("{}. ", i + 1), &question.prompt, BODY, 0.0);
            // A line to write on, with the unit after it.
            self.space(20.0);
            let indent = self.width(&format!("{}. ", i + 1), BODY);
            self.rules.push((MARGIN + indent, self.y, 220.0));
            self.lines
                .push((MARGIN + indent + 226.0, self.y, BODY, question.unit.clone()));
            self.space(14.0);
        }
        Ok(())
    }

    /// One block of the instructions.
    fn block(&mut self, block: &Block) {
        let text = |spans: &[crate::lesson::Span]| {
            spans.iter().map(|s| s.text.as_str()).collect::<String>()
        };
        match block {
            Block::Heading(spans) => {
                self.space(4.0);
                self.paragraph("", &text(spans), HEADING, 0.0);
            }
            Block::Paragraph(spans) => {
                self.space(4.0);
                self.paragraph("", &text(spans), BODY, 0.0);
            }
            Block::Item { mark, depth, spans } => {
                #[expect(clippy::cast_precision_loss, reason = "a list's depth")]
                let indent = 14.0 * *depth as f32;
                self.paragraph(mark, &text(spans), BODY, indent);
            }
            Block::Rule => {
                self.room(12.0);
                self.rules
                    .push((MARGIN, self.y + 6.0, PAGE.0 - 2.0 * MARGIN));
                self.space(12.0);
            }
        }
    }

    /// The picture across the text's width.
    fn image(&mut self, png: Vec<u8>) -> Result<(), String> {
        let image = krilla::image::Image::from_png(png.into(), true)?;
        let width = PAGE.0 - 2.0 * MARGIN;
        let height = width * PICTURE.1 / PICTURE.0;
        self.space(6.0);
        self.room(height + 6.0);
        let size = Size::from_wh(width, height).ok_or_else(|| tr("worksheet-no-picture"))?;
        self.images.push((image, MARGIN, self.y, size));
        self.space(height + 12.0);
        Ok(())
    }

    /// The answer key on a page of its own: each question's value and what is right.
    fn key(&mut self, lesson: &Lesson, answers: &[Result<f64, MeasureError>]) {
        self.page();
        let title = tr_with(
            "worksheet-key-title",
            &[("title", Arg::Text(&lesson.title))],
        );
        self.paragraph("", &title, TITLE, 0.0);
        self.space(8.0);
        for (i, (question, answer)) in lesson.questions.iter().zip(answers).enumerate() {
            let line = match answer {
                Ok(value) => {
                    let shown = |x: f64| rounded(x, question.tolerance);
                    let words = [
                        ("id", Arg::Text(&question.id)),
                        ("value", Arg::Text(&shown(*value))),
                        ("unit", Arg::Text(&question.unit)),
                        ("tolerance", Arg::Text(&shown(question.tolerance))),
                        ("close", Arg::Text(&shown(10.0 * question.tolerance))),
                    ];
                    tr_with("worksheet-key-line", &words)
                }
                Err(why) => tr_with(
                    "worksheet-key-none",
                    &[
                        ("id", Arg::Text(&question.id)),
                        ("why", Arg::Text(&why.to_string())),
                    ],
                ),
            };
            self.paragraph(&format!("{}. ", i + 1), &question.prompt, BODY, 0.0);
            self.paragraph("", &line, BODY, 14.0);
            self.space(6.0);
        }
    }

    fn finish(mut self) -> Result<Vec<u8>, String> {
        self.page();
        self.document
            .finish()
            .map_err(|e| tr_with("worksheet-failed", &[("why", Arg::Text(&format!("{e:?}")))]))
    }
}

/// A thin horizontal line from (`x`, `y`), `width` long.
fn rule(surface: &mut Surface<'_>, x: f32, y: f32, width: f32) {
    let mut path = PathBuilder::new();
    path.move_to(x, y);
    path.line_to(x + width, y);
    if let Some(path) = path.finish() {
        surface.set_fill(None);
        surface.set_stroke(Some(krilla::paint::Stroke {
            width: 0.6,
            ..Default::default()
        }));
        surface.draw_path(&path);
        surface.set_stroke(None);
    }
}

/// `value` with one decimal more than `tolerance` has (0.01 → 3 decimals), so that the key
/// shows what separates right from close and no more.
fn rounded(value: f64, tolerance: f64) -> String {
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a handful of decimals"
    )]
    let decimals = (1.0 - tolerance.log10().floor()).clamp(0.0, 12.0) as usize;
    format!("{value:.decimals$}")
}

impl crate::App {
    /// Writes the lesson's worksheet (with the key after it when `key`) to `path`.
    pub(crate) fn export_worksheet(&mut self, path: &str, key: bool) {
        let written = pdf(self.document.scene(), key)
            .and_then(|bytes| crate::platform::write_bytes(path, &bytes));
        match written {
            Ok(()) => self.tell(tr_with(
                "notice-worksheet-saved",
                &[("path", Arg::Text(path))],
            )),
            Err(message) => self.notify(message),
        }
    }
}
