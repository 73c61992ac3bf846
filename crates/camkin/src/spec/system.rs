//! System files: bodies, joints, drivers and contacts as plain data (`[[body]]`, `[[joint]]`,
//! `[[driver]]`, `[[contact]]`), validated and built into a [`crate::system::System`]. Every
//! error names the element by its table, index and name, at its key ([`SystemField`]).
//!
//! ```toml
//! length_unit = "mm"
//!
//! [[body]]
//! name = "cam"                  # position = [x, y] and angle_deg: where it starts (a guess)
//!
//! [[joint]]
//! name = "camshaft"
//! kind = "revolute"             # revolute, prismatic (axis, angle_deg) or fixed (angle_deg)
//! bodies = ["ground", "cam"]
//! at = [[0, 0], [0, 0]]         # the joint's point in each body's frame
//!
//! [[driver]]
//! name = "drive"
//! body = "cam"
//! coordinate = "angle"          # angle (speed_rpm, start in degrees) or x, y (speed, start)
//! speed_rpm = 3000
//!
//! [[contact]]
//! name = "cam on roller"
//! bodies = ["cam", "finger"]
//! curve_a = { kind = "ellipse", center = [0, -4], semi_axes = [15, 20] }
//! curve_b = { kind = "circle", center = [35, 0], radius = 6 }
//! ```

use super::build::{direction, finite, length_unit, point, positive, BuildOptions, SpecError};
use super::kinds::JointKindName;
use super::profile::Place;
use super::system_elements::within;
use super::{BuiltSystem, SpecWarning, SweepAngle};
use super::{ContactSpec, ProfileSpec};
use super::{DamperSpec, SpringSpec, TorsionSpringSpec};
use crate::body::Pose;
use crate::field::{Field, FollowerField, ProfileField, SystemField, SystemKey, SystemTable};
use crate::geometry::Point2;
use crate::system::{
    Body, BodyId, Contact, Driver, ForceElement, ForceKind, Joint, JointKind, System,
};
use std::collections::HashMap;

/// A system file.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SystemSpec {
    /// the unit of every length: "mm", "cm", "m" or "in" (required)
    pub length_unit: Option<String>,
    /// `[[body]]`: the moving bodies (the ground is `"ground"`)
    #[serde(default)]
    pub body: Vec<BodySpec>,
    /// `[[joint]]`
    #[serde(default)]
    pub joint: Vec<JointSpec>,
    /// `[[driver]]`
    #[serde(default)]
    pub driver: Vec<DriverSpec>,
    /// `[[contact]]`
    #[serde(default)]
    pub contact: Vec<ContactSpec>,
    /// `[[spring]]`: linear springs between two points (for dynamics)
    #[serde(default)]
    pub spring: Vec<SpringSpec>,
    /// `[[damper]]`: linear dampers between two points (for dynamics)
    #[serde(default)]
    pub damper: Vec<DamperSpec>,
    /// `[[torsion_spring]]`: between two bodies' angles (for dynamics)
    #[serde(default)]
    pub torsion_spring: Vec<TorsionSpringSpec>,
    /// `[dynamics]`: what a simulation needs beyond the bodies' masses and the force elements;
    /// with it the system's degrees of freedom need not all be driven (forces move them)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dynamics: Option<super::SystemDynamicsSpec>,
    /// `[[coil_spring]]`: coil springs with mass, as chains of lumped masses (for dynamics)
    #[serde(default)]
    pub coil_spring: Vec<super::CoilSpringSpec>,
    /// `[[gas_force]]`: forces from tables of the crank angle (for dynamics)
    #[serde(default)]
    pub gas_force: Vec<super::GasForceSpec>,
    /// `[lubrication]`: the oil of every contact with a face width (for dynamics)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lubrication: Option<super::SystemLubricationSpec>,
    /// `[[load]]`: forces and torques applied to bodies, constant or by a table of time (for
    /// dynamics)
    #[serde(default)]
    pub load: Vec<super::LoadSpec>,
    /// `[[lash_adjuster]]`: hydraulic lash adjusters, their chambers' pressures simulated (for
    /// dynamics)
    #[serde(default)]
    pub lash_adjuster: Vec<super::LashAdjusterSpec>,
    /// `[simulation]`: a run in time, its duration and output interval (for dynamics; a system
    /// without an angle driver needs it, or the front end's duration)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub simulation: Option<super::SimulationSpec>,
}

