//! Numbers for people: plain decimals with about six significant digits and a unit, the
//! way a teacher writes them on a board (15.7378 J, 0.000123 m), switching to powers of
//! ten only far from 1 (6.6742 × 10⁻¹¹). Full precision stays in the inspector's fields,
//! the CSV exports and the command line. In German and Spanish the screen writes a
//! decimal comma (15,7378 J), and a pair of numbers is split by a semicolon.

/// `value` to about six significant digits.
pub fn number(value: f64) -> String {
    if value == 0.0 {
        return "0".to_owned();
    }
    if !value.is_finite() {
        return value.to_string();
    }
    let exponent = value.abs().log10().floor();
    if (-4.0..6.0).contains(&exponent) {
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a small count of decimals"
        )]
        let decimals = (5.0 - exponent).max(0.0) as usize;
        let text = format!("{value:.decimals$}");
        local(trim_zeros(&text))
    } else {
        let mantissa = value / 10_f64.powf(exponent);
        format!(
            "{} × 10{}",
            local(trim_zeros(&format!("{mantissa:.4}"))),
            superscript(exponent)
        )
    }
}

/// A plot's tick at `value`, its ticks `step` apart: as [`number`] writes it (0.3, not
/// 0.30000000000000004; the language's decimal comma), far from 1 with a power of ten
/// (1e-11, not 0.00000000001), and 0 for the rounding a sum of steps leaves where the
/// tick is 0.
pub fn tick(value: f64, step: f64) -> String {
    if value.abs() <= 1e-9 * step.abs() {
        return "0".to_owned();
    }
    if (1e-4..1e6).contains(&value.abs()) {
        return number(value);
    }
    // The plot's font has no superscripts: 1e-11 rather than 1 × 10⁻¹¹.
    let text = format!("{value:.4e}");
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    local(format!("{}e{exponent}", trim_zeros(mantissa)))
}

/// [`tick`] as a plot's axis asks for it.
pub fn plot_tick(mark: egui_plot::GridMark, _range: &std::ops::RangeInclusive<f64>) -> String {
    tick(mark.value, mark.step_size)
}

/// `value` with exactly `decimals` decimals, in the app's decimal separator: a reading
/// whose precision is known (a located instant to the microsecond), not trimmed.
pub fn fixed(value: f64, decimals: usize) -> String {
    local(format!("{value:.decimals$}"))
}

/// `value` as a text field shows it: 15 significant digits at most, so that the last
/// bit of a sum (5.800000000000001 for 5.8) is not shown, and 0 for −0; a power of ten
/// (6.674e-11) far from 1, where a plain decimal would be a row of zeros to count; the
/// decimal separator of the app's language. What the field holds is not touched: only
/// what the user types is applied.
pub fn field(value: f64) -> String {
    if value == 0.0 {
        return "0".to_owned();
    }
    let rounded: f64 = format!("{value:.14e}").parse().unwrap_or(value);
    if (1e-4..1e15).contains(&rounded.abs()) || !rounded.is_finite() {
        local(rounded.to_string())
    } else {
        local(format!("{rounded:e}"))
    }
}

/// `text` as the user typed it, in the notation the parsers read: where the app's
/// language writes a decimal comma, a comma between two digits ("0,25") is a decimal
/// point. Elsewhere a comma is left as typed, so that "1,000" in English is refused
/// rather than read as one.
pub fn typed(text: &str) -> String {
    if !crate::i18n::decimal_comma() {
        return text.to_owned();
    }
    let chars: Vec<char> = text.chars().collect();
    chars
        .iter()
        .enumerate()
        .map(|(i, &c)| {
            let between_digits = i > 0
                && chars[i - 1].is_ascii_digit()
                && chars.get(i + 1).is_some_and(char::is_ascii_digit);
            if c == ',' && between_digits { '.' } else { c }
        })
        .collect()
}

/// `text` with the decimal separator of the app's language.
fn local(text: String) -> String {
    if crate::i18n::decimal_comma() {
        text.replace('.', ",")
    } else {
        text
    }
}

/// Two numbers as a pair: "(1.5, 2)", or "(1,5; 2)" where the comma is decimal.
pub fn pair(x: f64, y: f64) -> String {
    pair_of(&number(x), &number(y))
}

/// Two numbers already written, as a pair split as the app's language splits one: by a
/// semicolon where the comma is decimal.
pub fn pair_of(x: &str, y: &str) -> String {
    let separator = if crate::i18n::decimal_comma() {
        ";"
    } else {
        ","
    };
    format!("({x}{separator} {y})")
}

/// `value` and its unit: "15.7378 J".
pub fn with_unit(value: f64, unit: &str) -> String {
    if unit.is_empty() {
        number(value)
    } else {
        format!("{} {unit}", number(value))
    }
}

