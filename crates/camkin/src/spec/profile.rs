//! Validation of `[cam.profile]`: the profile kinds, inline and file points, motion programs.

use super::build::{
    check_kind, coordinate, finite, key, length, need, point, positive, vector, SpecError,
};
use super::SpecWarning;
use super::{ProfileKind, ProfileSpec};
use crate::cam::synthesis::synthesize;
use crate::cam::{Follower, Sense};
use crate::curve::{
    read_points_file, ArcsAndLines, Circle, ClosedSpline, Curve, CurveError, CurveField, Ellipse,
    InvoluteGear, InvoluteGearSpec, Line, Parameterization, PointCurve, TipRelief, MAX_POINTS,
};
use crate::field::{Field, ProfileField, SegmentField};
use crate::motion::{Law, Program, Segment};
use crate::valid::Rule;
use crate::Point2;
use std::path::Path;
use std::sync::Arc;

/// Where a spline's nodes came from, to place an error at a node.
enum Nodes<'a> {
    Inline(fn(ProfileField) -> Field),
    File { path: &'a str, lines: &'a [usize] },
}

impl Nodes<'_> {
    fn error(&self, node: usize, message: String) -> SpecError {
        match self {
            Nodes::Inline(place) => SpecError::Rule {
                field: place(ProfileField::Point(node)),
                reason: message,
            },
            Nodes::File { path, lines } => SpecError::PointsFile {
                path: path.to_string(),
                line: lines.get(node).copied(),
                message,
            },
        }
    }
    fn whole(&self, message: String) -> SpecError {
        match self {
            Nodes::Inline(place) => SpecError::Rule {
                field: place(ProfileField::Points),
                reason: message,
            },
            Nodes::File { path, .. } => SpecError::PointsFile {
                path: path.to_string(),
                line: None,
                message,
            },
        }
    }
}

/// A closed spline through `nodes`, refusing repeated points and a self-intersecting curve.
fn spline(
    nodes: &[Point2],
    param: Parameterization,
    from: &Nodes<'_>,
    warnings: &mut Vec<SpecWarning>,
) -> Result<Arc<dyn Curve>, SpecError> {
    let s = ClosedSpline::with_parameterization(nodes, param).map_err(|e| match e {
        CurveError::TooFewPoints { count } => from.whole(format!(
            "a closed spline needs at least 3 points, got {count}"
        )),
        CurveError::RepeatedPoint { index, next, x, y } => from.error(
            next,
            format!(
                "points {index} and {next} coincide at ({x}, {y}); consecutive points must differ"
            ),
        ),
        CurveError::NonFinitePoint { index, x, y } => {
            from.error(index, format!("point {index} = ({x}, {y}) is not finite"))
        }
        e @ (CurveError::FarPoint { index, .. } | CurveError::ChordLength { index, .. }) => {
            from.error(index, e.to_string())
        }
        other => from.whole(other.to_string()),
    })?;
    if let Some((ua, ub, p)) = s.self_intersection() {
        let n = nodes.len();
        let node_of = |u: f64| match param {
            Parameterization::Uniform => (u.floor() as usize).min(n - 1),
            _ => (0..s.segments())
                .rev()
                .find(|&i| s.node_param(i) <= u)
                .unwrap_or(0),
        };
        let (i, j) = (node_of(ua), node_of(ub));
        return Err(from.error(
            i,
            format!(
                "the spline through the points crosses itself near ({:.6}, {:.6}), between points {i}–{} and {j}–{}",
                p.x,
                p.y,
                (i + 1) % n,
                (j + 1) % n
            ),
        ));
    }
    if param == Parameterization::Uniform {
        let n = nodes.len();
        let chords = (0..n).map(|i| (nodes[(i + 1) % n] - nodes[i]).norm());
        let (lo, hi) = chords.fold((f64::INFINITY, 0.0f64), |(lo, hi), c| {
            (lo.min(c), hi.max(c))
        });
        if hi > UNEVEN_RATIO * lo {
            warnings.push(SpecWarning::UnevenNodes {
                field: match from {
                    Nodes::Inline(place) => place(ProfileField::Points),
                    Nodes::File { .. } => Field::Profile(ProfileField::Path),
                },
                ratio: hi / lo,
            });
        }
    }
    Ok(Arc::new(s))
}

/// The most segments a motion program may have.
pub const MAX_SEGMENTS: usize = 1000;

