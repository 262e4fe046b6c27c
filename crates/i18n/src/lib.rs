//! Every word `NewtonLab` says to its user — the app's, the command line's and the scene
//! checker's — in the user's language: English, German and Spanish, with
//! [Project Fluent](https://projectfluent.org) (`fluent-bundle`). The messages live in
//! `i18n/<language>/newtonlab.ftl` at the top of the repository, compiled in.
//!
//! [`tr`] gives a message by its id in the current language, [`tr_with`] with arguments
//! (`{ $ratio }`); a message missing from a language falls back to English, and an id
//! missing from English shows as itself, so nothing the app shows is ever blank. The
//! language is per thread (the app's is the UI thread's), so tests on parallel threads
//! each keep their own; the app starts in the system's language and switches live from
//! the View menu; the command line takes `--lang` or the system's.
//!
//! Numbers in files and CSV keep a decimal point in every language; only the screen
//! follows the language's convention ([`decimal_comma`]).
//!
//! To add a language: copy `i18n/en/newtonlab.ftl` to `i18n/<code>/newtonlab.ftl`,
//! translate every message, add it to [`Language`] and to [`SOURCES`]; the test
//! `every_language_has_every_message` fails until no message is missing.

use std::cell::Cell;
use std::sync::OnceLock;

use fluent_bundle::concurrent::FluentBundle;
use fluent_bundle::{FluentArgs, FluentResource, FluentValue};

/// A language of the app.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Language {
    /// `en`, the language every message is written in first.
    English,
    /// `de`.
    German,
    /// `es`.
    Spanish,
}

impl Language {
    /// Every language, in the menu's order.
    pub const ALL: [Self; 3] = [Self::English, Self::German, Self::Spanish];

    /// The language's code: `en`, `de`, `es`.
    pub fn code(self) -> &'static str {
        match self {
            Self::English => "en",
            Self::German => "de",
            Self::Spanish => "es",
        }
    }

    /// The language's name in itself, as the menu lists it.
    pub fn name(self) -> &'static str {
        match self {
            Self::English => "English",
            Self::German => "Deutsch",
            Self::Spanish => "Español",
        }
    }

    /// The language of a locale such as `de-AT`, `es_ES.UTF-8` or `en`, if the app has it.
    pub fn from_locale(locale: &str) -> Option<Self> {
        let code = locale
            .split(['-', '_', '.'])
            .next()
            .unwrap_or_default()
            .to_ascii_lowercase();
        Self::ALL.into_iter().find(|l| l.code() == code)
    }

    /// The system's language (`LANG`, the desktop's setting, the browser's), or English.
    pub fn of_system() -> Self {
        sys_locale::get_locale()
            .as_deref()
            .and_then(Self::from_locale)
            .unwrap_or(Self::English)
    }

    fn index(self) -> usize {
        match self {
            Self::English => 0,
            Self::German => 1,
            Self::Spanish => 2,
        }
    }
}

/// The message files: English, German, Spanish (the order of [`Language::ALL`]).
pub const SOURCES: [&str; 3] = [
    include_str!("../../../i18n/en/newtonlab.ftl"),
    include_str!("../../../i18n/de/newtonlab.ftl"),
    include_str!("../../../i18n/es/newtonlab.ftl"),
];

thread_local! {
    static CURRENT: Cell<Language> = const { Cell::new(Language::English) };
}

/// The language the app speaks on this thread.
pub fn language() -> Language {
    CURRENT.with(Cell::get)
}

/// Switches this thread's language: every string drawn from the next frame on.
pub fn set_language(language: Language) {
    CURRENT.with(|c| c.set(language));
}

/// Whether the language writes a decimal comma (German, Spanish) on screen.
pub fn decimal_comma() -> bool {
    language() != Language::English
}

/// `x` with `decimals` digits after the separator this language writes on screen: a
/// point in English, a comma in German and Spanish.
pub fn decimal(x: f64, decimals: usize) -> String {
    let text = format!("{x:.decimals$}");
    if decimal_comma() {
        text.replace('.', ",")
    } else {
        text
    }
}

/// The bundles, parsed once. A file that fails to parse keeps what parsed (the test
/// `every_file_parses` holds them to no error).
fn bundles() -> &'static [FluentBundle<FluentResource>; 3] {
    static BUNDLES: OnceLock<[FluentBundle<FluentResource>; 3]> = OnceLock::new();
    BUNDLES.get_or_init(|| {
        Language::ALL.map(|language| {
            let id = language.code().parse().unwrap_or_default();
            let mut bundle = FluentBundle::new_concurrent(vec![id]);
            // No Unicode isolation marks around arguments: egui's fonts draw them as
            // boxes, and labels would not match what tests look for.
            bundle.set_use_isolating(false);
            let resource = FluentResource::try_new(SOURCES[language.index()].to_owned())
                .unwrap_or_else(|(partial, _)| partial);
            // Duplicate ids keep the first; the key test reports them.
            let _ = bundle.add_resource(resource);
            bundle
        })
    })
}

