//! Mechanism files (TOML): the schema of the README, turned into a [`camkin::cam::Mechanism`].
//!
//! Lengths are in any one unit; angles in degrees. Unknown fields, and fields that do not belong to
//! the chosen `kind`, are errors.

use anyhow::{anyhow, Context, Result};
use camkin::cam::{Cam, Follower, Mechanism, Sense};
use camkin::curve::{read_points_file, Circle, ClosedSpline, Curve, Ellipse, Parameterization};
use camkin::{Point2, Vec2};
use serde::Deserialize;
use std::path::Path;
use std::sync::Arc;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MechanismFile {
    pub cam: CamSpec,
    pub follower: FollowerSpec,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CamSpec {
    /// rpm, > 0
    pub speed_rpm: f64,
    #[serde(default)]
    pub direction: SenseSpec,
    #[serde(default)]
    pub pivot: [f64; 2],
    /// optional constant angular acceleration, degrees/s², in the cam's direction of motion
    #[serde(default)]
    pub angular_acceleration_deg_s2: f64,
    pub profile: ProfileSpec,
}

#[derive(Debug, Deserialize, Default, Clone, Copy)]
#[serde(rename_all = "lowercase")]
pub enum SenseSpec {
    #[default]
    Ccw,
    Cw,
}

impl From<SenseSpec> for Sense {
    fn from(s: SenseSpec) -> Self {
        match s {
            SenseSpec::Ccw => Sense::Ccw,
            SenseSpec::Cw => Sense::Cw,
        }
    }
}

#[derive(Debug, Deserialize, Default, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
pub enum ParamSpec {
    #[default]
    Uniform,
    ChordLength,
}

impl From<ParamSpec> for Parameterization {
    fn from(p: ParamSpec) -> Self {
        match p {
            ParamSpec::Uniform => Parameterization::Uniform,
            ParamSpec::ChordLength => Parameterization::ChordLength,
        }
    }
}

#[derive(Debug, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum ProfileSpec {
    Spline {
        points: Vec<[f64; 2]>,
        #[serde(default)]
        parameterization: ParamSpec,
    },
    Circle {
        center: [f64; 2],
        radius: f64,
    },
    Ellipse {
        center: [f64; 2],
        semi_axes: [f64; 2],
        #[serde(default)]
        rotation_deg: f64,
    },
    PointsFile {
        path: String,
        #[serde(default)]
        parameterization: ParamSpec,
    },
}

fn default_direction() -> [f64; 2] {
    [1.0, 0.0]
}

#[derive(Debug, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum FollowerSpec {
    TranslatingFlat {
        #[serde(default = "default_direction")]
        direction: [f64; 2],
    },
    TranslatingRoller {
        #[serde(default = "default_direction")]
        direction: [f64; 2],
        #[serde(default)]
        offset: f64,
        roller_radius: f64,
    },
    TranslatingKnife {
        #[serde(default = "default_direction")]
        direction: [f64; 2],
        #[serde(default)]
        offset: f64,
    },
    OscillatingFlat {
        pivot: [f64; 2],
        #[serde(default)]
        offset: f64,
        #[serde(default = "default_closing")]
        closing: SenseSpec,
        #[serde(default)]
        initial_angle_deg: f64,
    },
    OscillatingRoller {
        pivot: [f64; 2],
        arm_length: f64,
        roller_radius: f64,
        #[serde(default = "default_closing")]
        closing: SenseSpec,
        #[serde(default)]
        initial_angle_deg: f64,
    },
}

fn default_closing() -> SenseSpec {
    SenseSpec::Cw
}

fn pt(p: [f64; 2]) -> Point2 {
    Point2::new(p[0], p[1])
}

/// Reads and builds a mechanism file; every error is bad input (exit code 2).
pub fn load(path: &Path) -> Result<Mechanism> {
    let text = std::fs::read_to_string(path)
        .with_context(|| format!("cannot read mechanism file {}", path.display()))?;
    let spec: MechanismFile =
        toml::from_str(&text).map_err(|e| anyhow!("{}: {e}", path.display()))?;
    build(&spec, path.parent().unwrap_or(Path::new(".")))
        .with_context(|| format!("invalid mechanism file {}", path.display()))
}

