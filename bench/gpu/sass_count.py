#!/usr/bin/env python3
"""Instructions per integration step of the CUDA ensemble kernel, by class,
read from its SASS (no GPU needed: NVRTC, through build/arnoldweb_cubin, and
nvdisasm or cuobjdump).

The kernel of a configuration is compiled as the cuda backend compiles it (the
defines `arnoldweb check` prints for a scene, the backend's NVRTC options, and
the extra options given here as ARNOLDWEB_NVRTC_OPTIONS would give them). The
step loop is found from the control flow (the loops of aw_ensemble are its
backward branches): the smallest loop that holds the wrap's three roundings
(x + 1.5 2^52 by DADD; a sincos rounds by DFMA) is the step loop, and a loop
inside it with force evaluations (x - 1.5 2^52: three a force) is the stage
loop, counted (stages - 1) times a step (kick-first; stages for drift-first);
with the stages unrolled there is none. The wrap's roundings give the
trajectory-steps of an iteration (one: a thread takes one trajectory);
the subtractions, 3 stages + 3 a step of the paper's model, check it. Written
for the paper's model (seibert2011) and its kinetic energy.

  python3 bench/gpu/sass_count.py [--scene S] [--defines=D] [--options=O] [--sass FILE]
  python3 bench/gpu/sass_count.py --variants "default=;unroll=-DAW_CUDA_UNROLL_STAGES=1"

  --scene    a scene (default scenes/fig3_e15.toml: Figure 3 panel (a));
             its [[panel]] sections are left out
  --defines  the kernel's -D options instead of the scene's
  --options  extra NVRTC options, e.g. --options="-DAW_CUDA_UNROLL_STAGES=0" (with =)
  --variants a Markdown table, a row per variant (the format of
             bench/gpu/rates.sh's AW_RATES_VARIANTS: name=options, ';' between)
  --sass     also write the disassembly here
nvdisasm (or cuobjdump) is taken from $NVDISASM ($CUOBJDUMP), PATH,
/usr/local/cuda/bin or pip's packages (pip install nvidia-cuda-nvdisasm
nvidia-cuda-cuobjdump); cuobjdump also gives the registers.
"""
import argparse
import collections
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MAGIC = "6.75539944105574400000e+15"

CLASSES = [  # (name, predicate on the opcode's first word)
    ("FP64", lambda o: o.split(".")[0] in ("DFMA", "DMUL", "DADD", "DSETP", "DMNMX", "DSET")),
    ("FP32 pipe (FSEL, ...)", lambda o: o.split(".")[0] in ("FSEL", "FADD", "FMUL", "FFMA", "FSETP", "FMNMX", "FCHK")),
    ("conversion", lambda o: o.split(".")[0] in ("F2F", "F2I", "I2F", "FRND", "I2FP", "F2IP")),
    ("uniform", lambda o: o.startswith("U") or o.startswith("S2UR") or o.startswith("R2UR")),
    ("memory", lambda o: o.split(".")[0] in ("LDG", "STG", "LDC", "LDS", "STS", "LDL", "STL", "LD", "ST", "ATOM",
                                             "ATOMG", "RED", "LDGSTS")),
    ("control", lambda o: o.split(".")[0] in ("BRA", "BSSY", "BSYNC", "YIELD", "EXIT", "CALL", "RET", "NOP",
                                              "WARPSYNC", "BAR", "BREAK", "BMOV")),
    ("integer and predicate", lambda o: True),
]


def tool(*names):
    for n in names:
        if os.environ.get(n.upper()):
            return os.environ[n.upper()]
        found = shutil.which(n) or (os.path.exists(f"/usr/local/cuda/bin/{n}") and f"/usr/local/cuda/bin/{n}")
        if found:
            return found
        for p in sys.path + glob.glob("/usr/lib/python3*/site-packages") + glob.glob(os.path.join(sys.prefix, "lib/python3*/site-packages")):
            cand = glob.glob(os.path.join(p, "nvidia", "cu*", "bin", n))
            if cand:
                return cand[0]
    sys.exit(f"sass_count: {' or '.join(names)} not found (pip install nvidia-cuda-nvdisasm nvidia-cuda-cuobjdump, "
             f"or set ${names[0].upper()})")


