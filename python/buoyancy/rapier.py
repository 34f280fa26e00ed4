"""Buoyancy and hydrodynamic damping for bodies of `rapier3d <https://pypi.org/project/rapier3d/>`_,
rapier's official Python binding (``pip install 'buoyancy[rapier]'``).

:class:`FloatingBodies` holds the bodies that float, each with a :class:`buoyancy.Mesh` in the
body's local frame, and the water. Call :meth:`FloatingBodies.apply` once per step, before the
world steps (or :meth:`FloatingBodies.step`, which does both): for every registered body it
computes the exact buoyancy and the hydrodynamic damping of :meth:`buoyancy.Mesh.damping` at
the body's current pose and velocity, and applies their sum as a force and a torque about the
body's world center of mass. It mirrors the Rust adapter ``buoyancy-rapier``.

Example (a 1 m crate of density 500 kg/m³ floats half submerged)::

    import rapier3d, buoyancy
    from buoyancy.rapier import FloatingBodies

    world = rapier3d.PhysicsWorld(gravity=(0.0, -9.81, 0.0))
    crate = world.add_body(
        rapier3d.RigidBody.dynamic().translation((0.0, 1.0, 0.0)).can_sleep(False),
        [rapier3d.Collider.cuboid(0.5, 0.5, 0.5).density(500.0)],
    )
    water = FloatingBodies.for_world(world)        # fresh water, surface y = 0, y up
    water.register(crate, buoyancy.shapes.cube())  # the body's shape, in its own frame
    for _ in range(600):
        water.step(world)                          # apply(...), then world.step()
    print(world.rigid_bodies[crate].translation)   # y ≈ 0: half under water

Sleeping
    rapier puts a body to sleep once it has moved slower than its activation thresholds
    (0.4 m/s by default) for 2 s, and a floating body bobbing gently does so before it reaches
    equilibrium: asleep, it stays where it was (within a few mm for a 1 m body). Build floating
    bodies with ``can_sleep(False)``, or lower their ``activation`` thresholds, when the
    equilibrium matters. ``apply`` wakes a sleeping body only when its force changes by more
    than 0.1% (say the water moved).

Forces the application adds itself
    rapier keeps the forces and torques added to a body (``add_force``, ``add_torque``) until
    ``reset_forces`` / ``reset_torques``. ``FloatingBodies`` never resets them: it remembers the
    force and torque it added at the previous :meth:`~FloatingBodies.apply` and adds only the
    difference, so the body's ``user_force`` is always *the application's own forces + this
    step's buoyancy and damping*. A constant thrust added once stays. If the application resets
    the forces of a registered body it must then call :meth:`~FloatingBodies.forget_applied`;
    :meth:`~FloatingBodies.unregister` takes the adapter's share back off.

Stability
    The damping is explicit. So that a body dropped fast into the water cannot overshoot, the
    damping force is scaled down, when needed, so that over one step it can at most stop the
    body's velocity relative to the water (``|F| dt <= m |v|``), and the damping torque so that
    it can at most stop the rotation (``|I⁻¹ τ| dt <= |ω|``, with the body's world inertia).
    A body whose pose, velocity or result is not finite gets no force (the previous one is
    taken back) and its report says ``skipped``.

Frames and units
    The water, forces and torques are in rapier's world frame, SI units. A body's mesh is in the
    body's frame (the frame of ``RigidBody.position``, not its center of mass); the torque is
    taken about rapier's world center of mass, which need not be the mesh centroid. rapier works
    in ``float32``; buoyancy and damping are computed in ``float64``.
"""

from __future__ import annotations

import math
from collections.abc import Hashable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from ._core import DampingCoefficients, Mesh, Water

try:
    import rapier3d  # noqa: F401  (the bodies this module drives are rapier3d's)
except ImportError as error:  # pragma: no cover - exercised only without rapier3d
    raise ImportError(
        "buoyancy.rapier needs rapier's Python binding: pip install 'buoyancy[rapier]' (or pip install rapier3d)"
    ) from error

