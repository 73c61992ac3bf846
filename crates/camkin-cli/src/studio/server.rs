//! The studio's HTTP server: the page and its JSON API, on 127.0.0.1 by default.
//!
//! | route | answer |
//! |---|---|
//! | `GET /` `GET /studio.js` `GET /studio.css` | the page (embedded) |
//! | `GET /api/session` | `{name, toml, folder}`: the mechanism opened |
//! | `POST /api/analyze` | [`api::analyze`]: [`super::AnalyzeRequest`] → `{toml, result}` ([`super::answer::Analysis`]); `toml` is the text with dragged nodes written in |
//! | `POST /api/compare` | [`api::compare`]: [`super::CompareRequest`] → [`super::answer::Compare`] |
//! | `POST /api/csv` | [`super::AnalyzeRequest`] → the analysis table as `camkin analyze` writes it |
//! | `POST /api/report` | [`super::AnalyzeRequest`] → the report's HTML |
//!
//! Every refusal is JSON `{"error": {kind, message, line, column}}` with a 4xx status (503 when
//! busy beyond the wait allowed). Bodies are limited in size; each computation is estimated and
//! refused over its time limit; at most [`Limits::workers`] computations run at once and the
//! others wait their turn, so no request is dropped while the server keeps up.

use super::source::Source;
use super::{api, assets, Limits, StudioError};
use axum::body::Bytes;
use axum::extract::rejection::BytesRejection;
use axum::extract::{DefaultBodyLimit, State};
use axum::http::{header, HeaderMap, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use axum::Router;
use serde::Serialize;
use std::sync::Arc;
use std::time::Duration;
use tokio::sync::Semaphore;

/// The mechanism a server opened.
#[derive(Debug, Clone)]
pub struct Session {
    /// its text
    pub text: String,
    /// its name and folder
    pub source: Source,
}

#[derive(Debug)]
struct AppState {
    session: Session,
    limits: Limits,
    turns: Semaphore,
}

/// A refusal answered: its status and its JSON error body.
#[derive(Debug)]
struct Refused(StudioError);

impl From<StudioError> for Refused {
    fn from(e: StudioError) -> Self {
        Self(e)
    }
}

impl IntoResponse for Refused {
    fn into_response(self) -> Response {
        let status = StatusCode::from_u16(self.0.status()).unwrap_or(StatusCode::BAD_REQUEST);
        json(status, &self.0.body())
    }
}

fn json<T: Serialize>(status: StatusCode, value: &T) -> Response {
    match serde_json::to_vec(value) {
        Ok(body) => (status, [(header::CONTENT_TYPE, "application/json")], body).into_response(),
        Err(e) => (
            StatusCode::INTERNAL_SERVER_ERROR,
            [(header::CONTENT_TYPE, "application/json")],
            format!(
                "{{\"error\":{{\"kind\":\"internal\",\"message\":{:?}}}}}",
                e.to_string()
            ),
        )
            .into_response(),
    }
}

/// [`json`], gzipped when the client takes it (`Accept-Encoding: gzip`, as every browser
/// does): the analysis answers a drag with some 100 kB of JSON, a fifth of that compressed.
fn json_gzip<T: Serialize>(status: StatusCode, value: &T, headers: &HeaderMap) -> Response {
    use std::io::Write;
    let takes_gzip = headers
        .get_all(header::ACCEPT_ENCODING)
        .iter()
        .filter_map(|v| v.to_str().ok())
        .any(|v| {
            v.split(',')
                .any(|e| e.trim().split(';').next() == Some("gzip"))
        });
    let body = match (takes_gzip, serde_json::to_vec(value)) {
        (true, Ok(body)) => body,
        _ => return json(status, value),
    };
    // fast compression: the answer is made on every drag
    let mut z = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    match z.write_all(&body).and_then(|()| z.finish()) {
        Ok(zipped) => (
            status,
            [
                (header::CONTENT_TYPE, "application/json"),
                (header::CONTENT_ENCODING, "gzip"),
                (header::VARY, "accept-encoding"),
            ],
            zipped,
        )
            .into_response(),
        Err(_) => (status, [(header::CONTENT_TYPE, "application/json")], body).into_response(),
    }
}

/// The router of the studio for `session` within `limits`.
pub fn router(session: Session, limits: Limits) -> Router {
    let state = Arc::new(AppState {
        session,
        limits,
        turns: Semaphore::new(limits.workers.max(1)),
    });
    Router::new()
        .route("/", get(index))
        .route("/index.html", get(index))
        .route("/studio.js", get(script))
        .route("/studio.css", get(style))
        .route("/api/session", get(session_info))
        .route("/api/analyze", post(analyze))
        .route("/api/compare", post(compare))
        .route("/api/csv", post(csv))
        .route("/api/report", post(report))
        .fallback(not_found)
        .method_not_allowed_fallback(not_allowed)
        .layer(DefaultBodyLimit::max(limits.max_body_bytes))
        .with_state(state)
}

/// How long a connection may stay open, requests and idle time together.
pub const CONNECTION_TIMEOUT: Duration = Duration::from_secs(600);

/// Serves the studio on `listener` until the process ends (a runtime of as many threads as
/// computations run at once). Each connection is served by hyper with a header timeout
/// ([`Limits::header_seconds`]) and a lifetime ([`CONNECTION_TIMEOUT`]); at most
/// [`Limits::max_connections`] are open at once, well within the process's file descriptors,
/// so that accepting never fails for lack of them. A connection beyond them is admitted by
/// closing the oldest one that is not answering a request (idle, or still without its headers),
/// so that slow clients holding every place cannot keep a normal request waiting; only where
/// every connection is being answered is the new one closed.
pub fn serve(
    listener: std::net::TcpListener,
    session: Session,
    limits: Limits,
) -> std::io::Result<()> {
    listener.set_nonblocking(true)?;
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(limits.workers.max(1))
        .enable_all()
        .build()?;
    runtime.block_on(async move {
        let listener = tokio::net::TcpListener::from_std(listener)?;
        let app = router(session, limits);
        let open = Arc::new(Connections::default());
        let header = Duration::from_secs_f64(limits.header_seconds.max(0.001));
        loop {
            let stream = match listener.accept().await {
                Ok((stream, _)) => stream,
                // out of descriptors, a connection reset before it was taken: try again shortly
                Err(_) => {
                    tokio::time::sleep(Duration::from_millis(20)).await;
                    continue;
                }
            };
            if !open.make_room(limits.max_connections.max(1)) {
                drop(stream);
                continue;
            }
            let busy = Arc::new(std::sync::atomic::AtomicUsize::new(0));
            let counted = busy.clone();
            let router = app.clone();
            // the connection is answering while a request's response is being made
            let service =
                tower::service_fn(move |request: hyper::Request<hyper::body::Incoming>| {
                    let answering = Answering::start(counted.clone());
                    let mut router = router.clone();
                    async move {
                        let response = tower::Service::call(&mut router, request).await;
                        drop(answering);
                        response
                    }
                });
            let service = hyper_util::service::TowerToHyperService::new(service);
            let id = open.next_id();
            let registry = open.clone();
            let task = tokio::spawn(async move {
                let io = hyper_util::rt::TokioIo::new(stream);
                let mut http = hyper::server::conn::http1::Builder::new();
                http.timer(hyper_util::rt::TokioTimer::new())
                    .header_read_timeout(header);
                let _ =
                    tokio::time::timeout(CONNECTION_TIMEOUT, http.serve_connection(io, service))
                        .await;
                registry.remove(id);
            });
            open.insert(id, busy, task.abort_handle());
        }
    })
}

/// The connections open, oldest first: each one's number, whether it is answering a request,
/// and the handle that closes it.
#[derive(Default)]
struct Connections {
    open: std::sync::Mutex<std::collections::VecDeque<Connection>>,
    next: std::sync::atomic::AtomicU64,
}

struct Connection {
    id: u64,
    busy: Arc<std::sync::atomic::AtomicUsize>,
    close: tokio::task::AbortHandle,
}

impl Connections {
    fn next_id(&self) -> u64 {
        self.next.fetch_add(1, std::sync::atomic::Ordering::Relaxed)
    }

    fn list(&self) -> std::sync::MutexGuard<'_, std::collections::VecDeque<Connection>> {
        self.open
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    fn insert(
        &self,
        id: u64,
        busy: Arc<std::sync::atomic::AtomicUsize>,
        close: tokio::task::AbortHandle,
    ) {
        let mut open = self.list();
        // a connection that ended before it was listed is not listed
        if !close.is_finished() {
            open.push_back(Connection { id, busy, close });
        }
    }

    fn remove(&self, id: u64) {
        self.list().retain(|c| c.id != id);
    }

    /// Whether a new connection may open: below `max`, or after closing the oldest that is not
    /// answering a request.
    fn make_room(&self, max: usize) -> bool {
        let mut open = self.list();
        open.retain(|c| !c.close.is_finished());
        if open.len() < max {
            return true;
        }
        let idle = open
            .iter()
            .position(|c| c.busy.load(std::sync::atomic::Ordering::SeqCst) == 0);
        match idle.and_then(|k| open.remove(k)) {
            Some(c) => {
                c.close.abort();
                true
            }
            None => false,
        }
    }
}

/// A request being answered on a connection (counted while it lives, so a request dropped
/// half-way is no longer counted).
struct Answering(Arc<std::sync::atomic::AtomicUsize>);

impl Answering {
    fn start(busy: Arc<std::sync::atomic::AtomicUsize>) -> Self {
        busy.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
        Self(busy)
    }
}

impl Drop for Answering {
    fn drop(&mut self) {
        self.0.fetch_sub(1, std::sync::atomic::Ordering::SeqCst);
    }
}

/// A response that is `body` of type `content_type`, never cached (the page follows the binary).
fn asset(content_type: &'static str, body: &'static str) -> Response {
    (
        [
            (header::CONTENT_TYPE, content_type),
            (header::CACHE_CONTROL, "no-store"),
        ],
        body,
    )
        .into_response()
}

async fn index() -> Response {
    asset("text/html; charset=utf-8", assets::INDEX_HTML)
}

async fn script() -> Response {
    asset("text/javascript; charset=utf-8", assets::STUDIO_JS)
}

async fn style() -> Response {
    asset("text/css; charset=utf-8", assets::STYLE_CSS)
}

async fn not_found(uri: axum::http::Uri) -> Refused {
    Refused(StudioError::NotFound {
        message: format!("no such page or API: {}", uri.path()),
    })
}

async fn not_allowed(method: axum::http::Method, uri: axum::http::Uri) -> Response {
    let e = StudioError::BadRequest {
        message: format!("{method} is not allowed on {}", uri.path()),
    };
    json(StatusCode::METHOD_NOT_ALLOWED, &e.body())
}

#[derive(Serialize)]
struct SessionInfo<'a> {
    name: &'a str,
    toml: &'a str,
    folder: bool,
}

