//! Validation of a [`MechanismSpec`] and the mechanism it describes.

use super::{DynamicsSpec, FollowerKind, FollowerSpec, MechanismSpec, SpecWarning};
use crate::cam::{Cam, CamError, Follower, Mechanism, Sense};
use crate::dynamics::FollowerDynamics;
use crate::field::{CamField, DynamicsField, Field, FollowerField, Key, ProfileField};
use crate::gears::{GearError, GearPair};
use crate::valid::Rule;
use crate::{Point2, Vec2};
use std::path::PathBuf;

/// The unit of a mechanism's lengths.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum LengthUnit {
    /// metres
    #[default]
    M,
    /// centimetres
    Cm,
    /// millimetres
    Mm,
    /// inches
    In,
}

impl LengthUnit {
    /// All units with their names.
    pub const ALL: [(LengthUnit, &'static str); 4] = [
        (LengthUnit::Mm, "mm"),
        (LengthUnit::Cm, "cm"),
        (LengthUnit::M, "m"),
        (LengthUnit::In, "in"),
    ];
    /// Metres per unit.
    pub fn metres(self) -> f64 {
        match self {
            LengthUnit::M => 1.0,
            LengthUnit::Cm => 0.01,
            LengthUnit::Mm => 0.001,
            LengthUnit::In => 0.0254,
        }
    }
    /// The unit's symbol.
    pub fn name(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(u, _)| *u == self)
            .map_or("m", |(_, n)| n)
    }
}

/// How a spec is built.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BuildOptions {
    /// the folder a relative points-file path is read from (default: the current folder)
    pub base_dir: PathBuf,
    /// convert lengths to metres with `length_unit` (for a dynamic simulation); otherwise the
    /// mechanism is built in the file's units
    pub si: bool,
    /// read points files only from inside `base_dir` (a server that opened one mechanism's
    /// folder): an absolute path, a `..` component, or a path that resolves (through symbolic
    /// links) outside the folder is refused
    pub confine: bool,
    /// the most work building may take (the library's limits by default): a profile whose
    /// search index would take more memory or time is refused before it is built
    /// ([`crate::cam::build_work`])
    pub limits: crate::work::Limits,
}

/// A built mechanism with what else its spec said.
#[derive(Debug, Clone)]
pub struct Built {
    /// the mechanism
    pub mechanism: Mechanism,
    /// the follower's dynamics, when the spec has them (SI units)
    pub dynamics: Option<FollowerDynamics>,
    /// `[lubrication]`, when the spec has it
    pub lubrication: Option<super::BuiltLubrication>,
    /// `[gear_loads]`, when the spec has it (a gear pair's)
    pub gear_loads: Option<super::BuiltGearLoads>,
    /// the unit of the spec's lengths
    pub length_unit: LengthUnit,
    /// built in metres ([`BuildOptions::si`]), not in `length_unit`
    pub si: bool,
    /// what is valid but probably not meant (a front end shows them)
    pub warnings: Vec<SpecWarning>,
}

/// What is wrong with a spec. Every variant names the field ([`SpecError::field`]).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SpecError {
    /// A value is out of range.
    #[error("{field} = {value}: {reason}")]
    Invalid {
        /// the field
        field: Field,
        /// the value, as written in a file
        value: String,
        /// what it must be
        reason: String,
    },
    /// A name (a kind, a law, a unit) is not one of those known.
    #[error("{field} = {value:?} is not {what} ({known})")]
    Unknown {
        /// the field
        field: Field,
        /// the name given
        value: String,
        /// what it should name
        what: &'static str,
        /// the names known
        known: String,
    },
    /// A kind needs a field that is missing (the error is placed at the kind).
    #[error("[{}] kind = {kind:?} needs `{missing}`", field.table())]
    Missing {
        /// the kind's field
        field: Field,
        /// the kind
        kind: String,
        /// the missing field's name
        missing: &'static str,
    },
    /// A field that the kind does not take.
    #[error("[{}] kind = {kind:?} takes no `{name}` (its fields: {allowed})", field.table())]
    Foreign {
        /// the field present
        field: Field,
        /// its name
        name: &'static str,
        /// the kind
        kind: String,
        /// the fields the kind takes
        allowed: String,
    },
    /// A rule about a field or a table as a whole is broken.
    #[error("{field}: {reason}")]
    Rule {
        /// the field or the table
        field: Field,
        /// what is wrong
        reason: String,
    },
    /// Building the mechanism would take more memory or time than allowed
    /// ([`BuildOptions::limits`]); the field is the curve that costs most.
    #[error("{field}: {refusal}")]
    TooMuch {
        /// the cam's profile or the follower's curve
        field: Field,
        /// the estimate refused
        refusal: crate::work::Refusal,
    },
    /// A points file is malformed or its points do not make a profile.
    #[error("{path}{}: {message}", line.map(|l| format!(":{l}")).unwrap_or_default())]
    PointsFile {
        /// the file
        path: String,
        /// the 1-based line, where known
        line: Option<usize>,
        /// what is wrong
        message: String,
    },
}

