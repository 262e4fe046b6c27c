//! The validation report: tables in the paper's layout, the checks behind them, rendered
//! as aligned text for the terminal and as Markdown for `report.md`.

use std::fmt::Write as _;

/// One of the paper's tables, reproduced.
pub(crate) struct Table {
    /// The paper's section, "4.2".
    pub section: &'static str,
    pub title: String,
    /// The closed-form result the theory column comes from.
    pub theory: &'static str,
    pub header: Vec<&'static str>,
    pub rows: Vec<Vec<String>>,
}

/// A simulated value held against theory.
pub(crate) struct Check {
    pub what: String,
    /// |simulated − theory| / scale; for a printed value, |printed − simulated|.
    pub error: f64,
    /// For a value the paper printed: the largest difference its rounding allows,
    /// which the check must meet instead of the tolerance.
    pub rounding: Option<f64>,
}

pub(crate) struct Report {
    pub tolerance: f64,
    pub tables: Vec<Table>,
    pub checks: Vec<Check>,
}

impl Report {
    pub fn new(tolerance: f64) -> Self {
        Self {
            tolerance,
            tables: Vec::new(),
            checks: Vec::new(),
        }
    }

    /// Records a check and returns its error, |simulated − theory| / scale.
    pub fn check(
        &mut self,
        what: impl Into<String>,
        simulated: f64,
        theory: f64,
        scale: f64,
    ) -> f64 {
        let error = (simulated - theory).abs() / scale;
        // NaN fails: `error <= tolerance` is false for it.
        self.checks.push(Check {
            what: what.into(),
            error,
            rounding: None,
        });
        error
    }

    /// Records that a value the paper `printed` is `simulated` up to its rounding
    /// (`rounding`, e.g. 0.002 for three decimals); returns printed − simulated.
    pub fn check_printed(
        &mut self,
        what: impl Into<String>,
        printed: f64,
        simulated: f64,
        rounding: f64,
    ) -> f64 {
        let difference = printed - simulated;
        self.checks.push(Check {
            what: what.into(),
            error: difference.abs(),
            rounding: Some(rounding),
        });
        difference
    }

    pub fn failures(&self) -> impl Iterator<Item = &Check> {
        // A NaN error (a quantity that could not be measured) fails too.
        self.checks
            .iter()
            .filter(|c| c.error.is_nan() || c.error > c.rounding.unwrap_or(self.tolerance))
    }

    /// Every table as aligned plain text.
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        for table in &self.tables {
            let _ = writeln!(out, "\n{} {}", table.section, table.title);
            let _ = writeln!(out, "theory: {}", table.theory);
            let widths: Vec<usize> = (0..table.header.len())
                .map(|c| {
                    table
                        .rows
                        .iter()
                        .map(|r| r.get(c).map_or(0, |s| s.chars().count()))
                        .chain([table.header[c].chars().count()])
                        .max()
                        .unwrap_or(0)
                })
                .collect();
            let line = |cells: &[String]| {
                cells
                    .iter()
                    .zip(&widths)
                    .map(|(cell, width)| format!("{cell:>width$}"))
                    .collect::<Vec<_>>()
                    .join("  ")
            };
            let header: Vec<String> = table.header.iter().map(|h| (*h).to_owned()).collect();
            let _ = writeln!(out, "{}", line(&header));
            for row in &table.rows {
                let _ = writeln!(out, "{}", line(row));
            }
        }
        out
    }

    /// Every table as Markdown.
    pub fn to_markdown(&self) -> String {
        let mut out = String::new();
        for table in &self.tables {
            let _ = writeln!(out, "\n## {} {}\n", table.section, table.title);
            let _ = writeln!(out, "Theory: {}\n", table.theory);
            let _ = writeln!(out, "| {} |", table.header.join(" | "));
            let _ = writeln!(out, "|{}|", vec!["---:"; table.header.len()].join("|"));
            for row in &table.rows {
                let _ = writeln!(out, "| {} |", row.join(" | "));
            }
        }
        out
    }

    /// The closing lines: how many checks, and which failed.
    pub fn summary(&self) -> String {
        let failed: Vec<&Check> = self.failures().collect();
        if failed.is_empty() {
            let (printed, computed): (Vec<&Check>, Vec<&Check>) =
                self.checks.iter().partition(|c| c.rounding.is_some());
            return format!(
                "all {} checks within the tolerance {:e} (largest error {:.2e}); all {} of the paper's printed values reproduced within their rounding",
                computed.len(),
                self.tolerance,
                computed.iter().map(|c| c.error).fold(0.0, f64::max),
                printed.len()
            );
        }
        let mut out = format!(
            "{} of {} checks exceed the tolerance {:e}:",
            failed.len(),
            self.checks.len(),
            self.tolerance
        );
        for check in failed {
            let _ = write!(out, "\n  {}: error {:.3e}", check.what, check.error);
        }
        out
    }
}

/// A value with enough digits to show a 1e-9 difference.
pub(crate) fn value(x: f64) -> String {
    format!("{x:.10}")
}

/// An error, relative unless stated.
pub(crate) fn error(x: f64) -> String {
    format!("{x:.2e}")
}

/// An angle in degrees.
pub(crate) fn degrees(x: f64) -> String {
    format!("{x:.6}")
}

#[cfg(test)]
mod tests {
    use super::Report;

    /// A value the paper printed is held to its rounding, whatever the tolerance: a
    /// difference beyond it fails even under a tolerance of 1, and one within it passes
    /// under 1e-12.
    #[test]
    fn printed_values_are_held_to_their_rounding_not_the_tolerance() {
        let mut loose = Report::new(1.0);
        loose.check_printed("off by 3 in the last place", 15.850, 15.853, 0.002);
        assert_eq!(loose.failures().count(), 1, "beyond the rounding fails");
        let mut strict = Report::new(1e-12);
        strict.check_printed("off by half a unit", 15.850, 15.8505, 0.002);
        assert_eq!(strict.failures().count(), 0, "within the rounding passes");
    }
}
