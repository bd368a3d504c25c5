"""Run.plot: a plot drawn exactly as `mechkit run` draws it. The SVG is byte for byte the file
the console script writes for the same scenario and spec (a plot the scenario lists comes from
the run; another, such as the acceleration a(t) that no trajectory column holds, from the
scenario run again: the same points); the PNG is a PNG of the right size; a bad spec is the
scenario check's error."""

import struct
from pathlib import Path

import pytest

import mechkit
from conftest import EXAMPLES, mechkit as cli

FEATHER = EXAMPLES / "feather.toml"
SIGNATURE = b"\x89PNG\r\n\x1a\n"


def png_size(png):
    """(width, height) from the IHDR chunk, which follows the signature."""
    assert png[:8] == SIGNATURE
    length, kind, width, height = struct.unpack(">I4sII", png[8:24])
    assert kind == b"IHDR" and length == 13
    return width, height


def cli_plots(tmp_path, scenario_text, *flags):
    """Runs `mechkit run` on `scenario_text`; returns the output directory."""
    (tmp_path / "s.toml").write_text(scenario_text)
    cli("run", "s.toml", "-o", "out", "-q", *flags, cwd=tmp_path)
    return tmp_path / "out"


def with_plots(text, plots):
    """The scenario `text` with `[output] plots = plots`."""
    head, sep, _ = text.partition("plots = [")
    assert sep, "the scenario lists its plots"
    listed = ", ".join(f'"{p}"' for p in plots)
    return f"{head}plots = [{listed}]\n"


@pytest.fixture(scope="module")
def feather():
    return mechkit.Scenario.load(FEATHER).run()


def test_the_scenarios_plots_are_the_files_mechkit_run_writes(tmp_path, feather):
    out = cli_plots(tmp_path, FEATHER.read_text())
    listed = [("x(t)", "x_t"), ("v(t)", "v_t"), ("v(x)", "v_x"), ("energy(t)", "energy_t")]
    for spec, stem in listed:
        plot = feather.plot(spec)
        assert plot.file_stem == stem
        assert plot.svg == (out / f"{stem}.svg").read_text(), spec
        assert plot._repr_svg_() == plot.svg
        assert plot.spec == spec and plot.title == feather.summary["title"]


def test_a_plot_the_scenario_does_not_list_is_drawn_from_the_same_run(tmp_path, feather):
    # the acceleration is in no trajectory column: the scenario runs again, recording it
    text = with_plots(FEATHER.read_text(), ["a(t)", "energy-bars", "K(v)"])
    out = cli_plots(tmp_path, text)
    for spec, stem in [("a(t)", "a_t"), ("energy-bars", "energy-bars"), ("K(v)", "K_v")]:
        assert feather.plot(spec).svg == (out / f"{stem}.svg").read_text(), spec
    # the points are the run's: the acceleration at the last row is the terminal speed's ~0
    (curve,) = feather.plot("a(t)").series
    assert curve["label"] == "feather"
    assert len(feather) <= len(curve["x"]) == len(curve["y"]) <= len(feather) + 1
    assert abs(curve["y"][-1]) < 0.1 and abs(curve["y"][0] + 9.8) < 1e-12


def test_constants_given_to_run_are_those_of_the_plot(tmp_path):
    text = with_plots(FEATHER.read_text(), ["a(x)"])
    out = cli_plots(tmp_path, text, "--set", "Dmg=2 s^2/m^2")
    run = mechkit.Scenario.load(FEATHER).run(Dmg="2 s^2/m^2")
    assert run.plot("a(x)").svg == (out / "a_x.svg").read_text()
    assert run.plot("a(x)").svg != mechkit.Scenario.load(FEATHER).run().plot("a(x)").svg


def test_slides_style(tmp_path, feather):
    out = cli_plots(tmp_path, FEATHER.read_text(), "--style", "slides")
    slides = feather.plot("v(t)", style="slides")
    assert slides.style == "slides"
    assert slides.svg == (out / "v_t.svg").read_text()
    assert slides.svg != feather.plot("v(t)").svg
    with pytest.raises(ValueError, match='style must be "paper" or "slides"'):
        feather.plot("v(t)", style="poster")


def test_png_is_the_commands_png_of_the_right_size(tmp_path, feather):
    out = cli_plots(tmp_path, FEATHER.read_text(), "--format", "png", "--dpi", "96")
    plot = feather.plot("v(x)")
    png = plot.png(dpi=96)
    assert png_size(png) == (900, 600)
    assert png == (out / "v_x.png").read_bytes()
    assert png_size(plot.png()) == (1800, 1200)
    assert png_size(plot._repr_png_()) == (1800, 1200)
    with pytest.raises(ValueError, match="dpi must be from 24 to 1200"):
        plot.png(dpi=10)


def test_save_by_extension(tmp_path, feather):
    plot = feather.plot("energy(t)")
    plot.save(tmp_path / "e.svg")
    assert (tmp_path / "e.svg").read_text() == plot.svg
    plot.save(str(tmp_path / "e.PNG"), dpi=48)
    assert png_size((tmp_path / "e.PNG").read_bytes()) == (450, 300)
    with pytest.raises(ValueError, match=r"give a path ending in \.svg or \.png"):
        plot.save(tmp_path / "e.pdf")
    with pytest.raises(OSError, match="cannot write"):
        plot.save(tmp_path / "no" / "such" / "dir.svg")
    assert sorted(p.name for p in Path(tmp_path).iterdir()) == ["e.PNG", "e.svg"]


@pytest.mark.parametrize("spec", ["w(t)", "v of t", "energy-barz"])
def test_a_bad_spec_is_the_scenario_checks_error(feather, spec):
    with pytest.raises(mechkit.ScenarioError) as info:
        feather.plot(spec)
    with pytest.raises(mechkit.ScenarioError) as check:
        mechkit.Scenario.from_str(with_plots(FEATHER.read_text(), [spec]))
    error = info.value
    assert isinstance(error, mechkit.MechkitError)
    assert error.message == check.value.message and spec in error.message
    assert error.hint == check.value.hint
    assert error.kind == "invalid" and error.line is None
    assert str(error) == f"{error.message}\n  = hint: {error.hint}"


def test_a_bad_spec_lists_what_a_plot_is(feather):
    with pytest.raises(mechkit.ScenarioError) as info:
        feather.plot("v of t")
    assert '"energy-bars" draws the energy ledger as bars' in info.value.hint
    with pytest.raises(mechkit.ScenarioError) as info:
        feather.plot("vv(t)")
    assert "did you mean `v`" in info.value.hint


def test_plot_repr(feather):
    assert repr(feather.plot("energy(t)")) == '<mechkit.Plot "energy(t)": 5 curves>'
    assert repr(feather.plot("energy-bars")).startswith('<mechkit.Plot "energy-bars": ')
