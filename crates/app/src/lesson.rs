//! The lesson panel: a scene's `[lesson]` beside the canvas — its title and instructions
//! (Markdown), its sliders (the numbers a student may change, with units), and its
//! questions, each with a box for an answer with units and a Check button that compares
//! the answer with what the scene, as the student set it up, measures.
//!
//! The answers are measured in one run of the scene to the lesson's `until`, the first time
//! Check is pressed for that scene; a scene changed since (a slider moved) is run again.

use egui::text::LayoutJob;
use egui::{Color32, RichText, TextFormat, Ui};
use physics::series::{MeasureError, Setting};
use physics::{Lesson, Scene, Verdict};
use pulldown_cmark::{Event, Options, Parser, Tag, TagEnd};

use crate::document::Document;
use crate::edit::Edit;
use crate::i18n::{Arg, tr, tr_with};
use crate::run_loop::Runner;

/// The panel's width, points: a column of text that reads well.
pub const WIDTH: f32 = 320.0;

const RIGHT: Color32 = Color32::from_rgb(30, 140, 60);
const CLOSE: Color32 = Color32::from_rgb(200, 120, 20);
const NOT_YET: Color32 = Color32::from_rgb(200, 30, 30);

/// What Check said of one question's answer.
#[derive(Clone, Debug, PartialEq)]
pub enum Checked {
    /// The verdict, and the simulation's value where the lesson reveals it.
    Verdict(Verdict, Option<f64>),
    /// The answer is no quantity of the question's unit.
    Unreadable(String),
    /// The simulation has no answer (an event that never happens, a run that failed).
    Unmeasured(MeasureError),
}

/// The lesson's answers typed so far and what Check said of them.
#[derive(Default)]
pub struct LessonPanel {
    /// Each question's answer as typed, by the question's index.
    pub answers: Vec<String>,
    /// What Check said of each, by index.
    pub checked: Vec<Option<Checked>>,
    /// The scene last measured, and what it measured for each question.
    measured: Option<(Scene, Result<physics::series::Measured, MeasureError>)>,
}

impl LessonPanel {
    /// Checks question `index`'s answer on `scene`.
    pub fn check(&mut self, scene: &Scene, index: usize) {
        let Some(lesson) = &scene.lesson else { return };
        let Some(question) = lesson.questions.get(index) else {
            return;
        };
        self.fit(lesson);
        let outdated = self.measured.as_ref().is_none_or(|(s, _)| s != scene);
        if outdated {
            self.measured = Some((scene.clone(), lesson.answers(scene)));
        }
        let checked = match question.read_answer(&crate::format::typed(&self.answers[index])) {
            Err(why) => Checked::Unreadable(why),
            Ok(answer) => match self.measured.as_ref().map(|(_, m)| m) {
                Some(Ok(values)) => match &values[index] {
                    Ok(value) => Checked::Verdict(
                        Verdict::of(answer, *value, question.tolerance),
                        question.reveal.then_some(*value),
                    ),
                    Err(why) => Checked::Unmeasured(why.clone()),
                },
                Some(Err(why)) => Checked::Unmeasured(why.clone()),
                None => return,
            },
        };
        self.checked[index] = Some(checked);
    }

    /// One answer box and one result for each question.
    fn fit(&mut self, lesson: &Lesson) {
        let n = lesson.questions.len();
        self.answers.resize(n, String::new());
        self.checked.resize(n, None);
    }

    /// The panel.
    pub fn ui(&mut self, ui: &mut Ui, document: &mut Document, runner: &Runner) {
        let Some(lesson) = document.scene().lesson.clone() else {
            return;
        };
        self.fit(&lesson);
        ui.add(
            egui::Label::new(RichText::new(&lesson.title).heading())
                .sense(egui::Sense::focusable_noninteractive()),
        );
        markdown(ui, &lesson.text);
        if !lesson.sliders.is_empty() {
            ui.separator();
            ui.label(RichText::new(tr("lesson-sliders")).strong());
            let editable = runner.is_editing();
            ui.add_enabled_ui(editable, |ui| {
                for slider in &lesson.sliders {
                    slider_ui(ui, document, slider);
                }
            })
            .response
            .on_disabled_hover_text(tr("lesson-sliders-reset"));
        }
        if !lesson.questions.is_empty() {
            ui.separator();
            ui.label(RichText::new(tr("lesson-questions")).strong());
        }
        for (index, question) in lesson.questions.iter().enumerate() {
            ui.add_space(4.0);
            let prompt = ui.label(format!("{}. {}", index + 1, question.prompt));
            let mut pressed = false;
            ui.horizontal(|ui| {
                let hint = tr_with("lesson-answer-hint", &[("unit", Arg::Text(&question.unit))]);
                let entry = ui
                    .add(
                        egui::TextEdit::singleline(&mut self.answers[index])
                            .hint_text(hint)
                            .desired_width(140.0),
                    )
                    .labelled_by(prompt.id);
                if entry.changed() {
                    self.checked[index] = None;
                }
                let enter = entry.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
                pressed = ui.button(tr("lesson-check")).clicked() || enter;
            });
            if pressed {
                self.check(document.scene(), index);
            }
            if let Some(checked) = &self.checked[index] {
                result_ui(ui, checked, &question.unit);
            }
        }
    }
}

