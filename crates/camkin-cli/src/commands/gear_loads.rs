//! `camkin forces GEAR.toml --torque T`: a gear pair's loads along its whole path of contact
//! (the library's [`camkin::report::GearLoads`]).

use crate::args::forces::{lubrication_request, ForcesArgs};
use crate::forces_text::num;
use crate::output::{write_atomic, write_cell_table, TableFormat};
use crate::Failure;
use anyhow::anyhow;
use camkin::gears::GearPair;
use camkin::report::{GearLoadRequest, GearLoads};
use camkin::spec::{GivenLoads, LoadInput};

/// Points along the path of contact.
const POINTS: usize = 201;

fn bad(msg: String) -> Failure {
    Failure::Input(anyhow!(msg))
}

/// The loads of the gear pair `built` (in metres, read from `name`).
pub fn run(args: &ForcesArgs, name: &str, built: &camkin::spec::Built) -> Result<(), Failure> {
    let unit = built.length_unit;
    let mech = &built.mechanism;
    let asked = match (args.torque, args.power) {
        (Some(t), _) => format!("--torque {}", camkin::human::human(t)),
        (None, Some(p)) => format!("--power {}", camkin::human::human(p)),
        (None, None) => "[gear_loads]".into(),
    };
    let Ok(pair) = GearPair::new(mech) else {
        return Err(bad(format!(
            "{asked}: {name} is not a gear pair (a [gear_pair], or an involute-gear cam driving a rotating follower carrying one): a cam mechanism's forces come from its [dynamics]"
        )));
    };
    for (given, flag) in [
        (args.margin != 0.0, "--margin"),
        (args.target_rpm.is_some(), "--target-rpm"),
        (args.allowable.is_some(), "--allowable"),
    ] {
        if given {
            return Err(bad(format!(
                "{flag}: a gear pair's loads come from --torque (the spring and jump-speed checks are a cam's)"
            )));
        }
    }
    let given = GivenLoads {
        torque: args.torque,
        power_kw: args.power,
        face_width: args.face_width,
        materials: args.materials.as_ref().map(|m| m.0.clone()),
    };
    let resolved = built.gear_loads_inputs(&given).map_err(|e| {
        let flag = match e.input {
            LoadInput::Torque => "--torque",
            LoadInput::Power => "--power",
            _ => "--face-width",
        };
        bad(match &e.value {
            Some(v) => format!("{flag} {v}: {e}"),
            None => format!("{flag}: {e}"),
        })
    })?;
    let file = built.lubrication.as_ref();
    let materials = resolved.materials.clone();
    let lubrication = lubrication_request(args, file, &materials)?;
    if let Some(l) = &lubrication {
        l.validate().map_err(|e| bad(format!("--oil: {e}")))?;
    }
    let od = crate::out_dir::OutDir::begin_if(args.out.as_deref(), args.force.force)?;
    let req = GearLoadRequest {
        torque: resolved.torque,
        face_width: resolved.face_width,
        materials,
        lubrication,
        points: POINTS,
    };
    let omega = mech.cam().speed();
    let loads = GearLoads::new(&pair, omega, &req).map_err(|e| bad(e.to_string()))?;
    crate::out!("{}", summary(&loads, name, &req, unit))?;
    if let Some(od) = od {
        let (columns, rows) = loads.table();
        write_atomic(Some(&od.path().join("gear_loads.csv")), |w| {
            write_cell_table(w, TableFormat::Csv, &columns, rows)
        })
        .map_err(Failure::output)?;
        charts(od.path(), &loads, unit).map_err(Failure::output)?;
        let dir = od.commit().map_err(Failure::output)?;
        crate::say!("camkin: wrote {}", dir.display());
    }
    Ok(())
}

