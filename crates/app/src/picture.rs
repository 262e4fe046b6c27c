//! Pictures of the app: a graph or the canvas as a PNG file. The frame is captured as
//! egui draws it (a viewport screenshot), cut to the part asked for and encoded with the
//! `png` crate, so the file shows exactly what is on screen.

use std::sync::{Arc, Mutex};

use egui::{ColorImage, Rect};

/// Where a requested screenshot lands when the renderer has it.
pub type Slot = Arc<Mutex<Option<Arc<ColorImage>>>>;

/// Asks for a screenshot of the next frame drawn.
pub fn request(ctx: &egui::Context) -> Slot {
    let slot = Slot::default();
    let (filled, repaint) = (slot.clone(), ctx.clone());
    ctx.request_screenshot(move |image| {
        if let Ok(mut place) = filled.lock() {
            *place = Some(image);
        }
        repaint.request_repaint();
    });
    slot
}

/// The screenshot, once it has arrived.
pub fn take(slot: &Slot) -> Option<Arc<ColorImage>> {
    slot.lock().ok().and_then(|mut place| place.take())
}

/// What a graph's figure to print is written as (`figure.rs`, on the desktop).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Png,
    Svg,
}

/// What a picture shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Subject {
    Canvas,
    /// Graph number N.
    Graph(usize),
}

impl Subject {
    /// The file name offered.
    pub fn file_name(self) -> &'static str {
        match self {
            Self::Canvas => "canvas.png",
            Self::Graph(_) => "graph.png",
        }
    }
}

/// The part of `image` (a screenshot, in pixels) under `rect` (in points), as PNG.
///
/// # Errors
/// When `rect` is not on the screenshot, or encoding fails.
pub fn png_of(image: &ColorImage, rect: Rect, pixels_per_point: f32) -> Result<Vec<u8>, String> {
    let [width, height] = image.size;
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "pixel coordinates, clamped to the image"
    )]
    let clamp = |v: f32, max: usize| ((v * pixels_per_point).round().max(0.0) as usize).min(max);
    let (x0, x1) = (clamp(rect.min.x, width), clamp(rect.max.x, width));
    let (y0, y1) = (clamp(rect.min.y, height), clamp(rect.max.y, height));
    if x1 <= x0 || y1 <= y0 {
        return Err("nothing to draw: the part is off screen".to_owned());
    }
    let mut rgba = Vec::with_capacity((x1 - x0) * (y1 - y0) * 4);
    for y in y0..y1 {
        for pixel in &image.pixels[y * width + x0..y * width + x1] {
            rgba.extend_from_slice(&pixel.to_srgba_unmultiplied());
        }
    }
    let mut out = Vec::new();
    let fail = |e: png::EncodingError| {
        crate::i18n::tr_text("file-cannot-encode", &[("error", &e.to_string())])
    };
    let size = |v: usize| u32::try_from(v).map_err(|_| "the picture is too large".to_owned());
    let mut encoder = png::Encoder::new(&mut out, size(x1 - x0)?, size(y1 - y0)?);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(fail)?;
    writer.write_image_data(&rgba).map_err(fail)?;
    writer.finish().map_err(fail)?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::{Color32, pos2};

    /// A 4 × 3 image at 2 pixels per point: the point rectangle (1, 0.5)–(2, 1.5) is the
    /// pixels x 2..4, y 1..3, decoded back with their colours.
    #[test]
    fn a_part_of_the_screen_comes_back_as_its_pixels() {
        let mut image = ColorImage::filled([4, 3], Color32::WHITE);
        image.pixels[4 + 3] = Color32::RED;
        let bytes = png_of(
            &image,
            Rect::from_min_max(pos2(1.0, 0.5), pos2(2.0, 1.5)),
            2.0,
        )
        .expect("encoded");
        let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
        let mut reader = decoder.read_info().expect("a PNG");
        let mut buffer = vec![0; reader.output_buffer_size().expect("a size")];
        let info = reader.next_frame(&mut buffer).expect("a frame");
        assert_eq!((info.width, info.height), (2, 2));
        assert_eq!(&buffer[4..8], &[255, 0, 0, 255], "the red pixel at (3, 1)");
        assert_eq!(&buffer[0..4], &[255, 255, 255, 255], "white elsewhere");
        assert!(
            png_of(
                &image,
                Rect::from_min_max(pos2(9.0, 9.0), pos2(10.0, 10.0)),
                2.0
            )
            .is_err()
        );
    }
}
