"""Mesh.equilibrium, Mesh.gz_curve and Mesh.hydrostatic_table against the box formulas, the
square-log rule, and Mesh.buoyancy at the poses they return."""

import math
import pathlib
import warnings

import numpy as np
import pytest

import buoyancy
from buoyancy import shapes

from conftest import run_examples

RHO, G = 1000.0, 9.81
LENGTH, DEPTH, BEAM = 4.0, 1.0, 2.0


def box() -> buoyancy.Mesh:
    """4 m long (x), 1 m deep (y, up), 2 m wide (z), about the origin."""
    return shapes.cube(2).scaled((LENGTH, DEPTH, BEAM))


@pytest.mark.parametrize("draft", [0.1, 0.25, 0.6])
def test_box_floats_at_its_draft(draft: float) -> None:
    mass = RHO * LENGTH * BEAM * draft
    rest = box().equilibrium(mass, (0, -0.2, 0))
    assert rest.draft == pytest.approx(draft, rel=1e-10)
    assert rest.heel == pytest.approx(0, abs=1e-9) and rest.trim == pytest.approx(0, abs=1e-9)
    assert rest.stable
    assert np.abs(rest.residual).max() < 1e-9
    assert rest.hydrostatics.displaced_volume == pytest.approx(mass / RHO, rel=1e-10)


def test_rest_is_where_mesh_buoyancy_balances_the_weight() -> None:
    """An offset center of mass heels the box; at the pose returned, Mesh.buoyancy (not the
    solver) gives a force equal to the weight and no torque about the center of mass."""
    mass, cog = 2400.0, np.array([0.3, -0.1, 0.15])
    mesh = box()
    rest = mesh.equilibrium(mass, cog)
    assert abs(rest.heel) > 1 and abs(rest.trim) > 0.1  # it did turn
    q = rest.rotation
    b = mesh.buoyancy(rest.position, q)
    x, y, z, w = q
    rotation = np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )
    g_world = rotation @ cog + rest.position
    weight = mass * G
    np.testing.assert_allclose(b.force, (0, weight, 0), rtol=0, atol=1e-8 * weight)
    torque = np.cross(b.center - g_world, b.force)
    assert np.abs(torque).max() < 1e-7 * weight * LENGTH


@pytest.mark.parametrize(
    ("density", "upright"),
    [(0.15, True), (0.5, False), (0.85, True), ((3 - math.sqrt(3)) / 6 + 0.03, False)],
)
def test_square_log_rule(density: float, upright: bool) -> None:
    """A square log of relative density s floats upright only for s < (3 - √3)/6 or
    s > (3 + √3)/6; otherwise corner-down, and the solver finds the stable attitude."""
    log = shapes.cube(2).scaled((3.0, 1.0, 1.0))
    rest = log.equilibrium(density * RHO * 3.0, (0, 0, 0))
    assert rest.stable
    heel = abs(rest.heel) % 90
    if upright:
        assert min(heel, 90 - heel) < 1e-6
    else:
        assert min(heel, 90 - heel) > 1.0
    if density == 0.5:
        assert heel == pytest.approx(45, abs=1e-6)


def test_gz_of_a_wall_sided_box_and_its_slope_is_gm() -> None:
    mass, kg = RHO * LENGTH * BEAM * 0.25, 0.5 - 0.1  # draft 0.25, G 0.1 below the center
    curve = box().gz_curve(mass, (0, -0.1, 0), heel_deg=[0, 1, 2, 4, 8, 12])
    kb, bm = 0.125, BEAM**2 / (12 * 0.25)
    gm = kb + bm - kg
    phi = np.radians(curve.heel)
    np.testing.assert_allclose(curve.gz, np.sin(phi) * (gm + bm * np.tan(phi) ** 2 / 2), rtol=0, atol=1e-9)
    np.testing.assert_allclose(curve.trim, 0, atol=1e-9)
    np.testing.assert_allclose(curve.draft[0], 0.25, rtol=1e-10)
    slope = curve.gz[1] / math.radians(1)
    assert slope == pytest.approx(gm, rel=1e-3)  # dGZ/dφ at upright is GM (O(φ²) off)
    assert curve.area == pytest.approx(np.trapezoid(curve.gz, phi), rel=1e-12)
    assert curve.positions.shape == (6, 3) and curve.rotations.shape == (6, 4)
    assert len(curve) == 6


def test_fixed_trim_is_held() -> None:
    curve = box().gz_curve(2000.0, (0.2, 0, 0), heel_deg=[0, 10], free_trim=False, trim_deg=1.5)
    np.testing.assert_allclose(curve.trim, 1.5, rtol=1e-12)
    free = box().gz_curve(2000.0, (0.2, 0, 0), heel_deg=[0, 10])
    assert abs(free.trim[0]) > 0.1  # G forward of the center trims the box


