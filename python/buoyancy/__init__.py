"""Exact buoyant force, center of buoyancy and torque on closed triangle meshes.

The five methods of Fábián's *Approximate and exact buoyancy calculation for real-time floating
simulation of meshes*, computed in Rust (the ``buoyancy-core`` crate) against a flat water plane
of any orientation, with the torque of the pressure field integrated exactly; and the exact
hydrostatic pressure under waves (:class:`AiryWave`, :class:`Waves`, :class:`GerstnerWaves`,
:class:`HeightGrid` or any vectorised function, given to :class:`Water` as ``waves``).

>>> import numpy as np, buoyancy
>>> cube = buoyancy.shapes.cube()                     # the unit cube about the origin
>>> b = cube.buoyancy(position=(0, -0.25, 0))         # 3/4 under fresh water, y up
>>> round(b.volume, 12), b.force.round(3).tolist()
(0.75, [0.0, 7357.5, 0.0])

Everything is in SI units (m, kg/m³, m/s², N, N·m). A :class:`Mesh` lives in its own frame; a
pose ``(position, rotation)`` maps it to the world, ``x_world = R @ x_mesh + position``; the
:class:`Water` and every result are in the world frame.
"""

from . import shapes
from ._core import (
    METHODS,
    AiryWave,
    Buoyancy,
    BuoyancyBatch,
    Controller,
    Damping,
    DampingCoefficients,
    Equilibrium,
    FloatReport,
    GerstnerWaves,
    GzCurve,
    HeightGrid,
    Hydrostatics,
    HydrostaticTable,
    Mesh,
    MeshDefect,
    MeshError,
    Water,
    Waterplane,
    Waves,
    load,
)

__all__ = [
    "METHODS",
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
    "load",
    "shapes",
]

try:
    from importlib.metadata import version as _version

    __version__ = _version("buoyancy")
except Exception:  # pragma: no cover - running from a source tree
    __version__ = "0+unknown"
