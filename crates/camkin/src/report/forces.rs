//! The force report of a cam mechanism over a revolution under permanent contact: the contact
//! force and camshaft torque with their extremes, the power balance, the jump speed and the
//! spring that keeps the follower on up to a target speed, the Hertz stress at each contact, a
//! form-closed follower's load reversals and play, the force–speed curve, and the verdict of each
//! check. One computation for every front end (the command's text and files, Python, the
//! studio); the formulas are [`crate::dynamics::Forces`]'s.

use super::spring::{spring_sizing, SpringSizing};
use super::{Extreme, ForceField, Materials, ReportError};
use crate::cam::Mechanism;
use crate::dynamics::{hertz_line_pressure, FollowerDynamics, ForceState, Forces};
use crate::extreme::best_refined;
use crate::spec::LengthUnit;
use crate::table::Cell;
use crate::work::Work;
use std::f64::consts::TAU;

/// What a force report is asked for.
#[derive(Debug, Clone, PartialEq)]
pub struct ForceRequest {
    /// cam-angle step, degrees (the revolution is cut into `round(360/step)` equal steps)
    pub step_deg: f64,
    /// the contact force that must remain, N
    pub margin: f64,
    /// the speed up to which the follower must stay on the cam, rpm (`None`: the file's)
    pub target_rpm: Option<f64>,
    /// the contact's face width, in the mechanism file's length unit (`None`: no Hertz stress)
    pub face_width: Option<f64>,
    /// the cam's and the follower's materials (for the Hertz stress)
    pub materials: Materials,
    /// the allowable contact stress, MPa (a check when given)
    pub allowable_mpa: Option<f64>,
    /// the mechanism file's length unit (the mechanism itself is in metres)
    pub unit: LengthUnit,
    /// the force–speed curve (151 speeds, each over every angle): a page that evaluates the
    /// coefficients at its own speed leaves it out
    pub force_speed: bool,
    /// the lubrication of the contacts (needs the face width and the materials)
    pub lubrication: Option<super::LubricationRequest>,
}

impl Default for ForceRequest {
    fn default() -> Self {
        Self {
            step_deg: 0.5,
            margin: 0.0,
            target_rpm: None,
            face_width: None,
            materials: Materials::default(),
            allowable_mpa: None,
            unit: LengthUnit::M,
            force_speed: true,
            lubrication: None,
        }
    }
}

/// The jump speed: the lowest constant speed at which the contact force reaches the margin
/// somewhere (a form-closed follower: from which its second curve takes load).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Jump {
    /// the speed, rad/s (∞: never; 0: at rest already)
    pub speed: f64,
    /// the cam angle where it happens first, rad
    pub cam_angle: f64,
    /// the index of that angle among the report's angles
    pub index: usize,
}

/// A form-closed follower: the load on each of its curves, where it passes between them, and
/// the second curve's play.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FormClosed {
    /// the largest force on the follower's own curve
    pub own_peak: Extreme,
    /// the largest force on the second curve
    pub second_peak: Extreme,
    /// the cam angles (rad) where the load passes to the other curve (`R` changes sign, linear
    /// between the samples)
    pub reversals: Vec<f64>,
    /// with no reversal: the second curve carries at every angle (else the own curve does)
    pub second_carries_throughout: bool,
    /// the second curve's smallest and largest play over the revolution (m, or rad for an arm)
    pub play: (f64, f64),
    /// below this the play is none (1e-6 of the cam's size, or of a radian)
    pub play_tolerance: f64,
}

/// The Hertz stress at one of the contacts (the follower's own curve, or the second curve).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct HertzSide {
    /// 0: the follower's own curve; 1: the second curve of a form-closed follower
    pub side: usize,
    /// the largest stress, Pa, where it is, and the cam's radius of curvature there (m)
    pub worst: Option<(f64, f64, f64)>,
    /// angles where a force is carried but the curvatures do not close (conformal contact)
    pub conformal: usize,
    /// angles where a force is carried on a corner of a curve (a point contact)
    pub on_corner: usize,
}

