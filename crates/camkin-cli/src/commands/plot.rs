//! `camkin plot`: kinematics over a revolution, drawings of the mechanism, an animation.

use crate::args::{AngleList, RevolutionStep};
use crate::draw::chart::{self, Chart, Series};
use crate::draw::mechanism::{self as scene, Shape};
use crate::draw::svaj;
use crate::mechfile::BySolver;
use crate::{Failure, Loaded};
use anyhow::{anyhow, Result};
use camkin::cam::{FollowerState, Mechanism};
use camkin::table::{Per, Units};
use camkin::Point2;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

#[derive(Debug, clap::Args)]
pub struct PlotArgs {
    /// Mechanism file (TOML); without it, the paper's built-in cam.
    pub mechanism: Option<PathBuf>,
    /// Directory for the figures.
    #[arg(long, value_name = "DIR", default_value = "camkin-plot")]
    pub out: PathBuf,
    /// Cam angles (degrees) at which to draw the mechanism, comma-separated.
    #[arg(
        long,
        value_name = "A1,A2,...",
        default_value = "0,90,180,270",
        allow_hyphen_values = true
    )]
    pub at: AngleList,
    /// Angle step of the kinematic curves, degrees.
    #[arg(long, value_name = "DEG", default_value = "0.25")]
    pub step: RevolutionStep,
    /// Frames of the animation over one revolution.
    #[arg(long, value_name = "N", default_value_t = 72)]
    pub frames: usize,
    #[command(flatten)]
    pub units: crate::args::MotionUnitArgs,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
    #[command(flatten)]
    pub force: crate::out_dir::ForceArg,
}

fn rgb(c: scene::Rgb) -> RGBColor {
    RGBColor(c.0, c.1, c.2)
}

/// Draws shapes with equal axis scales in the box `(lo, hi)`.
/// Writes the drawings (`scenes[..drawings]`: `drawing_<angle>.svg/png`, one per distinct angle
/// modulo 360°) and the animation of the rest (`animation.svg`, one revolution in 6 s) into
/// `dir`, all in one box so that the scale does not jump; `what` names the angle in titles
/// (`cam angle`, `driver angle`). Returns the files written.
pub(crate) fn draw_all(
    dir: &Path,
    scenes: &[(f64, Vec<Shape>)],
    drawings: usize,
    what: &str,
    unit: &str,
    legend: &str,
) -> Result<Vec<PathBuf>, Failure> {
    let (lo, hi) = scene::bounds(scenes.iter().flat_map(|(_, s)| s.iter()));
    let pad = 0.05 * (hi - lo).norm();
    let bbox = (
        lo - camkin::Vec2::new(pad, pad),
        hi + camkin::Vec2::new(pad, pad),
    );
    let aspect = (bbox.1.y - bbox.0.y) / (bbox.1.x - bbox.0.x);
    let size = (
        800u32,
        (800.0 * aspect + 40.0).round().clamp(200.0, 2400.0) as u32,
    );
    chart::register_font();
    let mut written = Vec::new();
    // one drawing per distinct angle modulo 360°, named by it (`drawing_0.5.svg`: the name is
    // built whole, since a `.5` would be taken for an extension; 1e300 is named by its 280-ish
    // residue, not by 301 digits)
    let mut names = std::collections::BTreeSet::new();
    for (a, shapes) in scenes.iter().take(drawings) {
        let reduced = a.rem_euclid(360.0);
        // the angle's shortest form that reads back (`drawing_1e-300`, not 300 zeros)
        let text = format!("{reduced}");
        let name = if text.len() > 24 {
            format!("drawing_{reduced:e}")
        } else {
            format!("drawing_{text}")
        };
        if !names.insert(name.clone()) {
            continue; // the same angle as an earlier one: the same drawing
        }
        let title = if reduced == *a {
            format!("{what} {a}°")
        } else {
            format!("{what} {}° ≡ {reduced}°", camkin::human::human(*a))
        };
        let svg = dir.join(format!("{name}.svg"));
        let png = dir.join(format!("{name}.png"));
        chart::write_svg(&svg, size, |root| {
            draw_scene(root, shapes, bbox, &title, unit, legend)
        })
        .map_err(Failure::output)?;
        chart::write_png(&png, size, |root| {
            draw_scene(root, shapes, bbox, &title, unit, legend)
        })
        .map_err(Failure::output)?;
        written.extend([svg, png]);
    }
    let frames: Vec<Vec<Shape>> = scenes
        .iter()
        .skip(drawings)
        .map(|(_, s)| s.clone())
        .collect();
    let titles: Vec<String> = scenes
        .iter()
        .skip(drawings)
        .map(|(a, _)| format!("{what} {a:.1}° (one revolution in 6 s)"))
        .collect();
    let svg = scene::animated_svg(&frames, &titles, bbox, 6.0);
    let anim = dir.join("animation.svg");
    crate::output::write_atomic(Some(&anim), |w| Ok(w.write_all(svg.as_bytes())?))
        .map_err(Failure::output)?;
    written.push(anim);
    Ok(written)
}

