//! Deserialisation of `[x, y]` pairs that refuses any other length (serde's fixed-size arrays
//! would read `[1.0, 0.0, 7.0]` as its first two elements in some formats).

use serde::de::{Deserializer, Error, SeqAccess, Visitor};
use std::fmt;

struct PairVisitor;

impl<'de> Visitor<'de> for PairVisitor {
    type Value = [f64; 2];
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a pair of numbers [x, y]")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<[f64; 2], A::Error> {
        let mut got: Vec<f64> = Vec::with_capacity(2);
        while let Some(v) = seq.next_element::<f64>()? {
            got.push(v);
            if got.len() > 64 {
                break;
            }
        }
        match got[..] {
            [x, y] => Ok([x, y]),
            _ => Err(A::Error::custom(format!(
                "expected a pair of numbers [x, y], found {} number{}: {}",
                got.len(),
                if got.len() == 1 { "" } else { "s" },
                show(&got)
            ))),
        }
    }
}

fn show(v: &[f64]) -> String {
    let items: Vec<String> = v.iter().take(8).map(|x| format!("{x:?}")).collect();
    let more = if v.len() > 8 { ", …" } else { "" };
    format!("[{}{more}]", items.join(", "))
}

/// A pair, exactly two numbers.
pub fn exact<'de, D: Deserializer<'de>>(d: D) -> Result<[f64; 2], D::Error> {
    d.deserialize_seq(PairVisitor)
}

/// An optional pair (with `#[serde(default)]`).
pub fn option<'de, D: Deserializer<'de>>(d: D) -> Result<Option<[f64; 2]>, D::Error> {
    exact(d).map(Some)
}

struct Pairs;

impl<'de> Visitor<'de> for Pairs {
    type Value = Vec<[f64; 2]>;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a list of pairs [[x, y], …]")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec<[f64; 2]>, A::Error> {
        let mut out = Vec::new();
        while let Some(Pair(p)) = seq
            .next_element::<Pair>()
            .map_err(|e| A::Error::custom(format!("point {}: {e}", out.len() + 1)))?
        {
            out.push(p);
        }
        Ok(out)
    }
}

struct Pair([f64; 2]);

impl<'de> serde::Deserialize<'de> for Pair {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        exact(d).map(Pair)
    }
}

/// An optional list of pairs (with `#[serde(default)]`).
pub fn option_list<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Vec<[f64; 2]>>, D::Error> {
    d.deserialize_seq(Pairs).map(Some)
}

/// Exactly `N` values of `T` (a list of another length is refused, saying how many it has).
struct Exact<T, const N: usize> {
    what: &'static str,
    of: std::marker::PhantomData<T>,
}

impl<'de, T: serde::Deserialize<'de>, const N: usize> Visitor<'de> for Exact<T, N> {
    type Value = [T; N];
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.what)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<[T; N], A::Error> {
        let mut got: Vec<T> = Vec::with_capacity(N);
        let mut count = 0usize;
        while let Some(v) = seq.next_element::<T>()? {
            count += 1;
            if got.len() < N {
                got.push(v);
            }
            if count > 64 {
                break;
            }
        }
        if count != N {
            return Err(A::Error::custom(format!(
                "expected {}, found {count} value{}",
                self.what,
                if count == 1 { "" } else { "s" }
            )));
        }
        got.try_into()
            .map_err(|_| A::Error::custom(format!("expected {}", self.what)))
    }
}

fn exactly<'de, D: Deserializer<'de>, T: serde::Deserialize<'de>, const N: usize>(
    d: D,
    what: &'static str,
) -> Result<[T; N], D::Error> {
    d.deserialize_seq(Exact::<T, N> {
        what,
        of: std::marker::PhantomData,
    })
}

/// Two bodies' names, exactly (`bodies = ["ground", "cam"]`).
pub fn names<'de, D: Deserializer<'de>>(d: D) -> Result<[String; 2], D::Error> {
    exactly(d, "two bodies' names [\"a\", \"b\"]")
}

/// Two points, each a pair, exactly (`at = [[0, 0], [10, 0]]`).
pub fn points<'de, D: Deserializer<'de>>(d: D) -> Result<[[f64; 2]; 2], D::Error> {
    exactly::<D, Pair, 2>(d, "two points [[x, y], [x, y]]").map(|[a, b]| [a.0, b.0])
}

/// Optional [`points`] (with `#[serde(default)]`).
pub fn option_points<'de, D: Deserializer<'de>>(d: D) -> Result<Option<[[f64; 2]; 2]>, D::Error> {
    points(d).map(Some)
}

/// Two whole numbers, exactly (`teeth = [20, 42]`).
pub fn counts<'de, D: Deserializer<'de>>(d: D) -> Result<[u32; 2], D::Error> {
    exactly(d, "two whole numbers [a, b]")
}

/// A list of pairs (`table = [[0, 0], [90, 1.5]]`).
pub fn list<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<[f64; 2]>, D::Error> {
    d.deserialize_seq(Pairs)
}
