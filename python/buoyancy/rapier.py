"""Buoyancy and hydrodynamic damping for bodies of `rapier3d <https://pypi.org/project/rapier3d/>`_,
rapier's official Python binding (``pip install 'buoyancy[rapier]'``).

:class:`FloatingBodies` holds the bodies that float, each made of one or more closed
:class:`buoyancy.Mesh` es placed on the body (its colliders meshed as the Rust adapter meshes
them, :func:`collider_parts`, or meshes you give), and the water. Call :meth:`FloatingBodies.apply`
once per step, before the world steps (or :meth:`FloatingBodies.step`, which does both): it reads
every registered body's state from rapier, computes the exact buoyancy and the hydrodynamic
damping of all of them in one call to the engine-independent :class:`buoyancy.Controller` (in
Rust, in parallel, without the interpreter lock), and adds to each body the change of its force
and torque about the body's world center of mass. It is glue over the same controller as the Rust
adapter ``buoyancy-rapier``, and behaves like it.

Example (a 1 m crate of density 500 kg/m³ floats half submerged)::

    import rapier3d, buoyancy
    from buoyancy.rapier import FloatingBodies

    world = rapier3d.PhysicsWorld(gravity=(0.0, -9.81, 0.0))
    crate = world.add_body(
        rapier3d.RigidBody.dynamic().translation((0.0, 1.0, 0.0)),
        [rapier3d.Collider.cuboid(0.5, 0.5, 0.5).density(500.0)],
    )
    water = FloatingBodies.for_world(world)        # fresh water, surface y = 0, y up
    water.register(crate)                          # its collider, meshed, is its hull
    for _ in range(600):
        water.step(world)                          # apply(...), then world.step()
    print(world.rigid_bodies[crate].translation)   # y ≈ 0: half under water

Waves
    The water may carry waves, ``Water(waves=...)`` (an :class:`~buoyancy.AiryWave`,
    :class:`~buoyancy.Waves` such as ``Waves.jonswap(...)``, :class:`~buoyancy.GerstnerWaves`, a
    :class:`~buoyancy.HeightGrid` or a callable ``f(points, t)``): the bodies float on the surface
    at :attr:`FloatingBodies.time` (s), which every :meth:`~FloatingBodies.apply` advances by its
    ``dt`` (:meth:`~FloatingBodies.step`: the world's ``integration_parameters.dt``), so the sea
    runs with the world. The buoyancy is the hydrostatic pressure of the waves integrated exactly
    over the wetted surface, and the damping is relative to the water's orbital velocity (Airy
    waves). See :class:`buoyancy.Controller` for the details::

        swell = buoyancy.Water(waves=buoyancy.AiryWave(amplitude=0.1, wavelength=20.0))
        water = FloatingBodies.for_world(world, water=swell)
        water.register(buoy, buoyancy.shapes.uv_sphere(0.25))
        for _ in range(600):
            water.step(world)                      # 10 s at rapier's 60 Hz
        print(water.time)                          # ≈ 10.0 s

Sleeping
    rapier puts a body to sleep once it has moved slower than its activation thresholds for a
    while, which a floating body still bobbing by millimetres does.
    ``apply`` wakes a sleeping body when its force or torque has changed by more than 0.1 % (of
    the force plus the body's weight) since it was last awake, so that slow changes, a rising
    tide, add up; and when it fell asleep out of balance (its net force above 0.1 % of its
    weight, or its net torque above that times its size), so that it settles on, unless it was
    woken for that at the same pose before (the ground or a joint holds it).

Forces the application adds itself
    rapier keeps the forces and torques added to a body (``add_force``, ``add_torque``) until
    ``reset_forces`` / ``reset_torques``. ``FloatingBodies`` never resets them: it remembers the
    force and torque it added (its *share*, in rapier's ``float32``) and adds only the
    difference, so the body's ``user_force`` is always *the application's own forces + this
    step's buoyancy and damping*. A constant thrust added once stays. If the application resets
    the forces of a registered body it must then call :meth:`~FloatingBodies.forget_applied`
    (the share was wiped too; rapier's NaN quarantine, which zeroes both, is noticed by itself).
    :meth:`~FloatingBodies.unregister` takes the share back off, even from a body that is not
    dynamic (made dynamic for the time of the addition, since rapier ignores ``add_force`` on
    other bodies). Kinematic, fixed and disabled bodies get nothing new and keep their share, so
    that a body made kinematic and dynamic again gets its buoyancy once, not twice.

Stability
    The damping is semi-implicit: the damping wrench ``W`` of the model is applied as
    ``(W − α·dt·G) / (1 + α·dt)``, with ``G`` the step's buoyancy, gravity and the application's
    own forces (not contacts or joints) and ``α = √(W·M⁻¹W / q̇·M·q̇)`` the damping rate in the
    metric of the body's mass and inertia (locked axes left out), so that a light body reaches
    the damping model's terminal velocity and a body dropped fast into the water neither
    overshoots nor oscillates; at rest (``G = 0``) it is one factor on the whole wrench, which
    keeps its line of action. Where that one rate would throw a direction of motion back faster
    than it came (a fast spin under a strong angular damping while the body sinks fast), the
    damping is taken implicitly through its stiffness ``K = −∂W/∂q̇`` instead, each direction at
    its own rate. A body whose pose, velocity or result is not finite gets no force (its share
    is taken back) and its report's ``outcome`` is ``"not_finite"``.

Frames and units
    The water, forces and torques are in rapier's world frame, SI units. A body's meshes are in
    the body's frame (the frame of ``RigidBody.position``, not its center of mass), or placed on
    it by a ``(mesh, position, quaternion)`` part; the torque is taken about rapier's world
    center of mass, which need not be the mesh centroid. rapier works in ``float32``; buoyancy
    and damping are computed in ``float64``.
"""

