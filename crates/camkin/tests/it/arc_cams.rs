//! The textbook arc cams against their closed forms: the tangent cam under a radial roller
//! (on the flank `s = (r_b + r_r)/cos φ`, so `a = ω² (r_b + r_r)` where the flank starts; on the
//! nose `s = d cos φ + √((r_n + r_r)² − d² sin² φ)`), and the circular-arc cam under a flat face
//! (on a flank of radius `R`, `lift = (R − r_b)(1 − cos β)` and `v = ω (R − r_b) sin β`, β the cam
//! angle from the flank's start), each differentiated with hyper-dual numbers; both senses.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Follower, Sense};
use camkin::curve::{ArcsAndLines, Piece};
use camkin::{Point2, Vec2};
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

const RB: f64 = 20.0;
const RN: f64 = 8.0;
const LIFT: f64 = 12.0;

/// The cam angle at which a follower along +x sees the cam's direction `phi` (cam frame).
fn theta_of(phi: f64, sense: Sense) -> f64 {
    (-sense.sign() * phi).rem_euclid(TAU)
}

#[test]
fn the_tangent_cam_under_a_radial_roller_is_its_closed_form() {
    let rr = 5.0;
    let d = LIFT + RB - RN;
    let psi = ((RB - RN) / d).acos();
    // where the roller leaves the flank for the nose: the pitch nose's foot's polar angle
    let beta = ((RN + rr) * psi.sin()).atan2(d + (RN + rr) * psi.cos());
    let flank = |phi: HD| HD::c(RB + rr) / (phi + (-psi)).cos();
    let nose = |phi: HD| {
        phi.cos() * HD::c(d)
            + (HD::c((RN + rr) * (RN + rr)) - phi.sin() * phi.sin() * HD::c(d * d)).sqrt()
    };
    for sense in [Sense::Ccw, Sense::Cw] {
        let cam = Arc::new(ArcsAndLines::tangent_cam(RB, RN, LIFT).unwrap());
        let m = mechanism(
            cam,
            Point2::origin(),
            sense,
            1200.0,
            Follower::TranslatingRoller {
                direction: Vec2::x(),
                offset: 0.0,
                roller_radius: rr,
            },
        );
        let w = m.cam().speed();
        let mut checked = [0, 0];
        for k in 1..200 {
            // the follower's direction in the cam's frame, on the upper side (the other mirrors it)
            let phi = psi * f64::from(k) / 200.0;
            let (s, which) = if phi < beta {
                (nose(HD::var(phi)), 1)
            } else {
                (flank(HD::var(phi)), 0)
            };
            if (phi - beta).abs() < 1e-6 {
                continue;
            }
            let st = m.analyze(theta_of(phi, sense)).unwrap();
            // d/dθ = −σ d/dφ
            assert_close(st.position, s.v, 1e-12, RB, "position");
            assert_close(
                st.velocity,
                -sense.sign() * w * s.d1,
                1e-11,
                w * RB,
                "velocity",
            );
            assert_close(
                st.acceleration,
                w * w * s.d2,
                1e-10,
                w * w * RB,
                "acceleration",
            );
            checked[which] += 1;
        }
        assert!(checked[0] > 20 && checked[1] > 20, "{checked:?}");
        // where the flank starts, the textbook's a = ω² (r_b + r_r)
        let st = m.analyze(theta_of(psi - 1e-9, sense)).unwrap();
        assert_close(
            st.acceleration,
            w * w * (RB + rr),
            1e-6,
            w * w * RB,
            "a at the flank's start",
        );
    }
}

#[test]
fn the_circular_arc_cam_under_a_flat_face_is_its_closed_form() {
    let r = 60.0;
    for sense in [Sense::Ccw, Sense::Cw] {
        let cam = ArcsAndLines::circular_arc_cam(RB, RN, LIFT, r).unwrap();
        // the upper flank (the last piece): from the nose to the base circle
        let Piece::Arc {
            start,
            sweep,
            centre,
            ..
        } = cam.pieces()[3]
        else {
            panic!("a flank arc")
        };
        assert!((centre.coords.norm() - (r - RB)).abs() < 1e-12);
        let m = mechanism(
            Arc::new(cam),
            Point2::origin(),
            sense,
            900.0,
            Follower::TranslatingFlat {
                direction: Vec2::x(),
            },
        );
        let w = m.cam().speed();
        for k in 1..100 {
            // the face's normal in the cam's frame; β from the flank's start at the base circle
            let phi = start + sweep * f64::from(k) / 100.0;
            let beta = start + sweep - phi;
            let st = m.analyze(theta_of(phi, sense)).unwrap();
            let lift = (r - RB) * (1.0 - beta.cos());
            assert_close(st.position - RB, lift, 1e-12, RB, "lift on the flank");
            // v = ω (R − r_b) sin β: turning counter-clockwise the cam brings this flank up
            // from the base circle (a rise), clockwise down from the nose (a return)
            let v = sense.sign() * w * (r - RB) * beta.sin();
            assert_close(st.velocity, v, 1e-11, w * RB, "v on the flank");
            // a = ω² (R − r_b) cos β
            assert_close(
                st.acceleration,
                w * w * (r - RB) * beta.cos(),
                1e-10,
                w * w * RB,
                "a on the flank",
            );
        }
        // on the base circle the follower rests; on the nose it is the nose's support
        let st = m.analyze(theta_of(PI, sense)).unwrap();
        assert_close(st.position, RB, 1e-12, RB, "rest on the base circle");
        let st = m.analyze(theta_of(0.0, sense)).unwrap();
        assert_close(st.position, RB + LIFT, 1e-12, RB, "full lift on the nose");
    }
}