/// The Hertz stress over the revolution.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct HertzReport {
    /// face width, m
    pub face_width: f64,
    /// the materials
    pub materials: Materials,
    /// their effective modulus `E*`, Pa
    pub effective_modulus: f64,
    /// per contact
    pub sides: Vec<HertzSide>,
    /// the largest stress at any contact, MPa
    pub worst_mpa: f64,
    /// the allowable stress, MPa, when given
    pub allowable_mpa: Option<f64>,
}

/// A check of the force report that failed.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(tag = "check", rename_all = "snake_case")]
#[non_exhaustive]
pub enum ForceCheck {
    /// the contact force falls below the margin at the file's speed
    BelowMargin {
        /// the smallest contact force, N, and where
        min: Extreme,
        /// the margin, N
        margin: f64,
    },
    /// the jump speed is below the target speed
    LeavesBelowTarget {
        /// the jump speed, rad/s
        jump: f64,
        /// the target speed, rad/s
        target: f64,
    },
    /// the contact stress exceeds the allowable
    StressOverAllowable {
        /// the largest stress, MPa
        worst_mpa: f64,
        /// the allowable, MPa
        allowable_mpa: f64,
    },
}

/// Forces over a revolution: the extremes, checks and curves of the module's notes.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ForceReport {
    /// the cam's speed, rad/s
    pub speed: f64,
    /// the file gives an angular acceleration (the speeds below assume a constant speed)
    pub accelerating: bool,
    /// the follower swings on an arm (its spring is a torque)
    pub oscillating: bool,
    /// the follower is form-closed
    pub closed: bool,
    /// the margin, N
    pub margin: f64,
    /// the target speed, rad/s
    pub target: f64,
    /// the forces at each angle (SI)
    pub states: Vec<ForceState>,
    /// per angle `[c2, c1, c0]` with `F |J| = c2 ω² + c1 ω + c0` at any constant speed ω
    /// ([`Forces::force_coefficients`]): the contact force at any speed without asking again
    pub coefficients: Vec<[f64; 3]>,
    /// the Hertz stress at each angle, MPa, on the own curve and the second (when asked for)
    pub stress_mpa: Vec<[Option<f64>; 2]>,
    /// the contact force's smallest and largest value (a form-closed follower's own curve)
    pub contact_force: (Extreme, Extreme),
    /// the camshaft torque's smallest and largest value, N·m
    pub camshaft_torque: (Extreme, Extreme),
    /// its root mean square over the revolution, N·m
    pub torque_rms: f64,
    /// the largest power into the follower, W
    pub peak_power: f64,
    /// the largest difference of torque × speed and the power into the follower, relative to
    /// the peak power (absolute where that is 0): the check of the torque
    pub power_balance: f64,
    /// the jump speed
    pub jump: Jump,
    /// a spring-held follower's spring sizing
    pub spring: Option<SpringSizing>,
    /// a form-closed follower's loads on each curve
    pub form_closed: Option<FormClosed>,
    /// the Hertz stress, when a face width was given
    pub hertz: Option<HertzReport>,
    /// the lubrication, when asked for
    pub lubrication: Option<super::LubricationReport>,
    /// the checks that failed
    pub failures: Vec<ForceCheck>,
    /// the force–speed curve: speeds (rad/s) and per speed the smallest contact force (a
    /// form-closed follower: the largest on each curve), N; empty when not asked for
    pub force_speed: Vec<(f64, [f64; 2])>,
}

/// The number of angles of a revolution at `step_deg`.
fn angles(step_deg: f64) -> usize {
    (360.0 / step_deg).round() as usize
}

