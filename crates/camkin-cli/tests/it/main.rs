//! The command's integration tests, one module per scenario (one test binary).
#![allow(clippy::unwrap_used)]

mod cli_analyze;
mod cli_arc_cams;
mod cli_bad_input;
mod cli_conjugate;
mod cli_contacts;
mod cli_engineer;
mod cli_files;
mod cli_gear_loads;
mod cli_help;
mod cli_human_output;
mod cli_lash;
mod cli_lubrication;
mod cli_mesh;
mod cli_output;
mod cli_plot;
mod cli_refusals;
mod cli_simulate;
mod cli_studio;
mod cli_study;
mod cli_synth;
mod cli_system;
mod cli_system_forces;
mod cli_system_simulate;
mod common;
mod properties;
mod studio_server;
