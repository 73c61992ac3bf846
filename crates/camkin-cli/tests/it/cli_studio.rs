//! `camkin report` and `camkin serve` as a newcomer runs them: the report is one file that needs
//! nothing else; bad input exits 2 with the reason and leaves no file.

use crate::common::run;
use crate::common::{examples, predicate, written};

#[test]
fn the_report_is_one_file_that_fetches_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("review.html");
    run!("report", examples().join("paper-dynamics.toml"), "-o", &out)
        .assert()
        .success()
        .stderr(predicate::str::contains("no network needed"));
    let html = std::fs::read_to_string(&out).unwrap();
    assert!(html.contains("window.CAMKIN_REPORT = {"));
    assert!(
        html.contains("\"dynamics\":{"),
        "the forces are in the report"
    );
    // nothing to fetch: no script or image by address, no link out, no style import
    for fetched in ["src=\"", "href=\"http", "url(", "@import"] {
        assert!(!html.contains(fetched), "{fetched}");
    }
    // only the page's own files were written
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(names.len(), 1);
}

#[test]
fn bad_report_input_exits_2_and_writes_nothing() {
    let (dir, bad) = written(
        "bad.toml",
        std::fs::read_to_string(examples().join("paper.toml"))
            .unwrap()
            .replace("speed_rpm = 1000.0", "speed_rpm = 0.0"),
    );
    let out = dir.path().join("r.html");
    run!("report", &bad, "-o", &out).refused("bad.toml:6:13");
    run!("report", "--step", "0.01", "-o", &out).refused("--step: 0.01°");
    run!("report", "--pressure-limit", "90", "-o", &out).refused("--pressure-limit");
    run!("report", "-o", dir.path().join("no/such/dir/r.html"))
        .assert()
        .code(2);
    assert!(!out.exists());
}

#[test]
fn serve_refuses_a_port_in_use_and_a_missing_file() {
    let taken = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let port = taken.local_addr().unwrap().port().to_string();
    run!("serve", "--port", &port).refused("pass --port");
    run!("serve", "no-such-file.toml", "--port", "0").refused("no-such-file.toml");
}