from __future__ import annotations

from collections.abc import Hashable, Sequence
from typing import Any, Literal

import numpy as np
import numpy.typing as npt

from ._core import (
    Controller,
    DampingCoefficients,
    Equilibrium,
    FloatReport,
    Mesh,
    Water,
    _rapier_bodies,
    _world_inverse_inertias,
)
from ._glue import ControllerSettings, quaternion_product, rotation_matrix, water_for_gravity

try:
    import rapier3d
except ImportError as error:  # pragma: no cover - exercised only without rapier3d
    raise ImportError(
        "buoyancy.rapier needs rapier's Python binding: pip install 'buoyancy[rapier]' (or pip install rapier3d)"
    ) from error

__all__ = ["FloatReport", "FloatingBodies", "collider_parts"]

_DYNAMIC = rapier3d.RigidBodyType.DYNAMIC

# A body's state is read from its whole serialisation (see _BODY_BYTES below) or, should that
# format differ, with the getters: the cheapest way to a rapier vector's numbers is then its
# serialised float32s, read by NumPy for every body at once (the unbound methods of the classes,
# no bound method made per call). The layout is rapier3d's ``to_bytes`` format (an 8-byte
# header, then the float32s: a rotation x, y, z, w before the translation for an Isometry3),
# checked once at import against values this module builds (see _bytes_layout_ok); if it ever
# differs, the numbers are read with ``to_tuple``.
_ISOMETRY_BYTES = rapier3d.Isometry3.to_bytes
_POINT_BYTES = rapier3d.Point3.to_bytes
_VEC_BYTES = rapier3d.Vec3.to_bytes
_VEC = rapier3d.Vec3.to_tuple
_POINT = rapier3d.Point3.to_tuple
_ROTATION = rapier3d.Rotation3.to_tuple  # (x, y, z, w)
_HEADER = "V8"
# One body's position, center of mass, velocities and applied force and torque.
_RECORD = np.dtype(
    [
        ("h0", _HEADER),
        ("rotation", "<f4", 4),
        ("translation", "<f4", 3),
        ("h1", _HEADER),
        ("center_of_mass", "<f4", 3),
        ("h2", _HEADER),
        ("linvel", "<f4", 3),
        ("h3", _HEADER),
        ("angvel", "<f4", 3),
        ("h4", _HEADER),
        ("force", "<f4", 3),
        ("h5", _HEADER),
        ("torque", "<f4", 3),
    ]
)
# The scalars of one body: mass, gravity scale, dynamic and enabled, sleeping, locked axes.
_MASS, _GRAVITY_SCALE, _ACTIVE, _SLEEPING, _LOCKED = range(5)
# A force or torque that adds nothing, as a row of the controller's results reads.
_ZERO = [0.0, 0.0, 0.0]
# rapier's LockedAxes bits: translations x, y, z, then rotations x, y, z.
_LOCK_BITS = np.array([1, 2, 4, 8, 16, 32], dtype=np.int64)


def _bytes_layout_ok() -> bool:
    """Whether rapier3d's ``to_bytes`` of an Isometry3, a Point3 and four Vec3s reads back as
    :data:`_RECORD` says."""
    try:
        pose = rapier3d.Isometry3((1.5, -2.0, 3.25), (0.0, 0.6, 0.0, 0.8))
        vectors = [(0.5, -1.0, 2.0), (4.0, 5.0, -6.0), (7.0, 0.25, 8.0), (-9.0, 10.0, 11.5)]
        blob = _ISOMETRY_BYTES(pose) + _POINT_BYTES(rapier3d.Point3(-0.5, 0.75, 1.0))
        blob += b"".join(_VEC_BYTES(rapier3d.Vec3(*v)) for v in vectors)
        record = np.frombuffer(blob, dtype=_RECORD)
        headers = {record[0][name].tobytes() for name in ("h0", "h1", "h2", "h3", "h4", "h5")}
        return (
            len(record) == 1
            and len(headers) == 1
            and record["rotation"][0].tolist() == [0.0, 0.6000000238418579, 0.0, 0.800000011920929]
            and record["translation"][0].tolist() == [1.5, -2.0, 3.25]
            and record["center_of_mass"][0].tolist() == [-0.5, 0.75, 1.0]
            and [record[name][0].tolist() for name in ("linvel", "angvel", "force", "torque")]
            == [list(v) for v in vectors]
        )
    except Exception:  # pragma: no cover - a rapier3d whose format differs
        return False


_BYTES_LAYOUT_OK = _bytes_layout_ok()

# Cheaper still: a whole body in one call, ``RigidBody.to_bytes`` (rapier's serialised
# ``RigidBody``, after the same 8-byte header), every body's state then read from those bytes by
# the bindings in one call (_rapier_bodies: the fields at fixed offsets from the start and the
# end, as the getters return them). Checked once at import against the getters, bit for bit, on
# bodies this module builds (see _body_layout_ok), and at every read for the header and flags of
# every body; if either check fails, the state is read with the getters as above.
_BODY_BYTES = rapier3d.RigidBody.to_bytes
_BODY_HEADER = _ISOMETRY_BYTES(rapier3d.Isometry3.identity())[:8]
# The state's names, as _states takes them.
_RECORD_NAMES = ("rotation", "translation", "center_of_mass", "linvel", "angvel", "force", "torque")

