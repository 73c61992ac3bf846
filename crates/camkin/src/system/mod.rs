//! Planar multibody systems: rigid bodies, joints between any two of them (or a body and the
//! ground), driven coordinates, and contacts between curves carried by any two bodies, each
//! contact imposed as the paper's one linear row (eq. 11) with its exact `γ`.
//!
//! # Coordinates and rows
//!
//! Body `i` has `q_i = (x_i, y_i, θ_i)`: its frame's origin and angle in the world
//! (counter-clockwise positive); the ground has none. Every joint, driver and contact gives rows
//! of `Φ(q, t) = 0`, and at one instant the analysis solves, in turn (Haug 1989, ch. 3):
//!
//! ```text
//! Φ(q, t) = 0                  positions: Newton from the previous instant (or the initial poses,
//!                              each contact's pairing found first by a global search)
//! Φ_q q̇ = −Φ_t                 velocities
//! Φ_q q̈ = γ                    accelerations
//! ```
//!
//! with one `Φ_q`. A contact's row is its gap along the common normal, `ν_A·(x_A − x_B)`, at the
//! pairing points (re-solved at every Newton step, so its derivative is the row
//! [`crate::contact::ContactKinematics::phi_q`]); its `γ` is the paper's, with the Coriolis
//! (`2 ω ṡ`) and relative (`κ ṡ²`) terms from the exact sliding rates: no difference in time, no
//! interpolation. The joints' rows (see [`JointKind`]) and the drivers' (`q_k − f(t)`) are the
//! textbook ones. See `multibody-systems.md` for the conventions.
//!
//! The bodies' jerk at a solved instant, [`System::jerk`], differentiates the rows once more in
//! time, exactly (Taylor jets), with each contact written as its pairing conditions instead of
//! its gap row; it is not defined where a contact sits on a curve's breakpoint.
//!
//! A system must have as many rows as coordinates (each degree of freedom driven): the analysis
//! says which rows are redundant or singular (a dead point, a toggle) at which instant, never an
//! answer from a singular matrix.

mod applied_load;
mod assemble;
mod bending;
mod coil_spring;
mod cost;
mod driver;
mod error;
mod force;
mod jerk;
mod joint;
mod lash_adjuster;
mod lu;
mod newton;
mod period;
mod search;
mod solve;
mod table_force;

pub use applied_load::{AppliedLoad, LoadFrame};
pub use coil_spring::CoilSpring;
pub use driver::{Coordinate, Driver, DriverLaw};
pub use error::SystemError;
pub use jerk::BodyJerk;
pub(crate) use joint::RowEval;
pub use joint::{Joint, JointKind};
pub use lash_adjuster::{LashAdjuster, LashAdjusterElement, ATMOSPHERE};
pub use solve::{ContactState, Instants, SystemState, SystemSweep};
pub use table_force::TableForce;

use crate::body::Pose;
use crate::curve::Curve;
use crate::geometry::Point2;
use std::sync::Arc;

/// A body of a [`System`], or the ground.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct BodyId(pub(crate) usize);

impl BodyId {
    /// The ground: fixed, no coordinates.
    pub const GROUND: BodyId = BodyId(usize::MAX);

    /// Whether this is the ground.
    pub fn is_ground(self) -> bool {
        self == Self::GROUND
    }

    /// The index of a moving body (`None` for the ground).
    pub fn index(self) -> Option<usize> {
        (!self.is_ground()).then_some(self.0)
    }
}

/// A rigid body: its name, its mass properties (for dynamics) and where it starts (the first
/// Newton iteration's guess: near its assembled pose).
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// its name, as errors and results name it
    pub name: String,
    /// mass
    pub mass: f64,
    /// moment of inertia about its centre of mass (what a CAD model reports as `I_G`)
    pub inertia: f64,
    /// its pose at the start, a guess
    pub pose: Pose,
    /// its centre of mass, in its frame (the origin for a body whose frame sits there)
    pub centre_of_mass: Point2,
}

