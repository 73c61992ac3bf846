//! Pictures: line charts (`chart`), the pages of a simulated system (`simulation`) and the
//! mechanism drawn to scale (`mechanism`, `system`: the studio's scenes,
//! [`camkin_studio::scene`]).

pub use camkin_studio::scene::{mechanism, scale_bar, system};

pub mod chart;
pub mod lubrication;
pub mod simulation;
pub mod svaj;
