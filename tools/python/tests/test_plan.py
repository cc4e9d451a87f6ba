import json
import time

import numpy as np
import pytest

import cordgrasp
from conftest import run


def strip_timings(doc):
    """plan.json without wall-clock figures."""
    doc = json.loads(json.dumps(doc))
    for key in list(doc["stats"]):
        if key.endswith("_s"):
            del doc["stats"][key]
    for g in doc["grasps"]:
        del g["timings_s"]
    return doc


def test_plan_matches_cli_with_same_seed(mug, hand, cli, tmp_path):
    out = tmp_path / "plan.json"
    run(cli, "plan", "--object", "mug", "--seed", "3", "--grasps", "2", "--out", str(out))
    from_cli = json.loads(out.read_text())
    plan = cordgrasp.plan(mug, hand, seed=3, grasps=2)
    assert len(plan.grasps) == 2
    assert strip_timings(plan.to_dict()) == strip_timings(from_cli)


def test_jobs_do_not_change_the_plan(mug, hand):
    one = cordgrasp.plan(mug, hand, seed=3, grasps=2, jobs=1)
    two = cordgrasp.plan(mug, hand, seed=3, grasps=2, jobs=2)
    assert strip_timings(one.to_dict()) == strip_timings(two.to_dict())


def test_grasps_are_numpy_objects(mug, hand):
    plan = cordgrasp.plan(mug, hand, seed=3)
    g = plan.grasps[0]
    assert g.hand_pose.shape == (4, 4) and g.gcp_pose.shape == (4, 4)
    np.testing.assert_allclose(g.hand_pose[3], [0, 0, 0, 1])
    rotation = g.hand_pose[:3, :3]
    np.testing.assert_allclose(rotation @ rotation.T, np.eye(3), atol=1e-9)
    assert set(g.joints) == set(hand.joint_names)
    assert g.force_closure and g.epsilon > 0
    assert len(g.contacts) >= 2
    assert all(c.link in hand.link_names for c in g.contacts)
    assert all(abs(np.linalg.norm(c.normal) - 1) < 1e-9 for c in g.contacts)


def test_keyword_defaults_are_the_cpp_defaults(mug, hand):
    defaults = cordgrasp.plan_parameters()
    assert defaults["planner"] == "cord"
    assert defaults["grasps"] == 1 and defaults["seed"] == 1
    assert defaults["xi_min_m"] == 0.015 and defaults["mu"] == 0.5
    assert defaults["soft_finger_radius_m"] is None
    plan = cordgrasp.plan(mug, hand, sets=5, mu=0.6)
    assert plan.parameters["cord"]["sets"] == 5
    assert plan.parameters["quality"]["contact"]["mu"] == 0.6


def test_every_keyword_reaches_the_plan_parameters(mug, hand):
    params = cordgrasp.plan(mug, hand, max_attempts=50, close_step=0.03).parameters
    flat = set()

    def walk(d):
        for k, v in d.items():
            flat.add(k)
            if isinstance(v, dict):
                walk(v)

    walk(params)
    assert params["max_attempts"] == 50 and params["finger"]["close_step"] == 0.03
    # PlanJobParams' own fields (units and scale are applied by load_mesh and only recorded)
    top_level = {"planner", "units", "scale", "soft_finger_radius_m"}
    assert set(cordgrasp.plan_parameters()) - top_level <= flat


def test_generic_planner_and_bad_arguments(mug, hand):
    plan = cordgrasp.plan(mug, hand, planner="generic", seed=2)
    assert plan.planner == "generic" and plan.grasps[0].region_rank is None
    with pytest.raises(TypeError, match="unexpected keyword argument 'no_such'"):
        cordgrasp.plan(mug, hand, no_such=1)
    with pytest.raises(ValueError, match="planner: unknown name 'x'"):
        cordgrasp.plan(mug, hand, planner="x")
    with pytest.raises(ValueError, match="unknown name 'bogus'"):
        cordgrasp.plan(mug, hand, side_cord_policy="bogus")


