//! `kind = "arcs-and-lines"`: a chain of lines and arcs from `start`, each piece from where the
//! one before ends, read into an exact [`ArcsAndLines`] profile; every error at its piece.

use super::build::{key, need, point, vector, SpecError};
use super::ProfileSpec;
use crate::curve::{ArcsAndLines, ArcsError, Piece};
use crate::field::{Field, PieceField, ProfileField};
use std::f64::consts::TAU;

/// The most pieces a profile may have (a cam has a handful; thousands are a mistake).
pub const MAX_PIECES: usize = 10_000;

impl ProfileSpec {
    /// The chain in the file's unit (checked there, its messages quoting the file's numbers),
    /// then scaled by `scale`.
    pub(super) fn arcs_and_lines(
        &self,
        scale: f64,
        f: fn(ProfileField) -> Field,
        kind_field: Field,
    ) -> Result<ArcsAndLines, SpecError> {
        use ProfileField as P;
        let kind = "arcs-and-lines";
        let start = point(
            f(P::Start),
            need(kind_field, kind, f(P::Start), self.start)?,
        )?;
        let pieces = self.pieces.as_ref().ok_or_else(|| SpecError::Missing {
            field: kind_field,
            kind: kind.into(),
            missing: key(f(P::Pieces)),
        })?;
        if pieces.len() < 2 || pieces.len() > MAX_PIECES {
            return Err(SpecError::Rule {
                field: f(P::Pieces),
                reason: format!(
                    "{} pieces: a closed profile has from 2 to {MAX_PIECES}",
                    pieces.len()
                ),
            });
        }
        let at = |i: usize, k: PieceField| f(P::Piece(i, k));
        // the size the joins are judged against
        let mut size = start.coords.norm();
        for p in pieces {
            size = size.max(p.to[0].hypot(p.to[1]));
            if let Some(c) = p.centre {
                size = size.max(c[0].hypot(c[1]));
            }
        }
        let tol = 1e-9 * size;
        let mut chain = Vec::with_capacity(pieces.len());
        let mut from = start;
        for (i, p) in pieces.iter().enumerate() {
            let to = point(at(i, PieceField::To), p.to)?;
            if (to - from).norm() <= tol && p.centre.is_none() {
                return Err(SpecError::Rule {
                    field: at(i, PieceField::To),
                    reason: format!(
                        "{} is where the piece starts: a line of no length",
                        vector(p.to)
                    ),
                });
            }
            chain.push(match p.centre {
                None => {
                    if p.clockwise.is_some() {
                        return Err(SpecError::Rule {
                            field: at(i, PieceField::Clockwise),
                            reason: "a line has no sense of turning: clockwise is an arc's (give its centre)".into(),
                        });
                    }
                    Piece::Line { from, to }
                }
                Some(c) => {
                    let c = point(at(i, PieceField::Centre), c)?;
                    let (r0, r1) = ((from - c).norm(), (to - c).norm());
                    if !(r0 > tol) || (r0 - r1).abs() > tol {
                        return Err(SpecError::Rule {
                            field: at(i, PieceField::Centre),
                            reason: format!(
                                "{} is {} from where the piece starts and {} from its end: not the centre of an arc through both",
                                vector([c.x, c.y]),
                                crate::human::human(r0),
                                crate::human::human(r1)
                            ),
                        });
                    }
                    let a0 = (from - c).y.atan2((from - c).x);
                    let a1 = (to - c).y.atan2((to - c).x);
                    let cw = p.clockwise.unwrap_or(false);
                    // the turn from start to end in the arc's sense; a closed circle when they meet
                    let mut sweep = if cw {
                        -(a0 - a1).rem_euclid(TAU)
                    } else {
                        (a1 - a0).rem_euclid(TAU)
                    };
                    if sweep.abs() * r0 <= tol {
                        sweep = if cw { -TAU } else { TAU };
                    }
                    Piece::Arc {
                        centre: c,
                        radius: r0,
                        start: a0,
                        sweep,
                    }
                }
            });
            from = to;
        }
        if (from - start).norm() > tol {
            let last = pieces.len() - 1;
            return Err(SpecError::Rule {
                field: at(last, PieceField::To),
                reason: format!(
                    "the chain ends at {}, not at its start {}: the profile does not close",
                    vector(pieces[last].to),
                    vector([start.x, start.y])
                ),
            });
        }
        // the last piece ends exactly at the start
        let scaled: Vec<Piece> = chain
            .into_iter()
            .map(|p| match p {
                Piece::Line { from, to } => Piece::Line {
                    from: from * scale,
                    to: to * scale,
                },
                Piece::Arc {
                    centre,
                    radius,
                    start,
                    sweep,
                } => Piece::Arc {
                    centre: centre * scale,
                    radius: radius * scale,
                    start,
                    sweep,
                },
            })
            .collect();
        ArcsAndLines::new(scaled).map_err(|e| match e {
            // at the later piece, the point in the file's unit
            ArcsError::Crosses { first, second, at: x } => SpecError::Rule {
                field: at(second, PieceField::To),
                reason: format!(
                    "the piece meets pieces[{first}] at {}, not at a join they share: the profile crosses or overlaps itself (a figure of eight, a fold); a cam's outline must be a simple closed curve",
                    vector([x.x / scale, x.y / scale])
                ),
            },
            e => SpecError::Rule {
                field: f(P::Pieces),
                reason: e.to_string(),
            },
        })
    }
}
