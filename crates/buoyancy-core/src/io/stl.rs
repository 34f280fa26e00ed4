//! STL, ASCII and binary.

use alloc::collections::BTreeMap;
use alloc::format;
use alloc::vec::Vec;

use nalgebra::Point3;

use super::parse_error;
use crate::mesh::primitives::Shape;
use crate::{Error, Real};

/// Parses an STL file, binary or ASCII, and welds vertices with identical coordinates (STL
/// stores every triangle's corners separately). Facet normals are ignored: orientation comes
/// from the vertex order.
pub fn parse_stl<T: Real>(bytes: &[u8]) -> Result<Shape<T>, Error> {
    let mut welder = Welder::default();
    let mut triangles = Vec::new();
    let binary_size = |n: u32| 84 + 50 * n as usize;
    let declared = bytes
        .get(80..84)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]));
    let looks_ascii = bytes.trim_ascii_start().starts_with(b"solid")
        && declared.is_none_or(|n| binary_size(n) != bytes.len());
    if looks_ascii {
        let text = core::str::from_utf8(bytes)
            .map_err(|_| parse_error(0, "ASCII STL that is not valid UTF-8".into()))?;
        let mut corners = Vec::with_capacity(3);
        for (number, line) in text.lines().enumerate() {
            let mut words = line.split_whitespace();
            match words.next() {
                Some("vertex") => {
                    let mut xyz = [0.0f64; 3];
                    for c in xyz.iter_mut() {
                        let word = words.next().ok_or_else(|| {
                            parse_error(number + 1, "a vertex needs three coordinates".into())
                        })?;
                        *c = word.parse().map_err(|_| {
                            parse_error(number + 1, format!("{word:?} is not a number"))
                        })?;
                    }
                    corners.push(welder.index(xyz));
                }
                Some("endloop") => {
                    if corners.len() != 3 {
                        return Err(parse_error(
                            number + 1,
                            format!("a facet has {} vertices, not 3", corners.len()),
                        ));
                    }
                    triangles.push([corners[0], corners[1], corners[2]]);
                    corners.clear();
                }
                _ => {}
            }
        }
    } else {
        let n = declared
            .ok_or_else(|| parse_error(0, "shorter than an STL header (84 bytes)".into()))?;
        if bytes.len() < binary_size(n) {
            return Err(parse_error(
                0,
                format!(
                    "binary STL declares {n} triangles but holds only {} bytes",
                    bytes.len()
                ),
            ));
        }
        for record in bytes[84..binary_size(n)].chunks_exact(50) {
            let float = |k: usize| {
                let b = &record[12 + 4 * k..16 + 4 * k];
                f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64
            };
            let corner = |c: usize| [float(3 * c), float(3 * c + 1), float(3 * c + 2)];
            triangles.push([0, 1, 2].map(|c| welder.index(corner(c))));
        }
    }
    if triangles.is_empty() {
        return Err(parse_error(0, "no facets found".into()));
    }
    let vertices = welder
        .vertices
        .into_iter()
        .map(|p| Point3::from(p.map(T::from_f64_lossy)))
        .collect();
    Ok((vertices, triangles))
}

/// Gives identical coordinates the same index (compared bit for bit, with -0 as +0).
#[derive(Default)]
struct Welder {
    index: BTreeMap<[u64; 3], u32>,
    vertices: Vec<[f64; 3]>,
}

impl Welder {
    fn index(&mut self, p: [f64; 3]) -> u32 {
        let key = p.map(|c| (c + 0.0).to_bits());
        *self.index.entry(key).or_insert_with(|| {
            self.vertices.push(p);
            (self.vertices.len() - 1) as u32
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Mesh, mesh::primitives};
    use alloc::string::String;
    use alloc::vec;

    fn binary_stl(v: &[Point3<f64>], t: &[[u32; 3]]) -> Vec<u8> {
        let mut out = vec![0u8; 80];
        out.extend((t.len() as u32).to_le_bytes());
        for tri in t {
            out.extend([0u8; 12]);
            for &i in tri {
                for c in v[i as usize].iter() {
                    out.extend((*c as f32).to_le_bytes());
                }
            }
            out.extend([0u8; 2]);
        }
        out
    }

    #[test]
    fn stl_binary_and_ascii_round_trip() {
        let (v, t) = primitives::cube::<f64>(2).unwrap();
        let (bv, bt) = parse_stl::<f64>(&binary_stl(&v, &t)).unwrap();
        assert_eq!((bv.len(), bt.len()), (v.len(), t.len()));
        assert!((Mesh::new(bv, bt).unwrap().volume() - 1.0).abs() < 1e-12);

        let mut ascii = String::from("solid cube\n");
        for tri in &t {
            ascii += "facet normal 0 0 0\nouter loop\n";
            for &i in tri {
                let p = v[i as usize];
                ascii += &format!("vertex {} {} {}\n", p.x, p.y, p.z);
            }
            ascii += "endloop\nendfacet\n";
        }
        ascii += "endsolid cube\n";
        let (av, at) = parse_stl::<f64>(ascii.as_bytes()).unwrap();
        assert!((Mesh::new(av, at).unwrap().volume() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn truncated_binary_stl_is_an_error() {
        let mut bytes = vec![0u8; 84];
        bytes[80] = 5;
        assert!(matches!(parse_stl::<f64>(&bytes), Err(Error::Parse { .. })));
        assert!(matches!(
            parse_stl::<f64>(&[1, 2, 3]),
            Err(Error::Parse { .. })
        ));
    }
}
