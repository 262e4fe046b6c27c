//! The validation report: tables in the paper's layout, the checks behind them, rendered
//! as aligned text for the terminal and as Markdown for `report.md`.

use std::fmt::Write as _;

/// A table of simulation beside theory: one of the paper's, reproduced, or one of a
/// later group's.
pub struct Table {
    /// The paper's section, "4.2", or the group's name.
    pub section: &'static str,
    /// What it shows.
    pub title: String,
    /// The closed-form result the theory column comes from.
    pub theory: &'static str,
    /// The columns' names.
    pub header: Vec<&'static str>,
    /// The rows, each value as printed.
    pub rows: Vec<Vec<String>>,
}

/// The rows of a table of checks, each a quantity against its closed form: quantity,
/// simulated, theory, error, tolerance.
pub struct Checks {
    /// The group's name, before each check's in the report's list.
    group: &'static str,
    rows: Vec<Vec<String>>,
}

impl Checks {
    /// No rows yet, for `group`'s checks.
    pub fn new(group: &'static str) -> Self {
        Self {
            group,
            rows: Vec::new(),
        }
    }

    /// Checks `simulated` against `theory`, the error relative to `scale`, within `limit`,
    /// and adds the row.
    pub fn check(
        &mut self,
        report: &mut Report,
        what: String,
        (simulated, theory, scale): (f64, f64, f64),
        limit: f64,
    ) {
        let e = report.check_within(
            format!("{}: {what}", self.group),
            (simulated, theory, scale),
            limit,
        );
        self.rows.push(vec![
            what,
            value(simulated),
            value(theory),
            error(e),
            bound(limit),
        ]);
    }

    /// The table of the rows, titled, with the closed forms they hold to.
    pub fn table(self, title: &str, theory: &'static str) -> Table {
        Table {
            section: self.group,
            title: title.to_owned(),
            theory,
            header: vec!["quantity", "simulated", "theory", "error", "tolerance"],
            rows: self.rows,
        }
    }
}

/// What a check's error must not exceed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Limit {
    /// The report's tolerance (`--tolerance`): the paper's experiments.
    Tolerance,
    /// A bound the group states, with its reason beside the check.
    Stated(f64),
    /// For a value the paper printed: the largest difference its rounding allows.
    Rounding(f64),
}

/// A simulated value held against theory.
pub struct Check {
    /// The group it belongs to (`paper`, `rods`, …).
    pub group: &'static str,
    /// What is checked, in words.
    pub what: String,
    /// |simulated − theory| / scale; for a printed value, |printed − simulated|.
    pub error: f64,
    /// What it must not exceed.
    pub limit: Limit,
}

/// Every check of a validation, and its tables.
pub struct Report {
    /// The paper's experiments' tolerance.
    pub tolerance: f64,
    /// The tables, in order.
    pub tables: Vec<Table>,
    /// The checks, in order.
    pub checks: Vec<Check>,
    /// The group whose checks are being recorded.
    pub group: &'static str,
}

impl Report {
    /// An empty report, the paper's experiments held to `tolerance`.
    pub fn new(tolerance: f64) -> Self {
        Self {
            tolerance,
            tables: Vec::new(),
            checks: Vec::new(),
            group: "paper",
        }
    }

    /// The largest error `check` may have.
    pub fn limit(&self, check: &Check) -> f64 {
        match check.limit {
            Limit::Tolerance => self.tolerance,
            Limit::Stated(x) | Limit::Rounding(x) => x,
        }
    }

    /// Records a check held to a bound of its own, `limit`, and returns its error,
    /// |simulated − theory| / scale.
    pub fn check_within(
        &mut self,
        what: impl Into<String>,
        (simulated, theory, scale): (f64, f64, f64),
        limit: f64,
    ) -> f64 {
        self.record(
            what,
            (simulated - theory).abs() / scale,
            Limit::Stated(limit),
        )
    }

    /// Records a check's `error` against `limit`, and returns the error.
    fn record(&mut self, what: impl Into<String>, error: f64, limit: Limit) -> f64 {
        self.checks.push(Check {
            group: self.group,
            what: what.into(),
            error,
            limit,
        });
        error
    }

