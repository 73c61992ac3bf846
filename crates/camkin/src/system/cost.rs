//! What one instant of a system costs, for the work estimates ([`crate::work::Work::system`])
//! and the refusal of an instant too far to reach ([`super::SystemError::TooFar`]).

use super::System;

impl System {
    /// The seconds one instant of a system's sweep takes, from what it is made of: 2e-5 s, 1e-5
    /// s a body, 5e-5 s a contact and 3.5e-4 s one with a gear's flank (its pairing searches
    /// the teeth), and the dense Newton's factorisations of its `3n × 3n` Jacobian, 1e-10 s per
    /// `(3n)³`. Measured (release, these 2-core machines): the valve train's kinematics 2.6e-5
    /// s an instant (estimate 1.5e-4), the gear train's 2e-4 warm and 3.7e-4 reached through
    /// far instants, 6e-4 on a busy machine (estimate 7.5e-4), 300 driven wheels 4.5e-2
    /// (7.6e-2), 1 000 of them 0.82
    /// s (2.7 s).
    pub fn instant_seconds(&self) -> f64 {
        let n = 3.0 * self.bodies().len() as f64;
        let contacts: f64 = self
            .contacts()
            .iter()
            .map(|c| {
                let gear = c.curve_a.as_involute_gear().is_some()
                    || c.curve_b.as_involute_gear().is_some();
                if gear {
                    3.5e-4
                } else {
                    5e-5
                }
            })
            .sum();
        2e-5 + 1e-5 * self.bodies().len() as f64 + contacts + 1e-10 * n * n * n
    }

    /// The bytes a system's analysis holds whatever its instants: its dense `3n × 3n`
    /// Jacobian, factor and the copies Newton and the dependent rows' search keep, five of
    /// 8-byte numbers (1 000 bodies measured at 300 MB, estimated 324 MB).
    pub fn held_bytes(&self) -> f64 {
        let n = 3.0 * self.bodies().len() as f64;
        5.0 * n * n * 8.0
    }
}
