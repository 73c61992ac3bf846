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
        // the field by enum, and its name as the schema writes it
        Err(CurveError::Gear { field, .. }) => (field, field.to_string()),
        Err(CurveError::NonPositive { field, .. }) => (field, field.to_string()),
        other => panic!("accepted: {other:?}"),
    };
    use super::super::CurveField as F;
    assert_eq!(
        field(InvoluteGearSpec::new(2.0, 2, a)),
        (F::Teeth, "teeth".to_string())
    );
    assert_eq!(
        field(InvoluteGearSpec::new(f64::NAN, 20, a)),
        (F::Module, "module".to_string())
    );
    assert_eq!(
        field(InvoluteGearSpec::new(2.0, 20, 60f64.to_radians())),
        (F::PressureAngle, "pressure_angle_deg".to_string())
    );
    let mut s = InvoluteGearSpec::new(2.0, 10, a);
    s.addendum = 2.0;
    assert_eq!(field(s), (F::Addendum, "addendum".to_string()));
    let mut s = InvoluteGearSpec::new(2.0, 20, a);
    s.fillet_radius = Some(5.0);
    assert_eq!(field(s), (F::FilletRadius, "fillet_radius".to_string()));
    let mut s = InvoluteGearSpec::new(2.0, 20, a);
    s.tip_relief = Some(TipRelief {
        amount: 0.01,
        length: 50.0,
        shape: ReliefShape::Linear,
    });
    assert_eq!(
        field(s),
        (F::TipReliefLength, "tip_relief.length".to_string())
    );
    let mut s = InvoluteGearSpec::new(2.0, 20, a);
    s.backlash = 3.0;
    assert_eq!(field(s), (F::Backlash, "backlash".to_string()));
    let message = InvoluteGear::new(InvoluteGearSpec::new(2.0, 2, a))
        .unwrap_err()
        .to_string();
    assert!(message.contains("teeth = 2"), "{message}");
}

/// Signed distance (negative inside) from `p` to the generating rack's tooth at rest, in the
/// frame of the space it cuts (its middle on the +x axis): the tooth `X ≥ r_f`,
/// `|Y| ≤ w − (r − X) tan α` with its two tip corners rounded to `ρ`, i.e. the same trapezoid
/// shrunk by `ρ` (a convex polygon, its distance by its edges) less `ρ`.
fn rack_tooth_distance(p: Vec2, (r, rf, alpha, w, rho): (f64, f64, f64, f64, f64)) -> f64 {
    let half = |x: f64| w - (r - x) * alpha.tan() - rho / alpha.cos();
    let (x0, x1) = (rf + rho, r + 10.0 * (r - rf));
    let poly = [
        Vec2::new(x0, -half(x0)),
        Vec2::new(x1, -half(x1)),
        Vec2::new(x1, half(x1)),
        Vec2::new(x0, half(x0)),
    ];
    let mut inside = true;
    let mut dist = f64::INFINITY;
    for k in 0..4 {
        let (a, b) = (poly[k], poly[(k + 1) % 4]);
        let e = b - a;
        let len = e.norm();
        if len == 0.0 {
            continue;
        }
        let t = ((p - a).dot(&e) / (len * len)).clamp(0.0, 1.0);
        dist = dist.min((p - (a + t * e)).norm());
        // counter-clockwise polygon: inside is left of every edge
        inside &= cross(e, p - a) > 0.0;
    }
    (if inside { -dist } else { dist }) - rho
}