async fn session_info(State(state): State<Arc<AppState>>) -> Response {
    let s = &state.session;
    json(
        StatusCode::OK,
        &SessionInfo {
            name: &s.source.name,
            toml: &s.text,
            folder: s.source.folder.is_some(),
        },
    )
}

fn read_body(body: Result<Bytes, BytesRejection>, limits: &Limits) -> Result<Bytes, StudioError> {
    body.map_err(|r| {
        if r.status() == StatusCode::PAYLOAD_TOO_LARGE {
            StudioError::TooLarge {
                message: format!(
                    "the request is larger than {} MiB",
                    limits.max_body_bytes >> 20
                ),
            }
        } else {
            StudioError::BadRequest {
                message: format!("cannot read the request: {}", r.body_text()),
            }
        }
    })
}

/// Runs `work` on the blocking pool when its turn comes.
async fn run<T: Send + 'static>(
    state: &AppState,
    work: impl FnOnce() -> Result<T, StudioError> + Send + 'static,
) -> Result<T, StudioError> {
    let wait = state.limits.max_wait_seconds;
    let _turn = tokio::time::timeout(Duration::from_secs_f64(wait), state.turns.acquire())
        .await
        .map_err(|_| StudioError::Busy {
            message: format!("the server is busy: no turn within {wait} s; try again"),
        })?
        .map_err(|_| StudioError::Busy {
            message: "the server is stopping".into(),
        })?;
    tokio::task::spawn_blocking(work)
        .await
        .map_err(|e| StudioError::BadRequest {
            message: format!("the computation failed: {e}"),
        })?
}