/// A slider over one number of the scene, in its unit; moving it is one undoable edit.
fn slider_ui(ui: &mut Ui, document: &mut Document, slider: &physics::Slider) {
    let setting = match Setting::parse(&slider.field, document.scene()) {
        Ok(setting) => setting,
        Err(why) => {
            ui.label(RichText::new(why).color(NOT_YET));
            return;
        }
    };
    let mut value = setting.value(document.scene());
    let unit = setting.unit();
    let suffix = if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    };
    let response = ui.add(
        egui::Slider::new(&mut value, slider.min..=slider.max)
            .step_by(slider.step)
            .suffix(suffix)
            .text(&slider.field),
    );
    // A drag, or the arrow keys while the slider has the focus, is one undoable step: the
    // slider that began the gesture ends it (a drag on the canvas is not its to end).
    let owner = response.id.with("gesture");
    let mut owns = ui.data(|d| d.get_temp::<bool>(owner)).unwrap_or(false);
    if response.changed() {
        let value = slider.snap(value);
        if !owns {
            document.begin_gesture(Edit::Slide);
            owns = true;
            ui.data_mut(|d| d.insert_temp(owner, true));
        }
        document.apply(Edit::Slide, |scene| setting.set(scene, value));
    }
    if owns && !response.dragged() && !response.has_focus() {
        document.end_gesture();
        ui.data_mut(|d| d.remove::<bool>(owner));
    }
}

/// What Check said, in colour and words.
fn result_ui(ui: &mut Ui, checked: &Checked, unit: &str) {
    match checked {
        Checked::Verdict(verdict, shown) => {
            let (id, colour) = match verdict {
                Verdict::Right => ("lesson-right", RIGHT),
                Verdict::Close => ("lesson-close", CLOSE),
                Verdict::NotYet => ("lesson-not-yet", NOT_YET),
            };
            ui.label(RichText::new(tr(id)).color(colour).strong());
            if let Some(value) = shown {
                let value = format!("{} {unit}", crate::format::number(*value));
                ui.label(tr_with("lesson-revealed", &[("value", Arg::Text(&value))]));
            }
        }
        Checked::Unreadable(why) => {
            ui.label(RichText::new(why).color(NOT_YET));
        }
        Checked::Unmeasured(why) => {
            ui.label(RichText::new(why.to_string()).color(NOT_YET));
        }
    }
}

/// A run of text in one style.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Span {
    pub text: String,
    pub strong: bool,
    pub emphasis: bool,
}

/// A block of a lesson's Markdown, as the panel and the worksheet lay it out.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Block {
    Heading(Vec<Span>),
    Paragraph(Vec<Span>),
    /// A list's item: its mark (`3. `, `• `) and how deep the list is (0 outermost).
    Item {
        mark: String,
        depth: usize,
        spans: Vec<Span>,
    },
    Rule,
}

