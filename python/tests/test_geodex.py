"""The Python module against the CLI (to the last bit), independent expected values, and every
class of bad input. Run by CTest (label `python`) with PYTHONPATH at the built package and
GEODEX_CLI / GEODEX_CGAL_MESH_DIR set; `python3 -m pytest python/tests` by hand with the same."""
import json
import math
import os
import subprocess
import threading

import numpy as np
import pytest

import geodex

CLI = os.environ.get("GEODEX_CLI", "build/release/bin/geodex")
MESHES = os.environ.get("GEODEX_CGAL_MESH_DIR", "build/release/data/meshes")

# A unit square in the plane z = 0, two triangles: distances are Euclidean.
SQUARE_V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
SQUARE_F = np.array([[0, 1, 2], [0, 2, 3]])


def grid(n):
    """An n x n planar grid of unit squares, alternating diagonals (Euclidean distances)."""
    V = np.array([[x, y, 0.0] for y in range(n + 1) for x in range(n + 1)])
    F = []
    for y in range(n):
        for x in range(n):
            a, b, c, d = y * (n + 1) + x, y * (n + 1) + x + 1, (y + 1) * (n + 1) + x + 1, (y + 1) * (n + 1) + x
            F += [[a, b, c], [a, c, d]] if (x + y) % 2 == 0 else [[a, b, d], [b, c, d]]
    return V, np.array(F)


def cli_distances(path, *specs):
    args = [CLI, "distance", path, "--quiet"]
    for s in specs:
        args += ["--source", s]
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout.split()
    return np.array([math.inf if x == "inf" else float(x) for x in out])


def mesh_path(name):
    path = os.path.join(MESHES, name)
    if not (os.path.isfile(path) and os.access(CLI, os.X_OK)):
        pytest.skip("needs libcgal-demo's %s and the geodex CLI" % name)
    return path


# ===  Results ==================================================================================

def test_square_distances_are_euclidean():
    d = geodex.distances(SQUARE_V, SQUARE_F, [0])
    assert d.dtype == np.float64 and d.shape == (4,)
    np.testing.assert_allclose(d, np.hypot(SQUARE_V[:, 0], SQUARE_V[:, 1]), rtol=0, atol=1e-15)


def test_grid_from_an_edge_and_a_face_point():
    V, F = grid(4)
    p = 0.25 * V[6] + 0.75 * V[7]
    d = geodex.distances(V, F, geodex.edge(6, 7, 0.75))
    np.testing.assert_allclose(d, np.linalg.norm(V - p, axis=1), rtol=0, atol=1e-14)
    corners = F[5]
    q = 0.2 * V[corners[0]] + 0.3 * V[corners[1]] + 0.5 * V[corners[2]]
    d = geodex.distances(V, F, [geodex.face(5, 0.2, 0.3, 0.5)])
    np.testing.assert_allclose(d, np.linalg.norm(V - q, axis=1), rtol=0, atol=1e-14)


@pytest.mark.parametrize("name", ["elephant.off", "fandisk.off", "mushroom.off", "cross.off"])
def test_the_same_bits_as_the_cli(name):
    path = mesh_path(name)
    V, F = geodex.load(path)
    solver = geodex.Solver(V, F)
    assert np.array_equal(solver.distances(0), cli_distances(path, "v:0"))
    assert np.array_equal(solver.distances([geodex.vertex(3), geodex.edge(int(F[0][0]), int(F[0][1]), 0.25)]),
                          cli_distances(path, "v:3", "e:%d,%d,0.25" % (F[0][0], F[0][1])))
    assert np.array_equal(solver.distances(geodex.face(7, 0.5, 0.25, 0.25)), cli_distances(path, "f:7,0.5,0.25,0.25"))


def test_unreachable_is_inf_and_stop_distance_and_targets():
    V = np.vstack([SQUARE_V, SQUARE_V + [5, 0, 0]])
    F = np.vstack([SQUARE_F, SQUARE_F + 4])
    d = geodex.distances(V, F, [0])
    assert np.all(np.isinf(d[4:])) and np.all(np.isfinite(d[:4]))
    stopped = geodex.distances(V, F, [0], stop_distance=1.2)
    assert stopped[2] == math.inf and stopped[1] == d[1]
    solver = geodex.Solver(V, F)
    t = solver.distances([0], targets=[1])
    assert t[1] == d[1]


