"""Figures of buoyancy on waves, drawn with matplotlib (``python -m buoyancy.plots waves``).

* ``waves_body.png``: a body on a regular Airy wave, side view (looking along −z, y up): the
  wave's profile through the body's center, and the body's triangles coloured by the hydrostatic
  pressure of the wave ``ρ g max(0, η − h)`` at their vertices (``h`` the height above the still
  level), the pressure the exact surface integration uses; dry triangles in grey.
* ``waves_box_heave.png``: the vertical force on a wall-sided box (length L along the wave,
  beam B, draft T) over one wave period, against the analytic heave force of hydrostatic
  pressure ``ρgB∫(T + η)dx = ρgBLT + ρgBa·(2/k)·sin(kL/2)·cos(ωt)``, and the difference.
"""

from __future__ import annotations

import math
import pathlib
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from . import AiryWave, Mesh, Water, Waves, shapes

FloatArray = npt.NDArray[np.float64]


@dataclass
class BoxInWave:
    """A wall-sided box in a regular deep-water Airy wave, SI units."""

    length: float = 4.0
    beam: float = 1.0
    draft: float = 0.5
    amplitude: float = 0.1
    wavelength: float = 10.0
    resolution: int = 32

    def water(self) -> Water:
        return Water(waves=Waves([AiryWave(self.amplitude, self.wavelength)]))

    def mesh(self) -> Mesh:
        """The box, centred at x = z = 0, of ``resolution²`` squares per face."""
        return shapes.cube(self.resolution).scaled((self.length, 1.0, self.beam))

    def position(self) -> tuple[float, float, float]:
        """Its bottom at y = −draft."""
        return (0.0, 0.5 - self.draft, 0.0)

    def period(self, gravity: float) -> float:
        return 2 * math.pi / math.sqrt(gravity * 2 * math.pi / self.wavelength)

    def analytic_heave(self, times: FloatArray, water: Water) -> FloatArray:
        """``ρgBLT + ρgBa·(2/k)·sin(kL/2)·cos(ωt)``, N."""
        k = 2 * math.pi / self.wavelength
        omega = math.sqrt(water.gravity * k)
        wave = self.amplitude * (2 / k) * math.sin(k * self.length / 2) * np.cos(omega * times)
        return water.specific_weight * self.beam * (self.length * self.draft + wave)


