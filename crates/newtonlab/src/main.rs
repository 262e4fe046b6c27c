//! `newtonlab`: the command line of `NewtonLab`. With no subcommand it opens the app; `run`,
//! `sweep`, `check`, `lesson`, `examples`, `bench` and `validate` are headless.
//!
//! Exit codes, for every subcommand: 0 success; 1 the simulation failed (a non-finite
//! value: the message names the particle and the time); 2 bad input (arguments or scene:
//! every problem listed, each with line and column where the file has them).

/// `println!` for a command's report: a reader that stops early (`newtonlab examples |
/// head -1`) ends the command quietly with success, as a closed pipe ends any Unix tool,
/// where `println!` panics.
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::write_line(format_args!($($arg)*))
    };
}

mod bench;
mod lesson;
mod plots;
mod run;
mod scene_source;
mod sweep;
mod validate;

use std::io::Write as _;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use newtonlab_i18n::{Language, tr_text as say};

/// `NewtonLab`: a 2D physics sandbox. Without a subcommand, opens the app.
#[derive(Debug, Parser)]
#[command(name = "newtonlab", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// The language of the messages (and of the app): en, de or es. Without it, the
    /// system's (LANG), or English.
    #[arg(long, global = true, value_name = "LANG", value_parser = parse_language)]
    lang: Option<Language>,
}

/// `--lang`: a language NewtonLab speaks, by its code (`de`, or a locale like `de_AT`).
fn parse_language(code: &str) -> Result<Language, String> {
    Language::from_locale(code).ok_or_else(|| {
        let codes: Vec<&str> = Language::ALL.iter().map(|l| l.code()).collect();
        format!(
            "'{code}' is not a language NewtonLab speaks; choose {}",
            codes.join(", ")
        )
    })
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run a scene and write its trajectory as CSV.
    Run(run::RunArgs),
    /// Vary a scene's values over ranges, run each, and write one CSV row of measures per run.
    Sweep(sweep::SweepArgs),
    /// Check a scene file and list every problem with it.
    Check {
        /// A scene file (.toml or .json), or example:NAME for a built-in scene.
        scene: String,
    },
    /// Check a student's answers to a scene's lesson against the simulation, or list its
    /// questions.
    Lesson(lesson::LessonArgs),
    /// Print a link that opens a scene, its lesson included, in the browser build.
    Link {
        /// A scene file (.toml or .json), or example:NAME for a built-in scene.
        scene: String,
        /// The address where the browser build is served.
        #[arg(long, value_name = "URL", default_value = newtonlab_app::share::DEFAULT_ADDRESS)]
        address: String,
    },
    /// List the built-in example scenes.
    Examples,
    /// Measure simulation speed (steps per second, pair interactions per second).
    Bench(bench::BenchArgs),
    /// Reproduce the paper's experiments (section 4) against theory.
    Validate(validate::ValidateArgs),
    /// Open the app on a given scene (what `newtonlab` alone does on the welcome scene).
    App(AppArgs),
}

#[derive(Debug, clap::Args)]
struct AppArgs {
    /// A scene file, or example:NAME; the welcome scene when absent.
    scene: Option<String>,
    /// Start playing at once.
    #[arg(long)]
    play: bool,
    /// Play, measure this many frames, print the frame times and close.
    #[arg(long, value_name = "N")]
    measure_frames: Option<usize>,
    /// Open in projector mode: the canvas alone, with large text (F11 switches).
    #[arg(long)]
    projector: bool,
    /// With --measure-frames, also print the mean frame time of every N frames.
    #[arg(long, value_name = "N")]
    report_every: Option<usize>,
    /// Draw the particles' electric or gravitational field as arrows (Measure menu).
    #[arg(long, value_enum, value_name = "FIELD")]
    field_view: Option<FieldView>,
}

/// The fields the app can draw.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
enum FieldView {
    Electric,
    Gravitational,
}

/// Why a command failed, and the exit code that says so.
#[derive(Debug)]
pub(crate) enum Failure {
    /// Exit 1: the simulation failed, or did not match theory.
    Simulation(String),
    /// Exit 2: bad arguments or a bad scene.
    Input(String),
}

