//! The studio's server without a browser: JSON errors with 4xx statuses, size and work limits,
//! reads confined to the opened folder, malformed requests, many clients at once, and the CSV
//! download equal to `camkin analyze` (a simulated system's to `camkin simulate`, its force
//! panel the same numbers).

use crate::common::examples;
use crate::common::run;
use camkin_cli::studio::server::{serve, Session};
use camkin_cli::studio::source::Source;
use camkin_cli::studio::Limits;
use serde_json::{json, Value};
use std::io::{Read, Write};
use std::net::{SocketAddr, TcpListener, TcpStream};
use std::path::Path;
use std::time::Duration;

/// A server on a free port of 127.0.0.1 for the file at `path` (the paper's cam when `None`).
fn start(path: Option<&Path>, limits: Limits) -> SocketAddr {
    let (text, source) = match path {
        Some(p) => (
            std::fs::read_to_string(p).unwrap(),
            Source {
                name: p.file_name().unwrap().to_string_lossy().into(),
                folder: Some(p.parent().unwrap().to_path_buf()),
            },
        ),
        None => (
            camkin_cli::mechfile::PAPER_TOML.to_string(),
            Source {
                name: "paper.toml".into(),
                folder: None,
            },
        ),
    };
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let addr = listener.local_addr().unwrap();
    std::thread::spawn(move || serve(listener, Session { text, source }, limits));
    addr
}

/// Sends raw bytes, returns (status, body).
fn raw(addr: SocketAddr, request: &[u8]) -> (u16, String) {
    let mut s = TcpStream::connect(addr).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(60))).unwrap();
    s.write_all(request).unwrap();
    let mut out = Vec::new();
    let _ = s.read_to_end(&mut out);
    let text = String::from_utf8_lossy(&out).to_string();
    let status = text
        .split_whitespace()
        .nth(1)
        .and_then(|c| c.parse().ok())
        .unwrap_or(0);
    let body = text
        .split_once("\r\n\r\n")
        .map(|(_, b)| b.to_string())
        .unwrap_or_default();
    (status, body)
}

fn request(addr: SocketAddr, method: &str, path: &str, body: &str) -> (u16, String) {
    raw(
        addr,
        format!(
            "{method} {path} HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{body}",
            body.len()
        )
        .as_bytes(),
    )
}

fn post(addr: SocketAddr, path: &str, body: &Value) -> (u16, Value) {
    let (status, text) = request(addr, "POST", path, &body.to_string());
    (
        status,
        serde_json::from_str(&text).unwrap_or(Value::String(text)),
    )
}

/// The error of a refused request, checked to be the JSON form.
fn error(status: u16, v: &Value) -> (u16, String, Value, Value) {
    let e = &v["error"];
    assert!(e["message"].is_string(), "not a JSON error: {v}");
    (
        status,
        e["kind"].as_str().unwrap().to_string(),
        e["line"].clone(),
        e["column"].clone(),
    )
}

fn paper() -> String {
    camkin_cli::mechfile::PAPER_TOML.to_string()
}

