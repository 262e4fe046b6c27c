//! A lesson (`[lesson]`): what a scene teaches — a title, instructions in Markdown, the
//! numbers a student may change (sliders) and questions that the simulation itself
//! answers. The answer key is the run: each question names a measure that a series
//! understands (`time at disc.x crosses -1.93`, `period Bob.x`, `max Ball.y`), and a
//! student's answer, typed with units, is compared with what the scene as the student set
//! it up measures.

use super::series::{Measure, Setting, Sweep};
use super::{Scene, Section, say};

/// How long a lesson's run lasts when `[lesson]` names no `until`, seconds after the
/// scene's start: long enough for a few swings, falls and bounces of a classroom scene,
/// short enough to answer at once.
pub const DEFAULT_UNTIL: f64 = 10.0;

/// The longest instructions or prompt a lesson may hold, bytes: a page of text is a few
/// thousand; more is an embedded picture or a file pasted by mistake, which would make
/// the scene file and its share link unusable.
pub const MOST_TEXT: usize = 64 * 1024;

/// A lesson.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Lesson {
    /// Its title.
    pub title: String,
    /// The introduction and numbered steps, in Markdown (headings, emphasis, lists).
    pub text: String,
    /// How long the run that answers the questions lasts, seconds (the instant it ends);
    /// default: [`DEFAULT_UNTIL`] after the scene's start.
    pub until: Option<f64>,
    /// What a student may change.
    pub sliders: Vec<Slider>,
    /// What a student is asked.
    pub questions: Vec<Question>,
}

/// A number of the scene a student may change, by its field path (as `sweep --vary`
/// names it), within a range and in steps.
#[derive(Clone, Debug, PartialEq)]
pub struct Slider {
    /// The field: `incline.friction`, `Ball.velocity.angle`, `world.gravity.y`.
    pub field: String,
    /// The smallest value.
    pub min: f64,
    /// The largest value.
    pub max: f64,
    /// The step between values.
    pub step: f64,
}

/// A question the simulation answers.
#[derive(Clone, Debug, PartialEq)]
pub struct Question {
    /// Unique in the lesson: what `newtonlab lesson --answer ID=VALUE` names.
    pub id: String,
    /// What the student is asked.
    pub prompt: String,
    /// The measure that answers it, as a series writes it.
    pub measure: String,
    /// The unit of the answer (any unit of the measure's kind: `cm` for a length).
    pub unit: String,
    /// How far off an answer may be and still be right, in `unit`; within ten times it,
    /// close.
    pub tolerance: f64,
    /// Whether Check may show the simulation's value.
    pub reveal: bool,
}

/// What Check says of an answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Within the tolerance.
    Right,
    /// Within ten times the tolerance.
    Close,
    /// Farther.
    NotYet,
}

impl Verdict {
    /// As `newtonlab lesson` prints it: `right`, `close`, `not yet`.
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Right => "right",
            Self::Close => "close",
            Self::NotYet => "not yet",
        }
    }

    /// The verdict on `answer` for a question whose measured value is `measured`, both in
    /// the question's unit. The bounds hold a billionth more than the tolerance, so that an
    /// answer typed to the tolerance's last digit is not judged by a rounding of its
    /// decimal: 1.34 against 1.33 with a tolerance of 0.01 is right.
    pub fn of(answer: f64, measured: f64, tolerance: f64) -> Self {
        let off = (answer - measured).abs();
        let slack = 1e-9 * (tolerance + measured.abs());
        if off <= tolerance + slack {
            Self::Right
        } else if off <= 10.0 * tolerance + slack {
            Self::Close
        } else {
            Self::NotYet
        }
    }
}

/// The words `newtonlab lesson` accepts as an id: letters, digits, `_` and `-`.
fn is_id(id: &str) -> bool {
    !id.is_empty()
        && id
            .chars()
            .all(|c| c.is_alphanumeric() || c == '_' || c == '-')
}

