#!/usr/bin/env python3
"""The layers of arnoldweb, written down and held (docs/design.md, "Layers").

Every source file belongs to one layer: the longest path prefix of LAYERS that
names it. A file may include the files of its own layer and of every layer of
a lower rank; an include of a layer of its own rank or a higher one (a
sibling, or up) fails the check, naming the file, the line and both layers.
A file under a checked folder that no prefix names fails too: a new folder or
public header is given its layer here, in the one table.

  scripts/check-layers.py             check the tree (exit 1 on a violation)
  scripts/check-layers.py --rules     print the layers and what each may include
  scripts/check-layers.py --self-test show that an include going up, or sideways, is caught

Run by ctest (layers, layers.self_test). Only the standard library.
"""
import os
import re
import sys
import tempfile

# (rank, layer, path prefixes), lowest first. A public header (lib/include/arnoldweb/)
# belongs to the layer of what it declares.
LAYERS = [
    (0, "device", ["lib/device/", "kernels_cl/", "kernels_cu/"]),
    (0, "base", ["lib/src/errors.cpp", "lib/src/os/", "lib/include/arnoldweb/errors.hpp",
                 "lib/include/arnoldweb/precision.hpp", "lib/include/arnoldweb/version.hpp"]),
    (1, "params", ["lib/src/params/"]),
    (1, "math", ["lib/src/sphere/", "lib/src/analysis/", "lib/include/arnoldweb/sphere.hpp",
                 "lib/include/arnoldweb/analysis.hpp", "lib/include/arnoldweb/diffusion.hpp"]),
    (2, "physics", ["lib/src/physics/", "lib/include/arnoldweb/methods.hpp", "lib/include/arnoldweb/models.hpp"]),
    (2, "outtable", ["lib/src/output_table/"]),
    (3, "scene", ["lib/src/scene/", "lib/include/arnoldweb/scene.hpp"]),
    (4, "plan", ["lib/src/plan/", "lib/include/arnoldweb/plan.hpp", "lib/include/arnoldweb/job.hpp",
                 "lib/include/arnoldweb/step_guard.hpp", "lib/include/arnoldweb/device_info.hpp",
                 "lib/include/arnoldweb/states.hpp", "lib/include/arnoldweb/accuracy_report.hpp"]),
    (5, "backends", ["lib/src/backends/", "lib/include/arnoldweb/device.hpp"]),
    (6, "run", ["lib/src/run/", "lib/include/arnoldweb/run.hpp", "lib/include/arnoldweb/result.hpp",
                "lib/include/arnoldweb/checkpoint.hpp"]),
    (7, "accuracy", ["lib/src/accuracy/", "lib/include/arnoldweb/accuracy.hpp"]),
    (7, "scale", ["lib/src/scale/", "lib/include/arnoldweb/cluster.hpp"]),
    (7, "outputs", ["lib/src/output/", "lib/src/states/", "lib/include/arnoldweb/output.hpp"]),
    (8, "inputs", ["lib/src/inputs/", "lib/include/arnoldweb/inputs.hpp"]),
    (8, "pictures", ["lib/src/pictures/"]),
    (9, "api", ["lib/include/arnoldweb/arnoldweb.hpp"]),
    (10, "explorer", ["explorer/"]),
    (10, "bench", ["bench/"]),
    (11, "faces", ["cli/", "python/src/"]),
]

# Where the build looks for a quoted include, after the including file's own folder.
SEARCH = ["lib/src/", "lib/include/", "lib/device/", "bench/include/", "bench/baselines/", "explorer/include/"]
# Files the build generates, by the name they are included as, and their layer.
GENERATED = {
    "models/aw_models.h": "device",
    "model_list.inc": "physics",
    "arnoldweb/version.hpp": "base",
    "cpu_runtime_config.hpp": "backends",
}
SOURCES = (".c", ".h", ".cpp", ".hpp", ".inc", ".in", ".cl", ".cu")
INCLUDE = re.compile(r'^\s*#\s*include\s*["<]([^">]+)[">]')
RANK = {name: rank for rank, name, _ in LAYERS}


