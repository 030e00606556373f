#!/usr/bin/env python3
"""Charts for Silva's benchmark and profiling results (python3-matplotlib + numpy).

    python3 scripts/bench_charts.py bench/results/<date>-<cpu>-bench.json    # `silva bench` results
    python3 scripts/bench_charts.py profile-placement/placement.json   # `silva profile placement`

PNGs are written next to the JSON: for bench results <stem>-<chart>.png (generation-density,
generation-elevation, capture-density, capture-resolution, capture-count, threads: thesis vs Silva
on a log axis, thread-scaling curves); for a placement profile profile-<chart>.png (per-ha,
cover, cost, spacing vs density).
"""
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def figures(doc, table):
    return [f for f in doc["figures"] if f["table"] == table]


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"wrote {path}", file=sys.stderr)


def thesis_vs_silva(doc, table, xlabel, path, numeric_x):
    """Silva and thesis seconds against x, log y axis."""
    fs = figures(doc, table)
    if not fs:
        return
    labels = [f["x"] for f in fs]
    xs = np.array([float(x) for x in labels]) if numeric_x else np.arange(len(labels))
    silva = np.array([f["silva_s"] for f in fs])
    thesis = np.array([f["thesis_s"] if f["thesis_s"] is not None else np.nan for f in fs])
    extrapolated = np.array([f["extrapolated"] for f in fs])
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.plot(xs, thesis, "s--", color="tab:gray", label="thesis (i9-13980HX + RTX 4060, UE5)")
    ax.plot(xs, silva, "o-", color="tab:green", label=f"Silva ({doc['machine']['cpu']}, {doc['machine']['cores']} cores)")
    if extrapolated.any():
        ax.plot(xs[extrapolated], silva[extrapolated], "o", mfc="white", color="tab:green", label="Silva, extrapolated")
    ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("seconds (log)")
    if not numeric_x:
        ax.set_xticks(xs, labels)
    elif table == "5.7":
        ax.set_xscale("log")
    ax.set_title(f"Table {table}: {doc['tables'].get(table, '')}")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, path)


def scaling(doc, path):
    """Speed-up against one thread for generation and capture, with the ideal line."""
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    top = 1
    for table, label in (("threads-generation", "generation (default world)"), ("threads-capture", "capture (autopilot subset)")):
        fs = figures(doc, table)
        if not fs:
            continue
        t = np.array([int(f["x"]) for f in fs])
        s = np.array([f["silva_s"] for f in fs])
        ax.plot(t, s[0] / s, "o-", label=label)
        top = max(top, t.max())
    ax.plot([1, top], [1, top], ":", color="tab:gray", label="ideal")
    ax.set_xlabel("threads (tbb::task_arena)")
    ax.set_ylabel("speed-up vs 1 thread")
    ax.set_title(f"Thread scaling on {doc['machine']['cpu']}")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, path)


def bench_charts(doc, path):
    stem = path.with_suffix("")
    thesis_vs_silva(doc, "5.1", "vegetation density (%)", f"{stem}-generation-density.png", True)
    thesis_vs_silva(doc, "5.2", "max terrain height (cm)", f"{stem}-generation-elevation.png", True)
    thesis_vs_silva(doc, "5.5", "vegetation density (%)", f"{stem}-capture-density.png", True)
    thesis_vs_silva(doc, "5.6", "resolution", f"{stem}-capture-resolution.png", False)
    thesis_vs_silva(doc, "5.7", "number of captures", f"{stem}-capture-count.png", True)
    scaling(doc, f"{stem}-threads.png")


def profile_charts(doc, path):
    out = path.parent
    means = doc["means"]
    groups = {}
    for m in means:
        groups.setdefault((m["max_elevation"], m["trail"]), []).append(m)
    classes = sorted({c for m in means for c in m["classes"]})

    def per_class(key, ylabel, name, log=False):
        fig, ax = plt.subplots(figsize=(6.4, 4.0))
        for (elev, trail), ms in groups.items():
            d = [m["density"] for m in ms]
            for c in classes:
                ys = [m["classes"].get(c, {}).get(key) for m in ms]
                ys = [y if y is not None else np.nan for y in ys]
                suffix = f" (elev {elev:g} m, trail {'on' if trail else 'off'})" if len(groups) > 1 else ""
                ax.plot(d, ys, "o-", label=c + suffix)
        ax.set_xlabel("vegetation.density (%)")
        ax.set_ylabel(ylabel)
        if log:
            ax.set_yscale("log")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
        save(fig, out / f"profile-{name}.png")

    per_class("per_ha", "objects per hectare (log)", "per-ha", log=True)
    per_class("cover_pct", "ground covered seen from above (%)", "cover")

    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for c in classes:
        for (elev, trail), ms in groups.items():
            d = [m["density"] for m in ms]
            nn = [m["classes"].get(c, {}).get("nearest_m") or {} for m in ms]
            med = [n.get("median", np.nan) for n in nn]
            lo = [n.get("p10", np.nan) for n in nn]
            hi = [n.get("p90", np.nan) for n in nn]
            line, = ax.plot(d, med, "o-", label=c)
            ax.fill_between(d, lo, hi, alpha=0.15, color=line.get_color())
    ax.set_xlabel("vegetation.density (%)")
    ax.set_ylabel("nearest same-class neighbour (m): median, p10-p90 band")
    ax.set_yscale("log")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, out / "profile-spacing.png")

    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for (elev, trail), ms in groups.items():
        d = np.array([m["density"] for m in ms])
        bottom = np.zeros(len(ms))
        for phase in ("generate", "place", "resolve"):
            v = np.array([m["world"][f"{phase}_ms_per_chunk"] for m in ms])
            ax.bar(d, v, bottom=bottom, width=1.5, label=f"{phase}")
            bottom += v
        break  # the first (elevation, trail) setting
    ax.set_xlabel("vegetation.density (%)")
    ax.set_ylabel("ms per chunk (one thread's time)")
    ax.set_title("cost per chunk per phase")
    ax.grid(True, axis="y", alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, out / "profile-cost.png")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    path = pathlib.Path(sys.argv[1])
    doc = json.loads(path.read_text())
    harness = doc.get("harness")
    if harness == "silva-bench":
        bench_charts(doc, path)
    elif harness == "silva-profile-placement":
        profile_charts(doc, path)
    else:
        sys.exit(f"{path}: not a silva bench or profile placement results file")


if __name__ == "__main__":
    main()
