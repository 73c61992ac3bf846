//! # camkin — exact contact kinematics of rotating planar curves
//!
//! Given two planar curves carried by moving rigid bodies, camkin computes at one instant where
//! they touch, how fast the contact point slides along each curve, the normal accelerations of the
//! contact point with their Coriolis and relative terms, and so the acceleration constraint between
//! the bodies as one linear equation. The method is K. Lee, *Efficient computation of the
//! acceleration of the contact point between rotating surfaces and application to cam-follower
//! mechanism* (Int. J. Automotive Technology, 2005); equation numbers in the docs are the paper's.
//!
//! Data flows one way: [`geometry`] → [`curve`] → [`body`] → [`contact`] → [`cam`]
//! (→ [`interp`], the paper's comparison method; [`reference`](mod@reference) holds the paper's cam).
//!
//! # Example: the paper's cam at one angle
//!
//! ```
//! use camkin::cam::{Cam, Follower, Mechanism, Sense};
//! use camkin::curve::ClosedSpline;
//! use camkin::{Point2, Vec2};
//! use std::sync::Arc;
//!
//! let nodes = [(5.0, 0.0), (3.4, 2.8), (0.6, 3.4), (-1.5, 2.6), (-2.8, 1.0),
//!              (-2.8, -1.0), (-1.5, -2.6), (0.6, -3.4), (3.4, -2.8)]
//!     .map(|(x, y)| Point2::new(x, y));
//! let profile = Arc::new(ClosedSpline::new(&nodes)?);
//! let cam = Cam::from_rpm(profile, Point2::origin(), Sense::Ccw, 1000.0)?;
//! let mech = Mechanism::new(cam, Follower::TranslatingFlat { direction: Vec2::x() })?;
//! let s = mech.analyze_deg(45.0)?;
//! assert!((s.position - 4.448456).abs() < 1e-6);          // cm
//! assert!((s.acceleration + 6291.918).abs() < 1e-3);      // cm/s²
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Sign conventions
//!
//! This section is the one place where the conventions are stated; every other doc refers here.
//!
//! - **Angles and angular velocities are counter-clockwise positive**, for every body (the paper
//!   takes body B's angular velocity clockwise, hence its `ω^A + ω^B`; camkin writes `ω_A − ω_B`).
//!   Angles are in radians inside the library; degrees appear only where a name says `_deg`.
//! - **Body frames.** A body X has origin `p_X` and angle `θ_X`; a point `r` fixed in the body is at
//!   `x = p_X + R(θ_X) r` in the world.
//! - **Curves** `r(u)` are fixed in their body frame; `u` is any regular parameter (the paper's α, β).
//!   With `r' = dr/du`, `r'' = d²r/du²`: metric factor `g = |r'|` (the paper's `dξ/dα`), unit tangent
//!   `t = r'/g`, **left normal** `ν = k × t = (−t_y, t_x)` (the paper's η axis) and **signed
//!   curvature** `κ = (r' × r'')/g³`, positive where the curve turns left. A closed curve traversed
//!   counter-clockwise has `κ > 0` where it is convex, and `ν` pointing inward.
//! - **Material on the left.** Curves built by camkin for followers (faces, rollers) are oriented
//!   with the body's material on their left, like a counter-clockwise closed profile. With that
//!   orientation the **gap** `ν_A·(x_A − x_B)` is positive when the curves are apart and negative
//!   when they overlap. The formulas themselves do not depend on the orientation: reversing a curve
//!   flips `t`, `ν`, `κ`, `σ` and that curve's sliding rate together.
//! - **σ** `= t_A·t_B = ±1` at a contact records whether the two parameter directions agree (two
//!   closed counter-clockwise curves touching externally give `σ = −1`).
//! - **Sliding rates** `ṡ_X = g_X u̇_X` are the speeds of the contact point along curve X relative to
//!   body X, positive in the direction of increasing `u_X`.
//! - **Normal accelerations** `a_n^A`, `a_n^B` are components along `ν_A` (eqs. 1, 2, 11).
//! - **Units.** Lengths in any one unit `L` chosen by the user; time in seconds. Velocities are
//!   `L/s` and `rad/s`, accelerations `L/s²` and `rad/s²`, curvature `1/L`.
//! - **Pressure angle** ([`cam::FollowerState::pressure_angle`]): from the direction of motion of
//!   the follower's reference point (a roller's centre, a knife's tip, a flat face's contact
//!   point) to the line of the contact force, oriented along the motion, counter-clockwise
//!   positive.
//! - **Cam angle** `θ` (see [`cam`]) is how far the cam has turned in its own direction of motion,
//!   always increasing with time: a counter-clockwise cam's frame is at `+θ`, a clockwise cam's at
//!   `−θ`.
//!
//! # Tolerances
//!
//! Tolerances are explicit: lengths are scaled by the size of the problem (see
//! [`contact::SearchOptions`] and [`cam::AnalysisOptions`]); no bare epsilon is hidden in the code.

pub mod body;
pub mod cam;
pub(crate) mod circle_tree;
pub mod contact;
pub mod curve;
pub mod dynamics;
mod error;
pub mod extreme;
pub mod field;
pub mod gears;
pub mod geometry;
pub mod human;
pub mod interp;
pub(crate) mod jet;
pub mod lift_table;
pub mod lubrication;
pub mod measured;
pub mod motion;
pub(crate) mod periodic;
pub mod reference;
pub mod report;
pub mod spec;
pub mod system;
pub mod table;
mod valid;
pub mod work;

pub use body::{BodyState, CurveInFrame, Pose};
pub use error::Error;
pub use geometry::{Frame, Rotation, UnitVec2};
pub use geometry::{Point2, Vec2};
