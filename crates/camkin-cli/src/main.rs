//! The `camkin` command. Exit codes: 0 success, 1 internal failure, 2 bad input.

use camkin_cli::commands::{
    analyze, bench, compare, contacts, deviation, forces, mesh, plot, profile, serve, simulate,
    synth,
};
use camkin_cli::Failure;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Exact cam-follower kinematics by the contact method of K. Lee (2005).
#[derive(Debug, Parser)]
#[command(name = "camkin", version, about, long_about = None, after_help = camkin_cli::exit_codes::sentence(None))]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Follower position, velocity, acceleration and contact data at cam angles, as CSV.
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin analyze                              # the paper's cam, one revolution in 1° steps\n  camkin analyze examples/paper.toml --at 0,45\n  camkin analyze cam.toml --angles 0:90:0.5 -o out.csv\n\nColumns: see docs/commands.md.", "analyze")
    )]
    Analyze(analyze::Args),
    /// A gear pair read as gears: transmission error and its rates, tooth pairs in contact,
    /// line of action, sliding and specific sliding at driver angles, as CSV.
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin mesh                                  # the built-in 20/42 pair, two mesh cycles\n  camkin mesh examples/gear-pair-tip-relief.toml --plot fig\n  camkin mesh pair.toml --angles 0:36:0.05 -o mesh.csv --format json\n\nThe contact ratio and the transmission error's range go to stderr. Columns: see docs/gears.md.", "mesh")
    )]
    Mesh(mesh::MeshArgs),
    /// Every contact between cam and follower at cam angles, one row each, with its sliding
    /// rates, normal accelerations and acceleration constraint row, as CSV.
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin contacts examples/gear-pair-20-42.toml --angles 0:18:0.5   # 3 or 4 contacts: both flanks touch without backlash\n  camkin contacts cam.toml --at 0,90 --format json\n\nThe first contact at each angle (contact = 0) is the follower's first touch; the others touch at\nthe same position within the touch tolerance. Each row holds row_cam·θ̈ + row_follower·q̈ = gamma.", "contacts")
    )]
    Contacts(contacts::ContactsArgs),
    /// The paper's study on its two built-in cams: CSV data, plots (SVG, PNG) and a summary.
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin paper                       # writes ./camkin-paper/{original,revised}/… and summary.md\n  camkin paper --out study --format json\n  camkin paper --step 0.1 --nodes 100,1000", "paper")
    )]
    Paper(compare::PaperArgs),
    /// The paper's study on any mechanism: interpolated against exact acceleration.
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin compare examples/paper-revised.toml\n  camkin compare cam.toml --nodes 360,3600 --step 0.1 --out study --zoom 5:10\n  camkin compare cam.toml --format json   # keys max_rel_error, mean_rel_error by N", "compare")
    )]
    Compare(compare::CompareArgs),
    /// Kinematics over a revolution, drawings of the mechanism and an animation (SVG, PNG).
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin plot                                  # the paper's cam into ./camkin-plot/\n  camkin plot examples/oscillating-roller.toml --out fig --at 0,45,90\n  camkin plot cam.toml --step 0.1 --frames 180\n\nWrites kinematics.{svg,png}, drawing_<angle>.{svg,png} and animation.svg.", "plot")
    )]
    Plot(plot::PlotArgs),
    /// In-process timings: contact method against the interpolation baseline.
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin bench                      # the paper's cam\n  camkin bench examples/oscillating-roller.toml --json", "bench")
    )]
    Bench(bench::BenchArgs),
    /// Dynamics: contact force, lift-off and impacts, with a [dynamics] section in the file (a mechanism or a system).
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin simulate examples/eccentric-flat-dynamics.toml --revolutions 3\n  camkin simulate cam.toml --revolutions 100 --out sim --format json\n\nTime series on stdout (or DIR/time_series.csv), events on stderr (and DIR/events.csv).", "simulate")
    )]
    Simulate(simulate::SimulateArgs),
    /// A cam synthesised from a motion program: profile (CSV, DXF, SVG), SVAJ plots, design checks.
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin synth examples/motion-roller.toml\n  camkin synth cam.toml --out design --step 0.25 --pressure-limit 25\n\nThe mechanism's profile must be kind = \"motion\".", "synth")
    )]
    Synth(synth::SynthArgs),
    /// Manufacturing output of any profile: polar table, pitch curve, cutter path, DXF of arcs.
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin profile examples/eccentric-roller.toml --out shop\n  camkin profile cam.toml --step 0.5 --tool-radius 8 --tolerance 0.0001\n\nWrites polar.csv, pitch.csv (rollers), cutter.csv (with --tool-radius), profile.dxf.", "profile")
    )]
    Profile(profile::ProfileArgs),
    /// Contact force, camshaft torque, jump speed, spring sizing and contact stress, with a
    /// [dynamics] section in the file (a form-closed follower: the load on each of its curves).
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin forces examples/eccentric-flat-dynamics.toml\n  camkin forces cam.toml --target-rpm 3000 --margin 20 --face-width 12 --materials steel,steel\n  camkin forces examples/fzg-c.toml            # a gear pair's loads (its [gear_loads])\n  camkin forces examples/valve-train.toml      # a system's forces and lubrication", "forces")
    )]
    Forces(Box<forces::ForcesArgs>),
    /// A measured profile (CMM points) against the design: radius, lift, velocity, acceleration.
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin deviation measured.csv --against cam.toml\n  camkin deviation measured.csv --against cam.toml --tolerance 0.002 --out dev\n\nThe points are smoothed by a Fourier series of the radius within --tolerance (the measurement's noise).", "deviation")
    )]
    Deviation(deviation::DeviationArgs),
    /// The cam studio in the browser: drag the profile's nodes or edit the file, watch the exact
    /// lift, velocity, acceleration, jerk, pressure angle and curvature react.
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin serve                          # the paper's cam at http://127.0.0.1:8765/\n  camkin serve examples/oscillating-roller.toml --port 9000\n\nPrints the URL on stdout; opens no browser by itself. Listens on 127.0.0.1 only unless --host says otherwise.", "serve")
    )]
    Serve(serve::ServeArgs),
    /// A self-contained HTML report of a mechanism (drawing, animation, plots, checks, inputs)
    /// for a design review: no network and no server needed to open it.
    #[command(
        after_help = camkin_cli::exit_codes::help("Examples:\n  camkin report examples/paper.toml -o report.html\n  camkin report cam.toml -o review.html --step 0.25 --pressure-limit 25", "report")
    )]
    Report(serve::ReportArgs),
}