/// Why `text` (a title, instructions, a prompt) cannot be shown: longer than
/// [`MOST_TEXT`], or holding HTML.
fn text_problem(text: &str) -> Option<String> {
    if text.len() > MOST_TEXT {
        let size = format!("{:.1}", text.len() as f64 / 1024.0);
        let most = (MOST_TEXT / 1024).to_string();
        Some(say(
            "lesson-text-too-long",
            &[("size", &size), ("most", &most)],
        ))
    } else if holds_html(text) {
        Some(say("lesson-html", &[]))
    } else {
        None
    }
}

/// Raw HTML in Markdown: a tag (`<script>`, `<img …>`, `</b>`) or a comment. The lesson
/// panel and the worksheet show text, never run or embed what a file brings.
fn holds_html(text: &str) -> bool {
    text.match_indices('<').any(|(at, _)| {
        let after = &text[at + 1..];
        after.starts_with(|c: char| c.is_ascii_alphabetic() || c == '/' || c == '!')
    })
}

impl Question {
    /// The measure, read.
    ///
    /// # Errors
    /// What the measure should have been (in words).
    pub fn parsed(&self) -> Result<Measure, String> {
        Measure::parse(&self.measure)
    }

    /// The measure's SI value `si` in the question's unit.
    pub fn in_unit(&self, si: f64) -> f64 {
        si / crate::units::si_of(&self.unit).1
    }

    /// The student's `answer` (a number with a unit of the question's kind, or arithmetic)
    /// in the question's unit.
    ///
    /// # Errors
    /// Not a number, or a unit of another kind (in words).
    pub fn read_answer(&self, answer: &str) -> Result<f64, String> {
        crate::units::parse_in(answer, &self.unit)
    }
}

impl Lesson {
    /// The instant the lesson's run ends on `scene`.
    pub fn until(&self, scene: &Scene) -> f64 {
        self.until
            .unwrap_or(scene.simulation.start_time + DEFAULT_UNTIL)
    }

    /// The question called `id`.
    pub fn question(&self, id: &str) -> Option<&Question> {
        self.questions.iter().find(|q| q.id == id)
    }

    /// Every problem with the lesson on `scene`, each with its section and key: text that
    /// holds HTML or is too long, a slider whose field is no number of the scene or whose
    /// range breaks the field's rule, a question whose measure does not read or names
    /// nothing, whose unit does not fit its measure, whose id is repeated.
    pub fn problems(&self, scene: &Scene) -> Vec<(Section, &'static str, String)> {
        let mut problems = Vec::new();
        let lesson = Section::Lesson;
        if self.title.trim().is_empty() {
            problems.push((lesson, "title", say("lesson-no-title", &[])));
        }
        for (key, text) in [("title", &self.title), ("text", &self.text)] {
            if let Some(why) = text_problem(text) {
                problems.push((lesson, key, why));
            }
        }
        let until = self.until(scene);
        if !(until.is_finite() && until > scene.simulation.start_time) {
            let until = until.to_string();
            problems.push((
                lesson,
                "until",
                say("scene-series-until", &[("until", &until)]),
            ));
        }
        for (i, slider) in self.sliders.iter().enumerate() {
            for (key, why) in slider.problems(scene) {
                problems.push((Section::Slider(i), key, why));
            }
        }
        let mut measures = Vec::new();
        for (i, question) in self.questions.iter().enumerate() {
            let section = Section::Question(i);
            if !is_id(&question.id) {
                let why = say("lesson-bad-id", &[("id", &question.id)]);
                problems.push((section, "id", why));
            } else if self.questions[..i].iter().any(|q| q.id == question.id) {
                let why = say("lesson-repeated-id", &[("id", &question.id)]);
                problems.push((section, "id", why));
            }
            if question.prompt.trim().is_empty() {
                problems.push((section, "prompt", say("lesson-no-prompt", &[])));
            } else if let Some(why) = text_problem(&question.prompt) {
                problems.push((section, "prompt", why));
            }
            match question
                .parsed()
                .and_then(|m| m.check_in(scene).map(|()| m))
            {
                Err(why) => problems.push((section, "measure", why)),
                Ok(measure) => {
                    let si = measure.unit();
                    if !crate::units::fits(&question.unit, si) {
                        let words = [("unit", question.unit.as_str()), ("si", si)];
                        problems.push((section, "unit", say("lesson-unit-misfit", &words)));
                    }
                    measures.push(measure);
                }
            }
            if !(question.tolerance.is_finite() && question.tolerance > 0.0) {
                let tolerance = question.tolerance.to_string();
                let why = say("lesson-tolerance", &[("tolerance", &tolerance)]);
                problems.push((section, "tolerance", why));
            }
        }
        let sweep = Sweep {
            varies: Vec::new(),
            until,
            measures,
            trace: false,
        };
        if until > scene.simulation.start_time
            && let Err(why) = sweep.extent(scene)
        {
            problems.push((lesson, "until", why));
        }
        problems
    }
}

