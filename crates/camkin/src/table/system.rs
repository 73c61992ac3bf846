//! The system table (`camkin analyze SYSTEM.toml`): one row an instant, each body's pose,
//! velocity, acceleration and jerk ([`System::jerk`], empty where it is not defined) and each contact's point, gap, sliding rates, the normal
//! acceleration of the contact point with its Coriolis and relative terms on each curve (the
//! paper's eqs. 1 and 2), `γ` and the residual of its row (eq. 11), named by the elements' names
//! with their units; angles in degrees.

use super::column::Cell;
use crate::system::{System, SystemError, SystemState};

/// A name made safe for a column: letters, digits and `_`.
pub(super) fn key(name: &str) -> String {
    name.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '_'
            }
        })
        .collect()
}

/// A body's pose, rates and accelerations as columns (`{body}_x_mm` … `{body}_alpha_deg_s2`):
/// the analysis's and the simulation's.
pub(super) fn body_columns(n: &str, unit: &str) -> Vec<String> {
    [
        ("x", unit.to_string()),
        ("y", unit.to_string()),
        ("angle", "deg".into()),
        ("vx", format!("{unit}_s")),
        ("vy", format!("{unit}_s")),
        ("omega", "deg_s".into()),
        ("ax", format!("{unit}_s2")),
        ("ay", format!("{unit}_s2")),
        ("alpha", "deg_s2".into()),
    ]
    .into_iter()
    .map(|(q, u)| format!("{n}_{q}_{u}"))
    .collect()
}

/// The columns of a system's table, lengths in its unit: first the sweep's angle
/// (`driver_angle_deg`, or a cam file's `angle_deg`, the cam angle as `camkin analyze` names
/// it without `--system`) and the time.
pub fn system_columns(built: &crate::spec::BuiltSystem) -> Vec<String> {
    let sys = &built.system;
    let unit = built.length_unit.name();
    let first = match built.sweep_angle {
        crate::spec::SweepAngle::FirstDriver => "driver_angle_deg",
        _ => "angle_deg",
    };
    let mut c = vec![first.to_string(), "time_s".to_string()];
    for b in sys.bodies() {
        let n = key(&b.name);
        c.extend(body_columns(&n, unit));
        for (q, u) in [
            ("jerk_x", format!("{unit}_s3")),
            ("jerk_y", format!("{unit}_s3")),
            ("jerk_angle", "deg_s3".into()),
        ] {
            c.push(format!("{n}_{q}_{u}"));
        }
    }
    for k in sys.contacts() {
        let n = key(&k.name);
        for (q, u) in [
            ("x", unit.to_string()),
            ("y", unit.to_string()),
            ("gap", unit.to_string()),
            ("sliding_rate_a", format!("{unit}_s")),
            ("sliding_rate_b", format!("{unit}_s")),
            ("normal_acceleration", format!("{unit}_s2")),
            ("coriolis_a", format!("{unit}_s2")),
            ("relative_a", format!("{unit}_s2")),
            ("coriolis_b", format!("{unit}_s2")),
            ("relative_b", format!("{unit}_s2")),
            ("gamma", format!("{unit}_s2")),
            ("residual", format!("{unit}_s2")),
        ] {
            c.push(format!("{n}_{q}_{u}"));
        }
        c.push(format!("{n}_jump"));
    }
    c.push("error".into());
    c
}

/// Contact `k` of the instant `s`: its state, the normal accelerations seen from each body and
/// the residual of its row (eq. 11) at the bodies' accelerations.
fn contact_terms(
    sys: &System,
    s: &SystemState,
    k: usize,
) -> (
    crate::system::ContactState,
    crate::contact::NormalAcceleration,
    crate::contact::NormalAcceleration,
    f64,
) {
    let body = |id: crate::system::BodyId| {
        id.index().map_or_else(
            || {
                crate::body::BodyState::at_rest(crate::body::Pose::new(
                    crate::Point2::origin(),
                    0.0,
                ))
            },
            |i| s.bodies[i],
        )
    };
    let (c, spec) = (s.contacts[k], &sys.contacts()[k]);
    let m = &c.kinematics;
    let (ba, bb) = (body(spec.a), body(spec.b));
    (
        c,
        m.normal_acceleration_a(&ba),
        m.normal_acceleration_b(&bb),
        m.acceleration_residual(&ba, &bb),
    )
}

