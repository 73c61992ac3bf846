//! `MechanismSpec`: a mechanism built from plain data, with no command-line code; every invalid
//! spec is refused with the field named by an enum and the value.

use crate::common::*;
use camkin::cam::{Cam, Follower, Mechanism, Sense};
use camkin::spec::{
    BuildOptions, CamField, CamSpec, DynamicsField, DynamicsSpec, Field, FollowerField,
    FollowerSpec, MechanismSpec, ProfileField, ProfileSpec, SegmentField, SegmentSpec, SpecError,
};
use camkin::Point2;

fn circle_spec(follower: FollowerSpec) -> MechanismSpec {
    MechanismSpec {
        length_unit: Some("mm".into()),
        cam: CamSpec {
            speed_rpm: 600.0,
            direction: Some(Sense::Cw),
            profile: ProfileSpec {
                kind: "circle".into(),
                center: Some([0.7, 0.3]),
                radius: Some(2.0),
                ..Default::default()
            },
            ..Default::default()
        },
        follower,
        ..Default::default()
    }
}

fn flat() -> FollowerSpec {
    FollowerSpec {
        kind: "translating-flat".into(),
        ..Default::default()
    }
}

#[test]
fn paper_spec_builds_the_papers_mechanism_bit_for_bit() {
    let spec = MechanismSpec {
        length_unit: Some("mm".into()),
        cam: CamSpec {
            speed_rpm: 1000.0,
            profile: ProfileSpec {
                kind: "spline".into(),
                points: Some(paper_nodes(false).iter().map(|p| [p.x, p.y]).collect()),
                ..Default::default()
            },
            ..Default::default()
        },
        follower: FollowerSpec {
            direction: Some([1.0, 0.0]),
            ..flat()
        },
        ..Default::default()
    };
    let m = Mechanism::try_from(spec).unwrap();
    let r = paper_mechanism(false);
    for k in 0..36 {
        let t = (k as f64 * 10.0).to_radians();
        let (a, b) = (m.analyze(t).unwrap(), r.analyze(t).unwrap());
        assert_eq!(
            (a.position, a.velocity, a.acceleration),
            (b.position, b.velocity, b.acceleration)
        );
    }
}

#[test]
fn eccentric_circle_spec_gives_the_closed_form() {
    // cw cam, centre off the follower's axis: s(θ) = x-extent of the circle turned by −θ
    let m = Mechanism::try_from(circle_spec(flat())).unwrap();
    let w = 600.0 * std::f64::consts::TAU / 60.0;
    for k in 0..24 {
        let t = (k as f64 * 15.0).to_radians();
        let s = m.analyze(t).unwrap();
        // centre (0.7, 0.3) turned by −θ: x = 0.7 cos θ + 0.3 sin θ
        let x = 0.7 * t.cos() + 0.3 * t.sin();
        let a = -w * w * x;
        assert_close(s.position, x + 2.0, 1e-13, 3.0, "s");
        assert_close(s.acceleration, a, 1e-11, w * w, "a");
    }
}

#[test]
fn every_follower_kind_matches_the_follower_built_directly() {
    let specs = [
        (
            FollowerSpec {
                kind: "translating-roller".into(),
                direction: Some([0.0, 1.0]),
                offset: Some(0.4),
                roller_radius: Some(0.5),
                ..Default::default()
            },
            Follower::TranslatingRoller {
                direction: camkin::Vec2::new(0.0, 1.0),
                offset: 0.4,
                roller_radius: 0.5,
            },
        ),
        (
            FollowerSpec {
                kind: "translating-knife".into(),
                offset: Some(-0.3),
                ..Default::default()
            },
            Follower::TranslatingKnife {
                direction: camkin::Vec2::x(),
                offset: -0.3,
            },
        ),
        (
            FollowerSpec {
                kind: "oscillating-flat".into(),
                pivot: Some([-3.0, 7.0]),
                offset: Some(0.2),
                closing: Some(Sense::Cw),
                initial_angle_deg: Some(-30.0),
                ..Default::default()
            },
            Follower::OscillatingFlat {
                pivot: Point2::new(-3.0, 7.0),
                face_offset: 0.2,
                closing: Sense::Cw,
                initial_angle: (-30f64).to_radians(),
            },
        ),
        (
            FollowerSpec {
                kind: "oscillating-roller".into(),
                pivot: Some([-3.0, 7.0]),
                arm_length: Some(9.0),
                roller_radius: Some(1.0),
                closing: Some(Sense::Cw),
                initial_angle_deg: Some(-30.0),
                ..Default::default()
            },
            Follower::OscillatingRoller {
                pivot: Point2::new(-3.0, 7.0),
                arm_length: 9.0,
                roller_radius: 1.0,
                closing: Sense::Cw,
                initial_angle: (-30f64).to_radians(),
            },
        ),
    ];
    for (spec, follower) in specs {
        let a = Mechanism::try_from(circle_spec(spec.clone())).unwrap();
        let profile =
            std::sync::Arc::new(camkin::curve::Circle::new(Point2::new(0.7, 0.3), 2.0).unwrap());
        let b = Mechanism::new(
            Cam::from_rpm(profile, Point2::origin(), Sense::Cw, 600.0).unwrap(),
            follower,
        )
        .unwrap();
        assert_eq!(a.follower(), b.follower(), "{}", spec.kind);
        let (sa, sb) = (a.analyze(0.4).unwrap(), b.analyze(0.4).unwrap());
        assert_eq!(
            (sa.position, sa.acceleration),
            (sb.position, sb.acceleration),
            "{}",
            spec.kind
        );
    }
}

