//! Reading nodal points from a text file: one point per line, `x,y` (commas, semicolons, tabs or
//! spaces between the two numbers). Blank lines and lines starting with `#` are skipped; a first
//! line that holds letters is taken as a header and skipped.

use super::CurveError;
use crate::geometry::Point2;
use std::path::Path;

/// Most points read from one file.
pub const MAX_POINTS: usize = 100_000;

/// Parses points from text: one `x,y` per line (commas, semicolons, tabs or spaces between the
/// numbers); blank lines and `#` comments are skipped, a first line with letters is a header.
/// Errors name the 1-based line.
pub fn parse_points(text: &str) -> Result<Vec<Point2>, CurveError> {
    parse_points_with_lines(text).map(|(p, _)| p)
}

/// As [`parse_points`], also returning the 1-based line of every point.
pub fn parse_points_with_lines(text: &str) -> Result<(Vec<Point2>, Vec<usize>), CurveError> {
    // a byte-order mark, as some CAD and spreadsheet exports write
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut points = Vec::new();
    let mut lines = Vec::new();
    let mut seen_data = false;
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let syntax = |message: &str| CurveError::PointsFileSyntax {
            line: i + 1,
            message: message.to_string(),
            content: raw.chars().take(120).collect(),
        };
        // commas or semicolons delimit fields (an empty field between two is an error, not
        // skipped); without them, whitespace does
        let fields: Vec<&str> = if line.contains([',', ';']) {
            line.split([',', ';']).map(str::trim).collect()
        } else {
            line.split_whitespace().collect()
        };
        // a header: the first line that holds no number at all, only words (`x,y`, `x_info y_mm`)
        if !seen_data
            && fields.iter().all(|f| f.parse::<f64>().is_err())
            && line.chars().any(|c| c.is_alphabetic())
        {
            seen_data = true;
            continue;
        }
        if let Some(k) = fields.iter().position(|f| f.is_empty()) {
            return Err(syntax(&format!(
                "field {} is empty (two delimiters in a row, or one at the end)",
                k + 1
            )));
        }
        seen_data = true;
        if fields.len() != 2 {
            return Err(syntax(&format!(
                "expected 2 numbers (x,y), found {} fields",
                fields.len()
            )));
        }
        let x: f64 = fields[0]
            .parse()
            .map_err(|_| syntax(&format!("x is not a number: {:?}", fields[0])))?;
        let y: f64 = fields[1]
            .parse()
            .map_err(|_| syntax(&format!("y is not a number: {:?}", fields[1])))?;
        if !(x.is_finite() && y.is_finite()) {
            return Err(syntax("coordinates must be finite"));
        }
        // the sizes the computation takes (their squares stay in f64), as a file's coordinates
        if x.abs().max(y.abs()) > 1e100 {
            return Err(syntax(
                "coordinates must be at most 1e100 in magnitude (their squares must stay finite)",
            ));
        }
        if points.len() == MAX_POINTS {
            return Err(syntax(&format!("more than {MAX_POINTS} points")));
        }
        points.push(Point2::new(x, y));
        lines.push(i + 1);
    }
    Ok((points, lines))
}

/// Largest points file read, bytes.
pub const MAX_FILE_BYTES: u64 = 16 << 20;

/// Reads and parses a points file (at most [`MAX_FILE_BYTES`], counted while reading, so that a
/// device or a pipe cannot make it read without end); returns the points and their lines.
pub fn read_points_file(path: &Path) -> Result<(Vec<Point2>, Vec<usize>), CurveError> {
    use std::io::Read;
    let io = |message: String| CurveError::PointsFileIo {
        path: path.display().to_string(),
        message,
    };
    let file = std::fs::File::open(path).map_err(|e| io(e.to_string()))?;
    let mut bytes = Vec::new();
    file.take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| io(e.to_string()))?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(io(format!(
            "more than {} MiB: not a points file (the limit is {MAX_FILE_BYTES} bytes)",
            MAX_FILE_BYTES >> 20
        )));
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        io(format!(
            "not UTF-8 text (invalid byte at offset {})",
            e.utf8_error().valid_up_to()
        ))
    })?;
    parse_points_with_lines(&text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_commas_spaces_comments_and_header() {
        let p = parse_points("x,y\n# comment\n1,2\n\n3.5 -4\n5;6e-1\n").unwrap();
        assert_eq!(
            p,
            vec![
                Point2::new(1.0, 2.0),
                Point2::new(3.5, -4.0),
                Point2::new(5.0, 0.6)
            ]
        );
    }

    #[test]
    fn byte_order_mark_and_crlf_are_accepted() {
        let p = parse_points("\u{feff}1,0\r\n0,1\r\n-1,0\r\n").unwrap();
        assert_eq!(p.len(), 3);
        assert_eq!(p[0], Point2::new(1.0, 0.0));
    }

    #[test]
    fn errors_name_the_line() {
        let e = parse_points("1,2\n3,abc\n").unwrap_err();
        assert!(
            matches!(e, CurveError::PointsFileSyntax { line: 2, .. }),
            "{e}"
        );
        let e = parse_points("1,2\n3,4,5\n").unwrap_err();
        assert!(e.to_string().contains("line 2"), "{e}");
        let e = parse_points("1,2\nnan,4\n").unwrap_err();
        assert!(
            matches!(e, CurveError::PointsFileSyntax { line: 2, .. }),
            "{e}"
        );
    }

    #[test]
    fn an_empty_field_is_an_error_not_skipped() {
        for text in [
            "1,2\n5.0,,0.0\n",
            "1,2\n5.0;;0.0\n",
            "1,2\n5.0,0.0,\n",
            "1,2\n,5.0,0.0\n",
        ] {
            let e = parse_points(text).unwrap_err();
            assert!(
                matches!(e, CurveError::PointsFileSyntax { line: 2, .. }),
                "{text:?}: {e}"
            );
            assert!(e.to_string().contains("empty"), "{e}");
        }
    }

    #[test]
    fn a_header_is_words_only_wherever_its_letters_are() {
        for header in ["x_info,y_info", "X Y", "x_mm;y_mm", "inflection,nancy"] {
            let p = parse_points(&format!("{header}\n1,2\n3,4\n")).unwrap();
            assert_eq!(p.len(), 2, "{header}");
        }
        // a first line with a number in it is data: a typo is an error, not a skipped header
        let e = parse_points("1.0,2.O\n3,4\n").unwrap_err();
        assert!(
            matches!(e, CurveError::PointsFileSyntax { line: 1, .. }),
            "{e}"
        );
    }

    #[test]
    fn reading_stops_at_the_cap_whatever_the_metadata_says() {
        // /dev/zero has length 0 in its metadata and no end
        let zero = Path::new("/dev/zero");
        if zero.exists() {
            let e = read_points_file(zero).unwrap_err();
            assert!(e.to_string().contains("MiB"), "{e}");
        }
    }
}
