//! Rows of [`Cell`]s written as CSV, the same bytes as the `csv` crate's serializer gives them
//! (tested below), but formatted in parallel chunks and without serde: numbers by `zmij` (the
//! shortest decimal that reads back to the same `f64`, as `ryu` writes it, about twice as fast),
//! whole numbers by `itoa`, text quoted only where it must be (a comma, a quote or a line break
//! in it; quotes doubled).
//!
//! A chunk of rows is cut into pieces of [`PIECE`] rows, each formatted into its own buffer on
//! rayon's threads, and the buffers are written in the rows' order: the bytes do not depend on
//! the number of threads.

use camkin::table::Cell;
use rayon::prelude::*;
use std::io::Write;

/// Rows formatted by one task.
pub const PIECE: usize = 128;

/// Appends one row (its cells separated by commas, a `\n` after it) to `out`.
pub fn format_row(out: &mut Vec<u8>, row: &[Cell], num: &mut zmij::Buffer) {
    let start = out.len();
    for (i, c) in row.iter().enumerate() {
        if i > 0 {
            out.push(b',');
        }
        match c {
            Cell::Num(Some(x)) => {
                if x.is_finite() {
                    shortest(out, num.format_finite(*x).as_bytes());
                } else {
                    out.extend_from_slice(non_finite(*x));
                }
            }
            Cell::Int(Some(x)) => out.extend_from_slice(itoa::Buffer::new().format(*x).as_bytes()),
            Cell::Count(Some(x)) => {
                out.extend_from_slice(itoa::Buffer::new().format(*x).as_bytes())
            }
            Cell::Flag(Some(x)) => out.extend_from_slice(if *x { b"true" } else { b"false" }),
            Cell::Text(Some(s)) => text(out, s),
            Cell::Num(None)
            | Cell::Int(None)
            | Cell::Count(None)
            | Cell::Flag(None)
            | Cell::Text(None) => {}
        }
    }
    if row.len() == 1 && out.len() == start {
        // a record of one empty field is written quoted, so that it reads back as a field
        out.extend_from_slice(b"\"\"");
    }
    out.push(b'\n');
}

/// `zmij`'s digits in `ryu`'s form: a positive exponent without its sign (`1e98`, not `1e+98`).
fn shortest(out: &mut Vec<u8>, s: &[u8]) {
    match s.iter().position(|&c| c == b'+') {
        Some(i) => {
            out.extend_from_slice(&s[..i]);
            out.extend_from_slice(&s[i + 1..]);
        }
        None => out.extend_from_slice(s),
    }
}

/// What `ryu` (and so the `csv` crate) writes for a value that is not finite.
fn non_finite(x: f64) -> &'static [u8] {
    if x.is_nan() {
        b"NaN"
    } else if x > 0.0 {
        b"inf"
    } else {
        b"-inf"
    }
}

/// A text field, quoted when it holds a comma, a quote or a line break (the `csv` crate's
/// `QuoteStyle::Necessary`).
fn text(out: &mut Vec<u8>, s: &str) {
    let b = s.as_bytes();
    if b.iter().any(|&c| matches!(c, b',' | b'"' | b'\n' | b'\r')) {
        out.push(b'"');
        for &c in b {
            if c == b'"' {
                out.push(b'"');
            }
            out.push(c);
        }
        out.push(b'"');
    } else {
        out.extend_from_slice(b);
    }
}

/// The rows formatted by `row`, piece by piece on rayon's threads, in order (each piece a
/// buffer of about 50 kB: below the allocator's threshold for mapping memory afresh, so that the
/// buffers of one chunk reuse the last chunk's memory).
pub fn format_rows<R: Sync>(
    rows: &[R],
    row: &(impl Fn(&R, &mut Vec<u8>, &mut zmij::Buffer) + Sync),
) -> Vec<Vec<u8>> {
    rows.par_chunks(PIECE)
        .map(|piece| {
            let mut num = zmij::Buffer::new();
            let mut out = Vec::with_capacity(piece.len() * 512);
            for r in piece {
                row(r, &mut out, &mut num);
            }
            out
        })
        .collect()
}

/// Writes the header `columns` and then every chunk `next_chunk` yields (until `None`), each
/// row's cells made by `cells` where the row is formatted (on rayon's threads: a row's cells
/// are made, written and dropped by one thread).
pub fn write_with<R: Sync, C: AsRef<[Cell]>>(
    w: &mut dyn Write,
    columns: &[String],
    next_chunk: impl FnMut() -> Option<Vec<R>>,
    cells: impl Fn(&R) -> C + Sync,
) -> std::io::Result<()> {
    write_formatted(w, columns, next_chunk, |r: &R, out, num| {
        format_row(out, cells(r).as_ref(), num)
    })
}

