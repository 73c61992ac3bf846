//! Every follower type on spline cams: velocity and acceleration by the contact method agree with
//! 8th-order central differences of the follower's own position (computed by first touch only).
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::cam::{Mechanism, Sense};
use camkin::Point2;

/// Checks the angles whose difference stencil stays on one spline segment (the position is only
/// C² across a node: its third derivative jumps there). Returns how many angles were checked.
fn check(m: &Mechanism, name: &str) -> usize {
    let w = m.cam().speed();
    let h = 2e-3;
    let mut checked = 0;
    let scale = w * w * m.size();
    for k in 0..90 {
        let th = (k as f64 * 4.0 + 0.7).to_radians();
        let s = m.analyze(th).unwrap_or_else(|e| panic!("{name}: {e}"));
        let lo = m.analyze(th - 4.0 * h).unwrap();
        let hi = m.analyze(th + 4.0 * h).unwrap();
        if lo.cam_param.floor() != s.cam_param.floor()
            || hi.cam_param.floor() != s.cam_param.floor()
        {
            continue;
        }
        let (d1, d2) = fd8(|t| m.position(t).unwrap(), th, h);
        assert_close(
            s.velocity,
            w * d1,
            1e-8,
            w * m.size(),
            &format!("{name} v at {k}"),
        );
        assert_close(
            s.acceleration,
            w * w * d2,
            1e-7,
            scale,
            &format!("{name} a at {k}"),
        );
        // eq. 11 holds between the two sides
        let (na, nb) = (
            s.normal_acceleration_cam.total(),
            s.normal_acceleration_follower.total(),
        );
        assert_close(na, nb, 1e-11, scale, &format!("{name} eq. 11 at {k}"));
        checked += 1;
    }
    checked
}

#[test]
fn every_follower_on_paper_cams_both_directions() {
    for revised in [false, true] {
        for (dir, pivot) in [
            (Sense::Ccw, Point2::origin()),
            (Sense::Cw, Point2::new(1.5, -2.0)),
        ] {
            for f in all_followers(pivot) {
                let m = mechanism(paper_profile(revised), pivot, dir, 1000.0, f.clone());
                let name = format!("{} revised={revised} {dir:?}", f.kind_name());
                let n = check(&m, &name);
                assert!(n >= 45, "{name}: only {n} angles away from nodes");
            }
        }
    }
}