/// Builds a mechanism from its parsed file; `base` resolves a relative points-file path.
pub fn build(spec: &MechanismFile, base: &Path) -> Result<Mechanism> {
    let profile: Arc<dyn Curve> = match &spec.cam.profile {
        ProfileSpec::Spline {
            points,
            parameterization,
        } => {
            let nodes: Vec<Point2> = points.iter().copied().map(pt).collect();
            Arc::new(
                ClosedSpline::with_parameterization(&nodes, (*parameterization).into())
                    .context("in [cam.profile] points")?,
            )
        }
        ProfileSpec::Circle { center, radius } => {
            Arc::new(Circle::new(pt(*center), *radius).context("in [cam.profile]")?)
        }
        ProfileSpec::Ellipse {
            center,
            semi_axes,
            rotation_deg,
        } => Arc::new(
            Ellipse::new(
                pt(*center),
                semi_axes[0],
                semi_axes[1],
                rotation_deg.to_radians(),
            )
            .context("in [cam.profile]")?,
        ),
        ProfileSpec::PointsFile {
            path,
            parameterization,
        } => {
            let full = base.join(path);
            let nodes = read_points_file(&full).context("in [cam.profile] path")?;
            Arc::new(
                ClosedSpline::with_parameterization(&nodes, (*parameterization).into())
                    .with_context(|| format!("in points file {}", full.display()))?,
            )
        }
    };
    let cam = Cam::from_rpm(
        profile,
        pt(spec.cam.pivot),
        spec.cam.direction.into(),
        spec.cam.speed_rpm,
    )?
    .with_angular_acceleration(spec.cam.angular_acceleration_deg_s2.to_radians())?;
    let v = |d: [f64; 2]| Vec2::new(d[0], d[1]);
    let follower = match spec.follower {
        FollowerSpec::TranslatingFlat { direction } => Follower::TranslatingFlat {
            direction: v(direction),
        },
        FollowerSpec::TranslatingRoller {
            direction,
            offset,
            roller_radius,
        } => Follower::TranslatingRoller {
            direction: v(direction),
            offset,
            roller_radius,
        },
        FollowerSpec::TranslatingKnife { direction, offset } => Follower::TranslatingKnife {
            direction: v(direction),
            offset,
        },
        FollowerSpec::OscillatingFlat {
            pivot,
            offset,
            closing,
            initial_angle_deg,
        } => Follower::OscillatingFlat {
            pivot: pt(pivot),
            face_offset: offset,
            closing: closing.into(),
            initial_angle: initial_angle_deg.to_radians(),
        },
        FollowerSpec::OscillatingRoller {
            pivot,
            arm_length,
            roller_radius,
            closing,
            initial_angle_deg,
        } => Follower::OscillatingRoller {
            pivot: pt(pivot),
            arm_length,
            roller_radius,
            closing: closing.into(),
            initial_angle: initial_angle_deg.to_radians(),
        },
    };
    Ok(Mechanism::new(cam, follower)?)
}

/// The paper's mechanism (section 3): nine-node spline cam (cm), 1000 rpm ccw, translating
/// flat-faced follower along +x. `revised` moves the right-extreme node from (5, 0) to (4.2, 0).
pub const PAPER_TOML: &str = include_str!("../../../examples/paper.toml");

/// The built-in paper mechanism.
pub fn paper() -> Mechanism {
    let spec: MechanismFile = toml::from_str(PAPER_TOML).expect("built-in mechanism parses");
    build(&spec, Path::new(".")).expect("built-in mechanism is valid")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn built_in_paper_mechanism_is_the_papers() {
        let m = paper();
        assert_eq!(m.follower().kind_name(), "translating-flat");
        let s = m.analyze(0.0).expect("analysis");
        assert!((s.position - 5.0).abs() < 1e-12);
    }

    #[test]
    fn unknown_and_misplaced_fields_are_rejected() {
        let bad = PAPER_TOML.replace("direction = [1.0, 0.0]", "roller_radius = 1.0");
        let e = toml::from_str::<MechanismFile>(&bad)
            .unwrap_err()
            .to_string();
        assert!(e.contains("roller_radius"), "{e}");
        let bad = PAPER_TOML.replace("kind = \"spline\"", "kind = \"blob\"");
        let e = toml::from_str::<MechanismFile>(&bad)
            .unwrap_err()
            .to_string();
        assert!(e.contains("blob") && e.contains("line"), "{e}");
    }
}
