"""Type stubs of the compiled module ``buoyancy._core`` (re-exported by ``buoyancy``)."""

import os
from collections.abc import Callable, Iterable, Sequence
from typing import Any, Final, Literal, Protocol, SupportsIndex, TypeAlias, final, overload

import numpy as np
import numpy.typing as npt
from typing_extensions import deprecated

# The canonical names; any case, with "_", "-" or nothing between the words, is accepted too
# ("ExactSurface", "exact-surface").
_MethodName: TypeAlias = Literal["fast", "improved", "exact", "fast_surface", "exact_surface"]
_TraversalName: TypeAlias = Literal["auto", "scan", "hierarchy"]
_Pressure: TypeAlias = Literal["hydrostatic", "froude_krylov"]
_DampingResolution: TypeAlias = int | Literal["full"]
_DefectKind: TypeAlias = Literal[
    "non_finite_vertex",
    "index_out_of_range",
    "repeated_index",
    "open_edge",
    "non_manifold_edge",
    "inconsistent_orientation",
]
_FloatArray: TypeAlias = npt.NDArray[np.float64]
_Float32Array: TypeAlias = npt.NDArray[np.float32]
_BoolArray: TypeAlias = npt.NDArray[np.bool_]
_Outcome: TypeAlias = Literal["not_evaluated", "applied", "inactive", "not_finite", "unsupported"]
# A part of a floating body: a mesh in the body's frame, or (mesh, position, quaternion) of a mesh
# in its own frame placed on the body.
_Part: TypeAlias = Mesh | tuple[Mesh, npt.ArrayLike, npt.ArrayLike]
_IntArray: TypeAlias = npt.NDArray[np.int64]
# A vectorised surface: the (N, 3) still-plane points and the time (s) to N elevations (m).
_SurfaceFunction: TypeAlias = Callable[[_FloatArray, float], npt.ArrayLike]
_Surface: TypeAlias = AiryWave | Waves | GerstnerWaves | HeightGrid | _SurfaceFunction

__all__ = [
    "MATRIX_TOLERANCE",
    "METHODS",
    "QUATERNION_TOLERANCE",
    "AiryWave",
    "Buoyancy",
    "BuoyancyBatch",
    "Controller",
    "Damping",
    "DampingCoefficients",
    "Equilibrium",
    "FloatReport",
    "GerstnerWaves",
    "GzCurve",
    "HeightGrid",
    "HydrostaticTable",
    "Hydrostatics",
    "Mesh",
    "MeshDefect",
    "MeshError",
    "Water",
    "Waterplane",
    "Waves",
    "_rapier_bodies",
    "_unpickle",
    "_world_inverse_inertias",
    "capsule",
    "cube",
    "cuboid",
    "cylinder",
    "ellipsoid",
    "load",
    "torus",
    "torus_knot",
    "uv_sphere",
    "wigley_hull",
]

METHODS: Final[tuple[str, str, str, str, str]]
QUATERNION_TOLERANCE: Final[float]
MATRIX_TOLERANCE: Final[float]

class MeshError(ValueError):
    """A mesh that cannot be used; the message names the vertices, triangles or edges at fault."""

    defects: tuple[MeshDefect, ...]
    triangle_soup: bool
    coincident_vertices: int
    one_based_indices: bool

@final
class MeshDefect:
    """One kind of problem found in a mesh, with its count and first culprits (zero-based)."""

    def __new__(
        cls,
        kind: _DefectKind,
        count: int,
        examples: tuple[dict[str, int | tuple[int, ...]], ...],
    ) -> MeshDefect: ...
    def __reduce__(self) -> tuple[type[MeshDefect], tuple[str, int, tuple[Any, ...]]]: ...
    @property
    def kind(self) -> _DefectKind: ...
    @property
    def count(self) -> int: ...
    @property
    def examples(self) -> tuple[dict[str, int | tuple[int, ...]], ...]: ...

class _HasVerticesAndFaces(Protocol):
    """A ``trimesh.Trimesh``, or anything with ``vertices`` and ``faces`` arrays."""

    @property
    def vertices(self) -> npt.ArrayLike: ...
    @property
    def faces(self) -> npt.ArrayLike: ...

class _HasToGeometry(Protocol):
    """A ``trimesh.Scene``: its geometry concatenated in place by ``to_geometry()``."""

    def to_geometry(self) -> _HasVerticesAndFaces: ...

