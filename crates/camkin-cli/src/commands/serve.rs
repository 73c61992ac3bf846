//! `camkin serve`: the cam studio in the browser, and `camkin report`: its self-contained HTML
//! report.

use crate::args::RevolutionStep;
use crate::output::write_atomic;
use crate::studio::server::{serve, Session};
use crate::studio::source::Source;
use crate::studio::{report, Limits, StudioError};
use crate::{mechfile, Failure};
use anyhow::anyhow;
use std::net::{IpAddr, Ipv4Addr, SocketAddr, TcpListener};
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub struct ServeArgs {
    /// Mechanism file (TOML); without it, the paper's built-in cam. Points files are read from
    /// its folder only.
    pub mechanism: Option<PathBuf>,
    /// Port to listen on (0: any free port).
    #[arg(long, short = 'p', value_name = "PORT", default_value_t = 8765)]
    pub port: u16,
    /// Address to listen on. The studio has no login: keep it on this machine unless the network
    /// is yours.
    #[arg(long, value_name = "IP", default_value_t = IpAddr::V4(Ipv4Addr::LOCALHOST))]
    pub host: IpAddr,
}

#[derive(Debug, clap::Args)]
pub struct ReportArgs {
    /// Mechanism file (TOML); without it, the paper's built-in cam.
    pub mechanism: Option<PathBuf>,
    /// The HTML file to write (replaced only once it is complete).
    #[arg(long, short = 'o', value_name = "FILE", default_value = "report.html")]
    pub output: PathBuf,
    /// Cam-angle step of the plots, degrees (at least 0.05).
    #[arg(long, value_name = "DEG", default_value = "0.5")]
    pub step: RevolutionStep,
    /// Pressure-angle limit of the checks, degrees.
    #[arg(long, value_name = "DEG", default_value_t = 30.0, value_parser = crate::args::real, allow_negative_numbers = true)]
    pub pressure_limit: f64,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
}

/// The text and source of the mechanism to open.
fn open(path: Option<&PathBuf>) -> Result<Session, Failure> {
    match path {
        Some(p) => {
            let (_, text) = mechfile::read_text(p).map_err(|e| Failure::Input(anyhow!(e)))?;
            let folder = p
                .parent()
                .map(|d| {
                    if d.as_os_str().is_empty() {
                        ".".into()
                    } else {
                        d.to_path_buf()
                    }
                })
                .unwrap_or_else(|| PathBuf::from("."));
            // its points files are inputs too
            if let Ok(spec) = mechfile::parse_spec(&text, "") {
                for f in spec.files() {
                    crate::output::note_input(&folder.join(f));
                }
            }
            Ok(Session {
                text,
                source: Source {
                    name: p
                        .file_name()
                        .map_or_else(|| p.display().to_string(), |s| s.to_string_lossy().into()),
                    folder: Some(folder),
                },
            })
        }
        None => Ok(Session {
            text: mechfile::PAPER_TOML.to_string(),
            source: Source {
                name: "paper.toml".into(),
                folder: None,
            },
        }),
    }
}

/// In the environment of the server process that `camkin serve` starts and watches over.
const WORKER_ENV: &str = "CAMKIN_SERVE_WORKER";

/// Restarts allowed within [`RESTART_WINDOW`] before `camkin serve` gives up.
const RESTARTS: usize = 5;
const RESTART_WINDOW: std::time::Duration = std::time::Duration::from_secs(60);

/// `camkin serve`: a watcher process that starts the server as a process of its own and starts
/// it again if it dies (a request that runs out of memory under a cap aborts the process: the
/// next request is served by a new one, on the same port). The server tells the watcher its
/// port once it listens; only then is the URL printed.
pub fn run_serve(args: &ServeArgs) -> Result<(), Failure> {
    if std::env::var_os(WORKER_ENV).is_some() {
        return run_worker(args);
    }
    let session = open(args.mechanism.as_ref())?;
    let checked = crate::studio::source::read(&session.text, &session.source, &Limits::default());
    if let Err(e) = checked {
        let e = match e {
            StudioError::Input { message, .. } => message,
            other => format!("{other:?}"),
        };
        crate::say!(
            "camkin: warning: the mechanism has an error; the studio opens it to be mended: {e}"
        );
    }
    let mut port = args.port;
    let mut restarts: std::collections::VecDeque<std::time::Instant> = Default::default();
    let mut first = true;
    loop {
        let (mut child, local) = start_worker(args, port)?;
        port = local.port();
        if first {
            let shown = match local.ip() {
                IpAddr::V4(ip) if ip.is_unspecified() => {
                    SocketAddr::new(Ipv4Addr::LOCALHOST.into(), local.port())
                }
                _ => local,
            };
            // the URL on stdout (scripts read it); the rest on stderr
            crate::out!("http://{shown}/\n")?;
            crate::say!(
                "camkin studio: {} at http://{shown}/ — open it in a browser; Ctrl-C stops the server",
                session.source.name
            );
            first = false;
        }
        let status = child
            .wait()
            .map_err(|e| Failure::Internal(anyhow!("cannot wait for the server: {e}")))?;
        if status.success() || stopped_by_user(&status) {
            return Ok(());
        }
        let now = std::time::Instant::now();
        restarts.retain(|t| now.duration_since(*t) < RESTART_WINDOW);
        if restarts.len() >= RESTARTS {
            return Err(Failure::Internal(anyhow!(
                "the server stopped {} times within {} s (last: {status}); giving up",
                RESTARTS + 1,
                RESTART_WINDOW.as_secs()
            )));
        }
        restarts.push_back(now);
        crate::say!(
            "camkin: the studio's server stopped ({status}), most likely out of memory on a request; starting it again on port {port}"
        );
    }
}