    /// Records a check and returns its error, |simulated − theory| / scale.
    pub fn check(
        &mut self,
        what: impl Into<String>,
        simulated: f64,
        theory: f64,
        scale: f64,
    ) -> f64 {
        // NaN fails: `error <= tolerance` is false for it.
        self.record(what, (simulated - theory).abs() / scale, Limit::Tolerance)
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
        self.record(what, difference.abs(), Limit::Rounding(rounding));
        difference
    }

    /// The checks whose error exceeds their limit (or could not be measured).
    pub fn failures(&self) -> impl Iterator<Item = &Check> {
        // A NaN error (a quantity that could not be measured) fails too.
        self.checks
            .iter()
            .filter(|c| c.error.is_nan() || c.error > self.limit(c))
    }

    /// Every table as aligned plain text.
    pub fn to_text(&self) -> String {
        self.tables.iter().map(Self::render_text).collect()
    }

    /// One table as aligned plain text.
    pub fn render_text(table: &Table) -> String {
        let mut out = String::new();
        {
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
        self.tables.iter().map(Self::render_markdown).collect()
    }

    /// One table as Markdown.
    pub fn render_markdown(table: &Table) -> String {
        let mut out = String::new();
        {
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
            let of = |limit: fn(&Limit) -> bool| -> Vec<&Check> {
                self.checks.iter().filter(|c| limit(&c.limit)).collect()
            };
            let computed = of(|l| *l == Limit::Tolerance);
            let stated = of(|l| matches!(l, Limit::Stated(_)));
            let printed = of(|l| matches!(l, Limit::Rounding(_)));
            let mut out = String::new();
            if !computed.is_empty() {
                let _ = write!(
                    out,
                    "all {} checks within the tolerance {:e} (largest error {:.2e}); all {} of the paper's printed values reproduced within their rounding",
                    computed.len(),
                    self.tolerance,
                    computed.iter().map(|c| c.error).fold(0.0, f64::max),
                    printed.len()
                );
            }
            if !stated.is_empty() {
                let _ = write!(
                    out,
                    "{}all {} checks of the other groups within their stated tolerances",
                    if out.is_empty() { "" } else { "; " },
                    stated.len()
                );
            }
            return out;
        }
        let mut out = format!(
            "{} of {} checks exceed the tolerance ({:e} for the paper's experiments, stated per check for the other groups):",
            failed.len(),
            self.checks.len(),
            self.tolerance
        );
        for check in failed {
            let _ = write!(
                out,
                "\n  [{}] {}: error {:.3e}, allowed {:.0e}",
                check.group,
                check.what,
                check.error,
                self.limit(check)
            );
        }
        out
    }

    /// One line per group: its checks, its worst error against what it allows (the
    /// largest ratio error / allowed), and whether it passed.
    pub fn groups(&self, statements: &[(&'static str, &'static str)]) -> Table {
        let mut rows = Vec::new();
        for &(group, statement) in statements {
            let checks: Vec<&Check> = self.checks.iter().filter(|c| c.group == group).collect();
            if checks.is_empty() {
                continue;
            }
            let worst = checks
                .iter()
                .copied()
                .max_by(|a, b| (a.error / self.limit(a)).total_cmp(&(b.error / self.limit(b))))
                .filter(|c| !c.error.is_nan());
            let failed = checks
                .iter()
                .filter(|c| c.error.is_nan() || c.error > self.limit(c))
                .count();
            rows.push(vec![
                group.to_owned(),
                statement.to_owned(),
                checks.len().to_string(),
                worst.map_or("NaN".to_owned(), |c| {
                    format!("{:.1e} of {}", c.error, bound(self.limit(c)))
                }),
                if failed == 0 {
                    "pass".to_owned()
                } else {
                    format!("FAIL ({failed})")
                },
            ]);
        }
        Table {
            section: "summary",
            title: "Every group, its worst error against the tolerance it is held to".to_owned(),
            theory: "each group's tables below say what its theory is",
            header: vec!["group", "what it proves", "checks", "worst error", "result"],
            rows,
        }
    }
}

/// A value with enough digits to show a 1e-9 difference.
pub fn value(x: f64) -> String {
    format!("{x:.10}")
}

/// An error, relative unless stated.
pub fn error(x: f64) -> String {
    format!("{x:.2e}")
}

/// A tolerance, as tables print it.
pub fn bound(x: f64) -> String {
    if x == 0.0 {
        "exactly".to_owned()
    } else {
        format!("{x:.0e}")
    }
}

/// An angle in degrees.
pub fn degrees(x: f64) -> String {
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
