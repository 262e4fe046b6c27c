//! What a number field accepts: a number, arithmetic on numbers (`2*pi`, `sqrt(2)/2`,
//! `1.5e3`, `3^2`), and after it a unit that converts to the field's SI unit (`30 km/h`,
//! `5 cm`, `250 g`, `45 deg`). The scene keeps the SI number; the file stores it.
//!
//! Arithmetic is `exmex`'s, on f64: + − × ÷ and ^, parentheses, the functions sqrt, cbrt,
//! sin, cos, tan (radians), asin, acos, atan, exp, ln, log10, abs, and the constants pi
//! (also π or PI), tau and e. The units are a small table per SI unit, below; a field's
//! own unit is always accepted.
//!
//! A lesson's answer is read the same way, in the unit its question names, which may be
//! any unit of a table ([`parse_in`]: `201 cm` for a question in metres is 2.01).

/// Units that may follow a number for a field in `si` units, with what one of each is
/// in `si`. Longer names first, so that `km/h` is not read as `h`.
fn units(si: &str) -> &'static [(&'static str, f64)] {
    match si {
        "m" => &[
            ("km", 1000.0),
            ("cm", 0.01),
            ("mm", 0.001),
            ("ft", 0.3048),
            ("in", 0.0254),
            ("m", 1.0),
        ],
        "m/s" => &[
            ("km/h", 1.0 / 3.6),
            ("cm/s", 0.01),
            ("mph", 0.447_04),
            ("m/s", 1.0),
        ],
        "m/s²" => &[("cm/s²", 0.01), ("m/s^2", 1.0), ("m/s²", 1.0)],
        "kg" => &[("kg", 1.0), ("mg", 1e-6), ("g", 1e-3), ("t", 1000.0)],
        "s" => &[("min", 60.0), ("ms", 1e-3), ("h", 3600.0), ("s", 1.0)],
        "C" => &[
            ("mC", 1e-3),
            ("µC", 1e-6),
            ("uC", 1e-6),
            ("nC", 1e-9),
            ("pC", 1e-12),
            ("C", 1.0),
        ],
        "N/m" => &[("N/cm", 100.0), ("kN/m", 1000.0), ("N/m", 1.0)],
        "N·s/m" => &[("N·s/m", 1.0), ("Ns/m", 1.0), ("kg/s", 1.0)],
        "°" => &[
            ("deg", 1.0),
            ("rad", 180.0 / std::f64::consts::PI),
            ("rev", 360.0),
            ("°", 1.0),
        ],
        "J" => &[("kJ", 1000.0), ("mJ", 1e-3), ("J", 1.0)],
        "N" => &[("kN", 1000.0), ("mN", 1e-3), ("N", 1.0)],
        "W" => &[("kW", 1000.0), ("mW", 1e-3), ("W", 1.0)],
        "kg·m/s" => &[
            ("kg·m/s", 1.0),
            ("kg*m/s", 1.0),
            ("kg m/s", 1.0),
            ("N·s", 1.0),
            ("Ns", 1.0),
        ],
        "rad/s" => &[
            ("rpm", std::f64::consts::TAU / 60.0),
            ("rev/s", std::f64::consts::TAU),
            ("deg/s", std::f64::consts::PI / 180.0),
            ("°/s", std::f64::consts::PI / 180.0),
            ("rad/s", 1.0),
        ],
        _ => &[],
    }
}

/// The SI units that have a table of other units.
const SI_UNITS: [&str; 14] = [
    "m", "m/s", "m/s²", "kg", "s", "C", "N/m", "N·s/m", "°", "J", "N", "W", "kg·m/s", "rad/s",
];

/// The SI unit whose table holds `unit`, and how much of it one `unit` is: (`m`, 0.01)
/// for `cm`; `unit` itself, one to one, where no table holds it.
pub fn si_of(unit: &str) -> (&str, f64) {
    let unit = unit.trim();
    SI_UNITS
        .iter()
        .find_map(|&si| {
            let factor = units(si)
                .iter()
                .find(|(name, _)| *name == unit)
                .map(|&(_, factor)| factor)
                .or_else(|| (si == unit).then_some(1.0))?;
            Some((si, factor))
        })
        .unwrap_or((unit, 1.0))
}

/// Whether a number in `unit` measures the same kind of thing as one in `si` (a length
/// in `cm` for a measure in `m`).
pub fn fits(unit: &str, si: &str) -> bool {
    si_of(unit).0 == si_of(si).0
}