/// One row: the instant at driver angle `angle_deg` (time `t`), or its error in the last column.
pub fn system_cells(
    sys: &System,
    angle_deg: f64,
    t: f64,
    state: &Result<SystemState, SystemError>,
) -> Vec<Cell> {
    let mut c = vec![Cell::Num(Some(angle_deg)), Cell::Num(Some(t))];
    let nb = sys.bodies().len();
    let nc = sys.contacts().len();
    match state {
        Ok(s) => {
            // none where it is not defined (a contact on a spline node): empty cells
            let jerk = sys.jerk(s).ok();
            for (i, b) in s.bodies.iter().enumerate() {
                for v in [
                    b.pose.origin.x,
                    b.pose.origin.y,
                    b.pose.angle.to_degrees(),
                    b.velocity.x,
                    b.velocity.y,
                    b.omega.to_degrees(),
                    b.acceleration.x,
                    b.acceleration.y,
                    b.alpha.to_degrees(),
                ] {
                    c.push(Cell::Num(Some(v)));
                }
                let j = jerk.as_ref().map(|j| j[i]);
                c.push(Cell::Num(j.map(|j| j.linear.x)));
                c.push(Cell::Num(j.map(|j| j.linear.y)));
                c.push(Cell::Num(j.map(|j| j.angular.to_degrees())));
            }
            for k in 0..s.contacts.len() {
                let (ks, on_a, on_b, residual) = contact_terms(sys, s, k);
                let m = &ks.kinematics;
                for v in [
                    m.point.x,
                    m.point.y,
                    ks.pairing.gap,
                    m.sliding_rate_a,
                    m.sliding_rate_b,
                    on_a.total(),
                    on_a.coriolis,
                    on_a.relative,
                    on_b.coriolis,
                    on_b.relative,
                    m.gamma,
                    residual,
                ] {
                    c.push(Cell::Num(Some(v)));
                }
                c.push(Cell::Flag(Some(ks.jumped)));
            }
            c.push(Cell::Text(None));
        }
        Err(e) => {
            c.extend((0..12 * nb).map(|_| Cell::Num(None)));
            for _ in 0..nc {
                c.extend((0..12).map(|_| Cell::Num(None)));
                c.push(Cell::Flag(None));
            }
            c.push(Cell::Text(Some(e.to_string())));
        }
    }
    c
}

/// The columns of a system's contacts table (`camkin contacts SYSTEM.toml`): one row per contact
/// per instant, with its acceleration constraint row `Φ_q q̈ = γ` in the coordinates
/// `(x_a, y_a, θ_a, x_b, y_b, θ_b)` of its two bodies (θ in rad: the angle entries are lengths
/// per radian), so that a solver of its own can stack the rows.
pub fn system_contact_columns(built: &crate::spec::BuiltSystem) -> Vec<String> {
    let u = built.length_unit.name();
    let first = match built.sweep_angle {
        crate::spec::SweepAngle::FirstDriver => "driver_angle_deg",
        _ => "angle_deg",
    };
    let mut c: Vec<String> = [first, "time_s", "contact", "body_a", "body_b"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    for (q, unit) in [
        ("x", u.to_string()),
        ("y", u.to_string()),
        ("normal_x", String::new()),
        ("normal_y", String::new()),
        ("gap", u.to_string()),
        ("normal_velocity", format!("{u}_s")),
        ("sliding_rate_a", format!("{u}_s")),
        ("sliding_rate_b", format!("{u}_s")),
        ("normal_accel_a", format!("{u}_s2")),
        ("coriolis_a", format!("{u}_s2")),
        ("relative_a", format!("{u}_s2")),
        ("normal_accel_b", format!("{u}_s2")),
        ("coriolis_b", format!("{u}_s2")),
        ("relative_b", format!("{u}_s2")),
        ("row_x_a", String::new()),
        ("row_y_a", String::new()),
        ("row_angle_a", u.to_string()),
        ("row_x_b", String::new()),
        ("row_y_b", String::new()),
        ("row_angle_b", u.to_string()),
        ("gamma", format!("{u}_s2")),
        ("residual", format!("{u}_s2")),
    ] {
        c.push(if unit.is_empty() {
            q.to_string()
        } else {
            format!("{q}_{unit}")
        });
    }
    c.push("jump".into());
    c.push("error".into());
    c
}

/// The contacts table's rows at one instant (see [`system_contact_columns`]): one per contact,
/// or, for an instant that failed, one per contact with the reason.
pub fn system_contact_cells(
    sys: &System,
    angle_deg: f64,
    t: f64,
    state: &Result<SystemState, SystemError>,
) -> Vec<Vec<Cell>> {
    sys.contacts()
        .iter()
        .enumerate()
        .map(|(i, spec)| {
            let mut c = vec![
                Cell::Num(Some(angle_deg)),
                Cell::Num(Some(t)),
                Cell::Text(Some(spec.name.clone())),
                Cell::Text(Some(sys.body_name(spec.a).to_string())),
                Cell::Text(Some(sys.body_name(spec.b).to_string())),
            ];
            match state {
                Ok(s) => {
                    let (k, on_a, on_b, residual) = contact_terms(sys, s, i);
                    let m = &k.kinematics;
                    for v in [
                        m.point.x,
                        m.point.y,
                        m.normal.x,
                        m.normal.y,
                        k.pairing.gap,
                        m.normal_velocity,
                        m.sliding_rate_a,
                        m.sliding_rate_b,
                        on_a.total(),
                        on_a.coriolis,
                        on_a.relative,
                        on_b.total(),
                        on_b.coriolis,
                        on_b.relative,
                    ]
                    .into_iter()
                    .chain(m.phi_q)
                    .chain([m.gamma, residual])
                    {
                        c.push(Cell::Num(Some(v)));
                    }
                    c.push(Cell::Flag(Some(k.jumped)));
                    c.push(Cell::Text(None));
                }
                Err(e) => {
                    c.extend((0..22).map(|_| Cell::Num(None)));
                    c.push(Cell::Flag(None));
                    c.push(Cell::Text(Some(e.to_string())));
                }
            }
            c
        })
        .collect()
}
