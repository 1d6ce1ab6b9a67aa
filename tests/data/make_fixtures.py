#!/usr/bin/env python3
"""Writes the glTF test fixtures next to this script: one valid triangle (.gltf and .glb), a valid
node hierarchy that exercises transforms and skipped parts (hierarchy.gltf) and, under
malformed/, one file per defect the loader must reject with a SceneLoadError. Each malformed file is
the valid triangle with exactly one thing broken, so a test that passes cannot pass for another reason.
The outputs are committed; rerun this only to change them (python3 tests/data/make_fixtures.py)."""
import base64
import copy
import json
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
MALFORMED = os.path.join(HERE, "malformed")


def buffer_bytes(positions=((0, 0, 0), (1, 0, 0), (0, 1, 0)), indices=(0, 1, 2)):
    """Positions (36 bytes) | uint16 indices (6 bytes + 2 padding) | texcoords (24 bytes) = 68 bytes."""
    data = b"".join(struct.pack("<3f", *p) for p in positions)
    data += struct.pack("<3H", *indices) + b"\0\0"
    data += struct.pack("<6f", 0, 0, 1, 0, 0, 1)
    return data


def data_uri(data):
    return "data:application/octet-stream;base64," + base64.b64encode(data).decode()


def valid_model(data=None):
    data = buffer_bytes() if data is None else data
    return {
        "asset": {"version": "2.0", "generator": "raylab tests/data/make_fixtures.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [
            {"name": "triangle", "mesh": 0},
            {"name": "camera_node", "camera": 0, "translation": [0.3, 0.3, 2.0]},
        ],
        "cameras": [{"name": "Cam", "type": "perspective",
                     "perspective": {"yfov": 0.7, "znear": 0.01, "aspectRatio": 1.5}}],
        "meshes": [{"name": "tri", "primitives": [
            {"attributes": {"POSITION": 0, "TEXCOORD_0": 2}, "indices": 1, "material": 0, "mode": 4}]}],
        "materials": [{"name": "orange", "emissiveFactor": [0.5, 0.25, 0.0],
                       "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4.0}},
                       "pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.5, 0.25, 1.0],
                                                "metallicFactor": 0.0, "roughnessFactor": 0.5}}],
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 36},
            {"buffer": 0, "byteOffset": 36, "byteLength": 6},
            {"buffer": 0, "byteOffset": 44, "byteLength": 24},
        ],
        "buffers": [{"byteLength": len(data), "uri": data_uri(data)}],
    }


def write_json(path, model):
    with open(path, "w") as f:
        json.dump(model, f, indent=1)
        f.write("\n")


def glb_bytes(model, data):
    """GLB container: 12-byte header, JSON chunk (space padded), BIN chunk (zero padded)."""
    model = copy.deepcopy(model)
    model["buffers"] = [{"byteLength": len(data)}]
    js = json.dumps(model).encode()
    js += b" " * (-len(js) % 4)
    bin_ = data + b"\0" * (-len(data) % 4)
    total = 12 + 8 + len(js) + 8 + len(bin_)
    return (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(js), b"JSON") + js +
            struct.pack("<I4s", len(bin_), b"BIN\0") + bin_)


