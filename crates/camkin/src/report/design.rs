//! The design report: each of [`DesignChecks`]' checks with its verdict and its words, written
//! once for every front end (`camkin synth`'s `checks.txt`, the studio's check list, Python's
//! `Mechanism.checks()`).
//!
//! A verdict is a statement of a value that passes, or a failure with the cam angles (and the
//! profile's stretches) where it fails. The words are in the mechanism's length unit, with an
//! arm's motion in degrees; numbers are rounded for people by [`crate::human::human`].

use crate::cam::{ConjugatePlay, DesignChecks};
use crate::human::human;

/// Which check a [`Verdict`] is of.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum Check {
    /// a synthesised profile's round trip: the contact method against its motion law
    RoundTrip,
    /// the profile's radii of curvature at the contact (a statement, always passes)
    Curvature,
    /// the follower fits every concave stretch (a roller's radius; a flat face: none)
    Undercut,
    /// the width of a flat face the contact uses (a statement, always passes)
    FaceWidth,
    /// the pressure angle within its limit
    PressureAngle,
    /// a conjugate follower's second curve keeps touch without cutting in
    ConjugatePlay,
    /// the contact moves continuously (no jump of the contact point)
    Jumps,
    /// every angle could be analysed
    Analysed,
}

impl Check {
    /// The check's name as `failures` lists it (`round trip`, `undercut`, …).
    pub fn name(self) -> &'static str {
        match self {
            Check::RoundTrip => "round trip",
            Check::Curvature => "curvature",
            Check::Undercut => "undercut",
            Check::FaceWidth => "face width",
            Check::PressureAngle => "pressure angle",
            Check::ConjugatePlay => "conjugate play",
            Check::Jumps => "contact jumps",
            Check::Analysed => "analysis",
        }
    }
}

/// One check's verdict and what a person reads of it.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Verdict {
    /// the check
    pub check: Check,
    /// it passed (or is a statement of a value)
    pub passed: bool,
    /// its lines, the first the headline: `checks.txt` prints them all, the studio the headline
    /// with the rest after semicolons
    pub lines: Vec<String>,
    /// cam angles (degrees) where it fails, to mark
    pub angles_deg: Vec<f64>,
    /// the profile's stretches (parameter intervals) where it fails, to mark
    pub stretches: Vec<(f64, f64)>,
}

impl Verdict {
    fn new(check: Check, passed: bool, lines: Vec<String>) -> Self {
        Self {
            check,
            passed,
            lines,
            angles_deg: Vec::new(),
            stretches: Vec::new(),
        }
    }
    /// The lines on one line (the studio's message).
    pub fn message(&self) -> String {
        self.lines.join("; ")
    }
}

/// The design checks with their verdicts ([`DesignReport::new`]).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DesignReport {
    /// the values checked
    pub checks: DesignChecks,
    /// each check's verdict, in the order `checks.txt` prints them
    pub verdicts: Vec<Verdict>,
}

/// Degrees for people: hundredths (no rounding noise such as −6e-14°).
fn deg(x: f64) -> String {
    let r = (x * 100.0).round() / 100.0;
    human(if r == 0.0 { 0.0 } else { r })
}

/// ` at N angles, from A° to B°` (nothing for none).
fn span(v: &[f64]) -> String {
    match (v.first(), v.last()) {
        (Some(a), Some(b)) => format!(
            " at {} angles, from {}° to {}°",
            v.len(),
            human(*a),
            human(*b)
        ),
        _ => String::new(),
    }
}

