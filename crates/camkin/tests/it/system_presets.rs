//! Issue 45: the cam-follower mechanism is a system. Every `[cam]` and `[gear_pair]` example,
//! turned into a system by [`camkin::cam::Mechanism::to_system`], gives through the system's
//! kinematic analysis (Newton on every body's three coordinates, the contact's row and `γ`) the
//! follower's position, velocity and acceleration that the cam path (one coordinate, closed
//! forms per follower kind) gives: to 1e-12 of the size, of `ω × size` and of `ω² × size`, at
//! every angle of a revolution.

use camkin::spec::text::{build_placed, is_system, parse_toml};
use camkin::spec::BuildOptions;
use std::path::Path;

fn examples() -> Vec<(String, String)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let path = e.unwrap().path();
        if path.extension().and_then(|x| x.to_str()) != Some("toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        if is_system(&text) {
            continue;
        }
        // the full path: a file's `path = "profile.csv"` is beside it
        out.push((path.to_string_lossy().into_owned(), text));
    }
    out.sort();
    assert!(out.len() >= 15, "{} cam examples", out.len());
    out
}

/// The largest differences of the follower's position, velocity and acceleration between the
/// system path and the cam path over a revolution at 1° steps, as fractions of the size, `ω ×
/// size` and `ω² × size`.
fn differences(name: &str, text: &str) -> [f64; 7] {
    let spec = parse_toml(text, name).unwrap();
    let options = BuildOptions {
        base_dir: Path::new(name).parent().unwrap().to_path_buf(),
        ..BuildOptions::default()
    };
    let built = build_placed(&spec, text, name, &options).unwrap().0;
    let mech = &built.mechanism;
    let preset = mech.to_system().unwrap();
    let size = mech.size();
    let w = preset.speed;
    let mut cam = mech.sweep();
    let mut sys = preset.system.sweep().unwrap();
    let mut d = [0.0f64; 7];
    let mut other_pair = 0;
    let (mut jerks, mut no_jerk) = (0, 0);
    // an arm's angle times the size: a length
    let scale = match mech.follower_joint() {
        camkin::cam::FollowerJoint::Rotating { .. } => size,
        _ => 1.0,
    };
    for k in 0..=360 {
        let th = f64::from(k).to_radians();
        let c = cam
            .step(th)
            .unwrap_or_else(|e| panic!("{name} at {k}°: {e}"));
        let s = sys
            .step(preset.time_of(th))
            .unwrap_or_else(|e| panic!("{name} at {k}° (system): {e}"));
        let [q, v, a] = preset.follower_coordinate(&s);
        // an arm's angle is one modulo a turn (a driven gear turns more than half a turn in
        // the driver's revolution: the system's coordinate is within ±180° of its start)
        let dq = match mech.follower_joint() {
            camkin::cam::FollowerJoint::Rotating { .. } => {
                (q - c.position + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
                    - std::f64::consts::PI
            }
            _ => q - c.position,
        };
        d[0] = d[0].max(dq.abs() * scale / size);
        d[1] = d[1].max((v - c.velocity).abs() * scale / (w * size));
        d[2] = d[2].max((a - c.acceleration).abs() * scale / (w * w * size));
        // the jerk: the system's from its rows in time (the contact as pairing conditions), the
        // cam path's from its tangency in the cam angle; both none where the contact is on a
        // breakpoint of a curve
        match (preset.system.jerk(&s), c.jerk) {
            (Ok(j), Some(cj)) => {
                let i = preset.follower.index().unwrap();
                let sj = match mech.follower_joint() {
                    camkin::cam::FollowerJoint::Translating { direction, .. } => {
                        j[i].linear.dot(&direction)
                    }
                    _ => j[i].angular,
                };
                // relative to ω³·size, or to the jerk itself where it is larger (a tangent
                // cam's steep flank: four times ω³·size, its rounding with it)
                let jerk_scale = (w * w * w * size).max(cj.abs() * scale);
                d[6] = d[6].max((sj - cj).abs() * scale / jerk_scale);
                jerks += 1;
            }
            (Err(e), None) => {
                assert!(
                    matches!(e, camkin::system::SystemError::NoJerk { .. }),
                    "{name} at {k}°: {e}"
                );
                no_jerk += 1;
            }
            (j, cj) => panic!("{name} at {k}°: the system's jerk {j:?}, the cam path's {cj:?}"),
        }
        // the contact: sliding rates on both curves, the normal acceleration seen from the cam;
        // where two pairs of gear teeth touch at once, the cam path names the first contact
        // and the system the pair it has followed: both exact, compared where they are one
        let kin = &s.contacts[0].kinematics;
        if (kin.point - c.contact_world).norm() > 1e-9 * size {
            // another pair of teeth, closed too
            assert!(
                s.contacts[0].pairing.gap.abs() <= 1e-12 * size,
                "{name} at {k}°"
            );
            other_pair += 1;
            continue;
        }
        let cam_body = &s.bodies[0];
        d[3] = d[3].max((kin.sliding_rate_a - c.sliding_rate_cam).abs() / (w * size));
        d[4] = d[4].max((kin.sliding_rate_b - c.sliding_rate_follower).abs() / (w * size));
        let an = kin.normal_acceleration_a(cam_body);
        let ac = c.normal_acceleration_cam;
        d[5] = d[5].max((an.total() - ac.total()).abs() / (w * w * size));
        d[5] = d[5].max((an.coriolis - ac.coriolis).abs() / (w * w * size));
        d[5] = d[5].max((an.relative - ac.relative).abs() / (w * w * size));
    }
    // only a gear pair has two pairs in contact at once (a contact ratio of 1.5 to 1.7)
    let gears = text.contains("involute") || text.contains("[gear_pair]");
    assert!(
        gears || other_pair == 0,
        "{name}: the system followed another contact at {other_pair} of 361 angles"
    );
    eprintln!(
        "{name}: the same contact at {} of 361 angles; jerk at {jerks}, none at {no_jerk}",
        361 - other_pair
    );
    d
}

fn check(name: &str, text: &str) {
    let [dq, dv, da, sa, sb, an, dj] = differences(name, text);
    eprintln!("{name}: position {dq:.1e}, velocity {dv:.1e}, acceleration {da:.1e}, sliding rates {sa:.1e} {sb:.1e}, normal acceleration {an:.1e}, jerk {dj:.1e}");
    assert!(
        sa <= 1e-12 && sb <= 1e-12,
        "{name}: sliding rates off by {sa:e}, {sb:e} of ω·size"
    );
    assert!(
        an <= 1e-12,
        "{name}: normal acceleration off by {an:e} of ω²·size"
    );
    assert!(dq <= 1e-12, "{name}: position off by {dq:e} of the size");
    assert!(dv <= 1e-12, "{name}: velocity off by {dv:e} of ω·size");
    assert!(da <= 1e-12, "{name}: acceleration off by {da:e} of ω²·size");
    assert!(dj <= 1e-12, "{name}: jerk off by {dj:e} of ω³·size");
}

#[test]
fn every_cam_example_through_the_system_path_gives_the_cam_paths_motion() {
    for (name, text) in examples() {
        check(&name, &text);
    }
}

/// Both cam senses and offsets both ways: every example with its cam turned the other way, and
/// with its follower's offset on the other side.
#[test]
fn both_senses_and_both_offsets_through_the_system_path() {
    for (name, text) in examples() {
        let text = text.lines().collect::<Vec<_>>().join("\n");
        // a driven gear's load turns it the driver's way (it resists the motion): it turns with
        // the driver's sense, as a [gear_pair] file's does. Flipped alone it would aid the
        // motion, and with backlash the system path, which has no load direction, may then
        // take the back flanks where the followed pair leaves (the guide's limits (docs/limits.md))
        let gear = text.contains("involute-gear");
        let flipped: String = text
            .lines()
            .map(|l| match l.trim_start() {
                t if t.starts_with("direction = \"ccw\"") => l.replace("\"ccw\"", "\"cw\""),
                t if t.starts_with("direction = \"cw\"") => l.replace("\"cw\"", "\"ccw\""),
                t if gear && t.starts_with("closing = \"ccw\"") => l.replace("\"ccw\"", "\"cw\""),
                t if gear && t.starts_with("closing = \"cw\"") => l.replace("\"cw\"", "\"ccw\""),
                _ => l.to_string(),
            })
            .collect::<Vec<_>>()
            .join("\n");
        if flipped != text {
            check(&format!("{name} (other sense)"), &flipped);
        }
        let offset: String = text
            .lines()
            .map(|l| match l.strip_prefix("offset = ") {
                Some(v) => {
                    let v: f64 = v.split('#').next().unwrap().trim().parse().unwrap();
                    // a zero offset moved off the axis both ways
                    let v = if v == 0.0 { 0.3 } else { -v };
                    format!("offset = {v}")
                }
                None => l.to_string(),
            })
            .collect::<Vec<_>>()
            .join("\n");
        if offset != text && !text.contains("face_offset") {
            check(&format!("{name} (offset the other way)"), &offset);
        }
    }
}

/// A cam speeding up: the system's driver turns the cam at `θ = ω t + α t²/2`, so at cam angle
/// `θ` the follower moves at `q′(θ) θ̇` with `q̈ = q″ θ̇² + q′ θ̈` (the chain rule), where `q′`
/// and `q″` are the cam path's velocity and acceleration at constant speed divided by `ω` and
/// `ω²`.
#[test]
fn a_cam_speeding_up_through_the_system_path_obeys_the_chain_rule() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    for file in ["paper.toml", "oscillating-roller.toml"] {
        let name = dir.join(file).to_string_lossy().into_owned();
        let text = std::fs::read_to_string(&name).unwrap();
        let build = |text: &str| {
            let spec = parse_toml(text, &name).unwrap();
            build_placed(&spec, text, &name, &BuildOptions::default())
                .unwrap()
                .0
                .mechanism
        };
        let steady = build(&text);
        let w = steady.cam().speed();
        // 2000°/s² speeds a 1000 rpm cam up by about 6 % in a revolution
        let alpha_deg = 2000.0 * w;
        let speeding = build(&text.replacen(
            "[cam]\n",
            &format!("[cam]\nangular_acceleration_deg_s2 = {alpha_deg}\n"),
            1,
        ));
        let alpha = alpha_deg.to_radians();
        assert!((speeding.cam().angular_acceleration() - alpha).abs() <= 1e-15 * alpha);
        let preset = speeding.to_system().unwrap();
        let size = steady.size();
        let scale = match steady.follower_joint() {
            camkin::cam::FollowerJoint::Rotating { .. } => size,
            _ => 1.0,
        };
        let mut sys = preset.system.sweep().unwrap();
        let mut cam = steady.sweep();
        let mut worst = [0.0f64; 2];
        for k in 0..=72 {
            let th = f64::from(5 * k).to_radians();
            let t = preset.time_of(th);
            // the cam's angle and speed at t, from the law written out
            assert!((w * t + 0.5 * alpha * t * t - th).abs() <= 1e-13 * th.max(1.0));
            let speed = w + alpha * t;
            let c = cam.step(th).unwrap();
            let (d1, d2) = (c.velocity / w, c.acceleration / (w * w));
            let s = sys.step(t).unwrap();
            let [_, v, a] = preset.follower_coordinate(&s);
            worst[0] = worst[0].max((v - d1 * speed).abs() * scale / (speed * size));
            worst[1] = worst[1]
                .max((a - d2 * speed * speed - d1 * alpha).abs() * scale / (speed * speed * size));
        }
        eprintln!(
            "{file} speeding up: velocity {:.1e}, acceleration {:.1e}",
            worst[0], worst[1]
        );
        assert!(worst[0] <= 1e-12 && worst[1] <= 1e-12, "{file}: {worst:?}");
    }
}
