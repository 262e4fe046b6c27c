//! Where the world is on screen: the transform between metres (y up) and screen points,
//! zoom about a point, fitting a box, following particles, and the nice round lengths
//! of the grid and the scale bar.

// World coordinates are f64 metres, screen coordinates f32 points.
#![expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "f64 world to f32 screen"
)]

use egui::{Pos2, Rect};
use physics::DVec2;

/// Where the world is on screen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// The world point at the canvas centre, metres.
    pub center: DVec2,
    pub pixels_per_metre: f64,
}

impl View {
    pub fn to_screen(&self, rect: Rect, p: DVec2) -> Pos2 {
        let d = (p - self.center) * self.pixels_per_metre;
        Pos2::new(rect.center().x + d.x as f32, rect.center().y - d.y as f32)
    }

    pub fn to_world(&self, rect: Rect, p: Pos2) -> DVec2 {
        let d = p - rect.center();
        self.center + DVec2::new(f64::from(d.x), -f64::from(d.y)) / self.pixels_per_metre
    }

    /// Zooms by `factor` keeping the world point under `anchor` in place.
    pub fn zoom_at(&mut self, rect: Rect, anchor: Pos2, factor: f64) {
        let before = self.to_world(rect, anchor);
        self.pixels_per_metre = (self.pixels_per_metre * factor).clamp(1e-6, 1e9);
        let after = self.to_world(rect, anchor);
        self.center += before - after;
    }

    /// Shows the box `min`–`max` with a margin.
    pub fn fit(&mut self, rect: Rect, min: DVec2, max: DVec2) {
        let size = (max - min).max(DVec2::splat(1.0));
        self.center = (min + max) / 2.0;
        let scale_x = f64::from(rect.width()) / size.x;
        let scale_y = f64::from(rect.height()) / size.y;
        self.pixels_per_metre = (scale_x.min(scale_y) * 0.85).clamp(1e-6, 1e9);
    }

    /// Moves a step of the way towards centring `target` at `pixels_per_metre`: called
    /// every frame, the camera glides instead of jumping.
    pub fn glide_to(&mut self, target: DVec2, pixels_per_metre: f64) {
        const RATE: f64 = 0.2;
        if !(target.is_finite() && pixels_per_metre.is_finite() && pixels_per_metre > 0.0) {
            return;
        }
        self.center += (target - self.center) * RATE;
        self.pixels_per_metre *= (pixels_per_metre / self.pixels_per_metre).powf(RATE);
    }

    /// Glides towards showing the box `min`–`max`, zooming out when it leaves the view
    /// and in when it fills less than a third of it.
    pub fn keep_in_view(&mut self, rect: Rect, min: DVec2, max: DVec2) {
        let mut wanted = *self;
        wanted.fit(rect, min, max);
        let (lo, hi) = (
            self.to_world(rect, rect.left_bottom()),
            self.to_world(rect, rect.right_top()),
        );
        let inside = lo.x <= min.x && lo.y <= min.y && max.x <= hi.x && max.y <= hi.y;
        let small = wanted.pixels_per_metre > 3.0 * self.pixels_per_metre;
        let scale = if inside && !small {
            self.pixels_per_metre
        } else {
            wanted.pixels_per_metre
        };
        self.glide_to(wanted.center, scale);
    }
}

/// The 1, 2 or 5 × 10ⁿ nearest above `length`.
pub fn nice_length(length: f64) -> f64 {
    let exponent = length.abs().max(1e-300).log10().floor();
    let base = 10_f64.powf(exponent);
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * base)
        .find(|v| *v >= length)
        .unwrap_or(10.0 * base)
}

/// A length in metres with no more decimals than the grid spacing needs.
pub(super) fn format_metres(value: f64, spacing: f64) -> String {
    let decimals = (-spacing.log10().floor()).max(0.0) as usize;
    let value = if value.abs() < spacing * 1e-6 {
        0.0
    } else {
        value
    };
    // The separator the language writes on screen, as the panels do.
    format!("{} m", newtonlab_i18n::decimal(value, decimals))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Grid labels write the decimal separator of the language, as the panels do: a
    /// point in English, a comma in German and Spanish; −0 is 0.
    #[test]
    fn grid_labels_speak_the_language() {
        use newtonlab_i18n::{Language, set_language};
        set_language(Language::English);
        assert_eq!(format_metres(-2.5, 0.5), "-2.5 m");
        set_language(Language::German);
        assert_eq!(format_metres(-2.5, 0.5), "-2,5 m");
        assert_eq!(format_metres(-1e-9, 0.5), "0,0 m");
        set_language(Language::English);
    }
}
