//! The list of keys (F1): every shortcut, from the one table in `action.rs`, and the
//! canvas's own keys (`canvas/keyboard.rs`).

use egui::{Context, Grid, RichText};

use crate::action::SHORTCUTS;
use crate::i18n::tr;

/// The canvas's keys while it has the focus, as the list shows them: the keys, and the
/// message saying what they do.
const CANVAS_KEYS: &[(&str, &str)] = &[
    ("Tab", "canvas-key-focus"),
    ("Tab / Shift+Tab", "canvas-key-cycle"),
    ("← ↑ → ↓", "canvas-key-move"),
    ("Shift+← ↑ → ↓", "canvas-key-fine"),
    ("Enter", "canvas-key-enter"),
    ("Escape", "canvas-key-escape"),
    ("M / A + Enter", "canvas-key-instrument-enter"),
    ("M / A + Tab", "canvas-key-instrument-tab"),
    ("P / M / A + ← ↑ → ↓", "canvas-key-instrument-move"),
];

/// Shows the list while `shown`; its close button clears it.
pub fn window(ctx: &Context, shown: &mut bool) {
    // Never taller than the screen: the list scrolls within the window.
    let height = (ctx.content_rect().height() - 80.0).max(200.0);
    egui::Window::new(tr("keys-title"))
        .open(shown)
        .resizable(false)
        .collapsible(false)
        .max_height(height)
        .show(ctx, |ui| {
            egui::ScrollArea::vertical()
                .max_height(height)
                .show(ui, |ui| {
                    ui.label(RichText::new(tr("keys-everywhere")).strong());
                    Grid::new("shortcuts").striped(true).show(ui, |ui| {
                        for (shortcut, action) in SHORTCUTS {
                            ui.label(RichText::new(ctx.format_shortcut(shortcut)).monospace());
                            ui.label(action.describe());
                            ui.end_row();
                        }
                    });
                    ui.separator();
                    ui.label(RichText::new(tr("keys-canvas")).strong());
                    Grid::new("canvas keys").striped(true).show(ui, |ui| {
                        for (keys, what) in CANVAS_KEYS {
                            ui.label(RichText::new(*keys).monospace());
                            ui.label(tr(what));
                            ui.end_row();
                        }
                    });
                    ui.separator();
                    ui.label(tr("keys-controls"));
                });
        });
}
