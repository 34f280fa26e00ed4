"""A wave energy converter in MuJoCo as a Gymnasium environment: an oscillating wave surge
converter (OWSC), a buoyant flap on a sea-bed hinge, swings in an irregular JONSWAP sea
(buoyancy.mujoco floats it) and a power take-off (PTO) at the hinge brakes it; an agent sets the
PTO torque and is rewarded with the energy it absorbs.

    pip install 'buoyancy[mujoco]' gymnasium matplotlib
    python examples/mujoco_wave_energy.py [--seconds 60] [--seed 1] [--out out/] [--require-render]

The device
    A box flap, 2 m wide along its hinge, 0.4 m thick along the waves and 3 m tall, of density
    300 kg/m³, hinged along y at its bottom edge on the sea bed, 2.5 m below the still water, so
    that its top pierces the surface by 0.5 m. Upright, the buoyancy's moment about the hinge
    (ρ g B T d²/2 per radian, 25 kN·m/rad) exceeds the weight's (ρ_flap g B T H²/2, 11 kN·m/rad):
    the flap stands up by itself. Its undamped natural period is 2.4 s (its own inertia about the
    hinge; the model has no added mass), shorter than the waves', and the hydrodynamic damping
    (buoyancy's default coefficients, ``damping=`` to change them) is about critical for it: in
    still water a tilted flap returns upright without swinging past. The buoyancy is exact on the
    wetted part of the box under the waves' hydrostatic pressure, and the damping is taken
    relative to the waves' orbital velocity: the sea tilts the flap to and fro mostly through the
    surface standing higher on one face than on the other. Its hinge stops at ±70°, which no policy
    here reaches. No diffraction or radiation is modelled, so the absorbed power is indicative,
    not a design figure.

The sea
    Sea water (1025 kg/m³), a long-crested JONSWAP sea travelling along +x (Hs 1 m, Tp 6 s,
    γ 3.3, 64 components) over water 2.5 m deep, the depth of the hinge. ``reset(seed=s)``
    rebuilds the sea with phases drawn from ``s``: the same seed, the same sea, the same episode.
    The waves run on ``data.time``, from the first step on.

Frames and units
    MuJoCo's world frame, z up, the still surface at z = 0, the hinge at (0, 0, −2.5) along y.
    The flap angle is the hinge's (rad), positive when the top leans down-wave (towards +x).
    SI units: m, s, rad, N·m, W, J.

The environment, ``WaveEnergyEnv``
    * observation (float32): flap angle (rad), angular velocity (rad/s), wave elevation at the
      hinge's position (m, from ``Water.elevation``);
    * action (float32): the PTO torque on the flap, N·m, within ±20 kN·m (not normalised: wrap it
      in ``gymnasium.wrappers.RescaleAction`` for an agent that wants [−1, 1]);
    * reward: the energy the PTO absorbed over the control interval, J: the torque's work on the
      flap with its sign turned, ``−τ·Δθ`` summed over the MuJoCo steps (positive when the PTO
      brakes the flap); ``info["power"]`` is its mean over the interval, W;
    * 10 actions a second, each held for 20 MuJoCo steps of 5 ms; the episode is truncated after
      ``seconds`` (60 s by default) and never terminates;
    * ``render_mode="rgb_array"``: a side view (looking along +y) by ``mujoco.Renderer``,
      offscreen: the flap (orange) on its foundation, the still level as a translucent plane (a
      visual-only geom of the model), and the water at the time drawn into the scene as a
      translucent section up to the wave surface on the near side and a sheet along the surface. Without a display, ``MUJOCO_GL`` defaults to ``osmesa``
      here (``apt-get install libosmesa6``; ``MUJOCO_GL=egl`` works too where EGL does).

What the script prints
    The design's hydrostatics, ``check_env``'s verdict, then one episode per policy over the same
    sea (the same seed): no PTO (zero torque: nothing absorbed, the flap swings freely), random
    torque (uniform in the action range, held for each interval: the PTO then mostly drives the
    flap against the water's drag, a large negative absorbed power), and linear damping
    ``τ = −c·ω`` for a few ``c`` (kN·m·s/rad), the best marked. The table gives each policy's mean
    absorbed power (W: the episode's absorbed energy over its length), the largest flap angle
    (degrees) and the RMS torque (kN·m); below it, the best damping's share of the incident wave
    power over the flap's width (the capture width ratio). The damping is held for 0.1 s, so too
    large a ``c`` makes the discrete loop unstable (beyond about 2·I/0.1 s ≈ 43 kN·m·s/rad); the
    sweep stays below. Last, one frame of the best damping's episode, at its largest tilt, is
    written to ``OUT/mujoco_wave_energy.png``; when no OpenGL context can be made the script says
    why and how to fix it and goes on (``--require-render`` makes that an error, exit status 1).
"""

