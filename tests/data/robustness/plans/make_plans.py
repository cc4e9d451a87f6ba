#!/usr/bin/python3
"""Writes the plan.json corpus of the robustness suite from one valid plan.

    cordgrasp plan --hand parallel_gripper --object box --grasps 1 -q --out /tmp/base.json
    /usr/bin/python3 tests/data/robustness/plans/make_plans.py /tmp/base.json

valid.json is that plan with its region dropped (smaller) and the inputs named, not given as
absolute paths (the cases pass --hand parallel_gripper --object box); every other file breaks
it in one place. Standard library only.
"""
import copy
import json
import os
import sys


def main():
    base = json.load(open(sys.argv[1]))
    base["grasps"] = base["grasps"][:1]
    base["grasps"][0].pop("region", None)
    base["inputs"]["hand"].update({"path": "parallel_gripper", "urdf_path": ""})
    base["inputs"]["object"]["path"] = "box"
    here = os.path.dirname(os.path.abspath(__file__))

    def write(name, edit):
        plan = copy.deepcopy(base)
        edit(plan)
        with open(os.path.join(here, name), "w") as f:
            json.dump(plan, f, indent=1, allow_nan=False)
            f.write("\n")

    g = lambda p: p["grasps"][0]
    write("valid.json", lambda p: None)
    write("hand_far.json", lambda p: g(p)["hand_pose"]["position_m"].__setitem__(0, 1e300))
    write("zero_quaternion.json",
          lambda p: g(p)["hand_pose"].update({"quaternion_wxyz": [0, 0, 0, 0]}))
    write("joint_outside_limits.json",
          lambda p: g(p)["joints"].update({"left_finger_joint": 0.5}))
    write("unknown_joint.json", lambda p: g(p)["joints"].update({"elbow": 0.1}))
    write("unknown_link.json", lambda p: g(p)["contacts"][0].update({"link": "thumb_tip"}))
    # NaN as null: what plan --mu nan used to write.
    write("mu_null.json",
          lambda p: p["parameters"]["quality"]["contact"].update({"mu": None}))
    write("position_null.json",
          lambda p: g(p)["gcp_pose"]["position_m"].__setitem__(1, None))
    # Wrong JSON types.
    write("epsilon_string.json", lambda p: g(p).update({"epsilon": "high"}))
    write("joint_string.json", lambda p: g(p)["joints"].update({"left_finger_joint": "0.02"}))
    write("grasps_object.json", lambda p: p.update({"grasps": {"0": g(p)}}))
    write("contacts_number.json", lambda p: g(p).update({"contacts": 2}))
    write("seed_string.json", lambda p: p["parameters"].update({"seed": "1"}))
    # Physics bad states: objects of 0.1 mm and 10 m (the 5 x 5 x 8 cm box scaled), degenerate
    # meshes, a hand 1 m from the object, fingers with broken inertials (relative paths: from
    # this folder).
    write("object_0.1mm.json", lambda p: p["inputs"]["object"].update({"scale": 0.002}))
    write("object_10m.json", lambda p: p["inputs"]["object"].update({"scale": 125.0}))
    write("object_one_triangle.json",
          lambda p: p["inputs"]["object"].update({"path": "../meshes/one_triangle.obj"}))
    write("object_collinear.json",
          lambda p: p["inputs"]["object"].update({"path": "../meshes/collinear.obj"}))
    write("hand_1m_away.json",
          lambda p: g(p)["hand_pose"]["position_m"].__setitem__(
              0, g(p)["hand_pose"]["position_m"][0] + 1.0))
    for name in ["zero", "nan", "light", "bare"]:
        write("inertials_%s.json" % name, lambda p, n=name: p["inputs"]["hand"].update(
            {"path": "../hands/inertials/%s.yaml" % n}))
    with open(os.path.join(here, "truncated.json"), "w") as f:
        f.write(json.dumps(base, indent=1)[:300])


if __name__ == "__main__":
    main()