pub(crate) fn draw_scene<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    shapes: &[Shape],
    (lo, hi): (Point2, Point2),
    title: &str,
    unit: &str,
    legend: &str,
) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("{e}");
    root.fill(&WHITE).map_err(e)?;
    let area = root.titled(title, ("sans-serif", 20)).map_err(e)?;
    // the legend, on one line at the foot
    let (_, h0) = area.dim_in_pixel();
    let (area, foot) = area.split_vertically(h0.saturating_sub(22));
    foot.draw(&Text::new(
        format!("to scale, lengths in {unit}{legend}"),
        (8, 4),
        ("sans-serif", 13).into_font().color(&RGBColor(80, 80, 80)),
    ))
    .map_err(e)?;
    // equal scales: grow the box to the drawing area's aspect
    let (w, h) = area.dim_in_pixel();
    let (bw, bh) = (hi.x - lo.x, hi.y - lo.y);
    let k = (bw / f64::from(w.max(1))).max(bh / f64::from(h.max(1)));
    let (cx, cy) = (0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y));
    let (hw, hh) = (0.5 * k * f64::from(w), 0.5 * k * f64::from(h));
    let mut ch = ChartBuilder::on(&area)
        .build_cartesian_2d((cx - hw)..(cx + hw), (cy - hh)..(cy + hh))
        .map_err(e)?;
    for s in shapes {
        match s {
            Shape::Polyline {
                pts,
                color,
                width,
                closed,
            } => {
                let mut v: Vec<(f64, f64)> = pts.iter().map(|p| (p.x, p.y)).collect();
                if *closed {
                    if let Some(&f) = v.first() {
                        v.push(f);
                    }
                }
                ch.draw_series(std::iter::once(PathElement::new(
                    v,
                    rgb(*color).stroke_width(*width),
                )))
                .map_err(e)?;
            }
            Shape::Circle { c, r, color, width } => {
                let v: Vec<(f64, f64)> = (0..=96)
                    .map(|k| {
                        let a = std::f64::consts::TAU * k as f64 / 96.0;
                        (c.x + r * a.cos(), c.y + r * a.sin())
                    })
                    .collect();
                ch.draw_series(std::iter::once(PathElement::new(
                    v,
                    rgb(*color).stroke_width(*width),
                )))
                .map_err(e)?;
            }
            Shape::Dot { p, color, px } => {
                ch.draw_series(std::iter::once(Circle::new(
                    (p.x, p.y),
                    *px,
                    rgb(*color).filled(),
                )))
                .map_err(e)?;
            }
        }
    }
    // a scale bar at the lower left: 1, 2 or 5 times a power of ten, at most a fifth of the width
    let span = 2.0 * hw;
    let bar = crate::draw::scale_bar(span);
    let (x0, y0) = (cx - hw + 0.04 * span, cy - hh + 0.04 * span);
    ch.draw_series(std::iter::once(PathElement::new(
        vec![(x0, y0), (x0 + bar, y0)],
        BLACK.stroke_width(3),
    )))
    .map_err(e)?;
    ch.draw_series(std::iter::once(Text::new(
        format!("{} {unit}", camkin::human::human(bar)),
        (x0, y0 + 0.015 * span),
        ("sans-serif", 14).into_font(),
    )))
    .map_err(e)?;
    Ok(())
}

/// Charts in a grid of two columns.
fn draw_panels<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, charts: &[Chart]) -> Result<()>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(|e| anyhow!("{e}"))?;
    for (area, c) in root
        .split_evenly((charts.len().div_ceil(2), 2))
        .into_iter()
        .zip(charts)
    {
        chart::draw(area, c)?;
    }
    Ok(())
}

