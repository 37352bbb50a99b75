#!/usr/bin/env python3
"""An importer's reading of a glTF 2.0 file written by fapc, independent of the writer: the
JSON and BIN chunks parsed by hand, sparse accessors applied, the animation sampled at a time as
the glTF specification says (linear between keyframes, quaternion slerp), every morphed vertex
computed as neutral + sum of weight x target and carried through the node rotations into world
space. Python's standard library only.

  gltf_pose.py FILE --time T [--points]   one JSON object: weights by target name, the world
                                          position (metres) of named vertices, node rotations
  gltf_pose.py FILE --time T --render OUT.ppm --size WxH --yaw DEG
                                          a flat-shaded orthographic picture (a second renderer
                                          for the browser test)
"""
import argparse
import json
import math
import struct
import sys


def read_gltf(path):
    data = open(path, 'rb').read()
    if data[:4] == b'glTF':
        length = struct.unpack_from('<I', data, 8)[0]
        assert length == len(data), 'glb length'
        offset, doc, binary = 12, None, b''
        while offset < length:
            chunk_length, chunk_type = struct.unpack_from('<II', data, offset)
            chunk = data[offset + 8: offset + 8 + chunk_length]
            if chunk_type == 0x4E4F534A:
                doc = json.loads(chunk.decode('utf-8'))
            elif chunk_type == 0x004E4942:
                binary = chunk
            offset += 8 + chunk_length
        return doc, [binary]
    doc = json.loads(data.decode('utf-8'))
    import base64
    buffers = []
    for b in doc['buffers']:
        uri = b['uri']
        assert uri.startswith('data:'), 'embedded buffers only'
        buffers.append(base64.b64decode(uri.split(',', 1)[1]))
    return doc, buffers


SIZES = {'SCALAR': 1, 'VEC2': 2, 'VEC3': 3, 'VEC4': 4}
FORMATS = {5126: 'f', 5125: 'I', 5123: 'H', 5121: 'B'}


def accessor(doc, buffers, index):
    a = doc['accessors'][index]
    n = SIZES[a['type']]
    fmt = FORMATS[a['componentType']]
    size = struct.calcsize(fmt)

    def view_values(view_index, byte_offset, count, comps, f):
        v = doc['bufferViews'][view_index]
        buf = buffers[v.get('buffer', 0)]
        start = v.get('byteOffset', 0) + byte_offset
        stride = v.get('byteStride', struct.calcsize(f) * comps)
        out = []
        for i in range(count):
            out.append(list(struct.unpack_from('<' + f * comps, buf, start + i * stride)))
        return out

    if 'bufferView' in a:
        values = view_values(a['bufferView'], a.get('byteOffset', 0), a['count'], n, fmt)
    else:
        values = [[0.0] * n for _ in range(a['count'])]
    sparse = a.get('sparse')
    if sparse:
        idx = view_values(sparse['indices']['bufferView'], sparse['indices'].get('byteOffset', 0),
                          sparse['count'], 1, FORMATS[sparse['indices']['componentType']])
        vals = view_values(sparse['values']['bufferView'], sparse['values'].get('byteOffset', 0),
                           sparse['count'], n, fmt)
        for (i,), v in zip(idx, vals):
            values[i] = v
    return values


def qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz]


def qrotate(q, v):
    p = qmul(qmul(q, [v[0], v[1], v[2], 0.0]), [-q[0], -q[1], -q[2], q[3]])
    return p[:3]


def slerp(a, b, t):
    d = sum(x * y for x, y in zip(a, b))
    if d < 0:
        b, d = [-x for x in b], -d
    if d > 0.9995:
        r = [x + t * (y - x) for x, y in zip(a, b)]
    else:
        th = math.acos(d)
        s = math.sin(th)
        r = [(math.sin((1 - t) * th) * x + math.sin(t * th) * y) / s for x, y in zip(a, b)]
    n = math.sqrt(sum(x * x for x in r))
    return [x / n for x in r]


def sample(doc, buffers, sampler, time, width):
    times = [t[0] for t in accessor(doc, buffers, sampler['input'])]
    out = accessor(doc, buffers, sampler['output'])
    flat = [x for v in out for x in v]
    k = 0
    while k + 1 < len(times) and times[k + 1] <= time:
        k += 1
    def key(i):
        return flat[i * width:(i + 1) * width]
    if k + 1 >= len(times) or time <= times[0]:
        return key(k if time > times[0] else 0)
    t = (time - times[k]) / (times[k + 1] - times[k])
    if sampler.get('interpolation', 'LINEAR') == 'STEP':
        return key(k)
    if width == 4 and sampler is not None and len(key(k)) == 4 and sampler.get('_rotation'):
        return slerp(key(k), key(k + 1), t)
    return [x + t * (y - x) for x, y in zip(key(k), key(k + 1))]


