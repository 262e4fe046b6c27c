//! `newtonlab validate`: the paper's section 4 reproduced against theory. Each experiment
//! runs built-in scenes and prints the paper's table with simulation, theory and error
//! columns; with `--out DIR` it also writes `DIR/report.md` and the paper's figures as
//! PNG. Exit 0 when every error is within the tolerance, 1 otherwise, listing the misses.

mod experiments;
mod paper_method;
mod plots;
mod report;
mod theory;

use std::fmt::Write as _;
use std::path::PathBuf;

use crate::Failure;

#[derive(Debug, clap::Args)]
pub(crate) struct ValidateArgs {
    /// Also write report.md and the figures (PNG) into this directory.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// The largest error allowed, relative to the quantity's scale.
    #[arg(long, value_name = "X", default_value_t = 1e-6)]
    tolerance: f64,
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
    experiments::processing_time(&mut report)?;
    experiments::kinematics(&mut report)?;
    experiments::collision(&mut report)?;
    experiments::ramps(&mut report)?;
    experiments::springs(&mut report, &mut figures)?;
    experiments::inverse_square(&mut report, &mut figures)?;
    paper_method::paper_method(&mut report, &mut figures)?;

    let summary = report.summary();
    #[expect(clippy::print_stdout, reason = "the command's report")]
    {
        println!(
            "NewtonLab against the paper's experiments (section 4){}",
            report.to_text()
        );
        println!("\n{summary}");
    }
    if let Some(directory) = &args.out {
        let mut markdown = format!(
            "# NewtonLab validation report\n\nThe experiments of the paper's section 4, run by `newtonlab validate`, \
             each against a closed-form result. Tolerance {:e}.\n{}",
            args.tolerance,
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
