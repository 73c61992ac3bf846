//! The follower's contact curve in its own body frame: a line (flat face), a circle (roller), a
//! point (knife edge), or any curve a general follower carries.

use super::*;

/// The follower's contact curve in its own body frame.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub enum FollowerCurve {
    /// a flat face
    Line(Line),
    /// a roller
    Circle(Circle),
    /// a knife edge
    Point(PointCurve),
    /// any curve carried by a general follower (a translating follower's turned into the
    /// world-aligned follower frame)
    Carried(std::sync::Arc<dyn crate::curve::Curve>),
}

impl FollowerCurve {
    /// The curve is a point (a knife edge, named or carried): it touches in a point, never
    /// along a line.
    pub fn is_point(&self) -> bool {
        match self {
            FollowerCurve::Point(_) => true,
            FollowerCurve::Carried(c) => matches!(c.domain(), crate::curve::Domain::Point),
            _ => false,
        }
    }

    /// The curve as a circle when it is one (a roller, named or carried).
    pub fn circle(&self) -> Option<&Circle> {
        match self {
            FollowerCurve::Circle(c) => Some(c),
            FollowerCurve::Carried(c) => c.as_circle(),
            _ => None,
        }
    }

    /// The curve as a shared trait object (for the dynamics).
    pub fn to_arc(self) -> std::sync::Arc<dyn crate::curve::Curve> {
        match self {
            FollowerCurve::Carried(c) => c,
            FollowerCurve::Line(c) => std::sync::Arc::new(c),
            FollowerCurve::Circle(c) => std::sync::Arc::new(c),
            FollowerCurve::Point(c) => std::sync::Arc::new(c),
        }
    }

    /// The parameter of the world contact point `c` on this curve (the follower frame is
    /// `frame`) and the curve's world derivatives there, without a virtual call; a roller's come
    /// from its radial unit vector; a carried curve's at the parameter `v` found with the contact.
    #[inline]
    pub(crate) fn world_at(&self, frame: &Frame, c: Point2, v: f64) -> (f64, WorldDerivs) {
        match self {
            FollowerCurve::Carried(k) => {
                use crate::body::CurveInFrame as _;
                (v, frame.curve_at(k.as_ref(), v))
            }
            FollowerCurve::Line(l) => {
                let d = frame.rotation * l.direction();
                let a = frame * l.anchor();
                let u = (c - a).dot(&d);
                (
                    u,
                    WorldDerivs {
                        p: a + u * d,
                        d1: d,
                        d2: Vec2::zeros(),
                        d3: Vec2::zeros(),
                    },
                )
            }
            FollowerCurve::Circle(k) => {
                let centre = frame * k.center();
                let r = k.radius();
                let m = c - centre;
                let radial = m * (1.0 / m.norm());
                let local = frame.rotation.inverse_transform_vector(&radial);
                let t = rot90(radial);
                (
                    local.y.atan2(local.x),
                    WorldDerivs {
                        p: centre + r * radial,
                        d1: r * t,
                        d2: -r * radial,
                        d3: -r * t,
                    },
                )
            }
            FollowerCurve::Point(q) => (
                0.0,
                WorldDerivs {
                    p: frame * q.at(),
                    d1: Vec2::zeros(),
                    d2: Vec2::zeros(),
                    d3: Vec2::zeros(),
                },
            ),
        }
    }
}
