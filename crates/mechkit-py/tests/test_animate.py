"""Run.animate(): the run's animation, the same value `mechkit animate` draws (the HTML
players are byte for byte equal), shown inline by Jupyter and saved as GIF or HTML."""

import pytest

import mechkit
from conftest import EXAMPLES, mechkit as cli


@pytest.fixture(scope="module")
def ball():
    return mechkit.Scenario.load(str(EXAMPLES / "bouncing_ball_floor.toml")).run()


def test_the_animation_has_frames_at_the_frame_rate(ball):
    a = ball.animate(fps=20, speed=1.0)
    times = a.times
    assert len(a) == len(times) >= 20
    assert a.fps == 20
    t_end = ball.summary["t_end"]
    assert times[0] == 0 and abs(times[-1] - t_end) < 1e-12
    steps = [b - a for a, b in zip(times, times[1:])]
    assert max(steps) - min(steps) < 1e-9
    # 4.06 s of run at real time, 20 frames per second
    assert len(a) == 83


def test_the_html_player_is_self_contained_and_equals_the_commands(ball, tmp_path):
    a = ball.animate()
    html = a._repr_html_()
    assert "http://" not in html and "https://" not in html
    assert 'id="slider"' in html and 'id="play"' in html
    cli("animate", EXAMPLES / "bouncing_ball_floor.toml", "--format", "html", "--out", tmp_path, "-q")
    assert (tmp_path / "animation.html").read_text() == html


def test_save_writes_gif_and_html(ball, tmp_path):
    a = ball.animate(width=320, height=240)
    gif = a.save(tmp_path / "ball.gif")
    assert (tmp_path / "ball.gif").read_bytes()[:6] == b"GIF89a"
    assert str(gif).endswith("ball.gif")
    a.save(tmp_path / "ball.html")
    assert (tmp_path / "ball.html").read_text() == a.html
    assert a.gif()[:6] == b"GIF89a"


def test_save_names_the_formats(ball, tmp_path):
    with pytest.raises(mechkit.MechkitError, match=r"\.gif, \.html or \.mp4"):
        ball.animate().save(tmp_path / "ball.png")


def test_options_out_of_range_are_errors(ball):
    with pytest.raises(mechkit.MechkitError, match="frame rate"):
        ball.animate(fps=0)