/// The checks every force report takes, a cam's or a system's: the smallest contact force
/// allowed (`margin`, N, finite and ≥ 0) and the allowable Hertz pressure (MPa, positive).
pub fn check_limits(margin: f64, allowable_mpa: Option<f64>) -> Result<(), ReportError> {
    if !(margin.is_finite() && margin >= 0.0) {
        return Err(ReportError::Invalid {
            field: ForceField::Margin,
            value: margin,
            unit: "N",
            reason: "must be finite and ≥ 0",
        });
    }
    if let Some(a) = allowable_mpa {
        if !(a.is_finite() && a > 0.0) {
            return Err(ReportError::Invalid {
                field: ForceField::Allowable,
                value: a,
                unit: "MPa",
                reason: "must be positive",
            });
        }
    }
    Ok(())
}

impl ForceRequest {
    /// Checks the request's values against `mech` (in metres), naming the field.
    pub fn validate(&self, mech: &Mechanism) -> Result<(), ReportError> {
        let bad = |field, value, unit, reason| ReportError::Invalid {
            field,
            value,
            unit,
            reason,
        };
        // the revolution cut into equal steps, as every front end's step is
        let n = 360.0 / self.step_deg;
        if !(self.step_deg.is_finite() && self.step_deg > 0.0 && self.step_deg <= 90.0)
            || (n - n.round()).abs() > 1e-9 * n
        {
            return Err(bad(
                ForceField::Step,
                self.step_deg,
                "°",
                "must be in (0°, 90°] and divide 360°",
            ));
        }
        check_limits(self.margin, self.allowable_mpa)?;
        if let Some(r) = self.target_rpm {
            if !(r.is_finite() && r > 0.0 && r <= 1e7) {
                return Err(bad(ForceField::TargetRpm, r, "rpm", "must be in (0, 1e7]"));
            }
        }
        let unit = self.unit.name();
        if let Some(w) = self.face_width {
            if !(w.is_finite() && w > 0.0) {
                return Err(bad(ForceField::FaceWidth, w, unit, "must be positive"));
            }
            // a face a thousandth of the cam or a thousand cams wide is a typing slip (a width in
            // metres in a millimetre file, or the other way round)
            if !plausible_face_width(w * self.unit.metres(), mech.size()) {
                return Err(bad(
                    ForceField::FaceWidth,
                    w,
                    unit,
                    "is not plausible for this cam: a face width from 1e-3 to 1e3 times the cam's size is taken (check the file's length_unit)",
                ));
            }
            if mech.follower_curve().is_point() {
                return Err(ReportError::NotApplicable {
                    field: ForceField::FaceWidth,
                    reason: "a knife-edge follower has no line contact (its edge is a point in the plane): no Hertz stress",
                });
            }
        }
        if let Some(l) = &self.lubrication {
            l.validate()?;
            if self.face_width.is_none() {
                return Err(ReportError::NotApplicable {
                    field: ForceField::FaceWidth,
                    reason: "lubrication needs the contact's face width (the film and the flash temperature depend on the load per unit width)",
                });
            }
        }
        if mech.is_conjugate() && (self.margin != 0.0 || self.target_rpm.is_some()) {
            return Err(ReportError::NotApplicable {
                field: if self.margin != 0.0 {
                    ForceField::Margin
                } else {
                    ForceField::TargetRpm
                },
                reason: "the follower is form-closed (follower.conjugate): its second curve takes the load where its own would lift off, so it has no jump speed and no spring to size",
            });
        }
        Ok(())
    }

    /// The work of the report on `mech`: a warm sweep per curve over the revolution (and one for
    /// a form-closed follower's play), and the force–speed curve.
    pub fn work(&self, mech: &Mechanism) -> Work {
        let n = angles(self.step_deg.clamp(1e-12, 360.0));
        let sweeps = if mech.is_conjugate() { 3 } else { 1 };
        let mut work = Work::sweep(mech, n * 2 + 720, sweeps);
        // a force state costs about three kinematic steps more than the sweep's two (its
        // dynamics, the force–speed row, the extremes' refinement): the paper's cam took
        // 5.7 µs an angle against the sweep's 2 µs estimate; and each angle holds its state,
        // its lubrication and their table rows (2.4 GB for 1e7 angles, measured)
        work.seconds *= 3.0;
        work.what =
            format!("{n} cam angles of forces on this profile, with the follower's travel,");
        let lubricated = self
            .lubrication
            .as_ref()
            .map_or(0, |_| std::mem::size_of::<super::LubricationPoint>());
        let per_angle = std::mem::size_of::<ForceState>() + lubricated + 64;
        work.with_bytes((n * sweeps) as f64 * per_angle as f64)
    }
}

