fn main() {
    let mut m = camkin::reference::paper_mechanism(false);
    let mut o = *m.options();
    o.jerk = false;
    m.set_options(o);
    let th: Vec<f64> = (0..7200).map(|k| (k as f64 * 0.05).to_radians()).collect();
    let reps: usize = std::env::var("REPS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(300);
    let motion = std::env::var("MOTION").is_ok();
    let mut acc = 0.0;
    for _ in 0..reps {
        let mut s = m.sweep();
        for &t in &th {
            acc += if motion {
                s.step_motion(t).map(|s| s.acceleration)
            } else {
                s.step(t).map(|s| s.acceleration)
            }
            .unwrap_or(0.0);
        }
    }
    println!("{acc}");
}
