#!/usr/bin/env python3
"""Writes the URDFs of cordgrasp's own primitive hands (deterministic, standard library only).

    python3 tools/make_primitive_hands.py      # rewrites assets/hands/*/<name>.urdf

cordgrasp_sah    4-finger anthropomorphic hand modelled on the Schunk SAH (13 actuated DOF:
                 4 x abduction/proximal/middle + thumb opposition; distal = middle via <mimic>).
parallel_gripper 2-finger parallel gripper, 0-10 cm opening, second finger <mimic> of the first.

Collision geometry = boxes, cylinders and spheres; visuals are the same primitives with colours.
Masses are set per part; inertias are the solid-body tensors of each link's primitives (about the
link's centre of mass, parallel-axis theorem), so they are consistent with the geometry.
All lengths in meters, angles in radians.
"""
import math
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEG = math.pi / 180.0

# ------------------------------------------------------------------------------------------------
# small 3x3 helpers (no numpy)


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def transpose(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def rot_x(t):
    c, s = math.cos(t), math.sin(t)
    return [[1, 0, 0], [0, c, -s], [0, s, c]]


def rot_y(t):
    c, s = math.cos(t), math.sin(t)
    return [[c, 0, s], [0, 1, 0], [-s, 0, c]]


def rot_z(t):
    c, s = math.cos(t), math.sin(t)
    return [[c, -s, 0], [s, c, 0], [0, 0, 1]]


def rpy_of(r):
    """URDF rpy (R = Rz(yaw) Ry(pitch) Rx(roll)) of a rotation matrix."""
    pitch = math.asin(max(-1.0, min(1.0, -r[2][0])))
    if abs(math.cos(pitch)) > 1e-9:
        roll = math.atan2(r[2][1], r[2][2])
        yaw = math.atan2(r[1][0], r[0][0])
    else:  # gimbal lock: put everything in yaw
        roll = 0.0
        yaw = math.atan2(-r[0][1], r[1][1])
    return (roll, pitch, yaw)


def columns(x, y, z):
    return [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]


def fmt(v):
    s = "%.9g" % v
    return "0" if s in ("-0", "0") else s


def vec(v):
    return " ".join(fmt(x) for x in v)


# ------------------------------------------------------------------------------------------------
# parts: primitive shapes with mass, giving geometry XML and inertia


class Shape:
    def __init__(self, kind, dims, xyz=(0, 0, 0), rpy=(0, 0, 0), mass=0.0, rgba=None):
        self.kind, self.dims, self.xyz, self.rpy, self.mass = kind, dims, xyz, rpy, mass
        self.rgba = rgba

    def geometry_xml(self):
        if self.kind == "box":
            return '<box size="%s"/>' % vec(self.dims)
        if self.kind == "cylinder":
            return '<cylinder radius="%s" length="%s"/>' % (fmt(self.dims[0]), fmt(self.dims[1]))
        return '<sphere radius="%s"/>' % fmt(self.dims[0])

    def local_inertia(self):
        m = self.mass
        if self.kind == "box":
            x, y, z = self.dims
            d = [m * (y * y + z * z) / 12, m * (x * x + z * z) / 12, m * (x * x + y * y) / 12]
        elif self.kind == "cylinder":
            r, h = self.dims
            d = [m * (3 * r * r + h * h) / 12, m * (3 * r * r + h * h) / 12, m * r * r / 2]
        else:
            r = self.dims[0]
            d = [2 * m * r * r / 5] * 3
        return [[d[0], 0, 0], [0, d[1], 0], [0, 0, d[2]]]

    def rotation(self):
        roll, pitch, yaw = self.rpy
        return matmul(rot_z(yaw), matmul(rot_y(pitch), rot_x(roll)))


def link_inertial(shapes):
    """Mass, centre of mass and inertia about the COM (link axes) of a set of solid shapes."""
    m = sum(s.mass for s in shapes)
    com = [sum(s.mass * s.xyz[i] for s in shapes) / m for i in range(3)]
    inertia = [[0.0] * 3 for _ in range(3)]
    for s in shapes:
        r = s.rotation()
        i_rot = matmul(r, matmul(s.local_inertia(), transpose(r)))
        d = [s.xyz[i] - com[i] for i in range(3)]
        d2 = sum(x * x for x in d)
        for a in range(3):
            for b in range(3):
                inertia[a][b] += i_rot[a][b] + s.mass * ((d2 if a == b else 0.0) - d[a] * d[b])
    return m, com, inertia


class Urdf:
    def __init__(self, name, header):
        self.name, self.header = name, header
        self.links, self.joints = [], []

    def link(self, name, shapes):
        out = ['  <link name="%s">' % name]
        for s in shapes:
            out.append('    <visual>\n      <origin xyz="%s" rpy="%s"/>\n'
                       '      <geometry>%s</geometry>' % (vec(s.xyz), vec(s.rpy), s.geometry_xml()))
            out.append('      <material name="%s_%s"><color rgba="%s"/></material>\n    </visual>'
                       % (name, len(out), vec(s.rgba)))
        for s in shapes:
            out.append('    <collision>\n      <origin xyz="%s" rpy="%s"/>\n'
                       '      <geometry>%s</geometry>\n    </collision>'
                       % (vec(s.xyz), vec(s.rpy), s.geometry_xml()))
        m, com, i = link_inertial(shapes)
        out.append('    <inertial>\n      <origin xyz="%s" rpy="0 0 0"/>\n      <mass value="%s"/>'
                   % (vec(com), fmt(m)))
        out.append('      <inertia ixx="%s" ixy="%s" ixz="%s" iyy="%s" iyz="%s" izz="%s"/>'
                   % tuple(fmt(x) for x in (i[0][0], i[0][1], i[0][2], i[1][1], i[1][2], i[2][2])))
        out.append('    </inertial>\n  </link>')
        self.links.append("\n".join(out))

    def joint(self, name, kind, parent, child, xyz, rpy=(0, 0, 0), axis=None, limit=None,
              mimic=None):
        out = ['  <joint name="%s" type="%s">' % (name, kind),
               '    <parent link="%s"/>\n    <child link="%s"/>' % (parent, child),
               '    <origin xyz="%s" rpy="%s"/>' % (vec(xyz), vec(rpy))]
        if axis:
            out.append('    <axis xyz="%s"/>' % vec(axis))
        if limit:
            out.append('    <limit lower="%s" upper="%s" effort="%s" velocity="%s"/>'
                       % tuple(fmt(x) for x in limit))
        if mimic:
            out.append('    <mimic joint="%s" multiplier="%s" offset="%s"/>'
                       % (mimic[0], fmt(mimic[1]), fmt(mimic[2])))
        out.append('  </joint>')
        self.joints.append("\n".join(out))

    def write(self, path):
        text = ['<?xml version="1.0"?>', "<!-- %s -->" % self.header,
                '<robot name="%s">' % self.name] + self.links + self.joints + ["</robot>", ""]
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write("\n".join(text))


# ------------------------------------------------------------------------------------------------
# cordgrasp_sah

PALM_RGBA = (0.30, 0.32, 0.36, 1.0)
LINK_RGBA = (0.78, 0.80, 0.84, 1.0)
JOINT_RGBA = (0.45, 0.47, 0.52, 1.0)
PAD_RGBA = (0.12, 0.12, 0.12, 1.0)

# Palm frame: z from the wrist towards the fingers, x = palm normal (the palm faces +x), y lateral
# (index side +y; right hand). Dimensions scaled from the Schunk SAH to ~0.8x (fingers ~10 cm).
PALM_SIZE = (0.030, 0.090, 0.090)      # thickness x width x length [m]
FINGER_BASE_Z = 0.100                 # abduction/proximal joints [m] (1 cm above the palm top)
FINGER_Y = {"index": 0.030, "middle": 0.0, "ring": -0.030}
PROX_LEN, MID_LEN, DIST_LEN = 0.050, 0.028, 0.020   # joint-to-joint / distal body length [m]
TIP_RADIUS = 0.0085                   # distal fingertip sphere [m]
PHAL_T, PHAL_W = 0.018, 0.020         # phalanx thickness (flexion direction) and width [m]
KNUCKLE_R = 0.009                     # knuckle sphere at the abduction/proximal joint [m]
GAP = 0.001                           # clearance between adjacent bodies [m]

# Joint ranges of the SAH (Simox SAH_RightHand.xml): abduction +-15 deg, proximal -4..75 deg,
# middle/distal 4..75 deg (distal coupled 1:1 to middle in the real hand).
ABD = (-15 * DEG, 15 * DEG)
PROX = (-4 * DEG, 75 * DEG)
MID = (4 * DEG, 75 * DEG)
# Effort [N m] and velocity [rad/s] limits, of the order of the SAH's (~2 N m at the base joint).
EFF_ABD, EFF_PROX, EFF_MID, EFF_DIST, EFF_OPP = 1.0, 2.0, 1.2, 0.8, 2.0
VEL_ABD, VEL_FLEX, VEL_OPP = 1.5, 2.5, 1.0
# Masses [kg]: whole hand ~1.25 kg.
M_PALM, M_METACARPAL, M_KNUCKLE, M_PROX, M_MID, M_DIST, M_TIP = 0.560, 0.080, 0.015, 0.055, \
    0.032, 0.016, 0.008

THUMB_A = (PALM_SIZE[0] / 2, 0.015, 0.066)   # thumb opposition joint on the palm front [m]
METACARPAL_LEN = 0.045                       # opposition joint to thumb base joint [m]
THUMB_TILT = 50 * DEG                        # opposed thumb: from +z towards +x (palm normal)


def finger_chain(u, prefix, parent, xyz, rpy):
    """abduction (axis x) + proximal, middle (axis y) + distal (<mimic> of middle); the finger
    points along its local +z and closes towards its local +x."""
    u.joint(prefix + "_abduction", "revolute", parent, prefix + "_knuckle", xyz, rpy, (1, 0, 0),
            (ABD[0], ABD[1], EFF_ABD, VEL_ABD))
    u.link(prefix + "_knuckle", [Shape("sphere", (KNUCKLE_R,), mass=M_KNUCKLE, rgba=JOINT_RGBA)])
    u.joint(prefix + "_proximal", "revolute", prefix + "_knuckle", prefix + "_proximal_link",
            (0, 0, 0), (0, 0, 0), (0, 1, 0), (PROX[0], PROX[1], EFF_PROX, VEL_FLEX))
    z0 = KNUCKLE_R + GAP
    u.link(prefix + "_proximal_link",
           [Shape("box", (PHAL_T, PHAL_W, PROX_LEN - z0 - GAP), (0, 0, (z0 + PROX_LEN - GAP) / 2),
                  mass=M_PROX, rgba=LINK_RGBA)])
    u.joint(prefix + "_middle", "revolute", prefix + "_proximal_link", prefix + "_middle_link",
            (0, 0, PROX_LEN), (0, 0, 0), (0, 1, 0), (MID[0], MID[1], EFF_MID, VEL_FLEX))
    u.link(prefix + "_middle_link",
           [Shape("box", (PHAL_T, PHAL_W, MID_LEN - 2 * GAP), (0, 0, MID_LEN / 2), mass=M_MID,
                  rgba=LINK_RGBA)])
    u.joint(prefix + "_distal", "revolute", prefix + "_middle_link", prefix + "_distal_link",
            (0, 0, MID_LEN), (0, 0, 0), (0, 1, 0), (MID[0], MID[1], EFF_DIST, VEL_FLEX),
            mimic=(prefix + "_middle", 1.0, 0.0))
    u.link(prefix + "_distal_link",
           [Shape("box", (PHAL_T, PHAL_W * 0.9, DIST_LEN - GAP), (0, 0, (DIST_LEN + GAP) / 2),
                  mass=M_DIST, rgba=LINK_RGBA),
            Shape("sphere", (TIP_RADIUS,), (0, 0, DIST_LEN), mass=M_TIP, rgba=PAD_RGBA)])


def make_cordgrasp_sah():
    u = Urdf("cordgrasp_sah",
             "cordgrasp_sah: 4-finger hand modelled on the Schunk SAH (right hand), primitives "
             "only. "
             "Generated by tools/make_primitive_hands.py - edit the script, not this file. "
             "Palm frame: z wrist->fingers, x palm normal, y towards the index. Meters, radians.")
    px, py, pz = PALM_SIZE
    u.link("palm", [
        Shape("box", (px, py, pz), (0, 0, pz / 2), mass=M_PALM * 0.93, rgba=PALM_RGBA),
        Shape("cylinder", (0.030, 0.012), (0, 0, -0.006), mass=M_PALM * 0.07, rgba=JOINT_RGBA),
    ])
    for name, y in FINGER_Y.items():
        finger_chain(u, name, "palm", (0, y, FINGER_BASE_Z), (0, 0, 0))

    # Thumb: the opposition joint (axis -z at the palm front) swings the metacarpal from lying
    # along +y in the palm plane (q = 0) to pointing out of the palm along +x (q = 90 deg,
    # opposed). The thumb finger then points up and out at THUMB_TILT and closes towards the
    # fingers/palm.
    u.joint("thumb_opposition", "revolute", "palm", "thumb_metacarpal", THUMB_A, (0, 0, 0),
            (0, 0, -1), (0.0, 90 * DEG, EFF_OPP, VEL_OPP))
    u.link("thumb_metacarpal", [Shape("box", (0.020, METACARPAL_LEN - KNUCKLE_R - GAP, 0.020),
                                      (0, (METACARPAL_LEN - KNUCKLE_R - GAP) / 2, 0),
                                      mass=M_METACARPAL, rgba=PALM_RGBA)])
    # Thumb frame when opposed (in the palm frame): z_t along the thumb, x_t towards the fingers.
    c, s = math.cos(THUMB_TILT), math.sin(THUMB_TILT)
    r_thumb = columns((-c, 0, s), (0, -1, 0), (s, 0, c))
    # The metacarpal frame is the palm frame turned by Rz(-90 deg) at q = 90 deg.
    r_mt = matmul(rot_z(90 * DEG), r_thumb)
    finger_chain(u, "thumb", "thumb_metacarpal", (0, METACARPAL_LEN, 0), rpy_of(r_mt))
    u.write(os.path.join(ROOT, "assets/hands/cordgrasp_sah/cordgrasp_sah.urdf"))


# ------------------------------------------------------------------------------------------------
# parallel_gripper

HOUSING = (0.050, 0.160, 0.060)       # x (pad width direction) y (opening) z (approach) [m]
FINGER_LEN = 0.060                    # finger length above the housing [m]
FINGER_BODY_T = 0.010                 # finger thickness (y) behind the pad [m]
PAD = (0.020, 0.003, 0.045)           # rubber pad: width x thickness x length [m]
STROKE = 0.050                        # each finger 0..5 cm -> opening 0..10 cm [m]


def make_parallel_gripper():
    u = Urdf("parallel_gripper",
             "parallel_gripper: 2-finger parallel gripper, opening 0-10 cm, primitives only. "
             "Generated by tools/make_primitive_hands.py - edit the script, not this file. "
             "Frame: z = approach (fingers point +z), y = opening direction. Meters, radians. "
             "Joint value = distance of each pad face from the centre plane (0 = closed).")
    hx, hy, hz = HOUSING
    u.link("gripper_base", [
        Shape("box", (hx, hy, hz), (0, 0, hz / 2), mass=0.46, rgba=PALM_RGBA),
        Shape("cylinder", (0.035, 0.010), (0, 0, -0.005), mass=0.04, rgba=JOINT_RGBA),
    ])
    for side, sign in (("left", 1.0), ("right", -1.0)):
        body_y = PAD[1] + FINGER_BODY_T / 2
        u.link(side + "_finger", [
            Shape("box", (PAD[0], FINGER_BODY_T, FINGER_LEN), (0, sign * body_y, FINGER_LEN / 2),
                  mass=0.040, rgba=LINK_RGBA),
            Shape("box", PAD, (0, sign * PAD[1] / 2, FINGER_LEN - PAD[2] / 2), mass=0.005,
                  rgba=PAD_RGBA),
        ])
        u.joint(side + "_finger_joint", "prismatic", "gripper_base", side + "_finger",
                (0, 0, hz + GAP), (0, 0, 0), (0, sign, 0), (0.0, STROKE, 80.0, 0.10),
                mimic=("left_finger_joint", 1.0, 0.0) if side == "right" else None)
    u.write(os.path.join(ROOT, "assets/hands/parallel_gripper/parallel_gripper.urdf"))


if __name__ == "__main__":
    make_cordgrasp_sah()
    make_parallel_gripper()
