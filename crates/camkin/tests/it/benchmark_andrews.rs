//! Issue 64, the public benchmarks: Andrews' squeezing mechanism (IFToMM benchmark A03; Hairer
//! and Wanner, *Solving ODE II*, §VII.7; the Test Set for IVP Solvers' problem "andrews",
//! Mazzia and Magherini), `examples/andrews-squeezer.toml`: seven links, a torque and a spring,
//! released at rest, against the test set's published solution at t = 0.03 s — its seven angles
//! and their rates (computed there by RADAU5 at tolerances of 1e-14, in the test set's relative
//! angles: `β`, `Θ` the connecting rod's turn from the crank, `γ`, `Φ`, `δ`, `Ω`, `ε`).

use crate::common::{body_index, run_timed};

/// The published solution at t = 0.03 s: `(β, Θ, γ, Φ, δ, Ω, ε)` and their rates.
const ANGLES: [f64; 7] = [
    0.1581077119629904e2,
    -0.1575637105984298e2,
    0.4082224013073101e-1,
    -0.5347301163226948,
    0.5244099658805304,
    0.5347301163226948,
    0.1048080741042263e1,
];
const RATES: [f64; 7] = [
    0.1139920302151208e4,
    -0.1424379294994111e4,
    0.1103291221937134e2,
    0.1929337464421385e2,
    0.5735699284790808,
    -0.1929337464421385e2,
    0.3231791658026955,
];

/// At the default tolerances (1e-10) the seven angles match the published ones to 1e-8 rad
/// (measured 2.8e-10 rad: the crank has turned 2.5 revolutions) and their rates to 1e-6 of the
/// fastest (the crank's 1140 rad/s), and the balance explains the energy the torque gave to 1e-9
/// of it: the torque's work is the energy's change.
#[test]
fn andrews_squeezer_matches_the_published_solution() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/andrews-squeezer.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let (built, out) = run_timed(&text, "andrews-squeezer.toml");
    assert_eq!(built.timed_run.map(|r| r.duration), Some(0.03));
    let last = out.samples.last().unwrap();
    assert!((last.time - 0.03).abs() < 1e-15);
    let index = |name: &str| body_index(&built, name);
    let bodies = [
        "crank",
        "connecting rod",
        "lever B",
        "link E",
        "triangle A",
        "link G",
        "triangle A2",
    ]
    .map(index);
    let [a, r]: [Vec<f64>; 2] =
        [&last.q, &last.qd].map(|v| bodies.iter().map(|&i| v[3 * i + 2]).collect());
    // the test set's angles from the bodies' absolute ones: Θ = φ₂ − φ₁, Φ = φ₄ − φ₅, Ω = φ₆ − φ₇
    let relative = |x: &[f64]| {
        [
            x[0],
            x[1] - x[0],
            x[2],
            x[3] - x[4],
            x[4],
            x[5] - x[6],
            x[6],
        ]
    };
    let (angles, rates) = (relative(&a), relative(&r));
    for k in 0..7 {
        assert!(
            (angles[k] - ANGLES[k]).abs() < 1e-8,
            "angle {k}: {} rad, published {} rad",
            angles[k],
            ANGLES[k]
        );
        assert!(
            (rates[k] - RATES[k]).abs() < 1e-6 * RATES[0],
            "rate {k}: {} rad/s, published {} rad/s",
            rates[k],
            RATES[k]
        );
    }
    let b = &last.balance;
    assert!(b.applied > 0.1, "the torque did work: {b:?}");
    assert!(b.residual().abs() < 1e-9 * b.applied, "{b:?}");
}