impl SpecError {
    /// The same error about the field `f` maps its field to (a gear pair's mechanism named by
    /// the `gear_pair` keys, a contact's curve by its element).
    pub fn map_field(self, f: impl Fn(Field) -> Field) -> Self {
        match self {
            SpecError::Invalid {
                field,
                value,
                reason,
            } => SpecError::Invalid {
                field: f(field),
                value,
                reason,
            },
            SpecError::Unknown {
                field,
                value,
                what,
                known,
            } => SpecError::Unknown {
                field: f(field),
                value,
                what,
                known,
            },
            SpecError::Missing {
                field,
                kind,
                missing,
            } => SpecError::Missing {
                field: f(field),
                kind,
                missing,
            },
            SpecError::Foreign {
                field,
                name,
                kind,
                allowed,
            } => SpecError::Foreign {
                field: f(field),
                name,
                kind,
                allowed,
            },
            SpecError::Rule { field, reason } => SpecError::Rule {
                field: f(field),
                reason,
            },
            SpecError::TooMuch { field, refusal } => SpecError::TooMuch {
                field: f(field),
                refusal,
            },
            other => other,
        }
    }

    /// The field the error is about (for a points file: `cam.profile.path`).
    pub fn field(&self) -> Field {
        match self {
            SpecError::Invalid { field, .. }
            | SpecError::Unknown { field, .. }
            | SpecError::Missing { field, .. }
            | SpecError::Foreign { field, .. }
            | SpecError::Rule { field, .. }
            | SpecError::TooMuch { field, .. } => *field,
            SpecError::PointsFile { .. } => Field::Profile(ProfileField::Path),
        }
    }
}

pub(super) fn vector(v: [f64; 2]) -> String {
    format!(
        "[{}, {}]",
        crate::human::human(v[0]),
        crate::human::human(v[1])
    )
}

impl From<CamError> for SpecError {
    fn from(e: CamError) -> Self {
        match e {
            CamError::Invalid {
                field,
                value,
                reason,
            } => SpecError::Invalid {
                field,
                value: crate::human::human(value),
                reason: reason.to_string(),
            },
            CamError::InvalidVector {
                field,
                x,
                y,
                reason,
            } => SpecError::Invalid {
                field,
                value: vector([x, y]),
                reason: reason.to_string(),
            },
            CamError::Unreachable {
                field,
                value,
                reason,
            } => SpecError::Invalid {
                field,
                value: crate::human::human(value),
                reason,
            },
            CamError::Conjugate { field, reason } => SpecError::Rule { field, reason },
            CamError::Cusp { .. } | CamError::NoArea { .. } => SpecError::Rule {
                field: Field::Profile(ProfileField::Table),
                reason: e.to_string(),
            },
            other => SpecError::Rule {
                field: Field::Cam(CamField::Table),
                reason: other.to_string(),
            },
        }
    }
}

impl TryFrom<MechanismSpec> for Mechanism {
    type Error = SpecError;
    /// Builds in the spec's units, reading points files relative to the current folder.
    fn try_from(spec: MechanismSpec) -> Result<Self, SpecError> {
        spec.build(&BuildOptions::default()).map(|b| b.mechanism)
    }
}

