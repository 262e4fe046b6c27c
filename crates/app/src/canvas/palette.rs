//! The canvas's colours and line widths (its instruments' too): the usual ones, and the
//! high-contrast ones that View → High contrast chooses with the panels' black-on-white
//! theme (the canvas reads the theme each frame, so both switch together). In high contrast every colour drawn
//! on the canvas's white stands out from it by at least WCAG's 4.5:1 (a test computes
//! the ratios), and lines are half as wide again.

use egui::Color32;

/// What the canvas draws with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Palette {
    /// The canvas itself.
    pub background: Color32,
    /// Grid lines.
    pub grid: Color32,
    /// The axes through the origin.
    pub axis: Color32,
    /// The grid's numbers.
    pub grid_text: Color32,
    /// The world's box, the scale bar, anchors, names.
    pub ink: Color32,
    /// Ramps.
    pub ramp: Color32,
    /// Springs.
    pub spring: Color32,
    /// Rods and strings.
    pub tie: Color32,
    /// Behind the selected object.
    pub highlight: Color32,
    /// The frame around the canvas while it has the keyboard's focus.
    pub focus: Color32,
    /// The velocity, acceleration and force arrows.
    pub velocity: Color32,
    /// See `velocity`.
    pub acceleration: Color32,
    /// See `velocity`.
    pub force: Color32,
    /// The instruments: the tape measure, the field probe, the protractor.
    pub tape: Color32,
    /// See `tape`.
    pub probe: Color32,
    /// See `tape`.
    pub angle: Color32,
    /// Particles' outlines: `None` is a darker shade of the particle's own colour.
    pub outline: Option<Color32>,
    /// Every line's width is multiplied by this.
    pub width: f32,
}

impl Palette {
    /// The usual colours, on an off-white canvas.
    pub const USUAL: Self = Self {
        background: Color32::from_rgb(250, 250, 247),
        grid: Color32::from_gray(228),
        axis: Color32::from_gray(170),
        grid_text: Color32::from_gray(120),
        ink: Color32::from_gray(60),
        ramp: Color32::from_rgb(150, 120, 90),
        spring: Color32::from_rgb(70, 70, 90),
        tie: Color32::from_rgb(90, 75, 60),
        highlight: Color32::from_rgb(255, 196, 0),
        focus: Color32::from_rgb(30, 90, 200),
        velocity: Color32::from_rgb(40, 150, 70),
        acceleration: Color32::from_rgb(230, 130, 30),
        force: Color32::from_rgb(200, 40, 40),
        tape: Color32::from_rgb(200, 120, 20),
        probe: Color32::from_rgb(40, 110, 180),
        angle: Color32::from_rgb(130, 60, 160),
        outline: None,
        width: 1.0,
    };

    /// High contrast: dark, saturated colours on white, black outlines, wider lines.
    pub const HIGH_CONTRAST: Self = Self {
        background: Color32::WHITE,
        grid: Color32::from_gray(200),
        axis: Color32::from_gray(90),
        grid_text: Color32::from_gray(60),
        ink: Color32::BLACK,
        ramp: Color32::from_rgb(100, 60, 20),
        spring: Color32::BLACK,
        tie: Color32::from_rgb(60, 40, 20),
        highlight: Color32::from_rgb(0, 60, 200),
        focus: Color32::BLACK,
        velocity: Color32::from_rgb(0, 110, 40),
        acceleration: Color32::from_rgb(160, 70, 0),
        force: Color32::from_rgb(180, 0, 0),
        tape: Color32::from_rgb(140, 60, 0),
        probe: Color32::from_rgb(0, 70, 150),
        angle: Color32::from_rgb(90, 20, 120),
        outline: Some(Color32::BLACK),
        width: 1.5,
    };

    /// The canvas's focus frame: three points wide (times the palette's width), in a
    /// colour that stands out from the canvas by WCAG's 3:1 for a focus indicator (the
    /// theme's selection stroke, one pale pixel, does not).
    pub fn focus_stroke(&self) -> egui::Stroke {
        egui::Stroke::new(3.0 * self.width, self.focus)
    }

    /// The palette for the theme `ui` draws with: high contrast when the theme forces a
    /// text colour, as the high-contrast theme does (`settings::high_contrast_visuals`).
    pub fn of(ui: &egui::Ui) -> Self {
        if ui.visuals().override_text_color.is_some() {
            Self::HIGH_CONTRAST
        } else {
            Self::USUAL
        }
    }
}

/// WCAG 2's contrast ratio between two colours, 1 to 21.
pub fn contrast(a: Color32, b: Color32) -> f32 {
    fn luminance(c: Color32) -> f32 {
        let channel = |v: u8| {
            let s = f32::from(v) / 255.0;
            if s <= 0.039_28 {
                s / 12.92
            } else {
                ((s + 0.055) / 1.055).powf(2.4)
            }
        };
        0.2126 * channel(c.r()) + 0.7152 * channel(c.g()) + 0.0722 * channel(c.b())
    }
    let (la, lb) = (luminance(a), luminance(b));
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Everything drawn in high contrast stands out from the white by WCAG's 4.5:1 for
    /// text (graphics need 3:1); the usual palette's grid, ramp and highlight do not,
    /// which is why the high-contrast one exists. The grid lines are left out: they
    /// are meant to recede (3:1 would hide nothing, but they are not content).
    #[test]
    fn high_contrast_colours_stand_out_from_the_canvas() {
        let p = Palette::HIGH_CONTRAST;
        for (name, colour) in [
            ("axis", p.axis),
            ("grid text", p.grid_text),
            ("ink", p.ink),
            ("ramp", p.ramp),
            ("spring", p.spring),
            ("tie", p.tie),
            ("highlight", p.highlight),
            ("velocity", p.velocity),
            ("acceleration", p.acceleration),
            ("force", p.force),
            ("tape", p.tape),
            ("probe", p.probe),
            ("protractor", p.angle),
        ] {
            let ratio = contrast(colour, p.background);
            assert!(ratio >= 4.5, "{name}: {ratio:.2}:1");
        }
        let usual = Palette::USUAL;
        assert!(
            contrast(usual.highlight, usual.background) < 3.0,
            "the usual yellow is faint"
        );
        assert!((contrast(Color32::BLACK, Color32::WHITE) - 21.0).abs() < 1e-3);
    }

    /// The focus frame is at least two points wide and stands out from the canvas by
    /// 3:1 or more, in both palettes.
    #[test]
    fn the_focus_frame_can_be_seen() {
        for palette in [Palette::USUAL, Palette::HIGH_CONTRAST] {
            let stroke = palette.focus_stroke();
            assert!(stroke.width >= 2.0, "{}", stroke.width);
            let ratio = contrast(stroke.color, palette.background);
            assert!(ratio >= 3.0, "{ratio:.2}:1");
        }
    }
}
