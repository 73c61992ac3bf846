//! The paper's cam (section 3): reference values of `cam-follower.md`.
#![allow(clippy::unwrap_used)]
use crate::common::*;

#[test]
fn paper_cam_reference_values() {
    let m = paper_mechanism(false);
    let s0 = m.analyze_deg(0.0).unwrap();
    assert_close(s0.position, 5.0, 1e-14, 5.0, "s(0)");
    assert_close(s0.acceleration, -26_961.97, 0.006, 1.0, "a(0)");
    let s45 = m.analyze_deg(45.0).unwrap();
    assert_close(s45.position, 4.448456, 5e-7, 1.0, "s(45°)");
    assert_close(s45.acceleration, -6_291.918, 6e-4, 1.0, "a(45°)");
}