impl ForceReport {
    /// The report of `mech` (lengths in metres) with `params` as `req` asks. The request is
    /// validated first; refusing work that is too large is the caller's ([`ForceRequest::work`]).
    pub fn new(
        mech: &Mechanism,
        params: FollowerDynamics,
        req: &ForceRequest,
    ) -> Result<Self, ReportError> {
        req.validate(mech)?;
        let n = angles(req.step_deg);
        let f = Forces::new(mech, params).map_err(ReportError::Dynamics)?;
        // the angles of the table's grid, in radians
        let grid = crate::table::AngleGrid::new(0.0, 360.0 / n as f64);
        let thetas: Vec<f64> = (0..n).map(|k| grid.at(k).to_radians()).collect();
        let mut sweep = f.sweep();
        let states: Vec<ForceState> = thetas
            .iter()
            .map(|&t| sweep.step(t))
            .collect::<Result<_, _>>()
            .map_err(ReportError::Kinematics)?;
        let closed = mech.is_conjugate();
        let speed = mech.cam().speed();
        let target = req.target_rpm.map_or(speed, |r| r * TAU / 60.0);
        // an extreme where it is: the best sample refined between its neighbours on the exact
        // state (the grid alone misses a peak between samples)
        let at = |t: f64| f.at(t).ok();
        let refined = |g: &dyn Fn(&ForceState) -> f64, sign: f64| {
            let values: Vec<Option<f64>> = states.iter().map(|s| Some(g(s))).collect();
            let (t, v) = best_refined(&thetas, &values, sign, Some(TAU), |t| at(t).map(|s| g(&s)))
                .unwrap_or((states[0].cam_angle, g(&states[0])));
            Extreme {
                value: v,
                cam_angle: t.rem_euclid(TAU),
            }
        };
        let extreme = |g: &dyn Fn(&ForceState) -> f64| (refined(g, -1.0), refined(g, 1.0));
        let contact_force = extreme(&|s| s.contact_force);
        let camshaft_torque = extreme(&|s| s.camshaft_torque);
        let torque_rms = (states
            .iter()
            .map(|s| s.camshaft_torque.powi(2))
            .sum::<f64>()
            / n as f64)
            .sqrt();
        let peak_power = states
            .iter()
            .map(|s| s.follower_power.abs())
            .fold(0.0, f64::max);
        let dmax = states
            .iter()
            .map(|s| (s.camshaft_torque * speed - s.follower_power).abs())
            .fold(0.0, f64::max);
        let power_balance = if peak_power > 0.0 {
            dmax / peak_power
        } else {
            dmax
        };
        let leave = |s: &ForceState| f.leave_speed(s, req.margin);
        let lowest = refined(&leave, -1.0);
        let jump = Jump {
            speed: lowest.value,
            cam_angle: lowest.cam_angle,
            // the sample nearest the refined angle
            index: ((lowest.cam_angle / TAU * n as f64).round() as usize) % n,
        };
        let mut failures = Vec::new();
        let (spring, form_closed) = if closed {
            (
                None,
                Some(form_closed_loads(mech, &states, &thetas, &|g| {
                    refined(g, 1.0)
                })?),
            )
        } else {
            let min = contact_force.0;
            if min.value < req.margin {
                failures.push(ForceCheck::BelowMargin {
                    min,
                    margin: req.margin,
                });
            }
            if jump.speed < target {
                failures.push(ForceCheck::LeavesBelowTarget {
                    jump: jump.speed,
                    target,
                });
            }
            (
                Some(spring_sizing(
                    &f, &states, &thetas, &params, req.margin, target,
                )),
                None,
            )
        };
        let (stress_mpa, hertz) = hertz(&states, &thetas, &at, req, closed);
        if let Some(h) = &hertz {
            if let Some(al) = h.allowable_mpa.filter(|&al| h.worst_mpa > al) {
                failures.push(ForceCheck::StressOverAllowable {
                    worst_mpa: h.worst_mpa,
                    allowable_mpa: al,
                });
            }
        }
        let lubrication = match (&req.lubrication, req.face_width) {
            (Some(l), Some(width)) => Some(super::LubricationReport::new(
                &f,
                &states,
                &thetas,
                width * req.unit.metres(),
                2.0 * req.materials.effective_modulus(),
                speed,
                l,
            )),
            _ => None,
        };
        let force_speed = if req.force_speed {
            force_speed(&f, &states, closed, target, jump.speed)
        } else {
            Vec::new()
        };
        let coefficients = states.iter().map(|s| f.force_coefficients(s)).collect();
        Ok(Self {
            speed,
            accelerating: mech.cam().angular_acceleration() != 0.0,
            oscillating: mech.follower().is_oscillating(),
            closed,
            margin: req.margin,
            target,
            states,
            coefficients,
            stress_mpa,
            contact_force,
            camshaft_torque,
            torque_rms,
            peak_power,
            power_balance,
            jump,
            spring,
            form_closed,
            hertz,
            lubrication,
            failures,
            force_speed,
        })
    }