@final
class AiryWave:
    """One linear wave component ``a cos(k·q − ω t + φ)``, SI units."""

    def __new__(
        cls,
        amplitude: float,
        wavelength: float,
        direction: npt.ArrayLike | None = (1.0, 0.0, 0.0),
        phase: float = 0.0,
    ) -> AiryWave: ...
    @property
    def amplitude(self) -> float:
        """m."""
    @property
    def wavelength(self) -> float:
        """m."""
    @property
    def direction(self) -> _FloatArray:
        """Direction of travel as given, shape (3,)."""
    @property
    def phase(self) -> float:
        """rad."""
    @property
    def wavenumber(self) -> float:
        """``2π / wavelength``, rad/m."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> tuple[type[AiryWave], tuple[float, float, tuple[float, float, float], float]]: ...

@final
class Waves:
    """Linear (Airy) waves: a sum of components over water of a depth (``None``: deep)."""

    def __new__(
        cls, components: Iterable[AiryWave], depth: float | None = None, pressure: _Pressure = "hydrostatic"
    ) -> Waves: ...
    @classmethod
    def jonswap(
        cls,
        hs: float,
        tp: float,
        gamma: float = 3.3,
        direction: npt.ArrayLike | None = (1.0, 0.0, 0.0),
        spreading: float | None = None,
        n: int = 64,
        seed: int = 0,
        depth: float | None = None,
        water: Water | None = None,
        pressure: _Pressure = "hydrostatic",
    ) -> Waves:
        """Components drawn from a JONSWAP spectrum of significant height ``hs`` (m), peak period ``tp`` (s)."""
    @classmethod
    def pierson_moskowitz(
        cls,
        hs: float,
        tp: float,
        direction: npt.ArrayLike | None = (1.0, 0.0, 0.0),
        spreading: float | None = None,
        n: int = 64,
        seed: int = 0,
        depth: float | None = None,
        water: Water | None = None,
        pressure: _Pressure = "hydrostatic",
    ) -> Waves:
        """Components drawn from a Pierson–Moskowitz spectrum."""
    @property
    def components(self) -> tuple[AiryWave, ...]: ...
    @property
    def depth(self) -> float | None:
        """m; ``None`` for deep water."""
    @property
    def pressure(self) -> _Pressure:
        """The pressure ``Mesh.buoyancy`` integrates under these waves."""
    def angular_frequencies(self, gravity: float = 9.81) -> _FloatArray:
        """``ω`` of each component, rad/s, from the dispersion relation."""
    def __len__(self) -> int: ...
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> tuple[Callable[..., Waves], tuple[object, ...]]: ...

@final
class GerstnerWaves:
    """Trochoidal waves in deep water; steepness ``Σ k a`` below 1."""

    def __new__(cls, components: Iterable[AiryWave]) -> GerstnerWaves: ...
    @property
    def components(self) -> tuple[AiryWave, ...]: ...
    @property
    def steepness(self) -> float:
        """``Σ kᵢ aᵢ``."""
    def __len__(self) -> int: ...
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> tuple[type[GerstnerWaves], tuple[tuple[AiryWave, ...]]]: ...

@final
class HeightGrid:
    """Elevations on a regular grid (rows, columns), bilinear, optionally periodic; axes from the water's normal."""

    def __new__(
        cls,
        heights: npt.ArrayLike,
        spacing: float | npt.ArrayLike,
        origin: npt.ArrayLike | None = (0.0, 0.0),
        periodic: bool = True,
    ) -> HeightGrid: ...
    def set_heights(self, heights: npt.ArrayLike) -> None:
        """Replaces the heights in place, shape (rows, columns)."""
    @property
    def heights(self) -> _FloatArray:
        """Shape (rows, columns), m."""
    @property
    def shape(self) -> tuple[int, int]: ...
    @property
    def spacing(self) -> tuple[float, float]: ...
    @property
    def origin(self) -> tuple[float, float]: ...
    @property
    def periodic(self) -> bool: ...
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(
        self,
    ) -> tuple[type[HeightGrid], tuple[_FloatArray, tuple[float, float], tuple[float, float], bool]]: ...

