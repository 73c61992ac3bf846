//! The library's shape, checked on its sources (issue 43): no file over 800 lines; `Mechanism` a
//! façade implemented in at most three files; no `Any` or `downcast_ref` deciding fast paths; no
//! import circle among the modules of `cam/`; no function of `cam/` taking both a cam angle and
//! a frame (the instant is passed once). Each check fails on the code it guards against (the
//! test `the_circle_finder_finds_a_circle` shows the cycle search does).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn src() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src")
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

fn files() -> Vec<(String, String)> {
    let mut v = Vec::new();
    rust_files(&src(), &mut v);
    v.sort();
    v.into_iter()
        .map(|p| {
            let name = p.strip_prefix(src()).unwrap().display().to_string();
            (name, std::fs::read_to_string(&p).unwrap())
        })
        .collect()
}

/// The code of a file without its comments and its tests.
fn code(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap();
    text.lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn no_library_file_is_over_800_lines() {
    let long: Vec<_> = files()
        .into_iter()
        .filter(|(_, t)| t.lines().count() > 800)
        .map(|(n, t)| format!("{n}: {} lines", t.lines().count()))
        .collect();
    assert!(long.is_empty(), "{long:?}");
}

#[test]
fn mechanism_is_a_facade_and_curves_carry_no_any() {
    let all = files();
    let impls: Vec<_> = all
        .iter()
        .filter(|(_, t)| code(t).contains("\nimpl Mechanism {"))
        .map(|(n, _)| n.clone())
        .collect();
    assert!(impls.len() <= 3, "impl Mechanism in {impls:?}");
    for (n, t) in &all {
        let c = code(t);
        assert!(!c.contains("downcast_ref"), "{n} downcasts");
        assert!(!c.contains("std::any::Any"), "{n} uses Any");
    }
}

/// The first path segments after `prefix` wherever it stands in `c`: `x` of `prefix x::…`, and
/// each group member's of `prefix {x, y::z}`.
fn segments_after(c: &str, prefix: &str) -> Vec<String> {
    let word = |s: &str| -> String {
        s.trim_start()
            .chars()
            .take_while(|ch| ch.is_alphanumeric() || *ch == '_')
            .collect()
    };
    let mut out = Vec::new();
    for (k, _) in c.match_indices(prefix) {
        let rest = &c[k + prefix.len()..];
        // a `super::` of a longer `super::super::` chain is not this prefix
        if (k > 0 && c[..k].ends_with("super::")) || rest.starts_with("super::") {
            continue;
        }
        match rest.strip_prefix('{') {
            Some(group) => {
                let (mut depth, mut item) = (0, String::new());
                for ch in group.chars() {
                    match ch {
                        '{' => depth += 1,
                        '}' if depth == 0 => break,
                        '}' => depth -= 1,
                        ',' if depth == 0 => {
                            out.push(word(&item));
                            item.clear();
                            continue;
                        }
                        _ => {}
                    }
                    item.push(ch);
                }
                out.push(word(&item));
            }
            None => out.push(word(rest)),
        }
    }
    out
}

/// `super::x`, `crate::cam::x` paths of a file of `cam/` as the top-level modules of `cam/`
/// they name.
fn cam_imports(module: &str, text: &str, modules: &BTreeSet<String>) -> BTreeSet<String> {
    let depth = module.matches('/').count();
    let c = code(text);
    // `super::x` from a top-level module (`cam/x.rs`), `super::super::x` from a child's
    let mut names = segments_after(&c, "crate::cam::");
    names.extend(segments_after(&c, &"super::".repeat(depth + 1)));
    names.into_iter().filter(|n| modules.contains(n)).collect()
}

/// A circle in `graph`, if it has one.
fn circle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        v: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(k) = path.iter().position(|p| p == v) {
            return Some(path[k..].to_vec());
        }
        if done.contains(v) {
            return None;
        }
        path.push(v.to_string());
        for w in graph.get(v).into_iter().flatten() {
            if let Some(c) = visit(w, graph, path, done) {
                return Some(c);
            }
        }
        path.pop();
        done.insert(v.to_string());
        None
    }
    let mut done = BTreeSet::new();
    for v in graph.keys() {
        if let Some(c) = visit(v, graph, &mut Vec::new(), &mut done) {
            return Some(c);
        }
    }
    None
}

#[test]
fn the_circle_finder_finds_a_circle() {
    let g: BTreeMap<String, BTreeSet<String>> = [("a", "b"), ("b", "c"), ("c", "a")]
        .into_iter()
        .map(|(a, b)| (a.to_string(), BTreeSet::from([b.to_string()])))
        .collect();
    assert_eq!(circle(&g).map(|c| c.len()), Some(3));
    let line: BTreeMap<String, BTreeSet<String>> = [("a", "b"), ("b", "c")]
        .into_iter()
        .map(|(a, b)| (a.to_string(), BTreeSet::from([b.to_string()])))
        .collect();
    assert_eq!(circle(&line), None);
    // and the imports are read, groups included
    assert_eq!(
        segments_after(
            "use super::{a, b::{c, d}, e};\nuse super::super::f;",
            "super::"
        ),
        ["a", "b", "e"]
    );
}

#[test]
fn the_modules_of_cam_import_in_one_direction() {
    let all = files();
    let cam: Vec<_> = all
        .iter()
        .filter(|(n, _)| n.starts_with("cam/") && n != "cam/mod.rs")
        .collect();
    let top = |n: &str| {
        n.trim_start_matches("cam/")
            .trim_end_matches(".rs")
            .split('/')
            .next()
            .unwrap()
            .to_string()
    };
    let modules: BTreeSet<String> = cam.iter().map(|(n, _)| top(n)).collect();
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (n, t) in &cam {
        let module = n.trim_start_matches("cam/").trim_end_matches(".rs");
        let module = module.trim_end_matches("/mod");
        let from = top(n);
        for to in cam_imports(module, t, &modules) {
            if to != from {
                graph.entry(from.clone()).or_default().insert(to);
            }
        }
    }
    assert!(
        graph.contains_key("follower"),
        "the graph was read: {graph:?}"
    );
    assert_eq!(circle(&graph), None, "{graph:?}");
}

/// The joint is behaviour: its users call its methods instead of matching on its kind (the
/// independent check in `support.rs` keeps its own, to share no code with what it checks).
#[test]
fn the_joint_is_matched_in_few_places() {
    let mut places = Vec::new();
    for (n, t) in files() {
        if n.ends_with("follower/joint.rs") || n.ends_with("cam/support.rs") {
            continue;
        }
        for (k, line) in code(&t).lines().enumerate() {
            let hits = line.matches("FollowerJoint::Translating").count()
                + line.matches("FollowerJoint::Rotating").count();
            places.extend(std::iter::repeat_n(format!("{n}:{}", k + 1), hits));
        }
    }
    assert!(places.len() <= 10, "{} places: {places:?}", places.len());
}

#[test]
fn no_function_of_cam_takes_an_angle_and_a_frame() {
    for (n, t) in files().iter().filter(|(n, _)| n.starts_with("cam/")) {
        let c = code(t);
        for (k, _) in c.match_indices("fn ") {
            let sig: String = c[k..].chars().take_while(|&ch| ch != '{').collect();
            assert!(
                !(sig.contains("theta: f64") && sig.contains(": &Frame")),
                "{n}: {}",
                sig.split_whitespace().collect::<Vec<_>>().join(" ")
            );
        }
    }
}