fn kinematics(
    loaded: &Loaded,
    u: &Units,
    grid: &[f64],
    states: &[Option<FollowerState>],
    dir: &Path,
) -> Result<Vec<PathBuf>> {
    let mech = &loaded.mech;
    let (pu, vu, au, ju) = (
        format!("lift ({})", u.motion_symbol(0)),
        format!("velocity ({})", u.motion_symbol(1)),
        format!("acceleration ({})", u.motion_symbol(2)),
        format!("jerk ({})", u.motion_symbol(3)),
    );
    let travel = mech.travel().ok();
    let conv = |s: &FollowerState| u.motion(s.position, s.velocity, s.acceleration, s.jerk);
    let series = |f: &dyn Fn(&FollowerState) -> Option<f64>| -> Vec<(f64, f64)> {
        grid.iter()
            .zip(states)
            .map(|(&a, s)| (a, s.as_ref().and_then(f).unwrap_or(f64::NAN)))
            .collect()
    };
    let chart = |title: &str, unit: &str, pts: Vec<(f64, f64)>| Chart {
        title: title.into(),
        x_label: "cam angle (°)".into(),
        y_label: unit.into(),
        series: vec![Series::line(title, pts)],
        log_y: false,
        x_range: Some((0.0, 360.0)),
    };
    // the jerk jumps where the contact passes a node of a spline profile (or of the follower's
    // curve): break the line there
    let pieces = Pieces::of(mech);
    let mut jerk = Vec::with_capacity(grid.len());
    for (k, (&a, s)) in grid.iter().zip(states).enumerate() {
        let prev = if k > 0 { states[k - 1].as_ref() } else { None };
        if let (Some(p), Some(c)) = (prev, s.as_ref()) {
            if pieces.several() && pieces.at(p) != pieces.at(c) {
                jerk.push((a, f64::NAN));
            }
        }
        jerk.push((a, s.as_ref().and_then(|s| conv(s)[3]).unwrap_or(f64::NAN)));
    }
    let lift = series(&|s| travel.map(|t| u.coord_value(t.lift(s.position))));
    let vel = series(&|s| conv(s)[1]);
    let acc = series(&|s| conv(s)[2]);
    let title = svaj_title(loaded, u);
    // rounding, drawn as zero: 1e-9 of the next lower derivative's largest value times the rate
    // of the axis (a gear pair's constant speed has an acceleration of 1e-10 °/s², not a signal)
    let rate = match u.per {
        Per::S => mech.cam().speed(),
        Per::Deg => 1.0,
    };
    let largest = |p: &[(f64, f64)]| p.iter().fold(0.0, |a: f64, q| a.max(q.1.abs()));
    let res = |lower: &[(f64, f64)]| 1e-9 * largest(lower) * rate;
    let (res_v, res_a, res_j) = (res(&lift), res(&vel), res(&acc));
    let page = svaj::Page {
        title,
        panels: vec![
            svaj::Panel {
                label: pu.clone(),
                unit: u.motion_symbol(0),
                points: lift.clone(),
                resolution: 0.0,
            },
            svaj::Panel {
                label: vu.clone(),
                unit: u.motion_symbol(1),
                points: vel.clone(),
                resolution: res_v,
            },
            svaj::Panel {
                label: au.clone(),
                unit: u.motion_symbol(2),
                points: acc.clone(),
                resolution: res_a,
            },
            svaj::Panel {
                label: ju.clone(),
                unit: u.motion_symbol(3),
                points: jerk.clone(),
                resolution: res_j,
            },
        ],
        marks: marks(mech, grid, states),
        x: svaj::Page::REVOLUTION,
        x_label: "cam angle (°)".into(),
    };
    let mut written = svaj::save(&page, &dir.join("svaj"))?;
    let charts = vec![
        chart("lift", &pu, lift),
        chart("velocity", &vu, vel),
        chart("acceleration", &au, acc),
        chart(
            "jerk (breaks where the contact passes a spline node)",
            &ju,
            jerk,
        ),
        chart(
            "pressure angle",
            "pressure angle (°)",
            series(&|s| Some(s.pressure_angle().to_degrees())),
        ),
        chart(
            "cam radius of curvature at contact",
            &format!("radius of curvature ({})", u.len()),
            series(&|s| Some(s.radius_of_curvature).filter(|r| r.abs() < 1e3 * mech.size())),
        ),
    ];
    let size = (1400, 1300);
    chart::register_font();
    let svg = dir.join("kinematics.svg");
    let png = dir.join("kinematics.png");
    chart::write_svg(&svg, size, |root| draw_panels(root, &charts))?;
    chart::write_png(&png, size, |root| draw_panels(root, &charts))?;
    written.extend([svg, png]);
    Ok(written)
}

