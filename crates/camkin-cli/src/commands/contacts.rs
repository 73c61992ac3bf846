//! `camkin contacts`: every contact between cam and follower at a list or range of cam angles,
//! one row per contact, each with its sliding rates, normal accelerations and acceleration
//! constraint row `Φ_θ θ̈ + Φ_q q̈ = γ`; CSV or JSON.

use crate::mechfile::BySolver;
use crate::Failure;
use camkin::table::{contact_cells, contact_columns, ContactRow, Units};
use std::path::PathBuf;

#[derive(Debug, clap::Args)]
pub struct ContactsArgs {
    /// Mechanism file (TOML); without it, the paper's built-in cam. A system file gives each
    /// of its contacts at each instant of its first driver's angle, with its constraint row in
    /// its two bodies' coordinates.
    pub mechanism: Option<PathBuf>,
    #[command(flatten)]
    pub sweep: crate::args::AngleArgs,
    #[command(flatten)]
    pub table: crate::args::TableArgs,
    #[command(flatten)]
    pub work: crate::args::WorkArgs,
}

pub fn run(args: &ContactsArgs) -> Result<(), Failure> {
    let model = crate::mechfile::load_model(args.mechanism.as_ref(), false)?;
    let loaded = match model.by_solver(false)? {
        BySolver::General { name, built, .. } => return system_contacts(args, &name, &built),
        BySolver::Cam { preset, stem, .. } => crate::Loaded::of(*preset, stem),
    };
    args.table.check()?;
    let mech = &loaded.mech;
    let angles = args.sweep.or_revolution();
    crate::refuse_large(
        &camkin::work::Work::contacts(mech, angles.len()),
        args.work.large,
        ", or use fewer angles",
    )?;
    let contiguous = args.sweep.contiguous();
    let states = mech.analyze_deg_each(&angles, contiguous);
    let rows: Vec<ContactRow> = angles
        .iter()
        .zip(&states)
        .flat_map(|(&a, s)| {
            let found = s
                .as_ref()
                .map_err(Clone::clone)
                .and_then(|s| mech.contacts_at(s));
            ContactRow::of(a, &found)
        })
        .collect();
    let units = Units::plain(mech, loaded.unit);
    let columns = contact_columns(&units);
    let mut chunk = Some(rows.clone());
    args.table
        .write_rows(&columns, || chunk.take(), |r| contact_cells(r, &units))?;
    let failed = rows.iter().filter(|r| r.error.is_some()).count();
    let most = angles
        .iter()
        .map(|&a| {
            rows.iter()
                .filter(|r| r.angle_deg == a && r.error.is_none())
                .count()
        })
        .max()
        .unwrap_or(0);
    let several = angles
        .iter()
        .filter(|&&a| {
            rows.iter()
                .filter(|r| r.angle_deg == a && r.error.is_none())
                .count()
                > 1
        })
        .count();
    let plural = |n: usize| if n == 1 { "" } else { "s" };
    let (found, n) = (rows.len() - failed, angles.len());
    crate::say!(
        "camkin: {found} contact{} at {n} cam angle{}; {several} angle{} with more than one contact, at most {most} at once",
        plural(found),
        plural(n),
        plural(several),
    );
    if failed > 0 {
        crate::say!(
            "camkin: {failed} of {} angles could not be analysed; see the error column",
            angles.len()
        );
    }
    Ok(())
}

/// Every contact of the system `built` (read from `name`) at each instant, one row per contact
/// ([`camkin::table::system_contact_columns`]): its point, normal, gap, sliding rates, normal
/// accelerations with their terms and its acceleration constraint row.
fn system_contacts(
    args: &ContactsArgs,
    name: &str,
    built: &camkin::spec::BuiltSystem,
) -> Result<(), Failure> {
    use camkin::table::{system_contact_cells, system_contact_columns};
    let sys = &built.system;
    let angles = args.sweep.or_revolution();
    crate::sweep::write_sweep(
        &args.table,
        &args.work,
        name,
        built,
        &angles,
        &system_contact_columns(built),
        |a, t, s| system_contact_cells(sys, a, t, s),
    )?;
    let n = sys.contacts().len();
    crate::say!(
        "camkin: {n} contact{} at {} instant{} of {}",
        if n == 1 { "" } else { "s" },
        angles.len(),
        if angles.len() == 1 { "" } else { "s" },
        built.angle_name()
    );
    Ok(())
}
