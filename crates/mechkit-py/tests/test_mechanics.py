"""The mechanics commands as functions: mechkit.potential, collide, impulse, com and inertia
return what `mechkit <command> ... --json` prints for the same input, the answers of
textbook cases exactly (equal masses exchange velocities in an elastic collision; a disk's
moment of inertia is M R²/2; a centred disk's centre of mass is its centre), and bad input
raises MechkitError with the command line's message, the argument named as in Python."""

import json
import math

import numpy as np
import pytest

import mechkit
from conftest import EXAMPLES, mechkit as mechkit_cli

DISK = EXAMPLES / "data" / "disk_r150.png"
BASEBALL = EXAMPLES / "data" / "baseballforce.d"
ROD = EXAMPLES / "bodies" / "rod_two_spheres.toml"


def cli_json(*args):
    """`mechkit ARGS... --json` as a dict."""
    return json.loads(mechkit_cli(*args, "--json").stdout)


def cli_error(*args):
    """The command line's message for bad input (exit status 2), without `error: `."""
    out = mechkit_cli(*args, check=False)
    assert out.returncode == 2, out
    assert out.stderr.startswith("error: ")
    return out.stderr[len("error: ") :].rstrip("\n")


def raises(call, *args, **kwargs):
    """The MechkitError `call(*args, **kwargs)` raises."""
    with pytest.raises(mechkit.MechkitError) as info:
        call(*args, **kwargs)
    return str(info.value)


# potential


LJ = "U0*((a/r)^12 - 2*(a/r)^6)"


def test_potential_is_the_commands_json():
    cli = cli_json(
        "potential", LJ, "--var", "r", "--range", "3 Å:10 Å",
        "--set", "U0=1 eV,a=3.4 Å", "--energy", "-0.5 eV", "--at", "4 Å, 5 Å",
    )  # fmt: skip
    py = mechkit.potential(
        LJ, "r", range=("3 Å", "10 Å"), U0="1 eV", a="3.4 Å",
        energy="-0.5 eV", at=["4 Å", "5 Å"],
    )  # fmt: skip
    assert py == cli
    # the units followed from the values given with units, as on the command line
    assert py["units"] == {"x": "m", "potential": "J"}
    [minimum] = py["equilibria"]
    assert minimum["stability"] == "stable"
    assert minimum["x"] == pytest.approx(3.4e-10, rel=1e-9)
    assert minimum["potential"] == pytest.approx(-1.602176634e-19, rel=1e-9)


def test_a_released_body_and_a_force_as_the_command():
    cli = cli_json(
        "potential", "--force", "-sin(2*pi*x)", "--range", "-1:2",
        "--mass", "1 kg", "--x0", "0", "--v0", "0.5",
    )  # fmt: skip
    py = mechkit.potential(force="-sin(2*pi*x)", range="-1:2", mass="1 kg", x0=0, v0=0.5)
    assert py == cli
    motion = py["motion"]
    assert motion["left_turn"] == pytest.approx(-motion["right_turn"], abs=1e-12)


def test_the_harmonic_well_exactly():
    r = mechkit.potential("k*x^2/2", range=(-2, 2), energy=4, k=2, table=True)
    assert r["force"] == "-k*x"
    assert r["parameters"] == {"k": 2.0}
    [well] = r["equilibria"]
    assert (well["x"], well["stability"]) == (0.0, "stable")
    # U = x² reaches E = 4 at x = ±2
    assert r["energy"]["turning_points"] == [-2.0, 2.0]
    table = r.pop("table")
    assert set(table) == {"x", "U", "F"}
    assert len(table["x"]) == 2001
    np.testing.assert_allclose(table["U"], table["x"] ** 2, rtol=0, atol=1e-12)
    np.testing.assert_allclose(table["F"], -2 * table["x"], rtol=0, atol=1e-12)
    assert r == mechkit.potential("k*x^2/2", range=(-2, 2), energy=4, k=2)


def test_a_potential_field():
    cli = cli_json(
        "potential", "k*(x^2 + y^2)/2", "--var", "x,y", "--set", "k=2", "--at", "0, 3; 1, 1"
    )
    py = mechkit.potential("k*(x^2 + y^2)/2", "x,y", k=2, at=[(0, 3), "1, 1"])
    assert py == cli
    assert py["force"] == ["-k*x", "-k*y"]
    assert py["at"][0]["force"] == [0.0, -6.0]
    assert mechkit.potential("k*(x^2 + y^2)/2", ("x", "y"), k=2, at="0, 3; 1, 1") == cli


