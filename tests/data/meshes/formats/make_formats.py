#!/usr/bin/env python3
"""Writes the same small box (meters) in every format load_mesh supports.

Box: x in [0.01, 0.03], y in [-0.01, 0.02], z in [0.005, 0.055], outward faces, each quad
split along its (v0, v2) diagonal. DAE (Z_UP) and glTF store the box in local coordinates under
node transforms, so the file only loads to the reference box when node transforms ARE applied
and the Collada up-axis rotation is NOT; box_zup_unit_mm.dae is in millimeters with
<unit meter="0.001">, which must be applied (as RViz does). Run from this folder: python3 make_formats.py
"""
import base64
import struct

LO = (0.01, -0.01, 0.005)
HI = (0.03, 0.02, 0.055)
V = [((HI if i & 1 else LO)[0], (HI if i & 2 else LO)[1], (HI if i & 4 else LO)[2])
     for i in range(8)]
QUADS = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
TRIS = [t for q in QUADS for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def fmt(x):
    return repr(round(x, 9))


def vec(p):
    return " ".join(fmt(c) for c in p)


def write_obj():
    with open("box.obj", "w") as f:
        f.write("# cordgrasp format test box (meters), quads\n")
        f.writelines("v %s\n" % vec(p) for p in V)
        f.writelines("f %d %d %d %d\n" % tuple(i + 1 for i in q) for q in QUADS)


def normal(t):
    a, b, c = (V[i] for i in t)
    u = [b[k] - a[k] for k in range(3)]
    w = [c[k] - a[k] for k in range(3)]
    n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    s = sum(x * x for x in n) ** 0.5
    return tuple(x / s for x in n)


def write_stl_ascii():
    with open("box_ascii.stl", "w") as f:
        f.write("solid box\n")
        for t in TRIS:
            f.write("  facet normal %s\n    outer loop\n" % vec(normal(t)))
            f.writelines("      vertex %s\n" % vec(V[i]) for i in t)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid box\n")


def write_stl_binary():
    with open("box_binary.stl", "wb") as f:
        f.write(b"cordgrasp format test box, binary STL, meters".ljust(80, b" "))
        f.write(struct.pack("<I", len(TRIS)))
        for t in TRIS:
            f.write(struct.pack("<3f", *normal(t)))
            for i in t:
                f.write(struct.pack("<3f", *V[i]))
            f.write(struct.pack("<H", 0))


def write_ply():
    with open("box.ply", "w") as f:
        f.write("ply\nformat ascii 1.0\ncomment cordgrasp format test box (meters)\n")
        f.write("element vertex 8\nproperty float x\nproperty float y\nproperty float z\n")
        f.write("element face 6\nproperty list uchar int vertex_indices\nend_header\n")
        f.writelines("%s\n" % vec(p) for p in V)
        f.writelines("4 %d %d %d %d\n" % q for q in QUADS)


def write_off():
    with open("box.off", "w") as f:
        f.write("OFF\n# cordgrasp format test box (meters)\n8 6 0\n")
        f.writelines("%s\n" % vec(p) for p in V)
        f.writelines("4 %d %d %d %d\n" % q for q in QUADS)


# DAE: parent node translates by T, child node rotates 90 deg about z; so world = T + Rz(local),
# local = Rz^-1 (world - T) = (y', -x', z') with (x', y', z') = world - T.
DAE_T = (0.02, 0.005, 0.03)


def dae_local(p):
    d = [p[k] - DAE_T[k] for k in range(3)]
    return (d[1], -d[0], d[2])


def write_dae(path="box_zup.dae", unit=1.0):
    """unit < 1: coordinates in 1/unit units and <unit meter=unit>, e.g. millimeters."""
    pos = " ".join(vec([c / unit for c in dae_local(p)]) for p in V)
    idx = " ".join("%d %d %d" % t for t in TRIS)
    with open(path, "w") as f:
        f.write(f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset>
    <contributor><authoring_tool>cordgrasp make_formats.py</authoring_tool></contributor>
    <unit name="{'meter' if unit == 1.0 else 'millimeter'}" meter="{unit:g}"/>
    <up_axis>Z_UP</up_axis>
  </asset>
  <library_geometries>
    <geometry id="box-mesh" name="box">
      <mesh>
        <source id="box-positions">
          <float_array id="box-positions-array" count="24">{pos}</float_array>
          <technique_common>
            <accessor source="#box-positions-array" count="8" stride="3">
              <param name="X" type="float"/><param name="Y" type="float"/>
              <param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <vertices id="box-vertices"><input semantic="POSITION" source="#box-positions"/></vertices>
        <triangles count="12">
          <input semantic="VERTEX" source="#box-vertices" offset="0"/>
          <p>{idx}</p>
        </triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="Scene" name="Scene">
      <node id="parent" name="parent">
        <translate>{vec([c / unit for c in DAE_T])}</translate>
        <node id="child" name="child">
          <rotate>0 0 1 90</rotate>
          <instance_geometry url="#box-mesh"/>
        </node>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#Scene"/></scene>
</COLLADA>
""")


GLTF_T = (0.02, 0.005, 0.03)


def write_gltf():
    local = [tuple(p[k] - GLTF_T[k] for k in range(3)) for p in V]
    pos = b"".join(struct.pack("<3f", *p) for p in local)
    ind = b"".join(struct.pack("<3H", *t) for t in TRIS)
    buf = pos + ind
    lo = [min(p[k] for p in local) for k in range(3)]
    hi = [max(p[k] for p in local) for k in range(3)]
    uri = "data:application/octet-stream;base64," + base64.b64encode(buf).decode()
    with open("box.gltf", "w") as f:
        f.write(f"""{{
  "asset": {{"version": "2.0", "generator": "cordgrasp make_formats.py"}},
  "scene": 0,
  "scenes": [{{"nodes": [0]}}],
  "nodes": [{{"name": "box", "mesh": 0, "translation": [{", ".join(fmt(c) for c in GLTF_T)}]}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "indices": 1, "mode": 4}}]}}],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
     "min": [{", ".join(fmt(c) for c in lo)}], "max": [{", ".join(fmt(c) for c in hi)}]}},
    {{"bufferView": 1, "componentType": 5123, "count": {3 * len(TRIS)}, "type": "SCALAR"}}
  ],
  "bufferViews": [
    {{"buffer": 0, "byteOffset": 0, "byteLength": {len(pos)}, "target": 34962}},
    {{"buffer": 0, "byteOffset": {len(pos)}, "byteLength": {len(ind)}, "target": 34963}}
  ],
  "buffers": [{{"byteLength": {len(buf)}, "uri": "{uri}"}}]
}}
""")


if __name__ == "__main__":
    write_obj()
    write_stl_ascii()
    write_stl_binary()
    write_ply()
    write_off()
    write_dae()
    write_dae("box_zup_unit_mm.dae", 0.001)
    write_gltf()