/// The keyed fields of a table and whether the spec gives each, for the foreign-field check.
/// Fields are named by their enum; the key's name is written once, in `crate::field`.
pub(super) type Present = [(Field, bool)];

/// The key's name of a field (`radius` of `cam.profile.radius`).
pub(super) fn key(field: Field) -> &'static str {
    match field.path().last() {
        Some(Key::Name(n)) => n,
        _ => "",
    }
}

/// Refuses a field present in the spec that the `kind` does not take.
pub(super) fn check_kind(
    kind: &str,
    present: &Present,
    allowed: &[Field],
) -> Result<(), SpecError> {
    for &(field, here) in present {
        if here && !allowed.contains(&field) {
            return Err(SpecError::Foreign {
                field,
                name: key(field),
                kind: kind.to_string(),
                allowed: allowed
                    .iter()
                    .map(|&f| key(f))
                    .collect::<Vec<_>>()
                    .join(", "),
            });
        }
    }
    Ok(())
}

/// The value of `field`, which the `kind` needs.
pub(super) fn need<T: Copy>(
    kind_field: Field,
    kind: &str,
    field: Field,
    v: Option<T>,
) -> Result<T, SpecError> {
    v.ok_or_else(|| SpecError::Missing {
        field: kind_field,
        kind: kind.to_string(),
        missing: key(field),
    })
}

/// `x` when it keeps `rule`, else the refusal naming `field` and `x`.
fn rule(rule: Rule, field: Field, x: f64) -> Result<f64, SpecError> {
    rule.check(x).map_err(|reason| SpecError::Invalid {
        field,
        value: crate::human::human(x),
        reason: reason.into(),
    })
}

pub(super) fn finite(field: Field, x: f64) -> Result<f64, SpecError> {
    rule(Rule::Finite, field, x)
}

pub(super) fn positive(field: Field, x: f64) -> Result<f64, SpecError> {
    rule(Rule::Positive, field, x)
}

/// A length or a speed the computation takes: from 1e-100 to 1e100 (its squares stay in `f64`).
pub(super) fn length(field: Field, x: f64) -> Result<f64, SpecError> {
    rule(Rule::Size, field, x)
}

/// A coordinate or an offset: finite, at most 1e100 in magnitude.
pub(super) fn coordinate(field: Field, x: f64) -> Result<f64, SpecError> {
    rule(Rule::Bounded, field, x)
}

pub(super) fn non_negative(field: Field, x: f64) -> Result<f64, SpecError> {
    rule(Rule::NonNegative, field, x)
}

pub(super) fn point(field: Field, v: [f64; 2]) -> Result<Point2, SpecError> {
    Rule::Bounded
        .check_point(Point2::new(v[0], v[1]))
        .map_err(|reason| SpecError::Invalid {
            field,
            value: vector(v),
            reason: reason.into(),
        })
}

pub(super) fn direction(field: Field, v: [f64; 2]) -> Result<Vec2, SpecError> {
    let p = point(field, v)?;
    // by its largest component: [1e-300, 0] is the x axis (its norm's square underflows)
    if p.x.abs().max(p.y.abs()) > 0.0 {
        Ok(p.coords)
    } else {
        Err(SpecError::Invalid {
            field,
            value: vector(v),
            reason: "must be a non-zero direction".into(),
        })
    }
}

/// The file's `length_unit`, required.
pub(super) fn length_unit(u: Option<&str>) -> Result<LengthUnit, SpecError> {
    match u {
        None => Err(SpecError::Rule {
            field: Field::LengthUnit,
            reason: "missing: a mechanism says the unit of its lengths, e.g. length_unit = \"mm\" (mm, cm, m or in)".into(),
        }),
        Some(u) => LengthUnit::ALL
            .iter()
            .find(|(_, n)| *n == u)
            .map(|(x, _)| *x)
            .ok_or_else(|| SpecError::Unknown {
                field: Field::LengthUnit,
                value: u.to_string(),
                what: "a unit",
                known: "mm, cm, m, in".into(),
            }),
    }
}

