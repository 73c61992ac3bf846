//! A form-closed (conjugate) follower: a second curve on the follower that touches the cam from
//! the other side, so that the cam drives the follower both ways without a spring. A yoke with a
//! roller on each side of a constant-diameter cam, a bell crank with two rollers, a flat-faced yoke
//! on a constant-breadth cam.
//!
//! The first curve (the follower's own) sets the position, by its first touch in the closing
//! sense as for every follower. The second curve, in the same follower frame, closes the other
//! way: its own first touch is where the follower would stop if it were pushed against its
//! closing sense. The distance between the two is the **play**:
//!
//! ```text
//! play = how far the follower can move against its closing sense before the second curve touches
//! ```
//!
//! zero for an exact conjugate, positive where the follower rattles, negative where the second
//! curve cuts into the cam (interference: overlap is data, not an error).
//!
//! The second curve is a follower carrying a curve on the same joint: for a pivot, the same frame
//! with the closing sense reversed; for a slide, the direction of travel and the offset reversed
//! and the curve turned by a half turn, so that its coordinate is the negative of the follower's
//! (`s' = −s`: a slide's first touch always comes from `s = +∞`).

use super::{
    CamContact, CamError, Follower, FollowerJoint, FollowerProfile, FollowerState, Instant,
    Mechanism, Sense,
};
use crate::curve::{Curve, Derivs, Domain};
use crate::field::{Field, ProfileField};
use crate::geometry::{rot90, Point2};
use std::sync::Arc;

/// The second curve's own mechanism and how its coordinate maps to the follower's.
#[derive(Debug, Clone)]
pub(crate) struct Conjugate {
    /// the same cam, the same joint, the second curve closing the other way
    mech: Mechanism,
    /// its coordinate is minus the follower's (a slide), else the same (a pivot)
    flip: bool,
}

/// A curve turned by a half turn about its frame's origin: every coordinate negated, exactly.
#[derive(Debug)]
struct HalfTurn(Arc<dyn Curve>);

impl Curve for HalfTurn {
    fn eval(&self, u: f64) -> Derivs {
        let d = self.0.eval(u);
        Derivs {
            p: Point2::from(-d.p.coords),
            d1: -d.d1,
            d2: -d.d2,
            d3: -d.d3,
        }
    }
    fn domain(&self) -> Domain {
        self.0.domain()
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.0.breakpoints()
    }
    fn symmetry(&self) -> u32 {
        self.0.symmetry()
    }
}

impl Conjugate {
    /// The follower's coordinate (position, rate or acceleration) in the second curve's.
    fn map(&self, x: f64) -> f64 {
        if self.flip {
            -x
        } else {
            x
        }
    }
}

/// The play of the second curve over a sweep of cam angles ([`Mechanism::conjugate_sweep`]):
/// its own warm-started sweep beside the follower's.
#[derive(Debug, Clone)]
pub struct ConjugateSweep<'a> {
    mech: &'a Mechanism,
    sweep: super::Sweep<'a>,
}

impl ConjugateSweep<'_> {
    /// The play at the state `s` of the follower (the next angle of the caller's sweep), in
    /// units of `q` (length, or rad for an arm); see [`Mechanism::conjugate_play`].
    pub fn play(&mut self, s: &FollowerState) -> Result<f64, CamError> {
        let c = self
            .mech
            .conjugate
            .as_ref()
            .expect("a sweep of a conjugate");
        let q2 = self.sweep.step_motion(s.cam_angle)?.position;
        Ok(c.mech.touch.ahead(c.map(s.position), q2))
    }
}