/// The blocks of Markdown `text`: headings, paragraphs with strong and emphasised words,
/// numbered and bulleted lists (nested), rules; inline code as text. HTML is never kept
/// (a scene with any is refused when it loads); an image is its description.
pub fn blocks(text: &str) -> Vec<Block> {
    let mut blocks = Vec::new();
    let mut spans: Vec<Span> = Vec::new();
    let (mut strong, mut emphasis) = (false, false);
    // What the text gathered now will be: a heading, or an item with its mark.
    let mut heading = false;
    let mut item: Option<(String, usize)> = None;
    // Each open list: the next item's number, or none for bullets.
    let mut lists: Vec<Option<u64>> = Vec::new();
    // The spans gathered so far as a block: an item, a heading or a paragraph.
    let flush = |blocks: &mut Vec<Block>,
                 spans: &mut Vec<Span>,
                 heading: bool,
                 item: &mut Option<(String, usize)>| {
        if spans.is_empty() {
            return;
        }
        let spans = std::mem::take(spans);
        blocks.push(match item.take() {
            Some((mark, depth)) => Block::Item { mark, depth, spans },
            None if heading => Block::Heading(spans),
            None => Block::Paragraph(spans),
        });
    };
    for event in Parser::new_ext(text, Options::empty()) {
        match event {
            Event::Start(Tag::Heading { .. }) => {
                flush(&mut blocks, &mut spans, heading, &mut item);
                heading = true;
            }
            Event::End(TagEnd::Heading(_)) => {
                flush(&mut blocks, &mut spans, heading, &mut item);
                heading = false;
            }
            Event::Start(Tag::Strong) => strong = true,
            Event::End(TagEnd::Strong) => strong = false,
            Event::Start(Tag::Emphasis) => emphasis = true,
            Event::End(TagEnd::Emphasis) => emphasis = false,
            Event::Start(Tag::List(first)) => {
                flush(&mut blocks, &mut spans, heading, &mut item);
                lists.push(first);
            }
            Event::End(TagEnd::List(_)) => {
                flush(&mut blocks, &mut spans, heading, &mut item);
                lists.pop();
            }
            Event::Start(Tag::Item) => {
                flush(&mut blocks, &mut spans, heading, &mut item);
                let mark = match lists.last_mut() {
                    Some(Some(n)) => {
                        *n += 1;
                        format!("{}. ", *n - 1)
                    }
                    _ => "• ".to_owned(),
                };
                item = Some((mark, lists.len().saturating_sub(1)));
            }
            Event::End(TagEnd::Paragraph | TagEnd::Item) => {
                flush(&mut blocks, &mut spans, heading, &mut item);
            }
            Event::Text(text) | Event::Code(text) => spans.push(Span {
                text: text.into_string(),
                strong: strong || heading,
                emphasis,
            }),
            Event::SoftBreak => spans.push(Span {
                text: " ".to_owned(),
                strong: false,
                emphasis: false,
            }),
            Event::HardBreak => spans.push(Span {
                text: "\n".to_owned(),
                strong: false,
                emphasis: false,
            }),
            Event::Rule => {
                flush(&mut blocks, &mut spans, heading, &mut item);
                blocks.push(Block::Rule);
            }
            _ => {}
        }
    }
    flush(&mut blocks, &mut spans, heading, &mut item);
    blocks
}

/// Markdown as the panel shows it ([`blocks`]), wrapped to the panel's width.
pub fn markdown(ui: &mut Ui, text: &str) {
    let body = egui::TextStyle::Body.resolve(ui.style());
    let (plain, strong) = (ui.visuals().text_color(), ui.visuals().strong_text_color());
    let job = |spans: &[Span], first: &str, font: &egui::FontId| {
        let mut job = LayoutJob::default();
        job.append(first, 0.0, TextFormat::simple(font.clone(), plain));
        for span in spans {
            let mut format =
                TextFormat::simple(font.clone(), if span.strong { strong } else { plain });
            format.italics = span.emphasis;
            job.append(&span.text, 0.0, format);
        }
        job
    };
    let mut heading_font = egui::TextStyle::Heading.resolve(ui.style());
    heading_font.size *= 0.8;
    for block in blocks(text) {
        let mut laid = match &block {
            Block::Heading(spans) => job(spans, "", &heading_font),
            Block::Paragraph(spans) => job(spans, "", &body),
            Block::Item { mark, depth, spans } => {
                job(spans, &format!("{}{mark}", "    ".repeat(*depth)), &body)
            }
            Block::Rule => {
                ui.separator();
                continue;
            }
        };
        laid.wrap.max_width = ui.available_width();
        ui.label(laid);
    }
}

impl crate::App {
    /// Asks where to write the lesson's worksheet (with the answer key when `key`).
    pub(crate) fn ask_worksheet(&mut self, key: bool) {
        let name = if key {
            "answer-key.pdf"
        } else {
            "worksheet.pdf"
        };
        self.files
            .ask(crate::files::Purpose::ExportPdf(key), None, name);
    }
}