/// Each edit of a valid spec is refused naming `field` (an enum) with `value` in the message.
#[test]
fn invalid_specs_name_the_field_by_enum_and_carry_the_value() {
    type Edit = fn(&mut MechanismSpec);
    let cases: Vec<(Edit, Field, &str)> = vec![
        (
            |s| s.cam.speed_rpm = -5.0,
            Field::Cam(CamField::SpeedRpm),
            "-5",
        ),
        (
            |s| s.cam.speed_rpm = f64::INFINITY,
            Field::Cam(CamField::SpeedRpm),
            "inf",
        ),
        (
            |s| s.cam.pivot = Some([0.0, f64::NAN]),
            Field::Cam(CamField::Pivot),
            "[0, NaN]",
        ),
        (
            |s| s.cam.angular_acceleration_deg_s2 = Some(f64::NAN),
            Field::Cam(CamField::AngularAcceleration),
            "NaN",
        ),
        (
            |s| s.cam.profile.radius = Some(0.0),
            Field::Profile(ProfileField::Radius),
            "0",
        ),
        (
            |s| s.cam.profile.kind = "blob".into(),
            Field::Profile(ProfileField::Kind),
            "\"blob\"",
        ),
        (
            |s| s.cam.profile.points = Some(vec![[0.0, 0.0]]),
            Field::Profile(ProfileField::Points),
            "points",
        ),
        (
            |s| s.cam.profile.radius = None,
            Field::Profile(ProfileField::Kind),
            "needs `radius`",
        ),
        (
            |s| s.follower.kind = "rocker".into(),
            Field::Follower(FollowerField::Kind),
            "\"rocker\"",
        ),
        (
            |s| s.follower.direction = Some([0.0, 0.0]),
            Field::Follower(FollowerField::Direction),
            "[0, 0]",
        ),
        (
            |s| s.follower.roller_radius = Some(1.0),
            Field::Follower(FollowerField::RollerRadius),
            "takes no `roller_radius`",
        ),
        (
            |s| s.length_unit = Some("furlong".into()),
            Field::LengthUnit,
            "\"furlong\"",
        ),
        (
            |s| s.length_unit = None,
            Field::LengthUnit,
            "length_unit: missing",
        ),
        (
            |s| {
                s.dynamics = Some(DynamicsSpec {
                    mass: Some(1.0),
                    spring_stiffness: 1.0,
                    spring_preload: 1.0,
                    restitution: Some(1.5),
                    ..Default::default()
                })
            },
            Field::Dynamics(DynamicsField::Restitution),
            "1.5",
        ),
        (
            |s| {
                s.dynamics = Some(DynamicsSpec {
                    inertia: Some(1.0),
                    spring_stiffness: 1.0,
                    spring_preload: 1.0,
                    ..Default::default()
                })
            },
            Field::Dynamics(DynamicsField::Inertia),
            "takes `mass`",
        ),
    ];
    for (edit, field, value) in cases {
        let mut s = circle_spec(flat());
        edit(&mut s);
        let e = Mechanism::try_from(s).unwrap_err();
        assert_eq!(e.field(), field, "{e}");
        assert!(e.to_string().contains(value), "{e} lacks {value:?}");
        assert!(
            e.to_string().starts_with(&field.to_string()) || e.to_string().starts_with('['),
            "{e}"
        );
    }
}

