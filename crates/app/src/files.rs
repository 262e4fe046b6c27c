//! Scene files in the app: New, Open, Save, Save As, the Examples menu, CSV export, and
//! the prompt before unsaved changes are lost. On the desktop the dialog is drawn by the
//! app itself (a folder, its files, a name), which works the same on every system,
//! including a headless one, and needs no desktop portal.

use egui::{Id, Modal, RichText, Ui};

use crate::i18n::{Arg, tr, tr_with};

/// What the file dialog is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Purpose {
    Open,
    Save,
    /// Export graph number N.
    ExportCsv(usize),
    /// Save the picture waiting in the app.
    ExportPng,
    /// Save the SVG figure waiting in the app.
    ExportSvg,
    /// Save the CSV table waiting in the app (an experiment series' results).
    ExportTable,
    /// Write the lesson's worksheet (with its answer key when `true`).
    ExportPdf(bool),
}

impl Purpose {
    /// The file types the dialog lists for this purpose (folders are always listed).
    fn extensions(self) -> &'static [&'static str] {
        match self {
            Self::Open | Self::Save => &["toml", "json"],
            Self::ExportCsv(_) | Self::ExportTable => &["csv"],
            Self::ExportPng => &["png"],
            Self::ExportSvg => &["svg"],
            Self::ExportPdf(_) => &["pdf"],
        }
    }
}

/// The file dialog's state.
#[derive(Clone, Debug)]
pub struct Dialog {
    pub purpose: Purpose,
    pub folder: String,
    pub name: String,
    /// Whether the file name has had the focus it gets when the dialog opens.
    focused: bool,
}

/// Something that would discard unsaved changes, waiting for the user's word.
#[derive(Clone, Debug, PartialEq)]
pub enum Pending {
    New,
    Open,
    Example(&'static str),
    /// A scene a pasted link carries.
    Link(Box<physics::Scene>),
    Quit,
}

/// The unsaved-changes prompt's buttons.
enum Answer {
    Save,
    Discard,
    Cancel,
}

/// What the user chose in a dialog this frame.
#[derive(Clone, Debug, PartialEq)]
pub enum Choice {
    /// Read or write this path for the dialog's purpose.
    Path(Purpose, String),
    /// Go ahead and discard the unsaved changes.
    Discard(Pending),
    /// Save the changes, then go ahead.
    SaveThen(Pending),
    /// Save over this file although it changed on disk.
    Overwrite(String),
    /// Bring back the work an earlier session left unsaved.
    #[cfg(not(target_arch = "wasm32"))]
    Recover(Box<crate::autosave::Recovered>),
    /// Throw that work away.
    #[cfg(not(target_arch = "wasm32"))]
    DropRecovery,
}

#[derive(Default)]
pub struct Files {
    pub dialog: Option<Dialog>,
    pub confirm: Option<Pending>,
    /// A message to show (a file that failed to load, a save that failed).
    pub message: Option<String>,
    /// A file that changed on disk, waiting for the word to overwrite it.
    pub overwrite: Option<String>,
    /// Work an earlier session left unsaved, waiting for the word to recover it.
    #[cfg(not(target_arch = "wasm32"))]
    pub recover: Option<crate::autosave::Recovered>,
}

impl Files {
    /// Whether a file dialog or the overwrite prompt is waiting for the user.
    pub fn is_asking(&self) -> bool {
        self.dialog.is_some() || self.overwrite.is_some()
    }

    /// Opens the dialog for `purpose`, starting in the folder of `current`.
    pub fn ask(&mut self, purpose: Purpose, current: Option<&str>, suggested: &str) {
        #[cfg(not(target_arch = "wasm32"))]
        let folder = current
            .and_then(|p| {
                std::path::Path::new(p)
                    .parent()
                    .map(|f| f.to_string_lossy().into_owned())
            })
            .filter(|f| !f.is_empty())
            .unwrap_or_else(crate::platform::current_folder);
        #[cfg(target_arch = "wasm32")]
        let folder = String::new();
        let name = current.map_or_else(
            || suggested.to_owned(),
            |p| p.rsplit(['/', '\\']).next().unwrap_or(p).to_owned(),
        );
        self.dialog = Some(Dialog {
            focused: false,
            purpose,
            folder,
            name,
        });
    }

