//! A table's columns written once: each column's name (with its unit), whether the mechanism has
//! it, and its cell from a row, side by side in one list. The name list and a row's cells are
//! read from the same list, so they cannot disagree, and a conditional column is written once.

use super::units::Units;

/// One cell of a table whose column names are only known at run time (they carry units).
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// a number (absent: an empty CSV cell, JSON `null`, NaN in an array)
    Num(Option<f64>),
    /// a small whole number
    Int(Option<u8>),
    /// a count or an index
    Count(Option<u32>),
    /// yes or no (CSV `true`/`false`, JSON a boolean)
    Flag(Option<bool>),
    /// text
    Text(Option<String>),
}

impl serde::Serialize for Cell {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        match self {
            Cell::Num(Some(x)) => s.serialize_f64(*x),
            Cell::Int(Some(x)) => s.serialize_u8(*x),
            Cell::Count(Some(x)) => s.serialize_u32(*x),
            Cell::Flag(Some(x)) => s.serialize_bool(*x),
            Cell::Text(Some(x)) => s.serialize_str(x),
            _ => s.serialize_none(),
        }
    }
}

/// One column of a table of rows `R`, each read beside `X`: what a row's cells share, such as
/// its motion converted to the table's units.
pub(crate) struct Col<R, X> {
    /// the column's name, with its unit
    pub(crate) name: fn(&Units) -> String,
    /// whether the table has the column (a carried curve's `corner`, a conjugate's play)
    pub(crate) when: fn(&Units) -> bool,
    /// the row's cell
    pub(crate) cell: fn(&R, &X) -> Cell,
}

/// Every table has the column.
pub(crate) fn always(_: &Units) -> bool {
    true
}

/// The names of the columns the table has.
pub(crate) fn names<R, X>(cols: &[Col<R, X>], u: &Units) -> Vec<String> {
    cols.iter()
        .filter(|c| (c.when)(u))
        .map(|c| (c.name)(u))
        .collect()
}

/// One row's cells, in the order of [`names`].
pub(crate) fn cells<R, X>(cols: &[Col<R, X>], u: &Units, r: &R, x: &X) -> Vec<Cell> {
    cols.iter()
        .filter(|c| (c.when)(u))
        .map(|c| (c.cell)(r, x))
        .collect()
}

/// A column that every table has, named `name` whatever the units.
macro_rules! fixed {
    ($name:literal, $cell:expr) => {
        $crate::table::column::Col {
            name: |_| $name.to_string(),
            when: $crate::table::column::always,
            cell: $cell,
        }
    };
}

/// A column that every table has, its name made from the units.
macro_rules! named {
    ($name:expr, $cell:expr) => {
        $crate::table::column::Col {
            name: $name,
            when: $crate::table::column::always,
            cell: $cell,
        }
    };
}

pub(crate) use {fixed, named};
