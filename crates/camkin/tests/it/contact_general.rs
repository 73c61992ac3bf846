//! The contact module on its own: two curves on two freely moving bodies.
//!
//! Oracle: when the curves touch with zero normal velocity at t = 0, the gap `d(t)` between the
//! pairing points (followed by Newton from the t = 0 pairing) has `d̈(0) = a_n^A − a_n^B =
//! Φ_q q̈ − γ` (eq. 11), and the pairing parameters drift at the rates of eqs. 5–7, 9. Both are
//! measured by finite differences of positions only.
#![allow(clippy::unwrap_used)]
use crate::common::*;
use camkin::body::{BodyState, Pose};
use camkin::contact::{
    find_contact, refine, ContactError, ContactKinematics, Pairing, Proximity, SearchOptions,
    Surface,
};
use camkin::curve::{Circle, ClosedSpline, Curve, Ellipse, Line, PointCurve};
use camkin::{Point2, Vec2};

fn at_time(b: &BodyState, t: f64) -> BodyState {
    BodyState {
        pose: Pose::new(
            b.pose.origin + b.velocity * t + 0.5 * b.acceleration * t * t,
            b.pose.angle + b.omega * t + 0.5 * b.alpha * t * t,
        ),
        velocity: b.velocity + b.acceleration * t,
        omega: b.omega + b.alpha * t,
        ..*b
    }
}

/// Places B touching A with zero normal velocity; returns (A, B, pairing).
fn touching(
    ca: &dyn Curve,
    cb: &dyn Curve,
    a: BodyState,
    mut b: BodyState,
    opts: &SearchOptions,
) -> (BodyState, BodyState, Pairing) {
    let p = find_contact(&Surface::new(ca, &a), &Surface::new(cb, &b), opts)
        .unwrap()
        .pairing();
    // move B along the normal to close the gap
    b.pose.origin += p.gap * *p.normal;
    let p = refine(
        &Surface::new(ca, &a),
        &Surface::new(cb, &b),
        p.u_a,
        p.u_b,
        opts,
    )
    .unwrap();
    assert!(p.gap.abs() < 1e-12);
    // zero normal velocity: adjust B's velocity along the normal
    let vn = p
        .normal
        .dot(&(a.velocity_at(p.point_a) - b.velocity_at(p.point_a)));
    b.velocity += vn * *p.normal;
    (a, b, p)
}

fn check_pair(ca: &dyn Curve, cb: &dyn Curve, a: BodyState, b: BodyState) {
    let opts = SearchOptions::for_length_scale(5.0);
    let (a, b, p0) = touching(ca, cb, a, b, &opts);
    let k =
        ContactKinematics::new(&Surface::new(ca, &a), &Surface::new(cb, &b), &p0, 1e-9).unwrap();
    assert!(
        k.normal_velocity.abs() < 1e-12,
        "normal velocity {}",
        k.normal_velocity
    );
    let track = |t: f64| {
        let (at, bt) = (at_time(&a, t), at_time(&b, t));
        refine(
            &Surface::new(ca, &at),
            &Surface::new(cb, &bt),
            p0.u_a,
            p0.u_b,
            &opts,
        )
        .unwrap()
    };
    let h = 2e-3;
    let (dd1, dd2) = fd8(|t| track(t).gap, 0.0, h);
    let scale = 1.0 + k.gamma.abs();
    assert!(dd1.abs() < 1e-9 * scale, "ḋ(0) = {dd1}");
    let (na, nb) = (k.normal_acceleration_a(&a), k.normal_acceleration_b(&b));
    assert_close(
        dd2,
        na.total() - nb.total(),
        1e-7,
        scale,
        "d̈ = a_n^A − a_n^B",
    );
    assert_close(
        k.acceleration_residual(&a, &b),
        na.total() - nb.total(),
        1e-12,
        scale,
        "Φ_q q̈ − γ = a_n^A − a_n^B",
    );
    let (ua_rate, _) = fd8(|t| track(t).u_a, 0.0, h);
    assert_close(k.param_rate_a, ua_rate, 1e-8, 1.0 + ua_rate.abs(), "u̇_A");
    if k.metric_b > 0.0 {
        let (ub_rate, _) = fd8(|t| track(t).u_b, 0.0, h);
        assert_close(k.param_rate_b, ub_rate, 1e-8, 1.0 + ub_rate.abs(), "u̇_B");
    }
}

