#!/usr/bin/env python3
"""Makes the seeds of the fuzz target of state files (fuzz_state_file.cpp) in
tests/fuzz/corpus-states/: descriptions of state files in the target's format (its header
comment), which the harness writes with the HDF5 C API and reads. One seed per good form (as
h5py and arnoldweb write state files) and per class of input the reader refuses (docs/
reliability.md, "Reading HDF5 files"; docs/outputs.md, "State files"). Run it again when the
format of the description changes:

    python3 tests/fuzz/make_state_corpus.py
"""
import math
import pathlib
import struct

HERE = pathlib.Path(__file__).resolve().parent
N = 8
# link: 0 hard, 1 soft, 2 external; storage: 0 contiguous, 1 chunked, 2 deflated, 3 compact,
# 4 first chunk only, 5 external storage, 6 virtual, 7 never written
F64, F32, F16, F64BE, I64, I32, U64, U8 = range(8)
DATASETS = ("momentum", "position_turns", "position", "winding", "status")


def value(kind, v) -> bytes:
    if kind <= F64BE:
        return struct.pack("<d", v)
    return struct.pack("<Q", int(v) % (1 << 64))


def dataset(values, kind=F64, columns=3, link=0, storage=0) -> bytes:
    rows = len(values) // max(columns, 1)
    flags = 1 | (link << 1) | (storage << 3)
    return bytes([flags, kind, rows, columns]) + b"".join(value(kind, v) for v in values)


def momenta(n=N):
    r = math.sqrt(26.0)
    return [c for k in range(n) for c in (r * math.cos(0.7 * k), r * math.sin(0.7 * k), 0.0)]


def seed(final=False, units=(0, 0), time=None, **given) -> bytes:
    out = bytes([1 if final else 0])
    for name in DATASETS:
        out += given.get(name, b"\0")
    out += bytes(units)
    out += b"\0" if time is None else b"\1" + struct.pack("<d", time)
    return out


ZEROS = [0.0] * (3 * N)
SEEDS = {
    "good-turns": seed(position_turns=dataset(ZEROS), winding=dataset([0] * (3 * N), I64),
                       momentum=dataset(momenta())),
    "good-final-deflated": seed(final=True, position_turns=dataset(ZEROS), momentum=dataset(momenta()),
                                winding=dataset([0] * (3 * N), I64, storage=2),
                                status=dataset([0] * N, I64, columns=0, storage=2), time=2.0),
    "good-radians-h5py": seed(position=dataset(ZEROS, F32), momentum=dataset(momenta(), F32), units=(1, 0),
                              time=0.0),
    "good-compact-big-endian": seed(position=dataset(ZEROS, F64BE, storage=3),
                                    momentum=dataset(momenta(), F64BE), units=(2, 1)),
    "soft-link": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta(), link=1)),
    "external-link": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta(), link=2)),
    "external-final": seed(final=True, position_turns=dataset(ZEROS, link=2), momentum=dataset(momenta())),
    "external-storage": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta(), storage=5)),
    "virtual": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta(), storage=6)),
    "never-written": seed(position_turns=dataset(ZEROS, storage=7), momentum=dataset(momenta(), storage=7)),
    "first-chunk-only": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta(), storage=4)),
    "short-status": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta()),
                         status=dataset([0] * (N // 2), I64, columns=0)),
    "winding-overflow": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta()),
                             winding=dataset([0] * 7 + [(1 << 63) - 2] + [0] * (3 * N - 8), I64)),
    "winding-unsigned": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta()),
                             winding=dataset([3] * 3 + [(1 << 64) - 1] + [3] * (3 * N - 4), U64)),
    "winding-int32": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta()),
                          winding=dataset([-5] * (3 * N), I32)),
    "momentum-float16": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta(), F16)),
    "momentum-nan": seed(position_turns=dataset(ZEROS), momentum=dataset([math.nan] + momenta()[1:])),
    "units-degrees": seed(position=dataset(ZEROS), momentum=dataset(momenta()), units=(1, 2)),
    "units-number": seed(position=dataset(ZEROS), momentum=dataset(momenta()), units=(3, 0)),
    "status-uint8": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta()),
                         status=dataset([0] * (N - 1) + [7], U8, columns=0)),
    "time-late": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta()), time=1e17),
    "shape-2-columns": seed(position_turns=dataset(ZEROS), momentum=dataset(momenta()[:2 * N], columns=2)),
}


def main() -> None:
    out = HERE / "corpus-states"
    out.mkdir(exist_ok=True)
    for name, data in SEEDS.items():
        (out / name).write_bytes(data)


if __name__ == "__main__":
    main()