@final
class Water:
    """A body of water: its still plane ``dot(normal, p) == level`` and optionally waves, SI units."""

    def __new__(
        cls,
        density: float = 1000.0,
        gravity: float = 9.81,
        level: float = 0.0,
        normal: npt.ArrayLike | None = (0.0, 1.0, 0.0),
        waves: _Surface | None = None,
    ) -> Water:
        """``gravity`` is a magnitude, m/s²; its direction is ``-normal``."""
    @property
    def density(self) -> float: ...
    @property
    def gravity(self) -> float: ...
    @property
    def level(self) -> float: ...
    @property
    def normal(self) -> _FloatArray:
        """Unit up normal, shape (3,)."""
    @property
    def specific_weight(self) -> float:
        """``density * gravity``, N/m³."""
    @property
    def waves(self) -> _Surface | None:
        """The waves as given; ``None`` for still water."""
    @overload
    def elevation(self, points: tuple[float, float, float], time: float = 0.0) -> float:
        """η at one point projected onto the still plane, m."""
    @overload
    def elevation(self, points: npt.ArrayLike, time: float = 0.0) -> _FloatArray | float:
        """η at the points projected onto the still plane, m: shape (N,), or a float for shape (3,)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(
        self,
    ) -> tuple[type[Water], tuple[float, float, float, tuple[float, float, float], _Surface | None]]: ...

@final
class Buoyancy:
    """The buoyancy at one pose, world frame."""

    def __new__(
        cls,
        volume: float,
        center: npt.ArrayLike,
        force: npt.ArrayLike,
        torque: npt.ArrayLike,
        about: npt.ArrayLike,
        fully_submerged: int = 0,
        partially_submerged: int = 0,
        method: _MethodName | str = "exact",
        wetted_area: float = 0.0,
    ) -> Buoyancy: ...
    @property
    def volume(self) -> float: ...
    @property
    def center(self) -> _FloatArray:
        """Center of buoyancy, shape (3,)."""
    @property
    def force(self) -> _FloatArray:
        """Buoyant force, N, shape (3,)."""
    @property
    def torque(self) -> _FloatArray:
        """Torque about ``about``, N·m, shape (3,)."""
    @property
    def about(self) -> _FloatArray:
        """The torque's reference point, shape (3,)."""
    @property
    def fully_submerged(self) -> int: ...
    @property
    def partially_submerged(self) -> int: ...
    @property
    def wetted_area(self) -> float:
        """Area of the surface under water, m² (``fast`` and ``fast_surface``: of the triangles
        entirely under water only)."""
    @property
    def method(self) -> str: ...
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(
        self,
    ) -> tuple[
        type[Buoyancy],
        tuple[
            float,
            tuple[float, float, float],
            tuple[float, float, float],
            tuple[float, float, float],
            tuple[float, float, float],
            int,
            int,
            str,
            float,
        ],
    ]: ...

@final
class BuoyancyBatch:
    """The buoyancy at K poses: arrays indexed by pose."""

    @property
    def volume(self) -> _FloatArray:
        """Shape (K,)."""
    @property
    def center(self) -> _FloatArray:
        """Shape (K, 3)."""
    @property
    def force(self) -> _FloatArray:
        """Shape (K, 3)."""
    @property
    def torque(self) -> _FloatArray:
        """Shape (K, 3)."""
    @property
    def about(self) -> _FloatArray:
        """Shape (K, 3)."""
    @property
    def fully_submerged(self) -> _IntArray: ...
    @property
    def partially_submerged(self) -> _IntArray: ...
    @property
    def wetted_area(self) -> _FloatArray:
        """Shape (K,), m²."""
    @property
    def method(self) -> str: ...
    def __len__(self) -> int: ...
    def __getitem__(self, index: SupportsIndex, /) -> Buoyancy: ...

@final
class DampingCoefficients:
    """The coefficients of the hydrodynamic damping model, SI units."""

    def __new__(
        cls,
        linear_drag: float = 1000.0,
        drag_coefficient: float = 1.0,
        angular_drag_linear: float = 0.1,
        angular_drag_quadratic: float = 0.1,
        current: npt.ArrayLike | None = (0.0, 0.0, 0.0),
    ) -> DampingCoefficients: ...
    @classmethod
    def off(cls) -> DampingCoefficients:
        """No damping at all."""
    @property
    def linear_drag(self) -> float:
        """Linear pressure-drag coefficient ``c₁``, Pa per m/s."""
    @property
    def drag_coefficient(self) -> float:
        """Dimensionless quadratic drag coefficient ``C_D``."""
    @property
    def angular_drag_linear(self) -> float:
        """Linear angular damping rate ``a₁``, 1/s."""
    @property
    def angular_drag_quadratic(self) -> float:
        """Dimensionless quadratic angular damping coefficient ``a₂``."""
    @property
    def current(self) -> _FloatArray:
        """Velocity of the water, m/s, shape (3,)."""
    @property
    def is_off(self) -> bool: ...
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(
        self,
    ) -> tuple[type[DampingCoefficients], tuple[float, float, float, float, tuple[float, float, float]]]: ...

