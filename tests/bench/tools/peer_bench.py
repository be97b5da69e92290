#!/usr/bin/env python3
"""pvscope against the tool its users would otherwise run, map by map, in one run.

Doom: `pvscope bake WAD --map MAP -o OUT.gwa` against glVIS 1.6 (`glvis -s -noreject -mMAP WAD`) on
the GL nodes glbsp makes, every map of Freedoom's two IWADs. Quake and Quake 2: `pvscope vis` against
ericw-tools `vis -nostate` on the same .bsp and .prt (maps without a .prt get the one pvscope builds
from their tree, written once with `bake --write-prt`), with and without the fast mode (`--fast` /
`-fast`). Each repetition runs both tools on fresh copies of the same inputs, back to back, the
order alternating, so a slow moment of a shared host falls on both; the ratio of the medians is the
figure. A peer that takes longer than --peer-timeout is stopped there once and not repeated.

Rows: after the timed runs pvscope runs once more, untimed, on the peer's output file, so its JSON
report compares pvscope's rows with the peer's (`file_pvs`: bits only pvscope's, bits only the
peer's). With --reference, `pvscope compare
--methods file` (the converged sampled reference, minutes on big maps) gives the missing and excess
bits of both outputs.

Writes DIR/runs.csv (one row per run), DIR/summary.csv (one row per map and mode) and DIR/ratios.png
(the wall-time ratio per map, sorted, drawn by plot_peer_ratios), and prints a markdown table.

Usage: tests/bench/tools/peer_bench.py BUILD_DIR [--corpus doom,quake] [--reps 3] [--threads 2]
       [--out DIR] [--maps REGEX] [--peer-timeout 1200] [--modes full,fast] [--reference]
"""
import argparse
import csv
import json
import os
import re
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
SHARED = Path(os.environ.get("PVSCOPE_SHARED_DATA_DIR", ROOT.parent / "shared" / "data"))
TOOLS = Path(os.environ.get("PVSCOPE_PEER_TOOLS_DIR", ROOT.parent / "shared" / "tools"))
ERICW_VIS = TOOLS / "ericw-tools" / "vis"
GLVIS = TOOLS / "glvis" / "glvis"
FREEDOOM = Path(os.environ.get("PVSCOPE_FREEDOOM_DIR", "/usr/share/games/doom"))

QUAKE_MAPS = [
    "quake/e1m1.bsp", "quake/e1m2.bsp", "quake/e2m1.bsp", "quake/start.bsp", "quake/end.bsp", "quake/dm2.bsp",
    "visdemo/example.bsp",
    "modern-quake/q1/lqdm2.bsp", "modern-quake/q1/lqdm2-bsp2.bsp", "modern-quake/q1/lqdm2-2psb.bsp",
    "modern-quake/q1/lqdm5.bsp", "modern-quake/q1/lq_e1m1.bsp", "modern-quake/q1/lq_e2m2.bsp",
    "modern-quake/q2/q2_liquids.bsp", "modern-quake/q2/q2_areaportals.bsp", "modern-quake/q2/q2_tjunc_matrix.bsp",
    "modern-quake/q2/lqdm2-q2.bsp", "modern-quake/q2/lqdm5-q2.bsp",
]


def timed(cmd, cwd, timeout=None):
    """Runs cmd under /usr/bin/time: (wall s, CPU s, peak RSS KiB, status)."""
    timing = Path(cwd) / ".time"
    start = time.monotonic()
    # A session of its own, so a timeout stops the tool, not only /usr/bin/time above it.
    proc = subprocess.Popen(["/usr/bin/time", "-f", "%e %U %S %M", "-o", str(timing)] + [str(c) for c in cmd],
                            cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, start_new_session=True)
    try:
        _, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return time.monotonic() - start, None, None, "timeout"
    wall = time.monotonic() - start  # /usr/bin/time's %e counts in 10 ms steps
    fields = timing.read_text().split()[-4:]
    user, system, rss = float(fields[1]), float(fields[2]), int(fields[3])
    status = "ok" if proc.returncode == 0 else "exit %d: %s" % (proc.returncode, err.decode()[-200:].strip())
    return wall, user + system, rss, status


def fresh(sources, folder):
    """Copies every source file into folder (writable), replacing what was there."""
    folder.mkdir(parents=True, exist_ok=True)
    for src, name in sources:
        dst = folder / name
        if dst.exists():
            dst.unlink()
        shutil.copyfile(src, dst)
        dst.chmod(0o644)
    return folder


class Case:
    """One map in one mode: how to prepare inputs and run each tool."""

    def __init__(self, corpus, name, mode):
        self.corpus, self.name, self.mode = corpus, name, mode


