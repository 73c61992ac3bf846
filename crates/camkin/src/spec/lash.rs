//! A contact's lash (valve clearance): `lash = δ` on a system file's `[[contact]]` moves the
//! contact's follower face — its `line` or `circle` curve — δ into its own material, so that the
//! file is drawn at zero lash (the follower on the cam's base circle with the valve on its seat)
//! and the clearance is one number. A line moves along its left normal (its material's side), a
//! circle (a roller, its material inside) shrinks by δ about its centre: either way the gap along
//! the common normal at the base circle is δ wherever they face each other. The face moved is
//! `curve_b`, or `curve_a` when `curve_b` is the contact's `motion` cam.
//!
//! [`BuiltSystem::with_lash`] makes the same system at another lash (a sweep), and
//! [`LashCycle::find`] finds a lashed contact's take-up and the seating that ends its lift among a
//! run's events; [`BuiltSystem::lash_sweep`] runs both over a list of lashes.

use super::{BuiltSystem, ContactSpec, PlanError, ProfileKind, SpecError};
use crate::curve::{Circle, Curve, Line};
use crate::dynamics::{ContactEvent, EventKind};
use crate::field::{Field, SystemField, SystemKey, SystemTable};
use crate::geometry::{Point2, Vec2};
use crate::table::LashRow;
use std::sync::Arc;

/// The largest lash, as a fraction of the system's size: a clearance is small.
const MAX_LASH_OF_SIZE: f64 = 0.1;

/// The face a lash moves, at zero lash (the system's unit).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Face {
    /// a flat face through `anchor` along the unit `direction`, its material on the left
    Line { anchor: Point2, direction: Vec2 },
    /// a roller, its material inside
    Circle { center: Point2, radius: f64 },
}

/// A contact with a lash: the face it moves at zero lash and the lash it has.
#[derive(Debug, Clone, PartialEq)]
pub struct Lashed {
    /// the contact, in the system's order
    pub contact: usize,
    /// its lash, the system's length unit
    pub lash: f64,
    /// the face moved is curve B (else curve A)
    on_b: bool,
    face: Face,
    /// the contact's `starts_closed` as written (at zero lash it starts as that says)
    starts_closed: Option<bool>,
}

impl Lashed {
    /// The face at `lash`: a line moved along its left normal, a circle shrunk.
    fn curve(&self, lash: f64) -> Result<Arc<dyn Curve>, String> {
        match self.face {
            Face::Line { anchor, direction } => {
                let left = Vec2::new(-direction.y, direction.x);
                Line::new(anchor + lash * left, direction)
                    .map(|l| Arc::new(l) as Arc<dyn Curve>)
                    .map_err(|e| e.to_string())
            }
            Face::Circle { center, radius } => {
                if lash >= radius {
                    return Err(format!(
                        "is not below the roller's radius {}",
                        crate::human::human(radius)
                    ));
                }
                Circle::new(center, radius - lash)
                    .map(|c| Arc::new(c) as Arc<dyn Curve>)
                    .map_err(|e| e.to_string())
            }
        }
    }

    /// How the contact starts at `lash`: apart when there is one, else as its file says.
    fn starts(&self, lash: f64) -> Option<bool> {
        if lash > 0.0 {
            Some(false)
        } else {
            self.starts_closed
        }
    }
}

fn at(index: usize, key: SystemKey) -> Field {
    Field::System(SystemField {
        table: SystemTable::Contact,
        index,
        key,
    })
}

