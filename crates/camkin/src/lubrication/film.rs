//! The elastohydrodynamic film of a line contact: central and minimum thickness by the
//! published curve fits.

use super::{LineContact, Lubricant};

/// Which curve fit gives the film thickness of a line contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum FilmFormula {
    /// Dowson and Higginson's minimum film, `H_min = 2.65 U^0.70 G^0.54 W^−0.13` (Dowson and
    /// Higginson, *Elasto-hydrodynamic Lubrication*, SI ed., Pergamon 1977), with Dowson and
    /// Toyoda's central film `H_c = 3.06 U^0.69 G^0.56 W^−0.10` (Proc. 5th Leeds–Lyon Symposium,
    /// 1979); `H = h/R`
    #[default]
    DowsonHigginson,
    /// Pan and Hamrock's line-contact fits, `H_min = 1.714 U^0.694 G^0.568 W^−0.128` and
    /// `H_c = 2.922 U^0.692 G^0.470 W^−0.166` (ASME J. Tribology 111, 1989, 246–251; Hamrock,
    /// Schmid and Jacobson 2004, §21.5): Hamrock's counterpart, for line contacts, of the
    /// Hamrock–Dowson point-contact formula
    Hamrock,
}

impl FilmFormula {
    /// The name in files and flags.
    pub fn name(self) -> &'static str {
        match self {
            Self::DowsonHigginson => "dowson-higginson",
            Self::Hamrock => "hamrock",
        }
    }

    /// Every formula.
    pub const ALL: [FilmFormula; 2] = [Self::DowsonHigginson, Self::Hamrock];

    /// `(k, a_U, a_G, a_W)` of `H = k U^a_U G^a_G W^a_W`: the minimum film's, the central film's.
    fn fits(self) -> [(f64, f64, f64, f64); 2] {
        match self {
            Self::DowsonHigginson => [(2.65, 0.70, 0.54, -0.13), (3.06, 0.69, 0.56, -0.10)],
            Self::Hamrock => [(1.714, 0.694, 0.568, -0.128), (2.922, 0.692, 0.470, -0.166)],
        }
    }
}

/// The film of a lubricated line contact, m.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Film {
    /// the central film thickness `h_c`
    pub central: f64,
    /// the minimum film thickness `h_min` (at the outlet constriction)
    pub minimum: f64,
}