/// The outline below the tip is what a rack cutter leaves, checked by simulating the cutting
/// and nothing of the gear's construction: the rack rolled on the pitch circle (its teeth a
/// pitch apart), every outline point of a half tooth (root, fillet, flank; undercut or not)
/// is never inside a rack tooth and is touched by one (its least distance over the rolling is
/// zero), to 1e-9 of the module. Gears of 7 to 60 teeth, shifted and not, two rack tip radii.
#[test]
fn outline_below_the_tip_is_what_the_rack_cutter_leaves() {
    let alpha = 20f64.to_radians();
    let m = 2.0;
    let mut checked = 0;
    for (z, x, rho) in [
        (7, 0.2, None),
        (10, 0.0, None),
        (12, 0.0, Some(0.2)),
        (12, 0.4, None),
        (17, 0.0, None),
        (18, 0.0, None),
        (30, -0.3, None),
        (60, 0.0, Some(0.0)),
    ] {
        let mut spec = InvoluteGearSpec::new(m, z, alpha);
        spec.profile_shift = x;
        spec.fillet_radius = rho;
        let g = InvoluteGear::new(spec).unwrap();
        let zf = f64::from(z);
        let r = g.pitch_radius();
        let s = m * (FRAC_PI_2 + 2.0 * x * alpha.tan());
        let rack = (
            r,
            g.root_radius(),
            alpha,
            PI * r / zf - s / 2.0,
            g.fillet_radius(),
        );
        let pitch = TAU * r / zf;
        // the half tooth up to the tip circle, in the space's frame
        let top = g.half.last().unwrap().start;
        for k in 1..200 {
            let w = top * f64::from(k) / 200.0;
            let q = g.position(w).coords;
            let (sn, cs) = (PI / zf).sin_cos();
            let p = Vec2::new(cs * q.x - sn * q.y, sn * q.x + cs * q.y);
            let at = |phi: f64| {
                let (sn, cs) = phi.sin_cos();
                let y = Vec2::new(cs * p.x - sn * p.y, sn * p.x + cs * p.y - r * phi);
                (-2..=2)
                    .map(|j| rack_tooth_distance(y - Vec2::new(0.0, f64::from(j) * pitch), rack))
                    .fold(f64::INFINITY, f64::min)
            };
            // the least distance over the rolling: samples, then golden-section refinement
            let span = 3.0 * PI / zf;
            let n = 3000;
            let best = (0..=n)
                .map(|i| -span + 2.0 * span * f64::from(i) / f64::from(n))
                .min_by(|a, b| at(*a).total_cmp(&at(*b)))
                .unwrap();
            let h = 2.0 * span / f64::from(n);
            let (mut lo, mut hi) = (best - h, best + h);
            let g_ratio = 0.5 * (5f64.sqrt() - 1.0);
            for _ in 0..100 {
                let (a, b) = (hi - g_ratio * (hi - lo), lo + g_ratio * (hi - lo));
                if at(a) < at(b) {
                    hi = b;
                } else {
                    lo = a;
                }
            }
            let least = at(0.5 * (lo + hi));
            assert!(
                least.abs() <= 1e-9 * m,
                "z {z}, x {x}, ρ {rho:?}: the point at {w:.4} of the half tooth ({:.4} from the centre) is {least:.3e} from the rack",
                p.norm()
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 8 * 199);
}

/// The rack undercuts the involute when its flank's lowest point lies deeper below the pitch
/// line than the interference point, `h = (h_f − x) m − ρ (1 − sin α) > r sin² α` (the textbook's
/// least tooth count, 17 for a standard 20° gear with `ρ = 0.38 m`): then the fillet and the
/// involute meet at a corner above the base circle; otherwise with a common tangent.
#[test]
fn undercut_begins_where_the_textbook_says() {
    let alpha = 20f64.to_radians();
    for (z, x, undercut) in [
        (17, 0.0, true),
        (18, 0.0, false),
        (12, 0.0, true),
        (12, 0.4, false),
        (10, 0.5, false),
        (30, -0.8, true),
    ] {
        let mut spec = InvoluteGearSpec::new(2.0, z, alpha);
        spec.profile_shift = x;
        let g = InvoluteGear::new(spec).unwrap();
        let r = g.pitch_radius();
        let h = (1.25 - x) * 2.0 - g.fillet_radius() * (1.0 - alpha.sin());
        assert_eq!(
            h > r * alpha.sin().powi(2),
            undercut,
            "z {z}, x {x}: the textbook's condition"
        );
        // the joint of the fillet and the involute: the tangent's turn across it
        let j = g
            .half
            .iter()
            .position(|p| matches!(p.shape, Shape::Involute { .. }))
            .unwrap();
        let u = g.half[j].start;
        let (a, b) = (
            g.eval(u - 1e-7).d1.normalize(),
            g.eval(u + 1e-7).d1.normalize(),
        );
        let turn = cross(a, b).abs();
        let radius = g.position(u).coords.norm();
        if undercut {
            assert!(
                turn > 1e-4 && radius >= g.base_radius(),
                "z {z}, x {x}: turn {turn}, radius {radius}"
            );
        } else {
            assert!(
                turn < 1e-6 && radius >= g.base_radius(),
                "z {z}, x {x}: turn {turn}"
            );
        }
    }
}