impl MechanismSpec {
    /// Validates the spec and builds its mechanism (and dynamics). Every error names its field.
    pub fn build(&self, options: &BuildOptions) -> Result<Built, SpecError> {
        let built = self.build_mechanism(options);
        if self.from_gear_pair {
            // read from [gear_pair]: its errors name the keys that were written
            return built.map_err(|e| e.map_field(super::gear_pair::gear_field));
        }
        built
    }

    fn build_mechanism(&self, options: &BuildOptions) -> Result<Built, SpecError> {
        let unit = length_unit(self.length_unit.as_deref())?;
        let scale = if options.si { unit.metres() } else { 1.0 };
        let cam = &self.cam;
        let mut warnings = Vec::new();
        let follower =
            self.follower
                .build(scale, &options.base_dir, options.confine, &mut warnings)?;
        let sense = cam.direction.unwrap_or(Sense::Ccw);
        let pivot = match cam.pivot {
            Some(p) => {
                let p = point(Field::Cam(CamField::Pivot), p)?;
                Point2::new(scale * p.x, scale * p.y)
            }
            None => Point2::origin(),
        };
        // a synthesis places the follower relative to the cam's axis
        let relative = follower.relative_to(pivot);
        let (profile, synthesis) = cam.profile.build(
            scale,
            &options.base_dir,
            options.confine,
            super::profile::Place::Cam(&relative, sense),
            &mut warnings,
        )?;
        let speed = positive(Field::Cam(CamField::SpeedRpm), cam.speed_rpm)?;
        let alpha = match cam.angular_acceleration_deg_s2 {
            Some(a) => finite(Field::Cam(CamField::AngularAcceleration), a)?,
            None => 0.0,
        };
        let mut cam_obj = Cam::from_rpm(profile, pivot, sense, speed)?
            .with_angular_acceleration(alpha.to_radians())?;
        cam_obj.set_alpha_given(alpha, 1f64.to_radians());
        if let Some(s) = synthesis {
            cam_obj.set_synthesis(s);
        }
        let oscillating = follower.is_oscillating();
        let conjugate = match &self.follower.conjugate {
            Some(c) => Some(
                c.build(
                    scale,
                    &options.base_dir,
                    options.confine,
                    super::profile::Place::Conjugate,
                    &mut warnings,
                )?
                .0,
            ),
            None => None,
        };
        // the search indexes' memory and time, before they are built
        let work = crate::cam::build_work(&cam_obj, &follower, conjugate.as_deref());
        if let Some(refusal) = work.refusal_under(&options.limits) {
            let cam_pieces = cam_obj.profile().breakpoints().len();
            let carried_pieces = follower
                .carried_profile()
                .map_or(0, |c| c.breakpoints().len());
            let field = if carried_pieces > cam_pieces {
                Field::Follower(FollowerField::Profile)
            } else {
                Field::Profile(ProfileField::Table)
            };
            return Err(SpecError::TooMuch { field, refusal });
        }
        // the lengths an unreachable follower's reason gives are in the file's unit (or metres)
        let lengths = if options.si { "m" } else { unit.name() };
        let mut mechanism = Mechanism::new(cam_obj, follower).map_err(|e| match e {
            CamError::Unreachable {
                field,
                value,
                reason,
            } => CamError::Unreachable {
                field,
                value,
                reason: format!("{reason} (lengths in {lengths})"),
            },
            e => e,
        })?;
        // two involute gears of one base pitch: refused where their teeth overlap (closer than
        // the tight mesh, or their base circles), or never mesh on their involutes, naming the
        // distance that would
        if let Err(
            e @ (GearError::Interference { .. }
            | GearError::NoMesh { .. }
            | GearError::TooClose { .. }),
        ) = GearPair::new(&mechanism)
        {
            return Err(SpecError::Rule {
                field: Field::Follower(FollowerField::Pivot),
                reason: format!("{e} (lengths in {lengths})"),
            });
        }
        if let Some(curve) = conjugate {
            mechanism = mechanism.with_conjugate(curve)?;
        }
        let dynamics = self
            .dynamics
            .as_ref()
            .map(|d| d.build(oscillating))
            .transpose()?;
        let lubrication = self
            .lubrication
            .as_ref()
            .map(super::LubricationSpec::build)
            .transpose()?;
        let gear_loads = match &self.gear_loads {
            None => None,
            Some(g) => {
                if GearPair::new(&mechanism).is_err() {
                    return Err(SpecError::Rule {
                        field: Field::GearLoads(crate::field::GearLoadsField::Table),
                        reason: "a gear pair's loads: this mechanism is not a gear pair (a cam's forces come from [dynamics])".into(),
                    });
                }
                Some(g.build(mechanism.cam().speed(), lubrication.as_ref())?)
            }
        };
        Ok(Built {
            mechanism,
            dynamics,
            lubrication,
            gear_loads,
            si: options.si,
            length_unit: unit,
            warnings,
        })
    }
}