#[test]
fn every_refusal_is_json_with_a_4xx_status() {
    let addr = start(None, Limits::default());
    let (s, b) = request(addr, "GET", "/nope", "");
    let v: Value = serde_json::from_str(&b).unwrap();
    assert_eq!((s, v["error"]["kind"].as_str()), (404, Some("not-found")));
    let (s, b) = request(addr, "GET", "/api/analyze", "");
    assert_eq!(s, 405);
    assert!(b.contains("\"error\""), "{b}");
    let (s, b) = request(addr, "POST", "/api/analyze", "not json");
    assert_eq!(s, 400, "{b}");
    assert!(b.contains("bad-request"));
    let (s, v) = post(addr, "/api/analyze", &json!({"toml": paper(), "colour": 1}));
    assert_eq!(error(s, &v).0, 400, "an unknown field: {v}");
    let (s, v) = post(addr, "/api/analyze", &json!({"toml": 5}));
    assert_eq!(error(s, &v).0, 400);
    // the mechanism's errors carry their line and column
    let bad = paper().replace("speed_rpm = 1000.0", "speed_rpm = -5.0");
    let (s, v) = post(addr, "/api/analyze", &json!({ "toml": bad }));
    assert_eq!(error(s, &v), (422, "input".into(), json!(6), json!(13)));
    let (s, v) = post(
        addr,
        "/api/analyze",
        &json!({"toml": paper().replace("[follower]", "[follower")}),
    );
    assert_eq!(error(s, &v).0, 422);
    assert_eq!(error(s, &v).2, json!(15));
    // arguments out of range
    for body in [
        json!({"toml": paper(), "step_deg": 0.001}),
        json!({"toml": paper(), "step_deg": 7.0}),
        json!({"toml": paper(), "pressure_limit_deg": 95.0}),
        json!({"toml": paper(), "nodes": [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]], "step_deg": -1}),
    ] {
        let (s, v) = post(addr, "/api/analyze", &body);
        assert_eq!(error(s, &v).0, 400, "{body}: {v}");
    }
    for body in [
        json!({"toml": paper(), "nodes": [0]}),
        json!({"toml": paper(), "nodes": [3, 1_000_000]}),
        json!({"toml": paper(), "nodes": [3, 4, 5, 6, 7]}),
    ] {
        let (s, v) = post(addr, "/api/compare", &body);
        assert_eq!(error(s, &v).0, 400, "{body}: {v}");
    }
    // nodes can be moved only on an inline spline
    let circle = "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100.0\n[cam.profile]\nkind = \"circle\"\ncenter = [1.0, 0.0]\nradius = 20.0\n[follower]\nkind = \"translating-roller\"\nroller_radius = 5.0\n";
    let (s, v) = post(
        addr,
        "/api/analyze",
        &json!({"toml": circle, "nodes": [[1.0, 2.0]]}),
    );
    assert_eq!(error(s, &v).0, 400);
    // and the server still answers
    let (s, v) = post(addr, "/api/analyze", &json!({ "toml": circle }));
    assert_eq!(s, 200, "{v}");
}

#[test]
fn malformed_http_and_cut_requests_leave_the_server_serving() {
    let addr = start(None, Limits::default());
    let (s, _) = raw(addr, b"GARBAGE\r\n\r\n");
    assert!(s == 400 || s == 0, "{s}");
    // a body shorter than its length, then the connection dropped
    {
        let mut c = TcpStream::connect(addr).unwrap();
        c.write_all(
            b"POST /api/analyze HTTP/1.1\r\nHost: x\r\nContent-Length: 100000\r\n\r\n{\"toml\": ",
        )
        .unwrap();
    }
    let (s, _) = raw(addr, b"\x00\x01\x02\xff\r\n\r\n");
    assert!(s == 400 || s == 0);
    let (s, v) = post(addr, "/api/analyze", &json!({ "toml": paper() }));
    assert_eq!(s, 200, "{v}");
}

#[test]
fn a_body_over_the_limit_is_refused_before_it_is_read() {
    let limits = Limits {
        max_body_bytes: 4096,
        ..Limits::default()
    };
    let addr = start(None, limits);
    let big = format!("{}\n# {}\n", paper(), "x".repeat(10_000));
    let (s, v) = post(addr, "/api/analyze", &json!({ "toml": big }));
    assert_eq!(error(s, &v).1, "too-large");
    assert_eq!(s, 413);
}

#[test]
fn work_over_the_time_limit_is_refused_with_the_estimate() {
    // a budget of 0.1 s, for a wavy (not convex) profile of 20 000 nodes: every angle searches
    // its samples (about 38 µs a step estimated) and the request asks for 0.05° steps (0.27 s)
    let addr = start(
        None,
        Limits {
            max_seconds: 0.1,
            ..Limits::default()
        },
    );
    let pts: Vec<String> = (0..20_000)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / 20_000.0;
            let r = 40.0 + 3.0 * (9.0 * t).sin();
            format!("[{:.6}, {:.6}]", r * t.cos(), r * t.sin())
        })
        .collect();
    let text = format!(
        "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100.0\n[cam.profile]\nkind = \"spline\"\npoints = [{}]\n[follower]\nkind = \"translating-knife\"\n",
        pts.join(", ")
    );
    let t = std::time::Instant::now();
    let (s, v) = post(
        addr,
        "/api/analyze",
        &json!({ "toml": text, "step_deg": 0.05 }),
    );
    assert_eq!(error(s, &v).1, "too-much-work", "{v}");
    let msg = v["error"]["message"].as_str().unwrap();
    assert!(
        msg.contains("would take about") && msg.contains(" s"),
        "{msg}"
    );
    // refused up front, before the work (a bound, not a timing)
    assert!(t.elapsed() < Duration::from_secs(30));
}

