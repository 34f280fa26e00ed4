//! Procedural closed meshes: cube, UV sphere, torus, torus knot and Wigley hull; and the
//! primitives of physics engines, each holding exactly the volume of the solid it stands for
//! (cuboid, ellipsoid, cylinder, capsule), so that a body's mass from its density and the water
//! it displaces agree.
//!
//! Each function returns `(vertices, triangles)` ready for [`Mesh::new`](crate::Mesh::new):
//! closed 2-manifolds wound counter-clockwise seen from outside, with shared (welded) vertices;
//! or [`Error::InvalidShape`] naming the parameter that is out of range (a count too small or so
//! large that the indices would not fit a `u32`, a length that is not finite and positive).

use alloc::vec::Vec;
use core::f64::consts::TAU;

use nalgebra::{Point3, Vector3};

use crate::error::vec_with_capacity;
use crate::{Error, Real};

/// Vertices and outward-wound triangles of a procedural mesh.
pub type Shape<T> = (Vec<Point3<T>>, Vec<[u32; 3]>);

fn finish<T: Real>(
    vertices: Vec<Point3<f64>>,
    triangles: Vec<[u32; 3]>,
) -> Result<Shape<T>, Error> {
    Ok((
        vertices
            .into_iter()
            .map(|p| p.map(T::from_f64_lossy))
            .collect(),
        triangles,
    ))
}

/// Checks that the count `value` is at least `min`.
fn at_least(
    value: usize,
    min: usize,
    parameter: &'static str,
    reason: &'static str,
) -> Result<(), Error> {
    if value >= min {
        Ok(())
    } else {
        Err(Error::InvalidShape { parameter, reason })
    }
}

/// Checks that the length `value` is finite and positive.
fn positive(value: f64, parameter: &'static str) -> Result<(), Error> {
    if !(value.is_finite() && value > 0.0) {
        Err(Error::InvalidShape {
            parameter,
            reason: "must be finite and positive",
        })
    } else if !(1e-100..=1e100).contains(&value) {
        Err(Error::InvalidShape {
            parameter,
            reason: "must lie between 1e-100 and 1e100 (m): beyond, the shape's volume \
                     overflows or vanishes in f64",
        })
    } else {
        Ok(())
    }
}

/// Checks that a tube of radius `tube` about a curve of size `size` is at least 10⁻⁶ of it:
/// thinner, `f64` cannot place the tube's vertices about the curve's (the mesh would be flat).
fn thick_enough(tube: f64, size: f64, parameter: &'static str) -> Result<(), Error> {
    if tube >= 1e-6 * size {
        Ok(())
    } else {
        Err(Error::InvalidShape {
            parameter,
            reason: "must be at least 1e-6 of the curve's radius: a thinner tube's vertices \
                     cannot be told apart in f64",
        })
    }
}

/// Checks that `vertices` vertices can be indexed by `u32` (`None`: the count overflowed).
fn indexable(vertices: Option<usize>, parameter: &'static str) -> Result<(), Error> {
    match vertices {
        Some(count) if count <= u32::MAX as usize => Ok(()),
        _ => Err(Error::InvalidShape {
            parameter,
            reason: "too large: the vertices would not fit u32 indices",
        }),
    }
}

/// The unit cube `[-1/2, 1/2]³`, each face split into `n × n` squares of two triangles:
/// `12·n²` triangles (`n = 10`: 1,200; `n = 100`: 120,000, the paper's two cubes).
///
/// # Errors
/// [`Error::InvalidShape`] if `n == 0` or `n` is too large for `u32` indices.
pub fn cube<T: Real>(n: usize) -> Result<Shape<T>, Error> {
    at_least(n, 1, "n", "must be at least 1")?;
    indexable(
        n.checked_mul(n)
            .and_then(|n2| n2.checked_mul(6))
            .and_then(|v| v.checked_add(2)),
        "n",
    )?;
    let side = n + 1;
    // Lattice points (i, j, k) ∈ [0, n]³ on the surface get an index on first use.
    let mut index = vec_with_capacity(side * side * side, "n")?;
    index.resize(side * side * side, u32::MAX);
    let mut vertices = vec_with_capacity(6 * n * n + 2, "n")?;
    let mut triangles = vec_with_capacity(12 * n * n, "n")?;
    let mut vertex = |p: [usize; 3]| -> u32 {
        let slot = &mut index[(p[0] * side + p[1]) * side + p[2]];
        if *slot == u32::MAX {
            *slot = vertices.len() as u32;
            vertices.push(Point3::from(Vector3::from(
                p.map(|c| c as f64 / n as f64 - 0.5),
            )));
        }
        *slot
    };
    // For each face: the fixed axis, its value, and two in-face axes (u, v) with u × v pointing out.
    for axis in 0..3 {
        let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
        for (fixed, (u, v)) in [(n, (u, v)), (0, (v, u))] {
            for a in 0..n {
                for b in 0..n {
                    let corner = |da: usize, db: usize| {
                        let mut p = [0; 3];
                        p[axis] = fixed;
                        p[u] = a + da;
                        p[v] = b + db;
                        p
                    };
                    let q =
                        [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)].map(&mut vertex);
                    triangles.push([q[0], q[1], q[2]]);
                    triangles.push([q[0], q[2], q[3]]);
                }
            }
        }
    }
    finish(vertices, triangles)
}

