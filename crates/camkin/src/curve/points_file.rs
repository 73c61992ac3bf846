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
        let fields: Vec<&str> = line
            .split(|c: char| c == ',' || c == ';' || c.is_whitespace())
            .filter(|f| !f.is_empty())
            .collect();
        if !seen_data
            && fields.iter().any(|f| f.parse::<f64>().is_err())
            && line.chars().any(|c| c.is_alphabetic())
            && !line.to_ascii_lowercase().contains("nan")
            && !line.to_ascii_lowercase().contains("inf")
        {
            seen_data = true; // header
            continue;
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
        if points.len() == MAX_POINTS {
            return Err(syntax(&format!("more than {MAX_POINTS} points")));
        }
        points.push(Point2::new(x, y));
        lines.push(i + 1);
    }
    Ok((points, lines))
}

/// Largest points file read, bytes.
pub const MAX_FILE_BYTES: u64 = 64 << 20;

/// Reads and parses a points file (at most [`MAX_FILE_BYTES`]); returns the points and their
/// lines.
pub fn read_points_file(path: &Path) -> Result<(Vec<Point2>, Vec<usize>), CurveError> {
    let io = |message: String| CurveError::PointsFileIo {
        path: path.display().to_string(),
        message,
    };
    let len = std::fs::metadata(path)
        .map_err(|e| io(e.to_string()))?
        .len();
    if len > MAX_FILE_BYTES {
        return Err(io(format!(
            "{len} bytes is more than the {MAX_FILE_BYTES} read"
        )));
    }
    let text = std::fs::read_to_string(path).map_err(|e| io(e.to_string()))?;
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
}