/// The value of `text` in `unit`, any unit of the tables: `201 cm` in `m` is 2.01, in
/// `cm` 201, and `2.01 m` in `cm` also 201; a number without a unit is in `unit` (`201`
/// in `cm` is 201).
///
/// # Errors
/// As [`parse`]: arithmetic that does not read, or a unit of another kind.
pub fn parse_in(text: &str, unit: &str) -> Result<f64, String> {
    let (si, factor) = si_of(unit);
    let text = text.trim();
    let (expression, _) = split_unit(text, si);
    if expression.len() == text.len() {
        // No unit written: the number as typed, in the question's unit.
        parse(text, si)
    } else {
        Ok(parse(text, si)? / factor)
    }
}

/// The longest expression read, characters: a law, a force or a field's arithmetic is a
/// line. The expression parser's time and memory grow faster than its text (a sum of 4 MB
/// took 1.8 GB, a power tower of 10 MB 4.4 GB, 200,000 nested functions over a minute),
/// so a text beyond any formula is refused before it is parsed.
const LONGEST_EXPRESSION: usize = 2_000;

/// The deepest nesting of brackets read (a formula rarely nests ten deep).
const DEEPEST_EXPRESSION: usize = 64;

/// Why `text` is too long or too deeply nested to read as an expression, in words
/// (without the text, which may be megabytes); `None` when it is neither.
pub(crate) fn too_big(text: &str) -> Option<String> {
    let length = text.chars().count();
    if length > LONGEST_EXPRESSION {
        let words = [
            ("length", length.to_string()),
            ("most", LONGEST_EXPRESSION.to_string()),
        ];
        let words: Vec<(&str, &str)> = words.iter().map(|(k, v)| (*k, v.as_str())).collect();
        return Some(newtonlab_i18n::tr_text("expression-too-long", &words));
    }
    let mut depth = 0_usize;
    let mut deepest = 0;
    for c in text.chars() {
        match c {
            '(' | '[' | '{' => {
                depth += 1;
                deepest = deepest.max(depth);
            }
            ')' | ']' | '}' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    (deepest > DEEPEST_EXPRESSION).then(|| {
        let (deepest, most) = (deepest.to_string(), DEEPEST_EXPRESSION.to_string());
        newtonlab_i18n::tr_text(
            "expression-too-deep",
            &[("depth", deepest.as_str()), ("most", most.as_str())],
        )
    })
}

/// The value of `text` in `si` units.
///
/// # Errors
/// What was wrong, in words for the inspector: the arithmetic that did not parse, or a
/// unit that does not fit the field.
pub fn parse(text: &str, si: &str) -> Result<f64, String> {
    let text = text.trim();
    if let Ok(value) = text.parse::<f64>() {
        return Ok(value);
    }
    if let Some(reason) = too_big(text) {
        return Err(reason);
    }
    let (expression, factor) = split_unit(text, si);
    let value = evaluate(expression).map_err(|reason| {
        let units: Vec<&str> = units(si).iter().map(|(name, _)| *name).collect();
        let words = [("text", text), ("reason", reason.as_str())];
        if units.is_empty() {
            newtonlab_i18n::tr_text("units-not-a-number", &words)
        } else {
            let units = units.join(", ");
            let words = [words[0], words[1], ("units", units.as_str())];
            newtonlab_i18n::tr_text("units-not-a-number-unit", &words)
        }
    })?;
    Ok(value * factor)
}

/// The expression and the factor of the unit at its end (1 without one).
fn split_unit<'t>(text: &'t str, si: &str) -> (&'t str, f64) {
    let own = (si, 1.0);
    let table = units(si);
    let candidates = table.iter().copied().chain((!si.is_empty()).then_some(own));
    for (name, factor) in candidates {
        if let Some(expression) = text.strip_suffix(name) {
            let expression = expression.trim_end();
            // A unit follows a number, a closing bracket or a space: "5 m", "(2+3)m", "5m".
            let fits = expression
                .chars()
                .last()
                .is_some_and(|c| c.is_ascii_digit() || c == ')' || c == '.' || c.is_alphabetic());
            if fits && !expression.is_empty() {
                return (expression, factor);
            }
        }
    }
    (text, 1.0)
}

/// The functions and constants arithmetic may name (`exmex`'s, as people write them).
const KNOWN_WORDS: [&str; 17] = [
    "sqrt", "cbrt", "sin", "cos", "tan", "asin", "acos", "atan", "exp", "ln", "log10", "abs", "pi",
    "Pi", "PI", "tau", "e",
];

/// An arithmetic expression's value. An angle in degrees inside a function's brackets
/// is turned into radians, which the functions read: `sin(30 deg)`, `cos(45°)`.
///
/// # Errors
/// What is wrong with it, in plain words.
fn evaluate(expression: &str) -> Result<f64, String> {
    if let Ok(value) = expression.trim().parse::<f64>() {
        return Ok(value);
    }
    let expression = powers_of_ten(&degrees_in_brackets(expression));
    if let Some(reason) = plain_reason(&expression) {
        return Err(reason);
    }
    // exmex names π PI, τ TAU and e E; people write pi and tau.
    let spelled: String = words(&expression)
        .map(|word| match word {
            "pi" | "Pi" => "PI",
            "tau" => "TAU",
            other => other,
        })
        .collect();
    let value = exmex::eval_str::<f64>(&spelled)
        .map_err(|_| newtonlab_i18n::tr_text("units-unreadable", &[]))?;
    if value.is_finite() {
        Ok(value)
    } else {
        Err(newtonlab_i18n::tr_text(
            "units-comes-to",
            &[("value", &value.to_string())],
        ))
    }
}

/// `expression` with each number written with a power of ten (`2e-3`, `1.5E6`) in
/// brackets as a product, which the arithmetic reads: `(2*10^(-3))`.
fn powers_of_ten(expression: &str) -> String {
    let chars: Vec<char> = expression.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let starts_number = chars[i].is_ascii_digit()
            && (i == 0 || !(chars[i - 1].is_alphanumeric() || chars[i - 1] == '.'));
        if !starts_number {
            out.push(chars[i]);
            i += 1;
            continue;
        }
        let mut end = i;
        while end < chars.len() && (chars[end].is_ascii_digit() || chars[end] == '.') {
            end += 1;
        }
        let mantissa: String = chars[i..end].iter().collect();
        let mut exponent_end = end + 1;
        if end < chars.len() && matches!(chars[end], 'e' | 'E') {
            if exponent_end < chars.len() && matches!(chars[exponent_end], '+' | '-') {
                exponent_end += 1;
            }
            let digits_from = exponent_end;
            while exponent_end < chars.len() && chars[exponent_end].is_ascii_digit() {
                exponent_end += 1;
            }
            if exponent_end > digits_from {
                let exponent: String = chars[end + 1..exponent_end].iter().collect();
                for part in ["(", &mantissa, "*10^(", &exponent, "))"] {
                    out.push_str(part);
                }
                i = exponent_end;
                continue;
            }
        }
        out.push_str(&mantissa);
        i = end;
    }
    out
}