def test_potential_errors_are_the_commands():
    assert raises(mechkit.potential, "x^2") == (
        "give the range to analyse, e.g. range=(0.8, 3) or range=\"-1:2\""
    )
    cli = cli_error("potential", "x^2", "--range", "2:-1")
    assert raises(mechkit.potential, "x^2", range=(2, -1)) == cli.replace("--range", "range")
    cli = cli_error("potential", "x^2", "--range", "0:1", "--mass", "-1 kg", "--x0", "0.5")
    assert raises(
        mechkit.potential, "x^2", range=(0, 1), mass="-1 kg", x0=0.5
    ) == cli.replace("--mass", "mass")
    cli = cli_error("potential", "k*x^2", "--range", "0:1")
    assert raises(mechkit.potential, "k*x^2", range=(0, 1)) == cli
    assert "kgz" in raises(mechkit.potential, "m*x", range=(0, 1), m="2 kgz")
    with pytest.raises(TypeError, match="range"):
        mechkit.potential("x^2", range={"a": 1})


# collide


def test_equal_masses_exchange_velocities():
    r = mechkit.collide(1, 2, 1, 0, restitution=1)
    assert r["collided"] is True
    assert (r["v1"], r["v2"]) == ([0.0], [2.0])
    assert r["kinetic_lost"] == 0.0
    assert r == cli_json("collide", "--m1", "1", "--v1", "2", "--m2", "1", "--v2", "0", "-e", "1")


def test_an_oblique_collision_with_friction_is_the_commands():
    cli = cli_json(
        "collide", "--m1", "0.2 kg", "--v1", "3 m/s, 0 m/s", "--m2", "300 g", "--v2", "0",
        "-e", "0.8", "--r1", "0, 0", "--r2", "1 m, 1 m", "--friction", "0.3", "--g", "9.81",
    )  # fmt: skip
    py = mechkit.collide(
        "0.2 kg", ["3 m/s", 0], "300 g", 0, restitution=0.8,
        r1="0, 0", r2=(1, 1), friction=0.3, g="9.81 m/s^2",
    )  # fmt: skip
    assert py == cli
    assert "rise1" in py and py["sticks"] in (True, False)


def test_a_wall_and_bodies_that_separate():
    r = mechkit.collide("2 kg", 4, "wall", 0, restitution=0.5)
    assert r["v1"] == [-2.0] and r["m2"] == "inf"
    assert mechkit.collide(2, 4, float("inf"), 0, restitution=0.5) == r
    apart = mechkit.collide(1, -1, 1, 1, restitution="elastic")
    assert apart == {"collided": False, "approach_speed": -2.0}


def test_collide_errors_are_the_commands():
    base = ["collide", "--m1", "1", "--v1", "2", "--m2", "1", "--v2", "0"]
    cli = cli_error(*base, "-e", "1.5")
    assert raises(mechkit.collide, 1, 2, 1, 0, restitution=1.5) == cli.replace(
        "--restitution", "restitution"
    )
    cli = cli_error("collide", "--m1", "1", "--v1", "2, 0", "--m2", "1", "--v2", "0", "-e", "1")
    message = raises(mechkit.collide, 1, [2, 0], 1, 0, restitution=1)
    assert message == cli.replace("--normal (or --r1 and --r2)", "normal (or r1 and r2)")
    cli = cli_error("collide", "--m1", "2 m", "--v1", "2", "--m2", "1", "--v2", "0", "-e", "1")
    assert raises(mechkit.collide, "2 m", 2, 1, 0, restitution=1) == cli.replace("--m1", "m1")
    with pytest.raises(TypeError, match="restitution"):
        mechkit.collide(1, 2, 1, 0, restitution=True)


# impulse


def test_impulse_of_a_file_is_the_commands():
    cli = cli_json("impulse", BASEBALL, "--mass", "0.145 kg", "--v0", "-40 m/s")
    py = mechkit.impulse(str(BASEBALL), mass="0.145 kg", v0="-40 m/s")
    assert py == cli
    assert py["impulse"] == py["integral"] and py["of"] == "time"


def test_impulse_of_arrays():
    t, f = np.loadtxt(BASEBALL, unpack=True)
    from_file = mechkit.impulse(BASEBALL, method="simpson", mass=0.145)
    from_arrays = mechkit.impulse(t=t, f=f, method="simpson", mass=0.145)
    assert from_arrays.pop("file") == "<arrays>"
    assert from_file.pop("file") == str(BASEBALL)
    assert from_arrays == from_file
    # a triangle pulse: J = 2 N·s exactly, Δv = J/m
    r = mechkit.impulse(t=[0, 1, 2], f=[0.0, 2.0, 0.0], mass="2 kg")
    assert (r["impulse"], r["mean_force"], r["delta_v"]) == (2.0, 1.0, 1.0)
    assert r["cumulative"] == [0.0, 1.0, 2.0]


