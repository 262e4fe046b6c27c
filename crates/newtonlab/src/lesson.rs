//! `newtonlab lesson`: a scene's lesson on the command line. With `--answer ID=VALUE`,
//! each answer is checked against what the scene measures (`ID: right`, `ID: close` or
//! `ID: not yet`); with `--worksheet FILE.pdf [--key]`, the worksheet is written (with the
//! answer key after it); with neither, the questions are listed.

use newtonlab_i18n::tr_text as say;
use physics::{Lesson, Verdict};

use crate::{Failure, scene_source};

#[derive(Debug, clap::Args)]
pub(crate) struct LessonArgs {
    /// A scene file with a `[lesson]` (.toml or .json), or example:NAME.
    scene: String,
    /// ID=VALUE: a student's answer to the question ID, with a unit of the question's kind
    /// (`disc_time="1.34 s"`, `range="201 cm"`). Repeatable; each is checked against the
    /// scene's own run.
    #[arg(long, value_name = "ID=VALUE", allow_hyphen_values = true)]
    answer: Vec<String>,
    /// Write the lesson's worksheet to print (PDF, A4): its title, instructions, a picture
    /// of the scene and its questions with lines for the answers.
    #[arg(long, value_name = "FILE.pdf")]
    worksheet: Option<String>,
    /// With --worksheet: add the answer key (the simulation's value of every question) on
    /// a page of its own after the worksheet.
    #[arg(long, requires = "worksheet")]
    key: bool,
}

pub(crate) fn lesson(args: &LessonArgs) -> Result<(), Failure> {
    let scene = scene_source::load(&args.scene)?;
    let lesson = scene.lesson.as_ref().ok_or_else(|| {
        Failure::Input(say("cli-lesson-none", &[("source", args.scene.as_str())]))
    })?;
    if let Some(path) = &args.worksheet {
        let bytes = newtonlab_app::worksheet::pdf(&scene, args.key).map_err(Failure::Simulation)?;
        std::fs::write(path, bytes).map_err(|error| {
            let words = [("path", path.as_str()), ("error", &error.to_string())];
            Failure::Input(say("cli-cannot-create", &words))
        })?;
    }
    if args.answer.is_empty() {
        if args.worksheet.is_none() {
            list(lesson);
        }
        return Ok(());
    }
    // Every answer is read before the run: a typing mistake is told at once.
    let answers = args
        .answer
        .iter()
        .map(|text| read_answer(lesson, text))
        .collect::<Result<Vec<_>, _>>()?;
    let measured = lesson
        .answers(&scene)
        .map_err(|why| Failure::Simulation(why.to_string()))?;
    for (index, value) in answers {
        let question = &lesson.questions[index];
        let verdict = match &measured[index] {
            Ok(measured) => Verdict::of(value, *measured, question.tolerance),
            Err(why) => {
                let why = why.to_string();
                let words = [("id", question.id.as_str()), ("why", why.as_str())];
                return Err(Failure::Simulation(say("cli-lesson-unmeasured", &words)));
            }
        };
        out!("{}: {}", question.id, verdict.as_str());
    }
    Ok(())
}

/// Each question's id, unit and prompt.
fn list(lesson: &Lesson) {
    out!("{}", lesson.title);
    for question in &lesson.questions {
        out!("{} [{}]: {}", question.id, question.unit, question.prompt);
    }
}

/// `ID=VALUE`: the question's index and the value in its unit.
fn read_answer(lesson: &Lesson, text: &str) -> Result<(usize, f64), Failure> {
    let first = lesson.questions.first().map_or("ID", |q| q.id.as_str());
    let bad = |id: &str| {
        Failure::Input(say(
            id,
            &[
                ("text", text),
                ("first", first),
                ("ids", &ids(lesson)),
                ("count", &lesson.questions.len().to_string()),
            ],
        ))
    };
    let (id, value) = text
        .split_once('=')
        .ok_or_else(|| bad("cli-lesson-answer-malformed"))?;
    let id = id.trim();
    let index = lesson
        .questions
        .iter()
        .position(|q| q.id == id)
        .ok_or_else(|| bad("cli-lesson-unknown-id"))?;
    let question = &lesson.questions[index];
    let value = question.read_answer(value).map_err(|why| {
        Failure::Input(say(
            "cli-lesson-answer-unreadable",
            &[("id", id), ("unit", &question.unit), ("why", &why)],
        ))
    })?;
    Ok((index, value))
}

fn ids(lesson: &Lesson) -> String {
    let ids: Vec<&str> = lesson.questions.iter().map(|q| q.id.as_str()).collect();
    ids.join(", ")
}