/// `expression` with each angle in degrees that ends a function's argument (`30 deg)`,
/// `45°)`) written in radians.
fn degrees_in_brackets(expression: &str) -> String {
    let mut out = expression.to_owned();
    for unit in ["deg", "°"] {
        let mut from = 0;
        while let Some(found) = out[from..].find(unit) {
            let at = from + found;
            let after = &out[at + unit.len()..];
            let closes = after.trim_start().starts_with([')', ',']);
            let before = out[..at].trim_end();
            let follows_a_number =
                before.ends_with(|c: char| c.is_ascii_digit() || c == '.' || c == ')');
            if closes && follows_a_number {
                out.replace_range(at..at + unit.len(), "*(pi/180)");
                from = at + "*(pi/180)".len();
            } else {
                from = at + unit.len();
            }
        }
    }
    out
}

/// Why `expression` cannot be arithmetic, in plain words, where that can be told before
/// reading it: empty, brackets that do not match, an operator at the end, or a word that
/// is no function, constant or unit of the field.
fn plain_reason(expression: &str) -> Option<String> {
    let say = |id: &str, args: &[(&str, &str)]| Some(newtonlab_i18n::tr_text(id, args));
    let trimmed = expression.trim();
    if trimmed.is_empty() {
        return say("units-empty", &[]);
    }
    let mut depth = 0_i32;
    for c in trimmed.chars() {
        depth += match c {
            '(' => 1,
            ')' => -1,
            _ => 0,
        };
        if depth < 0 {
            break;
        }
    }
    if depth != 0 {
        return say("units-brackets", &[]);
    }
    if trimmed.ends_with(['+', '-', '*', '/', '^']) {
        return say("units-ends-with-operator", &[]);
    }
    words(trimmed)
        .find(|w| w.starts_with(char::is_alphabetic) && !KNOWN_WORDS.contains(w))
        .and_then(|word| say("units-unknown-word", &[("word", word)]))
}