/// True when a failure is only the reader of our output going away (`camkin … | head -1`).
fn broken_pipe(e: &anyhow::Error) -> bool {
    // the csv writer wraps its io errors without exposing them as a source: the message then
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
            || c.downcast_ref::<csv::Error>().is_some_and(|ce| {
                matches!(ce.kind(), csv::ErrorKind::Io(io) if io.kind() == std::io::ErrorKind::BrokenPipe)
            })
    })
}

fn main() -> ExitCode {
    // `println!` panics when the reader of stdout has gone away: end quietly then, as a closed
    // pipe is the reader's choice, not a failure (exit 0); any other panic keeps the default hook
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let payload = info.payload();
        let msg = payload
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| payload.downcast_ref::<&str>().copied())
            .unwrap_or("");
        if msg.contains("Broken pipe") {
            std::process::exit(0);
        }
        default_hook(info);
    }));
    // an interrupted run (Ctrl-C, SIGTERM) removes the temporary file of a write in progress
    // (the output it would have replaced stays as it was) and exits 130, as shells expect
    let _ = ctrlc::set_handler(|| {
        camkin_cli::output::remove_temporaries();
        std::process::exit(camkin_cli::exit_codes::INTERRUPTED.into());
    });
    let cli = Cli::parse();
    // `--large` also lets a mechanism be built whose search index is over the work limits
    let large = match &cli.command {
        Command::Analyze(a) => a.work.large,
        Command::Mesh(a) => a.work.large,
        Command::Contacts(a) => a.work.large,
        Command::Paper(a) => a.work.large,
        Command::Compare(a) => a.work.large,
        Command::Plot(a) => a.work.large,
        Command::Bench(a) => a.work.large,
        Command::Simulate(a) => a.work.large,
        Command::Synth(a) => a.work.large,
        Command::Profile(a) => a.work.large,
        Command::Forces(a) => a.work.large,
        Command::Deviation(a) => a.work.large,
        Command::Report(a) => a.work.large,
        Command::Serve(_) => false,
    };
    camkin_cli::mechfile::allow_large(large);
    let result = match cli.command {
        Command::Analyze(args) => analyze::run(&args),
        Command::Mesh(args) => mesh::run(&args),
        Command::Contacts(args) => contacts::run(&args),
        Command::Paper(args) => compare::run_paper(&args),
        Command::Compare(args) => compare::run_compare(&args),
        Command::Plot(args) => plot::run(&args),
        Command::Bench(args) => bench::run(&args),
        Command::Simulate(args) => simulate::run(&args),
        Command::Synth(args) => synth::run(&args),
        Command::Profile(args) => profile::run(&args),
        Command::Forces(args) => forces::run(&args),
        Command::Deviation(args) => deviation::run(&args),
        Command::Serve(args) => serve::run_serve(&args),
        Command::Report(args) => serve::run_report(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Input(e) | Failure::Internal(e)) if broken_pipe(&e) => ExitCode::SUCCESS,
        Err(Failure::Input(e)) => {
            camkin_cli::say!("error: {e:#}");
            ExitCode::from(camkin_cli::exit_codes::INPUT)
        }
        Err(Failure::Internal(e)) => {
            camkin_cli::say!("internal error: {e:#}");
            ExitCode::from(camkin_cli::exit_codes::INTERNAL)
        }
        Err(Failure::Check(e)) => {
            camkin_cli::say!("camkin: {e:#}");
            ExitCode::from(camkin_cli::exit_codes::CHECK)
        }
    }
}