/// The SVAJ page's title: the mechanism, its follower and the cam's speed.
pub fn svaj_title(loaded: &Loaded, u: &Units) -> String {
    let mech = &loaded.mech;
    let cam = mech.cam();
    let rpm = cam.speed() * 60.0 / std::f64::consts::TAU;
    let per = match u.per {
        Per::S => "",
        Per::Deg => ", derivatives per degree of cam angle",
    };
    format!(
        "{}: SVAJ, {} follower, cam at {} rpm {}{per}",
        loaded.name,
        mech.follower().kind_name(),
        camkin::human::human((rpm * 1e6).round() / 1e6),
        match cam.direction() {
            camkin::cam::Sense::Ccw => "ccw",
            camkin::cam::Sense::Cw => "cw",
        }
    )
}

/// The breakpoints of the cam's profile and of the follower's curve (sorted): the jerk jumps
/// where the contact passes from one piece of either to the next (the named kinds' curves have
/// one piece).
struct Pieces {
    cam: Vec<f64>,
    follower: Vec<f64>,
}

impl Pieces {
    fn of(mech: &Mechanism) -> Self {
        let mut follower = mech.follower_curve().to_arc().breakpoints();
        follower.sort_by(f64::total_cmp);
        Self {
            cam: mech.cam().profile().breakpoints(),
            follower,
        }
    }

    fn several(&self) -> bool {
        self.cam.len() > 1 || self.follower.len() > 1
    }

    /// The pieces of the two curves a contact is on.
    fn at(&self, s: &FollowerState) -> (usize, usize) {
        (
            self.cam.partition_point(|&b| b <= s.cam_param),
            self.follower.partition_point(|&b| b <= s.follower_param),
        )
    }
}

/// Where the motion is discontinuous on the grid: the contact jumps (position), the contact
/// passes a node of the profile where the jerk jumps, or a motion program's junctions.
fn marks(mech: &Mechanism, grid: &[f64], states: &[Option<FollowerState>]) -> Vec<svaj::Mark> {
    let mut out = Vec::new();
    if let Some(synth) = mech.cam().synthesis() {
        for d in synth.discontinuities() {
            out.push(svaj::Mark {
                angle_deg: d.at.to_degrees().rem_euclid(360.0),
                order: d.order,
            });
        }
        return out;
    }
    let results: Vec<Result<FollowerState, camkin::cam::CamError>> = states
        .iter()
        .map(|s| s.ok_or(camkin::cam::CamError::OpenProfile))
        .collect();
    let jumps = camkin::table::contact_jumps(mech, &results, true);
    let motion: [Vec<Option<f64>>; 4] = [
        states.iter().map(|s| s.map(|s| s.position)).collect(),
        states.iter().map(|s| s.map(|s| s.velocity)).collect(),
        states.iter().map(|s| s.map(|s| s.acceleration)).collect(),
        states.iter().map(|s| s.and_then(|s| s.jerk)).collect(),
    ];
    let pieces = Pieces::of(mech);
    for k in 1..grid.len() {
        if jumps[k] {
            // the contact jumped: mark the lowest derivative of the motion that jumps with it (a
            // follower's position is continuous, its velocity jumps where the contact crosses a
            // stretch it cannot follow); none when the motion goes on smoothly (a gear's next
            // tooth pair taking over)
            if let Some(order) = jump_order(&motion, k) {
                out.push(svaj::Mark {
                    angle_deg: grid[k],
                    order,
                });
            }
        } else if let (Some(p), Some(c)) = (&states[k - 1], &states[k]) {
            // the jerk jumps at a node of either curve
            if pieces.several()
                && pieces.at(p) != pieces.at(c)
                && p.jerk.is_some()
                && c.jerk.is_some()
            {
                out.push(svaj::Mark {
                    angle_deg: 0.5 * (grid[k - 1] + grid[k]),
                    order: 3,
                });
            }
        }
    }
    out
}

/// The lowest derivative of the motion (0 position … 3 jerk) that jumps between rows `k − 1` and
/// `k`: its change there is more than four times the changes on either side (plus rounding,
/// 1e-9 of its largest value); `None` when none does. `motion[m][i]`: derivative `m` at row `i`.
fn jump_order(motion: &[Vec<Option<f64>>; 4], k: usize) -> Option<usize> {
    (0..4).find(|&m| {
        let x = &motion[m];
        let at = |i: usize| x.get(i).copied().flatten();
        let scale = x.iter().flatten().fold(0.0, |a: f64, v| a.max(v.abs()));
        let (Some(a), Some(b)) = (k.checked_sub(1).and_then(at), at(k)) else {
            return false;
        };
        let before = k.checked_sub(2).and_then(|i| Some((a - at(i)?).abs()));
        let after = at(k + 1).map(|c| (c - b).abs());
        let side = before.into_iter().chain(after).fold(0.0, f64::max);
        (b - a).abs() > 4.0 * side + 1e-9 * scale
    })
}