/// `[[body]]`.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// its name (unique; not "ground")
    pub name: String,
    /// kg (default 1; for dynamics)
    pub mass: Option<f64>,
    /// kg·m² about its centre of mass (default 1; 0: a point mass; for dynamics)
    pub inertia: Option<f64>,
    /// its centre of mass in its frame, in the file's length unit (default its frame's origin;
    /// for dynamics)
    #[serde(default, deserialize_with = "super::pair::option")]
    pub centre_of_mass: Option<[f64; 2]>,
    /// where its frame's origin starts (a guess for the first instant; default the origin)
    #[serde(default, deserialize_with = "super::pair::option")]
    pub position: Option<[f64; 2]>,
    /// its frame's starting angle, degrees (default 0)
    pub angle_deg: Option<f64>,
    /// its frame origin's starting velocity `[v_x, v_y]`, length unit/s (for dynamics; default
    /// at rest, or what the drivers give it): made consistent with the joints, drivers and
    /// closed contacts at the start, and the change reported
    #[serde(default, deserialize_with = "super::pair::option")]
    pub velocity: Option<[f64; 2]>,
    /// its starting angular velocity, rad/s counter-clockwise (for dynamics; as `velocity`)
    pub angular_velocity: Option<f64>,
}

/// `[[joint]]`.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JointSpec {
    /// its name
    pub name: String,
    /// "revolute", "prismatic" or "fixed"
    pub kind: String,
    /// the two bodies (either may be "ground")
    #[serde(deserialize_with = "super::pair::names")]
    pub bodies: [String; 2],
    /// the joint's point in each body's frame (default the origins)
    #[serde(default, deserialize_with = "super::pair::option_points")]
    pub at: Option<[[f64; 2]; 2]>,
    /// prismatic: the guide's direction in the first body's frame
    #[serde(default, deserialize_with = "super::pair::option")]
    pub axis: Option<[f64; 2]>,
    /// prismatic and fixed: the second body's angle to the first, degrees (default 0)
    pub angle_deg: Option<f64>,
}

/// `[[driver]]`.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DriverSpec {
    /// its name
    pub name: String,
    /// the driven body
    pub body: String,
    /// "angle", "x" or "y"
    pub coordinate: String,
    /// angle: rpm (counter-clockwise positive)
    pub speed_rpm: Option<f64>,
    /// x or y: length/s
    pub speed: Option<f64>,
    /// the value at time 0: degrees for an angle, length for x or y (default 0)
    pub start: Option<f64>,
    /// a constant acceleration: deg/s² for an angle, length/s² for x or y (default 0)
    pub acceleration: Option<f64>,
}

/// The field `key` of element `index` of `table`.
fn at(table: SystemTable, index: usize, key: SystemKey) -> Field {
    Field::System(SystemField { table, index, key })
}

/// A spec error of a carried curve, moved from the follower's profile (where the curve builder
/// names it) to the contact's curve.
fn moved(e: SpecError, to: impl Fn(ProfileField) -> Field) -> SpecError {
    e.map_field(|f| match f {
        // a follower's curve, or a cam's (a motion program)
        Field::FollowerProfile(p) | Field::Profile(p) => to(p),
        other => other,
    })
}

