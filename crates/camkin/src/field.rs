//! Fields of a mechanism, named by enums: what an error points at. [`Field`]'s `Display` is the
//! key path of the mechanism-file schema (`cam.profile.points[3]`), which front ends map to their
//! own places (a TOML key's line and column, a Python dict key).

use std::fmt;

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

/// Fields of `[gear_loads]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum GearLoadsField {
    /// the whole table
    Table,
    /// `torque`
    Torque,
    /// `power_kw`
    PowerKw,
    /// `face_width`
    FaceWidth,
    /// `materials`
    Materials,
}

/// Fields of `[gear_pair]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum GearPairField {
    /// the whole table
    Table,
    /// `teeth[i]`
    Teeth(usize),
    /// `module`
    Module,
    /// `pressure_angle_deg`
    PressureAngle,
    /// `profile_shift[i]`
    ProfileShift(usize),
    /// `centre_distance`
    CentreDistance,
    /// `backlash`
    Backlash,
    /// `speed_rpm`
    SpeedRpm,
    /// `direction`
    Direction,
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
        }
    }
}

/// The keys of a system file's elements.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum SystemKey {
    /// the element as a whole
    Table,
    /// `name`
    Name,
    /// `mass`
    Mass,
    /// `inertia`
    Inertia,
    /// `position`
    Position,
    /// `angle_deg`
    AngleDeg,
    /// `centre_of_mass`
    CentreOfMass,
    /// `kind`
    Kind,
    /// `bodies`
    Bodies,
    /// `at`
    At,
    /// `axis`
    Axis,
    /// `body`
    Body,
    /// `coordinate`
    Coordinate,
    /// `start`
    Start,
    /// `speed_rpm`
    SpeedRpm,
    /// `speed`
    Speed,
    /// `acceleration`
    Acceleration,
    /// `stiffness`
    Stiffness,
    /// `free_length`
    FreeLength,
    /// `free_angle_deg`
    FreeAngleDeg,
    /// `preload`
    Preload,
    /// `damping`
    Damping,
    /// a key of `curve_a`
    CurveA(ProfileField),
    /// a key of `curve_b`
    CurveB(ProfileField),
    /// a key of `motion_follower`
    MotionFollower(FollowerField),
    /// `motion_direction`
    MotionDirection,
    /// `restitution`
    Restitution,
    /// `gravity`
    Gravity,
    /// `masses`
    Masses,
    /// `solid_length`
    SolidLength,
    /// `face_width`
    FaceWidth,
    /// `materials`
    Materials,
    /// `direction`
    Direction,
    /// `table` (a force's, of the crank angle)
    ForceTable,
    /// `crank_per_driver`
    CrankPerDriver,
    /// `period_deg`
    PeriodDeg,
    /// `roughness_um[i]` (a contact's: 0 curve A's, 1 curve B's)
    RoughnessUm(usize),
    /// `rolls`
    Rolls,
}

impl SystemKey {
    fn name(self) -> Option<&'static str> {
        Some(match self {
            SystemKey::Table
            | SystemKey::CurveA(_)
            | SystemKey::CurveB(_)
            | SystemKey::MotionFollower(_) => return None,
            SystemKey::MotionDirection => "motion_direction",
            SystemKey::Name => "name",
            SystemKey::Mass => "mass",
            SystemKey::Inertia => "inertia",
            SystemKey::Position => "position",
            SystemKey::AngleDeg => "angle_deg",
            SystemKey::CentreOfMass => "centre_of_mass",
            SystemKey::Kind => "kind",
            SystemKey::Bodies => "bodies",
            SystemKey::At => "at",
            SystemKey::Axis => "axis",
            SystemKey::Body => "body",
            SystemKey::Coordinate => "coordinate",
            SystemKey::Start => "start",
            SystemKey::SpeedRpm => "speed_rpm",
            SystemKey::Speed => "speed",
            SystemKey::Acceleration => "acceleration",
            SystemKey::Stiffness => "stiffness",
            SystemKey::FreeLength => "free_length",
            SystemKey::FreeAngleDeg => "free_angle_deg",
            SystemKey::Preload => "preload",
            SystemKey::Damping => "damping",
            SystemKey::Restitution => "restitution",
            SystemKey::Gravity => "gravity",
            SystemKey::Masses => "masses",
            SystemKey::SolidLength => "solid_length",
            SystemKey::FaceWidth => "face_width",
            SystemKey::Materials => "materials",
            SystemKey::Direction => "direction",
            SystemKey::ForceTable => "table",
            SystemKey::CrankPerDriver => "crank_per_driver",
            SystemKey::PeriodDeg => "period_deg",
            SystemKey::RoughnessUm(_) => "roughness_um",
            SystemKey::Rolls => "rolls",
        })
    }
}