def scene_defines(scene):
    with open(scene) as f:
        text = f.read()
    text = re.split(r"^\[\[panel\]\]", text, flags=re.M)[0]
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as t:
        t.write(text)
    try:
        out = subprocess.run([os.path.join(ROOT, "build", "arnoldweb"), "check", t.name, "--device", "cpu"],
                             capture_output=True, text=True, check=True).stdout
    finally:
        os.unlink(t.name)
    for line in out.splitlines():
        if line.startswith("kernel "):
            return line.split(None, 1)[1].strip()
    sys.exit(f"sass_count: `arnoldweb check {scene}` printed no kernel line")


def resources(cubin):
    """aw_ensemble's registers and stack from cuobjdump -res-usage, or '' without cuobjdump."""
    try:
        dump = tool("cuobjdump")
        out = subprocess.run([dump, "-res-usage", cubin], capture_output=True, text=True, check=True).stdout
    except (SystemExit, subprocess.CalledProcessError):
        return ""
    m = re.search(r"Function aw_ensemble:\s*\n\s*REG:(\d+) STACK:(\d+)", out)
    return f"{m.group(1)} registers, stack {m.group(2)} bytes" if m else ""


def disassemble(cubin):
    dis = tool("nvdisasm", "cuobjdump")
    args = [dis, "-c", cubin] if os.path.basename(dis).startswith("nvdisasm") else [dis, "-sass", cubin]
    return subprocess.run(args, capture_output=True, text=True, check=True).stdout


def parse(sass, function="aw_ensemble"):
    """[(address, opcode, text)] of `function`, and label -> address."""
    ins, labels, inside, pending = [], {}, False, []
    for line in sass.splitlines():
        s = line.strip()
        head = re.match(r"^(?:\.text\.|Function : )(\w+)", s)
        if head:
            inside = head.group(1) == function
            continue
        if not inside:
            continue
        lab = re.match(r"^(\.L_x_\d+):", s)
        if lab:
            pending.append(lab.group(1))
            continue
        m = re.match(r"^/\*([0-9a-f]+)\*/\s+(.*?)\s*;", s)
        if not m:
            continue
        addr, text = int(m.group(1), 16), m.group(2)
        for p in pending:
            labels[p] = addr
        pending = []
        body = re.sub(r"^@!?U?P\w+\s+", "", text)
        ins.append((addr, body.split()[0], text))
    return ins, labels


def loops(ins, labels):
    """{header address: end address} from the backward branches."""
    out = {}
    for addr, op, text in ins:
        if not op.startswith("BRA"):
            continue
        t = re.search(r"`\((\.L_x_\d+)\)", text)
        target = labels.get(t.group(1)) if t else None
        if target is None:
            h = re.search(r"\b0x([0-9a-f]+)\b", text)
            target = int(h.group(1), 16) if h else None
        if target is not None and target <= addr:
            out[target] = max(out.get(target, 0), addr)
    return out


def classify(op):
    for name, pred in CLASSES:
        if pred(op):
            return name


def count(ins, lo, hi, skip=()):
    c = collections.Counter()
    for addr, op, text in ins:
        if lo <= addr <= hi and not any(a <= addr <= b for a, b in skip):
            c[op] += 1
            if op.startswith("DADD") and "-" + MAGIC in text:
                c["(magic subtractions)"] += 1
            elif op.startswith("DADD") and MAGIC in text:
                c["(wrap roundings)"] += 1
    return c


def compile_and_disassemble(a, defines):
    with tempfile.TemporaryDirectory() as d:
        cubin = os.path.join(d, "k.cubin")
        env = dict(os.environ, ARNOLDWEB_NVRTC_OPTIONS=a.options)
        r = subprocess.run([os.path.join(ROOT, "build", "arnoldweb_cubin"), a.arch, cubin] + defines.split(),
                           env=env, capture_output=True, text=True)
        if r.returncode:
            sys.exit(f"sass_count: arnoldweb_cubin failed:\n{r.stderr}")
        return r.stdout.strip(), disassemble(cubin), resources(cubin)