def box_heave_data(box: BoxInWave, samples: int = 65) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Times over one period (s), the computed vertical force and the analytic one (N)."""
    water = box.water()
    times = np.linspace(0.0, box.period(water.gravity), samples)
    positions = np.tile(box.position(), (samples, 1))
    force = box.mesh().buoyancy_batch(positions, None, water=water, times=times).force[:, 1]
    return times, np.asarray(force), box.analytic_heave(times, water)


def vertex_pressures(mesh: Mesh, position: npt.ArrayLike, water: Water, time: float) -> tuple[FloatArray, FloatArray]:
    """The world vertices of ``mesh`` at ``position`` (no rotation) and the hydrostatic pressure
    of the waves at each, ``ρ g max(0, η − h)``, Pa."""
    vertices = np.asarray(mesh.vertices) + np.asarray(position, dtype=float)
    height = vertices @ np.asarray(water.normal) - water.level
    eta = np.asarray(water.elevation(vertices, time=time))
    return vertices, water.specific_weight * np.maximum(eta - height, 0.0)


def _draw_body(ax, mesh: Mesh, position: tuple[float, float, float], water: Water, time: float) -> None:  # type: ignore[no-untyped-def]
    from matplotlib.collections import PolyCollection

    vertices, pressure = vertex_pressures(mesh, position, water, time)
    faces = np.asarray(mesh.faces)
    # Painter's order: the far side (smallest z) first, seen from +z.
    order = np.argsort(vertices[faces][:, :, 2].mean(axis=1))
    triangles = vertices[faces[order]][:, :, :2]
    face_pressure = pressure[faces[order]].mean(axis=1)
    wet = pressure[faces[order]].max(axis=1) > 0
    colours = np.where(wet, face_pressure, np.nan)
    collection = PolyCollection(list(triangles), cmap="viridis", edgecolors="face", linewidths=0.2)
    collection.set_array(np.ma.masked_invalid(colours))
    collection.cmap.set_bad("lightgrey")
    ax.add_collection(collection)
    x = np.linspace(vertices[:, 0].min() - 1.0, vertices[:, 0].max() + 1.0, 400)
    profile = np.c_[x, np.zeros_like(x), np.full_like(x, position[2])]
    ax.plot(x, water.elevation(profile, time=time), color="tab:blue", linewidth=1.5, label="free surface η(x)")
    ax.axhline(0.0, color="tab:blue", linewidth=0.6, linestyle=":", label="still level")
    ax.set_xlim(x[0], x[-1])
    ax.set_ylim(vertices[:, 1].min() - 0.3, vertices[:, 1].max() + 0.3)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.figure.colorbar(collection, ax=ax, shrink=0.8, label="pressure ρg·max(0, η − h) (Pa)")
    ax.legend(loc="upper right", fontsize="small")


def waves(out: pathlib.Path, samples: int = 65, small: bool = False) -> list[pathlib.Path]:
    """Writes the waves figures into ``out``; returns the PNG paths."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out.mkdir(parents=True, exist_ok=True)
    written = []

    sphere = shapes.uv_sphere(1.0, 32 if small else 96, 16 if small else 48)
    # Long-crested (both along x), so that the profile is the waterline on every side.
    sea = Water(waves=Waves([AiryWave(0.4, 6.0), AiryWave(0.1, 2.5, phase=1.0)]))
    fig, ax = plt.subplots(figsize=(9, 4.5))
    time = 0.8
    _draw_body(ax, sphere, (0.0, -0.2, 0.0), sea, time)
    b = sphere.buoyancy(position=(0.0, -0.2, 0.0), water=sea, time=time)
    force = ", ".join(f"{round(float(f)):d}" for f in b.force)  # whole newtons, no "-0"
    ax.set_title(f"a unit sphere on a two-component Airy sea at t = {time} s: F = ({force}) N")
    fig.tight_layout()
    path = out / "waves_body.png"
    fig.savefig(path, dpi=120)
    plt.close(fig)
    written.append(path)

    box = BoxInWave(resolution=16 if small else 32)
    times, force, analytic = box_heave_data(box, samples)
    reference = box.water().specific_weight * box.beam * box.length * box.draft
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True, height_ratios=(2, 1))
    top.plot(times, analytic / 1e3, color="black", linewidth=3, alpha=0.25, label="analytic ρgB∫(T + η)dx")
    top.plot(times, force / 1e3, color="tab:green", linestyle=":", label="exact surface integration")
    top.set_ylabel("vertical force (kN)")
    top.set_title(
        f"box {box.length:g} × {box.beam:g} m, draft {box.draft:g} m, in a wave a = {box.amplitude:g} m, "
        f"λ = {box.wavelength:g} m"
    )
    top.legend(fontsize="small")
    top.grid(alpha=0.3)
    bottom.plot(times, (force - analytic) / reference, color="tab:green")
    bottom.set_xlabel("time (s), one wave period")
    bottom.set_ylabel("difference / ρgBLT")
    bottom.grid(alpha=0.3)
    fig.tight_layout()
    path = out / "waves_box_heave.png"
    fig.savefig(path, dpi=120)
    plt.close(fig)
    written.append(path)

    worst = float(np.max(np.abs(force - analytic)) / reference)
    print(
        f"box in a regular wave, {box.resolution}² squares per face: largest |F − F_analytic| / ρgBLT "
        f"over {samples} times = {worst:.1e}"
    )
    for p in written:
        print(f"wrote {p}")
    return written
