"""Floats the Stanford bunny and a cube in a rapier3d world with buoyancy.rapier, and compares
their equilibrium with theory: a floating body displaces its own weight of water, so its
submerged volume is m / ρ_water and its submerged fraction is its relative density.

    pip install 'buoyancy[rapier]'
    python examples/float_rapier.py [--seconds 30]

The bunny is read from ``$BUOYANCY_MESHES/bunny.obj``, else ``../shared/meshes/bunny.obj``
beside the repository, and scaled to about 1 m long; without it, a procedural torus knot floats
in its place (and a note says so). tests/python/test_rapier.py runs :func:`run` and checks that
both bodies settle within 1% of theory.
"""

from __future__ import annotations

import argparse
import pathlib
from dataclasses import dataclass

import numpy as np
import rapier3d

import buoyancy
from buoyancy._sample_meshes import find_sample_mesh, not_found_message
from buoyancy.rapier import FloatingBodies

REPO = pathlib.Path(__file__).resolve().parents[1]
WATER_DENSITY = 1000.0


def first_body() -> tuple[str, buoyancy.Mesh, str | None]:
    """The bunny scaled to about 1 m long, or a torus knot; and a note if it is the knot."""
    path = find_sample_mesh("bunny.obj", REPO)
    if path is None:
        knot = buoyancy.shapes.torus_knot(radius=0.4, tube_radius=0.12, segments=120, sides=12)
        note = f"note: {not_found_message(REPO, 'bunny.obj')}; floating a procedural torus knot instead"
        return "torus knot", knot, note
    raw = buoyancy.load(path)
    size = float(np.ptp(raw.vertices, axis=0).max())
    return "bunny", buoyancy.Mesh(raw.vertices / size, raw.faces), None


@dataclass(frozen=True)
class Result:
    """One body's equilibrium: simulated against theory."""

    name: str
    density: float
    mass: float
    volume: float
    #: Submerged volume at the end, averaged over the last second, m³.
    submerged: float
    #: Largest speed of the center of mass over the last second, m/s.
    residual_speed: float

    @property
    def theory(self) -> float:
        """Submerged fraction in theory: the relative density (from the body's actual mass)."""
        return self.mass / (WATER_DENSITY * self.volume)

    @property
    def simulated(self) -> float:
        return self.submerged / self.volume

    @property
    def error(self) -> float:
        """Relative error of the submerged volume against m / ρ_water."""
        return self.simulated / self.theory - 1.0


def run(seconds: float = 30.0) -> tuple[list[Result], str | None]:
    """Drops the first body (density 400 kg/m³) and a 1 m cube (700 kg/m³) into fresh water
    from 0.5 m above it, simulates ``seconds`` at 60 Hz, and returns their equilibria and the
    note about the first body (``None`` for the bunny)."""
    name, mesh, note = first_body()
    cube = buoyancy.shapes.cube()
    world = rapier3d.PhysicsWorld(gravity=(0.0, -9.81, 0.0))
    floating = FloatingBodies.for_world(world)  # fresh water, surface y = 0, y up
    bodies = []
    for label, shape, density, x in ((name, mesh, 400.0, -1.5), ("cube", cube, 700.0, 1.5)):
        vertices = shape.vertices.astype(np.float32)
        faces = shape.faces.astype(np.uint32)
        # The mesh is in the body's frame; lift the body so that its lowest point is 0.5 m up.
        lift = 0.5 - float(shape.vertices[:, 1].min())
        handle = world.add_body(
            # A floating body's gentle bobbing is slow enough for rapier to put it to sleep
            # before it reaches equilibrium: keep it awake.
            rapier3d.RigidBody.dynamic().translation((x, lift, 0.0)).can_sleep(False),
            [rapier3d.Collider.trimesh(vertices, faces).density(density)],
        )
        floating.register(handle, shape)
        bodies.append((label, shape, density, handle))

    steps = round(seconds * 60)
    last_second = 60
    submerged = {h: [] for *_, h in bodies}
    speed = {h: 0.0 for *_, h in bodies}
    for step in range(steps):
        floating.step(world)
        if step >= steps - last_second:
            for *_, h in bodies:
                rb = world.rigid_bodies[h]
                # The report describes the pose before this step; recompute at the new pose.
                position, rotation = rb.translation, rb.rotation.quaternion
                q = np.array(rotation) / np.linalg.norm(rotation)
                submerged[h].append(floating.mesh(h).buoyancy(tuple(position), q, floating.water).volume)
                speed[h] = max(speed[h], float(np.linalg.norm(tuple(rb.linvel))))
    results = [
        Result(
            name=label,
            density=density,
            mass=float(world.rigid_bodies[h].mass),
            volume=shape.volume,
            submerged=float(np.mean(submerged[h])),
            residual_speed=speed[h],
        )
        for label, shape, density, h in bodies
    ]
    return results, note


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=30.0, help="simulated time (default 30)")
    args = parser.parse_args()
    results, note = run(args.seconds)
    if note:
        print(note)
    print(
        f"rapier3d {rapier3d._rapier3d.__version__}, buoyancy {buoyancy.__version__}: "
        f"{args.seconds:g} s at 60 Hz, fresh water (1000 kg/m³)"
    )
    print(
        f"{'body':<11} {'density':>8} {'volume m³':>10} {'mass kg':>9} "
        f"{'theory':>7} {'simulated':>9} {'error':>8} {'|v| m/s':>8}"
    )
    for r in results:
        print(
            f"{r.name:<11} {r.density:>8.0f} {r.volume:>10.5f} {r.mass:>9.3f} "
            f"{r.theory:>7.5f} {r.simulated:>9.5f} {r.error:>+8.3%} {r.residual_speed:>8.1e}"
        )
    print("theory: submerged fraction = mass / (ρ_water · volume) = relative density")


if __name__ == "__main__":
    main()
