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
    """A mesh that cannot be used: not a closed, consistently oriented 2-manifold, bad vertex or face
    arrays, or a mesh file that cannot be parsed. The message names the vertices, triangles or edges
    at fault and what usually fixes them.

    Attributes
    ----------
    defects : tuple of MeshDefect
        Each kind of problem of the triangles, with its count and first culprits; empty when the
        problem is not there (an empty or flat mesh, arrays of the wrong shape, a file that cannot
        be parsed).
    triangle_soup : bool
        Whether no two triangles share a vertex, as STL files store a mesh: weld the vertices.
    coincident_vertices : int
        How many used vertices sit exactly where a vertex of lower index does (counted when the
        mesh has open edges): welding them closes the edges they split.
    one_based_indices : bool
        Whether the indices look one-based (as in an OBJ file): subtract 1 from every index.
    """

    defects: tuple[MeshDefect, ...]
    triangle_soup: bool
    coincident_vertices: int
    one_based_indices: bool

@final
class MeshDefect:
    """One kind of problem found in a mesh, an item of ``MeshError.defects``.

    Attributes
    ----------
    kind : str
        ``"non_finite_vertex"``, ``"index_out_of_range"``, ``"repeated_index"``,
        ``"open_edge"``, ``"non_manifold_edge"`` or ``"inconsistent_orientation"``.
    count : int
        How many vertices (``non_finite_vertex``), triangles (``index_out_of_range``,
        ``repeated_index``) or edges (the others) have the problem.
    examples : tuple of dict
        The first few of them (at most 5), zero-based: ``{"vertex": v}``,
        ``{"triangle": t, "index": i}`` (its first index out of range),
        ``{"triangle": t, "indices": (a, b, c)}``, or ``{"edge": (a, b), "triangles": (t, ...)}``
        (every triangle that has the edge).

    Examples
    --------
    >>> v = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    >>> try:
    ...     buoyancy.Mesh(v, [(0, 2, 1), (0, 1, 3), (0, 3, 2)])  # the fourth face is missing
    ... except buoyancy.MeshError as error:
    ...     [(d.kind, d.count) for d in error.defects], error.defects[0].examples[0]
    ([('open_edge', 3)], {'edge': (1, 2), 'triangles': (0,)})
    """

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
    """One linear (Airy) wave component, world frame, SI units:
    ``η(q, t) = amplitude * cos(k·q − ω t + phase)``, with ``k`` of length
    ``2π / wavelength`` along ``direction`` and ``ω`` from the dispersion relation
    ``ω² = g k tanh(k h)`` (``g k`` in deep water) of the :class:`Waves` it belongs to.

    Parameters
    ----------
    amplitude : float
        ``a``, half the height from trough to crest, m; finite and non-negative.
    wavelength : float
        ``λ``, m; finite and positive.
    direction : array_like, shape (3,)
        The direction the wave travels in, world frame (default ``(1, 0, 0)``); finite and
        non-zero. Its component along the water's up normal is dropped, so it must not be along
        that normal (checked when the wave is given to a :class:`Water`).
    phase : float
        The phase at the world origin at ``t = 0``, rad (default 0: a crest there).

    Raises ``ValueError`` naming the parameter that is out of range, ``TypeError`` naming the
    one that is not a number.

    Examples
    --------
    >>> swell = buoyancy.AiryWave(amplitude=0.5, wavelength=20.0)
    >>> swell
    AiryWave(amplitude=0.5, wavelength=20, direction=(1, 0, 0), phase=0)
    >>> sea = buoyancy.Water(waves=swell)              # y up: the wave runs along x
    >>> sea.elevation([(0, 0, 0), (5, 0, 0), (10, 0, 0)]).round(12).tolist()
    [0.5, 0.0, -0.5]
    >>> buoyancy.AiryWave(amplitude=-1.0, wavelength=20.0)
    Traceback (most recent call last):
    ...
    ValueError: amplitude: invalid water surface: a wave amplitude must be finite and non-negative (m)

    ``AiryWave`` is immutable, compares by value and pickles.
    """

    def __new__(
        cls,
        amplitude: float,
        wavelength: float,
        direction: npt.ArrayLike | None = (1.0, 0.0, 0.0),
        phase: float = 0.0,
    ) -> AiryWave: ...
    @property
    def amplitude(self) -> float:
        """Amplitude ``a``, m."""
    @property
    def wavelength(self) -> float:
        """Wavelength ``λ``, m."""
    @property
    def direction(self) -> _FloatArray:
        """The direction of travel as given, world frame, shape (3,) (a new, read-only array)."""
    @property
    def phase(self) -> float:
        """Phase at the world origin at ``t = 0``, rad."""
    @property
    def wavenumber(self) -> float:
        """Wave number ``k = 2π / wavelength``, rad/m."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> tuple[type[AiryWave], tuple[float, float, tuple[float, float, float], float]]: ...

@final
class Waves:
    """Linear (Airy) waves: the sum of :class:`AiryWave` components over water of a finite depth or
    infinitely deep, ``η(q, t) = Σ aᵢ cos(kᵢ·q − ωᵢ t + φᵢ)``, each ``ωᵢ`` from the dispersion
    relation ``ω² = g k tanh(k h)`` (``ω² = g k`` in deep water), ``g`` the gravity of the
    :class:`Water` the waves are given to. Horizontal positions ``q`` are world points projected
    onto the water's still plane; ``η`` is along its up normal; m, s.

    Parameters
    ----------
    components : iterable of AiryWave
        The components (none: calm water).
    depth : float, optional
        Depth of the water from the still level to the bottom, m, finite and positive; ``None``
        (default) for deep water.
    pressure : str
        The pressure :meth:`Mesh.buoyancy` integrates over the wetted surface under these waves:
        ``"hydrostatic"`` (default), ``p = ρ g (η − z)`` with ``z`` the height above the still
        plane, what games use; or ``"froude_krylov"``, the linear Froude–Krylov pressure of the
        undisturbed wave, ``p = ρ g (Σ aᵢ P(kᵢ, z) cos θᵢ − z)``, whose wave part decays with depth
        as ``P = cosh k(z + h) / cosh k h`` (``e^{k z}`` in deep water) and is not stretched above
        the still plane (``P = 1`` there); integrated by a degree-5 quadrature on each wetted
        piece, its error falling as ``(k L)⁶`` for pieces of size ``L``. Either pressure is
        clipped at zero, and the wetted surface is cut where ``η − z``, interpolated linearly
        between the vertices, is zero.

    Examples
    --------
    >>> sea = buoyancy.Waves(
    ...     [buoyancy.AiryWave(0.5, 20.0), buoyancy.AiryWave(0.2, 7.0, direction=(0, 0, 1), phase=1.0)],
    ...     depth=30.0,
    ... )
    >>> sea
    Waves([AiryWave(amplitude=0.5, wavelength=20, direction=(1, 0, 0), phase=0), AiryWave(amplitude=0.2, wavelength=7, direction=(0, 0, 1), phase=1)], depth=30)
    >>> (2 * np.pi / sea.angular_frequencies(gravity=9.81)).round(3).tolist()  # periods, s
    [3.579, 2.117]
    >>> hull = buoyancy.shapes.cube().scaled((4, 1, 1))
    >>> b = hull.buoyancy(position=(0, -0.2, 0), water=buoyancy.Water(waves=sea), time=1.5)
    >>> b.method
    'exact'

    Under the Froude–Krylov pressure a ball of 0.5 m radius 3 m under a 10 m swell feels, besides
    ``ρ g V`` up, ``ρ V`` times the water's acceleration at its center, whose component along x
    is ``A ω² e^{k z} sin θ`` (a quarter period after a crest passed: ``θ = −π/2``):

    >>> fk = buoyancy.Waves([buoyancy.AiryWave(0.5, 10.0)], pressure="froude_krylov")
    >>> fk
    Waves([AiryWave(amplitude=0.5, wavelength=10, direction=(1, 0, 0), phase=0)], depth=None, pressure='froude_krylov')
    >>> ball = buoyancy.shapes.uv_sphere(0.5, 96, 48)
    >>> k = 2 * np.pi / 10.0
    >>> omega = np.sqrt(9.81 * k)
    >>> quarter = np.pi / 2 / omega                      # s; θ = −π/2 at the center
    >>> b = ball.buoyancy(position=(0, -3, 0), water=buoyancy.Water(waves=fk), time=quarter)
    >>> a_x = 0.5 * omega**2 * np.exp(-3 * k) * np.sin(-np.pi / 2)   # m/s²
    >>> round(float(b.force[0] / (1000 * ball.volume * a_x)), 3)
    1.0
    >>> buoyancy.Waves([buoyancy.AiryWave(0.5, 20.0)], depth=0.0)
    Traceback (most recent call last):
    ...
    ValueError: depth: invalid water surface: the depth must be finite and positive (m), or None for deep water

    Irregular seas come from a spectrum: :meth:`jonswap` and :meth:`pierson_moskowitz`.

    ``Waves`` is immutable, compares by value (its components, depth and pressure) and pickles;
    its repr names the pressure when it is ``"froude_krylov"``.
    """

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
        """Irregular waves from a JONSWAP spectrum (a fetch-limited wind sea): Pierson–Moskowitz
        times the peak enhancement ``gamma ** exp(−(ω − ω_p)² / (2 σ² ω_p²))``, ``σ = 0.07`` below
        the peak and 0.09 above, ``ω_p = 2π / tp``.

        The frequencies from ``ω_p / 2`` to ``4 ω_p`` are cut into ``n`` equal bins; each component
        takes a frequency drawn within its bin, the amplitude ``sqrt(2 S(ω) Δω)``, a random phase,
        the wavelength of its frequency by the dispersion relation, and, with ``spreading``, a
        direction drawn from ``cos^(2s)((θ − θ₀) / 2)`` about the water's up normal. The
        amplitudes are then scaled so that ``4 * sqrt(Σ aᵢ² / 2)`` is ``hs`` exactly. The same
        seed gives the same sea.

        Parameters
        ----------
        hs : float
            Significant wave height, m (four standard deviations of ``η``); finite, non-negative.
        tp : float
            Peak period, s; finite, positive.
        gamma : float
            Peak enhancement factor, at least 1 (default 3.3, the North Sea mean; 1 is
            Pierson–Moskowitz).
        direction : array_like, shape (3,)
            Mean direction of travel, world frame (default ``(1, 0, 0)``); not along the normal.
        spreading : float, optional
            The exponent ``s`` of the directional spreading, positive (larger is narrower: swell
            about 25, wind sea 2 to 10); ``None`` (default) for long-crested waves.
        n : int
            Number of components, at least 1 (default 64).
        seed : int
            Seed of the random frequencies, phases and directions (default 0).
        depth : float, optional
            Water depth, m; ``None`` (default) for deep water.
        water : Water, optional
            The water the waves are for: the wavelengths follow from its gravity, the spreading
            turns about its up normal. By default (``None``) the waves are drawn for the water
            they are given to: ``Water(normal=(0, 0, 1), waves=Waves.jonswap(2.0, 8.0))`` is a
            z-up sea, the same seed giving the same frequencies, amplitudes and phases (until
            then, and for :attr:`components` read here, ``Water()``: 9.81 m/s², y up, so that a
            ``direction`` along y needs ``water=``). With a water given, giving the waves to a
            :class:`Water` of another gravity or normal is a ``ValueError``.
        pressure : str
            ``"hydrostatic"`` (default) or ``"froude_krylov"``: the pressure
            :meth:`Mesh.buoyancy` integrates under the waves (see :class:`Waves`).

        Examples
        --------
        >>> sea = buoyancy.Waves.jonswap(hs=2.0, tp=8.0, spreading=10.0, seed=7)
        >>> sea
        Waves.jonswap(hs=2, tp=8, gamma=3.3, direction=(1, 0, 0), spreading=10, n=64, seed=7, depth=None)
        >>> a = np.array([c.amplitude for c in sea.components])
        >>> round(float(4 * np.sqrt(np.sum(a**2) / 2)), 12)    # the significant height, m
        2.0
        >>> ocean = buoyancy.Water(normal=(0, 0, 1), waves=buoyancy.Waves.jonswap(2.0, 8.0, spreading=10.0))
        >>> d = np.array([c.direction for c in ocean.waves.components])
        >>> bool(np.all(d[:, 2] == 0.0))    # drawn about the water's up normal, z
        True
        >>> buoyancy.Waves.jonswap(2.0, 8.0, n=16, pressure="froude_krylov").pressure
        'froude_krylov'
        """
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
        """Irregular waves from a Pierson–Moskowitz spectrum (a fully developed sea),
        ``S(ω) = (5/16) hs² ω_p⁴ ω⁻⁵ exp(−(5/4) (ω_p / ω)⁴)``, ``ω_p = 2π / tp``, drawn into ``n``
        components as :meth:`jonswap` does (whose parameters these are, without ``gamma``).

        >>> sea = buoyancy.Waves.pierson_moskowitz(hs=1.0, tp=6.0, n=32)
        >>> len(sea), sea.depth
        (32, None)
        """
    @property
    def components(self) -> tuple[AiryWave, ...]:
        """The components, a tuple of :class:`AiryWave`."""
    @property
    def depth(self) -> float | None:
        """Depth of the water, m; ``None`` for deep water."""
    @property
    def pressure(self) -> _Pressure:
        """The pressure :meth:`Mesh.buoyancy` integrates under these waves: ``"hydrostatic"`` or
        ``"froude_krylov"``.
        """
    def angular_frequencies(self, gravity: float = 9.81) -> _FloatArray:
        """The angular frequency ``ω`` of each component under gravity ``gravity`` (m/s²), rad/s,
        shape (n,): ``ω² = g k tanh(k h)`` (``g k`` in deep water). ``2π / ω`` is the period, s.

        >>> buoyancy.Waves([buoyancy.AiryWave(1.0, 2 * np.pi)]).angular_frequencies(gravity=4.0).tolist()
        [2.0]
        """
    def __len__(self) -> int: ...
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> tuple[Callable[..., Waves], tuple[object, ...]]: ...

@final
class GerstnerWaves:
    """Trochoidal (Gerstner) waves in deep water, world frame, SI units: the water particle at rest
    at horizontal position ``p`` moves to ``p − Σ dᵢ aᵢ sin θᵢ`` and rises by ``Σ aᵢ cos θᵢ``,
    ``θᵢ = kᵢ·p − ωᵢ t + φᵢ``, ``ωᵢ² = g kᵢ``: crests sharper than troughs. The elevation at a
    fixed point is that of the particle which is there, found by Newton's method to
    ``1e-12 * Σ aᵢ`` (m).

    Parameters
    ----------
    components : iterable of AiryWave
        Amplitude, wavelength, direction and phase of each component (as for :class:`Waves`).
        Their steepness ``Σ kᵢ aᵢ`` (``kᵢ = 2π / wavelengthᵢ``) must be below 1: at 1 the crests
        become cusps, beyond they fold over (a ``ValueError``).

    Examples
    --------
    >>> trochoid = buoyancy.GerstnerWaves([buoyancy.AiryWave(amplitude=1.0, wavelength=30.0)])
    >>> sea = buoyancy.Water(waves=trochoid)
    >>> sea.elevation([(0, 0, 0), (15, 0, 0)]).round(9).tolist()   # crest, trough
    [1.0, -1.0]
    >>> buoyancy.GerstnerWaves([buoyancy.AiryWave(amplitude=2.0, wavelength=12.0)])
    Traceback (most recent call last):
    ...
    ValueError: components: invalid water surface: a Gerstner sea with steepness Σ k·a of 1 or more folds over: lower the amplitudes

    ``GerstnerWaves`` is immutable, compares by value and pickles.
    """

    def __new__(cls, components: Iterable[AiryWave]) -> GerstnerWaves: ...
    @property
    def components(self) -> tuple[AiryWave, ...]:
        """The components, a tuple of :class:`AiryWave`."""
    @property
    def steepness(self) -> float:
        """The steepness ``Σ kᵢ aᵢ``, below 1."""
    def __len__(self) -> int: ...
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(self) -> tuple[type[GerstnerWaves], tuple[tuple[AiryWave, ...]]]: ...

@final
class HeightGrid:
    """Heights on a regular grid, interpolated bilinearly: the elevation ``η`` of the water surface
    above its still plane (m, along the up normal), for an ocean computed elsewhere (an FFT
    ocean, a game engine's water). The heights do not depend on time: replace them each step
    with :meth:`set_heights`.

    Parameters
    ----------
    heights : array_like, shape (rows, columns)
        Elevations at the nodes, m, finite; at least 2 rows and 2 columns.
        ``heights[j, i]`` is the node of column ``i`` and row ``j``.
    spacing : float or array_like, shape (2,)
        Distance between neighbouring columns and between neighbouring rows, m, finite and
        positive; one number for both.
    origin : array_like, shape (2,)
        Where node ``[0, 0]`` is, along the column and the row axis, m (default ``(0, 0)``).
    periodic : bool
        Whether the grid repeats (default ``True``), with periods ``columns * spacing[0]`` and
        ``rows * spacing[1]`` (one tile, as an FFT ocean's: the last column is not a copy of the
        first). Otherwise the edge values hold beyond the edges.

    The axes come from the up normal of the :class:`Water` the grid is given to: a point of the
    still plane is found on the grid by its two world coordinates other than the one most
    aligned with the normal. For y up, columns run along x and rows along z; for z up, along x
    and y; for x up, along y and z. So with y up, ``heights[j, i]`` is the elevation at
    ``x = origin[0] + i * spacing[0]``, ``z = origin[1] + j * spacing[1]``. For a tilted normal
    the grid is the one seen along that axis (the axis most aligned with the normal; ties go to
    y, then z), projected along it onto the still plane.

    Raises ``ValueError`` naming the parameter that is out of range or of the wrong shape.

    Examples
    --------
    >>> x = np.arange(64) * 0.5                           # 64 columns, 0.5 m apart
    >>> heights = np.tile(0.3 * np.cos(2 * np.pi * x / 32.0), (8, 1))  # (8, 64): crests along z
    >>> grid = buoyancy.HeightGrid(heights, spacing=0.5)
    >>> grid
    HeightGrid(shape=(8, 64), spacing=(0.5, 0.5), origin=(0, 0), periodic=True)
    >>> sea = buoyancy.Water(waves=grid)                 # y up: columns along x, rows along z
    >>> sea.elevation([(0, 0, 0), (8, 0, 1.2), (48, 0, 0)]).round(12).tolist()  # 48 m: wrapped
    [0.3, 0.0, -0.3]
    >>> grid.set_heights(np.zeros((8, 64)))               # in place: the water follows
    >>> sea.elevation((0, 0, 0))
    0.0

    A ``HeightGrid`` is the one object of this package that changes (:meth:`set_heights`);
    every :class:`Water` holding it sees the new heights. It compares by value (so it is not
    hashable) and pickles with the heights it has.
    """

    def __new__(
        cls,
        heights: npt.ArrayLike,
        spacing: float | npt.ArrayLike,
        origin: npt.ArrayLike | None = (0.0, 0.0),
        periodic: bool = True,
    ) -> HeightGrid: ...
    def set_heights(self, heights: npt.ArrayLike) -> None:
        """Replaces the heights in place (no new storage), shape ``(rows, columns)`` as the grid's,
        m, finite. Every :class:`Water` holding the grid sees them from then on; on an error the
        grid is unchanged.

        >>> grid = buoyancy.HeightGrid(np.zeros((4, 4)), spacing=1.0)
        >>> grid.set_heights(np.ones((4, 4)))
        >>> float(grid.heights.max())
        1.0
        >>> grid.set_heights(np.ones((4, 5)))
        Traceback (most recent call last):
        ...
        ValueError: heights: expected shape (4, 4), the grid's (rows, columns), got shape (4, 5)
        """
    @property
    def heights(self) -> _FloatArray:
        """The heights, shape (rows, columns), m (a new, read-only array)."""
    @property
    def shape(self) -> tuple[int, int]:
        """``(rows, columns)``."""
    @property
    def spacing(self) -> tuple[float, float]:
        """Distance between neighbouring columns and between neighbouring rows, m."""
    @property
    def origin(self) -> tuple[float, float]:
        """Where node ``[0, 0]`` is along the column and the row axis, m."""
    @property
    def periodic(self) -> bool:
        """Whether the grid repeats beyond its edges."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(
        self,
    ) -> tuple[type[HeightGrid], tuple[_FloatArray, tuple[float, float], tuple[float, float], bool]]: ...

