//! What the studio answers, as the page reads it (JSON): the series over the angles, the
//! drawings, the checks and events placed at their angles, the forces, the interpolation study.

use crate::scene::mechanism::Shape;
use serde::Serialize;

/// A number series over the cam angles, with its name and unit.
#[derive(Debug, Serialize)]
pub struct Series {
    /// short key (`acceleration`)
    pub key: String,
    /// what a person reads (`acceleration`)
    pub label: String,
    /// its unit (`cm/s²`)
    pub unit: String,
    /// one value per angle; `null` where it could not be computed (or is infinite)
    pub values: Vec<Option<f64>>,
    /// magnitudes below this are rounding (an ideal gear's zero acceleration): the page shows
    /// them as 0 and draws the plot on a span that shows them as zero
    #[serde(skip_serializing_if = "Option::is_none")]
    pub resolution: Option<f64>,
}

/// Polylines longer than this, closed, are drawn once in the body frame ([`ShapeOut::Curve`]).
pub(crate) const SHARED_POINTS: usize = 500;

/// A shape of the drawing in world coordinates.
#[derive(Debug, Serialize)]
#[serde(tag = "t", rename_all = "lowercase")]
pub enum ShapeOut {
    /// a polyline
    Line {
        pts: Vec<[f64; 2]>,
        color: String,
        width: u32,
        /// sent only when true (the page reads an absent `closed` as open)
        #[serde(skip_serializing_if = "std::ops::Not::not")]
        closed: bool,
    },
    /// a circle
    Circle {
        c: [f64; 2],
        r: f64,
        color: String,
        width: u32,
    },
    /// a dot of a size in pixels
    Dot { p: [f64; 2], color: String, px: u32 },
    /// a closed curve of the follower, drawn once in its body frame (`Analysis::curves[i]`) and
    /// placed at `pose` (origin and angle, rad) in each frame: a carried gear or spline would
    /// otherwise repeat thousands of points in every frame
    Curve {
        i: usize,
        pose: [f64; 3],
        color: String,
        width: u32,
    },
}

/// A colour as the page's canvas reads it, in its shortest form (`#3c3c3c`).
pub fn rgb(c: (u8, u8, u8)) -> String {
    format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2)
}

impl From<Shape> for ShapeOut {
    fn from(s: Shape) -> Self {
        match s {
            Shape::Polyline {
                pts,
                color,
                width,
                closed,
            } => ShapeOut::Line {
                pts: pts.iter().map(|p| [p.x, p.y]).collect(),
                color: rgb(color),
                width,
                closed,
            },
            Shape::Circle { c, r, color, width } => ShapeOut::Circle {
                c: [c.x, c.y],
                r,
                color: rgb(color),
                width,
            },
            Shape::Dot { p, color, px } => ShapeOut::Dot {
                p: [p.x, p.y],
                color: rgb(color),
                px,
            },
        }
    }
}

/// The mechanism at one cam angle.
#[derive(Debug, Serialize)]
pub struct Frame {
    /// the cam frame's pose: origin and angle (rad): a cam point `r` is at `origin + R(angle) r`
    pub cam: [f64; 3],
    /// the contact point, world frame (absent where the angle failed)
    pub contact: Option<[f64; 2]>,
    /// the common normal, world frame
    pub normal: Option<[f64; 2]>,
    /// the follower drawn from its model
    pub follower: Vec<ShapeOut>,
}

/// A design check, marked at its cam angles.
#[derive(Debug, Serialize)]
pub struct Check {
    /// which check (`pressure-angle`, `undercut`, `jumps`, `analysed`, `round-trip`, …)
    pub kind: camkin::report::Check,
    /// the check passed (a statement of a value) or failed
    pub ok: bool,
    /// what a person reads
    pub message: String,
    /// cam angles (degrees) to mark
    pub angles_deg: Vec<f64>,
    /// stretches of the profile to mark, cam frame
    pub stretches: Vec<Vec<[f64; 2]>>,
}

/// An event of a simulation (an impact), at its driver angle.
#[derive(Debug, Serialize)]
pub struct Event {
    /// what a person reads
    pub message: String,
    /// the driver's angle, degrees
    pub angle_deg: f64,
}