def quake_cases(args, work):
    cases = []
    for rel in QUAKE_MAPS:
        path = SHARED / rel
        if not path.exists():
            print("skipped (not found): %s" % path, file=sys.stderr)
            continue
        stem = path.stem
        prt = path.with_suffix(".prt")
        prepared = work / "inputs" / stem
        prepared.mkdir(parents=True, exist_ok=True)
        if not prt.exists():  # an id level: the portals pvscope builds from its tree, once
            made = prepared / (stem + ".prt")
            if not made.exists():
                subprocess.run([args.pvscope, "bake", path, "--method", "portal-fast", "--write-prt", made,
                                "-o", prepared / "unused.bsp"], check=True, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
            prt = made
        for mode in args.modes:
            c = Case("quake2" if "/q2/" in rel else "quake", stem, mode)
            c.inputs = [(path, stem + ".bsp"), (prt, stem + ".prt")]
            c.output = stem + ".bsp"
            fast_peer = ["-fast"] if mode == "fast" else []
            fast_ours = ["--fast"] if mode == "fast" else []
            c.peer = lambda d, c=c, f=fast_peer: [ERICW_VIS, "-threads", args.threads, "-nostate"] + f + [c.output]
            c.ours = lambda d, c=c, f=fast_ours: [args.pvscope, "vis", "-threads", args.threads, "--report",
                                                  "report.json"] + f + [c.output]
            cases.append(c)
    return cases


def doom_cases(args, work):
    cases = []
    for wad in ("freedoom1", "freedoom2"):
        src = FREEDOOM / (wad + ".wad")
        if not src.exists():
            print("skipped (not found): %s" % src, file=sys.stderr)
            continue
        prepared = work / "inputs" / wad
        prepared.mkdir(parents=True, exist_ok=True)
        gwa = prepared / (wad + ".gwa")
        if not gwa.exists():
            subprocess.run(["glbsp", "-q", src, "-o", gwa], check=True, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
        info = subprocess.run([args.pvscope, "info", src, "--gwa", gwa], capture_output=True, text=True).stdout
        maps = re.search(r"maps in the WAD \(--map NAME\): (.*)", info).group(1).split()
        for m in maps:
            for mode in args.modes:
                c = Case("doom", wad + ":" + m, mode)
                c.inputs = [(src, wad + ".wad"), (gwa, wad + ".gwa")]
                c.output = wad + ".gwa"
                peer_fast = ["-f"] if mode == "fast" else []
                ours_fast = ["--method", "portal-fast"] if mode == "fast" else []
                c.peer = lambda d, w=wad, m=m, f=peer_fast: [GLVIS, "-s", "-noreject"] + f + ["-m" + m, w + ".wad"]
                c.ours = lambda d, w=wad, m=m, f=ours_fast: [args.pvscope, "bake", w + ".wad", "--gwa", w + ".gwa",
                                                              "--map", m, "--threads", args.threads, "-o", "out.gwa",
                                                              "--report", "report.json"] + f
                cases.append(c)
    return cases


def run_case(c, args, work, runs):
    """Interleaved repetitions of both tools on fresh copies; returns the summary row."""
    folder = work / "run"
    peer_out = None
    peer_timed_out = False
    for rep in range(args.reps):
        order = ("peer", "ours") if rep % 2 == 0 else ("ours", "peer")
        for tool in order:
            if tool == "peer" and peer_timed_out:
                continue
            d = fresh(c.inputs, folder / tool)
            cmd = c.peer(d) if tool == "peer" else c.ours(d)
            wall, cpu, rss, status = timed(cmd, d, args.peer_timeout if tool == "peer" else None)
            runs.append({"corpus": c.corpus, "map": c.name, "mode": c.mode, "tool": tool, "rep": rep,
                         "wall_s": "%.4f" % wall, "cpu_s": "" if cpu is None else "%.4f" % cpu,
                         "peak_rss_kb": "" if rss is None else rss, "status": status})
            if tool == "peer":
                if status == "timeout":
                    peer_timed_out = True
                elif status == "ok" and peer_out is None:
                    peer_out = work / "peer-output"
                    shutil.copyfile(d / c.output, peer_out)
    # Untimed: pvscope once more, on the peer's output, so its report compares the two PVSs.
    d = fresh(c.inputs, folder / "rows")
    if peer_out is not None:
        shutil.copyfile(peer_out, d / c.output)
    subprocess.run([str(x) for x in c.ours(d)], cwd=d, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    c.report = json.loads((d / "report.json").read_text()) if (d / "report.json").exists() else {}
    mine = [r for r in runs if r["map"] == c.name and r["mode"] == c.mode and r["corpus"] == c.corpus]
    return summarise(c, mine, peer_timed_out, args)


def median(rows, field):
    values = [float(r[field]) for r in rows if r[field] != "" and r["status"] == "ok"]
    return statistics.median(values) if values else None


def summarise(c, rows, peer_timed_out, args):
    ours = [r for r in rows if r["tool"] == "ours"]
    peer = [r for r in rows if r["tool"] == "peer"]
    row = {"corpus": c.corpus, "map": c.name, "mode": c.mode}
    for name, part in (("pvscope", ours), ("peer", peer)):
        row[name + "_wall_s"] = median(part, "wall_s")
        row[name + "_cpu_s"] = median(part, "cpu_s")
        rss = [int(r["peak_rss_kb"]) for r in part if r["peak_rss_kb"] != ""]
        row[name + "_peak_rss_kb"] = max(rss) if rss else None
    row["peer_status"] = "timeout after %d s" % args.peer_timeout if peer_timed_out else peer[0]["status"] if peer else ""
    if peer_timed_out:
        row["peer_wall_s"] = None
    pw, ow = row["peer_wall_s"], row["pvscope_wall_s"]
    row["wall_ratio"] = ow / pw if pw and ow else None
    row["cpu_ratio"] = row["pvscope_cpu_s"] / row["peer_cpu_s"] if row["peer_cpu_s"] and row["pvscope_cpu_s"] else None
    rep = getattr(c, "report", {})
    row["regions"] = rep.get("regions")
    fp = rep.get("file_pvs") or {}
    row["pvscope_mean_visible"] = fp.get("mean_visible_baked", rep.get("mean_visible"))
    row["peer_mean_visible"] = fp.get("mean_visible_file")
    row["bits_only_pvscope"] = fp.get("bits_only_baked")
    row["bits_only_peer"] = fp.get("bits_only_file")
    for phase in ("load_seconds", "portalize_seconds", "base_seconds", "passage_seconds", "time_seconds",
                  "write_seconds"):
        row["pvscope_" + phase] = rep.get(phase)
    return row


def reference_bits(args, c, folder):
    """Missing and excess bits of the file in folder against the converged reference."""
    out = folder / "compare.json"
    cmd = [args.pvscope, "compare", folder / c.output, "--methods", "file", "--cameras", "0", "--threads",
           args.threads, "--json", out]
    if c.corpus == "doom":
        wad, m = c.name.split(":")
        cmd = [args.pvscope, "compare", folder / (wad + ".wad"), "--gwa", folder / c.output, "--map", m, "--methods",
               "file", "--cameras", "0", "--threads", args.threads, "--json", out]
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if not out.exists():
        return None, None
    row = next(m for m in json.loads(out.read_text())["methods"] if m["method"] == "file")
    return row["missing_bits"], row["excess_bits"]


def fmt(v, digits=2):
    if v is None:
        return "—"
    if isinstance(v, float):
        return "%.*f" % (digits, v)
    return str(v)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("build")
    p.add_argument("--corpus", default="doom,quake")
    p.add_argument("--reps", type=int, default=3)
    p.add_argument("--threads", default="2")
    p.add_argument("--out", default="peer-bench")
    p.add_argument("--maps", default=".*", help="regular expression on the map's name")
    p.add_argument("--peer-timeout", type=int, default=1200)
    p.add_argument("--modes", default="full,fast")
    p.add_argument("--reference", action="store_true")
    args = p.parse_args()
    args.pvscope = Path(args.build).resolve() / "app" / "pvscope"
    args.modes = args.modes.split(",")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix="pvscope-peer-bench-"))
    runs, summary = [], []
    try:
        cases = []
        corpora = args.corpus.split(",")
        if "quake" in corpora:
            cases += quake_cases(args, work)
        if "doom" in corpora:
            cases += doom_cases(args, work)
        cases = [c for c in cases if re.search(args.maps, c.name)]
        for i, c in enumerate(cases):
            print("[%d/%d] %s %s %s" % (i + 1, len(cases), c.corpus, c.name, c.mode), file=sys.stderr, flush=True)
            row = run_case(c, args, work, runs)
            if args.reference:
                row["pvscope_missing"], row["pvscope_excess"] = reference_bits(args, c, work / "run" / "ours")
                row["peer_missing"], row["peer_excess"] = reference_bits(args, c, work / "run" / "peer")
            summary.append(row)
            write_csv(out / "runs.csv", runs)
            write_csv(out / "summary.csv", summary)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    plot = Path(args.build).resolve() / "tests" / "bench" / "plot_peer_ratios"
    if plot.exists() and summary:
        subprocess.run([plot, out / "summary.csv", out / "ratios.png"], check=False)
    print_table(summary)


def write_csv(path, rows):
    if not rows:
        return
    fields = []
    for r in rows:
        fields += [k for k in r if k not in fields]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)


def print_table(summary):
    print("| corpus | map | mode | pvscope wall s | peer wall s | ratio | CPU ratio | peak RSS MB (pvscope / peer) | "
          "mean visible (pvscope / peer) | bits only pvscope / only peer |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for r in summary:
        rss = "%s / %s" % (fmt(r["pvscope_peak_rss_kb"] and r["pvscope_peak_rss_kb"] / 1024, 1),
                           fmt(r["peer_peak_rss_kb"] and r["peer_peak_rss_kb"] / 1024, 1))
        mean = "%s / %s" % (fmt(r["pvscope_mean_visible"], 1), fmt(r["peer_mean_visible"], 1))
        bits = "%s / %s" % (fmt(r["bits_only_pvscope"]), fmt(r["bits_only_peer"]))
        peer = fmt(r["peer_wall_s"], 3) if r["peer_wall_s"] is not None else r["peer_status"]
        print("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["corpus"], r["map"], r["mode"], fmt(r["pvscope_wall_s"], 3), peer, fmt(r["wall_ratio"], 3),
            fmt(r["cpu_ratio"], 3), rss, mean, bits))


if __name__ == "__main__":
    main()