from __future__ import annotations

import os

if not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
    os.environ.setdefault("MUJOCO_GL", "osmesa")  # offscreen rendering without a display

import argparse
import math
import pathlib
import re
import sys
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import gymnasium
import mujoco
import numpy as np
from gymnasium import spaces
from gymnasium.utils.env_checker import check_env

import buoyancy
from buoyancy.mujoco import FloatingBodies

REPO = pathlib.Path(__file__).resolve().parents[1]
SEA_WATER = 1025.0  # kg/m³
GRAVITY = 9.81  # m/s², MuJoCo's default gravity and the water's
#: The damping policies' coefficients c of τ = −c·ω, N·m·s/rad.
DAMPINGS = (5e3, 10e3, 20e3, 30e3)
#: The rendered frame's size, pixels (MuJoCo's default offscreen buffer).
WIDTH, HEIGHT = 640, 480
WATER_RGBA = np.array([0.1, 0.4, 0.75, 0.25], dtype=np.float32)
SURFACE_RGBA = np.array([0.3, 0.6, 0.9, 0.55], dtype=np.float32)


@dataclass(frozen=True)
class Flap:
    """The flap's box and hinge, m and kg/m³."""

    width: float = 2.0  # along the hinge axis, y
    thickness: float = 0.4  # along the waves, x
    height: float = 3.0  # from the hinge to the top
    depth: float = 2.5  # of the hinge below the still surface: the water's depth
    density: float = 300.0

    @property
    def mass(self) -> float:
        """kg."""
        return self.density * self.width * self.thickness * self.height

    @property
    def inertia(self) -> float:
        """About the hinge, kg·m²."""
        return self.mass * (self.height**2 / 3.0 + self.thickness**2 / 12.0)

    def buoyancy_stiffness(self) -> float:
        """The buoyancy's restoring moment about the hinge per radian of small tilt, upright in
        still water, N·m/rad: ``ρ g B T d² / 2``."""
        return SEA_WATER * GRAVITY * self.width * self.thickness * self.depth**2 / 2.0

    def weight_stiffness(self) -> float:
        """The weight's overturning moment about the hinge per radian, N·m/rad: ``m g H / 2``."""
        return self.mass * GRAVITY * self.height / 2.0

    def natural_period(self) -> float:
        """Of small swings in still water (no added mass), s."""
        return 2.0 * math.pi * math.sqrt(self.inertia / (self.buoyancy_stiffness() - self.weight_stiffness()))


@dataclass(frozen=True)
class Sea:
    """The JONSWAP sea state: significant height (m), peak period (s), peak enhancement, components."""

    hs: float = 1.0
    tp: float = 6.0
    gamma: float = 3.3
    components: int = 64

    def water(self, depth: float, seed: int) -> buoyancy.Water:
        """Sea water, z up, with this sea (long-crested, along +x) over ``depth`` (m), phases from ``seed``."""
        still = buoyancy.Water(density=SEA_WATER, gravity=GRAVITY, normal=(0.0, 0.0, 1.0))
        waves = buoyancy.Waves.jonswap(
            self.hs, self.tp, gamma=self.gamma, n=self.components, seed=seed, depth=depth, water=still
        )
        return buoyancy.Water(density=SEA_WATER, gravity=GRAVITY, normal=(0.0, 0.0, 1.0), waves=waves)


def incident_power(water: buoyancy.Water, depth: float) -> float:
    """The waves' energy flux per metre of crest, W/m: ``Σ ½ ρ g aᵢ² c_g,i`` with the group
    velocity of each component over ``depth``."""
    waves = water.waves
    assert isinstance(waves, buoyancy.Waves)
    omegas = waves.angular_frequencies(water.gravity)
    total = 0.0
    for component, omega in zip(waves.components, omegas, strict=True):
        k = component.wavenumber
        kh = k * depth
        group = 0.5 * (omega / k) * (1.0 + 2.0 * kh / math.sinh(2.0 * kh))
        total += 0.5 * water.density * water.gravity * component.amplitude**2 * group
    return total