#[test]
fn motion_spec_errors_name_the_segment() {
    let mut s = circle_spec(FollowerSpec {
        kind: "translating-roller".into(),
        roller_radius: Some(1.0),
        ..Default::default()
    });
    s.cam.profile = ProfileSpec {
        kind: "motion".into(),
        base_radius: Some(4.0),
        segments: Some(vec![
            SegmentSpec {
                law: "cycloidal".into(),
                rise: Some(1.0),
                degrees: Some(180.0),
                ..Default::default()
            },
            SegmentSpec {
                law: "parabolic".into(),
                rise: Some(-1.0),
                degrees: Some(180.0),
                ..Default::default()
            },
        ]),
        ..Default::default()
    };
    let e = Mechanism::try_from(s.clone()).unwrap_err();
    assert_eq!(
        e.field(),
        Field::Profile(ProfileField::Segment(1, SegmentField::Law))
    );
    assert_eq!(e.field().to_string(), "cam.profile.segments[1].law");
    s.cam.profile.segments.as_mut().unwrap()[1].law = "3-4-5".into();
    let m = Mechanism::try_from(s).unwrap();
    assert!(
        m.cam().synthesis().is_some(),
        "a motion profile keeps its synthesis"
    );
}

#[test]
fn specs_round_trip_through_json() {
    let s = circle_spec(FollowerSpec {
        kind: "oscillating-roller".into(),
        pivot: Some([-3.0, 7.0]),
        arm_length: Some(9.0),
        roller_radius: Some(1.0),
        ..Default::default()
    });
    let json = serde_json::to_string(&s).unwrap();
    let back: MechanismSpec = serde_json::from_str(&json).unwrap();
    assert_eq!(back, s);
    assert!(!json.contains("null"), "absent fields are left out: {json}");
    let bad = json.replace("\"arm_length\"", "\"arm_lenght\"");
    let err = serde_json::from_str::<MechanismSpec>(&bad)
        .unwrap_err()
        .to_string();
    assert!(err.contains("arm_lenght"), "{err}");
}

/// The keys of the schema are named once (`camkin::field`): serde's names for the profile and
/// follower tables are the field enums' names, no more and no fewer (read from serde's own
/// "expected one of" list for an unknown key), and a key present for a kind that does not take it
/// is refused naming it.
#[test]
fn the_schemas_keys_are_the_field_enums_names() {
    fn serde_names<T: serde::de::DeserializeOwned + std::fmt::Debug>() -> Vec<String> {
        let err = serde_json::from_str::<T>("{\"zz_not_a_key\": 1}")
            .unwrap_err()
            .to_string();
        let list = err
            .split("expected one of")
            .nth(1)
            .unwrap_or_else(|| panic!("{err}"));
        let mut v: Vec<String> = list
            .split('`')
            .skip(1)
            .step_by(2)
            .map(str::to_string)
            .collect();
        v.sort();
        v
    }
    let mut profile: Vec<String> = ProfileField::KEYED
        .iter()
        .map(|f| f.name().unwrap().to_string())
        .collect();
    profile.sort();
    assert_eq!(serde_names::<ProfileSpec>(), profile);
    let mut follower: Vec<String> = FollowerField::KEYED
        .iter()
        .map(|f| f.name().unwrap().to_string())
        .collect();
    // `[follower.conjugate]` is a table of its own, named by `Field::FollowerConjugate`
    follower.push(
        Field::FollowerConjugate(ProfileField::Table)
            .to_string()
            .trim_start_matches("follower.")
            .to_string(),
    );
    follower.sort();
    assert_eq!(serde_names::<FollowerSpec>(), follower);
    // every profile key but a circle's is foreign to a circle, and named so
    for f in ProfileField::KEYED {
        let name = f.name().unwrap();
        if ["kind", "center", "radius"].contains(&name) {
            continue;
        }
        let mut text = format!(
            "{{\"kind\": \"circle\", \"center\": [0.0, 0.0], \"radius\": 1.0, \"{name}\": "
        );
        text += match name {
            "points" => "[[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]]}",
            "parameterization" => "\"uniform\"}",
            "semi_axes" | "anchor" | "direction" | "at" | "start" => "[1.0, 0.5]}",
            "pieces" => "[]}",
            "path" => "\"x.csv\"}",
            "segments" => "[]}",
            "teeth" => "20}",
            "tip_relief_shape" => "\"linear\"}",
            _ => "1.0}",
        };
        let p: ProfileSpec = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
        let mut spec = circle_spec(FollowerSpec {
            kind: "translating-flat".into(),
            ..Default::default()
        });
        spec.cam.profile = p;
        let e = Mechanism::try_from(spec).unwrap_err();
        assert!(
            matches!(&e, SpecError::Foreign { name: n, .. } if *n == name),
            "{name}: {e}"
        );
    }
}

