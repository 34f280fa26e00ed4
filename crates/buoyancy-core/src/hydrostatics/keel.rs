//! The lowest point of a mesh along the up normal, found through the hierarchy.

use nalgebra::Vector3;

use crate::query::frame::Frame;
use crate::{Mesh, Real};

impl<T: Real> Mesh<T> {
    /// The vertex lowest along the up normal at the frame's pose (mesh frame, relative to the
    /// centroid) and its height above the surface.
    ///
    /// Depth first through the hierarchy, nearer child first, skipping every node whose box
    /// lies above the lowest vertex found so far (by more than the round-off of the box test):
    /// about the depth of the tree times a few leaves for a convex body.
    pub(crate) fn lowest_vertex(&self, frame: &Frame<T>) -> (Vector3<T>, T) {
        let n = &frame.normal_local;
        let nodes = &self.hierarchy.nodes;
        // The lowest point of a node's box, relative to the centroid, along `n`.
        let floor = |index: usize| {
            let b = &nodes[index].bounds;
            (0..3).fold(T::zero(), |sum, k| {
                let (lo, hi) = (T::from_f32_exact(b[k]), T::from_f32_exact(b[k + 3]));
                sum + (n[k] * lo).min(n[k] * hi)
            })
        };
        let margin = self.hierarchy.height_round_off(T::zero()) * T::from_f64_lossy(2.0);
        let first = self.corners(0)[0];
        let (mut best, mut lowest) = (first, n.dot(&first));
        let mut stack = [0usize; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let index = stack[top];
            if floor(index) - margin > lowest {
                continue;
            }
            match self.hierarchy.children(index) {
                Some((left, right)) => {
                    // The child whose box reaches lower goes on top, to be opened first.
                    let (near, far) = if floor(left) <= floor(right) {
                        (left, right)
                    } else {
                        (right, left)
                    };
                    stack[top] = far;
                    stack[top + 1] = near;
                    top += 2;
                }
                None => {
                    for i in self.hierarchy.range(index) {
                        for v in self.corners(i) {
                            let height = n.dot(&v);
                            if height < lowest {
                                (best, lowest) = (v, height);
                            }
                        }
                    }
                }
            }
        }
        (best, lowest + frame.height)
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{Translation3, UnitQuaternion, Vector3};

    use crate::query::frame::Frame;
    use crate::{Mesh, Pose, Water, mesh::primitives};

    #[test]
    fn lowest_vertex_matches_a_scan() {
        let (v, t) = primitives::torus::<f64>(1.0, 0.3, 48, 24).unwrap();
        let mesh = Mesh::new(v, t).unwrap();
        let water = Water::default();
        for k in 0..50 {
            let axis = Vector3::new(1.0, 0.3 * k as f64, -0.7 + 0.05 * k as f64);
            let pose = Pose::from_parts(
                Translation3::new(0.1 * k as f64, -0.2, 3.0),
                UnitQuaternion::from_scaled_axis(axis.normalize() * (0.13 * k as f64)),
            );
            let frame = Frame::new(&mesh, &pose, &water).unwrap();
            let (vertex, height) = mesh.lowest_vertex(&frame);
            let scan = mesh
                .vertices
                .iter()
                .map(|v| frame.normal_local.dot(v) + frame.height)
                .fold(f64::INFINITY, f64::min);
            assert_eq!(height, scan, "pose {k}");
            assert_eq!(frame.normal_local.dot(&vertex) + frame.height, scan);
        }
    }
}