/// A contact between a curve on body `a` and a curve on body `b` (either may be the ground): one
/// row, the gap along the common normal, with the paper's `γ`. The curves are in their bodies'
/// frames, material on the left (see the crate's sign conventions).
#[derive(Debug, Clone)]
pub struct Contact {
    /// its name
    pub name: String,
    /// the body carrying curve A
    pub a: BodyId,
    /// curve A, in `a`'s frame
    pub curve_a: Arc<dyn Curve>,
    /// the body carrying curve B
    pub b: BodyId,
    /// curve B, in `b`'s frame
    pub curve_b: Arc<dyn Curve>,
}

/// A force element between two bodies (or a body and the ground): for dynamics; the kinematic
/// analysis does not need them, but a system carries them so that one file describes the whole
/// mechanism.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum ForceKind {
    /// A linear spring between two points: tension `stiffness (length − free_length) + preload`.
    Spring {
        /// the first body
        a: BodyId,
        /// its end on `a`, in `a`'s frame
        at_a: Point2,
        /// the second body
        b: BodyId,
        /// its end on `b`, in `b`'s frame
        at_b: Point2,
        /// N per length
        stiffness: f64,
        /// the length at which the spring force is the preload
        free_length: f64,
        /// N at the free length
        preload: f64,
    },
    /// A linear damper between two points: force `damping × the rate of its length`.
    Damper {
        /// the first body
        a: BodyId,
        /// its end on `a`
        at_a: Point2,
        /// the second body
        b: BodyId,
        /// its end on `b`
        at_b: Point2,
        /// N·s per length
        damping: f64,
    },
    /// A torsion spring between two bodies' angles: torque
    /// `stiffness (θ_b − θ_a − free_angle) + preload`.
    TorsionSpring {
        /// the first body
        a: BodyId,
        /// the second body
        b: BodyId,
        /// N·length per rad
        stiffness: f64,
        /// rad
        free_angle: f64,
        /// N·length at the free angle
        preload: f64,
    },
    /// A torsion damper between two bodies' angles: torque `damping (ω_b − ω_a)`, `+` on `a`
    /// and `−` on `b` (it resists their relative turning, as a torsion spring resists their
    /// relative angle).
    TorsionDamper {
        /// the first body
        a: BodyId,
        /// the second body
        b: BodyId,
        /// N·length·s per rad
        damping: f64,
    },
}

impl ForceKind {
    /// The two bodies it acts between.
    pub fn bodies(&self) -> [BodyId; 2] {
        match *self {
            ForceKind::Spring { a, b, .. }
            | ForceKind::Damper { a, b, .. }
            | ForceKind::TorsionSpring { a, b, .. }
            | ForceKind::TorsionDamper { a, b, .. } => [a, b],
        }
    }
}

/// A named force element.
#[derive(Debug, Clone, PartialEq)]
pub struct ForceElement {
    /// its name
    pub name: String,
    /// what it is
    pub kind: ForceKind,
}

/// A planar multibody system: bodies, joints, drivers and contacts. Build it with
/// [`System::new`] and the `add_` methods; [`System::analyze`] solves one instant,
/// [`System::sweep`] many, warm-started.
#[derive(Debug, Clone, Default)]
pub struct System {
    pub(crate) bodies: Vec<Body>,
    pub(crate) joints: Vec<Joint>,
    pub(crate) drivers: Vec<Driver>,
    pub(crate) contacts: Vec<Contact>,
    pub(crate) forces: Vec<ForceElement>,
    pub(crate) table_forces: Vec<TableForce>,
    pub(crate) loads: Vec<AppliedLoad>,
    pub(crate) lash_adjusters: Vec<LashAdjusterElement>,
}

impl System {
    /// An empty system (the ground alone).
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a body; returns its id.
    pub fn add_body(&mut self, body: Body) -> BodyId {
        self.bodies.push(body);
        BodyId(self.bodies.len() - 1)
    }

    /// Adds a joint.
    pub fn add_joint(&mut self, joint: Joint) {
        self.joints.push(joint);
    }

    /// Adds a driver.
    pub fn add_driver(&mut self, driver: Driver) {
        self.drivers.push(driver);
    }

    /// Adds a contact.
    pub fn add_contact(&mut self, contact: Contact) {
        self.contacts.push(contact);
    }

    /// Adds a hydraulic lash adjuster (for dynamics: its chamber's pressure is a state).
    pub fn add_lash_adjuster(&mut self, adjuster: LashAdjusterElement) {
        self.lash_adjusters.push(adjuster);
    }