/// Issue 44: the server caps the memory one request may hold. A mechanism whose search index
/// would be over the cap (here 10 MB; a 2 000-node spline cam, about 10.4 MB) is refused with
/// the estimate before it is built, for the analysis, the table and the report alike, and the
/// server goes on answering.
#[test]
fn a_request_over_the_memory_cap_is_refused_before_it_is_built() {
    let addr = start(
        None,
        Limits {
            max_request_bytes: 1e7,
            ..Limits::default()
        },
    );
    let pts: Vec<String> = (0..2_000)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / 2_000.0;
            format!("[{:.6}, {:.6}]", 40.0 * t.cos(), 30.0 * t.sin())
        })
        .collect();
    let text = format!(
        "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100.0\n[cam.profile]\nkind = \"spline\"\npoints = [{}]\n[follower]\nkind = \"translating-flat\"\n",
        pts.join(", ")
    );
    for route in ["/api/analyze", "/api/csv", "/api/report"] {
        let (s, v) = post(addr, route, &json!({ "toml": text }));
        assert_eq!(error(s, &v).1, "too-much-work", "{route}: {v}");
        assert_eq!(s, 422);
        let msg = v["error"]["message"].as_str().unwrap();
        assert!(
            msg.contains("cam.profile") && msg.contains("would take about") && msg.contains("MB"),
            "{route}: {msg}"
        );
    }
    let (s, v) = post(addr, "/api/analyze", &json!({ "toml": paper() }));
    assert_eq!(s, 200, "{v}");
}

#[test]
fn points_files_are_read_only_inside_the_opened_folder() {
    let dir = tempfile::tempdir().unwrap();
    let folder = dir.path().join("cams");
    std::fs::create_dir(&folder).unwrap();
    std::fs::copy(examples().join("profile.csv"), folder.join("inside.csv")).unwrap();
    std::fs::copy(
        examples().join("profile.csv"),
        dir.path().join("secret.csv"),
    )
    .unwrap();
    #[cfg(unix)]
    std::os::unix::fs::symlink(dir.path().join("secret.csv"), folder.join("link.csv")).unwrap();
    let mech = |path: &str| {
        format!("length_unit = \"cm\"\n[cam]\nspeed_rpm = 1000.0\n[cam.profile]\nkind = \"points-file\"\npath = {path:?}\n[follower]\nkind = \"translating-flat\"\n")
    };
    std::fs::write(folder.join("cam.toml"), mech("inside.csv")).unwrap();
    let addr = start(Some(&folder.join("cam.toml")), Limits::default());
    let (s, v) = post(addr, "/api/analyze", &json!({ "toml": mech("inside.csv") }));
    assert_eq!(s, 200, "{v}");
    let secret = dir.path().join("secret.csv").display().to_string();
    for path in [
        "../secret.csv",
        "./../secret.csv",
        "sub/../../secret.csv",
        secret.as_str(),
        "/etc/passwd",
        "link.csv",
    ] {
        let (s, v) = post(addr, "/api/analyze", &json!({ "toml": mech(path) }));
        assert_eq!(error(s, &v).1, "input", "{path}: {v}");
        let msg = v["error"]["message"].as_str().unwrap();
        assert!(
            msg.contains("cam.profile.path") && msg.contains("folder"),
            "{path}: {msg}"
        );
        assert!(v["error"]["line"].is_number(), "{v}");
    }
    // the built-in cam has no folder: no file at all
    let addr = start(None, Limits::default());
    let (s, v) = post(addr, "/api/analyze", &json!({ "toml": mech("inside.csv") }));
    assert_eq!(error(s, &v).1, "input");
    assert!(v["error"]["message"]
        .as_str()
        .unwrap()
        .contains("no folder is open"));
}