@final
class Water:
    """A body of water, world frame, SI units: its still plane, and optionally the waves on it.

    Parameters
    ----------
    density : float
        kg/m³, finite and positive (default 1000, fresh water).
    gravity : float
        Magnitude of gravity, m/s², finite and non-negative (default 9.81). Its direction is
        ``-normal``: a gravity vector such as ``(0, 0, -9.81)`` is ``gravity=9.81,
        normal=(0, 0, 1)``.
    level : float
        The surface is the plane ``dot(normal, p) == level`` (default 0).
    normal : array_like, shape (3,)
        Up direction (out of the water, against gravity); normalised, must be non-zero.
    waves : optional
        The free surface, as its elevation ``η`` (m, along ``normal``) above the still plane at
        horizontal positions (world points projected onto the still plane) and time ``t`` (s):
        an :class:`AiryWave`, :class:`Waves`, a :class:`HeightGrid`, or a vectorised callable
        ``f(points, t)`` taking the positions as an (N, 3) array and returning N elevations,
        called once per evaluation (with the interpreter lock held around the call only).
        ``None`` (default): still water, ``η = 0``.

    On waves, :meth:`Mesh.buoyancy` integrates the hydrostatic pressure ``ρ g (η − h)`` (``h``
    the height above the still plane) over the wetted surface, which is cut exactly where the
    depth, interpolated linearly between the vertices, is zero: the methods ``"exact"`` (the
    default) and ``"exact_surface"`` alike (the other methods assume a flat surface). Under :class:`Waves` of
    ``pressure="froude_krylov"`` it integrates the linear Froude–Krylov pressure instead, whose
    wave part decays with depth (see :class:`Waves`).

    Raises ``ValueError`` naming the parameter that is out of range, ``TypeError`` naming the
    parameter that is not a number (or not 3 numbers, for ``normal``; or not a surface, for
    ``waves``).

    >>> buoyancy.Water(density=1025.0, normal=(0, 0, 1))
    Water(density=1025, gravity=9.81, level=0, normal=(0, 0, 1))
    >>> buoyancy.Water(gravity=(0, 0, -9.81))
    Traceback (most recent call last):
    ...
    TypeError: gravity: expected a number, the magnitude of gravity in m/s², got tuple; its direction is -normal: for the vector (0, 0, -9.81) write Water(gravity=9.81, normal=(0, 0, 1))

    A swell along x, and the elevation it gives:

    >>> swell = buoyancy.Water(waves=buoyancy.AiryWave(amplitude=0.5, wavelength=20.0))
    >>> swell
    Water(density=1000, gravity=9.81, level=0, normal=(0, 1, 0), waves=AiryWave(amplitude=0.5, wavelength=20, direction=(1, 0, 0), phase=0))
    >>> round(swell.elevation((0, -3, 0)), 12), round(swell.elevation((10, 2, 0)), 12)
    (0.5, -0.5)

    ``Water`` is immutable, safe to share between threads, compares by value (the same callable,
    for waves given as one) and pickles (with waves given as a callable: only if the callable
    pickles). Its waves can be a :class:`HeightGrid`, whose heights change in place.
    """

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
    def density(self) -> float:
        """Density, kg/m³."""
    @property
    def gravity(self) -> float:
        """Magnitude of gravity, m/s²."""
    @property
    def level(self) -> float:
        """Signed distance of the surface from the origin along ``normal``, m."""
    @property
    def normal(self) -> _FloatArray:
        """Unit up normal, shape (3,) (a new, read-only array)."""
    @property
    def specific_weight(self) -> float:
        """``density * gravity``, N/m³."""
    @property
    def waves(self) -> _Surface | None:
        """The waves as given (an :class:`AiryWave`, :class:`Waves`, :class:`HeightGrid` or
        callable), ``None`` for still water.
        """
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
    """The buoyancy of a body at one pose, world frame, SI units (m, m³, N, N·m).

    Attributes
    ----------
    volume : float
        Submerged volume, m³ (for the surface methods: the volume implied by the force).
    center : ndarray, shape (3,)
        Center of buoyancy, the point of application of the force, m.
    force : ndarray, shape (3,)
        Buoyant force, N (``density * gravity * volume`` along the water's up normal).
    torque : ndarray, shape (3,)
        Torque of the buoyant force about ``about``, N·m.
    about : ndarray, shape (3,)
        The point the torque is taken about: the ``about`` argument, by default the body's center
        of mass (the mesh centroid moved by the pose).
    fully_submerged, partially_submerged : int
        Number of triangles entirely under water, and cut by the surface.
    wetted_area : float
        Area of the mesh surface under water, m²: of the triangles entirely under water and of
        the parts under water of those the surface cuts. Exact for ``"exact"``, ``"improved"``,
        ``"exact_surface"`` and under waves (the wetted surface the pressure is integrated over);
        ``"fast"`` and ``"fast_surface"`` count the triangles entirely under water only, what they
        integrate over. A unit cube upright at draft ``d`` has ``1 + 4 d``.
    method : str
        The method that computed it.

    ``Buoyancy(volume, center, force, torque, about, fully_submerged=0, partially_submerged=0,
    method="exact", wetted_area=0.0)`` builds one (for unpickling and tests). It is immutable,
    compares by value (every attribute) and pickles; each array attribute returns a new,
    read-only array.

    Examples
    --------
    >>> b = buoyancy.shapes.cube().buoyancy(position=(0, -0.25, 0))
    >>> b.volume, b.center.tolist(), b.method
    (0.75, [0.0, -0.375, 0.0], 'exact')
    >>> import pickle
    >>> pickle.loads(pickle.dumps(b)) == b
    True
    """

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
    def center(self) -> _FloatArray: ...
    @property
    def force(self) -> _FloatArray: ...
    @property
    def torque(self) -> _FloatArray: ...
    @property
    def about(self) -> _FloatArray: ...
    @property
    def fully_submerged(self) -> int: ...
    @property
    def partially_submerged(self) -> int: ...
    @property
    def wetted_area(self) -> float: ...
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
    """The buoyancy of a body at K poses: arrays indexed by pose, world frame, SI units.

    Attributes
    ----------
    volume : ndarray, shape (K,)
    center : ndarray, shape (K, 3)
    force : ndarray, shape (K, 3)
    torque : ndarray, shape (K, 3)
    about : ndarray, shape (K, 3)
        The point each torque is taken about.
    fully_submerged, partially_submerged : ndarray of int64, shape (K,)
    wetted_area : ndarray, shape (K,)
        Area under water, m², as :attr:`Buoyancy.wetted_area`.
    method : str

    ``len(batch)`` is K; ``batch[k]`` is the :class:`Buoyancy` of pose ``k``. The arrays are
    created once and are read-only: attribute access returns the same array, and writing to it
    raises ``ValueError`` (``np.array(batch.force)`` is a copy to change).
    """

    @property
    def volume(self) -> _FloatArray: ...
    @property
    def center(self) -> _FloatArray: ...
    @property
    def force(self) -> _FloatArray: ...
    @property
    def torque(self) -> _FloatArray: ...
    @property
    def about(self) -> _FloatArray: ...
    @property
    def fully_submerged(self) -> _IntArray: ...
    @property
    def partially_submerged(self) -> _IntArray: ...
    @property
    def wetted_area(self) -> _FloatArray: ...
    @property
    def method(self) -> str: ...
    def __len__(self) -> int: ...
    def __getitem__(self, index: SupportsIndex, /) -> Buoyancy: ...