fn spline() -> ClosedSpline {
    ClosedSpline::new(&paper_nodes(false)).unwrap()
}

fn moving(
    origin: (f64, f64),
    angle: f64,
    v: (f64, f64),
    w: f64,
    acc: (f64, f64),
    alpha: f64,
) -> BodyState {
    BodyState {
        pose: Pose::new(Point2::new(origin.0, origin.1), angle),
        velocity: Vec2::new(v.0, v.1),
        omega: w,
        acceleration: Vec2::new(acc.0, acc.1),
        alpha,
    }
}

#[test]
fn spline_against_ellipse_both_moving() {
    let e = Ellipse::new(Point2::new(0.3, 0.1), 2.0, 1.2, 0.4).unwrap();
    check_pair(
        &spline(),
        &e,
        moving((0.0, 0.0), 0.3, (0.5, -0.2), 2.0, (1.0, 3.0), -4.0),
        moving((8.0, 1.0), -0.7, (-1.0, 0.4), -3.0, (-2.0, 0.5), 6.0),
    );
}

#[test]
fn circle_against_circle_and_roles_swapped() {
    let c1 = Circle::new(Point2::new(0.5, 0.0), 2.0).unwrap();
    let c2 = Circle::new(Point2::new(0.0, -0.3), 1.0).unwrap();
    let a = moving((0.0, 0.0), 0.1, (0.0, 0.0), 5.0, (0.0, 0.0), 1.0);
    let b = moving((4.0, 2.0), 0.2, (0.3, 0.0), -2.0, (0.5, -1.0), 0.0);
    check_pair(&c1, &c2, a, b);
    check_pair(&c2, &c1, b, a);
}

#[test]
fn swapping_a_and_b_gives_same_contact_and_sliding_rates() {
    let sp = spline();
    let e = Ellipse::new(Point2::origin(), 1.5, 1.0, 0.0).unwrap();
    let opts = SearchOptions::for_length_scale(5.0);
    let (a, b, p) = touching(
        &sp,
        &e,
        moving((0.0, 0.0), 1.0, (0.1, 0.2), 3.0, (0.0, 0.0), 0.0),
        moving((1.0, 7.0), 0.5, (0.0, -1.0), -1.0, (0.0, 0.0), 0.0),
        &opts,
    );
    let (sa, sb) = (Surface::new(&sp, &a), Surface::new(&e, &b));
    let kab = ContactKinematics::new(&sa, &sb, &p, 1e-9).unwrap();
    let q = find_contact(&sb, &sa, &opts).unwrap().pairing();
    let kba = ContactKinematics::new(&sb, &sa, &q, 1e-9).unwrap();
    assert_close(q.u_a, p.u_b, 1e-10, 1.0, "u swapped");
    assert_close(q.u_b, p.u_a, 1e-10, 1.0, "u swapped");
    assert_close(
        (q.point_a - p.point_a).norm(),
        0.0,
        1e-10,
        1.0,
        "same point",
    );
    assert_close(
        kba.sliding_rate_a,
        kab.sliding_rate_b,
        1e-12,
        10.0,
        "ṡ_A(BA) = ṡ_B(AB)",
    );
    assert_close(
        kba.sliding_rate_b,
        kab.sliding_rate_a,
        1e-12,
        10.0,
        "ṡ_B(BA) = ṡ_A(AB)",
    );
    assert_eq!(kab.sigma, kba.sigma);
    // the constraint is the same equation up to sign
    let (a2, b2) = (
        BodyState {
            acceleration: Vec2::new(1.0, -2.0),
            alpha: 3.0,
            ..a
        },
        BodyState {
            acceleration: Vec2::new(0.5, 0.5),
            alpha: -1.0,
            ..b
        },
    );
    assert_close(
        kab.acceleration_residual(&a2, &b2).abs(),
        kba.acceleration_residual(&b2, &a2).abs(),
        1e-12,
        100.0,
        "|residual|",
    );
}

