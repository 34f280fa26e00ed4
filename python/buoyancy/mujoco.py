"""Buoyancy and hydrodynamic damping for bodies of `MuJoCo <https://mujoco.org>`_
(``pip install 'buoyancy[mujoco]'``).

MuJoCo has no free surface: its fluid model is a uniform medium around ellipsoids. This module
makes the bodies of a MuJoCo model float on water, still or with waves, with the exact buoyancy
of their geoms (or of a mesh you give) and the hydrodynamic damping, computed by the same
engine-independent :class:`buoyancy.Controller` as :mod:`buoyancy.rapier` and the Rust adapter.

Two lines make a model float::

    import mujoco
    from buoyancy.mujoco import FloatingBodies

    model = mujoco.MjModel.from_xml_string('''
    <mujoco>
      <worldbody>
        <body name="raft" pos="0 0 0.5">
          <freejoint/>
          <geom type="box" size="0.5 0.5 0.2" density="500"/>
        </body>
      </worldbody>
    </mujoco>''')
    data = mujoco.MjData(model)
    water = FloatingBodies.for_model(model)   # fresh water, surface z = 0, against the gravity
    water.register("raft")                    # its geoms become its hull
    for _ in range(5000):                     # 10 s
        water.step(data)                      # mj_step1, the buoyancy into xfrc_applied, mj_step2
    print(data.body("raft").xpos)             # z ≈ 0: half under water

What each geom becomes
    Without ``mesh=``, a body floats with its own geoms, each placed where MuJoCo has it in the
    body's frame (``geom_pos``, ``geom_quat``): a box, sphere, ellipsoid, cylinder or capsule
    becomes a closed mesh whose volume is the solid's exactly (the mass MuJoCo gives it by
    density and the water it displaces agree: :func:`buoyancy.shapes.cuboid`,
    :func:`~buoyancy.shapes.ellipsoid`, :func:`~buoyancy.shapes.cylinder`,
    :func:`~buoyancy.shapes.capsule`); a mesh geom becomes its mesh asset as MuJoCo holds it
    (moved onto the mesh's inertia frame, which ``geom_pos``/``geom_quat`` compensate). When a
    body has geoms that collide (``contype`` or ``conaffinity`` not zero), only those count:
    visual geoms (both zero) are left out. Planes, height fields and SDF geoms are refused.

Geoms that overlap
    Parts that overlap would count their common volume twice. ``register`` looks for a common
    volume between every two of the body's geoms (on a grid of points in the overlap of their
    bounding boxes) and refuses the body if it finds one, saying which geoms. Give such a body
    one closed hull: ``register(body, mesh=buoyancy.load("hull.stl"))`` or a :class:`~buoyancy.Mesh`
    in the body's frame. Geoms that only touch (a box on a box) are fine.

Mass, frames and units
    The body's mass, center of mass and inertia are MuJoCo's (``body_mass``, ``xipos``,
    ``body_inertia``, an ``<inertial>`` element included). World frame, z up in MuJoCo's
    convention: the water's up is opposite to ``model.opt.gravity``; SI units. Meshes given to
    ``register`` are in the body's frame (``data.xpos``, ``data.xquat``). The force goes into
    ``data.xfrc_applied`` (N, at the body's center of mass, and N·m, world frame), as MuJoCo
    defines it.

Joints
    Free bodies float, and so do bodies on hinge, slide or ball joints (a flap on a sea-bed
    hinge, a buoy on a vertical slide): the buoyancy and damping are the same wrench, and
    MuJoCo's constraints take what the joints hold. The damping's semi-implicit step measures
    a body's motion by its mass as seen through its joints (the Cartesian compliance
    ``J·M⁻¹·Jᵀ`` at its center of mass, its linear diagonal and angular block); a lone free
    body's is its own mass and inertia.

Forces the application adds itself
    ``data.xfrc_applied`` may hold the application's own forces: :meth:`FloatingBodies.apply`
    adds the change of its own share and takes its previous share off, so that a thrust the
    application wrote once stays. An application that zeroes ``xfrc_applied`` (as after
    ``mj_resetData``) wipes the share too; that is noticed when both force and torque of a
    body are exactly zero, or say it with :meth:`~FloatingBodies.forget_applied`.

Stepping
    :meth:`FloatingBodies.step` is one MuJoCo step done right: ``mj_step1`` (positions and
    velocities), :meth:`~FloatingBodies.apply` with those kinematics, ``mj_step2``. Calling
    ``apply`` and then ``mj_step`` would use the kinematics of the previous step.
    :meth:`~FloatingBodies.apply` alone uses the kinematics ``data`` holds (valid after
    ``mj_step1``, ``mj_forward`` or ``mj_step``; a fresh ``MjData`` has its kinematics computed
    first). The waves run on ``data.time``. Bodies are evaluated every step, asleep in MuJoCo's
    island sleeping or not.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import Any, Literal

import numpy as np
import numpy.typing as npt

from . import shapes
from ._core import Controller, DampingCoefficients, Equilibrium, FloatReport, Mesh, Water, load
from ._glue import ControllerSettings, quaternion_product, rotation_matrix, water_for_gravity

try:
    import mujoco
except ImportError as error:  # pragma: no cover - exercised only without mujoco
    raise ImportError("buoyancy.mujoco needs MuJoCo: pip install 'buoyancy[mujoco]' (or pip install mujoco)") from error

__all__ = ["FloatReport", "FloatingBodies", "geom_parts"]

_GEOM = mujoco.mjtGeom
_REFUSED = {
    int(_GEOM.mjGEOM_PLANE): "a plane",
    int(_GEOM.mjGEOM_HFIELD): "a height field",
    int(_GEOM.mjGEOM_SDF): "an SDF",
}
_FREE = int(mujoco.mjtJoint.mjJNT_FREE)
# Our cylinders and capsules lie along y; MuJoCo's along z: a quarter turn about x, (x, y, z, w).
_Y_TO_Z = np.array([np.sqrt(0.5), 0.0, 0.0, np.sqrt(0.5)])
# Tessellation of the round geoms: segments around, rings pole to pole.
_SEGMENTS, _STACKS = 32, 16
# The overlap search: points per axis in the overlap of two parts' bounding boxes.
_OVERLAP_GRID = 12


def _xyzw(wxyz: npt.ArrayLike) -> np.ndarray:
    """MuJoCo's quaternion ``(w, x, y, z)`` as ``(x, y, z, w)``."""
    q = np.asarray(wxyz, dtype=np.float64)
    return q[..., [1, 2, 3, 0]]