@final
class DampingCoefficients:
    """The coefficients of the hydrodynamic damping model, SI units.

    The model (``buoyancy-core``'s ``damping`` module) damps a body moving through the water so
    that it settles instead of bobbing forever. With ``u`` the velocity of a surface point
    relative to the water (``current``), each wetted triangle of area ``A`` and outward normal
    ``n`` moving into the water (``u_n = n·u > 0``) feels the pressure
    ``linear_drag * u_n + 0.5 * density * drag_coefficient * u_n**2`` against its normal; the
    body also feels the angular damping torque
    ``-f * density * V**(5/3) * (angular_drag_linear + angular_drag_quadratic * |ω|) * ω``, with
    ``f`` the wetted fraction of its surface and ``V`` its volume. Nothing acts on what is above
    water.

    Parameters
    ----------
    linear_drag : float
        Linear pressure-drag coefficient ``c₁``, Pa per m/s (default 1000).
    drag_coefficient : float
        Dimensionless quadratic drag coefficient ``C_D`` (default 1; a flat plate face-on is about
        1.2, a sphere about 0.5).
    angular_drag_linear : float
        Linear angular damping rate ``a₁``, 1/s (default 0.1).
    angular_drag_quadratic : float
        Dimensionless quadratic angular damping coefficient ``a₂`` (default 0.1).
    current : array_like, shape (3,)
        Velocity of the water, world frame, m/s (default zero).

    Every coefficient must be finite and non-negative, and the current finite; anything else
    raises ``ValueError`` naming the parameter (``TypeError`` for a value that is not a number).

    Examples
    --------
    >>> buoyancy.DampingCoefficients()
    DampingCoefficients(linear_drag=1000, drag_coefficient=1, angular_drag_linear=0.1, angular_drag_quadratic=0.1, current=(0, 0, 0))
    >>> buoyancy.DampingCoefficients.off().is_off
    True
    >>> buoyancy.DampingCoefficients(linear_drag=-1.0)
    Traceback (most recent call last):
    ...
    ValueError: linear_drag: must be finite and non-negative

    ``DampingCoefficients`` is immutable, compares by value and pickles.
    """

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
        """No damping at all: ``Mesh.damping`` then returns zero force and torque.

        >>> buoyancy.DampingCoefficients.off()
        DampingCoefficients(linear_drag=0, drag_coefficient=0, angular_drag_linear=0, angular_drag_quadratic=0, current=(0, 0, 0))
        """
    @property
    def linear_drag(self) -> float:
        """Linear pressure-drag coefficient ``c₁``, Pa per m/s."""
    @property
    def drag_coefficient(self) -> float:
        """Dimensionless quadratic pressure-drag coefficient ``C_D``."""
    @property
    def angular_drag_linear(self) -> float:
        """Linear angular damping rate ``a₁``, 1/s."""
    @property
    def angular_drag_quadratic(self) -> float:
        """Dimensionless quadratic angular damping coefficient ``a₂``."""
    @property
    def current(self) -> _FloatArray:
        """Velocity of the water, world frame, m/s, shape (3,) (a new, read-only array)."""
    @property
    def is_off(self) -> bool:
        """Whether every coefficient is zero (the current alone damps nothing)."""
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(
        self,
    ) -> tuple[type[DampingCoefficients], tuple[float, float, float, float, tuple[float, float, float]]]: ...

@final
class Damping:
    """The hydrodynamic damping of a body at one instant, world frame, SI units.

    Attributes
    ----------
    force : ndarray, shape (3,)
        Damping force, N.
    torque : ndarray, shape (3,)
        Damping torque about ``about``, N·m (the moments of the pressure drag plus the angular
        damping).
    about : ndarray, shape (3,)
        The point the torque is taken about: the ``about`` argument of ``Mesh.damping``, by
        default the body's center of mass (the mesh centroid moved by the pose).
    wetted_area : float
        Area of the surface under water, m².
    wetted_fraction : float
        ``wetted_area`` over the whole surface area, in [0, 1].

    ``Damping(force, torque, about, wetted_area=0.0, wetted_fraction=0.0)`` builds one (for
    unpickling and tests). It is immutable, compares by value and pickles; each array attribute
    returns a new, read-only array.
    """

    def __new__(
        cls,
        force: npt.ArrayLike,
        torque: npt.ArrayLike,
        about: npt.ArrayLike,
        wetted_area: float = 0.0,
        wetted_fraction: float = 0.0,
    ) -> Damping: ...
    @property
    def force(self) -> _FloatArray: ...
    @property
    def torque(self) -> _FloatArray: ...
    @property
    def about(self) -> _FloatArray: ...
    @property
    def wetted_area(self) -> float: ...
    @property
    def wetted_fraction(self) -> float: ...
    def __eq__(self, other: object, /) -> bool: ...
    def __reduce__(
        self,
    ) -> tuple[
        type[Damping],
        tuple[tuple[float, float, float], tuple[float, float, float], tuple[float, float, float], float, float],
    ]: ...