/// Fields of `[cam]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum CamField {
    /// the whole table
    Table,
    /// `speed_rpm`
    SpeedRpm,
    /// the speed in rad/s of [`crate::cam::Cam::new`] (no file key: `speed_rpm` in files)
    Speed,
    /// `direction`
    Direction,
    /// `pivot`
    Pivot,
    /// `angular_acceleration_deg_s2`
    AngularAcceleration,
}

/// Fields of `[cam.profile]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ProfileField {
    /// the whole table (a property of the profile as a whole: its size, a cusp)
    Table,
    /// `kind`
    Kind,
    /// `points`
    Points,
    /// `points[i]`
    Point(usize),
    /// `parameterization`
    Parameterization,
    /// `center`
    Center,
    /// `radius`
    Radius,
    /// `semi_axes`
    SemiAxes,
    /// `rotation_deg`
    RotationDeg,
    /// `path`
    Path,
    /// `base_radius`
    BaseRadius,
    /// `segments`
    Segments,
    /// `nose_radius` (an arc cam's)
    NoseRadius,
    /// `lift` (an arc cam's)
    Lift,
    /// `flank_radius` (a circular-arc cam's)
    FlankRadius,
    /// `start` (an arcs-and-lines profile's first point)
    Start,
    /// `pieces`
    Pieces,
    /// `pieces[i]`, or its `to`, `centre` or `clockwise`
    Piece(usize, PieceField),
    /// `segments[i].law`, `.rise` or `.degrees`
    Segment(usize, SegmentField),
    /// `module` (a gear's)
    Module,
    /// `teeth`
    Teeth,
    /// `pressure_angle_deg`
    PressureAngle,
    /// `addendum` (factor)
    Addendum,
    /// `dedendum` (factor)
    Dedendum,
    /// `profile_shift` (coefficient)
    ProfileShift,
    /// `backlash` (thinning on the pitch circle, length)
    Backlash,
    /// `fillet_radius`
    FilletRadius,
    /// `tip_relief` (amount at the tip, length)
    TipRelief,
    /// `tip_relief_length` (along the line of action)
    TipReliefLength,
    /// `tip_relief_shape`
    TipReliefShape,
    /// `anchor` (a line's point)
    Anchor,
    /// `direction` (a line's)
    Direction,
    /// `at` (a point's place)
    At,
}

/// Fields of one motion segment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum SegmentField {
    /// `law`
    Law,
    /// `rise`
    Rise,
    /// `degrees`
    Degrees,
}

/// Keys of a piece of an `arcs-and-lines` profile.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum PieceField {
    /// the piece as a whole
    Table,
    /// `to`
    To,
    /// `centre`
    Centre,
    /// `clockwise`
    Clockwise,
}

impl PieceField {
    fn name(self) -> Option<&'static str> {
        Some(match self {
            PieceField::Table => return None,
            PieceField::To => "to",
            PieceField::Centre => "centre",
            PieceField::Clockwise => "clockwise",
        })
    }
}

/// Fields of `[follower]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum FollowerField {
    /// the whole table
    Table,
    /// `kind`
    Kind,
    /// `direction`
    Direction,
    /// `offset` (of the line of travel, or of an oscillating face)
    Offset,
    /// `roller_radius`
    RollerRadius,
    /// `pivot`
    Pivot,
    /// `arm_length`
    ArmLength,
    /// `closing`
    Closing,
    /// `initial_angle_deg`
    InitialAngle,
    /// `[follower.profile]`: the curve a general follower carries
    Profile,
}

/// Fields of `[dynamics]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum DynamicsField {
    /// the whole table
    Table,
    /// `mass`
    Mass,
    /// `inertia`
    Inertia,
    /// `spring_stiffness`
    SpringStiffness,
    /// `spring_preload`
    SpringPreload,
    /// `damping`
    Damping,
    /// `restitution`
    Restitution,
    /// `gravity`
    Gravity,
}

