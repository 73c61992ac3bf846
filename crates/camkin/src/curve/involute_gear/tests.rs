//! Checks of the gear outline against closed forms that do not use its construction: finite
//! differences, the involute's defining properties (its normal is tangent to the base circle, its
//! radius of curvature is the roll length), the tooth thickness, symmetry and the relief's
//! distance from the unrelieved flank.

use super::*;
use crate::curve::test_support::check_derivatives;
use crate::geometry::cross;

fn gear(teeth: u32) -> InvoluteGear {
    InvoluteGear::new(InvoluteGearSpec::new(2.0, teeth, 20f64.to_radians())).unwrap()
}

fn period(g: &InvoluteGear) -> f64 {
    match g.domain() {
        Domain::Periodic { period } => period,
        _ => unreachable!(),
    }
}

/// Flank parameters of tooth 0's lower flank: strictly inside its involute piece(s).
fn flank_params(g: &InvoluteGear, n: usize) -> Vec<f64> {
    let tooth = g.tooth_length();
    (1..n)
        .map(|k| tooth * k as f64 / (2 * n) as f64)
        .filter(|&u| g.roll_length(u).is_some_and(|l| l > 1e-3))
        .collect()
}

#[test]
fn derivatives_match_finite_differences_on_every_piece() {
    for g in [gear(12), gear(42), {
        let mut s = InvoluteGearSpec::new(3.0, 20, 25f64.to_radians());
        s.profile_shift = 0.3;
        s.tip_relief = Some(TipRelief {
            amount: 0.02,
            length: 1.5,
            shape: ReliefShape::Parabolic,
        });
        InvoluteGear::new(s).unwrap()
    }] {
        let mut bp = g.breakpoints();
        bp.push(period(&g));
        for w in bp.windows(2).take(24) {
            let (a, b) = (w[0], w[1]);
            if b - a > 1e-2 {
                for f in [0.3, 0.5, 0.7] {
                    check_derivatives(&g, a + f * (b - a), 1e-6);
                }
            }
        }
    }
}

#[test]
fn outline_is_continuous_closed_and_counter_clockwise() {
    for g in [gear(7), gear(12), gear(42), gear(100)] {
        let p = period(&g);
        for &b in g.breakpoints().iter().chain([0.0, p].iter()) {
            let (x0, x1) = (g.position(b - 1e-11), g.position(b + 1e-11));
            assert!((x0 - x1).norm() < 1e-9, "gap at {b}: {x0} {x1}");
        }
        // shoelace area: positive (counter-clockwise), between the root and tip discs
        let n = 20_000;
        let pts: Vec<Point2> = (0..n)
            .map(|k| g.position(p * k as f64 / n as f64))
            .collect();
        let area: f64 = (0..n)
            .map(|k| cross(pts[k].coords, pts[(k + 1) % n].coords) / 2.0)
            .sum();
        let (rf, ra) = (g.root_radius(), g.tip_radius());
        assert!(area > PI * rf * rf && area < PI * ra * ra, "area {area}");
        // radii within [r_f, r_a]
        for x in &pts {
            let r = x.coords.norm();
            assert!(
                r >= rf * (1.0 - 1e-12) && r <= ra * (1.0 + 1e-12),
                "radius {r}"
            );
        }
    }
}

#[test]
fn flank_normals_are_tangent_to_the_base_circle_and_curvature_is_the_roll_length() {
    for g in [gear(12), gear(42)] {
        let rb = g.base_radius();
        for u in flank_params(&g, 40) {
            let d = g.eval(u);
            // the normal line through p is at distance r_b from the centre
            let dist = cross(d.p.coords, d.normal()).abs();
            assert!((dist - rb).abs() < 1e-12 * rb, "{dist} vs {rb}");
            // radius of curvature = √(R² − r_b²); convex (material on the left: κ > 0)
            let roll = (d.p.coords.norm_squared() - rb * rb).sqrt();
            let k = d.curvature();
            assert!((k * roll - 1.0).abs() < 1e-9, "κ L = {}", k * roll);
            // and on a tooth, the whole flank is seen turning the same way round every tooth
            let next = g.eval(u + g.tooth_length());
            let a = TAU / f64::from(g.teeth());
            let turned = Point2::new(
                a.cos() * d.p.x - a.sin() * d.p.y,
                a.sin() * d.p.x + a.cos() * d.p.y,
            );
            assert!((next.p - turned).norm() < 1e-12 * g.tip_radius());
        }
    }
}

/// The polar angle at which the flank of tooth 0 on the side of `lo..hi` crosses radius `r`,
/// by bisection on positions only.
fn flank_angle_at(g: &InvoluteGear, r: f64, mut lo: f64, mut hi: f64) -> f64 {
    let f = |u: f64| g.position(u).coords.norm() - r;
    let up = f(hi) > f(lo);
    for _ in 0..200 {
        let m = 0.5 * (lo + hi);
        if (f(m) < 0.0) == up {
            lo = m;
        } else {
            hi = m;
        }
    }
    let p = g.position(0.5 * (lo + hi));
    p.y.atan2(p.x)
}

