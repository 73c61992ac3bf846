//! Fields of a mechanism, named by enums: what an error points at. [`Field`]'s `Display` is the
//! key path of the mechanism-file schema (`cam.profile.points[3]`), which front ends map to their
//! own places (a TOML key's line and column, a Python dict key).

use std::fmt;

/// Declares a field enum: the fields that are not one key (the table as a whole, indexed
/// ones), then each key with its name in files, the one place that name is written (the
/// variant's doc, [`name`](ProfileField::name) and the list of keys [`KEYED`](ProfileField::KEYED)
/// come from it).
macro_rules! keys {
    (
        $(#[$m:meta])*
        pub enum $name:ident {
            $( $(#[$om:meta])* $other:ident $( ( $($ot:ty),* ) )?, )*
            ; keys {
                $( $(#[$km:meta])* $v:ident = $s:literal, )*
            }
        }
    ) => {
        $(#[$m])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        #[non_exhaustive]
        pub enum $name {
            $( $(#[$om])* $other $( ( $($ot),* ) )?, )*
            $( #[doc = concat!("`", $s, "`")] $(#[$km])* $v, )*
        }
        impl $name {
            /// Every field that is one key, in the order declared: the one list of its keys.
            pub const KEYED: &'static [$name] = &[$($name::$v),*];
            /// The key's name in files (`None` for the table and the indexed fields).
            #[allow(unreachable_patterns)]
            pub fn name(self) -> Option<&'static str> {
                match self {
                    $( $name::$v => Some($s), )*
                    _ => None,
                }
            }
        }
    };
}

/// A field of a mechanism specification.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Field {
    /// `length_unit`
    LengthUnit,
    /// a field of `[cam]`
    Cam(CamField),
    /// a field of `[cam.profile]`
    Profile(ProfileField),
    /// a field of `[follower]`
    Follower(FollowerField),
    /// a field of `[follower.profile]` (the curve a general follower carries)
    FollowerProfile(ProfileField),
    /// a field of `[follower.conjugate]` (the second curve of a form-closed follower)
    FollowerConjugate(ProfileField),
    /// a field of `[dynamics]`
    Dynamics(DynamicsField),
    /// a field of `[lubrication]`
    Lubrication(LubricationField),
    /// a field of an element of a system file (`joint[2].bodies`)
    System(SystemField),
    /// a field of `[gear_pair]`
    GearPair(GearPairField),
    /// a field of `[gear_loads]`
    GearLoads(GearLoadsField),
}

keys! {
    /// Fields of `[gear_loads]`.
    pub enum GearLoadsField {
        /// the whole table
        Table,
        ; keys {
            Torque = "torque",
            PowerKw = "power_kw",
            FaceWidth = "face_width",
            Materials = "materials",
        }
    }
}

keys! {
    /// Fields of `[gear_pair]`.
    pub enum GearPairField {
        /// the whole table
        Table,
        /// `teeth[i]`
        Teeth(usize),
        /// `profile_shift[i]`
        ProfileShift(usize),
        ; keys {
            Module = "module",
            PressureAngle = "pressure_angle_deg",
            CentreDistance = "centre_distance",
            Backlash = "backlash",
            SpeedRpm = "speed_rpm",
            Direction = "direction",
        }
    }
}

/// A field of an element of a system file: which table, which element (0-based, in the file's
/// order) and which key.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SystemField {
    /// the array of tables
    pub table: SystemTable,
    /// the element's index in it
    pub index: usize,
    /// the key
    pub key: SystemKey,
}

/// The arrays of tables of a system file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum SystemTable {
    /// `[[body]]`
    Body,
    /// `[[joint]]`
    Joint,
    /// `[[driver]]`
    Driver,
    /// `[[contact]]`
    Contact,
    /// `[[spring]]`
    Spring,
    /// `[[damper]]`
    Damper,
    /// `[[torsion_spring]]`
    TorsionSpring,
    /// `[dynamics]` (one table: its index is 0)
    Dynamics,
    /// `[[coil_spring]]`
    CoilSpring,
    /// `[[gas_force]]`
    GasForce,
    /// `[simulation]` (one table: its index is 0)
    Simulation,
    /// `[[load]]`
    Load,
    /// `[[lash_adjuster]]`
    LashAdjuster,
}

impl SystemTable {
    /// Its name in the file.
    pub fn name(self) -> &'static str {
        match self {
            SystemTable::Body => "body",
            SystemTable::Joint => "joint",
            SystemTable::Driver => "driver",
            SystemTable::Contact => "contact",
            SystemTable::Spring => "spring",
            SystemTable::Damper => "damper",
            SystemTable::TorsionSpring => "torsion_spring",
            SystemTable::Dynamics => "dynamics",
            SystemTable::CoilSpring => "coil_spring",
            SystemTable::GasForce => "gas_force",
            SystemTable::Simulation => "simulation",
            SystemTable::Load => "load",
            SystemTable::LashAdjuster => "lash_adjuster",
        }
    }
}

keys! {
    /// The keys of a system file's elements.
    pub enum SystemKey {
        /// the element as a whole
        Table,
        /// a key of `curve_a`
        CurveA(ProfileField),
        /// a key of `curve_b`
        CurveB(ProfileField),
        /// a key of `motion_follower`
        MotionFollower(FollowerField),
        /// `roughness_um[i]` (a contact's: 0 curve A's, 1 curve B's)
        RoughnessUm(usize),
        ; keys {
            Name = "name",
            Mass = "mass",
            Inertia = "inertia",
            Position = "position",
            AngleDeg = "angle_deg",
            CentreOfMass = "centre_of_mass",
            Kind = "kind",
            Bodies = "bodies",
            At = "at",
            Axis = "axis",
            Body = "body",
            Coordinate = "coordinate",
            Start = "start",
            SpeedRpm = "speed_rpm",
            Speed = "speed",
            Acceleration = "acceleration",
            Stiffness = "stiffness",
            FreeLength = "free_length",
            FreeAngleDeg = "free_angle_deg",
            Preload = "preload",
            Damping = "damping",
            MotionDirection = "motion_direction",
            Restitution = "restitution",
            Gravity = "gravity",
            Masses = "masses",
            SolidLength = "solid_length",
            DampingRatio = "damping_ratio",
            FaceWidth = "face_width",
            Materials = "materials",
            Direction = "direction",
            /// (a force's, of the crank angle)
            ForceTable = "table",
            CrankPerDriver = "crank_per_driver",
            PeriodDeg = "period_deg",
            Rolls = "rolls",
            Velocity = "velocity",
            AngularVelocity = "angular_velocity",
            StartsClosed = "starts_closed",
            /// (a contact's clearance)
            Lash = "lash",
            /// (a lash adjuster's plunger diameter)
            Bore = "bore",
            ChamberLength = "chamber_length",
            ClearanceUm = "clearance_um",
            LeakLength = "leak_length",
            ViscosityMpaS = "viscosity_mpa_s",
            BulkModulusMpa = "bulk_modulus_mpa",
            AirFraction = "air_fraction",
            SupplyBar = "supply_bar",
            CheckOpeningBar = "check_opening_bar",
            CheckFlow = "check_flow",
            InitialPressureBar = "initial_pressure_bar",
            /// (a run's, s)
            Duration = "duration",
            /// (a run's output interval, s)
            Interval = "interval",
            /// (a load's, N)
            Force = "force",
            /// (a load's, N·L)
            Torque = "torque",
            /// (a load's force's frame)
            Frame = "frame",
            /// (a load's table of time)
            Profile = "profile",
        }
    }
}

keys! {
    /// Fields of `[cam]`.
    pub enum CamField {
        /// the whole table
        Table,
        ; keys {
            SpeedRpm = "speed_rpm",
            /// the speed in rad/s of [`crate::cam::Cam::new`] (no file key: `speed_rpm` in files)
            Speed = "speed",
            Direction = "direction",
            Pivot = "pivot",
            AngularAcceleration = "angular_acceleration_deg_s2",
        }
    }
}

keys! {
    /// Fields of `[cam.profile]`.
    pub enum ProfileField {
        /// the whole table (a property of the profile as a whole: its size, a cusp)
        Table,
        /// `points[i]`
        Point(usize),
        /// `pieces[i]`, or its `to`, `centre` or `clockwise`
        Piece(usize, PieceField),
        /// `segments[i].law`, `.rise` or `.degrees`
        Segment(usize, SegmentField),
        ; keys {
            Kind = "kind",
            Points = "points",
            Parameterization = "parameterization",
            Center = "center",
            Radius = "radius",
            SemiAxes = "semi_axes",
            RotationDeg = "rotation_deg",
            Path = "path",
            BaseRadius = "base_radius",
            Segments = "segments",
            /// (an arc cam's)
            NoseRadius = "nose_radius",
            /// (an arc cam's)
            Lift = "lift",
            /// (a circular-arc cam's)
            FlankRadius = "flank_radius",
            /// (an arcs-and-lines profile's first point)
            Start = "start",
            Pieces = "pieces",
            /// (a gear's)
            Module = "module",
            Teeth = "teeth",
            PressureAngle = "pressure_angle_deg",
            /// (factor)
            Addendum = "addendum",
            /// (factor)
            Dedendum = "dedendum",
            /// (coefficient)
            ProfileShift = "profile_shift",
            /// (thinning on the pitch circle, length)
            Backlash = "backlash",
            FilletRadius = "fillet_radius",
            /// (amount at the tip, length)
            TipRelief = "tip_relief",
            /// (along the line of action)
            TipReliefLength = "tip_relief_length",
            TipReliefShape = "tip_relief_shape",
            /// (a line's point)
            Anchor = "anchor",
            /// (a line's)
            Direction = "direction",
            /// (a point's place)
            At = "at",
        }
    }
}

keys! {
    /// Fields of one motion segment.
    pub enum SegmentField {
        ; keys {
            Law = "law",
            Rise = "rise",
            Degrees = "degrees",
            /// (a table's file)
            File = "file",
            /// (a table's inline step)
            StepDeg = "step_deg",
            /// (a table's inline lifts)
            Lift = "lift",
        }
    }
}

keys! {
    /// Keys of a piece of an `arcs-and-lines` profile.
    pub enum PieceField {
        /// the piece as a whole
        Table,
        ; keys {
            To = "to",
            Centre = "centre",
            Clockwise = "clockwise",
        }
    }
}

keys! {
    /// Fields of `[follower]`.
    pub enum FollowerField {
        /// the whole table
        Table,
        ; keys {
            Kind = "kind",
            Direction = "direction",
            /// (of the line of travel, or of an oscillating face)
            Offset = "offset",
            RollerRadius = "roller_radius",
            Pivot = "pivot",
            ArmLength = "arm_length",
            Closing = "closing",
            InitialAngle = "initial_angle_deg",
            /// `[follower.profile]`: the curve a general follower carries
            Profile = "profile",
        }
    }
}

keys! {
    /// Fields of `[dynamics]`.
    pub enum DynamicsField {
        /// the whole table
        Table,
        ; keys {
            Mass = "mass",
            Inertia = "inertia",
            SpringStiffness = "spring_stiffness",
            SpringPreload = "spring_preload",
            Damping = "damping",
            Restitution = "restitution",
            Gravity = "gravity",
        }
    }
}

keys! {
    /// Fields of `[lubrication]`.
    pub enum LubricationField {
        /// the whole table
        Table,
        /// `roughness_um[i]` (0: the cam's, 1: the follower's)
        RoughnessUm(usize),
        ; keys {
            Oil = "oil",
            FaceWidth = "face_width",
            Film = "film",
            Friction = "friction",
            Materials = "materials",
        }
    }
}

impl Field {
    /// The table the field is in (`cam.profile` for `cam.profile.radius`).
    pub fn table(&self) -> Field {
        match *self {
            Field::LengthUnit => Field::LengthUnit,
            Field::Cam(_) => Field::Cam(CamField::Table),
            Field::Profile(_) => Field::Profile(ProfileField::Table),
            Field::Follower(_) => Field::Follower(FollowerField::Table),
            Field::FollowerProfile(_) => Field::FollowerProfile(ProfileField::Table),
            Field::FollowerConjugate(_) => Field::FollowerConjugate(ProfileField::Table),
            Field::Dynamics(_) => Field::Dynamics(DynamicsField::Table),
            Field::Lubrication(_) => Field::Lubrication(LubricationField::Table),
            Field::GearPair(_) => Field::GearPair(GearPairField::Table),
            Field::GearLoads(_) => Field::GearLoads(GearLoadsField::Table),
            Field::System(f) => match f.key {
                SystemKey::CurveA(_) => Field::System(SystemField {
                    key: SystemKey::CurveA(ProfileField::Table),
                    ..f
                }),
                SystemKey::CurveB(_) => Field::System(SystemField {
                    key: SystemKey::CurveB(ProfileField::Table),
                    ..f
                }),
                SystemKey::MotionFollower(_) => Field::System(SystemField {
                    key: SystemKey::MotionFollower(FollowerField::Table),
                    ..f
                }),
                _ => Field::System(SystemField {
                    key: SystemKey::Table,
                    ..f
                }),
            },
        }
    }

    /// The key path as segments: names and array indices (`["cam", "profile", "points", 3]`).
    pub fn path(&self) -> Vec<Key> {
        use Key::{Index, Name};
        let mut p = Vec::new();
        match *self {
            Field::LengthUnit => p.push(Name("length_unit")),
            Field::Cam(c) => {
                p.push(Name("cam"));
                p.extend(c.name().map(Name));
            }
            Field::Profile(f) | Field::FollowerProfile(f) | Field::FollowerConjugate(f) => {
                p.extend(match self {
                    Field::Profile(_) => [Name("cam"), Name("profile")],
                    Field::FollowerProfile(_) => [Name("follower"), Name("profile")],
                    _ => [Name("follower"), Name("conjugate")],
                });
                f.push_path(&mut p);
            }
            Field::Follower(f) => {
                p.push(Name("follower"));
                p.extend(f.name().map(Name));
            }
            Field::Dynamics(f) => {
                p.push(Name("dynamics"));
                p.extend(f.name().map(Name));
            }
            Field::Lubrication(f) => {
                p.push(Name("lubrication"));
                match f {
                    LubricationField::RoughnessUm(i) => {
                        p.extend([Name("roughness_um"), Index(i)]);
                    }
                    f => p.extend(f.name().map(Name)),
                }
            }
            Field::GearLoads(g) => {
                p.push(Name("gear_loads"));
                p.extend(g.name().map(Name));
            }
            Field::GearPair(g) => {
                p.push(Name("gear_pair"));
                match g {
                    GearPairField::Teeth(i) => p.extend([Name("teeth"), Index(i)]),
                    GearPairField::ProfileShift(i) => p.extend([Name("profile_shift"), Index(i)]),
                    g => p.extend(g.name().map(Name)),
                }
            }
            Field::System(f) => {
                p.push(Name(f.table.name()));
                if !matches!(f.table, SystemTable::Dynamics | SystemTable::Simulation) {
                    p.push(Index(f.index));
                }
                match f.key {
                    SystemKey::CurveA(c) => {
                        p.push(Name("curve_a"));
                        c.push_path(&mut p);
                    }
                    SystemKey::CurveB(c) => {
                        p.push(Name("curve_b"));
                        c.push_path(&mut p);
                    }
                    SystemKey::MotionFollower(k) => {
                        p.push(Name("motion_follower"));
                        p.extend(k.name().map(Name));
                    }
                    SystemKey::RoughnessUm(i) => p.extend([Name("roughness_um"), Index(i)]),
                    k => p.extend(k.name().map(Name)),
                }
            }
        }
        p
    }
}

impl ProfileField {
    /// The field's path inside its profile table (`points[3]`, `segments[1].law`, `radius`).
    fn push_path(self, p: &mut Vec<Key>) {
        use Key::{Index, Name};
        match self {
            ProfileField::Point(i) => p.extend([Name("points"), Index(i)]),
            ProfileField::Segment(i, s) => {
                p.extend([Name("segments"), Index(i)]);
                p.extend(s.name().map(Name));
            }
            ProfileField::Piece(i, k) => {
                p.extend([Name("pieces"), Index(i)]);
                p.extend(k.name().map(Name));
            }
            other => p.extend(other.name().map(Name)),
        }
    }
}

/// One step of a key path.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Key {
    /// a table key
    Name(&'static str),
    /// an array index
    Index(usize),
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, k) in self.path().iter().enumerate() {
            match k {
                Key::Name(n) if i == 0 => f.write_str(n)?,
                Key::Name(n) => write!(f, ".{n}")?,
                Key::Index(j) => write!(f, "[{j}]")?,
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_print_as_key_paths() {
        assert_eq!(
            Field::Profile(ProfileField::Point(3)).to_string(),
            "cam.profile.points[3]"
        );
        assert_eq!(
            Field::Profile(ProfileField::Segment(1, SegmentField::Law)).to_string(),
            "cam.profile.segments[1].law"
        );
        assert_eq!(Field::Cam(CamField::SpeedRpm).to_string(), "cam.speed_rpm");
        assert_eq!(
            Field::Follower(FollowerField::Table).to_string(),
            "follower"
        );
        assert_eq!(Field::LengthUnit.to_string(), "length_unit");
        // the tables whose keys the path once spelled out by hand, and their indexed keys
        let cases = [
            (
                Field::GearPair(GearPairField::Teeth(1)),
                "gear_pair.teeth[1]",
            ),
            (
                Field::GearPair(GearPairField::PressureAngle),
                "gear_pair.pressure_angle_deg",
            ),
            (
                Field::GearLoads(GearLoadsField::PowerKw),
                "gear_loads.power_kw",
            ),
            (
                Field::Lubrication(LubricationField::RoughnessUm(0)),
                "lubrication.roughness_um[0]",
            ),
            (Field::Lubrication(LubricationField::Table), "lubrication"),
            (
                Field::Cam(CamField::AngularAcceleration),
                "cam.angular_acceleration_deg_s2",
            ),
            (
                Field::System(SystemField {
                    table: SystemTable::Contact,
                    index: 2,
                    key: SystemKey::CurveB(ProfileField::Piece(4, PieceField::Centre)),
                }),
                "contact[2].curve_b.pieces[4].centre",
            ),
            (
                Field::System(SystemField {
                    table: SystemTable::GasForce,
                    index: 0,
                    key: SystemKey::ForceTable,
                }),
                "gas_force[0].table",
            ),
        ];
        for (field, path) in cases {
            assert_eq!(field.to_string(), path);
        }
        // every key's name is its variant's, once: no two keys of a table share a name
        for names in [
            ProfileField::KEYED
                .iter()
                .map(|f| f.name())
                .collect::<Vec<_>>(),
            SystemKey::KEYED.iter().map(|f| f.name()).collect(),
            FollowerField::KEYED.iter().map(|f| f.name()).collect(),
        ] {
            let mut sorted = names.clone();
            sorted.sort();
            sorted.dedup();
            assert_eq!(sorted.len(), names.len());
            assert!(names.iter().all(Option::is_some));
        }
    }
}