/// A warning from the file (uneven nodes), placed.
#[derive(Debug, Serialize)]
pub struct Placed {
    /// the message
    pub message: String,
    /// 1-based line and column
    pub line: Option<usize>,
    /// 1-based column
    pub column: Option<usize>,
}

/// Forces under permanent contact at any constant speed: the page evaluates
/// `F = (c2 ω² + c1 ω + c0) / lever` for its speed slider (see
/// [`camkin::report::ForceReport::coefficients`]).
#[derive(Debug, Serialize)]
pub struct DynamicsOut {
    /// the file's cam speed, rpm
    pub rpm: f64,
    /// per angle `[c2, c1, c0, lever]` (SI; `null` where the angle failed)
    pub coefficients: Vec<Option<[f64; 4]>>,
    /// the lowest constant speed at which the contact force reaches zero somewhere, rpm (`null`:
    /// never)
    pub jump_rpm: Option<f64>,
    /// the cam angle where it happens first, degrees
    pub jump_angle_deg: Option<f64>,
    /// the force's unit (`N`)
    pub unit: &'static str,
    /// the lubrication at the file's speed, when the file has `[lubrication]`
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lubrication: Option<LubricationOut>,
}

/// The lubrication the force panel draws (the file's `[lubrication]`, at the file's speed).
#[derive(Debug, Serialize)]
pub struct LubricationOut {
    /// λ per angle (`null` where the contact carries nothing or is not a line contact)
    pub lambda: Vec<Option<f64>>,
    /// the regime per angle: 0 boundary, 1 mixed, 2 full film
    pub regime: Vec<Option<u8>>,
    /// the minimum film per angle, µm
    pub film_minimum_um: Vec<Option<f64>>,
    /// Blok's flash temperature per angle, K
    pub flash_temperature_k: Vec<Option<f64>>,
    /// the angles where the entrainment reverses, degrees
    pub entrainment_reversals_deg: Vec<f64>,
    /// the smallest λ and its angle (degrees)
    pub min_lambda: Option<[f64; 2]>,
    /// the largest flash temperature (K) and its angle (degrees)
    pub max_flash_k: Option<[f64; 2]>,
    /// the friction's mean power, W, and mean torque on the camshaft, N·m
    pub friction: [f64; 2],
}

/// A gear pair's loads along its whole path of contact (the file's `[gear_loads]`, and its
/// `[lubrication]`), over the contact's radius on the driver.
#[derive(Debug, Serialize)]
pub struct GearLoadsOut {
    /// the file's length unit
    pub unit: &'static str,
    /// the torque on the driver, N·m
    pub torque: f64,
    /// the normal force `T/r_b1`, N
    pub normal_force: f64,
    /// the face width, in the file's unit
    pub face_width: f64,
    /// the contact ratio (the path's length over the base pitch)
    pub contact_ratio: f64,
    /// the contact's radius on the driver at each point, the file's unit, its root to its tip
    pub radius: Vec<f64>,
    /// the tooth pairs in contact at each point
    pub pairs: Vec<u32>,
    /// the load on the pair, N
    pub load: Vec<f64>,
    /// Hertz's maximum pressure, MPa
    pub hertz_mpa: Vec<Option<f64>>,
    /// the driver's and the driven gear's specific sliding
    pub specific_sliding: [Vec<Option<f64>>; 2],
    /// λ at each point (with `[lubrication]`)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lambda: Option<Vec<Option<f64>>>,
    /// the regime at each point: 0 boundary, 1 mixed, 2 full film (with `[lubrication]`)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub regime: Option<Vec<Option<u8>>>,
    /// Blok's flash temperature, K (with `[lubrication]`)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub flash_temperature_k: Option<Vec<Option<f64>>>,
    /// the pitch point: the driver's radius and the Hertz pressure there (MPa)
    pub pitch: [f64; 2],
    /// the largest Hertz pressure (MPa) and its radius
    pub max_hertz: Option<[f64; 2]>,
    /// the smallest λ and its radius
    pub min_lambda: Option<[f64; 2]>,
    /// the largest flash temperature (K) and its radius
    pub max_flash_k: Option<[f64; 2]>,
}