#[test]
fn knife_edge_point_on_a_curve() {
    let tip = PointCurve::new(Point2::new(0.0, 0.0)).unwrap();
    // point as B, then as A
    check_pair(
        &spline(),
        &tip,
        moving((0.0, 0.0), 0.2, (0.0, 0.0), 4.0, (0.0, 0.0), 2.0),
        moving((7.0, 0.5), 0.0, (0.0, 1.0), 0.0, (3.0, -1.0), 0.0),
    );
    check_pair(
        &tip,
        &spline(),
        moving((7.0, 0.5), 0.0, (0.0, 1.0), 0.7, (3.0, -1.0), 0.0),
        moving((0.0, 0.0), 0.2, (0.0, 0.0), 4.0, (0.0, 0.0), 2.0),
    );
}

#[test]
fn flat_line_against_curve() {
    let face = Line::new(Point2::origin(), Vec2::new(0.0, -1.0)).unwrap();
    check_pair(
        &spline(),
        &face,
        moving((0.0, 0.0), 0.5, (0.0, 0.0), 6.0, (0.0, 0.0), 0.0),
        moving((9.0, 0.0), 0.1, (0.5, 0.0), 0.8, (1.0, 0.0), -1.0),
    );
}

#[test]
fn apart_touching_and_overlapping_are_results() {
    let c1 = Circle::new(Point2::origin(), 2.0).unwrap();
    let c2 = Circle::new(Point2::origin(), 1.0).unwrap();
    let a = BodyState::at_rest(Pose::new(Point2::origin(), 0.0));
    let opts = SearchOptions::for_length_scale(2.0);
    let far = BodyState::at_rest(Pose::new(Point2::new(3.5, 0.0), 0.0));
    match find_contact(&Surface::new(&c1, &a), &Surface::new(&c2, &far), &opts).unwrap() {
        Proximity::Apart(p) => assert_close(p.gap, 0.5, 1e-12, 1.0, "gap of separated circles"),
        other => panic!("expected apart, got {other:?}"),
    }
    let touch = BodyState::at_rest(Pose::new(Point2::new(3.0, 0.0), 0.0));
    let c = find_contact(&Surface::new(&c1, &a), &Surface::new(&c2, &touch), &opts)
        .unwrap()
        .contact()
        .expect("touching");
    assert_close(c.point_a.x, 2.0, 1e-12, 1.0, "contact point");
    let overlap = BodyState::at_rest(Pose::new(Point2::new(2.5, 0.0), 0.0));
    match find_contact(&Surface::new(&c1, &a), &Surface::new(&c2, &overlap), &opts) {
        Ok(Proximity::Overlapping(p)) => assert_close(-p.gap, 0.5, 1e-9, 1.0, "depth"),
        other => panic!("expected overlap, got {other:?}"),
    }
}

#[test]
fn conformal_contact_is_an_error_not_a_division() {
    // a pin in a hole of its own size: a circle inside an equal circle, traversed the same way
    let hole = Circle::new(Point2::origin(), 1.0).unwrap();
    let pin = Circle::new(Point2::origin(), 1.0).unwrap();
    let a = BodyState::rotating(Point2::origin(), 0.0, 1.0, 0.0);
    let b = BodyState::rotating(Point2::origin(), 0.3, -2.0, 0.0);
    let (sa, sb) = (Surface::new(&hole, &a), Surface::new(&pin, &b));
    let p = camkin::contact::pairing_at(&sa, &sb, 0.0, -0.3);
    match ContactKinematics::new(&sa, &sb, &p, 1e-9) {
        Err(ContactError::Conformal {
            kappa_a,
            kappa_b,
            sigma,
            ..
        }) => {
            assert_eq!((kappa_a, kappa_b, sigma), (1.0, 1.0, 1.0));
        }
        other => panic!("expected conformal error, got {other:?}"),
    }
    // flat on flat
    let l1 = Line::new(Point2::origin(), Vec2::x()).unwrap();
    let l2 = Line::new(Point2::origin(), -Vec2::x()).unwrap();
    let p = camkin::contact::pairing_at(&Surface::new(&l1, &a), &Surface::new(&l2, &a), 0.0, 0.0);
    assert!(matches!(
        ContactKinematics::new(&Surface::new(&l1, &a), &Surface::new(&l2, &a), &p, 1e-9),
        Err(ContactError::Conformal { .. })
    ));
}