@final
class Mesh:
    """A closed triangle mesh, validated and prepared for buoyancy queries.

    Parameters
    ----------
    vertices : array_like, shape (N, 3)
        Vertex positions in the mesh frame, metres (any numeric dtype; converted to float64).
    faces : array_like, shape (M, 3)
        Triangles as zero-based vertex indices (any integer dtype, or integral floats), wound
        counter-clockwise seen from outside. All-inward winding is detected and flipped.

    Raises
    ------
    MeshError
        (a ``ValueError``) if the arrays have the wrong shape, or the triangles are not a closed,
        consistently oriented 2-manifold enclosing a volume; the message names the vertex,
        triangle or edge at fault.

    Examples
    --------
    >>> import buoyancy
    >>> v = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    >>> f = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    >>> tet = buoyancy.Mesh(v, f)
    >>> tet
    Mesh(n_vertices=4, n_triangles=4, volume=0.166667, centroid=[0.25, 0.25, 0.25])
    >>> buoyancy.Mesh(v, f[:3])
    Traceback (most recent call last):
    ...
    buoyancy.MeshError: the mesh (4 vertices, 3 triangles) is not a closed, consistently oriented ...
    - 3 open edges (of one triangle only: the mesh is not closed): edge (1, 2) of triangle 0, ...

    The error's ``defects`` list the same problems as :class:`MeshDefect` items.

    ``Mesh`` is immutable and safe to share between threads; it compares (and hashes) by value,
    its vertices as given and its faces, and pickles. Its array attributes are read-only.
    """

    def __new__(cls, vertices: npt.ArrayLike, faces: npt.ArrayLike) -> Mesh: ...
    @classmethod
    def close_openings(cls, vertices: npt.ArrayLike, faces: npt.ArrayLike) -> Mesh:
        """A hull surface with planar openings (a hull without a deck, the usual input of naval
        architecture), each closed by a flat lid: a fan of triangles from a vertex added at the
        mean of the opening's rim. Everything computed counts the lids as hull, which holds while
        the water stays below every rim: :meth:`hydrostatics` and :meth:`equilibrium` raise
        ``ValueError`` when the water reaches one, :meth:`gz_curve` stops there
        (``GzCurve.flooding_angle``), :meth:`hydrostatic_table` refuses such a draft. A closed
        mesh is built as ``Mesh(vertices, faces)`` builds it.

        ``vertices`` then ``faces`` hold the lids' centers and triangles after the given ones;
        ``openings`` lists each rim's vertices. A rim that is not planar (within 1e-6 of its
        size) is a ``ValueError`` naming it.

        Examples
        --------
        >>> cube = buoyancy.shapes.cube(2)
        >>> top = np.all(cube.vertices[cube.faces][:, :, 1] == 0.5, axis=1)   # the y = 0.5 face
        >>> open_box = buoyancy.Mesh.close_openings(cube.vertices, cube.faces[~top])
        >>> len(open_box.openings), round(open_box.volume, 12)
        (1, 1.0)
        """
    @classmethod
    def welded(cls, vertices: npt.ArrayLike, faces: npt.ArrayLike) -> Mesh:
        """A closed mesh from a tessellation that repeats its vertices (the seams and poles of an
        engine's sphere, cylinder or capsule, such as ``rapier3d``'s ``to_trimesh``; an STL-like
        list of corners face by face): vertices within 1e-6 of the mesh's extent of an earlier one
        are merged and the triangles that collapse dropped (``buoyancy_core::mesh::primitives::weld``), then
        the mesh is built as ``Mesh(vertices, faces)`` builds it.

        Examples
        --------
        >>> import numpy as np
        >>> corners = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
        >>> faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
        >>> soup = corners[faces].reshape(-1, 3)            # 12 vertices, one per corner of a face
        >>> round(buoyancy.Mesh.welded(soup, np.arange(12).reshape(4, 3)).volume, 15)
        0.166666666666667
        """
    @property
    def openings(self) -> list[_IntArray]:
        """The openings closed by lids (:meth:`close_openings`): a list of int64 arrays, each the
        indices of one rim's vertices in order; empty for a closed mesh.
        """
    @classmethod
    def from_trimesh(cls, obj: _HasVerticesAndFaces | _HasToGeometry) -> Mesh:
        """Builds a mesh from a ``trimesh.Trimesh`` (or any object with ``vertices`` and ``faces``),
        or from a ``trimesh.Scene``: its geometry concatenated, each part placed by the scene's
        transforms (``scene.to_geometry()``), which must together be closed.

        The vertices are taken as they are; no up axis is applied. trimesh, CAD files and naval
        tools are usually z up, and :class:`Water`'s default is y up: float such a mesh in
        ``Water(normal=(0, 0, 1))`` (see the README's conventions).

        >>> import trimesh  # doctest: +SKIP
        >>> buoyancy.Mesh.from_trimesh(trimesh.creation.box())  # doctest: +SKIP
        Mesh(n_vertices=8, n_triangles=12, volume=1, centroid=[0, 0, 0])
        >>> from types import SimpleNamespace
        >>> tet = SimpleNamespace(
        ...     vertices=[(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)],
        ...     faces=[(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)],
        ... )
        >>> buoyancy.Mesh.from_trimesh(tet)
        Mesh(n_vertices=4, n_triangles=4, volume=0.166667, centroid=[0.25, 0.25, 0.25])

        Raises ``TypeError`` naming ``obj`` for anything else.
        """
    @property
    def volume(self) -> float:
        """Enclosed volume, m³ (positive)."""
    @property
    def centroid(self) -> _FloatArray:
        """Centroid of the enclosed volume (center of mass of a uniform body), mesh frame, shape (3,)
        (a new, read-only array).
        """
    @property
    def n_vertices(self) -> int:
        """Number of vertices."""
    @property
    def n_triangles(self) -> int:
        """Number of triangles."""
    @property
    def bounding_radius(self) -> float:
        """Largest distance of a vertex from the centroid, m."""
    @property
    def longest_edge(self) -> float:
        """The longest edge of the triangles, m: waves shorter than twice it are not seen between
        the vertices, where the surface is sampled (``buoyancy`` warns).
        """
    @property
    def was_reoriented(self) -> bool:
        """Whether the faces were wound inward and have all been flipped."""
    @property
    def vertices(self) -> _FloatArray:
        """The vertices as given, shape (N, 3), float64 (a new, read-only array)."""
    @property
    def faces(self) -> _IntArray:
        """The triangles wound outward (flipped if ``was_reoriented``), shape (M, 3), int64 (a new,
        read-only array).
        """
    def buoyancy(
        self,
        position: npt.ArrayLike | None = (0, 0, 0),
        rotation: npt.ArrayLike | None = None,
        water: Water | None = None,
        method: _MethodName | str = "exact",
        about: npt.ArrayLike | None = None,
        traversal: _TraversalName | str = "auto",
        time: float = 0.0,
    ) -> Buoyancy:
        """The buoyancy of the mesh at one pose.

        Parameters
        ----------
        position : array_like, shape (3,)
            Translation of the mesh frame in the world frame, m: ``x_world = R @ x_mesh + position``.
        rotation : array_like, shape (4,) or (3, 3), optional
            Quaternion ``(x, y, z, w)`` (scipy's order) or rotation matrix; ``None`` for identity.
            A quaternion must have norm 1 within 1e-5 (it is then normalised); a matrix must be
            orthonormal within 1e-5 with determinant +1. Anything else raises ``ValueError``.
        water : Water, optional
            Default ``Water()``: fresh water, y up, surface at y = 0.
        method : str
            ``"fast"``, ``"improved"``, ``"exact"`` (default), ``"fast_surface"`` or
            ``"exact_surface"``, in any case, with ``_``, ``-`` or nothing between the words
            (``"ExactSurface"``, the Rust name, works too). On a water with waves ``"exact"`` and
            ``"exact_surface"`` are the same exact integral of the pressure; the others assume a
            flat surface (a ``ValueError``).
        traversal : str
            ``"auto"`` (default), ``"scan"`` or ``"hierarchy"``: visit every triangle, or only the
            nodes of the mesh's bounding-volume hierarchy that the surface crosses.
            ``"auto"`` takes the hierarchy from 128 triangles up.
            All give the same result up to round-off. On waves the hierarchy is walked against
            the layer the surface lies in (``"scan"``: every vertex evaluated, every triangle on
            its own); under the Froude–Krylov pressure every triangle is integrated.
        about : array_like, shape (3,), optional
            World point the torque is taken about; default the body's center of mass (the mesh
            centroid moved by the pose).
        time : float
            The time of the water's waves, s, finite (default 0); still water does not depend on it.

        Returns
        -------
        Buoyancy
            On waves: the hydrostatic pressure of the waves integrated exactly over the wetted
            surface (sampled at the vertices, once per vertex), or, under :class:`Waves` of
            ``pressure="froude_krylov"``, the linear Froude–Krylov pressure integrated over it by
            a degree-5 quadrature; ``volume`` is the volume implied by
            the force along the normal, ``force / (density * gravity)``, and ``center`` a point of
            the force's line of action.

        Examples
        --------
        >>> cube = buoyancy.shapes.cube()            # unit cube about the origin
        >>> b = cube.buoyancy(position=(0, -0.25, 0))
        >>> round(b.volume, 12), b.force.round(6).tolist()
        (0.75, [0.0, 7357.5, 0.0])
        >>> cube.buoyancy(position=(0, -0.25, 0), method="ExactSurface").method
        'exact_surface'

        On a surface tilted by the slope 0.1 along x the force leans against the slope:

        >>> ramp = buoyancy.Water(waves=lambda p, t: 0.1 * p[:, 0])
        >>> fx, fy, _ = cube.buoyancy(position=(0, -0.25, 0), water=ramp).force
        >>> round(float(fx / fy), 12)
        -0.1
        """
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
    ) -> BuoyancyBatch:
        """The buoyancy of the mesh at K poses, computed in parallel without the interpreter lock.

        Parameters
        ----------
        positions : array_like, shape (K, 3)
        rotations : array_like, shape (K, 4) or (K, 3, 3), or None
            Quaternions ``(x, y, z, w)`` or rotation matrices, checked as in :meth:`buoyancy`;
            ``None`` for no rotation.
        water : Water, optional
        method : str
            As in :meth:`buoyancy`.
        about : array_like, shape (3,) or (K, 3), optional
            One world point, or one per pose, for the torques; default each pose's center of mass.
        threads : int, optional
            Run on a pool of this many threads (kept for later calls); default rayon's global
            pool (``RAYON_NUM_THREADS``, else one thread per core).
        traversal : str
            ``"auto"`` (default), ``"scan"`` or ``"hierarchy"``, as in :meth:`buoyancy`.
        times : float or array_like, shape (K,), optional
            The time of the water's waves at each pose, s, finite; one for every pose, or one per
            pose; default 0. A callable surface is called once per pose, holding the interpreter
            lock only around the call.

        Returns
        -------
        BuoyancyBatch
            Read-only arrays ``volume`` (K,), ``center``, ``force``, ``torque`` (K, 3); pose ``k``
            gives exactly what ``buoyancy(positions[k], rotations[k], ...)`` gives.

        Examples
        --------
        >>> cube = buoyancy.shapes.cube()
        >>> heights = np.linspace(-1, 1, 5)
        >>> batch = cube.buoyancy_batch(np.c_[0 * heights, heights, 0 * heights], None)
        >>> batch.volume.round(12).tolist()
        [1.0, 1.0, 0.5, 0.0, 0.0]

        A box riding a swell for one period, one time per pose:

        >>> swell = buoyancy.Waves([buoyancy.AiryWave(amplitude=0.1, wavelength=8.0)])
        >>> period = 2 * np.pi / swell.angular_frequencies()[0]
        >>> times = np.linspace(0, period, 5)
        >>> still = np.zeros((5, 3))
        >>> heave = cube.buoyancy_batch(still, None, water=buoyancy.Water(waves=swell), times=times)
        >>> heave.force[:, 1].round().tolist()     # N: crest, node, trough, node, crest
        [5811.0, 4905.0, 3999.0, 4905.0, 5811.0]
        """
    def damping(
        self,
        position: npt.ArrayLike | None = (0, 0, 0),
        rotation: npt.ArrayLike | None = None,
        linear_velocity: npt.ArrayLike | None = (0, 0, 0),
        angular_velocity: npt.ArrayLike | None = (0, 0, 0),
        water: Water | None = None,
        coefficients: DampingCoefficients | None = None,
        about: npt.ArrayLike | None = None,
    ) -> Damping:
        """The hydrodynamic damping of the mesh at one pose and velocity: pressure drag on the wetted
        surface plus angular damping (see :class:`DampingCoefficients` for the model). Zero when
        dry or at rest relative to the water.

        Parameters
        ----------
        position, rotation : array_like, optional
            The pose, as in :meth:`buoyancy`.
        linear_velocity : array_like, shape (3,)
            Velocity of the body's center of mass (the mesh centroid moved by the pose), world
            frame, m/s; default zero.
        angular_velocity : array_like, shape (3,)
            Angular velocity, world frame, rad/s; default zero.
        water : Water, optional
            Default ``Water()``; without waves (the model assumes a flat surface: a ``ValueError``).
        coefficients : DampingCoefficients, optional
            Default ``DampingCoefficients()``.
        about : array_like, shape (3,), optional
            World point the torque is taken about; default the body's center of mass.

        Returns
        -------
        Damping

        The model is explicit: a simulation applying it over a step ``dt`` should keep the impulse
        ``|force| * dt`` below the momentum it damps; :class:`Controller` (and so
        ``buoyancy.rapier``) applies it semi-implicitly, and :meth:`damping_stiffness` gives what
        an implicit integration needs.

        Examples
        --------
        A unit cube under water sinking at 2 m/s: only its bottom face (1 m²) faces the flow,
        and feels ``1000 * 2 + 0.5 * 1000 * 1 * 2**2 = 4000`` Pa.

        >>> cube = buoyancy.shapes.cube()
        >>> d = cube.damping(position=(0, -3, 0), linear_velocity=(0, -2, 0))
        >>> d.force.round(9).tolist(), d.wetted_area
        ([0.0, 4000.0, 0.0], 6.0)
        >>> cube.damping(position=(0, 2, 0), linear_velocity=(0, -2, 0)).force.tolist()  # dry
        [0.0, 0.0, 0.0]
        """
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
        """The stiffness of the damping, ``K = −∂W/∂q̇``: how the damping wrench ``W = (force,
        torque)`` of :meth:`damping` changes with the velocity ``q̇ = (linear_velocity,
        angular_velocity)``, what an implicit integration of the damping needs.

        Parameters are those of :meth:`damping`. The stiffness is taken about the point ``about``
        (default the center of mass): its rows are the force and the torque about that point, its
        columns the velocity of that point and the angular velocity.

        Returns
        -------
        numpy.ndarray, shape (6, 6)
            Symmetric and positive semi-definite, world frame, rows and columns in the order
            ``(vx, vy, vz, ωx, ωy, ωz)``; N·s/m, N·s and N·m·s. The pressure drag's part is
            ``∫ (c₁ + ρ·C_D·u) a aᵀ dA`` over the wetted surface facing the flow, with
            ``a = (n, (p − about) × n)`` and ``u`` the normal velocity there, integrated exactly;
            the angular damping adds ``s·((a₁ + a₂|ω|)·I + a₂·ω ωᵀ/|ω|)``, ``s = f·ρ·V^{5/3}``,
            to the ``ω`` block.

        Examples
        --------
        The unit cube under water, sinking at 2 m/s: its bottom face (1 m²) feels ``1000·u +
        500·u²`` Pa, so the heave stiffness is ``1000 + 1000·2 = 3000`` N·s/m.

        >>> cube = buoyancy.shapes.cube()
        >>> k = cube.damping_stiffness(position=(0, -3, 0), linear_velocity=(0, -2, 0))
        >>> k.shape, round(float(k[1, 1]), 9)
        ((6, 6), 3000.0)
        """
    def waterplane(
        self,
        position: npt.ArrayLike | None = (0, 0, 0),
        rotation: npt.ArrayLike | None = None,
        water: Water | None = None,
    ) -> Waterplane:
        """The waterplane at a pose: the section of the still water plane through the body, its
        area, center of flotation and second moments (exact for the mesh: the polygons where the
        plane cuts it, holes included).

        Parameters
        ----------
        position, rotation :
            The pose, as in :meth:`buoyancy`.
        water : Water, optional
            Still water (a ``Water`` with waves is a ``ValueError``); default ``Water()``.

        Returns
        -------
        Waterplane
            World frame; its ``axes[0]`` is the mesh's x axis projected on the plane (its z axis
            when x is within 30° of the vertical).

        Raises ``ValueError`` when the water reaches the rim of an opening closed by
        :meth:`close_openings` (its lid is no waterplane).

        Examples
        --------
        >>> ring = buoyancy.shapes.torus(1.0, 0.25, 64, 32)   # about y, the up axis
        >>> round(ring.waterplane().area / (np.pi * (1.25**2 - 0.75**2)), 3)   # an annulus
        0.998
        """
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
        """The hydrostatics at a pose: the waterplane, ``KB``, ``KG``, the metacentric radii and
        heights about both waterplane axes, and the hydrostatic stiffness in heave, roll and
        pitch.

        Parameters
        ----------
        center_of_mass : array_like, shape (3,)
            ``G``, the center of mass (of gravity), mesh frame, m.
        position, rotation :
            The pose, as in :meth:`buoyancy`.
        water : Water, optional
            Still water (waves are a ``ValueError``); default ``Water()``.
        mass : float, optional
            Kg, positive; default the mass of the water displaced at this pose (the body floats
            freely there).
        reference_point : array_like, shape (3,), optional
            The point the stiffness is taken about, mesh frame; default ``G``.
        axis : array_like, shape (3,), optional
            The body's fore-and-aft axis, mesh frame, default ``(1, 0, 0)``: roll is about it.
        keel : array_like, shape (3,), optional
            The point heights (``KB``, ``KG``) are measured from, mesh frame; default the lowest
            vertex at this pose.

        Returns
        -------
        Hydrostatics

        Examples
        --------
        A box 4 m long (x), 1 m deep (y, up), 2 m wide, floating at half its depth:

        >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))
        >>> h = box.hydrostatics(center_of_mass=(0, 0, 0))
        >>> round(h.bm_transverse, 12) == round(2.0**2 / (12 * 0.5), 12)
        True
        """
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
        """The hydrostatic stiffness at a pose, shape (3, 3): ``hydrostatics(...).stiffness``,
        rows and columns heave, roll, pitch (N/m, N/rad, N·m/m, N·m/rad), about
        ``reference_point`` (default ``G``). Arguments as in :meth:`hydrostatics`.

        Examples
        --------
        >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))
        >>> c = box.stiffness(center_of_mass=(0, 0, 0))
        >>> round(float(c[0, 0]) / (1000 * 9.81 * 8.0), 12)   # rho g A_wp
        1.0
        """
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
        """The stable pose at rest for a mass and center of mass: the draft, heel and trim where
        the water displaced weighs what the body weighs and the center of buoyancy lies on the
        vertical through the center of mass (Newton on the potential energy, with restarts from
        unstable states: a box whose upright is unstable comes to rest heeled at its angle of
        loll, a square log of middling density corner-down).

        Parameters
        ----------
        mass : float
            Kg, positive, less than the water the whole mesh displaces (else a ``ValueError``:
            the body does not float).
        center_of_mass : array_like, shape (3,)
            Mesh frame, m.
        water : Water, optional
            Still water (waves are a ``ValueError``); default ``Water()``.
        rotation : array_like, optional
            The upright orientation heel and trim are measured from (quaternion ``(x, y, z, w)``
            or matrix); default the mesh frame's own. Its yaw is kept.
        position : array_like, shape (3,), optional
            Start position: the horizontal position of the center of mass is kept from it;
            default the mesh frame at the world origin.
        axis : array_like, shape (3,), optional
            The body's longitudinal axis, mesh frame, default ``(1, 0, 0)``: heel is about it.
        keel : array_like, shape (3,), optional
            The point the draft is measured to, mesh frame; default the lowest vertex.
        tolerance : float, optional
            Relative tolerance on the residuals, in (0, 0.1); default about 3.7e-11.
        max_iterations : int, optional
            Newton iterations allowed, default 100; ``RuntimeError`` when they do not reach the
            tolerance (never a silent return).

        Returns
        -------
        Equilibrium

        Examples
        --------
        A square log 1 m across (x along it), half as dense as the water: upright is unstable,
        it floats corner-down, heeled 45°:

        >>> log = buoyancy.shapes.cube().scaled((3.0, 1.0, 1.0))
        >>> rest = log.equilibrium(mass=1500.0, center_of_mass=(0, 0, 0))
        >>> round(abs(rest.heel), 6), rest.stable
        (45.0, True)
        """
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
        """The righting-arm (GZ) curve: at each heel, the body is held at that heel about its
        longitudinal axis, its draft solved so that it displaces its mass and its trim solved too
        (by continuation from the heel before) or held, and ``GZ``, the lever between the
        verticals through the centers of buoyancy and mass, is measured.

        Parameters
        ----------
        mass, center_of_mass :
            As in :meth:`equilibrium`.
        heel_deg : array_like, shape (K,)
            Heel angles, degrees, strictly increasing, from the upright orientation (right-handed
            about ``axis``; see :class:`Equilibrium` for the side that goes down).
        axis : array_like, shape (3,), optional
            The body's longitudinal axis, mesh frame, default ``(1, 0, 0)``.
        free_trim : bool
            Solve the trim at each heel (default), or hold it at ``trim_deg`` (default 0).
        trim_deg : float, optional
            The trim held with ``free_trim=False``, degrees.
        water, rotation, position, keel, tolerance, max_iterations :
            As in :meth:`equilibrium`.

        Returns
        -------
        GzCurve

        Examples
        --------
        A box 4 m long, 1 m deep and 2 m wide, of 2 t (draft 0.25 m), its center of mass at its
        center: wall-sided while the deck edge is dry and the bilge wet (below 14°),
        ``GZ = sin φ (GM + BM tan² φ / 2)``.

        >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))
        >>> curve = box.gz_curve(2000.0, (0, 0, 0), heel_deg=[0, 4, 8, 12])
        >>> kb, bm, kg = 0.125, 2.0**2 / (12 * 0.25), 0.5
        >>> phi = np.radians(curve.heel)
        >>> wall_sided = np.sin(phi) * (kb + bm - kg + bm * np.tan(phi) ** 2 / 2)
        >>> bool(np.allclose(curve.gz, wall_sided, rtol=0, atol=1e-9))
        True
        """
    def hydrostatic_table(
        self,
        drafts: npt.ArrayLike,
        water: Water | None = None,
        rotation: npt.ArrayLike | None = None,
        axis: npt.ArrayLike | None = (1, 0, 0),
        center_of_mass: npt.ArrayLike | None = None,
        length: float | None = None,
    ) -> HydrostaticTable:
        """The hydrostatic table: the body upright at each draft (its keel, the lowest vertex, that
        far below the still level), with its displacement, centers, metacentric radii, waterplane,
        tonnes per centimetre and moment to change trim.

        Parameters
        ----------
        drafts : array_like, shape (K,)
            Drafts, m, each between 0 and the body's height.
        water : Water, optional
            Still water; default ``Water()``.
        rotation : array_like, optional
            The upright orientation, default the mesh frame's own.
        axis : array_like, shape (3,), optional
            Mesh frame, default ``(1, 0, 0)``: ``lcb``, ``lcf`` are along it, ``bm_transverse``
            is about it.
        center_of_mass : array_like, shape (3,), optional
            Mesh frame: the moment to change trim takes ``GM_L = KB + BM_L - KG`` with it, else
            ``BM_L``.
        length : float, optional
            The length of the moment to change trim, m; default the waterline length.

        Returns
        -------
        HydrostaticTable

        Examples
        --------
        >>> hull = buoyancy.shapes.wigley_hull()         # 4 m by 0.6 m, design draft 0.25 m
        >>> table = hull.hydrostatic_table([0.1, 0.25])
        >>> table.waterplane_area.round(2).tolist()      # 2/3 L B = 1.6 m² at the design draft
        [1.02, 1.6]
        """
    def transformed(self, matrix: npt.ArrayLike) -> Mesh:
        """A copy of the mesh with every vertex mapped by an affine transform, mesh frame:
        ``x' = A @ x + b`` for ``matrix = [[A, b], [0, 0, 0, 1]]``.

        Parameters
        ----------
        matrix : array_like, shape (4, 4)
            The homogeneous matrix, finite, its last row ``[0, 0, 0, 1]``. A mirroring map
            (``det A < 0``) keeps the faces wound outward.

        Returns
        -------
        Mesh
            Validated and prepared like any new mesh.

        Raises ``ValueError`` naming ``matrix`` if it is not such a matrix, ``MeshError`` if it is
        singular (it flattens the mesh).

        Examples
        --------
        >>> m = np.eye(4)
        >>> m[:3, :3] = np.diag([2.0, 0.5, 1.0])  # stretch along x, squash along y
        >>> m[:3, 3] = (0, 3, 0)                   # then move up 3 m
        >>> slab = buoyancy.shapes.cube().transformed(m)
        >>> round(slab.volume, 12), slab.centroid.round(12).tolist()
        (1.0, [0.0, 3.0, 0.0])
        """
    def scaled(self, factor: float | npt.ArrayLike) -> Mesh:
        """A copy of the mesh scaled about the origin of the mesh frame.

        Parameters
        ----------
        factor : float or array_like, shape (3,)
            One factor for all three axes, or one per axis; finite and non-zero. A negative factor
            mirrors the mesh (its faces stay wound outward).

        Returns
        -------
        Mesh

        Examples
        --------
        >>> cube = buoyancy.shapes.cube()
        >>> round(cube.scaled(2).volume, 12), round(cube.scaled((1, 2, 3)).volume, 12)
        (8.0, 6.0)
        """
    def translated(self, offset: npt.ArrayLike) -> Mesh:
        """A copy of the mesh moved by ``offset``, mesh frame, m.

        Parameters
        ----------
        offset : array_like, shape (3,)
            Finite.

        Returns
        -------
        Mesh

        Examples
        --------
        >>> buoyancy.shapes.cube().translated((0, 0.5, 0)).centroid.round(12).tolist()
        [0.0, 0.5, 0.0]
        """
    def __eq__(self, other: object, /) -> bool: ...
    def __hash__(self) -> int: ...
    def __reduce__(self) -> tuple[Callable[[_FloatArray, _IntArray], Mesh], tuple[_FloatArray, _IntArray]]: ...