def _name(model: Any, kind: Any, index: int) -> str:
    """The name of object ``index`` of ``kind`` in ``model``, or ``#index`` if it has none."""
    name = mujoco.mj_id2name(model, kind, index)
    return name if name else f"#{index}"


def _geom_label(model: Any, geom: int) -> str:
    return f"geom {_name(model, mujoco.mjtObj.mjOBJ_GEOM, geom)!r}"


def _geom_mesh(model: Any, geom: int, cache: dict[tuple[Any, ...], Mesh]) -> tuple[Mesh, np.ndarray]:
    """The closed mesh of one geom in its own frame, and the quaternion ``(x, y, z, w)`` that
    turns our shape's frame into the geom's (our cylinders and capsules lie along y)."""
    kind = int(model.geom_type[geom])
    size = tuple(float(s) for s in model.geom_size[geom])
    turn = np.array([0.0, 0.0, 0.0, 1.0])
    if kind in _REFUSED:
        raise ValueError(
            f"body: {_geom_label(model, geom)} is {_REFUSED[kind]}, which encloses no volume; "
            "give the body a closed hull with register(body, mesh=...)"
        )
    if kind == int(_GEOM.mjGEOM_MESH):
        mesh_id = int(model.geom_dataid[geom])
        key: tuple[Any, ...] = ("mesh", mesh_id)
    else:
        key = (kind, size)
    if kind in (int(_GEOM.mjGEOM_CYLINDER), int(_GEOM.mjGEOM_CAPSULE)):
        turn = _Y_TO_Z
    if key in cache:
        return cache[key], turn
    if kind == int(_GEOM.mjGEOM_BOX):
        mesh = shapes.cuboid(size)
    elif kind == int(_GEOM.mjGEOM_SPHERE):
        mesh = shapes.ellipsoid((size[0],) * 3, _SEGMENTS, _STACKS)
    elif kind == int(_GEOM.mjGEOM_ELLIPSOID):
        mesh = shapes.ellipsoid(size, _SEGMENTS, _STACKS)
    elif kind == int(_GEOM.mjGEOM_CYLINDER):
        mesh = shapes.cylinder(size[0], size[1], _SEGMENTS)
    elif kind == int(_GEOM.mjGEOM_CAPSULE):
        mesh = shapes.capsule(size[0], size[1], _SEGMENTS, _STACKS)
    elif kind == int(_GEOM.mjGEOM_MESH):
        start, count = int(model.mesh_vertadr[mesh_id]), int(model.mesh_vertnum[mesh_id])
        face_start, face_count = int(model.mesh_faceadr[mesh_id]), int(model.mesh_facenum[mesh_id])
        vertices = np.asarray(model.mesh_vert[start : start + count], dtype=np.float64)
        faces = np.asarray(model.mesh_face[face_start : face_start + face_count], dtype=np.int64)
        try:
            mesh = Mesh(vertices, faces)
        except ValueError as error:
            asset = _name(model, mujoco.mjtObj.mjOBJ_MESH, mesh_id)
            raise ValueError(
                f"body: {_geom_label(model, geom)} (mesh asset {asset!r}) is not a closed mesh: {error}. "
                "Give the body a closed hull with register(body, mesh=...)"
            ) from None
    else:  # pragma: no cover - a geom type newer than this module
        raise ValueError(f"body: {_geom_label(model, geom)} has geom type {kind}, which buoyancy.mujoco does not know")
    cache[key] = mesh
    return mesh, turn