pub fn run(args: &PlotArgs) -> Result<(), Failure> {
    // the model picks its solver: a system file is drawn as a system
    let model = crate::mechfile::load_model(args.mechanism.as_ref(), false)?;
    let loaded = match model.by_solver(false)? {
        BySolver::General { name, stem, built } => return plot_system(args, &name, &stem, &built),
        BySolver::Cam { preset, stem, .. } => crate::Loaded::of(*preset, stem),
    };
    let angles = args.at.0.clone();
    if angles.len() > 360 {
        return Err(Failure::Input(anyhow!(
            "--at: {} drawings is more than 360",
            angles.len()
        )));
    }
    let step = args.step.deg();
    if !(1..=3600).contains(&args.frames) {
        return Err(Failure::Input(anyhow!(
            "--frames: {} must be from 1 to 3600",
            args.frames
        )));
    }
    let mech = &loaded.mech;
    let units = Units::new(
        mech,
        loaded.unit,
        args.units.angle_unit_for(mech)?,
        args.units.per,
    );
    let curve_angles = (360.0 / step).round() as usize;
    // the rows of every plotted angle are held, about 450 bytes each
    crate::refuse_large(
        &camkin::work::Work::sweep(mech, curve_angles + args.frames + angles.len(), 1)
            .with_bytes(curve_angles as f64 * 450.0),
        args.work.large,
        ", or use a coarser --step",
    )?;
    let od = crate::out_dir::OutDir::begin(&args.out, args.force.force)?;
    let dir = od.path().to_path_buf();
    let n = (360.0 / step).round() as usize;
    let even = camkin::table::AngleGrid::new(0.0, step);
    let grid: Vec<f64> = (0..n).map(|k| even.at(k)).collect();
    let thetas: Vec<f64> = grid
        .iter()
        .map(|&a| camkin::geometry::deg_to_rad(a))
        .collect();
    let states: Vec<Option<FollowerState>> = mech
        .analyze_all(&thetas)
        .into_iter()
        .map(Result::ok)
        .collect();
    let failed = states.iter().filter(|s| s.is_none()).count();
    if failed == states.len() {
        return Err(Failure::Input(anyhow!("the follower cannot be analysed at any cam angle (try `camkin analyze` for the reasons)")));
    }
    let mut written = kinematics(&loaded, &units, &grid, &states, &dir).map_err(Failure::output)?;

    // one box for every drawing and frame, so the scale does not jump
    let frame_angles: Vec<f64> = (0..args.frames)
        .map(|k| 360.0 * k as f64 / args.frames as f64)
        .collect();
    let mut scenes: Vec<(f64, Vec<Shape>)> = Vec::new();
    for &a in angles.iter().chain(&frame_angles) {
        let st = mech.analyze_deg(a).ok();
        scenes.push((
            a,
            scene::scene(mech, camkin::geometry::deg_to_rad(a), st.as_ref()),
        ));
    }
    written.extend(draw_all(
        &dir,
        &scenes,
        angles.len(),
        "cam angle",
        loaded.unit.name(),
        "; blue: the cam (the arc: its sense of rotation; the line: its 0° mark), red: the contact, green: the common normal",
    )?);
    if failed > 0 {
        crate::say!(
            "camkin: {failed} of {n} angles could not be analysed; their points are left out"
        );
    }
    od.commit().map_err(Failure::output)?;
    crate::say!(
        "camkin: wrote {} files to {}",
        written.len(),
        args.out.display()
    );
    Ok(())
}

