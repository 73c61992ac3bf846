//! What a system file says for dynamics beyond its bodies' masses and its force elements:
//! `[dynamics]` (gravity, a default restitution) and each contact's restitution, face width and
//! materials (its Hertz pressure).

use super::build::{positive, SpecError};
use super::ContactSpec;
use crate::field::{Field, ProfileField, SystemField, SystemKey, SystemTable};

/// `[dynamics]` of a system file.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SystemDynamicsSpec {
    /// gravity in the world, m/s² (default none)
    #[serde(default, deserialize_with = "super::pair::option")]
    pub gravity: Option<[f64; 2]>,
    /// Newton's coefficient of restitution of every contact without its own, 0 to 1 (default 0)
    pub restitution: Option<f64>,
}

/// A restitution (or any ratio from 0 to 1) as written at `field`.
pub(super) fn unit_interval(field: Field, e: f64) -> Result<f64, SpecError> {
    if (0.0..=1.0).contains(&e) {
        Ok(e)
    } else {
        Err(SpecError::Invalid {
            field,
            value: crate::human::human(e),
            reason: "must be from 0 to 1".into(),
        })
    }
}

/// Contact `i`'s Hertz data: its face width (lengths times `scale`) and its materials' `E*`
/// (steel on steel unless it says), or none without a face width.
pub(super) fn contact_hertz(
    c: &ContactSpec,
    i: usize,
    scale: f64,
) -> Result<Option<crate::dynamics::ContactHertz>, SpecError> {
    let at = |key| {
        Field::System(SystemField {
            table: SystemTable::Contact,
            index: i,
            key,
        })
    };
    match c.face_width {
        Some(w) => {
            let width = scale * super::build::length(at(SystemKey::FaceWidth), w)?;
            let text = c.materials.as_deref().unwrap_or("steel,steel");
            let m: crate::report::Materials =
                text.parse()
                    .map_err(|e: crate::report::MaterialError| SpecError::Invalid {
                        field: at(SystemKey::Materials),
                        value: text.to_string(),
                        reason: e.to_string(),
                    })?;
            Ok(Some(crate::dynamics::ContactHertz {
                width,
                e_star: m.effective_modulus(),
            }))
        }
        None if c.materials.is_some() => Err(SpecError::Rule {
            field: at(SystemKey::Materials),
            reason: "materials need the contact's face_width (its Hertz pressure)".into(),
        }),
        None => Ok(None),
    }
}

/// `[[gas_force]]`: a force on a body from a table of the crank angle (a valve's gas force).
///
/// ```toml
/// [[gas_force]]
/// name = "cylinder pressure"
/// body = "valve"
/// at = [0, -60]                   # where, in the body's frame
/// direction = [0, -1]             # in the world: it pushes the valve open
/// table = [[0, 0], [360, 150], [380, 40], [540, 0]]   # [crank degrees, N]
/// crank_per_driver = 2            # crank degrees a degree of the first driver (default 2)
/// period_deg = 720                # the table's period in crank degrees (default 720)
/// ```
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GasForceSpec {
    /// its name
    pub name: String,
    /// the body it pushes
    pub body: String,
    /// where, in the body's frame (default its origin)
    #[serde(default, deserialize_with = "super::pair::option")]
    pub at: Option<[f64; 2]>,
    /// its direction in the world
    #[serde(deserialize_with = "super::pair::exact")]
    pub direction: [f64; 2],
    /// `[crank degrees, N]`, the angles increasing within one period
    #[serde(deserialize_with = "super::pair::list")]
    pub table: Vec<[f64; 2]>,
    /// crank degrees a degree of the first driver (default 2: a four-stroke's camshaft)
    pub crank_per_driver: Option<f64>,
    /// the table's period, crank degrees (default 720)
    pub period_deg: Option<f64>,
}