def geom_parts(model: Any, body: int | str) -> list[tuple[Mesh, np.ndarray, np.ndarray]]:
    """The parts a body floats with when registered without ``mesh``: one ``(mesh, position,
    quaternion (x, y, z, w))`` per geom that counts (see the module's *What each geom
    becomes*), placed in the body's frame. ``ValueError`` for a body with no such geom, a
    plane, height field or SDF geom, or geoms that overlap."""
    index = _body_id(model, body)
    return _geom_parts(model, index, {})


def _geom_parts(model: Any, body: int, cache: dict[tuple[Any, ...], Mesh]) -> list[tuple[Mesh, np.ndarray, np.ndarray]]:
    start, count = int(model.body_geomadr[body]), int(model.body_geomnum[body])
    geoms = list(range(start, start + count)) if start >= 0 else []
    colliding = [g for g in geoms if model.geom_contype[g] or model.geom_conaffinity[g]]
    geoms = colliding or geoms
    label = _name(model, mujoco.mjtObj.mjOBJ_BODY, body)
    if not geoms:
        raise ValueError(
            f"body: {label!r} has no geom to float with; give it one, or a closed hull with register(body, mesh=...)"
        )
    parts = []
    for g in geoms:
        mesh, turn = _geom_mesh(model, g, cache)
        quaternion = quaternion_product(_xyzw(model.geom_quat[g]), turn)
        parts.append((mesh, np.array(model.geom_pos[g], dtype=np.float64), quaternion))
    _refuse_overlaps(model, label, geoms, parts)
    return parts


def _winding_numbers(points: np.ndarray, corners: np.ndarray) -> np.ndarray:
    """The generalised winding number of a closed mesh (triangles ``corners``, (F, 3, 3)) at
    each point (P, 3): 1 inside, 0 outside (the solid angles of the triangles over 4π)."""
    result = np.empty(len(points))
    for lo in range(0, len(points), 64):
        rel = corners[None, :, :, :] - points[lo : lo + 64, None, None, :]  # (p, F, 3, 3)
        a, b, c = rel[:, :, 0], rel[:, :, 1], rel[:, :, 2]
        la, lb, lc = (np.linalg.norm(v, axis=-1) for v in (a, b, c))
        numerator = np.einsum("pfi,pfi->pf", a, np.cross(b, c))
        denominator = (
            la * lb * lc
            + np.einsum("pfi,pfi->pf", a, b) * lc
            + np.einsum("pfi,pfi->pf", b, c) * la
            + np.einsum("pfi,pfi->pf", c, a) * lb
        )
        result[lo : lo + 64] = np.arctan2(numerator, denominator).sum(axis=1) / (2.0 * np.pi)
    return result