impl DesignReport {
    /// The verdicts of `checks` (from [`crate::cam::Mechanism::design_checks`]): lengths are
    /// named `unit` (the mechanism's length unit, e.g. `mm`); `arm` says the follower's position
    /// is an arm angle (its motion then read in degrees).
    pub fn new(checks: DesignChecks, unit: &str, arm: bool) -> Self {
        let c = &checks;
        let mut v = Vec::new();
        if let Some(rt) = c.round_trip {
            let rel = if rt.has_peak {
                format!("{:.1e} of the peak", rt.acceleration / rt.scale)
            } else {
                format!(
                    "{:.1e} of ω² × the cam's size; the program has no acceleration",
                    rt.acceleration / rt.scale
                )
            };
            let (k, s) = if arm {
                (1f64.to_degrees(), "°")
            } else {
                (1.0, unit)
            };
            let sep = if arm { "" } else { " " };
            let mut lines = vec![format!(
                "round trip (contact method against the motion law): |Δs| ≤ {:.2e}{sep}{s}, |Δv| ≤ {:.2e}{sep}{s}/s, |Δa| ≤ {:.2e}{sep}{s}/s² ({rel})",
                k * rt.position,
                k * rt.velocity,
                k * rt.acceleration
            )];
            if !rt.passed {
                lines.push("round trip FAILED: the follower does not follow the synthesised profile (see the checks below)".into());
            }
            v.push(Verdict::new(Check::RoundTrip, rt.passed, lines));
        }
        let mut curvature = Vec::new();
        if let Some((rho, at)) = c.convex_min {
            curvature.push(format!(
                "smallest convex radius of curvature of the profile: {} {unit} at {}°",
                human(rho),
                human(at)
            ));
        }
        curvature.push(match c.concave_sharpest {
            Some((rho, at)) => format!(
                "sharpest concave radius of curvature of the profile: {} {unit} at {}° (negative: concave)",
                human(rho),
                human(at)
            ),
            None => "the profile is convex at every contact".into(),
        });
        v.push(Verdict::new(Check::Curvature, true, curvature));
        let broken = c.undercut();
        let mut undercut = |lines: Vec<String>| {
            let mut u = Verdict::new(Check::Undercut, !broken, lines);
            u.angles_deg.clone_from(&c.undercut_deg);
            u.stretches.clone_from(&c.stretches);
            v.push(u);
        };
        if let (Some(r), Some(pitch_min)) = (c.roller_radius, c.pitch_convex_min()) {
            // the pitch curve (the roller centre's path) has radius of curvature ρ + r: where
            // it is convex with a radius below r, the profile folds back (undercut)
            let pitch_concave = c
                .concave_sharpest
                .and_then(|(k, _)| (k + r < 0.0).then_some(k + r));
            undercut(vec![
                if broken {
                    format!(
                        "undercut: the profile is concave more sharply than the roller (radius {} {unit}){}",
                        human(r),
                        span(&c.undercut_deg)
                    )
                } else {
                    format!(
                        "undercut: none (the roller's radius {} {unit} fits everywhere)",
                        human(r)
                    )
                },
                format!(
                    "pitch curve (roller centre path): smallest convex radius of curvature {} {unit}{}",
                    if pitch_min.is_finite() { human(pitch_min) } else { "∞".into() },
                    pitch_concave.map_or(String::new(), |k| format!(", sharpest concave {} {unit}", human(k)))
                ),
            ]);
        } else if c.flat_face {
            undercut(vec![if broken {
                format!(
                    "concave stretches under the flat face: the follower cannot follow the profile{}",
                    span(&c.undercut_deg)
                )
            } else {
                "concave stretches under the flat face: none".into()
            }]);
            if let Some((umin, umax)) = c.face_range {
                v.push(Verdict::new(
                    Check::FaceWidth,
                    true,
                    vec![format!(
                        "face width needed: {} {unit} (contact from {} to {} {unit} along the face)",
                        human(umax - umin),
                        human(umin),
                        human(umax)
                    )],
                ));
            }
        } else if broken {
            undercut(vec![format!(
                "the follower cannot follow the profile{}",
                span(&c.undercut_deg)
            )]);
        }
        let over = &c.pressure_over_deg;
        let (pa, pa_at) = c.pressure_peak;
        let peak = format!("peak {}° at {}°", deg(pa), deg(pa_at));
        let limit = human(c.pressure_limit_deg);
        let mut p = Verdict::new(
            Check::PressureAngle,
            over.is_empty(),
            vec![if over.is_empty() {
                format!("pressure angle: {peak}, within ±{limit}° everywhere")
            } else {
                format!("pressure angle: {peak}, beyond ±{limit}°{}", span(over))
            }],
        );
        p.angles_deg.clone_from(over);
        v.push(p);
        if let Some(play) = c.conjugate_play {
            let mut j = Verdict::new(
                Check::ConjugatePlay,
                play.passed,
                vec![format!(
                    "conjugate play: {}",
                    conjugate_words(&play, arm, unit)
                )],
            );
            if !play.passed {
                j.angles_deg = vec![play.min.1, play.max.1];
            }
            v.push(j);
        }
        if c.failed > 0 {
            let mut a = Verdict::new(
                Check::Analysed,
                false,
                vec![format!(
                    "{} angles could not be analysed{}",
                    c.failed,
                    c.first_failure
                        .as_ref()
                        .map_or(String::new(), |e| format!(" (the first: {e})"))
                )],
            );
            a.angles_deg.clone_from(&c.failed_deg);
            v.push(a);
        }
        Self {
            checks,
            verdicts: v,
        }
    }