/// The analysis request's parsing, public here for the fuzz target.
pub use api::check_analysis_request;

/// Runs `work` on an analysis request's text (with its dragged nodes written in), step and
/// pressure-angle limit, all checked first.
async fn with_analysis_request<T: Send + 'static>(
    state: &AppState,
    body: Result<Bytes, BytesRejection>,
    work: impl FnOnce(String, &Source, f64, f64, &Limits) -> Result<T, StudioError> + Send + 'static,
) -> Result<T, StudioError> {
    let bytes = read_body(body, &state.limits)?;
    let (toml, step_deg, limit) = check_analysis_request(&bytes, &state.limits)?;
    let (source, limits) = (state.session.source.clone(), state.limits);
    run(state, move || work(toml, &source, step_deg, limit, &limits)).await
}

/// A download: `body` of `content_type`, saved as `filename`.
fn attachment(content_type: &'static str, filename: &'static str, body: String) -> Response {
    (
        [
            (header::CONTENT_TYPE, content_type.to_string()),
            (
                header::CONTENT_DISPOSITION,
                format!("attachment; filename=\"{filename}\""),
            ),
        ],
        body,
    )
        .into_response()
}

async fn analyze(
    State(state): State<Arc<AppState>>,
    headers: HeaderMap,
    body: Result<Bytes, BytesRejection>,
) -> Result<Response, Refused> {
    let answer = with_analysis_request(&state, body, |toml, source, step_deg, limit, limits| {
        api::analyze_checked(toml, source, step_deg, limit, limits)
    })
    .await?;
    Ok(json_gzip(StatusCode::OK, &answer, &headers))
}

