//! Everything the user can ask the app to do, as one enum. The menus, the tool bar, the
//! keyboard shortcuts and the panels all emit an [`Action`]; `App::perform` carries each
//! out in one place. A shortcut is defined once, here, and the menus show it.

use egui::{Key, KeyboardShortcut, Modifiers};

use crate::canvas::{FieldKind, Instrument, Tool};
use crate::picture::Subject;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    New,
    Open,
    Save,
    SaveAs,
    /// Export graph number N as CSV.
    ExportGraph(usize),
    /// Save a picture of the canvas or a graph as PNG.
    ExportPicture(Subject),
    /// Save graph number N as a figure to print (PNG or SVG).
    ExportFigure(usize, crate::picture::Format),
    /// The lesson's worksheet as a PDF; with the answer key (`true`) after it.
    ExportWorksheet(bool),
    /// Run experiment series number N.
    RunExperiment(usize),
    /// Export experiment series number N's results: CSV (`None`) or a figure.
    ExportExperiment(usize, Option<crate::picture::Format>),
    Example(&'static str),
    Quit,
    Undo,
    Redo,
    Delete,
    /// The selected object (with the particles a link ties) to the clipboard, as
    /// scene-file text.
    Copy,
    /// Copy, then delete.
    Cut,
    /// What was last copied in the app, pasted beside where it was.
    Paste,
    /// The selected object copied and pasted at once, beside itself.
    Duplicate,
    PlayPause,
    Step,
    Reset,
    Fit,
    Tool(Tool),
    /// Show or hide the inspector panel.
    ToggleInspector,
    /// Show or hide the graph panel.
    ToggleGraphs,
    /// Shows or hides the lesson panel.
    ToggleLesson,
    /// Full canvas with large text, for a projector.
    ToggleProjector,
    /// Take up or put away a measuring instrument.
    Instrument(Instrument),
    /// Draw a field as arrows, or none.
    FieldView(Option<FieldKind>),
    /// Take away the tape, the probe and the protractor.
    ClearMeasurements,
    /// Show the scene's share link to the browser build (desktop).
    ShareLink,
    /// Open a scene from a pasted link.
    OpenLink,
    /// Show or hide the stopwatch.
    ToggleStopwatch,
    /// One time step back in the run.
    StepBack,
    /// Show this step of the run.
    GoTo(u64),
    /// Show the selected particle's next (`true`) or previous turning point.
    TurningPoint(bool),
    /// Show the run's next (`true`) or previous impact.
    Impact(bool),
    /// Show the run at the instant of its impact number N (in the recording's list).
    GoToImpact(usize),
    /// Forget the earlier runs the graphs draw behind the last.
    ForgetEarlierRuns,
    /// Make the moment shown the scene's start.
    EditFromHere,
    /// Show or hide the list of keys (F1).
    ToggleHelp,
    /// The keyboard focus to the next region of the window (F6).
    NextRegion,
    /// The keyboard focus to the previous region (Shift+F6).
    PreviousRegion,
    /// Show or hide the Getting started page.
    ToggleGettingStarted,
}

const fn command(key: Key) -> KeyboardShortcut {
    KeyboardShortcut::new(Modifiers::COMMAND, key)
}

const fn command_shift(key: Key) -> KeyboardShortcut {
    KeyboardShortcut::new(Modifiers::COMMAND.plus(Modifiers::SHIFT), key)
}

const fn plain(key: Key) -> KeyboardShortcut {
    KeyboardShortcut::new(Modifiers::NONE, key)
}

