//! The dynamics of any [`crate::system::System`]: its bodies' masses, its joints and drivers as
//! bilateral rows, its contacts as unilateral rows (the paper's eq. 11 with its exact `γ`), its
//! springs, dampers and torsion springs, and gravity.
//!
//! The equations of motion `M q̈ + Φ_qᵀ λ = Q`, `Φ_q q̈ = γ` are solved at every evaluation by the
//! Schur complement (the augmented Lagrangian where rows are dependent: see the
//! [module docs](super)), integrated by the Dormand–Prince 5(4) pair with its steps chosen by the
//! tolerances, and after every step positions and velocities are projected mass-orthogonally onto
//! the active rows (Bayo and Ledesma 1996). The coordinates integrated are each body's centre of
//! mass and angle, so `M` is diagonal (mass, mass, the inertia about the centre); a body's frame
//! may sit anywhere on it (see [`centre`]), and the samples give the frames' coordinates.
//!
//! A contact is unilateral:
//! - in contact, its row holds while its force (`−λ`) is compressive; where it would turn
//!   tensile inside a step, the instant is located by bisection on the force and the contact
//!   leaves (a lift-off);
//! - in flight, its gap (along the common normal of the nearest points) is watched; where it
//!   closes inside a step, the instant is located by bisection on the gap, and the impact
//!   reverses the normal velocity times the restitution (Newton's law) by a mass-orthogonal
//!   projection of the velocities with every joint, driver and contact in touch held; a rebound
//!   below [`REBOUND_TOLERANCE`] of the system's speed scale re-engages the contact.
//!
//! Units: lengths in the system's unit `L` (its curves' and joints'), masses in kg and inertias
//! in kg·m² (converted with the unit's size in metres), forces in N, stiffnesses in N/L, gravity
//! in m/s²; energies are reported in N·L.

mod adjusters;
mod balance;
mod centre;
mod eval;
mod impact;
mod integrate;
mod project;
mod rates;
mod singular;
mod sparse;
mod start;

pub use balance::{ElementEnergy, EnergyBalance};
pub use start::StartReport;

use super::follower::EventKind;
use super::model::{Constraint, Load, Model, RigidBody};
use super::{AugmentedLagrangian, DynamicsError};
use crate::contact::{self, Pairing, Proximity, SearchOptions, Surface};
use crate::geometry::Vec2;
use crate::system::SystemError;

/// How a system is simulated.
#[derive(Debug, Clone, PartialEq)]
pub struct SystemDynamicsOptions {
    /// the system's length unit in metres (1e-3 for mm)
    pub metres_per_unit: f64,
    /// gravity in the world, m/s²
    pub gravity: Vec2,
    /// Newton's coefficient of restitution of each contact, 0 to 1, in the system's order (a
    /// contact past the list's end: 0)
    pub restitution: Vec<f64>,
    /// the augmented Lagrangian's parameters, where rows are dependent; by default its penalty
    /// is 1e4 of the largest mass (see [`SystemDynamicsOptions::default`]). Its stabilisation
    /// (`ξ`, `Ω`) is not used: positions and velocities are projected onto the rows after every
    /// step, and a stabilisation at every stage drained a conservative system's energy
    pub al: AugmentedLagrangian,
    /// the integration's tolerances (the step is chosen by them)
    pub tolerances: super::Tolerances,
    /// the integrator: explicit, implicit (stiff systems), or chosen by the system's rates
    pub scheme: super::Scheme,
    /// each contact's line-contact width and materials for its Hertz pressure, in the system's
    /// order (none past the list's end)
    pub hertz: Vec<Option<ContactHertz>>,
    /// whether each contact starts in touch whatever its gap at the starting poses, in the
    /// system's order: `Some(true)` closed (the poses are assembled onto it), `Some(false)`
    /// apart (a lash: the cam meets its follower later); a contact not marked (`None`, or past
    /// the list's end) starts in touch only where its curves are within 1e-3 of the system's
    /// size (otherwise it starts apart, and its bodies move onto it: a drop). The speed sweep
    /// ([`super::no_follow_speed`]) marks the contacts that a slow revolution closes and keeps
    /// closed, so that its verdict does not depend on how near the file's poses were.
    pub start_touching: Vec<Option<bool>>,
    /// each body's starting frame rates `(v_x, v_y, ω)` (L/s, L/s, rad/s) where given, in the
    /// system's order (a body past the list's end, or a rate not given: the assembled state's,
    /// at rest but for the drivers); made consistent with the rows at the start, and what that
    /// changed reported ([`SystemSimulation::start_report`])
    pub initial_rates: Vec<[Option<f64>; 3]>,
}

