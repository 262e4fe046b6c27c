//! Reading and writing `[lesson]` with its `[[lesson.slider]]` and `[[lesson.question]]`.

use super::read::{Reader, array_items};
use super::tree::{Node, Value};
use super::values::{read_bool, read_number, read_text};
use super::write::{Header, Out, OutSection};
use crate::scene::error::Section;
use crate::scene::validate;
use crate::scene::{Lesson, Question, Slider};

pub(super) const LESSON_KEYS: &[&str] = &["title", "text", "until", "slider", "question"];
pub(super) const SLIDER_KEYS: &[&str] = &["field", "min", "max", "step"];
pub(super) const QUESTION_KEYS: &[&str] =
    &["id", "prompt", "measure", "unit", "tolerance", "reveal"];

impl Reader<'_> {
    pub(super) fn lesson(&mut self, node: &Node) -> Lesson {
        let mut lesson = Lesson::default();
        let Some(mut t) = self.table(node, Section::Lesson, "[lesson]".to_owned()) else {
            return lesson;
        };
        lesson.title = self.required(&mut t, "title", read_text, String::new());
        lesson.text = self.field(&mut t, "text", read_text).unwrap_or_default();
        lesson.until = self.field(&mut t, "until", read_number);
        for (i, node) in self.items(&mut t, "slider").iter().enumerate() {
            let slider = self.slider(node, i);
            lesson.sliders.push(slider);
        }
        for (i, node) in self.items(&mut t, "question").iter().enumerate() {
            let question = self.question(node, i);
            lesson.questions.push(question);
        }
        self.close(&t, LESSON_KEYS);
        lesson
    }

    fn slider(&mut self, node: &Node, index: usize) -> Slider {
        let mut slider = Slider {
            field: String::new(),
            min: 0.0,
            max: 1.0,
            step: 1.0,
        };
        let label = validate::numbered("slider", index);
        let Some(mut t) = self.table(node, Section::Slider(index), label) else {
            return slider;
        };
        slider.field = self.required(&mut t, "field", read_text, String::new());
        slider.min = self.required(&mut t, "min", read_number, 0.0);
        slider.max = self.required(&mut t, "max", read_number, 1.0);
        slider.step = self.required(&mut t, "step", read_number, 1.0);
        self.close(&t, SLIDER_KEYS);
        slider
    }

    fn question(&mut self, node: &Node, index: usize) -> Question {
        let mut question = Question {
            id: String::new(),
            prompt: String::new(),
            measure: String::new(),
            unit: String::new(),
            tolerance: 1.0,
            reveal: false,
        };
        let label = validate::numbered("question", index);
        let Some(mut t) = self.table(node, Section::Question(index), label) else {
            return question;
        };
        question.id = self.required(&mut t, "id", read_text, String::new());
        question.prompt = self.required(&mut t, "prompt", read_text, String::new());
        question.measure = self.required(&mut t, "measure", read_text, String::new());
        question.unit = self.required(&mut t, "unit", read_text, String::new());
        question.tolerance = self.required(&mut t, "tolerance", read_number, 1.0);
        question.reveal = self.field(&mut t, "reveal", read_bool).unwrap_or(false);
        self.close(&t, QUESTION_KEYS);
        question
    }
}

/// Within the lesson's table `lesson`: itself, or a slider's or a question's item.
pub(super) fn lesson_node<'n>(lesson: &'n Node<'n>, section: Section) -> Option<&'n Node<'n>> {
    let Value::Table(entries) = &lesson.value else {
        return None;
    };
    match section {
        Section::Slider(i) => array_items(entries, "slider").get(i),
        Section::Question(i) => array_items(entries, "question").get(i),
        _ => Some(lesson),
    }
}

/// The lesson as sections: `[lesson]`, then each slider and each question.
pub(super) fn lesson_sections(lesson: &Lesson) -> Vec<OutSection> {
    let mut entries = vec![("title", Out::Text(lesson.title.clone()))];
    if !lesson.text.is_empty() {
        entries.push(("text", Out::Text(lesson.text.clone())));
    }
    if let Some(until) = lesson.until {
        entries.push(("until", Out::Number(until)));
    }
    let mut sections = vec![OutSection {
        header: Header::Table("lesson"),
        entries,
    }];
    for slider in &lesson.sliders {
        sections.push(OutSection {
            header: Header::Nested("lesson", "slider"),
            entries: vec![
                ("field", Out::Text(slider.field.clone())),
                ("min", Out::Number(slider.min)),
                ("max", Out::Number(slider.max)),
                ("step", Out::Number(slider.step)),
            ],
        });
    }
    for question in &lesson.questions {
        let mut entries = vec![
            ("id", Out::Text(question.id.clone())),
            ("prompt", Out::Text(question.prompt.clone())),
            ("measure", Out::Text(question.measure.clone())),
            ("unit", Out::Text(question.unit.clone())),
            ("tolerance", Out::Number(question.tolerance)),
        ];
        if question.reveal {
            entries.push(("reveal", Out::Bool(true)));
        }
        sections.push(OutSection {
            header: Header::Nested("lesson", "question"),
            entries,
        });
    }
    sections
}
