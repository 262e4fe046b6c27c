//! Landmarks: **F6** and **Shift+F6** move the keyboard focus to the next or previous
//! region of the window — the menu bar, the tool bar, the canvas, the inspector, the
//! graphs and the time machine's bar — instead of dozens of Tab presses between them.
//! Each region marks the control that takes the focus for it, every frame it is shown
//! ([`mark`]); a region hidden (a panel closed, projector mode, the time bar before a
//! run) is passed over.

use egui::{Context, Id, Ui};

/// A region of the window, in the order F6 visits them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Region {
    Menu,
    Toolbar,
    Canvas,
    Inspector,
    Graphs,
    TimeBar,
}

impl Region {
    pub const ALL: [Self; 6] = [
        Self::Menu,
        Self::Toolbar,
        Self::Canvas,
        Self::Inspector,
        Self::Graphs,
        Self::TimeBar,
    ];
}

fn key(region: Region) -> Id {
    Id::unique(("landmark", region))
}

/// Marks `id` as the control that takes the focus for `region` this frame.
pub fn mark(ui: &Ui, region: Region, id: Id) {
    let pass = ui.ctx().cumulative_pass_nr();
    ui.ctx()
        .data_mut(|d| d.insert_temp(key(region), (id, pass)));
}

/// The control marked for `region` in this frame or the last: the region is shown.
fn marked(ctx: &Context, region: Region) -> Option<Id> {
    let pass = ctx.cumulative_pass_nr();
    ctx.data(|d| d.get_temp::<(Id, u64)>(key(region)))
        .filter(|&(_, at)| at + 1 >= pass)
        .map(|(id, _)| id)
}

/// Moves the focus to the next region shown (`forward`) or the previous, from the one
/// holding the focus, or from the one F6 last went to; returns the region.
pub fn step(ctx: &Context, forward: bool) -> Option<Region> {
    let shown: Vec<(Region, Id)> = Region::ALL
        .into_iter()
        .filter_map(|region| Some((region, marked(ctx, region)?)))
        .collect();
    if shown.is_empty() {
        return None;
    }
    let last = Id::unique("landmark last");
    let focused = ctx.memory(egui::Memory::focused);
    let from = focused
        .and_then(|f| shown.iter().position(|&(_, id)| id == f))
        .or_else(|| {
            let region = ctx.data(|d| d.get_temp::<Region>(last))?;
            shown.iter().position(|&(r, _)| r == region)
        });
    let n = shown.len();
    let to = match (from, forward) {
        (None, true) => 0,
        (None, false) => n - 1,
        (Some(k), true) => (k + 1) % n,
        (Some(k), false) => (k + n - 1) % n,
    };
    let (region, id) = shown[to];
    ctx.memory_mut(|m| m.request_focus(id));
    ctx.data_mut(|d| d.insert_temp(last, region));
    Some(region)
}