#[test]
fn spec_errors_are_not_panics_for_any_kind_without_its_fields() {
    for kind in camkin::spec::FollowerKind::ALL {
        let e = Mechanism::try_from(circle_spec(FollowerSpec {
            kind: kind.name().into(),
            ..Default::default()
        }));
        if let Err(e) = e {
            assert!(matches!(e, SpecError::Missing { .. }), "{kind}: {e}");
        }
    }
}

/// Issue 44: each length unit's size, not only its name. One cam and follower written in metres,
/// millimetres, centimetres and inches (the lengths divided by the unit's size, written here:
/// 1e-3, 1e-2, 0.0254 m), built in SI as a simulation builds it: the same positions, velocities
/// and accelerations in metres, to rounding.
#[test]
fn every_length_units_size_is_its_own() {
    use camkin::spec::BuildOptions;
    let spec_in = |unit: &str, size: f64| MechanismSpec {
        length_unit: Some(unit.into()),
        cam: CamSpec {
            speed_rpm: 600.0,
            profile: ProfileSpec {
                kind: "circle".into(),
                center: Some([0.007 / size, 0.003 / size]),
                radius: Some(0.02 / size),
                ..Default::default()
            },
            ..Default::default()
        },
        follower: FollowerSpec {
            kind: "translating-roller".into(),
            offset: Some(0.004 / size),
            roller_radius: Some(0.005 / size),
            ..Default::default()
        },
        ..Default::default()
    };
    let si = BuildOptions {
        si: true,
        ..Default::default()
    };
    let metres = spec_in("m", 1.0).build(&si).unwrap().mechanism;
    for (unit, size) in [("mm", 1e-3), ("cm", 1e-2), ("in", 0.0254)] {
        let m = spec_in(unit, size).build(&si).unwrap().mechanism;
        for k in 0..12 {
            let t = k as f64 * 0.5;
            let (a, b) = (metres.analyze(t).unwrap(), m.analyze(t).unwrap());
            for (x, y) in [
                (a.position, b.position),
                (a.velocity, b.velocity),
                (a.acceleration, b.acceleration),
            ] {
                assert!(
                    (x - y).abs() <= 1e-12 * x.abs().max(1e-3),
                    "{unit} at {t}: {x} against {y}"
                );
            }
        }
    }
}

/// Issue 44: a profile whose search index would hold more memory than the limits is refused
/// before it is built, naming the curve that costs most (the cam's, or the follower's when it
/// carries the larger), with the estimate; the same spec builds with no limit. The estimate
/// counts the samples from the nodes (16 a piece for the cam, 48 for a carried curve).
#[test]
fn a_profile_over_the_memory_limit_is_refused_before_it_is_built() {
    use camkin::work::Limits;
    let ring = |n: usize, r: f64, x: f64| -> Vec<[f64; 2]> {
        (0..n)
            .map(|k| {
                let t = k as f64 * std::f64::consts::TAU / n as f64;
                [x + r * t.cos(), 0.8 * r * t.sin()]
            })
            .collect()
    };
    let spline = |points| ProfileSpec {
        kind: "spline".into(),
        points: Some(points),
        ..Default::default()
    };
    let spec = |cam_nodes: usize, carried_nodes: usize| {
        let mut s = circle_spec(FollowerSpec {
            kind: "translating".into(),
            direction: Some([1.0, 0.0]),
            offset: Some(0.0),
            profile: Some(Box::new(spline(ring(carried_nodes, 2.0, 3.0)))),
            ..Default::default()
        });
        s.cam.profile = spline(ring(cam_nodes, 40.0, 0.0));
        s
    };
    let tight = BuildOptions {
        limits: Limits {
            seconds: 30.0,
            bytes: 5e6,
        },
        ..Default::default()
    };
    // 2 000 cam nodes: 40 000 samples, about 10 MB; a 100-node carried curve, about 0.8 MB
    for (cam_nodes, carried_nodes, field) in [
        (2_000, 100, Field::Profile(ProfileField::Table)),
        (100, 2_000, Field::Follower(FollowerField::Profile)),
    ] {
        let s = spec(cam_nodes, carried_nodes);
        match s.build(&tight) {
            Err(SpecError::TooMuch { field: f, refusal }) => {
                assert_eq!(f, field);
                let words = refusal.to_string();
                assert!(words.contains("MB"), "{words}");
                assert!(refusal.0.bytes > 5e6 && refusal.0.bytes < 1e8, "{words}");
            }
            other => panic!("{cam_nodes}/{carried_nodes}: {:?}", other.map(|_| ())),
        }
        let free = BuildOptions {
            limits: Limits::NONE,
            ..Default::default()
        };
        assert!(s.build(&free).is_ok());
        // the library's own limits (1 GB) take it too
        assert!(s.build(&BuildOptions::default()).is_ok());
    }
}