def mjcf(flap: Flap, timestep: float, max_torque: float) -> str:
    """The MuJoCo model: the flap on its hinge, its PTO motor, and visual-only scenery (the still
    level, the sea bed, the hinge's foundation, a side camera)."""
    t, b, h, d = flap.thickness, flap.width, flap.height, flap.depth
    return f"""
<mujoco model="owsc">
  <option timestep="{timestep}"/>
  <visual><global offwidth="{WIDTH}" offheight="{HEIGHT}"/><headlight ambient="0.35 0.35 0.35"/></visual>
  <asset>
    <texture name="sky" type="skybox" builtin="gradient" rgb1="0.75 0.85 0.95" rgb2="0.3 0.45 0.6"
             width="32" height="512"/>
  </asset>
  <worldbody>
    <light directional="true" pos="0 -6 10" dir="0 0.5 -1"/>
    <camera name="side" pos="0 -9.5 0.6" xyaxes="1 0 0 0 0.15 1"/>
    <geom name="still_water" type="plane" size="12 {b / 2 + 0.8} 0.1" rgba="0.2 0.5 0.85 0.2"
          contype="0" conaffinity="0" group="1"/>
    <geom name="sea_bed" type="box" size="12 {b / 2 + 0.8} 0.5" pos="0 0 {-d - 0.5}" rgba="0.76 0.7 0.5 1"
          contype="0" conaffinity="0" group="1"/>
    <geom name="foundation" type="cylinder" size="0.12 {b / 2 + 0.15}" pos="0 0 {-d}" quat="0.7071068 0.7071068 0 0"
          rgba="0.3 0.3 0.3 1" contype="0" conaffinity="0" group="1"/>
    <body name="flap" pos="0 0 {-d}">
      <joint name="hinge" type="hinge" axis="0 1 0" range="-70 70" limited="true"/>
      <geom name="flap" type="box" size="{t / 2} {b / 2} {h / 2}" pos="0 0 {h / 2}" density="{flap.density}"
            rgba="0.95 0.55 0.1 1"/>
    </body>
  </worldbody>
  <actuator>
    <motor name="pto" joint="hinge" gear="1" ctrllimited="true" ctrlrange="{-max_torque} {max_torque}"/>
  </actuator>
</mujoco>"""


