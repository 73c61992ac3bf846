//! The library's integration tests, one module per scenario (one test binary builds much faster
//! than one per file).
#![allow(clippy::unwrap_used)]

mod arc_cams;
mod benchmark_andrews;
mod benchmark_n_four_bar;
mod build_work;
mod circle_followers;
mod common;
mod conjugate;
mod conjugate_forces;
mod contact_general;
mod contact_jumps;
mod corner_contacts;
mod dynamics_cam_energy;
mod dynamics_contact;
mod dynamics_energy;
mod dynamics_initial_state;
mod dynamics_lash;
mod dynamics_lash_adjuster;
mod dynamics_liftoff;
mod dynamics_loads;
mod dynamics_reduced;
mod dynamics_slider_crank;
mod dynamics_stiff;
mod dynamics_system;
mod dynamics_system_cam;
mod dynamics_system_centre;
#[cfg(feature = "text")]
mod dynamics_valve_train;
mod eccentric_circle;
mod ellipse_flat;
mod extremes;
mod forces;
mod gear_limits;
mod gear_loads;
mod gear_mesh;
#[cfg(feature = "text")]
mod gear_pair_files;
mod general_follower;
mod hyperdual_selfcheck;
mod interpolation_study;
mod jerk;
mod layout;
mod lift_tables;
mod lubrication;
mod motion_closed_form;
mod no_follow;
mod oscillating_branch;
mod paper_cam;
mod point_follower;
mod pressure_angle;
mod properties;
mod run_work;
mod several_contacts;
mod spec;
mod spline_finite_differences;
mod support_check;
mod sweep;
mod synthesis_round_trip;
mod system_cam;
#[cfg(feature = "text")]
mod system_files;
#[cfg(feature = "text")]
mod system_jerk;
mod system_linkages;
mod system_lubrication;
#[cfg(feature = "text")]
mod system_presets;
mod system_valve_train;
mod thin_geometry;
