//! The kinds of the schema's tables, each with the keys it takes: the one table that decides
//! which keys belong to which kind (the build refuses any other, naming these). A mechanism file
//! writes a kind as its name (`kind = "involute-gear"`); the build reads it into these enums
//! first, then matches on them exhaustively, so a new kind is a variant here (with its keys) and
//! one arm in the build.

use super::{FollowerField as F, ProfileField as P};
use crate::field::SystemKey as S;

/// Declares a kind enum: each variant with its name in mechanism files and its keys.
macro_rules! kinds {
    (
        $(#[$m:meta])*
        pub enum $name:ident ($field:ident) {
            $( $(#[$vm:meta])* $v:ident = $s:literal [$($k:ident),* $(,)?], )*
        }
    ) => {
        $(#[$m])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        #[non_exhaustive]
        pub enum $name {
            $( $(#[$vm])* $v, )*
        }
        impl $name {
            /// Every kind, in the order the docs list them.
            pub const ALL: &'static [$name] = &[$($name::$v),*];
            /// The kind's name in mechanism files.
            pub fn name(self) -> &'static str {
                match self { $( $name::$v => $s, )* }
            }
            /// The keys this kind takes (besides `kind`).
            pub fn fields(self) -> &'static [$field] {
                match self { $( $name::$v => &[$($field::$k),*], )* }
            }
            /// The kind named `s` (as in a mechanism file).
            pub fn parse(s: &str) -> Option<Self> {
                Self::ALL.iter().copied().find(|k| k.name() == s)
            }
            /// The kinds' names for a message: `spline, circle, …`.
            pub fn names() -> String {
                Self::ALL.iter().map(|k| k.name()).collect::<Vec<_>>().join(", ")
            }
        }
        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(self.name())
            }
        }
    };
}

kinds! {
    /// `[cam.profile]`'s (and a general follower's `profile`'s) `kind`.
    pub enum ProfileKind (P) {
        /// a closed cubic spline through inline points
        Spline = "spline" [Points, Parameterization],
        /// a circle
        Circle = "circle" [Center, Radius],
        /// an ellipse
        Ellipse = "ellipse" [Center, SemiAxes, RotationDeg],
        /// a closed spline through a file's points (measured or digitised)
        PointsFile = "points-file" [Path, Parameterization],
        /// a cam synthesised from a motion program for its follower
        Motion = "motion" [BaseRadius, Segments],
        /// the textbook tangent cam: base circle, straight flanks, nose circle (exact arcs and
        /// lines)
        TangentCam = "tangent-cam" [BaseRadius, NoseRadius, Lift],
        /// the textbook circular-arc cam: base circle, convex circular flanks, nose circle
        CircularArcCam = "circular-arc-cam" [BaseRadius, NoseRadius, Lift, FlankRadius],
        /// a chain of circular arcs and straight lines, exact, joined tangentially or at corners
        ArcsAndLines = "arcs-and-lines" [Start, Pieces],
        /// an involute spur gear
        InvoluteGear = "involute-gear" [Module, Teeth, PressureAngle, Addendum, Dedendum,
            ProfileShift, Backlash, FilletRadius, TipRelief, TipReliefLength, TipReliefShape],
        /// a straight line (a follower's face)
        Line = "line" [Anchor, Direction],
        /// a point (a follower's knife edge)
        Point = "point" [At],
    }
}

kinds! {
    /// `[follower]`'s `kind`: a joint carrying any curve, or one of the five named kinds.
    pub enum FollowerKind (F) {
        /// a slide carrying any curve (`profile`)
        Translating = "translating" [Direction, Offset, Profile],
        /// an arm carrying any curve (`profile`)
        Rotating = "rotating" [Pivot, Closing, InitialAngle, Profile],
        /// a flat face on a slide
        TranslatingFlat = "translating-flat" [Direction],
        /// a roller on a slide
        TranslatingRoller = "translating-roller" [Direction, Offset, RollerRadius],
        /// a knife edge on a slide
        TranslatingKnife = "translating-knife" [Direction, Offset],
        /// a flat face on an arm
        OscillatingFlat = "oscillating-flat" [Pivot, Offset, Closing, InitialAngle],
        /// a roller on an arm
        OscillatingRoller = "oscillating-roller" [Pivot, ArmLength, RollerRadius, Closing,
            InitialAngle],
    }
}

kinds! {
    /// `[[joint]]`'s `kind`.
    pub enum JointKindName (S) {
        /// a pin: the two points stay together
        Revolute = "revolute" [At],
        /// a slide along `axis` of the first body, at a fixed relative angle
        Prismatic = "prismatic" [At, Axis, AngleDeg],
        /// the two bodies welded at a relative angle
        Fixed = "fixed" [At, AngleDeg],
    }
}

kinds! {
    /// `[[driver]]`'s `coordinate`.
    pub enum DriverCoordinate (S) {
        /// the body's angle, at `speed_rpm`
        Angle = "angle" [SpeedRpm, Start, Acceleration],
        /// the body's x, at `speed` (length/s)
        X = "x" [Speed, Start, Acceleration],
        /// the body's y, at `speed` (length/s)
        Y = "y" [Speed, Start, Acceleration],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_reads_back_and_no_kind_takes_its_own_kind_key() {
        for &k in ProfileKind::ALL {
            assert_eq!(ProfileKind::parse(k.name()), Some(k));
            assert!(!k.fields().contains(&P::Kind), "{k}");
        }
        for &k in FollowerKind::ALL {
            assert_eq!(FollowerKind::parse(k.name()), Some(k));
            assert!(!k.fields().contains(&F::Kind), "{k}");
        }
        for &k in JointKindName::ALL {
            assert_eq!(JointKindName::parse(k.name()), Some(k));
        }
        for &k in DriverCoordinate::ALL {
            assert_eq!(DriverCoordinate::parse(k.name()), Some(k));
        }
        assert_eq!(ProfileKind::parse("Circle"), None);
        assert_eq!(FollowerKind::parse(""), None);
    }
}