_State = tuple[dict[str, np.ndarray], dict[str, np.ndarray], list[bytes]]


def _parse_bodies(blobs: list[bytes]) -> _State | None:
    """The bodies' state from their serialisations (:data:`_BODY_BYTES`), as the getters read
    it (see :meth:`FloatingBodies._read`), and the keys of their mass properties; None if a
    serialisation does not look as expected."""
    parsed = _rapier_bodies(blobs, _BODY_HEADER)
    if parsed is None:
        return None
    values, wrench, flags, keys = parsed
    record = {
        "rotation": values[:, 0:4],
        "translation": values[:, 4:7],
        "center_of_mass": values[:, 7:10],
        "linvel": values[:, 10:13],
        "angvel": values[:, 13:16],
        "force": wrench[:, 0:3],
        "torque": wrench[:, 3:6],
    }
    scalars = {
        "mass": values[:, 16],
        "gravity_scale": values[:, 17],
        "active": flags[:, 0].view(np.bool_),
        "sleeping": flags[:, 1].view(np.bool_),
        "locked": flags[:, 2],
    }
    return record, scalars, keys


def _local_mass_properties(rb: Any) -> tuple[float, np.ndarray]:
    """A body's inverse mass (1/kg) and inverse inertia tensor in its own frame (3, 3),
    1/(kg·m²), as rapier computes them (zero for a zero mass or principal inertia)."""
    props = rb.mass_properties
    inverse_mass = float(props.inv_mass)
    principal = np.array(_VEC(props.principal_inertia), dtype=np.float64)
    inverse = np.divide(1.0, principal, out=np.zeros(3), where=principal != 0)
    frame = np.asarray(props.principal_inertia_local_frame.to_matrix(), dtype=np.float64).reshape(3, 3)
    return inverse_mass, (frame * inverse) @ frame.T


def _swap_remove(values: list[Any], i: int) -> None:
    """Removes item ``i``, the last item taking its place."""
    last = values.pop()
    if i < len(values):
        values[i] = last


class _Bodies:
    """The registered bodies' handles in the controller's numbering, rapier's live views of them,
    and their mass properties, read again only when they change."""

    def __init__(self) -> None:
        self.handles: list[Hashable] = []
        self.index: dict[Hashable, int] = {}
        # rapier's views of the bodies (``bodies[handle]``, which follow the body), for the set
        # `owner`; None when they must be looked up again.
        self.views: list[Any] | None = None
        self.owner: Any = None
        # rapier's serialised mass properties of each body when last read, and what was read of
        # them: the inverse mass and the inverse inertia in the body's frame.
        self.keys: list[bytes | None] = []
        self.inverse_masses: list[float] = []
        self.local_inverse_inertias: list[np.ndarray] = []
        # The two lists above as arrays, (N,) and (N, 3, 3); None when they must be made again.
        self.arrays: tuple[np.ndarray, np.ndarray] | None = None

    def add(self, handle: Hashable) -> None:
        self.index[handle] = len(self.handles)
        self.handles.append(handle)
        self.keys.append(None)
        self.inverse_masses.append(0.0)
        self.local_inverse_inertias.append(np.zeros((3, 3)))
        self.views = self.arrays = None

    def remove(self, i: int) -> None:
        """Forgets body ``i``; the last body takes its number (as in the controller)."""
        del self.index[self.handles[i]]
        for values in (self.handles, self.keys, self.inverse_masses, self.local_inverse_inertias):
            _swap_remove(values, i)
        if i < len(self.handles):
            self.index[self.handles[i]] = i
        self.views = self.arrays = None

    def look_up(self, bodies: Any) -> list[Any]:
        """rapier's views of the bodies in the set ``bodies`` (``InvalidHandle`` if one is not
        there)."""
        if self.views is None or self.owner is not bodies:
            self.views = [bodies[h] for h in self.handles]
            self.owner = bodies
        return self.views

    def refresh(self, keys: list[bytes | None]) -> None:
        """Reads again the mass properties of the bodies whose key changed."""
        views = self.views
        assert views is not None
        for i, (old, new) in enumerate(zip(self.keys, keys, strict=True)):
            if old != new:
                self.inverse_masses[i], self.local_inverse_inertias[i] = _local_mass_properties(views[i])
        self.keys = keys
        self.arrays = None

    def mass_arrays(self) -> tuple[np.ndarray, np.ndarray]:
        """The inverse masses (N,) and the inverse inertias in the bodies' frames (N, 3, 3)."""
        if self.arrays is None:
            inertias = np.array(self.local_inverse_inertias, dtype=np.float64).reshape(-1, 3, 3)
            self.arrays = (np.array(self.inverse_masses, dtype=np.float64), inertias)
        return self.arrays