def step_counts(sass, defines):
    """(per-step Counter of opcodes, description of the loops, trajectory-steps an iteration)."""
    stages = int(re.search(r"-DAW_STAGES=(\d+)", defines).group(1))
    kick_first = re.search(r"-DAW_KICK_FIRST=1", defines) is not None
    ins, labels = parse(sass)
    lp = loops(ins, labels)
    # the step loop: the smallest loop with the wrap's roundings (x + 1.5 2^52 by DADD, 3 a step; the
    # sincos round by DFMA); an inner loop of it with force evaluations (3 subtractions a trajectory)
    # is the stage loop
    with_wrap = [he for he in lp.items() if count(ins, *he)["(wrap roundings)"] >= 3]
    if not with_wrap:
        sys.exit("sass_count: no loop of aw_ensemble holds the wrap's roundings (not the paper's stepper?)")
    outer = min(with_wrap, key=lambda he: he[1] - he[0])
    subtractions = lambda he: count(ins, *he)["(magic subtractions)"]
    stage_loops = [(h, e) for h, e in lp.items()
                   if outer[0] < h and e < outer[1] and subtractions((h, e)) and subtractions((h, e)) % 3 == 0]
    trips = stages - 1 if kick_first else stages
    step = count(ins, *outer, skip=stage_loops)
    shape = f"step loop {outer[0]:#06x}-{outer[1]:#06x}"
    for h, e in stage_loops:
        for op, n in count(ins, h, e).items():
            step[op] += trips * n
        shape += f" around the stage loop {h:#06x}-{e:#06x} (x {trips})"
    if not stage_loops:
        shape += " (stages unrolled)"
    per_iter = step["(wrap roundings)"] / 3
    shape += (f"; {per_iter:g} trajectory-step(s) an iteration; {step['(magic subtractions)'] / per_iter:g} "
              f"rounding subtractions a step (3 stages + 3 = {3 * stages + 3})")
    return step, shape, per_iter


def by_class(step, per_iter):
    c = collections.Counter()
    for op, n in step.items():
        if not op.startswith("("):
            c[classify(op)] += n / per_iter
    return c


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scene", default=os.path.join(ROOT, "scenes", "fig3_e15.toml"))
    ap.add_argument("--defines")
    ap.add_argument("--options", default="")
    ap.add_argument("--variants", help='a table of variants, as AW_RATES_VARIANTS: "default=;name=-DX=1;..."')
    ap.add_argument("--sass")
    ap.add_argument("--cubin", help="count this cubin instead of compiling one (with --defines)")
    ap.add_argument("--arch", default="90")
    a = ap.parse_args()
    defines = a.defines or scene_defines(a.scene)
    if a.variants:
        names = [c for c, _ in CLASSES]
        print("| variant (NVRTC options) | " + " | ".join(names) + " | all | registers |")
        print("|---" * (len(names) + 3) + "|")
        for v in a.variants.split(";"):
            name, _, options = v.partition("=")
            a.options = options
            _, sass, res = compile_and_disassemble(a, defines)
            step, _, per_iter = step_counts(sass, defines)
            c = by_class(step, per_iter)
            print(f"| {name} (" + (f"`{options}`" if options else "none") + ") | " +
                  " | ".join(f"{c[n]:g}" for n in names) +
                  f" | {sum(c.values()):g} | {res} |")
        return
    if a.cubin:
        options, sass, res = "(" + a.cubin + ") " + defines, disassemble(a.cubin), resources(a.cubin)
    else:
        options, sass, res = compile_and_disassemble(a, defines)
    if a.sass:
        with open(a.sass, "w") as f:
            f.write(sass)
    step, shape, per_iter = step_counts(sass, defines)
    c = by_class(step, per_iter)
    print(f"options   {options}")
    print(f"loop      {shape}")
    if res:
        print(f"kernel    {res}")
    print(f"{'class':24s} {'per step':>9s}")
    for name, _ in CLASSES:
        print(f"{name:24s} {c[name]:9.1f}")
    print(f"{'all':24s} {sum(c.values()):9.1f}")
    ops = sorted(((n, op) for op, n in step.items() if not op.startswith("(")), reverse=True)
    print("opcodes per step: " + ", ".join(f"{op} {n / per_iter:g}" for n, op in ops))


if __name__ == "__main__":
    main()