/// `text` cut into runs of letters and runs of everything else, in order.
fn words(text: &str) -> impl Iterator<Item = &str> {
    let mut rest = text;
    std::iter::from_fn(move || {
        let first = rest.chars().next()?;
        let letters = first.is_alphabetic();
        let end = rest
            .char_indices()
            .find(|&(_, c)| c.is_alphabetic() != letters)
            .map_or(rest.len(), |(i, _)| i);
        let (word, tail) = rest.split_at(end);
        rest = tail;
        Some(word)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 * b.abs().max(1.0)
    }

    /// The examples the guide gives, and the units of each kind of field.
    #[test]
    fn numbers_arithmetic_and_units_become_si() {
        let cases = [
            ("30 km/h", "m/s", 30.0 / 3.6),
            ("5 cm", "m", 0.05),
            ("5cm", "m", 0.05),
            ("250 g", "kg", 0.25),
            ("2*pi", "", 2.0 * std::f64::consts::PI),
            ("sqrt(2)/2", "m", std::f64::consts::SQRT_2 / 2.0),
            ("1.5e3", "kg", 1500.0),
            ("1/2", "s", 0.5),
            ("3^2 m", "m", 9.0),
            ("(1 + 2) km", "m", 3000.0),
            ("-4.5", "m", -4.5),
            ("2 µC", "C", 2e-6),
            ("90 deg", "°", 90.0),
            ("pi/2 rad", "°", 90.0),
            ("1 min", "s", 60.0),
            ("9.81 m/s^2", "m/s²", 9.81),
            ("12 m/s", "m/s", 12.0),
            ("sin(30 deg)", "", 0.5),
            ("cos(60°)", "", 0.5),
            ("2*sin(30deg) m", "m", 1.0),
            ("1.5e3 g", "kg", 1.5),
            ("2e-3*5 s", "s", 0.01),
        ];
        for (text, si, expected) in cases {
            let value = parse(text, si).unwrap_or_else(|e| panic!("{text}: {e}"));
            assert!(
                close(value, expected),
                "{text} in {si}: {value}, expected {expected}"
            );
        }
    }

    /// An answer in any unit of the question's kind is read in the question's unit.
    #[test]
    fn answers_are_read_in_the_questions_unit() {
        let cases = [
            ("201 cm", "m", 2.01),
            ("2.01 m", "cm", 201.0),
            ("2.01", "cm", 2.01),
            ("201", "cm", 201.0),
            ("2*100 cm", "m", 2.0),
            ("1340 ms", "s", 1.34),
            ("1.34 s", "ms", 1340.0),
            ("3 kJ", "J", 3000.0),
            ("2 N·s", "kg·m/s", 2.0),
            ("90 deg", "rad", std::f64::consts::FRAC_PI_2),
        ];
        for (text, unit, expected) in cases {
            let value = parse_in(text, unit).unwrap_or_else(|e| panic!("{text}: {e}"));
            assert!(close(value, expected), "{text} in {unit}: {value}");
        }
        assert!(parse_in("2 kg", "m").is_err(), "a mass is no length");
        assert!(fits("cm", "m") && fits("km/h", "m/s") && !fits("s", "m"));
        assert!(fits("furlong", "furlong"), "a unit of no table fits itself");
    }

    /// Text that is not a quantity of the field is refused with a reason.
    #[test]
    fn what_does_not_fit_is_refused_with_a_reason() {
        for (text, si) in [
            ("abc", "m"),
            ("5 kg", "m"),
            ("2*", "s"),
            ("1/0", "m"),
            ("", "m"),
        ] {
            let error = parse(text, si).expect_err(text);
            assert!(error.contains("is not a number"), "{text}: {error}");
        }
        assert!(
            parse("5 kg", "m")
                .expect_err("kg is no length")
                .contains("km"),
            "names the units"
        );
        // In plain words, not the parser's.
        for (text, says) in [
            ("(2+3", "brackets"),
            ("2*", "operator"),
            ("sinn(1)", "'sinn'"),
            ("2 3", "cannot be read"),
        ] {
            let error = parse(text, "").expect_err(text);
            assert!(error.contains(says), "{text}: {error}");
            assert!(
                !error.contains("node") && !error.contains("ops"),
                "{text}: {error}"
            );
        }
    }
}