    /// The hydraulic lash adjusters.
    pub fn lash_adjusters(&self) -> &[LashAdjusterElement] {
        &self.lash_adjusters
    }

    /// Adds a force element.
    pub fn add_force(&mut self, force: ForceElement) {
        self.forces.push(force);
    }

    /// The force elements.
    pub fn forces(&self) -> &[ForceElement] {
        &self.forces
    }

    /// Adds a force from a table of the crank angle (a gas force).
    pub fn add_table_force(&mut self, force: TableForce) {
        self.table_forces.push(force);
    }

    /// The forces from tables of the crank angle.
    pub fn table_forces(&self) -> &[TableForce] {
        &self.table_forces
    }

    /// Adds an applied load: a force and a torque on a body, constant or by a table of time.
    pub fn add_load(&mut self, load: AppliedLoad) {
        self.loads.push(load);
    }

    /// The applied loads.
    pub fn loads(&self) -> &[AppliedLoad] {
        &self.loads
    }

    /// The bodies, in the order they were added.
    pub fn bodies(&self) -> &[Body] {
        &self.bodies
    }

    /// The joints.
    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }

    /// The drivers.
    pub fn drivers(&self) -> &[Driver] {
        &self.drivers
    }

    /// The first driver's speed at time 0, rpm (its rate in rad/s turned to turns a minute; 0
    /// without a driver): the speed a system's revolution, sweeps and pages are given at.
    pub fn first_driver_rpm(&self) -> f64 {
        self.drivers
            .first()
            .map_or(0.0, |d| d.law.at(0.0)[1] * 60.0 / std::f64::consts::TAU)
    }

    /// Driver `index`'s law replaced by `law` (a speed sweep: the same system at another speed);
    /// `false` when there is no such driver.
    pub fn set_driver_law(&mut self, index: usize, law: DriverLaw) -> bool {
        match self.drivers.get_mut(index) {
            Some(d) => {
                d.law = law;
                true
            }
            None => false,
        }
    }

    /// The contacts.
    pub fn contacts(&self) -> &[Contact] {
        &self.contacts
    }

    /// The body of `id`'s name (`ground` for the ground).
    pub fn body_name(&self, id: BodyId) -> &str {
        match id.index() {
            Some(i) => self.bodies.get(i).map_or("?", |b| b.name.as_str()),
            None => "ground",
        }
    }

    /// A length of the system's size: the largest distance of a body's start, a joint's point
    /// or a curve's point from the world's origin (at least 1e-300), for tolerances.
    pub fn size(&self) -> f64 {
        let mut s: f64 = 0.0;
        for b in &self.bodies {
            s = s.max(b.pose.origin.coords.norm());
        }
        for j in &self.joints {
            for (_, p) in j.kind.points() {
                s = s.max(p.coords.norm());
            }
        }
        for c in &self.contacts {
            for curve in [&c.curve_a, &c.curve_b] {
                for k in 0..16 {
                    let u = match curve.domain() {
                        crate::curve::Domain::Periodic { period } => period * k as f64 / 16.0,
                        crate::curve::Domain::Interval { min, max }
                            if min.is_finite() && max.is_finite() =>
                        {
                            min + (max - min) * k as f64 / 16.0
                        }
                        _ => 0.0,
                    };
                    s = s.max(curve.position(u).coords.norm());
                }
            }
        }
        s.max(1e-300)
    }

    /// Checks that every joint, driver and contact names bodies of this system and that the
    /// rows can determine the coordinates (as many rows as coordinates).
    pub fn check(&self) -> Result<(), SystemError> {
        self.check_elements()?;
        let rows = self.rows();
        let n = self.bodies.len();
        if rows != 3 * n {
            return Err(SystemError::NotSquare {
                coordinates: 3 * n,
                rows,
            });
        }
        Ok(())
    }

    /// Checks that every joint, driver, contact and force element names bodies of this system,
    /// two different ones, and that no coordinate is driven twice: what a simulation needs
    /// (its degrees of freedom need not be driven).
    pub fn check_elements(&self) -> Result<(), SystemError> {
        let n = self.bodies.len();
        let known = |id: BodyId| id.is_ground() || id.0 < n;
        for j in &self.joints {
            for id in j.kind.bodies() {
                if !known(id) {
                    return Err(SystemError::UnknownBody {
                        element: j.name.clone(),
                    });
                }
            }
            let [a, b] = j.kind.bodies();
            if a == b {
                return Err(SystemError::SameBody {
                    element: j.name.clone(),
                    body: self.body_name(a).to_string(),
                });
            }
            if let JointKind::Prismatic { axis, .. } = j.kind {
                let unit = joint::unit(axis);
                if !(unit.x.is_finite() && unit.y.is_finite()) {
                    return Err(SystemError::Axis {
                        element: j.name.clone(),
                    });
                }
            }
        }
        for c in &self.contacts {
            if !known(c.a) || !known(c.b) {
                return Err(SystemError::UnknownBody {
                    element: c.name.clone(),
                });
            }
            if c.a == c.b {
                return Err(SystemError::SameBody {
                    element: c.name.clone(),
                    body: self.body_name(c.a).to_string(),
                });
            }
        }
        let mut driven = std::collections::HashSet::new();
        for d in &self.drivers {
            if d.body.is_ground() || !known(d.body) {
                return Err(SystemError::UnknownBody {
                    element: d.name.clone(),
                });
            }
            if !driven.insert((d.body, d.coordinate)) {
                return Err(SystemError::DrivenTwice {
                    element: d.name.clone(),
                    body: self.body_name(d.body).to_string(),
                    coordinate: d.coordinate,
                });
            }
        }
        for f in &self.forces {
            let [a, b] = f.kind.bodies();
            if !known(a) || !known(b) {
                return Err(SystemError::UnknownBody {
                    element: f.name.clone(),
                });
            }
        }
        for f in &self.table_forces {
            if !known(f.body) {
                return Err(SystemError::UnknownBody {
                    element: f.name.clone(),
                });
            }
        }
        for l in &self.loads {
            if !known(l.body) {
                return Err(SystemError::UnknownBody {
                    element: l.name.clone(),
                });
            }
        }
        Ok(())
    }

    /// The time at which the first driver, an angle, is at `angle` (rad): how a sweep over a
    /// driver angle maps to instants (with an acceleration, the instant nearest the start at
    /// which it is there); `None` when the first driver is not an angle, its rate at the start
    /// is zero, or, slowing down, it never turns so far.
    pub fn driver_time(&self, angle: f64) -> Option<f64> {
        let d = self.drivers.first()?;
        match (d.coordinate, d.law) {
            (
                Coordinate::Angle,
                DriverLaw::Quadratic {
                    start,
                    rate,
                    acceleration,
                },
            ) if acceleration == 0.0 && rate != 0.0 && rate.is_finite() => {
                Some((angle - start) / rate)
            }
            // accelerating: the first instant it reaches the angle, 2Δ/(ω + √(ω² + 2αΔ)) (no
            // cancellation for a small α); none where, slowing down, it never does
            (
                Coordinate::Angle,
                DriverLaw::Quadratic {
                    start,
                    rate,
                    acceleration,
                },
            ) if rate != 0.0 && rate.is_finite() && acceleration.is_finite() => {
                let d = angle - start;
                let disc = rate * rate + 2.0 * acceleration * d;
                let t = 2.0 * d / (rate + rate.signum() * disc.sqrt());
                t.is_finite().then_some(t)
            }
            _ => None,
        }
    }

    /// The number of constraint rows: every joint's, driver's and contact's.
    pub fn rows(&self) -> usize {
        self.joints.iter().map(|j| j.kind.rows()).sum::<usize>()
            + self.drivers.len()
            + self.contacts.len()
    }

    /// The name of row `r` and what it constrains (`joint "pivot" (x)`), for messages.
    pub fn row_name(&self, r: usize) -> String {
        let mut k = r;
        for j in &self.joints {
            let n = j.kind.rows();
            if k < n {
                return format!("joint {:?} ({})", j.name, j.kind.row_label(k));
            }
            k -= n;
        }
        if k < self.drivers.len() {
            return format!("driver {:?}", self.drivers[k].name);
        }
        k -= self.drivers.len();
        match self.contacts.get(k) {
            Some(c) => format!("contact {:?}", c.name),
            None => format!("row {r}"),
        }
    }
}
