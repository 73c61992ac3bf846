//! Numbers as people read them in messages: six significant digits at most, exponent notation
//! outside `[1e-4, 1e9)` (`1e200`, not two hundred digits; `1.209e9`, not `1209000000`; `340`,
//! not `339.99999999999994`).
//! CSV and JSON output keep round-trip precision; this is only for text.

/// `x` rounded for a message.
pub fn human(x: f64) -> String {
    if x.is_nan() {
        return "NaN".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf" } else { "-inf" }.into();
    }
    if x == 0.0 {
        return "0".into();
    }
    let a = x.abs();
    if (1e-4..1e9).contains(&a) {
        let digits = (5 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{x:.digits$}");
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        };
        if s == "-0" {
            "0".into()
        } else {
            s
        }
    } else {
        // the shortest form that reads back as `x` when it is short (5e-324, not 4.94066e-324)
        let shortest = format!("{x:e}");
        if shortest
            .split_once('e')
            .is_some_and(|(m, _)| m.trim_start_matches('-').len() <= 7)
        {
            return shortest;
        }
        let s = format!("{x:.5e}");
        // 1.23400e200 → 1.234e200
        match s.split_once('e') {
            Some((m, e)) => {
                let m = if m.contains('.') {
                    m.trim_end_matches('0').trim_end_matches('.')
                } else {
                    m
                };
                format!("{m}e{e}")
            }
            None => s,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::human;

    #[test]
    fn rounds_for_people() {
        assert_eq!(human(339.99999999999994), "340");
        assert_eq!(human(1e200), "1e200");
        assert_eq!(human(-1.234567e-300), "-1.23457e-300");
        assert_eq!(human(0.1 + 0.2), "0.3");
        assert_eq!(human(1000.0), "1000");
        assert_eq!(human(2.5e-3), "0.0025");
        assert_eq!(human(f64::INFINITY), "inf");
        assert_eq!(human(-0.0), "0");
        assert_eq!(human(123456.7), "123457");
        assert_eq!(human(1209000000.0), "1.209e9");
        assert_eq!(human(999999999.0), "999999999");
        assert_eq!(human(5e-324), "5e-324");
        assert_eq!(human(-2.5e-120), "-2.5e-120");
    }
}