/// A contact's face width and elastic materials: its Hertz line pressure
/// `p = √(F E* (1/R₁ + 1/R₂) / (π L))` (Johnson, Contact Mechanics, 1985, §4.2) from the force
/// and the curves' radii of curvature at the contact point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactHertz {
    /// the face width `L`, in the system's length unit
    pub width: f64,
    /// `E*` of the two materials, Pa
    pub e_star: f64,
}

impl Default for SystemDynamicsOptions {
    /// No gravity, lengths in metres, no rebound, and the augmented Lagrangian with a penalty
    /// of 1e4 of the largest mass (not the cam model's 1e8): the matrix `M + α Φ_qᵀ Φ_q` it
    /// factors has a condition number of about the penalty, which costs the free motion that
    /// many ulps — at 1e8 a pendulum's energy wandered by 3e-9 of itself whatever the step, at
    /// 1e4 by the integration's own error alone, in a few more iterations. Tolerances of 1e-10
    /// ([`super::Tolerances::default`]).
    fn default() -> Self {
        Self {
            metres_per_unit: 1.0,
            gravity: Vec2::zeros(),
            restitution: Vec::new(),
            hertz: Vec::new(),
            start_touching: Vec::new(),
            initial_rates: Vec::new(),
            al: AugmentedLagrangian {
                penalty: 1e4,
                ..AugmentedLagrangian::default()
            },
            tolerances: super::Tolerances::default(),
            scheme: super::Scheme::Auto,
        }
    }
}

/// A lift-off or an impact of a contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactEvent {
    /// lift-off or impact
    pub kind: EventKind,
    /// when, s
    pub time: f64,
    /// which contact, in the system's order
    pub contact: usize,
    /// an impact's approach speed along the normal (L/s; 0 for a lift-off)
    pub approach: f64,
}

/// The state of a simulated system at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct SystemSample {
    /// s
    pub time: f64,
    /// every body's `(x, y, θ)`, in the system's order
    pub q: Vec<f64>,
    /// their rates
    pub qd: Vec<f64>,
    /// their accelerations
    pub qdd: Vec<f64>,
    /// each contact's compressive force, N (0 in flight)
    pub contact_forces: Vec<f64>,
    /// each contact's gap along its common normal, L (0 in contact)
    pub gaps: Vec<f64>,
    /// whether each contact is in touch
    pub in_contact: Vec<bool>,
    /// kinetic plus potential energy (springs, torsion springs, gravity), N·L
    pub energy: f64,
    /// the energy balance: kinetic, each element's potential and work, the drivers', loads'
    /// and constraint forces' work, the impacts' losses, the momentum
    pub balance: EnergyBalance,
    /// the work the drivers, the forces from tables of the crank angle (a gas force) and the
    /// applied loads have done since the start, N·L
    pub driver_work: f64,
    /// each driver's effort along its coordinate: an angle's torque (N·L, counter-clockwise
    /// positive: a camshaft's driving torque), a position's force (N)
    pub driver_efforts: Vec<f64>,
    /// each contact's Hertz pressure, Pa: where it has a width and materials
    /// ([`ContactHertz`]) and is closed (0 open), none where its curvatures do not close (a
    /// concave curve as sharp as the other) or a curve is a point
    pub hertz_pa: Vec<Option<f64>>,
    /// each contact's nearest pair of points (its contact point and normal in touch), world
    pub pairings: Vec<Option<Pairing>>,
    /// each closed contact's curves' radii and surface speeds (none where it is open or a curve
    /// is a point)
    pub surfaces: Vec<Option<ContactSurface>>,
    /// each lash adjuster's chamber: its gauge pressure (Pa) and height (L)
    pub adjusters: Vec<AdjusterSample>,
}

