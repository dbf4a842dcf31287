#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Runs every SOFA scene (.scn) under a folder with `stroma run -n 100` and reports which run.

Each scene runs in a folder of its own (exporters write into the current folder), with SOFA's
data path (--data-path <sofa>/share --data-path <sofa>/examples, as the README says), one
thread per run (--threads 1; --jobs runs several at once) and a time limit (a scene still
running then is killed: "timeout"). Outcomes:

  runs     exit code 0: loaded and ran every step without an error
  error    exit code 1 (a step failed, or the state diverged) or 2 (bad input: the scene did
           not load, e.g. it uses a component Stroma lacks)
  crash    any other exit code, or killed by a signal: a bug
  timeout  still running at the time limit: a bug (or a very slow scene)

Writes docs/sofa-compatibility.md (the summary, the components Stroma lacks ranked by the
scenes they block, and every scene grouped by the first component it lacks) and
docs/sofa-compatibility.tsv (one line a scene); --write-list FILE writes the scenes that run,
for tests/scenes/sofa-running-scenes.txt. Standard library only.

  scripts/sofa-corpus.py --jobs 2
  scripts/sofa-corpus.py --stroma build/bin/stroma --write-list tests/scenes/sofa-running-scenes.txt
"""

import argparse
import collections
import concurrent.futures
import datetime
import os
import platform
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time

CLONE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The texts with which Stroma says that a component is missing (framework/core/Runtime.cpp and
# ObjectFactory.cpp): a SOFA class it does not provide, an unknown class, a template variant it
# lacks, or a class of a plugin that this build left out.
SOFA_CLASS = re.compile(r"^'([^']+)' is a SOFA component that Stroma does not provide")
UNKNOWN_CLASS = re.compile(r"^unknown component '([^']+)'")
NO_TEMPLATE = re.compile(r"^component '([^']+)' has no template '([^']*)'")
PLUGIN_LEFT_OUT = re.compile(
    r"^component '([^']+)' is in plugin ([^,\s]+), which (?:this build left out|failed to load)")
STEPS_PER_S = re.compile(r"\(([0-9.eE+-]+|inf|nan) steps/s\)")
RAN = re.compile(r"^Ran (\d+) steps of ")


def missing_component(message):
    """The component that a log message says Stroma lacks ("Class" or "Class<template>"), or
    None when the message says something else."""
    text = message.get("text", "")
    for pattern in (SOFA_CLASS, UNKNOWN_CLASS):
        m = pattern.match(text)
        if m:
            return m.group(1)
    m = NO_TEMPLATE.match(text)
    if m and message.get("field") == "template":
        return "%s<%s>" % (m.group(1), m.group(2))
    m = PLUGIN_LEFT_OUT.match(text)
    if m:
        return "%s (plugin %s left out)" % (m.group(1), m.group(2))
    return None


# A message as Stroma prints it (formatForConsole, framework/core/Message.cpp):
# "FILE:LINE: LEVEL: PATH (Class), field 'name': text", each part but LEVEL and text optional.
# (The messages are read from the console, not from --log-json: a run with --log-json crashes
# when its scene logs while it is destroyed, after the JSON file is closed.)
CONSOLE = re.compile(r"^(?:(.*?): )?(error|warning|info): (.*)$")
COMPONENT = re.compile(r"^(.*?) \(([^()]*)\)(?:, |: )(.*)$")
FIELD = re.compile(r"^field '([^']*)': (.*)$")


def parse_message(line):
    """The level, component, class, field and text of a message line, or None."""
    m = CONSOLE.match(line)
    if not m:
        return None
    message = {"level": m.group(2), "component": "", "class": "", "field": "", "text": m.group(3)}
    c = COMPONENT.match(message["text"])
    if c and (c.group(1).startswith("/") or c.group(1) == "?"):
        message["component"], message["class"], message["text"] = c.groups()
    f = FIELD.match(message["text"])
    if f:
        message["field"], message["text"] = f.groups()
    return message


def signal_name(number):
    try:
        return signal.Signals(number).name
    except ValueError:
        return "signal %d" % number


def shorten(text, folders):
    """Machine-independent text: the scene and clone folders written as relative paths."""
    for folder, name in folders:
        text = text.replace(folder + os.sep, name).replace(folder, name.rstrip("/") or ".")
    return " ".join(text.split())


def run_scene(args, scene):
    """Runs one scene; returns its row (a dict)."""
    rel = os.path.relpath(scene, args.scenes)
    work = tempfile.mkdtemp(prefix="stroma-corpus-")
    command = [args.stroma, "run", "-n", str(args.steps), "--threads", str(args.threads)]
    for folder in args.data_path:
        command += ["--data-path", folder]
    command.append(scene)
    start = time.monotonic()
    process = subprocess.Popen(command, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               stdin=subprocess.DEVNULL, start_new_session=True, text=True,
                               errors="replace")
    timed_out = False
    try:
        out, err = process.communicate(timeout=args.timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, err = process.communicate()
    seconds = time.monotonic() - start
    shutil.rmtree(work, ignore_errors=True)
    messages = [m for m in map(parse_message, err.splitlines()) if m]

    rc = process.returncode
    steps_per_s = ""
    ran = None
    for line in out.splitlines():
        m = RAN.match(line)
        if m:
            ran = int(m.group(1))
        m = STEPS_PER_S.search(line)
        if m and not steps_per_s:
            steps_per_s = m.group(1)
    if timed_out:
        outcome = "timeout"
    elif rc < 0 or rc not in (0, 1, 2):
        outcome = "crash"
    elif rc == 0 and ran == args.steps:
        outcome = "runs"
    else:
        outcome = "error"

    sofa = os.path.dirname(args.scenes)
    folders = [(sofa, os.path.relpath(sofa, CLONE) + "/"), (CLONE, "")]
    errors = [m for m in messages if m.get("level") == "error"]
    missing = []
    for m in errors:
        c = missing_component(m)
        if c and c not in missing:
            missing.append(c)
    first_error = ""
    if errors:
        m = errors[0]
        where = m.get("component") or ""
        if m.get("class"):
            where += " (%s)" % m["class"]
        if m.get("field"):
            where += ", field '%s'" % m["field"]
        first_error = (where + ": " if where else "") + m.get("text", "")
    err_lines = [l for l in err.splitlines() if l.strip()]
    if outcome == "timeout":
        first_error = "killed after %g s%s" % (args.timeout, ("; " + first_error) if first_error else "")
    elif outcome == "crash":
        why = signal_name(-rc) if rc < 0 else "exit code %d" % rc
        last = err_lines[-1] if err_lines else ""
        first_error = why + (": " + last if last else "")
    elif outcome == "error" and not first_error:
        told = [l for l in err_lines if l.startswith("stroma:")] or err_lines
        first_error = told[0] if told else "exit code %d without a message" % rc
    return {
        "scene": rel,
        "outcome": outcome,
        "exit_code": "" if timed_out else (rc if rc >= 0 else "signal %d" % -rc),
        "steps_per_s": steps_per_s,
        "warnings": sum(1 for m in messages if m.get("level") == "warning"),
        "errors": len(errors),
        "missing": missing,
        "first_error": shorten(first_error, folders),
        "seconds": seconds,
    }


def git(*args):
    try:
        return subprocess.run(["git", "-C", CLONE] + list(args), capture_output=True, text=True,
                              check=True).stdout.rstrip()
    except (OSError, subprocess.CalledProcessError):
        return ""


def machine():
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return "%s, %d cores, %s %s" % (cpu, os.cpu_count() or 0, platform.system(), platform.release())


def md(text):
    """Text for a Markdown table cell."""
    return str(text).replace("|", "\\|").replace("<", "&lt;").replace(">", "&gt;")


def code(text):
    """A code span for a Markdown table cell (entities are not decoded in code spans)."""
    return "`%s`" % str(text).replace("|", "\\|")


def rate(steps_per_s):
    """Steps per second, to 0.1 below 100, else to 1."""
    try:
        value = float(steps_per_s)
    except ValueError:
        return steps_per_s
    return "%.1f" % value if value < 100 else "%.0f" % value


def write_tsv(path, rows):
    with open(path, "w", encoding="utf-8") as f:
        f.write("scene\toutcome\texit_code\tsteps_per_s\twarnings\tfirst_missing\tmissing\tfirst_error\n")
        for r in rows:
            f.write("\t".join(str(x).replace("\t", " ") for x in (
                r["scene"], r["outcome"], r["exit_code"], r["steps_per_s"], r["warnings"],
                r["missing"][0] if r["missing"] else "", ";".join(r["missing"]),
                r["first_error"])) + "\n")


def write_doc(path, rows, args, header):
    total = len(rows)
    by_outcome = collections.Counter(r["outcome"] for r in rows)
    first = collections.Counter(r["missing"][0] for r in rows if r["missing"])
    needed = collections.Counter(c for r in rows for c in r["missing"])
    running = by_outcome["runs"]
    lines = []
    w = lines.append
    w("# SOFA's example scenes in Stroma")
    w("")
    w("Generated by `scripts/sofa-corpus.py`: do not edit by hand, rerun it. The same table, one")
    w("line a scene: [sofa-compatibility.tsv](%s)." % os.path.basename(args.tsv))
    w("")
    for key, value in header:
        w("- %s: %s" % (key, value))
    w("")
    w("Each scene ran with `stroma run -n %d --threads %d` and SOFA's data path, in a folder of its"
      % (args.steps, args.threads))
    w("own, killed after %g s. Outcomes: **runs** (exit code 0: %d steps without an error), "
      % (args.timeout, args.steps))
    w("**error** (exit code 1: a step failed or the state diverged; 2: the scene did not load),")
    w("**crash** (another exit code, or a signal) and **timeout** (still running at the limit).")
    w("")
    w("## Summary")
    w("")
    w("**%d of %d scenes run %d steps.**" % (running, total, args.steps))
    w("")
    w("| outcome | scenes |")
    w("|---|---:|")
    for outcome in ("runs", "error", "crash", "timeout"):
        w("| %s | %d |" % (outcome, by_outcome[outcome]))
    errors_by_code = collections.Counter(r["exit_code"] for r in rows if r["outcome"] == "error")
    w("")
    w("Errors: %s. %d scenes fail on a component Stroma lacks (at least); %d fail on something"
      % (", ".join("%d with exit code %s" % (n, c) for c, n in sorted(errors_by_code.items(), key=str)),
         sum(1 for r in rows if r["missing"]),
         sum(1 for r in rows if r["outcome"] != "runs" and not r["missing"])))
    w("else (listed below).")
    w("")
    w("### Missing components")
    w("")
    w("%d components (a class, or a template of a class: `Class<template>`) that SOFA's scenes use"
      % len(needed))
    w("and Stroma lacks, ranked by the scenes they block: *first blocker* counts the scenes whose")
    w("first missing component it is (providing it is the first step to running them), *needed by*")
    w("counts the scenes that use it at all.")
    w("")
    w("| rank | component | first blocker | needed by |")
    w("|---:|---|---:|---:|")
    ranked = sorted(needed, key=lambda c: (-first[c], -needed[c], c))
    for i, c in enumerate(ranked, 1):
        w("| %d | %s | %d | %d |" % (i, code(c), first[c], needed[c]))
    w("")
    w("By the scenes that need them at all:")
    w("")
    w(", ".join("%s (%d)" % (code(c), n)
                for c, n in sorted(needed.items(), key=lambda cn: (-cn[1], cn[0]))))
    w("")
    bugs = [r for r in rows if r["outcome"] in ("crash", "timeout")]
    if bugs:
        w("### Crashes and timeouts (bugs)")
        w("")
        w("| scene | outcome | exit code | message |")
        w("|---|---|---|---|")
        for r in bugs:
            w("| %s | %s | %s | %s |" % (md(r["scene"]), r["outcome"], r["exit_code"],
                                          md(r["first_error"])))
        w("")

    def table(group):
        w("| scene | outcome | exit code | steps/s | warnings | first error |")
        w("|---|---|---:|---:|---:|---|")
        for r in group:
            message = r["first_error"]
            if len(message) > args.max_message:
                message = message[:args.max_message - 3] + "..."
            w("| %s | %s | %s | %s | %d | %s |" % (md(r["scene"]), r["outcome"], r["exit_code"],
                                                    rate(r["steps_per_s"]), r["warnings"], md(message)))
        w("")

    w("## Scenes that run")
    w("")
    table([r for r in rows if r["outcome"] == "runs"])
    w("## Scenes that fail without a missing component")
    w("")
    w("They load every component they name, and fail on something else: the first error says what.")
    w("")
    table([r for r in rows if r["outcome"] != "runs" and not r["missing"]])
    w("## Scenes by the first component they lack")
    w("")
    for c in sorted(first, key=lambda c: (-first[c], c)):
        w("### %s (%d)" % (code(c), first[c]))
        w("")
        table([r for r in rows if r["missing"] and r["missing"][0] == c])
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines).rstrip() + "\n")


def write_list(path, rows, args):
    prefix = os.path.basename(os.path.normpath(args.scenes))
    with open(path, "w", encoding="utf-8") as f:
        f.write("# SOFA example scenes (../shared/sofa) that run %d steps with `stroma run` (exit code 0):\n"
                % args.steps)
        f.write("# SofaRunningScenes_test runs each for a few steps, so that none silently stops\n")
        f.write("# running. Generated: scripts/sofa-corpus.py --write-list %s\n"
                % os.path.relpath(os.path.abspath(path), CLONE))
        for r in rows:
            if r["outcome"] == "runs":
                f.write("%s/%s\n" % (prefix, r["scene"]))


def main():
    default_scenes = os.path.normpath(os.path.join(CLONE, "..", "shared", "sofa", "examples"))
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scenes", default=default_scenes,
                   help="folder searched for .scn files (default: ../shared/sofa/examples)")
    p.add_argument("--stroma", default=os.path.join(CLONE, "build", "bin", "stroma"),
                   help="the stroma program (default: build/bin/stroma)")
    p.add_argument("--data-path", action="append",
                   help="data folder (repeatable; default: <scenes>/../share and <scenes>)")
    p.add_argument("-n", "--steps", type=int, default=100, help="steps a scene runs (default 100)")
    p.add_argument("--timeout", type=float, default=60, help="seconds before a scene is killed (60)")
    p.add_argument("-j", "--jobs", type=int, default=1, help="scenes run at once (default 1)")
    p.add_argument("--threads", type=int, default=1, help="threads of each run (default 1)")
    p.add_argument("--doc", default=os.path.join(CLONE, "docs", "sofa-compatibility.md"),
                   help="the Markdown report (default docs/sofa-compatibility.md; '' for none)")
    p.add_argument("--tsv", default=os.path.join(CLONE, "docs", "sofa-compatibility.tsv"),
                   help="the table, tab-separated (default docs/sofa-compatibility.tsv; '' for none)")
    p.add_argument("--write-list", metavar="FILE",
                   help="also write the scenes that run (tests/scenes/sofa-running-scenes.txt)")
    p.add_argument("--built-from", metavar="COMMIT",
                   help="the commit the stroma program was built from, for the report's header "
                        "(default: the clone's HEAD)")
    p.add_argument("--max-message", type=int, default=200,
                   help="characters of the first error in the Markdown table (200)")
    p.add_argument("scene_filter", nargs="*", help="run only scenes whose path contains one of these")
    args = p.parse_args()
    args.scenes = os.path.abspath(args.scenes)
    args.stroma = os.path.abspath(args.stroma)
    if not args.data_path:
        args.data_path = [os.path.join(os.path.dirname(args.scenes), "share"), args.scenes]
    if not os.path.isdir(args.scenes):
        sys.exit("sofa-corpus: no folder %s (SOFA's scenes live beside the clone: ../shared)" % args.scenes)
    if not os.access(args.stroma, os.X_OK):
        sys.exit("sofa-corpus: no program %s (build it: scripts/build.sh, or give --stroma)" % args.stroma)

    scenes = []
    for folder, _, files in os.walk(args.scenes):
        scenes += [os.path.join(folder, f) for f in files if f.endswith(".scn")]
    scenes.sort()
    if args.scene_filter:
        scenes = [s for s in scenes if any(f in s for f in args.scene_filter)]
    started = datetime.datetime.now(datetime.timezone.utc)
    rows = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(run_scene, args, s): s for s in scenes}
        for i, future in enumerate(concurrent.futures.as_completed(futures), 1):
            r = future.result()
            rows.append(r)
            print("[%3d/%d] %-7s %5.1f s  %s%s" % (
                i, len(scenes), r["outcome"], r["seconds"], r["scene"],
                "" if r["outcome"] == "runs" else "  -- " + r["first_error"][:120]), flush=True)
    rows.sort(key=lambda r: r["scene"])
    elapsed = (datetime.datetime.now(datetime.timezone.utc) - started).total_seconds()

    commit = args.built_from
    if not commit:
        commit = git("rev-parse", "--short=12", "HEAD") or "unknown"
        changed = sorted({"/".join(line[3:].split(" -> ")[-1].split("/")[:2])
                          for line in git("status", "--porcelain").splitlines()
                          if line[3:].startswith(("framework/", "plugins/", "applications/"))})
        if changed:
            commit += " with uncommitted changes in %s" % ", ".join(changed)
    command = " ".join(["scripts/sofa-corpus.py"] + [shlex.quote(
        a if not a.startswith(CLONE + os.sep) else os.path.relpath(a, CLONE)) for a in sys.argv[1:]])
    header = [
        ("Command", "`%s` (%d jobs, %.0f s in all)" % (command, args.jobs, elapsed)),
        ("Date", started.strftime("%Y-%m-%d %H:%M UTC")),
        ("Commit", commit + (" (the build of `--stroma`)" if args.built_from else " (the clone's)")),
        ("Stroma", "`%s`" % (os.path.relpath(args.stroma, CLONE)
                             if args.stroma.startswith(CLONE + os.sep) else args.stroma)),
        ("Machine", machine()),
        ("Scenes", "%d `.scn` files under %s" % (len(rows), os.path.relpath(args.scenes, CLONE))),
    ]
    if args.doc:
        write_doc(args.doc, rows, args, header)
    if args.tsv:
        write_tsv(args.tsv, rows)
    if args.write_list:
        write_list(args.write_list, rows, args)
    counts = collections.Counter(r["outcome"] for r in rows)
    print("%d of %d scenes run %d steps; %s" % (counts["runs"], len(rows), args.steps, ", ".join(
        "%s %d" % (o, counts[o]) for o in ("error", "crash", "timeout"))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
