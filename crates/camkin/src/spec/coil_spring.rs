//! `[[coil_spring]]` of a system file: a coil spring with mass (a valve spring) as a chain of
//! lumped masses, with coil clash ([`crate::system::CoilSpring`]).
//!
//! ```toml
//! [[coil_spring]]
//! name = "valve spring"
//! bodies = ["ground", "valve"]      # its seat, the body it pushes
//! at = [[25, -70], [0, -5]]         # its ends, each in its body's frame
//! stiffness = 30.0                  # N per length: the whole spring
//! free_length = 45.333
//! mass = 0.02                       # kg, its active coils
//! masses = 8                        # lumped masses (0: massless)
//! solid_length = 24.0               # coil clash when it is this short (optional)
//! damping_ratio = 0.03              # of the first surge mode (optional, default 0)
//! ```

/// `[[coil_spring]]`.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CoilSpringSpec {
    /// its name
    pub name: String,
    /// the body its first end sits on and the body its other end pushes
    #[serde(deserialize_with = "super::pair::names")]
    pub bodies: [String; 2],
    /// its ends, each in its body's frame
    #[serde(deserialize_with = "super::pair::points")]
    pub at: [[f64; 2]; 2],
    /// the whole spring's stiffness, N per length unit
    pub stiffness: f64,
    /// length unit
    pub free_length: f64,
    /// N at the free length (default 0), a tension as a `[[spring]]`'s
    pub preload: Option<f64>,
    /// kg: the active coils' mass
    pub mass: f64,
    /// lumped masses in the chain (0: massless)
    pub masses: usize,
    /// length unit: the length at which its coils touch (optional)
    pub solid_length: Option<f64>,
    /// the first surge mode's damping ratio, from 0 (the default: undamped) to 1; a damper
    /// beside each segment, stiffness-proportional
    /// ([`crate::system::CoilSpring::damping_ratio`])
    pub damping_ratio: Option<f64>,
}