#[test]
fn many_clients_at_once_all_get_the_same_answer() {
    let addr = start(None, Limits::default());
    let body = json!({ "toml": paper() });
    let strip = |mut v: Value| {
        v["result"]["server_ms"] = Value::Null;
        v
    };
    let (s, first) = post(addr, "/api/analyze", &body);
    assert_eq!(s, 200);
    let first = strip(first);
    let threads: Vec<_> = (0..16)
        .map(|_| {
            let body = body.clone();
            std::thread::spawn(move || {
                (0..8)
                    .map(|_| post(addr, "/api/analyze", &body))
                    .collect::<Vec<_>>()
            })
        })
        .collect();
    let mut answered = 0;
    for t in threads {
        for (s, v) in t.join().unwrap() {
            assert_eq!(s, 200);
            assert!(strip(v) == first, "an answer differs");
            answered += 1;
        }
    }
    assert_eq!(answered, 128);
}

#[test]
fn the_csv_download_is_what_camkin_analyze_writes() {
    let addr = start(None, Limits::default());
    let (s, csv) = request(
        addr,
        "POST",
        "/api/csv",
        &json!({"toml": paper(), "step_deg": 0.5}).to_string(),
    );
    assert_eq!(s, 200);
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("a.csv");
    run!(
        "analyze",
        examples().join("paper.toml"),
        "--angles",
        "0:360:0.5",
        "-o",
        &out
    )
    .assert();
    let expected = std::fs::read_to_string(&out).unwrap_or_default();
    assert_eq!(csv, expected);
}

/// Issue 47: the analysis the page draws is at the page's precision and gzipped for a client
/// that takes it: the paper cam's answer is under a quarter of its 426 502 bytes at full
/// precision, decompresses to the plain answer, and its series are the download's to 1e-7 of
/// their largest magnitude.
#[test]
fn the_pages_answer_is_rounded_gzipped_and_the_downloads_figures() {
    use std::io::Read;
    let addr = start(None, Limits::default());
    let body = json!({"toml": paper(), "step_deg": 0.5}).to_string();
    let mut s = TcpStream::connect(addr).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(60))).unwrap();
    write!(
        s,
        "POST /api/analyze HTTP/1.1\r\nHost: x\r\nAccept-Encoding: gzip, deflate, br\r\nContent-Type: application/json\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    )
    .unwrap();
    let mut raw = Vec::new();
    let _ = s.read_to_end(&mut raw);
    let split = raw.windows(4).position(|w| w == b"\r\n\r\n").unwrap();
    let head = String::from_utf8_lossy(&raw[..split]).to_lowercase();
    assert!(head.contains("content-encoding: gzip"), "{head}");
    let zipped = &raw[split + 4..];
    assert!(zipped.len() * 4 < 426_502, "{} bytes", zipped.len());
    let mut text = String::new();
    flate2::read::GzDecoder::new(zipped)
        .read_to_string(&mut text)
        .unwrap();
    let (st, plain) = post(
        addr,
        "/api/analyze",
        &json!({"toml": paper(), "step_deg": 0.5}),
    );
    assert_eq!(st, 200);
    // the same answer but for the server's time
    let (mut zipped, mut plain2) = (serde_json::from_str::<Value>(&text).unwrap(), plain.clone());
    zipped["result"]["server_ms"] = Value::Null;
    plain2["result"]["server_ms"] = Value::Null;
    assert_eq!(zipped, plain2);
    // the download's figures, at the page's precision
    let (_, csv) = request(addr, "POST", "/api/csv", &body);
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = header
        .iter()
        .position(|h| *h == "acceleration_cm_s2")
        .unwrap();
    let column: Vec<f64> = lines
        .map(|l| l.split(',').nth(col).unwrap().parse().unwrap())
        .collect();
    let top = column.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let series = plain["result"]["series"].as_array().unwrap();
    let acc = series.iter().find(|x| x["key"] == "acceleration").unwrap();
    for (k, x) in column.iter().enumerate() {
        let page = acc["values"][k].as_f64().unwrap();
        assert!(
            (page - x).abs() <= 1e-7 * top,
            "row {k}: {page} against {x}"
        );
    }
}