/// Fields of `[lubrication]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum LubricationField {
    /// the whole table
    Table,
    /// `oil`
    Oil,
    /// `roughness_um[i]` (0: the cam's, 1: the follower's)
    RoughnessUm(usize),
    /// `face_width`
    FaceWidth,
    /// `film`
    Film,
    /// `friction`
    Friction,
    /// `materials`
    Materials,
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
                if let Some(n) = c.name() {
                    p.push(Name(n));
                }
            }
            Field::Profile(f) | Field::FollowerProfile(f) | Field::FollowerConjugate(f) => {
                p.extend(match self {
                    Field::Profile(_) => [Name("cam"), Name("profile")],
                    Field::FollowerProfile(_) => [Name("follower"), Name("profile")],
                    _ => [Name("follower"), Name("conjugate")],
                });
                match f {
                    ProfileField::Point(i) => p.extend([Name("points"), Index(i)]),
                    ProfileField::Segment(i, s) => {
                        p.extend([Name("segments"), Index(i), Name(s.name())]);
                    }
                    ProfileField::Piece(i, k) => {
                        p.extend([Name("pieces"), Index(i)]);
                        p.extend(k.name().map(Name));
                    }
                    other => p.extend(other.name().map(Name)),
                }
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
                use LubricationField as L;
                match f {
                    L::Table => {}
                    L::Oil => p.push(Name("oil")),
                    L::RoughnessUm(i) => p.extend([Name("roughness_um"), Index(i)]),
                    L::FaceWidth => p.push(Name("face_width")),
                    L::Film => p.push(Name("film")),
                    L::Friction => p.push(Name("friction")),
                    L::Materials => p.push(Name("materials")),
                }
            }
            Field::GearLoads(g) => {
                p.push(Name("gear_loads"));
                use GearLoadsField as G;
                match g {
                    G::Table => {}
                    G::Torque => p.push(Name("torque")),
                    G::PowerKw => p.push(Name("power_kw")),
                    G::FaceWidth => p.push(Name("face_width")),
                    G::Materials => p.push(Name("materials")),
                }
            }
            Field::GearPair(g) => {
                p.push(Name("gear_pair"));
                use GearPairField as G;
                match g {
                    G::Table => {}
                    G::Teeth(i) => p.extend([Name("teeth"), Index(i)]),
                    G::ProfileShift(i) => p.extend([Name("profile_shift"), Index(i)]),
                    G::Module => p.push(Name("module")),
                    G::PressureAngle => p.push(Name("pressure_angle_deg")),
                    G::CentreDistance => p.push(Name("centre_distance")),
                    G::Backlash => p.push(Name("backlash")),
                    G::SpeedRpm => p.push(Name("speed_rpm")),
                    G::Direction => p.push(Name("direction")),
                }
            }
            Field::System(f) => {
                p.push(Name(f.table.name()));
                if f.table != SystemTable::Dynamics {
                    p.push(Index(f.index));
                }
                match f.key {
                    SystemKey::CurveA(c) | SystemKey::CurveB(c) => {
                        p.push(Name(if matches!(f.key, SystemKey::CurveA(_)) {
                            "curve_a"
                        } else {
                            "curve_b"
                        }));
                        match c {
                            ProfileField::Point(i) => p.extend([Name("points"), Index(i)]),
                            ProfileField::Segment(i, s) => {
                                p.extend([Name("segments"), Index(i), Name(s.name())]);
                            }
                            ProfileField::Piece(i, k) => {
                                p.extend([Name("pieces"), Index(i)]);
                                p.extend(k.name().map(Name));
                            }
                            other => p.extend(other.name().map(Name)),
                        }
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

/// One step of a key path.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Key {
    /// a table key
    Name(&'static str),
    /// an array index
    Index(usize),
}

impl CamField {
    fn name(self) -> Option<&'static str> {
        Some(match self {
            CamField::Table => return None,
            CamField::SpeedRpm => "speed_rpm",
            CamField::Speed => "speed",
            CamField::Direction => "direction",
            CamField::Pivot => "pivot",
            CamField::AngularAcceleration => "angular_acceleration_deg_s2",
        })
    }
}

impl ProfileField {
    /// Every keyed field of a profile table: the one list of its keys (their names are
    /// [`ProfileField::name`]'s; the schema's serde names are checked equal to them).
    pub const KEYED: [ProfileField; 29] = [
        ProfileField::Kind,
        ProfileField::Points,
        ProfileField::Parameterization,
        ProfileField::Center,
        ProfileField::Radius,
        ProfileField::SemiAxes,
        ProfileField::RotationDeg,
        ProfileField::Path,
        ProfileField::BaseRadius,
        ProfileField::Segments,
        ProfileField::NoseRadius,
        ProfileField::Lift,
        ProfileField::FlankRadius,
        ProfileField::Start,
        ProfileField::Pieces,
        ProfileField::Module,
        ProfileField::Teeth,
        ProfileField::PressureAngle,
        ProfileField::Addendum,
        ProfileField::Dedendum,
        ProfileField::ProfileShift,
        ProfileField::Backlash,
        ProfileField::FilletRadius,
        ProfileField::TipRelief,
        ProfileField::TipReliefLength,
        ProfileField::TipReliefShape,
        ProfileField::Anchor,
        ProfileField::Direction,
        ProfileField::At,
    ];

    /// The key's name (`None` for the table, and for indexed fields).
    pub fn name(self) -> Option<&'static str> {
        Some(match self {
            ProfileField::Table
            | ProfileField::Point(_)
            | ProfileField::Segment(..)
            | ProfileField::Piece(..) => return None,
            ProfileField::Kind => "kind",
            ProfileField::Points => "points",
            ProfileField::Parameterization => "parameterization",
            ProfileField::Center => "center",
            ProfileField::Radius => "radius",
            ProfileField::SemiAxes => "semi_axes",
            ProfileField::RotationDeg => "rotation_deg",
            ProfileField::Path => "path",
            ProfileField::BaseRadius => "base_radius",
            ProfileField::Segments => "segments",
            ProfileField::NoseRadius => "nose_radius",
            ProfileField::Lift => "lift",
            ProfileField::FlankRadius => "flank_radius",
            ProfileField::Start => "start",
            ProfileField::Pieces => "pieces",
            ProfileField::Module => "module",
            ProfileField::Teeth => "teeth",
            ProfileField::PressureAngle => "pressure_angle_deg",
            ProfileField::Addendum => "addendum",
            ProfileField::Dedendum => "dedendum",
            ProfileField::ProfileShift => "profile_shift",
            ProfileField::Backlash => "backlash",
            ProfileField::FilletRadius => "fillet_radius",
            ProfileField::TipRelief => "tip_relief",
            ProfileField::TipReliefLength => "tip_relief_length",
            ProfileField::TipReliefShape => "tip_relief_shape",
            ProfileField::Anchor => "anchor",
            ProfileField::Direction => "direction",
            ProfileField::At => "at",
        })
    }
}

impl SegmentField {
    fn name(self) -> &'static str {
        match self {
            SegmentField::Law => "law",
            SegmentField::Rise => "rise",
            SegmentField::Degrees => "degrees",
        }
    }
}

