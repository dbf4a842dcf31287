#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Stroma and SOFA side by side on SOFA's own scenes (issue 20).

For each scene of SCENES (files of ../shared/sofa, run unmodified): each engine's own steps/s,
one thread each, alternating runs, the median of --rounds; then the same result: SOFA's
positions after N steps (its WriteState, in a copy of the scene with a WriteState beside each
MechanicalObject) against Stroma's (`stroma run --export-state`), the largest difference over
the states both have (matched in scene order, by size; centers only for rigid frames). Writes the table (markdown) to stdout and, with --write-readme, into bench/README.md
between its side-by-side markers.

SOFA is ../shared/sofa-runtime's runSofa (RUNSOFA=path overrides; see its README to install);
without it the script says so and exits 0 with Stroma's column only. The machine must be
otherwise idle: the two engines' rates are compared, not absolute numbers.

    bench/side-by-side.py [--rounds 3] [--only SUBSTRING] [--no-state] [--write-readme]
"""

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SHARED = Path(os.environ.get("STROMA_SHARED_DIR", ROOT.parent / "shared"))
SOFA = SHARED / "sofa"

# (scene under ../shared/sofa, steps): issue 20's list.
SCENES = [
    ("benchmarks/TetrahedronFEMForceField_beam10x10x40_cpu.scn", 200),
    ("benchmarks/TetrahedronFEMForceField_beam16x16x76_cpu.scn", 50),
    ("benchmarks/HexahedronFEMForceField_beam10x10x40_cpu.scn", 200),
    ("benchmarks/HexahedronFEMForceField_beam16x16x76_cpu.scn", 50),
    ("examples/Benchmark/Performance/MatrixAssembly/MatrixAssembly_matrixfreeCG.scn", 200),
    ("examples/Benchmark/Performance/MatrixAssembly/MatrixAssembly_assembledCG.scn", 200),
    ("examples/Benchmark/Performance/MatrixAssembly/MatrixAssembly_assembledCG_blocs.scn", 200),
    ("examples/Benchmark/Performance/MatrixAssembly/MatrixAssembly_direct.scn", 200),
    ("examples/Benchmark/Performance/MatrixAssembly/MatrixAssembly_direct_blocs.scn", 200),
    ("examples/Component/SolidMechanics/TensorMass/TetrahedralTensorMassForceField.scn", 1000),
    ("examples/Component/SolidMechanics/FEM/HexahedronFEMForceField.scn", 1000),
    ("examples/Demos/liver.scn", 1000),
    ("examples/Demos/fallingBeamLagrangianCollision.scn", 100),
]

BEGIN = "<!-- side-by-side:begin (bench/side-by-side.py --write-readme) -->"
END = "<!-- side-by-side:end -->"


def find_runsofa():
    given = os.environ.get("RUNSOFA") or shutil.which("runSofa")
    for candidate in (given, "/tmp/sofa/sofa/bin/runSofa"):
        if candidate and Path(candidate).is_file():
            return candidate
    return None


def sofa_env(scene):
    env = dict(os.environ, OMP_NUM_THREADS="1")
    # The scene's own folder first: a copy of the scene elsewhere finds its files as SOFA would.
    env["SOFA_DATA_PATH"] = ":".join(str(p) for p in (scene.parent, SOFA / "share", SOFA / "examples"))
    return env


def run_sofa(runsofa, scene, steps, timeout):
    out = subprocess.run([runsofa, "-g", "batch", "-n", str(steps), str(scene)], env=sofa_env(scene),
                         capture_output=True, text=True, timeout=timeout)
    m = re.search(r"iterations done in [0-9.e+-]+ s \( *([0-9.e+-]+) FPS\)", out.stdout + out.stderr)
    if not m:
        raise RuntimeError("runSofa printed no rate:\n" + (out.stdout + out.stderr)[-2000:])
    return float(m.group(1))


def stroma_command(stroma, scene, steps):
    return [stroma, "run", str(scene), "-n", str(steps), "--threads", "1",
            "--data-path", str(SOFA / "share"), "--data-path", str(SOFA / "examples")]


def run_stroma(stroma, scene, steps, timeout, extra=()):
    out = subprocess.run(stroma_command(stroma, scene, steps) + list(extra), capture_output=True,
                         text=True, timeout=timeout)
    if out.returncode != 0:
        errors = [l for l in (out.stdout + out.stderr).splitlines() if "error" in l]
        raise RuntimeError(f"stroma run exited {out.returncode}: " + (errors[0] if errors else ""))
    m = re.search(r"\(([0-9.e+-]+) steps/s\)", out.stdout)
    if not m:
        raise RuntimeError("stroma printed no rate:\n" + out.stdout[-2000:])
    return float(m.group(1))


def scene_dt(text):
    m = re.search(r"<Node[^>]*\bdt\s*=\s*\"([^\"]+)\"", text)
    return float(m.group(1)) if m else 0.01


def sofa_positions(runsofa, scene, steps, work, timeout):
    """SOFA's positions after `steps` steps, per MechanicalObject in scene order."""
    text = scene.read_text()
    period = scene_dt(text) * steps
    count = 0

    def add_writer(match):
        nonlocal count
        count += 1
        return (match.group(0) + f'\n<WriteState filename="{work}/sofa-{count}.state" '
                f'period="{period!r}" writeX="1" />')

    copy = re.sub(r"<MechanicalObject\b[^>]*/>", add_writer, text)
    copy = re.sub(r"(<Node\b[^>]*[^/]>)", r'\1\n<RequiredPlugin name="Sofa.Component.Playback" />',
                  copy, count=1)
    path = work / scene.name
    path.write_text(copy)
    # SOFA writes the state at the start of a step: N + 1 steps give the state after N.
    subprocess.run([runsofa, "-g", "batch", "-n", str(steps + 1), str(path)], env=sofa_env(scene),
                   capture_output=True, text=True, timeout=timeout)
    states = []
    for k in range(1, count + 1):
        f = work / f"sofa-{k}.state"
        records = re.findall(r"X=\s*([^\n]*)", f.read_text()) if f.exists() else []
        states.append([float(v) for v in records[-1].split()] if records else None)
    return states