/// The analysis the studio shows.
#[derive(Debug, Serialize)]
pub struct Analysis {
    /// the file's name
    pub name: String,
    /// the file's length unit
    pub length_unit: &'static str,
    /// the follower swings on an arm (its coordinate is an angle)
    pub oscillating: bool,
    /// cam speed, rpm
    pub rpm: f64,
    /// the cam angle step, degrees
    pub step_deg: f64,
    /// the cam angles, degrees
    pub angles_deg: Vec<f64>,
    /// lift, velocity, acceleration, jerk, pressure angle, radius of curvature
    pub series: Vec<Series>,
    /// the drawing at every angle
    pub frames: Vec<Frame>,
    /// the follower's closed curves in its body frame, which frames place by their pose
    pub curves: Vec<Vec<[f64; 2]>>,
    /// the cam profile in the cam frame, closed polyline
    pub profile: Vec<[f64; 2]>,
    /// the spline's nodes (cam frame): draggable when `nodes_editable`
    pub nodes: Vec<[f64; 2]>,
    /// the nodes are the file's inline `cam.profile.points`
    pub nodes_editable: bool,
    /// the cam's axis, world frame
    pub pivot: [f64; 2],
    /// the drawing's extent over the revolution, `[xmin, ymin, xmax, ymax]`
    pub extent: [f64; 4],
    /// design checks
    pub checks: Vec<Check>,
    /// warnings from the file
    pub warnings: Vec<Placed>,
    /// angles that could not be analysed, and the first reason
    pub failed: usize,
    /// the first failure's message
    pub first_error: Option<String>,
    /// forces, when the file has `[dynamics]`
    pub dynamics: Option<DynamicsOut>,
    /// a gear pair's loads along its path of contact, when the file has `[gear_loads]`
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gear_loads: Option<GearLoadsOut>,
    /// a system file (bodies, joints, contacts): no cam profile, nodes, checks or study
    pub system: bool,
    /// a system simulated (its file has `[dynamics]`): the frames and series are its
    /// simulation's, and `events` its impacts
    pub simulated: bool,
    /// a simulated system's impacts, for people, at their driver angles
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub events: Vec<Event>,
    /// server time for this analysis, ms
    pub server_ms: f64,
}

/// Cam angles of one revolution in steps of `step_deg`.
pub fn revolution(step_deg: f64) -> Vec<f64> {
    let n = (360.0 / step_deg).round() as usize;
    let grid = camkin::table::AngleGrid::new(0.0, step_deg);
    (0..n).map(|k| grid.at(k)).collect()
}

/// The interpolation study (the paper's section 3) at `step_deg` for node counts `nodes`.
#[derive(Debug, Serialize)]
pub struct Compare {
    /// cam angles, degrees
    pub angles_deg: Vec<f64>,
    /// the acceleration's unit
    pub unit: String,
    /// the exact acceleration
    pub exact: Vec<Option<f64>>,
    /// one run per node count
    pub runs: Vec<CompareRun>,
    /// server time, ms
    pub server_ms: f64,
    /// the acceleration's natural scale (at least ω times the velocity's), in `unit`: the
    /// relative errors' scale when the exact acceleration is zero but for rounding
    pub scale: f64,
    /// why there is no study (a motion that does not repeat every revolution), when there is none
    pub refused: Option<String>,
}

/// One node count of the study.
#[derive(Debug, Serialize)]
pub struct CompareRun {
    /// nodal points per revolution
    pub nodes: usize,
    /// the interpolated acceleration
    pub acceleration: Vec<Option<f64>>,
    /// |a_N − a| / max |a|
    pub rel_error: Vec<Option<f64>>,
    /// largest relative error
    pub max_rel_error: f64,
    /// mean relative error
    pub mean_rel_error: f64,
}

/// A table's column names and its rows of cells.
pub type CellTable = (Vec<String>, Vec<Vec<camkin::table::Cell>>);