__all__ = ["FloatReport", "FloatingBodies"]

_ZERO3 = np.zeros(3)


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``np.cross`` for two 3-vectors, without its general-case overhead."""
    return np.array(
        (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]),
        dtype=np.float64,
    )


def _norm(v: np.ndarray) -> float:
    return math.hypot(float(v[0]), float(v[1]), float(v[2]))


def _vec(v: Any) -> np.ndarray:
    """A rapier ``Vec3``/``Point3`` (or any 3-sequence) as a float64 array."""
    return np.array((v[0], v[1], v[2]), dtype=np.float64)


@dataclass(frozen=True, eq=False)
class FloatReport:
    """What :meth:`FloatingBodies.apply` computed and applied for one body, world frame, SI
    units, torques about the body's world center of mass.

    Attributes
    ----------
    submerged_volume : float
        Volume under water, m³.
    center_of_buoyancy : ndarray, shape (3,)
        Center of the submerged volume, m.
    center_of_mass : ndarray, shape (3,)
        The body's world center of mass (rapier's), m.
    buoyancy_force, buoyancy_torque : ndarray, shape (3,)
        Buoyant force, N, and its torque about the center of mass, N·m.
    damping_force, damping_torque : ndarray, shape (3,)
        Damping force and torque after the stability clamp.
    wetted_area : float
        Area of the surface under water, m².
    skipped : bool
        Whether a pose, velocity or result was not finite, so that no force was applied.
    """

    submerged_volume: float = 0.0
    center_of_buoyancy: np.ndarray = field(default_factory=lambda: _ZERO3.copy())
    center_of_mass: np.ndarray = field(default_factory=lambda: _ZERO3.copy())
    buoyancy_force: np.ndarray = field(default_factory=lambda: _ZERO3.copy())
    buoyancy_torque: np.ndarray = field(default_factory=lambda: _ZERO3.copy())
    damping_force: np.ndarray = field(default_factory=lambda: _ZERO3.copy())
    damping_torque: np.ndarray = field(default_factory=lambda: _ZERO3.copy())
    wetted_area: float = 0.0
    skipped: bool = False

    @property
    def force(self) -> np.ndarray:
        """The total force applied, ``buoyancy_force + damping_force``, N."""
        return self.buoyancy_force + self.damping_force

    @property
    def torque(self) -> np.ndarray:
        """The total torque applied about the center of mass, N·m."""
        return self.buoyancy_torque + self.damping_torque


@dataclass
class _Body:
    mesh: Mesh
    water: Water | None
    method: str | None
    damping: DampingCoefficients | None
    # What the adapter has added to the body and not taken back yet, in rapier's float32.
    applied_force: np.ndarray = field(default_factory=lambda: np.zeros(3, dtype=np.float32))
    applied_torque: np.ndarray = field(default_factory=lambda: np.zeros(3, dtype=np.float32))
    report: FloatReport = field(default_factory=FloatReport)


def _water_for_gravity(gravity: npt.ArrayLike) -> Water:
    """Fresh water whose surface passes through the origin, up opposite to gravity (y up when
    gravity is zero), with ``g = |gravity|``. A gravity that is not 3 finite numbers is a
    ``ValueError`` naming it."""
    try:
        g = np.asarray(gravity, dtype=np.float64)
    except (TypeError, ValueError) as error:
        raise ValueError(f"gravity: expected 3 numbers, the gravity vector in m/s² ({error})") from None
    if g.shape != (3,):
        raise ValueError(f"gravity: expected 3 numbers, the gravity vector in m/s², got shape {g.shape}")
    if not np.isfinite(g).all():
        raise ValueError(f"gravity: has a NaN or infinite component: {tuple(g.tolist())}")
    with np.errstate(over="ignore"):
        norm = float(np.linalg.norm(g))
    if not math.isfinite(norm):
        raise ValueError(f"gravity: too large, its magnitude overflows: {tuple(g.tolist())}")
    if norm == 0.0:
        return Water(gravity=0.0)
    return Water(gravity=norm, normal=tuple(-g / norm))


def _unit_quaternion(rb: Any) -> tuple[float, float, float, float]:
    """The body's rotation as a unit quaternion (x, y, z, w), renormalised in float64."""
    q = np.array(rb.rotation.quaternion, dtype=np.float64)
    n = float(np.linalg.norm(q))
    return tuple(q / n) if n > 0 and math.isfinite(n) else tuple(q)  # type: ignore[return-value]