@final
class Waterplane:
    """The waterplane of a body at a pose: the section of the still water plane through the body,
    world frame, SI units (m², m, m⁴). From :meth:`Mesh.waterplane`.

    Attributes
    ----------
    area : float
        Waterplane area, m².
    center_of_flotation : ndarray, shape (3,)
        Its centroid, on the water plane, m.
    axes : ndarray, shape (2, 3)
        The in-plane unit vectors ``e1``, ``e2`` (``e1 x e2`` is the water's up normal) that
        ``second_moments`` is written in: ``e1`` the body's longitudinal axis projected on the
        plane.
    second_moments : ndarray, shape (2, 2)
        ``[[∫η² dA, −∫ξη dA], [−∫ξη dA, ∫ξ² dA]]`` about the center of flotation, m⁴, with
        ``ξ, η`` the coordinates along ``e1``, ``e2``: the first diagonal entry is the
        transverse moment (about ``e1``, what rolling feels), the second the longitudinal one.
    principal_moments : ndarray, shape (2,)
        Its eigenvalues, least first, m⁴.
    principal_axes : ndarray, shape (2, 3)
        The in-plane lines through the center of flotation about which the second moments are
        ``principal_moments``, unit vectors.

    Examples
    --------
    >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))   # 4 m long, 2 m wide, y up
    >>> w = box.waterplane()
    >>> round(w.area, 12), w.second_moments.diagonal().round(12).tolist()
    (8.0, [2.666666666667, 10.666666666667])
    """

    @property
    def area(self) -> float: ...
    @property
    def center_of_flotation(self) -> _FloatArray: ...
    @property
    def axes(self) -> _FloatArray: ...
    @property
    def second_moments(self) -> _FloatArray: ...
    @property
    def principal_moments(self) -> _FloatArray: ...
    @property
    def principal_axes(self) -> _FloatArray: ...

@final
class Hydrostatics:
    """The hydrostatics of a body at a pose: the waterplane, the centers, the metacentric radii and
    heights, and the linear hydrostatic stiffness. World frame, SI units (m, m³, kg, N/m, N/rad,
    N·m/rad). From :meth:`Mesh.hydrostatics`.

    Heights are along the water's up normal ``n``; ``e1``, ``e2`` are ``waterplane.axes``
    (``e1`` the body's longitudinal axis on the plane). *Transverse* quantities belong to
    rolling (about ``e1``), *longitudinal* ones to pitching (about ``e2``).

    Attributes
    ----------
    waterplane : Waterplane
    displaced_volume : float
        ``V``, m³.
    center_of_buoyancy, center_of_gravity, keel, reference_point : ndarray, shape (3,)
        ``B``, ``G``, the keel point ``K`` (the lowest vertex unless given) and the point ``P``
        the stiffness is taken about (``G`` unless given), m.
    mass : float
        The mass of the weight's terms, kg: as given, else ``density * V``.
    kb, kg : float
        ``KB = n·(B − K)``, ``KG = n·(G − K)``, m.
    bm_transverse, bm_longitudinal : float
        ``I_T / V`` and ``I_L / V``, m.
    gm_transverse, gm_longitudinal : float
        ``KB + BM − KG``, m: positive is stable.
    bm_principal, gm_principal : ndarray, shape (2,)
        The same about the waterplane's principal axes, least first.
    stiffness : ndarray, shape (3, 3)
        The hydrostatic stiffness about ``P``, rows and columns heave (along ``n``), roll
        (about ``e1``), pitch (about ``e2``): a small displacement ``x`` changes the vertical
        force and the moments by ``−stiffness @ x``. In equilibrium about ``G``,
        ``stiffness[1, 1] = density * gravity * V * gm_transverse``.

    Examples
    --------
    >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))   # draft 0.5 m, beam 2 m
    >>> h = box.hydrostatics(center_of_mass=(0, 0, 0))
    >>> round(h.kb, 12), round(h.bm_transverse, 12), round(h.gm_transverse, 12)
    (0.25, 0.666666666667, 0.416666666667)
    """

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
    def stiffness(self) -> _FloatArray: ...