    /// Adds the verdict on the contact's jumps: `impulsive_deg`, the cam angles where the contact
    /// point jumps and the follower's velocity with it (the acceleration is impulsive there), and
    /// `handover_deg`, where only the place of contact moves (a gear pair's next tooth pair takes
    /// over: the velocity is continuous, no impulse). [`split_jumps`] tells them apart.
    pub fn with_jumps(mut self, impulsive_deg: Vec<f64>, handover_deg: Vec<f64>) -> Self {
        let (n, m) = (impulsive_deg.len(), handover_deg.len());
        let s = |k: usize| if k == 1 { "" } else { "s" };
        let line = match (n, m) {
            (0, 0) => "the contact moves continuously (no jumps)".to_string(),
            (0, m) => format!(
                "the contact moves to the next contact at {m} angle{} with no jump in the follower's velocity (a tooth pair's handover): no impulse",
                s(m)
            ),
            (n, 0) => format!(
                "the contact jumps at {n} angle{} (the acceleration is impulsive there)",
                s(n)
            ),
            (n, m) => format!(
                "the contact jumps at {n} angle{} (the acceleration is impulsive there); at {m} more it moves to the next contact with no jump in velocity",
                s(n)
            ),
        };
        let mut j = Verdict::new(Check::Jumps, n == 0, vec![line]);
        j.angles_deg = if n == 0 { handover_deg } else { impulsive_deg };
        self.verdicts.push(j);
        self
    }

    /// Every check passed.
    pub fn passed(&self) -> bool {
        self.verdicts.iter().all(|v| v.passed)
    }

    /// The names of the checks that failed ([`Check::name`]); a flat face's undercut is named
    /// `concave stretch under the flat face`.
    pub fn failures(&self) -> Vec<&'static str> {
        self.verdicts
            .iter()
            .filter(|v| !v.passed)
            .map(|v| match v.check {
                Check::Undercut if self.checks.flat_face => "concave stretch under the flat face",
                k => k.name(),
            })
            .collect()
    }

    /// Every verdict's lines, one a line (`checks.txt`).
    pub fn text(&self) -> String {
        self.verdicts
            .iter()
            .flat_map(|v| &v.lines)
            .map(|l| format!("{l}\n"))
            .collect()
    }
}

/// A conjugate follower's play in words: its range (an arm's in degrees) and what it means.
fn conjugate_words(c: &ConjugatePlay, arm: bool, unit: &str) -> String {
    let (k, unit) = if arm {
        (1f64.to_degrees(), "°")
    } else {
        (1.0, unit)
    };
    let v = |x: f64| format!("{} {unit}", human(k * x)).replace(" °", "°");
    let (lo, hi) = (c.min, c.max);
    let range = format!(
        "from {} at {}° to {} at {}°",
        v(lo.0),
        deg(lo.1),
        v(hi.0),
        deg(hi.1)
    );
    if c.failed > 0 {
        format!("{range}; {} angles could not be computed", c.failed)
    } else if lo.0 < -c.tolerance && hi.0 - lo.0 <= c.tolerance {
        format!("the second curve cuts {} into the cam everywhere", v(-lo.0))
    } else if lo.0 < -c.tolerance {
        format!("{range}: the second curve cuts into the cam")
    } else if hi.0 - lo.0 > c.tolerance {
        format!("{range}: it varies, so the second curve loses touch (the program does not suit the conjugate)")
    } else if hi.0 > c.tolerance {
        format!("a constant clearance of {}", v(hi.0))
    } else {
        format!(
            "none: both curves touch everywhere (|play| below {})",
            v(c.tolerance)
        )
    }
}