@final
class Damping:
    """The hydrodynamic damping at one instant, world frame."""

    def __new__(
        cls,
        force: npt.ArrayLike,
        torque: npt.ArrayLike,
        about: npt.ArrayLike,
        wetted_area: float = 0.0,
        wetted_fraction: float = 0.0,
    ) -> Damping: ...
    @property
    def force(self) -> _FloatArray:
        """Damping force, N, shape (3,)."""
    @property
    def torque(self) -> _FloatArray:
        """Torque about ``about``, N·m, shape (3,)."""
    @property
    def about(self) -> _FloatArray:
        """The torque's reference point, shape (3,)."""
    @property
    def wetted_area(self) -> float:
        """Area of the surface under water, m²."""
    @property
    def wetted_fraction(self) -> float:
        """Wetted area over the whole surface area, in [0, 1]."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(
        self,
    ) -> tuple[
        type[Damping],
        tuple[tuple[float, float, float], tuple[float, float, float], tuple[float, float, float], float, float],
    ]: ...

@final
class Mesh:
    """A closed triangle mesh, validated and prepared for buoyancy queries."""

    def __new__(cls, vertices: npt.ArrayLike, faces: npt.ArrayLike) -> Mesh: ...
    @classmethod
    def close_openings(cls, vertices: npt.ArrayLike, faces: npt.ArrayLike) -> Mesh:
        """A hull whose planar openings are closed by flat lids (a hull without a deck)."""
    @classmethod
    def welded(cls, vertices: npt.ArrayLike, faces: npt.ArrayLike) -> Mesh:
        """A closed mesh from a tessellation that repeats its vertices (seams, poles, corners)."""
    @property
    def openings(self) -> list[_IntArray]:
        """Each opening's rim, vertex indices in order."""
    @classmethod
    def from_trimesh(cls, obj: _HasVerticesAndFaces | _HasToGeometry) -> Mesh: ...
    @property
    def volume(self) -> float: ...
    @property
    def centroid(self) -> _FloatArray:
        """Shape (3,), mesh frame."""
    @property
    def n_vertices(self) -> int: ...
    @property
    def n_triangles(self) -> int: ...
    @property
    def bounding_radius(self) -> float: ...
    @property
    def longest_edge(self) -> float: ...
    @property
    def was_reoriented(self) -> bool: ...
    @property
    def vertices(self) -> _FloatArray:
        """Shape (N, 3), as given."""
    @property
    def faces(self) -> _IntArray:
        """Shape (M, 3), wound outward."""
    def buoyancy(
        self,
        position: npt.ArrayLike | None = (0, 0, 0),
        rotation: npt.ArrayLike | None = None,
        water: Water | None = None,
        method: _MethodName | str = "exact",
        about: npt.ArrayLike | None = None,
        traversal: _TraversalName | str = "auto",
        time: float = 0.0,
    ) -> Buoyancy: ...
    def buoyancy_batch(
        self,
        positions: npt.ArrayLike,
        rotations: npt.ArrayLike | None,
        water: Water | None = None,
        method: _MethodName | str = "exact",
        about: npt.ArrayLike | None = None,
        threads: int | None = None,
        traversal: _TraversalName | str = "auto",
        times: float | npt.ArrayLike | None = None,
    ) -> BuoyancyBatch: ...
    def damping(
        self,
        position: npt.ArrayLike | None = (0, 0, 0),
        rotation: npt.ArrayLike | None = None,
        linear_velocity: npt.ArrayLike | None = (0, 0, 0),
        angular_velocity: npt.ArrayLike | None = (0, 0, 0),
        water: Water | None = None,
        coefficients: DampingCoefficients | None = None,
        about: npt.ArrayLike | None = None,
    ) -> Damping: ...
    def damping_stiffness(
        self,
        position: npt.ArrayLike | None = (0, 0, 0),
        rotation: npt.ArrayLike | None = None,
        linear_velocity: npt.ArrayLike | None = (0, 0, 0),
        angular_velocity: npt.ArrayLike | None = (0, 0, 0),
        water: Water | None = None,
        coefficients: DampingCoefficients | None = None,
        about: npt.ArrayLike | None = None,
    ) -> _FloatArray:
        """The damping's stiffness ``K = −∂W/∂q̇``, (6, 6), about ``about``."""
    def waterplane(
        self,
        position: npt.ArrayLike | None = (0, 0, 0),
        rotation: npt.ArrayLike | None = None,
        water: Water | None = None,
    ) -> Waterplane:
        """The section of the still water plane through the body at a pose, world frame."""
    def hydrostatics(
        self,
        center_of_mass: npt.ArrayLike,
        position: npt.ArrayLike | None = (0, 0, 0),
        rotation: npt.ArrayLike | None = None,
        water: Water | None = None,
        mass: float | None = None,
        reference_point: npt.ArrayLike | None = None,
        axis: npt.ArrayLike | None = (1, 0, 0),
        keel: npt.ArrayLike | None = None,
    ) -> Hydrostatics:
        """KB, KG, BM, GM and the heave-roll-pitch stiffness at a pose; points in the mesh frame."""
    def stiffness(
        self,
        center_of_mass: npt.ArrayLike,
        position: npt.ArrayLike | None = (0, 0, 0),
        rotation: npt.ArrayLike | None = None,
        water: Water | None = None,
        mass: float | None = None,
        reference_point: npt.ArrayLike | None = None,
        axis: npt.ArrayLike | None = (1, 0, 0),
        keel: npt.ArrayLike | None = None,
    ) -> _FloatArray:
        """Shape (3, 3): heave, roll, pitch; ``hydrostatics(...).stiffness``."""
    def equilibrium(
        self,
        mass: float,
        center_of_mass: npt.ArrayLike,
        water: Water | None = None,
        rotation: npt.ArrayLike | None = None,
        position: npt.ArrayLike | None = None,
        axis: npt.ArrayLike | None = (1, 0, 0),
        keel: npt.ArrayLike | None = None,
        tolerance: float | None = None,
        max_iterations: int | None = 100,
    ) -> Equilibrium:
        """The stable pose at rest for a mass (kg) and center of mass (mesh frame, m)."""
    def gz_curve(
        self,
        mass: float,
        center_of_mass: npt.ArrayLike,
        heel_deg: npt.ArrayLike,
        axis: npt.ArrayLike | None = (1, 0, 0),
        free_trim: bool = True,
        trim_deg: float | None = None,
        water: Water | None = None,
        rotation: npt.ArrayLike | None = None,
        position: npt.ArrayLike | None = None,
        keel: npt.ArrayLike | None = None,
        tolerance: float | None = None,
        max_iterations: int | None = 100,
    ) -> GzCurve:
        """The righting-arm curve over heels in degrees, draft (and trim) solved at each."""
    def hydrostatic_table(
        self,
        drafts: npt.ArrayLike,
        water: Water | None = None,
        rotation: npt.ArrayLike | None = None,
        axis: npt.ArrayLike | None = (1, 0, 0),
        center_of_mass: npt.ArrayLike | None = None,
        length: float | None = None,
    ) -> HydrostaticTable:
        """The body upright at each draft (m): one row a draft."""
    def transformed(self, matrix: npt.ArrayLike) -> Mesh:
        """A copy mapped by the affine 4×4 ``matrix`` (mesh frame)."""
    def scaled(self, factor: float | npt.ArrayLike) -> Mesh:
        """A copy scaled about the mesh frame's origin, by one factor or one per axis."""
    def translated(self, offset: npt.ArrayLike) -> Mesh:
        """A copy moved by ``offset``, m."""
    def __eq__(self, other: object, /) -> bool: ...
    def __hash__(self) -> int: ...
    def __reduce__(self) -> tuple[Callable[[_FloatArray, _IntArray], Mesh], tuple[_FloatArray, _IntArray]]: ...