def test_table_of_a_box() -> None:
    drafts = [0.1, 0.25, 0.5, 0.9]
    table = box().hydrostatic_table(drafts, center_of_mass=(0, -0.1, 0))
    assert len(table) == 4
    d = np.array(drafts)
    np.testing.assert_allclose(table.draft, d, rtol=1e-12)
    np.testing.assert_allclose(table.displacement, RHO * LENGTH * BEAM * d, rtol=1e-12)
    np.testing.assert_allclose(table.kb, d / 2, rtol=1e-12)
    np.testing.assert_allclose(table.bm_transverse, BEAM**2 / (12 * d), rtol=1e-12)
    np.testing.assert_allclose(table.bm_longitudinal, LENGTH**2 / (12 * d), rtol=1e-12)
    np.testing.assert_allclose(table.tpc, RHO * LENGTH * BEAM / 1e5, rtol=1e-12)
    np.testing.assert_allclose(table.lcb, 0, atol=1e-12)
    np.testing.assert_allclose(table.lcf, 0, atol=1e-12)
    gm_l = d / 2 + LENGTH**2 / (12 * d) - 0.4
    np.testing.assert_allclose(table.mct, RHO * LENGTH * BEAM * d * gm_l / (100 * LENGTH), rtol=1e-10)
    assert table.columns[0] == "draft" and len(table.units) == len(table.columns)
    assert set(table.as_dict()) == set(table.columns)


