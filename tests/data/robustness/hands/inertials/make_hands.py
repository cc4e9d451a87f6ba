#!/usr/bin/python3
"""Writes the parallel gripper with broken links, for the physics bad-state cases.

    /usr/bin/python3 tests/data/robustness/hands/inertials/make_hands.py

From the shipped assets/hands/parallel_gripper: every <mass>/<inertia> of the fingers set to
zero (zero.urdf), to nan (nan.urdf), or to 1e-6 kg / 1e-12 kg m^2 (light.urdf), and the fingers
without any geometry (bare.urdf: no collider, so Bullet never solves their joints' rows); each
with a hand description of the same name (parallel_gripper), so the robustness plans apply.
Standard library only.
"""
import os
import re

here = os.path.dirname(os.path.abspath(__file__))
shipped = os.path.join(here, "../../../../../assets/hands/parallel_gripper")


def finger_inertials(urdf, mass, inertia):
    def edit(m):
        link = m.group(0)
        if 'name="gripper_base"' in link:
            return link
        link = re.sub(r'<mass value="[^"]*"/>', '<mass value="%s"/>' % mass, link)
        diagonal = lambda a: '%s="%s"' % (a.group(1), inertia if a.group(1)[1] == a.group(1)[2]
                                                else "0")
        return re.sub(r'(i[xyz]{2})="[^"]*"', diagonal, link)
    return re.sub(r"<link .*?</link>", edit, urdf, flags=re.S)


def bare_fingers(urdf):
    def edit(m):
        link = m.group(0)
        if 'name="gripper_base"' in link:
            return link
        return re.sub(r"<(visual|collision)>.*?</\1>", "", link, flags=re.S)
    return re.sub(r"<link .*?</link>", edit, urdf, flags=re.S)


def main():
    urdf = open(os.path.join(shipped, "parallel_gripper.urdf")).read()
    yaml = open(os.path.join(shipped, "parallel_gripper.yaml")).read()
    variants = {name: finger_inertials(urdf, mass, inertia)
                for name, mass, inertia in [("zero", "0", "0"), ("nan", "nan", "nan"),
                                            ("light", "1e-6", "1e-12")]}
    variants["bare"] = bare_fingers(urdf)
    for name, text in variants.items():
        with open(os.path.join(here, name + ".urdf"), "w") as f:
            f.write(text)
        with open(os.path.join(here, name + ".yaml"), "w") as f:
            f.write(yaml.replace("urdf: parallel_gripper.urdf", "urdf: %s.urdf" % name))


if __name__ == "__main__":
    main()