def pose(doc, buffers, time):
    """World-space positions of every primitive's vertices, and the animated values."""
    nodes = doc['nodes']
    rotation = {i: n.get('rotation', [0, 0, 0, 1]) for i, n in enumerate(nodes)}
    weights = {i: doc['meshes'][n['mesh']].get('weights', []) for i, n in enumerate(nodes) if 'mesh' in n}
    for anim in doc.get('animations', [])[:1]:
        for ch in anim['channels']:
            s = dict(anim['samplers'][ch['sampler']])
            node, path = ch['target']['node'], ch['target']['path']
            if path == 'rotation':
                s['_rotation'] = True
                rotation[node] = sample(doc, buffers, s, time, 4)
            elif path == 'weights':
                weights[node] = sample(doc, buffers, s, time, len(weights[node]))
    parent = {}
    for i, n in enumerate(nodes):
        for c in n.get('children', []):
            parent[c] = i

    def to_world(i, p):
        while True:
            n = nodes[i]
            p = qrotate(rotation[i], p)
            t = n.get('translation', [0, 0, 0])
            p = [p[0] + t[0], p[1] + t[1], p[2] + t[2]]
            if i not in parent:
                return p
            i = parent[i]

    cache = {}
    drawn = []
    for i, n in enumerate(nodes):
        if 'mesh' not in n:
            continue
        mesh = doc['meshes'][n['mesh']]
        for prim in mesh['primitives']:
            key = (prim['attributes']['POSITION'], n['mesh'], i)
            if key not in cache:
                pos = [list(p) for p in accessor(doc, buffers, prim['attributes']['POSITION'])]
                for w, target in zip(weights.get(i, []), prim.get('targets', [])):
                    if w == 0:
                        continue
                    delta = accessor(doc, buffers, target['POSITION'])
                    for v, d in zip(pos, delta):
                        v[0] += w * d[0]; v[1] += w * d[1]; v[2] += w * d[2]
                cache[key] = [to_world(i, p) for p in pos]
            drawn.append((cache[key], [x[0] for x in accessor(doc, buffers, prim['indices'])],
                          doc['materials'][prim['material']]['pbrMetallicRoughness']['baseColorFactor']))
    return drawn, weights, rotation, cache


def render(drawn, width, height, yaw_degrees, out):
    """Flat shading (light from the viewer), orthographic along -z after turning the view about y,
    a z-buffer; the picture spans 0.3 m on its shorter side about (0, 0, 0) of the scene shifted
    to the head's centre."""
    yaw = math.radians(yaw_degrees)
    cy, sy = math.cos(yaw), math.sin(yaw)
    scale = min(width, height) / 0.30
    cx0, cy0 = 0.0, 0.0  # the view is centred on the head: x = 0, y = 0 of the face (1 mm = scale/1000 px)
    depth = [[-1e9] * width for _ in range(height)]
    image = bytearray([255] * (width * height * 3))
    for positions, indices, colour in drawn:
        view = []
        for p in positions:
            x = cy * p[0] + sy * p[2]
            z = -sy * p[0] + cy * p[2]
            view.append((width / 2 + (x - cx0) * scale, height / 2 - (p[1] - cy0) * scale, z))
        for t in range(0, len(indices), 3):
            a, b, c = view[indices[t]], view[indices[t + 1]], view[indices[t + 2]]
            area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
            if area >= 0:  # back-facing (y grows downwards on the picture)
                continue
            pa, pb, pc = positions[indices[t]], positions[indices[t + 1]], positions[indices[t + 2]]
            u = [pb[k] - pa[k] for k in range(3)]
            v = [pc[k] - pa[k] for k in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            nz = (-sy * n[0] + cy * n[2]) / (math.sqrt(sum(x * x for x in n)) or 1)
            shade = 0.35 + 0.65 * max(nz, 0.0)
            rgb = [int(round(255 * min(1.0, (colour[k] ** (1 / 2.2)) * shade))) for k in range(3)]
            x0, x1 = max(int(min(a[0], b[0], c[0])), 0), min(int(max(a[0], b[0], c[0])) + 1, width - 1)
            y0, y1 = max(int(min(a[1], b[1], c[1])), 0), min(int(max(a[1], b[1], c[1])) + 1, height - 1)
            for y in range(y0, y1 + 1):
                for x in range(x0, x1 + 1):
                    px, py = x + 0.5, y + 0.5
                    w0 = ((b[0] - px) * (c[1] - py) - (b[1] - py) * (c[0] - px)) / area
                    w1 = ((c[0] - px) * (a[1] - py) - (c[1] - py) * (a[0] - px)) / area
                    w2 = 1 - w0 - w1
                    if w0 < 0 or w1 < 0 or w2 < 0:
                        continue
                    z = w0 * a[2] + w1 * b[2] + w2 * c[2]
                    if z > depth[y][x]:
                        depth[y][x] = z
                        o = (y * width + x) * 3
                        image[o:o + 3] = bytes(rgb)
    with open(out, 'wb') as f:
        f.write(b'P6 %d %d 255\n' % (width, height))
        f.write(bytes(image))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('file')
    ap.add_argument('--time', type=float, default=0.0)
    ap.add_argument('--vertices', default='', help='comma-separated vertex indices of the head mesh')
    ap.add_argument('--render')
    ap.add_argument('--size', default='320x240')
    ap.add_argument('--yaw', type=float, default=0.0)
    args = ap.parse_args()
    doc, buffers = read_gltf(args.file)
    drawn, weights, rotation, cache = pose(doc, buffers, args.time)
    if args.render:
        w, h = (int(x) for x in args.size.split('x'))
        render(drawn, w, h, args.yaw, args.render)
        return
    names = doc['meshes'][0].get('extras', {}).get('targetNames', [])
    head = next(i for i, n in enumerate(doc['nodes']) if n.get('name') == 'head')
    positions = next(v for k, v in cache.items() if k[2] == head)
    result = {
        'weights': dict(zip(names, weights.get(head, []))),
        'rotations': {doc['nodes'][i].get('name', str(i)): q for i, q in rotation.items()},
        'vertices': {i: positions[int(i)] for i in args.vertices.split(',') if i},
    }
    json.dump(result, sys.stdout)
    sys.stdout.write('\n')


if __name__ == '__main__':
    main()
