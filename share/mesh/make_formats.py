#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Writes the meshes that MeshAssimpLoader's tests and scenes/anatomy read, with Debian's python3
and its standard library only (run: /usr/bin/python3 share/mesh/make_formats.py).

1. The organ surface (organ_surface.stl, binary, made by make_organ_surface.sh) as
   organ_surface.obj, organ_surface.ply (binary little endian) and organ_surface.gltf (glTF 2.0,
   its buffer embedded as base64). The STL repeats each point for every triangle: the points are
   merged first (same bytes, same point), in the order of their first use, so the three new files
   hold the same 643 points, in the same order, and the same 1282 triangles. The coordinates stay
   the STL's float32 values (OBJ writes them with 9 significant digits, which read back to the
   same float). Each point also gets texture coordinates, a planar projection on x and y: (u, v) =
   ((x - xmin) / (xmax - xmin), (y - ymin) / (ymax - ymin)); the STL has none. glTF counts v
   from the image's top, OBJ and PLY from its bottom: the glTF file stores 1 - v, so that every
   reader that follows the formats (assimp does) gives the same (u, v).
2. two_parts.gltf: a scene of two nodes, to check that node transforms are applied. Node "base"
   (translation (1, 2, 3), rotation 90 degrees about z) holds mesh "box" (the unit cube
   [0,1]^3, 12 triangles, a red material with a texture file name); its child node "tip"
   (translation (0, 0, 2), scale 2) holds mesh "wedge" (one triangle (0,0,0) (1,0,0) (0,1,0),
   a green material). A point p of the box ends at R p + t; of the wedge at R (2 p + (0,0,2)) + t.
