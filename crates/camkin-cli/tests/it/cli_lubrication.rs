//! `camkin forces --oil …`: the lubrication table, page and summary, and its bad input.
use crate::common::*;
use std::path::Path;

/// The eccentric disc of `eccentric-flat-dynamics.toml` (R = 40 mm, e = 10 mm, flat face) at
/// 1000 rpm, where it stays on the cam.
fn slow_disc(dir: &Path) -> std::path::PathBuf {
    let slow = dir.join("slow.toml");
    std::fs::write(
        &slow,
        std::fs::read_to_string(examples().join("eccentric-flat-dynamics.toml"))
            .unwrap()
            .replace("speed_rpm = 1380.0", "speed_rpm = 1000.0"),
    )
    .unwrap();
    slow
}

/// The command's `lubrication.csv` against the disc's closed forms, written out here: the
/// surface speeds `ω R` and `−ω e cos φ` (their mean the entrainment), the load
/// `F = −m e ω² cos φ + F₀ + k e (1 + cos φ)` over the 10 mm face, Dowson and Higginson's minimum
/// film in its dimensional form for SAE 30 at 100 °C (η₀ = 10.9 mm²/s × 816 kg/m³, α = 2e-8 1/Pa)
/// on steel (E' = 206 GPa/(1 − 0.3²)), λ over √(0.2² + 0.3²) µm, and the mixed friction's
/// power; every row, 1e-12. The page and the summary are written.
#[test]
fn the_lubrication_table_is_the_discs_closed_form() {
    let dir = tempfile::tempdir().unwrap();
    let out = run!(
        "forces",
        slow_disc(dir.path()),
        "--face-width",
        "10",
        "--oil",
        "sae-30@100c",
        "--roughness",
        "0.2,0.3",
        "--out",
        dir.path().join("out")
    )
    .stdout_ok();
    let report = String::from_utf8(out).unwrap();
    for needle in [
        "lubrication (η₀ = 8.894 mPa·s, α = 20 1/GPa, Dowson–Higginson film",
        "λ = h_min/σ: min ",
        "entrainment: never reverses",
        "flash temperature (Blok): max ",
        "friction (dissipated; the forces above neglect it): mean power ",
    ] {
        assert!(report.contains(needle), "{needle}: {report}");
    }
    let out = dir.path().join("out");
    for f in ["lubrication.png", "lubrication.svg"] {
        assert!(out.join(f).exists(), "{f}");
    }
    let (h, rows) = parse_csv(&std::fs::read(out.join("lubrication.csv")).unwrap());
    let c = columns(&h);
    assert_eq!(rows.len(), 720);
    let (r, e, m, k, f0, b) = (0.04, 0.01, 0.3, 2000.0, 20.0, 0.01);
    let w = 1000.0 * std::f64::consts::TAU / 60.0;
    let (eta, alpha): (f64, f64) = (10.9e-6 * 816.0, 2e-8);
    let e_prime: f64 = 2.0 * 206e9 / (2.0 * (1.0 - 0.09));
    let sigma = (0.2e-6f64.powi(2) + 0.3e-6f64.powi(2)).sqrt();
    let x = |row: &Vec<String>, name: &str| -> f64 { row[c[name]].parse().unwrap() };
    for row in &rows {
        let phi = x(row, "angle_deg").to_radians();
        let (u1, u2) = (w * r, -w * e * phi.cos());
        let ue = 0.5 * (u1 + u2);
        let force = -m * e * w * w * phi.cos() + f0 + k * e * (1.0 + phi.cos());
        let load = force / b;
        let close = |a: f64, b: f64, what: &str| {
            assert!(
                (a - b).abs() <= 1e-12 * b.abs(),
                "{what} at {phi}: {a} vs {b}"
            );
        };
        close(x(row, "entrainment_m_s"), ue, "entrainment");
        close(x(row, "sliding_m_s"), u1 - u2, "sliding");
        close(x(row, "load_N_per_m"), load, "load");
        close(x(row, "reduced_radius_m"), r, "reduced radius");
        let h_min = 2.65 * alpha.powf(0.54) * (eta * ue).powf(0.70) * r.powf(0.43)
            / (e_prime.powf(0.03) * load.powf(0.13));
        close(x(row, "film_minimum_um"), h_min * 1e6, "minimum film");
        let lambda = h_min / sigma;
        close(x(row, "lambda"), lambda, "λ");
        let regime = if lambda < 1.0 {
            "boundary"
        } else if lambda < 3.0 {
            "mixed"
        } else {
            "full-film"
        };
        assert_eq!(row[c["regime"]], regime);
        let mu = (0.1 + (lambda.clamp(1.0, 3.0) - 1.0) / 2.0 * (0.03 - 0.1)).clamp(0.03, 0.1);
        close(x(row, "friction_coefficient"), mu, "μ");
        close(
            x(row, "friction_power_W"),
            mu * force * (u1 - u2).abs(),
            "friction power",
        );
    }
}

