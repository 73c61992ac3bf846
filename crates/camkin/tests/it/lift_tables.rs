//! Issue 65, "lift tables as programs": a motion program's `law = "table"` segment — a lift table
//! interpolated by a quintic spline (C⁴) and the cam synthesised exactly from it — against closed
//! forms through the whole chain (file → table → synthesis → the contact method's analysis):
//! a periodic table of the whole revolution and a table between dwells, each at three spacings;
//! the stated noise of a rounded table against its actual acceleration error; and every table
//! that cannot be, refused at its key or its file's line.

use camkin::spec::BuildOptions;
use std::f64::consts::TAU;

/// A bucket (flat face) on a cam of base radius 20 mm at 1500 rpm whose program is `segments`
/// (TOML), read as the command reads it (files from `examples/`), with its warnings.
fn bucket_warned(segments: &str) -> Result<(camkin::spec::Built, Vec<String>), String> {
    let text = format!(
        r#"length_unit = "mm"
[cam]
speed_rpm = 1500.0
[cam.profile]
kind = "motion"
base_radius = 20.0
segments = [{segments}]
[follower]
kind = "translating-flat"
direction = [0.0, 1.0]
"#
    );
    let options = BuildOptions {
        base_dir: std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples"),
        ..BuildOptions::default()
    };
    let model = camkin::spec::read_model(&text, "table.toml", &options).map_err(|e| e.message)?;
    let preset = model.into_preset().expect("a cam file");
    Ok((
        preset.built,
        preset.warnings.into_iter().map(|w| w.message).collect(),
    ))
}

/// [`bucket_warned`] without its warnings.
fn bucket(segments: &str) -> Result<camkin::spec::Built, String> {
    bucket_warned(segments).map(|b| b.0)
}

/// Inline table segment: `lifts` every `step` degrees.
fn inline(step: f64, lifts: &[f64]) -> String {
    let l: Vec<String> = lifts.iter().map(|v| format!("{v:e}")).collect();
    format!(
        "{{ law = \"table\", step_deg = {step}, lift = [{}] }}",
        l.join(", ")
    )
}

/// The largest errors of the analysed lift, velocity and acceleration against `s(θ)` and its
/// derivatives (mm, rad) over `angles` (degrees), relative to each one's peak.
fn errors(built: &camkin::spec::Built, s: &dyn Fn(f64) -> [f64; 3], angles: &[f64]) -> [f64; 3] {
    let mech = &built.mechanism;
    let w = 1500.0 * TAU / 60.0;
    let base = mech.analyze(0.0).unwrap().position - s(0.0)[0];
    let (mut err, mut peak) = ([0.0f64; 3], [0.0f64; 3]);
    for &a in angles {
        let t = a.to_radians();
        let st = mech.analyze(t).unwrap();
        let want = s(t);
        let got = [
            st.position - base,
            st.velocity / w,
            st.acceleration / (w * w),
        ];
        for d in 0..3 {
            err[d] = err[d].max((got[d] - want[d]).abs());
            peak[d] = peak[d].max(want[d].abs());
        }
    }
    [err[0] / peak[0], err[1] / peak[1], err[2] / peak[2]]
}

/// `8 ((1 − cos θ)/2)⁴` mm over the whole revolution: smooth, a dwell-like flat at 0°.
fn periodic(t: f64) -> [f64; 3] {
    let (s, c) = t.sin_cos();
    let u = 0.5 * (1.0 - c);
    let (du, ddu) = (0.5 * s, 0.5 * c);
    [
        8.0 * u.powi(4),
        32.0 * u.powi(3) * du,
        96.0 * u * u * du * du + 32.0 * u.powi(3) * ddu,
    ]
}

/// `8 ((1 − cos 2πx)/2)²` mm over a 200° event (`x = θ/β`), the base circle after it: at rest
/// with its acceleration and jerk zero at both ends, smooth between.
fn event(t: f64) -> [f64; 3] {
    let beta = 200f64.to_radians();
    if !(0.0..=beta).contains(&t) {
        return [0.0; 3];
    }
    let k = TAU / beta;
    let (s, c) = (k * t).sin_cos();
    let u = 0.5 * (1.0 - c);
    let (du, ddu) = (0.5 * k * s, 0.5 * k * k * c);
    [8.0 * u * u, 16.0 * u * du, 16.0 * (du * du + u * ddu)]
}