def _refuse_overlaps(model: Any, body: str, geoms: list[int], parts: list[tuple[Mesh, np.ndarray, np.ndarray]]) -> None:
    """``ValueError`` if two parts share a volume: a point of a grid in the overlap of their
    bounding boxes inside both."""
    if len(parts) < 2:
        return
    corners = []
    for mesh, position, quaternion in parts:
        vertices = mesh.vertices @ rotation_matrix(quaternion).T + position
        corners.append(vertices[mesh.faces])
    boxes = [(c.reshape(-1, 3).min(axis=0), c.reshape(-1, 3).max(axis=0)) for c in corners]
    n = _OVERLAP_GRID
    steps = (np.arange(n) + 0.5) / n
    for i in range(len(parts)):
        for j in range(i + 1, len(parts)):
            lo = np.maximum(boxes[i][0], boxes[j][0])
            hi = np.minimum(boxes[i][1], boxes[j][1])
            scale = max(float(np.max(boxes[i][1] - boxes[i][0])), float(np.max(boxes[j][1] - boxes[j][0])))
            if np.any(hi - lo <= 1e-9 * scale):
                continue  # bounding boxes apart, or touching
            axes = [lo[k] + steps * (hi[k] - lo[k]) for k in range(3)]
            grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
            inside = _winding_numbers(grid, corners[i]) > 0.5
            if not inside.any():
                continue
            both = inside.copy()
            both[inside] = _winding_numbers(grid[inside], corners[j]) > 0.5
            if both.any():
                shared = both.mean() * float(np.prod(hi - lo))
                smaller = min(parts[i][0].volume, parts[j][0].volume)
                raise ValueError(
                    f"body: {body!r}: {_geom_label(model, geoms[i])} and {_geom_label(model, geoms[j])} overlap "
                    f"(about {shared:.3g} m³ in common, {100 * shared / smaller:.2g} % of the smaller), which would "
                    "count twice. Give the body one closed hull: register(body, mesh=buoyancy.load('hull.stl')) "
                    "or a buoyancy.Mesh in the body's frame"
                )


def _body_id(model: Any, body: int | str) -> int:
    """The id of ``body`` (a name or an id) in ``model``; ``ValueError`` if there is none."""
    if isinstance(body, str):
        index = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, body)
        if index < 0:
            names = [_name(model, mujoco.mjtObj.mjOBJ_BODY, b) for b in range(1, min(model.nbody, 11))]
            more = ", ..." if model.nbody > 11 else ""
            raise ValueError(f"body: no body named {body!r} in the model (its bodies: {', '.join(names)}{more})")
        return int(index)
    if isinstance(body, (bool, np.bool_)) or not isinstance(body, (int, np.integer)):
        raise TypeError(f"body: expected a body's name (str) or id (int), got {type(body).__name__}")
    if not 0 <= body < model.nbody:
        raise ValueError(f"body: id {body} is not in the model, which has bodies 0 to {model.nbody - 1}")
    return int(body)


def _floating_body_id(model: Any, body: int | str) -> int:
    """``_body_id``, refusing the world, bodies fixed to it and mocap bodies (nothing moves them)."""
    index = _body_id(model, body)
    label = _name(model, mujoco.mjtObj.mjOBJ_BODY, index)
    if index == 0:
        raise ValueError("body: the world body (id 0) cannot float; register a body that has a joint")
    if model.body_mocapid[index] >= 0:
        raise ValueError(f"body: {label!r} is a mocap body, which the application moves, not forces")
    if model.body_weldid[index] == 0:
        raise ValueError(
            f"body: {label!r} is fixed to the world (no joint between it and the world body), so no force moves it; "
            "give it a joint (<freejoint/>, a hinge or a slide)"
        )
    return index