def test_impulse_errors():
    cli = cli_error("impulse", BASEBALL, "--f", "3")
    assert raises(mechkit.impulse, BASEBALL, f=3) == cli.replace("--f", "f")
    cli = cli_error("impulse", BASEBALL, "--method", "spline")
    assert raises(mechkit.impulse, BASEBALL, method="spline") == cli.replace(
        "--method", "method"
    )
    message = raises(mechkit.impulse, t=[2, 1, 0], f=[1, 1, 1])
    assert "<arrays>" in message and "decreases" in message
    message = raises(mechkit.impulse, t=[0, 1, 2], f=[1, 1])
    assert message == "<arrays>: `F` has 2 values but `t` has 3; every column needs one value per row"
    assert "not a finite number" in raises(mechkit.impulse, t=[0, 1], f=[1, np.nan])
    assert "give a data file" in raises(mechkit.impulse, t=[0, 1])
    with pytest.raises(TypeError, match=r"shape \(1, 2\): give the samples as a 1-D array"):
        mechkit.impulse(t=[[0, 1]], f=[[1, 1]])


# com


def test_point_masses_are_the_commands():
    cli = cli_json(
        "com", "--mass", "5.972e24 kg", "--at", "0, 0", "--velocity", "0, 0",
        "--mass", "7.348e22 kg", "--at", "384400 km, 0", "--velocity", "0, 1.022 km/s",
        "--in", "6371 km",
    )  # fmt: skip
    py = mechkit.com(
        [("5.972e24 kg", (0, 0)), ("7.348e22 kg", "384400 km, 0")],
        velocities=["0, 0", [0, "1.022 km/s"]],
        unit="6371 km",
    )
    assert py == cli
    # 1 kg at 0 and 3 kg at 4 m: the centre at 3 m exactly
    assert mechkit.com([(1, 0), ("3 kg", "4 m")])["centre_of_mass"] == [3.0]


def disk_pixels():
    """The disk of examples/data/shapes.py: black where the pixel's centre is inside."""
    y, x = np.mgrid[0:400, 0:400] + 0.5
    inside = (x - 200) ** 2 + (y - 200) ** 2 < 150**2
    return np.where(inside, 0, 255).astype(np.uint8)


IMAGE_OPTIONS = {"pixel_size": "0.5 mm", "total_mass": "2 kg", "about": "0, 0"}


def test_an_image_file_is_the_commands():
    cli = cli_json(
        "com", DISK, "--pixel-size", "0.5 mm", "--total-mass", "2 kg", "--about", "0, 0"
    )
    py = mechkit.com(DISK, **IMAGE_OPTIONS)
    assert py == cli
    assert py["pixel_centre_of_mass"] == [200.0, 200.0]
    assert py["centre_of_mass"] == [0.1, 0.1]


def test_an_image_array_measures_as_its_file():
    from_file = mechkit.com(str(DISK), **IMAGE_OPTIONS)
    assert from_file.pop("file") == str(DISK)
    grey = disk_pixels()
    variants = {
        "grey uint8": grey,
        "grey int64": grey.astype(np.int64),
        "grey float": grey / 255.0,
        "rgb": np.repeat(grey[:, :, None], 3, axis=2),
        "rgb float32": np.repeat(grey[:, :, None], 3, axis=2).astype(np.float32) / 255,
        # an opaque black disk on a transparent background: composed on white
        "rgba": np.dstack([np.zeros_like(grey)] * 3 + [255 - grey]),
        # a view with strides: the same pixels
        "transposed twice": np.ascontiguousarray(grey.T).T,
    }
    for name, pixels in variants.items():
        r = mechkit.com(pixels, **IMAGE_OPTIONS)
        assert r.pop("file") == "<array>", name
        assert r == from_file, name


