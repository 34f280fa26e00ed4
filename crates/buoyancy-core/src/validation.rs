//! The checks a mesh passes before anything is computed from it: indices in range, finite
//! vertices, and a closed, consistently oriented 2-manifold.

use alloc::vec::Vec;

use nalgebra::Point3;

use crate::{Error, Real};

/// Checks `vertices` and `triangles` as [`Mesh::new`](crate::Mesh::new) documents, in its
/// order of checking; the enclosed volume is checked afterwards, by the caller.
pub(crate) fn validate<T: Real>(
    vertices: &[Point3<T>],
    triangles: &[[u32; 3]],
) -> Result<(), Error> {
    if triangles.is_empty() {
        return Err(Error::EmptyMesh);
    }
    if u32::try_from(vertices.len()).is_err() {
        return Err(Error::TooManyVertices {
            count: vertices.len(),
        });
    }
    if let Some(vertex) = vertices
        .iter()
        .position(|p| !p.iter().all(|c| c.is_finite()))
    {
        return Err(Error::NonFiniteVertex { vertex });
    }
    for (triangle, t) in triangles.iter().enumerate() {
        if let Some(&index) = t.iter().find(|&&i| i as usize >= vertices.len()) {
            return Err(Error::IndexOutOfRange {
                triangle,
                index,
                vertex_count: vertices.len(),
            });
        }
        if t[0] == t[1] || t[1] == t[2] || t[2] == t[0] {
            return Err(Error::RepeatedIndex {
                triangle,
                indices: *t,
            });
        }
    }
    check_closed_manifold(triangles)
}

/// Checks that every edge is shared by exactly two triangles traversing it in opposite
/// directions. Runs in O(n log n) with one sort, no hashing (no_std).
fn check_closed_manifold(triangles: &[[u32; 3]]) -> Result<(), Error> {
    // (smaller vertex, larger vertex, triangle, whether the triangle goes smaller -> larger)
    let mut edges: Vec<(u32, u32, u32, bool)> = Vec::with_capacity(triangles.len() * 3);
    for (i, t) in triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            edges.push((a.min(b), a.max(b), i as u32, a < b));
        }
    }
    edges.sort_unstable();
    let mut start = 0;
    while start < edges.len() {
        let (lo, hi, first, forward) = edges[start];
        let mut end = start + 1;
        while end < edges.len() && edges[end].0 == lo && edges[end].1 == hi {
            end += 1;
        }
        let edge = [lo, hi];
        match end - start {
            1 => {
                return Err(Error::OpenEdge {
                    edge,
                    triangle: first as usize,
                });
            }
            2 => {
                let (_, _, second, second_forward) = edges[start + 1];
                if forward == second_forward {
                    return Err(Error::InconsistentOrientation {
                        edge: if forward { [lo, hi] } else { [hi, lo] },
                        triangles: [first as usize, second as usize],
                    });
                }
            }
            n => {
                return Err(Error::NonManifoldEdge {
                    edge,
                    triangle_count: n,
                    triangles: [first as usize, edges[start + 1].2 as usize],
                });
            }
        }
        start = end;
    }
    Ok(())
}