    /// The units of the spring's force and stiffness and of the torque: `(N, N/m, N·m)`, or
    /// `(N·m, N·m/rad, N·m)` for an arm.
    pub fn units(&self) -> (&'static str, &'static str, &'static str) {
        if self.oscillating {
            ("N·m", "N·m/rad", "N·m")
        } else {
            ("N", "N/m", "N·m")
        }
    }

    /// The per-angle table (`forces.csv`): each column's name with its unit and its cell, written
    /// once.
    pub fn table(&self) -> (Vec<String>, Vec<Vec<Cell>>) {
        type Get = fn(&ForceState, &[Option<f64>; 2]) -> Option<f64>;
        let (fu, _, tu) = self.units();
        let mut columns: Vec<(String, Get)> = vec![
            ("angle_deg".into(), |s, _| Some(s.cam_angle.to_degrees())),
            ("contact_force_N".into(), |s, _| Some(s.contact_force)),
            (format!("spring_force_{}", fu.replace('·', "_")), |s, _| {
                Some(s.spring_force)
            }),
            (
                format!("camshaft_torque_{}", tu.replace('·', "_")),
                |s, _| Some(s.camshaft_torque),
            ),
            ("pressure_angle_deg".into(), |s, _| {
                Some(s.pressure_angle.to_degrees())
            }),
            ("contact_stress_MPa".into(), |_, p| p[0]),
        ];
        if self.closed {
            columns.extend::<[(String, Get); 3]>([
                ("second_contact_force_N".into(), |s, _| {
                    s.second.map(|c| c.contact_force)
                }),
                ("second_pressure_angle_deg".into(), |s, _| {
                    s.second.map(|c| c.pressure_angle.to_degrees())
                }),
                ("second_contact_stress_MPa".into(), |_, p| p[1]),
            ]);
        }
        // the angle column as the grid's decimals (7.5, not 7.499999999999999)
        let grid = crate::table::AngleGrid::new(0.0, 360.0 / self.states.len().max(1) as f64);
        let rows = self
            .states
            .iter()
            .zip(&self.stress_mpa)
            .enumerate()
            .map(|(k, (s, p))| {
                let mut row = vec![Cell::Num(Some(grid.at(k)))];
                row.extend(columns[1..].iter().map(|c| Cell::Num((c.1)(s, p))));
                row
            })
            .collect();
        (columns.into_iter().map(|c| c.0).collect(), rows)
    }