@final
class Waterplane:
    """The section of the still water plane through a body, world frame, SI units."""

    @property
    def area(self) -> float:
        """m²."""
    @property
    def center_of_flotation(self) -> _FloatArray:
        """Shape (3,), m."""
    @property
    def axes(self) -> _FloatArray:
        """Shape (2, 3): ``e1`` (the longitudinal axis on the plane), ``e2``."""
    @property
    def second_moments(self) -> _FloatArray:
        """Shape (2, 2), m⁴, about the center of flotation in the basis ``axes``."""
    @property
    def principal_moments(self) -> _FloatArray:
        """Shape (2,), m⁴, least first."""
    @property
    def principal_axes(self) -> _FloatArray:
        """Shape (2, 3)."""

@final
class Hydrostatics:
    """Hydrostatics of a body at a pose, world frame, SI units."""

    @property
    def waterplane(self) -> Waterplane: ...
    @property
    def displaced_volume(self) -> float: ...
    @property
    def center_of_buoyancy(self) -> _FloatArray: ...
    @property
    def center_of_gravity(self) -> _FloatArray: ...
    @property
    def keel(self) -> _FloatArray: ...
    @property
    def reference_point(self) -> _FloatArray: ...
    @property
    def mass(self) -> float: ...
    @property
    def kb(self) -> float: ...
    @property
    def kg(self) -> float: ...
    @property
    def bm_transverse(self) -> float: ...
    @property
    def bm_longitudinal(self) -> float: ...
    @property
    def gm_transverse(self) -> float: ...
    @property
    def gm_longitudinal(self) -> float: ...
    @property
    def bm_principal(self) -> _FloatArray: ...
    @property
    def gm_principal(self) -> _FloatArray: ...
    @property
    def stiffness(self) -> _FloatArray:
        """Shape (3, 3): heave, roll, pitch, about ``reference_point``."""

