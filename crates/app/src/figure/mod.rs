//! A graph as a figure to print: 1200 × 800 pixels as PNG, or SVG, with a title, axes
//! with tick numbers and each quantity with its unit, and the legend beside the curves,
//! never over them. Drawn with plotters from the run's recording (every sample), the
//! text in the Ubuntu Light font egui ships, so no system font is needed. On the
//! desktop: plotters lays out text with that font only outside the browser, where the
//! web build saves a graph as the picture on screen instead.
#![cfg(not(target_arch = "wasm32"))]

use plotters::prelude::*;
use plotters::style::FontStyle;

use physics::Graph;

use crate::i18n::{Arg, tr_with};
use crate::recording::Recording;

pub mod canvas;

/// The figure's size, pixels.
pub const SIZE: (u32, u32) = (1200, 800);
/// The legend's width beside the plot, pixels: at least this, more for longer labels...
const LEGEND_WIDTH: u32 = 260;
/// ...up to this, beyond which a label wraps onto further lines.
const LEGEND_WIDEST: u32 = 480;
/// The legend's text size, pixels.
const LEGEND_FONT: u32 = 22;
/// From the legend's left edge to its text (the mark goes before), pixels.
const LEGEND_INDENT: u32 = 60;

pub use crate::picture::Format;

/// The curves' colours, in order (plotters' palette, strong enough to print).
const COLOURS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
];

/// Makes the bundled font available to plotters as "sans-serif" (once per process; the
/// command line's `validate` figures use it too).
///
/// # Errors
/// The font could not be loaded.
pub fn register_font() -> Result<(), String> {
    static REGISTERED: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            epaint_default_fonts::UBUNTU_LIGHT,
        )
        .is_ok()
    });
    ok.then_some(())
        .ok_or_else(|| "the bundled font could not be loaded".to_owned())
}

/// The figure of `graph` over `recording`, titled `title`, as `format`'s bytes; each
/// series in its object's colour where `colours` gives them (as
/// [`crate::plots::object_colours`] does), else in the palette's.
///
/// # Errors
/// Nothing to draw (no sample, no series), or drawing or encoding failed (in words).
pub fn graph(
    recording: &Recording,
    graph: &Graph,
    colours: Option<&[[u8; 3]]>,
    title: &str,
    format: Format,
) -> Result<Vec<u8>, String> {
    let x = graph.x.clone();
    let mut units = Vec::new();
    let curves: Vec<Curve> = graph
        .y
        .iter()
        .enumerate()
        .filter_map(|(k, q)| {
            let (across, up) = (recording.column(&x)?, recording.column(q)?);
            let points = (0..recording.len())
                .map(|k| (recording.at(k, across), recording.at(k, up)))
                .filter(|(a, b)| a.is_finite() && b.is_finite())
                .collect();
            units.push(q.unit());
            Some(Curve {
                label: crate::plots::label(q),
                points,
                dots: false,
                colour: colours.and_then(|c| c.get(k).copied()),
            })
        })
        .collect();
    if recording.is_empty() || curves.is_empty() {
        return Err(crate::i18n::tr("notice-nothing-to-export"));
    }
    let y_label = match &curves[..] {
        [only] => only.label.clone(),
        _ => units_label(units.into_iter()),
    };
    let figure = Figure {
        title,
        x_label: crate::plots::label(&x),
        y_label,
        curves: &curves,
    };
    figure.encode(format)
}

/// A series' results as a figure to print, `format`'s bytes: the measured points, the
/// law's curve, a title that says what was measured against what, both axes with units.
///
/// # Errors
/// Drawing or encoding failed (in words).
pub fn series(
    scene: &physics::Scene,
    results: &crate::experiments::Results,
    format: Format,
) -> Result<Vec<u8>, String> {
    let mut curves: Vec<Curve> = crate::experiments::columns(results)
        .into_iter()
        .map(|(label, points)| Curve {
            label,
            points: points.iter().map(|p| (p[0], p[1])).collect(),
            dots: true,
            colour: None,
        })
        .collect();
    if let Some(law) = crate::experiments::law(scene, &results.series) {
        curves.push(Curve {
            label: law.name,
            points: law.curve.iter().map(|p| (p[0], p[1])).collect(),
            dots: false,
            colour: None,
        });
    }
    let (title, x_label, y_label) = figure_words(scene, &results.series);
    Figure {
        title: &title,
        x_label,
        y_label,
        curves: &curves,
    }
    .encode(format)
}

