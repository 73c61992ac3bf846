//! One instant of a cam mechanism, passed once: the cam angle, the cam body's state at it (pose,
//! angular velocity and acceleration) and its frame.

use super::Cam;
use crate::body::BodyState;
use crate::geometry::Frame;

/// One instant: the cam angle `θ` (rad, in the cam's own direction), the cam body's state and
/// its frame (see the [`cam`](super) module's conventions).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Instant {
    /// the cam angle, rad
    pub(crate) theta: f64,
    /// the cam body's state
    pub(crate) cam: BodyState,
    /// the cam body's frame
    pub(crate) frame: Frame,
}

impl Instant {
    /// The instant at cam angle `theta` of `cam`.
    #[inline]
    pub(crate) fn new(cam: &Cam, theta: f64) -> Self {
        let state = cam.state(theta);
        Self {
            theta,
            frame: state.frame(),
            cam: state,
        }
    }
}