/// A hydraulic lash adjuster's chamber at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AdjusterSample {
    /// its gauge pressure, Pa
    pub pressure: f64,
    /// its height (the plunger's travel out of the bore from empty), L
    pub chamber: f64,
    /// its push on the two bodies, N
    pub force: f64,
}

/// A closed contact's two curves at the contact point: what its lubrication needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactSurface {
    /// each curve's radius of curvature there, m, convex positive (`∞`: straight; negative:
    /// concave)
    pub radius: [f64; 2],
    /// the speed at which each curve's material passes the contact point, m/s, along curve A's
    /// tangent `t_A`: `−ṡ_A` and `−σ ṡ_B` (the contact point moves along each curve at its
    /// sliding rate relative to that body), so that their mean is the entrainment and their
    /// difference the sliding
    pub speed: [f64; 2],
}

/// A simulated run: a sample at the start and after every output step, and the events between.
#[derive(Debug, Clone, PartialEq)]
pub struct SystemRun {
    /// the samples, the first at the start
    pub samples: Vec<SystemSample>,
    /// every lift-off and impact, in order
    pub events: Vec<ContactEvent>,
}

/// A simulation of a [`crate::system::System`] (see the module docs).
#[derive(Debug, Clone)]
pub struct SystemSimulation<'a> {
    /// the system: borrowed from the caller, or owned (a preset built for the run)
    sys: std::borrow::Cow<'a, crate::system::System>,
    model: Model,
    opts: SystemDynamicsOptions,
    /// the model's constraint index of contact 0 (joints, then drivers, then contacts)
    first_contact: usize,
    size: f64,
    /// each contact's sense: +1 where its gap (along curve A's left normal, or B's where A is
    /// a point) is positive apart — the curve runs with its material on its left — and −1
    /// where that curve runs the other way round (a cam synthesised clockwise)
    sense: Vec<f64>,
    /// each contact's two curves' orientations (+1 material on the left), for their curvatures
    /// convex positive
    turning: Vec<[f64; 2]>,
    /// each body's centre of mass in its frame
    centres: Vec<Vec2>,
    /// whether any centre is away from its frame's origin
    offset: bool,
    /// a speed of the system (its drivers' rates times the size, or `√(g size)`), for the
    /// rebound that re-engages a contact
    speed_scale: f64,
    t: f64,
    q: Vec<f64>,
    qd: Vec<f64>,
    in_contact: Vec<bool>,
    pairings: Vec<Option<Pairing>>,
    /// the work integrated with the motion, channel by channel ([`balance`])
    work: Vec<f64>,
    /// each lash adjuster's chamber pressure, gauge, Pa ([`adjusters`])
    z: Vec<f64>,
    /// the energy the impacts and the projections changed, and `T + V` at the start
    impacts: f64,
    projections: f64,
    initial_energy: f64,
    pending: Vec<ContactEvent>,
    /// the last evaluation of the equations of motion: a step's end is evaluated by its force
    /// check, then by the sample, then by the next step's first stage — once
    pub(super) last: std::cell::RefCell<Option<eval::Evaluated>>,
    /// buffers an evaluation reuses
    pub(super) scratch: std::cell::RefCell<eval::Scratch>,
    /// the integrator's stages, interpolant and step control
    pub(super) integrator: integrate::Integrator,
    /// a projection's pairings
    pub(super) spare_pairings: Vec<Option<Pairing>>,
    /// buffers of [`SystemSimulation::motion`]
    sampled: std::cell::RefCell<(Vec<Option<Pairing>>, eval::Accel)>,
    /// the fastest rate and its element, found once ([`SystemSimulation::fastest_rate`]: the
    /// masses and elements do not change)
    fastest: std::cell::OnceCell<rates::Fastest>,
    /// whether [`crate::dynamics::Scheme::Auto`] takes the implicit method, decided once
    auto_implicit: std::cell::OnceCell<bool>,
    /// the inverse of the mass matrix's diagonal, one per coordinate
    pub(super) inv_mass: Vec<f64>,
    /// each coordinate's weight in the rows' geometry: 1 a length's, `1/size²` an angle's
    pub(super) geometry: Vec<f64>,
    /// what the start changed
    start_report: StartReport,
}

