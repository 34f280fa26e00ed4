//! What the hierarchy's nodes carry for the methods: the sums, over each node's triangles, of
//! the terms a method adds for a fully submerged triangle, so that a node entirely under water
//! is added without visiting its triangles.
//!
//! Both kinds are built here, by one bottom-up pass over the tree, in `f64` and about the mesh
//! centroid (mesh frame), from per-triangle terms the mesh supplies ([`TriangleTerms`]):
//!
//! * for the volume methods, every node (leaves included) stores `Σ detᵢ` and
//!   `Σ detᵢ·(aᵢ + bᵢ + cᵢ)` with `detᵢ = aᵢ·(bᵢ×cᵢ)`: six times the volume and twenty-four
//!   times the first moment of the tetrahedra from the centroid to its triangles, what `Fast`
//!   sums over the fully submerged triangles, and `Σ (bᵢ − aᵢ)×(cᵢ − aᵢ)`, which moves the
//!   tetrahedra's apex onto the water plane for `Exact` and `Improved`, and
//!   `Σ |(bᵢ − aᵢ)×(cᵢ − aᵢ)|`, twice the area, what a node under water adds to the wetted area
//!   ([`VolumeNodeSums`]);
//! * for the surface methods, every inner node stores the 30 coefficients of its triangles'
//!   pressure integrals as polynomials in the water plane, and their area beside them, where the
//!   surface walk reads it ([`SurfaceMoments`]); leaves hold at most a few triangles, which a
//!   query integrates directly, so they store nothing.

use alloc::vec::Vec;

use nalgebra::Vector3;

use crate::Real;
use crate::mesh::hierarchy::Hierarchy;
use crate::query::surface_integral::moments::SurfaceMoments;

/// One triangle's terms, `f64`, mesh frame, about the centroid: what a node sums.
pub(crate) struct TriangleTerms {
    /// `det = a·(b×c)`.
    pub volume6: f64,
    /// `det·(a + b + c)`.
    pub moment24: Vector3<f64>,
    /// `(b − a)×(c − a)`, twice the area vector.
    pub area2: Vector3<f64>,
    /// `|(b − a)×(c − a)|`, twice the area.
    pub double_area: f64,
    /// The coefficients of its pressure integrals.
    pub surface: SurfaceMoments<f64>,
}

/// The volume methods' sums over a node's triangles, about the centroid, mesh frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct VolumeNodeSums<T: Real> {
    /// `Σ det`: six times the volume of the tetrahedra from the centroid to the triangles.
    pub volume6: T,
    /// `Σ det·(a + b + c)`: twenty-four times their first moment about the centroid.
    pub moment24: Vector3<T>,
    /// `Σ (b − a)×(c − a)`: twice the sum of their area vectors.
    pub area2: Vector3<T>,
    /// `Σ |(b − a)×(c − a)|`: twice their area, m².
    pub double_area: T,
}

impl VolumeNodeSums<f64> {
    fn zero() -> Self {
        VolumeNodeSums {
            volume6: 0.0,
            moment24: Vector3::zeros(),
            area2: Vector3::zeros(),
            double_area: 0.0,
        }
    }

    fn add(&mut self, o: &Self) {
        self.volume6 += o.volume6;
        self.moment24 += o.moment24;
        self.area2 += o.area2;
        self.double_area += o.double_area;
    }

    fn cast<T: Real>(&self) -> VolumeNodeSums<T> {
        VolumeNodeSums {
            volume6: T::from_f64_lossy(self.volume6),
            moment24: self.moment24.map(T::from_f64_lossy),
            area2: self.area2.map(T::from_f64_lossy),
            double_area: T::from_f64_lossy(self.double_area),
        }
    }
}

/// The sums of every node of a [`Hierarchy`], indexed by node.
#[derive(Debug, Clone)]
pub(crate) struct NodeSums<T: Real> {
    /// Per node (leaves included), the volume methods' sums.
    volume: Vec<VolumeNodeSums<T>>,
    /// Per node: the position of its coefficients in `surface`, or `u32::MAX` for a leaf.
    surface_slots: Vec<u32>,
    /// The surface methods' coefficients of the inner nodes.
    surface: Vec<SurfaceMoments<T>>,
}

impl<T: Real> NodeSums<T> {
    /// Sums `terms(i)` of the triangles `i` (in leaf order) over every node of `hierarchy`,
    /// bottom-up, in `f64`.
    pub fn build(hierarchy: &Hierarchy<T>, terms: impl Fn(usize) -> TriangleTerms) -> Self {
        let count = hierarchy.nodes.len();
        let mut builder = Builder {
            hierarchy,
            terms,
            volume: alloc::vec![VolumeNodeSums::zero(); count],
            surface_slots: alloc::vec![u32::MAX; count],
            surface: Vec::new(),
        };
        if count > 0 {
            builder.subtree(0);
        }
        NodeSums {
            volume: builder.volume.iter().map(VolumeNodeSums::cast).collect(),
            surface_slots: builder.surface_slots,
            surface: builder.surface.iter().map(SurfaceMoments::cast).collect(),
        }
    }

    /// The volume sums of node `index`.
    #[inline(always)]
    pub fn volume(&self, index: usize) -> &VolumeNodeSums<T> {
        &self.volume[index]
    }

    /// The surface coefficients of node `index`, `None` for a leaf.
    #[inline]
    pub fn surface(&self, index: usize) -> Option<&SurfaceMoments<T>> {
        self.surface.get(self.surface_slots[index] as usize)
    }

    /// Bytes of memory used.
    pub fn memory(&self) -> usize {
        self.volume.len() * core::mem::size_of::<VolumeNodeSums<T>>()
            + self.surface_slots.len() * core::mem::size_of::<u32>()
            + self.surface.len() * core::mem::size_of::<SurfaceMoments<T>>()
    }
}

struct Builder<'a, T: Real, F> {
    hierarchy: &'a Hierarchy<T>,
    terms: F,
    volume: Vec<VolumeNodeSums<f64>>,
    surface_slots: Vec<u32>,
    surface: Vec<SurfaceMoments<f64>>,
}

impl<T: Real, F: Fn(usize) -> TriangleTerms> Builder<'_, T, F> {
    /// The sums of the subtree at `index`, recording those of its nodes.
    fn subtree(&mut self, index: usize) -> (VolumeNodeSums<f64>, SurfaceMoments<f64>) {
        let (volume, surface) = match self.hierarchy.children(index) {
            None => {
                let (mut volume, mut surface) = (VolumeNodeSums::zero(), SurfaceMoments::zero());
                for i in self.hierarchy.range(index) {
                    let t = (self.terms)(i);
                    volume.add(&VolumeNodeSums {
                        volume6: t.volume6,
                        moment24: t.moment24,
                        area2: t.area2,
                        double_area: t.double_area,
                    });
                    surface.add(&t.surface);
                }
                (volume, surface)
            }
            Some((left, right)) => {
                let slot = self.surface.len();
                self.surface_slots[index] = slot as u32;
                self.surface.push(SurfaceMoments::zero());
                let (mut volume, mut surface) = self.subtree(left);
                let (right_volume, right_surface) = self.subtree(right);
                volume.add(&right_volume);
                surface.add(&right_surface);
                self.surface[slot] = surface;
                (volume, surface)
            }
        };
        self.volume[index] = volume;
        (volume, surface)
    }
}