/// Tables of each lift at 2°, 1° and 0.5°: every error falls with the step as the quintic
/// spline's order says (lift ~h⁶, halving the step dividing it by over 25 until it reaches
/// rounding; velocity ~h⁵ and acceleration ~h⁴, by over 12; measured 64, 33 and 16), and at
/// 0.5° the lift is within 1e-13, the velocity 1e-11 and the acceleration 1e-9 of their peaks,
/// over 0.1° steps of the revolution through the synthesised cam.
#[test]
fn a_table_converges_to_its_lift_through_the_synthesised_cam() {
    let angles: Vec<f64> = (0..3600).map(|k| 0.1 * k as f64).collect();
    for (name, lift, dwell) in [
        ("periodic", periodic as fn(f64) -> [f64; 3], None),
        ("between dwells", event as fn(f64) -> [f64; 3], Some(160.0)),
    ] {
        let mut errs = Vec::new();
        for step in [2.0f64, 1.0, 0.5] {
            let span = dwell.map_or(360.0 - step, |d| 360.0 - d);
            let n = (span / step).round() as usize + 1;
            let lifts: Vec<f64> = (0..n)
                .map(|i| lift((i as f64 * step).to_radians())[0])
                .collect();
            let mut segs = inline(step, &lifts);
            if let Some(d) = dwell {
                segs += &format!(", {{ law = \"dwell\", degrees = {d} }}");
            }
            let built = bucket(&segs).unwrap();
            let e = errors(&built, &lift, &angles);
            eprintln!("{name} at {step}°: {e:?}");
            errs.push(e);
        }
        let last = errs[2];
        assert!(
            last[0] < 1e-13 && last[1] < 1e-11 && last[2] < 1e-9,
            "{name}: {last:?}"
        );
        for k in 0..2 {
            let (a, b) = (errs[k], errs[k + 1]);
            assert!(
                a[0] / b[0] > 25.0 || b[0] < 1e-14,
                "{name}: lift {a:?} {b:?}"
            );
            assert!(a[1] / b[1] > 12.0, "{name}: velocity {a:?} {b:?}");
            assert!(a[2] / b[2] > 12.0, "{name}: acceleration {a:?} {b:?}");
        }
    }
}

/// A table rounded to 0.1 µm every 1° (`event`'s lifts): the noise it states is honest — its
/// acceleration noise within a factor of 2 of the RMS acceleration error the synthesised cam
/// actually has against the closed form over the event — and the rounding's σ within 20 % of
/// `q/√12`; the same table unrounded states a noise 1000 times smaller.
#[test]
fn a_rounded_table_states_its_acceleration_noise_honestly() {
    let step = 1.0f64;
    let n = 201;
    let exact: Vec<f64> = (0..n).map(|i| event((i as f64).to_radians())[0]).collect();
    let q = 1e-4;
    let rounded: Vec<f64> = exact.iter().map(|p| (p / q).round() * q).collect();
    let table = |l: &[f64]| {
        camkin::lift_table::LiftTable::new(step.to_radians(), l.to_vec(), false).unwrap()
    };
    let noise = table(&rounded).noise();
    let want_sigma = q / 12f64.sqrt();
    assert!((noise.sigma / want_sigma - 1.0).abs() < 0.2, "{noise:?}");
    assert!(table(&exact).noise().acceleration < 1e-3 * noise.acceleration);
    let built = bucket(&(inline(step, &rounded) + ", { law = \"dwell\", degrees = 160 }")).unwrap();
    let w = 1500.0 * TAU / 60.0;
    let (mut sum, mut count) = (0.0, 0);
    for k in 0..2000 {
        let t = (0.1 * k as f64).to_radians();
        let a = built.mechanism.analyze(t).unwrap().acceleration / (w * w);
        sum += (a - event(t)[2]).powi(2);
        count += 1;
    }
    let rms = (sum / count as f64).sqrt();
    eprintln!("stated {} actual RMS {rms} (mm/rad²)", noise.acceleration);
    assert!(
        noise.acceleration < 2.0 * rms && rms < 2.0 * noise.acceleration,
        "stated {} actual {rms}",
        noise.acceleration
    );
}

