#!/usr/bin/env python3
"""Fuzzes `flatfacet remesh` with broken meshes and asks of every run what DESIGN.md 4 asks.

Each run takes a shared mesh, breaks it (geometry: a stray vertex, NaN, flipped, duplicate or
missing faces, bad indices, a non-manifold fin, far-off or tiny coordinates, ...; then often
the file's bytes: flips, truncation, odd tokens, lines doubled or dropped), writes it as OFF,
OBJ, STL (ASCII or binary) or PLY (ASCII or binary), and runs `remesh` with random options
under a time and memory limit. A run is bad when:
  - it crashes (a signal, or an exit code other than 0, 2 and 3), takes longer than the time
    limit or grows past the memory limit;
  - exit 2 without exactly one line on stderr, or with an output written;
  - exit 0 or 3 without its outputs, or with a report that contradicts the exit code
    (exit 0: every panel valid, topology kept, an oriented 2-manifold);
  - planarity above 1e-9 unless the coordinates' rounding explains it (the report's
    planarity_floor, or planarity_floor_solve for a far-off part) or the least flat panel is
    an invalid one, and a warning says so;
  - exit 3 with nothing on stderr;
  - a sanitizer wrote a report (AddressSanitizer, "runtime error:").

Deterministic: run i of --seed S is always the same input and options, so
`fuzz_cli.py --seed S --only i` replays it; bad inputs are kept in --keep.

  tests/cli/fuzz_cli.py --flatfacet build/release/cli/flatfacet --runs 150        # the test
  tests/cli/fuzz_cli.py --flatfacet ... --minutes 20 --jobs 2 --seed 7            # a long hunt
"""
import argparse
import concurrent.futures
import json
import os
import random
import shutil
import struct
import subprocess
import sys
import tempfile
import time

SOURCES = ["epcot.off", "3holes.off", "bumpy.off"]  # small: most of the time goes to bad input
FORMATS = ["off", "obj", "stl", "stl-binary", "ply", "ply-binary"]
TOKENS = [b"nan", b"inf", b"-inf", b"1e308", b"-1", b"0", b"999999999", b"4294967296", b"", b"#",
          b"1.5", b"-0", b"1e-320", b"f", b"v", b"x", b"\x00", b"3 0 0 0", b"12 1 2"]
BINARY_WORDS = [b"\xff\xff\xff\x7f", b"\x00\x00\xc0\x7f", b"\x00\x00\x80\x7f", b"\xff\xff\xff\xff",
                b"\x00\x00\x00\x80", b"\x00\x00\x80\x4f"]


def read_off(path):
    tokens = open(path).read().split()
    nv, nf = int(tokens[1]), int(tokens[2])
    vertices = [[float(x) for x in tokens[4 + 3 * i:7 + 3 * i]] for i in range(nv)]
    faces, p = [], 4 + 3 * nv
    for _ in range(nf):
        k = int(tokens[p])
        faces.append([int(x) for x in tokens[p + 1:p + 1 + k]])
        p += 1 + k
    return vertices, faces


# --- geometry: each breaks the mesh the way real files are broken ---------------------------

def stray_vertex(rng, v, f):
    i = rng.randrange(len(v))
    v[i][rng.randrange(3)] = rng.choice([1e3, 1e6, 4294967296.0, -1e9, 1e12, 1e30])


def non_finite(rng, v, f):
    v[rng.randrange(len(v))][rng.randrange(3)] = rng.choice([float("nan"), float("inf"), -float("inf")])


def flip_faces(rng, v, f):
    for _ in range(rng.randint(1, 20)):
        f[rng.randrange(len(f))].reverse()


def duplicate_faces(rng, v, f):
    for _ in range(rng.randint(1, 5)):
        face = list(f[rng.randrange(len(f))])
        f.append(face[::-1] if rng.random() < 0.5 else face)