@final
class Equilibrium:
    """A floating body at rest, world frame, SI units, angles in degrees."""

    @property
    def position(self) -> _FloatArray:
        """Shape (3,), m."""
    @property
    def rotation(self) -> _FloatArray:
        """Shape (4,), quaternion ``(x, y, z, w)``."""
    @property
    def draft(self) -> float: ...
    @property
    def heel(self) -> float:
        """Degrees, right-handed about the longitudinal axis."""
    @property
    def trim(self) -> float:
        """Degrees, positive puts the head of the longitudinal axis down."""
    @property
    def residual(self) -> _FloatArray: ...
    @property
    def length(self) -> float: ...
    @property
    def iterations(self) -> int: ...
    @property
    def restarts(self) -> int: ...
    @property
    def stable(self) -> bool: ...
    @property
    def stiffness_eigenvalues(self) -> _FloatArray: ...
    @property
    def hydrostatics(self) -> Hydrostatics: ...

@final
class GzCurve:
    """A righting-arm curve, SI units, angles in degrees."""

    @property
    def heel(self) -> _FloatArray: ...
    @property
    def trim(self) -> _FloatArray: ...
    @property
    def gz(self) -> _FloatArray:
        """Shape (K,), m; positive is righting at positive heel."""
    @property
    def draft(self) -> _FloatArray: ...
    @property
    def positions(self) -> _FloatArray: ...
    @property
    def rotations(self) -> _FloatArray: ...
    @property
    def residuals(self) -> _FloatArray: ...
    @property
    def iterations(self) -> int: ...
    @property
    def area(self) -> float:
        """m·rad."""
    def area_up_to(self, heel_deg: float) -> float:
        """m·rad, from the first heel to ``heel_deg``."""
    @property
    def max_gz(self) -> float: ...
    @property
    def angle_of_max_gz(self) -> float: ...
    @property
    def angle_of_vanishing_stability(self) -> float | None: ...
    @property
    def positive_stability(self) -> Literal["vanishes", "beyond", "none"]:
        """Where positive stability ends: at the vanishing angle, beyond the curve, or nowhere."""
    @property
    def flooding_angle(self) -> float | None:
        """Degrees: the first heel at which the water reaches an opening (the curve stops)."""
    def __len__(self) -> int: ...

@final
class HydrostaticTable:
    """A hydrostatic table: one row a draft, each column an array of shape (K,)."""

    @property
    def columns(self) -> list[str]: ...
    @property
    def units(self) -> list[str]: ...
    def as_dict(self) -> dict[str, _FloatArray]: ...
    @property
    def draft(self) -> _FloatArray: ...
    @property
    def displaced_volume(self) -> _FloatArray: ...
    @property
    def displacement(self) -> _FloatArray: ...
    @property
    def kb(self) -> _FloatArray: ...
    @property
    def bm_transverse(self) -> _FloatArray: ...
    @property
    def bm_longitudinal(self) -> _FloatArray: ...
    @property
    def km_transverse(self) -> _FloatArray: ...
    @property
    def km_longitudinal(self) -> _FloatArray: ...
    @property
    def lcb(self) -> _FloatArray: ...
    @property
    def lcf(self) -> _FloatArray: ...
    @property
    def waterplane_area(self) -> _FloatArray: ...
    @property
    def waterline_length(self) -> _FloatArray: ...
    @property
    def tpc(self) -> _FloatArray: ...
    @property
    def gm_longitudinal(self) -> _FloatArray: ...
    @property
    def trim_length(self) -> _FloatArray: ...
    @property
    def mct(self) -> _FloatArray: ...
    def __len__(self) -> int: ...

