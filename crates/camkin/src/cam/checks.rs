//! Self-consistency checks of the contact method's acceleration over analysed states, for reports
//! and benchmarks. They measure rounding, not correctness: for a flat face `s̈ = ω² (ρ − s)` is the
//! method's own algebra, and implicit differentiation shares its search and residual. The
//! independent checks are the tests (closed forms, differences of position).

use super::{CamError, FollowerCurve, FollowerState, Joint, Mechanism};

/// One check: its name and the largest difference from the contact method, relative to the
/// largest acceleration of the states checked.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Check {
    /// what the contact method was compared with
    pub name: &'static str,
    /// `max |a − a_check| / max |a|`
    pub max_rel_diff: f64,
}

impl Mechanism {
    /// Checks the accelerations of `states` against self-consistency relations: the identity
    /// `s̈ = ω² (ρ − s) + ω̇ s'` for a translating flat face on a convex cam, and implicit
    /// differentiation of the first-touch conditions ([`Mechanism::angle_derivatives`]) always.
    pub fn consistency_checks(&self, states: &[FollowerState]) -> Result<Vec<Check>, CamError> {
        let w = self.cam.speed;
        let al = self.cam.angular_acceleration;
        let amax = states
            .iter()
            .fold(0.0f64, |m, s| m.max(s.acceleration.abs()));
        let rel = |d: f64| if amax > 0.0 { d / amax } else { d };
        let mut out = Vec::new();
        let flat_face = matches!(
            (self.follower_joint(), self.follower_curve()),
            (Joint::Translating { .. }, FollowerCurve::Line(_))
        );
        if flat_face && self.convex {
            let d = states
                .iter()
                .map(|s| {
                    (s.acceleration
                        - (w * w * (s.radius_of_curvature - s.position) + al * s.velocity / w))
                        .abs()
                })
                .fold(0.0f64, f64::max);
            out.push(Check {
                name: "s̈ = ω²(ρ − s)",
                max_rel_diff: rel(d),
            });
        }
        let mut d = 0.0f64;
        for s in states {
            let q = self.angle_derivatives(s.cam_angle)?;
            d = d.max((s.acceleration - (w * w * q[1] + al * q[0])).abs());
        }
        out.push(Check {
            name: "implicit differentiation of the first touch",
            max_rel_diff: rel(d),
        });
        Ok(out)
    }
}