/// Most events in one call of [`SystemSimulation::advance`].
const MAX_EVENTS: usize = 64;

/// The radius of gyration a point mass (a body of inertia 0) is given, times the system's size.
pub const POINT_MASS_RADIUS: f64 = 1e-6;

/// A contact whose curves are this close (times the size) at the starting poses starts in touch
/// (the positions are then assembled onto it).
const STARTS_IN_TOUCH: f64 = 1e-3;

impl<'a> SystemSimulation<'a> {
    /// Starts `sys` at time 0 from its bodies' poses (assembled onto the joints and drivers and
    /// every contact whose curves are within 1e-3 of the size there, or that
    /// [`SystemDynamicsOptions::start_touching`] marks), at rest but for the drivers' rates and
    /// the [`SystemDynamicsOptions::initial_rates`] (made consistent with the rows); what the
    /// assembly and the rates' projection changed is in [`SystemSimulation::start_report`]. A
    /// contact whose force would be tensile at the start, or that the rates asked part, lifts off
    /// at once (the first [`SystemSimulation::advance`] reports it).
    pub fn new(
        sys: &'a crate::system::System,
        opts: SystemDynamicsOptions,
    ) -> Result<Self, DynamicsError> {
        Self::start(std::borrow::Cow::Borrowed(sys), opts)
    }

