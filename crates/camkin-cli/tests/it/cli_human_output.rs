//! Issue 49: every number a person reads is rounded for people. Each command that prints a
//! summary or a message is run on every example (`analyze`, `profile`, `forces`, `synth`,
//! `mesh`), and everything it prints for people (stdout where it is a summary, stderr always)
//! is scanned for rounding noise: a plain number of more than 6 significant digits
//! (`339.99999999999994`), a fraction ending in four or more zeros (`62.000000`), a mantissa of
//! more than 4 digits in exponent notation (`2.84217e-14`), and values below 1e-9 anywhere but
//! a check's stated bound (a round trip's error, a largest difference or distance).

use crate::common::*;

/// The noise in `line`, if any.
fn noise(line: &str) -> Option<String> {
    let bound = ["≤", "difference", "distance", "round trip", "of the peak"]
        .iter()
        .any(|w| line.contains(w));
    let chars: Vec<char> = line.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        // a number starts at a digit not inside a word (a name like `sae-30` or `x2` is not)
        let starts = chars[i].is_ascii_digit()
            && (i == 0 || !(chars[i - 1].is_alphanumeric() || chars[i - 1] == '_'));
        if !starts {
            i += 1;
            continue;
        }
        let s = i;
        while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
            i += 1;
        }
        let mantissa: String = chars[s..i].iter().collect();
        let mut exponent = None;
        if i + 1 < chars.len()
            && chars[i] == 'e'
            && (chars[i + 1] == '-' || chars[i + 1].is_ascii_digit())
        {
            let e0 = i + 1;
            i += 2;
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
            }
            let e: String = chars[e0..i].iter().collect();
            exponent = e.parse::<i32>().ok();
        }
        let mantissa = mantissa.trim_end_matches('.');
        let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
        let significant = digits.trim_start_matches('0');
        let significant = if mantissa.contains('.') {
            significant
        } else {
            significant.trim_end_matches('0')
        };
        let token: String = chars[s..i].iter().collect();
        match exponent {
            None if significant.len() > 6 => return Some(token),
            None if mantissa.contains('.') && mantissa.ends_with("0000") => return Some(token),
            Some(_) if significant.len() > 4 => return Some(token),
            Some(e) if e <= -10 && !bound => return Some(token),
            _ => {}
        }
    }
    None
}

#[test]
fn the_scanner_finds_the_issues_examples() {
    for bad in [
        "the segments cover 339.99999999999994°",
        "centre distance 62.000000",
        "|play| ≤ 2.84217e-14 mm",
        "lift 7.1e-15 mm at 3°",
    ] {
        assert!(noise(bad).is_some(), "{bad}");
    }
    for good in [
        "max 8.92 N·m at 44°, mean 0.0003388 N·m",
        "sae-30@100c, 2 pairs, iso-vg-100",
        "round trip |Δs| ≤ 1.42e-14 mm",
        "1.209e9 rpm",
        "720001 rows",
    ] {
        assert!(noise(good).is_none(), "{good}");
    }
}

#[test]
fn no_command_prints_rounding_noise_on_any_example() {
    let dir = tempfile::tempdir().unwrap();
    let mut seen = Vec::new();
    let mut files: Vec<_> = std::fs::read_dir(examples())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 20);
    for f in &files {
        let name = f.file_stem().unwrap().to_string_lossy().to_string();
        let text = std::fs::read_to_string(f).unwrap();
        let out = |sub: &str| dir.path().join(format!("{name}-{sub}"));
        // (command, arguments, whether its stdout is for people)
        let mut runs: Vec<(Vec<std::ffi::OsString>, bool)> = vec![
            (
                vec!["analyze".into(), f.into(), "-o".into(), out("a.csv").into()],
                false,
            ),
            (
                vec!["profile".into(), f.into(), "--out".into(), out("p").into()],
                true,
            ),
        ];
        if text.contains("[dynamics]") || text.contains("[gear_loads]") {
            runs.push((
                vec!["forces".into(), f.into(), "--step".into(), "1".into()],
                true,
            ));
        }
        if text.contains("kind = \"motion\"") && !text.contains("[[body]]") {
            runs.push((
                vec!["synth".into(), f.into(), "--out".into(), out("s").into()],
                true,
            ));
        }
        if text.contains("involute-gear") || text.contains("[gear_pair]") {
            runs.push((
                vec!["mesh".into(), f.into(), "-o".into(), out("m.csv").into()],
                false,
            ));
        }
        for (args, stdout_for_people) in runs {
            let o = camkin().args(&args).assert().get_output().clone();
            let mut text = String::from_utf8_lossy(&o.stderr).to_string();
            if stdout_for_people {
                text += &String::from_utf8_lossy(&o.stdout);
            }
            for line in text.lines() {
                if let Some(n) = noise(line) {
                    seen.push(format!("{name} {:?}: {n} in {line:?}", args[0]));
                }
            }
        }
    }
    assert!(seen.is_empty(), "{}", seen.join("\n"));
}