def hierarchy_model():
    """Valid but awkward: no scenes (roots are the parentless nodes), TRS and matrix transforms, a
    mesh instanced three times (once mirrored), 4 indices (the last is ignored), a LINES primitive
    (skipped), no material (the default one)."""
    data = b"".join(struct.pack("<3f", *p) for p in ((0, 0, 0), (1, 0, 0), (0, 1, 0)))
    data += struct.pack("<4H", 0, 1, 2, 0)
    s45 = 0.5 ** 0.5
    return {
        "asset": {"version": "2.0", "generator": "raylab tests/data/make_fixtures.py"},
        "nodes": [
            {"name": "turned", "mesh": 0, "translation": [10, 0, 0], "rotation": [0, s45, 0, s45],
             "scale": [2, 2, 2], "children": [1]},
            {"name": "lifted", "mesh": 0, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 0, 1]},
            {"name": "mirrored", "mesh": 0, "scale": [-1, 1, 1]},
        ],
        "meshes": [{"name": "tri", "primitives": [
            {"attributes": {"POSITION": 0}, "indices": 1},
            {"attributes": {"POSITION": 0}, "mode": 1}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 4, "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 36},
            {"buffer": 0, "byteOffset": 36, "byteLength": 8},
        ],
        "buffers": [{"byteLength": len(data), "uri": data_uri(data)}],
    }


# Strips and fans (modes/): planar, counter-clockwise seen from +z, so every triangle of a correct expansion
# faces +z. The indexed forms store the vertices in another order (reversed, behind an unused vertex) and
# index them back, so all forms of a mode describe the same triangles.
STRIP = ((0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, 2, 0), (1, 2, 0))
FAN = ((0, 0, 0), (2, 0, 0), (1.5, 1.5, 0), (0, 2, 0), (-1.5, 1.5, 0), (-2, 0, 0))
INDEX_FORMS = {"u8": (5121, "<%dB", 1), "u16": (5123, "<%dH", 2), "u32": (5125, "<%dI", 4)}


def mode_model(points, mode, form):
    """One primitive in `mode` over `points`; form: 'none' (no indices) or an INDEX_FORMS key."""
    if form == "none":
        stored, indices = list(points), None
    else:
        stored = [(9, 9, 9)] + list(reversed(points))  # vertex k of the strip is stored at n - k
        indices = [len(points) - k for k in range(len(points))]
    data = b"".join(struct.pack("<3f", *p) for p in stored)
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": len(data)}]
    accessors = [{"bufferView": 0, "componentType": 5126, "count": len(stored), "type": "VEC3",
                  "min": [min(p[a] for p in stored) for a in range(3)],
                  "max": [max(p[a] for p in stored) for a in range(3)]}]
    prim = {"attributes": {"POSITION": 0}, "mode": mode}
    if indices is not None:
        ctype, fmt, size = INDEX_FORMS[form]
        raw = struct.pack(fmt % len(indices), *indices)
        views.append({"buffer": 0, "byteOffset": len(data), "byteLength": len(raw)})
        accessors.append({"bufferView": 1, "componentType": ctype, "count": len(indices), "type": "SCALAR"})
        prim["indices"] = 1
        data += raw + b"\0" * (-len(raw) % 4)
    return {
        "asset": {"version": "2.0", "generator": "raylab tests/data/make_fixtures.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "shape", "mesh": 0}],
        "meshes": [{"name": "shape", "primitives": [prim]}],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(data), "uri": data_uri(data)}],
    }


def write_mode_fixtures():
    modes = os.path.join(HERE, "modes")
    os.makedirs(modes, exist_ok=True)
    for form in ["none"] + list(INDEX_FORMS):
        write_json(os.path.join(modes, "strip_%s.gltf" % form), mode_model(STRIP, 5, form))
        write_json(os.path.join(modes, "fan_%s.gltf" % form), mode_model(FAN, 6, form))
    for name, mode in (("points", 0), ("lines", 1), ("line_loop", 2), ("line_strip", 3)):
        write_json(os.path.join(modes, name + ".gltf"), mode_model(STRIP, mode, "u16"))


def malformed(name, edit):
    model = valid_model()
    edit(model)
    write_json(os.path.join(MALFORMED, name + ".gltf"), model)


def set_path(path, value):
    def edit(model):
        obj = model
        for key in path[:-1]:
            obj = obj[key]
        obj[path[-1]] = value
    return edit