/// A series' figure in words: its title ("period of bob.x against bob.length"), its x
/// axis (the varied setting with its unit) and its y axis (the measure with its unit,
/// or the units of several).
fn figure_words(scene: &physics::Scene, series: &physics::Series) -> (String, String, String) {
    let unit = |unit: &str| {
        if unit.is_empty() {
            String::new()
        } else {
            format!(" ({unit})")
        }
    };
    let x_unit = physics::series::Setting::parse(&series.vary, scene)
        .map_or(String::new(), |s| unit(s.unit()));
    let units: Vec<&str> = series
        .measure
        .iter()
        .filter_map(|m| physics::series::Measure::parse(m).ok().map(|m| m.unit()))
        .collect();
    let y_label = match (&series.measure[..], &units[..]) {
        ([measure], [only]) => format!("{measure}{}", unit(only)),
        _ => units_label(units.into_iter()),
    };
    let title = tr_with(
        "experiment-figure-title",
        &[
            ("measure", Arg::Text(&series.measure.join(", "))),
            ("vary", Arg::Text(&series.vary)),
        ],
    );
    (title, format!("{}{x_unit}", series.vary), y_label)
}

/// One y axis for several quantities: its label names their unit, "(m)", or their
/// units in order where they differ, "(m/s, rad/s)".
pub fn units_label<'a>(units: impl Iterator<Item = &'a str>) -> String {
    let mut distinct: Vec<&str> = Vec::new();
    for unit in units {
        if !distinct.contains(&unit) {
            distinct.push(unit);
        }
    }
    format!("({})", distinct.join(", "))
}

/// A figure's content: labelled curves (lines, or dots for measured points) on one pair
/// of axes.
pub struct Figure<'a> {
    pub title: &'a str,
    pub x_label: String,
    pub y_label: String,
    pub curves: &'a [Curve],
}

/// One curve of a figure.
pub struct Curve {
    pub label: String,
    pub points: Vec<(f64, f64)>,
    /// Drawn as dots (measurements) rather than a line.
    pub dots: bool,
    /// Its own colour (its object's on the canvas); the palette's where `None`.
    pub colour: Option<[u8; 3]>,
}

impl Figure<'_> {
    /// The figure as `format`'s bytes, [`SIZE`] pixels.
    ///
    /// # Errors
    /// Drawing or encoding failed (in words).
    pub fn encode(&self, format: Format) -> Result<Vec<u8>, String> {
        register_font()?;
        match format {
            Format::Png => {
                let (w, h) = SIZE;
                let mut pixels = vec![255_u8; (w * h * 3) as usize];
                {
                    let root = BitMapBackend::with_buffer(&mut pixels, SIZE).into_drawing_area();
                    self.draw(&root)?;
                    root.present().map_err(|e| e.to_string())?;
                }
                encode_png(&pixels, SIZE)
            }
            Format::Svg => {
                let mut text = String::new();
                {
                    let root = SVGBackend::with_string(&mut text, SIZE).into_drawing_area();
                    self.draw(&root)?;
                    root.present().map_err(|e| e.to_string())?;
                }
                Ok(text.into_bytes())
            }
        }
    }

    /// The figure on `root`: the title, the plot with its axes, the legend to its right.
    fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
    ) -> Result<(), String> {
        let fail = |e: &dyn std::fmt::Display| e.to_string();
        root.fill(&WHITE).map_err(|e| fail(&e))?;
        let root = root
            .titled(self.title, ("sans-serif", 32))
            .map_err(|e| fail(&e))?;
        let (width, _) = root.dim_in_pixel();
        let labels: Vec<Vec<String>> = self
            .curves
            .iter()
            .map(|c| wrap(&c.label, LEGEND_WIDEST - LEGEND_INDENT))
            .collect();
        let widest = labels
            .iter()
            .flatten()
            .map(|l| text_width(l))
            .max()
            .unwrap_or(0);
        let legend_width = (widest + LEGEND_INDENT + 20).clamp(LEGEND_WIDTH, LEGEND_WIDEST);
        let (plot, legend) = root.split_horizontally(width.saturating_sub(legend_width));
        let ((x0, x1), (y0, y1)) = extent(self.curves);
        let mut chart = ChartBuilder::on(&plot)
            .margin(20)
            .x_label_area_size(60)
            .y_label_area_size(100)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|e| fail(&e))?;
        chart
            .configure_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .label_style(("sans-serif", 20))
            .axis_desc_style(("sans-serif", 24))
            .draw()
            .map_err(|e| fail(&e))?;
        for (k, curve) in self.curves.iter().enumerate() {
            let colour = curve.rgb(k);
            let points = curve.points.iter().copied();
            if curve.dots {
                chart
                    .draw_series(points.map(|p| Circle::new(p, 6, colour.filled())))
                    .map_err(|e| fail(&e))?;
            } else {
                chart
                    .draw_series(LineSeries::new(points, colour.stroke_width(3)))
                    .map_err(|e| fail(&e))?;
            }
        }
        // The legend beside the plot: a mark of each colour and the curve's label, a long
        // label on as many lines as it needs.
        let line_height = 30;
        let mut y = 40;
        for (k, (curve, lines)) in self.curves.iter().zip(&labels).enumerate() {
            let colour = curve.rgb(k);
            if curve.dots {
                legend
                    .draw(&Circle::new((30, y), 6, colour.filled()))
                    .map_err(|e| fail(&e))?;
            } else {
                legend
                    .draw(&PathElement::new(
                        vec![(10, y), (50, y)],
                        colour.stroke_width(4),
                    ))
                    .map_err(|e| fail(&e))?;
            }
            for line in lines {
                legend
                    .draw(&Text::new(
                        line.clone(),
                        (i32::try_from(LEGEND_INDENT).unwrap_or(60), y - 11),
                        ("sans-serif", LEGEND_FONT).into_font(),
                    ))
                    .map_err(|e| fail(&e))?;
                y += line_height;
            }
            y += 6;
        }
        Ok(())
    }
}