class WaveEnergyEnv(gymnasium.Env[np.ndarray, np.ndarray]):
    """An OWSC flap in a JONSWAP sea; the action is its PTO torque (see the module's docstring).

    Parameters
    ----------
    seconds : float
        The episode's length, s (truncated then).
    control_rate : float
        Actions a second, Hz; ``1 / (control_rate · timestep)`` must be a whole number of steps.
    timestep : float
        MuJoCo's step, s.
    max_torque : float
        The PTO's largest torque, N·m: the action space is ``[−max_torque, max_torque]``.
    flap, sea : Flap, Sea
        The device and the sea state.
    render_mode : "rgb_array" or None
    """

    metadata: dict[str, Any] = {"render_modes": ["rgb_array"], "render_fps": 10}  # noqa: RUF012

    def __init__(
        self,
        *,
        seconds: float = 60.0,
        control_rate: float = 10.0,
        timestep: float = 0.005,
        max_torque: float = 20e3,
        flap: Flap | None = None,
        sea: Sea | None = None,
        damping: buoyancy.DampingCoefficients | None = None,
        render_mode: str | None = None,
    ) -> None:
        super().__init__()
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode: expected None or 'rgb_array', got {render_mode!r}")
        if not (math.isfinite(seconds) and seconds > 0):
            raise ValueError(f"seconds: expected a positive duration, got {seconds}")
        substeps = round(1.0 / (control_rate * timestep))
        if substeps < 1 or abs(substeps * control_rate * timestep - 1.0) > 1e-9:
            raise ValueError(
                f"control_rate {control_rate} Hz and timestep {timestep} s: the control interval must be a whole "
                "number of MuJoCo steps"
            )
        self.flap = flap if flap is not None else Flap()
        self.sea = sea if sea is not None else Sea()
        self.damping = damping if damping is not None else buoyancy.DampingCoefficients()
        self.seconds = float(seconds)
        self.substeps = substeps
        self.max_torque = float(max_torque)
        self.render_mode = render_mode
        self.model = mujoco.MjModel.from_xml_string(mjcf(self.flap, timestep, self.max_torque))
        self.data = mujoco.MjData(self.model)
        self.interval = substeps * timestep
        self.episode_steps = math.ceil(self.seconds / self.interval - 1e-9)
        # Bounds the state never reaches: angles within the hinge's stops, a wave crest far below 4 Hs.
        high = np.array([math.pi / 2, 20.0, 4.0 * self.sea.hs], dtype=np.float32)
        self._high = high
        self.observation_space = spaces.Box(-high, high, dtype=np.float32)
        self.action_space = spaces.Box(-self.max_torque, self.max_torque, shape=(1,), dtype=np.float32)
        self.sea_seed = 0
        self.water = self.sea.water(self.flap.depth, self.sea_seed)
        self.bodies = self._float(self.water)
        self._steps = 0
        self._renderer: Any = None

    def _float(self, water: buoyancy.Water) -> FloatingBodies:
        bodies = FloatingBodies.for_model(self.model, water=water, damping=self.damping)
        bodies.register("flap")
        return bodies

    def _observation(self) -> np.ndarray:
        eta = float(self.water.elevation((0.0, 0.0, 0.0), float(self.data.time)))
        observation = np.array([self.data.qpos[0], self.data.qvel[0], eta], dtype=np.float32)
        return np.clip(observation, -self._high, self._high)

    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[np.ndarray, dict[str, Any]]:
        """The flap upright at rest at t = 0 in a sea whose phases come from ``seed`` (through
        ``np_random``; ``options={"sea_seed": n}`` gives the sea's own seed instead)."""
        super().reset(seed=seed)
        if options and "sea_seed" in options:
            self.sea_seed = int(options["sea_seed"])
        else:
            self.sea_seed = int(self.np_random.integers(2**31))
        self.water = self.sea.water(self.flap.depth, self.sea_seed)
        mujoco.mj_resetData(self.model, self.data)
        self.bodies = self._float(self.water)  # a fresh adapter: nothing of the last episode stays
        mujoco.mj_forward(self.model, self.data)
        self._steps = 0
        return self._observation(), {"time": 0.0, "sea_seed": self.sea_seed}

    def step(self, action: np.ndarray) -> tuple[np.ndarray, float, bool, bool, dict[str, Any]]:
        torque = float(np.clip(np.asarray(action, dtype=np.float64).reshape(-1)[0], -self.max_torque, self.max_torque))
        data = self.data
        data.ctrl[0] = torque
        energy = 0.0
        for _ in range(self.substeps):
            before = float(data.qpos[0])
            self.bodies.step(data)
            # The PTO's work over the step, sign turned: MuJoCo's Euler step moves the hinge by
            # the new velocity times dt, so this is the discrete work exactly.
            energy -= float(data.actuator_force[0]) * (float(data.qpos[0]) - before)
        self._steps += 1
        truncated = self._steps >= self.episode_steps
        info = {"time": float(data.time), "torque": torque, "power": energy / self.interval}
        return self._observation(), energy, False, truncated, info

    def render(self) -> np.ndarray | None:  # type: ignore[override]
        if self.render_mode != "rgb_array":
            return None
        if self._renderer is None:
            self._renderer = mujoco.Renderer(self.model, HEIGHT, WIDTH)
        renderer = self._renderer
        renderer.update_scene(self.data, camera="side")
        self._draw_water(renderer.scene)
        return np.asarray(renderer.render())

    def _draw_water(self, scene: Any) -> None:
        """The water between two planes across the flap's sides: its section up to the surface
        along x (translucent, on the near plane) and the surface as a translucent sheet."""
        n, extent = 120, 12.0
        edges = np.linspace(-extent, extent, n + 1)
        points = np.column_stack([edges, np.zeros(n + 1), np.zeros(n + 1)])
        eta = np.asarray(self.water.elevation(points, float(self.data.time)), dtype=np.float64)
        side, depth = self.flap.width / 2 + 0.8, self.flap.depth
        box = int(mujoco.mjtGeom.mjGEOM_BOX)
        for i in range(n):
            if scene.ngeom + 2 > scene.maxgeom:
                break
            x0, x1, z0, z1 = edges[i], edges[i + 1], eta[i], eta[i + 1]
            middle = 0.5 * (z0 + z1)
            half_height = 0.5 * (middle + depth)
            mujoco.mjv_initGeom(
                scene.geoms[scene.ngeom],
                box,
                np.array([0.5 * (x1 - x0), 0.002, half_height]),
                np.array([0.5 * (x0 + x1), -side, -depth + half_height]),
                np.eye(3).reshape(-1),
                WATER_RGBA,
            )
            scene.ngeom += 1
            slope = math.atan2(z1 - z0, x1 - x0)
            c, s = math.cos(slope), math.sin(slope)
            tilt = np.array([[c, 0.0, -s], [0.0, 1.0, 0.0], [s, 0.0, c]])  # about y, x towards z
            mujoco.mjv_initGeom(
                scene.geoms[scene.ngeom],
                box,
                np.array([0.5 * math.hypot(x1 - x0, z1 - z0), side, 0.002]),
                np.array([0.5 * (x0 + x1), 0.0, middle]),
                tilt.reshape(-1),
                SURFACE_RGBA,
            )
            scene.ngeom += 1

    def close(self) -> None:
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None