def test_path_is_as_long_as_the_distance_and_runs_from_target_to_source():
    V, F = grid(4)
    solver = geodex.Solver(V, F)
    points, length = solver.path(0, 24)
    assert points.shape[1] == 3 and points.shape[0] >= 2
    assert np.array_equal(points[0], V[24]) and np.array_equal(points[-1], V[0])
    assert abs(length - math.hypot(4, 4)) < 1e-14
    assert abs(np.sum(np.linalg.norm(np.diff(points, axis=0), axis=1)) - length) < 1e-14


def test_stats_name_the_degenerate_cases():
    solver = geodex.Solver(*grid(3))
    solver.distances(0)
    s = solver.stats
    for key in ["cases", "degenerate_cases", "windows_propagated", "G1", "G2", "G3", "G4", "G5",
                "D1", "D2", "D3", "D4"]:
        assert key in s
    assert s["windows_propagated"] > 0
    assert s["degenerate_cases"] <= s["cases"]


def test_any_array_like():
    want = geodex.distances(SQUARE_V, SQUARE_F, [0])
    for V, F in [(SQUARE_V.tolist(), SQUARE_F.tolist()),
                 (SQUARE_V.astype(np.float32), SQUARE_F.astype(np.int32)),
                 (np.asfortranarray(SQUARE_V), np.asfortranarray(SQUARE_F)),
                 (SQUARE_V.astype(int), SQUARE_F.astype(np.uint64))]:
        np.testing.assert_array_equal(geodex.distances(V, F, [np.int64(0)]), want)


def test_scale_is_exact_from_python_too():
    V, F = grid(3)
    d = geodex.distances(V, F, [5])
    assert np.array_equal(geodex.distances(np.ldexp(V, 900), F, [5]), np.ldexp(d, 900))


def test_solves_in_parallel_threads_give_the_sequential_results():
    V, F = grid(12)
    sources = [0, 40, 77, 120]
    want = [geodex.distances(V, F, [s]) for s in sources]
    got = [None] * len(sources)

    def work(i):
        got[i] = geodex.Solver(V, F).distances([sources[i]])

    threads = [threading.Thread(target=work, args=(i,)) for i in range(len(sources))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for w, g in zip(want, got):
        assert np.array_equal(w, g)


def test_one_solver_shared_by_threads_gives_each_its_own_sources_results():
    # Each call solves and reads under the Solver's lock: no thread reads another's field.
    V, F = grid(12)
    sources = [0, 40, 77, 120]
    want = {s: geodex.distances(V, F, [s]) for s in sources}
    shared = geodex.Solver(V, F)
    wrong = []

    def work(s):
        for _ in range(20):
            if not np.array_equal(shared.distances([s]), want[s]):
                wrong.append(s)

    threads = [threading.Thread(target=work, args=(s,)) for s in sources]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert wrong == []


def test_docstrings_read_well():
    assert "sources" in geodex.distances.__doc__ and "inf" in geodex.distances.__doc__
    assert "path" in geodex.Solver.__doc__
    assert geodex.InputError.__mro__[1] is ValueError


# ===  Bad input: geodex.InputError with the CLI's message, never a crash =========================

BAD_MESHES = [
    (np.zeros((3, 2)), SQUARE_F, "shape \\(n, 3\\)"),
    (SQUARE_V, np.zeros((2, 4), int), "shape \\(m, 3\\)"),
    (SQUARE_V, SQUARE_F.astype(float), "integer vertex indices"),
    (np.array([["a", "b", "c"]] * 4), SQUARE_F, "real numbers"),
    (np.where(np.arange(12).reshape(4, 3) == 4, np.nan, SQUARE_V), SQUARE_F, "vertex 1 has a non-finite coordinate"),
    (SQUARE_V, np.array([[0, 1, 7]]), "face 0 refers to vertex 7, but there are only 4 vertices"),
    (SQUARE_V, np.array([[0, 1, -1]]), "refers to vertex -1"),
    (SQUARE_V, np.array([[0, 1, 1]]), "uses vertex 1 twice"),
    (np.array([[0, 0, 0], [0, 0, 0], [0, 1, 0]], float), np.array([[0, 1, 2]]), "zero-length edge"),
    (np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], float),
     np.array([[0, 1, 2], [1, 0, 3], [0, 1, 4]]), "edge 0-1 has 3 faces"),
    (np.array([[0, 0, 0], [1e-120, 0, 0], [0, 1, 0]]), np.array([[0, 1, 2]]), "edge 0-1 is 1e-120 times"),
]