@final
class Equilibrium:
    """A floating body at rest: the pose where the displaced water's mass equals the body's and
    the center of buoyancy lies on the vertical through the center of mass, the stable one.
    World frame, SI units, angles in degrees. From :meth:`Mesh.equilibrium`.

    Attributes
    ----------
    position : ndarray, shape (3,)
        Translation of the mesh frame at rest, m.
    rotation : ndarray, shape (4,)
        Rotation of the mesh frame at rest, quaternion ``(x, y, z, w)``: pass both to
        :meth:`Mesh.buoyancy` to find the body at rest.
    draft : float
        Depth of the keel (the lowest vertex) below the surface, m.
    heel, trim : float
        Degrees from the upright orientation (the ``rotation`` argument): heel about the body's
        longitudinal axis ``e1``, right-handed, so that a positive heel puts the side towards
        ``-e2`` down (``e2 = n x e1``, ``n`` the water's up normal: for a ship modelled x
        forward and z up, ``e2`` is y, port, and a positive heel puts starboard down); trim about
        ``e2``, right-handed (positive puts the head of the longitudinal axis down).
    residual : ndarray, shape (3,)
        Relative residuals: ``(rho V - m) / m`` and the moments about ``G`` over ``m g L``.
    length : float
        The body length ``L`` the moments are scaled by, m.
    iterations, restarts : int
        Newton iterations, and restarts from an unstable state.
    stable : bool
        Whether every eigenvalue of the heave-roll-pitch stiffness (scaled as
        ``stiffness_eigenvalues``) exceeds the square root of the tolerance, 6.1e-6 by default:
        ``False`` for a neutral state (a uniform cylinder rolling about its axis).
    stiffness_eigenvalues : ndarray, shape (3,)
        Those eigenvalues, scaled to be dimensionless (a tilt's is ``GM / L``), least first.
    hydrostatics : Hydrostatics
        The hydrostatics at rest (``gm_transverse``, ...).

    Examples
    --------
    A box 4 m long, 1 m deep, 2 m wide, of 2 t, its center of mass 0.1 m below its center:

    >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))
    >>> rest = box.equilibrium(mass=2000.0, center_of_mass=(0, -0.1, 0))
    >>> round(rest.draft, 9), round(rest.heel, 6), rest.stable   # 2 t / (1000 kg/m³ · 8 m²)
    (0.25, 0.0, True)
    """

    @property
    def position(self) -> _FloatArray: ...
    @property
    def rotation(self) -> _FloatArray: ...
    @property
    def draft(self) -> float: ...
    @property
    def heel(self) -> float: ...
    @property
    def trim(self) -> float: ...
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
    """A righting-arm (GZ) curve: at each heel imposed, the draft (and trim) solved so that the
    body displaces its mass, and the lever ``GZ`` between the verticals through ``B`` and ``G``.
    SI units, angles in degrees. From :meth:`Mesh.gz_curve`.

    Attributes
    ----------
    heel, trim : ndarray, shape (K,)
        Degrees (heel as given; trim solved, or held).
    gz : ndarray, shape (K,)
        The righting arm, m: positive turns the body back towards upright from a positive heel.
    draft : ndarray, shape (K,)
        Depth of the keel below the surface, m.
    positions : ndarray, shape (K, 3)
    rotations : ndarray, shape (K, 4)
        The pose at each heel (quaternions ``(x, y, z, w)``).
    residuals : ndarray, shape (K, 3)
        Relative residuals ``(rho V - m) / m`` and the moments over ``m g L`` (the roll moment is
        the heeling moment the curve measures, not a residual).
    iterations : int
    area : float
        ``∫ GZ dφ`` over the curve, m·rad (trapezoidal rule).
    max_gz, angle_of_max_gz : float
        The greatest ``GZ`` (m) and its heel (degrees), refined by a parabola.
    angle_of_vanishing_stability : float or None
        The heel (degrees) past the upright where ``GZ`` falls back to zero, interpolated;
        ``None`` if it does not within the curve (``positive_stability`` says why).
    positive_stability : str
        Where the range of positive stability ends: ``"vanishes"`` (at
        ``angle_of_vanishing_stability``), ``"beyond"`` (``GZ`` is still positive at the last
        heel) or ``"none"`` (``GZ`` is not positive at any heel above zero).
    flooding_angle : float or None
        For a hull whose openings were closed by lids: the first heel given (degrees) at which
        the water reaches an opening; the curve stops before it. ``None`` otherwise.

    Examples
    --------
    >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))
    >>> curve = box.gz_curve(2000.0, (0, -0.1, 0), heel_deg=np.arange(0, 91, 5))
    >>> bool((curve.gz[1:] > 0).all()), abs(round(float(curve.gz[0]), 12))
    (True, 0.0)
    >>> round(curve.angle_of_max_gz), round(curve.max_gz, 2), curve.angle_of_vanishing_stability
    (40, 0.43, None)
    >>> curve.positive_stability
    'beyond'
    >>> box.gz_curve(2000.0, (0, 3.0, 0), heel_deg=np.arange(0, 91, 5)).positive_stability
    'none'
    """

    @property
    def heel(self) -> _FloatArray: ...
    @property
    def trim(self) -> _FloatArray: ...
    @property
    def gz(self) -> _FloatArray: ...
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
    def area(self) -> float: ...
    def area_up_to(self, heel_deg: float) -> float:
        """The area under the curve from its first heel to ``heel_deg`` (degrees, clamped to the
        curve), m·rad, trapezoidal with the last piece interpolated.
        """
    @property
    def max_gz(self) -> float: ...
    @property
    def angle_of_max_gz(self) -> float: ...
    @property
    def angle_of_vanishing_stability(self) -> float | None: ...
    @property
    def positive_stability(self) -> Literal["vanishes", "beyond", "none"]: ...
    @property
    def flooding_angle(self) -> float | None: ...
    def __len__(self) -> int: ...

