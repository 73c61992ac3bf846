//! Pictures: line charts (`chart`) and the mechanism drawn to scale (`mechanism`).

pub mod chart;
pub mod lubrication;
pub mod mechanism;
pub mod svaj;
pub mod system;