fn built(text: &str) -> Result<camkin::cam::Mechanism, camkin::spec::text::TextError> {
    use camkin::spec::text::{build_placed, parse_toml};
    let spec = parse_toml(text, "p.toml")?;
    build_placed(
        &spec,
        text,
        "p.toml",
        &camkin::spec::BuildOptions::default(),
    )
    .map(|b| b.0.mechanism)
}

const FOLLOWER: &str = "[follower]\nkind = \"translating-roller\"\ndirection = [1.0, 0.0]\noffset = 0.0\nroller_radius = 5.0\n";

/// The tangent cam written out as `arcs-and-lines` pieces (its tangent points computed here from
/// the circles' geometry) is the `tangent-cam` kind: the same motion at every angle (1e-12).
#[test]
fn arcs_and_lines_written_out_are_the_tangent_cam() {
    let d = LIFT + RB - RN;
    let psi = ((RB - RN) / d).acos();
    let (c, s) = (psi.cos(), psi.sin());
    let pieces = format!(
        "start = [{bx}, {by}]\npieces = [\n  {{ to = [{bx}, {nby}], centre = [0.0, 0.0] }},\n  {{ to = [{nx}, {nny}] }},\n  {{ to = [{nx}, {ny}], centre = [{d}, 0.0] }},\n  {{ to = [{bx}, {by}] }},\n]\n",
        bx = RB * c,
        by = RB * s,
        nby = -RB * s,
        nx = d + RN * c,
        ny = RN * s,
        nny = -RN * s,
    );
    let head = "length_unit = \"mm\"\n[cam]\nspeed_rpm = 1000.0\n";
    let by_pieces = built(&format!(
        "{head}[cam.profile]\nkind = \"arcs-and-lines\"\n{pieces}{FOLLOWER}"
    ))
    .unwrap();
    let preset = built(&format!(
        "{head}[cam.profile]\nkind = \"tangent-cam\"\nbase_radius = {RB}\nnose_radius = {RN}\nlift = {LIFT}\n{FOLLOWER}"
    ))
    .unwrap();
    for k in 0..360 {
        let t = f64::from(k).to_radians() + 0.001;
        let (a, b) = (by_pieces.motion(t).unwrap(), preset.motion(t).unwrap());
        assert_close(a.position, b.position, 1e-12, RB, "position");
        assert_close(a.acceleration, b.acceleration, 1e-9, 1e6, "acceleration");
    }
}

/// Pieces that do not make a profile are refused at the piece, with its line and column.
#[test]
fn pieces_that_do_not_join_are_refused_at_the_piece() {
    let head = "length_unit = \"mm\"\n[cam]\nspeed_rpm = 1000.0\n[cam.profile]\nkind = \"arcs-and-lines\"\nstart = [20.0, 0.0]\n";
    for (pieces, path, needle) in [
        (
            "pieces = [\n  { to = [0.0, 20.0], centre = [0.0, 0.0] },\n  { to = [-20.0, 0.0], centre = [1.0, 0.0] },\n  { to = [20.0, 0.0] },\n]\n",
            "cam.profile.pieces[1].centre",
            "not the centre of an arc through both",
        ),
        (
            "pieces = [\n  { to = [0.0, 20.0], centre = [0.0, 0.0] },\n  { to = [-20.0, 0.0], centre = [0.0, 0.0] },\n  { to = [0.0, -21.0] },\n]\n",
            "cam.profile.pieces[2].to",
            "does not close",
        ),
        (
            "pieces = [\n  { to = [-20.0, 0.0], centre = [0.0, 0.0] },\n  { to = [20.0, 0.0], clockwise = true },\n]\n",
            "cam.profile.pieces[1].clockwise",
            "a line has no sense",
        ),
        ("pieces = [\n  { to = [20.0, 0.0], centre = [0.0, 0.0] },\n]\n", "cam.profile.pieces", "from 2 to"),
    ] {
        let e = built(&format!("{head}{pieces}{FOLLOWER}")).unwrap_err();
        assert_eq!(e.path.as_deref(), Some(path), "{e:?}");
        assert!(e.message.contains(needle), "{}", e.message);
        assert!(e.at.is_some(), "placed: {e:?}");
    }
}