def test_image_options_and_mark(tmp_path):
    # a bright square on black, inverted, in pixels, its origin at the top-left corner
    img = np.zeros((40, 60, 3), dtype=np.uint8)
    img[10:20, 30:50] = (200, 40, 40)
    r = mechkit.com(img, channel="r", invert=True, origin=(0, 0), scale=(10, "1 cm"))
    assert r["pixel_centre_of_mass"] == [40.0, 15.0]
    assert r["centre_of_mass"] == pytest.approx([0.04, -0.015], abs=1e-15)
    assert (r["rule"], r["selected_pixels"]) == ("R ≥ 0.5", 200)
    mark = tmp_path / "marked.png"
    r = mechkit.com(img, channel="r", invert=True, mark=mark)
    assert r["mark"] == str(mark)
    assert mark.read_bytes().startswith(b"\x89PNG\r\n\x1a\n")


def test_a_body_file_is_the_commands():
    cli = cli_json("com", ROD, "--about", "0.5 m, 0, 0", "--total-mass", "4 kg")
    assert mechkit.com(ROD, about=("0.5 m", 0, 0), total_mass=4) == cli
    assert mechkit.com(text=ROD.read_text(), about="0.5 m, 0, 0", total_mass="4 kg") == cli


def test_com_errors():
    # the same message, with the arguments to change named as in Python
    cli = cli_error("com", DISK, "--threshold", "0")
    hint = '(threshold=; channel="sum", "r", "g" or "b"; invert=True for a bright body'
    cli = cli.replace(
        "(--threshold; --channel sum, r, g or b; --invert for a bright body", hint
    )
    assert raises(mechkit.com, DISK, threshold=0) == cli
    assert raises(mechkit.com, disk_pixels(), threshold=0) == cli.replace(str(DISK), "<array>")
    assert "velocities is for point masses" in raises(
        mechkit.com, DISK, velocities=[0]
    )
    assert "threshold applies to an image" in raises(mechkit.com, [(1, 0)], threshold=1)
    assert "from 0 to 1, not 255;" in raises(mechkit.com, disk_pixels().astype(float))
    assert "shape (400,) is not an image" in raises(mechkit.com, disk_pixels()[0])
    assert "pixel_size or scale, not both" in raises(
        mechkit.com, DISK, pixel_size=1, scale="1 px = 1 m"
    )
    cli = cli_error("com", "--mass", "1 kg", "--at", "0", "--mass", "2 kg", "--at", "1, 2")
    assert raises(mechkit.com, [(1, 0), (2, (1, 2))]) == cli.replace("--at", "body")
    with pytest.raises(TypeError, match="boolean mask|bool"):
        mechkit.com(disk_pixels() == 0)
    with pytest.raises(TypeError, match="pair"):
        mechkit.com([1, 2])


# inertia

DISK_BODY = """title = "a disk"
[[part]]
shape = "disk"
radius = "20 cm"
mass = "3 kg"
"""


def test_disk_inertia_and_the_parallel_axis():
    r = mechkit.inertia(text=DISK_BODY, about=("20 cm", 0, 0), axis=(0, 0, 1))
    m, radius = 3.0, 0.2
    assert r["inertia_cm"][2][2] == pytest.approx(m * radius**2 / 2, rel=1e-14)
    assert r["inertia_about"][2][2] == pytest.approx(1.5 * m * radius**2, rel=1e-14)
    assert r["axis"]["moment"] == pytest.approx(1.5 * m * radius**2, rel=1e-14)
    assert r["axis"]["radius_of_gyration"] == pytest.approx(math.sqrt(1.5) * radius)


def test_inertia_is_the_commands(tmp_path):
    args = ["--about", "0.5 m, 0, 0", "--axis", "0, 0, 1", "--in", "g*cm^2"]
    cli = cli_json("inertia", ROD, *args)
    py = mechkit.inertia(ROD, about="0.5 m, 0, 0", axis=[0, 0, 1], unit="g*cm^2")
    assert py == cli
    path = tmp_path / "disk.toml"
    path.write_text(DISK_BODY)
    assert mechkit.inertia(path, total_mass="6 kg") == cli_json(
        "inertia", path, "--total-mass", "6 kg"
    )


def test_inertia_errors(tmp_path):
    cli = cli_error("inertia", ROD, "--axis", "0, 0, 0")
    assert raises(mechkit.inertia, ROD, axis=(0, 0, 0)) == cli.replace("--axis", "axis")
    cli = cli_error("inertia", ROD, "--in", "kg")
    assert raises(mechkit.inertia, ROD, unit="kg") == cli.replace("--in", "unit")
    with pytest.raises(mechkit.ScenarioError) as info:
        mechkit.inertia(tmp_path / "nowhere.toml")
    assert info.value.kind == "io"
    with pytest.raises(mechkit.ScenarioError) as info:
        mechkit.inertia(text=DISK_BODY.replace('"3 kg"', '"3 kgz"'))
    assert info.value.line == 5