def main():
    os.makedirs(MALFORMED, exist_ok=True)
    write_json(os.path.join(HERE, "valid_triangle.gltf"), valid_model())
    glb = glb_bytes(valid_model(), buffer_bytes())
    with open(os.path.join(HERE, "valid_triangle.glb"), "wb") as f:
        f.write(glb)
    write_json(os.path.join(HERE, "hierarchy.gltf"), hierarchy_model())
    write_mode_fixtures()

    # The defects the brief names.
    def bad_index(m):
        m["buffers"][0]["uri"] = data_uri(buffer_bytes(indices=(0, 1, 5)))
    malformed("index_out_of_range", bad_index)
    malformed("accessor_out_of_range", set_path(["meshes", 0, "primitives", 0, "attributes", "POSITION"], 7))
    malformed("bufferview_out_of_range", set_path(["accessors", 0, "bufferView"], 12))

    def missing_bin(m):
        m["buffers"][0]["uri"] = "missing_bin.bin"  # deliberately absent
    malformed("missing_bin", missing_bin)

    def cycle(m):
        m["nodes"][0]["children"] = [1]
        m["nodes"][1]["children"] = [0]
        m["scenes"][0]["nodes"] = [0]
    malformed("node_cycle", cycle)
    malformed("node_child_out_of_range", set_path(["nodes", 0, "children"], [5]))
    malformed("position_vec2", set_path(["accessors", 0, "type"], "VEC2"))
    malformed("position_unsigned_short", set_path(["accessors", 0, "componentType"], 5123))
    malformed("accessor_past_bufferview", set_path(["accessors", 0, "count"], 4))
    malformed("material_out_of_range", set_path(["meshes", 0, "primitives", 0, "material"], 3))
    with open(os.path.join(MALFORMED, "invalid_json.gltf"), "w") as f:
        f.write(json.dumps(valid_model(), indent=1)[:300])  # cut mid-document
    with open(os.path.join(MALFORMED, "truncated.glb"), "wb") as f:
        f.write(glb[:len(glb) - 40])  # the BIN chunk is cut short
    with open(os.path.join(MALFORMED, "truncated_header.glb"), "wb") as f:
        f.write(glb[:10])

    # Further defects tinygltf lets through unless checked.
    malformed("buffer_out_of_range", set_path(["bufferViews", 0, "buffer"], 2))
    malformed("bufferview_past_buffer", set_path(["bufferViews", 2, "byteLength"], 200))
    malformed("accessor_offset_past_bufferview", set_path(["accessors", 2, "byteOffset"], 8))
    malformed("stride_too_small", set_path(["bufferViews", 0, "byteStride"], 4))
    malformed("indices_float", set_path(["accessors", 1, "componentType"], 5126))
    malformed("texcoord_count_mismatch", set_path(["accessors", 2, "count"], 2))
    malformed("mesh_out_of_range", set_path(["nodes", 0, "mesh"], 3))
    malformed("camera_out_of_range", set_path(["nodes", 1, "camera"], 2))
    malformed("scene_node_out_of_range", set_path(["scenes", 0, "nodes"], [0, 9]))
    malformed("default_scene_out_of_range", set_path(["scene"], 4))
    malformed("texture_out_of_range",
              set_path(["materials", 0, "pbrMetallicRoughness", "baseColorTexture"], {"index": 4}))

    def image_out_of_range(m):
        m["textures"] = [{"source": 2}]
        m["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    malformed("image_out_of_range", image_out_of_range)

    def nan_position(m):
        m["buffers"][0]["uri"] = data_uri(buffer_bytes(positions=((0, 0, 0), (float("nan"), 0, 0), (0, 1, 0))))
    malformed("nan_position", nan_position)

    def sparse(m):
        m["accessors"][0]["sparse"] = {"count": 1, "indices": {"bufferView": 1, "componentType": 5123},
                                       "values": {"bufferView": 0}}
    malformed("sparse_accessor", sparse)
    malformed("no_triangles", set_path(["meshes", 0, "primitives", 0, "mode"], 0))


if __name__ == "__main__":
    main()