# --- policies and episodes ------------------------------------------------------------------------

Policy = Callable[[np.ndarray], np.ndarray]


def zero_torque(observation: np.ndarray) -> np.ndarray:
    """No PTO."""
    return np.zeros(1, dtype=np.float32)


def linear_damping(c: float, max_torque: float) -> Policy:
    """``τ = −c·ω``, N·m, within ``±max_torque``."""

    def policy(observation: np.ndarray) -> np.ndarray:
        return np.array([np.clip(-c * float(observation[1]), -max_torque, max_torque)], dtype=np.float32)

    return policy


def random_torque(env: gymnasium.Env[np.ndarray, np.ndarray], seed: int) -> Policy:
    """A torque drawn uniformly in the action space each interval (seeded)."""
    env.action_space.seed(seed)

    def policy(observation: np.ndarray) -> np.ndarray:
        return np.asarray(env.action_space.sample())

    return policy


@dataclass
class Episode:
    """One episode's record, one entry per control interval."""

    name: str
    seconds: float
    energies: np.ndarray  # J
    angles: np.ndarray  # rad, at the interval's end
    torques: np.ndarray  # N·m
    wall: float  # s

    @property
    def mean_power(self) -> float:
        """W."""
        return float(self.energies.sum()) / self.seconds

    @property
    def max_angle_deg(self) -> float:
        return math.degrees(float(np.abs(self.angles).max()))

    @property
    def rms_torque(self) -> float:
        """N·m."""
        return float(np.sqrt(np.mean(self.torques**2)))


def run_episode(env: WaveEnergyEnv, policy: Policy, seed: int, name: str, *, steps: int | None = None) -> Episode:
    """Runs ``policy`` from ``env.reset(seed=seed)`` to truncation (or for ``steps`` intervals)."""
    started = time.perf_counter()
    observation, _ = env.reset(seed=seed)
    energies, angles, torques = [], [], []
    while True:
        observation, reward, terminated, truncated, info = env.step(policy(observation))
        energies.append(reward)
        angles.append(float(observation[0]))
        torques.append(info["torque"])
        if terminated or truncated or (steps is not None and len(energies) >= steps):
            break
    return Episode(
        name,
        len(energies) * env.interval,
        np.array(energies),
        np.array(angles),
        np.array(torques),
        time.perf_counter() - started,
    )


# --- the script -----------------------------------------------------------------------------------


