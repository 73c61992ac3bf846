//! The force report ([`camkin::report::ForceReport`]) in words, for people: every number rounded
//! to four significant digits with its unit, angles to 0.01°.

use camkin::human::human;
use camkin::lubrication::{regime, FilmFormula, Friction};
use camkin::report::{rpm, ForceCheck, ForceReport, FormClosed, HertzReport, LubricationReport};

/// An angle (rad) as `12.5°`, in [0°, 360°), to 0.01°.
pub fn angle(t: f64) -> String {
    format!(
        "{}°",
        human((t.to_degrees().rem_euclid(360.0) * 100.0).round() / 100.0)
    )
}

/// A number to four significant digits.
pub fn num(x: f64) -> String {
    human(if x == 0.0 {
        0.0
    } else {
        let d = 10f64.powi(3 - x.abs().log10().floor() as i32);
        (x * d).round() / d
    })
}

/// How a report's lengths read: the file's unit's name and its size in metres.
#[derive(Debug, Clone, Copy)]
pub struct LengthUnit<'a> {
    /// `mm`
    pub name: &'a str,
    /// 0.001
    pub metres: f64,
}

/// The summary `camkin forces` prints, `title` being the file's name.
pub fn summary(r: &ForceReport, title: &str, lu: LengthUnit<'_>) -> String {
    let (fu, ku, tu) = r.units();
    let mut out = format!(
        "forces on {title} at {} rpm, permanent contact, friction neglected{}:\n",
        num(rpm(r.speed)),
        if r.accelerating {
            " (with the file's angular acceleration; speeds below assume a constant speed)"
        } else {
            ""
        }
    );
    let (flo, fhi) = r.contact_force;
    match &r.form_closed {
        Some(c) => out += &form_closed(c, r.oscillating, lu),
        None => {
            out += &format!(
                "contact force: max {} N {}, min {} N {}\n",
                num(fhi.value),
                place(r, fhi),
                num(flo.value),
                place(r, flo)
            )
        }
    }
    let (tlo, thi) = r.camshaft_torque;
    out += &format!(
        "camshaft torque: max {} {tu} at {}, min {} {tu} at {}, RMS {} {tu}\n",
        num(thi.value),
        angle(thi.cam_angle),
        num(tlo.value),
        angle(tlo.cam_angle),
        num(r.torque_rms)
    );
    out += &format!(
        "power balance (torque × speed against the power into the follower): largest difference {:.1e} of the peak power {} W\n",
        r.power_balance,
        num(r.peak_power)
    );
    let jump = r.jump;
    if r.closed {
        out += &if jump.speed == 0.0 {
            "the second curve takes load at any constant speed (no spring holds the follower's own curve on)\n".to_string()
        } else if jump.speed.is_finite() {
            format!(
                "the second curve takes load from {} rpm (first at {}, at constant speed)\n",
                num(rpm(jump.speed)),
                angle(jump.cam_angle)
            )
        } else {
            "the second curve takes no load at any constant speed (the spring holds the follower's own curve on)\n".to_string()
        };
    } else {
        out += &if jump.speed == 0.0 {
            format!(
                "jump speed: none is safe: the contact force is under {} N even at rest, first at {} (the spring holds less than the margin there)\n",
                num(r.margin),
                angle(jump.cam_angle)
            )
        } else if jump.speed.is_finite() {
            format!(
                "jump speed: {} rpm (the contact force reaches {} N first at {}, at constant speed)\n",
                num(rpm(jump.speed)),
                num(r.margin),
                angle(jump.cam_angle)
            )
        } else {
            format!(
                "jump speed: none (the contact force stays above {} N at any constant speed)\n",
                num(r.margin)
            )
        };
    }
    if let Some(s) = &r.spring {
        // a need within rounding of the peak force is none
        let scale = r
            .contact_force
            .1
            .value
            .abs()
            .max(s.from_motion.force_at_full_lift);
        let snap = |x: f64| if x.abs() <= 1e-9 * scale { 0.0 } else { x };
        let no_spring = s.file_stiffness == 0.0 && s.file_preload == 0.0;
        if !no_spring {
            out += &format!(
                "spring for {} rpm with a margin of {} N: preload ≥ {} {fu} with the stiffness {} {ku} (file: preload {} {fu}); ",
                num(rpm(r.target)),
                num(r.margin),
                num(snap(s.preload)),
                num(s.file_stiffness),
                num(s.file_preload)
            );
            out += &match s.stiffness {
                Some(k) => format!(
                    "or stiffness ≥ {} {ku} with the preload {} {fu}\n",
                    num(snap(k)),
                    num(s.file_preload)
                ),
                None => format!(
                    "no stiffness will do with the preload {} {fu} (the follower leaves the cam at rest position, where only the preload acts)\n",
                    num(s.file_preload)
                ),
            };
        }
        let d = &s.from_motion;
        // a slide's lengths in the file's unit, an arm's angles in degrees
        let (len, lunit) = if r.oscillating {
            (d.full_lift.to_degrees(), "°".to_string())
        } else {
            (d.full_lift / lu.metres, format!(" {}", lu.name))
        };
        let deflection = match d.preload_deflection {
            Some(x) => {
                let x = if r.oscillating {
                    x.to_degrees()
                } else {
                    x / lu.metres
                };
                format!(", compressed {}{lunit} at the lowest position (its free length is the installed length plus this)", num(x))
            }
            None => String::new(),
        };
        out += &format!(
            "{} for {} rpm with a margin of {} N: stiffness {} {ku} with a preload of {} {fu}{deflection}; {} {fu} at full lift ({}{lunit}), the least of any spring that holds; a constant force of {} {fu} would do too\n",
            if no_spring { "no spring in the file: the spring from the motion" } else { "the spring from the motion alone" },
            num(rpm(r.target)),
            num(r.margin),
            num(snap(d.stiffness)),
            num(snap(d.preload)),
            num(snap(d.force_at_full_lift)),
            num(len),
            num(snap(d.constant_force)),
        );
        if d.trade_off[4][0] > 0.0 {
            out += &format!(
                "  the least preload by stiffness: {}\n",
                d.trade_off
                    .iter()
                    .map(|[k, p]| format!("{} {ku} → {} {fu}", num(snap(*k)), num(snap(*p))))
                    .collect::<Vec<_>>()
                    .join(", ")
            );
        }
    }
    if let Some(h) = &r.hertz {
        out += &hertz(h, r.closed, lu);
    }
    if let Some(l) = &r.lubrication {
        out += &lubrication(l);
    }
    out
}