impl Curve {
    /// Its colour: its own, or the palette's `k`th.
    fn rgb(&self, k: usize) -> RGBColor {
        self.colour
            .map_or(COLOURS[k % COLOURS.len()], |[r, g, b]| RGBColor(r, g, b))
    }
}

/// How wide `text` is in the legend's font, pixels (a rough width where the font fails).
pub fn text_width(text: &str) -> u32 {
    ("sans-serif", LEGEND_FONT)
        .into_font()
        .box_size(text)
        .map_or_else(
            |_| LEGEND_FONT * u32::try_from(text.chars().count()).unwrap_or(0) / 2,
            |(w, _)| w,
        )
}

/// `text` on lines at most `width` pixels wide in the legend's font, broken between
/// words (a single word wider than that stays whole on its line).
pub fn wrap(text: &str, width: u32) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split_whitespace() {
        match lines.last_mut() {
            Some(line) if text_width(&format!("{line} {word}")) <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_owned()),
        }
    }
    lines
}

/// The range of the points across and up, widened by 5 % (and around a single value).
fn extent(curves: &[Curve]) -> ((f64, f64), (f64, f64)) {
    let mut x = (f64::INFINITY, f64::NEG_INFINITY);
    let mut y = (f64::INFINITY, f64::NEG_INFINITY);
    for curve in curves {
        for &(a, b) in &curve.points {
            x = (x.0.min(a), x.1.max(a));
            y = (y.0.min(b), y.1.max(b));
        }
    }
    let widen = |(low, high): (f64, f64)| {
        if !(low.is_finite() && high.is_finite()) {
            return (0.0, 1.0);
        }
        let margin = if high > low {
            0.05 * (high - low)
        } else {
            0.5 * low.abs().max(1.0)
        };
        (low - margin, high + margin)
    };
    let x = if x.1 > x.0 { x } else { widen(x) };
    (x, widen(y))
}

/// RGB `pixels` of `size` as PNG bytes.
pub(crate) fn encode_png(pixels: &[u8], (w, h): (u32, u32)) -> Result<Vec<u8>, String> {
    let mut out = Vec::new();
    let fail = |e: png::EncodingError| {
        crate::i18n::tr_text("file-cannot-encode", &[("error", &e.to_string())])
    };
    let mut encoder = png::Encoder::new(&mut out, w, h);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(fail)?;
    writer.write_image_data(pixels).map_err(fail)?;
    writer.finish().map_err(fail)?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::{register_font, text_width, units_label, wrap};

    /// A long legend label breaks between words into lines that each fit, losing no
    /// word; a short one stays on one line.
    #[test]
    fn a_long_label_wraps_into_lines_that_fit() {
        register_font().expect("the bundled font");
        let label = "period of Bob.x from Bob.y crosses 0 down to the second such crossing";
        let lines = wrap(label, 200);
        assert!(lines.len() >= 3, "{lines:?}");
        assert!(lines.iter().all(|l| text_width(l) <= 200), "{lines:?}");
        assert_eq!(lines.join(" "), label);
        assert_eq!(wrap("bob.x (m)", 200), ["bob.x (m)"]);
        assert!(
            text_width("Ball.x at Ball.y crosses 0 down") > 200,
            "a real width"
        );
    }

    #[test]
    fn one_axis_names_each_unit_once_in_order() {
        assert_eq!(units_label(["m", "m"].into_iter()), "(m)");
        assert_eq!(
            units_label(["m/s", "rad/s", "m/s"].into_iter()),
            "(m/s, rad/s)"
        );
    }
}
