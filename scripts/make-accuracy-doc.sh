#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the tables and plots of docs/accuracy.md (issue 7 item 8): runs the studies of
# bench/studies (Cantilever, TruthCube, UniaxialBlock, Hertz) with `stroma bench` (full versions, one thread), keeps their CSV and PNG under
# docs/accuracy/, and rewrites each table of docs/accuracy.md between its markers
# <!-- BEGIN name --> and <!-- END name --> (the prose around them is written by hand).
#
#   scripts/make-accuracy-doc.sh [STROMA]     (default build/bin/stroma; about 11 minutes)
#   scripts/make-accuracy-doc.sh --tables-only   (the tables again from docs/accuracy/*.csv)
#
# A study whose rows fail still gives its table (the status column says why); the script stops
# only when a study cannot run at all (exit code 2) or python3 is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
stroma=${1:-build/bin/stroma}
out=docs/accuracy
mkdir -p "$out"
command -v python3 >/dev/null || { echo "make-accuracy-doc: python3 is needed" >&2; exit 2; }

studies="Cantilever TruthCube UniaxialBlock Hertz"
[ "$stroma" = --tables-only ] && studies=""
for study in $studies; do
  code=0
  "$stroma" bench "bench/studies/$study.xml" --output "$out" --threads 1 || code=$?
  if [ "$code" -ge 2 ]; then echo "make-accuracy-doc: study $study did not run" >&2; exit 2; fi
  # The gnuplot script and data beside the PNG name this machine's paths: the CSV is the data.
  rm -f "$out/$study.png.gp" "$out/$study.png.dat"
done

python3 - "$out" docs/accuracy.md <<'PY'
import csv, re, sys
out, doc = sys.argv[1], sys.argv[2]

def rows(study):
    with open(f"{out}/{study}.csv", newline="") as f:
        return list(csv.DictReader(f))

def num(text, digits=3):
    return f"{float(text):.{digits}g}" if text else "-"

def cantilever():
    """Per solver, models x resolutions: max tip error (% of the tip deflection) and wall time."""
    r = rows("Cantilever")
    resolutions = list(dict.fromkeys(x["resolution"] for x in r))
    text = []
    for solver in dict.fromkeys(x["solver"] for x in r):
        text.append(f"\n**{solver}**: max tip error in % of the tip deflection (wall time of the "
                    "steps, s)\n")
        text.append("| model | " + " | ".join(resolutions) + " |")
        text.append("|---" * (len(resolutions) + 1) + "|")
        for model in dict.fromkeys(x["model"] for x in r if x["solver"] == solver):
            cells = []
            for res in resolutions:
                hit = [x for x in r if x["model"] == model and x["solver"] == solver
                       and x["resolution"] == res]
                if not hit:
                    cells.append("")
                elif hit[0]["status"] != "ok":
                    cells.append(hit[0]["status"])
                else:
                    cells.append(f"{100 * float(hit[0]['max_error']):.3g} ({num(hit[0]['wall_s'], 2)})")
            text.append(f"| {model} | " + " | ".join(cells) + " |")
    return "\n".join(text).strip("\n")

def truthcube():
    r = rows("TruthCube")
    text = ["| model | cells | solver | 5 %: mean / max (mm) | 12.5 %: mean / max (mm) | wall (s) | steps/s |",
            "|---|---|---|---|---|---|---|"]
    for x in r:
        if x["status"] != "ok":
            text.append(f"| {x['model']} | {x['resolution']} | {x['solver']} | {x['status']} | | | |")
            continue
        text.append(f"| {x['model']} | {x['resolution']} | {x['solver']} | "
                    f"{num(x['mean_5pc_mm'])} / {num(x['max_5pc_mm'])} | "
                    f"{num(x['mean_12pc_mm'])} / {num(x['max_error'])} | {num(x['wall_s'], 2)} | "
                    f"{num(x['steps_per_s'], 3)} |")
    return "\n".join(text)

def block():
    r = rows("UniaxialBlock")
    text = ["| model | cells | to neo-Hookean | to linear | to StVK | status |",
            "|---|---|---|---|---|---|"]
    for x in r:
        text.append(f"| {x['model']} | {x['resolution']} | {num(x['max_error'], 2)} | "
                    f"{num(x['vs_linear'], 2)} | {num(x['vs_stvk'], 2)} | {x['status']} |")
    return "\n".join(text)

def hertz():
    """Per response, meshes: the largest error over the 4 indentations (%) and the signed errors
    at d / R = 2 %, against the half-space solution at the centre's depth and against the law."""
    r = rows("Hertz")
    resolutions = list(dict.fromkeys(x["resolution"] for x in r))
    def cell(model, res, text):
        hit = [x for x in r if x["model"] == model and x["resolution"] == res]
        if not hit:
            return ""
        return hit[0]["status"] if hit[0]["status"] != "ok" else text(hit[0])
    pc = lambda v: f"{100 * float(v):+.3g}"
    tables = [("largest |error| over d / R = 0.5 to 2 %, in %: against the half-space solution / "
               "against F_H(delta) (wall time of the 4 steps, s)",
               lambda x: f"{100 * float(x['max_error']):.3g} / {100 * float(x['max_hertz_error']):.3g} "
                         f"({num(x['wall_s'], 2)})"),
              ("signed error at d / R = 2 %, in %: against the half-space solution / against "
               "F_H(delta); contact force (N)",
               lambda x: f"{pc(x['half_space_error_2pc'])} / {pc(x['hertz_error_2pc'])}; "
                         f"{num(x['force_2pc_N'], 4)}")]
    text = []
    for title, show in tables:
        text.append(f"\n**{title}**\n")
        text.append("| response | " + " | ".join(f"N = {x}" for x in resolutions) + " |")
        text.append("|---" * (len(resolutions) + 1) + "|")
        for model in dict.fromkeys(x["model"] for x in r):
            text.append(f"| {model} | " + " | ".join(cell(model, res, show) for res in resolutions)
                        + " |")
    return "\n".join(text).strip("\n")

text = open(doc).read()
for name, table in (("Cantilever", cantilever()), ("TruthCube", truthcube()),
                    ("UniaxialBlock", block()), ("Hertz", hertz())):
    pattern = re.compile(rf"<!-- BEGIN {name} -->.*?<!-- END {name} -->", re.S)
    if not pattern.search(text):
        sys.exit(f"make-accuracy-doc: {doc} has no markers for {name}")
    text = pattern.sub(lambda m: f"<!-- BEGIN {name} -->\n{table}\n<!-- END {name} -->", text)
open(doc, "w").write(text)
print(f"Wrote {doc}")
PY