@pytest.mark.parametrize(
    ("call", "error", "match"),
    [
        (lambda m: m.equilibrium(1e6, (0, 0, 0)), ValueError, "does not float"),
        (lambda m: m.equilibrium(0.0, (0, 0, 0)), ValueError, "^mass"),
        (lambda m: m.equilibrium(-5.0, (0, 0, 0)), ValueError, "^mass"),
        (lambda m: m.equilibrium(2000.0, (0, np.nan, 0)), ValueError, "^center_of_mass"),
        (lambda m: m.equilibrium(2000.0, (0, 0, 0), axis=(0, 1, 0)), ValueError, "^axis"),
        (lambda m: m.equilibrium(2000.0, (0, 0, 0), tolerance=0.5), ValueError, "^tolerance"),
        (
            lambda m: m.equilibrium(2000.0, (0.5, 0.3, 0.4), max_iterations=1, tolerance=1e-14),
            RuntimeError,
            "did not converge",
        ),
        (
            lambda m: m.equilibrium(2000.0, (0, 0, 0), water=buoyancy.Water(waves=buoyancy.AiryWave(0.1, 9.0))),
            ValueError,
            "^water",
        ),
        (lambda m: m.gz_curve(2000.0, (0, 0, 0), heel_deg=[10, 5]), ValueError, "^heel_deg"),
        (lambda m: m.gz_curve(2000.0, (0, 0, 0), heel_deg=[]), ValueError, "^heel_deg"),
        (lambda m: m.gz_curve(2000.0, (0, 0, 0), heel_deg=[[0, 1]]), ValueError, "^heel_deg"),
        (lambda m: m.gz_curve(2000.0, (0, 0, 0), heel_deg=[0, 5], trim_deg=1.0), ValueError, "^trim_deg"),
        (lambda m: m.hydrostatic_table([0.5, -0.1]), ValueError, r"^drafts\[1\]"),
        (lambda m: m.hydrostatic_table([np.nan]), ValueError, r"^drafts\[0\]"),
        (lambda m: m.hydrostatic_table([2.0]), ValueError, r"^drafts\[0\]"),
        (lambda m: m.hydrostatic_table([0.5], length=-1.0), ValueError, "^length"),
    ],
)
def test_errors_name_the_argument(call, error: type[Exception], match: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(error, match=match):
        call(box())


@pytest.mark.parametrize(
    "obj",
    [
        buoyancy.Mesh.equilibrium,
        buoyancy.Mesh.gz_curve,
        buoyancy.Mesh.hydrostatic_table,
        buoyancy.Mesh.close_openings,
        buoyancy.Equilibrium,
        buoyancy.GzCurve,
        buoyancy.HydrostaticTable,
    ],
    ids=lambda o: o.__qualname__,
)
def test_docstring_examples(obj: object) -> None:
    assert run_examples(obj.__doc__ or "", getattr(obj, "__qualname__", "?")) > 0


def holed_box() -> tuple[np.ndarray, np.ndarray]:
    """A unit cube (y up) without the upper half of its +x face: a planar hole in its side."""
    cube = shapes.cube(2)
    corners = cube.vertices[cube.faces]
    hole = np.all((corners[:, :, 0] == 0.5) & (corners[:, :, 1] >= 0.0), axis=1)
    return cube.vertices, cube.faces[~hole]


def test_open_hull_closed_by_a_lid() -> None:
    vertices, faces = holed_box()
    with pytest.raises(buoyancy.MeshError):
        buoyancy.Mesh(vertices, faces)
    hull = buoyancy.Mesh.close_openings(vertices, faces)
    assert len(hull.openings) == 1 and len(hull.openings[0]) == 6
    assert hull.volume == pytest.approx(1.0, rel=1e-12)
    assert hull.n_vertices == len(vertices) + 1 and hull.n_triangles == len(faces) + 6
    # Pickled as given and closed again; transformed copies keep their openings.
    import pickle

    copy = pickle.loads(pickle.dumps(hull))
    assert copy == hull and len(copy.openings) == 1
    moved = hull.translated((1.0, 2.0, 3.0))
    assert len(moved.openings) == 1 and pickle.loads(pickle.dumps(moved)) == moved
    # A closed mesh through close_openings is the plain mesh.
    closed = shapes.cube(2)
    assert buoyancy.Mesh.close_openings(closed.vertices, closed.faces) == closed


def test_water_reaching_an_opening() -> None:
    hull = buoyancy.Mesh.close_openings(*holed_box())
    rest = hull.equilibrium(300.0, (0, -0.2, 0), axis=(0, 0, 1))  # 0.3 m deep, the hole 0.2 m up
    assert rest.draft == pytest.approx(0.3, rel=1e-9)
    with pytest.raises(ValueError, match="opening"):
        hull.equilibrium(700.0, (0, -0.2, 0), axis=(0, 0, 1))  # would float 0.7 m deep
    with pytest.raises(ValueError, match="opening"):
        hull.hydrostatics((0, 0, 0), position=(0, -0.3, 0))
    # The waterplane: the unit square while the hole is dry, an error once the water reaches it.
    assert hull.waterplane(position=(0, 0.3, 0)).area == pytest.approx(1.0, rel=1e-12)
    with pytest.raises(ValueError, match="opening"):
        hull.waterplane(position=(0, -0.3, 0))
    heels = np.arange(0, 91, 5)
    one = hull.gz_curve(300.0, (0, -0.2, 0), heels, axis=(0, 0, 1))
    other = hull.gz_curve(300.0, (0, -0.2, 0), heels, axis=(0, 0, -1))
    flooded = one if one.flooding_angle is not None else other
    dry = other if flooded is one else one
    assert dry.flooding_angle is None and len(dry) == len(heels)
    # Wall-sided while the bottom is wet: the hole's lower edge meets the water at atan(0.2/0.5).
    assert math.degrees(math.atan(0.4)) <= flooded.flooding_angle < math.degrees(math.atan(0.4)) + 5
    assert flooded.heel.max() < flooded.flooding_angle


def test_cli_closes_openings(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    from buoyancy.stability import main

    vertices, faces = holed_box()
    path = tmp_path / "open.obj"
    path.write_text(
        "".join(f"v {x:.17g} {y:.17g} {z:.17g}\n" for x, y, z in vertices)
        + "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in faces)
    )
    args = [str(path), "--mass", "300", "--cog", "0", "-0.2", "0", "--up", "y", "--out", str(tmp_path)]
    assert main(args) == 2  # not closed
    assert "open" in capsys.readouterr().err
    printed = []
    for axis in ("--axis=z", "--axis=-z"):  # heeled one way, the hole goes under
        assert main([*args, axis, "--close-openings"]) == 0
        printed.append(capsys.readouterr().out)
    assert sum("the water reaches an opening at" in out for out in printed) == 1


def test_inputs_in_unlikely_units_are_warned_of() -> None:
    water = buoyancy.Water(density=1025.0, normal=(0, 0, 1))
    millimetres = buoyancy.shapes.cube().scaled((4000.0, 2000.0, 1000.0))
    with pytest.warns(UserWarning, match="units: the mesh spans 4.5826e3 m and holds 8.0000e9 m³") as caught:
        with pytest.raises(RuntimeError, match="did not converge.*; but first check the units: the mesh spans"):
            millimetres.equilibrium(3000.0, (0, 0, -200.0), water=water)
    assert any("multiply it by 1000; if the mesh is in millimetres" in str(w.message) for w in caught)
    box = buoyancy.shapes.cube().scaled((4.0, 2.0, 1.0))
    with pytest.warns(UserWarning, match=r"the water's density is 1.025 kg/m³: if it is in t/m³"):
        box.equilibrium(3.0, (0, 0, -0.2), water=buoyancy.Water(density=1.025, normal=(0, 0, 1)))
    with pytest.warns(UserWarning, match="heel_deg: the heels reach only 0.5°"):
        box.gz_curve(3000.0, (0, 0, -0.2), heel_deg=[0.0, 0.25, 0.5], water=water)
    # Plausible input: no warning.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        box.equilibrium(3000.0, (0, 0, -0.2), water=water)
        box.gz_curve(3000.0, (0, 0, -0.2), heel_deg=[0.0, 10.0], water=water)
