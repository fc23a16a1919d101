#!/usr/bin/env python3
"""A solver that is wrong in a known way, for geodex crosscheck's tests: shortest paths along the
mesh's edges (Dijkstra on the edge graph) instead of across faces. Exact on a path of edges,
too long wherever a geodesic crosses a face.

    edge_dijkstra.py MESH.off SOURCE OUT.txt
"""
import heapq
import math
import sys


def read_off(path):
    words = open(path).read().split()
    if words[0] != "OFF":
        raise SystemExit(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    at = 4
    points = []
    for _ in range(nv):
        points.append(tuple(float(w) for w in words[at:at + 3]))
        at += 3
    faces = []
    for _ in range(nf):
        k = int(words[at])
        faces.append([int(w) for w in words[at + 1:at + 1 + k]])
        at += 1 + k
    return points, faces


def main():
    mesh, source, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    points, faces = read_off(mesh)
    neighbours = [set() for _ in points]
    for f in faces:
        for a, b in zip(f, f[1:] + f[:1]):
            neighbours[a].add(b)
            neighbours[b].add(a)
    dist = [math.inf] * len(points)
    dist[source] = 0.0
    queue = [(0.0, source)]
    while queue:
        d, v = heapq.heappop(queue)
        if d > dist[v]:
            continue
        for w in neighbours[v]:
            nd = d + math.dist(points[v], points[w])
            if nd < dist[w]:
                dist[w] = nd
                heapq.heappush(queue, (nd, w))
    with open(out, "w") as f:
        f.writelines("%.17g\n" % d for d in dist)


main()