/// Contact `i`'s lash, when it has one: its record, and its face at that lash in place of the
/// built one (`curves`, A and B); `scale` takes the file's lengths to the system's.
pub(crate) fn apply(
    c: &ContactSpec,
    i: usize,
    scale: f64,
    curves: &mut [Arc<dyn Curve>; 2],
) -> Result<Option<Lashed>, SpecError> {
    let Some(lash) = c.lash else {
        return Ok(None);
    };
    let h = crate::human::human;
    if !(lash >= 0.0 && lash.is_finite()) {
        return Err(SpecError::Invalid {
            field: at(i, SystemKey::Lash),
            value: h(lash),
            reason: "must be zero or more, and finite (a clearance, the file's length unit)".into(),
        });
    }
    if lash > 0.0 && c.starts_closed == Some(true) {
        return Err(SpecError::Rule {
            field: at(i, SystemKey::StartsClosed),
            reason: format!(
                "is true, and the contact has a lash of {}: it starts apart (leave starts_closed out)",
                h(lash)
            ),
        });
    }
    let on_b = c.curve_b.kind != ProfileKind::Motion.name();
    let (spec, key) = if on_b {
        (&c.curve_b, SystemKey::CurveB as fn(_) -> SystemKey)
    } else {
        (&c.curve_a, SystemKey::CurveA as fn(_) -> SystemKey)
    };
    let face = if spec.kind == ProfileKind::Line.name() {
        let [x, y] = spec.anchor.unwrap_or([0.0, 0.0]);
        let d = spec.direction.unwrap_or([1.0, 0.0]);
        let d = Vec2::new(d[0], d[1]);
        Face::Line {
            anchor: Point2::new(scale * x, scale * y),
            direction: d / d.norm(),
        }
    } else if spec.kind == ProfileKind::Circle.name() {
        let [x, y] = spec.center.unwrap_or([0.0, 0.0]);
        Face::Circle {
            center: Point2::new(scale * x, scale * y),
            radius: scale * spec.radius.unwrap_or(f64::NAN),
        }
    } else {
        return Err(SpecError::Rule {
            field: at(i, key(crate::field::ProfileField::Kind)),
            reason: format!(
                "is {:?}, and the contact has a lash: the lash moves the follower's face, a \"line\" (a flat face) or a \"circle\" (a roller); draw a face of another shape a lash away from the cam instead",
                spec.kind
            ),
        });
    };
    let lashed = Lashed {
        contact: i,
        lash: scale * lash,
        on_b,
        face,
        starts_closed: c.starts_closed,
    };
    let curve = lashed
        .curve(lashed.lash)
        .map_err(|reason| SpecError::Invalid {
            field: at(i, SystemKey::Lash),
            value: h(lash),
            reason,
        })?;
    curves[usize::from(on_b)] = curve;
    Ok(Some(lashed))
}

/// Why a lash cannot be set.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum LashError {
    /// No contact of the system has a `lash` key.
    #[error("no contact has a lash: give the contact whose clearance it is `lash = …` (the file's length unit), its follower's face drawn touching the cam's base circle")]
    NoLash,
    /// The lash is out of its range.
    #[error("{value}: {reason}")]
    Invalid {
        /// the lash, as given (the system's unit)
        value: String,
        /// why
        reason: String,
    },
    /// A run at a lash cannot be planned or simulated.
    #[error(transparent)]
    Plan(#[from] PlanError),
}

/// A lashed contact's cycle among a run's events: its take-up (the impact that closes it) and
/// the seating that ends the lift it starts — the first impact, after the take-up, of a contact
/// the take-up released (the valve leaving its seat at the instant the cam takes up the lash).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LashCycle {
    /// the impact of the lashed contact
    pub take_up: ContactEvent,
    /// the seat's impact, when the run has it
    pub seating: Option<ContactEvent>,
}

impl LashCycle {
    /// Contact `contact`'s last take-up in `events` that a seating follows (the last take-up
    /// when none does); `None` when it never closes by an impact.
    pub fn find(events: &[ContactEvent], contact: usize) -> Option<Self> {
        let same = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + a.abs().max(b.abs()));
        let mut found: Option<Self> = None;
        for (k, e) in events.iter().enumerate() {
            if e.kind != EventKind::Impact || e.contact != contact {
                continue;
            }
            let released: Vec<usize> = events
                .iter()
                .filter(|r| {
                    r.kind == EventKind::LiftOff && r.contact != contact && same(r.time, e.time)
                })
                .map(|r| r.contact)
                .collect();
            let seating = events[k + 1..]
                .iter()
                .find(|s| {
                    s.kind == EventKind::Impact
                        && released.contains(&s.contact)
                        && !same(s.time, e.time)
                })
                .copied();
            if seating.is_some() || found.is_none_or(|f| f.seating.is_none()) {
                found = Some(Self {
                    take_up: *e,
                    seating,
                });
            }
        }
        found
    }
}