/// Draws the system in `text` at the driver angles `--at` (`drawing_<angle>.svg/png`) and over a
/// revolution in `--frames` frames (`animation.svg`), into `--out`.
fn plot_system(
    args: &PlotArgs,
    name: &str,
    stem: &str,
    built: &camkin::spec::BuiltSystem,
) -> Result<(), Failure> {
    use crate::draw::mechanism::Shape;
    use crate::draw::system::system_scene;
    let sys = &built.system;
    let angles = args.at.0.clone();
    if angles.len() > 360 || !(1..=3600).contains(&args.frames) {
        return Err(Failure::Input(anyhow::anyhow!(
            "--at: at most 360 drawings, --frames: 1 to 3600 (given {} and {})",
            angles.len(),
            args.frames
        )));
    }
    let frames: Vec<f64> = (0..args.frames)
        .map(|k| 360.0 * k as f64 / args.frames as f64)
        .collect();
    let all: Vec<f64> = angles.iter().chain(&frames).copied().collect();
    crate::refuse_large(
        // the instants drawn and those half a degree apart between them, and the pictures
        &camkin::work::Work::system(sys, all.len() + 720).and(&camkin::work::Work::new(
            "the pictures",
            all.len() as f64 * 5e-3,
        )),
        args.work.large,
        ", or use fewer --frames",
    )?;
    let times = crate::sweep::times_of(built, name, &all)?;
    let size = sys.size();
    // the drawings at --at, then a revolution's frames, from one sweep in order through
    // instants at most half a degree of the driver apart (a contact is followed, not guessed
    // afresh after a long jump: a gear's tooth pairs hand over every pitch)
    let mut scenes: Vec<(f64, Vec<Shape>)> = Vec::new();
    let mut order: Vec<usize> = (0..all.len()).collect();
    order.sort_by(|&i, &j| times[i].total_cmp(&times[j]));
    let mut sweep = sys
        .sweep()
        .map_err(|e| Failure::Input(anyhow::anyhow!("{name}: {}", built.explain(&e))))?;
    let mut by_index: Vec<Option<Vec<Shape>>> = vec![None; all.len()];
    let per_degree =
        built.time_of(1f64.to_radians()).unwrap_or(0.0) - built.time_of(0.0).unwrap_or(0.0);
    let mut at: Option<f64> = None;
    for i in order {
        let to = times[i];
        if let Some(from) = at {
            let n = ((to - from) / (0.5 * per_degree).abs())
                .abs()
                .ceil()
                .min(1e6) as usize;
            for k in 1..n {
                let _ = sweep.step(from + (to - from) * k as f64 / n as f64);
            }
        }
        let s = sweep.step(to).map_err(|e| {
            Failure::Input(anyhow::anyhow!(
                "{name}: at {}°: {e}",
                camkin::human::human(all[i])
            ))
        })?;
        at = Some(to);
        by_index[i] = Some(system_scene(sys, &s, size));
    }
    for (i, shapes) in by_index.into_iter().enumerate() {
        scenes.push((all[i], shapes.unwrap_or_default()));
    }
    let od = crate::out_dir::OutDir::begin(&args.out, args.force.force)?;
    let what = format!("{stem} at driver angle");
    let written = draw_all(
        od.path(),
        &scenes,
        angles.len(),
        &what,
        built.length_unit.name(),
        "",
    )?;
    od.commit().map_err(Failure::output)?;
    crate::say!(
        "camkin: wrote {} files to {}",
        written.len(),
        args.out.display()
    );
    Ok(())
}

/// The file's name without its folder and extension, for titles.
#[cfg(test)]
mod tests {
    use super::jump_order;

    /// Where the contact jumped, the mark goes on the derivative that jumps: the velocity of a
    /// follower whose contact crossed a stretch it cannot follow, nothing for a gear's next tooth
    /// pair taking over smoothly (it was marked as a jump of the position on every panel).
    #[test]
    fn contact_jump_marks_the_derivative_that_jumps() {
        let n = 40;
        let smooth = |f: &dyn Fn(f64) -> f64| -> Vec<Option<f64>> {
            (0..n).map(|i| Some(f(f64::from(i) * 0.01))).collect()
        };
        // constant speed: nothing jumps
        let steady = [
            smooth(&|t| 3.0 * t),
            smooth(&|_| 3.0),
            smooth(&|_| 0.0),
            vec![None; n as usize],
        ];
        assert_eq!(jump_order(&steady, 20), None);
        // a kink of the position at row 20: the velocity jumps
        let kink = |t: f64| if t < 0.2 { t } else { 0.2 - 2.0 * (t - 0.2) };
        let kinked = [
            smooth(&kink),
            smooth(&|t| if t < 0.2 { 1.0 } else { -2.0 }),
            smooth(&|_| 0.0),
            vec![None; n as usize],
        ];
        assert_eq!(jump_order(&kinked, 20), Some(1));
        // a step of the position
        let mut stepped = steady.clone();
        stepped[0] = smooth(&|t| 3.0 * t + if t < 0.2 { 0.0 } else { 1.0 });
        assert_eq!(jump_order(&stepped, 20), Some(0));
    }
}