    /// The force–speed table (`force_speed.csv`).
    pub fn force_speed_table(&self) -> (Vec<String>, Vec<Vec<Cell>>) {
        let names: &[&str] = if self.closed {
            &["max_contact_force_N", "max_second_contact_force_N"]
        } else {
            &["min_contact_force_N"]
        };
        let curves = names.len();
        let mut columns = vec!["speed_rpm".to_string()];
        columns.extend(names.iter().map(|c| c.to_string()));
        let rows = self
            .force_speed
            .iter()
            .map(|(w, f)| {
                let mut row = vec![Cell::Num(Some(rpm(*w)))];
                row.extend(f[..curves].iter().map(|&x| Cell::Num(Some(x))));
                row
            })
            .collect();
        (columns, rows)
    }
}

/// A face width (m) taken as plausible for a mechanism of `size` (m): from 1e-3 to 1e3 times
/// it (a thousandth of the cam or a thousand cams wide is a typing slip: a width in metres in a
/// millimetre file, or the other way round).
pub fn plausible_face_width(width: f64, size: f64) -> bool {
    (1e-3..=1e3).contains(&(width / size))
}

/// rad/s → rpm
pub fn rpm(w: f64) -> f64 {
    w * 60.0 / TAU
}

/// The greatest of a quantity over the revolution, refined between the samples.
type Peak<'a> = dyn Fn(&dyn Fn(&ForceState) -> f64) -> Extreme + 'a;

fn form_closed_loads(
    mech: &Mechanism,
    states: &[ForceState],
    thetas: &[f64],
    peak: &Peak<'_>,
) -> Result<FormClosed, ReportError> {
    let (p1, p2) = (peak(&|s| s.contact_force), peak(&ForceState::second_force));
    // which curve carries, angle by angle (neither, or a force at rounding level of the peak:
    // the last one's), around the revolution
    let small = 1e-9 * p1.value.max(p2.value);
    let side = |s: &ForceState| {
        if s.contact_force > small {
            Some(false)
        } else if s.second_force() > small {
            Some(true)
        } else {
            None
        }
    };
    // `R = F₁ |J₁| − F₂ |J₂|`: where it changes sign, the load passes (linear between samples)
    let net = |s: &ForceState| {
        s.contact_force * s.lever - s.second.map_or(0.0, |c| c.contact_force * c.lever)
    };
    let mut last = states
        .iter()
        .rev()
        .find_map(|s| side(s).map(|d| (d, s.cam_angle - TAU, net(s))));
    let mut reversals = Vec::new();
    for s in states {
        if let Some(now) = side(s) {
            let r = net(s);
            if let Some((_, t0, r0)) = last.filter(|l| l.0 != now) {
                reversals.push(t0 + (s.cam_angle - t0) * r0 / (r0 - r));
            }
            last = Some((now, s.cam_angle, r));
        }
    }
    // the second curve's play over the same angles
    let (mut sweep, mut plays) = (mech.sweep(), mech.conjugate_sweep().expect("form-closed"));
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for &t in thetas {
        let play = plays
            .play(&sweep.step(t).map_err(ReportError::Play)?)
            .map_err(ReportError::Play)?;
        (lo, hi) = (lo.min(play), hi.max(play));
    }
    // as the design check of the play: 1e-6 of the cam's size (of 1 rad for an arm)
    let play_tolerance = if mech.follower().is_oscillating() {
        1e-6
    } else {
        1e-6 * mech.size()
    };
    Ok(FormClosed {
        own_peak: p1,
        second_peak: p2,
        reversals,
        second_carries_throughout: last.is_some_and(|l| l.0),
        play: (lo, hi),
        play_tolerance,
    })
}

