import numpy as np
import pytest

import cordgrasp


@pytest.fixture(scope="module")
def plan(mug, hand):
    return cordgrasp.plan(mug, hand, seed=3)


def test_validate_returns_the_sim_document(plan):
    sim = cordgrasp.validate(plan, tests="lift")
    assert sim["format"] == "cordgrasp-sim" and len(sim["grasps"]) == 1
    result = sim["grasps"][0]
    assert result["outcome"] in ("held", "slipped", "dropped", "unstable")
    assert [p["name"] for p in result["phases"]][:3] == ["settle", "close", "lift"]


def test_validate_is_deterministic_and_counts_trials(plan):
    a = cordgrasp.validate(plan, tests="lift", trials=2)
    b = cordgrasp.validate(plan, tests="lift", trials=2, jobs=2)
    assert a["grasps"][0]["trials"] == b["grasps"][0]["trials"]
    assert len(a["grasps"][0]["trials"]["outcomes"]) == 2
    with pytest.raises(ValueError, match="unknown name 'slow'"):
        cordgrasp.validate(plan, protocol="slow")


def test_validate_reads_a_physics_settings_file(plan, tmp_path):
    settings = tmp_path / "physics.yaml"
    settings.write_text("solver_iterations: 40\nlift_height_m: 0.05\n")
    sim = cordgrasp.validate(plan, tests="lift", physics=str(settings))
    assert sim["parameters"]["solver_iterations"] == 40
    assert sim["parameters"]["lift_height_m"] == 0.05
    settings.write_text("solver_iterations: 0\n")
    with pytest.raises(cordgrasp.InputError, match="solver_iterations"):
        cordgrasp.validate(plan, tests="lift", physics=str(settings))


def test_render_array_and_png(plan):
    image = cordgrasp.render(plan, width=160, height=120)
    assert image.shape == (120, 160, 4) and image.dtype == np.uint8
    assert (image[..., :3] < 200).any() and (image[..., :3] > 250).any()  # drawing on white
    png = cordgrasp.render(plan, width=160, height=120, png=True)
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(IndexError):
        cordgrasp.render(plan, grasp=5)