impl Mechanism {
    /// This mechanism with a second curve on the follower, in the follower's frame (the frame of
    /// [`Mechanism::follower_body`]: for the named kinds, see `general-follower-and-gears.md`),
    /// that touches the cam from the other side: a conjugate, form-closed follower. The follower's
    /// own curve still sets its position; the second curve's play is
    /// [`Mechanism::conjugate_play`], and where it touches it is one of [`Mechanism::contacts`].
    ///
    /// Refused when the second curve does not touch the cam from the other side at cam angle 0
    /// (the error names `follower.conjugate` and says why). The second curve's search uses the
    /// default analysis options for the cam's size.
    pub fn with_conjugate(mut self, curve: Arc<dyn Curve>) -> Result<Self, CamError> {
        let table = Field::FollowerConjugate(ProfileField::Table);
        if matches!(curve.domain(), Domain::Point) {
            return Err(CamError::Conjugate {
                field: table,
                reason: "a point (a knife edge) cannot be a follower's second curve: give a circle of small radius".into(),
            });
        }
        let pivot = self.touch.cam().pivot;
        let (follower, flip) = match self.touch.geometry().joint {
            FollowerJoint::Translating { origin, direction } => (
                Follower::Translating {
                    direction: -*direction,
                    // the origin is the cam axis moved by e·rot90(d) = (−e)·rot90(−d)
                    offset: -(origin - pivot).dot(&rot90(*direction)),
                    profile: FollowerProfile(Arc::new(HalfTurn(curve))),
                },
                true,
            ),
            FollowerJoint::Rotating {
                pivot: o,
                closing,
                initial_angle,
                ..
            } => (
                Follower::Rotating {
                    pivot: o,
                    closing: match closing {
                        Sense::Ccw => Sense::Cw,
                        Sense::Cw => Sense::Ccw,
                    },
                    initial_angle,
                    profile: FollowerProfile(curve),
                },
                false,
            ),
        };
        let mech = Mechanism::new(self.touch.cam().clone(), follower).map_err(|e| {
            CamError::Conjugate {
                field: table,
                reason: e.to_string(),
            }
        })?;
        mech.analyze(0.0).map_err(|e| CamError::Conjugate {
            field: table,
            reason: format!(
                "the second curve must touch the cam from the other side of the follower's own: {e}"
            ),
        })?;
        self.conjugate = Some(Arc::new(Conjugate { mech, flip }));
        Ok(self)
    }

    /// The follower carries a second curve (a conjugate, form-closed follower).
    pub fn is_conjugate(&self) -> bool {
        self.conjugate.is_some()
    }

    /// A conjugate follower's second curve in the frame of [`Mechanism::follower_body`]'s pose
    /// (for a slide, world-aligned: the curve as given, along the direction of travel, turned).
    pub fn conjugate_curve(&self) -> Option<Arc<dyn Curve>> {
        // the second curve's own frame is the follower's (for a slide at q' = −q, the same
        // origin, world-aligned)
        self.conjugate.as_ref().map(|c| c.mech.follower_body(0.0).1)
    }

    /// How far the follower at the state `s` can move against its closing sense before its
    /// second curve touches the cam, in units of `q` (length, or rad for an arm): zero for an
    /// exact conjugate, positive where it has play, negative where the second curve cuts into
    /// the cam. `None` without a second curve ([`Mechanism::with_conjugate`]). A cold search;
    /// over many angles, [`Mechanism::conjugate_sweep`] is faster.
    pub fn conjugate_play(&self, s: &FollowerState) -> Option<Result<f64, CamError>> {
        let c = self.conjugate.as_ref()?;
        Some(
            c.mech
                .motion(s.cam_angle)
                .map(|m| c.mech.touch.ahead(c.map(s.position), m.position)),
        )
    }

    /// The second curve's own mechanism (the same cam, the second curve on the same joint
    /// closing the other way) and the sign that maps its coordinate to the follower's (−1 for a
    /// slide, +1 for an arm); `None` without a second curve.
    pub(crate) fn conjugate_side(&self) -> Option<(&Mechanism, f64)> {
        self.conjugate
            .as_ref()
            .map(|c| (&c.mech, if c.flip { -1.0 } else { 1.0 }))
    }