/// A UV sphere of `radius` about the origin with `slices` segments around the y axis and
/// `stacks` from pole to pole: `2·slices·(stacks − 1)` triangles, single vertices at the poles
/// (`50, 50`: 4,900; `200, 200`: 79,600). Every vertex lies on the sphere; the mesh is convex.
///
/// # Errors
/// [`Error::InvalidShape`] if `radius` is not finite and positive, `slices < 3`, `stacks < 2`,
/// or there are too many vertices for `u32` indices.
pub fn uv_sphere<T: Real>(radius: f64, slices: usize, stacks: usize) -> Result<Shape<T>, Error> {
    positive(radius, "radius")?;
    at_least(slices, 3, "slices", "must be at least 3")?;
    at_least(stacks, 2, "stacks", "must be at least 2")?;
    indexable(
        slices
            .checked_mul(stacks - 1)
            .and_then(|v| v.checked_add(2)),
        "slices",
    )?;
    let mut vertices = vec_with_capacity(2 + slices * (stacks - 1), "slices")?;
    vertices.push(Point3::new(0.0, radius, 0.0));
    for i in 1..stacks {
        let polar = core::f64::consts::PI * i as f64 / stacks as f64;
        for j in 0..slices {
            let azimuth = TAU * j as f64 / slices as f64;
            vertices.push(Point3::new(
                radius * libm::sin(polar) * libm::cos(azimuth),
                radius * libm::cos(polar),
                -radius * libm::sin(polar) * libm::sin(azimuth),
            ));
        }
    }
    let south = vertices.len() as u32;
    vertices.push(Point3::new(0.0, -radius, 0.0));
    let ring = |i: usize, j: usize| (1 + (i - 1) * slices + j % slices) as u32;
    let mut triangles = vec_with_capacity(2 * slices * (stacks - 1), "slices")?;
    for j in 0..slices {
        triangles.push([0, ring(1, j), ring(1, j + 1)]);
        triangles.push([south, ring(stacks - 1, j + 1), ring(stacks - 1, j)]);
    }
    for i in 1..stacks - 1 {
        for j in 0..slices {
            let (a, b, c, d) = (
                ring(i, j),
                ring(i + 1, j),
                ring(i + 1, j + 1),
                ring(i, j + 1),
            );
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    finish(vertices, triangles)
}

/// A torus about the y axis: tube of radius `minor` around a circle of radius `major`,
/// `segments` around the axis and `sides` around the tube: `2·segments·sides` triangles.
///
/// # Errors
/// [`Error::InvalidShape`] if a radius is not finite and positive, `minor >= major` (the tube
/// would cross itself), `segments < 3`, `sides < 3`, or there are too many vertices for `u32`
/// indices.
pub fn torus<T: Real>(
    major: f64,
    minor: f64,
    segments: usize,
    sides: usize,
) -> Result<Shape<T>, Error> {
    positive(major, "major")?;
    positive(minor, "minor")?;
    if minor >= major {
        return Err(Error::InvalidShape {
            parameter: "minor",
            reason: "must be smaller than major",
        });
    }
    thick_enough(minor, major, "minor")?;
    tube(segments, sides, minor, |u| {
        let (s, c) = (libm::sin(u), libm::cos(u));
        (
            Vector3::new(major * c, 0.0, -major * s),
            Vector3::new(-s, 0.0, -c),
        )
    })
}

/// A `(p, q)` torus knot (`p = 2, q = 3`: the trefoil) on a torus of radius `radius`, swept by a
/// tube of radius `tube_radius`: `2·segments·sides` triangles (`80, 11`: 1,760, the size of the
/// paper's torus knot).
///
/// # Errors
/// [`Error::InvalidShape`] if `p` or `q` is zero, `p` and `q` have a common factor (the curve
/// would run over itself `gcd(p, q)` times), a radius is not finite and positive, the tube is
/// too thick for the curve (it would run into itself: any two points of the curve more than
/// `π·tube_radius` apart along it must be at least `2·tube_radius` apart, on 1,024 to 8,192
/// samples), or thinner than 10⁻⁶ of `radius`, `segments < 3`,
/// `sides < 3`, or there are too many vertices for `u32` indices.
pub fn torus_knot<T: Real>(
    p: u32,
    q: u32,
    radius: f64,
    tube_radius: f64,
    segments: usize,
    sides: usize,
) -> Result<Shape<T>, Error> {
    at_least(p as usize, 1, "p", "must be at least 1")?;
    at_least(q as usize, 1, "q", "must be at least 1")?;
    if greatest_common_divisor(p, q) > 1 {
        return Err(Error::InvalidShape {
            parameter: "q",
            reason: "must have no common factor with p: a (p, q) torus knot with gcd(p, q) = d \
                     > 1 runs over the same curve d times",
        });
    }
    positive(radius, "radius")?;
    positive(tube_radius, "tube_radius")?;
    thick_enough(tube_radius, radius, "tube_radius")?;
    let samples = (64 * p.max(q) as usize).clamp(1024, 8192);
    let (p, q) = (p as f64, q as f64);
    let point = |u: f64| {
        let r = radius * (2.0 + libm::cos(q * u)) / 2.0;
        Vector3::new(
            r * libm::cos(p * u),
            r * libm::sin(p * u),
            radius * libm::sin(q * u) / 2.0,
        )
    };
    if !tube_fits(&point, samples, tube_radius) {
        return Err(Error::InvalidShape {
            parameter: "tube_radius",
            reason: "is too large for the knot: the tube would run into itself (for p = 2, \
                     q = 3 it must stay under 0.41 times the radius)",
        });
    }
    tube(segments, sides, tube_radius, move |u| {
        // Central differences: the tangent is only needed up to scale.
        let du = 1e-4;
        (point(u), point(u + du) - point(u - du))
    })
}

/// The greatest common divisor of `a` and `b` (Euclid).
fn greatest_common_divisor(mut a: u32, mut b: u32) -> u32 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// Whether a tube of radius `r` about the closed curve `point(u)`, `u ∈ [0, 2π)`, stays clear of
/// itself, judged on `samples` points of the curve: any two points further apart along the
/// curve than half the tube's circumference, `π·r`, must be at least `2r` apart in space. (On
/// a circle of radius `ρ ≥ r`, two points `π·r` apart along it are `2ρ·sin(πr/2ρ) ≥ 2r`
/// apart, so the test also bounds the curvature: `r ≤ ρ`; and a tube no shorter around than
/// the curve is long, `2π·r ≥ L`, does not fit.)
fn tube_fits(point: &impl Fn(f64) -> Vector3<f64>, samples: usize, r: f64) -> bool {
    let points: Vec<Vector3<f64>> = (0..samples)
        .map(|k| point(TAU * k as f64 / samples as f64))
        .collect();
    // Arc length from the first point to each, along the polygon, and the whole length.
    let mut arc = Vec::with_capacity(samples);
    let mut length = 0.0;
    for k in 0..samples {
        arc.push(length);
        length += (points[(k + 1) % samples] - points[k]).norm();
    }
    let (half_turn, diameter) = (core::f64::consts::PI * r, 2.0 * r);
    // A closed curve turns by at least 2π (Fenchel), so somewhere its radius of curvature is at
    // most its length over 2π: a thicker tube folds there, with no pair of points to show it.
    if 2.0 * half_turn >= length {
        return false;
    }
    (0..samples).all(|i| {
        (i + 1..samples).all(|j| {
            let along = arc[j] - arc[i];
            along.min(length - along) < half_turn || (points[j] - points[i]).norm() >= diameter
        })
    })
}

/// A closed Wigley hull, the parabolic hull form of the seakeeping benchmarks, floating upright
/// at its design draft: `length` L, `beam` B, `draft` T, closed above the design waterline by a
/// wall-sided topside of `freeboard` D and a flat deck. `4·(stations − 1)·waterlines +
/// 2·(stations − 2)` triangles on `2·(stations − 1)·waterlines + stations` vertices
/// (`41, 17`: 2,798 triangles).
///
/// Frame (the frame of [`Water::default`](crate::Water::default), y up): x along the length,
/// ends at `x = ±L/2`, midship section at `x = 0`; y up, keel at `y = −T`, design waterline at
/// `y = 0`, deck at `y = D`; z across the beam, the sides at `z = ±w`.
/// The half-breadth is
///
/// * underwater, `−T ≤ y ≤ 0`: `w = (B/2)·(1 − (2x/L)²)·(1 − (y/T)²)`;
/// * topside, `0 ≤ y ≤ D`: `w = (B/2)·(1 − (2x/L)²)`, the waterline carried straight up;
///
/// and the deck is the plane `y = D` between the sides. Below the design waterline the hull
/// displaces `V = 4LBT/9` with its center of buoyancy `KB = 5T/8` above the keel (at
/// `y = −3T/8`); its waterplane has area `2LB/3` and `BM = 3B²/(35T)`.
///
/// The vertices lie on the hull: `stations` equally spaced sections from `x = −L/2` to `L/2` and
/// `waterlines` equally spaced levels from the keel to the design waterline, plus the deck edge.
/// The two sides share the vertices where the breadth vanishes, along the keel and the two
/// stems (the end sections, which are vertical lines), so no triangle has zero area. The
/// volume below `y = 0` and its centroid approach `V` and `KB` as the square of the spacing;
/// the topside, a prism on the polygonal waterline, holds exactly
/// `D·(2LB/3)·(1 − 1/(stations − 1)²)` (the trapezoidal rule on the parabola). The mesh is
/// symmetric about `z = 0`, and about `x = 0` when `stations` is odd (a station at
/// midship): then a body of mass ρ times the volume below `y = 0` with its center of mass on the
/// mesh's vertical axis through the centroid is in equilibrium at the identity pose. Upright is
/// stable in roll if the center of mass is below the metacentre, `KG < 5T/8 + 3B²/(35T)` above
/// the keel: a uniform body (center of mass at the mesh centroid,
/// `KG = T + (6D² − 3T²)/(8T + 12D)`) of the benchmark's `B/T = 1.6` needs `D ≲ 0.4·T`; a
/// higher topside needs a lower center of mass (ballast).
///
/// ```
/// use buoyancy_core::{Mesh, Method, Pose, Water, mesh::primitives};
///
/// let (length, beam, draft) = (2.5, 0.25, 0.15625);
/// let (v, t) = primitives::wigley_hull::<f64>(length, beam, draft, 0.1, 41, 17)?;
/// let hull = Mesh::new(v, t)?;
/// let b = hull.buoyancy(&Pose::identity(), &Water::default(), Method::Exact)?;
/// let displacement = 4.0 * length * beam * draft / 9.0;
/// assert!((b.submerged_volume / displacement - 1.0).abs() < 2e-3); // 1.0e-3 low here
/// assert!((b.center_of_buoyancy.y + 3.0 * draft / 8.0).abs() < 1e-3 * draft);
/// # Ok::<(), buoyancy_core::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidShape`] if a length is not finite and positive, `stations < 3` (the two ends
/// and one section between), `waterlines < 2` (the keel and the design waterline), or there
/// are too many vertices for `u32` indices (or triangles for memory).
pub fn wigley_hull<T: Real>(
    length: f64,
    beam: f64,
    draft: f64,
    freeboard: f64,
    stations: usize,
    waterlines: usize,
) -> Result<Shape<T>, Error> {
    positive(length, "length")?;
    positive(beam, "beam")?;
    positive(draft, "draft")?;
    positive(freeboard, "freeboard")?;
    at_least(stations, 3, "stations", "must be at least 3")?;
    at_least(waterlines, 2, "waterlines", "must be at least 2")?;
    // Rows j = 0..=m of a side: the keel (j = 0), the waterlines above it (up to the design
    // waterline, j = m − 1) and the deck edge (j = m); columns i = 0..n, the stations.
    let (n, m) = (stations, waterlines);
    indexable(
        (n - 1)
            .checked_mul(m)
            .and_then(|v| v.checked_mul(2))
            .and_then(|v| v.checked_add(n)),
        "stations",
    )?;
    // The vertex count fits a u32; the triangle count, about twice that, may not fit a 32-bit
    // usize, and either may not fit in memory: an error, not a panic.
    let too_large = || Error::InvalidShape {
        parameter: "stations",
        reason: "too large: the mesh would not fit in memory",
    };
    let triangle_count = (n - 1)
        .checked_mul(m)
        .and_then(|t| t.checked_mul(4))
        .and_then(|t| t.checked_add(2 * (n - 2)))
        .ok_or_else(too_large)?;
    let mut triangles = Vec::new();
    triangles
        .try_reserve_exact(triangle_count)
        .map_err(|_| too_large())?;
    let mut vertices = Vec::new();
    vertices
        .try_reserve_exact(2 * (n - 1) * m + n)
        .map_err(|_| too_large())?;
    // ξ = 2x/L and ζ = y/T from integers, so that mirrored stations are exact negatives and the
    // ends and the waterline fall exactly on ξ = ±1 and ζ = 0.
    let xi = |i: usize| (2.0 * i as f64 - (n - 1) as f64) / (n - 1) as f64;
    let zeta = |j: usize| (j as f64 - (m - 1) as f64) / (m - 1) as f64;
    let point = |i: usize, j: usize, side: f64| {
        let (xi, waterline) = (xi(i), 1.0 - xi(i) * xi(i));
        let (y, w) = if j == m {
            (freeboard, beam / 2.0 * waterline)
        } else {
            let zeta = zeta(j);
            (draft * zeta, beam / 2.0 * waterline * (1.0 - zeta * zeta))
        };
        Point3::new(length / 2.0 * xi, y, side * w)
    };
    // The keel (n vertices), the stem at x = −L/2 and the one at x = L/2 (m each, above the
    // keel), then the inner vertices of the side z > 0 and of the side z < 0.
    for i in 0..n {
        vertices.push(point(i, 0, 0.0));
    }
    for i in [0, n - 1] {
        for j in 1..=m {
            vertices.push(point(i, j, 0.0));
        }
    }
    for side in [1.0, -1.0] {
        for i in 1..n - 1 {
            for j in 1..=m {
                vertices.push(point(i, j, side));
            }
        }
    }
    let index = |i: usize, j: usize, positive: bool| -> u32 {
        (if j == 0 {
            i
        } else if i == 0 {
            n + j - 1
        } else if i == n - 1 {
            n + m + j - 1
        } else {
            n + 2 * m + if positive { 0 } else { (n - 2) * m } + (i - 1) * m + j - 1
        }) as u32
    };
    // Cells in x < 0 (2i ≤ n − 2) are split along the diagonal from their lower corner at the
    // smaller x to their upper corner at the larger x, cells in x > 0 along the mirror image:
    // no diagonal joins two corners on the keel or a stem, so no triangle has its three corners
    // there (shared by both sides, it would make a flat pair with its twin), and the mesh is
    // symmetric about x = 0 where a station lies at midship.
    let forward = |i: usize| 2 * i <= n - 2;
    for positive in [true, false] {
        for i in 0..n - 1 {
            for j in 0..m {
                let (a, b, c, d) = (
                    index(i, j, positive),
                    index(i + 1, j, positive),
                    index(i + 1, j + 1, positive),
                    index(i, j + 1, positive),
                );
                // Counter-clockwise in (x, y) faces +z: as is on the side z > 0, flipped on the
                // side z < 0.
                let pair = if forward(i) {
                    [[a, b, c], [a, c, d]]
                } else {
                    [[a, b, d], [b, c, d]]
                };
                for [p, q, r] in pair {
                    triangles.push(if positive { [p, q, r] } else { [p, r, q] });
                }
            }
        }
    }
    // The deck, facing +y: quads (i and i + 1 on the side z > 0, i + 1 and i on the side
    // z < 0), split like the sides' cells; the end quads are triangles (the stems are shared).
    for i in 0..n - 1 {
        let (p, q, r, s) = (
            index(i, m, true),
            index(i + 1, m, true),
            index(i + 1, m, false),
            index(i, m, false),
        );
        if forward(i) {
            triangles.push([p, q, r]);
            if i > 0 {
                triangles.push([p, r, s]);
            }
        } else {
            triangles.push([p, q, s]);
            if i < n - 2 {
                triangles.push([q, r, s]);
            }
        }
    }
    finish(vertices, triangles)
}

/// A box of `half_extents` `[a, b, c]` about the origin, its edges along the axes: 12 triangles
/// on the 8 corners, volume `8·a·b·c` exactly.
///
/// # Errors
/// [`Error::InvalidShape`] if a half extent is not finite and positive.
pub fn cuboid<T: Real>(half_extents: [f64; 3]) -> Result<Shape<T>, Error> {
    for h in half_extents {
        positive(h, "half_extents")?;
    }
    let (vertices, triangles) = cube::<f64>(1)?;
    let scale = half_extents.map(|h| 2.0 * h);
    finish(
        vertices
            .into_iter()
            .map(|p| Point3::new(p.x * scale[0], p.y * scale[1], p.z * scale[2]))
            .collect(),
        triangles,
    )
}

/// An ellipsoid of semi-axes `radii` `[a, b, c]` along x, y and z about the origin, as
/// [`uv_sphere`] (`slices` around the y axis, `stacks` from pole to pole) scaled by `radii` and
/// then uniformly by the factor `(4π/3 / V₁)^(1/3)` (`V₁` the unit polyhedron's volume, just
/// under `4π/3`), so that it holds the ellipsoid's volume `4π·a·b·c/3` exactly (to rounding); its
/// vertices lie just outside the ellipsoid (`32, 16`: by a factor 1.0054).
///
/// # Errors
/// [`Error::InvalidShape`] if a radius is not finite and positive, `slices < 3`, `stacks < 2`,
/// or there are too many vertices for `u32` indices.
pub fn ellipsoid<T: Real>(
    radii: [f64; 3],
    slices: usize,
    stacks: usize,
) -> Result<Shape<T>, Error> {
    for r in radii {
        positive(r, "radii")?;
    }
    let (unit, triangles) = uv_sphere::<f64>(1.0, slices, stacks)?;
    let factor = libm::cbrt(4.0 / 3.0 * core::f64::consts::PI / volume(&unit, &triangles));
    finish(
        unit.into_iter()
            .map(|p| {
                Point3::new(
                    p.x * radii[0] * factor,
                    p.y * radii[1] * factor,
                    p.z * radii[2] * factor,
                )
            })
            .collect(),
        triangles,
    )
}

/// A cylinder of `radius` about the y axis from `y = −half_height` to `y = half_height`: a prism
/// on a regular `segments`-gon, its caps fanned from their centers (`4·segments` triangles). The
/// polygon's circumradius is `radius·√(2π / (n·sin(2π/n)))`, so that its area is `π·radius²`
/// and the prism holds the cylinder's volume `2π·radius²·half_height` exactly (to rounding).
///
/// # Errors
/// [`Error::InvalidShape`] if a length is not finite and positive, `segments < 3`, or there are
/// too many vertices for `u32` indices.
pub fn cylinder<T: Real>(
    radius: f64,
    half_height: f64,
    segments: usize,
) -> Result<Shape<T>, Error> {
    positive(radius, "radius")?;
    positive(half_height, "half_height")?;
    at_least(segments, 3, "segments", "must be at least 3")?;
    let n = segments as f64;
    let rim = radius * libm::sqrt(TAU / (n * libm::sin(TAU / n)));
    finish_lathe(
        &[
            (0.0, half_height),
            (rim, half_height),
            (rim, -half_height),
            (0.0, -half_height),
        ],
        segments,
    )
}

/// A capsule about the y axis: the cylinder of `radius` from `y = −half_height` to
/// `y = half_height` capped by two half spheres, `segments` around the axis and `stacks` (even)
/// latitude bands from pole to pole over both caps (`2·segments·stacks` triangles).
/// Every ring's radius, and the caps' height above and below the cylinder, are scaled by the
/// factor `s` (just over 1) that solves `s²·A + s³·B = π·radius²·(2·half_height + 4·radius/3)`,
/// `A` the inscribed prism's volume and `B` that of the two inscribed caps: the mesh holds the
/// capsule's volume exactly (to rounding).
///
/// # Errors
/// [`Error::InvalidShape`] if a length is not finite and positive, `segments < 3`, `stacks` is
/// odd or less than 2, or there are too many vertices for `u32` indices.
pub fn capsule<T: Real>(
    radius: f64,
    half_height: f64,
    segments: usize,
    stacks: usize,
) -> Result<Shape<T>, Error> {
    positive(radius, "radius")?;
    positive(half_height, "half_height")?;
    at_least(segments, 3, "segments", "must be at least 3")?;
    at_least(stacks, 2, "stacks", "must be at least 2")?;
    if !stacks.is_multiple_of(2) {
        return Err(Error::InvalidShape {
            parameter: "stacks",
            reason: "must be even (a ring at each end of the cylinder)",
        });
    }
    // The rings' vertices, before the profile is made (`stacks + 2` of it would overflow).
    indexable(
        segments.checked_mul(stacks).and_then(|v| v.checked_add(2)),
        "stacks",
    )?;
    let profile = |scale: f64, half_height: f64| -> Result<Vec<(f64, f64)>, Error> {
        let mut profile = vec_with_capacity(stacks + 2, "stacks")?;
        for i in 0..=stacks {
            let polar = core::f64::consts::PI * i as f64 / stacks as f64;
            let (sin, cos) = (libm::sin(polar), libm::cos(polar));
            let r = if i == 0 || i == stacks {
                0.0
            } else {
                scale * radius * sin
            };
            // Upper cap from the pole to the equator, then the lower cap from its equator on.
            if 2 * i <= stacks {
                profile.push((r, half_height + scale * radius * cos));
            }
            if 2 * i >= stacks {
                profile.push((r, -half_height + scale * radius * cos));
            }
        }
        Ok(profile)
    };
    // A: the prism between the two rims, exact for the polygon; B: the two caps, closed on
    // each other (half height 0, one shared equator counted once).
    let n = segments as f64;
    let prism = n / 2.0 * libm::sin(TAU / n) * radius * radius * 2.0 * half_height;
    let (caps, caps_triangles) = lathe(&profile(1.0, 0.0)?[..], segments)?;
    let caps = volume(&caps, &caps_triangles);
    let target = core::f64::consts::PI * radius * radius * (2.0 * half_height + 4.0 * radius / 3.0);
    let mut scale = 1.0;
    for _ in 0..8 {
        let f = scale * scale * (prism + scale * caps) - target;
        scale -= f / (scale * (2.0 * prism + 3.0 * scale * caps));
    }
    let mut full = profile(scale, half_height)?;
    // The equator ring is pushed by both caps: once on each end of the cylinder.
    full.dedup_by(|a, b| a == b);
    finish_lathe(&full, segments)
}

/// Welds a tessellation that repeats its vertices (the seams and poles of an engine's sphere,
/// cylinder or capsule; the corners of a box given face by face) so that [`Mesh::new`](crate::Mesh::new)
/// sees it closed: every vertex within `10⁻⁶` of the mesh's extent (its bounding box's diagonal)
/// of an earlier one is replaced by that one in `triangles`, and the triangles that collapse
/// (two corners the same vertex) are dropped. The merged vertices stay in `points`, unused;
/// indices out of range are left for [`Mesh::new`](crate::Mesh::new) to report.
///
/// ```
/// use buoyancy_core::{Mesh, nalgebra::Point3, mesh::primitives};
///
/// // A tetrahedron given face by face: 12 vertices, no edge shared until welded.
/// let corners = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// let points: Vec<Point3<f64>> = faces.iter().flatten().map(|&i| corners[i].into()).collect();
/// let mut triangles: Vec<[u32; 3]> = (0..4).map(|t| [3 * t, 3 * t + 1, 3 * t + 2]).collect();
/// assert!(Mesh::new(points.clone(), triangles.clone()).is_err());
/// primitives::weld(&points, &mut triangles);
/// assert!((Mesh::new(points, triangles)?.volume() - 1.0 / 6.0).abs() < 1e-15);
/// # Ok::<(), buoyancy_core::Error>(())
/// ```
pub fn weld(points: &[Point3<f64>], triangles: &mut Vec<[u32; 3]>) {
    let finite: Vec<&Point3<f64>> = points
        .iter()
        .filter(|p| p.coords.iter().all(|c| c.is_finite()))
        .collect();
    let Some(first) = finite.first() else {
        return;
    };
    let (lo, hi) = finite
        .iter()
        .fold((**first, **first), |(lo, hi), p| (lo.inf(p), hi.sup(p)));
    let tolerance = 1e-6 * (hi - lo).norm().max(f64::MIN_POSITIVE);
    let mut order: Vec<usize> = (0..points.len())
        .filter(|&i| points[i].x.is_finite())
        .collect();
    order.sort_by(|&a, &b| points[a].x.total_cmp(&points[b].x));
    let mut representative: Vec<u32> = (0..points.len() as u32).collect();
    for (k, &i) in order.iter().enumerate() {
        for &j in order[..k].iter().rev() {
            if points[i].x - points[j].x > tolerance {
                break;
            }
            if (points[i] - points[j]).norm() <= tolerance {
                representative[i] = representative[j];
                break;
            }
        }
    }
    for t in triangles.iter_mut() {
        *t = t.map(|i| representative.get(i as usize).copied().unwrap_or(i));
    }
    triangles.retain(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
}

/// The signed volume `Σ (a · (b × c)) / 6` of a closed mesh (positive when wound outward).
fn volume(vertices: &[Point3<f64>], triangles: &[[u32; 3]]) -> f64 {
    triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| vertices[i as usize].coords);
            a.dot(&b.cross(&c))
        })
        .sum::<f64>()
        / 6.0
}