/// The film of `contact` under `lubricant` by `formula` (see [`FilmFormula`] and the module's
/// conventions): zero where the entrainment speed is zero (nothing draws oil into the contact);
/// `None` where the contact carries no load or its curvatures do not close (`R ≤ 0`), where the
/// fits do not apply.
pub fn film_thickness(
    formula: FilmFormula,
    lubricant: &Lubricant,
    contact: &LineContact,
) -> Option<Film> {
    let (r, w, e) = (
        contact.reduced_radius,
        contact.load_per_width,
        contact.effective_modulus,
    );
    if !(r > 0.0 && r.is_finite() && w > 0.0 && w.is_finite() && e > 0.0) {
        return None;
    }
    let u = contact.entrainment().abs();
    let groups = (
        lubricant.viscosity * u / (e * r),
        lubricant.pressure_viscosity * e,
        w / (e * r),
    );
    let h = |(k, au, ag, aw): (f64, f64, f64, f64)| {
        if u == 0.0 {
            return 0.0;
        }
        k * groups.0.powf(au) * groups.1.powf(ag) * groups.2.powf(aw) * r
    };
    let [min, central] = formula.fits();
    Some(Film {
        central: h(central),
        minimum: h(min),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn contact(u: [f64; 2], r: f64, w: f64, e: f64) -> LineContact {
        LineContact {
            surface_speeds: u,
            reduced_radius: r,
            load_per_width: w,
            effective_modulus: e,
        }
    }

    /// Dowson and Higginson's minimum film in its dimensional form,
    /// `h_min = 2.65 α^0.54 (η₀ u)^0.70 R^0.43 / (E'^0.03 w^0.13)` (the exponents collected by
    /// hand), and at one chosen point evaluated by hand: η₀ = 0.01 Pa·s, α = 2e-8 1/Pa,
    /// u = 5 m/s, R = 10 mm, w = 100 kN/m, E' = 228 GPa gives U = 2.1930e-11, G = 4560,
    /// W = 4.3860e-5 and h_min = 0.31941 µm, h_c = 0.41290 µm.
    #[test]
    fn dowson_higginson_agrees_with_its_dimensional_form_and_a_hand_evaluation() {
        let oil = Lubricant {
            viscosity: 0.01,
            pressure_viscosity: 2e-8,
        };
        let c = contact([4.0, 6.0], 0.01, 1e5, 228e9);
        let f = film_thickness(FilmFormula::DowsonHigginson, &oil, &c).unwrap();
        let dimensional =
            2.65 * 2e-8f64.powf(0.54) * (0.01f64 * 5.0).powf(0.70) * 0.01f64.powf(0.43)
                / (228e9f64.powf(0.03) * 1e5f64.powf(0.13));
        assert!(
            (f.minimum / dimensional - 1.0).abs() < 1e-12,
            "{f:?} {dimensional}"
        );
        assert!((f.minimum / 0.31941e-6 - 1.0).abs() < 2e-5, "{f:?}");
        assert!((f.central / 0.41290e-6 - 1.0).abs() < 2e-5, "{f:?}");
        // the central film is the thicker (the outlet constriction is the minimum)
        assert!(f.central > f.minimum);
    }

    /// Pan and Hamrock at the same point, by hand: h_min = 0.29703 µm, h_c = 0.34104 µm.
    #[test]
    fn hamrock_agrees_with_a_hand_evaluation() {
        let oil = Lubricant {
            viscosity: 0.01,
            pressure_viscosity: 2e-8,
        };
        let c = contact([4.0, 6.0], 0.01, 1e5, 228e9);
        let f = film_thickness(FilmFormula::Hamrock, &oil, &c).unwrap();
        assert!((f.minimum / 0.29703e-6 - 1.0).abs() < 2e-5, "{f:?}");
        assert!((f.central / 0.34104e-6 - 1.0).abs() < 2e-5, "{f:?}");
    }

    /// The film depends on the entrainment speed alone (not on which surface moves, nor on the
    /// sliding, nor on its sign), grows as its 0.7th power, and is zero without entrainment;
    /// no load or an open contact has no film.
    #[test]
    fn the_film_follows_the_entrainment_and_refuses_what_the_fits_do_not_cover() {
        let oil = Lubricant {
            viscosity: 0.02,
            pressure_viscosity: 1.5e-8,
        };
        for formula in FilmFormula::ALL {
            let h = |u: [f64; 2]| {
                film_thickness(formula, &oil, &contact(u, 0.02, 2e5, 230e9))
                    .unwrap()
                    .minimum
            };
            assert_eq!(h([3.0, 1.0]), h([1.0, 3.0]));
            assert_eq!(h([3.0, 1.0]), h([-3.0, -1.0]));
            assert_eq!(h([2.0, 2.0]), h([4.0, 0.0]));
            let exponent = (h([4.0, 4.0]) / h([2.0, 2.0])).log2();
            let expected = formula.fits()[0].1;
            assert!((exponent - expected).abs() < 1e-12, "{exponent}");
            assert_eq!(h([1.0, -1.0]), 0.0);
            assert!(
                film_thickness(formula, &oil, &contact([1.0, 1.0], 0.02, 0.0, 230e9)).is_none()
            );
            assert!(
                film_thickness(formula, &oil, &contact([1.0, 1.0], -0.02, 1e5, 230e9)).is_none()
            );
            assert!(film_thickness(
                formula,
                &oil,
                &contact([1.0, 1.0], f64::INFINITY, 1e5, 230e9)
            )
            .is_none());
        }
    }
}
