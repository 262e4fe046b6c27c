//! `newtonlab validate`: every physical claim against theory, in groups. `paper` is the
//! paper's section 4 (its tables, with simulation, theory and error columns); the other
//! groups hold what NewtonLab added since (rods, strings, the integrators' orders, the
//! tree, softening, the energy ledger, friction, saved states) to closed forms or to
//! computations written here apart from the simulation's code, each check to a tolerance
//! stated beside it. A summary of every group's worst error comes first. With `--out DIR`
//! it also writes `DIR/report.md` and the figures as PNG. Exit 0 when every error is
//! within its tolerance, 1 otherwise, listing the misses.

mod books;
mod drag;
mod events;
mod experiments;
mod methods;
mod paper_method;
mod plots;
mod report;
mod series;
mod theory;
mod ties;

use std::fmt::Write as _;
use std::path::PathBuf;

use crate::Failure;

#[derive(Debug, clap::Args)]
pub(crate) struct ValidateArgs {
    /// Also write report.md and the figures (PNG) into this directory.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// The largest error allowed in the paper's experiments, relative to the quantity's
    /// scale (the other groups state their own).
    #[arg(long, value_name = "X", default_value_t = 1e-6)]
    tolerance: f64,
    /// Run only these groups (repeatable); all of them when left out.
    #[arg(long, value_name = "GROUP", value_enum)]
    only: Vec<Group>,
}

/// A group of checks, named as `--only` takes it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum Group {
    Paper,
    Rods,
    Strings,
    Integrators,
    Tree,
    Softening,
    Ledger,
    Friction,
    SavedState,
    Events,
    Drag,
    Series,
}

impl Group {
    const ALL: [Self; 12] = [
        Self::Paper,
        Self::Rods,
        Self::Strings,
        Self::Integrators,
        Self::Tree,
        Self::Softening,
        Self::Ledger,
        Self::Friction,
        Self::SavedState,
        Self::Events,
        Self::Drag,
        Self::Series,
    ];

    fn name(self) -> &'static str {
        match self {
            Self::Paper => "paper",
            Self::Rods => "rods",
            Self::Strings => "strings",
            Self::Integrators => "integrators",
            Self::Tree => "tree",
            Self::Softening => "softening",
            Self::Ledger => "ledger",
            Self::Friction => "friction",
            Self::SavedState => "saved-state",
            Self::Events => "events",
            Self::Drag => "drag",
            Self::Series => "series",
        }
    }

    /// What the group proves, in one line.
    fn statement(self) -> &'static str {
        match self {
            Self::Paper => {
                "the paper's section 4 (kinematics, collision, ramps, springs, inverse-square bounces) against closed forms"
            }
            Self::Rods => {
                "a rod pendulum keeps the elliptic-integral period at any amplitude; rods between unequal masses keep momentum and the centre of mass"
            }
            Self::Strings => {
                "a string goes slack where its tension vanishes, the ball flies on the parabola, and the string snaps taut where the parabola meets its length"
            }
            Self::Integrators => {
                "each integrator converges at its order (halving the step divides the error by 2^order); the symplectic ones keep a bounded energy error"
            }
            Self::Tree => {
                "the Barnes–Hut tree's forces and potential energy agree with the direct sum"
            }
            Self::Softening => {
                "both pair laws are softened alike in the motion, the energy and the probe"
            }
            Self::Ledger => {
                "the energy ledger books what damping, friction and impacts take; the books close"
            }
            Self::Friction => {
                "friction on ramps: g(sin θ − μ cos θ), held while tan θ ≤ μ, stopping at v₀²/2μg"
            }
            Self::SavedState => "a saved state reopens and continues its run",
            Self::Events => {
                "events are located inside a step: a landing, a pendulum's turning points, a spring's maxima at their closed-form instants"
            }
            Self::Drag => {
                "air resistance: linear drag's exponentials, quadratic drag's tanh fall to the terminal speed, and the energy it takes in the books"
            }
            Self::Series => {
                "laws measured as series: a pendulum's period against its amplitude, a baseball's range against its angle with drag"
            }
        }
    }
}

pub(crate) fn validate(args: &ValidateArgs) -> Result<(), Failure> {
    if !(args.tolerance.is_finite() && args.tolerance > 0.0) {
        return Err(Failure::Input(format!(
            "--tolerance must be a number greater than 0; got {}",
            args.tolerance
        )));
    }
    if let Some(directory) = &args.out {
        std::fs::create_dir_all(directory).map_err(|e| {
            Failure::Input(format!(
                "cannot create the directory '{}': {e}",
                directory.display()
            ))
        })?;
    }
    let mut report = report::Report::new(args.tolerance);
    let mut figures = Vec::new();
    let groups: Vec<Group> = Group::ALL
        .into_iter()
        .filter(|g| args.only.is_empty() || args.only.contains(g))
        .collect();
    for &group in &groups {
        report.group = group.name();
        let (report, figures) = (&mut report, &mut figures);
        match group {
            Group::Paper => {
                experiments::processing_time(report)?;
                experiments::kinematics(report)?;
                experiments::collision(report)?;
                experiments::ramps(report)?;
                experiments::springs(report, figures)?;
                experiments::inverse_square(report, figures)?;
                paper_method::paper_method(report, figures)?;
            }
            Group::Rods => ties::rods(report)?,
            Group::Strings => ties::strings(report, figures)?,
            Group::Integrators => methods::integrators(report, figures)?,
            Group::Tree => methods::tree(report)?,
            Group::Softening => methods::softening(report)?,
            Group::Ledger => books::ledger(report)?,
            Group::Friction => books::friction(report)?,
            Group::SavedState => books::saved_state(report)?,
            Group::Events => events::events(report)?,
            Group::Drag => drag::drag(report)?,
            Group::Series => series::series(report)?,
        }
    }
    let statements: Vec<(&str, &str)> = groups.iter().map(|g| (g.name(), g.statement())).collect();
    let overview = report.groups(&statements);
    let summary = report.summary();
    #[expect(clippy::print_stdout, reason = "the command's report")]
    {
        println!(
            "NewtonLab against theory: the paper's experiments (section 4) and every claim since{}{}",
            report::Report::render_text(&overview),
            report.to_text()
        );
        println!("\n{summary}");
    }
    if let Some(directory) = &args.out {
        let mut markdown = format!(
            "# NewtonLab validation report\n\nRun by `newtonlab validate`: the experiments of the paper's section 4 \
             (tolerance {:e}) and every claim since, in groups, each check against a closed-form result \
             or a computation written apart from the simulation's, to the tolerance stated beside it.\n{}{}",
            args.tolerance,
            report::Report::render_markdown(&overview),
            report.to_markdown()
        );
        markdown.push_str("\n## Figures\n\n");
        for figure in &figures {
            plots::draw(figure, directory)
                .map_err(|e| Failure::Input(format!("cannot draw a figure: {e}")))?;
            let _ = write!(
                markdown,
                "### {}\n\n![{}]({})\n\n",
                figure.title, figure.title, figure.file
            );
        }
        let _ = write!(markdown, "## Result\n\n{summary}\n");
        let path = directory.join("report.md");
        std::fs::write(&path, markdown)
            .map_err(|e| Failure::Input(format!("cannot write '{}': {e}", path.display())))?;
        #[expect(clippy::print_stdout, reason = "the command's report")]
        {
            println!("wrote {} and {} figures", path.display(), figures.len());
        }
    }
    if report.failures().next().is_some() {
        return Err(Failure::Simulation(summary));
    }
    Ok(())
}