fn finish_lathe<T: Real>(profile: &[(f64, f64)], segments: usize) -> Result<Shape<T>, Error> {
    let (vertices, triangles) = lathe(profile, segments)?;
    finish(vertices, triangles)
}

/// The surface of revolution about the y axis of a `profile` of `(radius, y)` from the top pole
/// (radius 0) down to the bottom pole (radius 0), `segments` around the axis; the rings as
/// [`uv_sphere`] places them.
fn lathe(profile: &[(f64, f64)], segments: usize) -> Result<Shape<f64>, Error> {
    let rings = profile.len() - 2;
    indexable(
        segments.checked_mul(rings).and_then(|v| v.checked_add(2)),
        "segments",
    )?;
    let mut vertices = vec_with_capacity(2 + segments * rings, "segments")?;
    vertices.push(Point3::new(0.0, profile[0].1, 0.0));
    for &(r, y) in &profile[1..=rings] {
        for j in 0..segments {
            let azimuth = TAU * j as f64 / segments as f64;
            vertices.push(Point3::new(
                r * libm::cos(azimuth),
                y,
                -r * libm::sin(azimuth),
            ));
        }
    }
    let south = vertices.len() as u32;
    vertices.push(Point3::new(0.0, profile[rings + 1].1, 0.0));
    let ring = |i: usize, j: usize| (1 + (i - 1) * segments + j % segments) as u32;
    let mut triangles = vec_with_capacity(2 * segments * rings, "segments")?;
    for j in 0..segments {
        triangles.push([0, ring(1, j), ring(1, j + 1)]);
        triangles.push([south, ring(rings, j + 1), ring(rings, j)]);
    }
    for i in 1..rings {
        for j in 0..segments {
            let (a, b, c, d) = (
                ring(i, j),
                ring(i + 1, j),
                ring(i + 1, j + 1),
                ring(i, j + 1),
            );
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    Ok((vertices, triangles))
}

/// Sweeps a circle of radius `r` along a closed curve `u ∈ [0, 2π) ↦ (point, tangent)`, with a
/// frame transported by projection so that the tube does not twist over one turn.
fn tube<T: Real>(
    segments: usize,
    sides: usize,
    r: f64,
    curve: impl Fn(f64) -> (Vector3<f64>, Vector3<f64>),
) -> Result<Shape<T>, Error> {
    at_least(segments, 3, "segments", "must be at least 3")?;
    at_least(sides, 3, "sides", "must be at least 3")?;
    indexable(segments.checked_mul(sides), "segments")?;
    let mut vertices = vec_with_capacity(segments * sides, "segments")?;
    let mut frames = vec_with_capacity(segments, "segments")?;
    frames.extend((0..segments).map(|i| curve(TAU * i as f64 / segments as f64)));
    // A normal per segment: Frenet-free, from a fixed axis least aligned with the first tangent,
    // then carried along by projecting out each new tangent.
    let first_tangent = frames[0].1.normalize();
    let helper = [Vector3::x(), Vector3::y(), Vector3::z()]
        .into_iter()
        .min_by(|a, b| {
            a.dot(&first_tangent)
                .abs()
                .total_cmp(&b.dot(&first_tangent).abs())
        })
        .unwrap_or_else(Vector3::x);
    let mut normal = (helper - first_tangent * helper.dot(&first_tangent)).normalize();
    for (center, tangent) in &frames {
        let tangent = tangent.normalize();
        normal = (normal - tangent * normal.dot(&tangent)).normalize();
        let binormal = tangent.cross(&normal);
        for j in 0..sides {
            let angle = TAU * j as f64 / sides as f64;
            let out = normal * libm::cos(angle) + binormal * libm::sin(angle);
            vertices.push(Point3::from(center + out * r));
        }
    }
    // The transported frame may come back rotated after one turn; reconnect the last ring to
    // the first by the side offset that matches best, so the seam does not twist the tube.
    let last = (segments - 1) * sides;
    let shift = (0..sides)
        .min_by(|&a, &b| {
            let d = |s: usize| (vertices[last] - vertices[s]).norm_squared();
            d(a).total_cmp(&d(b))
        })
        .unwrap_or(0);
    let index = |i: usize, j: usize| -> u32 {
        if i == segments {
            ((j + shift) % sides) as u32
        } else {
            (i * sides + j % sides) as u32
        }
    };
    let mut triangles = vec_with_capacity(2 * segments * sides, "segments")?;
    for i in 0..segments {
        for j in 0..sides {
            let (a, b, c, d) = (
                index(i, j),
                index(i + 1, j),
                index(i + 1, j + 1),
                index(i, j + 1),
            );
            triangles.push([a, d, c]);
            triangles.push([a, c, b]);
        }
    }
    finish(vertices, triangles)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Mesh;
    use core::f64::consts::PI;

    #[test]
    fn bad_parameters_are_errors() {
        let shape = |e: Result<Shape<f64>, Error>| match e {
            Err(Error::InvalidShape { parameter, .. }) => parameter,
            other => panic!("{:?}", other.map(|(v, t)| (v.len(), t.len()))),
        };
        assert_eq!(shape(cube(0)), "n");
        assert_eq!(shape(cube(usize::MAX)), "n");
        assert_eq!(shape(uv_sphere(0.0, 8, 8)), "radius");
        assert_eq!(shape(uv_sphere(f64::NAN, 8, 8)), "radius");
        assert_eq!(shape(uv_sphere(1.0, 2, 8)), "slices");
        assert_eq!(shape(uv_sphere(1.0, 8, 1)), "stacks");
        assert_eq!(shape(torus(1.0, -0.1, 8, 8)), "minor");
        assert_eq!(shape(torus(1.0, 1.0, 8, 8)), "minor");
        assert_eq!(shape(torus(f64::INFINITY, 0.1, 8, 8)), "major");
        assert_eq!(shape(torus(1.0, 0.5, 2, 8)), "segments");
        assert_eq!(shape(torus(1.0, 0.5, 8, 2)), "sides");
        assert_eq!(shape(torus(1.0, 0.5, 1 << 20, 1 << 13)), "segments");
        assert_eq!(shape(torus_knot(0, 3, 1.0, 0.25, 80, 11)), "p");
        assert_eq!(shape(torus_knot(2, 0, 1.0, 0.25, 80, 11)), "q");
        assert_eq!(shape(torus_knot(2, 3, 1.0, 0.0, 80, 11)), "tube_radius");
        // A common factor: the (4, 6) knot is the trefoil's curve run twice.
        assert_eq!(shape(torus_knot(4, 6, 1.0, 0.1, 80, 11)), "q");
        assert_eq!(shape(torus_knot(3, 3, 1.0, 0.1, 80, 11)), "q");
        // The trefoil's tube fits up to 0.416 of the radius (sampled at 2,048 points).
        assert!(torus_knot::<f64>(2, 3, 1.0, 0.41, 80, 11).is_ok());
        assert_eq!(shape(torus_knot(2, 3, 1.0, 0.42, 80, 11)), "tube_radius");
        assert_eq!(shape(torus_knot(2, 5, 1.0, 0.3, 80, 11)), "tube_radius");
        assert!(torus_knot::<f64>(1, 1, 1.0, 0.9, 80, 11).is_ok());
        let message = alloc::string::ToString::to_string(&uv_sphere::<f64>(1.0, 2, 8).unwrap_err());
        assert_eq!(
            message,
            "invalid shape parameter slices: must be at least 3"
        );
    }

    #[test]
    fn cube_is_closed_unit_and_centered() {
        for n in [1, 3, 10] {
            let (v, t) = cube::<f64>(n).unwrap();
            assert_eq!(t.len(), 12 * n * n);
            assert_eq!(v.len(), 6 * n * n + 2);
            let m = Mesh::new(v, t).unwrap();
            assert!(!m.was_reoriented());
            assert!((m.volume() - 1.0).abs() < 1e-13);
            assert!(m.centroid().coords.norm() < 1e-14);
        }
    }

    #[test]
    fn sphere_volume_converges() {
        let (v, t) = uv_sphere::<f64>(1.0, 50, 50).unwrap();
        assert_eq!(t.len(), 4900);
        let m = Mesh::new(v, t).unwrap();
        assert!(!m.was_reoriented());
        let ball = 4.0 / 3.0 * PI;
        assert!(
            m.volume() < ball && m.volume() > 0.99 * ball,
            "{}",
            m.volume()
        );
    }

    #[test]
    fn torus_volume() {
        let (v, t) = torus::<f64>(2.0, 0.5, 128, 64).unwrap();
        let m = Mesh::new(v, t).unwrap();
        assert!(!m.was_reoriented());
        // Pappus on the inscribed polygons: a 64-gon of circumradius 0.5 swept by a 128-gon of
        // radius 2 (the 64-gon's centroid is on the circle of radius 2).
        let polygon = |k: f64| k / TAU * libm::sin(TAU / k);
        let exact = PI * 0.25 * polygon(64.0) * TAU * 2.0 * polygon(128.0);
        assert!(
            (m.volume() / exact - 1.0).abs() < 1e-12,
            "{} vs {exact}",
            m.volume()
        );
    }

    #[test]
    fn torus_knot_is_closed_and_outward() {
        let (v, t) = torus_knot::<f64>(2, 3, 1.0, 0.25, 80, 11).unwrap();
        assert_eq!(t.len(), 1760);
        assert!(!Mesh::new(v, t).unwrap().was_reoriented());
        let (v, t) = torus_knot::<f64>(2, 3, 1.0, 0.25, 800, 64).unwrap();
        let m = Mesh::new(v, t).unwrap();
        // A tube of radius r along a curve of length L encloses about π r² L.
        let length: f64 = (0..10000)
            .map(|i| {
                let (a, b) = (TAU * i as f64 / 10000.0, TAU * (i + 1) as f64 / 10000.0);
                let pt = |u: f64| {
                    let r = (2.0 + libm::cos(3.0 * u)) / 2.0;
                    Vector3::new(
                        r * libm::cos(2.0 * u),
                        r * libm::sin(2.0 * u),
                        libm::sin(3.0 * u) / 2.0,
                    )
                };
                (pt(b) - pt(a)).norm()
            })
            .sum();
        let expected = PI * 0.25 * 0.25 * length;
        assert!(
            (m.volume() / expected - 1.0).abs() < 3e-3,
            "{} vs {expected}",
            m.volume()
        );
    }

    #[test]
    fn primitives_hold_their_solids_volume() {
        let check = |shape: Result<Shape<f64>, Error>, exact: f64, triangles: usize| {
            let (v, t) = shape.unwrap();
            assert_eq!(t.len(), triangles);
            let m = Mesh::new(v, t).unwrap();
            assert!(!m.was_reoriented());
            assert!(
                (m.volume() / exact - 1.0).abs() < 1e-12,
                "{} vs {exact}",
                m.volume()
            );
            assert!(m.centroid().coords.norm() < 1e-12);
        };
        check(cuboid([0.5, 0.25, 2.0]), 8.0 * 0.5 * 0.25 * 2.0, 12);
        for (slices, stacks) in [(3, 2), (8, 5), (32, 16)] {
            check(
                ellipsoid([1.0, 0.5, 2.0], slices, stacks),
                4.0 / 3.0 * PI * 1.0,
                2 * slices * (stacks - 1),
            );
        }
        for segments in [3, 7, 32] {
            check(cylinder(0.3, 1.5, segments), PI * 0.09 * 3.0, 4 * segments);
        }
        for (segments, stacks) in [(3, 2), (12, 4), (32, 16)] {
            check(
                capsule(0.3, 0.5, segments, stacks),
                PI * 0.09 * (1.0 + 0.4),
                2 * segments * stacks,
            );
        }
        let shape = |e: Result<Shape<f64>, Error>| match e {
            Err(Error::InvalidShape { parameter, .. }) => parameter,
            other => panic!("{:?}", other.map(|(v, t)| (v.len(), t.len()))),
        };
        assert_eq!(shape(cuboid([1.0, 0.0, 1.0])), "half_extents");
        assert_eq!(shape(ellipsoid([1.0, 1.0, f64::NAN], 8, 8)), "radii");
        assert_eq!(shape(cylinder(1.0, -1.0, 8)), "half_height");
        assert_eq!(shape(cylinder(1.0, 1.0, 2)), "segments");
        assert_eq!(shape(capsule(1.0, 1.0, 8, 3)), "stacks");
        assert_eq!(shape(capsule(0.0, 1.0, 8, 4)), "radius");
    }
}