@final
class HydrostaticTable:
    """A hydrostatic table: the body upright at each draft, one row a draft. From
    :meth:`Mesh.hydrostatic_table`.

    Each column is an attribute, a read-only array of shape (K,): ``draft`` (m),
    ``displaced_volume`` (m³), ``displacement`` (kg), ``kb``, ``bm_transverse``,
    ``bm_longitudinal``, ``km_transverse``, ``km_longitudinal`` (m), ``lcb``, ``lcf`` (m along
    the longitudinal axis from the mesh origin), ``waterplane_area`` (m²), ``waterline_length``
    (m), ``tpc`` (tonnes per centimetre immersion), ``gm_longitudinal`` and ``trim_length`` (m,
    what the moment to change trim takes) and ``mct`` (moment to change trim one centimetre,
    kg·m/cm). ``columns`` names them, ``units`` gives their units, ``as_dict()`` returns them
    all.

    Examples
    --------
    >>> box = buoyancy.shapes.cube().scaled((4.0, 1.0, 2.0))
    >>> table = box.hydrostatic_table([0.25, 0.5])
    >>> table.displacement.round(6).tolist(), table.kb.round(12).tolist()
    ([2000.0, 4000.0], [0.125, 0.25])
    """

    @property
    def columns(self) -> list[str]: ...
    @property
    def units(self) -> list[str]: ...
    def as_dict(self) -> dict[str, _FloatArray]:
        """Every column, by name."""
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
    """What :meth:`Controller.step` computed and applied for one body at its last step, world
    frame, SI units, torques about the body's world center of mass.

    Attributes
    ----------
    submerged_volume : float
        Volume under water, m³ (all the body's parts).
    center_of_buoyancy : ndarray, shape (3,)
        Center of the submerged volume, m (the volume-weighted mean of the parts' centers; the
        center of mass projected onto the surface when nothing is under water).
    center_of_mass : ndarray, shape (3,)
        The body's world center of mass, as the engine gave it, m.
    buoyancy_force, buoyancy_torque : ndarray, shape (3,)
        Buoyant force, N, and its torque about the center of mass, N·m.
    damping_force, damping_torque : ndarray, shape (3,)
        Hydrodynamic damping as applied, after the semi-implicit step, N and N·m.
    wetted_area : float
        Area of the surface under water, m².
    outcome : str
        What became of the body at the last step: ``"not_evaluated"`` (added, not stepped
        since), ``"applied"`` (the forces above are the controller's share of the body's force),
        ``"inactive"`` (not dynamic, or disabled: nothing computed, the share it had left as it
        is), ``"not_finite"`` (a pose, velocity or result was not finite: no force, the share
        taken back) or ``"unsupported"`` (the query was refused: a method that assumes a flat
        surface under waves, or the Froude–Krylov pressure under waves that are not Airy waves).
        Unless ``"applied"``, the forces are zero and the center of buoyancy is the
        center of mass.
    force, torque : ndarray, shape (3,)
        ``buoyancy_force + damping_force`` and ``buoyancy_torque + damping_torque``: what the
        controller holds on the body.

    ``FloatReport(submerged_volume=0.0, ..., outcome="not_evaluated")`` builds one (for
    unpickling and tests). It is immutable, compares by value and pickles; each array attribute
    returns a new, read-only array.

    Examples
    --------
    >>> controller = buoyancy.Controller()
    >>> report = controller.report(controller.add(buoyancy.shapes.cube()))
    >>> report.outcome, report.submerged_volume
    ('not_evaluated', 0.0)
    """

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
        """Damping force as applied (after the semi-implicit step), N, shape (3,)."""
    @property
    def damping_torque(self) -> _FloatArray:
        """Damping torque as applied, about the center of mass, N·m, shape (3,)."""
    @property
    def wetted_area(self) -> float:
        """Area of the surface under water, m²."""
    @property
    def outcome(self) -> _Outcome:
        """``"not_evaluated"``, ``"applied"``, ``"inactive"``, ``"not_finite"`` or ``"unsupported"``."""
    @property
    def force(self) -> _FloatArray:
        """The total force held on the body, ``buoyancy_force + damping_force``, N, shape (3,)."""
    @property
    def torque(self) -> _FloatArray:
        """The total torque held on the body about its center of mass, N·m, shape (3,)."""
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
    """Bodies that float, for any physics engine: the core's controller (``buoyancy-core``'s
    ``controller`` module, also behind the Rust rapier adapter and :mod:`buoyancy.rapier`).

    Each body is made of one or more closed meshes (its *parts*) placed on it. Once per step the
    engine's glue reads every body's state into NumPy arrays, one row per body, and calls
    :meth:`step`, which computes the exact buoyancy and the hydrodynamic damping of every body
    (in parallel, without the interpreter lock) and returns, per body, a force and a torque to
    **add** to what the engine holds for it, and whether to wake it.

    Parameters
    ----------
    water : Water, optional
        The water, still or with waves; default ``Water()`` (fresh, surface ``y = 0``, y up,
        ``g = 9.81``, still). Gravity on the bodies is taken as the water's: ``g`` against its
        normal, times each body's gravity scale. See *Waves* below.
    method : str
        The buoyancy method (see :data:`buoyancy.METHODS`), default ``"exact"``.
    damping : DampingCoefficients, optional
        The hydrodynamic damping, default ``DampingCoefficients()``;
        ``DampingCoefficients.off()`` for none.
    damping_resolution : int or str
        How finely the pressure drag is integrated: over a reduced copy of at most this many
        triangles (at least 64) of each mesh of more, built once per mesh when a body is added
        (vertex clustering; a mesh no reduction keeps within 10 % of its area and volume is taken
        whole), or ``"full"``: over every triangle, the model exactly. Default 384 (the bunny of
        5,002 triangles becomes 362; its drag within 5 % of the full drag's force). The buoyancy
        always takes the full mesh.

    The controller's settings apply to every body added without an override.

    Forces the application adds itself
        Engines such as rapier keep the forces added to a body until they are reset. The
        controller never asks to reset them: it remembers the force and torque it had added (its
        *share*, in ``float32`` like the engine's) and asks to add only the difference, so the
        engine holds *the application's own forces + this step's buoyancy and damping*. After
        resetting a body's forces, call :meth:`forget_applied`; :meth:`remove` returns what to
        add to take the share back off. A dynamic body whose applied force and torque are both
        exactly zero while the share is not had them reset by the engine: the share is
        forgotten, and the whole share is added again.

    Bodies the engine does not move by forces
        (``dynamic`` False: kinematic, fixed, disabled) get nothing computed and keep their
        share, so that a body made kinematic and dynamic again gets its buoyancy once.

    Sleeping bodies
        are woken (``wake``) when the controller's force or torque on them has changed by more
        than 0.1 % (of the force plus the body's weight) since they were last awake, and when
        they fell asleep out of balance (net force above 0.1 % of the weight, or net torque
        above that times the body's size), unless woken for that at the same pose before.

    Stability
        The damping is semi-implicit: the damping wrench ``W`` of the model is applied as
        ``(W − α·dt·G) / (1 + α·dt)``, with ``G`` the step's buoyancy, gravity and the
        application's own forces and ``α = √(W·M⁻¹W / q̇·M·q̇)`` the damping rate in the metric of
        the body's mass and inertia, so that light bodies reach the model's terminal velocity and
        bodies dropped fast do not overshoot. Where that one rate would throw a direction of
        motion back faster than it came (a fast spin under a strong angular damping while the
        body sinks fast), the damping is taken implicitly through its stiffness ``K = −∂W/∂q̇``
        instead, each direction at its own rate. A body whose pose, velocity or result is not
        finite gets no force (its share is taken back); its report's outcome is ``"not_finite"``.

    Waves
        The water may carry waves (``Water(waves=...)``: an :class:`AiryWave`, :class:`Waves`
        such as ``Waves.jonswap(...)``, :class:`GerstnerWaves`, a :class:`HeightGrid` or a
        callable ``f(points, t)``). The bodies then float on the surface at the controller's
        :attr:`time` (s), which every :meth:`step` advances by its ``dt``: the buoyancy is the
        pressure of the waves integrated exactly over each part's wetted surface: the
        hydrostatic ``ρ g (η − h)``, or under ``Waves`` of ``pressure="froude_krylov"`` the linear
        Froude–Krylov pressure (``method`` holds there too: ``"exact"`` and ``"exact_surface"``
        integrate exactly; under a method that assumes a flat surface a body gets no force and
        its report's outcome is ``"unsupported"``), and the damping is taken relative to the water's
        velocity at the body's center of mass: the orbital velocity of Airy waves (and
        ``Waves``); Gerstner waves, height grids and callables move no water. The waves are the
        controller's, shared by every body: a body's own ``water`` must be still.

        A callable is called once per part of each body per step, from the threads of the step,
        each call holding the interpreter lock (the rest of the step runs without it). If it
        raises (or returns other than one finite elevation per point), :meth:`step` raises that
        error and the controller is left as it was before the call: nothing applied, the time
        not advanced. A :class:`HeightGrid` is read at every evaluation: heights set between two
        steps float the bodies at the next one.

    Bodies are numbered from 0 in the order they were added; :meth:`remove` moves the last body
    into the freed number. World frame, SI units, torques about each body's center of mass;
    quaternions ``(x, y, z, w)``.

    :meth:`step` releases the interpreter lock, so other Python threads run meanwhile. A
    controller may be shared by threads: it serves one call at a time, and a call from another
    thread during a step waits for it (without the interpreter lock). A call from within its own
    step (a surface function of its water calling back into it) raises ``RuntimeError``. A
    controller does not pickle (it is one simulation's running state); its meshes and water do.

    Examples
    --------
    A 1 m cube of 500 kg at rest with its center at the water level gets its weight, 4905 N:

    >>> controller = buoyancy.Controller()                 # fresh water, surface y = 0
    >>> cube = controller.add(buoyancy.shapes.cube())      # body 0: one part, on its origin
    >>> add_force, add_torque, wake = controller.step(
    ...     1 / 60,                                        # dt, s
    ...     positions=np.zeros((1, 3)),                    # body frame → world, m
    ...     quaternions=np.array([[0.0, 0.0, 0.0, 1.0]]),  # (x, y, z, w)
    ...     centers_of_mass=np.zeros((1, 3)),              # world, m
    ...     linear_velocities=np.zeros((1, 3)),            # m/s
    ...     angular_velocities=np.zeros((1, 3)),           # rad/s
    ...     masses=np.array([500.0]),                      # kg
    ...     inverse_masses=np.full((1, 3), 1 / 500),       # 1/kg, per world axis
    ...     inverse_inertias=np.eye(3)[None] * 6 / 500,    # world, 1/(kg·m²)
    ...     gravity_scales=np.ones(1),
    ...     applied_forces=np.zeros((1, 3), np.float32),   # what the engine holds, N
    ...     applied_torques=np.zeros((1, 3), np.float32),  # N·m
    ...     dynamic=np.array([True]),
    ...     sleeping=np.array([False]),
    ... )
    >>> add_force.tolist(), wake.tolist()    # add this to the engine's force; it is awake
    ([[0.0, 4905.0, 0.0]], [False])
    >>> report = controller.report(cube)
    >>> report.outcome, report.submerged_volume
    ('applied', 0.5)

    On a swell 20 m long and 0.2 m high, the cube held at the same place feels the surface at
    the controller's time, which the step advanced by ``dt``:

    >>> swell = buoyancy.Water(waves=buoyancy.AiryWave(amplitude=0.1, wavelength=20.0))
    >>> controller = buoyancy.Controller(swell)
    >>> cube = controller.add(buoyancy.shapes.cube())
    >>> arrays = dict(positions=np.zeros((1, 3)), quaternions=[[0.0, 0.0, 0.0, 1.0]],
    ...               centers_of_mass=np.zeros((1, 3)), linear_velocities=np.zeros((1, 3)),
    ...               angular_velocities=np.zeros((1, 3)), masses=[500.0], inverse_masses=[1 / 500],
    ...               inverse_inertias=np.eye(3)[None] * 6 / 500, gravity_scales=[1.0],
    ...               applied_forces=np.zeros((1, 3), np.float32),
    ...               applied_torques=np.zeros((1, 3), np.float32), dynamic=[True], sleeping=[False])
    >>> _ = controller.step(0.5, **arrays)               # at t = 0: the crest is on the cube
    >>> controller.time                                  # s
    0.5
    >>> round(controller.report(cube).submerged_volume, 3)  # m³, 0.5 in still water
    0.599
    """

    def __new__(
        cls,
        water: Water | None = None,
        method: _MethodName | str | None = "exact",
        damping: DampingCoefficients | None = None,
        damping_resolution: _DampingResolution | None = 384,
    ) -> Controller: ...
    @property
    def water(self) -> Water:
        """The controller's water, with its waves if it has any (a body's ``water`` overrides its
        still plane, density and gravity, not the waves). Setting it keeps :attr:`time`.
        """
    @water.setter
    def water(self, water: Water, /) -> None:
        """The controller's water, with its waves if it has any (a body's ``water`` overrides its
        still plane, density and gravity, not the waves). Setting it keeps :attr:`time`.
        """
    @property
    def time(self) -> float:
        """The time of the water's waves, s: the bodies are floated on the surface at this time,
        and every :meth:`step` advances it by its ``dt``. Starts at 0; set it to any finite
        number (e.g. to restart a sea, or to match a world's clock). Kept when :attr:`water`
        changes; it also runs in still water.
        """
    @time.setter
    def time(self, time: float, /) -> None:
        """The time of the water's waves, s: the bodies are floated on the surface at this time,
        and every :meth:`step` advances it by its ``dt``. Starts at 0; set it to any finite
        number (e.g. to restart a sea, or to match a world's clock). Kept when :attr:`water`
        changes; it also runs in still water.
        """
    @property
    def method(self) -> str:
        """The controller's buoyancy method, as its canonical name (``"exact"``, …)."""
    @method.setter
    def method(self, method: _MethodName | str, /) -> None:
        """The controller's buoyancy method, as its canonical name (``"exact"``, …)."""
    @property
    def damping(self) -> DampingCoefficients:
        """The controller's damping coefficients."""
    @damping.setter
    def damping(self, damping: DampingCoefficients, /) -> None:
        """The controller's damping coefficients."""
    @property
    def damping_resolution(self) -> _DampingResolution:
        """How finely the pressure drag of the bodies without their own is integrated: the most
        triangles of the reduced copy of each mesh (an int), or ``"full"``. Setting it builds the
        reduced copies it asks for (once per mesh).
        """
    @damping_resolution.setter
    def damping_resolution(self, resolution: _DampingResolution, /) -> None:
        """How finely the pressure drag of the bodies without their own is integrated: the most
        triangles of the reduced copy of each mesh (an int), or ``"full"``. Setting it builds the
        reduced copies it asks for (once per mesh).
        """
    def body_damping_resolution(self, index: SupportsIndex) -> _DampingResolution:
        """The damping resolution body ``index`` has: its own, else the controller's (see
        :attr:`damping_resolution`). ``IndexError`` if there is no such body.
        """
    def __len__(self) -> int: ...
    def add(
        self,
        parts: _Part | Sequence[_Part],
        method: _MethodName | str | None = None,
        water: Water | None = None,
        damping: DampingCoefficients | None = None,
        damping_resolution: _DampingResolution | None = None,
    ) -> int:
        """Adds a body; returns its number (the count of bodies before it).

        Parameters
        ----------
        parts : Mesh or list
            The body's closed meshes: one :class:`Mesh`, in the body's frame, or a list of
            parts, each a ``Mesh`` in the body's frame or a tuple ``(mesh, position,
            quaternion)`` of a mesh in its own frame and the pose of that frame in the body's
            (``x_body = R @ x_mesh + position``; a quaternion ``(x, y, z, w)`` or a 3×3 rotation
            matrix). The body's frame is the one of the ``positions`` and ``quaternions`` given
            to :meth:`step`. A ``Mesh`` is shared, not copied: the bodies made of the same
            ``Mesh`` share it, and the reduced copy its damping is integrated over, built once.
            A ``Mesh`` equal to one a body is made of already (same vertices and faces) is
            replaced by that one, so that equal meshes built apart are not all kept.
        method : str, optional
            This body's method; default the controller's.
        water : Water, optional
            This body's still water (its density, level, normal and gravity); default the
            controller's. It floats on the controller's waves, if any: a water with waves here
            is a ``ValueError``.
        damping : DampingCoefficients, optional
            This body's damping; default the controller's.
        damping_resolution : int or str, optional
            How finely this body's pressure drag is integrated (see :class:`Controller`); default
            the controller's.

        Buoyancy and pressure drag add up over the parts; the angular damping is the whole
        body's (total volume, total wetted fraction), so that splitting a shape into parts does
        not change it.

        >>> controller = buoyancy.Controller()
        >>> cube = buoyancy.shapes.cube()
        >>> controller.add([(cube, (-1, 0, 0), (0, 0, 0, 1)), (cube, (1, 0, 0), (0, 0, 0, 1))])
        0
        >>> len(controller.parts(0))
        2
        """
    def replace(
        self,
        index: SupportsIndex,
        parts: _Part | Sequence[_Part],
        method: _MethodName | str | None = None,
        water: Water | None = None,
        damping: DampingCoefficients | None = None,
        damping_resolution: _DampingResolution | None = None,
    ) -> None:
        """Replaces the parts and overrides of body ``index`` (arguments as in :meth:`add`),
        keeping the books of what was applied to it. ``IndexError`` if there is no such body.
        """
    def remove(self, index: SupportsIndex) -> tuple[_Float32Array, _Float32Array]:
        """Removes body ``index`` and returns ``(force, torque)``, float32 arrays of shape (3,),
        N and N·m: what to add to the engine's force and torque to take the controller's share
        back off the body. Add it even to a body the engine does not move by forces (the share
        is there: with rapier, make the body dynamic for the time of the addition). The last
        body takes the number ``index``. ``IndexError`` if there is no such body.
        """
    def forget_applied(self, index: SupportsIndex) -> None:
        """Tells the controller that the engine's forces and torques of body ``index`` were reset,
        so that its share is zero now; the next :meth:`step` adds the whole share again.
        ``IndexError`` if there is no such body.
        """
    def rest(
        self,
        index: SupportsIndex,
        position: npt.ArrayLike,
        quaternion: npt.ArrayLike,
        center_of_mass: npt.ArrayLike,
        mass: float,
        gravity_scale: float = 1.0,
    ) -> tuple[_FloatArray, _FloatArray, Equilibrium]:
        """Where body ``index`` comes to rest in the still water (the still level under waves), for
        its mass and center of mass: the pose at which the water it displaces weighs what it
        weighs and its center of buoyancy lies on the vertical through its center of mass, the
        stable attitude (see :meth:`Mesh.equilibrium`; a body of several parts is solved as one
        mesh, its parts merged). Heel and trim are measured from the given orientation, whose yaw
        and the horizontal position of the center of mass are kept. An engine's glue sets the body
        there, at rest, before the first step.

        Parameters
        ----------
        index : int
        position : array_like, shape (3,)
            The body's position now, world frame, m.
        quaternion : array_like, shape (4,)
            Its orientation now, ``(x, y, z, w)``.
        center_of_mass : array_like, shape (3,)
            Its center of mass now, world frame, m.
        mass : float
            Kg, positive.
        gravity_scale : float
            The factor of gravity on the body (default 1): it weighs ``mass * gravity_scale``.

        Returns
        -------
        (ndarray, ndarray, Equilibrium)
            The body's position (3,) and quaternion (4,) at rest, and the equilibrium (draft,
            heel, trim, GM, ...). ``IndexError`` for no such body, ``ValueError`` for a body
            that does not float, ``RuntimeError`` if the solver does not converge.
        """
    def report(self, index: SupportsIndex) -> FloatReport:
        """What the last :meth:`step` computed and applied for body ``index``
        (a :class:`FloatReport`). ``IndexError`` if there is no such body.
        """
    def parts(self, index: SupportsIndex) -> list[tuple[Mesh, _FloatArray, _FloatArray]]:
        """The parts of body ``index``: a list of ``(mesh, position, quaternion)``, each mesh the
        object given to :meth:`add` (or the equal one the controller held already) and its pose
        in the body's frame (arrays of shape (3,) and (4,), the quaternion ``(x, y, z, w)``).
        ``IndexError`` if there is no such body.
        """
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
        """One step of ``dt`` seconds for every body: its buoyancy and damping at the state given,
        and what to add to the engine's force and torque for it.

        Every array has one row per body, in the controller's numbering (``N = len(self)``).
        Arrays of the right dtype are read in place, others are converted first. The pose,
        center of mass and velocities may be NaN or infinite: the body then gets no force and
        its report says ``"not_finite"``.

        Parameters
        ----------
        dt : float
            The step, s, finite and non-negative (the damping's semi-implicit scheme needs it).
            The bodies are evaluated on the water's waves at :attr:`time`, which then advances
            by ``dt``.
        positions : array_like, shape (N, 3)
            Origin of each body's frame (the frame its parts are placed in), world, m.
        quaternions : array_like, shape (N, 4)
            Rotation of each body's frame, ``(x, y, z, w)``; normalised (a finite one whose norm
            is off 1 by more than :data:`QUATERNION_TOLERANCE` is a ``ValueError``).
        centers_of_mass : array_like, shape (N, 3)
            World centers of mass, m: the torques are about them.
        linear_velocities : array_like, shape (N, 3)
            Velocities of the centers of mass, m/s.
        angular_velocities : array_like, shape (N, 3)
            Angular velocities, rad/s.
        masses : array_like, shape (N,)
            Masses, kg, finite and non-negative.
        inverse_masses : array_like, shape (N, 3) or (N,)
            Inverse masses, 1/kg, per world axis (zero on a locked translation axis) or one per
            body; finite and non-negative.
        inverse_inertias : array_like, shape (N, 3, 3)
            World inverse inertia tensors about the centers of mass, 1/(kg·m²) (zero rows and
            columns on locked rotation axes), finite.
        gravity_scales : array_like, shape (N,)
            The factor of gravity on each body, finite.
        applied_forces, applied_torques : array_like, shape (N, 3), float32
            The force (N) and torque (N·m, about the center of mass) the engine holds for each
            body: the application's own plus the controller's share (float64 is rounded to
            float32, what the controller keeps its share in).
        dynamic : array_like of bool, shape (N,)
            Whether the engine moves each body by forces (False: kinematic, fixed, disabled).
        sleeping : array_like of bool, shape (N,)
            Whether each body sleeps.

        Returns
        -------
        add_forces : ndarray, shape (N, 3), float32
            Force to add to what the engine holds for each body, N (zero: nothing to add).
        add_torques : ndarray, shape (N, 3), float32
            Torque to add, about the center of mass, N·m.
        wake : ndarray, shape (N,), bool
            Whether to wake each body if it sleeps: the force or torque changed by more than
            0.1 % since it was last awake, or it sleeps out of balance (then possibly with
            nothing to add: wake it whenever this is True).

        Raises
        ------
        ValueError
            Naming the argument (and the row) at fault: a shape other than the one above (with
            ``N`` the number of bodies), values that cannot be converted, a non-unit quaternion,
            negative or non-finite mass properties, a ``dt`` that is negative or not finite; a
            water surface given as a callable that returned other than one finite elevation per
            point (``water: waves: ...``).
        Exception
            Whatever a water surface given as a callable raised.

        After any error nothing was applied and :attr:`time` did not advance.
        """