/// Regression: `refine` used `r_A'·d = r_B'·d = 0`, whose Jacobian is singular at contact (d = 0),
/// so Newton from an exact contact stopped with a non-finite step; crossings also solved it.
#[test]
fn regression_refine_singular_at_contact() {
    let c1 = Circle::new(Point2::origin(), 2.0).unwrap();
    let c2 = Circle::new(Point2::origin(), 1.0).unwrap();
    let a = BodyState::at_rest(Pose::new(Point2::origin(), 0.0));
    let b = BodyState::at_rest(Pose::new(Point2::new(3.0, 0.0), 0.0));
    let opts = SearchOptions::for_length_scale(2.0);
    let p = refine(
        &Surface::new(&c1, &a),
        &Surface::new(&c2, &b),
        0.05,
        std::f64::consts::PI - 0.05,
        &opts,
    )
    .unwrap();
    assert_close(p.u_a, 0.0, 1e-12, 1.0, "u_a");
    assert_close(p.gap, 0.0, 1e-12, 1.0, "gap");
    // from a crossing of two overlapping circles Newton must not stop at the crossing
    let b = BodyState::at_rest(Pose::new(Point2::new(2.5, 0.0), 0.0));
    let x = 1.85f64; // crossing at (1.85, ±0.76)
    let (ua, ub) = ((0.76f64).atan2(x), (0.76f64).atan2(x - 2.5));
    if let Ok(p) = refine(
        &Surface::new(&c1, &a),
        &Surface::new(&c2, &b),
        ua,
        ub,
        &opts,
    ) {
        assert!(
            tangent_misalignment_is_zero(&c1, &c2, &a, &b, &p),
            "stopped at a crossing: {p:?}"
        );
    }
}

fn tangent_misalignment_is_zero(
    c1: &dyn Curve,
    c2: &dyn Curve,
    a: &BodyState,
    b: &BodyState,
    p: &Pairing,
) -> bool {
    camkin::contact::tangent_misalignment(&Surface::new(c1, a), &Surface::new(c2, b), p).abs()
        < 1e-9
}

/// Regression: with a point as A the swapped constraint row had the sign of γ flipped against
/// Φ_q, so `Φ_q q̈ − γ` was not `a_n^A − a_n^B`.
#[test]
fn regression_point_as_a_constraint_sign() {
    let tip = PointCurve::new(Point2::origin()).unwrap();
    let c = Circle::new(Point2::origin(), 1.0).unwrap();
    let a = moving((2.0, 0.0), 0.0, (0.0, 1.0), 0.5, (1.0, 2.0), 0.3);
    let b = moving((1.0, 0.0), 0.0, (0.0, 0.0), -1.0, (0.0, 0.0), 0.7);
    let (sa, sb) = (Surface::new(&tip, &a), Surface::new(&c, &b));
    let p = camkin::contact::pairing_at(&sa, &sb, 0.0, 0.0);
    let k = ContactKinematics::new(&sa, &sb, &p, 1e-9).unwrap();
    let direct = k.normal_acceleration_a(&a).total() - k.normal_acceleration_b(&b).total();
    assert_close(
        k.acceleration_residual(&a, &b),
        direct,
        1e-12,
        10.0,
        "Φ_q q̈ − γ",
    );
    assert_eq!(*k.normal, Vec2::new(1.0, 0.0)); // −ν_B of a ccw circle at angle 0 (ν_B = (−1, 0))
}

