//! A graph as a figure to print: 1200 × 800 pixels as PNG, or SVG, with a title, axes
//! with tick numbers and each quantity with its unit, and the legend beside the curves,
//! never over them. Drawn with plotters from the run's recording (every sample), the
//! text in the Ubuntu Light font egui ships, so no system font is needed. On the
//! desktop: plotters lays out text with that font only outside the browser, where the
//! web build saves a graph as the picture on screen instead.
#![cfg(not(target_arch = "wasm32"))]

use plotters::prelude::*;
use plotters::style::FontStyle;

use physics::{Graph, Quantity};

use crate::recording::Recording;

pub mod canvas;

/// The figure's size, pixels.
pub const SIZE: (u32, u32) = (1200, 800);
/// The legend's width beside the plot, pixels.
const LEGEND_WIDTH: u32 = 260;

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

/// The figure of `graph` over `recording`, titled `title`, as `format`'s bytes.
///
/// # Errors
/// Nothing to draw (no sample, no series), or drawing or encoding failed (in words).
pub fn graph(
    recording: &Recording,
    graph: &Graph,
    title: &str,
    format: Format,
) -> Result<Vec<u8>, String> {
    let x = graph.x.clone();
    let series: Vec<(Quantity, Vec<(f64, f64)>)> = graph
        .y
        .iter()
        .filter_map(|q| {
            let (across, up) = (recording.column(&x)?, recording.column(q)?);
            let points = (0..recording.len())
                .map(|k| (recording.at(k, across), recording.at(k, up)))
                .filter(|(a, b)| a.is_finite() && b.is_finite())
                .collect();
            Some((q.clone(), points))
        })
        .collect();
    if recording.is_empty() || series.is_empty() {
        return Err(crate::i18n::tr("notice-nothing-to-export"));
    }
    // One y axis: its label names the unit when every series shares it.
    let units: Vec<&str> = series.iter().map(|(q, _)| q.unit()).collect();
    let y_label = match &series[..] {
        [(only, _)] => crate::plots::label(only),
        _ if units.windows(2).all(|w| w[0] == w[1]) => format!("({})", units[0]),
        _ => String::new(),
    };
    let curves: Vec<Curve> = series
        .into_iter()
        .map(|(q, points)| Curve {
            label: crate::plots::label(&q),
            points,
            dots: false,
        })
        .collect();
    let figure = Figure {
        title,
        x_label: crate::plots::label(&x),
        y_label,
        curves: &curves,
    };
    figure.encode(format)
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
        let (plot, legend) = root.split_horizontally(width.saturating_sub(LEGEND_WIDTH));
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
            let colour = COLOURS[k % COLOURS.len()];
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
        // The legend beside the plot: a mark of each colour and the curve's label.
        for (k, curve) in self.curves.iter().enumerate() {
            let colour = COLOURS[k % COLOURS.len()];
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_possible_wrap,
                reason = "a few rows"
            )]
            let y = 40 + 36 * k as i32;
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
            legend
                .draw(&Text::new(
                    curve.label.clone(),
                    (60, y - 11),
                    ("sans-serif", 22).into_font(),
                ))
                .map_err(|e| fail(&e))?;
        }
        Ok(())
    }
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
