//! File → Share link… and File → Open link…: the desktop makes the link the browser
//! build makes (the scene, lesson included, in the address's fragment, `share.rs`), to
//! the address where the class's browser build is served; and opens one that is pasted.
//! In the browser, File → Copy link puts the link in the address bar instead (`web.rs`).
//! Both are modal: the link is of the scene as it was when the window opened.

use egui::{Id, Modal, RichText, Ui};

use crate::files::Pending;
use crate::i18n::{Arg, tr, tr_with};
use crate::{App, share};

/// The link window: sharing the scene, or opening a pasted link.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LinkWindow {
    /// The scene's fragment, or why it has none (too large for a link).
    Share(Result<String, String>),
    /// The text pasted so far, and why it did not open.
    Open {
        text: String,
        problem: Option<String>,
    },
}

/// The longest part of a link shown in the window: a ball pit's runs to 40,000 characters.
const SHOWN: usize = 72;
/// The width of the fields, points.
const WIDTH: f32 = 420.0;

impl App {
    /// The address share links point to: the one the user set, or the default.
    pub fn web_address(&self) -> String {
        self.settings
            .web_address
            .clone()
            .filter(|a| !a.trim().is_empty())
            .unwrap_or_else(|| share::DEFAULT_ADDRESS.to_owned())
    }

    pub(crate) fn open_link_window(&mut self, share: bool) {
        // The scene as it would be saved, the document untouched: sharing is no edit.
        self.link = Some(if share {
            LinkWindow::Share(share::fragment(&self.laid_out()))
        } else {
            LinkWindow::Open {
                text: String::new(),
                problem: None,
            }
        });
    }

    /// Opens the scene `text` links to (after asking about unsaved changes).
    ///
    /// # Errors
    /// Why it opens nothing, in words ([`share::open`]).
    pub fn open_link(&mut self, text: &str) -> Result<(), String> {
        let scene = share::open(text)?;
        self.guard(Pending::Link(Box::new(scene)));
        Ok(())
    }

    pub(crate) fn link_window(&mut self, ui: &Ui) {
        let Some(mut window) = self.link.take() else {
            return;
        };
        let modal = Modal::new(Id::unique("link window")).show(ui.ctx(), |ui| {
            let done = match &mut window {
                LinkWindow::Share(fragment) => {
                    ui.heading(tr("link-share-title"));
                    self.share_ui(ui, fragment.as_deref().map_err(String::as_str))
                }
                LinkWindow::Open { text, problem } => {
                    ui.heading(tr("link-open-title"));
                    self.open_ui(ui, text, problem)
                }
            };
            ui.separator();
            done || ui.button(tr("file-cancel")).clicked()
        });
        if !(modal.inner || modal.should_close()) {
            self.link = Some(window);
        }
    }

    /// The address, the link and its Copy button; a scene too large for a link says so
    /// and offers Save as… instead. True once done.
    fn share_ui(&mut self, ui: &mut Ui, fragment: Result<&str, &str>) -> bool {
        let label = ui.label(tr("link-address"));
        let mut address = self.web_address();
        let field = ui
            .add(
                egui::TextEdit::singleline(&mut address)
                    .desired_width(WIDTH)
                    .hint_text(share::DEFAULT_ADDRESS),
            )
            .labelled_by(label.id);
        if field.changed() {
            self.settings.web_address = Some(address.clone());
        }
        if field.lost_focus() {
            self.keep_settings();
        }
        ui.label(RichText::new(tr("link-address-hint")).small());
        ui.add_space(6.0);
        match fragment {
            Ok(fragment) => {
                let link = share::join(&address, fragment);
                let shown: String = link.chars().take(SHOWN).collect();
                #[expect(clippy::cast_precision_loss, reason = "a count of characters")]
                let length = link.len() as f64;
                ui.label(RichText::new(format!("{shown}…")).monospace())
                    .on_hover_text(tr_with("link-length", &[("length", Arg::Number(length))]));
                if ui.button(tr("link-copy")).clicked() {
                    ui.ctx().copy_text(link);
                    self.tell(tr("link-copied"));
                    return true;
                }
            }
            Err(reason) => {
                ui.label(RichText::new(reason).color(ui.visuals().warn_fg_color));
                if ui.button(tr("menu-save-as")).clicked() {
                    self.perform(crate::Action::SaveAs);
                    return true;
                }
            }
        }
        false
    }

    /// The pasted link and Open (Enter too); true once the link opens.
    fn open_ui(&mut self, ui: &mut Ui, text: &mut String, problem: &mut Option<String>) -> bool {
        let label = ui.label(tr("link-paste"));
        let field = ui
            .add(
                egui::TextEdit::singleline(text)
                    .desired_width(WIDTH)
                    .hint_text(share::DEFAULT_ADDRESS.to_owned() + "#scene=…"),
            )
            .labelled_by(label.id);
        // The window's one field has the keys while it is empty: a paste goes there.
        if text.is_empty() && problem.is_none() && !field.has_focus() {
            field.request_focus();
        }
        let entered = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        if field.changed() {
            *problem = None;
        }
        if let Some(why) = problem {
            ui.label(RichText::new(why.as_str()).color(ui.visuals().error_fg_color));
        }
        let clicked = ui
            .add_enabled(!text.trim().is_empty(), egui::Button::new(tr("link-open")))
            .clicked();
        if (clicked || entered) && !text.trim().is_empty() {
            match self.open_link(text) {
                Ok(()) => return true,
                Err(why) => *problem = Some(why),
            }
        }
        false
    }
}
