//! The figures `validate` draws: one quantity against time (or another variable),
//! simulated and theoretical, two panels stacked. What they hold, not how they are drawn
//! (the command line draws them with plotters).

/// One quantity against time (or another variable), simulated and theoretical.
pub struct Panel {
    /// The horizontal axis's label.
    pub x_label: &'static str,
    /// The quantity's label.
    pub label: &'static str,
    /// The simulation's points.
    pub simulated: Vec<(f64, f64)>,
    /// Theory's, at the same abscissae.
    pub theory: Vec<(f64, f64)>,
    /// Where each curve after the first begins (indices into both lists): several curves
    /// drawn in one panel, not joined.
    pub breaks: Vec<usize>,
}

impl Panel {
    /// A quantity against time.
    pub fn new(label: &'static str) -> Self {
        Self::against("time t (s)", label)
    }

    /// A quantity against the variable `x_label` names.
    pub fn against(x_label: &'static str, label: &'static str) -> Self {
        Self {
            x_label,
            label,
            simulated: Vec::new(),
            theory: Vec::new(),
            breaks: Vec::new(),
        }
    }

    /// Starts a new curve: the next point is not joined to the last.
    pub fn new_curve(&mut self) {
        if !self.simulated.is_empty() {
            self.breaks.push(self.simulated.len());
        }
    }

    /// Each curve's points of `points` (the simulated or the theory list).
    pub fn curves<'a>(&self, points: &'a [(f64, f64)]) -> impl Iterator<Item = &'a [(f64, f64)]> {
        let starts = std::iter::once(0).chain(self.breaks.iter().copied());
        let ends = self
            .breaks
            .iter()
            .copied()
            .chain(std::iter::once(points.len()));
        starts.zip(ends).map(move |(a, b)| &points[a.min(b)..b])
    }

    /// A point of both curves at `t`.
    pub fn add(&mut self, t: f64, simulated: f64, theory: f64) {
        self.simulated.push((t, simulated));
        self.theory.push((t, theory));
    }
}

/// A figure of two panels, stacked.
pub struct Figure {
    /// The file's name (PNG).
    pub file: String,
    /// What it shows.
    pub title: String,
    /// The two panels, top first.
    pub panels: [Panel; 2],
}