    /// As [`SystemSimulation::new`], owning the system (a preset built for the run).
    pub(crate) fn owning(
        sys: crate::system::System,
        opts: SystemDynamicsOptions,
    ) -> Result<SystemSimulation<'static>, DynamicsError> {
        SystemSimulation::start(std::borrow::Cow::Owned(sys), opts)
    }

    fn start(
        sys: std::borrow::Cow<'a, crate::system::System>,
        mut opts: SystemDynamicsOptions,
    ) -> Result<Self, DynamicsError> {
        sys.check_elements()?;
        if let Some((which, value)) = opts.tolerances.out_of_range() {
            return Err(DynamicsError::Tolerance { which, value });
        }
        // the projection after every step holds the rows (see `SystemDynamicsOptions::al`)
        (opts.al.xi, opts.al.omega) = (0.0, 0.0);
        let u = opts.metres_per_unit;
        if !(u > 0.0 && u.is_finite()) {
            return Err(DynamicsError::Element {
                element: "the system".into(),
                key: "length unit (m)",
                value: u,
                reason: "must be positive",
            });
        }
        for (k, &e) in opts.restitution.iter().enumerate() {
            if !(0.0..=1.0).contains(&e) {
                return Err(DynamicsError::Element {
                    element: format!(
                        "contact {:?}",
                        sys.contacts().get(k).map_or("?", |c| c.name.as_str())
                    ),
                    key: "restitution",
                    value: e,
                    reason: "must be from 0 to 1",
                });
            }
        }
        // a table of the crank angle needs the first driver to turn an angle
        if let Some(g) = sys.table_forces().first() {
            let angle = sys
                .drivers()
                .first()
                .is_some_and(|d| d.coordinate == crate::system::Coordinate::Angle);
            if !angle {
                return Err(DynamicsError::Element {
                    element: format!("gas force {:?}", g.name),
                    key: "table",
                    value: f64::NAN,
                    reason: "is of the crank angle: the system's first driver must turn an angle",
                });
            }
        }
        // the system's size, with its bodies' centres of mass (a wheel pinned at its frame's
        // origin has no other length), a unit where it has none: the scale of its tolerances
        let size = sys
            .bodies()
            .iter()
            .map(|b| b.pose.origin.coords.norm() + b.centre_of_mass.coords.norm())
            .fold(sys.size(), f64::max);
        let size = if size > 1e-300 { size } else { 1.0 };
        let mut bodies = Vec::with_capacity(sys.bodies().len());
        for b in sys.bodies() {
            for (key, v, point) in [("mass", b.mass, false), ("inertia", b.inertia, true)] {
                if !(v > 0.0 && v.is_finite() || point && v == 0.0) {
                    return Err(DynamicsError::Element {
                        element: format!("body {:?}", b.name),
                        key,
                        value: v,
                        reason: if point {
                            "must be positive, or 0 for a point mass, for a simulation"
                        } else {
                            "must be positive for a simulation"
                        },
                    });
                }
            }
            // a point mass turns as a ring of [`POINT_MASS_RADIUS`] times the size: nothing
            // that acts at its centre turns it, and where a joint does, its inertia is 1e-12 of
            // the system's in its metric
            let inertia = if b.inertia == 0.0 {
                b.mass * (POINT_MASS_RADIUS * size * u).powi(2)
            } else {
                b.inertia
            };
            // kg → N·s²/L, kg·m² → N·L·s²
            bodies.push(RigidBody {
                mass: b.mass * u,
                inertia: inertia / u,
            });
        }
        let mut constraints: Vec<Constraint> = sys
            .joints()
            .iter()
            .map(|j| Constraint::Joint(j.kind))
            .collect();
        constraints.extend(sys.drivers().iter().map(|d| Constraint::Driver {
            body: d.body.0,
            coordinate: d.coordinate,
            law: d.law,
        }));
        let first_contact = constraints.len();
        constraints.extend(sys.contacts().iter().map(|c| Constraint::Contact {
            a: c.a.0,
            curve_a: c.curve_a.clone(),
            b: c.b.0,
            curve_b: c.curve_b.clone(),
        }));
        let gravity = opts.gravity / u;
        let mut forces: Vec<Load> = sys.forces().iter().map(|f| Load::Element(f.kind)).collect();
        if gravity != Vec2::zeros() {
            forces.push(Load::Gravity(gravity));
        }
        let model = Model {
            bodies,
            constraints,
            forces,
            search: SearchOptions::for_length_scale(size),
        };
        let rates = sys
            .drivers()
            .iter()
            .map(|d| {
                let r = d.law.at(0.0)[1].abs();
                match d.coordinate {
                    crate::system::Coordinate::Angle => r * size,
                    _ => r,
                }
            })
            .fold(0.0f64, f64::max);
        let speed_scale = rates.max((gravity.norm() * size).sqrt());
        let q: Vec<f64> = sys
            .bodies()
            .iter()
            .flat_map(|b| [b.pose.origin.x, b.pose.origin.y, b.pose.angle])
            .collect();
        let centres: Vec<Vec2> = sys
            .bodies()
            .iter()
            .map(|b| b.centre_of_mass.coords)
            .collect();
        for (b, c) in sys.bodies().iter().zip(&centres) {
            if !(c.x.is_finite() && c.y.is_finite()) {
                return Err(DynamicsError::Element {
                    element: format!("body {:?}", b.name),
                    key: "centre_of_mass",
                    value: if c.x.is_finite() { c.y } else { c.x },
                    reason: "must be finite",
                });
            }
        }
        let offset = centres.iter().any(|c| *c != Vec2::zeros());
        let nc = sys.contacts().len();
        let sense = sys
            .contacts()
            .iter()
            .map(|c| {
                if matches!(c.curve_a.domain(), crate::curve::Domain::Point) {
                    orientation(c.curve_b.as_ref())
                } else {
                    orientation(c.curve_a.as_ref())
                }
            })
            .collect();
        let turning = sys
            .contacts()
            .iter()
            .map(|c| {
                [
                    orientation(c.curve_a.as_ref()),
                    orientation(c.curve_b.as_ref()),
                ]
            })
            .collect();
        let z = sys
            .lash_adjusters()
            .iter()
            .map(|h| h.adjuster.initial_pressure)
            .collect();
        let mut sim = Self {
            sys,
            model,
            opts,
            first_contact,
            size,
            sense,
            turning,
            centres,
            offset,
            speed_scale,
            t: 0.0,
            qd: vec![0.0; q.len()],
            q,
            in_contact: vec![false; nc],
            pairings: vec![None; first_contact + nc],
            work: Vec::new(),
            z,
            impacts: 0.0,
            projections: 0.0,
            initial_energy: 0.0,
            pending: Vec::new(),
            last: std::cell::RefCell::new(None),
            scratch: Default::default(),
            integrator: Default::default(),
            spare_pairings: Vec::new(),
            sampled: Default::default(),
            fastest: Default::default(),
            auto_implicit: Default::default(),
            inv_mass: Vec::new(),
            geometry: Vec::new(),
            start_report: StartReport::default(),
        };
        if !(sim.speed_scale > 0.0) {
            // nothing driven and no gravity: the springs' fastest rate (a vibration's: a
            // damper's decay sets no speed), or the dampers', or a size a second
            let f = sim.fastest.get_or_init(|| sim.find_fastest_rate());
            let rate = if f.vibration > 0.0 {
                f.vibration
            } else {
                f.rate
            };
            sim.speed_scale = size * rate.max(1.0);
        }
        sim.geometry = (0..sim.model.bodies.len())
            .flat_map(|_| [1.0, 1.0, 1.0 / (size * size)])
            .collect();
        sim.inv_mass = sim
            .model
            .bodies
            .iter()
            .flat_map(|b| [1.0 / b.mass, 1.0 / b.mass, 1.0 / b.inertia])
            .collect();
        // the coordinates integrated are the centres of mass'
        let mut q = std::mem::take(&mut sim.q);
        sim.centres_at(&mut q);
        sim.q = q;
        // each contact's nearest (or deepest) pair of points, globally
        for k in 0..nc {
            let c = &sim.sys.contacts()[k];
            let (sa, sb) = (sim.state(c.a.0), sim.state(c.b.0));
            let found = contact::find_contact(
                &Surface::new(c.curve_a.as_ref(), &sa),
                &Surface::new(c.curve_b.as_ref(), &sb),
                &sim.model.search,
            )
            .map_err(|e| SystemError::Contact {
                time: 0.0,
                contact: c.name.clone(),
                reason: e.to_string(),
            })?;
            let (Proximity::Apart(p) | Proximity::Touching(p) | Proximity::Overlapping(p)) = found;
            sim.in_contact[k] = match sim.opts.start_touching.get(k).copied().flatten() {
                Some(marked) => marked,
                None => sim.sense[k] * p.gap <= STARTS_IN_TOUCH * size,
            };
            sim.pairings[first_contact + k] = Some(p);
        }
        let before = sim.frame_coordinates();
        sim.project().map_err(|e| match e {
            DynamicsError::Singular { .. } => DynamicsError::System(SystemError::NoAssembly {
                time: 0.0,
                reason: "the starting poses cannot be assembled onto the joints, drivers and contacts in touch (their rows are dependent)",
                residual: f64::NAN,
                row: String::new(),
            }),
            e => e,
        })?;
        let residual = sim.constraint_residual()?;
        if residual > 1e-9 * size {
            return Err(SystemError::NoAssembly {
                time: 0.0,
                reason: "the starting poses cannot be assembled onto the joints, drivers and contacts in touch",
                residual,
                row: String::new(),
            }
            .into());
        }
        sim.note_moves(&before);
        sim.start_rates()?;
        sim.work = vec![0.0; sim.channels()];
        sim.initial_energy = sim.energy();
        Ok(sim)
    }

    /// Body `i`'s state now (the ground's for [`super::GROUND`]).
    pub(crate) fn state(&self, i: usize) -> crate::body::BodyState {
        self.frame_state(&self.q, &self.qd, i)
    }

    /// The rows that hold in the modes `in_contact`: joints and drivers always.
    fn active(&self, in_contact: &[bool]) -> Vec<bool> {
        let mut a = Vec::new();
        self.active_into(in_contact, &mut a);
        a
    }

    /// [`SystemSimulation::active`] written into `a` (its buffer reused).
    fn active_into(&self, in_contact: &[bool], a: &mut Vec<bool>) {
        a.clear();
        a.resize(self.first_contact, true);
        a.extend_from_slice(in_contact);
    }

    /// The largest `|Φ|` of the active rows now, L (angles' rows in rad): the drift.
    pub fn constraint_residual(&self) -> Result<f64, DynamicsError> {
        let mut p = self.pairings.clone();
        let rows = self.dense(&self.q, &self.qd, &self.in_contact, &mut p)?;
        Ok(rows.phi.iter().fold(0.0f64, |m, x| m.max(x.abs())))
    }

    /// The current time, s.
    pub fn time(&self) -> f64 {
        self.t
    }

    /// The system simulated.
    pub fn system(&self) -> &crate::system::System {
        &self.sys
    }

    /// The sample at the current state.
    pub fn sample(&self) -> Result<SystemSample, DynamicsError> {
        let mut p = self.pairings.clone();
        let eval::Accel {
            mut qdd,
            forces: contact_forces,
            efforts: driver_efforts,
            ..
        } = self.accel(self.t, &self.q, &self.qd, &self.z, &self.in_contact, &mut p)?;
        self.frame_accelerations(&self.q, &self.qd, &mut qdd);
        let (q, qd) = self.frames(&self.q, &self.qd);
        let mut gaps = vec![0.0; self.in_contact.len()];
        for (k, g) in gaps.iter_mut().enumerate() {
            if !self.in_contact[k] {
                *g = self.gap(&self.q, &self.qd, k, &mut p)?;
            }
        }
        let hertz_pa = (0..self.in_contact.len())
            .map(|k| {
                let h = self.opts.hertz.get(k).copied().flatten()?;
                if !self.in_contact[k] {
                    return Some(0.0);
                }
                let c = &self.sys.contacts()[k];
                let pairing = p[self.first_contact + k]?;
                // each curve's curvature at the contact, convex positive, 1/m
                let u = self.opts.metres_per_unit;
                let bend = |curve: &dyn crate::curve::Curve, at: f64, turn: f64| -> Option<f64> {
                    if matches!(curve.domain(), crate::curve::Domain::Point) {
                        return None;
                    }
                    Some(turn * curve.eval(at).curvature() / u)
                };
                let [ta, tb] = self.turning[k];
                let (ka, kb) = (
                    bend(c.curve_a.as_ref(), pairing.u_a, ta)?,
                    bend(c.curve_b.as_ref(), pairing.u_b, tb)?,
                );
                let radius = |k: f64| if k == 0.0 { f64::INFINITY } else { 1.0 / k };
                super::hertz_line_pressure(
                    contact_forces[k].max(0.0),
                    h.width * u,
                    radius(ka),
                    radius(kb),
                    h.e_star,
                )
            })
            .collect();
        let surfaces = (0..self.in_contact.len())
            .map(|k| self.surface(k, p[self.first_contact + k].as_ref()))
            .collect();
        Ok(SystemSample {
            time: self.t,
            q: q.into_owned(),
            qd: qd.into_owned(),
            qdd,
            contact_forces,
            gaps,
            in_contact: self.in_contact.clone(),
            energy: self.energy(),
            balance: self.balance(),
            driver_work: self.work[balance::DRIVERS] + self.work[balance::APPLIED],
            driver_efforts,
            hertz_pa,
            pairings: p[self.first_contact..].to_vec(),
            surfaces,
            adjusters: self.adjuster_samples(),
        })
    }

    /// `read` of the frames' coordinates, rates and the evaluation now (their accelerations,
    /// each contact's compressive force and each driver's effort): the part of
    /// [`SystemSample`] a preset reads back, without the gaps, energies and Hertz pressures a
    /// sample adds, and without a copy. The evaluation is the one that ended the last step.
    pub(crate) fn motion<R>(
        &self,
        read: impl FnOnce(&[f64], &[f64], &eval::Accel) -> R,
    ) -> Result<R, DynamicsError> {
        let mut kept = self.sampled.take();
        let (p, a) = &mut kept;
        p.clone_from(&self.pairings);
        self.accel_into(self.t, &self.q, &self.qd, &self.z, &self.in_contact, p, a)?;
        self.frame_accelerations(&self.q, &self.qd, &mut a.qdd);
        let (q, qd) = self.frames(&self.q, &self.qd);
        let r = read(&q, &qd, a);
        self.sampled.replace(kept);
        Ok(r)
    }

    /// Whether contact `k` is closed now.
    pub(crate) fn in_contact(&self, k: usize) -> bool {
        self.in_contact.get(k).copied().unwrap_or(false)
    }

    /// The drivers' work since the start, N·L.
    pub(crate) fn driver_work(&self) -> f64 {
        self.work[balance::DRIVERS] + self.work[balance::APPLIED]
    }

    /// Contact `k`'s curves at its contact `pairing` now, where it is closed and neither curve
    /// is a point (a point has no radius, and no line contact).
    fn surface(&self, k: usize, pairing: Option<&Pairing>) -> Option<ContactSurface> {
        let pairing = pairing.filter(|_| self.in_contact[k])?;
        let c = &self.sys.contacts()[k];
        let point =
            |curve: &dyn crate::curve::Curve| matches!(curve.domain(), crate::curve::Domain::Point);
        if point(c.curve_a.as_ref()) || point(c.curve_b.as_ref()) {
            return None;
        }
        let (sa, sb) = (self.state(c.a.0), self.state(c.b.0));
        let (fa, fb) = (
            Surface::new(c.curve_a.as_ref(), &sa),
            Surface::new(c.curve_b.as_ref(), &sb),
        );
        let kin = contact::ContactKinematics::new(&fa, &fb, pairing, contact::CONFORMAL_TOLERANCE)
            .ok()?;
        let u = self.opts.metres_per_unit;
        let [ta, tb] = self.turning[k];
        let radius = |curve: &dyn crate::curve::Curve, at: f64, turn: f64| {
            let k = turn * curve.eval(at).curvature() / u;
            if k == 0.0 {
                f64::INFINITY
            } else {
                1.0 / k
            }
        };
        Some(ContactSurface {
            radius: [
                radius(c.curve_a.as_ref(), pairing.u_a, ta),
                radius(c.curve_b.as_ref(), pairing.u_b, tb),
            ],
            speed: [-kin.sliding_rate_a * u, -kin.sigma * kin.sliding_rate_b * u],
        })
    }
}

/// +1 for a curve that runs with its material on its left (a closed curve counter-clockwise:
/// positive area by the shoelace formula over 512 points), −1 for a closed curve run clockwise;
/// +1 for an open curve or a point (the convention).
fn orientation(curve: &dyn crate::curve::Curve) -> f64 {
    match curve.domain() {
        crate::curve::Domain::Periodic { period } => {
            let n = 512;
            let p = |k: usize| curve.position(period * k as f64 / n as f64);
            let area2: f64 = (0..n)
                .map(|k| crate::geometry::cross(p(k).coords, p((k + 1) % n).coords))
                .sum();
            if area2 >= 0.0 {
                1.0
            } else {
                -1.0
            }
        }
        _ => 1.0,
    }
}
