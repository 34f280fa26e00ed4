use core::fmt;
use core::str::FromStr;

use crate::Error;

/// How the buoyancy of a mesh is computed: the five methods of the paper.
///
/// | method | what it sums | exact for a flat plane |
/// |---|---|---|
/// | `Fast` | tetrahedra from the mesh centroid to the fully submerged triangles, precomputed | no: misses the cone from the centroid to the waterline, whatever the resolution |
/// | `Improved` | tetrahedra from a point on the water plane to the fully submerged triangles | no: misses the waterline triangles; the error shrinks with the resolution |
/// | `Exact` | `Fast`'s tetrahedra + the submerged part of each waterline triangle (clipped) + the cap on the water plane | yes |
/// | `FastSurface` | the pressure `ρ·g·depth` over the fully submerged triangles | no |
/// | `ExactSurface` | the pressure over the exact wetted surface (waterline triangles clipped) | yes |
///
/// Their speed on the paper's models is measured in `benches/RESULTS.md`
/// (`cargo bench --bench table`).
///
/// The volume methods apply the divergence theorem: the submerged volume is a sum of signed
/// tetrahedra `V_i(o) = (a−o)·((b−o)×(c−o))/6`. With the reference point `o` on the water plane
/// (`Improved`, `Exact`) the cap where the plane cuts the body contributes nothing, so clipping
/// the waterline triangles is all `Exact` needs. (The implementation sums about the centroid
/// instead and adds the cap explicitly, as a fan over the waterline, so that `Exact` reuses
/// `Fast`'s precomputed tetrahedra; the result is the same.) `Fast` uses the mesh centroid as `o`, which lets
/// it precompute every `V_i`, and misses the cone from the centroid to the cap: its error does
/// not shrink when the mesh is refined.
///
/// The surface methods integrate the hydrostatic pressure `p = ρ·g·depth` over the wetted
/// surface, `F = −∫ p dA`, and its moment exactly (pressure is linear on each triangle). Their
/// volume is the one implied by the force, `V = n·F / (ρ·g)`, and their center of buoyancy the
/// centroid implied by the pressure moments (see [`Buoyancy`](crate::Buoyancy)); for a closed
/// mesh under a flat plane both equal the exact ones.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Method {
    /// Fully submerged triangles only, tetrahedra to the mesh centroid (precomputed).
    Fast,
    /// Fully submerged triangles only, tetrahedra to a reference point on the water plane.
    Improved,
    /// Exact submerged volume: `Improved` plus the clipped waterline triangles.
    #[default]
    Exact,
    /// Pressure integrated over the fully submerged triangles.
    FastSurface,
    /// Pressure integrated over the exact wetted surface (waterline triangles clipped).
    ExactSurface,
}

impl Method {
    /// All five methods, in the paper's order.
    pub const ALL: [Method; 5] = [
        Method::Fast,
        Method::Improved,
        Method::Exact,
        Method::FastSurface,
        Method::ExactSurface,
    ];

    /// The method's snake-case name: `fast`, `improved`, `exact`, `fast_surface`, `exact_surface`.
    pub const fn name(self) -> &'static str {
        match self {
            Method::Fast => "fast",
            Method::Improved => "improved",
            Method::Exact => "exact",
            Method::FastSurface => "fast_surface",
            Method::ExactSurface => "exact_surface",
        }
    }

    /// Whether the method is exact (up to round-off) for a closed mesh under a flat plane.
    pub const fn is_exact(self) -> bool {
        matches!(self, Method::Exact | Method::ExactSurface)
    }

    /// Whether the method integrates pressure over the surface rather than volume elements.
    pub const fn is_surface(self) -> bool {
        matches!(self, Method::FastSurface | Method::ExactSurface)
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Method {
    type Err = Error;

    /// Parses a name of [`Method::name`], ignoring case and the separators between words:
    /// `exact_surface`, `exact-surface` and `ExactSurface` all name [`Method::ExactSurface`].
    fn from_str(s: &str) -> Result<Self, Error> {
        Method::ALL
            .into_iter()
            .find(|m| names_match(m.name(), s))
            .ok_or_else(|| Error::UnknownMethod { name: s.into() })
    }
}

/// Whether `given` spells the snake-case `name` in any common way: ignoring case, with `_`,
/// `-` or nothing between the words (`exact_surface`, `exact-surface`, `ExactSurface`).
pub(crate) fn names_match(name: &str, given: &str) -> bool {
    let mut expected = name.bytes().filter(|&b| b != b'_');
    let mut given = given
        .bytes()
        .filter(|&b| b != b'_' && b != b'-')
        .map(|b| b.to_ascii_lowercase());
    loop {
        match (expected.next(), given.next()) {
            (None, None) => return true,
            (Some(a), Some(b)) if a == b => {}
            _ => return false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_spelling_of_a_name_parses() {
        for method in Method::ALL {
            let debug = alloc::format!("{method:?}");
            for spelling in [method.name(), &debug, &method.name().replace('_', "-")] {
                assert_eq!(spelling.parse::<Method>(), Ok(method), "{spelling}");
                let upper = spelling.to_ascii_uppercase();
                assert_eq!(upper.parse::<Method>(), Ok(method), "{upper}");
            }
        }
        for wrong in ["", "exac", "exactsurfaces", "exact surface", "fast surface"] {
            assert!(wrong.parse::<Method>().is_err(), "{wrong}");
        }
    }
}