def _world_inverse_inertia(rb: Any) -> np.ndarray:
    """The body's inverse inertia tensor in the world frame (locked axes not taken into account)."""
    props = rb.mass_properties
    principal = _vec(props.principal_inertia)
    inverse = np.divide(1.0, principal, out=np.zeros(3), where=principal > 0)
    frame = np.asarray((rb.rotation * props.principal_inertia_local_frame).to_matrix(), dtype=np.float64)
    r = frame.reshape(3, 3)
    return (r * inverse) @ r.T


class FloatingBodies:
    """The bodies that float in one rapier world, and their water.

    Parameters
    ----------
    gravity : array_like, shape (3,)
        The world's gravity, m/s² (default ``(0, -9.81, 0)``). Unless ``water`` is given, the
        water is fresh (1000 kg/m³), its surface passes through the origin with its up normal
        opposite to gravity, and ``g = |gravity|``.
    water : Water, optional
        The world's water (overrides the one derived from ``gravity``).
    method : str
        The buoyancy method (see :data:`buoyancy.METHODS`), default ``"exact"``.
    damping : DampingCoefficients, optional
        The hydrodynamic damping, default ``DampingCoefficients()``;
        ``DampingCoefficients.off()`` for none.

    The world's settings apply to every body registered without an override. See the module
    documentation for how forces are applied.
    """

    def __init__(
        self,
        gravity: npt.ArrayLike = (0.0, -9.81, 0.0),
        *,
        water: Water | None = None,
        method: str = "exact",
        damping: DampingCoefficients | None = None,
    ) -> None:
        world_water = _water_for_gravity(gravity)  # checks the gravity even when `water` is given
        self.water = world_water if water is None else water
        self.method = method
        self.damping = DampingCoefficients() if damping is None else damping
        self._bodies: dict[Hashable, _Body] = {}

    @classmethod
    def for_world(cls, world: Any, **kwargs: Any) -> FloatingBodies:
        """A ``FloatingBodies`` for a ``rapier3d.PhysicsWorld``, with the world's gravity.

        Note that a ``PhysicsWorld()`` built without ``gravity=`` has none, and then nothing
        floats (``g = 0``).
        """
        return cls(_vec(world.gravity), **kwargs)

    # --- settings -----------------------------------------------------------------------------

    @property
    def water(self) -> Water:
        """The world's water."""
        return self._water

    @water.setter
    def water(self, water: Water) -> None:
        if not isinstance(water, Water):
            raise TypeError(f"water: expected a buoyancy.Water, got {type(water).__name__}")
        self._water = water

    @property
    def method(self) -> str:
        """The world's buoyancy method."""
        return self._method

    @method.setter
    def method(self, method: str) -> None:
        self._method = _check_method(method)

    @property
    def damping(self) -> DampingCoefficients:
        """The world's damping coefficients."""
        return self._damping

    @damping.setter
    def damping(self, damping: DampingCoefficients) -> None:
        if not isinstance(damping, DampingCoefficients):
            raise TypeError(f"damping: expected a buoyancy.DampingCoefficients, got {type(damping).__name__}")
        self._damping = damping

    # --- bodies -------------------------------------------------------------------------------

    def __len__(self) -> int:
        return len(self._bodies)

    def __contains__(self, body: object) -> bool:
        return body in self._bodies

    def __repr__(self) -> str:
        return f"FloatingBodies({len(self)} bodies, water={self._water!r}, method={self._method!r})"

    def register(
        self,
        body: Hashable,
        mesh: Mesh,
        *,
        water: Water | None = None,
        method: str | None = None,
        damping: DampingCoefficients | None = None,
    ) -> None:
        """Makes ``body`` (a ``rapier3d.RigidBodyHandle``) float with ``mesh``, a closed mesh in
        the body's local frame (the frame of ``RigidBody.position``), e.g. the vertices and
        faces of its trimesh collider. ``water``, ``method`` and ``damping`` override the
        world's for this body. Registering a body again replaces its mesh and overrides (the
        force already applied is kept track of)."""
        if not isinstance(mesh, Mesh):
            raise TypeError(f"mesh: expected a buoyancy.Mesh, got {type(mesh).__name__}")
        if water is not None and not isinstance(water, Water):
            raise TypeError(f"water: expected a buoyancy.Water, got {type(water).__name__}")
        if damping is not None and not isinstance(damping, DampingCoefficients):
            raise TypeError(f"damping: expected a buoyancy.DampingCoefficients, got {type(damping).__name__}")
        method = None if method is None else _check_method(method)
        old = self._bodies.get(body)
        entry = _Body(mesh, water, method, damping)
        if old is not None:
            entry.applied_force, entry.applied_torque = old.applied_force, old.applied_torque
        self._bodies[body] = entry

    def unregister(self, body: Hashable, bodies: Any) -> bool:
        """Stops ``body`` from floating and takes back the force and torque the adapter added to
        it (``bodies``: the ``RigidBodySet``). Returns whether it was registered."""
        entry = self._bodies.pop(body, None)
        if entry is None:
            return False
        if body in bodies:
            rb = bodies[body]
            rb.add_force(tuple(-entry.applied_force.astype(np.float64)), False)
            rb.add_torque(tuple(-entry.applied_torque.astype(np.float64)), False)
        return True

    def forget_applied(self, body: Hashable) -> None:
        """Tells the adapter that the application reset the forces and torques of ``body``
        (``reset_forces`` / ``reset_torques``), so that its own share is zero now."""
        entry = self._bodies.get(body)
        if entry is not None:
            entry.applied_force = np.zeros(3, dtype=np.float32)
            entry.applied_torque = np.zeros(3, dtype=np.float32)

    def report(self, body: Hashable) -> FloatReport | None:
        """What was computed and applied for ``body`` at the last :meth:`apply` (``None`` if it
        is not registered)."""
        entry = self._bodies.get(body)
        return None if entry is None else entry.report

    def mesh(self, body: Hashable) -> Mesh | None:
        """The mesh ``body`` floats with (``None`` if it is not registered)."""
        entry = self._bodies.get(body)
        return None if entry is None else entry.mesh

    # --- stepping -----------------------------------------------------------------------------

    def apply(self, bodies: Any, dt: float) -> None:
        """Computes buoyancy and damping for every registered body at its current pose and
        velocity, and sets the body's share of the applied force and torque to it. Call it once
        per step, before the world steps, with the step's ``dt`` (s; it only bounds the damping
        impulse). ``bodies`` is the ``rapier3d.RigidBodySet`` (``world.rigid_bodies``). Bodies
        no longer in ``bodies`` are forgotten; fixed, kinematic and disabled bodies get nothing.
        """
        dt = float(dt)
        for handle in [h for h in self._bodies if h not in bodies]:
            del self._bodies[handle]
        for handle, entry in self._bodies.items():
            rb = bodies[handle]
            report, force, torque = self._evaluate(entry, rb, dt)
            with np.errstate(over="ignore"):
                force32 = force.astype(np.float32)
                torque32 = torque.astype(np.float32)
            if not (np.isfinite(force32).all() and np.isfinite(torque32).all()):
                # Finite in float64 but beyond rapier's float32.
                com = report.center_of_mass
                report = FloatReport(center_of_buoyancy=com, center_of_mass=com, skipped=True)
                force32 = torque32 = np.zeros(3, dtype=np.float32)
            entry.report = report
            delta_force = force32 - entry.applied_force
            delta_torque = torque32 - entry.applied_torque
            if not (delta_force.any() or delta_torque.any()):
                continue
            # Wake a sleeping body only for a change that matters (say the water moved).
            scale = _norm(force) + float(rb.mass) * 9.81e-3 + 1e-30
            wake = bool(_norm(delta_force) > 1e-3 * scale or _norm(delta_torque) > 1e-3 * (_norm(torque) + scale))
            rb.add_force(tuple(delta_force.astype(np.float64)), wake)
            rb.add_torque(tuple(delta_torque.astype(np.float64)), wake)
            entry.applied_force = force32
            entry.applied_torque = torque32

    def step(self, world: Any) -> None:
        """``apply(world.rigid_bodies, world.integration_parameters.dt)``, then ``world.step()``,
        for a ``rapier3d.PhysicsWorld``."""
        self.apply(world.rigid_bodies, world.integration_parameters.dt)
        world.step()

    def _evaluate(self, entry: _Body, rb: Any, dt: float) -> tuple[FloatReport, np.ndarray, np.ndarray]:
        """The report of one body and the force and torque to apply (about its world center of
        mass); zero for non-dynamic bodies and anything non-finite."""
        com = _vec(rb.center_of_mass)
        zero = np.zeros(3)
        if not rb.is_dynamic or not rb.is_enabled:
            return FloatReport(center_of_buoyancy=com, center_of_mass=com), zero, zero
        water = self._water if entry.water is None else entry.water
        method = self._method if entry.method is None else entry.method
        coefficients = self._damping if entry.damping is None else entry.damping
        position = _vec(rb.translation)
        rotation = _unit_quaternion(rb)
        velocity = _vec(rb.linvel)
        omega = _vec(rb.angvel)
        try:
            b = entry.mesh.buoyancy(position, rotation, water, method)
            # The core takes the velocity of the mesh's own centroid (b.about, the torque point).
            centroid = b.about
            d = entry.mesh.damping(
                position,
                rotation,
                velocity + _cross(omega, centroid - com),
                omega,
                water,
                coefficients,
                about=com,
            )
        except ValueError:
            return FloatReport(center_of_buoyancy=com, center_of_mass=com, skipped=True), zero, zero
        buoyancy_torque = b.torque + _cross(centroid - com, b.force)
        damping_force, damping_torque = d.force, d.torque

        # Stability clamp of the explicit damping (see the module documentation).
        mass = float(rb.mass)
        relative_speed = _norm(velocity - coefficients.current)
        impulse = _norm(damping_force) * dt
        if mass > 0 and impulse > mass * relative_speed:
            damping_force = damping_force * (mass * relative_speed / impulse)
        spin = _norm(omega)
        spin_change = _norm(_world_inverse_inertia(rb) @ damping_torque) * dt if damping_torque.any() else 0.0
        if spin_change > spin:
            damping_torque = damping_torque * (spin / spin_change)

        force = b.force + damping_force
        torque = buoyancy_torque + damping_torque
        if not (np.isfinite(force).all() and np.isfinite(torque).all() and np.isfinite(b.center).all()):
            return FloatReport(center_of_buoyancy=com, center_of_mass=com, skipped=True), zero, zero
        report = FloatReport(
            submerged_volume=b.volume,
            center_of_buoyancy=b.center,
            center_of_mass=com,
            buoyancy_force=b.force,
            buoyancy_torque=buoyancy_torque,
            damping_force=damping_force,
            damping_torque=damping_torque,
            wetted_area=d.wetted_area,
        )
        return report, force, torque


_METHOD_PROBE: Mesh | None = None


def _check_method(method: str) -> str:
    """``method`` if the core knows it; ``ValueError`` listing the valid names otherwise."""
    global _METHOD_PROBE
    if not isinstance(method, str):
        raise TypeError(f"method: expected a str, got {type(method).__name__}")
    if _METHOD_PROBE is None:
        from ._core import cube

        _METHOD_PROBE = cube()
    _METHOD_PROBE.buoyancy(method=method)  # raises ValueError("method: ...")
    return method
