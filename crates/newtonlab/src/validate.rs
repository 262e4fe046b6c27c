//! `newtonlab validate`: every physical claim against theory, in groups
//! (`newtonlab_validation`). A summary of every group's worst error comes first. With
//! `--out DIR` it also writes `DIR/report.md` and the figures as PNG. Exit 0 when every
//! error is within its tolerance, 1 otherwise, listing the misses.

use std::fmt::Write as _;
use std::path::PathBuf;

use newtonlab_validation::report::Report;
use newtonlab_validation::{Group, validate as check_all};

use crate::{Failure, plots};

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
    #[arg(long, value_name = "GROUP", value_parser = group_names())]
    only: Vec<String>,
    /// Threads each simulation's step may use; every core when absent. The results are
    /// the same bits for any number.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u16).range(1..=1024))]
    threads: Option<u16>,
}

/// `--only`'s values: the groups' names, which clap lists in the help and checks.
fn group_names() -> clap::builder::PossibleValuesParser {
    clap::builder::PossibleValuesParser::new(Group::ALL.map(Group::name))
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
    let groups: Vec<Group> = Group::ALL
        .into_iter()
        .filter(|g| args.only.is_empty() || args.only.iter().any(|name| name == g.name()))
        .collect();
    let threads = args.threads.map_or_else(physics::every_core, usize::from);
    let (report, figures) =
        check_all(&groups, args.tolerance, threads).map_err(|failure| match failure {
            newtonlab_validation::Failure::Simulation(why) => Failure::Simulation(why),
            newtonlab_validation::Failure::Input(why) => Failure::Input(why),
        })?;
    let statements: Vec<(&str, &str)> = groups.iter().map(|g| (g.name(), g.statement())).collect();
    let overview = report.groups(&statements);
    let summary = report.summary();
    {
        out!(
            "NewtonLab against theory: the paper's experiments (section 4) and every claim since{}{}",
            Report::render_text(&overview),
            report.to_text()
        );
        out!("\n{summary}");
    }
    if let Some(directory) = &args.out {
        let mut markdown = format!(
            "# NewtonLab validation report\n\nRun by `newtonlab validate`: the experiments of the paper's section 4 \
             (tolerance {:e}) and every claim since, in groups, each check against a closed-form result \
             or a computation written apart from the simulation's, to the tolerance stated beside it.\n{}{}",
            args.tolerance,
            Report::render_markdown(&overview),
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
        {
            out!("wrote {} and {} figures", path.display(), figures.len());
        }
    }
    if report.failures().next().is_some() {
        return Err(Failure::Simulation(summary));
    }
    Ok(())
}