def remove_faces(rng, v, f):  # holes, from one face to a patch
    start = rng.randrange(len(f))
    del f[start:start + rng.choice([1, 2, 5, 30, 200])]


def valid_indices(v, *indices):  # an earlier mutation (bad_index) may have broken them
    return all(0 <= i < len(v) for i in indices)


def collapse_vertex(rng, v, f):  # zero-area faces where a vertex lands on its neighbour
    face = f[rng.randrange(len(f))]
    if valid_indices(v, face[0], face[1]):
        v[face[0]] = list(v[face[1]])


def bad_index(rng, v, f):
    face = f[rng.randrange(len(f))]
    face[rng.randrange(len(face))] = rng.choice([len(v), len(v) + 7, -1, 2**31 - 1])


def repeated_index(rng, v, f):
    face = f[rng.randrange(len(f))]
    face[1] = face[0]


def fin(rng, v, f):  # a third face on an edge: non-manifold
    a, b = f[rng.randrange(len(f))][:2]
    if not valid_indices(v, a, b):
        return
    c = [(v[a][d] + v[b][d]) / 2 + rng.uniform(-0.1, 0.1) for d in range(3)]
    v.append(c)
    f.append([a, b, len(v) - 1])


def pinch(rng, v, f):  # two far vertices welded into one: a non-manifold vertex
    a, b = rng.randrange(len(v)), rng.randrange(len(v))
    v[b] = list(v[a])


def far_piece(rng, v, f):
    base = len(v)
    at = rng.choice([10.0, 1e4, 1e8])
    v.extend([[at, 0, 0], [at + 1e-3, 0, 0], [at, 1e-3, 0]])
    f.append([base, base + 1, base + 2])


def unused_vertices(rng, v, f):
    for _ in range(rng.randint(1, 50)):
        v.append([rng.uniform(-1e3, 1e3) for _ in range(3)])


def scale_all(rng, v, f):  # millimetres of a kilometre, or a model drawn at 1e-12
    s = rng.choice([1e-12, 1e-6, 1e6, 1e12])
    for p in v:
        p[:] = [x * s for x in p]


def translate_far(rng, v, f):  # georeferenced coordinates
    t = rng.choice([1e5, 1e7, 1e9])
    for p in v:
        p[0] += t


def flatten(rng, v, f):  # the whole mesh (nearly) in one plane
    s = rng.choice([0.0, 1e-12, 1e-6])
    for p in v:
        p[2] *= s


def quads(rng, v, f):  # polygons the file format allows: two triangles joined, or a bad one
    for _ in range(rng.randint(1, 20)):
        i = rng.randrange(len(f))
        f[i] = f[i] + [rng.randrange(len(v))]


def few_faces(rng, v, f):
    del f[rng.choice([0, 1, 2, 3, 10]):]


GEOMETRY = [stray_vertex, non_finite, flip_faces, duplicate_faces, remove_faces, collapse_vertex, bad_index,
            repeated_index, fin, pinch, far_piece, unused_vertices, scale_all, translate_far, flatten, quads,
            few_faces]


# --- files ---------------------------------------------------------------------------------

def fmt(x):
    return repr(float(x))


