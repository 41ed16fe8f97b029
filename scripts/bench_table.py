#!/usr/bin/env python3
"""Merge the benchmark of one or more builds into one table.

Usage: python3 scripts/bench_table.py OUTDIR DIR [DIR ...]

Each DIR holds the bench.tsv written by one build of bench/bench.c (make
bench: build/bench-out/O2 from build/bench, build/bench-out/native from
build/bench-native).  Writes OUTDIR/bench.md (printed too): the machine,
compiler, flags and date, then the main table (every row against its
round-to-nearest Arvo baseline, one column group per build) and the
throughput table (against memcpy of the same bytes); and OUTDIR/bench.dat,
the plotted rows for scripts/bench.gp (time of the first build and of the
second, max excess).  The exact columns (excess, ulps) come from the first
build; every build checked its own outputs and the containment column
shows each build's count when they differ.  Exit status 1 when a build
reports a failure, or when a certbox row's output (its checksum, on the
same inputs) differs between builds: the library is meant to give the same
bits whatever the optimisation, since every build keeps -ffp-contract=off
-fno-fast-math.
"""
import math
import os
import sys


def read_tsv(path):
    meta, rows, header = {}, [], None
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("#meta\t"):
                _, k, v = line.split("\t", 2)
                meta[k] = v
                continue
            if not line or line.startswith("#"):
                continue
            fields = line.split("\t")
            if header is None:
                header = fields
                continue
            rows.append(dict(zip(header, fields)))
    return meta, rows


def fnum(s):
    try:
        return float(s)
    except (TypeError, ValueError):
        return math.nan


def num(v):
    """The number format of bench/bench.c."""
    if isinstance(v, str):
        v = fnum(v)
    if math.isnan(v):
        return "-"
    if v == 0:
        return "0"
    if abs(v) >= 1e5 or abs(v) < 1e-2:
        return "%.3g" % v
    return "%.2f" % v


def pct(ratio):
    r = fnum(ratio)
    return "-" if not r > 0 else "%.0f%%" % (100.0 / r)


def base_cell(r):
    return "(baseline)" if r["base"] == r["id"] else r["base"]


def containment(r, builds):
    cells = []
    for label, _, rows in builds:
        x = rows.get(r["id"])
        if x is None or x["ends"] == "0":
            cells.append((label, "-"))
        else:
            cells.append((label, "%s / %s" % (x["fails"], x["ends"])))
    if len({c for _, c in cells}) == 1:
        return cells[0][1]
    return "; ".join("%s: %s" % c for c in cells)


def notes(r, builds, differs):
    parts = [r["note"]] if r["note"] else []
    if len(builds) == 1:
        if r["tnote"]:
            parts.append(r["tnote"])
    else:
        for label, _, rows in builds:
            x = rows.get(r["id"])
            if x is not None and x["tnote"]:
                parts.append("%s: %s" % (label, x["tnote"]))
    if r["id"] in differs:
        parts.append("**output differs between the builds**")
    return "; ".join(parts)


