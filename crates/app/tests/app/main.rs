//! The app driven as a user would, through its accessibility tree (`egui_kittest)`: no GPU,
//! no display. Each test clicks, types and presses keys, then checks the app's state.

#![expect(
    clippy::float_cmp,
    reason = "typed values and paused clocks are compared exactly"
)]

mod bodies;
mod common;
mod editing;
mod experiments;
mod files;
mod instruments;
mod keyboard;
mod languages;
mod lesson_panel;
mod lessons;
mod links;
mod readouts;
mod run_controls;
mod timeline;
