//! Help: the Getting started page (three guided tasks, open on the first run) and the
//! list of keys (F1): every shortcut, from the one table in `action.rs`, and the
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
    ("Shift+click", "canvas-key-add"),
    ("Shift+drag", "canvas-key-box"),
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

/// The Getting started page's tasks: each a title and its steps, as messages.
const TASKS: &[(&str, &[&str])] = &[
    (
        "start-place",
        &[
            "start-place-1",
            "start-place-2",
            "start-place-3",
            "start-place-4",
        ],
    ),
    (
        "start-measure",
        &["start-measure-1", "start-measure-2", "start-measure-3"],
    ),
    (
        "start-graph",
        &["start-graph-1", "start-graph-2", "start-graph-3"],
    ),
];

/// Shows the Getting started page while `shown`: three short tasks (place and run,
/// measure, graph), beside the graphs so that the canvas stays free to follow them.
pub fn getting_started(ctx: &Context, shown: &mut bool) {
    let height = (ctx.content_rect().height() - 120.0).max(200.0);
    let right = ctx.content_rect().right();
    egui::Window::new(tr("start-title"))
        .open(shown)
        .collapsible(true)
        .resizable(false)
        .default_width(330.0)
        .default_pos([(right - 350.0).max(0.0), 90.0])
        .min_height(height.min(560.0))
        .max_height(height)
        .show(ctx, |ui| {
            egui::ScrollArea::vertical()
                .max_height(height)
                .show(ui, |ui| {
                    ui.label(tr("start-intro"));
                    for (title, steps) in TASKS {
                        ui.add_space(6.0);
                        ui.label(RichText::new(tr(title)).strong());
                        for (k, step) in steps.iter().enumerate() {
                            ui.horizontal_wrapped(|ui| {
                                ui.label(RichText::new(format!("{}.", k + 1)).monospace());
                                ui.label(tr(step));
                            });
                        }
                    }
                });
        });
}