/// Gas force `i` of a file built, its body found by `body` (lengths times `scale`).
pub(super) fn gas_force(
    g: &GasForceSpec,
    i: usize,
    scale: f64,
    body: &dyn Fn(&str) -> Result<crate::system::BodyId, SpecError>,
) -> Result<crate::system::TableForce, SpecError> {
    use super::build::{direction, finite, point};
    let at = |key| {
        Field::System(SystemField {
            table: SystemTable::GasForce,
            index: i,
            key,
        })
    };
    let id = body(&g.body)?;
    if id.is_ground() {
        return Err(SpecError::Rule {
            field: at(SystemKey::Body),
            reason: "the ground does not move: a gas force pushes a body (a piston)".into(),
        });
    }
    let p = point(at(SystemKey::At), g.at.unwrap_or([0.0, 0.0]))?;
    let period = positive(at(SystemKey::PeriodDeg), g.period_deg.unwrap_or(720.0))?;
    let ratio = positive(
        at(SystemKey::CrankPerDriver),
        g.crank_per_driver.unwrap_or(2.0),
    )?;
    let mut table = Vec::with_capacity(g.table.len());
    for [angle, force] in &g.table {
        let (angle, force) = (
            finite(at(SystemKey::ForceTable), *angle)?,
            super::system_elements::within(
                at(SystemKey::ForceTable),
                finite(at(SystemKey::ForceTable), *force)?,
                0.0,
                1e12,
            )?,
        );
        if !(0.0..period).contains(&angle) || table.last().is_some_and(|&(a, _)| angle <= a) {
            return Err(SpecError::Rule {
                field: at(SystemKey::ForceTable),
                reason: format!(
                    "crank angle {}°: the table's angles must increase within one period, from 0 to below {}°",
                    crate::human::human(angle),
                    crate::human::human(period)
                ),
            });
        }
        table.push((angle, force));
    }
    if table.is_empty() {
        return Err(SpecError::Rule {
            field: at(SystemKey::ForceTable),
            reason: "needs at least one [crank degrees, N] point".into(),
        });
    }
    Ok(crate::system::TableForce {
        name: g.name.clone(),
        body: id,
        at: crate::Point2::new(scale * p.x, scale * p.y),
        direction: direction(at(SystemKey::Direction), g.direction)?,
        table,
        crank_per_driver: ratio,
        period_deg: period,
    })
}

/// A simulated system's cam program must move its follower with a continuous velocity: where
/// the velocity (or the position) jumps between two segments, the follower can only pass by an
/// impulse, and the synthesised curve breaks there (a roller's offset profile steps by the
/// roller's radius times the turn of the path: 0.06 mm for the valve train's former
/// constant-velocity ramps, where Newton could not follow the contact); the simulation would
/// follow a curve that is not the cam. (An acceleration jump is a force jump: allowed.)
pub(super) fn smooth_enough(
    program: &crate::cam::synthesis::SynthesizedProfile,
    field: impl Fn(ProfileField) -> Field,
) -> Result<(), SpecError> {
    if let Some(d) = program.discontinuities().into_iter().find(|d| d.order <= 1) {
        let what = if d.order == 0 { "position" } else { "velocity" };
        return Err(SpecError::Rule {
            field: field(ProfileField::Segment(
                d.segment,
                crate::field::SegmentField::Law,
            )),
            reason: format!(
                "the follower's {what} jumps where this segment starts (at {}°): the cam synthesised for it breaks there (a roller's profile steps by a part of a millimetre, a flat face's has a flat), and the follower passes it only by an impulse, so [dynamics] needs a program whose velocity is continuous — between a dwell and a lift, a ramp of a law that starts and ends at rest (cycloidal, 3-4-5, 4-5-6-7), not a constant-velocity ramp",
                crate::human::human(d.at.to_degrees()),
            ),
        });
    }
    Ok(())
}

