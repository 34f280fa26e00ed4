"""buoyancy.mujoco: MuJoCo bodies that float.

Each test builds its model from MJCF text. Physics against closed forms (a flat box at its
theoretical draft, the heel of an off-centre center of mass from the wall-sided formula, a sphere
at its analytic cap height), against the core (a mesh asset hull at the core's equilibrium, one
``apply`` equal to ``Mesh.buoyancy`` at that pose), and the adapter's books (the application's
own ``xfrc_applied`` kept, bad input leaving ``data`` untouched).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

import buoyancy

from conftest import quaternion_matrix, skip_unless_ci

try:
    import mujoco
except ImportError as error:  # not installed, or installed but not loadable here
    skip_unless_ci(f"mujoco cannot be imported ({error}); pip install 'buoyancy[mujoco]' (scripts/test.sh does)")
import buoyancy.mujoco
from buoyancy.mujoco import FloatingBodies, geom_parts

RHO, G = 1000.0, 9.81


def model_of(bodies: str, *, timestep: float = 0.002, assets: str = "", options: str = "") -> Any:
    """A model of the ``bodies`` (MJCF) in a world with no floor."""
    return mujoco.MjModel.from_xml_string(
        f"""<mujoco><option timestep="{timestep}" {options}/><asset>{assets}</asset>
        <worldbody>{bodies}</worldbody></mujoco>"""
    )


def run(water: FloatingBodies, data: Any, seconds: float) -> None:
    end = data.time + seconds
    while data.time < end:
        water.step(data)


def tilt_deg(data: Any, body: str) -> float:
    """The angle of the body's z axis from the world's, degrees."""
    z = data.body(body).xmat.reshape(3, 3)[:, 2]
    return math.degrees(math.acos(min(1.0, abs(float(z[2])))))


def test_flat_box_floats_at_its_theoretical_draft() -> None:
    # 2 m × 1 m × 0.5 m, density 400: draft 0.4·0.5 = 0.2 m, its center 0.25 − 0.2 = 0.05 m above the surface.
    model = model_of(
        '<body name="box" pos="0 0 0.6"><freejoint/><geom type="box" size="1 0.5 0.25" density="400"/></body>'
    )
    data = mujoco.MjData(model)
    water = FloatingBodies.for_model(model)
    water.register("box")
    run(water, data, 20.0)
    assert data.body("box").xpos[2] == pytest.approx(0.05, abs=1e-3)
    assert tilt_deg(data, "box") < 0.1
    report = water.report("box")
    assert report.submerged_volume == pytest.approx(0.2 * 2 * 1, rel=1e-3)
    assert report.outcome == "applied"


def test_sphere_at_the_analytic_cap_height() -> None:
    # Density 300: the cap under water holds 0.3 of the sphere, V = πh²(3r − h)/3.
    r, s = 0.4, 0.3
    h = float(np.roots([-math.pi / 3, math.pi * r, 0.0, -s * 4 / 3 * math.pi * r**3])[1].real)
    assert 0 < h < r
    model = model_of(
        f'<body name="ball" pos="0 0 0.5"><freejoint/><geom type="sphere" size="{r}" density="{s * RHO}"/></body>'
    )
    data = mujoco.MjData(model)
    water = FloatingBodies.for_model(model)
    water.register("ball")
    run(water, data, 15.0)
    assert data.body("ball").xpos[2] == pytest.approx(r - h, abs=2e-3)


def test_off_centre_center_of_mass_heels_as_the_wall_sided_formula() -> None:
    # A barge B = 1 m wide, 4 m long, 0.6 m high, 800 kg (draft T = 0.2 m), its center of mass
    # t = 0.05 m off the centreline at KG = 0.2 m: tan φ (GM + BM tan²φ / 2) = t (wall-sided,
    # exact while the deck edge stays dry and the bilge wet), GM = KB + BM − KG, BM = B²/(12 T).
    b, length, height, mass, t, kg = 1.0, 4.0, 0.6, 800.0, 0.05, 0.2
    draft = mass / (RHO * b * length)
    bm, kb = b * b / (12 * draft), draft / 2
    gm = kb + bm - kg
    tan = float(min(r.real for r in np.roots([bm / 2, 0.0, gm, -t]) if abs(r.imag) < 1e-12))
    expected = math.degrees(math.atan(tan))
    model = model_of(
        f"""<body name="barge" pos="0 0 0.3"><freejoint/>
        <inertial pos="0 {t} {kg - height / 2}" mass="{mass}" diaginertia="91 1091 1133"/>
        <geom type="box" size="{b / 2} {length / 2} {height / 2}" quat="0.7071068 0 0 0.7071068" mass="0"/></body>"""
    )
    data = mujoco.MjData(model)
    water = FloatingBodies.for_model(model)
    water.register("barge")
    run(water, data, 30.0)
    # The barge's length lies along x (the geom turned a quarter about z): it heels about x.
    y_axis = data.body("barge").xmat.reshape(3, 3)[:, 1]
    heel = math.degrees(math.atan2(-y_axis[2], y_axis[1]))
    assert abs(heel) == pytest.approx(expected, abs=0.005), f"heel {heel}° against {expected}°"
    # It also equals where place_at_rest puts it.
    rest = mujoco.MjData(model)
    water.place_at_rest("barge", rest)
    y_rest = rest.body("barge").xmat.reshape(3, 3)[:, 1]
    assert math.degrees(math.atan2(-y_rest[2], y_rest[1])) == pytest.approx(expected, abs=1e-6)


def wigley_assets() -> tuple[str, buoyancy.Mesh]:
    """A Wigley hull (z up) as an MJCF mesh asset, and the same hull as a buoyancy.Mesh."""
    hull = buoyancy.shapes.wigley_hull(4.0, 0.6, 0.25, 0.15, 31, 13)
    # The shape is y up: turn it to z up, keeping its length along x.
    turn = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
    hull = hull.transformed(np.block([[turn, np.zeros((3, 1))], [np.zeros((1, 3)), np.ones((1, 1))]]))
    vertices = " ".join(f"{v:.17g}" for v in hull.vertices.ravel())
    faces = " ".join(str(int(i)) for i in hull.faces.ravel())
    return f'<mesh name="wigley" vertex="{vertices}" face="{faces}"/>', hull


def test_mesh_asset_hull_settles_at_the_cores_equilibrium() -> None:
    assets, hull = wigley_assets()
    mass = 0.5 * RHO * hull.volume  # floats lighter than its design draft
    model = model_of(
        f"""<body name="hull" pos="0.3 -0.2 0.2" euler="4 -3 20"><freejoint/>
        <geom type="mesh" mesh="wigley" mass="{mass}"/></body>""",
        assets=assets,
    )
    data = mujoco.MjData(model)
    water = FloatingBodies.for_model(model)
    water.register("hull")
    # The geom's mesh is the asset as MuJoCo holds it (moved onto its inertia frame): placed by
    # its geom pos/quat it is the hull in the body frame again.
    ((mesh, position, quaternion),) = water.parts("hull")
    placed = mesh.vertices @ quaternion_matrix(quaternion).T + position
    assert np.abs(np.sort(placed, axis=0) - np.sort(hull.vertices, axis=0)).max() < 1e-5
    assert mesh.volume == pytest.approx(hull.volume, rel=1e-6)
    run(water, data, 40.0)
    equilibrium = hull.equilibrium(mass, data.body("hull").xipos - data.body("hull").xpos, water.water)
    rest = mujoco.MjData(model)
    water.place_at_rest("hull", rest)
    # Upright: the center of mass is on the centreline.
    assert tilt_deg(data, "hull") < 0.05
    assert data.body("hull").xpos[2] == pytest.approx(rest.body("hull").xpos[2], abs=1e-3)
    assert equilibrium.draft > 0
    assert water.report("hull").submerged_volume == pytest.approx(mass / RHO, rel=1e-3)


def test_hinged_flap_returns_upright() -> None:
    # A flap 1 m wide, 0.2 m thick, 3 m tall on a hinge 2 m under water, 0.3 as dense as water:
    # upright, its buoyancy (400 kg at 1 m up) outweighs its weight (180 kg at 1.5 m) about the
    # hinge; tilted 20°, it turns back, and the damping settles it.
    model = model_of(
        """<body name="flap" pos="0 0 -2"><joint name="hinge" type="hinge" axis="0 1 0"/>
        <geom type="box" size="0.1 0.5 1.5" pos="0 0 1.5" density="300"/></body>"""
    )
    data = mujoco.MjData(model)
    data.qpos[0] = math.radians(20)
    water = FloatingBodies.for_model(model)
    water.register("flap")
    run(water, data, 40.0)
    assert abs(math.degrees(data.qpos[0])) < 0.2
    assert abs(data.qvel[0]) < 1e-2


def test_ball_dropped_from_two_metres_neither_explodes_nor_tunnels() -> None:
    model = model_of('<body name="ball" pos="0 0 2"><freejoint/><geom type="sphere" size="0.3" density="500"/></body>')
    data = mujoco.MjData(model)
    water = FloatingBodies.for_model(model)
    water.register("ball")
    lowest, highest_after = 10.0, -10.0
    while data.time < 20.0:
        water.step(data)
        z = float(data.body("ball").xpos[2])
        assert math.isfinite(z)
        lowest = min(lowest, z)
        if data.time > 3.0:
            highest_after = max(highest_after, z)
    # Hits the water at about 6 m/s: it dives less than a metre, never jumps back to its drop
    # height, and ends floating half under water (density 500: its center at the surface).
    assert -1.0 < lowest < -0.1
    assert highest_after < 1.0
    assert data.body("ball").xpos[2] == pytest.approx(0.0, abs=2e-3)
    assert np.abs(data.qvel).max() < 1e-2


def test_buoy_heaves_with_a_long_swell() -> None:
    # A ball 0.5 m across, a tenth as dense as water, in a swell 20 m long and 0.2 m high, on a
    # vertical slide: over the last periods its heave has the wave's amplitude within 3 % and
    # its phase within 5° (the waves' time is data.time).
    amplitude, wavelength = 0.1, 20.0
    wave = buoyancy.AiryWave(amplitude, wavelength)
    omega = float(buoyancy.Waves([wave]).angular_frequencies(G)[0])
    model = model_of(
        """<body name="buoy" pos="0 0 0.05"><joint type="slide" axis="0 0 1"/>
        <geom type="sphere" size="0.25" density="100"/></body>""",
        timestep=0.005,
    )
    data = mujoco.MjData(model)
    water = FloatingBodies.for_model(model, water=buoyancy.Water(normal=(0, 0, 1), waves=wave))
    water.register("buoy")
    period = 2 * math.pi / omega
    run(water, data, 40.0 - 5 * period)
    times, heights = [], []
    while data.time < 40.0:
        water.step(data)
        times.append(data.time)
        heights.append(float(data.body("buoy").xipos[2]))
    t = np.array(times)
    basis = np.column_stack([np.cos(omega * t), np.sin(omega * t), np.ones_like(t)])
    (a, b, _), *_ = np.linalg.lstsq(basis, np.array(heights), rcond=None)
    heave, phase = math.hypot(a, b), math.degrees(math.atan2(b, a))
    assert abs(heave / amplitude - 1.0) < 0.03, f"heave {heave} m against {amplitude} m (phase {phase}°)"
    assert abs(phase) < 5.0, f"phase {phase}°"


def offset_body_model() -> Any:
    """A body of two boxes placed off its frame (turned, shifted) with an <inertial> off their
    centroid, on a free joint."""
    return model_of(
        """<body name="b" pos="0.1 -0.2 -0.15" quat="0.9 0.2 -0.3 0.25"><freejoint/>
        <inertial pos="0.05 0.1 -0.08" mass="450" diaginertia="40 55 70" quat="0.8 0.1 0.5 0.3"/>
        <geom type="box" size="0.5 0.3 0.2" pos="0.2 0 0.1" quat="0.95 0.1 0.2 -0.2" mass="0"/>
        <geom type="box" size="0.2 0.2 0.2" pos="-0.5 0.6 0" quat="0.7 0 0.7 0" mass="0"/></body>"""
    )


def test_one_apply_is_the_cores_buoyancy_at_that_pose() -> None:
    model = offset_body_model()
    data = mujoco.MjData(model)
    data.qvel[:] = [0.3, -0.2, 0.5, 0.4, -0.1, 0.2]
    mujoco.mj_forward(model, data)
    water = FloatingBodies.for_model(model, damping=buoyancy.DampingCoefficients.off())
    water.register("b")
    water.apply(data)
    body = data.body("b")
    com = np.array(body.xipos)
    assert np.linalg.norm(com - body.xpos) > 0.05
    quaternion = np.array(body.xquat)[[1, 2, 3, 0]]  # MuJoCo's (w, x, y, z)
    force, torque, volume = np.zeros(3), np.zeros(3), 0.0
    for mesh, position, part_quaternion in water.parts("b"):
        # The part's pose in the world: body ∘ part, written out with matrices.
        rotation = quaternion_matrix(quaternion) @ quaternion_matrix(part_quaternion)
        b = mesh.buoyancy(quaternion_matrix(quaternion) @ position + body.xpos, rotation, water.water, about=com)
        force, torque, volume = force + b.force, torque + b.torque, volume + b.volume
    assert 0.05 < volume < 0.2  # partly under water
    np.testing.assert_allclose(data.xfrc_applied[1, :3], force, rtol=1e-6, atol=1e-3)
    np.testing.assert_allclose(data.xfrc_applied[1, 3:], torque, rtol=1e-6, atol=1e-3)
    report = water.report("b")
    np.testing.assert_allclose(report.center_of_mass, com, atol=1e-12)
    np.testing.assert_allclose(report.buoyancy_force, force, rtol=1e-12)


def test_the_state_read_is_mujocos_own_velocity_and_mass() -> None:
    # The centre-of-mass velocity the adapter gathers from cvel equals mj_objectVelocity's; the
    # inverse mass of a body on a hinge is the compliance J·M⁻¹·Jᵀ, which for a hinge about y at
    # distance d below the center of mass has 1/I_hinge in its (y, y) angular entry.
    model = model_of(
        """<body name="free" pos="0 0 0" quat="0.9 0.3 0.2 0.1"><freejoint/><geom type="box" size="0.4 0.3 0.2" pos="0.3 0 0" density="500"/></body>
        <body name="flap" pos="3 0 -2"><joint type="hinge" axis="0 1 0"/><geom type="box" size="0.1 0.5 1.5" pos="0 0 1.5" density="500"/></body>"""
    )
    data = mujoco.MjData(model)
    data.qvel[:] = [0.3, -0.2, 0.5, 0.4, -0.1, 0.2, 0.7]
    mujoco.mj_forward(model, data)
    arrays = buoyancy.mujoco._Arrays(model, [1, 2])
    inverse_masses, inverse_inertias = arrays.inverse_mass_properties(data)
    velocity = np.zeros(6)
    mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_BODY, 1, velocity, 0)
    cvel = data.cvel[1]
    linear = cvel[3:] + np.cross(cvel[:3], data.xipos[1] - data.subtree_com[model.body_rootid[1]])
    np.testing.assert_allclose(linear, velocity[3:], atol=1e-12)
    np.testing.assert_allclose(inverse_masses[0], 1 / model.body_mass[1])
    flap_mass, d = model.body_mass[2], 1.5
    hinge_inertia = model.body_inertia[2][1] + flap_mass * d * d
    assert inverse_inertias[1][1, 1] == pytest.approx(1 / hinge_inertia, rel=1e-9)
    assert inverse_masses[1][0] == pytest.approx(d * d / hinge_inertia, rel=1e-9)
    assert abs(inverse_masses[1][2]) < 1e-12


def test_the_applications_own_forces_stay() -> None:
    model = model_of(
        '<body name="box" pos="0 0 0"><freejoint/><geom type="box" size="1 0.5 0.25" density="400"/></body>'
    )
    data = mujoco.MjData(model)
    water = FloatingBodies.for_model(model)
    water.register("box")
    own = np.array([30.0, -20.0, 10.0, 1.0, 2.0, -3.0])
    data.xfrc_applied[1] = own
    for _ in range(300):
        water.step(data)
        report = water.report("box")
        ours = np.concatenate(
            [report.buoyancy_force + report.damping_force, report.buoyancy_torque + report.damping_torque]
        )
        np.testing.assert_allclose(data.xfrc_applied[1] - ours, own, atol=2e-3)
    assert water.unregister("box", data)
    np.testing.assert_allclose(data.xfrc_applied[1], own, atol=2e-3)
    assert not water.unregister("box", data)
    assert "box" not in water and len(water) == 0


def test_zeroed_xfrc_applied_gets_the_whole_share_again() -> None:
    model = model_of(
        '<body name="box" pos="0 0 0"><freejoint/><geom type="box" size="1 0.5 0.25" density="400"/></body>'
    )
    data = mujoco.MjData(model)
    water = FloatingBodies.for_model(model)
    water.register("box")
    for _ in range(10):
        water.step(data)
    data.xfrc_applied[:] = 0.0  # what an application resetting its forces does
    water.step(data)
    report = water.report("box")
    np.testing.assert_allclose(data.xfrc_applied[1, :3], report.buoyancy_force + report.damping_force, rtol=1e-6)
    mujoco.mj_resetData(model, data)
    water.step(data)  # a fresh state: the kinematics computed, the share added whole
    assert data.xfrc_applied[1, 2] > 1000.0


def test_a_fresh_mjdata_can_apply_before_any_step() -> None:
    model = model_of(
        '<body name="box" pos="0 0 -0.05"><freejoint/><geom type="box" size="1 0.5 0.25" density="400"/></body>'
    )
    data = mujoco.MjData(model)
    water = FloatingBodies.for_model(model)
    water.register("box")
    water.apply(data)
    # Its bottom 0.3 m under water: 2 m × 1 m × 0.3 m displaced.
    assert data.xfrc_applied[1, 2] == pytest.approx(RHO * 0.6 * G, rel=1e-9)


def test_geoms_become_parts_with_the_solids_volumes() -> None:
    model = model_of(
        """<body name="b"><freejoint/>
        <geom type="box" size="0.1 0.2 0.3" pos="0 0 0"/>
        <geom type="sphere" size="0.2" pos="1 0 0"/>
        <geom type="ellipsoid" size="0.1 0.2 0.15" pos="2 0 0"/>
        <geom type="cylinder" size="0.2 0.3" pos="3 0 0"/>
        <geom type="capsule" size="0.1 0.25" pos="4 0 0" euler="0 90 0"/>
        <geom type="sphere" size="0.5" pos="0 0 0" contype="0" conaffinity="0"/></body>"""
    )
    parts = geom_parts(model, "b")
    volumes = [mesh.volume for mesh, _, _ in parts]
    exact = [
        0.2 * 0.4 * 0.6,
        4 / 3 * math.pi * 0.2**3,
        4 / 3 * math.pi * 0.1 * 0.2 * 0.15,
        math.pi * 0.2**2 * 0.6,
        math.pi * 0.1**2 * 0.5 + 4 / 3 * math.pi * 0.1**3,
    ]
    # The visual sphere (contype = conaffinity = 0) is left out, so nothing overlaps.
    np.testing.assert_allclose(volumes, exact, rtol=1e-12)
    # MuJoCo's own volume of the geoms (mass over density 1000) agrees: the visual sphere has
    # a mass too (its density is MuJoCo's default), though it displaces no water.
    visual = 4 / 3 * math.pi * 0.5**3
    np.testing.assert_allclose((sum(exact) + visual) * 1000.0, model.body_mass[1], rtol=1e-9)
    # Cylinders and capsules lie along the geom's z: the capsule turned 90° about y lies along x.
    mesh, position, quaternion = parts[4]
    placed = mesh.vertices @ quaternion_matrix(quaternion).T + position
    np.testing.assert_allclose(placed.max(axis=0) - placed.min(axis=0), [0.7, 0.2, 0.2], rtol=0.02)


def test_overlapping_geoms_are_refused_touching_ones_are_not() -> None:
    crossing = model_of(
        """<body name="cross"><freejoint/><geom name="long" type="box" size="1 0.1 0.1"/>
        <geom name="wide" type="box" size="0.1 1 0.1"/></body>"""
    )
    water = FloatingBodies.for_model(crossing)
    with pytest.raises(ValueError, match=r"'long'.*'wide' overlap.*mesh="):
        water.register("cross")
    assert len(water) == 0
    touching = model_of(
        """<body name="stack"><freejoint/><geom type="box" size="0.5 0.5 0.25" pos="0 0 0.25"/>
        <geom type="box" size="0.5 0.5 0.25" pos="0 0 -0.25"/><geom type="sphere" size="0.2" pos="0 0 0.7"/></body>"""
    )
    water = FloatingBodies.for_model(touching)
    water.register("stack")
    assert len(water.parts("stack")) == 3
    # The remedy works: one closed hull given as the mesh.
    water = FloatingBodies.for_model(crossing)
    water.register("cross", buoyancy.shapes.cuboid((1.0, 0.1, 0.1)))
    assert "cross" in water


def test_bad_input_is_a_clear_error_and_leaves_data_untouched() -> None:
    model = model_of(
        """<geom name="floor" type="plane" size="5 5 0.1"/>
        <body name="fixed" pos="0 0 1"><geom type="box" size="0.1 0.1 0.1"/></body>
        <body name="ground" pos="0 0 0"><freejoint/><geom type="hfield" hfield="terrain"/></body>
        <body name="box" pos="0 0 0"><freejoint/><geom type="box" size="0.5 0.5 0.2" density="400"/></body>""",
        assets='<hfield name="terrain" nrow="3" ncol="3" size="1 1 0.1 0.1"/>',
    )
    water = FloatingBodies.for_model(model)
    with pytest.raises(ValueError, match="no body named 'boat'.*box"):
        water.register("boat")
    with pytest.raises(ValueError, match="world body"):
        water.register(0)
    with pytest.raises(ValueError, match="'fixed' is fixed to the world"):
        water.register("fixed")
    with pytest.raises(ValueError, match="is a height field.*mesh="):
        water.register("ground")
    with pytest.raises(ValueError, match="id 9 is not in the model"):
        water.register(9)
    with pytest.raises(TypeError, match="body: expected"):
        water.register(1.5)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="mesh: expected"):
        water.register("box", mesh=3)  # type: ignore[arg-type]
    assert len(water) == 0
    water.register("box")
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    data.qvel[-6] = math.nan
    mujoco.mj_fwdVelocity(model, data)
    before = data.xfrc_applied.copy()
    with pytest.raises(ValueError, match="'box' has a pose or velocity that is not finite"):
        water.apply(data)
    np.testing.assert_array_equal(data.xfrc_applied, before)
    other = mujoco.MjData(model_of('<body><freejoint/><geom type="box" size="1 1 1"/></body>'))
    with pytest.raises(ValueError, match="data: made for another model"):
        water.apply(other)
    with pytest.raises(TypeError, match="data: expected a mujoco.MjData"):
        water.apply(model)
    with pytest.raises(TypeError, match="model: expected a mujoco.MjModel"):
        FloatingBodies(data)


def test_water_is_up_against_gravity_and_z_up_without_it() -> None:
    model = model_of('<body name="b"><freejoint/><geom type="box" size="1 1 1"/></body>')
    water = FloatingBodies.for_model(model)
    np.testing.assert_allclose(water.water.normal, [0, 0, 1])
    assert water.water.gravity == pytest.approx(G)
    model.opt.gravity = (0.0, 0.0, 0.0)
    np.testing.assert_allclose(FloatingBodies.for_model(model).water.normal, [0, 0, 1])
    model.opt.gravity = (0.0, -9.0, 0.0)
    np.testing.assert_allclose(FloatingBodies.for_model(model).water.normal, [0, 1, 0])


def test_module_docstring_example_runs() -> None:
    text = buoyancy.mujoco.__doc__
    assert text is not None
    code = text.split("Two lines make a model float::", 1)[1].split("What each geom becomes", 1)[0]
    lines = [line[4:] for line in code.splitlines() if line.strip()]
    scope: dict[str, Any] = {}
    exec(compile("\n".join(lines).replace("print(", "result = ("), "docstring", "exec"), scope)
    assert scope["result"][2] == pytest.approx(0.0, abs=2e-3)
