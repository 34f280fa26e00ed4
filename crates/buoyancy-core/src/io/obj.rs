//! Wavefront OBJ text.

use alloc::format;
use alloc::vec::Vec;

use nalgebra::Point3;

use super::parse_error;
use crate::mesh::primitives::Shape;
use crate::{Error, Real};

/// Parses Wavefront OBJ text: `v x y z` and `f` lines (`f 1 2 3`, `f 1/1/1 2/2/2 3/3/3`,
/// negative relative indices, polygons fanned into triangles); every other statement is ignored.
/// OBJ counts vertices from 1; the triangles returned count from 0, so the file's vertex `n` is
/// vertex `n - 1` in them and in the errors of [`Mesh::new`](crate::Mesh::new).
///
/// ```
/// let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
/// let (vertices, triangles) = buoyancy_core::io::parse_obj::<f64>(text).unwrap();
/// assert_eq!((vertices.len(), triangles.len()), (4, 4));
/// assert_eq!(triangles[0], [0, 2, 1]);
/// ```
pub fn parse_obj<T: Real>(text: &str) -> Result<Shape<T>, Error> {
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    let mut polygon: Vec<u32> = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let number = number + 1;
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let mut xyz = [0.0f64; 3];
                for c in xyz.iter_mut() {
                    let word = words.next().ok_or_else(|| {
                        parse_error(number, "a vertex needs three coordinates".into())
                    })?;
                    *c = word
                        .parse()
                        .map_err(|_| parse_error(number, format!("{word:?} is not a number")))?;
                }
                vertices.push(Point3::from(xyz.map(T::from_f64_lossy)));
            }
            Some("f") => {
                polygon.clear();
                for word in words {
                    let index = word.split('/').next().unwrap_or("");
                    let i: i64 = index.parse().map_err(|_| {
                        parse_error(number, format!("{word:?} is not a vertex index"))
                    })?;
                    let resolved = match i {
                        0 => None,
                        i if i > 0 => Some(i - 1),
                        i => Some(vertices.len() as i64 + i),
                    };
                    let resolved = resolved
                        .filter(|&r| r >= 0 && r < vertices.len() as i64)
                        .ok_or_else(|| {
                            parse_error(
                                number,
                                format!("vertex index {i} does not refer to one of the {} vertices read so far", vertices.len()),
                            )
                        })?;
                    polygon.push(resolved as u32);
                }
                if polygon.len() < 3 {
                    return Err(parse_error(
                        number,
                        "a face needs at least three vertices".into(),
                    ));
                }
                for k in 1..polygon.len() - 1 {
                    triangles.push([polygon[0], polygon[k], polygon[k + 1]]);
                }
            }
            _ => {}
        }
    }
    if triangles.is_empty() {
        return Err(parse_error(0, "no faces (`f` lines) found".into()));
    }
    Ok((vertices, triangles))
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec;

    #[test]
    fn obj_errors_name_the_line() {
        let e = parse_obj::<f64>("v 0 0 0\nv 1 0 0\nf 1 2 7\n").unwrap_err();
        assert!(matches!(e, Error::Parse { line: 3, .. }), "{e}");
        let e = parse_obj::<f64>("v 0 0 x\n").unwrap_err();
        assert!(matches!(e, Error::Parse { line: 1, .. }), "{e}");
        let e = parse_obj::<f64>("v 0 0 0\n").unwrap_err();
        assert!(matches!(e, Error::Parse { line: 0, .. }), "{e}");
        let (_, t) =
            parse_obj::<f64>("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4/1 -3/2 -2/3 -1/4\n")
                .unwrap();
        assert_eq!(t, vec![[0, 1, 2], [0, 2, 3]]);
    }
}