async fn compare(
    State(state): State<Arc<AppState>>,
    body: Result<Bytes, BytesRejection>,
) -> Result<Response, Refused> {
    let bytes = read_body(body, &state.limits)?;
    let (req, step_deg, nodes) = api::check_compare_request(&bytes, &state.limits)?;
    let (source, l) = (state.session.source.clone(), state.limits);
    let out = run(&state, move || {
        api::compare_checked(&req, step_deg, &nodes, &source, &l)
    })
    .await?;
    Ok(json(StatusCode::OK, &out))
}

async fn csv(
    State(state): State<Arc<AppState>>,
    body: Result<Bytes, BytesRejection>,
) -> Result<Response, Refused> {
    let text = with_analysis_request(&state, body, |toml, source, step_deg, _, limits| {
        super::report::csv(&toml, source, step_deg, limits)
    })
    .await?;
    Ok(attachment("text/csv; charset=utf-8", "analysis.csv", text))
}

async fn report(
    State(state): State<Arc<AppState>>,
    body: Result<Bytes, BytesRejection>,
) -> Result<Response, Refused> {
    let html = with_analysis_request(&state, body, |toml, source, step_deg, limit, limits| {
        super::report::html(&toml, source, step_deg, limit, limits)
    })
    .await?;
    Ok(attachment("text/html; charset=utf-8", "report.html", html))
}