/// Longest over shortest chord between neighbouring nodes above which the uniform
/// parameterisation draws a warning. Measured on a circle of 24 nodes at alternating angular
/// steps: at a ratio of 1.5 the uniform spline's accelerations under a flat face are off by 17
/// times their peak (chord-length: 0.07, the spline's own approximation of the circle), at 2 by
/// 270 times; the paper's own nodes have a ratio of 1.6.
pub const UNEVEN_RATIO: f64 = 2.0;

/// The profile and, for `kind = "motion"`, its synthesis.
type BuiltProfile = (
    Arc<dyn Curve>,
    Option<Arc<crate::cam::synthesis::SynthesizedProfile>>,
);

/// Where a profile is: the cam's (with the follower and sense a motion program is synthesised
/// for) or a general follower's.
pub(super) enum Place<'a> {
    Cam(&'a Follower, Sense),
    Follower,
    /// a form-closed follower's second curve
    Conjugate,
}

impl ProfileSpec {
    pub(super) fn build(
        &self,
        scale: f64,
        base: &Path,
        confine: bool,
        place: Place<'_>,
        warnings: &mut Vec<SpecWarning>,
    ) -> Result<BuiltProfile, SpecError> {
        use ProfileField as P;
        let f: fn(ProfileField) -> Field = match place {
            Place::Cam(..) => Field::Profile,
            Place::Follower => Field::FollowerProfile,
            Place::Conjugate => Field::FollowerConjugate,
        };
        let kind_field = f(P::Kind);
        let k = ProfileKind::parse(&self.kind).ok_or_else(|| SpecError::Unknown {
            field: kind_field,
            value: self.kind.clone(),
            what: "a profile kind",
            known: format!("{} (line and point: a follower's)", ProfileKind::names()),
        })?;
        let kind = k.name();
        let refuse = |reason: &str| {
            Err(SpecError::Rule {
                field: kind_field,
                reason: reason.into(),
            })
        };
        match (k, &place) {
            (ProfileKind::Line, Place::Cam(..)) => return refuse("a cam's profile is a closed curve: a line can only be carried by a follower"),
            (ProfileKind::Point, Place::Cam(..)) => return refuse("a cam's profile is a closed curve: a point can only be carried by a follower (a knife edge)"),
            (ProfileKind::Point, Place::Conjugate) => return refuse("a point (a knife edge) cannot be a follower's second curve: give a circle of small radius"),
            (ProfileKind::Motion, Place::Follower | Place::Conjugate) => return refuse("a motion program is synthesised into a cam's profile: a follower cannot carry one"),
            _ => {}
        }
        let allowed: Vec<Field> = k.fields().iter().map(|&x| f(x)).collect();
        let present: Vec<(Field, bool)> =
            self.present().into_iter().map(|(x, b)| (f(x), b)).collect();
        check_kind(kind, &present, &allowed)?;
        let param = self.parameterization.unwrap_or_default();
        let scaled = |p: Point2| Point2::new(scale * p.x, scale * p.y);
        let center = || -> Result<Point2, SpecError> {
            Ok(scaled(point(
                f(P::Center),
                need(kind_field, kind, f(P::Center), self.center)?,
            )?))
        };
        let curve: Arc<dyn Curve> = match k {
            ProfileKind::Spline => {
                let pts = self.points.as_ref().ok_or_else(|| SpecError::Missing {
                    field: kind_field,
                    kind: kind.to_string(),
                    missing: key(f(P::Points)),
                })?;
                if pts.len() > MAX_POINTS {
                    return Err(SpecError::Rule {
                        field: f(P::Points),
                        reason: format!(
                            "{} points is more than the {MAX_POINTS} allowed",
                            pts.len()
                        ),
                    });
                }
                let nodes = pts
                    .iter()
                    .enumerate()
                    .map(|(i, &q)| point(f(P::Point(i)), q).map(scaled))
                    .collect::<Result<Vec<_>, _>>()?;
                spline(&nodes, param, &Nodes::Inline(f), warnings)?
            }
            ProfileKind::Circle => {
                let c = center()?;
                let r = scale
                    * length(
                        f(P::Radius),
                        need(kind_field, kind, f(P::Radius), self.radius)?,
                    )?;
                Arc::new(Circle::new(c, r).map_err(|e| SpecError::Rule {
                    field: kind_field,
                    reason: e.to_string(),
                })?)
            }
            ProfileKind::Ellipse => {
                let c = center()?;
                let ax = need(kind_field, kind, f(P::SemiAxes), self.semi_axes)?;
                let [a, b] = ax;
                if let Err(why) = Rule::Size.check(a).and(Rule::Size.check(b)) {
                    return Err(SpecError::Invalid {
                        field: f(P::SemiAxes),
                        value: vector(ax),
                        reason: format!("both {why}"),
                    });
                }
                let rot = self
                    .rotation_deg
                    .map(|r| finite(f(P::RotationDeg), r))
                    .transpose()?
                    .unwrap_or(0.0);
                Arc::new(
                    Ellipse::new(c, scale * a, scale * b, rot.to_radians()).map_err(|e| {
                        SpecError::Rule {
                            field: kind_field,
                            reason: e.to_string(),
                        }
                    })?,
                )
            }
            ProfileKind::TangentCam | ProfileKind::CircularArcCam => {
                let get = |field: ProfileField, v: Option<f64>| -> Result<f64, SpecError> {
                    length(f(field), need(kind_field, kind, f(field), v)?)
                };
                let base = get(P::BaseRadius, self.base_radius)?;
                let nose = get(P::NoseRadius, self.nose_radius)?;
                let lift = get(P::Lift, self.lift)?;
                let flank = if k == ProfileKind::CircularArcCam {
                    Some(get(P::FlankRadius, self.flank_radius)?)
                } else {
                    None
                };
                // in the file's unit (its messages quote the file's numbers), then scaled
                let make = |x: f64| match flank {
                    None => ArcsAndLines::tangent_cam(x * base, x * nose, x * lift),
                    Some(r) => ArcsAndLines::circular_arc_cam(x * base, x * nose, x * lift, x * r),
                };
                if let Err(e) = make(1.0) {
                    let field = if nose >= base {
                        f(P::NoseRadius)
                    } else if flank.is_some() {
                        f(P::FlankRadius)
                    } else {
                        kind_field
                    };
                    return Err(SpecError::Rule {
                        field,
                        reason: e.to_string(),
                    });
                }
                Arc::new(make(scale).map_err(|e| SpecError::Rule {
                    field: kind_field,
                    reason: e.to_string(),
                })?)
            }
            ProfileKind::ArcsAndLines => Arc::new(self.arcs_and_lines(scale, f, kind_field)?),
            ProfileKind::InvoluteGear => Arc::new(self.gear(scale, f)?),
            ProfileKind::Line => {
                let a = point(f(P::Anchor), self.anchor.unwrap_or([0.0, 0.0]))?;
                let d = need(kind_field, kind, f(P::Direction), self.direction)?;
                let line = Line::new(
                    Point2::new(scale * a.x, scale * a.y),
                    crate::Vec2::new(d[0], d[1]),
                )
                .map_err(|e| SpecError::Invalid {
                    field: f(P::Direction),
                    value: vector(d),
                    reason: e.to_string(),
                })?;
                Arc::new(line)
            }
            ProfileKind::Point => {
                let a = point(f(P::At), self.at.unwrap_or([0.0, 0.0]))?;
                Arc::new(
                    PointCurve::new(Point2::new(scale * a.x, scale * a.y)).map_err(|e| {
                        SpecError::Invalid {
                            field: f(P::At),
                            value: vector(self.at.unwrap_or([0.0, 0.0])),
                            reason: e.to_string(),
                        }
                    })?,
                )
            }
            ProfileKind::Motion => {
                let Place::Cam(follower, sense) = place else {
                    unreachable!("refused above")
                };
                let rb = scale
                    * length(
                        f(P::BaseRadius),
                        need(kind_field, kind, f(P::BaseRadius), self.base_radius)?,
                    )?;
                let segs = self.segments.as_ref().ok_or_else(|| SpecError::Missing {
                    field: kind_field,
                    kind: kind.to_string(),
                    missing: key(f(P::Segments)),
                })?;
                // a program's work grows with its segments (each is checked and synthesised): a
                // cam has a handful; thousands are a mistake, refused before the work
                if segs.len() > MAX_SEGMENTS {
                    return Err(SpecError::Rule {
                        field: f(P::Segments),
                        reason: format!(
                            "{} segments is more than the {MAX_SEGMENTS} a motion program may have",
                            segs.len()
                        ),
                    });
                }
                // rises: lengths for translating followers, degrees of arm angle for oscillating
                let rise_scale = if follower.is_oscillating() {
                    1f64.to_radians()
                } else {
                    scale
                };
                let mut list = Vec::with_capacity(segs.len());
                for (i, sg) in segs.iter().enumerate() {
                    let seg = |x| f(P::Segment(i, x));
                    if sg.law == "table" {
                        list.push(super::lift_table::table_segment(
                            sg,
                            &seg,
                            segs.len() == 1,
                            rise_scale,
                            base,
                            confine,
                            warnings,
                        )?);
                        continue;
                    }
                    for (given, key) in [
                        (sg.file.is_some(), SegmentField::File),
                        (sg.step_deg.is_some(), SegmentField::StepDeg),
                        (sg.lift.is_some(), SegmentField::Lift),
                    ] {
                        if given {
                            return Err(SpecError::Rule {
                                field: seg(key),
                                reason: format!(
                                    "is a table's key, and this segment's law is {:?}",
                                    sg.law
                                ),
                            });
                        }
                    }
                    let law = Law::ALL
                        .iter()
                        .find(|l| l.name() == sg.law)
                        .cloned()
                        .ok_or_else(|| SpecError::Unknown {
                            field: seg(SegmentField::Law),
                            value: sg.law.clone(),
                            what: "a law",
                            known: Law::ALL.map(|l| l.name()).join(", ") + ", table",
                        })?;
                    // a law other than a dwell moves the follower: its rise is required and
                    // non-zero (a missing rise silently meaning a dwell is refused); a dwell has none
                    let rise = match (&law, sg.rise) {
                        (Law::Dwell, None) => 0.0,
                        (Law::Dwell, Some(0.0)) => 0.0,
                        (Law::Dwell, Some(r)) => {
                            return Err(SpecError::Invalid {
                                field: seg(SegmentField::Rise),
                                value: crate::human::human(r),
                                reason: "a dwell has no rise (leave it out, or choose a law that moves)".into(),
                            })
                        }
                        (_, None) => {
                            return Err(SpecError::Invalid {
                                field: seg(SegmentField::Rise),
                                value: "none".into(),
                                reason: format!(
                                    "the {} law needs a rise (negative for a return); a segment that does not move is law = \"dwell\"",
                                    law.name()
                                ),
                            })
                        }
                        (_, Some(r)) => {
                            let r = coordinate(seg(SegmentField::Rise), r)?;
                            if r == 0.0 {
                                return Err(SpecError::Invalid {
                                    field: seg(SegmentField::Rise),
                                    value: "0".into(),
                                    reason: format!(
                                        "the {} law with no rise is a dwell: write law = \"dwell\"",
                                        law.name()
                                    ),
                                });
                            }
                            r
                        }
                    };
                    let degrees = positive(
                        seg(SegmentField::Degrees),
                        sg.degrees.ok_or_else(|| SpecError::Rule {
                            field: seg(SegmentField::Degrees),
                            reason: format!("the {} law needs its extent, degrees = …", law.name()),
                        })?,
                    )?;
                    list.push(Segment {
                        law,
                        rise: rise * rise_scale,
                        extent: degrees.to_radians(),
                    });
                }
                let program = Program::new(0.0, list).map_err(|e| SpecError::Rule {
                    field: f(P::Segments),
                    reason: e.to_string(),
                })?;
                let prof = Arc::new(synthesize(program, rb, follower, sense)?);
                return Ok((prof.clone(), Some(prof)));
            }
            ProfileKind::PointsFile => {
                let path = self.path.as_ref().ok_or_else(|| SpecError::Missing {
                    field: kind_field,
                    kind: kind.to_string(),
                    missing: key(f(P::Path)),
                })?;
                let full = base.join(path);
                if confine {
                    confined(base, path).map_err(|reason| SpecError::Invalid {
                        field: f(P::Path),
                        value: format!("{path:?}"),
                        reason,
                    })?;
                }
                let file = full.display().to_string();
                let (nodes, lines) = read_points_file(&full).map_err(|e| match e {
                    CurveError::PointsFileIo { message, .. } => SpecError::Invalid {
                        field: f(P::Path),
                        value: format!("{path:?}"),
                        reason: format!("cannot read {file}: {message}"),
                    },
                    CurveError::PointsFileSyntax {
                        line,
                        message,
                        content,
                    } => SpecError::PointsFile {
                        path: file.clone(),
                        line: Some(line),
                        message: format!("{message}: {content:?}"),
                    },
                    other => SpecError::Invalid {
                        field: f(P::Path),
                        value: format!("{path:?}"),
                        reason: other.to_string(),
                    },
                })?;
                let nodes: Vec<Point2> = nodes.into_iter().map(scaled).collect();
                // measured or digitised points are rarely evenly spaced: chord-length unless
                // the file says otherwise
                spline(
                    &nodes,
                    self.parameterization
                        .unwrap_or(Parameterization::ChordLength),
                    &Nodes::File {
                        path: &file,
                        lines: &lines,
                    },
                    warnings,
                )?
            }
        };
        Ok((curve, None))
    }
}