3. empty_scene.gltf: a valid glTF with a scene and no mesh.
"""
import base64
import json
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def read_binary_stl(path):
    """The merged points (float32 triples, first-use order) and the triangles as point indices."""
    with open(path, "rb") as f:
        data = f.read()
    (count,) = struct.unpack_from("<I", data, 80)
    index_of = {}
    points = []
    triangles = []
    for t in range(count):
        offset = 84 + 50 * t + 12  # skip the facet normal
        corners = []
        for c in range(3):
            xyz = struct.unpack_from("<3f", data, offset + 12 * c)
            key = struct.pack("<3f", *xyz)
            if key not in index_of:
                index_of[key] = len(points)
                points.append(xyz)
            corners.append(index_of[key])
        triangles.append(tuple(corners))
    return points, triangles


def planar_texcoords(points):
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    # Rounded to float32 here so that every format stores the same values.
    f32 = lambda v: struct.unpack("<f", struct.pack("<f", v))[0]
    return [(f32((p[0] - x0) / (x1 - x0)), f32((p[1] - y0) / (y1 - y0))) for p in points]


def write_obj(path, points, uvs, triangles):
    with open(path, "w") as f:
        f.write("# organ_surface.stl written by make_formats.py: points merged, planar texcoords\n")
        for p in points:
            f.write("v %.9g %.9g %.9g\n" % p)
        for uv in uvs:
            f.write("vt %.9g %.9g\n" % uv)
        for a, b, c in triangles:
            f.write("f %d/%d %d/%d %d/%d\n" % (a + 1, a + 1, b + 1, b + 1, c + 1, c + 1))


def write_ply(path, points, uvs, triangles):
    header = (
        "ply\nformat binary_little_endian 1.0\n"
        "comment organ_surface.stl written by make_formats.py\n"
        "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
        "property float s\nproperty float t\n"
        "element face %d\nproperty list uchar int vertex_indices\nend_header\n"
        % (len(points), len(triangles))
    )
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        for p, uv in zip(points, uvs):
            f.write(struct.pack("<5f", *p, *uv))
        for t in triangles:
            f.write(struct.pack("<B3i", 3, *t))


class GltfWriter:
    """Collects meshes, materials and nodes, with all arrays in one embedded buffer."""

    def __init__(self):
        self.blob = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "Stroma make_formats.py"},
                    "buffers": [], "bufferViews": [], "accessors": [], "meshes": [],
                    "materials": [], "nodes": [], "scenes": [{"nodes": []}], "scene": 0}

    def _accessor(self, fmt, rows, gl_type, component, target, with_bounds):
        while len(self.blob) % 4:
            self.blob.append(0)
        start = len(self.blob)
        for row in rows:
            self.blob += struct.pack("<" + fmt, *row)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": start,
                                        "byteLength": len(self.blob) - start, "target": target})
        accessor = {"bufferView": len(self.doc["bufferViews"]) - 1, "componentType": component,
                    "count": len(rows), "type": gl_type}
        if with_bounds:
            accessor["min"] = [min(r[i] for r in rows) for i in range(len(rows[0]))]
            accessor["max"] = [max(r[i] for r in rows) for i in range(len(rows[0]))]
        self.doc["accessors"].append(accessor)
        return len(self.doc["accessors"]) - 1

    def material(self, name, rgba, texture=None):
        material = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(rgba),
                                                            "metallicFactor": 0.0}}
        if texture:
            self.doc.setdefault("images", []).append({"uri": texture})
            self.doc.setdefault("textures", []).append({"source": len(self.doc["images"]) - 1})
            material["pbrMetallicRoughness"]["baseColorTexture"] = {
                "index": len(self.doc["textures"]) - 1}
        self.doc["materials"].append(material)
        return len(self.doc["materials"]) - 1

    def mesh(self, name, points, triangles, uvs=None, material=None):
        attributes = {"POSITION": self._accessor("3f", points, "VEC3", 5126, 34962, True)}
        if uvs:
            attributes["TEXCOORD_0"] = self._accessor("2f", uvs, "VEC2", 5126, 34962, False)
        indices = self._accessor("I", [(i,) for t in triangles for i in t], "SCALAR", 5125,
                                 34963, False)
        primitive = {"attributes": attributes, "indices": indices, "mode": 4}
        if material is not None:
            primitive["material"] = material
        self.doc["meshes"].append({"name": name, "primitives": [primitive]})
        return len(self.doc["meshes"]) - 1

    def node(self, name, mesh=None, parent=None, **transform):
        node = {"name": name, **transform}
        if mesh is not None:
            node["mesh"] = mesh
        self.doc["nodes"].append(node)
        index = len(self.doc["nodes"]) - 1
        if parent is None:
            self.doc["scenes"][0]["nodes"].append(index)
        else:
            self.doc["nodes"][parent].setdefault("children", []).append(index)
        return index

    def write(self, path):
        doc = {k: v for k, v in self.doc.items() if v != []}
        if self.blob:
            doc["buffers"] = [{"byteLength": len(self.blob), "uri":
                               "data:application/octet-stream;base64," +
                               base64.b64encode(bytes(self.blob)).decode("ascii")}]
        with open(path, "w") as f:
            json.dump(doc, f, indent=1)
            f.write("\n")


def cube():
    points = [(x, y, z) for z in (0.0, 1.0) for y in (0.0, 1.0) for x in (0.0, 1.0)]
    # Two triangles per face, oriented outwards.
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    triangles = [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]
    return points, triangles


def main():
    points, triangles = read_binary_stl(os.path.join(HERE, "organ_surface.stl"))
    uvs = planar_texcoords(points)
    write_obj(os.path.join(HERE, "organ_surface.obj"), points, uvs, triangles)
    write_ply(os.path.join(HERE, "organ_surface.ply"), points, uvs, triangles)
    organ = GltfWriter()
    flesh = organ.material("flesh", (0.8, 0.45, 0.4, 1.0))
    gltf_uvs = [(u, 1.0 - v) for u, v in uvs]
    organ.node("organ", organ.mesh("organ_surface", points, triangles, gltf_uvs, flesh))
    organ.write(os.path.join(HERE, "organ_surface.gltf"))

    parts = GltfWriter()
    box_points, box_triangles = cube()
    box_uvs = [(p[0], 1.0 - p[1]) for p in box_points]  # glTF's v, from the top
    red = parts.material("red", (0.8, 0.1, 0.1, 1.0), texture="box_texture.png")
    green = parts.material("green", (0.1, 0.7, 0.2, 1.0))
    box = parts.mesh("box", box_points, box_triangles, box_uvs, red)
    wedge = parts.mesh("wedge", [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)], [(0, 1, 2)],
                       None, green)
    half = 0.5 ** 0.5  # the quaternion (x, y, z, w) of 90 degrees about z
    base = parts.node("base", box, translation=[1.0, 2.0, 3.0], rotation=[0.0, 0.0, half, half])
    parts.node("tip", wedge, parent=base, translation=[0.0, 0.0, 2.0], scale=[2.0, 2.0, 2.0])
    parts.write(os.path.join(HERE, "two_parts.gltf"))

    empty = GltfWriter()
    empty.node("nothing")
    empty.write(os.path.join(HERE, "empty_scene.gltf"))
    print("%d points, %d triangles: organ_surface.obj .ply .gltf; two_parts.gltf; "
          "empty_scene.gltf" % (len(points), len(triangles)))


if __name__ == "__main__":
    main()