fn summary(
    l: &GearLoads,
    name: &str,
    req: &GearLoadRequest,
    unit: camkin::spec::LengthUnit,
) -> String {
    let mm = |x: f64| format!("{} {}", num(x / unit.metres()), unit.name());
    let eps = (l.path[1] - l.path[0]) / l.base_pitch;
    let mut out = format!(
        "loads on {name}: torque {} N·m on the driver, normal force T/r_b1 = {} N, face width {}, {} on {}\n",
        num(req.torque),
        num(l.normal_force),
        mm(req.face_width),
        req.materials.cam.name,
        req.materials.follower.name,
    );
    out += &format!(
        "path of contact: {} long along the line of action (contact ratio {}), from the driven gear's tip to the driver's; one pair carries the whole load over its middle {}, two pairs share it equally elsewhere (rigid teeth)\n",
        mm(l.path[1] - l.path[0]),
        num(eps),
        mm(((2.0 - eps) * l.base_pitch).max(0.0)),
    );
    let at = |p: &camkin::report::PathPoint| {
        format!(
            "{}the driver's radius {}, {} pair{}",
            p.name.map_or(String::new(), |n| format!("{n}, ")),
            mm(p.radius[0]),
            p.pairs,
            if p.pairs == 1 { "" } else { "s" },
        )
    };
    if let (Some(max), Some(min)) = (&l.max_hertz, &l.min_hertz) {
        out += &format!(
            "Hertz: max {} MPa ({}), min {} MPa ({}); {} MPa at the pitch point\n",
            num(max.hertz / 1e6),
            at(max),
            num(min.hertz / 1e6),
            at(min),
            num(l.at_pitch.hertz / 1e6),
        );
    }
    out += "named points (ISO 6336-2; two rows where the pairs change):\n";
    for p in l.named() {
        out += &format!(
            "  {:<6} driver's radius {:>10}  {} pair{}  load {:>8} N  Hertz {:>8} MPa\n",
            p.name.unwrap_or(""),
            mm(p.radius[0]),
            p.pairs,
            if p.pairs == 1 { " " } else { "s" },
            num(p.load),
            if p.hertz.is_finite() {
                num(p.hertz / 1e6)
            } else {
                "—".into()
            },
        );
    }
    let first = &l.points[0];
    let last = &l.points[l.points.len() - 1];
    let z = |x: Option<f64>| x.map_or("—".to_string(), num);
    out += &format!(
        "specific sliding: driver {} at its root (radius {}), driven {} at its root (radius {}); 0 at the pitch point\n",
        z(first.specific_sliding[0]),
        mm(first.radius[0]),
        z(last.specific_sliding[1]),
        mm(last.radius[1]),
    );
    if let Some(p) = &l.min_lambda {
        let x = p.lambda.unwrap_or(f64::NAN);
        out += &format!(
            "lubrication: λ min {} at the driver's radius {} ({})\n",
            num(x),
            mm(p.radius[0]),
            camkin::lubrication::regime(x).name()
        );
    }
    if let Some(p) = &l.max_flash_temperature {
        out += &format!(
            "flash temperature (Blok): max {} K at the driver's radius {}\n",
            num(p.flash_temperature.unwrap_or(f64::NAN)),
            mm(p.radius[0])
        );
    }
    out
}

/// The loads' pictures over the path of contact (the driver's radius on the axis): Hertz and
/// the load a pair carries, and the specific sliding of each gear.
fn charts(
    dir: &std::path::Path,
    l: &GearLoads,
    unit: camkin::spec::LengthUnit,
) -> anyhow::Result<()> {
    use crate::draw::chart::{self, Chart, Series};
    let x = |p: &camkin::report::PathPoint| p.radius[0] / unit.metres();
    let series =
        |name: &str, dashed, y: &dyn Fn(&camkin::report::PathPoint) -> Option<f64>| Series {
            name: name.into(),
            points: l
                .points
                .iter()
                .map(|p| (x(p), y(p).unwrap_or(f64::NAN)))
                .collect(),
            dashed,
        };
    let x_label = format!(
        "contact radius on the driver ({}): its root (left) to its tip",
        unit.name()
    );
    chart::save(
        &Chart::new(
            "Hertz pressure along the path of contact (load shared equally where two pairs touch)",
            x_label.clone(),
            "Hertz pressure (MPa)",
            vec![series("Hertz pressure", false, &|p| {
                p.hertz.is_finite().then_some(p.hertz / 1e6)
            })],
        ),
        &dir.join("gear_hertz"),
    )?;
    chart::save(
        &Chart::new(
            "specific sliding along the path of contact",
            x_label,
            "specific sliding (1)",
            vec![
                series("driver (w1 - w2)/w1", false, &|p| p.specific_sliding[0]),
                series("driven (w2 - w1)/w2", true, &|p| p.specific_sliding[1]),
            ],
        ),
        &dir.join("gear_specific_sliding"),
    )?;
    Ok(())
}