def write_mesh(v, f, form):
    if form == "off":
        lines = ["OFF", f"{len(v)} {len(f)} 0"] + [" ".join(map(fmt, p)) for p in v]
        lines += [" ".join(map(str, [len(face)] + face)) for face in f]
        return ("\n".join(lines) + "\n").encode()
    if form == "obj":
        lines = ["v " + " ".join(map(fmt, p)) for p in v]
        lines += ["f " + " ".join(str(i + 1) for i in face) for face in f]
        return ("\n".join(lines) + "\n").encode()
    triangles = [[face[0], face[k], face[k + 1]] for face in f for k in range(1, len(face) - 1)]
    corner = lambda i: v[i] if 0 <= i < len(v) else [0.0, 0.0, 0.0]
    if form == "stl":
        out = ["solid fuzz"]
        for t in triangles:
            out += ["facet normal 0 0 0", "outer loop"] + ["vertex " + " ".join(map(fmt, corner(i))) for i in t]
            out += ["endloop", "endfacet"]
        return ("\n".join(out + ["endsolid fuzz"]) + "\n").encode()
    if form == "stl-binary":
        data = bytearray(b"fuzz".ljust(80, b" ")) + struct.pack("<I", len(triangles))
        for t in triangles:
            data += struct.pack("<3f", 0, 0, 0)
            for i in t:
                data += struct.pack("<3f", *[max(-3e38, min(3e38, x)) if x == x else x for x in corner(i)])
            data += b"\0\0"
        return bytes(data)
    header = ["ply", "format " + ("binary_little_endian" if form == "ply-binary" else "ascii") + " 1.0",
              f"element vertex {len(v)}", "property float x", "property float y", "property float z",
              f"element face {len(f)}", "property list uchar int vertex_indices", "end_header"]
    if form == "ply":
        body = [" ".join(map(fmt, p)) for p in v] + [" ".join(map(str, [len(face)] + face)) for face in f]
        return ("\n".join(header + body) + "\n").encode()
    data = bytearray(("\n".join(header) + "\n").encode())
    for p in v:
        data += struct.pack("<3f", *[max(-3e38, min(3e38, x)) if x == x else x for x in p])
    for face in f:
        data += struct.pack("<B", len(face) % 256) + b"".join(struct.pack("<i", max(-2**31, min(2**31 - 1, i)))
                                                           for i in face)
    return bytes(data)


def break_bytes(rng, data, binary):
    data = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        r = rng.random()
        if r < 0.15 and binary and len(data) > 8:
            i = rng.randrange(len(data) - 4)
            data[i:i + 4] = rng.choice(BINARY_WORDS)
        elif r < 0.3 and data:
            data[rng.randrange(len(data))] = rng.randrange(256)
        elif r < 0.4:
            data = data[:rng.randrange(len(data) + 1)]
        elif r < 0.75:
            tokens = bytes(data).split(b" ")
            i = rng.randrange(len(tokens))
            tokens[i] = rng.choice(TOKENS) + (b"\n" if tokens[i].endswith(b"\n") else b"")
            data = bytearray(b" ".join(tokens))
        else:
            lines = bytes(data).split(b"\n")
            if len(lines) > 2:
                i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
                if rng.random() < 0.5:
                    lines.insert(j, lines[i])
                else:
                    del lines[i]
            data = bytearray(b"\n".join(lines))
    return bytes(data)


def random_options(rng):
    opts = ["--panels", str(rng.choice([1, 2, 3, 4, 5, 8, 13, 30, 60, 200]))]
    if rng.random() < 0.3:
        opts += ["--retries", str(rng.choice([0, 1, 2]))]
    if rng.random() < 0.15:
        opts += ["--prepare", "off"]
    if rng.random() < 0.1:
        opts += ["--fill-holes", str(rng.choice([3, 50, 500]))]
    if rng.random() < 0.1:
        opts += ["--largest-part"]
    if rng.random() < 0.1:
        opts += ["--glass"]
    if rng.random() < 0.1:
        opts += ["--min-angle", str(rng.choice([5, 20]))]
    if rng.random() < 0.1:
        opts += ["--single-point-nodes"]
    if rng.random() < 0.1:
        opts += ["--subdivide", "1"]
    if rng.random() < 0.15:
        opts += ["--thickness", str(rng.choice([0.001, 0.02, 5]))]
    return opts


def make_case(seed, index, sources):
    rng = random.Random(f"{seed}:{index}")
    name = rng.choice(sorted(sources))
    v = [list(p) for p in sources[name][0]]
    f = [list(face) for face in sources[name][1]]
    for _ in range(rng.choice([0, 1, 1, 1, 2, 3])):
        if f and v:
            rng.choice(GEOMETRY)(rng, v, f)
    form = rng.choice(FORMATS)
    data = write_mesh(v, f, form)
    if rng.random() < 0.5:
        data = break_bytes(rng, data, form.endswith("binary"))
    extension = form.split("-")[0]
    return name, extension, data, random_options(rng)