impl FollowerSpec {
    pub(super) fn build(
        &self,
        scale: f64,
        base: &std::path::Path,
        confine: bool,
        warnings: &mut Vec<SpecWarning>,
    ) -> Result<Follower, SpecError> {
        use FollowerField as F;
        let f = |x| Field::Follower(x);
        let kind_field = f(F::Kind);
        let k = FollowerKind::parse(&self.kind).ok_or_else(|| SpecError::Unknown {
            field: kind_field,
            value: self.kind.clone(),
            what: "a follower kind",
            known: FollowerKind::names(),
        })?;
        let kind = k.name();
        let allowed: Vec<Field> = k.fields().iter().map(|&x| f(x)).collect();
        let present: Vec<(Field, bool)> =
            self.present().into_iter().map(|(x, b)| (f(x), b)).collect();
        check_kind(kind, &present, &allowed)?;
        let mut carried = || -> Result<crate::cam::FollowerProfile, SpecError> {
            let p = self.profile.as_ref().ok_or_else(|| SpecError::Missing {
                field: kind_field,
                kind: kind.to_string(),
                missing: key(f(F::Profile)),
            })?;
            let (curve, _) = p.build(
                scale,
                base,
                confine,
                super::profile::Place::Follower,
                warnings,
            )?;
            Ok(crate::cam::FollowerProfile(curve))
        };
        let dir = || -> Result<Vec2, SpecError> {
            self.direction
                .map_or(Ok(Vec2::x()), |d| direction(f(F::Direction), d))
        };
        let offset = || -> Result<f64, SpecError> {
            self.offset
                .map_or(Ok(0.0), |o| coordinate(f(F::Offset), o).map(|v| scale * v))
        };
        let closing = self.closing.unwrap_or(Sense::Cw);
        let initial = || -> Result<f64, SpecError> {
            Ok(self
                .initial_angle_deg
                .map(|a| finite(f(F::InitialAngle), a))
                .transpose()?
                .unwrap_or(0.0)
                .to_radians())
        };
        let pivot = || -> Result<Point2, SpecError> {
            let p = point(
                f(F::Pivot),
                need(kind_field, kind, f(F::Pivot), self.pivot)?,
            )?;
            Ok(Point2::new(scale * p.x, scale * p.y))
        };
        let len = |field: F, v: Option<f64>| -> Result<f64, SpecError> {
            Ok(scale * length(f(field), need(kind_field, kind, f(field), v)?)?)
        };
        Ok(match k {
            FollowerKind::Translating => Follower::Translating {
                direction: dir()?,
                offset: offset()?,
                profile: carried()?,
            },
            FollowerKind::Rotating => Follower::Rotating {
                pivot: pivot()?,
                closing,
                initial_angle: initial()?,
                profile: carried()?,
            },
            FollowerKind::TranslatingFlat => Follower::TranslatingFlat { direction: dir()? },
            FollowerKind::TranslatingRoller => {
                let r = len(F::RollerRadius, self.roller_radius)?;
                Follower::TranslatingRoller {
                    direction: dir()?,
                    offset: offset()?,
                    roller_radius: r,
                }
            }
            FollowerKind::TranslatingKnife => Follower::TranslatingKnife {
                direction: dir()?,
                offset: offset()?,
            },
            FollowerKind::OscillatingFlat => Follower::OscillatingFlat {
                pivot: pivot()?,
                face_offset: offset()?,
                closing,
                initial_angle: initial()?,
            },
            FollowerKind::OscillatingRoller => {
                let pivot = pivot()?;
                let l = len(F::ArmLength, self.arm_length)?;
                let r = len(F::RollerRadius, self.roller_radius)?;
                Follower::OscillatingRoller {
                    pivot,
                    arm_length: l,
                    roller_radius: r,
                    closing,
                    initial_angle: initial()?,
                }
            }
        })
    }
}