impl Failure {
    fn exit(self) -> ExitCode {
        let (code, message) = match self {
            Self::Simulation(message) => (1, message),
            Self::Input(message) => (2, message),
        };
        eprintln!("{message}");
        ExitCode::from(code)
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let language = cli.lang.unwrap_or_else(Language::of_system);
    newtonlab_i18n::set_language(language);
    let result = match cli.command {
        None => open_app(
            &AppArgs {
                scene: None,
                play: false,
                measure_frames: None,
                projector: false,
                report_every: None,
                field_view: None,
            },
            cli.lang,
        ),
        Some(Command::App(args)) => open_app(&args, cli.lang),
        Some(Command::Run(args)) => run::run(&args),
        Some(Command::Sweep(args)) => sweep::sweep(&args),
        Some(Command::Check { scene }) => check(&scene),
        Some(Command::Lesson(args)) => lesson::lesson(&args),
        Some(Command::Link { scene, address }) => link(&scene, &address),
        Some(Command::Examples) => {
            examples();
            Ok(())
        }
        Some(Command::Bench(args)) => bench::bench(&args),
        Some(Command::Validate(args)) => validate::validate(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => failure.exit(),
    }
}

/// Opens the app; `language`, when given on the command line, is the one it speaks
/// (otherwise the one chosen in it last time, or the system's).
fn open_app(args: &AppArgs, language: Option<Language>) -> Result<(), Failure> {
    let mut app = match &args.scene {
        None => newtonlab_app::App::default(),
        Some(source) => {
            let scene = scene_source::load(source)?;
            let title = scene.name.clone();
            let mut app = newtonlab_app::App::new(scene);
            if source.starts_with("example:") || scene_source::is_link(source) {
                app.document.label = title;
            } else {
                app.document.mark_saved(source.clone());
            }
            app
        }
    };
    // Unsaved work is kept in the platform's data directory (NEWTONLAB_DATA_DIR
    // overrides it: for tests, and for a portable install).
    let data = std::env::var_os("NEWTONLAB_DATA_DIR")
        .map(std::path::PathBuf::from)
        .or_else(newtonlab_app::autosave::Autosave::default_dir);
    if let Some(dir) = data {
        app = app.with_autosave(newtonlab_app::autosave::Autosave::in_dir(
            dir,
            newtonlab_app::autosave::INTERVAL,
        ));
    }
    app = app.with_launch(newtonlab_app::Launch {
        play: args.play || args.measure_frames.is_some(),
        measure_frames: args.measure_frames,
        projector: args.projector,
        report_every: args.report_every,
        field_view: args.field_view.map(|f| match f {
            FieldView::Electric => newtonlab_app::FieldKind::Electric,
            FieldView::Gravitational => newtonlab_app::FieldKind::Gravitational,
        }),
        language,
    });
    newtonlab_app::run_native(app)
        .map_err(|e| Failure::Simulation(say("cli-no-window", &[("error", &e.to_string())])))
}

/// Prints the share link to `source` in the browser build at `address`.
fn link(source: &str, address: &str) -> Result<(), Failure> {
    let scene = scene_source::load(source)?;
    let link = newtonlab_app::share::link(address, &scene).map_err(Failure::Input)?;
    out!("{link}");
    Ok(())
}

fn check(source: &str) -> Result<(), Failure> {
    let scene = scene_source::load(source)?;
    {
        out!(
            "{}",
            say(
                "cli-check-ok",
                &[
                    ("source", source),
                    ("particles", &scene.particles.len().to_string()),
                    ("springs", &scene.springs.len().to_string()),
                    ("ramps", &scene.ramps.len().to_string()),
                    ("integrator", scene.simulation.integrator.as_str()),
                    ("step", &scene.simulation.time_step.to_string()),
                ],
            )
        );
        for body in &scene.bodies {
            out!("{}", describe_body(body));
        }
        for joint in &scene.joints {
            out!("{}", describe_joint(&scene, joint));
        }
        for force in &scene.forces {
            let on = if force.on.is_empty() {
                say("cli-check-force-everything", &[])
            } else {
                force.on.join(", ")
            };
            let words = [
                ("name", force.name.as_str()),
                ("fx", &force.fx),
                ("fy", &force.fy),
                ("on", &on),
            ];
            let id = if force.potential.is_some() {
                "cli-check-force-potential"
            } else {
                "cli-check-force"
            };
            out!("{}", say(id, &words));
        }
        if scene.world.magnetic_field != 0.0 {
            let charged = scene.particles.iter().filter(|p| p.charge != 0.0).count();
            let (field, charged) = (nine_digits(scene.world.magnetic_field), charged.to_string());
            let words = [("field", field.as_str()), ("charged", charged.as_str())];
            out!("{}", say("cli-check-magnetic", &words));
        }
        if let Some(lost) = physics::Simulation::new(&scene)
            .ok()
            .and_then(|s| s.joints_start_loss())
        {
            out!(
                "{}",
                say("cli-check-joints-start", &[("lost", &nine_digits(lost))])
            );
        }
        if let Some(lesson) = &scene.lesson {
            let words = [
                ("title", lesson.title.as_str()),
                ("sliders", &lesson.sliders.len().to_string()),
                ("questions", &lesson.questions.len().to_string()),
            ];
            out!("{}", say("cli-check-lesson", &words));
        }
        if !scene.bodies.is_empty() {
            out!("{}", say("cli-check-bodies-free", &[]));
        }
        if scene.simulation.pair_forces == physics::PairForces::Tree {
            let charged = scene.particles.iter().filter(|p| p.charge != 0.0).count();
            let angle = scene.simulation.opening_angle.to_string();
            let id = if charged > 0 && scene.world.electrostatics {
                "cli-check-tree-and-charges"
            } else {
                "cli-check-tree"
            };
            out!(
                "{}",
                say(id, &[("angle", &angle), ("charged", &charged.to_string())])
            );
        }
    }
    Ok(())
}
/// A body's mass properties as `check` says them, to nine significant digits.
/// `x` to nine significant digits, as the shortest text of the number rounded to them.
fn nine_digits(x: f64) -> String {
    let rounded: f64 = format!("{x:.8e}").parse().unwrap_or(x);
    format!("{}", rounded + 0.0)
}

/// A pin's body and its moment of inertia about the pin (I + m d², what its swing
/// obeys), or the two bodies a hinge joins; where, and its motor.
fn describe_joint(scene: &physics::Scene, joint: &physics::Joint) -> String {
    let at = joint.at.to_dvec2();
    let place = format!("({}, {})", nine_digits(at.x), nine_digits(at.y));
    let motor = match joint.motor {
        None => String::new(),
        Some(physics::Motor::Torque(torque)) => say(
            "cli-check-motor-torque",
            &[("torque", &nine_digits(torque))],
        ),
        Some(physics::Motor::Spin { spin, max_torque }) => say(
            "cli-check-motor-spin",
            &[
                ("spin", &nine_digits(spin)),
                ("torque", &nine_digits(max_torque)),
            ],
        ),
    };
    if let physics::JointKind::Pulley {
        a, radius, mass, ..
    } = &joint.kind
    {
        return say(
            "cli-check-pulley",
            &[
                ("name", &joint.name),
                ("a", a),
                ("b", &joint.body),
                ("radius", &nine_digits(*radius)),
                ("mass", &nine_digits(*mass)),
                ("at", &place),
            ],
        );
    }
    let text = if let Some(a) = joint.other() {
        say(
            "cli-check-hinge",
            &[
                ("name", &joint.name),
                ("a", a),
                ("b", &joint.body),
                ("at", &place),
            ],
        )
    } else {
        let body = scene.bodies.iter().find(|b| b.name == joint.body);
        let about = body.map_or(f64::NAN, |b| {
            b.inertia() + b.total_mass() * b.position.to_dvec2().distance_squared(at)
        });
        say(
            "cli-check-pin",
            &[
                ("name", &joint.name),
                ("body", &joint.body),
                ("at", &place),
                ("inertia", &nine_digits(about)),
            ],
        )
    };
    text + &motor
}

fn describe_body(body: &physics::Body) -> String {
    let number = nine_digits;
    let outline = body.outline();
    let moments = physics::moments(&outline);
    // A centroid within rounding of the frame's origin is at it.
    let size = moments.area.abs().sqrt();
    let centroid = moments
        .centroid
        .map(|c| if c.abs() <= 1e-12 * size { 0.0 } else { c });
    let shape = match &body.shape {
        physics::Shape::Box => format!("box {} × {} m", number(body.width), number(body.height)),
        physics::Shape::Polygon(vertices) => format!("polygon of {} vertices", vertices.len()),
    };
    say(
        "cli-check-body",
        &[
            ("name", &body.name),
            ("shape", &shape),
            ("area", &number(moments.area)),
            ("mass", &number(body.total_mass())),
            ("inertia", &number(body.inertia())),
            (
                "centroid",
                &format!("({}, {})", number(centroid.x), number(centroid.y)),
            ),
        ],
    )
}

fn examples() {
    for example in physics::EXAMPLES {
        let title = example
            .scene()
            .ok()
            .and_then(|scene| scene.name)
            .unwrap_or_default();
        out!("example:{:<24} {title}", example.name);
    }
}

/// Writes one line of a command's report to standard output ([`out!`]). A closed pipe
/// ends the process with success; another failure to write ends it with exit 1, said.
fn write_line(line: std::fmt::Arguments<'_>) {
    if let Err(error) = writeln!(std::io::stdout().lock(), "{line}") {
        if error.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        eprintln!("newtonlab: cannot write to standard output: {error}");
        std::process::exit(1);
    }
}