# --- one run -------------------------------------------------------------------------------

def rss_mib(pid):
    try:
        for line in open(f"/proc/{pid}/status"):
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    except OSError:
        pass
    return 0.0


def run_case(flatfacet, work, seed, index, sources, timeout_s, memory_mib):
    name, extension, data, opts = make_case(seed, index, sources)
    folder = os.path.join(work, f"run{index}")
    os.makedirs(folder, exist_ok=True)
    mesh = os.path.join(folder, "in." + extension)
    with open(mesh, "wb") as out:
        out.write(data)
    outputs = {"obj": os.path.join(folder, "panels.obj"), "report": os.path.join(folder, "report.json"),
               "parts": os.path.join(folder, "parts.csv")}
    args = [flatfacet, "remesh", mesh, *opts, "--out", outputs["obj"], "--report", outputs["report"],
            "--parts", outputs["parts"]]
    start = time.monotonic()
    with open(os.path.join(folder, "stderr.txt"), "wb") as err:
        child = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=err)
        problem, peak = "", 0.0
        while child.poll() is None:
            peak = max(peak, rss_mib(child.pid))
            if peak > memory_mib:
                problem = f"grew past {memory_mib} MiB"
            elif time.monotonic() - start > timeout_s:
                problem = f"took over {timeout_s} s"
            if problem:
                child.kill()
                child.wait()
                break
            time.sleep(0.02)
    seconds = time.monotonic() - start
    stderr = open(os.path.join(folder, "stderr.txt"), "rb").read().decode("utf-8", "replace")
    code = child.returncode
    problem = problem or judge(code, stderr, outputs)
    result = {"index": index, "source": name, "format": extension, "options": opts, "exit": code,
              "seconds": round(seconds, 3), "problem": problem, "stderr": stderr.strip()[-400:]}
    if not problem:
        shutil.rmtree(folder, ignore_errors=True)
    return result