/// Whether the server ended because the user stopped it (Ctrl-C, a termination signal).
fn stopped_by_user(status: &std::process::ExitStatus) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if matches!(status.signal(), Some(2 | 15)) {
            return true;
        }
    }
    status.code() == Some(130)
}

/// Starts the server process on `port`; returns it and the address it listens on (its first
/// line of output), or its error when it could not listen.
fn start_worker(args: &ServeArgs, port: u16) -> Result<(std::process::Child, SocketAddr), Failure> {
    use std::io::BufRead;
    let exe = std::env::current_exe()
        .map_err(|e| Failure::Internal(anyhow!("cannot find the camkin program: {e}")))?;
    let mut cmd = std::process::Command::new(exe);
    cmd.arg("serve");
    if let Some(m) = &args.mechanism {
        cmd.arg(m);
    }
    cmd.args([
        "--host",
        &args.host.to_string(),
        "--port",
        &port.to_string(),
    ])
    .env(WORKER_ENV, "1")
    .stdout(std::process::Stdio::piped());
    let mut child = cmd
        .spawn()
        .map_err(|e| Failure::Internal(anyhow!("cannot start the server: {e}")))?;
    let mut line = String::new();
    if let Some(out) = child.stdout.take() {
        let _ = std::io::BufReader::new(out).read_line(&mut line);
    }
    match line.trim().parse::<SocketAddr>() {
        Ok(addr) => Ok((child, addr)),
        Err(_) => {
            // it could not listen: it said why on stderr
            let status = child.wait().ok();
            Err(match status.and_then(|s| s.code()) {
                Some(2) => Failure::Input(anyhow!("the server could not start (see above)")),
                _ => Failure::Internal(anyhow!("the server could not start")),
            })
        }
    }
}

/// The server process: listens, tells the watcher its address on stdout, serves; ends when the
/// watcher is gone (killed: no server is left behind holding the port).
fn run_worker(args: &ServeArgs) -> Result<(), Failure> {
    let session = open(args.mechanism.as_ref())?;
    let addr = SocketAddr::new(args.host, args.port);
    let listener = TcpListener::bind(addr).map_err(|e| {
        Failure::Input(anyhow!(
            "cannot listen on {addr}: {e}{}",
            if e.kind() == std::io::ErrorKind::AddrInUse {
                " (another program uses it: pass --port with another number, or 0 for any free port)"
            } else {
                ""
            }
        ))
    })?;
    let local = listener
        .local_addr()
        .map_err(|e| Failure::Internal(anyhow!(e)))?;
    crate::out!("{local}\n")?;
    #[cfg(unix)]
    {
        let watcher = std::os::unix::process::parent_id();
        std::thread::spawn(move || loop {
            std::thread::sleep(std::time::Duration::from_millis(200));
            if std::os::unix::process::parent_id() != watcher {
                std::process::exit(0);
            }
        });
    }
    serve(listener, session, Limits::default())
        .map_err(|e| Failure::Internal(anyhow!("the server stopped: {e}")))
}

pub fn run_report(args: &ReportArgs) -> Result<(), Failure> {
    let session = open(args.mechanism.as_ref())?;
    crate::output::refuse_input(&args.output, "-o").map_err(Failure::Input)?;
    let limit = crate::studio::pressure_limit(Some(args.pressure_limit)).map_err(|_| {
        Failure::Input(anyhow!(
            "--pressure-limit: {} must be in (0, 90) degrees",
            camkin::human::human(args.pressure_limit)
        ))
    })?;
    let limits = if args.work.large {
        Limits {
            max_seconds: f64::INFINITY,
            max_request_bytes: f64::INFINITY,
            ..Limits::default()
        }
    } else {
        Limits {
            // a report is made once, on purpose: allow it longer than a click in the studio
            max_seconds: 60.0,
            max_request_bytes: camkin::work::BYTES_LIMIT,
            ..Limits::default()
        }
    };
    let step_deg = crate::studio::step(Some(args.step.deg()), &limits).map_err(|_| {
        Failure::Input(anyhow!(
            "--step: {}° must be from {}° to 10° and divide 360°",
            camkin::human::human(args.step.deg()),
            limits.min_step_deg
        ))
    })?;
    let html = report::html(&session.text, &session.source, step_deg, limit, &limits).map_err(
        |e| match e {
            StudioError::Input { message, .. } => Failure::Input(anyhow!(message)),
            StudioError::TooMuch { message } => {
                Failure::Input(anyhow!("{message}; pass --large to make it anyway"))
            }
            other => Failure::Input(anyhow!(other.body().error.message)),
        },
    )?;
    write_atomic(Some(&args.output), |w| Ok(w.write_all(html.as_bytes())?))
        .map_err(Failure::output)?;
    crate::say!(
        "camkin: wrote {} ({} kB): open it in any browser, no network needed",
        args.output.display(),
        html.len() / 1000
    );
    Ok(())
}