/// Indexes built once answer as the search that builds them (two discs, closed form: the gap is
/// the centres' distance minus the radii at every pose), a missing index is built, and an index
/// of another curve is refused rather than searched with.
#[test]
fn indexed_search_answers_as_the_plain_one_and_refuses_a_foreign_index() {
    use camkin::contact::{find_contact_indexed, CurveIndex};
    let (c1, c2) = (
        Circle::new(Point2::new(0.3, 0.0), 2.0).unwrap(),
        Circle::new(Point2::origin(), 1.0).unwrap(),
    );
    let opts = SearchOptions::for_length_scale(2.0);
    let (i1, i2) = (CurveIndex::new(&c1, &opts), CurveIndex::new(&c2, &opts));
    for k in 0..20 {
        let t = f64::from(k) * 0.31;
        let a = BodyState::at_rest(Pose::new(Point2::new(0.1, -0.2), t));
        let b = BodyState::at_rest(Pose::new(Point2::new(3.5 + 0.1 * t, 0.4), -t));
        let (sa, sb) = (Surface::new(&c1, &a), Surface::new(&c2, &b));
        let want = (a.pose.to_world(Point2::new(0.3, 0.0)) - b.pose.origin).norm() - 3.0;
        for p in [
            find_contact(&sa, &sb, &opts).unwrap(),
            find_contact_indexed(&sa, i1.as_ref(), &sb, i2.as_ref(), &opts).unwrap(),
            find_contact_indexed(&sa, None, &sb, i2.as_ref(), &opts).unwrap(),
        ] {
            assert!((p.gap() - want).abs() <= 1e-12, "{} {want}", p.gap());
        }
        let e = find_contact_indexed(&sa, i2.as_ref(), &sb, i1.as_ref(), &opts).unwrap_err();
        assert!(matches!(e, ContactError::Unsupported(_)), "{e}");
    }
}

/// Regression (issue 45): two meshing spur gears (20 and 31 teeth, module 2, 20°) at their
/// standard centre distance touch on their flanks; the global search used to report them
/// overlapping by 5.9 mm, at a pair of points across a tooth space whose normals are opposed (a
/// flank and the next tooth's tip): a negative gap, but neither point inside the other gear. The
/// same gears 0.3 mm closer do overlap, and the deepest pair found has each point inside the
/// other gear's outline.
#[test]
fn meshing_gears_touch_and_do_not_overlap_across_a_space() {
    use camkin::curve::{InvoluteGear, InvoluteGearSpec};
    use std::f64::consts::PI;
    let (m, alpha) = (2.0, 20f64.to_radians());
    let g1 = InvoluteGear::new(InvoluteGearSpec::new(m, 20, alpha)).unwrap();
    let g2 = InvoluteGear::new(InvoluteGearSpec::new(m, 31, alpha)).unwrap();
    let s1 = BodyState::at_rest(Pose::new(Point2::origin(), 0.0));
    let opts = SearchOptions::for_length_scale(50.0);
    for turn in [0.0, 0.05, 0.11] {
        // gear 2's space faces gear 1's tooth 0, both turned by the ratio
        let s1 = BodyState::at_rest(Pose::new(Point2::origin(), turn));
        let s2 = BodyState::at_rest(Pose::new(
            Point2::new(51.0, 0.0),
            PI + PI / 31.0 - turn * 20.0 / 31.0,
        ));
        match find_contact(&Surface::new(&g1, &s1), &Surface::new(&g2, &s2), &opts).unwrap() {
            Proximity::Touching(p) => assert!(p.gap.abs() <= 1e-9, "{p:?}"),
            other => panic!("turned {turn}: {other:?}"),
        }
    }
    let closer = BodyState::at_rest(Pose::new(Point2::new(50.7, 0.0), PI + PI / 31.0));
    match find_contact(&Surface::new(&g1, &s1), &Surface::new(&g2, &closer), &opts).unwrap() {
        Proximity::Overlapping(p) => {
            assert!(p.gap < 0.0 && p.gap > -0.3, "{p:?}");
            // each point inside the other gear: within its tip circle, beyond its root circle
            let r1 = p.point_b.coords.norm();
            let r2 = (p.point_a - closer.pose.origin).norm();
            assert!(r1 < g1.tip_radius() && r2 < g2.tip_radius(), "{p:?}");
        }
        other => panic!("{other:?}"),
    }
}
