//! Blok's flash temperature: the surface temperature rise in a sliding line contact.

use super::LineContact;

/// Blok's constant for a line contact whose frictional heat is distributed like the Hertz
/// pressure (semi-elliptically) over the band `2a`: `ΔT = 1.11 μ w |u₁ − u₂| /
/// ((β₁ √|u₁| + β₂ √|u₂|) √(2a))` (H. Blok, *Theoretical study of temperature rise at surfaces of
/// actual contact under oiliness lubricating conditions*, Proc. General Discussion on
/// Lubrication, IMechE, 1937, vol. 2, 222–235; as in AGMA 925-A03's flash temperature, whose
/// `0.80/√b_H` is the same constant per half-width). The exact maximum of the moving semi-elliptic
/// source at large Péclet numbers is `1.1115` (this module's tests integrate it).
pub const BLOK_CONSTANT: f64 = 1.11;

/// The half-width of the Hertz band of a line contact, `a = √(8 w R / (π E'))` (Johnson,
/// *Contact Mechanics*, 1985, eq. 4.43 with `E' = 2E*`), m; `None` where the contact carries no
/// load or its curvatures do not close.
pub fn hertz_half_width(contact: &LineContact) -> Option<f64> {
    let (r, w, e) = (
        contact.reduced_radius,
        contact.load_per_width,
        contact.effective_modulus,
    );
    (r > 0.0 && r.is_finite() && w > 0.0 && w.is_finite() && e > 0.0)
        .then(|| (8.0 * w * r / (std::f64::consts::PI * e)).sqrt())
}

/// Blok's flash temperature of `contact`, K above the bulk: the friction coefficient `mu`, the
/// two bodies' thermal coefficients `beta` (`√(k ρ c)`, W·s^½/(m²·K), in the order of the
/// contact's surface speeds). Valid where each surface's Péclet number `|u| a/(2κ)` is large
/// (above about 5: the heat has no time to spread along the surface). Zero without sliding;
/// `None` where [`hertz_half_width`] is, or where neither surface moves through the contact
/// while they slide (a heat source standing on both surfaces: no steady flash temperature).
pub fn blok_flash_temperature(contact: &LineContact, mu: f64, beta: [f64; 2]) -> Option<f64> {
    let a = hertz_half_width(contact)?;
    let [u1, u2] = contact.surface_speeds;
    let slide = (u1 - u2).abs();
    if slide == 0.0 {
        return Some(0.0);
    }
    let carry = beta[0] * u1.abs().sqrt() + beta[1] * u2.abs().sqrt();
    (carry > 0.0)
        .then(|| BLOK_CONSTANT * mu * contact.load_per_width * slide / (carry * (2.0 * a).sqrt()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn contact(u: [f64; 2]) -> LineContact {
        LineContact {
            surface_speeds: u,
            reduced_radius: 0.015,
            load_per_width: 3e5,
            effective_modulus: 226e9,
        }
    }

    /// The temperature at the trailing part of a band heat source of half-width `a` moving at
    /// `u` over a half-space of thermal coefficient `beta` at a large Péclet number: each surface
    /// point conducts heat into its depth as a one-dimensional half-space for the time it spends
    /// under the source, `T(ξ) = (1/(β √(π u))) ∫_{−a}^{ξ} q(x) / √(ξ − x) dx`
    /// (Carslaw and Jaeger, *Conduction of Heat in Solids*, 1959, §2.9); the maximum over ξ.
    fn moving_source_peak(q: impl Fn(f64) -> f64, a: f64, u: f64, beta: f64) -> f64 {
        let mut best = 0.0f64;
        for k in 0..=200 {
            let xi = -a + 2.0 * a * f64::from(k) / 200.0;
            // x = ξ − s²: the integrand's singularity removed
            let smax = (xi + a).sqrt();
            let n = 4000;
            let h = smax / f64::from(n);
            let mut sum = 0.0;
            for i in 0..n {
                let s = (f64::from(i) + 0.5) * h;
                sum += 2.0 * q(xi - s * s) * h;
            }
            best = best.max(sum / (beta * (PI * u).sqrt()));
        }
        best
    }

    /// Blok's formula against the heat conduction it summarises: the frictional heat
    /// `μ p(x) |u₁ − u₂|` of the Hertz pressure, split between the surfaces so that their peak
    /// temperatures agree (Blok's postulate), each conducting as a moving source. The peak
    /// temperature found by integration is Blok's within the rounding of his 1.11 (0.2 %).
    #[test]
    fn blok_agrees_with_the_conduction_of_a_moving_semi_elliptic_source() {
        let (u1, u2) = (7.0, 2.0);
        let (b1, b2) = (12_000.0, 9_000.0);
        let c = contact([u1, u2]);
        let mu = 0.06;
        let a = hertz_half_width(&c).unwrap();
        let blok = blok_flash_temperature(&c, mu, [b1, b2]).unwrap();
        // the Hertz pressure over the band, its mean w/(2a)
        let w = c.load_per_width;
        let p = |x: f64| 2.0 * w / (PI * a * a) * (a * a - x * x).max(0.0).sqrt();
        let heat = |x: f64| mu * p(x) * (u1 - u2).abs();
        // a fraction f of the heat into surface 1: its peak is linear in f; equal peaks
        let t1 = moving_source_peak(heat, a, u1, b1);
        let t2 = moving_source_peak(heat, a, u2, b2);
        let f = t2 / (t1 + t2);
        let peak = f * t1;
        assert!((peak - (1.0 - f) * t2).abs() < 1e-9 * peak);
        assert!(
            (blok / peak - 1.0).abs() < 2e-3,
            "Blok {blok} K, conduction {peak} K"
        );
        // the exact constant behind the rounded one
        let exact = BLOK_CONSTANT * peak / blok;
        assert!((exact - 1.1115).abs() < 5e-4, "{exact}");
    }

    /// A hand evaluation: w = 300 kN/m, R = 15 mm, E' = 226 GPa give a = √(8·3e5·0.015/(π·226e9))
    /// = 0.225176 mm; μ = 0.06, u = 7 and 2 m/s, β = 12 000 and 9 000 give ΔT = 1.11·0.06·3e5·5 /
    /// ((12 000·√7 + 9 000·√2)·√(2a)) = 105.841 K.
    #[test]
    fn blok_agrees_with_a_hand_evaluation_and_vanishes_without_sliding() {
        let c = contact([7.0, 2.0]);
        let a = hertz_half_width(&c).unwrap();
        assert!((a / 0.225176e-3 - 1.0).abs() < 5e-6, "{a}");
        let t = blok_flash_temperature(&c, 0.06, [12_000.0, 9_000.0]).unwrap();
        assert!((t / 105.841 - 1.0).abs() < 5e-6, "{t}");
        // the formula is symmetric in the bodies
        let swapped = blok_flash_temperature(&contact([2.0, 7.0]), 0.06, [9_000.0, 12_000.0]);
        assert!((swapped.unwrap() / t - 1.0).abs() < 1e-15);
        assert_eq!(
            blok_flash_temperature(&contact([3.0, 3.0]), 0.06, [1.0, 1.0]),
            Some(0.0)
        );
        // sliding with both surfaces standing still relative to the contact is not Blok's case
        let mut standing = contact([0.0, 0.0]);
        standing.surface_speeds = [0.0, -0.0];
        assert_eq!(
            blok_flash_temperature(&standing, 0.06, [1.0, 1.0]),
            Some(0.0)
        );
        let mut open = contact([1.0, 2.0]);
        open.reduced_radius = -0.01;
        assert!(blok_flash_temperature(&open, 0.06, [1.0, 1.0]).is_none());
    }
}