def load(path: str | os.PathLike[str], close_openings: bool = False) -> Mesh:
    r"""Reads a closed triangle mesh from a file, its format chosen by the extension
    (case-insensitive): ``.obj`` (Wavefront), ``.stl`` (ASCII or binary) or ``.ply`` (ASCII or
    binary, either byte order; polygons are split into triangles).

    The vertices are taken as they are, in metres; no up axis is applied (files do not say
    one). STL from CAD and hull files are usually z up, and :class:`Water`'s default is y up:
    float such a mesh in ``Water(normal=(0, 0, 1))``.

    Parameters
    ----------
    path : str or os.PathLike
        The file.
    close_openings : bool
        Close the mesh's planar openings with lids, as :meth:`Mesh.close_openings` does (a hull
        without a deck); default ``False``, the mesh must be closed.

    Memory: the file is read whole; preparing the mesh holds about 340 bytes per triangle at its
    peak (a binary STL stores 50), so a 100 MB binary STL of 2 million triangles peaks at 680 MB,
    6.8 times its size (``python benches/mesh_memory.py``).

    Raises
    ------
    FileNotFoundError, PermissionError, IsADirectoryError, OSError
        If the file cannot be read (the ``OSError`` subclass of the operating system's reason);
        a FIFO, device or socket is not read (an ``OSError``), it could wait or run forever.
    MemoryError
        If the memory to read or prepare it cannot be had.
    ValueError
        If the extension names no format that can be read.
    MeshError
        If the file cannot be parsed (bytes that are not a mesh, in any of the formats), or its
        mesh is not closed and oriented.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "tetrahedron.obj"
    >>> _ = path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
    >>> buoyancy.load(path)
    Mesh(n_vertices=4, n_triangles=4, volume=0.166667, centroid=[0.25, 0.25, 0.25])
    """

def _unpickle(
    class_name: str, state: str
) -> Waterplane | Hydrostatics | Equilibrium | GzCurve | HydrostaticTable | BuoyancyBatch:
    """Rebuilds a pickled result (what its ``__reduce__`` returns)."""

def cube(n: int = 1) -> Mesh:
    """The unit cube [-1/2, 1/2]³, each face split in n × n squares (12·n² triangles).

    >>> buoyancy.shapes.cube(10).n_triangles
    1200
    """

def uv_sphere(radius: float = 1.0, slices: int = 32, stacks: int = 16) -> Mesh:
    """A UV sphere of the given radius (m) about the origin: `slices` segments around the y axis,
    `stacks` from pole to pole (2·slices·(stacks − 1) triangles).

    >>> buoyancy.shapes.uv_sphere(1.0, 50, 50).n_triangles
    4900
    """

def torus(major: float = 1.0, minor: float = 0.25, segments: int = 48, sides: int = 16) -> Mesh:
    """A torus about the y axis: the tube of radius `minor` (m) swept around the circle of radius
    `major` (m), `segments` around the axis and `sides` around the tube (2·segments·sides
    triangles).

    >>> round(buoyancy.shapes.torus(1.0, 0.25, 96, 32).volume, 3)  # the true torus: 2π²·R·r² = 1.234
    1.225
    """

def torus_knot(
    p: int = 2,
    q: int = 3,
    radius: float = 1.0,
    tube_radius: float = 0.2,
    segments: int = 80,
    sides: int = 11,
) -> Mesh:
    """A (p, q) torus knot of the given radius (m) swept by a tube of radius `tube_radius` (m),
    `segments` along the knot and `sides` around the tube (2·segments·sides triangles).

    >>> buoyancy.shapes.torus_knot().n_triangles
    1760
    """

def wigley_hull(
    length: float = 4.0,
    beam: float = 0.6,
    draft: float = 0.25,
    freeboard: float = 0.15,
    stations: int = 41,
    waterlines: int = 17,
) -> Mesh:
    """A closed Wigley hull, the parabolic hull form of the seakeeping benchmarks, floating upright
    at its design draft: ``length`` L, ``beam`` B and ``draft`` T (m), closed above the design
    waterline by a wall-sided topside of ``freeboard`` D (m) and a flat deck; ``stations``
    sections along the length and ``waterlines`` levels from the keel to the design waterline
    (``4·(stations − 1)·waterlines + 2·(stations − 2)`` triangles: 2,798 for the defaults).

    Frame (the frame of ``Water()``, y up): x along the length, ends at ``x = ±L/2``; keel at
    ``y = −T``, design waterline at ``y = 0``, deck at ``y = D``; z across the beam. The
    half-breadth underwater is ``(B/2)·(1 − (2x/L)²)·(1 − (y/T)²)``, and the topside carries the
    waterline straight up. Below ``y = 0`` the hull displaces ``V = 4LBT/9`` (m³) with its center
    of buoyancy at ``y = −3T/8``. With an odd number of stations, a body of mass ``ρ·V`` (the
    mesh's volume below ``y = 0``) whose center of mass is on the mesh's vertical axis through its
    centroid floats in equilibrium at the identity pose. ``ValueError`` naming the argument for a
    length that is not finite and positive, ``stations < 3`` or ``waterlines < 2``.

    >>> hull = buoyancy.shapes.wigley_hull(4.0, 0.6, 0.25, 0.15)
    >>> hull.n_triangles
    2798
    >>> below = hull.buoyancy().volume                   # m³ under water at the identity pose
    >>> round(below / (4 * 4.0 * 0.6 * 0.25 / 9), 3)    # against 4LBT/9
    0.999
    """

def cuboid(half_extents: npt.ArrayLike) -> Mesh:
    """A box of ``half_extents`` (a, b, c) (m) about the origin, edges along the axes: 12 triangles,
    volume ``8·a·b·c`` exactly.

    >>> buoyancy.shapes.cuboid((1.0, 0.5, 0.25)).volume
    1.0
    """

def ellipsoid(radii: npt.ArrayLike, slices: int = 32, stacks: int = 16) -> Mesh:
    """An ellipsoid of semi-axes ``radii`` (a, b, c) (m) along x, y, z about the origin: a UV
    sphere (``slices`` around y, ``stacks`` from pole to pole) scaled by the radii and then
    uniformly, just enough that it holds the ellipsoid's volume ``4π·a·b·c/3`` exactly.

    >>> import math
    >>> round(buoyancy.shapes.ellipsoid((1.0, 0.5, 0.5)).volume / (math.pi / 3), 12)
    1.0
    """

def cylinder(radius: float, half_height: float, segments: int = 32) -> Mesh:
    """A cylinder of ``radius`` (m) about the y axis from ``y = −half_height`` to ``half_height``:
    a prism on a regular ``segments``-gon whose area is ``π·radius²``, so that it holds the
    cylinder's volume ``2π·radius²·half_height`` exactly (4·segments triangles).

    >>> import math
    >>> round(buoyancy.shapes.cylinder(0.5, 1.0).volume / (math.pi / 2), 12)
    1.0
    """

def capsule(radius: float, half_height: float, segments: int = 32, stacks: int = 16) -> Mesh:
    """A capsule about the y axis: the cylinder of ``radius`` (m) from ``y = −half_height`` to
    ``half_height`` capped by half spheres; ``segments`` around the axis, ``stacks`` (even)
    latitude bands from pole to pole over both caps (2·segments·stacks triangles). Its rings are
    scaled just enough that it holds the capsule's volume ``π·r²·(2·half_height + 4r/3)``
    exactly.

    >>> import math
    >>> round(buoyancy.shapes.capsule(0.5, 1.0).volume / (math.pi * 0.25 * (2 + 2 / 3)), 12)
    1.0
    """

def _rapier_bodies(
    blobs: list[bytes], header: bytes
) -> tuple[npt.NDArray[np.float64], _Float32Array, npt.NDArray[np.uint8], list[bytes]] | None:
    """The state of rapier3d's rigid bodies from their ``RigidBody.to_bytes`` (buoyancy.rapier's
    bulk read): values (N, 18), wrench (N, 6), flags (N, 3) and the mass properties' bytes."""

def _world_inverse_inertias(quaternions: npt.ArrayLike, inverse_inertias: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """The world inverse inertia tensors R·I⁻¹·Rᵀ (N, 3, 3) of bodies turned by the unit
    quaternions (x, y, z, w) (N, 4) from their inverse inertias in their own frames (N, 3, 3); a
    non-finite quaternion counts as no rotation (buoyancy.rapier's glue)."""
