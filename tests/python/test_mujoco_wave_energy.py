"""examples/mujoco_wave_energy.py: the OWSC flap's Gymnasium environment passes check_env, swings
in its JONSWAP sea, is reproducible by its seed, and a damping PTO absorbs more than none or a
random torque; its render is a picture (skipped, outside CI, where no OpenGL context can be made)."""

from __future__ import annotations

import importlib.util
import os
import pathlib
import sys
from types import ModuleType
from typing import Any

import numpy as np
import pytest

from conftest import skip_unless_ci

if not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
    os.environ.setdefault("MUJOCO_GL", "osmesa")  # as the example does; read when mujoco is first imported

try:
    import gymnasium  # noqa: F401
    import mujoco  # noqa: F401
except ImportError as error:  # not installed, or installed but not loadable here
    skip_unless_ci(f"mujoco or gymnasium cannot be imported ({error}); pip install 'buoyancy[mujoco]' gymnasium")

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "mujoco_wave_energy.py"
SECONDS = 20.0
SEED = 3


@pytest.fixture(scope="module")
def example() -> ModuleType:
    spec = importlib.util.spec_from_file_location("mujoco_wave_energy", EXAMPLE)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up
    try:
        spec.loader.exec_module(module)
    finally:
        del sys.modules[spec.name]
    return module


@pytest.fixture(scope="module")
def episodes(example: ModuleType) -> dict[str, Any]:
    """Zero torque, random torque and the best damping of the sweep, 20 s each of one sea."""
    env = example.WaveEnergyEnv(seconds=SECONDS)
    policies = {
        "zero": example.zero_torque,
        "random": example.random_torque(env, SEED),
        "damping": example.linear_damping(20e3, env.max_torque),
    }
    return {name: example.run_episode(env, policy, SEED, name) for name, policy in policies.items()}


def test_check_env_passes(example: ModuleType) -> None:
    notes = example.checked(example.WaveEnergyEnv(seconds=2.0))  # raises if a check fails
    assert all("recommend using a symmetric and normalized space" in note for note in notes), notes


def test_the_flap_stands_upright_by_itself(example: ModuleType) -> None:
    flap = example.Flap()
    assert flap.buoyancy_stiffness() > 2.0 * flap.weight_stiffness()
    # In still water (a calm sea) a flap tilted by 0.2 rad, without PTO, returns upright, the
    # damping being about critical for it.
    env = example.WaveEnergyEnv(seconds=10.0, sea=example.Sea(hs=1e-6))
    env.reset(seed=0)
    env.data.qpos[0] = 0.2
    angles = []
    truncated = False
    while not truncated:
        observation, _, _, truncated, _ = env.step(np.zeros(1, dtype=np.float32))
        angles.append(float(observation[0]))
    assert angles[0] < 0.2 and abs(angles[-1]) < 0.01, f"the tilted flap went to {angles[-1]} rad"
    assert min(angles) > -0.05, f"it swung past upright to {min(angles)} rad"


def test_the_flap_swings_in_the_sea_and_damping_absorbs_the_most(episodes: dict[str, Any]) -> None:
    zero, random, damping = episodes["zero"], episodes["random"], episodes["damping"]
    assert zero.mean_power == 0.0  # no PTO, no work
    assert 3.0 < zero.max_angle_deg < 60.0, f"the free flap's largest angle {zero.max_angle_deg}°"
    assert damping.mean_power > 20.0, f"damping absorbs {damping.mean_power} W"
    assert damping.mean_power > random.mean_power + 20.0, (damping.mean_power, random.mean_power)
    assert damping.max_angle_deg < zero.max_angle_deg  # the PTO brakes the swing


def test_observations_are_finite_and_within_their_space(example: ModuleType) -> None:
    env = example.WaveEnergyEnv(seconds=SECONDS)
    env.action_space.seed(SEED)
    observation, _ = env.reset(seed=SEED)
    observations = [observation]
    truncated = False
    while not truncated:
        observation, reward, terminated, truncated, info = env.step(env.action_space.sample())
        assert not terminated and np.isfinite(reward) and np.isfinite(info["power"])
        observations.append(observation)
    stacked = np.array(observations)
    assert stacked.dtype == np.float32 and stacked.shape == (env.episode_steps + 1, 3)
    assert np.isfinite(stacked).all()
    assert all(o in env.observation_space for o in observations)
    assert np.ptp(stacked[:, 2]) > 0.5, "the wave elevation at the flap hardly changes"
    assert info["time"] == pytest.approx(SECONDS)


def test_reset_with_a_seed_reproduces_the_episode(example: ModuleType) -> None:
    env = example.WaveEnergyEnv(seconds=SECONDS)
    policy = example.linear_damping(10e3, env.max_torque)

    def first(seed: int) -> np.ndarray:
        observation, _ = env.reset(seed=seed)
        observations = [observation]
        for _ in range(30):
            observation, *_ = env.step(policy(observation))
            observations.append(observation)
        return np.array(observations)

    a, b, other = first(11), first(11), first(12)
    np.testing.assert_array_equal(a, b)
    assert not np.array_equal(a[:, 2], other[:, 2]), "another seed gave the same sea"


def test_render_is_a_picture(example: ModuleType) -> None:
    env = example.WaveEnergyEnv(seconds=2.0, render_mode="rgb_array")
    try:
        env.reset(seed=SEED)
        for _ in range(5):
            env.step(np.zeros(1, dtype=np.float32))
        try:
            frame = env.render()
        except Exception as error:  # no OpenGL context: no display, no OSMesa or EGL
            skip_unless_ci(f"cannot render here ({type(error).__name__}: {error}). {example.gl_advice()}")
    finally:
        env.close()
    assert isinstance(frame, np.ndarray)
    assert frame.shape == (example.HEIGHT, example.WIDTH, 3) and frame.dtype == np.uint8
    assert len(np.unique(frame.reshape(-1, 3), axis=0)) > 10, "the frame is (nearly) one colour"
    # The flap's orange shows above the water: some pixels far redder than blue.
    assert np.any((frame[..., 0].astype(int) - frame[..., 2].astype(int)) > 80)