impl SystemSpec {
    /// Validates the spec and builds its system (lengths in the file's unit, or metres with
    /// [`BuildOptions::si`]). Every error names the element and its key.
    pub fn build(&self, options: &BuildOptions) -> Result<BuiltSystem, SpecError> {
        use SystemKey as K;
        use SystemTable as T;
        let unit = length_unit(self.length_unit.as_deref())?;
        let scale = if options.si { unit.metres() } else { 1.0 };
        let metres_per_unit = if options.si { 1.0 } else { unit.metres() };
        let mut sys = System::new();
        let mut ids: HashMap<&str, BodyId> = HashMap::new();
        ids.insert("ground", BodyId::GROUND);
        let named = |t: T, i: usize, name: &str| -> Result<(), SpecError> {
            if name.trim().is_empty() {
                return Err(SpecError::Rule {
                    field: at(t, i, K::Name),
                    reason: format!("[[{}]] number {} needs a name", t.name(), i + 1),
                });
            }
            Ok(())
        };
        self.unique_names()?;
        for (i, b) in self.body.iter().enumerate() {
            named(T::Body, i, &b.name)?;
            if ids.contains_key(b.name.as_str()) {
                return Err(SpecError::Rule {
                    field: at(T::Body, i, K::Name),
                    reason: format!(
                        "{:?}: {}",
                        b.name,
                        if b.name == "ground" {
                            "the ground is there already: it needs no [[body]]"
                        } else {
                            "another body has this name"
                        }
                    ),
                });
            }
            let mass = positive(at(T::Body, i, K::Mass), b.mass.unwrap_or(1.0))?;
            // an inertia of 0 is a point mass
            let inertia = match b.inertia.unwrap_or(1.0) {
                0.0 => 0.0,
                x => within(
                    at(T::Body, i, K::Inertia),
                    positive(at(T::Body, i, K::Inertia), x)?,
                    1e-15,
                    1e9,
                )?,
            };
            within(at(T::Body, i, K::Mass), mass, 1e-9, 1e9)?;
            let p = point(
                at(T::Body, i, K::Position),
                b.position.unwrap_or([0.0, 0.0]),
            )?;
            let angle = finite(at(T::Body, i, K::AngleDeg), b.angle_deg.unwrap_or(0.0))?;
            let centre = point(
                at(T::Body, i, K::CentreOfMass),
                b.centre_of_mass.unwrap_or([0.0, 0.0]),
            )?;
            let id = sys.add_body(Body {
                name: b.name.clone(),
                mass,
                inertia,
                pose: Pose::new(Point2::new(scale * p.x, scale * p.y), angle.to_radians()),
                centre_of_mass: Point2::new(scale * centre.x, scale * centre.y),
            });
            ids.insert(b.name.as_str(), id);
        }
        let body = |t: T, i: usize, key: K, name: &str| -> Result<BodyId, SpecError> {
            ids.get(name).copied().ok_or_else(|| SpecError::Unknown {
                field: at(t, i, key),
                value: name.to_string(),
                what: "a body of this file",
                known: std::iter::once("ground")
                    .chain(self.body.iter().map(|b| b.name.as_str()))
                    .collect::<Vec<_>>()
                    .join(", "),
            })
        };
        let two = |t: T, i: usize, names: &[String; 2]| -> Result<[BodyId; 2], SpecError> {
            let (a, b) = (
                body(t, i, K::Bodies, &names[0])?,
                body(t, i, K::Bodies, &names[1])?,
            );
            if a == b {
                return Err(SpecError::Rule {
                    field: at(t, i, K::Bodies),
                    reason: format!(
                        "joins {:?} to itself: an element joins two bodies (one may be \"ground\")",
                        names[0]
                    ),
                });
            }
            Ok([a, b])
        };
        for (i, j) in self.joint.iter().enumerate() {
            named(T::Joint, i, &j.name)?;
            let [a, b] = two(T::Joint, i, &j.bodies)?;
            let pts = j.at.unwrap_or([[0.0, 0.0], [0.0, 0.0]]);
            let (pa, pb) = (
                point(at(T::Joint, i, K::At), pts[0])?,
                point(at(T::Joint, i, K::At), pts[1])?,
            );
            let (at_a, at_b) = (
                Point2::new(scale * pa.x, scale * pa.y),
                Point2::new(scale * pb.x, scale * pb.y),
            );
            let angle =
                finite(at(T::Joint, i, K::AngleDeg), j.angle_deg.unwrap_or(0.0))?.to_radians();
            let kind = JointKindName::parse(&j.kind).ok_or_else(|| SpecError::Unknown {
                field: at(T::Joint, i, K::Kind),
                value: j.kind.clone(),
                what: "a joint kind",
                known: JointKindName::names(),
            })?;
            for (key, present) in [
                (K::Axis, j.axis.is_some()),
                (K::AngleDeg, j.angle_deg.is_some()),
            ] {
                if present && !kind.fields().contains(&key) {
                    return Err(SpecError::Rule {
                        field: at(T::Joint, i, key),
                        reason: format!("a {kind} joint takes no {}", at(T::Joint, i, key)),
                    });
                }
            }
            let kind = match kind {
                JointKindName::Revolute => JointKind::Revolute { a, at_a, b, at_b },
                JointKindName::Prismatic => {
                    let axis = j.axis.ok_or_else(|| SpecError::Rule {
                        field: at(T::Joint, i, K::Kind),
                        reason: "a prismatic joint needs `axis`, the guide's direction in the first body's frame".into(),
                    })?;
                    JointKind::Prismatic {
                        a,
                        at_a,
                        // a unit vector: by its largest component first, so that
                        // [1e-300, 0] is the x axis (its norm's square underflows)
                        axis: {
                            let v = direction(at(T::Joint, i, K::Axis), axis)?;
                            (v / v.x.abs().max(v.y.abs())).normalize()
                        },
                        b,
                        at_b,
                        angle,
                    }
                }
                JointKindName::Fixed => JointKind::Fixed {
                    a,
                    at_a,
                    b,
                    at_b,
                    angle,
                },
            };
            sys.add_joint(Joint {
                name: j.name.clone(),
                kind,
            });
        }
        for (i, d) in self.driver.iter().enumerate() {
            named(T::Driver, i, &d.name)?;
            let id = body(T::Driver, i, K::Body, &d.body)?;
            if id.is_ground() {
                return Err(SpecError::Rule {
                    field: at(T::Driver, i, K::Body),
                    reason: "the ground does not move: drive a body".into(),
                });
            }
            let (coordinate, law) = super::system_driver::law(d, i, scale)?;
            if let Some((k, _)) = self.driver[..i]
                .iter()
                .enumerate()
                .find(|(_, e)| e.body == d.body && e.coordinate == d.coordinate)
            {
                return Err(SpecError::Rule {
                    field: at(T::Driver, i, K::Coordinate),
                    reason: format!(
                        "the {} of {:?} is driven already, by {:?}",
                        d.coordinate, d.body, self.driver[k].name
                    ),
                });
            }
            sys.add_driver(Driver {
                name: d.name.clone(),
                body: id,
                coordinate,
                law,
            });
        }
        let mut warnings = Vec::new();
        let unit_interval = super::system_dynamics::unit_interval;
        let (gravity, default_restitution) = match &self.dynamics {
            Some(d) => (
                d.gravity,
                match d.restitution {
                    Some(e) => unit_interval(at(T::Dynamics, 0, K::Restitution), e)?,
                    None => 0.0,
                },
            ),
            None => (None, 0.0),
        };
        let mut restitution = Vec::with_capacity(self.contact.len());
        // a lash starts apart ([`super::lash`])
        let start_touching = self
            .contact
            .iter()
            .map(|c| match c.lash {
                Some(l) if l > 0.0 => Some(false),
                _ => c.starts_closed,
            })
            .collect();
        let mut lash = Vec::new();
        let mut hertz = Vec::with_capacity(self.contact.len());
        let mut lubricated = Vec::with_capacity(self.contact.len());
        for (i, c) in self.contact.iter().enumerate() {
            named(T::Contact, i, &c.name)?;
            let [a, b] = two(T::Contact, i, &c.bodies)?;
            // a motion program is synthesised for the follower the contact names
            let motion = [&c.curve_a, &c.curve_b]
                .iter()
                .any(|p| p.kind == super::ProfileKind::Motion.name());
            let program_follower = match (&c.motion_follower, motion) {
                (Some(f), true) => Some(
                    f.build(scale, &options.base_dir, options.confine, &mut warnings)
                        .map_err(|e| {
                            e.map_field(|f| match f {
                                Field::Follower(k) => at(T::Contact, i, K::MotionFollower(k)),
                                Field::FollowerProfile(_) | Field::FollowerConjugate(_) => {
                                    at(T::Contact, i, K::MotionFollower(FollowerField::Table))
                                }
                                other => other,
                            })
                        })?,
                ),
                (None, true) => {
                    return Err(SpecError::Rule {
                        field: at(T::Contact, i, K::Table),
                        reason: "a kind = \"motion\" curve is a cam synthesised from its program for a follower: give the follower as motion_follower = { kind = ..., ... } (a mechanism file's [follower], in the cam body's frame, its origin the cam's axis)".into(),
                    })
                }
                (Some(_), false) => {
                    return Err(SpecError::Rule {
                        field: at(T::Contact, i, K::MotionFollower(FollowerField::Table)),
                        reason: "is for a kind = \"motion\" curve, and neither curve of this contact is one".into(),
                    })
                }
                (None, false) => None,
            };
            if c.motion_direction.is_some() && !motion {
                return Err(SpecError::Rule {
                    field: at(T::Contact, i, K::MotionDirection),
                    reason:
                        "is for a kind = \"motion\" curve, and neither curve of this contact is one"
                            .into(),
                });
            }
            let sense = c.motion_direction.unwrap_or(crate::cam::Sense::Ccw);
            let curve = |spec: &ProfileSpec,
                         to: fn(ProfileField) -> SystemKey,
                         warnings: &mut Vec<SpecWarning>| {
                let place = match &program_follower {
                    Some(f) if spec.kind == super::ProfileKind::Motion.name() => {
                        Place::Cam(f, sense)
                    }
                    _ => Place::Follower,
                };
                let (curve, synthesised) = spec
                    .build(scale, &options.base_dir, options.confine, place, warnings)
                    .map_err(|e| {
                        // a synthesis that the follower's geometry refuses names its key
                        moved(e, |p| at(T::Contact, i, to(p))).map_field(|f| match f {
                            Field::Follower(k) => at(T::Contact, i, K::MotionFollower(k)),
                            other => other,
                        })
                    })?;
                if let Some(program) = synthesised {
                    super::system_dynamics::unfolded(
                        &program,
                        spec.base_radius.unwrap_or(f64::NAN),
                        |s| at(T::Contact, i, to(s)),
                    )?;
                    if self.dynamics.is_some() {
                        super::system_dynamics::smooth_enough(&program, |s| {
                            at(T::Contact, i, to(s))
                        })?;
                    }
                }
                Ok::<_, SpecError>(curve)
            };
            let mut curves = [
                curve(&c.curve_a, SystemKey::CurveA, &mut warnings)?,
                curve(&c.curve_b, SystemKey::CurveB, &mut warnings)?,
            ];
            lash.extend(super::lash::apply(c, i, scale, &mut curves)?);
            let [curve_a, curve_b] = curves;
            hertz.push(super::system_dynamics::contact_hertz(c, i, scale)?);
            lubricated.push(super::system_lubrication::contact_lubrication(
                self.lubrication.as_ref(),
                c,
                i,
                unit.metres(),
            )?);
            restitution.push(match c.restitution {
                Some(e) => unit_interval(at(T::Contact, i, K::Restitution), e)?,
                None => default_restitution,
            });
            sys.add_contact(Contact {
                name: c.name.clone(),
                a,
                curve_a,
                b,
                curve_b,
            });
        }
        let non_negative = |f: Field, x: f64| -> Result<f64, SpecError> {
            if x >= 0.0 && x.is_finite() {
                Ok(x)
            } else {
                Err(SpecError::Invalid {
                    field: f,
                    value: crate::human::human(x),
                    reason: "must be zero or more, and finite".into(),
                })
            }
        };
        // a spring or damper with both ends on one body does nothing (a rigid body never
        // stretches it): a mistake
        let ends = |t: T, i: usize, names: &[String; 2], pts: [[f64; 2]; 2]| {
            let [a, b] = two(t, i, names)?;
            let (pa, pb) = (
                point(at(t, i, K::At), pts[0])?,
                point(at(t, i, K::At), pts[1])?,
            );
            Ok::<_, SpecError>((
                a,
                Point2::new(scale * pa.x, scale * pa.y),
                b,
                Point2::new(scale * pb.x, scale * pb.y),
            ))
        };
        for (i, sp) in self.spring.iter().enumerate() {
            named(T::Spring, i, &sp.name)?;
            let (a, at_a, b, at_b) = ends(T::Spring, i, &sp.bodies, sp.at)?;
            sys.add_force(ForceElement {
                name: sp.name.clone(),
                kind: ForceKind::Spring {
                    a,
                    at_a,
                    b,
                    at_b,
                    stiffness: within(
                        at(T::Spring, i, K::Stiffness),
                        non_negative(at(T::Spring, i, K::Stiffness), sp.stiffness)?,
                        0.0,
                        1e15,
                    )? / scale,
                    free_length: scale
                        * non_negative(at(T::Spring, i, K::FreeLength), sp.free_length)?,
                    preload: within(
                        at(T::Spring, i, K::Preload),
                        finite(at(T::Spring, i, K::Preload), sp.preload.unwrap_or(0.0))?,
                        0.0,
                        1e12,
                    )?,
                },
            });
        }
        for (i, d) in self.damper.iter().enumerate() {
            named(T::Damper, i, &d.name)?;
            let (a, at_a, b, at_b) = ends(T::Damper, i, &d.bodies, d.at)?;
            sys.add_force(ForceElement {
                name: d.name.clone(),
                kind: ForceKind::Damper {
                    a,
                    at_a,
                    b,
                    at_b,
                    damping: within(
                        at(T::Damper, i, K::Damping),
                        non_negative(at(T::Damper, i, K::Damping), d.damping)?,
                        0.0,
                        1e12,
                    )? / scale,
                },
            });
        }
        for (i, ts) in self.torsion_spring.iter().enumerate() {
            named(T::TorsionSpring, i, &ts.name)?;
            let [a, b] = two(T::TorsionSpring, i, &ts.bodies)?;
            sys.add_force(ForceElement {
                name: ts.name.clone(),
                kind: ForceKind::TorsionSpring {
                    a,
                    b,
                    stiffness: scale
                        * within(
                            at(T::TorsionSpring, i, K::Stiffness),
                            non_negative(at(T::TorsionSpring, i, K::Stiffness), ts.stiffness)?,
                            0.0,
                            1e15,
                        )?,
                    // a free angle within a thousand turns or so of the body's
                    free_angle: within(
                        at(T::TorsionSpring, i, K::FreeAngleDeg),
                        finite(
                            at(T::TorsionSpring, i, K::FreeAngleDeg),
                            ts.free_angle_deg.unwrap_or(0.0),
                        )?,
                        0.0,
                        1e6,
                    )?
                    .to_radians(),
                    preload: scale
                        * within(
                            at(T::TorsionSpring, i, K::Preload),
                            finite(
                                at(T::TorsionSpring, i, K::Preload),
                                ts.preload.unwrap_or(0.0),
                            )?,
                            0.0,
                            1e12,
                        )?,
                },
            });
        }
        let mut coil_springs = Vec::with_capacity(self.coil_spring.len());
        for (i, c) in self.coil_spring.iter().enumerate() {
            named(T::CoilSpring, i, &c.name)?;
            let (a, at_a, b, at_b) = ends(T::CoilSpring, i, &c.bodies, c.at)?;
            let f = |key| at(T::CoilSpring, i, key);
            let spring = crate::system::CoilSpring {
                name: c.name.clone(),
                a,
                at_a,
                b,
                at_b,
                stiffness: within(
                    f(K::Stiffness),
                    non_negative(f(K::Stiffness), c.stiffness)?,
                    0.0,
                    1e15,
                )? / scale,
                free_length: scale * non_negative(f(K::FreeLength), c.free_length)?,
                preload: within(
                    f(K::Preload),
                    finite(f(K::Preload), c.preload.unwrap_or(0.0))?,
                    0.0,
                    1e12,
                )?,
                mass: within(f(K::Mass), non_negative(f(K::Mass), c.mass)?, 0.0, 1e9)?,
                masses: match c.masses {
                    n if n <= 64 => n,
                    n => {
                        return Err(SpecError::Invalid {
                            field: f(K::Masses),
                            value: n.to_string(),
                            reason: "must be from 0 to 64".into(),
                        })
                    }
                },
                solid_length: c
                    .solid_length
                    .map(|s| non_negative(f(K::SolidLength), s).map(|s| scale * s))
                    .transpose()?,
                damping_ratio: within(
                    f(K::DampingRatio),
                    non_negative(f(K::DampingRatio), c.damping_ratio.unwrap_or(0.0))?,
                    0.0,
                    1.0,
                )?,
            };
            if let Some(solid) = spring.solid_length.filter(|&s| s >= spring.free_length) {
                return Err(SpecError::Invalid {
                    field: f(K::SolidLength),
                    value: crate::human::human(solid / scale),
                    reason: format!(
                        "must be below the free length {} (a spring is solid when its coils touch, shorter than free)",
                        crate::human::human(spring.free_length / scale)
                    ),
                });
            }
            if spring.masses > 0 && !(spring.mass > 0.0) {
                return Err(SpecError::Rule {
                    field: f(K::Mass),
                    reason: format!("{} lumped masses need the coils' mass", spring.masses),
                });
            }
            if spring.damping_ratio > 0.0 && spring.masses == 0 {
                return Err(SpecError::Rule {
                    field: f(K::DampingRatio),
                    reason: "is of the first surge mode: it needs lumped masses".into(),
                });
            }
            spring.add_to(&mut sys, metres_per_unit);
            // its coil-clash contacts take the default restitution
            restitution.resize(sys.contacts().len(), default_restitution);
            coil_springs.push(spring);
        }
        for (i, g) in self.gas_force.iter().enumerate() {
            named(T::GasForce, i, &g.name)?;
            let find = |name: &str| body(T::GasForce, i, K::Body, name);
            sys.add_table_force(super::system_dynamics::gas_force(g, i, scale, &find)?);
        }
        for (i, h) in self.lash_adjuster.iter().enumerate() {
            named(T::LashAdjuster, i, &h.name)?;
            let (a, at_a, b, at_b) = ends(T::LashAdjuster, i, &h.bodies, h.at)?;
            // its length as the file places the bodies
            let world = |id: BodyId, p: Point2| match id.index() {
                Some(k) => sys.bodies()[k].pose.to_world(p),
                None => p,
            };
            let drawn = (world(b, at_b) - world(a, at_a)).norm();
            sys.add_lash_adjuster(crate::system::LashAdjusterElement {
                name: h.name.clone(),
                adjuster: super::system_adjuster::lash_adjuster(
                    h,
                    i,
                    (a, at_a),
                    (b, at_b),
                    drawn,
                    scale,
                    metres_per_unit,
                )?,
            });
        }
        for (i, l) in self.load.iter().enumerate() {
            named(T::Load, i, &l.name)?;
            let find = |name: &str| body(T::Load, i, K::Body, name);
            sys.add_load(super::system_dynamics::load(l, i, scale, &find)?);
        }
        let timed_run = match (&self.simulation, &self.dynamics) {
            (Some(s), Some(_)) => Some(super::system_dynamics::timed_run(s)?),
            (Some(_), None) => {
                return Err(SpecError::Rule {
                    field: at(T::Simulation, 0, K::Table),
                    reason: "a simulation moves the system by its forces: give it a [dynamics] table (gravity, restitution)".into(),
                })
            }
            (None, _) => None,
        };
        // as many rows as coordinates, unless forces move the free degrees of freedom
        let (rows, coords) = (sys.rows(), 3 * sys.bodies().len());
        if rows != coords && self.dynamics.is_none() {
            return Err(SpecError::Rule {
                // at the last driver: the rule is most often met by driving one more coordinate
                field: at(T::Driver, self.driver.len().saturating_sub(1), K::Table),
                reason: format!(
                    "the system has {coords} coordinates (three for each of its {} bodies) and {rows} constraint rows (revolute and prismatic joints 2 each, fixed 3, drivers and contacts 1): a kinematic analysis needs as many rows as coordinates (drive each degree of freedom, or remove a redundant joint; a system simulated with [dynamics] need not)",
                    sys.bodies().len()
                ),
            });
        }
        let dynamics = crate::dynamics::SystemDynamicsOptions {
            metres_per_unit,
            gravity: match gravity {
                Some(g) => {
                    let g = point(at(T::Dynamics, 0, K::Gravity), g)?;
                    if g.coords.norm() > 1e6 {
                        return Err(SpecError::Invalid {
                            field: at(T::Dynamics, 0, K::Gravity),
                            value: super::build::vector([g.x, g.y]),
                            reason: "is outside the range the dynamics is computed in (at most 1e6 m/s²)".into(),
                        });
                    }
                    crate::Vec2::new(g.x, g.y)
                }
                None => crate::Vec2::zeros(),
            },
            restitution,
            hertz,
            start_touching,
            initial_rates: super::system_dynamics::initial_rates(&self.body, scale)?,
            ..crate::dynamics::SystemDynamicsOptions::default()
        };
        if let (Some(_), None) = (&self.lubrication, &self.dynamics) {
            return Err(SpecError::Rule {
                field: Field::Lubrication(crate::field::LubricationField::Table),
                reason: "a system's lubrication comes from its simulation's forces: give it a [dynamics] table".into(),
            });
        }
        if self.lubrication.is_some()
            && self.dynamics.is_some()
            && lubricated.iter().all(Option::is_none)
        {
            // a table no contact takes its oil from: nothing would be lubricated
            return Err(SpecError::Rule {
                field: Field::Lubrication(crate::field::LubricationField::Table),
                reason: "no contact takes this oil: only a contact with a face_width is lubricated (a line contact); give the contacts that run in it their face_width, or leave the table out".into(),
            });
        }
        Ok(BuiltSystem {
            system: sys,
            length_unit: unit,
            warnings,
            sweep_angle: SweepAngle::FirstDriver,
            dynamics,
            coil_springs,
            simulated: self.dynamics.is_some(),
            timed_run,
            lash,
            lubrication: self.lubrication.as_ref().map(|_| {
                crate::report::SystemLubricationRequest {
                    contacts: lubricated,
                }
            }),
        })
    }
}