/// "1.2500" → "1.25", "3.000" → "3".
fn trim_zeros(text: &str) -> String {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text.to_owned()
    }
}

#[expect(
    clippy::cast_possible_truncation,
    reason = "an exponent of an f64 fits an i32"
)]
fn superscript(exponent: f64) -> String {
    (exponent as i32)
        .to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹']
                [d.to_digit(10).unwrap_or(0) as usize],
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::field;

    /// A field shows what a person typed, not the last bit of the sum that made it: 5.8
    /// for 5.8 + 1 ulp, 0.3 for 0.1 + 0.2, 0 for −0; and every other value in full.
    #[test]
    fn fields_show_fifteen_digits_and_no_negative_zero() {
        assert_eq!(field(5.800_000_000_000_001), "5.8");
        assert_eq!(field(0.1 + 0.2), "0.3");
        assert_eq!(field(-0.0), "0");
        assert_eq!(field(9.81), "9.81");
        assert_eq!(field(6.674e-11), "6.674e-11");
        assert_eq!(field(2.5e20), "2.5e20");
        assert_eq!(field(0.000_25), "0.00025");
        assert_eq!(field(1.234_567_890_123_45), "1.23456789012345");
        assert_eq!(field(-2.5), "-2.5");
    }

    use super::*;

    #[test]
    fn numbers_read_as_a_person_writes_them() {
        assert_eq!(number(15.737_825_81), "15.7378");
        assert_eq!(number(-0.827_688_218_144_400_7), "-0.827688");
        assert_eq!(number(3.0), "3");
        assert_eq!(number(0.000_123), "0.000123");
        assert_eq!(number(123_456.7), "123457");
        assert_eq!(number(6.6742e-11), "6.6742 × 10⁻¹¹");
        assert_eq!(number(8.988e9), "8.988 × 10⁹");
        assert_eq!(number(0.0), "0");
        assert_eq!(with_unit(-1.2e-11, "J"), "-1.2 × 10⁻¹¹ J");
    }

    #[test]
    fn german_and_spanish_write_a_decimal_comma() {
        crate::i18n::set_language(crate::i18n::Language::German);
        assert_eq!(number(15.7378), "15,7378");
        assert_eq!(pair(1.5, -2.0), "(1,5; -2)");
        assert_eq!(number(6.6742e-11), "6,6742 × 10⁻¹¹");
        crate::i18n::set_language(crate::i18n::Language::English);
        assert_eq!(pair(1.5, -2.0), "(1.5, -2)");
    }

    /// Tick numbers read as a person writes them, in every plot: no run of zeros for a
    /// residual's scale, no last bit of a sum of steps.
    #[test]
    fn ticks_are_written_as_numbers_are() {
        assert_eq!(tick(1e-11, 1e-11), "1e-11");
        assert_eq!(tick(-2.000_000_000_000_000_4e-11, 1e-11), "-2e-11");
        assert_eq!(tick(2.5e7, 5e6), "2.5e7");
        assert_eq!(tick(0.1 + 0.2, 0.1), "0.3");
        assert_eq!(tick(1.3e-17, 0.5), "0");
        assert_eq!(tick(250.0, 50.0), "250");
        crate::i18n::set_language(crate::i18n::Language::German);
        assert_eq!(tick(0.25, 0.05), "0,25");
        assert_eq!(tick(2.5e-11, 5e-12), "2,5e-11");
        crate::i18n::set_language(crate::i18n::Language::English);
    }

    /// A German or Spanish field shows the comma its readouts show, and reads back what
    /// it shows as well as what a person used to a point types; English reads a comma
    /// as typed, so "1,000" is refused rather than taken for 1.
    #[test]
    fn fields_write_and_read_the_languages_decimal_separator() {
        for language in [
            crate::i18n::Language::German,
            crate::i18n::Language::Spanish,
        ] {
            crate::i18n::set_language(language);
            assert_eq!(field(1.2), "1,2");
            assert_eq!(field(-6.674e-11), "-6,674e-11");
            for value in [1.2, -6.674e-11, 0.001, 123_456.789] {
                let read = crate::units::parse(&typed(&field(value)), "m");
                assert_eq!(read, Ok(value), "{language:?} {value}");
            }
            assert_eq!(typed("0,25 m + 1.5 cm"), "0.25 m + 1.5 cm");
            assert_eq!(typed("Bob.y crosses -0,5"), "Bob.y crosses -0.5");
            assert_eq!(typed(",5, 3,"), ",5, 3,");
        }
        crate::i18n::set_language(crate::i18n::Language::English);
        assert_eq!(field(1.2), "1.2");
        assert_eq!(typed("1,000"), "1,000");
        assert!(crate::units::parse(&typed("1,000"), "m").is_err());
    }
}