def main():
    if len(sys.argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    outdir, dirs = sys.argv[1], sys.argv[2:]
    builds = []
    for d in dirs:
        meta, rows = read_tsv(os.path.join(d, "bench.tsv"))
        builds.append((meta.get("label", d), meta, {r["id"]: r for r in rows}))
    order = read_tsv(os.path.join(dirs[0], "bench.tsv"))[1]
    m0 = builds[0][1]

    # outputs that differ between builds (rows with an output checksum)
    differs = []
    for r in order:
        ds = {rows[r["id"]]["digest"] for _, _, rows in builds if r["id"] in rows}
        ds.discard("0000000000000000")
        if len(ds) > 1:
            differs.append(r["id"])
    certbox_differs = [i for i in differs if builds[0][2][i]["pcode"] == "1"]
    failed = [(label, meta["status"]) for label, meta, _ in builds if meta.get("status") != "ok"]

    out = []
    w = out.append
    w("# certbox benchmark (bench/bench.c)\n\n")
    w("- machine: %s, %s cores (/proc/cpuinfo); %s\n" % (m0["machine"], m0["cores"], m0["caches"]))
    w("- compiler: %s (`%s`)\n" % (m0["cc_version"], m0["cc"]))
    w("- builds (bench/bench.c and the library compiled with the same flags; run one after the "
      "other, one column group each):\n")
    for label, meta, _ in builds:
        w("  - **%s**: `%s`; run %s; load average at its end: %s\n"
          % (label, meta["flags"], meta["date"], meta["loadavg"]))
    w("- certbox %s; seed %s; date %s\n" % (m0["version"], m0["seed"], m0["date"][:10]))
    w("- timing: each row is timed in a group with its baseline: a warm-up round, then %s "
      "interleaved rounds, each running the baseline once and then every row of the group once. "
      "ns/box: the median of the rounds; **vs Arvo**: the median of the per-round ratios "
      "(the row's run / the baseline's run of the same round); CPU: the same in thread CPU "
      "time. A run is %s passes over %s cases (main rows; GMP: 1 pass over %s), %s passes over "
      "%s (in-cache throughput), %s over %s (large arrays), %s over the %s scene instances "
      "(per-class rows: about %s calls)\n"
      % (m0["rounds"], m0["passes"], m0["n"], m0["ng"], m0["passes_c"], m0["nc"], m0["passes_b"],
         m0["nb"], m0["passes_s"], m0["ns"], m0["calls"]))
    w("- excess and containment: exact (GMP, MPFR for spheres) on the first %s cases (%d ends per "
      "row); units of u S + eta (binary64: u = 2^-53, eta = 2^-1074; binary32 rows: u = 2^-24, "
      "eta = 2^-149); ulps of the exact end on the ends with \\|end\\| >= S/4; from the first "
      "build (every build checks its own)\n"
      % (m0["ne"], 6 * int(m0["ne"])))
    if len(builds) > 1:
        if differs:
            w("- outputs: **differ between the builds** in rows %s\n" % ", ".join(differs))
        else:
            w("- outputs: bit-identical in every build (checksums of every checked row's output)\n")
    for label, status in failed:
        w("- **%s: %s**\n" % (label, status))
    w("\n")

    # where the rows of the fast-path issue are (those present)
    ids = {r["id"] for r in order}
    guide = [("single calls, own map per box", ["3"], "2"),
             ("single calls, one map for every box", ["3a"], "2a"),
             ("prepared single calls, own / one prepared map", ["3p", "3ap"], "2 / 2a"),
             ("batch, one map (per box)", ["3b", "3bp"], "2a"),
             ("tight mode", ["3t"], "2"),
             ("binary32: own map, one map, batch (prepared: 3fp, 3afp, 3bfp)",
              ["3f", "3af", "3bf"], "2f / 2af"),
             ("out-of-cache batch throughput, % of memcpy", ["T2b", "T2p", "T2f"], "M2b")]
    w("Rows: ")
    w("; ".join("%s: %s vs %s" % (what, ", ".join(i for i in rs if i in ids), base)
                for what, rs, base in guide if any(i in ids for i in rs)))
    w(".\n\n")

    # the main table
    head = ["#", "method", "vs"]
    for label, _, _ in builds:
        head += ["ns/box %s" % label, "**vs Arvo %s**" % label, "CPU vs Arvo %s" % label]
    head += ["max excess", "mean excess", "max ulps", "mean ulps", "containment failures",
             "proven", "notes"]
    w("| " + " | ".join(head) + " |\n")
    w("|" + "|".join(["---"] * 3 + ["---:"] * (3 * len(builds) + 5) + ["---", "---"]) + "|\n")
    for r in order:
        if r["sec"] != "main":
            continue
        cells = [r["id"], r["name"], base_cell(r)]
        for _, _, rows in builds:
            x = rows.get(r["id"], {})
            cells += [num(x.get("ns")), "**%s**" % num(x.get("rw")) if r["pcode"] == "1"
                      else num(x.get("rw")), num(x.get("rc"))]
        if r["pcode"] == "2":
            cells += ["0", "0", "0", "0", "0 (exact)"]
        else:
            cells += [num(r["ex_max"]), num(r["ex_mean"]), num(r["ulp_max"]), num(r["ulp_mean"]),
                      containment(r, builds)]
        cells += [r["proven"], notes(r, builds, differs)]
        w("| " + " | ".join(cells) + " |\n")

    # the throughput table
    tp = [r for r in order if r["sec"] == "tp"]
    if tp:
        w("\nThroughput: against memcpy of the same bytes (in + out), timed in the same rounds; "
          "**% of memcpy**: memcpy's time / the row's time, per byte (its bandwidth as a share "
          "of memcpy's).\n\n")
        head = ["#", "method", "vs", "cases", "MB in+out"]
        for label, _, _ in builds:
            head += ["ns/case " + label, "GB/s " + label, "**% of memcpy " + label + "**",
                     "CPU % " + label]
        head += ["containment failures", "proven", "notes"]
        w("| " + " | ".join(head) + " |\n")
        w("|" + "|".join(["---"] * 3 + ["---:"] * (2 + 4 * len(builds) + 1) + ["---", "---"])
          + "|\n")
        for r in tp:
            unit, cases = fnum(r["unit"]), fnum(r["cases"])
            cells = [r["id"], r["name"], base_cell(r), r["cases"], "%.0f" % (cases * unit / 1e6)
                     if cases * unit >= 1e6 else "%.2f" % (cases * unit / 1e6)]
            for _, _, rows in builds:
                x = rows.get(r["id"], {})
                ns = fnum(x.get("ns"))
                cells += [num(ns), num(unit / ns) if ns > 0 else "-", "**%s**" % pct(x.get("rw")),
                          pct(x.get("rc"))]
            cells += [containment(r, builds), r["proven"], notes(r, builds, differs)]
            w("| " + " | ".join(cells) + " |\n")

    w("\nvs: the baseline row, run on the same inputs in the same rounds (round-to-nearest "
      "Arvo, unsound; throughput: memcpy). max / mean excess: signed (negative = inside the "
      "exact image); a proven row must have 0 containment failures. Timings vary with load; "
      "the ratios, measured in the same rounds, much less.\n")
    md = "".join(out)
    os.makedirs(outdir, exist_ok=True)
    with open(os.path.join(outdir, "bench.md"), "w", encoding="utf-8") as f:
        f.write(md)
    sys.stdout.write(md)

    # bench.dat for scripts/bench.gp
    with open(os.path.join(outdir, "bench.dat"), "w", encoding="utf-8") as f:
        f.write("# certbox bench (bench/bench.c, scripts/bench_table.py), for scripts/bench.gp: one\n"
                "# data block per plotted row (blocks separated by two blank lines), each a header\n"
                "# line (its 6th field is the row's title) and one data line.\n")
        f.write("# machine: %s, %s cores; %s\n" % (m0["machine"], m0["cores"], m0["cc_version"]))
        f.write("# build1: %s\n# build2: %s\n" % (builds[0][0], builds[1][0] if len(builds) > 1
                                                   else "(none)"))
        f.write("# columns: row ns_per_box(build1) max_excess y_plotted proven(1 yes, 0 no, 2 exact) "
                "label ns_per_box(build2, NaN if none)\n")
        f.write("# y_plotted: max excess, floored at 0.01 for the log scale (exact: 0)\n")
        for r in order:
            if r["sec"] != "main" or r["plot"] != "1":
                continue
            mx = fnum(r["ex_max"])
            mx = 0.0 if math.isnan(mx) else mx
            y = max(mx, 0.01)
            lab = r["name"].replace("`", "").replace('"', "")
            tag = {"1": " [proven]", "2": " [exact]"}.get(r["pcode"], "")
            ns2 = fnum(builds[1][2].get(r["id"], {}).get("ns")) if len(builds) > 1 else math.nan
            f.write('\n\nrow ns_per_box max_excess y_plotted proven "%s: %s%s" ns2\n'
                    % (r["id"], lab, tag))
            f.write('%s %.6g %.6g %.6g %s "%s" %s\n' % (r["id"], fnum(r["ns"]), mx, y, r["pcode"],
                                                        r["id"], "NaN" if math.isnan(ns2)
                                                        else "%.6g" % ns2))
    sys.stderr.write("bench: wrote %s and %s\n" % (os.path.join(outdir, "bench.md"),
                                                  os.path.join(outdir, "bench.dat")))
    if failed:
        for label, status in failed:
            sys.stderr.write("bench: %s: %s\n" % (label, status))
        return 1
    if certbox_differs:
        sys.stderr.write("bench: FAILED: certbox outputs differ between the builds in rows %s\n"
                         % ", ".join(certbox_differs))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