impl Slider {
    /// What is wrong with the slider on `scene`, each with its key.
    fn problems(&self, scene: &Scene) -> Vec<(&'static str, String)> {
        let setting = match Setting::parse(&self.field, scene) {
            Ok(setting) => setting,
            Err(why) => return vec![("field", why)],
        };
        let (min, max) = (self.min.to_string(), self.max.to_string());
        if self.min >= self.max {
            let why = say("lesson-slider-range", &[("min", &min), ("max", &max)]);
            return vec![("max", why)];
        }
        if !(self.step > 0.0 && self.step <= self.max - self.min) {
            let step = self.step.to_string();
            let why = say("lesson-slider-step", &[("step", &step)]);
            return vec![("step", why)];
        }
        // The ends must obey the field's rules as a file's value would: the scene with the
        // slider at either end is checked, and a problem with the slider's field is the
        // slider's (as the inspector judges a typed value).
        let field = Some(setting.field());
        let mut moved = scene.clone();
        moved.lesson = None;
        let mut problems = Vec::new();
        for (key, value) in [("min", self.min), ("max", self.max)] {
            setting.set(&mut moved, value);
            if let Some(new) = moved.validate().into_iter().find(|p| p.field == field) {
                let value = value.to_string();
                let words = [("value", value.as_str()), ("why", new.message.as_str())];
                problems.push((key, say("lesson-slider-rule", &words)));
            }
        }
        problems
    }

    /// The value of the slider's steps (`min`, `min + step`, … up to `max`) nearest to
    /// `value`, to twelve significant digits: six steps of 0.1 are 0.6 as a teacher
    /// writes it, not 0.6000000000000001.
    pub fn snap(&self, value: f64) -> f64 {
        let steps = ((value - self.min) / self.step).round();
        let exact = (self.min + steps * self.step).clamp(self.min, self.max);
        format!("{exact:.11e}").parse().unwrap_or(exact)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn verdicts_at_and_beyond_the_tolerance() {
        assert_eq!(
            Verdict::of(1.34, 1.33, 0.01),
            Verdict::Right,
            "to its last digit"
        );
        assert_eq!(Verdict::of(1.32, 1.33, 0.01), Verdict::Right);
        assert_eq!(Verdict::of(1.3401, 1.33, 0.01), Verdict::Close);
        assert_eq!(Verdict::of(1.43, 1.33, 0.01), Verdict::Close);
        assert_eq!(Verdict::of(1.4301, 1.33, 0.01), Verdict::NotYet);
        assert_eq!(Verdict::of(-1.33, 1.33, 0.01), Verdict::NotYet, "a sign");
    }

    #[test]
    fn html_is_found_and_arithmetic_is_not() {
        assert!(holds_html("Press <script>alert(1)</script>"));
        assert!(holds_html("<img src=x>"));
        assert!(holds_html("a <!-- comment -->"));
        assert!(!holds_html("when x < 2 and y<3, 1 <= t"));
    }

    #[test]
    fn a_slider_snaps_to_its_steps() {
        let slider = Slider {
            field: String::new(),
            min: 0.0,
            max: 1.0,
            step: 0.25,
        };
        assert!((slider.snap(0.3) - 0.25).abs() < 1e-15);
        assert!((slider.snap(7.0) - 1.0).abs() < 1e-15);
        assert!(slider.snap(-1.0).abs() < 1e-15);
        let tenths = Slider {
            step: 0.1,
            ..slider
        };
        assert_eq!(tenths.snap(0.59).to_bits(), 0.6_f64.to_bits());
    }
}