def stroma_positions(stroma, scene, steps, work, timeout):
    """Stroma's positions after `steps` steps per state in graph order, with their template."""
    out_file = work / "stroma.state"
    run_stroma(stroma, scene, steps, timeout, ["--export-state", str(out_file)])
    states, current = [], None
    for line in out_file.read_text().splitlines():
        fields = line.split()
        if not fields or line.startswith("#") or fields[0] in ("snapshot", "end", "data"):
            continue
        if fields[0] == "state":
            current = {"template": fields[2], "coords": int(fields[4]), "values": []}
            states.append(current)
        elif current is not None:
            current["values"].extend(float(v) for v in fields[:current["coords"]])
    return states


def largest_difference(sofa_states, stroma_states):
    """Largest |x_sofa - x_stroma| over the states matched in order by size (centers only for
    rigid frames), and how many states were matched."""
    worst, matched = 0.0, 0
    remaining = list(stroma_states)
    for values in sofa_states:
        if not values:
            continue
        for i, s in enumerate(remaining):
            if len(s["values"]) == len(values):
                c = s["coords"]
                for k, (a, b) in enumerate(zip(values, s["values"])):
                    if c == 7 and k % 7 >= 3:
                        continue
                    worst = max(worst, abs(a - b))
                matched += 1
                del remaining[:i + 1]
                break
    return worst, matched


def measure(scene_rel, steps, args, runsofa):
    scene = SOFA / scene_rel
    row = {"scene": scene_rel, "steps": steps}
    sofa_rates, stroma_rates = [], []
    for _ in range(args.rounds):
        if runsofa:
            sofa_rates.append(run_sofa(runsofa, scene, steps, args.timeout))
        stroma_rates.append(run_stroma(args.stroma, scene, steps, args.timeout))
    row["sofa"] = statistics.median(sofa_rates) if sofa_rates else None
    row["stroma"] = statistics.median(stroma_rates)
    if runsofa and not args.no_state:
        with tempfile.TemporaryDirectory() as tmp:
            work = Path(tmp)
            sofa_states = sofa_positions(runsofa, scene, steps, work, args.timeout)
            stroma_states = stroma_positions(args.stroma, scene, steps, work, args.timeout)
            row["difference"], row["matched"] = largest_difference(sofa_states, stroma_states)
    return row


def table(rows):
    lines = ["| scene (steps) | SOFA steps/s | Stroma steps/s | ratio | largest position difference (states matched) |",
             "|---|---|---|---|---|"]
    for r in rows:
        name = r["scene"].split("/")[-1] + f" ({r['steps']})"
        if "error" in r:
            lines.append(f"| {name} | | | | {r['error']} |")
            continue
        sofa = f"{r['sofa']:.1f}" if r.get("sofa") else "(no runSofa)"
        ratio = f"{r['stroma'] / r['sofa']:.2f}" if r.get("sofa") else ""
        diff = f"{r['difference']:.3g} ({r['matched']})" if "difference" in r else ""
        lines.append(f"| {name} | {sofa} | {r['stroma']:.1f} | {ratio} | {diff} |")
    return "\n".join(lines)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--only", help="run only the scenes whose path contains this")
    p.add_argument("--no-state", action="store_true", help="skip the position comparison")
    p.add_argument("--write-readme", action="store_true")
    p.add_argument("--timeout", type=float, default=900)
    p.add_argument("--stroma", default=str(ROOT / "build/bin/stroma"))
    args = p.parse_args()
    if not SOFA.is_dir():
        print(f"{SOFA} not found: nothing to compare", file=sys.stderr)
        return 0
    runsofa = find_runsofa()
    if not runsofa:
        print("runSofa not found (../shared/sofa-runtime/README.md says how to install it): "
              "Stroma's column only", file=sys.stderr)
    rows = []
    for scene_rel, steps in SCENES:
        if args.only and args.only not in scene_rel:
            continue
        print(f"... {scene_rel}", file=sys.stderr, flush=True)
        try:
            rows.append(measure(scene_rel, steps, args, runsofa))
        except (RuntimeError, subprocess.TimeoutExpired) as e:
            rows.append({"scene": scene_rel, "steps": steps, "error": str(e).splitlines()[0]})
    text = table(rows)
    print(text)
    if args.write_readme:
        readme = ROOT / "bench/README.md"
        content = readme.read_text()
        if BEGIN not in content or END not in content:
            print(f"bench/README.md has no side-by-side markers", file=sys.stderr)
            return 1
        head, rest = content.split(BEGIN, 1)
        tail = rest.split(END, 1)[1]
        readme.write_text(head + BEGIN + "\n" + text + "\n" + END + tail)
    return 0


if __name__ == "__main__":
    sys.exit(main())