/// Bad lubrication input: exit 2, the flag and the value as written, nothing written.
#[test]
fn bad_lubrication_input_is_refused_naming_the_flag() {
    let dir = tempfile::tempdir().unwrap();
    let disc = slow_disc(dir.path());
    let out = dir.path().join("out");
    // (the flags, split at spaces; what the refusal says)
    for (args, needles) in [
        (
            "--face-width 10 --oil eta=-0.01:alpha=2e-8 --roughness 0.2,0.3",
            vec!["--oil", "eta = -0.01"],
        ),
        (
            "--face-width 10 --oil eta=9000:alpha=2e-8 --roughness 0.2,0.3",
            vec!["--oil", "did you write mPa·s"],
        ),
        (
            "--face-width 10 --oil eta=0.01:alpha=20 --roughness 0.2,0.3",
            vec!["--oil", "did you write 1/GPa"],
        ),
        (
            "--face-width 10 --oil sae-30@100c --roughness 0,0.3",
            vec!["--roughness", "0 µm is not a plausible roughness"],
        ),
        (
            "--face-width 10 --oil sae-30@100c --roughness 0.2",
            vec!["--roughness", "CAM,FOLLOWER"],
        ),
        (
            "--face-width 10 --oil sae-30@100c",
            vec!["--oil", "--roughness CAM,FOLLOWER"],
        ),
        (
            "--face-width 10 --roughness 0.2,0.3",
            vec!["--roughness", "--oil"],
        ),
        (
            "--oil sae-30@100c --roughness 0.2,0.3",
            vec!["--face-width", "lubrication needs the contact's face width"],
        ),
        (
            "--face-width 10 --oil sae-30@100c --roughness 0.2,0.3 --friction 1.5",
            vec!["--friction", "1.5 is not a friction coefficient"],
        ),
        (
            "--face-width 10 --oil sae-30@100c --roughness 0.2,0.3 --film grubin",
            vec!["--film", "\"grubin\" is not a film formula"],
        ),
        (
            "--face-width 10 --oil castor --roughness 0.2,0.3",
            vec!["--oil", "\"castor\" is not a lubricant", "sae-30@100c"],
        ),
    ] {
        let args: Vec<&str> = args.split(' ').collect();
        let a = run!("forces", &disc)
            .args(&args)
            .arg("--out")
            .arg(&out)
            .assert()
            .code(2);
        let err = String::from_utf8(a.get_output().stderr.clone()).unwrap();
        for n in needles {
            assert!(err.contains(n), "{args:?}: {n:?} not in {err}");
        }
        assert!(!out.exists(), "{args:?}: nothing written");
    }
    // a knife edge has no line contact, so no film
    let knife = dir.path().join("knife.toml");
    std::fs::write(
        &knife,
        std::fs::read_to_string(&disc).unwrap().replace(
            "kind = \"translating-flat\"",
            "kind = \"translating-knife\"",
        ),
    )
    .unwrap();
    run!(
        "forces",
        &knife,
        "--face-width",
        "10",
        "--oil",
        "sae-30@100c",
        "--roughness",
        "0.2,0.3"
    )
    .refused("--face-width");
}

/// A `[lubrication]` section gives what the flags would (the same `lubrication.csv`, byte for
/// byte), each flag replaces its value, and a bad value in it is refused at its place in the
/// file (line and column), exit 2.
#[test]
fn a_lubrication_section_is_the_flags_in_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let disc = slow_disc(dir.path());
    let with = dir.path().join("with.toml");
    let section = "\n[lubrication]\noil = \"sae-30@100c\"\nroughness_um = [0.2, 0.3]\nface_width = 10.0\nfriction = [0.12, 0.04]\nmaterials = \"steel,bronze\"\n";
    std::fs::write(&with, std::fs::read_to_string(&disc).unwrap() + section).unwrap();
    let run = |file: &Path, args: &[&str], out: &str| {
        run!("forces", file)
            .args(args)
            .arg("--out")
            .arg(dir.path().join(out))
            .assert()
            .success();
        std::fs::read(dir.path().join(out).join("lubrication.csv")).unwrap()
    };
    let flags = run(
        &disc,
        &[
            "--face-width",
            "10",
            "--oil",
            "sae-30@100c",
            "--roughness",
            "0.2,0.3",
            "--friction",
            "0.12:0.04",
            "--materials",
            "steel,bronze",
        ],
        "flags",
    );
    assert_eq!(run(&with, &[], "file"), flags);
    // a flag replaces the file's value
    let other = run(&with, &["--roughness", "0.4,0.4"], "other");
    assert_ne!(other, flags);
    assert_eq!(
        run(
            &disc,
            &[
                "--face-width",
                "10",
                "--oil",
                "sae-30@100c",
                "--roughness",
                "0.4,0.4",
                "--friction",
                "0.12:0.04",
                "--materials",
                "steel,bronze"
            ],
            "other-flags"
        ),
        other
    );
    // a bad value, placed in the file
    let bad = dir.path().join("bad.toml");
    std::fs::write(
        &bad,
        std::fs::read_to_string(&with)
            .unwrap()
            .replace("roughness_um = [0.2, 0.3]", "roughness_um = [0.2, -1]"),
    )
    .unwrap();
    let lines = std::fs::read_to_string(&bad).unwrap();
    let line = lines
        .lines()
        .position(|l| l.starts_with("roughness_um"))
        .unwrap()
        + 1;
    run!("forces", &bad).refused(format!(
        "bad.toml:{line}:22: lubrication.roughness_um[1] = -1"
    ));
}