/// The example's table (examples/lift-table.csv, every 1° to 1 nm) is read through its file
/// with no noise to state: the event's 260° and the lift's 8.3 mm nose, the base circle after
/// it; against the program it was sampled from (ramps and cycloidal laws, whose jerk steps where
/// they meet: a C⁴ spline rounds those steps off over a step or two) the synthesised cam's lift
/// is within 5e-6 mm, its velocity 1e-4 and its acceleration 1.5 % of their peaks (measured
/// 3.0e-6 mm, 6.1e-5 and 0.97 %, the last next to the jerk's steps).
#[test]
fn the_example_table_is_read_from_its_file() {
    let (built, warnings) = bucket_warned(
        "{ law = \"table\", file = \"lift-table.csv\" }, { law = \"dwell\", degrees = 100 }",
    )
    .unwrap();
    assert!(warnings.is_empty(), "{warnings:?}");
    let program = bucket(
        "{ law = \"ramp\", rise = 0.3, degrees = 30 }, { law = \"cycloidal\", rise = 8.0, degrees = 100 }, \
         { law = \"cycloidal\", rise = -8.0, degrees = 100 }, { law = \"ramp\", rise = -0.3, degrees = 30 }, \
         { law = \"dwell\", degrees = 100 }",
    )
    .unwrap();
    let (mut err, mut peak) = ([0.0f64; 3], [0.0f64; 3]);
    for k in 0..3600 {
        let t = (0.1 * k as f64).to_radians();
        let (a, b) = (
            built.mechanism.analyze(t).unwrap(),
            program.mechanism.analyze(t).unwrap(),
        );
        for (d, (x, y)) in [
            (a.position, b.position),
            (a.velocity, b.velocity),
            (a.acceleration, b.acceleration),
        ]
        .into_iter()
        .enumerate()
        {
            err[d] = err[d].max((x - y).abs());
            peak[d] = peak[d].max(y.abs());
        }
    }
    eprintln!("example against its program: {err:?} of {peak:?}");
    assert!(err[0] < 5e-6, "{err:?}");
    assert!(err[1] < 1e-4 * peak[1], "{err:?} {peak:?}");
    assert!(err[2] < 1.5e-2 * peak[2], "{err:?} {peak:?}");
    let mech = &built.mechanism;
    let base = mech.analyze(0.0).unwrap().position;
    let nose = mech.analyze(130f64.to_radians()).unwrap().position - base;
    assert!((nose - 8.3).abs() < 1e-12, "{nose}");
    let dwell = mech.analyze(300f64.to_radians()).unwrap().position - base;
    assert!(dwell.abs() < 1e-12, "{dwell}");
    // rounded to 0.1 µm, the same table states its acceleration noise at its key
    let dir = std::env::temp_dir().join(format!("camkin-lift-example-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/lift-table.csv"),
    )
    .unwrap();
    let rounded: Vec<String> = text
        .lines()
        .map(|l| match l.split_once(',') {
            Some((a, v)) if v.parse::<f64>().is_ok() => {
                format!("{a},{:.4}", v.parse::<f64>().unwrap())
            }
            _ => l.to_string(),
        })
        .collect();
    let path = dir.join("rounded.csv");
    std::fs::write(&path, rounded.join("\n")).unwrap();
    let (_, warnings) = bucket_warned(&format!(
        "{{ law = \"table\", file = {:?} }}, {{ law = \"dwell\", degrees = 100 }}",
        path.display().to_string()
    ))
    .unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(
        warnings
            .iter()
            .any(|w| w.contains("segments[0].file") && w.contains("acceleration noise")),
        "{warnings:?}"
    );
}

/// Every table that cannot be is refused naming its key, or its file's line: rows not in equal
/// steps; a table alone that is not the whole revolution; a whole revolution whose 360° row is
/// not its 0° row; one between dwells that is not at rest at an end; `rise` or `degrees`
/// given; both a file and inline lifts, or neither; inline lifts without their step; a
/// table's key on another law; a file that is not there.
#[test]
fn a_table_that_cannot_be_is_refused_at_its_key_or_line() {
    let dir = std::env::temp_dir().join(format!("camkin-lift-tables-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let uneven = dir.join("uneven.csv");
    std::fs::write(&uneven, "angle,lift\n0,0\n1,0.1\n2,0.3\n3.5,0.2\n4,0\n").unwrap();
    let file = |p: &std::path::Path| {
        format!(
            "{{ law = \"table\", file = {:?} }}, {{ law = \"dwell\", degrees = 356 }}",
            p.display().to_string()
        )
    };
    let sixty: Vec<f64> = (0..60)
        .map(|i| (i as f64 * 6f64.to_radians()).sin().powi(2))
        .collect();
    let mut closing = sixty.clone();
    closing.push(0.5);
    let cases: Vec<(String, &str)> = vec![
        (file(&uneven), "uneven.csv:5"),
        (file(&uneven), "equal steps"),
        (inline(6.0, &sixty[..30]), "is the whole revolution"),
        (inline(6.0, &closing), "is not the lift at 0°"),
        (
            inline(1.0, &[0.0, 0.5, 1.0, 1.0, 0.0]) + ", { law = \"dwell\", degrees = 356 }",
            "not at rest at its start",
        ),
        (
            "{ law = \"table\", step_deg = 6, lift = [0, 1, 0], rise = 1.0 }".into(),
            "segments[0].rise",
        ),
        (
            "{ law = \"table\", step_deg = 6, lift = [0, 1, 0], degrees = 12 }".into(),
            "segments[0].degrees",
        ),
        ("{ law = \"table\" }".into(), "give one"),
        ("{ law = \"table\", lift = [0, 1, 0] }".into(), "step_deg"),
        (
            "{ law = \"cycloidal\", rise = 1.0, degrees = 360, step_deg = 1 }".into(),
            "segments[0].step_deg",
        ),
        (
            "{ law = \"table\", file = \"no-such-table.csv\" }".into(),
            "cannot read",
        ),
    ];
    for (segs, says) in cases {
        match bucket(&segs) {
            Ok(_) => panic!("{segs} was accepted"),
            Err(e) => assert!(e.contains(says), "{segs}: {e}"),
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