def layer_of(path):
    best = None
    for _, name, prefixes in LAYERS:
        for p in prefixes:
            if (path == p or path.startswith(p)) and (best is None or len(p) > len(best[1])):
                best = (name, p)
    return best[0] if best else None


def checked_files(root):
    for top in sorted({p.split("/")[0] for _, _, ps in LAYERS for p in ps}):
        base = os.path.join(root, top)
        if os.path.isfile(base):
            yield top
            continue
        for folder, dirs, files in os.walk(base):
            dirs[:] = sorted(d for d in dirs if d not in ("tests", "build", "__pycache__"))
            for f in sorted(files):
                if f.endswith(SOURCES):
                    yield os.path.relpath(os.path.join(folder, f), root).replace(os.sep, "/")


def resolve(root, path, name):
    """The tree's file an include names, or None (a system header, a generated file)."""
    for folder in [os.path.dirname(path) + "/"] + SEARCH:
        candidate = os.path.normpath(folder + name).replace(os.sep, "/")
        if os.path.isfile(os.path.join(root, candidate)):
            return candidate
        if os.path.isfile(os.path.join(root, candidate + ".in")):  # configured (version.hpp)
            return candidate + ".in"
    return None


def violations(root):
    found = []
    for path in checked_files(root):
        own = layer_of(path)
        if own is None:
            found.append(f"{path}: in no layer: give its folder or header a layer in scripts/check-layers.py")
            continue
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                target = resolve(root, path, m.group(1))
                other = layer_of(target) if target else GENERATED.get(m.group(1))
                if other is None or other == own or RANK[other] < RANK[own]:
                    continue
                where = "up" if RANK[other] > RANK[own] else "sideways"
                found.append(f"{path}:{number}: includes \"{m.group(1)}\": {own} (rank {RANK[own]}) may not "
                             f"include {other} (rank {RANK[other]}), an include {where}")
    return found


def rules():
    lines = []
    for rank, name, prefixes in LAYERS:
        below = [n for r, n, _ in LAYERS if r < rank]
        lines.append(f"{rank:2d} {name:9s} {' '.join(prefixes)}")
        lines.append(f"   {'':9s} may include: {', '.join(below) if below else 'only itself'}")
    return "\n".join(lines)


def self_test():
    """An include up and one sideways are each found; includes down and within a layer pass."""
    with tempfile.TemporaryDirectory() as root:
        files = {
            "lib/src/plan/plan.cpp": '#include "plan/plan.hpp"\n#include "physics/model.hpp"\n#include "aw_params.h"\n',
            "lib/src/plan/plan.hpp": "",
            "lib/src/physics/model.hpp": '#include <vector>\n',
            "lib/device/aw_params.h": "",
            "lib/src/plan/job_plan.cpp": '// a plan asks the outputs\n#include "output/pictures.hpp"\n',
            "lib/src/output/pictures.hpp": "",
            "lib/src/accuracy/pilot.cpp": '#include "scale/worker.hpp"\n',
            "lib/src/scale/worker.hpp": "",
        }
        for path, text in files.items():
            os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
            with open(os.path.join(root, path), "w") as f:
                f.write(text)
        found = violations(root)
        expected = ["lib/src/plan/job_plan.cpp:2: includes \"output/pictures.hpp\": plan (rank 4) may not include "
                    "outputs (rank 7), an include up",
                    "lib/src/accuracy/pilot.cpp:1: includes \"scale/worker.hpp\": accuracy (rank 7) may not include "
                    "scale (rank 7), an include sideways"]
        if sorted(found) != sorted(expected):
            print("self-test FAILED: found\n  " + "\n  ".join(found) + "\nexpected\n  " + "\n  ".join(expected))
            return 1
    print("self-test: an include up and one sideways are caught; includes down and within a layer pass")
    return 0


def main(argv):
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
    if "--root" in argv:
        root = argv[argv.index("--root") + 1]
    if "--rules" in argv:
        print(rules())
        return 0
    if "--self-test" in argv:
        return self_test()
    found = violations(root)
    for v in found:
        print(v)
    if found:
        print(f"{len(found)} include(s) against the layers (docs/design.md, \"Layers\")")
        return 1
    print(f"layers: every include of {sum(1 for _ in checked_files(root))} files goes down or stays in its layer")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