impl FollowerField {
    /// Every keyed field of `[follower]` (see [`ProfileField::KEYED`]).
    pub const KEYED: [FollowerField; 9] = [
        FollowerField::Kind,
        FollowerField::Direction,
        FollowerField::Offset,
        FollowerField::RollerRadius,
        FollowerField::Pivot,
        FollowerField::ArmLength,
        FollowerField::Closing,
        FollowerField::InitialAngle,
        FollowerField::Profile,
    ];

    /// The key's name (`None` for the table).
    pub fn name(self) -> Option<&'static str> {
        Some(match self {
            FollowerField::Table => return None,
            FollowerField::Kind => "kind",
            FollowerField::Direction => "direction",
            FollowerField::Offset => "offset",
            FollowerField::RollerRadius => "roller_radius",
            FollowerField::Pivot => "pivot",
            FollowerField::ArmLength => "arm_length",
            FollowerField::Closing => "closing",
            FollowerField::InitialAngle => "initial_angle_deg",
            FollowerField::Profile => "profile",
        })
    }
}

impl DynamicsField {
    fn name(self) -> Option<&'static str> {
        Some(match self {
            DynamicsField::Table => return None,
            DynamicsField::Mass => "mass",
            DynamicsField::Inertia => "inertia",
            DynamicsField::SpringStiffness => "spring_stiffness",
            DynamicsField::SpringPreload => "spring_preload",
            DynamicsField::Damping => "damping",
            DynamicsField::Restitution => "restitution",
            DynamicsField::Gravity => "gravity",
        })
    }
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
    }
}
