//! The list of keys (F1): every shortcut, from the one table in `action.rs`, and the
//! canvas's own keys (`canvas/keyboard.rs`).

use egui::{Context, Grid, RichText};

use crate::action::SHORTCUTS;

/// The canvas's keys while it has the focus, as the list shows them.
const CANVAS_KEYS: &[(&str, &str)] = &[
    ("Tab (or a click)", "Give the canvas the keyboard"),
    ("Tab / Shift+Tab", "Select the next / previous object"),
    (
        "Arrow keys",
        "Move the selected particle or ramp one grid step",
    ),
    ("Shift+arrow keys", "Move it a tenth of a grid step"),
    (
        "Enter",
        "Add the current tool's object at the view's centre (a spring, rod or string from the selected particle)",
    ),
    (
        "Escape",
        "Give the keyboard back; Tab then moves to the next control",
    ),
];

/// Shows the list while `shown`; its close button clears it.
pub fn window(ctx: &Context, shown: &mut bool) {
    egui::Window::new("Keys")
        .open(shown)
        .resizable(false)
        .collapsible(false)
        .show(ctx, |ui| {
            ui.label(RichText::new("Everywhere (except while typing in a field)").strong());
            Grid::new("shortcuts").striped(true).show(ui, |ui| {
                for (shortcut, action) in SHORTCUTS {
                    ui.label(RichText::new(ctx.format_shortcut(shortcut)).monospace());
                    ui.label(action.describe());
                    ui.end_row();
                }
            });
            ui.separator();
            ui.label(RichText::new("On the canvas").strong());
            Grid::new("canvas keys").striped(true).show(ui, |ui| {
                for (keys, what) in CANVAS_KEYS {
                    ui.label(RichText::new(*keys).monospace());
                    ui.label(*what);
                    ui.end_row();
                }
            });
            ui.separator();
            ui.label(
                "Tab and Shift+Tab move between the controls; Enter or Space presses a button; \
                 the menus open with a click or, once focused, with Enter.",
            );
        });
}