impl BuiltSystem {
    /// The same system with every lashed contact at `lash` (the system's unit); `LashError::NoLash`
    /// when none has a lash.
    pub fn with_lash(&self, lash: f64) -> Result<BuiltSystem, LashError> {
        if self.lash.is_empty() {
            return Err(LashError::NoLash);
        }
        let h = crate::human::human;
        let limit = MAX_LASH_OF_SIZE * self.system.size();
        if !(lash >= 0.0 && lash <= limit) {
            return Err(LashError::Invalid {
                value: h(lash),
                reason: format!(
                    "must be from 0 to {} (a tenth of the system's size)",
                    h(limit)
                ),
            });
        }
        let mut out = self.clone();
        for l in &mut out.lash {
            let curve = l.curve(lash).map_err(|reason| LashError::Invalid {
                value: h(lash),
                reason,
            })?;
            let c = &mut out.system.contacts[l.contact];
            if l.on_b {
                c.curve_b = curve;
            } else {
                c.curve_a = curve;
            }
            if let Some(s) = out.dynamics.start_touching.get_mut(l.contact) {
                *s = l.starts(lash);
            }
            l.lash = lash;
        }
        Ok(out)
    }

    /// Each lash of `lashes` (the system's unit) run over `revolutions` of the first driver in
    /// `step_deg` output steps: a row per lash and lashed contact, with its take-up and seating
    /// ([`LashCycle::find`]) at their driver angles. The lashes run on rayon's threads with the
    /// `parallel` feature.
    pub fn lash_sweep(
        &self,
        lashes: &[f64],
        revolutions: f64,
        step_deg: f64,
    ) -> Result<Vec<LashRow>, LashError> {
        let one = |&lash: &f64| -> Result<Vec<LashRow>, LashError> {
            let built = self.with_lash(lash)?;
            let (plan, mut sim) = built.plan(revolutions, step_deg)?;
            let run = sim
                .run(plan.outputs, plan.h_out, |_| {
                    std::ops::ControlFlow::Continue(())
                })
                .map_err(PlanError::from)?;
            Ok(built
                .lash
                .iter()
                .map(|l| {
                    let cycle = LashCycle::find(&run.events, l.contact);
                    let name = |k: usize| built.system.contacts()[k].name.clone();
                    let take_up = cycle.map(|c| c.take_up);
                    let seating = cycle.and_then(|c| c.seating);
                    LashRow {
                        lash,
                        contact: name(l.contact),
                        take_up_angle_deg: take_up.and_then(|e| plan.angle_of(e.time)),
                        take_up_speed: take_up.map(|e| e.approach),
                        seat: seating.map(|e| name(e.contact)),
                        seating_angle_deg: seating.and_then(|e| plan.angle_of(e.time)),
                        seating_speed: seating.map(|e| e.approach),
                    }
                })
                .collect())
        };
        #[cfg(feature = "parallel")]
        let rows: Vec<_> = {
            use rayon::prelude::*;
            lashes.par_iter().map(one).collect()
        };
        #[cfg(not(feature = "parallel"))]
        let rows: Vec<_> = lashes.iter().map(one).collect();
        let mut out = Vec::new();
        for r in rows {
            out.extend(r?);
        }
        Ok(out)
    }

    /// The work of [`Self::lash_sweep`] over `lashes` lashes: that many runs of the plan.
    pub fn lash_sweep_work(
        &self,
        lashes: usize,
        revolutions: f64,
        step_deg: f64,
    ) -> Result<crate::work::Work, LashError> {
        let (plan, sim) = self.plan(revolutions, step_deg)?;
        let n = lashes as f64;
        Ok(crate::work::Work::system_simulation(
            &self.system,
            n * sim.steps_estimate(plan.duration(), plan.h_out),
            n * (plan.outputs + 1) as f64,
            plan.outputs + 1,
        ))
    }
}