/// The Hertz stress at each angle and contact, and its summary (none without a face width).
fn hertz(
    states: &[ForceState],
    thetas: &[f64],
    at: &dyn Fn(f64) -> Option<ForceState>,
    req: &ForceRequest,
    closed: bool,
) -> (Vec<[Option<f64>; 2]>, Option<HertzReport>) {
    let mut stress: Vec<[Option<f64>; 2]> = vec![[None; 2]; states.len()];
    let Some(width) = req.face_width else {
        return (stress, None);
    };
    let width = width * req.unit.metres();
    let es = req.materials.effective_modulus();
    let mut worst_mpa = 0.0f64;
    let mut sides = Vec::new();
    for side in if closed { 0..2 } else { 0..1 } {
        let contact = |s: &ForceState| match (side, s.second) {
            (0, _) => Some((s.contact_force, s.cam_radius, s.follower_radius)),
            (_, Some(c)) => Some((c.contact_force, c.cam_radius, c.follower_radius)),
            _ => None,
        };
        let mut h = HertzSide {
            side,
            worst: None,
            conformal: 0,
            on_corner: 0,
        };
        for (k, s) in states.iter().enumerate() {
            let Some((force, rc, rf)) = contact(s) else {
                continue;
            };
            let Some(rf) = rf else {
                if force > 0.0 {
                    h.on_corner += 1;
                }
                continue;
            };
            match hertz_line_pressure(force.max(0.0), width, rc, rf, es) {
                Some(p) => {
                    stress[k][side] = Some(p / 1e6);
                    if h.worst.is_none_or(|w| p > w.0) {
                        h.worst = Some((p, s.cam_angle, rc));
                    }
                }
                None if force > 0.0 => h.conformal += 1,
                None => {}
            }
        }
        // the worst where it is, refined between the samples
        let pressure = |s: &ForceState| {
            let (force, rc, rf) = contact(s)?;
            hertz_line_pressure(force.max(0.0), width, rc, rf?, es)
        };
        let values: Vec<Option<f64>> = states.iter().map(pressure).collect();
        if let Some((t, p)) = best_refined(thetas, &values, 1.0, Some(TAU), |t| {
            at(t).as_ref().and_then(pressure)
        }) {
            let t = t.rem_euclid(TAU);
            let rc = at(t).and_then(|s| contact(&s)).map_or(f64::NAN, |c| c.1);
            h.worst = Some((p, t, rc));
        }
        if let Some((p, ..)) = h.worst {
            worst_mpa = worst_mpa.max(p / 1e6);
        }
        sides.push(h);
    }
    (
        stress,
        Some(HertzReport {
            face_width: width,
            materials: req.materials.clone(),
            effective_modulus: es,
            sides,
            worst_mpa,
            allowable_mpa: req.allowable_mpa,
        }),
    )
}

/// The smallest contact force over the revolution against a constant speed from 0 to 1.5 times
/// the larger of the target and the jump speed, 151 speeds (a form-closed follower: the largest
/// force on each curve).
fn force_speed(
    f: &Forces<'_>,
    states: &[ForceState],
    closed: bool,
    target: f64,
    jump: f64,
) -> Vec<(f64, [f64; 2])> {
    let top = 1.5 * target.max(if jump.is_finite() { jump } else { 0.0 });
    (0..=150)
        .map(|k| {
            let w = top * k as f64 / 150.0;
            let forces = if closed {
                // the first curve's force at ω is `R/|J₁|` where positive; the second's `−R/|J₂|`
                let (a, b) = states.iter().fold((0.0f64, 0.0f64), |(a, b), s| {
                    let f1 = f.force_at_speed(s, w);
                    let f2 = s.second.map_or(0.0, |c| -f1 * s.lever / c.lever);
                    (a.max(f1), b.max(f2))
                });
                [a, b]
            } else {
                let min = states
                    .iter()
                    .map(|s| f.force_at_speed(s, w))
                    .fold(f64::INFINITY, f64::min);
                [min, f64::NAN]
            };
            (w, forces)
        })
        .collect()
}