def _parts_of(mesh: Any) -> Any:
    """``mesh`` as the controller takes it: a path is loaded."""
    if isinstance(mesh, (str, os.PathLike)):
        return load(mesh)
    if not isinstance(mesh, (Mesh, list, tuple)):
        raise TypeError(
            f"mesh: expected a buoyancy.Mesh, a path to a mesh file, or a list of meshes and "
            f"(mesh, position, quaternion) parts, got {type(mesh).__name__}"
        )
    return mesh


class FloatingBodies(ControllerSettings):
    """The bodies that float in one MuJoCo model, and their water.

    Parameters
    ----------
    model : mujoco.MjModel
        The model. Unless ``water`` is given, the water is fresh (1000 kg/m³), its surface
        passes through the origin with its up normal opposite to ``model.opt.gravity`` (z up
        without gravity), and ``g = |gravity|``.
    water : Water, optional
        The water, still or with waves (their time is ``data.time``). Gravity on the bodies is
        taken as the water's, times ``1 − body_gravcomp`` (zero with gravity disabled).
    method : str
        The buoyancy method (see :data:`buoyancy.METHODS`), default ``"exact"``.
    damping : DampingCoefficients, optional
        The hydrodynamic damping, default ``DampingCoefficients()``;
        ``DampingCoefficients.off()`` for none.
    damping_resolution : int or str
        The most triangles of each mesh's reduced copy for the pressure drag, or ``"full"``;
        default 384 (see :class:`buoyancy.Controller`).

    Example::

        water = FloatingBodies.for_model(model, water=buoyancy.Water(
            normal=(0, 0, 1), waves=buoyancy.Waves.jonswap(1.0, 6.0)))
        water.register("buoy")
        while data.time < 60.0:
            water.step(data)
    """

    def __init__(
        self,
        model: Any,
        *,
        water: Water | None = None,
        method: str = "exact",
        damping: DampingCoefficients | None = None,
        damping_resolution: int | Literal["full"] = 384,
    ) -> None:
        if not isinstance(model, mujoco.MjModel):
            raise TypeError(f"model: expected a mujoco.MjModel, got {type(model).__name__}")
        model_water = water_for_gravity(model.opt.gravity, up_without_gravity=(0.0, 0.0, 1.0))
        self._model = model
        self._controller = Controller(
            model_water if water is None else water, method, damping, damping_resolution=damping_resolution
        )
        self._ids: list[int] = []
        self._index: dict[int, int] = {}
        self._meshes: dict[tuple[Any, ...], Mesh] = {}
        self._arrays: _Arrays | None = None

    @classmethod
    def for_model(cls, model: Any, **kwargs: Any) -> FloatingBodies:
        """``FloatingBodies(model, **kwargs)``: the bodies that float in ``model``."""
        return cls(model, **kwargs)

    # --- settings -----------------------------------------------------------------------------

    @property
    def model(self) -> Any:
        """The ``mujoco.MjModel``."""
        return self._model

    # --- bodies -------------------------------------------------------------------------------

    def __len__(self) -> int:
        return len(self._ids)

    def __contains__(self, body: object) -> bool:
        try:
            return _body_id(self._model, body) in self._index  # type: ignore[arg-type]
        except (TypeError, ValueError):
            return False

    def __repr__(self) -> str:
        return f"FloatingBodies({len(self)} bodies, water={self.water!r}, method={self.method!r})"

    def register(
        self,
        body: int | str,
        mesh: Mesh | str | os.PathLike[str] | Sequence[Mesh | tuple[Mesh, npt.ArrayLike, npt.ArrayLike]] | None = None,
        *,
        water: Water | None = None,
        method: str | None = None,
        damping: DampingCoefficients | None = None,
        damping_resolution: int | Literal["full"] | None = None,
    ) -> None:
        """Makes ``body`` (its name or id) float.

        Without ``mesh``, the body floats with its geoms (see :func:`geom_parts`). ``mesh`` is a
        closed :class:`~buoyancy.Mesh` in the body's frame (the frame of ``data.xpos`` and
        ``data.xquat``), a path to a mesh file (:func:`buoyancy.load`), or a list of parts, each
        such a mesh or a ``(mesh, position, quaternion (x, y, z, w))`` placed on the body.
        ``water`` (a still one: its density, level and normal; the body floats on the model's
        waves, if any), ``method``, ``damping`` and ``damping_resolution`` override the model's
        for this body. Registering a body again replaces its meshes and overrides.

        ``ValueError`` for an unknown body, the world body, a body fixed to the world or a mocap
        body, a plane, height field or SDF geom, an open mesh asset, or geoms that overlap;
        nothing is registered then.
        """
        index = _floating_body_id(self._model, body)
        parts = _geom_parts(self._model, index, self._meshes) if mesh is None else _parts_of(mesh)
        i = self._index.get(index)
        if i is None:
            self._controller.add(
                parts, method=method, water=water, damping=damping, damping_resolution=damping_resolution
            )
            self._index[index] = len(self._ids)
            self._ids.append(index)
        else:
            self._controller.replace(
                i, parts, method=method, water=water, damping=damping, damping_resolution=damping_resolution
            )
        self._arrays = None

    def unregister(self, body: int | str, data: Any) -> bool:
        """Stops ``body`` from floating and takes the force and torque the adapter added to it
        back off ``data.xfrc_applied``. Returns whether it was registered."""
        index = _body_id(self._model, body)
        i = self._index.get(index)
        if i is None:
            return False
        self._check_data(data)
        force, torque = self._controller.remove(i)
        data.xfrc_applied[index, :3] += force
        data.xfrc_applied[index, 3:] += torque
        last = self._ids.pop()
        del self._index[index]
        if i < len(self._ids):
            self._ids[i] = last
            self._index[last] = i
        self._arrays = None
        return True

    def forget_applied(self, body: int | str) -> None:
        """Tells the adapter that the application wiped the ``xfrc_applied`` row of ``body``:
        its share is zero now, and the next :meth:`apply` adds it whole."""
        i = self._index.get(_body_id(self._model, body))
        if i is not None:
            self._controller.forget_applied(i)

    def report(self, body: int | str) -> FloatReport | None:
        """What was computed and applied for ``body`` at the last :meth:`apply` (``None`` if it
        is not registered); its ``outcome`` is ``"not_evaluated"`` before the first."""
        i = self._index.get(_body_id(self._model, body))
        return None if i is None else self._controller.report(i)

    def parts(self, body: int | str) -> list[tuple[Mesh, np.ndarray, np.ndarray]] | None:
        """The parts ``body`` floats with, each ``(mesh, position, quaternion (x, y, z, w))`` in
        the body's frame; ``None`` if it is not registered."""
        i = self._index.get(_body_id(self._model, body))
        return None if i is None else self._controller.parts(i)

    # --- stepping -----------------------------------------------------------------------------

    def step(self, data: Any) -> None:
        """One MuJoCo step with the water: ``mj_step1``, :meth:`apply`, ``mj_step2``."""
        self._check_data(data)
        mujoco.mj_step1(self._model, data)
        self.apply(data)
        mujoco.mj_step2(self._model, data)

    def apply(self, data: Any) -> None:
        """Computes buoyancy and damping for every registered body from the kinematics ``data``
        holds, on the waves at ``data.time``, and makes the adapter's share of
        ``data.xfrc_applied`` that wrench (the application's own forces there stay).

        ``ValueError``, with ``data`` left untouched, if ``data`` is not of this model or a
        registered body's pose or velocity is not finite."""
        self._check_data(data)
        if not self._ids:
            return
        model = self._model
        if not data.xquat[0].any():  # a fresh MjData: no kinematics yet
            mujoco.mj_fwdPosition(model, data)
            mujoco.mj_fwdVelocity(model, data)
        arrays = self._arrays
        if arrays is None:
            arrays = self._arrays = _Arrays(model, self._ids)
        ids = arrays.ids
        positions = data.xpos[ids]
        quaternions = data.xquat[ids][:, [1, 2, 3, 0]]
        centers = data.xipos[ids]
        cvel = data.cvel[ids]
        angular = cvel[:, :3]
        linear = cvel[:, 3:] + np.cross(angular, centers - data.subtree_com[arrays.roots])
        state = np.concatenate((positions, quaternions, centers, linear, angular), axis=1)
        if not np.isfinite(state).all():
            bad = ids[~np.isfinite(state).all(axis=1)][0]
            raise ValueError(
                f"data: body {_name(model, mujoco.mjtObj.mjOBJ_BODY, int(bad))!r} has a pose or velocity that is not "
                "finite (qpos or qvel holds NaN or inf); nothing was applied"
            )
        inverse_masses, inverse_inertias = arrays.inverse_mass_properties(data)
        applied = data.xfrc_applied[ids]
        gravity_scales = arrays.gravity_scales
        if model.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_GRAVITY:
            gravity_scales = np.zeros_like(gravity_scales)  # the water's g still weighs the water
        self._controller.time = float(data.time)
        add_forces, add_torques, _ = self._controller.step(
            float(model.opt.timestep),
            positions,
            quaternions,
            centers,
            linear,
            angular,
            arrays.masses,
            inverse_masses,
            inverse_inertias,
            gravity_scales,
            applied[:, :3],
            applied[:, 3:],
            arrays.dynamic,
            arrays.sleeping,
        )
        data.xfrc_applied[ids, :3] += add_forces
        data.xfrc_applied[ids, 3:] += add_torques

    def place_at_rest(self, body: int | str, data: Any) -> Equilibrium:
        """Places a free ``body`` where it floats at rest in the still water (the still level
        under waves), for its mass and center of mass (:meth:`Controller.rest`): its free
        joint's ``qpos`` set to that pose (heel and trim measured from its current orientation,
        whose yaw and the horizontal position of its center of mass are kept), its ``qvel`` to
        zero, then ``mj_forward``. Call it after :meth:`register` and before stepping, so that a
        spawned boat does not bob.

        Returns the :class:`~buoyancy.Equilibrium`. ``ValueError`` for a body that is not
        registered, not on a free joint of its own, or does not float; ``RuntimeError`` if the
        solver does not converge."""
        model = self._model
        index = _body_id(model, body)
        label = _name(model, mujoco.mjtObj.mjOBJ_BODY, index)
        i = self._index.get(index)
        if i is None:
            raise ValueError(f"body: {label!r} is not registered (register it first)")
        joint = int(model.body_jntadr[index])
        if (
            model.body_jntnum[index] != 1
            or model.jnt_type[joint] != _FREE
            or model.body_parentid[index] != 0
            or not _lone(model, index)
        ):
            raise ValueError(
                f"body: {label!r} is not a lone free body (one <freejoint/>, a child of the world, no bodies on it); "
                "place_at_rest sets a free joint's pose"
            )
        self._check_data(data)
        mujoco.mj_kinematics(model, data)
        gravity_scale = float(self._gravity_scales()[index])
        position, quaternion, equilibrium = self._controller.rest(
            i,
            data.xpos[index],
            _xyzw(data.xquat[index]),
            data.xipos[index],
            float(model.body_mass[index]),
            gravity_scale,
        )
        address, dof = int(model.jnt_qposadr[joint]), int(model.jnt_dofadr[joint])
        data.qpos[address : address + 3] = position
        data.qpos[address + 3 : address + 7] = quaternion[[3, 0, 1, 2]]
        data.qvel[dof : dof + 6] = 0.0
        mujoco.mj_forward(model, data)
        return equilibrium

    def _gravity_scales(self) -> np.ndarray:
        """Every body's gravity scale, by body id."""
        model = self._model
        scales = 1.0 - np.asarray(model.body_gravcomp, dtype=np.float64)
        if model.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_GRAVITY:
            scales[:] = 0.0
        return scales

    def _check_data(self, data: Any) -> None:
        if not isinstance(data, mujoco.MjData):
            raise TypeError(f"data: expected a mujoco.MjData, got {type(data).__name__}")
        model = self._model
        if data.xpos.shape[0] != model.nbody or data.qpos.shape[0] != model.nq or data.qvel.shape[0] != model.nv:
            raise ValueError(
                f"data: made for another model ({data.xpos.shape[0]} bodies, nq {data.qpos.shape[0]}, nv "
                f"{data.qvel.shape[0]}; this model has {model.nbody}, {model.nq}, {model.nv})"
            )