@final
class FloatReport:
    """What ``Controller.step`` computed and applied for one body, world frame, SI units."""

    def __new__(
        cls,
        submerged_volume: float = 0.0,
        center_of_buoyancy: npt.ArrayLike | None = (0, 0, 0),
        center_of_mass: npt.ArrayLike | None = (0, 0, 0),
        buoyancy_force: npt.ArrayLike | None = (0, 0, 0),
        buoyancy_torque: npt.ArrayLike | None = (0, 0, 0),
        damping_force: npt.ArrayLike | None = (0, 0, 0),
        damping_torque: npt.ArrayLike | None = (0, 0, 0),
        wetted_area: float = 0.0,
        outcome: _Outcome = "not_evaluated",
    ) -> FloatReport: ...
    @property
    def submerged_volume(self) -> float:
        """Volume under water, m³."""
    @property
    def center_of_buoyancy(self) -> _FloatArray:
        """Center of buoyancy, m, shape (3,)."""
    @property
    def center_of_mass(self) -> _FloatArray:
        """The body's world center of mass, m, shape (3,)."""
    @property
    def buoyancy_force(self) -> _FloatArray:
        """Buoyant force, N, shape (3,)."""
    @property
    def buoyancy_torque(self) -> _FloatArray:
        """Torque of the buoyancy about the center of mass, N·m, shape (3,)."""
    @property
    def damping_force(self) -> _FloatArray:
        """Damping force as applied (semi-implicit), N, shape (3,)."""
    @property
    def damping_torque(self) -> _FloatArray:
        """Damping torque as applied, N·m, shape (3,)."""
    @property
    def wetted_area(self) -> float:
        """Area of the surface under water, m²."""
    @property
    def outcome(self) -> _Outcome:
        """What became of the body at the last step."""
    @property
    def force(self) -> _FloatArray:
        """``buoyancy_force + damping_force``, N, shape (3,)."""
    @property
    def torque(self) -> _FloatArray:
        """``buoyancy_torque + damping_torque``, N·m, shape (3,)."""
    @property
    @deprecated("use FloatReport.outcome == 'not_finite'")
    def skipped(self) -> bool:
        """Deprecated: ``outcome == "not_finite"``."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(
        self,
    ) -> tuple[
        type[FloatReport],
        tuple[
            float,
            tuple[float, float, float],
            tuple[float, float, float],
            tuple[float, float, float],
            tuple[float, float, float],
            tuple[float, float, float],
            tuple[float, float, float],
            float,
            str,
        ],
    ]: ...

@final
class Controller:
    """Bodies that float, for any physics engine: one call to ``step`` per step for every body."""

    def __new__(
        cls,
        water: Water | None = None,
        method: _MethodName | str | None = "exact",
        damping: DampingCoefficients | None = None,
        damping_resolution: _DampingResolution | None = 384,
    ) -> Controller: ...
    @property
    def water(self) -> Water:
        """The controller's water, with its waves if it has any."""
    @water.setter
    def water(self, water: Water, /) -> None: ...
    @property
    def time(self) -> float:
        """The time of the water's waves, s; every ``step`` advances it by its ``dt``."""
    @time.setter
    def time(self, time: float, /) -> None: ...
    @property
    def method(self) -> str:
        """The controller's buoyancy method (in still water), its canonical name."""
    @method.setter
    def method(self, method: _MethodName | str, /) -> None: ...
    @property
    def damping(self) -> DampingCoefficients:
        """The controller's damping coefficients."""
    @damping.setter
    def damping(self, damping: DampingCoefficients, /) -> None: ...
    @property
    def damping_resolution(self) -> _DampingResolution:
        """The most triangles of each mesh's reduced copy for the pressure drag, or ``"full"``."""
    @damping_resolution.setter
    def damping_resolution(self, resolution: _DampingResolution, /) -> None: ...
    def body_damping_resolution(self, index: SupportsIndex) -> _DampingResolution:
        """The damping resolution body ``index`` has: its own, else the controller's."""
    def __len__(self) -> int: ...
    def add(
        self,
        parts: _Part | Sequence[_Part],
        method: _MethodName | str | None = None,
        water: Water | None = None,
        damping: DampingCoefficients | None = None,
        damping_resolution: _DampingResolution | None = None,
    ) -> int:
        """Adds a body; returns its number."""
    def replace(
        self,
        index: SupportsIndex,
        parts: _Part | Sequence[_Part],
        method: _MethodName | str | None = None,
        water: Water | None = None,
        damping: DampingCoefficients | None = None,
        damping_resolution: _DampingResolution | None = None,
    ) -> None:
        """Replaces the parts and overrides of body ``index``, keeping its books."""
    def remove(self, index: SupportsIndex) -> tuple[_Float32Array, _Float32Array]:
        """Removes body ``index``; returns the force and torque that take its share back off."""
    def forget_applied(self, index: SupportsIndex) -> None:
        """The engine's forces of body ``index`` were reset: its share is zero now."""
    def rest(
        self,
        index: SupportsIndex,
        position: npt.ArrayLike,
        quaternion: npt.ArrayLike,
        center_of_mass: npt.ArrayLike,
        mass: float,
        gravity_scale: float = 1.0,
    ) -> tuple[_FloatArray, _FloatArray, Equilibrium]:
        """The body's position (3,) and quaternion (4,) at rest in still water, and the equilibrium."""
    def report(self, index: SupportsIndex) -> FloatReport:
        """What the last ``step`` computed and applied for body ``index``."""
    def parts(self, index: SupportsIndex) -> list[tuple[Mesh, _FloatArray, _FloatArray]]:
        """The parts of body ``index``: (mesh, position, quaternion (x, y, z, w))."""
    def step(
        self,
        dt: float,
        positions: npt.ArrayLike,
        quaternions: npt.ArrayLike,
        centers_of_mass: npt.ArrayLike,
        linear_velocities: npt.ArrayLike,
        angular_velocities: npt.ArrayLike,
        masses: npt.ArrayLike,
        inverse_masses: npt.ArrayLike,
        inverse_inertias: npt.ArrayLike,
        gravity_scales: npt.ArrayLike,
        applied_forces: npt.ArrayLike,
        applied_torques: npt.ArrayLike,
        dynamic: npt.ArrayLike,
        sleeping: npt.ArrayLike,
    ) -> tuple[_Float32Array, _Float32Array, _BoolArray]:
        """One step of every body: the forces and torques to add (N, 3) and whether to wake (N,)."""