#[test]
fn a_dragged_node_is_written_into_the_text_analysed() {
    let addr = start(None, Limits::default());
    let mut nodes = vec![
        [5.0, 0.0],
        [3.4, 2.8],
        [0.6, 3.4],
        [-1.5, 2.6],
        [-2.8, 1.0],
        [-2.8, -1.0],
        [-1.5, -2.6],
        [0.6, -3.4],
        [3.4, -2.8],
    ];
    nodes[1] = [3.6, 3.0];
    let (s, v) = post(
        addr,
        "/api/analyze",
        &json!({"toml": paper(), "nodes": nodes}),
    );
    assert_eq!(s, 200, "{v}");
    let text = v["toml"].as_str().unwrap();
    assert!(text.contains("[3.6, 3.0]") && !text.contains("[3.4, 2.8]"));
    assert!(text.starts_with("# The paper's cam"), "comments kept");
    // the answer is the analysis of that text
    let (_, again) = post(addr, "/api/analyze", &json!({ "toml": text }));
    assert_eq!(again["result"]["series"], v["result"]["series"]);
    assert_eq!(v["result"]["nodes"], json!(nodes));
}

/// Issue 44: clients that open connections and never finish their headers cannot lock anyone
/// out: each is closed after the header timeout, connections beyond the cap are closed at once,
/// and a normal client is answered within a few timeouts (1 100 such clients used to hold the
/// server for good).
#[test]
fn clients_that_never_finish_their_headers_cannot_lock_anyone_out() {
    let limits = Limits {
        header_seconds: 1.0,
        max_connections: 64,
        ..Limits::default()
    };
    let addr = start(None, limits);
    let slow: Vec<TcpStream> = (0..300)
        .filter_map(|_| {
            let mut s = TcpStream::connect(addr).ok()?;
            let _ = s.write_all(b"GET /api/session HTTP/1.1\r\nHost: x\r\n");
            Some(s)
        })
        .collect();
    assert!(slow.len() > 64);
    let t0 = std::time::Instant::now();
    loop {
        let (status, _) = raw(
            addr,
            b"GET /api/session HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n",
        );
        if status == 200 {
            break;
        }
        assert!(t0.elapsed() < Duration::from_secs(10), "locked out");
        std::thread::sleep(Duration::from_millis(50));
    }
    // the slow clients' connections were closed by the server
    let mut closed = 0;
    for mut s in slow {
        s.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
        let mut buf = [0u8; 256];
        // closed: an end of file (or a reset), not a read that times out waiting
        match s.read(&mut buf) {
            Err(e)
                if matches!(
                    e.kind(),
                    std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut
                ) => {}
            _ => closed += 1,
        }
    }
    assert_eq!(closed, 300);
}

/// Issue 63: while slow clients hold every place (64 connections without their headers, a cap
/// of 64), a normal request is admitted at once by closing the oldest of them, and answered on
/// its first try within the header timeout — not reset, and not after waiting for timeouts.
#[test]
fn a_normal_request_is_served_at_once_while_slow_clients_hold_every_place() {
    let limits = Limits {
        header_seconds: 5.0,
        max_connections: 64,
        ..Limits::default()
    };
    let addr = start(None, limits);
    let slow: Vec<TcpStream> = (0..200)
        .filter_map(|_| {
            let mut s = TcpStream::connect(addr).ok()?;
            let _ = s.write_all(b"GET /api/session HTTP/1.1\r\nHost: x\r\n");
            Some(s)
        })
        .collect();
    assert_eq!(slow.len(), 200);
    // the server has taken them all (each beyond the cap closing the oldest)
    std::thread::sleep(Duration::from_millis(300));
    for k in 0..5 {
        let t0 = std::time::Instant::now();
        let (status, _) = raw(
            addr,
            b"GET /api/session HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n",
        );
        assert_eq!(status, 200, "request {k}");
        assert!(
            t0.elapsed() < Duration::from_secs(2),
            "request {k}: {:?}",
            t0.elapsed()
        );
    }
    drop(slow);
}

