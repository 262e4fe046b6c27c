//! The paper's figures: position and acceleration against time, simulation and theory
//! overlaid, drawn with plotters into PNG files. Text is rendered with the Ubuntu Light
//! font that egui ships, registered as the app's figures register it, so no system font
//! is needed.

use std::path::Path;

use plotters::prelude::*;

use newtonlab_validation::figures::{Figure, Panel};

/// Draws `figure` into `directory/figure.file`.
pub(crate) fn draw(figure: &Figure, directory: &Path) -> Result<(), String> {
    newtonlab_app::figure::register_font()?;
    let path = directory.join(&figure.file);
    let root = BitMapBackend::new(&path, (1000, 760)).into_drawing_area();
    let problem = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    root.fill(&WHITE).map_err(|e| problem(&e))?;
    let root = root
        .titled(&figure.title, ("sans-serif", 24))
        .map_err(|e| problem(&e))?;
    let areas = root.split_evenly((2, 1));
    for (area, panel) in areas.iter().zip(&figure.panels) {
        let ((t_min, t_max), (low, high)) = extent(panel);
        let mut chart = ChartBuilder::on(area)
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(t_min..t_max, low..high)
            .map_err(|e| problem(&e))?;
        chart
            .configure_mesh()
            .x_desc(panel.x_label)
            .y_desc(panel.label)
            .label_style(("sans-serif", 15))
            .draw()
            .map_err(|e| problem(&e))?;
        let theory_colour = RGBColor(240, 160, 60);
        for curve in panel.curves(&panel.theory).skip(1) {
            chart
                .draw_series(LineSeries::new(
                    curve.iter().copied(),
                    theory_colour.stroke_width(5),
                ))
                .map_err(|e| problem(&e))?;
        }
        chart
            .draw_series(LineSeries::new(
                panel
                    .curves(&panel.theory)
                    .next()
                    .unwrap_or_default()
                    .iter()
                    .copied(),
                theory_colour.stroke_width(5),
            ))
            .map_err(|e| problem(&e))?
            .label("theory")
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], theory_colour.stroke_width(5))
            });
        let simulated_colour = RGBColor(40, 90, 200);
        for curve in panel.curves(&panel.simulated).skip(1) {
            chart
                .draw_series(LineSeries::new(
                    curve.iter().copied(),
                    simulated_colour.stroke_width(1),
                ))
                .map_err(|e| problem(&e))?;
        }
        chart
            .draw_series(LineSeries::new(
                panel
                    .curves(&panel.simulated)
                    .next()
                    .unwrap_or_default()
                    .iter()
                    .copied(),
                simulated_colour.stroke_width(1),
            ))
            .map_err(|e| problem(&e))?
            .label("simulation")
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], simulated_colour.stroke_width(2))
            });
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 15))
            .draw()
            .map_err(|e| problem(&e))?;
    }
    root.present().map_err(|e| problem(&e))
}

/// The horizontal range (from 0 when nothing is negative) and a padded value range of a
/// panel.
fn extent(panel: &Panel) -> ((f64, f64), (f64, f64)) {
    let all = panel.simulated.iter().chain(&panel.theory);
    let t_min = all.clone().map(|p| p.0).fold(0.0, f64::min);
    let t_max = all
        .clone()
        .map(|p| p.0)
        .fold(0.0, f64::max)
        .max(t_min + 1e-9);
    let t_max = (t_min, t_max);
    let (low, high) = all
        .map(|p| p.1)
        .filter(|y| y.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), y| {
            (lo.min(y), hi.max(y))
        });
    if !(low.is_finite() && high.is_finite()) {
        return (t_max, (-1.0, 1.0));
    }
    let pad = ((high - low) * 0.08).max(1e-9);
    (t_max, (low - pad, high + pad))
}
