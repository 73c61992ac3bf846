//! `[gear_pair]`: a spur gear pair in a gear engineer's words — teeth, module, pressure angle,
//! profile shifts, centre distance (the tight mesh's by default), backlash — with nothing to copy
//! from an example (no pivot, closing sense or initial angle). It is read as the cam-follower
//! mechanism every gear command takes: the driver (gear 1) is the cam, the driven gear a rotating
//! follower on its centre, a space of it facing the driver's tooth 0 on the line of centres, its
//! load turning it against its motion; backlash is the driven gear's coast flanks thinned by it
//! (a conjugate follower). Errors name the `gear_pair` key that was written.
//!
//! ```toml
//! length_unit = "mm"
//! [gear_pair]
//! teeth = [20, 42]
//! module = 2.0
//! pressure_angle_deg = 20.0      # default 20
//! profile_shift = [0.2, -0.1]    # default [0, 0]
//! centre_distance = 62.5         # default: the tight mesh's (no backlash) for these shifts
//! backlash = 0.05                # default 0: the coast flanks' play on the pitch circle
//! speed_rpm = 1000.0             # the driver's
//! direction = "ccw"              # the driver's (default ccw)
//! ```

use super::build::SpecError;
use super::{CamSpec, DynamicsSpec, FollowerSpec, MechanismSpec, ProfileSpec};
use crate::cam::Sense;
use crate::curve::{InvoluteGear, InvoluteGearSpec};
use crate::field::{CamField, Field, FollowerField, GearPairField, ProfileField};

/// A gear-pair file.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GearPairFile {
    /// the unit of every length (required)
    pub length_unit: Option<String>,
    /// `[gear_pair]`
    pub gear_pair: GearPairSpec,
    /// `[dynamics]`: the driven gear's (its `inertia`; `spring_preload` is the load torque)
    pub dynamics: Option<DynamicsSpec>,
    /// `[lubrication]`: the flanks' lubrication along the path of contact
    pub lubrication: Option<super::LubricationSpec>,
    /// `[gear_loads]`: the torque on the driver and the face width
    pub gear_loads: Option<super::GearLoadsSpec>,
}

/// `[gear_pair]`.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GearPairSpec {
    /// the driver's and the driven gear's numbers of teeth
    #[serde(deserialize_with = "super::pair::counts")]
    pub teeth: [u32; 2],
    /// the module (length)
    pub module: f64,
    /// degrees (default 20)
    pub pressure_angle_deg: Option<f64>,
    /// each gear's profile shift coefficient (default 0)
    #[serde(default, deserialize_with = "super::pair::option")]
    pub profile_shift: Option<[f64; 2]>,
    /// the centre distance (length; default the tight mesh's for these shifts)
    pub centre_distance: Option<f64>,
    /// the play on the pitch circle (length; default 0): the driven gear's coast flanks
    pub backlash: Option<f64>,
    /// the driver's speed, rpm
    pub speed_rpm: f64,
    /// the driver's sense (default ccw)
    pub direction: Option<Sense>,
}

/// A field of the mechanism a gear pair is read as, named by the `gear_pair` key it came from.
pub(super) fn gear_field(f: Field) -> Field {
    use GearPairField as G;
    let gear = |p: ProfileField, i: usize| match p {
        ProfileField::Module => G::Module,
        ProfileField::Teeth => G::Teeth(i),
        ProfileField::PressureAngle => G::PressureAngle,
        ProfileField::ProfileShift => G::ProfileShift(i),
        ProfileField::Backlash => G::Backlash,
        _ => G::Table,
    };
    Field::GearPair(match f {
        Field::Profile(p) => gear(p, 0),
        Field::FollowerProfile(p) | Field::FollowerConjugate(p) => gear(p, 1),
        Field::Cam(CamField::SpeedRpm | CamField::Speed) => G::SpeedRpm,
        Field::Cam(CamField::Direction) => G::Direction,
        Field::Follower(FollowerField::Pivot) => G::CentreDistance,
        Field::Dynamics(_) | Field::LengthUnit | Field::Lubrication(_) | Field::GearLoads(_) => {
            return f
        }
        _ => G::Table,
    })
}

impl GearPairFile {
    /// The mechanism this pair is read as (its build's errors name the `gear_pair` keys).
    pub fn to_mechanism(&self) -> Result<MechanismSpec, SpecError> {
        let g = &self.gear_pair;
        let alpha = g.pressure_angle_deg.unwrap_or(20.0);
        let shifts = g.profile_shift.unwrap_or([0.0, 0.0]);
        let gear = |i: usize, backlash: Option<f64>| ProfileSpec {
            kind: "involute-gear".into(),
            module: Some(g.module),
            teeth: Some(g.teeth[i]),
            pressure_angle_deg: Some(alpha),
            profile_shift: (shifts[i] != 0.0).then_some(shifts[i]),
            backlash,
            ..Default::default()
        };
        let centre = match g.centre_distance {
            Some(a) => a,
            None => {
                // the tight mesh, from the gears as the file gives them; a gear that cannot be
                // made is reported by the mechanism's build, at its key (the standard distance
                // stands in meanwhile)
                let built = |i: usize| {
                    let mut s = InvoluteGearSpec::new(g.module, g.teeth[i], alpha.to_radians());
                    s.profile_shift = shifts[i];
                    InvoluteGear::new(s).ok()
                };
                match (built(0), built(1)) {
                    (Some(a), Some(b)) => crate::gears::tight_mesh_distance(&a, &b),
                    _ => 0.5 * g.module * (f64::from(g.teeth[0]) + f64::from(g.teeth[1])),
                }
            }
        };
        // a size the file did not write, derived from the module: beyond the sizes the
        // computation takes it is the module's fault, named as written
        if g.centre_distance.is_none() && !(1e-100..=1e100).contains(&centre.abs()) {
            return Err(SpecError::Invalid {
                field: Field::GearPair(GearPairField::Module),
                value: crate::human::human(g.module),
                reason: format!(
                    "gives a centre distance of {} (the module times the teeth's half sum), beyond the sizes the computation takes (1e-100 to 1e100)",
                    crate::human::human(centre)
                ),
            });
        }
        let direction = g.direction.unwrap_or(Sense::Ccw);
        let z2 = f64::from(g.teeth[1]).max(1.0);
        Ok(MechanismSpec {
            length_unit: self.length_unit.clone(),
            cam: CamSpec {
                speed_rpm: g.speed_rpm,
                direction: Some(direction),
                profile: gear(0, None),
                ..Default::default()
            },
            follower: FollowerSpec {
                kind: "rotating".into(),
                pivot: Some([centre, 0.0]),
                // the load resists the driven gear's motion: it turns it the driver's way
                closing: Some(direction),
                // a space of the driven gear faces the driver's tooth 0 on the line of centres
                initial_angle_deg: Some(180.0 + 180.0 / z2),
                profile: Some(Box::new(gear(1, None))),
                conjugate: g
                    .backlash
                    .filter(|&b| b != 0.0)
                    .map(|b| Box::new(gear(1, Some(b)))),
                ..Default::default()
            },
            dynamics: self.dynamics.clone(),
            lubrication: self.lubrication.clone(),
            gear_loads: self.gear_loads.clone(),
            from_gear_pair: true,
        })
    }
}