/// Issue 44: the server survives any one request. Under a memory cap (`ulimit -v`, 700 MB of
/// address space) a request within the server's own estimate (an 80 000-node cam, about 420 MB
/// estimated) runs out of memory and aborts the server process; `camkin serve` starts it again on
/// the same port, says so, and the next request is answered. Killing `camkin serve` leaves no
/// server behind.
#[cfg(unix)]
#[test]
fn the_server_survives_a_request_that_runs_out_of_memory() {
    use std::io::BufRead;
    let mut child = std::process::Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -v 700000; exec '{}' serve --port 0",
            env!("CARGO_BIN_EXE_camkin")
        ))
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut url = String::new();
    std::io::BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut url)
        .unwrap();
    let addr: SocketAddr = url
        .trim()
        .trim_start_matches("http://")
        .trim_end_matches('/')
        .parse()
        .unwrap();
    let n = 80_000;
    let pts: Vec<String> = (0..n)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / n as f64;
            format!("[{:.6}, {:.6}]", 40.0 * t.cos(), 30.0 * t.sin())
        })
        .collect();
    let text = format!(
        "length_unit = \"mm\"\n[cam]\nspeed_rpm = 100.0\n[cam.profile]\nkind = \"spline\"\npoints = [{}]\n[follower]\nkind = \"translating-flat\"\n",
        pts.join(", ")
    );
    let (s, _) = post(addr, "/api/analyze", &json!({ "toml": text }));
    assert_ne!(
        s, 200,
        "the request was expected to run out of memory under the cap"
    );
    // the next request is answered by the server started again (it may take a moment: a
    // request sent while the old process is still dying is lost with it)
    let mut answered = false;
    for _ in 0..50 {
        if std::net::TcpStream::connect(addr).is_ok() {
            let (s, _) = post(addr, "/api/analyze", &json!({ "toml": paper() }));
            if s == 200 {
                answered = true;
                break;
            }
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    assert!(answered, "no answer within 5 s of the crash");
    let watcher = child.id();
    child.kill().unwrap();
    let _ = child.wait();
    let mut err = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    assert!(err.contains("starting it again on port"), "{err}");
    // the server process notices its watcher is gone and ends, freeing the port
    let mut freed = false;
    for _ in 0..50 {
        std::thread::sleep(Duration::from_millis(100));
        if TcpStream::connect(addr).is_err() {
            freed = true;
            break;
        }
    }
    assert!(freed, "a server was left behind by watcher {watcher}");
}

/// The valve train (a system with `[dynamics]`): the studio simulates it as `camkin simulate`
/// does, its CSV download is that command's bytes, its force panel those numbers, and its
/// impacts are listed at their angles.
#[test]
fn a_simulated_systems_force_panel_and_csv_are_camkin_simulates() {
    let path = examples().join("valve-train.toml");
    let addr = start(Some(&path), Limits::default());
    let text = std::fs::read_to_string(&path).unwrap();
    let (s, csv) = request(
        addr,
        "POST",
        "/api/csv",
        &json!({"toml": text, "step_deg": 0.5}).to_string(),
    );
    assert_eq!(s, 200, "{csv}");
    let out = run!("simulate", &path, "--step", "0.5").assert().success();
    let expected = String::from_utf8_lossy(&out.get_output().stdout).to_string();
    assert_eq!(csv, expected);
    let (s, v) = post(
        addr,
        "/api/analyze",
        &json!({"toml": text, "step_deg": 0.5}),
    );
    assert_eq!(s, 200, "{v}");
    let v = &v["result"];
    assert_eq!(v["simulated"], true);
    let series = v["series"].as_array().unwrap();
    let force = series
        .iter()
        .find(|x| x["key"] == "cam on roller_force")
        .unwrap_or_else(|| panic!("{series:?}"));
    assert_eq!(force["unit"], "N");
    // the command's column, value for value at the page's precision (within 1e-7 of the
    // column's largest magnitude: `studio::page_precision`; the download above keeps every digit)
    let mut lines = expected.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = header
        .iter()
        .position(|h| *h == "cam_on_roller_force_N")
        .unwrap();
    let column: Vec<f64> = lines
        .map(|line| line.split(',').nth(col).unwrap().parse().unwrap())
        .collect();
    let top = column.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for (k, x) in column.iter().enumerate() {
        let page = force["values"][k].as_f64().unwrap();
        assert!(
            (page - x).abs() <= 1e-7 * top,
            "row {k}: {page} against {x}"
        );
    }
    let torque = series.iter().find(|x| x["unit"] == "N·m").unwrap();
    assert!(torque["label"].as_str().unwrap().contains("torque"));
    let events = v["events"].as_array().unwrap();
    assert!(
        events[0]["message"].as_str().unwrap().contains("\"seat\"")
            && events[0]["angle_deg"].as_f64().unwrap() > 150.0,
        "{events:?}"
    );
}