def judge(code, stderr, outputs):
    lines = [line for line in stderr.splitlines() if line.strip()]
    if "AddressSanitizer" in stderr or "runtime error:" in stderr or "LeakSanitizer" in stderr:
        return "a sanitizer report"
    if code not in (0, 2, 3):
        return f"exit {code}"
    written = [k for k, path in outputs.items() if os.path.exists(path)]
    if code == 2:
        # One error line; warnings said on load before it are about the input (a mutated
        # file whose surface passes through itself, say).
        errors = [line for line in lines if not line.startswith("flatfacet: warning: ")]
        if len(errors) != 1:
            return f"exit 2 with {len(errors)} stderr lines besides warnings (want 1)"
        if written:
            return f"exit 2 but wrote {', '.join(written)}"
        return ""
    if code == 3 and not lines:
        return "exit 3 with nothing on stderr"
    missing = [k for k in outputs if k not in written]
    if missing:
        return f"exit {code} without {', '.join(missing)}"
    try:
        report = json.load(open(outputs["report"]))
    except ValueError as e:
        return f"the report is not JSON: {e}"
    valid = report.get("status") == "valid"
    folded = "folds over" in stderr  # exit 3 for parts that cannot be cut at --thickness
    if (code == 0) != valid and not (code == 3 and valid and folded):
        return f"exit {code} with status {report.get('status')!r}"
    planarity = report.get("max_planarity")
    if not isinstance(planarity, (int, float)):
        return f"max_planarity {planarity!r}"
    # Above 1e-9 only where the coordinates cannot hold it or at an invalid panel (a vertex
    # whose planes do not meet), and then the designer is told.
    if planarity > 1e-9:
        least_flat = report.get("max_planarity_panel")
        floor = max(report.get("planarity_floor", 0), report.get("planarity_floor_solve", 0))
        explained = floor * 100 >= planarity or (
            code == 3 and any(p.get("panel") == least_flat for p in report.get("invalid", [])))
        if not explained or "flat to" not in stderr:
            return f"max_planarity {planarity} at panel {least_flat} (floor {report.get('planarity_floor')}) unexplained"
    if code == 0:
        truths = {"invalid_panels": report.get("invalid_panels") == 0,
                  "topology_preserved": report.get("topology_preserved") is True,
                  "oriented_manifold": report.get("oriented_manifold") is True,
                  "flipped_edges": report.get("flipped_edges") == 0}
        broken = [k for k, ok in truths.items() if not ok]
        if broken:
            return "exit 0 but " + ", ".join(f"{k}={report.get(k)}" for k in broken)
    return ""


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--flatfacet", default=os.environ.get("FLATFACET"), required="FLATFACET" not in os.environ)
    parser.add_argument("--meshes", default=os.environ.get("FF_SHARED_MESHES", os.path.join(here, "../../../shared/meshes")))
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--runs", type=int, default=0, help="this many runs (with --minutes: at most)")
    parser.add_argument("--minutes", type=float, default=0.0, help="run until this much time has passed")
    parser.add_argument("--only", type=int, default=-1, help="replay run ONLY of --seed")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds per run")
    parser.add_argument("--memory-mib", type=float, default=4096.0, help="resident memory per run")
    parser.add_argument("--keep", default="", help="folder for the bad runs' files (default: a temporary one)")
    a = parser.parse_args()
    if a.runs <= 0 and a.minutes <= 0 and a.only < 0:
        parser.error("give --runs, --minutes or --only")
    sources = {name: read_off(os.path.join(a.meshes, name)) for name in SOURCES}
    work = a.keep or tempfile.mkdtemp(prefix="ff-fuzz-")
    os.makedirs(work, exist_ok=True)
    deadline = time.monotonic() + a.minutes * 60 if a.minutes > 0 else float("inf")
    indices = [a.only] if a.only >= 0 else range(a.runs if a.runs > 0 else 10**9)
    bad, codes, slowest = [], {}, None

    def count(r):
        nonlocal slowest
        codes[r["exit"]] = codes.get(r["exit"], 0) + 1
        if slowest is None or r["seconds"] > slowest["seconds"]:
            slowest = r
        if r["problem"]:
            bad.append(r)
            print(f"BAD run {r['index']} (--seed {a.seed} --only {r['index']}): {r['problem']}; {r['source']} as "
                  f"{r['format']}, {' '.join(r['options'])}; kept in {work}/run{r['index']}; stderr: {r['stderr']}",
                  flush=True)

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        pending = set()
        for index in indices:
            if time.monotonic() > deadline:
                break
            pending.add(pool.submit(run_case, a.flatfacet, work, a.seed, index, sources, a.timeout, a.memory_mib))
            if len(pending) >= 2 * max(1, a.jobs):
                finished, pending = concurrent.futures.wait(pending, return_when=concurrent.futures.FIRST_COMPLETED)
                for future in finished:
                    count(future.result())
        for future in concurrent.futures.as_completed(pending):
            count(future.result())
    exits = ", ".join(f"exit {k}: {v}" for k, v in sorted(codes.items(), key=lambda kv: str(kv[0])))
    print(f"fuzz_cli: {sum(codes.values())} runs (seed {a.seed}; {exits}), {len(bad)} bad")
    if slowest:  # how close the slowest came to --timeout
        print(f"fuzz_cli: slowest run {slowest['index']} took {slowest['seconds']} s of {a.timeout} s "
              f"({slowest['source']} as {slowest['format']}, {' '.join(slowest['options'])}; exit {slowest['exit']})")
    if not bad and not a.keep:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
