//! The canvas as a picture to print, at twice the screen's resolution: the shapes egui
//! was given for the canvas this frame (circles, lines, paths, rectangles, text), drawn
//! again by plotters at the larger scale, so that lines stay lines and text stays text
//! rather than a screenshot's pixels blown up. The text in the bundled font, as the
//! graphs' figures.

use egui::epaint::{ClippedShape, ColorMode, PathStroke, Shape, TextShape};
use egui::{Color32, Pos2, Rect};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// How many times the screen's pixels the picture has across and down.
pub const SCALE: f32 = 2.0;

type Area<'a> = DrawingArea<BitMapBackend<'a>, plotters::coord::Shift>;

/// The shapes of `shapes` that lie on `rect` (the canvas's, in points), drawn at
/// `pixels_per_point` × [`SCALE`] pixels a point, as PNG bytes.
///
/// # Errors
/// The canvas has no size, or drawing or encoding failed (in words).
pub fn png(shapes: &[ClippedShape], rect: Rect, pixels_per_point: f32) -> Result<Vec<u8>, String> {
    super::register_font()?;
    let scale = pixels_per_point * SCALE;
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a window's size in pixels"
    )]
    let size = (
        (rect.width() * scale).round().max(0.0) as u32,
        (rect.height() * scale).round().max(0.0) as u32,
    );
    if size.0 == 0 || size.1 == 0 {
        return Err(crate::i18n::tr("notice-nothing-to-export"));
    }
    let mut pixels = vec![255_u8; size.0 as usize * size.1 as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, size).into_drawing_area();
        let painter = Painter { rect, scale };
        for clipped in shapes {
            painter.shape(&root, &clipped.shape)?;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    super::encode_png(&pixels, size)
}

/// Where the canvas's points land in the picture.
struct Painter {
    rect: Rect,
    scale: f32,
}

impl Painter {
    #[expect(
        clippy::cast_possible_truncation,
        reason = "pixel coordinates of a picture a few thousand pixels wide"
    )]
    fn at(&self, p: Pos2) -> (i32, i32) {
        let v = (p - self.rect.min) * self.scale;
        (v.x.round() as i32, v.y.round() as i32)
    }

    /// A width in points as whole pixels, at least one.
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a stroke's width in pixels"
    )]
    fn width(&self, points: f32) -> u32 {
        ((points * self.scale).round() as u32).max(1)
    }

    fn shape(&self, area: &Area<'_>, shape: &Shape) -> Result<(), String> {
        let fail = |e: &dyn std::fmt::Display| e.to_string();
        match shape {
            Shape::Vec(shapes) => {
                for shape in shapes {
                    self.shape(area, shape)?;
                }
            }
            Shape::Circle(c) => {
                let (centre, radius) = (self.at(c.center), self.width(c.radius));
                if let Some(fill) = colour(c.fill) {
                    area.draw(&Circle::new(centre, radius, fill.filled()))
                        .map_err(|e| fail(&e))?;
                }
                if let Some(line) = colour(c.stroke.color).filter(|_| c.stroke.width > 0.0) {
                    let style = line.stroke_width(self.width(c.stroke.width));
                    area.draw(&Circle::new(centre, radius, style))
                        .map_err(|e| fail(&e))?;
                }
            }
            Shape::Ellipse(e) => {
                let points: Vec<Pos2> = (0..48)
                    .map(|k| {
                        let a = std::f32::consts::TAU * k as f32 / 48.0;
                        let (s, c) = a.sin_cos();
                        let (sa, ca) = e.angle.sin_cos();
                        let (x, y) = (e.radius.x * c, e.radius.y * s);
                        e.center + egui::vec2(x * ca - y * sa, x * sa + y * ca)
                    })
                    .collect();
                self.path(area, &points, true, e.fill, &PathStroke::from(e.stroke))?;
            }
            Shape::LineSegment { points, stroke } => {
                self.path(area, points, false, Color32::TRANSPARENT, &(*stroke).into())?;
            }
            Shape::Path(p) => self.path(area, &p.points, p.closed, p.fill, &p.stroke)?,
            Shape::Rect(r) => {
                let corners = [self.at(r.rect.min), self.at(r.rect.max)];
                if let Some(fill) = colour(r.fill) {
                    area.draw(&Rectangle::new(corners, fill.filled()))
                        .map_err(|e| fail(&e))?;
                }
                if let Some(line) = colour(r.stroke.color).filter(|_| r.stroke.width > 0.0) {
                    let style = line.stroke_width(self.width(r.stroke.width));
                    area.draw(&Rectangle::new(corners, style))
                        .map_err(|e| fail(&e))?;
                }
            }
            Shape::Text(text) => self.text(area, text)?,
            Shape::Mesh(mesh) => {
                for triangle in mesh.indices.chunks_exact(3) {
                    let corners: Vec<(i32, i32)> = triangle
                        .iter()
                        .filter_map(|&k| mesh.vertices.get(k as usize))
                        .map(|v| self.at(v.pos))
                        .collect();
                    let first = mesh.vertices.get(triangle[0] as usize);
                    if let Some(fill) = first.and_then(|v| colour(v.color)) {
                        area.draw(&Polygon::new(corners, fill.filled()))
                            .map_err(|e| fail(&e))?;
                    }
                }
            }
            Shape::QuadraticBezier(b) => {
                self.path(area, &b.flatten(None), b.closed, b.fill, &b.stroke)?;
            }
            Shape::CubicBezier(b) => {
                self.path(area, &b.flatten(None), b.closed, b.fill, &b.stroke)?;
            }
            // Nothing the canvas draws: a plot's bands, a renderer's callback.
            Shape::Noop | Shape::Band(_) | Shape::Callback(_) => {}
        }
        Ok(())
    }

    fn path(
        &self,
        area: &Area<'_>,
        points: &[Pos2],
        closed: bool,
        fill: Color32,
        stroke: &PathStroke,
    ) -> Result<(), String> {
        let fail = |e: &dyn std::fmt::Display| e.to_string();
        let mut corners: Vec<(i32, i32)> = points.iter().map(|&p| self.at(p)).collect();
        if let Some(fill) = colour(fill).filter(|_| closed && corners.len() > 2) {
            area.draw(&Polygon::new(corners.clone(), fill.filled()))
                .map_err(|e| fail(&e))?;
        }
        let line = match &stroke.color {
            ColorMode::Solid(c) => colour(*c),
            ColorMode::UV(_) => Some(BLACK.to_rgba()),
        };
        if let Some(line) = line.filter(|_| stroke.width > 0.0 && corners.len() > 1) {
            if closed {
                corners.push(corners[0]);
            }
            let style = line.stroke_width(self.width(stroke.width));
            area.draw(&PathElement::new(corners, style))
                .map_err(|e| fail(&e))?;
        }
        Ok(())
    }

    /// Each row of a label at its place, in its first section's colour and size.
    fn text(&self, area: &Area<'_>, text: &TextShape) -> Result<(), String> {
        let Some(section) = text.galley.job.sections.first() else {
            return Ok(());
        };
        let mut ink = text.override_text_color.unwrap_or(section.format.color);
        if ink == Color32::PLACEHOLDER {
            ink = text.fallback_color;
        }
        let Some(ink) = colour(ink) else {
            return Ok(());
        };
        let size = f64::from(section.format.font_id.size * self.scale);
        let font = ("sans-serif", size)
            .into_font()
            .color(&ink)
            .pos(Pos::new(HPos::Left, VPos::Top));
        for row in &text.galley.rows {
            let words: String = row.row.glyphs.iter().map(|g| g.chr).collect();
            let Some(first) = row.row.glyphs.first() else {
                continue;
            };
            let at = text.pos + row.pos.to_vec2() + egui::vec2(first.pos.x, 0.0);
            area.draw(&Text::new(words, self.at(at), font.clone()))
                .map_err(|e| e.to_string())?;
        }
        Ok(())
    }
}