def load(path: str | os.PathLike[str], close_openings: bool = False) -> Mesh: ...
def _unpickle(
    class_name: str, state: str
) -> Waterplane | Hydrostatics | Equilibrium | GzCurve | HydrostaticTable | BuoyancyBatch:
    """Rebuilds a pickled result (what its ``__reduce__`` returns)."""

def cube(n: int = 1) -> Mesh: ...
def uv_sphere(radius: float = 1.0, slices: int = 32, stacks: int = 16) -> Mesh: ...
def torus(major: float = 1.0, minor: float = 0.25, segments: int = 48, sides: int = 16) -> Mesh: ...
def torus_knot(
    p: int = 2,
    q: int = 3,
    radius: float = 1.0,
    tube_radius: float = 0.2,
    segments: int = 80,
    sides: int = 11,
) -> Mesh: ...
def wigley_hull(
    length: float = 4.0,
    beam: float = 0.6,
    draft: float = 0.25,
    freeboard: float = 0.15,
    stations: int = 41,
    waterlines: int = 17,
) -> Mesh:
    """A closed Wigley hull floating upright at its design draft (y up, waterline at y = 0)."""

def cuboid(half_extents: npt.ArrayLike) -> Mesh:
    """A box of half extents (a, b, c), m, about the origin: volume 8·a·b·c."""

def ellipsoid(radii: npt.ArrayLike, slices: int = 32, stacks: int = 16) -> Mesh:
    """An ellipsoid of semi-axes (a, b, c), m, holding exactly 4π·a·b·c/3."""

def cylinder(radius: float, half_height: float, segments: int = 32) -> Mesh:
    """A cylinder about y holding exactly 2π·radius²·half_height, m³."""

def capsule(radius: float, half_height: float, segments: int = 32, stacks: int = 16) -> Mesh:
    """A capsule about y holding exactly π·radius²·(2·half_height + 4·radius/3), m³."""

def _rapier_bodies(
    blobs: list[bytes], header: bytes
) -> tuple[npt.NDArray[np.float64], _Float32Array, npt.NDArray[np.uint8], list[bytes]] | None:
    """The state of rapier3d's rigid bodies from their ``RigidBody.to_bytes`` (buoyancy.rapier's
    bulk read): values (N, 18), wrench (N, 6), flags (N, 3) and the mass properties' bytes."""

def _world_inverse_inertias(quaternions: npt.ArrayLike, inverse_inertias: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """The world inverse inertia tensors R·I⁻¹·Rᵀ (N, 3, 3) of bodies turned by the unit
    quaternions (x, y, z, w) (N, 4) from their inverse inertias in their own frames (N, 3, 3); a
    non-finite quaternion counts as no rotation (buoyancy.rapier's glue)."""
