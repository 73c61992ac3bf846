//! What building a mechanism costs, estimated before it is built: the search index samples the
//! cam's profile 16 times a piece (at least 256 times) and 4 times for the convex scan, and a
//! carried curve 48 times a piece (at least 1024 times), so a spline of 100 000 nodes holds
//! about 400 MB before a single angle is analysed. [`build_work`] counts the samples
//! from the curves' joints (no evaluation) and prices them at the bytes and seconds measured by
//! the integration test `build_estimates_bound_the_measured_memory`.

use super::{Cam, Follower};
use crate::curve::{Curve, Domain};
use crate::work::Work;

/// Bytes held per sample of the cam's index (its parameter, point and tangent, their trees,
/// the corners' samples, the convex scan's share): 210 measured by the allocator, with a margin.
pub(crate) const CAM_BYTES_PER_SAMPLE: f64 = 260.0;

/// Bytes held per sample of a carried curve (its polygon, the level buckets and the copies the
/// coverage keeps): 125 measured by the allocator, with a margin.
pub(crate) const CARRIED_BYTES_PER_SAMPLE: f64 = 170.0;

/// Seconds per sample to build either index, with a margin over the 0.4 µs measured (a
/// 100 000-node spline's cam index: 0.8 s).
pub(crate) const SECONDS_PER_SAMPLE: f64 = 1e-6;

/// How many samples `per_piece` a piece (at least `per_curve`) a curve gets.
fn samples(curve: &dyn Curve, per_piece: usize, per_curve: usize) -> f64 {
    match curve.domain() {
        Domain::Periodic { .. } => (curve.breakpoints().len() * per_piece).max(per_curve) as f64,
        Domain::Interval { .. } => per_curve as f64,
        Domain::Point => 1.0,
    }
}

/// The memory and time building the mechanism of `cam` and `follower` (with the
/// `conjugate` second curve, [`crate::cam::Mechanism::with_conjugate`]) takes: its search indexes, for
/// refusing a profile of millions of nodes before it is built. Cheap: the samples are
/// counted from the curves' joints.
pub fn build_work(cam: &Cam, follower: &Follower, conjugate: Option<&dyn Curve>) -> Work {
    let profile = cam.profile.as_ref();
    let mut cam_samples = samples(profile, 16, 256) + samples(profile, 4, 32);
    let mut carried = follower
        .carried_profile()
        .map_or(0.0, |c| samples(c.as_ref(), 48, 1024));
    if let Some(c) = conjugate {
        // the second curve is a mechanism of its own on the same cam
        cam_samples *= 2.0;
        carried += samples(c, 48, 1024);
    }
    let bytes = cam_samples * CAM_BYTES_PER_SAMPLE + carried * CARRIED_BYTES_PER_SAMPLE;
    let seconds = (cam_samples + carried) * SECONDS_PER_SAMPLE;
    let pieces = cam.profile.breakpoints().len();
    let what = match follower.carried_profile() {
        Some(c) => format!(
            "the search indexes of a cam of {pieces} pieces and a follower's curve of {} pieces",
            c.breakpoints().len()
        ),
        None => format!("the search index of a cam of {pieces} pieces"),
    };
    Work::new(what, seconds).with_bytes(bytes)
}