/// The lubrication lines: the oil and formula, λ's minimum and the regimes' shares, the film,
/// the entrainment's reversals, the flash temperature and the friction.
fn lubrication(l: &LubricationReport) -> String {
    let q = &l.request;
    let formula = match q.formula {
        FilmFormula::Hamrock => "Pan–Hamrock",
        _ => "Dowson–Higginson",
    };
    let friction = match q.friction {
        Friction::Constant(mu) => format!("μ = {}", num(mu)),
        Friction::Mixed {
            boundary,
            full_film,
        } => format!(
            "μ from {} (boundary, λ ≤ 1) to {} (full film, λ ≥ 3)",
            num(boundary),
            num(full_film)
        ),
        _ => String::new(),
    };
    let mut out = format!(
        "lubrication (η₀ = {} mPa·s, α = {} 1/GPa, {formula} film, composite roughness {} µm, {friction}):
",
        num(q.lubricant.viscosity * 1e3),
        num(q.lubricant.pressure_viscosity * 1e9),
        num(l.composite_roughness * 1e6),
    );
    match l.min_lambda {
        Some(m) => {
            let [b, mixed, full] = l.regime_shares.map(|x| num(100.0 * x));
            out += &format!(
                "  λ = h_min/σ: min {} at {} ({}); of the loaded angles {b} % boundary (λ < 1), {mixed} % mixed, {full} % full film (λ ≥ 3)\n",
                num(m.value),
                angle(m.cam_angle),
                regime(m.value).name()
            );
            let thinnest = l.thinnest_film.map(|e| (e.value, e.cam_angle));
            if let Some((h, t)) = thinnest {
                out += &format!(
                    "  film: thinnest h_min {} µm at {}\n",
                    num(h * 1e6),
                    angle(t)
                );
            }
        }
        None => out += "  no film: the contact is not a loaded line contact at any angle\n",
    }
    out += &if l.entrainment_reversals.is_empty() {
        "  entrainment: never reverses (the oil is drawn in from one side throughout)\n".into()
    } else {
        format!(
            "  entrainment reverses (passes through zero: no film is drawn in) at {}\n",
            l.entrainment_reversals
                .iter()
                .map(|&t| format!("{:.4}°", t.to_degrees()))
                .collect::<Vec<_>>()
                .join(", ")
        )
    };
    out += &match l.max_flash_temperature {
        Some(t) => format!(
            "  flash temperature (Blok): max {} K above the bulk at {}\n",
            num(t.value),
            angle(t.cam_angle)
        ),
        None if l.request.surfaces.iter().any(|s| s.thermal.is_none()) => {
            "  flash temperature: needs each material's k, rho and c (a preset has them; E=…:nu=…:k=…:rho=…:c=…)\n".into()
        }
        None => "  flash temperature: none (nothing slides under load)\n".into(),
    };
    out += &format!(
        "  friction (dissipated; the forces above neglect it): mean power {} W, {} J a revolution, mean torque on the camshaft {} N·m\n",
        num(l.mean_friction_power),
        num(l.friction_energy_per_revolution),
        num(l.mean_friction_torque)
    );
    out
}