def _lone(model: Any, body: int) -> bool:
    """Whether ``body`` has no bodies below it."""
    return not np.any(np.asarray(model.body_parentid)[body + 1 :] == body) and int(model.body_rootid[body]) == body


class _Arrays:
    """What the step reads of the model for the registered bodies, gathered once: ids, roots,
    masses, gravity scales, and which bodies are lone free bodies (their mass and inertia are
    their own) and which move through joints (their mass as seen through the joints)."""

    def __init__(self, model: Any, ids: list[int]) -> None:
        self.model = model
        self.ids = np.array(ids, dtype=np.int64)
        self.roots = np.asarray(model.body_rootid, dtype=np.int64)[self.ids]
        self.masses = np.asarray(model.body_mass, dtype=np.float64)[self.ids]
        self.gravity_scales = 1.0 - np.asarray(model.body_gravcomp, dtype=np.float64)[self.ids]
        self.dynamic = np.ones(len(ids), dtype=bool)
        self.sleeping = np.zeros(len(ids), dtype=bool)
        free = np.array(
            [
                model.body_jntnum[b] == 1
                and model.jnt_type[model.body_jntadr[b]] == _FREE
                and model.body_parentid[b] == 0
                and _lone(model, b)
                for b in ids
            ],
            dtype=bool,
        )
        self.free = free
        self.jointed = np.flatnonzero(~free)
        inertia = np.asarray(model.body_inertia, dtype=np.float64)[self.ids]
        with np.errstate(divide="ignore"):
            self.inverse_principal = np.where(inertia > 0, 1.0 / inertia, 0.0)
        with np.errstate(divide="ignore"):
            inverse_mass = np.where(self.masses > 0, 1.0 / self.masses, 0.0)
        self.inverse_masses = np.repeat(inverse_mass[:, None], 3, axis=1)
        nv = model.nv
        self.jacobian = np.zeros((6 * len(self.jointed), nv))
        self.solved = np.zeros_like(self.jacobian)

    def inverse_mass_properties(self, data: Any) -> tuple[np.ndarray, np.ndarray]:
        """Inverse masses per world axis (N, 3) and world inverse inertias (N, 3, 3): a lone free
        body's own, ``R·I⁻¹·Rᵀ`` with ``R = ximat``; a body on joints, the blocks of the
        Cartesian compliance ``J·M⁻¹·Jᵀ`` at its center of mass (the linear block's diagonal,
        the angular block)."""
        rotations = data.ximat[self.ids].reshape(-1, 3, 3)
        inertias = np.einsum("nij,nj,nkj->nik", rotations, self.inverse_principal, rotations)
        inverse_masses = self.inverse_masses
        if len(self.jointed):
            inverse_masses = inverse_masses.copy()
            model, jacobian, nv = self.model, self.jacobian, self.model.nv
            for k, n in enumerate(self.jointed):
                rows = jacobian[6 * k : 6 * k + 6]
                mujoco.mj_jacBodyCom(model, data, rows[:3], rows[3:], int(self.ids[n]))
            mujoco.mj_solveM(model, data, self.solved, jacobian)
            rows = jacobian.reshape(-1, 6, nv)
            compliance = np.einsum("kin,kjn->kij", rows, self.solved.reshape(-1, 6, nv))
            inverse_masses[self.jointed] = np.einsum("kii->ki", compliance[:, :3, :3])
            angular = compliance[:, 3:, 3:]
            inertias[self.jointed] = 0.5 * (angular + angular.transpose(0, 2, 1))
        return inverse_masses, inertias