class FloatingBodies(ControllerSettings):
    """The bodies that float in one rapier world, and their water.

    Parameters
    ----------
    gravity : array_like, shape (3,)
        The world's gravity, m/s² (default ``(0, -9.81, 0)``). Unless ``water`` is given, the
        water is fresh (1000 kg/m³), its surface passes through the origin with its up normal
        opposite to gravity, and ``g = |gravity|``.
    water : Water, optional
        The world's water, still or with waves (overrides the one derived from ``gravity``).
        Gravity on the bodies is taken as the water's: ``g`` against its normal, times the body's
        gravity scale. Its waves run on :attr:`time`.
    method : str
        The buoyancy method (see :data:`buoyancy.METHODS`), default ``"exact"``.
    damping : DampingCoefficients, optional
        The hydrodynamic damping, default ``DampingCoefficients()``;
        ``DampingCoefficients.off()`` for none.
    damping_resolution : int or str
        How finely the pressure drag is integrated: over a reduced copy of at most this many
        triangles of each mesh of more (built once per mesh), or ``"full"`` (every triangle, the
        model exactly). Default 384; see :class:`buoyancy.Controller`.

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
        damping_resolution: int | Literal["full"] = 384,
    ) -> None:
        world_water = water_for_gravity(gravity)  # checks the gravity even when `water` is given
        self._controller = Controller(
            world_water if water is None else water, method, damping, damping_resolution=damping_resolution
        )
        self._bodies = _Bodies()
        self._world: Any = None
        self._collider_meshes: dict[tuple[Any, ...], Mesh] = {}

    @classmethod
    def for_world(cls, world: Any, **kwargs: Any) -> FloatingBodies:
        """A ``FloatingBodies`` for a ``rapier3d.PhysicsWorld``, with the world's gravity; its
        :meth:`register` reads a body's colliders from ``world`` when no mesh is given.

        Note that a ``PhysicsWorld()`` built without ``gravity=`` has none, and then nothing
        floats (``g = 0``).
        """
        floating = cls(_VEC(world.gravity), **kwargs)
        floating._world = world
        return floating

    # --- settings -----------------------------------------------------------------------------

    @property
    def time(self) -> float:
        """The time of the water's waves, s: the bodies are floated on the surface at this time,
        and every :meth:`apply` advances it by its ``dt``. Starts at 0; settable (a finite
        number)."""
        return self._controller.time

    @time.setter
    def time(self, time: float) -> None:
        self._controller.time = time

    # --- bodies -------------------------------------------------------------------------------

    def __len__(self) -> int:
        return len(self._bodies.handles)

    def __contains__(self, body: object) -> bool:
        return body in self._bodies.index

    def __repr__(self) -> str:
        waves = "" if self.water.waves is None else f", time={self.time:g}"
        return f"FloatingBodies({len(self)} bodies, water={self.water!r}, method={self.method!r}{waves})"

    def register(
        self,
        body: Hashable,
        mesh: Mesh | Sequence[Mesh | tuple[Mesh, npt.ArrayLike, npt.ArrayLike]] | None = None,
        *,
        world: Any = None,
        colliders: Sequence[Any] | None = None,
        subdivisions: int = 32,
        water: Water | None = None,
        method: str | None = None,
        damping: DampingCoefficients | None = None,
        damping_resolution: int | Literal["full"] | None = None,
    ) -> None:
        """Makes ``body`` (a ``rapier3d.RigidBodyHandle``) float.

        Without ``mesh``, the body floats with its colliders, meshed as the Rust adapter meshes
        them (see :func:`collider_parts`): every collider attached to it, or only the handles in
        ``colliders``, read from ``world`` (the ``rapier3d.PhysicsWorld`` holding the body; by
        default the one given to :meth:`for_world`); ``subdivisions`` segments around balls,
        cylinders, capsules and cones. ``mesh`` instead is a closed mesh in the body's local frame
        (the frame of ``RigidBody.position``); or a list of parts, each such a mesh or a tuple
        ``(mesh, position, quaternion)`` of a mesh in its own frame placed on the body
        (``x_body = R @ x_mesh + position``, the quaternion ``(x, y, z, w)``). ``water``,
        ``method``, ``damping`` and ``damping_resolution`` override the world's for this body
        (``water``: a still one, its density, level and normal; the body floats on the world's
        waves, if any). Registering a body again replaces its meshes and overrides (the force
        already applied is kept track of).

        ``ValueError`` for a body or collider the world does not hold, a collider attached to
        another body, or a shape that cannot float (a half-space, height field, …: give
        ``mesh``); nothing is registered then."""
        if mesh is None:
            world = self._world if world is None else world
            if world is None:
                raise TypeError(
                    "world: register(body) without a mesh reads the body's colliders from its world: pass "
                    "world=the rapier3d.PhysicsWorld, or build FloatingBodies.for_world(world)"
                )
            mesh = collider_parts(world, body, colliders, subdivisions=subdivisions, cache=self._collider_meshes)
        elif not isinstance(mesh, (Mesh, list, tuple)):
            raise TypeError(
                f"mesh: expected a buoyancy.Mesh, or a list of meshes and (mesh, position, quaternion) "
                f"parts, got {type(mesh).__name__}"
            )
        i = self._bodies.index.get(body)
        if i is None:
            self._controller.add(
                mesh, method=method, water=water, damping=damping, damping_resolution=damping_resolution
            )
            self._bodies.add(body)
        else:
            self._controller.replace(
                i, mesh, method=method, water=water, damping=damping, damping_resolution=damping_resolution
            )

    def unregister(self, body: Hashable, bodies: Any) -> bool:
        """Stops ``body`` from floating and takes back the force and torque the adapter added to
        it (``bodies``: the ``RigidBodySet``), even if it is not dynamic now (it is made dynamic
        for the time of the addition, its type and sleep left as they were). Returns whether it
        was registered."""
        i = self._bodies.index.get(body)
        if i is None:
            return False
        force, torque = self._controller.remove(i)
        self._bodies.remove(i)
        if (force.any() or torque.any()) and body in bodies:
            rb = bodies[body]
            body_type, sleeping = rb.body_type, rb.is_sleeping
            if body_type != _DYNAMIC:
                rb.body_type = _DYNAMIC  # rapier3d's setter wakes the body
            rb.add_force(force.tolist(), False)
            rb.add_torque(torque.tolist(), False)
            if body_type != _DYNAMIC:
                rb.body_type = body_type
                if sleeping and not rb.is_sleeping:
                    rb.sleep()
        return True

    def forget_applied(self, body: Hashable) -> None:
        """Tells the adapter that the application reset the forces and torques of ``body``
        (``reset_forces`` / ``reset_torques``), so that its share is zero now: the next
        :meth:`apply` adds the whole share again."""
        i = self._bodies.index.get(body)
        if i is not None:
            self._controller.forget_applied(i)

    def report(self, body: Hashable) -> FloatReport | None:
        """What was computed and applied for ``body`` at the last :meth:`apply` (``None`` if it
        is not registered); its ``outcome`` is ``"not_evaluated"`` before the first."""
        i = self._bodies.index.get(body)
        return None if i is None else self._controller.report(i)

    def parts(self, body: Hashable) -> list[tuple[Mesh, np.ndarray, np.ndarray]] | None:
        """The parts ``body`` floats with, each ``(mesh, position, quaternion)`` (its pose in the
        body's frame); ``None`` if it is not registered."""
        i = self._bodies.index.get(body)
        return None if i is None else self._controller.parts(i)

    def mesh(self, body: Hashable) -> Mesh | None:
        """The mesh ``body`` floats with (``None`` if it is not registered); for a body of
        several parts, see :meth:`parts` (a ``ValueError`` here)."""
        parts = self.parts(body)
        if parts is None:
            return None
        if len(parts) != 1:
            raise ValueError(f"body: floats with {len(parts)} parts, not one mesh: see FloatingBodies.parts")
        return parts[0][0]

    # --- stepping -----------------------------------------------------------------------------

    def apply(self, bodies: Any, dt: float) -> None:
        """Computes buoyancy and damping for every registered body at its current pose and
        velocity, and sets the body's share of the applied force and torque to it. Call it once
        per step, before the world steps, with the step's ``dt`` (s), which the damping's
        semi-implicit scheme needs and by which :attr:`time` then advances (the bodies are
        evaluated on the waves at the time before the step). ``bodies`` is the ``rapier3d.RigidBodySet``
        (``world.rigid_bodies``). Bodies no longer in ``bodies`` are forgotten; fixed, kinematic
        and disabled bodies get nothing new (their share is left as it is)."""
        if not self._bodies.handles:
            return
        try:
            views, record, scalars = self._read(bodies)
        except rapier3d.InvalidHandle:
            self._forget_removed(bodies)
            if not self._bodies.handles:
                return
            views, record, scalars = self._read(bodies)
        add_forces, add_torques, wake = self._controller.step(float(dt), *self._states(record, scalars))
        zero = _ZERO
        for rb, force, torque, wake_up in zip(
            views, add_forces.tolist(), add_torques.tolist(), wake.tolist(), strict=True
        ):
            # rapier ignores a zero addition (and does not wake the body for it). A row with a
            # NaN is not zero; one of zeros of either sign is.
            if force != zero:
                rb.add_force(force, wake_up)
            if torque != zero:
                rb.add_torque(torque, wake_up)
            if wake_up and force == zero and torque == zero:
                rb.wake_up()  # asleep out of balance: woken with nothing to add

    def place_at_rest(self, body: Hashable, bodies: Any, colliders: Any) -> Equilibrium:
        """Places ``body`` where it floats at rest in the still water (the still level under
        waves), for its mass and center of mass: the pose at which the water it displaces weighs
        what it weighs and its center of buoyancy lies on the vertical through its center of
        mass, the stable attitude (:meth:`Controller.rest`, the Rust adapter's
        ``place_at_rest``). Heel and trim are measured from its current orientation, whose yaw
        and the horizontal position of its center of mass are kept; its velocities are set to
        zero. Call it after :meth:`register` and before the first step, so that a spawned boat
        does not bob. ``bodies`` and ``colliders`` are the world's sets (``world.rigid_bodies``,
        ``world.colliders``): the body's mass properties are computed from its colliders first
        (rapier computes them at the next step).

        Returns the :class:`~buoyancy.Equilibrium` (draft, heel, trim, GM, ...). ``ValueError``
        for a body that is not registered or does not float; ``RuntimeError`` if the solver
        does not converge."""
        i = self._bodies.index.get(body)
        if i is None:
            raise ValueError(f"body: {body!r} is not registered (register it first)")
        rb = bodies[body]
        rb.recompute_mass_properties_from_colliders(colliders)
        position, quaternion, equilibrium = self._controller.rest(
            i, _VEC(rb.translation), _ROTATION(rb.rotation), _POINT(rb.center_of_mass), rb.mass, rb.gravity_scale
        )
        rb.translation = tuple(position.tolist())
        rb.rotation = tuple(quaternion.tolist())
        rb.linvel = (0.0, 0.0, 0.0)
        rb.angvel = (0.0, 0.0, 0.0)
        rb.wake_up()
        return equilibrium

    def step(self, world: Any) -> None:
        """``apply(world.rigid_bodies, world.integration_parameters.dt)``, then ``world.step()``,
        for a ``rapier3d.PhysicsWorld``: the waves' :attr:`time` advances with the world's (set
        ``world.integration_parameters.dt`` to change the step)."""
        self.apply(world.rigid_bodies, world.integration_parameters.dt)
        world.step()

    def _forget_removed(self, bodies: Any) -> None:
        """Forgets the bodies no longer in ``bodies`` (nothing to take back from them)."""
        for handle in [h for h in self._bodies.handles if h not in bodies]:
            i = self._bodies.index[handle]
            self._controller.remove(i)
            self._bodies.remove(i)

    def _read(self, bodies: Any) -> tuple[list[Any], dict[str, np.ndarray], dict[str, np.ndarray]]:
        """rapier's views of the registered bodies, their state and their scalars (see
        :func:`_columns`); reads again the mass properties that changed."""
        registered = self._bodies
        views = registered.look_up(bodies)
        state = _parse_bodies(list(map(_BODY_BYTES, views))) if _BODY_LAYOUT_OK else None
        if state is None:  # a rapier3d whose serialisation differs
            state = _read_vectors(views) if _BYTES_LAYOUT_OK else _read_tuples(views)
        record, scalars, keys = state
        if keys != registered.keys:
            registered.refresh(keys)
        return views, record, scalars

    def _states(self, record: dict[str, np.ndarray], scalars: dict[str, np.ndarray]) -> tuple[np.ndarray, ...]:
        """The arguments of :meth:`Controller.step` after ``dt``, from the state :meth:`_read`
        read: with rapier's effective inverse masses and world inverse inertias (zero on locked
        axes) from the mass properties in each body's frame."""
        registered = self._bodies
        quaternions = np.asarray(record["rotation"], dtype=np.float64)
        inverse_masses, local_inverse_inertias = registered.mass_arrays()
        # R·I⁻¹·Rᵀ for every body in one call; a body whose rotation is not finite gets no force
        # (the controller says so), and its inertia stays finite.
        inverse_inertias = _world_inverse_inertias(quaternions, local_inverse_inertias)
        locked = scalars["locked"]
        if locked.any():
            free = ((locked.astype(np.int64)[:, None] & _LOCK_BITS) == 0).astype(np.float64)
            inverse_masses = inverse_masses[:, None] * free[:, :3]
            inverse_inertias *= free[:, None, 3:] * free[:, 3:, None]
        return (
            record["translation"],
            quaternions,
            record["center_of_mass"],
            record["linvel"],
            record["angvel"],
            scalars["mass"],
            inverse_masses,
            inverse_inertias,
            scalars["gravity_scale"],
            record["force"],
            record["torque"],
            scalars["active"],
            scalars["sleeping"],
        )


def collider_parts(
    world: Any,
    body: Any,
    colliders: Sequence[Any] | None = None,
    *,
    subdivisions: int = 32,
    cache: dict[tuple[Any, ...], Mesh] | None = None,
) -> list[tuple[Mesh, np.ndarray, np.ndarray]]:
    """The colliders of ``body`` (a ``rapier3d.RigidBodyHandle`` of ``world``, a
    ``rapier3d.PhysicsWorld``) as closed meshes placed on the body: ``(mesh, position,
    quaternion (x, y, z, w))`` parts in the body's frame, one per shape (a compound's shapes each
    placed by its pose), every collider attached to the body or only those in ``colliders``
    (repeats count once).

    The meshes are rapier's own tessellations (``to_trimesh``, parry's, as the Rust adapter
    ``buoyancy-rapier`` uses them), welded (:meth:`buoyancy.Mesh.welded`): cuboids and convex
    polyhedra exactly, trimeshes as they are, balls, capsules, cylinders and cones with
    ``subdivisions`` segments around their axis (half as many, even, from pole to pole). Those
    are inscribed in the round shapes, so they hold a little less than the collider's volume
    (``subdivisions = 32``: 1.3 % less for a ball). ``cache`` (a dict kept between calls) shares
    one mesh between equal shapes.

    ``ValueError`` for a body or collider the world does not hold, a collider attached to
    another body, no collider at all, or a shape that cannot float (a half-space, a height
    field, a round or voxel shape, …: give ``register`` a mesh).

    >>> import rapier3d
    >>> world = rapier3d.PhysicsWorld(gravity=(0.0, -9.81, 0.0))
    >>> handle = world.add_body(rapier3d.RigidBody.dynamic(), [rapier3d.Collider.cuboid(1.0, 0.5, 0.25)])
    >>> ((mesh, position, quaternion),) = collider_parts(world, handle)
    >>> mesh.n_triangles, mesh.volume
    (12, 1.0)
    """
    if isinstance(subdivisions, bool) or not isinstance(subdivisions, (int, np.integer)) or subdivisions < 0:
        raise ValueError(f"subdivisions: expected a non-negative integer, got {subdivisions!r}")
    cache = {} if cache is None else cache
    try:
        rigid_body = world.rigid_bodies[body]
    except (KeyError, IndexError, TypeError, ValueError, AttributeError) as error:
        raise ValueError(f"body: {body!r} is not a body of this world ({error})") from error
    handles = list(rigid_body.colliders) if colliders is None else list(dict.fromkeys(colliders))
    parts: list[tuple[Mesh, np.ndarray, np.ndarray]] = []
    for handle in handles:
        try:
            collider = world.colliders[handle]
        except (KeyError, IndexError, TypeError, ValueError) as error:
            raise ValueError(f"colliders: {handle!r} is not a collider of this world ({error})") from error
        if collider.parent != body:
            raise ValueError(f"colliders: {handle!r} is attached to {collider.parent!r}, not to the body {body!r}")
        pose = collider.position_wrt_parent
        _append_shape_parts(
            handle, collider.shape, _VEC(pose.translation), _ROTATION(pose.rotation), subdivisions, cache, parts
        )
    if not parts:
        raise ValueError(f"body: {body!r} has no collider to float with; give register a mesh")
    return parts


def _append_shape_parts(
    handle: Any,
    shape: Any,
    position: Sequence[float],
    quaternion: Sequence[float],
    subdivisions: int,
    cache: dict[tuple[Any, ...], Mesh],
    parts: list[tuple[Mesh, np.ndarray, np.ndarray]],
) -> None:
    """Appends the meshes of ``shape``, placed on the body at ``position``/``quaternion``."""
    kind = shape.shape_type
    around = max(subdivisions, 3)
    pole_to_pole = max(subdivisions // 2, 2)
    pole_to_pole += pole_to_pole % 2  # even: a capsule's two hemispheres have whole rings
    types = rapier3d.ShapeType
    if kind == types.COMPOUND:
        for sub_pose, sub_shape in shape.as_compound().shapes():
            sub_position = _VEC(sub_pose.translation)
            sub_quaternion = _ROTATION(sub_pose.rotation)
            # The body ← collider ← sub-shape chain: p_body = q ⊗ (q_sub ⊗ p ⊗ q_sub⁻¹ + t_sub) ⊗ q⁻¹ + t.
            rotation = rotation_matrix(quaternion)
            _append_shape_parts(
                handle,
                sub_shape,
                tuple(rotation @ np.asarray(sub_position) + np.asarray(position)),
                tuple(quaternion_product(quaternion, sub_quaternion)),
                subdivisions,
                cache,
                parts,
            )
        return
    if kind == types.TRIMESH:
        trimesh = shape.as_trimesh()
        key: tuple[Any, ...] = (
            "trimesh",
            np.asarray(trimesh.vertices).tobytes(),
            np.asarray(trimesh.indices).tobytes(),
        )
        tessellation = None
    else:
        args: tuple[int, ...] = ()
        if kind == types.CUBOID:
            typed = shape.as_cuboid()
            key = ("cuboid", _VEC(typed.half_extents))
        elif kind == types.BALL:
            typed, args = shape.as_ball(), (around, pole_to_pole)
            key = ("ball", typed.radius, *args)
        elif kind == types.CAPSULE:
            typed, args = shape.as_capsule(), (around, pole_to_pole)
            key = ("capsule", _POINT(typed.a), _POINT(typed.b), typed.radius, *args)
        elif kind == types.CYLINDER:
            typed, args = shape.as_cylinder(), (around,)
            key = ("cylinder", typed.half_height, typed.radius, *args)
        elif kind == types.CONE:
            typed, args = shape.as_cone(), (around,)
            key = ("cone", typed.half_height, typed.radius, *args)
        elif kind == types.CONVEX_POLYHEDRON:
            typed, args = shape.as_convex_polyhedron(), ()
            key = ("convex", np.asarray(typed.points).tobytes())
        else:
            raise ValueError(
                f"colliders: {handle!r} is a {str(kind).rsplit('.', 1)[-1].lower()} shape, which cannot float; "
                "give register a closed buoyancy.Mesh in the body's frame (mesh=...)"
            )
        tessellation = (typed, args)
    mesh = cache.get(key)
    if mesh is None:
        try:
            if tessellation is None:
                mesh = Mesh(np.asarray(trimesh.vertices, dtype=np.float64), np.asarray(trimesh.indices))
            else:
                vertices, faces = tessellation[0].to_trimesh(*tessellation[1])
                mesh = Mesh.welded(np.asarray(vertices, dtype=np.float64), faces)
        except ValueError as error:
            raise ValueError(f"colliders: {handle!r}: {error}") from error
        cache[key] = mesh
    parts.append((mesh, np.array(position, dtype=np.float64), np.array(quaternion, dtype=np.float64)))


def _scalars(rb: Any) -> tuple[float, float, bool, bool, int]:
    """A body's scalars (see the column numbers above), read with the getters."""
    return rb.mass, rb.gravity_scale, rb.is_dynamic and rb.is_enabled, rb.is_sleeping, rb.locked_axes.bits


def _columns(record: np.ndarray, scalars: list[tuple[float, float, bool, bool, int]], keys: list[bytes]) -> _State:
    """The state as :meth:`FloatingBodies._read` returns it, from :data:`_RECORD` s and rows of
    scalars: the record's fields by name (rapier's float32s, in float32 or float64 arrays; the
    rotation ``(x, y, z, w)``); the masses and gravity scales (float64), whether each body is
    dynamic and enabled and whether it sleeps (bool) and its locked axes (rapier's bits) by name;
    and the mass properties' keys."""
    table = np.array(scalars, dtype=np.float64).reshape(-1, 5)
    columns = {
        "mass": table[:, _MASS],
        "gravity_scale": table[:, _GRAVITY_SCALE],
        "active": table[:, _ACTIVE] != 0,
        "sleeping": table[:, _SLEEPING] != 0,
        "locked": table[:, _LOCKED],
    }
    return {name: record[name] for name in _RECORD_NAMES}, columns, keys


def _read_vectors(views: list[Any]) -> _State:
    """The state of :func:`_parse_bodies`, read with the getters and each vector's ``to_bytes``."""
    isometry, point, vec = _ISOMETRY_BYTES, _POINT_BYTES, _VEC_BYTES
    chunks: list[bytes] = []
    scalars = []
    keys = []
    for rb in views:
        chunks += (
            isometry(rb.position),
            point(rb.center_of_mass),
            vec(rb.linvel),
            vec(rb.angvel),
            vec(rb.user_force),
            vec(rb.user_torque),
        )
        scalars.append(_scalars(rb))
        keys.append(rb.mass_properties.to_bytes())
    return _columns(np.frombuffer(b"".join(chunks), dtype=_RECORD), scalars, keys)


def _read_tuples(views: list[Any]) -> _State:
    """The state of :func:`_parse_bodies`, read with the getters and ``to_tuple``."""
    rows = []
    scalars = []
    keys = []
    for rb in views:
        rows.append(
            (
                *_ROTATION(rb.rotation),
                *_VEC(rb.translation),
                *_POINT(rb.center_of_mass),
                *_VEC(rb.linvel),
                *_VEC(rb.angvel),
                *_VEC(rb.user_force),
                *_VEC(rb.user_torque),
            )
        )
        scalars.append(_scalars(rb))
        keys.append(rb.mass_properties.to_bytes())
    return _columns(_records(np.array(rows, dtype=np.float32)), scalars, keys)


def _records(table: np.ndarray) -> np.ndarray:
    """:data:`_RECORD` s from rows of float32: rotation (x, y, z, w), translation, center of mass,
    velocities, force, torque."""
    record = np.zeros(len(table), dtype=_RECORD)
    start = 0
    for name in ("rotation", "translation", "center_of_mass", "linvel", "angvel", "force", "torque"):
        width = record.dtype[name].shape[0]
        record[name] = table[:, start : start + width]
        start += width
    return record


def _body_layout_ok() -> bool:
    """Whether :func:`_parse_bodies` reads bit for bit what the getters read (their vectors'
    ``to_bytes``, as :func:`_read_vectors`), on bodies of every kind this module tells apart:
    moving, tilted (32 rotations), with forces and locked axes; of three colliders with an
    additional mass (a longer serialisation); kinematic and fixed with forces kept (read as zero);
    disabled; sleeping. Each alone (serialisations of one length) and all together."""
    if not _BYTES_LAYOUT_OK:
        return False
    try:
        world = rapier3d.PhysicsWorld(gravity=(0.0, -9.81, 0.0))
        views = []
        for k in range(32):
            builder = rapier3d.RigidBody.dynamic().translation((1.5 + k, -2.0, 3.25))
            builder = builder.rotation((0.1 + 0.05 * k, -0.3 + 0.07 * k, 0.3 - 0.11 * k))
            builder = builder.linvel((0.5, -1.0, 2.0 + k)).angvel((4.0, 5.0, -6.0 - k)).gravity_scale(0.75 + k)
            colliders = [
                rapier3d.Collider.cuboid(0.5, 0.25 + 0.1 * k, 0.125).density(500.0 + k).translation((0.1 * j, 0.2, 0.3))
                for j in range(3 if k == 1 else 1)
            ]
            rb = world.rigid_bodies[world.add_body(builder, colliders)]
            rb.add_force((7.0, 0.25, 8.0 + k), False)
            rb.add_torque((-9.0, 10.0 + k, 11.5), False)
            if k == 0:
                rb.locked_axes = rapier3d.LockedAxes.ROTATION_LOCKED_X | rapier3d.LockedAxes.TRANSLATION_LOCKED_Z
            elif k == 1:
                rb.set_additional_mass(3.0, False)
            rb.recompute_mass_properties_from_colliders(world.colliders)
            if k == 2:
                rb.body_type = rapier3d.RigidBodyType.KINEMATIC_VELOCITY_BASED
            elif k == 3:
                rb.body_type = rapier3d.RigidBodyType.FIXED
            elif k == 4:
                rb.is_enabled = False
            elif k == 5:
                rb.sleep()
            views.append(rb)
        blobs = [_BODY_BYTES(rb) for rb in views]
        active = [rb.is_dynamic and rb.is_enabled for rb in views[:6]]
        if len({len(blob) for blob in blobs}) < 2 or active != [True, True, False, False, False, True]:
            return False  # not the bodies the check needs

        def same(a: dict[str, np.ndarray], b: dict[str, np.ndarray]) -> bool:
            return a.keys() == b.keys() and all(
                a[name].dtype.kind == b[name].dtype.kind
                and np.asarray(a[name], dtype=np.float64).tobytes() == np.asarray(b[name], dtype=np.float64).tobytes()
                for name in a
            )

        for part in [slice(None), *(slice(i, i + 1) for i in range(len(blobs)))]:
            parsed, expected = _parse_bodies(blobs[part]), _read_vectors(views[part])
            if (
                parsed is None
                or not same(parsed[0], expected[0])
                or not same(parsed[1], {**expected[1], "locked": expected[1]["locked"].astype(np.uint8)})
                or parsed[2] != [key[8:] for key in expected[2]]  # the keys without the header
            ):
                return False
        return True
    except Exception:  # pragma: no cover - a rapier3d whose format differs
        return False


_BODY_LAYOUT_OK = _body_layout_ok()