/// A synthesised cam must not fold back on itself: where the follower's envelope turns back (a
/// flat face's radius of curvature `R + s + s''` negative, a roller's pitch curve sharper than
/// the roller) the profile has a cusp and a loop that no cam has and no follower can follow —
/// before this check a system ran into it as a contact search that "did not converge". The
/// profile's tangent is sampled every 0.125°; where two neighbours point apart it folds.
pub(super) fn unfolded(
    program: &crate::cam::synthesis::SynthesizedProfile,
    base_radius: f64,
    field: impl Fn(ProfileField) -> Field,
) -> Result<(), SpecError> {
    use crate::curve::Curve;
    let n = 2880;
    let tangent = |k: usize| program.eval(std::f64::consts::TAU * k as f64 / n as f64).d1;
    let mut last = tangent(0);
    for k in 1..=n {
        let t = tangent(k);
        if t.dot(&last) < 0.0 {
            let at = 360.0 * (k as f64 - 0.5) / n as f64;
            return Err(SpecError::Rule {
                field: field(ProfileField::BaseRadius),
                reason: format!(
                    "{}: the cam synthesised for its follower folds back on itself near {}° (under a flat face its radius of curvature R + s + s'' is negative there; a roller's path is sharper than the roller): no follower can follow it; a larger base radius, or a lift over more degrees",
                    crate::human::human(base_radius),
                    crate::human::human((at * 8.0).round() / 8.0),
                ),
            });
        }
        last = t;
    }
    Ok(())
}

/// `[simulation]` of a system file: a run in time.
///
/// ```toml
/// [simulation]
/// duration = 2.0      # s
/// interval = 0.001    # s between outputs (default a thousandth of the duration)
/// ```
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SimulationSpec {
    /// how long, s
    pub duration: f64,
    /// the output interval, s (default a thousandth of the duration)
    pub interval: Option<f64>,
}

/// The `[simulation]` table's run, its settings checked where they are written.
pub(super) fn timed_run(s: &SimulationSpec) -> Result<super::TimedRun, SpecError> {
    super::TimedRun::new(s.duration, s.interval).map_err(|e| match e {
        super::PlanError::OutOfRange {
            field,
            value,
            range,
        } => SpecError::Invalid {
            field: Field::System(SystemField {
                table: SystemTable::Simulation,
                index: 0,
                key: if field == super::PlanField::Interval {
                    SystemKey::Interval
                } else {
                    SystemKey::Duration
                },
            }),
            value,
            reason: format!("must be {range}"),
        },
        e => SpecError::Rule {
            field: Field::System(SystemField {
                table: SystemTable::Simulation,
                index: 0,
                key: SystemKey::Table,
            }),
            reason: e.to_string(),
        },
    })
}

/// Each body's starting frame rates `(v_x, v_y, ω)` where its `velocity` and
/// `angular_velocity` give them (lengths times `scale`).
pub(super) fn initial_rates(
    bodies: &[super::BodySpec],
    scale: f64,
) -> Result<Vec<[Option<f64>; 3]>, SpecError> {
    use super::system_elements::within;
    bodies
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let at = |key| {
                Field::System(SystemField {
                    table: SystemTable::Body,
                    index: i,
                    key,
                })
            };
            let v = b
                .velocity
                .map(|v| super::build::point(at(SystemKey::Velocity), v))
                .transpose()?;
            if let Some(v) = v {
                within(at(SystemKey::Velocity), v.x, 0.0, 1e12)?;
                within(at(SystemKey::Velocity), v.y, 0.0, 1e12)?;
            }
            let w = b
                .angular_velocity
                .map(|w| {
                    super::build::finite(at(SystemKey::AngularVelocity), w)
                        .and_then(|w| within(at(SystemKey::AngularVelocity), w, 0.0, 1e9))
                })
                .transpose()?;
            Ok([v.map(|v| scale * v.x), v.map(|v| scale * v.y), w])
        })
        .collect()
}