impl DynamicsSpec {
    fn build(&self, oscillating: bool) -> Result<FollowerDynamics, SpecError> {
        use DynamicsField as D;
        let f = |x| Field::Dynamics(x);
        let needed = |field: D, v: Option<f64>| match v {
            Some(v) => positive(f(field), v),
            None => Err(SpecError::Rule {
                field: f(D::Table),
                reason: format!("needs `{}` for this follower", key(f(field))),
            }),
        };
        let (mass, inertia) = if oscillating {
            if self.mass.is_some() {
                return Err(SpecError::Rule {
                    field: f(D::Mass),
                    reason: "an oscillating follower takes `inertia`, not `mass`".into(),
                });
            }
            (1.0, needed(D::Inertia, self.inertia)?)
        } else {
            if self.inertia.is_some() {
                return Err(SpecError::Rule {
                    field: f(D::Inertia),
                    reason: "a translating follower takes `mass`, not `inertia`".into(),
                });
            }
            (needed(D::Mass, self.mass)?, 1.0)
        };
        let restitution = self
            .restitution
            .map(|r| non_negative(f(D::Restitution), r))
            .transpose()?
            .unwrap_or(0.0);
        if restitution > 1.0 {
            return Err(SpecError::Invalid {
                field: f(D::Restitution),
                value: crate::human::human(restitution),
                reason: "must be from 0 to 1".into(),
            });
        }
        let gravity = self
            .gravity
            .map(|g| point(f(D::Gravity), g))
            .transpose()?
            .map_or(Vec2::zeros(), |p| p.coords);
        // the range the dynamics is computed in (SI units): wide for any machine, narrow enough
        // that forces, energies and the penalty of the constraint solve stay far from overflow
        let within = |field: D, v: f64, lo: f64, hi: f64| {
            if v == 0.0 && lo == 0.0 || (lo..=hi).contains(&v) {
                Ok(v)
            } else {
                Err(SpecError::Invalid {
                    field: f(field),
                    value: crate::human::human(v),
                    reason: format!(
                        "is outside the range the dynamics is computed in ({} to {})",
                        crate::human::human(lo),
                        crate::human::human(hi)
                    ),
                })
            }
        };
        if !oscillating {
            within(D::Mass, mass, 1e-9, 1e9)?;
        } else {
            within(D::Inertia, inertia, 1e-12, 1e9)?;
        }
        let stiffness = within(
            D::SpringStiffness,
            non_negative(f(D::SpringStiffness), self.spring_stiffness)?,
            0.0,
            1e15,
        )?;
        let preload = within(
            D::SpringPreload,
            non_negative(f(D::SpringPreload), self.spring_preload)?,
            0.0,
            1e12,
        )?;
        let damping = within(
            D::Damping,
            self.damping
                .map(|c| non_negative(f(D::Damping), c))
                .transpose()?
                .unwrap_or(0.0),
            0.0,
            1e12,
        )?;
        if gravity.norm() > 1e6 {
            return Err(SpecError::Invalid {
                field: f(D::Gravity),
                value: vector([gravity.x, gravity.y]),
                reason: "is outside the range the dynamics is computed in (at most 1e6 m/s²)"
                    .into(),
            });
        }
        Ok(FollowerDynamics {
            mass,
            inertia,
            spring_stiffness: stiffness,
            spring_preload: preload,
            damping,
            restitution,
            gravity,
        })
    }
}