    /// Shows whatever dialog is open; returns what the user chose.
    #[expect(
        clippy::too_many_lines,
        reason = "three dialogs, each laid out in order"
    )]
    pub fn ui(&mut self, ui: &mut Ui, title: &str) -> Option<Choice> {
        let mut choice = None;
        if let Some(message) = self.message.clone() {
            // However long the message (a CSV opened as a scene gives one line per line),
            // the box fits the window and its OK button stays on screen.
            let height = (ui.ctx().content_rect().height() * 0.6).max(120.0);
            let modal = Modal::new(Id::unique("file message")).show(ui.ctx(), |ui| {
                ui.set_max_width(640.0);
                ui.heading("NewtonLab");
                egui::ScrollArea::vertical()
                    .max_height(height)
                    .show(ui, |ui| ui.label(RichText::new(message).monospace()));
                let ok = ui.button(tr("file-ok")).on_hover_text(tr("file-ok-hint"));
                ok.clicked() || ui.input(|i| i.key_pressed(egui::Key::Enter))
            });
            if modal.inner || modal.should_close() {
                self.message = None;
            }
        }
        if let Some(path) = self.overwrite.clone() {
            let answer = two_buttons(
                ui,
                &tr("file-changed-title"),
                &tr_with("file-changed-body", &[("path", Arg::Text(&path))]),
                (&tr("file-overwrite"), &tr("file-overwrite-hint")),
                (&tr("file-cancel"), &tr("file-keep-hint")),
            );
            if let Some(overwrite) = answer {
                self.overwrite = None;
                if overwrite {
                    choice = Some(Choice::Overwrite(path));
                }
            }
        }
        #[cfg(not(target_arch = "wasm32"))]
        if let Some(recovered) = self.recover.clone() {
            let body = recovered.path.as_deref().map_or_else(
                || tr("file-recover-body"),
                |p| tr_with("file-recover-body-path", &[("path", Arg::Text(p))]),
            );
            let answer = two_buttons(
                ui,
                &tr("file-recover-title"),
                &body,
                (&tr("file-recover"), &tr("file-recover-hint")),
                (&tr("file-discard"), &tr("file-discard-hint")),
            );
            if let Some(recover) = answer {
                self.recover = None;
                choice = Some(if recover {
                    Choice::Recover(Box::new(recovered))
                } else {
                    Choice::DropRecovery
                });
            }
        }
        if let Some(pending) = self.confirm.clone() {
            let modal = Modal::new(Id::unique("confirm-discard")).show(ui.ctx(), |ui| {
                ui.heading(tr("file-unsaved-title"));
                ui.label(tr_with("file-unsaved-body", &[("title", Arg::Text(title))]));
                ui.horizontal(|ui| {
                    if ui
                        .button(tr("file-save-changes"))
                        .on_hover_text(tr("file-save-changes-hint"))
                        .clicked()
                    {
                        return Some(Answer::Save);
                    }
                    if ui
                        .button(tr("file-discard-changes"))
                        .on_hover_text(tr("file-discard-changes-hint"))
                        .clicked()
                    {
                        return Some(Answer::Discard);
                    }
                    if ui
                        .button(tr("file-cancel"))
                        .on_hover_text(tr("file-keep-editing-hint"))
                        .clicked()
                    {
                        return Some(Answer::Cancel);
                    }
                    None
                })
                .inner
            });
            match modal.inner {
                Some(Answer::Save) => {
                    self.confirm = None;
                    choice = Some(Choice::SaveThen(pending));
                }
                Some(Answer::Discard) => {
                    self.confirm = None;
                    choice = Some(Choice::Discard(pending));
                }
                Some(Answer::Cancel) => self.confirm = None,
                None if modal.should_close() => self.confirm = None,
                None => {}
            }
        }
        if let Some(dialog) = &mut self.dialog {
            let mut close = false;
            let verb = tr(match dialog.purpose {
                Purpose::Open => "file-verb-open",
                Purpose::Save => "file-verb-save",
                Purpose::ExportCsv(_)
                | Purpose::ExportTable
                | Purpose::ExportPng
                | Purpose::ExportSvg
                | Purpose::ExportPdf(_) => "file-verb-export",
            });
            let extensions = dialog.purpose.extensions();
            Modal::new(Id::unique("file dialog")).show(ui.ctx(), |ui| {
                ui.set_min_width(460.0);
                ui.heading(tr(match dialog.purpose {
                    Purpose::Open => "file-title-open",
                    Purpose::Save => "file-title-save",
                    Purpose::ExportCsv(_) | Purpose::ExportTable => "file-title-csv",
                    Purpose::ExportPng => "file-title-png",
                    Purpose::ExportSvg => "file-title-svg",
                    Purpose::ExportPdf(_) => "file-title-pdf",
                }));
                ui.horizontal(|ui| {
                    let label = ui.label(tr("file-folder"));
                    ui.add(egui::TextEdit::singleline(&mut dialog.folder).desired_width(360.0))
                        .labelled_by(label.id)
                        .on_hover_text(tr("file-folder-hint"));
                });
                // A file double-clicked in the list is chosen at once.
                #[cfg(target_arch = "wasm32")]
                let chosen_now = false;
                #[cfg(not(target_arch = "wasm32"))]
                let chosen_now = egui::ScrollArea::vertical()
                    .max_height(220.0)
                    .show(ui, |ui| {
                        let mut chosen_now = false;
                        if ui
                            .small_button(tr("file-parent"))
                            .on_hover_text(tr("file-parent-hint"))
                            .clicked()
                            && let Some(parent) = std::path::Path::new(&dialog.folder).parent()
                        {
                            dialog.folder = parent.to_string_lossy().into_owned();
                        }
                        let listed = crate::platform::list_folder(&dialog.folder)
                            .into_iter()
                            .filter(|(name, is_folder)| {
                                *is_folder
                                    || std::path::Path::new(name).extension().is_some_and(|e| {
                                        extensions.iter().any(|x| e.eq_ignore_ascii_case(x))
                                    })
                            });
                        for (name, is_folder) in listed {
                            let shown = if is_folder {
                                format!("{name}/")
                            } else {
                                name.clone()
                            };
                            let entry = ui.selectable_label(dialog.name == name, shown);
                            if entry.double_clicked() && !is_folder {
                                dialog.name.clone_from(&name);
                                chosen_now = true;
                            } else if entry.clicked() {
                                if is_folder {
                                    dialog.folder = std::path::Path::new(&dialog.folder)
                                        .join(&name)
                                        .to_string_lossy()
                                        .into_owned();
                                } else {
                                    dialog.name = name;
                                }
                            }
                        }
                        chosen_now
                    })
                    .inner;
                let mut submit = chosen_now;
                ui.horizontal(|ui| {
                    let label = ui.label(tr("file-name"));
                    let field = ui
                        .add(egui::TextEdit::singleline(&mut dialog.name).desired_width(300.0))
                        .labelled_by(label.id)
                        .on_hover_text(tr_with(
                            "file-name-hint",
                            &[("extensions", Arg::Text(&extensions.join(", ")))],
                        ));
                    // The name is what a user types first: it has the focus on opening.
                    if !dialog.focused {
                        field.request_focus();
                        dialog.focused = true;
                    }
                    submit |= field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
                });
                ui.horizontal(|ui| {
                    submit |= ui
                        .button(&verb)
                        .on_hover_text(tr_with("file-submit-hint", &[("verb", Arg::Text(&verb))]))
                        .clicked();
                    if submit && !dialog.name.trim().is_empty() {
                        let path = if dialog.folder.is_empty() {
                            dialog.name.trim().to_owned()
                        } else {
                            std::path::Path::new(&dialog.folder)
                                .join(dialog.name.trim())
                                .to_string_lossy()
                                .into_owned()
                        };
                        choice = Some(Choice::Path(dialog.purpose, path));
                        close = true;
                    }
                    if ui
                        .button(tr("file-cancel"))
                        .on_hover_text(tr("file-close-hint"))
                        .clicked()
                    {
                        close = true;
                    }
                });
            });
            if close {
                self.dialog = None;
            }
        }
        choice
    }
}

/// A question with two answers in a modal: `Some(true)` for the first, `Some(false)` for
/// the second or Esc, `None` while unanswered.
fn two_buttons(
    ui: &Ui,
    heading: &str,
    question: &str,
    yes: (&str, &str),
    no: (&str, &str),
) -> Option<bool> {
    let modal = Modal::new(Id::unique(("question", heading))).show(ui.ctx(), |ui| {
        ui.set_max_width(520.0);
        ui.heading(heading);
        ui.label(question);
        ui.horizontal(|ui| {
            if ui.button(yes.0).on_hover_text(yes.1).clicked() {
                return Some(true);
            }
            if ui.button(no.0).on_hover_text(no.1).clicked() {
                return Some(false);
            }
            None
        })
        .inner
    });
    modal
        .inner
        .or_else(|| modal.should_close().then_some(false))
}