/// An egui colour as plotters', `None` when it is fully transparent.
fn colour(c: Color32) -> Option<RGBAColor> {
    let [r, g, b, a] = c.to_srgba_unmultiplied();
    (a > 0).then(|| RGBAColor(r, g, b, f64::from(a) / 255.0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::{Stroke, pos2, vec2};

    /// A red disc and a black line on a 100 × 50 point canvas at 1 pixel a point come
    /// back as a 200 × 100 PNG, the disc's centre red at twice its coordinates.
    #[test]
    fn shapes_come_back_at_twice_the_scale() {
        let rect = Rect::from_min_size(pos2(10.0, 20.0), vec2(100.0, 50.0));
        let shapes = [
            Shape::circle_filled(pos2(30.0, 40.0), 5.0, Color32::RED),
            Shape::line_segment(
                [pos2(60.0, 30.0), pos2(100.0, 60.0)],
                Stroke::new(1.0, Color32::BLACK),
            ),
        ]
        .map(|shape| ClippedShape {
            clip_rect: rect,
            shape,
            transform_after_tessellation: egui::emath::TSTransform::IDENTITY,
        });
        let bytes = png(&shapes, rect, 1.0).expect("drawn");
        let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
        let mut reader = decoder.read_info().expect("a PNG");
        let mut buffer = vec![0; reader.output_buffer_size().expect("a size")];
        let info = reader.next_frame(&mut buffer).expect("a frame");
        assert_eq!((info.width, info.height), (200, 100));
        let pixel = |x: usize, y: usize| &buffer[(y * 200 + x) * 3..(y * 200 + x) * 3 + 3];
        assert_eq!(pixel(40, 40), &[255, 0, 0], "the disc at (20, 20) × 2");
        assert_eq!(pixel(5, 5), &[255, 255, 255], "white elsewhere");
        assert!(pixel(100, 20)[0] < 128, "the line starts at (50, 10) × 2");
        assert!(pixel(180, 80)[0] < 128, "and ends at (90, 40) × 2");
    }
}