fn hertz(h: &HertzReport, closed: bool, lu: LengthUnit<'_>) -> String {
    let mut out = String::new();
    for side in &h.sides {
        let whose = match (closed, side.side) {
            (false, _) => "",
            (true, 0) => " on the follower's own curve",
            _ => " on the second curve",
        };
        if let Some((p, t, rho)) = side.worst {
            out += &format!(
                "contact stress{whose} (Hertz line contact, face {} {}, {} cam on {} follower, E* = {} GPa): max {} MPa at {} (cam radius of curvature {} {})\n",
                num(h.face_width / lu.metres),
                lu.name,
                h.materials.cam.name,
                h.materials.follower.name,
                num(h.effective_modulus / 1e9),
                num(p / 1e6),
                angle(t),
                if rho.is_finite() { num(rho / lu.metres) } else { "∞".into() },
                lu.name
            );
        }
        if side.conformal > 0 {
            out += &format!("contact stress{whose}: at {} angles the cam is concave as sharply as the follower's curve: no Hertz solution (conformal contact)\n", side.conformal);
        }
        if side.on_corner > 0 {
            out += &format!("contact stress{whose}: at {} angles the contact rests on a corner of a curve (a point, not a line contact): no Hertz stress there\n", side.on_corner);
        }
    }
    if let Some(al) = h.allowable_mpa {
        out += &format!(
            "contact stress: max {} MPa, {} the allowable {} MPa\n",
            num(h.worst_mpa),
            if h.worst_mpa > al { "OVER" } else { "within" },
            num(al)
        );
    }
    out
}

fn form_closed(c: &FormClosed, oscillating: bool, lu: LengthUnit<'_>) -> String {
    let mut r = format!(
        "form-closed: the follower's own curve carries where the load presses it onto the cam, its second curve elsewhere\ncontact force on the follower's own curve: max {} N at {}; on the second curve: max {} N at {}\n",
        num(c.own_peak.value),
        angle(c.own_peak.cam_angle),
        num(c.second_peak.value),
        angle(c.second_peak.cam_angle)
    );
    r += &if c.reversals.is_empty() {
        format!(
            "load reversals: none (the {} carries at every angle)\n",
            if c.second_carries_throughout {
                "second curve"
            } else {
                "follower's own curve"
            }
        )
    } else {
        let shown: Vec<String> = c.reversals.iter().take(6).map(|&t| angle(t)).collect();
        format!(
            "load reversals: {} a revolution, where the load passes to the other curve (at {}{}): with play, each is an impact (`camkin simulate`)\n",
            c.reversals.len(),
            shown.join(", "),
            if c.reversals.len() > 6 { ", …" } else { "" }
        )
    };
    let show = |x: f64| {
        if oscillating {
            format!("{}°", num(x.to_degrees()))
        } else {
            format!("{} {}", num(x / lu.metres), lu.name)
        }
    };
    let (lo, hi) = c.play;
    r += &if lo.abs().max(hi.abs()) > c.play_tolerance {
        format!(
            "play of the second curve: {} to {} (its force is taken at its own contact, the motion from the follower's own curve: exact without play)\n",
            show(lo),
            show(hi)
        )
    } else {
        format!(
            "play of the second curve: none (within {} at every angle: an exact conjugate)\n",
            show(c.play_tolerance)
        )
    };
    r
}

/// Where an extreme of the contact force is: its angle, or the stretch of angles over which
/// the force stays at it (a dwell's constant force: `from 150° to 210°`, not one sample of it).
fn place(r: &ForceReport, e: camkin::report::Extreme) -> String {
    let Some(k) = r.states.iter().position(|s| s.cam_angle == e.cam_angle) else {
        return format!("at {}", angle(e.cam_angle));
    };
    let scale = r
        .contact_force
        .1
        .value
        .abs()
        .max(r.contact_force.0.value.abs());
    let forces: Vec<f64> = r.states.iter().map(|s| s.contact_force).collect();
    match camkin::extreme::held_run(&forces, k, 1e-9 * scale) {
        None => format!("at {}", angle(e.cam_angle)),
        Some((a, b)) => format!(
            "{} (constant)",
            camkin::extreme::stretch_words(
                r.states[a].cam_angle.to_degrees(),
                r.states[b].cam_angle.to_degrees(),
                |d| angle(d.to_radians())
            )
        ),
    }
}

/// The failed checks in one sentence (`check failed: …`), `None` when all passed.
pub fn failures(r: &ForceReport) -> Option<String> {
    let all: Vec<String> = r
        .failures
        .iter()
        .map(|f| match f {
            ForceCheck::BelowMargin { min, margin } => format!(
                "the contact force falls to {} N at {} at the file's speed (margin {} N)",
                num(min.value),
                angle(min.cam_angle),
                num(*margin)
            ),
            ForceCheck::LeavesBelowTarget { jump, target } if *jump == 0.0 => format!(
                "the contact force is under the margin {} N even at rest: no speed up to {} rpm is safe (the spring holds less than the margin)",
                num(r.margin),
                num(rpm(*target))
            ),
            ForceCheck::LeavesBelowTarget { jump, target } => format!(
                "the follower leaves the cam at {} rpm, below {} rpm",
                num(rpm(*jump)),
                num(rpm(*target))
            ),
            ForceCheck::StressOverAllowable {
                worst_mpa,
                allowable_mpa,
            } => format!(
                "the contact stress {} MPa exceeds the allowable {} MPa",
                num(*worst_mpa),
                num(*allowable_mpa)
            ),
            _ => "a check failed".into(),
        })
        .collect();
    (!all.is_empty()).then(|| format!("check failed: {}", all.join("; ")))
}