/// Every shortcut, most specific first (Ctrl+Shift+S before Ctrl+S). The plain keys are
/// ignored while a text field has the keyboard.
pub const SHORTCUTS: &[(KeyboardShortcut, Action)] = &[
    (command_shift(Key::Z), Action::Redo),
    (command(Key::Y), Action::Redo),
    (command(Key::Z), Action::Undo),
    (command_shift(Key::S), Action::SaveAs),
    (command(Key::S), Action::Save),
    (command(Key::O), Action::Open),
    (command(Key::N), Action::New),
    (plain(Key::Space), Action::PlayPause),
    (plain(Key::Period), Action::Step),
    (plain(Key::Comma), Action::StepBack),
    (plain(Key::CloseBracket), Action::TurningPoint(true)),
    (plain(Key::OpenBracket), Action::TurningPoint(false)),
    (plain(Key::R), Action::Reset),
    (plain(Key::F), Action::Fit),
    (plain(Key::Num1), Action::Tool(Tool::Select)),
    (plain(Key::Num2), Action::Tool(Tool::Particle)),
    (plain(Key::Num3), Action::Tool(Tool::Spring)),
    (plain(Key::Num4), Action::Tool(Tool::Ramp)),
    (plain(Key::Num5), Action::Tool(Tool::Rod)),
    (plain(Key::Num6), Action::Tool(Tool::String)),
    (plain(Key::Num7), Action::Tool(Tool::Box)),
    (plain(Key::Num8), Action::Tool(Tool::Polygon)),
    (plain(Key::M), Action::Instrument(Instrument::Tape)),
    (plain(Key::P), Action::Instrument(Instrument::Probe)),
    (plain(Key::T), Action::ToggleStopwatch),
    (plain(Key::A), Action::Instrument(Instrument::Protractor)),
    (command(Key::D), Action::Duplicate),
    (plain(Key::Delete), Action::Delete),
    (plain(Key::Backspace), Action::Delete),
    (plain(Key::F9), Action::ToggleInspector),
    (plain(Key::F10), Action::ToggleGraphs),
    (plain(Key::F8), Action::ToggleLesson),
    (plain(Key::F11), Action::ToggleProjector),
    (plain(Key::F1), Action::ToggleHelp),
    // Shift+F6 first: a shortcut without Shift also matches with it.
    (
        KeyboardShortcut::new(Modifiers::SHIFT, Key::F6),
        Action::PreviousRegion,
    ),
    (plain(Key::F6), Action::NextRegion),
];

impl Action {
    /// The first shortcut that does this.
    pub fn shortcut(self) -> Option<KeyboardShortcut> {
        SHORTCUTS.iter().find(|(_, a)| *a == self).map(|(s, _)| *s)
    }

    /// The shortcut as the menus show it ("Ctrl+S"), or "".
    pub fn shortcut_text(self, ctx: &egui::Context) -> String {
        self.shortcut()
            .map(|s| ctx.format_shortcut(&s))
            .unwrap_or_default()
    }

    /// What a shortcut's action does, for the list of keys (F1), in the app's language.
    pub fn describe(self) -> String {
        let id = match self {
            Self::New => "key-new",
            Self::Open => "key-open",
            Self::Save => "key-save",
            Self::SaveAs => "key-save-as",
            Self::Undo => "key-undo",
            Self::Redo => "key-redo",
            Self::Delete => "key-delete",
            Self::Duplicate => "key-duplicate",
            Self::PlayPause => "key-play-pause",
            Self::Step => "key-step",
            Self::StepBack => "key-step-back",
            Self::TurningPoint(true) => "key-next-turn",
            Self::TurningPoint(false) => "key-previous-turn",
            Self::Reset => "key-reset",
            Self::Fit => "key-fit",
            Self::Tool(tool) => return tool.label(),
            Self::Instrument(instrument) => return instrument.label(),
            Self::ToggleStopwatch => "key-stopwatch",
            Self::ToggleInspector => "key-inspector",
            Self::ToggleGraphs => "key-graphs",
            Self::ToggleLesson => "key-lesson",
            Self::ToggleProjector => "key-projector",
            Self::ToggleHelp => "key-help",
            Self::NextRegion => "key-next-region",
            Self::PreviousRegion => "key-previous-region",
            _ => return String::new(),
        };
        crate::i18n::tr(id)
    }

    /// Whether the shortcut is a bare key, which a focused text field must keep.
    pub fn is_plain(shortcut: &KeyboardShortcut) -> bool {
        // A function key types nothing: F6 leaves a field for the next region.
        let function = matches!(
            shortcut.logical_key,
            Key::F1 | Key::F6 | Key::F8 | Key::F9 | Key::F10 | Key::F11
        );
        shortcut.modifiers.is_none() && !function
    }
}