/// [`write_with`] of rows that are cells already.
pub fn write(
    w: &mut dyn Write,
    columns: &[String],
    next_chunk: impl FnMut() -> Option<Vec<Vec<Cell>>>,
) -> std::io::Result<()> {
    write_formatted(w, columns, next_chunk, |r: &Vec<Cell>, out, num| {
        format_row(out, r, num)
    })
}

fn write_formatted<R: Sync>(
    w: &mut dyn Write,
    columns: &[String],
    mut next_chunk: impl FnMut() -> Option<Vec<R>>,
    row: impl Fn(&R, &mut Vec<u8>, &mut zmij::Buffer) + Sync,
) -> std::io::Result<()> {
    let header: Vec<Cell> = columns
        .iter()
        .map(|c| Cell::Text(Some(c.clone())))
        .collect();
    let mut out = Vec::new();
    format_row(&mut out, &header, &mut zmij::Buffer::new());
    w.write_all(&out)?;
    while let Some(rows) = next_chunk() {
        for piece in format_rows(&rows, &row) {
            w.write_all(&piece)?;
        }
    }
    w.flush()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The `csv` crate's bytes for the same rows (serde, ryu).
    fn reference(columns: &[String], rows: &[Vec<Cell>]) -> Vec<u8> {
        let mut out = Vec::new();
        {
            let mut c = csv::WriterBuilder::new()
                .has_headers(false)
                .from_writer(&mut out);
            c.write_record(columns).unwrap();
            for r in rows {
                c.serialize(r).unwrap();
            }
            c.flush().unwrap();
        }
        out
    }

    fn ours(columns: &[String], rows: Vec<Vec<Cell>>) -> Vec<u8> {
        let mut out = Vec::new();
        let mut once = Some(rows);
        write(&mut out, columns, || once.take()).unwrap();
        out
    }

    fn cell() -> impl Strategy<Value = Cell> {
        prop_oneof![
            any::<u64>().prop_map(|b| Cell::Num(Some(f64::from_bits(b)))),
            any::<f64>().prop_map(|x| Cell::Num(Some(x))),
            (-1e6f64..1e6).prop_map(|x| Cell::Num(Some(x))),
            (-40i32..40, -1.0f64..1.0).prop_map(|(e, m)| Cell::Num(Some(m * 10f64.powi(e)))),
            Just(Cell::Num(None)),
            Just(Cell::Num(Some(0.0))),
            Just(Cell::Num(Some(-0.0))),
            any::<Option<u8>>().prop_map(Cell::Int),
            any::<Option<u32>>().prop_map(Cell::Count),
            any::<Option<bool>>().prop_map(Cell::Flag),
            proptest::option::of("[ -~\n\r]{0,12}").prop_map(Cell::Text),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]
        /// Any rows of any cells: the same bytes as the `csv` crate's.
        #[test]
        fn the_same_bytes_as_the_csv_crate(
            rows in proptest::collection::vec(proptest::collection::vec(cell(), 1..6), 0..6)
        ) {
            let n = rows.iter().map(Vec::len).max().unwrap_or(1);
            let columns: Vec<String> = (0..n).map(|i| format!("c{i}")).collect();
            // the csv crate wants rows of one length
            let rows: Vec<Vec<Cell>> = rows
                .into_iter()
                .map(|mut r| { r.resize(n, Cell::Num(None)); r })
                .collect();
            prop_assert_eq!(
                String::from_utf8(ours(&columns, rows.clone())).unwrap(),
                String::from_utf8(reference(&columns, &rows)).unwrap()
            );
        }
    }

    /// Chosen values: zeros, extremes, subnormals, powers of ten at the switch to exponents,
    /// text needing quotes, and more rows than one piece.
    #[test]
    fn chosen_values_and_many_pieces() {
        let mut rows = Vec::new();
        let specials = [
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            5e-324,
            f64::MAX,
            f64::MIN,
            f64::EPSILON,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            297.49999999999994,
            0.1 + 0.2,
            1.0 / 3.0,
        ];
        for x in specials {
            rows.push(vec![
                Cell::Num(Some(x)),
                Cell::Text(Some("a,b \"c\"".into())),
            ]);
        }
        for e in -30..30 {
            for m in [1.0, 1.5, 9.999999999999998, 123456789.0] {
                let x = m * 10f64.powi(e);
                rows.push(vec![Cell::Num(Some(x)), Cell::Num(Some(-x))]);
            }
        }
        for k in 0..(3 * PIECE + 7) {
            rows.push(vec![
                Cell::Count(Some(k as u32)),
                Cell::Num(Some(k as f64 * 0.05)),
            ]);
        }
        let columns = vec!["x".to_string(), "y".to_string()];
        let (a, b) = (ours(&columns, rows.clone()), reference(&columns, &rows));
        for (x, y) in String::from_utf8(a.clone())
            .unwrap()
            .lines()
            .zip(String::from_utf8(b.clone()).unwrap().lines())
        {
            assert_eq!(x, y);
        }
        assert_eq!(a, b);
    }
}
