//! One module per subcommand: its arguments (`clap::Args`) and its `run`.

pub mod analyze;
pub mod bench;
pub mod compare;
pub mod contacts;
pub mod deviation;
pub mod forces;
pub mod gear_loads;
mod lash_sweep;
pub mod mesh;
pub mod plot;
pub mod profile;
pub mod serve;
pub mod simulate;
pub mod synth;