impl ProfileSpec {
    /// `kind = "involute-gear"`: lengths scaled, errors placed at the field that caused them.
    fn gear(&self, scale: f64, f: fn(ProfileField) -> Field) -> Result<InvoluteGear, SpecError> {
        use ProfileField as P;
        let kind_field = f(P::Kind);
        let kind = "involute-gear";
        let module = scale
            * length(
                f(P::Module),
                need(kind_field, kind, f(P::Module), self.module)?,
            )?;
        let teeth = need(kind_field, kind, f(P::Teeth), self.teeth)?;
        let alpha = finite(
            f(P::PressureAngle),
            need(
                kind_field,
                kind,
                f(P::PressureAngle),
                self.pressure_angle_deg,
            )?,
        )?;
        let mut g = InvoluteGearSpec::new(module, teeth, alpha.to_radians());
        if let Some(v) = self.addendum {
            g.addendum = v;
        }
        if let Some(v) = self.dedendum {
            g.dedendum = v;
        }
        if let Some(v) = self.profile_shift {
            g.profile_shift = v;
        }
        if let Some(v) = self.backlash {
            g.backlash = scale * v;
        }
        g.fillet_radius = self.fillet_radius.map(|v| scale * v);
        match (self.tip_relief, self.tip_relief_length) {
            (Some(amount), Some(length)) => {
                g.tip_relief = Some(TipRelief {
                    amount: scale * amount,
                    length: scale * length,
                    shape: self.tip_relief_shape.unwrap_or(crate::curve::ReliefShape::Linear),
                });
            }
            (None, None) if self.tip_relief_shape.is_none() => {}
            _ => {
                return Err(SpecError::Rule {
                    field: f(if self.tip_relief.is_none() {
                        P::TipRelief
                    } else {
                        P::TipReliefLength
                    }),
                    reason: "tip relief needs both `tip_relief` (the amount at the tip) and `tip_relief_length` (along the line of action)".into(),
                })
            }
        }
        InvoluteGear::new(g).map_err(|e| match e.field() {
            Some((field, value)) => {
                let reason = match &e {
                    CurveError::Gear { reason, .. } => reason.clone(),
                    CurveError::NonPositive { .. } => "must be positive and finite".into(),
                    CurveError::NonFinite { .. } => "must be finite".into(),
                    other => other.to_string(),
                };
                let at = match field {
                    CurveField::Teeth => P::Teeth,
                    CurveField::PressureAngle => P::PressureAngle,
                    CurveField::Addendum => P::Addendum,
                    CurveField::Dedendum => P::Dedendum,
                    CurveField::ProfileShift => P::ProfileShift,
                    CurveField::Backlash => P::Backlash,
                    CurveField::FilletRadius => P::FilletRadius,
                    CurveField::TipReliefLength => P::TipReliefLength,
                    CurveField::TipReliefAmount => P::TipRelief,
                    CurveField::Module => P::Module,
                    _ => P::Kind,
                };
                SpecError::Invalid {
                    field: f(at),
                    value: crate::human::human(value),
                    reason,
                }
            }
            None => SpecError::Rule {
                field: kind_field,
                reason: e.to_string(),
            },
        })
    }
}

/// Checks that the points file `path` lies inside the folder `base` (see
/// [`super::BuildOptions::confine`]): why not, when it does not.
pub(super) fn confined(base: &Path, path: &str) -> Result<(), String> {
    use std::path::Component;
    let p = Path::new(path);
    if p.is_absolute() || p.has_root() {
        return Err(
            "an absolute path: only files in the mechanism's folder can be read here".into(),
        );
    }
    if p.components()
        .any(|c| !matches!(c, Component::Normal(_) | Component::CurDir))
    {
        return Err(
            "leaves the mechanism's folder (`..`): only files in it can be read here".into(),
        );
    }
    let folder = base
        .canonicalize()
        .map_err(|e| format!("the mechanism's folder cannot be read: {e}"))?;
    // a missing file is reported by the read that follows; a symbolic link out is refused here
    if let Ok(real) = base.join(p).canonicalize() {
        if !real.starts_with(&folder) {
            return Err(
                "a symbolic link out of the mechanism's folder: only files in it can be read here"
                    .into(),
            );
        }
    }
    Ok(())
}