def test_mesh_from_arrays_plans_like_the_file(mug, hand):
    same = cordgrasp.Mesh(mug.vertices, mug.faces, "mug")
    a = cordgrasp.plan(mug, hand, seed=3).grasps[0]
    b = cordgrasp.plan(same, hand, seed=3).grasps[0]
    np.testing.assert_array_equal(a.hand_pose, b.hand_pose)
    assert a.joints == b.joints


def test_errors_carry_the_cpp_message(tmp_path):
    with pytest.raises(cordgrasp.InputError, match="no such file, nor a shipped object"):
        cordgrasp.load_mesh(str(tmp_path / "missing.obj"))
    with pytest.raises(cordgrasp.InputError, match="no shipped hand of that name"):
        cordgrasp.load_hand("no_such_hand")
    with pytest.raises(ValueError, match="out of range"):
        cordgrasp.Mesh(np.zeros((3, 3)), np.array([[0, 1, 5]]))


def test_plan_json_round_trip(mug, hand, tmp_path):
    plan = cordgrasp.plan(mug, hand, seed=3)
    path = tmp_path / "plan.json"
    plan.write(str(path))
    back = cordgrasp.read_plan(str(path))
    assert back.to_dict() == plan.to_dict()
    np.testing.assert_array_equal(back.grasps[0].hand_pose, plan.grasps[0].hand_pose)


def test_read_plan_accepts_complete_incomplete_and_older_plans(mug, hand, tmp_path):
    doc = cordgrasp.plan(mug, hand, seed=3).to_dict()
    assert doc["complete"] is True
    path = tmp_path / "plan.json"
    for extra, expected in [({}, None), ({"complete": False, "interrupted": "SIGINT"}, "SIGINT")]:
        written = {k: v for k, v in doc.items() if k not in ("complete", "interrupted")}
        written.update(extra)  # without the keys: written before they existed
        path.write_text(json.dumps(written))
        back = cordgrasp.read_plan(str(path), hand)
        assert back.interrupted == expected
        assert len(back.grasps) == len(doc["grasps"])
        assert back.to_dict()["complete"] is (expected is None)


def test_call_overhead_is_small(mug, hand):
    """Wall time of cordgrasp.plan() minus the C++ plan job's, over the plan's total_s."""
    overheads = []
    for seed in (3, 4, 5):
        start = time.perf_counter()
        plan = cordgrasp.plan(mug, hand, seed=seed)
        wall = time.perf_counter() - start
        overheads.append((wall - plan.job_wall_s) / plan.stats["total_s"])
    print("overhead fractions", overheads)
    assert min(overheads) < 0.05


def test_assets_dir_is_the_source_tree_and_the_environment_overrides(monkeypatch, tmp_path):
    assert (cordgrasp.assets_dir().rstrip("/")).endswith("assets")
    monkeypatch.setenv("CORDGRASP_ASSETS_DIR", str(tmp_path))
    assert cordgrasp.assets_dir() == str(tmp_path)
    with pytest.raises(cordgrasp.InputError, match="no shipped hand"):
        cordgrasp.load_hand("cordgrasp_sah")


def test_plan_validated_keeps_only_grasps_that_held(mug, hand):
    assert cordgrasp.validation_parameters()["min_held"] == 2
    plan = cordgrasp.plan_validated(mug, hand, validation={"trials": 2, "min_held": 1},
                                    grasps=1, seed=1)
    assert plan.validation is not None
    stats = plan.validation["stats"]
    assert len(plan.grasps) == stats["accepted"] <= 1
    for g in plan.to_dict()["grasps"]:
        assert g["validation"]["held_trials"] >= 1
    with pytest.raises(TypeError):
        cordgrasp.plan_validated(mug, hand, validation={"no_such_key": 1})


def test_validate_tests_the_object_a_validated_plan_was_accepted_with(mug, hand):
    assert cordgrasp.validation_parameters()["mass_kg"] is None
    plan = cordgrasp.plan_validated(mug, hand, grasps=1, seed=1,
                                    validation={"trials": 1, "min_held": 1, "mass_kg": 0.05})
    assert plan.validation["parameters"]["physics"]["mass_kg"] == 0.05
    assert cordgrasp.validate(plan, tests="lift")["object"]["mass_kg"] == 0.05
    assert cordgrasp.validate(plan, tests="lift", mass_kg=0.07)["object"]["mass_kg"] == 0.07
