#!/usr/bin/env python3
"""Cuts a real Quake III map (IBSP 46) down to a small, still valid seed for q3_bsp_fuzz.

A whole map is 1-8 MB; libFuzzer then spends its time hashing and copying megabytes (about
100 inputs a second here) instead of mutating the fields that matter. This keeps the real
records of a few faces of every type (polygons, patches, meshes, billboards) with their
vertices and meshverts, the real shaders, and a BSP tree of one real node over two real
leaves with their brushes, sides and planes, every index renumbered so that the result
parses. Lightmaps, light volumes, visibility, leaf faces and effects are dropped (the
parser does not read them).

usage: make_q3_seed.py MAP.bsp OUT.bsp
"""
import struct
import sys

RECORD = {1: 72, 2: 16, 3: 36, 4: 48, 6: 4, 7: 40, 8: 12, 9: 8, 10: 44, 11: 4, 13: 104}


def lumps(data):
    if data[:4] != b"IBSP" or struct.unpack_from("<i", data, 4)[0] != 46:
        sys.exit("not an IBSP 46 map")
    out = {}
    for l in range(17):
        offset, length = struct.unpack_from("<ii", data, 8 + 8 * l)
        blob = data[offset:offset + length]
        size = RECORD.get(l, 1)
        out[l] = [blob[i:i + size] for i in range(0, len(blob), size)] if l in RECORD else blob
    return out


def main(source, target):
    src = lumps(open(source, "rb").read())
    faces, vertexes, meshverts = [], [], []
    wanted = {1: 6, 2: 3, 3: 3, 4: 2}  # face type -> how many to keep
    for face in src[13]:
        ftype = struct.unpack_from("<i", face, 8)[0]
        if wanted.get(ftype, 0) == 0:
            continue
        first, count, first_mv, count_mv = struct.unpack_from("<4i", face, 12)
        if count > (40 if ftype == 2 else 400):  # small faces and patches: a short seed
            continue
        wanted[ftype] -= 1
        new = bytearray(face)
        struct.pack_into("<ii", new, 12, len(vertexes), count)
        vertexes += src[10][first:first + count]
        if ftype in (1, 3):
            struct.pack_into("<ii", new, 20, len(meshverts), count_mv)
            meshverts += src[11][first_mv:first_mv + count_mv]
        else:
            struct.pack_into("<ii", new, 20, 0, 0)
        struct.pack_into("<i", new, 4, -1)  # no effect
        faces.append(bytes(new))

    # The tree: node 0 of the map over an outside leaf and the first open leaf with brushes.
    planes, plane_index = [], {}

    def plane(i):
        if i not in plane_index:
            plane_index[i] = len(planes)
            planes.append(src[2][i])
        return plane_index[i]

    leaves_src = src[4]
    outside = next(l for l in leaves_src if struct.unpack_from("<i", l, 0)[0] < 0)
    inside = next(l for l in leaves_src
                  if struct.unpack_from("<i", l, 0)[0] >= 0 and struct.unpack_from("<i", l, 44)[0] > 0)
    brushes, sides, leafbrushes = [], [], []
    first_lb, count_lb = struct.unpack_from("<ii", inside, 40)
    for lb in src[6][first_lb:first_lb + count_lb]:
        brush = src[8][struct.unpack_from("<i", lb, 0)[0]]
        first_side, count_side, shader = struct.unpack_from("<3i", brush, 0)
        leafbrushes.append(struct.pack("<i", len(brushes)))
        brushes.append(struct.pack("<3i", len(sides), count_side, shader))
        for side in src[9][first_side:first_side + count_side]:
            p, s = struct.unpack_from("<ii", side, 0)
            sides.append(struct.pack("<ii", plane(p), s))
    node = bytearray(src[3][0])
    struct.pack_into("<3i", node, 0, plane(struct.unpack_from("<i", node, 0)[0]), -1, -2)
    out_leaf = bytearray(outside)
    struct.pack_into("<4i", out_leaf, 32, 0, 0, 0, 0)
    in_leaf = bytearray(inside)
    struct.pack_into("<4i", in_leaf, 32, 0, 0, 0, len(leafbrushes))

    # The first entities (worldspawn and a few more), whole blocks.
    entities = src[0][:src[0].rfind(b"}", 0, 1024) + 1] + b"\0"
    out = {0: entities, 1: b"".join(src[1]), 2: b"".join(planes), 3: bytes(node),
           4: bytes(out_leaf) + bytes(in_leaf), 6: b"".join(leafbrushes), 7: src[7][0],
           8: b"".join(brushes), 9: b"".join(sides), 10: b"".join(vertexes),
           11: b"".join(meshverts), 13: b"".join(faces)}
    header = bytearray(b"IBSP" + struct.pack("<i", 46) + bytes(8 * 17))
    body = bytearray()
    for l in range(17):
        blob = out.get(l, b"")
        struct.pack_into("<ii", header, 8 + 8 * l, len(header) + len(body), len(blob))
        body += blob
    open(target, "wb").write(bytes(header + body))
    print(f"{target}: {len(header) + len(body)} bytes, {len(faces)} faces, "
          f"{len(vertexes)} vertices, {len(brushes)} brushes")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