@pytest.mark.parametrize("V,F,message", BAD_MESHES)
def test_bad_meshes(V, F, message):
    with pytest.raises(geodex.InputError, match=message):
        geodex.distances(V, F, [0])


@pytest.mark.parametrize("source,message", [
    (9, "vertex 9"),
    (-1, "negative"),
    (True, "not a bool"),
    ("v:0", "vertex index or a SurfacePoint"),
    (1.5, "not an integer"),
    ([], "at least one source"),
    (geodex.edge(0, 2, 0.5), None),  # 0-2 is the diagonal: fine
    (geodex.edge(1, 3, 0.5), "share no edge"),
    (geodex.edge(0, 1, 1.5), "0.*1"),
    (geodex.face(0, 0.5, 0.6, 0.1), "sum"),
    (geodex.face(5, 1, 0, 0), "face 5"),
])
def test_bad_sources(source, message):
    if message is None:
        geodex.distances(SQUARE_V, SQUARE_F, source)
        return
    with pytest.raises(geodex.InputError, match=message):
        geodex.distances(SQUARE_V, SQUARE_F, source)


@pytest.mark.parametrize("stop", [-1.0, math.nan])
def test_bad_stop_distance(stop):
    with pytest.raises(geodex.InputError, match="stop_distance"):
        geodex.distances(SQUARE_V, SQUARE_F, [0], stop_distance=stop)


def test_load_names_the_file_and_line(tmp_path):
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 42\n")
    with pytest.raises(geodex.InputError, match="bad.off:6: face 0 refers to vertex 42"):
        geodex.load(str(bad))
    with pytest.raises(geodex.InputError):
        geodex.load(str(tmp_path / "missing.off"))


# ===  geodex.check: the CLI's `geodex check`, the same report ===================================

def cli_check(path, *args):
    out = subprocess.run([CLI, "check", path, "--json", *args], capture_output=True, text=True)
    assert out.returncode in (0, 1), out.stderr
    return json.loads(out.stdout)


@pytest.mark.parametrize("name", ["elephant.off", "cross.off"])
def test_check_reports_what_the_cli_reports(name):
    path = mesh_path(name)
    V, F = geodex.load(path)
    report = geodex.check(V, F, [0, geodex.edge(int(F[0][0]), int(F[0][1]), 0.25)])
    assert report == cli_check(path, "--source", "v:0", "--source", "e:%d,%d,0.25" % (F[0][0], F[0][1]),
                               "--level", "full")
    assert report["ok"] is True and report["violations"] == []


def test_check_cheap_level_and_chosen_oracles():
    V, F = grid(6)
    report = geodex.check(V, F, 0, level="cheap", oracles=["bounds", "planar"])
    assert sorted(report["oracles"]) == ["bounds-dijkstra", "bounds-euclidean", "planar"]
    assert report["oracles"]["planar"]["checked"] > 0 and report["ok"] is True
    # The pointwise minimum is the full tier's: the cheap one leaves it unchecked.
    assert report["invariants"]["pointwise-min"]["checked"] == 0
    assert geodex.check(V, F, 0, oracles=["bounds"])["invariants"]["pointwise-min"]["checked"] > 0


@pytest.mark.parametrize("kwargs,message", [
    ({"level": "thorough"}, "level must be"),
    ({"oracles": ["bounds", "nonsense"]}, "nonsense"),
    ({"oracles": "bounds"}, "list of names"),
])
def test_check_bad_options(kwargs, message):
    with pytest.raises(geodex.InputError, match=message):
        geodex.check(SQUARE_V, SQUARE_F, [0], **kwargs)