/// `[[load]]`: a force at a point of a body and a torque on it, constant or scaled by a table
/// of time ([`crate::system::AppliedLoad`]).
///
/// ```toml
/// [[load]]
/// name = "push"
/// body = "slider"
/// at = [0, 0]                     # where the force acts, in the body's frame (default its origin)
/// force = [0, -50]                # N (default none)
/// frame = "world"                 # or "body": the force turns with the body (default world)
/// torque = 2.0                    # N·length, counter-clockwise (default 0)
/// profile = [[0, 0], [0.1, 1]]    # [s, factor]: linear between, held at the ends (default 1)
/// ```
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadSpec {
    /// its name
    pub name: String,
    /// the body it acts on
    pub body: String,
    /// where the force acts, in the body's frame (default its origin)
    #[serde(default, deserialize_with = "super::pair::option")]
    pub at: Option<[f64; 2]>,
    /// the force, N, in `frame` (default none)
    #[serde(default, deserialize_with = "super::pair::option")]
    pub force: Option<[f64; 2]>,
    /// `"world"` (default) or `"body"`: the force turns with the body
    pub frame: Option<String>,
    /// the torque, N·length counter-clockwise (default 0)
    pub torque: Option<f64>,
    /// `[s, factor]`, increasing in time: the force and torque scaled, linear between points
    /// and held at the ends (default constant)
    #[serde(default, deserialize_with = "super::pair::list")]
    pub profile: Vec<[f64; 2]>,
}

/// Load `i` of a file built, its body found by `body` (lengths times `scale`).
pub(super) fn load(
    l: &LoadSpec,
    i: usize,
    scale: f64,
    body: &dyn Fn(&str) -> Result<crate::system::BodyId, SpecError>,
) -> Result<crate::system::AppliedLoad, SpecError> {
    use super::build::{finite, point};
    use super::system_elements::within;
    let at = |key| {
        Field::System(SystemField {
            table: SystemTable::Load,
            index: i,
            key,
        })
    };
    let id = body(&l.body)?;
    if id.is_ground() {
        return Err(SpecError::Rule {
            field: at(SystemKey::Body),
            reason: "the ground does not move: a load acts on a body".into(),
        });
    }
    let p = point(at(SystemKey::At), l.at.unwrap_or([0.0, 0.0]))?;
    let f = point(at(SystemKey::Force), l.force.unwrap_or([0.0, 0.0]))?;
    within(at(SystemKey::Force), f.x, 0.0, 1e12)?;
    within(at(SystemKey::Force), f.y, 0.0, 1e12)?;
    let torque = within(
        at(SystemKey::Torque),
        finite(at(SystemKey::Torque), l.torque.unwrap_or(0.0))?,
        0.0,
        1e12,
    )?;
    let frame = match l.frame.as_deref() {
        None | Some("world") => crate::system::LoadFrame::World,
        Some("body") => crate::system::LoadFrame::Body,
        Some(other) => {
            return Err(SpecError::Unknown {
                field: at(SystemKey::Frame),
                value: other.to_string(),
                what: "a load's frame",
                known: "world, body".into(),
            })
        }
    };
    let mut profile = Vec::with_capacity(l.profile.len());
    for [t, k] in &l.profile {
        let (t, k) = (
            finite(at(SystemKey::Profile), *t)?,
            within(
                at(SystemKey::Profile),
                finite(at(SystemKey::Profile), *k)?,
                0.0,
                1e6,
            )?,
        );
        if profile.last().is_some_and(|&(last, _)| t <= last) {
            return Err(SpecError::Rule {
                field: at(SystemKey::Profile),
                reason: format!(
                    "{} s: the profile's times must increase",
                    crate::human::human(t)
                ),
            });
        }
        profile.push((t, k));
    }
    Ok(crate::system::AppliedLoad {
        name: l.name.clone(),
        body: id,
        at: crate::Point2::new(scale * p.x, scale * p.y),
        force: crate::Vec2::new(f.x, f.y),
        torque: scale * torque,
        frame,
        profile,
    })
}