    /// The play of the second curve at the states of a sweep, warm-started from angle to angle
    /// (`None` without a second curve).
    pub fn conjugate_sweep(&self) -> Option<ConjugateSweep<'_>> {
        let c = self.conjugate.as_ref()?;
        Some(ConjugateSweep {
            mech: self,
            sweep: c.mech.sweep(),
        })
    }

    /// The second curve's contact at the state `s` when it touches or cuts into the cam (its
    /// play at most the touch tolerance), in this mechanism's coordinates; its
    /// [`CamContact::gap`] is the play as a length.
    pub(super) fn conjugate_contact(
        &self,
        s: &FollowerState,
    ) -> Result<Option<CamContact>, CamError> {
        let Some(c) = self.conjugate.as_ref() else {
            return Ok(None);
        };
        let theta = s.cam_angle;
        let own = c.mech.analyze(theta)?;
        let mapped = FollowerState {
            position: c.map(s.position),
            velocity: c.map(s.velocity),
            acceleration: c.map(s.acceleration),
            ..*s
        };
        if c.mech.touch.ahead(mapped.position, own.position) > c.mech.touch.touch_slack() {
            return Ok(None);
        }
        let at = &Instant::new(self.cam(), theta);
        let t = super::Touch {
            u: own.cam_param,
            q: own.position,
            v: own.follower_param,
            corner: own.corner,
        };
        let mut k = super::contacts::contact(&c.mech, at, &t, &mapped)?;
        k.row_follower = c.map(k.row_follower);
        k.conjugate = true;
        Ok(Some(k))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cam::Cam;
    use crate::curve::Circle;

    fn yoke(gap: f64) -> Mechanism {
        // an eccentric circle (radius 30, eccentricity 5) between two rollers of radius 10 on a
        // vertical slide through the axis
        let cam = Cam::new(
            Arc::new(Circle::new(Point2::new(5.0, 0.0), 30.0).unwrap()),
            Point2::origin(),
            Sense::Ccw,
            10.0,
        )
        .unwrap();
        let f = Follower::TranslatingRoller {
            direction: crate::geometry::Vec2::new(0.0, 1.0),
            offset: 0.0,
            roller_radius: 10.0,
        };
        let chord = 2.0 * (40.0f64.powi(2) - 25.0).sqrt();
        let second = Circle::new(Point2::new(-(chord + gap), 0.0), 10.0).unwrap();
        Mechanism::new(cam, f)
            .unwrap()
            .with_conjugate(Arc::new(second))
            .unwrap()
    }

    #[test]
    fn a_half_turn_negates_every_derivative() {
        let c: Arc<dyn Curve> = Arc::new(Circle::new(Point2::new(3.0, -2.0), 1.5).unwrap());
        let h = HalfTurn(c.clone());
        for u in [0.0, 1.0, 4.0] {
            let (a, b) = (c.eval(u), h.eval(u));
            assert_eq!(b.p, Point2::from(-a.p.coords));
            assert_eq!((b.d1, b.d2, b.d3), (-a.d1, -a.d2, -a.d3));
        }
    }

    #[test]
    fn the_play_of_a_yoke_on_an_eccentric_is_its_distance_less_the_chord() {
        // at cam angle 0 the pitch circle's centre is on the x axis, 5 from the slide: the
        // rollers' centres are 2·sqrt(40² − 5²) apart when both touch
        for gap in [0.0, 0.25, -0.1] {
            let m = yoke(gap);
            let s = m.analyze(0.0).unwrap();
            let play = m.conjugate_play(&s).unwrap().unwrap();
            assert!((play - gap).abs() < 1e-9, "{gap}: {play}");
        }
    }

    #[test]
    fn a_second_curve_that_cannot_touch_is_refused_naming_the_field() {
        let m = yoke(0.0);
        let far = Circle::new(Point2::new(0.0, 500.0), 10.0).unwrap();
        let e = m.clone().with_conjugate(Arc::new(far)).unwrap_err();
        assert!(e.to_string().starts_with("follower.conjugate"), "{e}");
        let knife = crate::curve::PointCurve::new(Point2::new(-80.0, 0.0)).unwrap();
        let e = m.with_conjugate(Arc::new(knife)).unwrap_err();
        assert!(
            e.to_string().contains("a point (a knife edge) cannot be"),
            "{e}"
        );
    }
}