#[test]
fn tooth_thickness_on_the_pitch_circle_is_the_textbook_value() {
    for (z, shift, backlash) in [
        (12, 0.0, 0.0),
        (42, 0.0, 0.1),
        (17, 0.4, 0.0),
        (30, -0.2, 0.05),
    ] {
        let mut s = InvoluteGearSpec::new(2.0, z, 20f64.to_radians());
        s.profile_shift = shift;
        s.backlash = backlash;
        let g = InvoluteGear::new(s).unwrap();
        let r = g.pitch_radius();
        let h = g.tooth_length() / 2.0;
        // lower flank in the first half tooth, upper in the second
        let a_lo = flank_angle_at(&g, r, 0.0, h);
        let a_hi = flank_angle_at(&g, r, h, 2.0 * h);
        let expect =
            2.0 * (PI / 2.0 + 2.0 * shift * 20f64.to_radians().tan()) - 2.0 * backlash / 2.0;
        let thickness = r * (a_hi - a_lo);
        assert!(
            (thickness - expect).abs() < 1e-10,
            "z = {z}: {thickness} vs {expect}"
        );
        // symmetric about the tooth's centre line (tooth 0 on the +x axis)
        assert!((a_lo + a_hi).abs() < 1e-12);
    }
}

#[test]
fn radii_follow_the_textbook() {
    let mut s = InvoluteGearSpec::new(2.5, 30, 20f64.to_radians());
    s.profile_shift = 0.25;
    let g = InvoluteGear::new(s).unwrap();
    assert!((g.pitch_radius() - 37.5).abs() < 1e-12);
    assert!((g.base_radius() - 37.5 * 20f64.to_radians().cos()).abs() < 1e-12);
    assert!((g.tip_radius() - (37.5 + 2.5 * 1.25)).abs() < 1e-12);
    assert!((g.root_radius() - (37.5 - 2.5 * 1.0)).abs() < 1e-12);
    assert_eq!(g.symmetry(), 30);
}

/// The distance from `x` to the flank of `g` near parameter `u0`, by Newton on the foot point.
fn distance_to_flank(g: &InvoluteGear, x: Point2, u0: f64) -> f64 {
    let mut u = u0;
    for _ in 0..50 {
        let d = g.eval(u);
        let r = d.p - x;
        let f = r.dot(&d.d1);
        let df = d.d1.norm_squared() + r.dot(&d.d2);
        u -= f / df;
    }
    (g.position(u) - x).norm()
}

#[test]
fn tip_relief_removes_the_closed_form_amount_along_the_normal() {
    for shape in [ReliefShape::Linear, ReliefShape::Parabolic] {
        let (amount, length) = (0.015, 2.0);
        let plain_spec = InvoluteGearSpec::new(2.0, 24, 20f64.to_radians());
        let mut spec = plain_spec;
        spec.tip_relief = Some(TipRelief {
            amount,
            length,
            shape,
        });
        let (g, plain) = (
            InvoluteGear::new(spec).unwrap(),
            InvoluteGear::new(plain_spec).unwrap(),
        );
        let rb = g.base_radius();
        let la = (g.tip_radius().powi(2) - rb * rb).sqrt();
        let mut seen = 0;
        for u in flank_params(&g, 200) {
            let x = g.position(u);
            let roll = (x.coords.norm_squared() - rb * rb).sqrt();
            let t = ((roll - (la - length)) / length).max(0.0);
            let expect = match shape {
                ReliefShape::Linear => amount * t,
                ReliefShape::Parabolic => amount * t * t,
            };
            let got = distance_to_flank(&plain, x, u);
            assert!(
                (got - expect).abs() < 1e-12,
                "L = {roll}: {got} vs {expect}"
            );
            seen += usize::from(t > 0.0);
        }
        assert!(seen > 5);
    }
}

#[test]
fn refuses_gears_that_cannot_be_made() {
    let a = 20f64.to_radians();
    let field = |s: InvoluteGearSpec| match InvoluteGear::new(s) {
        Err(CurveError::Gear { field, .. }) => field,
        Err(CurveError::NonPositive { field, .. }) => field,
        other => panic!("accepted: {other:?}"),
    };
    assert_eq!(field(InvoluteGearSpec::new(2.0, 2, a)), "teeth");
    assert_eq!(field(InvoluteGearSpec::new(f64::NAN, 20, a)), "module");
    assert_eq!(
        field(InvoluteGearSpec::new(2.0, 20, 60f64.to_radians())),
        "pressure_angle_deg"
    );
    let mut s = InvoluteGearSpec::new(2.0, 10, a);
    s.addendum = 2.0;
    assert_eq!(field(s), "addendum");
    let mut s = InvoluteGearSpec::new(2.0, 20, a);
    s.fillet_radius = Some(5.0);
    assert_eq!(field(s), "fillet_radius");
    let mut s = InvoluteGearSpec::new(2.0, 20, a);
    s.tip_relief = Some(TipRelief {
        amount: 0.01,
        length: 50.0,
        shape: ReliefShape::Linear,
    });
    assert_eq!(field(s), "tip_relief.length");
    let mut s = InvoluteGearSpec::new(2.0, 20, a);
    s.backlash = 3.0;
    assert_eq!(field(s), "backlash");
    let message = InvoluteGear::new(InvoluteGearSpec::new(2.0, 2, a))
        .unwrap_err()
        .to_string();
    assert!(message.contains("teeth = 2"), "{message}");
}

#[test]
fn many_teeth_meet_the_root_at_a_corner_and_few_get_a_fillet() {
    // r_f ≥ r_b from about 42 teeth at 20°: no room for a fillet below the base circle
    assert_eq!(gear(60).fillet_radius(), 0.0);
    let g = gear(20);
    assert!(g.fillet_radius() > 0.0 && g.fillet_radius() <= 0.38 * 2.0 + 1e-15);
}