/// The contact's jumps of a sweep told apart: at each jumped row `k` of `rows` (`jump_at`, the
/// first row after each jump; the rows a revolution, so row 0 follows the last), the follower's
/// velocity either jumps too — by more than a smooth motion can change in a step, `2·max|a|·dt`
/// (the mean value theorem's bound, doubled) plus `1e-9·max|v|` — and the acceleration is
/// impulsive there, or does not: only the place of contact moves (an ideal gear pair's handover).
/// `dt` is the time between rows, s. Returns the cam angles (degrees) of each kind.
pub fn split_jumps(
    rows: &[crate::table::AnalysisRow],
    jump_at: &[usize],
    dt: f64,
) -> (Vec<f64>, Vec<f64>) {
    let top = |f: &dyn Fn(&crate::table::AnalysisRow) -> Option<f64>| {
        rows.iter()
            .filter_map(f)
            .filter(|v| v.is_finite())
            .fold(0.0f64, |m, v| m.max(v.abs()))
    };
    let (v_max, a_max) = (top(&|r| r.velocity), top(&|r| r.acceleration));
    let bound = 2.0 * a_max * dt.abs() + 1e-9 * v_max;
    let (mut impulsive, mut handover) = (Vec::new(), Vec::new());
    for &k in jump_at {
        let Some(row) = rows.get(k) else { continue };
        let before = &rows[(k + rows.len() - 1) % rows.len()];
        let smooth = match (row.velocity, before.velocity) {
            (Some(a), Some(b)) => (a - b).abs() <= bound,
            _ => false,
        };
        if smooth {
            handover.push(row.angle_deg);
        } else {
            impulsive.push(row.angle_deg);
        }
    }
    (impulsive, handover)
}

#[cfg(test)]
mod tests {

    fn rows(v: impl Fn(usize) -> f64, a: f64) -> Vec<crate::table::AnalysisRow> {
        (0..360)
            .map(|k| crate::table::AnalysisRow {
                angle_deg: k as f64,
                velocity: Some(v(k)),
                acceleration: Some(a),
                ..Default::default()
            })
            .collect()
    }

    /// A jump of the contact with a continuous velocity is a handover; with a velocity step
    /// beyond what the acceleration allows in a step, an impulse; row 0 follows the last.
    #[test]
    fn jumps_are_told_apart_by_the_velocity() {
        let dt = 1e-3;
        // constant velocity: every jump a handover
        let (imp, hand) = split_jumps(&rows(|_| 5.0, 0.0), &[0, 18, 36], dt);
        assert!(imp.is_empty() && hand == [0.0, 18.0, 36.0]);
        // a ramp within its acceleration: still handovers (row 0 after row 359: a step of 359·dv
        // is an impulse)
        let (imp, hand) = split_jumps(&rows(|k| k as f64 * 1e-3, 1.0), &[0, 100], dt);
        assert_eq!((imp, hand), (vec![0.0], vec![100.0]));
        // a velocity step of 1e-6 of the peak with no acceleration: an impulse
        let (imp, hand) = split_jumps(
            &rows(|k| if k < 90 { 5.0 } else { 5.0 + 5e-6 }, 0.0),
            &[90],
            dt,
        );
        assert_eq!((imp, hand), (vec![90.0], vec![]));
    }

    use super::*;
    use crate::cam::RoundTrip;

    /// A revolution's checks that pass, for a roller of radius 10 (lengths in mm).
    fn passing() -> DesignChecks {
        DesignChecks {
            pressure_limit_deg: 30.0,
            angles: 720,
            failed: 0,
            failed_deg: Vec::new(),
            first_failure: None,
            round_trip: None,
            convex_min: Some((40.0, 12.5)),
            concave_sharpest: None,
            roller_radius: Some(10.0),
            flat_face: false,
            face_range: None,
            pressure_peak: (-12.114, 84.0),
            pressure_over_deg: Vec::new(),
            undercut_deg: Vec::new(),
            stretches: Vec::new(),
            conjugate_play: None,
        }
    }