def checked(env: WaveEnergyEnv) -> list[str]:
    """``check_env`` on ``env`` (raises if it fails); the warnings it gave."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_env(env.unwrapped, skip_render_check=env.render_mode is None)
    return sorted({re.sub(r"\x1b\[[0-9;]*m", "", str(w.message)).split(". ")[0] for w in caught})


def gl_advice() -> str:
    """Which OpenGL backend MuJoCo took, and how to get one that renders without a display."""
    backend = getattr(getattr(mujoco, "GLContext", None), "__module__", "none")
    return (
        f"MuJoCo could not make an offscreen OpenGL context (its backend: {backend}, which it picks from MUJOCO_GL "
        f"when first imported; MUJOCO_GL is {os.environ.get('MUJOCO_GL', '')!r} now). Install OSMesa "
        "(apt-get install libosmesa6) and set MUJOCO_GL=osmesa before starting Python, or MUJOCO_GL=egl where EGL works"
    )


def save_frame(env: WaveEnergyEnv, policy: Policy, seed: int, steps: int, path: pathlib.Path) -> str | None:
    """Renders the episode of ``policy`` after ``steps`` intervals and writes it as a PNG;
    ``None``, or why it could not."""
    try:
        run_episode(env, policy, seed, "frame", steps=steps)
        frame = env.render()
    except Exception as error:
        return f"{type(error).__name__}: {error}. {gl_advice()}"
    finally:
        env.close()
    assert frame is not None
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        from matplotlib import image
    except ImportError:
        try:
            from PIL import Image
        except ImportError:
            return "neither matplotlib nor Pillow is installed to write the PNG (pip install matplotlib)"
        Image.fromarray(frame).save(path)
    else:
        image.imsave(path, frame)
    return None


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=60.0, help="each episode's length, s (default 60)")
    parser.add_argument("--seed", type=int, default=1, help="the sea's seed, the same for every policy (default 1)")
    parser.add_argument("--out", type=pathlib.Path, default=REPO / "out", help="the folder of the PNG (default out/)")
    parser.add_argument("--require-render", action="store_true", help="fail when the frame cannot be rendered")
    args = parser.parse_args()
    if not (math.isfinite(args.seconds) and args.seconds >= 1.0):
        parser.error(f"--seconds: expected at least 1 s, got {args.seconds:g}")
    started = time.perf_counter()

    env = WaveEnergyEnv(seconds=args.seconds)
    flap, sea = env.flap, env.sea
    print(
        f"flap: {flap.width:g} m wide × {flap.thickness:g} m thick × {flap.height:g} m tall, {flap.density:g} kg/m³ "
        f"({flap.mass:.0f} kg, {flap.inertia:.0f} kg·m² about the hinge), hinge {flap.depth:g} m deep"
    )
    kb, kw = flap.buoyancy_stiffness(), flap.weight_stiffness()
    print(
        f"  upright: buoyancy moment {kb / 1e3:.1f} kN·m/rad > weight moment {kw / 1e3:.1f} kN·m/rad "
        f"(net {(kb - kw) / 1e3:.1f}); natural period {flap.natural_period():.2f} s"
    )
    print(
        f"sea: JONSWAP Hs {sea.hs:g} m, Tp {sea.tp:g} s, γ {sea.gamma:g}, {sea.components} components, "
        f"depth {flap.depth:g} m, seed {args.seed}; PTO within ±{env.max_torque / 1e3:g} kN·m, "
        f"{1 / env.interval:g} actions/s × {env.substeps} MuJoCo steps"
    )

    t0 = time.perf_counter()
    notes = checked(WaveEnergyEnv(seconds=2.0))
    print(f"check_env passed ({time.perf_counter() - t0:.1f} s)")
    for note in notes:
        print(f"  its warning: {note}")

    env.reset(seed=args.seed)
    flux = incident_power(env.water, flap.depth)
    print(f"incident wave power {flux / 1e3:.2f} kW/m, {flux * flap.width / 1e3:.2f} kW over the flap's width\n")

    policies: list[tuple[str, Policy]] = [("zero torque (no PTO)", zero_torque)]
    policies.append(("random torque", random_torque(env, args.seed)))
    for c in DAMPINGS:
        policies.append((f"damping c = {c / 1e3:g} kN·m·s/rad", linear_damping(c, env.max_torque)))
    episodes = []
    for name, policy in policies:
        episode = run_episode(env, policy, args.seed, name)
        episodes.append(episode)
        print(f"  {name:<32} {episode.mean_power:9.1f} W   ({episode.wall:.1f} s)", flush=True)
    damped = episodes[2:]
    best = max(damped, key=lambda e: e.mean_power)

    print(f"\n{args.seconds:g} s of the same sea (seed {args.seed}) per policy:\n")
    print(f"{'policy':<34} {'mean power (W)':>14} {'max |angle| (°)':>16} {'rms torque (kN·m)':>18}")
    for episode in episodes:
        mark = "  ← best" if episode is best else ""
        print(
            f"{episode.name:<34} {episode.mean_power:14.1f} {episode.max_angle_deg:16.1f} "
            f"{episode.rms_torque / 1e3:18.2f}{mark}"
        )
    print(
        f"\nbest damping: {best.mean_power:.0f} W of the {flux * flap.width:.0f} W incident over the flap's width "
        f"(capture width ratio {best.mean_power / (flux * flap.width):.1%})"
    )

    path = args.out / "mujoco_wave_energy.png"
    at = int(np.argmax(np.abs(best.angles))) + 1
    best_policy = dict(policies)[best.name]
    problem = save_frame(WaveEnergyEnv(seconds=args.seconds, render_mode="rgb_array"), best_policy, args.seed, at, path)
    if problem is None:
        print(f"wrote {path} ({best.name}, t = {at * env.interval:.1f} s, angle {best.max_angle_deg:.1f}°)")
    else:
        print(f"no frame rendered: {problem}", file=sys.stderr)
    env.close()
    print(f"finished in {time.perf_counter() - started:.1f} s")
    return 1 if problem is not None and args.require_render else 0


if __name__ == "__main__":
    sys.exit(main())