/// The message `id` in `language` with `args`, if that language has it.
fn format(language: Language, id: &str, args: Option<&FluentArgs<'_>>) -> Option<String> {
    let bundle = &bundles()[language.index()];
    let pattern = bundle.get_message(id)?.value()?;
    let mut errors = Vec::new();
    Some(
        bundle
            .format_pattern(pattern, args, &mut errors)
            .into_owned(),
    )
}

/// The message `id` in the current language (English if it lacks it; `id` itself if
/// English does too).
pub fn tr(id: &str) -> String {
    tr_args(id, None)
}

/// [`tr`] with named arguments: numbers or text.
pub fn tr_with(id: &str, args: &[(&str, Arg<'_>)]) -> String {
    let mut fluent = FluentArgs::new();
    for (name, value) in args {
        match value {
            Arg::Number(x) => fluent.set(*name, FluentValue::from(*x)),
            Arg::Text(s) => fluent.set(*name, FluentValue::from(*s)),
        }
    }
    tr_args(id, Some(&fluent))
}

/// Whether English has the message `id` (every language then has it: a test holds
/// them equal).
pub fn has(id: &str) -> bool {
    bundles()[Language::English.index()].has_message(id)
}

/// [`tr_with`] with every argument given as text: numbers written by the caller, as
/// the files and the command line write them.
pub fn tr_text(id: &str, args: &[(&str, &str)]) -> String {
    let args: Vec<(&str, Arg<'_>)> = args
        .iter()
        .map(|&(name, text)| (name, Arg::Text(text)))
        .collect();
    tr_with(id, &args)
}

/// A message argument.
#[derive(Clone, Copy, Debug)]
pub enum Arg<'a> {
    /// A number, written as Fluent writes numbers.
    Number(f64),
    /// Text, as it is.
    Text(&'a str),
}

fn tr_args(id: &str, args: Option<&FluentArgs<'_>>) -> String {
    format(language(), id, args)
        .or_else(|| format(Language::English, id, args))
        .unwrap_or_else(|| id.to_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The message ids of a file, in order.
    fn ids(source: &str) -> Vec<String> {
        source
            .lines()
            .filter_map(|line| {
                let (id, _) = line.split_once(" =")?;
                let first = id.chars().next()?;
                (first.is_ascii_alphabetic() && !id.contains(' ')).then(|| id.to_owned())
            })
            .collect()
    }

    #[test]
    fn every_file_parses() {
        for (language, source) in Language::ALL.iter().zip(SOURCES) {
            if let Err((_, errors)) = FluentResource::try_new(source.to_owned()) {
                panic!("{}: {errors:?}", language.code());
            }
        }
    }

    /// Every language has exactly English's messages: none missing, none extra, none twice.
    #[test]
    fn every_language_has_every_message() {
        let english = ids(SOURCES[0]);
        let mut sorted = english.clone();
        sorted.sort();
        sorted.dedup();
        assert_eq!(sorted.len(), english.len(), "an id twice in English");
        for (language, source) in Language::ALL.iter().zip(SOURCES).skip(1) {
            let mut theirs = ids(source);
            theirs.sort();
            let missing: Vec<_> = sorted.iter().filter(|id| !theirs.contains(id)).collect();
            let extra: Vec<_> = theirs.iter().filter(|id| !sorted.contains(id)).collect();
            assert!(
                missing.is_empty() && extra.is_empty() && theirs.len() == sorted.len(),
                "{}: missing {missing:?}, extra {extra:?}",
                language.code()
            );
        }
    }

    #[test]
    fn messages_switch_with_the_language_and_fall_back_to_english() {
        set_language(Language::German);
        assert_eq!(tr("menu-file"), "Datei");
        set_language(Language::Spanish);
        assert_eq!(tr("menu-file"), "Archivo");
        assert_eq!(tr("no-such-message"), "no-such-message");
        set_language(Language::English);
        assert_eq!(tr("menu-file"), "File");
        assert_eq!(
            tr_with(
                "status-behind",
                &[("ratio", Arg::Text("0.6")), ("real", Arg::Text("0.3"))]
            ),
            "running at 0.6× of the requested speed (0.3× real time)"
        );
        assert_eq!(decimal(0.25, 2), "0.25");
        set_language(Language::German);
        assert_eq!(decimal(0.25, 2), "0,25", "a decimal comma on screen");
        set_language(Language::English);
    }

    #[test]
    fn locales_name_their_language() {
        assert_eq!(Language::from_locale("de-AT"), Some(Language::German));
        assert_eq!(
            Language::from_locale("es_ES.UTF-8"),
            Some(Language::Spanish)
        );
        assert_eq!(Language::from_locale("en"), Some(Language::English));
        assert_eq!(Language::from_locale("fr-FR"), None);
        assert_eq!(Language::from_locale("C"), None);
    }
}