    #[test]
    fn a_passing_revolution_states_its_values() {
        let r = DesignReport::new(passing(), "mm", false);
        assert!(r.passed() && r.failures().is_empty());
        let t = r.text();
        assert!(
            t.contains("smallest convex radius of curvature of the profile: 40 mm at 12.5°"),
            "{t}"
        );
        assert!(
            t.contains("undercut: none (the roller's radius 10 mm fits everywhere)"),
            "{t}"
        );
        // the pitch curve's radius is ρ + r
        assert!(
            t.contains("smallest convex radius of curvature 50 mm"),
            "{t}"
        );
        assert!(
            t.contains("pressure angle: peak -12.11° at 84°, within ±30° everywhere"),
            "{t}"
        );
    }

    #[test]
    fn each_failure_is_named_and_marks_its_angles() {
        let mut c = passing();
        c.pressure_over_deg = vec![80.0, 80.5, 81.0];
        c.undercut_deg = vec![100.0];
        c.failed = 2;
        c.failed_deg = vec![200.0, 200.5];
        c.first_failure = Some("no contact".into());
        c.round_trip = Some(RoundTrip {
            position: 0.0,
            velocity: 0.0,
            acceleration: 1.0,
            peak_acceleration: 100.0,
            scale: 100.0,
            has_peak: true,
            passed: false,
        });
        let r = DesignReport::new(c, "in", false);
        assert_eq!(
            r.failures(),
            ["round trip", "undercut", "pressure angle", "analysis"]
        );
        assert!(!r.passed());
        let of = |k: Check| r.verdicts.iter().find(|v| v.check == k).unwrap();
        assert_eq!(of(Check::PressureAngle).angles_deg, [80.0, 80.5, 81.0]);
        assert_eq!(of(Check::Analysed).angles_deg, [200.0, 200.5]);
        assert!(of(Check::Analysed).lines[0]
            .contains("2 angles could not be analysed (the first: no contact)"));
        assert!(
            of(Check::PressureAngle).lines[0].ends_with("beyond ±30° at 3 angles, from 80° to 81°")
        );
        // the unit is the one given, by its name
        assert!(of(Check::Undercut).lines[0].contains("(radius 10 in) at 1 angles"));
        assert!(of(Check::RoundTrip).lines[1].contains("FAILED"));
    }

    #[test]
    fn a_flat_face_names_its_concave_stretch_and_its_width() {
        let mut c = passing();
        c.roller_radius = None;
        c.flat_face = true;
        c.face_range = Some((-3.0, 5.5));
        c.stretches = vec![(0.25, 0.5)];
        let r = DesignReport::new(c, "mm", false);
        assert_eq!(r.failures(), ["concave stretch under the flat face"]);
        let t = r.text();
        assert!(
            t.contains("face width needed: 8.5 mm (contact from -3 to 5.5 mm along the face)"),
            "{t}"
        );
        let u = r
            .verdicts
            .iter()
            .find(|v| v.check == Check::Undercut)
            .unwrap();
        assert_eq!(u.stretches, [(0.25, 0.5)]);
        // a knife: no radius to fit, yet a stretch it cannot follow still fails
        let mut k = passing();
        k.roller_radius = None;
        k.undercut_deg = vec![10.0];
        assert_eq!(DesignReport::new(k, "mm", false).failures(), ["undercut"]);
    }

    #[test]
    fn an_arms_play_reads_in_degrees() {
        let mut c = passing();
        c.conjugate_play = Some(ConjugatePlay {
            min: (0.01, 10.0),
            max: (0.01, 20.0),
            failed: 0,
            tolerance: 1e-6,
            passed: true,
        });
        let r = DesignReport::new(c, "mm", true);
        let t = r.text();
        // 0.01 rad is 0.572958°
        assert!(
            t.contains("conjugate play: a constant clearance of 0.572958°"),
            "{t}"
        );
        let j = DesignReport::new(r.checks.clone(), "mm", false).with_jumps(vec![90.0], vec![]);
        assert_eq!(j.failures(), ["contact jumps"]);
        assert!(j.text().contains("a constant clearance of 0.01 mm"));
    }
}
